"""One evaluation of a cam synthesis (:class:`Problem`): a point's law built through the specification's cam section,
sampled on a grid of the flank and refined around each extreme; the objective and the margins of the limits, the
one-mass train's separation only where it can change the best point; a whole population at once."""

from dataclasses import replace
import math
import time

import numpy as np
from pydantic import BaseModel, ValidationError

from .. import flow, springs
from ..design.drive import spring_options
from ..design.dynamics import build_train
from ..design.valve_checks import MAX_LIFT_TO_THROAT
from ..dynamics.models import one_mass_train
from ..dynamics.sweep import sweep
from ..errors import InputError
from ..laws.base import batch_derivatives, member_values, valve_lift_of
from ..layouts import finger_inertia_force, train_mass
from ..specification.models import Dynamics, Valve
from ..specification.si import si
from ..units import DEG, cam_per_crank
from .constraints import worst_cam_force
from .objectives import BREATHING, OBJECTIVES


GRID = 1201
"""Camshaft angles of the opening flank (of the whole event for a cam with a closing flank of its own) on which one
evaluation samples the law."""

REFINE = 65
"""Camshaft angles of each window, between the neighbours of a sampled extreme, on which one evaluation samples the
law again: the extremes are those of the contour to 1/32 of the grid's step."""

NEAR = 0.01
"""Summed relative violations of the other limits up to which a point's follower separation is simulated (beyond,
its penalty of :data:`PENALTY` times them already ranks it below any candidate of the search)."""

SPRING_SLACK = 0.1
"""How far below 0 the spring design's margin of the search (a conservative closed form) may lie for a point to be
designed in full: the final spring search decides."""

SPEEDS = (1.0,)
"""Engine speeds, fractions of the rated speed, at which one evaluation simulates the train (with the limit's own
multiple of the rated speed); the final check sweeps the whole range."""

PENALTY = 10.0
"""Weight of the summed constraint violations (relative margins below 0) against the objective over its starting
value in the global search (an exact penalty: a feasible point always beats a point that violates a limit by more
than a tenth of the objective's range)."""

FRONTIER_RANGE = (0.5, 3.0)
"""Factors on the starting design's required spring force between which the spring frontier is searched."""

FRONTIER_TOLERANCE = 2e-3
"""Width of the bisection bracket of the spring frontier (its lower end is used: on the side where a spring passes)."""

SPRING_ITERATIONS = 4
"""Spring searches of one evaluation at most while the reduced mass settles on the found spring's mass."""


