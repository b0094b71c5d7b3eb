"""The checks across the sections of a specification, and its document's dotted keys.

Every problem becomes one message naming the key, the value and what is allowed (:func:`problems`, which
:func:`valvetrain.specification.validate` runs once every field is valid).  What needs a computation (a cam
that the angles admit but the law cannot make, a spring that does not fit) is the design's to
find (:func:`valvetrain.design.run`); ``valvetrain validate`` runs it.  :func:`set_keys` and :func:`spec_document`
are the dotted keys that :meth:`Spec.replace` and ``study --grid`` change.
"""

import copy
import math
from typing import Any, Optional

from ..errors import InputError
from ..followers import REGISTRY as FOLLOWERS
from ..layouts import LAYOUTS
from ..springs import feasible_mean_diameters, shortest_solid_length
from ..units import MM
from .cam_base import main_half_angle_deg
from .messages import Problem, shown
from .si import si


def _valve_problems(name, v, engine):
    at = f"valves.{name}"
    missing = [k for k in ("max_lift_mm", "opens_deg", "closes_deg") if getattr(v, k) is None]
    if missing and v.cam.needs_timing:
        return [Problem(f"{at}.{k}", "required key is missing (only a measured table, law = \"table\", sets its own "
                        "lift and timing)") for k in missing]
    out = []
    if len({"opens_deg", "closes_deg"} & set(missing)) == 1:
        given, other = ("opens_deg", "closes_deg") if v.closes_deg is None else ("closes_deg", "opens_deg")
        return [Problem(f"{at}.{given}", f"needs {other} too: the timing is given by both or, for a measured table, "
                        "by neither", f"{getattr(v, given):g}", " ")]
    if v.throat_diameter_mm >= engine.bore_mm:
        out.append(Problem(f"{at}.throat_diameter_mm", f"must be smaller than engine.bore_mm = {engine.bore_mm:g}",
                           f"{v.throat_diameter_mm:g}", " "))
    stem = v.parts.stem_diameter_mm
    if stem is not None and stem >= v.throat_diameter_mm:
        out.append(Problem(f"{at}.parts.stem_diameter_mm", f"must be smaller than throat_diameter_mm = "
                           f"{v.throat_diameter_mm:g}", f"{stem:g}", " "))
    if v.cam.base_radius_mm <= v.clearance_mm:
        out.append(Problem(f"{at}.cam.base_radius_mm", f"must exceed clearance_mm = {v.clearance_mm:g}",
                           f"{v.cam.base_radius_mm:g}", " "))
    if v.lash_adjuster is not None and v.clearance_mm != 0.0:
        out.append(Problem(f"{at}.clearance_mm", "allowed 0 with a lash_adjuster section (it leaves no lash on the "
                           "base circle for a ramp to take up)", f"{v.clearance_mm:g}"))
    axis = None if v.lash_adjuster is None else v.lash_adjuster.axis_angle_deg
    if axis is not None and (v.lash_adjuster.location != "pivot" or not FOLLOWERS[v.cam.follower].pivot_axis):
        out.append(Problem(f"{at}.lash_adjuster.axis_angle_deg", "allowed only at the pivot of a finger given by its "
                           "geometry (location = \"pivot\", cam.follower = \"finger\"): a tappet's adjuster moves "
                           "along the tappet, a rocker's of a given rocker_ratio along the straight lever's normal",
                           f"{axis:g}", " "))
    if v.switching is not None and not FOLLOWERS[v.cam.follower].switchable:
        out.append(Problem(f"{at}.switching", "allowed only on a finger given by its geometry (cam.follower = "
                           f"\"finger\"), not with cam.follower = {v.cam.follower!r}: the switching finger's inner arm "
                           "carries the finger's roller"))
    low = None if v.switching is None else v.switching.low_lobe
    if low is not None and v.max_lift_mm is not None and low.max_lift_mm >= v.max_lift_mm:
        out.append(Problem(f"{at}.switching.low_lobe.max_lift_mm", f"allowed below the valve's max_lift_mm = "
                           f"{v.max_lift_mm:g} (the second lobe is the low lift)", f"{low.max_lift_mm:g}"))
    if v.switching is not None and v.switching.compression_ratio is not None and engine.rod_length_mm is None:
        out.append(Problem(f"{at}.switching.compression_ratio", "needs engine.rod_length_mm: the deactivated "
                           "cylinder's volume follows the slider-crank", f"{v.switching.compression_ratio:g}", " "))
    ratio = v.spring.mean_diameter_ratio
    wires = v.spring.wire_diameter_range_mm
    low, high = (x / MM for x in feasible_mean_diameters(wires))
    if ratio[1] * v.throat_diameter_mm < low or ratio[0] * v.throat_diameter_mm > high:
        out.append(Problem(f"{at}.spring.mean_diameter_ratio", f"with throat_diameter_mm = "
                   f"{v.throat_diameter_mm:g} gives spring mean diameters {ratio[0] * v.throat_diameter_mm:g}..."
                   f"{ratio[1] * v.throat_diameter_mm:g} mm; wire of {wires[0]:g}...{wires[1]:g} mm makes "
                   f"{low:g}...{high:g} mm (index D/d = 3...12, Valve-train practical works (n.d.), work 6)",
                           f"{list(ratio)}", " "))
    out += [p.within(at) for p in spring_length_problems(v.spring, v.max_lift_mm)]
    if (v.drive.layout is not None and not any(link.lever for link in LAYOUTS[v.drive.layout].links)
            and v.rocker_ratio != 1.0):
        out.append(Problem(f"{at}.drive.layout", f"needs rocker_ratio = 1 (got {v.rocker_ratio:g})",
                           f"\"{v.drive.layout}\"", " "))
    if FOLLOWERS[v.cam.follower].geometric_lever:
        if v.rocker_ratio != 1.0:
            out.append(Problem(f"{at}.rocker_ratio", f"allowed 1 with cam.follower = \"{v.cam.follower}\" (the law is "
                               "the valve's; the finger's ratio follows from its geometry)", f"{v.rocker_ratio:g}"))
        if v.max_lift_mm is not None:
            problem = FOLLOWERS[v.cam.follower].from_cam(si(v.cam)).geometry_problem(
                (v.cam.base_radius_mm - v.clearance_mm) * MM, v.max_lift_mm * MM + v.clearance_mm * MM)
            if problem:
                key, value, message, joiner = problem
                out.append(Problem(f"{at}.cam.{key}", message, value, joiner))
        if v.drive.layout != "rocker":
            out.append(Problem(f"{at}.drive.layout", f"allowed \"rocker\" with cam.follower = \"{v.cam.follower}\" "
                               "(the finger's inertia about its pivot)", shown(v.drive.layout)))
        if v.drive.valve_arm_mm is not None:
            out.append(Problem(f"{at}.drive.valve_arm_mm", f"not allowed with cam.follower = \"{v.cam.follower}\": "
                               "the finger's valve arm G = dv/dpsi follows from its geometry at every lift",
                               f"{v.drive.valve_arm_mm:g}"))
    elif v.drive.masses is not None and v.drive.masses.rocker_inertia_kg_mm2 > 0 and v.drive.valve_arm_mm is None:
        out.append(Problem(f"{at}.drive.masses.rocker_inertia_kg_mm2", "needs drive.valve_arm_mm (the valve-side "
                           "rocker arm)", f"{v.drive.masses.rocker_inertia_kg_mm2:g}"))
    if v.lubrication is not None and v.parts.cam_width_mm is None:
        out.append(Problem(f"{at}.lubrication", f"needs {at}.parts.cam_width_mm (the load per unit width of the "
                           "contact)", joiner=" "))
    if v.piston_gap_tdc_mm is not None and engine.rod_length_mm is None:
        out.append(Problem(f"{at}.piston_gap_tdc_mm", "needs engine.rod_length_mm for the piston kinematics",
                           joiner=" "))
    if not {"opens_deg", "closes_deg"} & set(missing):
        half = main_half_angle_deg(v, engine.strokes)
        if not 0.0 < half < 180.0:
            out.append(Problem(f"{at}.opens_deg", "the valve event opens_deg + 180 + closes_deg must lie in (0, 360) "
                               "crank deg", f"{v.opens_deg + v.closes_deg:g}",
                               text=f"{at}.opens_deg + closes_deg = {v.opens_deg + v.closes_deg:g}: the valve event "
                               "opens_deg + 180 + closes_deg must lie in (0, 360) crank deg"))
        out += v.cam.problems(at, v, engine)
    return out


