"""Valve springs: characteristic (Valve-train practical works (n.d.), work 5) and design (work 6), with a textbook spring example."""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from valvetrain import masses, spring_materials, springs
from valvetrain.locale.wording import diagnosis_text
from valvetrain.springs import diagnosis

from appendix import appendix_text

from conftest import SEED000_OMEGA_EXACT, seed000_law


def test_bhandari_example_11_1():
    """V. B. Bhandari, Design of Machine Elements (Tata McGraw-Hill), Example 11.1: P = 1250 N, deflection
    30 mm, index 6, G = 81370 N/mm2, tau = 0.5 x 1090 = 545 N/mm2, square and ground ends.
    Printed results: Wahl K = 1.2525, d = 6.63 mm -> 7 mm, D = 42 mm, N = 7.91 -> 8 active coils."""
    k = float(springs.wahl_factor(6.0))
    assert k == pytest.approx(1.2525, abs=5e-5)
    # tau = K 8 P C / (pi d^2) = 545 MPa solved for d (eq. 6.1 with D = C d)
    d = np.sqrt(k * 8 * 1250.0 * 6.0 / (np.pi * 545e6))
    assert d * 1e3 == pytest.approx(6.63, abs=0.005)
    assert springs.shear_stress(1250.0, 6 * d, d, k) == pytest.approx(545e6, rel=1e-12)
    n = springs.active_coils(81370e6, 7e-3, 30e-3, 1250.0, 42e-3)
    assert n == pytest.approx(7.91, abs=0.005)
    # rate of the rounded spring: G d^4 / (8 D^3 N) with N = 8: 1250 N now deflects it 30 x 8/7.91 mm
    rate = springs.spring_rate(81370e6, 7e-3, 42e-3, 8.0)
    assert 1250.0 / rate * 1e3 == pytest.approx(30.0 * 8.0 / 7.911, abs=0.005)


def test_shape_factor_table_is_close_to_wahl():
    """The manual's chi table (eq. 6.1) lies below Wahl's formula: by 5.1 % at D/d = 3, by under 1.9 % from 4 to 12
    (independent evaluation of both)."""
    c, chi = springs.SHAPE_FACTOR_TABLE
    rel = chi / springs.wahl_factor(c) - 1.0
    assert np.all(rel < 0)
    assert rel[0] == pytest.approx(-0.0506, abs=1e-4)
    assert np.max(np.abs(rel[1:])) < 0.019
    assert float(springs.shape_factor_table(3.5)) == pytest.approx(1.44)  # linear interpolation of (3, 1.5), (4, 1.38)
    assert np.isnan(springs.shape_factor_table(2.5))


def test_natural_frequency_reading():
    """(6.13) reading [A] agrees within 1.2 % with Kolchin's n_c = 2.17e7 d/(i D^2) min^-1 (spec work 6)."""
    d, D, i = 4e-3, 30e-3, 6.0
    w = springs.natural_frequency(d, D, i, 8.0e10, 7850.0)
    kolchin = 2.17e7 * 4.0 / (i * 30.0**2) * np.pi / 30.0
    assert w == pytest.approx(kolchin, rel=0.012)


def test_fatigue_without_mean_stress_factor():
    """Valve-train practical works (n.d.), corrections note 24: without a mean-stress reduction (psi_tau = 1) n = tau_-1/(tau_a + tau_m) = tau_-1/tau_max, below 1.2
    for tau_max > 333 MPa at tau_-1 = 400 MPa; psi_tau = 0.2 gives tau_-1/(tau_a + 0.2 tau_m)."""
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 1.0) == pytest.approx(400 / 340)
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 1.0) < 1.2
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 0.2) == pytest.approx(400 / (120 + 0.2 * 220))


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


