"""Valve spring characteristic and spring design (seed 000, works 5 and 6).

SI units inside: N, m, Pa, kg, rad/s.  The characteristic is written against the valve
lift y: P(y) = P_min + C y (eq. 5.6).
"""

from dataclasses import dataclass, field

import numpy as np

from .checks import check
from .masses import spring_mass

SPRING_RESERVE_RANGE = (1.5, 2.25)
"""Spring reserve factor K_z (seed 000, eq. 5.3)."""

DEFLECTION_RATIO_RANGE = (1.6, 3.2)
"""f_max / f_min (seed 000, work 5; 2 is the optimum)."""

INNER_SHARE_RANGE = (0.35, 0.45)
"""Share of the force taken by the inner spring of a nested pair (seed 000, work 5)."""

WIRE_SERIES_MM = (2.8, 3.0, 3.5, 3.8, 4.0, 4.2, 4.5, 4.8, 5.0, 5.5, 6.0)
"""Valve-spring wire diameters [mm] (seed 000, work 6)."""

SHAPE_FACTOR_TABLE = (np.array([3, 4, 5, 6, 7, 8, 9, 10, 11, 12], dtype=float),
                      np.array([1.5, 1.38, 1.3, 1.23, 1.2, 1.17, 1.15, 1.13, 1.11, 1.1]))
"""Spring index D/d and shape factor chi (seed 000, work 6, table of eq. 6.1)."""


class NoSpringFits(ValueError):
    """No spring of the wire series can be wound within the given diameters."""


def feasible_mean_diameters(wire_series_mm=WIRE_SERIES_MM):
    """Mean diameters D [m] some wire of the series can make: D/d within the shape-factor table (3...12)."""
    index = SHAPE_FACTOR_TABLE[0]
    return index[0] * min(wire_series_mm) * 1e-3, index[-1] * max(wire_series_mm) * 1e-3


MEAN_DIAMETER_RANGE = (0.7, 0.9)
"""Spring mean diameter / valve throat diameter (seed 000, work 6)."""

RESONANCE_RATIO_MIN = 10.0
"""omega_c1 / omega_cam (seed 000, eq. 6.14)."""


def required_spring_force(mass_at_valve, valve_acceleration, reserve):
    """Spring force that keeps the train on the cam, K_z m_v |j_v| where j_v < 0, else 0 [N].

    Parameters
    ----------
    mass_at_valve : float
        Reduced mass at the valve m_v [kg].
    valve_acceleration : ndarray
        Valve acceleration j_v = i_k j_T [m/s^2].
    reserve : float
        Spring reserve factor K_z.

    Notes
    -----
    :math:`P_j = m_v j_v` (5.1), :math:`P_{spr} = K_z P_j` (5.3) over the negative-acceleration part.

    References
    ----------
    seed 000, work 5, eqs. (5.1), (5.3).
    """
    return reserve * mass_at_valve * np.clip(-np.asarray(valve_acceleration, dtype=float), 0.0, None)