def spring_length_problems(spring, lift_mm, lift_key="max_lift_mm") -> list[Problem]:
    """The lengths a spring section allows against the valve lift (keys under ``spring.``): the longest installed
    length must exceed the lift plus the solid length of the shortest spring of the wire range, 4 x its thinnest wire
    (:func:`valvetrain.springs.shortest_solid_length`), else every spring goes solid before full lift; the longest
    free length must exceed that too, and the shortest installed length.  A spring between that bound and the coil
    gap the design asks for is its ``coil_gap_at_full_lift`` and ``installed_length`` checks.

    Parameters
    ----------
    spring : Spring
        The spring section, its keys in mm.
    lift_mm : float or None
        The valve lift [mm]; None where not known yet (a measured table's, known once its law is built).
    lift_key : str
        What the lift is called in the messages.
    """
    installed, free, out = spring.installed_length_mm, spring.max_free_length_mm, []
    below = {}
    if lift_mm is not None:
        wire, per_wire = spring.wire_diameter_range_mm[0], shortest_solid_length(1.0)
        least = f"{lift_key} + {per_wire:g} x the thinnest wire_diameter_range_mm = {lift_mm:g} + {per_wire:g} x {wire:g}"
        below[least] = lift_mm + per_wire * wire
        if installed is not None and installed[1] <= below[least]:
            out.append(Problem("spring.installed_length_mm", f"allowed [low, high] with high above {least} = "
                               f"{below[least]:g} mm: below, every spring goes solid before full lift (one working "
                               "and two end coils, eq. 6.4)", f"{list(installed)}"))
    if installed is not None:
        below["the shortest installed_length_mm"] = installed[0]
    if free is not None and below and free <= max(below.values()):
        out.append(Problem("spring.max_free_length_mm", "allowed above " + " and ".join(
            f"{key} = {value:g}" for key, value in below.items()) + " mm (installing and lifting the spring "
            "compress it, Valve-train practical works (n.d.), eq. 6.5)", f"{free:g}"))
    return out


