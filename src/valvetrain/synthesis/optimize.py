"""A first cam synthesis by optimisation: the power-polynomial cam's parameters that maximise the fullness.

The variables are the cam keys a_qd (``peak_acceleration_mm_per_rad2``), phi_1 (``phi1_deg``), x_d
(``peak_position``) and x_g (``trough_position``) of a ``law = "power_polynomial"`` cam; the lift, the
ramp and the timing stay as the specification gives them.  The objective is the fullness of the tappet
lift over the valve-open part; the constraints are those of :class:`~.constraints.Limits`, evaluated
here on the law alone (the profile on a grid, the starting design's spring and reduced mass held fixed,
as a cam is synthesised for a given train), and checked at the end on the full design of the optimum
with :func:`~.constraints.constraints`.

Search: :func:`scipy.optimize.differential_evolution` over the bounds with the constraints' margins as
nonlinear constraints, then a local polish with SLSQP from its best point (kept when it is feasible and
better), as the seed article of the method does (UkrSURT Proceedings (2019); Shang Hanji (1988), section 4.3).
"""

from dataclasses import dataclass, field, replace
import time
import tomllib

import numpy as np
from scipy import optimize

from ..design import run as run_design
from ..laws import PolydyneLaw, PowerPolynomialLaw
from ..units import DEG, MM
from .constraints import Limits, constraints, spring_reserve

VARIABLES = ("peak_acceleration_mm_per_rad2", "phi1_deg", "peak_position", "trough_position")
"""The cam keys the optimiser varies."""

POSITION_BOUNDS = (0.02, 0.98)
"""Bounds of x_d and x_g: a peak at the very end of its part is a step of the acceleration."""

GRID = 1201
"""Camshaft angles of the opening flank on which the fast evaluation samples the profile."""


class Problem:
    """The fast evaluation of one valve's power-polynomial cam: fullness and constraint margins of the variables.

    Parameters
    ----------
    design : ValveDesign
        The starting design (its law gives the lift, ramp and angle; its drive the spring and the mass).
    limits : Limits
    """

    def __init__(self, design, limits):
        law = design.law
        if not isinstance(law, PowerPolynomialLaw):
            raise ValueError(f"optimize: the cam of valve {design.name!r} has law = {law.name!r}; this first "
                             "optimiser varies a law = \"power_polynomial\" cam")
        self.law0, self.limits = law, limits
        self.heel, self.follower, self.roller = design.heel_radius, design.follower, design.roller_radius
        self.omega, self.i_k = design.omega_cam, design.rocker_ratio
        self.mass = design.drive.masses.at_valve
        self.spring = design.drive.lines["chosen"]
        half = np.degrees(law.main_half_angle)
        self.bounds = [(10.0, 600.0), (2.0, 0.9 * half), POSITION_BOUNDS, POSITION_BOUNDS]
        self.evaluations = 0
        self.seconds = 0.0
        self._cache = (None, None)

    def law(self, x):
        """The law of the variables x (keys' units), or None where they admit no cam."""
        L = self.law0
        try:
            return PowerPolynomialLaw(L.lift_max, L.main_half_angle, L.ramp_height, L.ramp_angle, L.v_qb, x[0] * MM,
                                      x[1] * DEG, x[2], x[3], L.exponents, L.reconstruction, L.sharpness)
        except ValueError:
            return None

    def margin_names(self):
        """Names of the entries of :meth:`evaluate`'s margins."""
        names = ["spring reserve"]
        if self.follower == "roller":
            names += ["pressure angle"] + (["concave radius"] if self.limits.grinding_wheel_radius else [])
        elif self.limits.min_rho is not None:
            names.append("rho_min")
        if self.limits.max_acceleration is not None:
            names.append("max acceleration")
        if self.limits.min_acceleration is not None:
            names.append("min acceleration")
        return names

    def evaluate(self, x):
        """(fullness, margins) of the variables; a law that cannot be made has fullness 0 and margins -1."""
        key = tuple(float(v) for v in x)
        if self._cache[0] == key:
            return self._cache[1]
        t0 = time.perf_counter()
        self.evaluations += 1
        n = len(self.margin_names())
        law = self.law(x)
        if law is None:
            out = (0.0, -np.ones(n))
        else:
            out = (law.fullness(), self._margins(law))
        self.seconds += time.perf_counter() - t0
        self._cache = (key, out)
        return out

    def _margins(self, law):
        L = self.limits
        theta = np.unique(np.concatenate([np.linspace(law.start, 0.0, GRID), law.breakpoints[law.breakpoints <= 0]]))
        h, dh, d2h, _ = law.derivatives(theta)
        y = self.i_k * np.clip(h - law.ramp_height, 0.0, None)
        inertia = self.mass * self.i_k * self.omega**2 * np.clip(-d2h, 0.0, None)
        loaded = (inertia > 0.0) & (y > 0.0)
        reserve = np.min(self.spring.force(y[loaded]) / inertia[loaded]) if np.any(loaded) else 10.0
        out = [(reserve - L.min_spring_reserve) / L.min_spring_reserve]
        _, rho, beta, _ = law.profile(theta, self.heel, self.follower, self.roller)
        if self.follower == "roller":
            out.append((L.max_pressure_angle - np.max(np.abs(beta))) / L.max_pressure_angle)
            if L.grinding_wheel_radius:
                curvature = np.min(1.0 / rho)
                out.append(1.0 - L.grinding_wheel_radius * max(-curvature, 0.0))
        elif L.min_rho is not None:
            out.append((np.min(rho) - L.min_rho) / L.min_rho)
        a = self.omega**2 * d2h
        if L.max_acceleration is not None:
            out.append((L.max_acceleration - a.max()) / L.max_acceleration)
        if L.min_acceleration is not None:
            out.append((a.min() - L.min_acceleration) / abs(L.min_acceleration))
        return np.array(out, dtype=float)