def enveloping_line(lift, required, ratio_range=DEFLECTION_RATIO_RANGE, min_preload=0.0):
    """The tightest straight spring characteristic above a required spring-force curve.

    Parameters
    ----------
    lift : ndarray
        Valve lift y [m] at the points of the curve.
    required : ndarray
        Required spring force at those lifts [N].
    ratio_range : (float, float)
        Allowed f_max / f_min = P_max / P_min (seed 000, work 5: usually 1.6...3.2).
    min_preload : float
        Smallest preload [N]: the gas force that tends to open the closed valve
        (eqs. 5.4-5.5); the manual raises P_min to meet it.

    Returns
    -------
    (float, float)
        Preload P_min [N] and rate C [N/m] of the line P(y) = P_min + C y.

    Notes
    -----
    The manual replaces the curve a'b'c' of required force against valve lift by a
    straight line a''c'' drawn by hand (seed 000, work 5, Fig. 5.1).  Here the line is
    the one with the smallest maximum force P_max = P_min + C h (the spring's largest
    stress) among the lines that

    * stay on or above the requirement at every point, :math:`P_{min} + C y_i \\ge P_i`;
    * keep the deflection ratio in the usual range, :math:`r_1 P_{min} \\le P_{min} + C h \\le r_2 P_{min}`;
    * hold the valve closed against the gas force, :math:`P_{min} \\ge P_g`.

    This is a linear programme in (P_min, C), solved here in closed form.  Written with
    the ratio r = P_max / P_min and u_i = y_i / h, a line of ratio r above the requirement
    has :math:`P_{max} \\ge \\max_i r P_i / (1 + (r - 1) u_i)` (and :math:`\\ge r P_g`);
    every term grows with r, so the smallest P_max is
    :math:`P^* = \\max(\\max_i r_1 P_i / (1 + (r_1 - 1) u_i), r_1 P_g)`, reached by every
    ratio up to :math:`r^* = \\min(r_2, \\min_{P_i > P^* u_i} P^* (1 - u_i) / (P_i - P^* u_i),
    P^* / P_g)`.  Of these optimal lines the steepest, r*, is taken: where the ratio bound
    is slack it is the steepest line through the full-lift point c' that stays above the
    curve (the reading of the graphical construction in spec/valvetrain-works-1-8.md,
    work 5); a polydyne cam, whose requirement is flat at the nose, gets the line of the
    smallest allowed ratio.  The line touches the requirement at least once, or sits on
    the gas force.

    References
    ----------
    seed 000, work 5, eqs. (5.3)-(5.9) and Fig. 5.1.

    Examples
    --------
    A requirement proportional to lift, 10 N/mm up to 2 mm: the ratio bound 3.2 binds,
    P_min = 20/3.2 N and the line touches at full lift.

    >>> p0, c = enveloping_line(np.array([0.0, 1.0, 2.0]), np.array([0.0, 10.0, 20.0]))
    >>> round(p0, 6), round(c, 6)
    (6.25, 6.875)
    """
    y = np.asarray(lift, dtype=float)
    p = np.asarray(required, dtype=float)
    h = float(y.max())
    u = y / h
    r1, r2 = ratio_range
    gas = max(min_preload, 0.0)
    p_max = max(float(np.max(r1 * p / (1.0 + (r1 - 1.0) * u))), r1 * gas)
    if p_max <= 0.0:
        return 0.0, 0.0
    excess = p - p_max * u
    bounds = [r2, *(p_max * (1.0 - u[excess > 0.0]) / excess[excess > 0.0])] + ([p_max / gas] if gas > 0.0 else [])
    ratio = max(min(bounds), r1)
    preload = p_max / ratio
    return float(preload), float((ratio - 1.0) * preload / h)


def gas_opening_force(throat_diameter, port_pressure, cylinder_pressure):
    """Gas force that tends to open a closed valve, f_g (p_port - p_cyl), zero if negative [N].

    Parameters
    ----------
    throat_diameter : float
        Throat diameter of the valve [m].
    port_pressure : float
        Absolute pressure behind the valve head in the port [Pa]: exhaust manifold p_tr
        for an exhaust valve (5.4), boost p_k for an inlet valve (5.5).
    cylinder_pressure : float
        Absolute cylinder pressure at the same time [Pa]: p_a during intake (5.4), p_r
        during the exhaust stroke (5.5, E19).

    References
    ----------
    seed 000, work 5, eqs. (5.4), (5.5).

    Examples
    --------
    An exhaust valve of 31 mm throat, p_tr = 0.106 MPa, p_a = 0.085 MPa: 15.85 N.

    >>> round(gas_opening_force(0.031, 0.106e6, 0.085e6), 2)
    15.85
    """
    return float(max(np.pi * throat_diameter**2 / 4.0 * (port_pressure - cylinder_pressure), 0.0))


@dataclass(frozen=True)
class Characteristic:
    """A straight spring characteristic at the valve, P(y) = preload + rate y (seed 000, eqs. 5.6-5.9)."""

    preload: float     # P_min [N]
    rate: float        # C [N/m]
    lift: float        # valve lift h [m]

    @property
    def max_force(self):
        """P_max = P_min + C h [N] (5.7)."""
        return self.preload + self.rate * self.lift

    @property
    def preload_deflection(self):
        """f_min = P_min / C [m] (5.8)."""
        return self.preload / self.rate

    @property
    def max_deflection(self):
        """f_max = P_max / C = f_min + h [m] (5.9)."""
        return self.max_force / self.rate

    def force(self, y):
        """Spring force at valve lift y [N]."""
        return self.preload + self.rate * np.asarray(y)

    def split(self, share):
        """(outer, inner) characteristics of a nested pair, the inner taking ``share`` of the force (5.10)-(5.14)."""
        inner = Characteristic(share * self.preload, share * self.rate, self.lift)
        outer = Characteristic(self.preload - inner.preload, self.rate - inner.rate, self.lift)
        return outer, inner