def _same(spec, key_crank, key_engine):
    """A [crank] value that defaults to [engine]'s; a problem message when both are given and differ."""
    a, b = getattr(spec.crank, key_crank) if spec.crank else None, getattr(spec.engine, key_engine)
    if a is not None and b is not None and abs(a - b) > 1e-9 * max(abs(a), abs(b)):
        return a, [Problem(f"crank.{key_crank}", f"differs from engine.{key_engine} = {b:g}; give it in one place",
                           f"{a:g}", " ")]
    return (a if a is not None else b), []


def crank_geometry(spec) -> tuple[Optional[float], ...]:
    """Effective bore, stroke, rod length [mm] and speed [rpm] of the crank mechanism."""
    return tuple(_same(spec, kc, ke)[0] for kc, ke in (("bore_mm", "bore_mm"), ("stroke_mm", "stroke_mm"),
                                                      ("rod_length_mm", "rod_length_mm"),
                                                      ("speed_rpm", "rated_speed_rpm")))


def _crank_problems(spec):
    if spec.crank is None and spec.two_stroke is None:
        return []
    out = []
    for kc, ke in (("bore_mm", "bore_mm"), ("stroke_mm", "stroke_mm"), ("rod_length_mm", "rod_length_mm"),
                   ("speed_rpm", "rated_speed_rpm")):
        out += _same(spec, kc, ke)[1]
    bore, stroke, rod, _ = crank_geometry(spec)
    if rod is None:
        out.append(Problem("crank.rod_length_mm", "(or engine.rod_length_mm) is required for the crank mechanism and "
                           "the two-stroke ports", joiner=" "))
    elif rod <= stroke / 2.0:
        out.append(Problem("crank.rod_length_mm", f"must exceed the crank radius {stroke / 2.0:g} mm", f"{rod:g}", " "))
    c = spec.crank
    if c is None:
        return out
    if rod is not None and rod > stroke / 2.0 and abs(c.offset_mm) >= rod - stroke / 2.0:
        out.append(Problem("crank.offset_mm", f"allowed |offset| < rod length - crank radius = "
                           f"{rod - stroke / 2.0:g} mm", f"{c.offset_mm:g}"))
    cycle = 180.0 * spec.engine.strokes
    n = cycle / c.step_deg
    if abs(n - round(n)) > 1e-9:
        out.append(Problem("crank.step_deg", f"must divide the {cycle:g} deg cycle into whole steps", f"{c.step_deg:g}",
                           " "))
    return out