def _brute_force(line, throat, omega, options):
    """Every candidate of the search, one at a time with the scalar formulas of Valve-train practical works (n.d.), (6.1), (6.2), (6.9)-(6.14)
    and the wire limits written out (Shigley Table 10-4: R_m = A/d^m; [tau] = 0.5 R_m; Goodman through Zimmerli's
    peened point, S_su = 0.67 R_m): (passing springs as (mass, D, d), number of candidates)."""
    material = options.materials[0]
    a, m = {"VDSiCr": (1974.0, 0.108), "VDCrV": (2005.0, 0.168)}[material.grade]
    g, rho, h = material.shear_modulus, material.density, line.lift
    low, high = options.ratio_range
    passing, count = [], 0
    for big_d in np.arange(np.ceil(options.diameter_range[0] * throat / options.diameter_step - 1e-9),
                           np.floor(options.diameter_range[1] * throat / options.diameter_step + 1e-9) + 1) \
            * options.diameter_step:
        for d in springs.wire_series(options.wire_range_mm, options.wire_step_mm):
            if not 3.0 <= big_d / d <= 12.0:
                continue
            count += 1
            rm = a / (d * 1e3) ** m * 1e6
            su = 0.67 * rm
            endurance = 398e6 / (1.0 - 534e6 / su)
            chi = float(np.interp(big_d / d, *springs.SHAPE_FACTOR_TABLE))
            exact = g * d**4 * line.max_deflection / (8.0 * line.max_force * big_d**3)
            coils = max(np.floor(2.0 * exact) / 2.0, 1.0)
            rate = g * d**4 / (8.0 * big_d**3 * coils)
            p_max = line.preload + rate * h
            tau_max = 8.0 * chi * p_max * big_d / (np.pi * d**3)
            tau_min = 8.0 * chi * line.preload * big_d / (np.pi * d**3)
            safety = endurance / ((tau_max - tau_min) / 2 + endurance / su * (tau_max + tau_min) / 2)
            omega_c1 = d / (big_d**2 * coils) * np.sqrt(g / (2.0 * rho))
            installed = d * 1.12 * (coils + 2.0) + d + h
            if (tau_max <= 0.5 * rm and safety >= material.min_safety and omega_c1 / omega >= 10.0 and exact >= 2.0
                    and low <= p_max / line.preload <= high and installed <= 6.0 * h):
                passing.append((rho * np.pi * d**2 / 4 * np.pi * big_d * (coils + 2.0), big_d, d))
    return passing, count


@pytest.mark.parametrize("grade", ["VDSiCr", "VDCrV"])
def test_vectorised_search_equals_brute_force(grade):
    """The array search picks the lightest of the candidates a Python loop over the same grid finds passing,
    and counts the same ones (a line the size of that of the appendix of Valve-train practical works (n.d.): 260 N + 52 N/mm over 10 mm, at 6000 rpm)."""
    line = springs.Characteristic(260.0, 52e3, 0.010)
    omega = SEED000_OMEGA_EXACT * 6000 / 7000
    options = springs.SpringOptions(materials=(springs.SpringMaterial(grade),), wire_range_mm=(3.0, 6.0),
                                    diameter_step=0.5e-3)
    best, n_pass, tried = springs.design_spring(line, 0.0368, omega, options)
    passing, count = _brute_force(line, 0.0368, omega, options)
    assert tried == count and count > 300 and passing
    assert n_pass == len(passing)
    mass, big_d, d = min(passing)
    assert (best.mass, best.mean_diameter, best.wire_diameter) == pytest.approx((mass, big_d, d), rel=1e-12)
    assert best.passes


def _every_candidate(preloads, rates, lift, throat, omega, options, material, **limits):
    """The exhaustive search the screen shortens: every line x D x d of the grid designed
    (:func:`valvetrain.springs.evaluate_springs` over the whole grid), as a (lines, grid) array of passes."""
    big_d, d = springs.search._grid(throat, options.diameter_range, options.diameter_step,
                             springs.wire_series(options.wire_range_mm, options.wire_step_mm))
    found = springs.evaluate_springs(np.asarray(preloads)[:, None], np.asarray(rates)[:, None], lift, big_d[None, :],
                                     d[None, :], material, omega, ratio_range=options.ratio_range, **limits)
    return found, big_d, d


@settings(max_examples=60, deadline=None)
@given(preload=st.floats(30.0, 900.0), lift=st.floats(0.004, 0.016),
       throat=st.floats(0.025, 0.06), rpm=st.floats(800.0, 8000.0), resonance=st.sampled_from([0.0, 6.0, 10.0]),
       grade=st.sampled_from(["60S2A", "VDSiCr", "VDCrV"]), longest=st.sampled_from([None, 4.0, 6.0]),
       safety=st.sampled_from([0.0, 1.1, 1.3, 1.6]))