def shape_factor_table(index):
    """Shape factor chi from the manual's table, linear interpolation in D/d (seed 000, work 6, eq. 6.1).

    >>> round(float(shape_factor_table(5.5)), 6)
    1.265
    """
    return np.interp(index, *SHAPE_FACTOR_TABLE, left=np.nan, right=np.nan)


def wahl_factor(index):
    """Wahl's curvature and direct-shear factor, (4c - 1)/(4c - 4) + 0.615/c.

    Engineering literature (A. M. Wahl, Mechanical Springs, 1944); printed beside the
    manual's table, which lies below it by 5 % at D/d = 3 and by under 2 % from 4 to 12.

    >>> round(float(wahl_factor(6.0)), 4)
    1.2525
    """
    c = np.asarray(index, dtype=float)
    return (4.0 * c - 1.0) / (4.0 * c - 4.0) + 0.615 / c


def shear_stress(force, mean_diameter, wire_diameter, factor):
    """Maximum shear stress in the wire, tau = 8 chi P D / (pi d^3) [Pa] (seed 000, eq. 6.1)."""
    return 8.0 * factor * force * mean_diameter / (np.pi * wire_diameter**3)


def active_coils(shear_modulus, wire_diameter, max_deflection, max_force, mean_diameter):
    """Working coils i_p = G d^4 f_max / (8 P_max D^3) (seed 000, eq. 6.2).

    Examples
    --------
    V. B. Bhandari, Design of Machine Elements, Example 11.1 (G = 81370 MPa, d = 7 mm,
    deflection 30 mm at 1250 N, D = 42 mm): 7.91 coils.

    >>> round(active_coils(81370e6, 7e-3, 30e-3, 1250.0, 42e-3), 2)
    7.91
    """
    return shear_modulus * wire_diameter**4 * max_deflection / (8.0 * max_force * mean_diameter**3)


def spring_rate(shear_modulus, wire_diameter, mean_diameter, coils):
    """Rate of a helical spring, C = G d^4 / (8 D^3 i_p) [N/m] (inverse of eq. 6.2)."""
    return shear_modulus * wire_diameter**4 / (8.0 * mean_diameter**3 * coils)


def natural_frequency(wire_diameter, mean_diameter, coils, shear_modulus, density):
    """First natural (surge) frequency of a spring fixed at both ends, omega_c1 [rad/s].

    Notes
    -----
    .. math:: \\omega_{c1} = \\frac{d}{D^2 i_p}\\sqrt{\\frac{G}{2\\rho}}

    which is the manual's 10^6 d/(D^2 i_p) sqrt(G/(2 rho)) with d, D in mm and G in MPa.

    References
    ----------
    seed 000, work 6, eq. (6.13), reading [A] of spec/valvetrain-works-1-8.md section 6
    (the alternative reading is 4.44 times smaller); agrees within 1.2 % with Kolchin's
    n_c = 2.17e7 d/(i_p D^2) min^-1.
    """
    return wire_diameter / (mean_diameter**2 * coils) * np.sqrt(shear_modulus / (2.0 * density))


def fatigue_safety(tau_max, tau_min, endurance, mean_stress_factor):
    """Fatigue safety factor n = tau_-1 / (tau_a + psi_tau tau_m) (seed 000, eqs. 6.9-6.12).

    The manual defines no mean-stress coefficient psi_tau (E24); 0.1-0.2 is usual in the
    engineering literature, and the design takes it from the specification.
    """
    tau_m = 0.5 * (tau_max + tau_min)
    tau_a = 0.5 * (tau_max - tau_min)
    return endurance / (tau_a + mean_stress_factor * tau_m)


