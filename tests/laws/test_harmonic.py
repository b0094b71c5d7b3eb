"""The N-harmonic cam (laws/harmonic.py; Shang Hanji (1988), sections 4.2 and 3.3): a finite Fourier series fitted to a
target law under end constraints."""

import numpy as np
import pytest

from valvetrain.laws.harmonic import HarmonicLaw, harmonic_limit
from valvetrain.laws.polydyne import PolydyneLaw

from appendix import appendix_cam, appendix_with


def _polydyne_target():
    """The spec's section 7 cam: h_max 8, h0 0.3, v0 0.4 mm/rad, 55 deg, exponents 2, 10, 18, 26, 34."""
    return PolydyneLaw(7.7e-3, np.radians(55), 10, 18, 26, 34, ramp_height=0.3e-3, ramp_velocity=0.4e-3)


@pytest.mark.parametrize("n,m", [(12, 1), (20, 2), (30, 2)])
def test_harmonic_cam_constraints(n, m):
    """Shang Hanji (1988), section 4.2 (spec section 9): h(0) = h_max and the even derivatives up to 2m vanish at
    +-alpha_W (odd ones by construction), the fit residual small against the lift."""
    target = _polydyne_target()
    law = HarmonicLaw(target, n, m)
    assert law.lift(0.0) == pytest.approx(8e-3, abs=1e-15)
    ends = law.derivatives(np.array([law.start, law.end]))
    assert np.abs(ends).max() < 1e-12
    k = np.arange(n + 1)
    for j in range(m + 1):  # h^(2j)(alpha_W) = sum a_k (-1)^j (k pi / alpha_W)^(2j) (-1)^k
        assert abs(np.sum(law.a * (-1.0) ** k * law.w ** (2 * j))) < 1e-9 * np.abs(law.a * law.w ** (2 * j)).sum()
    assert law.deviation < 0.05e-3


def test_harmonic_fit_improves_with_n():
    target = _polydyne_target()
    devs = [HarmonicLaw(target, n, 2).deviation for n in (10, 20, 40)]
    assert devs[0] > devs[1] > devs[2]


def test_harmonic_limit_rule():
    """N < alpha_W omega_n / (pi omega) (Shang Hanji (1988), section 4.2; spec section 9): with epsilon = 0.00164 and
    alpha_W = 70 deg, N < 9.6."""
    eps = 0.00164
    assert harmonic_limit(np.radians(70), 1.0 / np.sqrt(eps), 1.0) == pytest.approx(9.6, abs=0.05)


def test_high_harmonic_and_junction_orders_fit(tmp_path):
    """N = 400, m = 10 made the KKT system singular (a lift of 1.5e10 mm); the null-space solution follows the
    Kurz target of the appendix of Valve-train practical works (n.d.) (10 mm valve lift) within 2 um."""
    from valvetrain.design import run
    from valvetrain.specification import parse_spec

    res = run(parse_spec(_harmonic(400, 10))).to_dict()["valves"]["intake"]
    assert res["flow"]["valve_lift_mm"] == pytest.approx(10.0, rel=1e-9)
    assert res["cam"]["coefficients"]["max_deviation_mm"] < 2e-3


def _harmonic(n, m):
    return appendix_with((appendix_cam(), f"""[valves.intake.cam]
law = "harmonic"
harmonics = {n}
junction_order = {m}
base_radius_mm = 20.0
[valves.intake.cam.target]
law = "kurz"
ramp_end_velocity_mm_per_deg = 0.02
phi1_deg = 27.0
phi2_deg = 6.0
phi3_deg = 38.0

"""))