def test_the_screen_keeps_every_passing_spring(preload, lift, throat, rpm, resonance, grade, longest, safety):
    """The bounds of the screen (:func:`valvetrain.springs.search._may_pass`) never drop a spring that passes: every
    candidate of the exhaustive search that passes every check lies inside the screen, for lines of every ratio,
    grades with and without the resonance and fatigue checks and installed-length limits."""
    omega = np.pi * rpm / 60.0
    ratios = springs.deflection_ratios()
    preloads, rates = np.full(ratios.size, preload), (ratios - 1.0) * preload / lift
    material = springs.SpringMaterial(grade, min_resonance_ratio=resonance, min_safety=safety)
    options = springs.SpringOptions(materials=(material,))
    high = None if longest is None else longest * lift
    found, big_d, d = _every_candidate(preloads, rates, lift, throat, omega, options, material,
                                       max_installed_length=high)
    passed = found.passed.reshape(ratios.size, d.size)
    keep = springs.search._may_pass(preloads, rates, lift, big_d, d, material, omega, high)
    assert not np.any(passed & ~keep)


@pytest.mark.parametrize("scale, passing", [(1.0, True), (5.0, False)])
def test_the_screened_search_finds_what_the_exhaustive_one_finds(scale, passing):
    """design_springs designs only the springs the screen keeps (or every spring when none of them passes): the
    spring chosen, the number passing and the number tried are those of the exhaustive search over every line of
    the requirement (the lightest passing candidate, first in grid order; else the best worst margin)."""
    law = seed000_law()
    omega = SEED000_OMEGA_EXACT * 6 / 7
    y, req = _requirement(law, 0.147)
    requirement = springs.Requirement(y, req * scale * (6 / 7) ** 2, springs.seat_load(0.147))
    material = springs.SpringMaterial("VDSiCr")
    options = springs.SpringOptions(materials=(material,))
    search = springs.design_springs(requirement, 0.0368, omega, options)
    preloads, rates = requirement.lines(options.ratio_range)
    found, _, _ = _every_candidate(preloads, rates, requirement.max_lift, 0.0368, omega, options, material,
                                   max_installed_length=6.0 * requirement.max_lift)
    n_pass = int(np.count_nonzero(found.passed))
    assert (n_pass > 0) == passing and search.passing == n_pass and search.tried == len(found)
    i = int(np.argmin(np.where(found.passed, found.mass, np.inf))) if passing else int(np.argmax(found.worst_margin))
    chosen = search.designs["spring"]
    assert (chosen.mean_diameter, chosen.wire_diameter, chosen.coils, chosen.characteristic.preload) == (
        found.mean_diameter[i], found.wire_diameter[i], found.coils[i], found.preload[i])
    assert chosen.passes == passing
    designed = sum(len(c) for c in springs.search._search(preloads, rates, requirement.max_lift, 0.0368, omega, options)[0])
    assert designed < len(found) / 10 if passing else designed == len(found)   # the screen's point


def test_design_picks_the_lightest_passing_spring():
    line = springs.Characteristic(150.0, 25e3, 0.009)
    options = springs.SpringOptions(materials=(springs.SpringMaterial(min_resonance_ratio=5.0),))
    best, n_pass, tried = springs.design_spring(line, 0.034, 300.0, options)
    assert n_pass > 0 and best.passes and tried >= n_pass
    # every lighter candidate of the search space fails a check
    for big_d in np.arange(0.7 * 0.034, 0.9 * 0.034, 0.5e-3):
        for d in springs.wire_series():
            s = springs.evaluate_spring(line, big_d, d, options.materials[0], 300.0, max_installed_length=0.054)
            if s is not None and s.mass < best.mass - 1e-12:
                assert not s.passes
    # the actual line (rounded coils) still envelops the required one
    assert best.characteristic.rate >= line.rate
    assert best.characteristic.preload == pytest.approx(line.preload)
    assert best.binding_check in best.checks


def test_a_zero_minimum_switches_a_check_off():
    """min_resonance_ratio = 0 is allowed (the check off): its margin is infinite, never a division by zero."""
    line = springs.Characteristic(150.0, 25e3, 0.009)
    s = springs.evaluate_spring(line, 0.03, 0.004, springs.SpringMaterial(min_resonance_ratio=0.0), 300.0)
    assert s.margins["resonance_ratio"] == np.inf
    assert s.binding_check != "resonance_ratio"


def test_array_checks_agree_with_the_check_records():
    """Pass and margin of every candidate's checks as arrays are those of the valvetrain.checks.Check records."""
    line = springs.Characteristic(270.0, 58e3, 0.010)
    found = springs.evaluate_springs(line.preload, line.rate, line.lift, np.linspace(0.02, 0.034, 29)[:, None],
                                     springs.wire_series((2.0, 7.0), 0.25)[None, :], springs.SpringMaterial("VDCrV"),
                                     SEED000_OMEGA_EXACT, max_installed_length=0.06)
    for i in range(len(found)):
        design = found.design(i)
        assert design.passes == found.passed[i]
        assert min(design.margins.values()) == pytest.approx(found.worst_margin[i], rel=1e-12)