def _two_stroke_problems(spec):
    ts = spec.two_stroke
    if ts is None:
        return []
    out = []
    if spec.engine.strokes != 2:
        out.append(Problem("engine.strokes", "allowed 2 with a [two_stroke] section", f"{spec.engine.strokes}",
                           text=f"[two_stroke] needs engine.strokes = 2 (got {spec.engine.strokes})"))
    if not ts.ports:
        out.append(Problem("two_stroke.ports", "needs at least one [two_stroke.ports.NAME]",
                           text="[two_stroke] needs at least one [two_stroke.ports.NAME]"))
    bore, stroke = crank_geometry(spec)[:2]
    for name, port in ts.ports.items():
        if port.width_mm >= math.pi * bore:
            out.append(Problem(f"two_stroke.ports.{name}.width_mm", f"allowed below the cylinder's circumference pi x "
                               f"bore = {math.pi * bore:.4g} mm (the port, or its group's summed width, is cut in the "
                               "cylinder wall)", f"{port.width_mm:g}"))
        if port.height_mm is not None and port.kind != "inlet" and port.height_mm >= stroke:
            out.append(Problem(f"two_stroke.ports.{name}.height_mm", f"must be smaller than the stroke {stroke:g} mm",
                               f"{port.height_mm:g}", " "))
        if port.kind == "inlet" and ts.piston_height_mm is None:
            out.append(Problem(f"two_stroke.ports.{name}", "an inlet port needs two_stroke.piston_height_mm"))
        elif port.kind == "inlet" and not ts.piston_height_mm < port.lower_edge_mm < ts.piston_height_mm + stroke:
            out.append(Problem(f"two_stroke.ports.{name}.lower_edge_mm", f"allowed between piston_height_mm = "
                               f"{ts.piston_height_mm:g} and piston_height_mm + stroke = "
                               f"{ts.piston_height_mm + stroke:g} mm, where the piston's skirt passes: else the port "
                               "is never uncovered or never covered (Valve-train practical works (n.d.), eq. 8.4)",
                               f"{port.lower_edge_mm:g}"))
    if ts.speed_range_rpm is not None and ts.speed_range_rpm[0] >= ts.speed_range_rpm[1]:
        out.append(Problem("two_stroke.speed_range_rpm", "must be [low, high] with low < high",
                           f"{list(ts.speed_range_rpm)}", " "))
    return out


