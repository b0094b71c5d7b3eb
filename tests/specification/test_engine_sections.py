"""The sections of the engine's further stages (specification/engine_sections.py): the crank's cylinder pressure file
is refused where it cannot be a cycle (a gap over half of it, counted from the firing TDC, p-V files that are no
cycle of the cylinder), a whole cycle runs; the camshaft's torsional damping is bounded away from zero."""

from pathlib import Path

from click.testing import CliRunner
import numpy as np
import pytest

from valvetrain.cli import main
from valvetrain.crank import pressure
from valvetrain.specification import SpecError, load_spec

from appendix import appendix_text


def _indicator(tmp_path, phi_deg, p):
    """The example with its Wiebe cycle replaced by an indicator file of p(phi_deg) [Pa]."""
    (tmp_path / "ind.csv").write_text("crank_deg,pressure_MPa\n" + "".join(f"{a:.6f},{b / 1e6:.9f}\n"
                                                                           for a, b in zip(phi_deg, p)))
    text = appendix_text()
    text = text.replace(text[text.index("# Without a pressure_file"):text.index("[output]")], "")
    return text.replace('# pressure_file = "indicator.csv"', 'pressure_file = "ind.csv"')


def _wiebe(phi_deg):
    return pressure.wiebe_pressure(np.radians(phi_deg), pressure.WiebeCycle(10.0, 950.0), 0.080, 0.0385714, 0.2857, 4)


def test_a_whole_cycle_file_runs(tmp_path):
    phi = np.arange(0.0, 720.0, 1.0)
    f = tmp_path / "spec.toml"
    f.write_text(_indicator(tmp_path, phi, _wiebe(phi)))
    assert CliRunner().invoke(main, ["validate", str(f)]).exit_code == 0


def test_a_pressure_file_over_half_the_cycle_is_refused(tmp_path, refused):
    """A four-stroke file of 0-360 deg only: interpolating across 360-720 gave -816 J of indicated work."""
    phi = np.arange(0.0, 361.0, 1.0)
    out = refused(_indicator(tmp_path, phi, _wiebe(phi)), "run")
    assert "crank.pressure_file:" in out and "a gap of 360 deg; allowed at most 60 deg" in out


def test_a_pressure_file_from_firing_tdc_is_refused(tmp_path, refused):
    """The same cycle counted from the firing TDC peaks near 0 instead of 360 deg."""
    phi = np.arange(0.0, 720.0, 1.0)
    out = refused(_indicator(tmp_path, phi, _wiebe(phi + 360.0)))
    assert "the pressure peaks at crank_deg = " in out and "shift the angles" in out


@pytest.mark.parametrize("volumes,message", [
    (np.full(40, 300.0), "the volume changes direction 0 times; a 4-stroke cycle needs 4 monotone branches"),
    (np.concatenate([np.linspace(45, 430, 20), np.linspace(430, 45, 20)]), "changes direction 1 times"),
    (np.concatenate([np.linspace(45, 900, 10), np.linspace(900, 45, 10)] * 2), "is outside the cylinder volume"),
])
def test_bad_p_v_files_are_refused(tmp_path, refused, volumes, message):
    (tmp_path / "pv.csv").write_text("volume_cm3,pressure_MPa\n" + "".join(f"{v:g},0.5\n" for v in volumes))
    text = _indicator(tmp_path, [0.0], [1e5]).replace('pressure_file = "ind.csv"', 'pressure_file = "pv.csv"')
    out = refused(text)
    assert "crank.pressure_file:" in out and message in out


PUSHROD = Path(__file__).parents[2] / "examples" / "pushrod-dynamics.toml"


@pytest.mark.parametrize("value", [5e-324, 1e-300, 0.00099])
def test_a_torsional_damping_of_almost_nothing_is_refused(value):
    """Fuzz (fuzz11): [camshaft] torsional_damping_ratio, then (0, 0.5], took 5e-324 and overflowed the forced
    response (a traceback), and 1e-300 gave a timing fluctuation of 1.5e298 cam deg; now at least 0.001 (at which
    the pushrod example's chain resonance, amplified 1 / (2 x 0.001) = 500 times, moves its timing by 15 cam deg:
    Camshaft's docstring), and 0.001 itself is taken."""
    spec = load_spec(PUSHROD)
    with pytest.raises(SpecError, match=rf"^camshaft.torsional_damping_ratio = {value!r}: allowed \[0.001, 0.5\]$"):
        spec.replace({"camshaft.torsional_damping_ratio": value})
    assert spec.replace({"camshaft.torsional_damping_ratio": 0.001}).camshaft.torsional_damping_ratio == 0.001