@dataclass
class Result:
    """An optimisation: the variables and responses at the start and at the optimum, and the cost."""

    valve: str
    start: dict
    optimum: dict
    start_fullness: float
    fullness: float
    margins: dict
    evaluations: int
    seconds: float
    seconds_in_evaluations: float
    polydyne_fullness: float = float("nan")
    spec_text: str = field(repr=False, default="")
    checks: list = field(repr=False, default_factory=list)


def polydyne_fullness(law, exponents=(10, 18, 26, 34)):
    """Fullness of the polydyne (2, p, q, r, s) with the same lift, cosine ramp of the same height and end velocity
    and the same main angle as a power-polynomial ``law``, on the same definition (tappet lift over the valve-open
    part): the serial-type reference of the comparison.

    References
    ----------
    Valve-train practical works (n.d.), work 3 (the polydyne); UkrSURT Proceedings (2019) (the comparison).
    """
    poly = PolydyneLaw(law.lift_max, law.main_half_angle, *exponents, ramp_height=law.ramp_height,
                       ramp_velocity=law.v_qb)
    phi = np.linspace(poly.valve_opens, poly.valve_closes, 20001)
    lift = poly.lift(phi)
    area = float(np.sum((lift[1:] + lift[:-1]) * np.diff(phi)) / 2.0)
    return area / ((poly.lift_max + poly.ramp_height) * (phi[-1] - phi[0]))


def optimize_valve(spec, valve=None, limits=None, seed=1, maxiter=60, popsize=12, progress=None):
    """Maximise the fullness of one valve's power-polynomial cam under the limits.

    Parameters
    ----------
    spec : valvetrain.specification.Spec
    valve : str, optional
        The valve's name (default: the first with a power-polynomial cam).
    limits : Limits, optional
        Default :meth:`Limits.article` with the spring reserve of the valve's ``drive.spring_reserve``.
    seed, maxiter, popsize : int
        Of :func:`scipy.optimize.differential_evolution` (deterministic for a seed).
    progress : callable, optional
        ``progress(generation, best fullness)`` after each generation.

    Returns
    -------
    Result
        With ``spec_text``, the specification with the optimum's cam keys (TOML), and ``checks``, the
        constraints on the full design of the optimum.
    """
    t0 = time.perf_counter()
    start = run_design(spec)
    if valve is None:
        valve = next((n for n, v in start.valves.items() if v.law.name == "power_polynomial"), None)
        if valve is None:
            raise ValueError("optimize: no valve has a law = \"power_polynomial\" cam")
    design = start.valves[valve]
    if limits is None:
        limits = Limits.article(min_spring_reserve=spec.valves[valve].drive.spring_reserve)
    problem = Problem(design, limits)
    cam = spec.valves[valve].cam
    x0 = np.array([getattr(cam, k) for k in VARIABLES], dtype=float)

    def objective(x):
        return -problem.evaluate(x)[0]

    def margins(x):
        return problem.evaluate(x)[1]

    constraint = optimize.NonlinearConstraint(margins, 0.0, np.inf)
    generation = [0]

    def callback(xk, convergence=None):
        generation[0] += 1
        if progress is not None:
            progress(generation[0], -objective(xk))

    found = optimize.differential_evolution(objective, problem.bounds, constraints=(constraint,), seed=seed,
                                            maxiter=maxiter, popsize=popsize, tol=1e-7, polish=False,
                                            callback=callback, init="sobol")
    best = found.x
    local = optimize.minimize(objective, best, method="SLSQP", bounds=problem.bounds,
                              constraints=({"type": "ineq", "fun": margins},), options={"maxiter": 200, "ftol": 1e-10})
    if local.success and np.all(margins(local.x) >= -1e-9) and -objective(local.x) > -objective(best):
        best = local.x
    values = {k: float(v) for k, v in zip(VARIABLES, best)}
    text = optimum_spec_text(spec, valve, values)
    from ..specification.validate import parse_spec
    checked = run_design(parse_spec(text)).valves[valve]
    line = design.drive.lines["chosen"]
    checks = constraints(checked, limits) + [
        replace(spring_reserve(checked, limits.min_spring_reserve, line.preload, line.rate),
                note="with the starting design's spring")]
    return Result(valve, {k: float(v) for k, v in zip(VARIABLES, x0)}, values, problem.evaluate(x0)[0],
                  checked.records["power_polynomial"]["tappet_fullness"],
                  dict(zip(problem.margin_names(), map(float, margins(best)))), problem.evaluations,
                  time.perf_counter() - t0, problem.seconds, polydyne_fullness(checked.law), text, checks)


def optimum_spec_text(spec, valve, values):
    """The specification file of ``spec`` with the cam keys of ``valve`` set to ``values`` (TOML text).

    The specification is written back from its validated keys (those the user gave), so ``valvetrain run``
    reads it as the original with the optimum's cam.
    """
    import tomli_w

    data = spec.model_dump(mode="json", exclude_unset=True, exclude_none=True)
    data["valves"][valve]["cam"].update({k: round(v, 6) for k, v in values.items()})
    head = (f"# The optimum of valvetrain optimize for valve {valve!r}: the power-polynomial cam's "
            f"{', '.join(VARIABLES)} that maximise the fullness under the limits (UkrSURT Proceedings (2019)).\n\n")
    text = head + tomli_w.dumps(data)
    tomllib.loads(text)
    return text