def spring_lengths(wire_diameter, coils, lift, preload_deflection, gap_factor, end_coils=2, installed_length=None):
    """Pitches and lengths of a valve spring (seed 000, eqs. 6.3-6.8).

    Parameters
    ----------
    installed_length : float, optional
        Imposed installed length l_0 [m] (the inner spring of a nested pair sits between
        the same seat and retainer as the outer one); l_min = l_0 - h then, and t_min
        follows from (6.4).

    Returns
    -------
    dict
        ``min_pitch`` t_min = d + Delta_min (6.3); ``min_length`` (valve fully open)
        l_min = t_min (i_p + 2) + d (i_0 - 1) (6.4, reading [A]); ``installed_length``
        l_0 = l_min + h (6.5); ``installed_pitch`` t_0 (6.6); ``free_length``
        l_free = l_0 + f_min (6.7); ``free_pitch`` t_free (6.8) [m].
    """
    d = wire_diameter
    if installed_length is None:
        t_min = d * (1.0 + gap_factor)
        l_min = t_min * (coils + 2.0) + d * (end_coils - 1.0)
    else:
        l_min = installed_length - lift
        t_min = (l_min - d * (end_coils - 1.0)) / (coils + 2.0)
    l_0 = l_min + lift
    l_free = l_0 + preload_deflection
    return {"min_pitch": t_min, "min_length": l_min, "installed_length": l_0,
            "installed_pitch": (l_0 - d * (end_coils - 1.0)) / (coils + 2.0), "free_length": l_free,
            "free_pitch": (l_free - d * (end_coils - 1.0)) / (coils + 2.0)}


@dataclass(frozen=True)
class SpringMaterial:
    """Material and design limits of a valve spring (SI)."""

    shear_modulus: float = 8.0e10        # G, 7.6-8.2e4 MPa (seed 000, work 6)
    density: float = 7850.0              # rho, 7800-7900 kg/m^3
    allowable_stress: float = 500e6      # [tau], 350-600 MPa
    endurance_limit: float = 370e6       # tau_-1, 340-400 MPa
    mean_stress_factor: float = 0.2      # psi_tau (literature; not in the manual, E24)
    min_safety: float = 1.3              # n >= 1.2-1.4
    min_resonance_ratio: float = RESONANCE_RATIO_MIN
    gap_factor: float = 0.12             # Delta_min / d, 0.10-0.15
    end_coils: float = 2.0               # i_0


@dataclass
class SpringDesign:
    """One helical spring: geometry, loads and every check (SI)."""

    mean_diameter: float
    wire_diameter: float
    coils: float
    characteristic: Characteristic       # the actual line with the rounded coils
    shape_factor: float                  # chi from the table
    wahl: float                          # Wahl factor, for comparison
    tau_max: float
    tau_min: float
    safety: float
    natural_frequency: float             # omega_c1 [rad/s]
    resonance_ratio: float
    lengths: dict
    mass: float
    checks: dict = field(default_factory=dict)   # name -> valvetrain.checks.Check

    @property
    def margins(self):
        """Relative margin of each check: >= 0 passes (value/limit - 1 for a minimum, 1 - value/limit for a
        maximum; +inf for a check switched off by a zero minimum)."""
        return {k: c.margin for k, c in self.checks.items()}

    @property
    def passes(self):
        return all(c.passed for c in self.checks.values())

    @property
    def binding_check(self):
        """The check with the smallest margin."""
        return min(self.margins, key=self.margins.get)


def _minimum(limit):
    """A lower bound of a check, or None where a zero minimum switches the check off."""
    return limit if limit > 0.0 else None