def test_surge_frequency_is_bought_with_stress():
    """omega_c1 = pi tau_max / (chi f_max sqrt(2 rho G)), from (6.1), (6.2) and (6.13) with the actual (rounded)
    coils, for every candidate of a grid; so a resonance ratio needs a stress independent of d and D."""
    line = springs.Characteristic(270.0, 58e3, 0.010)
    material = springs.SpringMaterial("VDSiCr")
    found = springs.evaluate_springs(line.preload, line.rate, line.lift, np.linspace(0.02, 0.034, 15)[:, None],
                                     springs.wire_series()[None, :], material, SEED000_OMEGA_EXACT)
    ok = np.isfinite(found.shape_factor)
    f_max = (found.preload + found.rate * line.lift) / found.rate
    stress = springs.resonance_stress(found.resonance_ratio, SEED000_OMEGA_EXACT, f_max, found.shape_factor,
                                      material.shear_modulus, material.density)
    assert np.allclose(stress[ok], found.tau_max[ok], rtol=1e-12)


def test_resonance_needs_more_stress_than_60s2a_allows_at_7000_rpm():
    """Valve-train practical works (n.d.), corrections note 27 in numbers: at the speed (omega_cam = 366.5 rad/s) and lift (10 mm) of the appendix of Valve-train practical works (n.d.) a line of
    f_max/f_min <= 3.2 has f_max >= 14.545 mm; with chi >= 1.1 (D/d <= 12) the ratio 10 needs, by hand,
    10 x 366.52 x 1.1 x 0.014545 x sqrt(2 x 7850 x 8e10) / pi = 661.5 MPa, above [tau] = 500 MPa of 60S2A
    (Valve-train practical works (n.d.), work 6): no spring of the manual's steel can pass."""
    w = springs.stress_window(springs.SpringMaterial(), 0.010, SEED000_OMEGA_EXACT)
    assert w.deflection_ratio == pytest.approx(3.2)
    assert w.max_deflection == pytest.approx(0.010 * 3.2 / 2.2)
    assert w.needed / 1e6 == pytest.approx(661.5, abs=0.1)
    assert w.allowed == pytest.approx(500e6)
    tau = springs.fatigue_stress_limit(370e6, 0.2, 3.2, 1.3)
    assert tau / 1e6 == pytest.approx(2 * 370 / (1.3 * (1 - 1 / 3.2 + 0.2 * (1 + 1 / 3.2))), rel=1e-12)


def test_diagnosis_of_the_example_in_60s2a():
    """The appendix requirement (m_v 0.147 kg: the example's parts with its spring) with the manual's steel:
    no spring passes; the diagnosis names tau_max and the resonance ratio, shows the stress window of Valve-train practical works (n.d.), corrections note 27, and
    each remedy it proposes passes when tried (VDSiCr; a lower speed), while a lower mass does not help (the
    resonance ratio does not depend on the force)."""
    law = seed000_law()
    y, req = _requirement(law, 0.147)
    requirement = springs.Requirement(y, req, springs.seat_load(0.147))
    options = springs.SpringOptions()
    search = springs.design_springs(requirement, 0.0368, SEED000_OMEGA_EXACT, options)
    assert not search.passes and search.passing == 0
    d = springs.diagnose(requirement, 0.0368, SEED000_OMEGA_EXACT, options, search, np.pi * 7000 / 30)
    checks = {x.check for x in d.conflicts}
    assert {"tau_max", "resonance_ratio"} <= checks
    assert d.kind == diagnosis.RESONANCE_STRESS
    assert d.window.needed > d.window.allowed == pytest.approx(500e6)
    remedies = {x.change: x for x in d.helped}
    assert remedies["material"].value == "VDSiCr" and remedies["material"].key == "material"
    vdsicr = replace(options, materials=(springs.SpringMaterial("VDSiCr"),))
    assert springs.design_springs(requirement, 0.0368, SEED000_OMEGA_EXACT, vdsicr).passes
    f = remedies["rated_speed_factor"].value
    assert 0.3 < f < 1.0 and remedies["rated_speed_factor"].rated_speed == pytest.approx(np.pi * 7000 / 30 * f)
    assert remedies["rated_speed_factor"].key == "rated_speed_rpm"
    slower = springs.design_springs(requirement.scaled(f**2), 0.0368, SEED000_OMEGA_EXACT * f, options)
    assert slower.passes
    assert springs.Remedy("reduced_mass_factor", 0.1, False) in d.tried
    text = diagnosis_text(d, "en")
    assert "needs tau_max >= 662 MPa" in text and 'material = "VDSiCr"' in text


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