class Problem:
    """The fast evaluation of one valve's design variables: the objective and the constraint margins.

    Parameters
    ----------
    spec : valvetrain.specification.Spec
    design : ValveDesign
        The starting design of the valve (its train and spring are those of the search).
    variables : list of Variable
    limits : Limits
    objective : str
        A name of :data:`OBJECTIVES`.
    breathing : BreathingObjective, optional
        Required for the objectives of :data:`BREATHING`.

    Notes
    -----
    One evaluation samples the law twice (:data:`GRID` angles, then :data:`REFINE` around each extreme) and
    integrates the objective by the flow module's quadrature (an objective of the breathing: the cycles converged at
    each of its speeds, :meth:`BreathingObjective.value`); ``evaluations``, ``seconds`` and ``law_samples`` (the
    angles at which the law was evaluated, the quadrature's nodes not counted) measure its cost.  A population is
    evaluated as one batch (:meth:`evaluate_many`): each point's law is built on its own, then all are sampled on
    their own grids in one call (:func:`~valvetrain.laws.base.batch_derivatives`), their quantities and least values
    found together and their objectives integrated in one quadrature; each point's numbers are those of evaluating it
    alone.
    """

    def __init__(self, spec, design, variables, limits, objective="fullness", breathing=None):
        self.name, self.variables, self.limits, self.objective = design.name, list(variables), limits, objective
        self.breathing = breathing
        self.spec, self.engine = spec, si(spec.engine)
        self.section = spec.valves[self.name]
        self.data = self.section.model_dump(mode="json", exclude_unset=True, exclude_none=True)
        self.x0 = np.array([self._value(v) for v in self.variables], dtype=float)
        self.bounds = [(v.low, v.high) for v in self.variables]
        self.reserve0 = self.section.drive.spring_reserve
        self.follower = design.cam.follower_model
        # a roller's pressure angle and concave radius are margins of the search too, a sliding face has neither
        self.limited = self.follower.limited_contact(design.profile.contact) is not None
        self.heel, self.i_k, self.omega = design.cam.heel_radius, design.cam.rocker_ratio, design.cam.cam_speed
        self.whole_event = getattr(self.section.cam, "closing", None) is not None
        self.mass = design.drive.masses.at_valve
        self.spring = design.drive.lines.chosen
        self.valve = si(self.section, self.spec)
        self.parts = {v.path.split(".")[0] for v in self.variables}
        self.spring_inputs = (self.valve.throat_diameter, spring_options(self.valve.spring),
                              max(design.drive.spring.gas_force, design.drive.spring.seat_load))
        self.law0, self.frontier = design.law, None
        self._train_parameters(design)
        self.names = self.margin_names()
        self.jump = self.names.index("no jump") if "no jump" in self.names else None
        self.evaluations, self.seconds, self.law_samples, self.simulations, self.best = 0, 0.0, 0, 0, -math.inf
        self.history, self.points = [], []
        self._cache, self._grid_kept = {}, (None, None, None)

    def _value(self, v):
        """The variable's value in the specification (given or the key's default).

        Raises
        ------
        ValueError
            The path names no numeric key of the valve's section.
        """
        node = self.section
        try:
            for part in v.path.split("."):
                node = node[int(part) - 1] if isinstance(node, list) else getattr(node, part)
        except (AttributeError, IndexError, ValueError):
            node = None
        if isinstance(node, bool) or not isinstance(node, (int, float)):
            raise InputError(f"optimize: valves.{self.name}.{v.path} is not a numeric key of the valve; allowed the "
                             "numbers of [valves.NAME] and its sections (cam.phi1_deg, drive.spring_reserve, ...)")
        return float(node)

    def _train_parameters(self, design):
        """The one-mass train of the search: the valve's [dynamics] section's (or the defaults'), a finger's mass
        changing with the lift (:func:`~valvetrain.design.dynamics.build_train`)."""
        self.speeds = None
        if self.limits.no_jump_factor is None:
            return
        dyn = self.section.dynamics or Dynamics()
        rated = self.engine.rated_speed * cam_per_crank(self.engine.strokes)
        train, self.train_parameters = build_train(si(dyn.model_copy(update={"model": "1dof"})), self.valve,
                                                   design.law, design.drive, f"valves.{self.name}", rated)
        self.variable_mass = train.variable_mass
        self.speeds = rated * np.unique(np.array(SPEEDS + (self.limits.no_jump_factor,)))

    def margin_names(self) -> list[str]:
        """Names of the entries of :meth:`evaluate`'s margins."""
        L = self.limits
        names = ["spring reserve"]
        if self.limited:
            names += ["pressure angle"] + (["concave radius"] if L.grinding_wheel_radius else [])
        names += [n for n, lim in (("rho_min", L.min_rho), ("contact stress", L.cam_width),
                                   ("max acceleration", L.max_acceleration), ("min acceleration", L.min_acceleration),
                                   ("seating velocity", L.seating_velocity)) if lim is not None]
        if self.speeds is not None:
            names.append("no jump")
        return names + ["spring design"]

    def point(self, x) -> dict:
        """The valve section's data with the variables ``x`` (the start's data, the parts the variables change
        copied)."""
        data = {**self.data, **{p: _copied(self.data[p]) for p in self.parts if p in self.data}}
        for v, value in zip(self.variables, x, strict=True):
            v.put(data, float(value))
        cam = data["cam"]
        for key, sources in self.section.cam.derived_keys.items():
            if any(v.path in sources for v in self.variables):
                cam.pop(key, None)
        return data

    def law(self, x) -> tuple | None:
        """(law, SI valve, spring scale K_z / K_z,0) of the variables, or None where they admit no law."""
        data = self.point(x)
        try:
            section = Valve.model_validate(data)
        except ValidationError:
            return None
        if section.cam.problems(f"valves.{self.name}", section, self.spec.engine):
            return None
        try:
            valve = self._si(section)
            law = valve.cam.section.build(valve, self.engine)
        except ValueError:
            return None
        if not law.end - law.start < 2.0 * np.pi or law.lift_max * valve.rocker_ratio > (
                MAX_LIFT_TO_THROAT * valve.throat_diameter):
            return None
        return law, valve, section.drive.spring_reserve / self.reserve0

    def _si(self, section):
        """The SI view of a point's valve section: the start's, with the sections that the variables change made
        anew (the whole view where a variable is a key of the valve itself)."""
        if any(not isinstance(getattr(section, p), BaseModel) for p in self.parts):
            return si(section, self.spec)
        return replace(self.valve, section=section, **{p: si(getattr(section, p), self.spec) for p in self.parts})

    def _angles(self, law):
        """The grid of one evaluation and the law's junctions on it [rad from the nose]."""
        end = law.end if self.whole_event else 0.0
        bp = law.breakpoints
        return np.unique(np.concatenate([self._grid(law.start, end), bp[(bp > law.start) & (bp < end)],
                                         [law.valve_opens], [law.valve_closes] if self.whole_event else []]))

    def _grid(self, start, end):
        """:data:`GRID` angles from ``start`` to ``end`` [rad], kept for the next law with the same event (the laws of
        a search share it where no variable changes the event's angles)."""
        if self._grid_kept[:2] != (start, end):
            self._grid_kept = (start, end, np.linspace(start, end, GRID))
        return self._grid_kept[2]

    def _quantities(self, laws, theta, member, scales):
        """Each sampled quantity as one to minimise at the angles ``theta`` of the laws ``laws[member]`` at K_z =
        ``scales[member]`` x K_z,0, and (h, dh, d2h) there."""
        L = self.limits
        h, dh, d2h, _ = batch_derivatives(laws, theta, member)
        self.law_samples += theta.size
        ramp = member_values([law.ramp_height for law in laws], member)
        y = self.i_k * np.clip(h - ramp, 0.0, None)
        spring = scales[member] * self.spring.force(y)
        finger = finger_inertia_force(self.valve, self.heel, h, dh, d2h)
        inertia = np.clip(-(self.mass * self.i_k * self.omega**2 * d2h + self.omega**2 * finger), 0.0, None)
        loaded = (inertia > 0.0) & (y > 0.0)
        nose = member_values([law.lift_max + law.ramp_height for law in laws], member)
        acc = self.follower.travel_acceleration(self.heel, h, dh, d2h)
        q = {"spring reserve": np.where(loaded, spring / np.where(loaded, inertia, 1.0), np.inf),
             "lift": h / nose, "overshoot": -h / nose,
             "max acceleration": -acc, "min acceleration": acc}
        rho = self.follower.curvature(self.heel, h, dh, d2h)
        if self.limited:
            q["pressure angle"] = -np.abs(self.follower.pressure_angle(self.heel, h, dh))
            q["concave radius"] = np.where(rho < 0.0, 1.0 / np.where(rho < 0.0, rho, -1.0), 0.0)
        q["rho_min"] = self.follower.convex_radius(rho)
        if L.cam_width is not None:
            top = (self.omega * L.top_speed)**2
            force = worst_cam_force(spring, self.mass, self.i_k, top * d2h, top * finger)
            at_cam = force * self.follower.force_ratio(self.heel, h, dh)
            q["contact stress"] = -self.follower.contact_stress(at_cam, rho, L.cam_width, L.contact_modulus)
        return q, h, dh, d2h

    def _extremes(self, laws, scales):
        """Per law of ``laws`` (at K_z = ``scales`` x K_z,0): the least value of each quantity of :meth:`_quantities`
        on the grid refined around its least sample (:data:`REFINE` angles between the neighbours), the grid's
        (theta, h, dh, d2h) and |dh/dtheta| [m/rad] at the valve's opening and closing; all laws sampled together."""
        theta, member, starts = _ragged([self._angles(law) for law in laws])
        q, h, dh, d2h = self._quantities(laws, theta, member, scales)
        least = {k: _least(v, starts) for k, v in q.items()}
        ends = np.append(starts[1:], theta.size)
        windows = []
        for i, (a, b) in enumerate(zip(starts, ends, strict=True)):
            at = a + np.array(sorted({int(first[i]) for _, first in least.values()}))
            windows.append(np.linspace(theta[np.maximum(at - 1, a)], theta[np.minimum(at + 1, b - 1)], REFINE,
                                       axis=1).ravel())
        fine, fine_member, fine_starts = _ragged(windows)
        fine_least = {k: _least(v, fine_starts)[0] for k, v in self._quantities(laws, fine, fine_member,
                                                                                  scales)[0].items()}
        out = []
        for i, (law, a, b) in enumerate(zip(laws, starts, ends, strict=True)):
            t = theta[a:b]
            seat = np.abs(dh[a:b][np.searchsorted(t, [law.valve_opens, law.valve_closes if self.whole_event else
                                                      law.valve_opens])])
            out.append(({k: min(float(least[k][0][i]), float(fine_least[k][i])) for k in q}, t, h[a:b], dh[a:b],
                        d2h[a:b], seat))
        return out

    def _objectives(self, laws, valves):
        """The objective of :data:`OBJECTIVES` of each law as the flow stage computes it, all quadratures at once (an
        objective of the breathing as its stage computes it, law by law)."""
        if self.objective in BREATHING:
            return [self.breathing.value(self.name, OBJECTIVES[self.objective][0], law, valve)
                    for law, valve in zip(laws, valves, strict=True)]
        ramp = np.array([law.ramp_height for law in laws])
        rocker = np.array([valve.rocker_ratio for valve in valves])
        opens, closes = (np.array([getattr(law, k) for law in laws]) for k in ("valve_opens", "valve_closes"))
        bp = [law.breakpoints for law in laws]

        def valve_lift(t, member):
            return valve_lift_of(batch_derivatives(laws, t, member)[0], ramp[member], rocker[member], self.follower)

        if self.objective == "fullness":
            return flow.fullnesses(valve_lift, opens, closes, rocker * np.array([law.lift_max for law in laws]), bp)
        throat, seat = (np.array([getattr(valve, k) for valve in valves]) for k in ("throat_diameter", "seat_angle"))
        return flow.time_areas(lambda t, member: flow.curtain_area(valve_lift(t, member), throat[member], seat[member]),
                               opens, closes, self.omega, bp)

    def evaluate(self, x, dynamics=None) -> tuple[float, np.ndarray]:
        """(objective, margins) of the variables; a point that admits no design has objective 0 and margins -1.

        The follower separation is simulated (``dynamics`` None) only where it can matter: until a candidate is found
        (:meth:`acceptable`) at every point, to rank the infeasible ones; then where the objective beats the best
        candidate's and the other margins are violated by at most :data:`NEAR` in all (a point farther out is ranked
        below every candidate by its penalty alone); with ``dynamics`` True always, with False never.  Where it is
        not simulated its margin is NaN.  The evaluation of one point is the batch of one (:meth:`evaluate_many`).
        """
        return self.evaluate_many([x], dynamics)[0]

    def evaluate_many(self, xs, dynamics=None) -> list[tuple[float, np.ndarray]]:
        """(objective, margins) of each point of ``xs`` (a sequence of variable vectors) as :meth:`evaluate` gives it,
        in order: the points not evaluated before have their laws built one by one and sampled, checked and integrated
        together (:meth:`_entries`); the separation is then decided point by point, in order."""
        t0 = time.perf_counter()
        keys = [tuple(float(v) for v in x) for x in xs]
        new = list(dict.fromkeys(key for key in keys if key not in self._cache))
        for key, entry in zip(new, self._entries([self.law(np.array(key)) for key in new]), strict=True):
            self.evaluations += 1
            self._cache[key] = entry
            self.history.append((entry[0], entry[1]))
            self.points.append(np.array(key))
        out = []
        for key in keys:
            objective, margins, kept = self._cache[key]
            if self.jump is not None and kept is not None and np.isnan(margins[self.jump]) and (
                    dynamics or (dynamics is None and objective > self.best and (
                        self.best == -math.inf or self.violation(margins) <= NEAR))):
                margins[self.jump] = self._separation(*kept)
                self.simulations += 1
            if self.acceptable(margins):
                self.best = max(self.best, objective)
            out.append((objective, margins))
        self.seconds += time.perf_counter() - t0
        return out

    def _entries(self, found):
        """[objective, margins, (law, scale) or None] of each of :meth:`law`'s results ``found``: objective 0 and
        margins -1 where there is no law or no cam."""
        out = [[0.0, -np.ones(len(self.names)), None] for _ in found]
        built = [(i, f) for i, f in enumerate(found) if f is not None]
        if not built:
            return out
        index, (laws, valves, scales) = [i for i, _ in built], zip(*(f for _, f in built), strict=True)
        margins = self._margins(laws, valves, np.array(scales))
        cams = [k for k, m in enumerate(margins) if m is not None]
        if cams:
            objectives = self._objectives([laws[k] for k in cams], [valves[k] for k in cams])
            for k, objective in zip(cams, objectives, strict=True):
                out[index[k]] = [float(objective), margins[k], (laws[k], scales[k])]
        return out

    def penalised_many(self, xs, scale) -> np.ndarray:
        """The objective over ``scale``, negated, plus :data:`PENALTY` times the summed violations, of each point of
        ``xs``, evaluated together (:meth:`evaluate_many`)."""
        return np.array([-objective / scale + PENALTY * float(np.nansum(np.clip(-margins, 0.0, None)))
                         for objective, margins in self.evaluate_many(xs)])

    def _margins(self, laws, valves, scales):
        """The margins of the limits of each law, or None where its lift leaves 0...the nose lift (no cam)."""
        return [self._margins_of(law, valve, scale, extremes)
                for law, valve, scale, extremes in zip(laws, valves, scales, self._extremes(laws, scales),
                                                       strict=True)]

    def _margins_of(self, law, valve, scale, extremes):
        """The margins of one law from its :meth:`_extremes`, or None where the lift leaves 0...the nose lift."""
        L = self.limits
        least, theta, h, dh, d2h, seat = extremes
        if least["lift"] < -1e-6 or least["overshoot"] < -1.0 - 1e-6:
            return None
        reserve = least["spring reserve"] if np.isfinite(least["spring reserve"]) else 10.0
        target = L.min_spring_reserve * scale
        out = [(reserve - target) / target]
        if self.limited:
            out.append((L.max_pressure_angle + least["pressure angle"]) / L.max_pressure_angle)
            if L.grinding_wheel_radius:
                out.append(1.0 - L.grinding_wheel_radius * max(-least["concave radius"], 0.0))
        if L.min_rho is not None:
            out.append((min(least["rho_min"], self.heel) - L.min_rho) / L.min_rho)
        if L.cam_width is not None:
            out.append((L.max_contact_stress + least["contact stress"]) / L.max_contact_stress)
        if L.max_acceleration is not None:
            out.append((L.max_acceleration + self.omega**2 * least["max acceleration"]) / abs(L.max_acceleration))
        if L.min_acceleration is not None:
            out.append((self.omega**2 * least["min acceleration"] - L.min_acceleration) / abs(L.min_acceleration))
        if L.seating_velocity is not None:
            velocity = valve.rocker_ratio * self.omega * float(np.max(seat))
            out.append((L.seating_velocity[1] - velocity) / L.seating_velocity[1])
        if self.speeds is not None:
            out.append(math.nan)
        out.append(self.spring_design(law, theta, h, dh, d2h, scale))
        return np.array(out, dtype=float)

    def _requirement(self, law, theta, h, dh, d2h, scale):
        """The required spring force (:class:`valvetrain.springs.Requirement`) of a cam at K_z = scale x K_z,0 on the
        starting design's reduced mass, from the samples of the open event (a finger's inertia by its variable ratio
        as an acceleration of that mass, as the drive stage takes it)."""
        open_ = (theta >= law.valve_opens) & (theta <= law.valve_closes)
        y = self.i_k * np.clip(h[open_] - law.ramp_height, 0.0, None)
        finger = finger_inertia_force(self.valve, self.heel, h[open_], dh[open_], d2h[open_])
        force = springs.required_spring_force(self.mass, self.i_k * self.omega**2 * d2h[open_]
                                              + self.omega**2 * finger / self.mass, self.reserve0 * scale)
        return springs.Requirement(y, force, self.spring_inputs[2])

    def _spring_passes(self, requirement):
        """Whether the design's spring search finds a spring for ``requirement`` (times a factor), the reduced mass
        iterated on the found spring's mass as the drive stage does: ``passes(factor)``."""
        throat, options, _ = self.spring_inputs
        masses = self.valve.drive.masses

        def passes(factor):
            required, mass = requirement.scaled(factor), self.mass
            for _ in range(SPRING_ITERATIONS):
                search = springs.design_springs(required, throat, self.omega, options)
                if masses is None or masses.spring_kg is not None:
                    break
                settled = train_mass(self.valve, sum(d.mass for d in search.designs.values()))[0]
                if abs(settled - mass) < 1e-7:
                    break
                required, mass = requirement.scaled(factor * settled / self.mass), settled
            return search.passes
        return passes

    def _spring_frontier(self):
        """The largest factor on the starting design's required spring force for which a spring passes every spring
        check (bisection to :data:`FRONTIER_TOLERANCE`, at most :data:`FRONTIER_RANGE`), and that required line."""
        law = self.law0
        theta = self._angles(law)
        h, dh, d2h, _ = law.derivatives(theta)
        requirement = self._requirement(law, theta, h, dh, d2h, 1.0)
        line = requirement.line(self.spring_inputs[1].ratio_range)
        passes = self._spring_passes(requirement)
        low, high = FRONTIER_RANGE
        if not passes(low):
            return 0.0, line
        if passes(high):
            return high, line
        while high - low > FRONTIER_TOLERANCE:
            mid = 0.5 * (low + high)
            low, high = (mid, high) if passes(mid) else (low, mid)
        return low, line

    def spring_design(self, law, theta, h, dh, d2h, scale) -> float:
        """Margin of the spring design: the largest of the candidate's required preload and largest force over the
        starting design's, against the factor up to which a spring passes (:meth:`_spring_frontier`, found once);
        >= 0 when a spring of the specification's options is expected to pass.

        Notes
        -----
        The required force line of a cam is a closed form of its samples (:class:`valvetrain.springs.Requirement`);
        the discrete spring search runs once, for the start's frontier, and for the final design
        (:func:`~valvetrain.synthesis.optimize.final_checks`), which checks the optimum's own spring exactly.
        """
        if self.frontier is None:
            self.frontier = self._spring_frontier()
        factor, line0 = self.frontier
        line = self._requirement(law, theta, h, dh, d2h, scale).line(self.spring_inputs[1].ratio_range)
        ratio = max(line.preload / line0.preload, line.max_force / line0.max_force)
        return (factor - ratio) / max(factor, FRONTIER_RANGE[0])

    def _separation(self, law, scale):
        """Margin of the follower separation: the smallest contact force while the cam lifts the valve over the
        spring preload (> 0), or minus the separated camshaft angle [rad] (< 0); 0 on the border."""
        p = self.train_parameters
        train = replace(one_mass_train(p.mass, p.drive_stiffness, p.spring_rate * scale, p.preload * scale,
                                       p.rocker_ratio, p.lash, damping_ratio=p.damping_ratio,
                                       seat_stiffness=p.seat_stiffness, seat_damping_ratio=p.seat_damping_ratio),
                        variable_mass=self.variable_mass)
        worst = math.inf
        for r in sweep(law, train, self.speeds, p.revolutions, p.step / DEG).per_speed():
            if len(r.jump_intervals):
                worst = min(worst, -float(np.sum(np.diff(r.jump_intervals, axis=1))))
            else:
                lifting = (r.kinematic_lift > 0.0) & (r.lift > 0.0)
                force = float(r.contact_force[lifting].min()) if lifting.any() else p.preload * scale
                worst = min(worst, force / (p.preload * scale))
        return worst

    def _slack(self, margins):
        """The margins with the spring design's raised by :data:`SPRING_SLACK`."""
        return margins + np.where(np.arange(margins.size) == margins.size - 1, SPRING_SLACK, 0.0)

    def acceptable(self, margins) -> bool:
        """Whether a point is a candidate for the full design: every margin holds (a NaN one does not), the spring
        design's within :data:`SPRING_SLACK`."""
        return bool(np.all(self._slack(margins) >= 0.0))

    def violation(self, margins) -> float:
        """The summed violations of the margins but a NaN one, the spring design's beyond :data:`SPRING_SLACK`."""
        return float(np.nansum(np.clip(-self._slack(margins), 0.0, None)))

    def candidates(self) -> list[tuple[float, np.ndarray, float]]:
        """The points evaluated that are :meth:`acceptable`, best objective first: (objective, x, worst margin)."""
        found = [(o, x, float(np.nanmin(m))) for (o, m), x in zip(self.history, self.points, strict=True)
                 if self.acceptable(m)]
        return sorted(found, key=lambda p: -p[0])


def _copied(node):
    """A copy of specification data (dicts and lists of numbers, texts and booleans), each dict and list new."""
    if isinstance(node, dict):
        return {k: _copied(v) for k, v in node.items()}
    return [_copied(v) for v in node] if isinstance(node, list) else node


def _ragged(arrays):
    """(concatenation, index of the array of each entry, start of each array in it) of 1-D arrays."""
    sizes = [a.size for a in arrays]
    return (np.concatenate(arrays), np.repeat(np.arange(len(arrays)), sizes),
            np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(int))


def _least(values, starts):
    """(least value, index of its first occurrence from the start) of each run of ``values`` beginning at ``starts``
    (``np.min`` and ``np.argmin`` of each run: a run holding NaN gives NaN at its first NaN)."""
    least = np.minimum.reduceat(values, starts)
    sizes = np.diff(np.append(starts, values.size))
    hits = np.flatnonzero((values == np.repeat(least, sizes)) | np.isnan(values))
    return least, hits[np.searchsorted(hits, starts)] - starts