def evaluate_spring(required, mean_diameter, wire_diameter, material, camshaft_speed, installed_length=None):
    """Design one spring of given diameters for a required characteristic.

    The working coils from (6.2) are rounded **down** to a multiple of 0.5 (at least 1):
    the spring gets slightly stiffer, and with the preload kept the actual line stays
    above the required one (the envelope property is preserved).

    Returns
    -------
    SpringDesign or None
        None when the spring index D/d is outside the manual's table (3...12).
    """
    index = mean_diameter / wire_diameter
    chi = float(shape_factor_table(index))
    if not np.isfinite(chi):
        return None
    exact = active_coils(material.shear_modulus, wire_diameter, required.max_deflection, required.max_force,
                         mean_diameter)
    coils = max(np.floor(exact * 2.0) / 2.0, 1.0)
    rate = spring_rate(material.shear_modulus, wire_diameter, mean_diameter, coils)
    actual = Characteristic(required.preload, rate, required.lift)
    tau_max = shear_stress(actual.max_force, mean_diameter, wire_diameter, chi)
    tau_min = shear_stress(actual.preload, mean_diameter, wire_diameter, chi)
    safety = fatigue_safety(tau_max, tau_min, material.endurance_limit, material.mean_stress_factor)
    omega = natural_frequency(wire_diameter, mean_diameter, coils, material.shear_modulus, material.density)
    lengths = spring_lengths(wire_diameter, coils, required.lift, actual.preload_deflection, material.gap_factor,
                             material.end_coils, installed_length)
    mass = float(spring_mass(mean_diameter, wire_diameter, coils + material.end_coils, material.density))
    checks = {
        "tau_max": check("tau_max", tau_max, high=material.allowable_stress, unit="MPa", severity="failure",
                         source="seed 000, eq. (6.1): [tau] = 350-600 MPa"),
        "fatigue_safety": check("fatigue safety factor", safety, low=_minimum(material.min_safety), severity="failure",
                                source=f"seed 000, eq. (6.12) with psi_tau = {material.mean_stress_factor:g}: "
                                       "n >= 1.2-1.4"),
        "resonance_ratio": check("resonance ratio omega_c1/omega_cam", omega / camshaft_speed,
                                 low=_minimum(material.min_resonance_ratio),
                                 source="seed 000, eq. (6.14): >= 10 (hard to meet at high speed, E27)"),
        "working_coils": check("working coils", exact, low=2.0, source="seed 000, eq. (6.2)"),
    }
    if installed_length is not None:
        checks["coil_gap_at_full_lift"] = check("coil gap at full lift / wire diameter",
                                                lengths["min_pitch"] / wire_diameter - 1.0, low=material.gap_factor,
                                                source="seed 000, eq. (6.3): Delta_min = 0.10-0.15 d")
    return SpringDesign(mean_diameter, wire_diameter, coils, actual, chi, float(wahl_factor(index)), tau_max, tau_min,
                        safety, omega, omega / camshaft_speed, lengths, mass, checks)


def design_spring(required, throat_diameter, material, camshaft_speed, diameter_range=MEAN_DIAMETER_RANGE,
                  max_outer=None, wire_series_mm=WIRE_SERIES_MM, diameter_step=0.5e-3, extra_check=None,
                  installed_length=None):
    """Choose the lightest spring of the wire series that passes every check.

    Parameters
    ----------
    required : Characteristic
        The required line at the valve.
    throat_diameter : float
        Valve throat diameter d_g [m]; mean diameters from ``diameter_range`` x d_g.
    material : SpringMaterial
    camshaft_speed : float
        omega_cam [rad/s] for the resonance ratio (6.14).
    max_outer : float, optional
        Largest outside diameter D + d [m] (the inner spring of a nested pair).
    diameter_step : float
        Step of the mean diameters tried [m].
    extra_check : callable, optional
        ``extra_check(design) -> dict`` of further checks ``name -> Check``.
    installed_length : float, optional
        Imposed installed length [m] (inner spring of a nested pair); the coils must then
        keep their minimum gap at full lift.

    Returns
    -------
    (SpringDesign, int)
        The lightest spring passing every check or, when none does, the one whose worst
        margin is best; and the number of candidates that passed.

    References
    ----------
    seed 000, work 6 (D = 0.7-0.9 d_g, wire series 2.8-6.0 mm, checks (6.1), (6.12), (6.14)).
    """
    lo, hi = diameter_range[0] * throat_diameter, diameter_range[1] * throat_diameter
    diameters = np.arange(np.ceil(lo / diameter_step), np.floor(hi / diameter_step) + 1) * diameter_step
    candidates = []
    for D in diameters:
        for d_mm in wire_series_mm:
            d = d_mm * 1e-3
            if max_outer is not None and D + d > max_outer:
                continue
            s = evaluate_spring(required, D, d, material, camshaft_speed, installed_length)
            if s is None:
                continue
            if extra_check is not None:
                s.checks.update(extra_check(s))
            candidates.append(s)
    if not candidates:
        low, high = feasible_mean_diameters(wire_series_mm)
        inside = f" inside the outer spring (outside diameter <= {max_outer * 1e3:.1f} mm)" if max_outer else ""
        raise NoSpringFits(f"no spring of the wire series fits{inside} with D in {lo * 1e3:.1f}...{hi * 1e3:.1f} mm; "
                           f"the series makes D = {low * 1e3:g}...{high * 1e3:g} mm (index 3...12)")
    passing = [s for s in candidates if s.passes]
    if passing:
        return min(passing, key=lambda s: s.mass), len(passing)
    return max(candidates, key=lambda s: min(s.margins.values())), 0