def test_installed_length_limits():
    """A given installed-length range is kept: a spring shorter than its lower end is installed there (the coils
    further apart), none longer than its upper end passes; without a range the limit is 6 x lift."""
    line = springs.Characteristic(270.0, 58e3, 0.010)
    material = springs.SpringMaterial("VDSiCr")
    free, _, _ = springs.design_spring(line, 0.0368, SEED000_OMEGA_EXACT,
                                       springs.SpringOptions(materials=(material,), installed_length_range=(None, None)))
    assert "installed_length" not in free.checks
    default, _, _ = springs.design_spring(line, 0.0368, SEED000_OMEGA_EXACT, springs.SpringOptions(materials=(material,)))
    assert default.checks["installed_length"].high == pytest.approx(0.060)
    natural = default.lengths["installed_length"]
    raised, n, _ = springs.design_spring(line, 0.0368, SEED000_OMEGA_EXACT, springs.SpringOptions(
        materials=(material,), installed_length_range=(natural + 5e-3, natural + 8e-3)))
    assert n > 0 and raised.lengths["installed_length"] >= natural + 5e-3 - 1e-12
    assert raised.checks["coil_gap_at_full_lift"].passed
    short, n, _ = springs.design_spring(line, 0.0368, SEED000_OMEGA_EXACT, springs.SpringOptions(
        materials=(material,), installed_length_range=(None, 0.030)))
    assert n == 0 and not short.checks["installed_length"].passed


def test_nested_pair_is_installed_together():
    """A pair (eqs. 5.10-5.14): one installed length, the inner spring inside the outer one with the radial gap,
    natural frequencies 10 % apart; both pass at 5000 rpm."""
    law = seed000_law()
    omega = SEED000_OMEGA_EXACT * 5 / 7
    y, req = _requirement(law, 0.147)
    requirement = springs.Requirement(y, req * (5 / 7) ** 2, springs.seat_load(0.147))
    options = springs.SpringOptions(materials=(springs.SpringMaterial("VDSiCr"),), count=2)
    search = springs.design_springs(requirement, 0.0368, omega, options)
    outer, inner = search.designs["outer"], search.designs["inner"]
    assert search.passes and search.passing > 0
    assert inner.lengths["installed_length"] == pytest.approx(outer.lengths["installed_length"], rel=1e-12)
    assert inner.mean_diameter + inner.wire_diameter <= outer.mean_diameter - outer.wire_diameter - 2e-3 + 1e-12
    assert abs(inner.natural_frequency / outer.natural_frequency - 1.0) >= 0.1
    assert inner.characteristic.preload == pytest.approx(0.4 / 0.6 * outer.characteristic.preload, rel=1e-12)


def test_spring_mass_and_reduced_masses():
    # rho (pi d^2 / 4) pi D i: 7850 * pi/4 * 0.004^2 * pi * 0.03 * 8
    assert masses.spring_mass(0.03, 0.004, 8, 7850.0) == pytest.approx(7850 * np.pi**2 / 4 * 16e-6 * 0.03 * 8)
    m_v = masses.reduced_mass_at_valve(0.05, 0.02, 0.005, 0.045, 0.06, 0.04, 4e-5, 0.04, 1.6)
    # (5.2) term by term; (7.2) = (5.2) x i_k^2
    assert m_v == pytest.approx(0.05 + 0.02 + 0.005 + 0.015 + 4e-5 / 0.04**2 + 0.1 / 1.6**2)
    assert masses.reduced_mass_at_tappet(m_v, 1.6) == pytest.approx(
        0.06 + 0.04 + 4e-5 / 0.025**2 + (0.05 + 0.02 + 0.005 + 0.015) * 1.6**2)


