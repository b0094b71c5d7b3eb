"""The required spring force and its enveloping line (springs/requirement.py; Valve-train practical works (n.d.),
work 5): the line above the requirement, the closed form against a linear programme, the gas force, the seat load."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from valvetrain import springs

from conftest import SEED000_OMEGA_EXACT, seed000_law


def test_gas_force():
    # eq. (5.4): pi/4 * 0.031^2 * (0.106 - 0.085) MPa = 15.85 N; no force when the cylinder pressure is higher
    assert springs.gas_opening_force(0.031, 0.106e6, 0.085e6) == pytest.approx(15.85, abs=0.01)
    assert springs.gas_opening_force(0.031, 0.100e6, 0.115e6) == 0.0


def test_characteristic_relations():
    """(5.6)-(5.9): f_max = f_min + h; the nested split keeps the sums (5.10)-(5.12)."""
    c = springs.Characteristic(300.0, 60e3, 0.010)
    assert c.max_force == pytest.approx(900.0)
    assert c.max_deflection == pytest.approx(c.preload_deflection + 0.010)
    outer, inner = c.split(0.4)
    assert outer.preload + inner.preload == pytest.approx(c.preload)
    assert outer.rate + inner.rate == pytest.approx(c.rate)
    assert inner.max_force == pytest.approx(0.4 * c.max_force)


def _requirement(law, mass, reserve=1.8, ratio=1.6):
    theta = np.linspace(law.valve_opens, law.valve_closes, 2001)
    y = law.valve_lift(theta, ratio)
    a = ratio * SEED000_OMEGA_EXACT**2 * law.derivatives(theta)[2]
    return y, springs.required_spring_force(mass, a, reserve)


@settings(max_examples=40, deadline=None)
@given(st.floats(0.05, 0.4), st.floats(1.5, 2.25), st.floats(0.0, 400.0))
def test_envelope_property(mass, reserve, gas):
    """The line is above the requirement everywhere and touches it at least once (issue 3)."""
    y, req = _requirement(seed000_law(), mass, reserve)
    p0, c = springs.enveloping_line(y, req, min_preload=gas)
    line = p0 + c * y
    assert np.all(line >= req - 1e-6 * req.max())
    touching = np.min(line - req) <= 1e-6 * req.max()
    assert touching or p0 == pytest.approx(gas)
    ratio = (p0 + c * y.max()) / p0
    assert 1.6 - 1e-9 <= ratio <= 3.2 + 1e-9
    assert p0 >= gas - 1e-9


def test_envelope_is_steepest_line_through_full_lift_when_ratio_allows():
    """With the ratio bound slack the optimum goes through c' (full lift) and is tangent below it (Fig. 5.1)."""
    y, req = _requirement(seed000_law(), 0.16)
    p0, c = springs.enveloping_line(y, req, ratio_range=(1.0, 100.0))
    top = np.argmax(y)
    assert p0 + c * y[top] == pytest.approx(req[top], rel=1e-9)
    below = y < y[top] - 1e-9
    # the linear programme meets its constraints to HiGHS's feasibility tolerance, not to round-off
    assert c == pytest.approx(np.min((req[top] - req[below]) / (y[top] - y[below])), rel=1e-4)


def test_closed_form_envelope_is_the_linear_programme():
    """The closed-form line of enveloping_line is the optimum of the linear programme of its docstring, solved
    independently with scipy's HiGHS: the same smallest P_max and, of the optimal lines, the steepest (largest
    C at that P_max).  Requirements of the cam of the appendix of Valve-train practical works (n.d.) at random masses, reserves and gas forces."""
    from scipy.optimize import linprog

    rng = np.random.default_rng(10)
    law = seed000_law()
    for _ in range(20):
        y, req = _requirement(law, rng.uniform(0.05, 0.4), rng.uniform(1.5, 2.25))
        gas = rng.choice([0.0, rng.uniform(0.0, 600.0)])
        ratios = tuple(rng.choice([(1.6, 3.2), (1.0, 100.0), (2.0, 2.5)]))
        p0, c = springs.enveloping_line(y, req, ratios, gas)
        h = y.max()
        a_ub = np.vstack([np.column_stack([-np.ones_like(y), -y]), [[ratios[0] - 1.0, -h], [1.0 - ratios[1], h]]])
        b_ub = np.concatenate([-req, [0.0, 0.0]])
        bounds = [(gas, None), (0.0, None)]
        lp = linprog([1.0, h], A_ub=a_ub, b_ub=b_ub, bounds=bounds, method="highs")
        assert p0 + c * h == pytest.approx(lp.fun, rel=1e-6)
        steep = linprog([0.0, -1.0], A_ub=np.vstack([a_ub, [[1.0, h]]]), b_ub=np.append(b_ub, lp.fun * (1 + 1e-9)),
                        bounds=bounds, method="highs")
        # HiGHS meets the constraints to its feasibility tolerance, not to round-off
        assert c == pytest.approx(steep.x[1], rel=1e-4)


