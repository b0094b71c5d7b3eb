"""Every law runs through the whole design chain (flow, contour, springs, strength, report) without special cases."""

import json
import re

from click.testing import CliRunner
import numpy as np
import pytest

from valvetrain.cli import main
from valvetrain.design import run
from valvetrain.specification import parse_spec

from appendix import appendix_text

KURZ_KEYS = '''law = "kurz"                 # "kurz" or "polydyne"'''
KURZ_BLOCK = ["ramp_end_velocity_mm_per_deg = 0.02\n", "phi1_deg = 27.0", "phi2_deg = 6.0", "phi3_deg = 38.0",
              "shape_factor = 0.625"]

CAMS = {
    "polynomial": 'law = "polynomial"\nexponents = [2, 6, 10, 14, 18, 22]\nramp = true\n'
                  'ramp_end_velocity_mm_per_deg = 0.015\nramp_type = "constant_acceleration"',
    "constant_acceleration": 'law = "constant_acceleration"\nramp_end_velocity_mm_per_deg = 0.02\n'
                             'phi1_deg = 22.0\nphi2_deg = 30.0\nkappa = 0.6',
    "three_arc": 'law = "three_arc"\nflank_angle_deg = 25.0',
    "harmonic": 'law = "harmonic"\nharmonics = 24\njunction_order = 2\ntarget = {law = "polydyne", p = 8, '
                'ramp = true, ramp_end_velocity_mm_per_deg = 0.02}',
    "dynamic": 'law = "dynamic"\nvalve_opening_velocity_m_s = 0.3\ndrive_stiffness_N_per_mm = 15000.0\n'
               'spring_rate_N_per_mm = 70.0\nspring_preload_N = 250.0\nramp_type = "constant_acceleration"',
    "combined": 'law = "combined"\nramp_end_velocity_mm_per_deg = 0.02\nsegments = [{shape = "half_sine", '
                'length_deg = 25.0}, {shape = "quarter_sine", length_deg = 8.0}, {shape = "parabola_to_nose", '
                'length_deg = 38.0}]\nratios = [{segment = 2, value = 0.625}]',
    "tangent": 'law = "tangent"',
}


def _text(cam_keys):
    """The example with its Kurz keys replaced by ``cam_keys``."""
    text = appendix_text()
    for line in KURZ_BLOCK:
        text = text.replace(line, "", 1)
    return text.replace(KURZ_KEYS, cam_keys)


def _spec(law, *replacements):
    """The example with the cam of ``law``; further ``(old, new)`` text replacements are applied in order."""
    text = _text(CAMS[law])
    if law == "tangent":
        text = text.replace('follower = "flat"', 'follower = "roller"\nroller_radius_mm = 11.0')
    for old, new in replacements:
        text = text.replace(old, new)
    return parse_spec(text)


@pytest.mark.parametrize("law", sorted(CAMS))
def test_law_runs_through_the_design(law):
    res = run(_spec(law))
    v = res.to_dict()["valves"]["intake"]
    assert v["cam"]["law"] == law
    # the valve lift reaches the specified 10 mm (at the valve), the tappet lift 6.25 mm above the ramp; the harmonic
    # fit to the target's lift; the dynamic cam's rigid lift differs: its valve reaches 10 mm only elastically
    if law not in ("harmonic", "dynamic"):
        assert float(res.valves["intake"].table.valve_lift.max()) * 1e3 == pytest.approx(10.0, abs=1e-3)
        assert v["cam"]["tappet_lift_mm"] == pytest.approx(6.25)
    elif law == "harmonic":
        assert v["cam"]["tappet_lift_mm"] == pytest.approx(6.25, abs=1e-9)
    for key in ("time_area_mm2_s", "V3_m_s", "fullness"):
        assert np.isfinite(v["flow"][key])
    assert v["spring"]["max_force_N"] > v["spring"]["preload_N"] > 0
    assert v["strength"]["checks"]


def test_constant_acceleration_phi3_is_the_remainder():
    cam = _spec("constant_acceleration").valves["intake"].cam
    res = run(_spec("constant_acceleration"))
    law = res.valves["intake"].law
    # 71 - 22 - 30 = 19 cam deg for the third segment (the remainder of phi_p0, as for Kurz)
    assert np.degrees(law.phi[2]) == pytest.approx(71.0 - cam.phi1_deg - cam.phi2_deg)