def _breathing_problems(spec):
    """[breathing] against the engine, [crank] and the valves: a four-stroke, a rod length and a compression ratio,
    each side's lift (a file or designed valves of its kind) and, with a measured lift, its C_D table; a wall
    temperature for every condition; firing needs [crank.cycle]."""
    b = spec.breathing
    if b is None:
        return []
    out = []
    if spec.engine.strokes != 4:
        out.append(Problem("engine.strokes", "allowed 4 with a [breathing] section (a four-stroke's gas exchange)",
                           f"{spec.engine.strokes}"))
    if crank_geometry(spec)[2] is None:
        out.append(Problem("engine.rod_length_mm", "(or crank.rod_length_mm) is required for the breathing's piston "
                           "motion", joiner=" "))
    if b.compression_ratio is None and (spec.crank is None or spec.crank.compression_ratio is None):
        out.append(Problem("breathing.compression_ratio", "is required (or crank.compression_ratio)", joiner=" "))
    if b.mode == "fired" and (spec.crank is None or spec.crank.cycle is None):
        out.append(Problem("breathing.mode", "'fired' burns on the Wiebe schedule of [crank.cycle]: give [crank] with "
                           "[crank.cycle], or mode = 'motored'", "'fired'"))
    kinds = {v.kind for v in spec.valves.values()}
    for side in ("intake", "exhaust"):
        s = getattr(b, side)
        if s.lift_file is None and side not in kinds:
            out.append(Problem(f"breathing.{side}.lift_file", f"is required: no [valves.NAME] of kind '{side}' to "
                               "take the lift from", joiner=" "))
        if s.lift is not None and s.lift_file is not None:
            out.append(Problem(f"breathing.{side}.lift", "allowed only without lift_file (the measured lift is the "
                               "lift; a measured lift has no train to move it): give lift_file or lift, not both",
                               f"'{s.lift}'"))
        elif s.lift == "dynamics":
            bare = [name for name, v in spec.valves.items() if v.kind == side and v.dynamics is None]
            if bare:
                out.append(Problem(f"breathing.{side}.lift", f"'dynamics' needs the [dynamics] of every {side} valve "
                                   f"(the train that moves it): none in {', '.join(f'[valves.{n}]' for n in bare)}; "
                                   "allowed 'designed'", "'dynamics'"))
        if s.lift_file is not None and s.cd_file is None:
            out.append(Problem(f"breathing.{side}.cd_file", "is required with lift_file (the default C_D needs a "
                               "designed valve's flow section)", joiner=" "))
    walls = [("curve", b.curve)] if b.curve is not None else []
    walls += [(f"conditions.{i}", c) for i, c in enumerate(b.conditions)]
    for where, c in walls:
        if c.wall_temperature_C is None and b.wall_temperature_C is None:
            out.append(Problem(f"breathing.{where}.wall_temperature_C", "is required (or breathing.wall_temperature_C)",
                               joiner=" "))
    return out


def _acceptance_problems(spec):
    """An [[accepted]] table naming a valve the specification does not have."""
    names = ", ".join(repr(n) for n in spec.valves) or "none: the specification has no valves"
    return [Problem(f"accepted.{i}.valve", f"allowed {names}", shown(a.valve, 40))
            for i, a in enumerate(spec.accepted) if a.valve is not None and a.valve not in spec.valves]


def _camshaft_problems(spec):
    """[camshaft] against the engine and the valves: the valves it names exist, its cylinders are the engine's,
    one position per cylinder."""
    c = spec.camshaft
    if c is None:
        return []
    out = []
    if not spec.valves:
        out.append(Problem("camshaft", "the camshaft needs at least one [valves.NAME] section (its lobes)"))
    missing = [n for n in (c.valves or []) if n not in spec.valves]
    if missing or c.valves == []:
        out.append(Problem("camshaft.valves", f"allowed a non-empty list of the valves {sorted(spec.valves)}",
                           f"{c.valves}"))
    n = spec.engine.cylinders
    cylinders = c.cylinders if c.cylinders is not None else list(range(1, n + 1))
    if not cylinders or len(set(cylinders)) != len(cylinders) or max(cylinders) > n:
        out.append(Problem("camshaft.cylinders", f"allowed distinct cylinders 1...{n} (engine.cylinders)",
                           f"{c.cylinders}"))
    elif c.cylinders is None and len(c.cylinder_positions_mm) != n:
        out.append(Problem("camshaft.cylinder_positions_mm", f"has {len(c.cylinder_positions_mm)} entries: one per "
                           f"cylinder (engine.cylinders = {n}) is needed", joiner=" "))
    carried = [name for name in (c.valves or spec.valves) if name in spec.valves]
    if len({spec.valves[name].phaser for name in carried}) > 1:
        phased = [name for name in carried if spec.valves[name].phaser is not None]
        out.append(Problem("camshaft.valves", f"a phaser turns the whole camshaft: every valve it carries has the same "
                           f"[valves.NAME.phaser] (phased: {', '.join(phased)}), or name only the phased ones",
                           f"{carried}"))
    return out