def test_lines_of_every_ratio_envelop_the_requirement():
    """enveloping_lines: each line has its ratio, stays above the requirement and touches it (or the gas force);
    the required line's own ratio gives the required line (eqs. 5.6-5.9)."""
    y, req = _requirement(seed000_law(), 0.16)
    ratios = springs.deflection_ratios()
    p0, c = springs.enveloping_lines(y, req, ratios, 50.0)
    h = y.max()
    assert np.allclose((p0 + c * h) / p0, ratios, rtol=1e-12)
    gap = p0[:, None] + c[:, None] * y[None, :] - req[None, :]
    assert np.all(gap >= -1e-9 * req.max())
    assert np.all((np.min(gap, axis=1) <= 1e-9 * req.max()) | np.isclose(p0, 50.0))
    line = springs.enveloping_line(y, req, min_preload=50.0)
    p1, c1 = springs.enveloping_lines(y, req, [(line[0] + line[1] * h) / line[0]], 50.0)
    assert (p1[0], c1[0]) == pytest.approx(line, rel=1e-12)


def test_a_line_set_by_an_inner_point_has_the_smallest_ratio_exactly():
    """Where the point that sets the smallest P_max lies inside the lift (here at 5/6 of it), no steeper line keeps
    that P_max (enveloping_line's Notes): the ratio is r1 = 1.6 itself, P_min = P* / 1.6 to the bit, not 1.6 plus
    the round-off of P_i - P* u_i (before: 1.600000000000002), which another BLAS kernel can put on either side of
    1.6; and lines() tries that ratio once, not 1.6 and 1.6 + 2e-15 as two lines."""
    y = np.linspace(0.0, 0.01, 7)
    req = np.array([0.0, 435.3, 423.6, 407.7, 291.8, 598.6, 590.4])
    u = y / y.max()
    p_star = float(np.max(1.6 * req / (1.0 + 0.6 * u)))
    assert int(np.argmax(1.6 * req / (1.0 + 0.6 * u))) == 5
    p0, c = springs.enveloping_line(y, req)
    assert p0 == p_star / 1.6
    requirement = springs.Requirement(y, req)
    preloads, _ = requirement.lines(line=springs.Characteristic(p0, c, y.max()))
    assert preloads.size == springs.deflection_ratios().size


def test_lines_keep_the_required_ratio_off_the_grid():
    """A required line of ratio 2.05 (between the grid's 2.0 and 2.1) is tried as a line of its own; one of ratio
    2.0 within round-off is the grid's line 2.0."""
    y = np.linspace(0.0, 0.01, 5)
    requirement = springs.Requirement(y, np.array([0.0, 100.0, 200.0, 250.0, 280.0]))
    grid = springs.deflection_ratios().size
    for ratio, extra in ((2.05, 1), (2.0 * (1.0 + 4e-16), 0), (2.0 * (1.0 - 4e-16), 0)):
        line = springs.Characteristic(100.0, (ratio - 1.0) * 100.0 / y.max(), y.max())
        assert requirement.lines(line=line)[0].size == grid + extra


def test_the_seat_load_holds_a_slow_engine_s_valve():
    """Issue 10: at 600 rpm the inertia asks for a 2.3 N preload.  The preload is at least m_v x 100 g (a stated
    default), or min_preload_N, and never below the gas force (5.4)."""
    law = seed000_law()
    slow = SEED000_OMEGA_EXACT * 600 / 7000
    theta = np.linspace(law.valve_opens, law.valve_closes, 2001)
    y = law.valve_lift(theta, 1.6)
    req = springs.required_spring_force(0.147, 1.6 * slow**2 * law.derivatives(theta)[2], 1.8)
    assert springs.enveloping_line(y, req)[0] < 5.0
    seat = springs.seat_load(0.147)
    assert seat == pytest.approx(0.147 * 9.80665 * 100)
    p0, _ = springs.enveloping_line(y, req, min_preload=max(seat, 15.85))
    assert p0 == pytest.approx(seat)