def test_three_arc_construction_in_results():
    cam = run(_spec("three_arc")).to_dict()["valves"]["intake"]["cam"]
    assert cam["coefficients"]["phi1_deg"] == pytest.approx(25.0, abs=1e-9)
    # flat follower on arcs: the profile radius is the nose radius at the nose, the flank radius on the flank
    assert cam["rho_min_mm"] == pytest.approx(cam["coefficients"]["r2"], rel=1e-9)
    assert cam["rho_max_mm"] == pytest.approx(cam["coefficients"]["r1"], rel=1e-9)


def test_impossible_arc_cam_is_refused(refused):
    assert "valves.intake.cam: three-arc cam" in refused(_text('law = "three_arc"\nnose_radius_mm = 19.9'))


def test_tangent_needs_a_roller(refused):
    assert 'needs follower = "roller"' in refused(_text('law = "tangent"'))


def test_tangent_cam_has_no_concave_stretch():
    """Straight flanks and arcs only (spec section 4): no concave radius is reported, whatever the event length
    (a 78 deg opening lengthens the flanks)."""
    for opens in (26.0, 78.0):
        spec = _spec("tangent", ("opens_deg = 26.0", f"opens_deg = {opens}"))
        assert run(spec).to_dict()["valves"]["intake"]["cam"]["min_concave_radius_mm"] is None


def test_report_for_an_arc_cam(tmp_path):
    out = tmp_path / "d"
    f = tmp_path / "e.toml"
    f.write_text(_text(CAMS["three_arc"]))
    assert CliRunner().invoke(main, ["run", str(f), "--out", str(out)]).exit_code == 0
    assert json.loads((out / "results.json").read_text())["valves"]["intake"]["cam"]["law"] == "three_arc"
    html = (out / "report.html").read_text()
    assert "three_arc" in html
    # the report names the three-arc cam's own sources (by their numbers in its list, issue 39), not the polydyne
    # formula of Valve-train practical works (n.d.), work 3
    assert re.search(r"three-arc convex cam for a flat follower \(\[\d+\]; \[\d+\]\)", html)
    assert "Колчин А. И., Демидов В. П. Расчёт автомобильных" in html and "Исследование динамики МГР" in html
    assert not re.search(r"\[\d+, work 3\b", html)


def test_train_natural_frequency_and_harmonic_rule():
    """omega_n = sqrt((c + K)/M), epsilon = M omega^2/(c + K) (SPEC.md: M omega^2 / c, not omega^3); an N-harmonic
    cam above N < alpha_W omega_n / (pi omega) is flagged (spec section 9)."""
    spec = _spec("harmonic")
    drive = spec.valves["intake"].drive.model_copy(update={"stiffness_N_per_mm": 3000.0})
    valve = spec.valves["intake"].model_copy(update={"drive": drive})
    res = run(spec.model_copy(update={"valves": {"intake": valve}}))
    m = res.to_dict()["valves"]["intake"]["masses"]
    rate = res.to_dict()["valves"]["intake"]["spring"]["rate_N_per_mm"] * 1e3
    omega_n = np.sqrt((3000e3 + rate) / m["at_valve_kg"])
    assert m["natural_frequency_Hz"] == pytest.approx(omega_n / (2 * np.pi), rel=1e-12)
    omega = np.pi * 7000 / 60
    assert m["epsilon"] == pytest.approx(m["at_valve_kg"] * omega**2 / (3000e3 + rate), rel=1e-12)
    law = res.valves["intake"].law
    # the rule is one check record of the valve (its upper bound the limit), passed or failed
    rule = next(c for c in res.to_dict()["checks"] if c["quantity"] == "intake: harmonic order N of the cam")
    assert rule["high"] == pytest.approx(law.alpha * omega_n / (np.pi * omega), rel=1e-12)
    assert rule["pass"] == (24 <= rule["high"])


def test_tangent_cam_lift_table_has_no_inf(tmp_path):
    """The straight flanks' infinite radius is an empty rho_mm cell (documented), never 'inf' or 'nan'."""
    import csv

    from valvetrain.export import write_csv
    from valvetrain.tables import lift_table_columns

    write_csv(tmp_path / "t.csv", lift_table_columns(run(_spec("tangent")).valves["intake"].table))
    rows = list(csv.DictReader((tmp_path / "t.csv").open()))
    assert any(r["rho_mm"] == "" for r in rows)
    assert not any(c in ("inf", "-inf", "nan") for r in rows for c in r.values())