def _phaser_problems(spec):
    """A valve's [phaser] against the breathing: the phased valve's designed lift is what breathes."""
    out = []
    for name, v in spec.valves.items():
        side = None if spec.breathing is None else getattr(spec.breathing, v.kind)
        if v.phaser is not None and side is not None and side.lift_file is not None:
            out.append(Problem(f"valves.{name}.phaser", f"the breathing's {v.kind} lift is measured "
                               f"(breathing.{v.kind}.lift_file), not the designed valve's the phaser turns; allowed "
                               "without that lift_file"))
    return out


def problems(spec) -> list[Problem]:
    """The problems across the sections of a specification whose every field is valid, one message each ([] if
    none): angles that must add up, a throat smaller than the bore, files and keys that must agree, ...."""
    out = [p for name, v in spec.valves.items() for p in _valve_problems(name, v, spec.engine)]
    out += _crank_problems(spec) + _two_stroke_problems(spec) + _camshaft_problems(spec) + _acceptance_problems(spec)
    out += _breathing_problems(spec) + _phaser_problems(spec)
    if spec.engine.strokes != 4 and spec.valves:
        out.insert(0, Problem("engine.strokes", "the valve timing (opens_deg/closes_deg before and after TDC/BDC of "
                              "the gas-exchange strokes) is defined for four-stroke engines; allowed 4 with "
                              "[valves.NAME] sections", f"{spec.engine.strokes}"))
    return out


def set_keys(document, values) -> dict[str, Any]:
    """A deep copy of a specification ``document`` (a dict of TOML tables) with the dotted keys of ``values`` set.

    A key is the path of TOML tables, then the key (``engine.bore_mm``, ``valves.intake.cam.shape_factor``); tables
    on the path that the document lacks are made, except a valve it does not have.  The copy is not validated.

    Parameters
    ----------
    document : dict
    values : dict
        Dotted key -> value.

    Returns
    -------
    dict

    Raises
    ------
    ValueError
        A key naming a valve the document lacks, passing through a value, or naming a table; the message starts
        with the key.
    """
    out = copy.deepcopy(document)
    for key, value in values.items():
        parts = key.split(".")
        if not all(parts):
            raise InputError(Problem(key, "an empty name in the dotted key"))
        node = out
        for i, part in enumerate(parts[:-1]):
            if part not in node:
                if i == 1 and parts[0] == "valves":
                    raise InputError(Problem(key, f"the specification has no valve {part!r} (valves: "
                                             f"{', '.join(node) or 'none'})"))
                node[part] = {}
            node = node[part]
            if isinstance(node, list):
                raise InputError(Problem(key, f"{'.'.join(parts[:i + 1])} is an array, not a table: a dotted key "
                                         "does not reach into it; set the whole array"))
            if not isinstance(node, dict):
                raise InputError(Problem(key, f"{'.'.join(parts[:i + 1])} is a value, not a table"))
        if isinstance(node.get(parts[-1]), dict):
            raise InputError(Problem(key, "a table, not a value; give one of its keys"))
        node[parts[-1]] = value
    return out


def spec_document(spec) -> dict[str, Any]:
    """The document of a :class:`Spec` (a dict of its tables, every default written out) that :func:`validate`
    turns back into the same specification."""
    return {**spec.model_dump(), "source_dir": spec.source_dir}
