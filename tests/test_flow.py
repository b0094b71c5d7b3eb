"""Flow sections, conditional velocities, time-area and fullness (Valve-train practical works (n.d.), works 1 and 4, Shang Hanji (1988))."""

import numpy as np
import pytest
from scipy.integrate import quad

from valvetrain import flow
from valvetrain.checks import failed
from valvetrain.numerics import cumulative_integral

from conftest import SEED000_OMEGA_EXACT, seed000_law

D, S, N = 0.080, 30.0 * 18.0 / 7000.0, 7000.0  # S = 30 c_p / n (appendix of Valve-train practical works (n.d.))
D_THROAT, SEAT, I_K = 0.0368, np.pi / 4, 1.6


def test_seed000_flow_sections():
    cp = flow.mean_piston_speed(S, N)
    assert cp == pytest.approx(18.0, rel=1e-12)  # appendix of Valve-train practical works (n.d.): c_p = 18 m/s
    f_max = flow.curtain_area(0.010, D_THROAT, SEAT)
    assert f_max * 1e6 == pytest.approx(928.56, abs=0.01)  # spec 4.4 / E7: 9.2856 cm2 from (1.3)
    assert flow.throat_velocity(cp, D, D_THROAT, 1) == pytest.approx(85.07, abs=0.005)  # spec 4.4
    assert flow.curtain_velocity(cp, D, f_max, 1) == pytest.approx(97.44, abs=0.005)   # spec 4.4
    # Valve-train practical works (n.d.), corrections note 7: the appendix's 9.5 cm2 is c_p F_p / (i * 95 m/s) = 9.524 cm2
    assert flow.curtain_velocity(cp, D, 952.4e-6, 1) == pytest.approx(95.0, abs=0.01)


def _curtain(law):
    return lambda t: flow.curtain_area(law.valve_lift(t, I_K), D_THROAT, SEAT)


def test_seed000_time_area():
    """Spec 4.4: 2.8564 mm2 s TDC->BDC (V''' = 135.75 m/s), 3.2772 mm2 s over the whole opening."""
    law = seed000_law()
    nose = np.deg2rad(116.0)  # crank deg of the nose after TDC (Table P1)
    a, b = (0.0 - nose) / 2, (np.pi - nose) / 2
    ta = flow.time_area(_curtain(law), a, b, SEED000_OMEGA_EXACT, law.breakpoints)
    assert ta * 1e6 == pytest.approx(2.8564, abs=1e-4)
    assert flow.time_area_velocity(flow.swept_volume(D, S), ta, 1) == pytest.approx(135.75, abs=0.01)
    ta_open = flow.time_area(_curtain(law), law.valve_opens, law.valve_closes, SEED000_OMEGA_EXACT,
                             law.breakpoints)
    assert ta_open * 1e6 == pytest.approx(3.2772, abs=1e-4)
    # independent computation: adaptive quadrature of the same integrand (scipy.integrate.quad)
    ref = quad(lambda t: float(_curtain(law)(np.array([t]))[0]), a, b, points=law.breakpoints, limit=200,
               epsabs=0, epsrel=1e-12)[0] / SEED000_OMEGA_EXACT
    assert ta == pytest.approx(ref, rel=1e-9)


def test_linearised_time_area_of_work4():
    """Work 4's M_F linearises (1.3) (drops h sin cos^2): 2.5665 mm2 s and v_vp = 151.08 m/s (spec 4.4, Valve-train practical works (n.d.), corrections note 29)."""
    law = seed000_law()
    nose = np.deg2rad(116.0)
    a, b = -nose / 2, (np.pi - nose) / 2
    lin = lambda t: np.pi * D_THROAT * np.cos(SEAT) * law.valve_lift(t, I_K)  # noqa: E731
    ta = flow.time_area(lin, a, b, SEED000_OMEGA_EXACT, law.breakpoints)
    assert ta * 1e6 == pytest.approx(2.5665, abs=1e-4)
    assert flow.mean_charge_velocity(flow.swept_volume(D, S), ta) == pytest.approx(151.08, abs=0.01)


def test_swept_volume():
    # spec 4.4: V_h = 3.8776e-4 m3
    assert flow.swept_volume(D, S) == pytest.approx(3.8776e-4, abs=1e-8)


def test_fullness_identities():
    # a rectangle has fullness 1, a half-sine 2/pi, a triangle 1/2 (definition of Shang Hanji (1988), eq. 2.3)
    assert flow.fullness(lambda t: np.ones_like(t), 0.0, 2.0, 1.0) == pytest.approx(1.0, rel=1e-14)
    assert flow.fullness(np.sin, 0.0, np.pi, 1.0) == pytest.approx(2 / np.pi, rel=1e-14)
    tri = lambda t: 1.0 - np.abs(t)  # noqa: E731
    assert flow.fullness(tri, -1.0, 1.0, 1.0, breakpoints=[0.0]) == pytest.approx(0.5, rel=1e-14)


def test_cumulative_integral_exact_for_polynomials():
    """16-point Gauss-Legendre is exact to degree 31: running integral of x^5 is x^6/6."""
    x = np.linspace(0.0, 2.0, 7)
    assert np.allclose(cumulative_integral(lambda t: t**5, x), x**6 / 6.0, rtol=1e-13, atol=1e-14)


def test_curtain_area_closed_valve_is_zero():
    assert flow.curtain_area(np.array([-1e-3, 0.0]), D_THROAT, SEAT).tolist() == [0.0, 0.0]


def test_flow_checks_flag_the_appendix():
    """Valve-train practical works (n.d.), corrections note 8: V' = 85.1 m/s above 50-80 and V'' = 97.4 above 80-95."""
    found = flow.check_flow("intake", bore=D, throat_diameter=D_THROAT, max_lift=0.010, v1=85.07, v2=97.44,
                            v3=135.75, charge_velocity=135.75, engine_type="si", chamber="hemispherical")
    names = [f.quantity for f in failed(found)]
    assert names == ["V' (throat velocity)", "V'' (curtain velocity at full lift)"]
    assert failed(found)[0].range == "50...80 m/s"


def test_several_diagrams_at_once():
    """fullnesses and time_areas take each diagram's own interval and breakpoints in one quadrature: a rectangle 1,
    a half-sine 2/pi, a triangle 1/2 (as test_fullness_identities); the time-area of a constant area f over
    [a, b] at omega is f (b - a) / omega."""
    shapes = [lambda t: np.ones_like(t), np.sin, lambda t: 1.0 - np.abs(t)]

    def lift(t, member):
        out = np.empty_like(t)
        for i, shape in enumerate(shapes):
            out[member == i] = shape(t[member == i])
        return out

    got = flow.fullnesses(lift, [0.0, 0.0, -1.0], [2.0, np.pi, 1.0], [1.0, 1.0, 1.0], [[], [], [0.0]])
    np.testing.assert_allclose(got, [1.0, 2.0 / np.pi, 0.5], rtol=1e-14)
    areas = np.array([2e-4, 3e-4])
    got = flow.time_areas(lambda t, member: areas[member] * np.ones_like(t), [0.0, -0.5], [1.0, 0.7], 50.0, [[], [0.1]])
    np.testing.assert_allclose(got, areas * np.array([1.0, 1.2]) / 50.0, rtol=1e-14)