def test_wire_grades():
    """60S2A is the manual's steel with the middle of its ranges (Valve-train practical works (n.d.), work 6); the VD grades follow
    Shigley Table 10-4 (R_m = A/d^m), Table 10-6 ([tau] = 0.5 R_m) and section 10-9 (S_su = 0.67 R_m, Goodman
    line through Zimmerli's peened point): the manual's n of eq. (6.12) is 1 exactly at that point
    (tau_m = 534 MPa, tau_a = 398 MPa, i.e. tau_max = 932 MPa, tau_min = 136 MPa) for every wire."""
    seed = springs.SpringMaterial()
    allowable, endurance, psi = seed.limits(np.array([2.8e-3, 6e-3]))
    assert (seed.shear_modulus, seed.density) == (8e10, 7850.0)
    assert np.all(allowable == 500e6) and np.all(endurance == 370e6) and np.all(psi == 0.2)
    d = springs.wire_series()
    for grade, a, m in (("VDSiCr", 1974.0, 0.108), ("VDCrV", 2005.0, 0.168)):
        material = springs.SpringMaterial(grade)
        assert material.shear_modulus == 79.5e9
        allowable, endurance, psi = material.limits(d)
        rm = a / (d * 1e3) ** m * 1e6
        assert np.allclose(allowable, 0.5 * rm, rtol=1e-12)
        assert np.allclose(springs.fatigue_safety(932e6, 136e6, endurance, psi), 1.0, rtol=1e-12)
        # a thinner wire is stronger: a higher [tau]; the Goodman line through the fixed point then runs flatter
        assert np.all(np.diff(allowable) < 0) and np.all(np.diff(psi) > 0)
    # chrome-silicon is the stronger wire, by 7 % at 4 mm: 1974/4^0.108 against 2005/4^0.168
    assert spring_materials.GRADES["VDSiCr"].tensile_strength(4e-3) / 1e6 == pytest.approx(1699.5, abs=0.1)
    assert spring_materials.GRADES["VDCrV"].tensile_strength(4e-3) / 1e6 == pytest.approx(1588.4, abs=0.1)


def test_a_property_given_replaces_the_grade_s():
    material = springs.SpringMaterial("vd-sicr", shear_modulus=8.1e10, allowable_stress=600e6)
    assert material.grade == "VDSiCr" and material.shear_modulus == 8.1e10
    allowable, endurance, _ = material.limits(np.array([3e-3, 5e-3]))
    assert np.all(allowable == 600e6) and endurance[0] < endurance[1]
    with pytest.raises(KeyError, match="allowed '60S2A', 'VDSiCr', 'VDCrV'"):
        springs.SpringMaterial("65G")


def _with_spring(section):
    """The built-in example with ``section`` as its [valves.intake.spring] table."""
    from valvetrain.specification import parse_spec

    text = appendix_text()
    start, end = text.index("[valves.intake.spring]"), text.index("[valves.intake.parts]")
    return parse_spec(text[:start] + "[valves.intake.spring]\n" + section + "\n\n" + text[end:])


def test_spring_keys_of_the_specification():
    """material names a grade (or several, all searched); a property key replaces the grade's value; the wire
    range, installed length and seat load are keys; a name or range that admits no spring is refused."""
    from valvetrain.design import run
    from valvetrain.design.drive import spring_options
    from valvetrain.specification import SpecError, si

    both = _with_spring('material = ["VD-SiCr", "vdcrv"]\nallowable_stress_MPa = 700.0\n'
                        'wire_diameter_range_mm = [3.0, 6.0]\nmin_preload_N = 300.0\ninstalled_length_mm = [45.0, 52.0]')
    options = spring_options(si(both.valves["intake"].spring))
    assert [m.grade for m in options.materials] == ["VDSiCr", "VDCrV"]
    assert all(m.allowable_stress == 700e6 for m in options.materials)
    assert options.wire_range_mm == (3.0, 6.0) and options.installed_length_range == pytest.approx((0.045, 0.052))
    spring = run(both).to_dict()["valves"]["intake"]["spring"]
    assert spring["preload_N"] == pytest.approx(300.0) and spring["preload_set_by_seat_load"]
    assert 45.0 - 1e-9 <= spring["installed_length_mm"] and 3.0 <= spring["wire_mm"] <= 6.0
    assert spring["margins"]["tau_max"] == pytest.approx(1.0 - spring["tau_max_MPa"] / 700.0)
    with pytest.raises(SpecError, match=r"material = '65G': allowed '60S2A', 'VDSiCr', 'VDCrV'"):
        _with_spring('material = "65G"')
    with pytest.raises(SpecError, match=r"installed_length_mm = \[5.0, 9.0\]: the spring must be longer than the "
                                        r"valve lift max_lift_mm = 10"):
        _with_spring('material = "VDSiCr"\ninstalled_length_mm = [5.0, 9.0]')
