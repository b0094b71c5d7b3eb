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
from ..locale import NoteText, note
from ..springs import feasible_mean_diameters, shortest_solid_length
from ..units import MM
from .cam_base import main_half_angle_deg
from .messages import Problem, shown
from .si import si


def _valve_problems(name, v, engine):
    at = f"valves.{name}"
    missing = [k for k in ("max_lift_mm", "opens_deg", "closes_deg") if getattr(v, k) is None]
    if missing and v.cam.needs_timing:
        return [Problem(f"{at}.{k}", NoteText.of("spec.timing_missing")) for k in missing]
    out = []
    if len({"opens_deg", "closes_deg"} & set(missing)) == 1:
        given, other = ("opens_deg", "closes_deg") if v.closes_deg is None else ("closes_deg", "opens_deg")
        return [Problem(f"{at}.{given}", NoteText.of("spec.timing_pair", other=other), f"{getattr(v, given):g}", " ")]
    if v.throat_diameter_mm >= engine.bore_mm:
        out.append(Problem(f"{at}.throat_diameter_mm", NoteText.of("spec.throat_bore", bore=engine.bore_mm),
                           f"{v.throat_diameter_mm:g}", " "))
    stem = v.parts.stem_diameter_mm
    if stem is not None and stem >= v.throat_diameter_mm:
        out.append(Problem(f"{at}.parts.stem_diameter_mm", NoteText.of("spec.stem_throat", throat=v.throat_diameter_mm),
                           f"{stem:g}", " "))
    if v.cam.base_radius_mm <= v.clearance_mm:
        out.append(Problem(f"{at}.cam.base_radius_mm",
                           NoteText.of("spec.base_radius_clearance", clearance=v.clearance_mm),
                           f"{v.cam.base_radius_mm:g}", " "))
    if v.lash_adjuster is not None and v.clearance_mm != 0.0:
        out.append(Problem(f"{at}.clearance_mm", NoteText.of("spec.adjuster_clearance"), f"{v.clearance_mm:g}"))
    axis = None if v.lash_adjuster is None else v.lash_adjuster.axis_angle_deg
    if axis is not None and (v.lash_adjuster.location != "pivot" or not FOLLOWERS[v.cam.follower].pivot_axis):
        out.append(Problem(f"{at}.lash_adjuster.axis_angle_deg", NoteText.of("spec.adjuster_axis"), f"{axis:g}", " "))
    if v.switching is not None and not FOLLOWERS[v.cam.follower].switchable:
        out.append(Problem(f"{at}.switching", NoteText.of("spec.switching_finger", follower=repr(v.cam.follower))))
    low = None if v.switching is None else v.switching.low_lobe
    if low is not None and v.max_lift_mm is not None and low.max_lift_mm >= v.max_lift_mm:
        out.append(Problem(f"{at}.switching.low_lobe.max_lift_mm", NoteText.of("spec.low_lobe", lift=v.max_lift_mm),
                           f"{low.max_lift_mm:g}"))
    if v.switching is not None and v.switching.compression_ratio is not None and engine.rod_length_mm is None:
        out.append(Problem(f"{at}.switching.compression_ratio", NoteText.of("spec.deactivated_rod"),
                           f"{v.switching.compression_ratio:g}", " "))
    ratio = v.spring.mean_diameter_ratio
    wires = v.spring.wire_diameter_range_mm
    low, high = (x / MM for x in feasible_mean_diameters(wires))
    if ratio[1] * v.throat_diameter_mm < low or ratio[0] * v.throat_diameter_mm > high:
        out.append(Problem(f"{at}.spring.mean_diameter_ratio", NoteText.of(
            "spec.spring_diameters", throat=v.throat_diameter_mm, smallest=ratio[0] * v.throat_diameter_mm,
            largest=ratio[1] * v.throat_diameter_mm, thinnest=wires[0], thickest=wires[1], low=low, high=high),
                           f"{list(ratio)}", " "))
    out += [p.within(at) for p in spring_length_problems(v.spring, v.max_lift_mm)]
    if (v.drive.layout is not None and not any(link.lever for link in LAYOUTS[v.drive.layout].links)
            and v.rocker_ratio != 1.0):
        out.append(Problem(f"{at}.drive.layout", NoteText.of("spec.layout_ratio", ratio=v.rocker_ratio),
                           f"\"{v.drive.layout}\"", " "))
    if FOLLOWERS[v.cam.follower].geometric_lever:
        if v.rocker_ratio != 1.0:
            out.append(Problem(f"{at}.rocker_ratio", NoteText.of("spec.finger_ratio", follower=v.cam.follower),
                               f"{v.rocker_ratio:g}"))
        if v.max_lift_mm is not None:
            problem = FOLLOWERS[v.cam.follower].from_cam(si(v.cam)).geometry_problem(
                (v.cam.base_radius_mm - v.clearance_mm) * MM, v.max_lift_mm * MM + v.clearance_mm * MM)
            if problem:
                key, value, message, joiner = problem
                out.append(Problem(f"{at}.cam.{key}", message, value, joiner))
        if v.drive.layout != "rocker":
            out.append(Problem(f"{at}.drive.layout", NoteText.of("spec.finger_layout", follower=v.cam.follower),
                               shown(v.drive.layout)))
        if v.drive.valve_arm_mm is not None:
            out.append(Problem(f"{at}.drive.valve_arm_mm", NoteText.of("spec.finger_arm", follower=v.cam.follower),
                               f"{v.drive.valve_arm_mm:g}"))
    elif v.drive.masses is not None and v.drive.masses.rocker_inertia_kg_mm2 > 0 and v.drive.valve_arm_mm is None:
        out.append(Problem(f"{at}.drive.masses.rocker_inertia_kg_mm2", NoteText.of("spec.rocker_arm"),
                           f"{v.drive.masses.rocker_inertia_kg_mm2:g}"))
    if v.lubrication is not None and v.parts.cam_width_mm is None:
        out.append(Problem(f"{at}.lubrication", NoteText.of("spec.cam_width", key=f"{at}.parts.cam_width_mm"),
                           joiner=" "))
    if v.piston_gap_tdc_mm is not None and engine.rod_length_mm is None:
        out.append(Problem(f"{at}.piston_gap_tdc_mm", NoteText.of("spec.piston_rod"), joiner=" "))
    if not {"opens_deg", "closes_deg"} & set(missing):
        half = main_half_angle_deg(v, engine.strokes)
        if not 0.0 < half < 180.0:
            event = NoteText.of("spec.event_range")
            out.append(Problem(f"{at}.opens_deg", event, f"{v.opens_deg + v.closes_deg:g}",
                               text=f"{at}.opens_deg + closes_deg = {v.opens_deg + v.closes_deg:g}: {event}"))
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
    lift_key : str or tuple
        What the lift is called in the messages: a key, or a note (:func:`valvetrain.locale.note`).
    """
    installed, free, out = spring.installed_length_mm, spring.max_free_length_mm, []
    below = []
    if lift_mm is not None:
        wire, per_wire = spring.wire_diameter_range_mm[0], shortest_solid_length(1.0)
        least = note("spec.solid_at_lift", lift_key=lift_key, per_wire=per_wire, lift=lift_mm, wire=wire)
        below.append((least, lift_mm + per_wire * wire))
        if installed is not None and installed[1] <= below[0][1]:
            out.append(Problem("spring.installed_length_mm", NoteText.of("spec.installed_solid", least=least,
                                                                         length=below[0][1]), f"{list(installed)}"))
    if installed is not None:
        below.append((note("spec.shortest_installed"), installed[0]))
    if free is not None and below and free <= max(length for _, length in below):
        bounds = sum((note("spec.bound", name=name, length=length) for name, length in below), ())
        out.append(Problem("spring.max_free_length_mm", NoteText.of("spec.free_length", bounds=bounds), f"{free:g}"))
    return out


def _same(spec, key_crank, key_engine):
    """A [crank] value that defaults to [engine]'s; a problem message when both are given and differ."""
    a, b = getattr(spec.crank, key_crank) if spec.crank else None, getattr(spec.engine, key_engine)
    if a is not None and b is not None and abs(a - b) > 1e-9 * max(abs(a), abs(b)):
        return a, [Problem(f"crank.{key_crank}", NoteText.of("spec.differs", key=f"engine.{key_engine}", value=b),
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
        out.append(Problem("crank.rod_length_mm", NoteText.of("spec.crank_rod"), joiner=" "))
    elif rod <= stroke / 2.0:
        out.append(Problem("crank.rod_length_mm", NoteText.of("spec.rod_radius", radius=stroke / 2.0), f"{rod:g}", " "))
    c = spec.crank
    if c is None:
        return out
    if rod is not None and rod > stroke / 2.0 and abs(c.offset_mm) >= rod - stroke / 2.0:
        out.append(Problem("crank.offset_mm", NoteText.of("spec.offset", most=rod - stroke / 2.0), f"{c.offset_mm:g}"))
    cycle = 180.0 * spec.engine.strokes
    n = cycle / c.step_deg
    if abs(n - round(n)) > 1e-9:
        out.append(Problem("crank.step_deg", NoteText.of("spec.step", cycle=cycle), f"{c.step_deg:g}", " "))
    return out


def _two_stroke_problems(spec):
    ts = spec.two_stroke
    if ts is None:
        return []
    out = []
    if spec.engine.strokes != 2:
        needs = NoteText.of("spec.two_stroke_strokes", strokes=spec.engine.strokes)
        out.append(Problem("engine.strokes", needs, f"{spec.engine.strokes}", text=f"[two_stroke] {needs}"))
    if not ts.ports:
        needs = NoteText.of("spec.no_ports")
        out.append(Problem("two_stroke.ports", needs, text=f"[two_stroke] {needs}"))
    bore, stroke = crank_geometry(spec)[:2]
    for name, port in ts.ports.items():
        if port.width_mm >= math.pi * bore:
            out.append(Problem(f"two_stroke.ports.{name}.width_mm", NoteText.of("spec.port_width", most=math.pi * bore),
                               f"{port.width_mm:g}"))
        if port.height_mm is not None and port.kind != "inlet" and port.height_mm >= stroke:
            out.append(Problem(f"two_stroke.ports.{name}.height_mm", NoteText.of("spec.port_height", stroke=stroke),
                               f"{port.height_mm:g}", " "))
        if port.kind == "inlet" and ts.piston_height_mm is None:
            out.append(Problem(f"two_stroke.ports.{name}", NoteText.of("spec.inlet_piston")))
        elif port.kind == "inlet" and not ts.piston_height_mm < port.lower_edge_mm < ts.piston_height_mm + stroke:
            out.append(Problem(f"two_stroke.ports.{name}.lower_edge_mm", NoteText.of(
                "spec.lower_edge", piston=ts.piston_height_mm, top=ts.piston_height_mm + stroke),
                               f"{port.lower_edge_mm:g}"))
    if ts.speed_range_rpm is not None and ts.speed_range_rpm[0] >= ts.speed_range_rpm[1]:
        out.append(Problem("two_stroke.speed_range_rpm", NoteText.of("spec.low_high"), f"{list(ts.speed_range_rpm)}",
                           " "))
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
        out.append(Problem("engine.strokes", NoteText.of("spec.breathing_strokes"), f"{spec.engine.strokes}"))
    if crank_geometry(spec)[2] is None:
        out.append(Problem("engine.rod_length_mm", NoteText.of("spec.breathing_rod"), joiner=" "))
    if b.compression_ratio is None and (spec.crank is None or spec.crank.compression_ratio is None):
        out.append(Problem("breathing.compression_ratio",
                           NoteText.of("spec.required_or", other="crank.compression_ratio"), joiner=" "))
    if b.mode == "fired" and (spec.crank is None or spec.crank.cycle is None):
        out.append(Problem("breathing.mode", NoteText.of("spec.fired"), "'fired'"))
    kinds = {v.kind for v in spec.valves.values()}
    for side in ("intake", "exhaust"):
        s = getattr(b, side)
        if s.lift_file is None and side not in kinds:
            out.append(Problem(f"breathing.{side}.lift_file", NoteText.of("spec.lift_file", side=side), joiner=" "))
        if s.lift is not None and s.lift_file is not None:
            out.append(Problem(f"breathing.{side}.lift", NoteText.of("spec.lift_or_file"), f"'{s.lift}'"))
        elif s.lift == "dynamics":
            bare = [name for name, v in spec.valves.items() if v.kind == side and v.dynamics is None]
            if bare:
                out.append(Problem(f"breathing.{side}.lift", NoteText.of(
                    "spec.lift_dynamics", side=side, bare=", ".join(f"[valves.{n}]" for n in bare)), "'dynamics'"))
        if s.lift_file is not None and s.cd_file is None:
            out.append(Problem(f"breathing.{side}.cd_file", NoteText.of("spec.cd_file"), joiner=" "))
    walls = [("curve", b.curve)] if b.curve is not None else []
    walls += [(f"conditions.{i}", c) for i, c in enumerate(b.conditions)]
    for where, c in walls:
        if c.wall_temperature_C is None and b.wall_temperature_C is None:
            out.append(Problem(f"breathing.{where}.wall_temperature_C",
                               NoteText.of("spec.required_or", other="breathing.wall_temperature_C"), joiner=" "))
    return out


def _acceptance_problems(spec):
    """An [[accepted]] table naming a valve the specification does not have."""
    said = (NoteText.of("spec.allowed_names", names=", ".join(repr(n) for n in spec.valves)) if spec.valves
            else NoteText.of("spec.no_valves"))
    return [Problem(f"accepted.{i}.valve", said, shown(a.valve, 40))
            for i, a in enumerate(spec.accepted) if a.valve is not None and a.valve not in spec.valves]


def _camshaft_problems(spec):
    """[camshaft] against the engine and the valves: the valves it names exist, its cylinders are the engine's,
    one position per cylinder."""
    c = spec.camshaft
    if c is None:
        return []
    out = []
    if not spec.valves:
        out.append(Problem("camshaft", NoteText.of("spec.camshaft_valves")))
    missing = [n for n in (c.valves or []) if n not in spec.valves]
    if missing or c.valves == []:
        out.append(Problem("camshaft.valves", NoteText.of("spec.valve_list", valves=f"{sorted(spec.valves)}"),
                           f"{c.valves}"))
    n = spec.engine.cylinders
    cylinders = c.cylinders if c.cylinders is not None else list(range(1, n + 1))
    if not cylinders or len(set(cylinders)) != len(cylinders) or max(cylinders) > n:
        out.append(Problem("camshaft.cylinders", NoteText.of("spec.cylinders", count=n), f"{c.cylinders}"))
    elif c.cylinders is None and len(c.cylinder_positions_mm) != n:
        out.append(Problem("camshaft.cylinder_positions_mm",
                           NoteText.of("spec.positions", entries=len(c.cylinder_positions_mm), count=n), joiner=" "))
    carried = [name for name in (c.valves or spec.valves) if name in spec.valves]
    if len({spec.valves[name].phaser for name in carried}) > 1:
        phased = [name for name in carried if spec.valves[name].phaser is not None]
        out.append(Problem("camshaft.valves", NoteText.of("spec.phased_camshaft", phased=", ".join(phased)),
                           f"{carried}"))
    return out


def _phaser_problems(spec):
    """A valve's [phaser] against the breathing: the phased valve's designed lift is what breathes."""
    out = []
    for name, v in spec.valves.items():
        side = None if spec.breathing is None else getattr(spec.breathing, v.kind)
        if v.phaser is not None and side is not None and side.lift_file is not None:
            out.append(Problem(f"valves.{name}.phaser", NoteText.of("spec.phaser_measured", side=v.kind)))
    return out


def problems(spec) -> list[Problem]:
    """The problems across the sections of a specification whose every field is valid, one message each ([] if
    none): angles that must add up, a throat smaller than the bore, files and keys that must agree, ...."""
    out = [p for name, v in spec.valves.items() for p in _valve_problems(name, v, spec.engine)]
    out += _crank_problems(spec) + _two_stroke_problems(spec) + _camshaft_problems(spec) + _acceptance_problems(spec)
    out += _breathing_problems(spec) + _phaser_problems(spec)
    if spec.engine.strokes != 4 and spec.valves:
        out.insert(0, Problem("engine.strokes", NoteText.of("spec.valve_strokes"), f"{spec.engine.strokes}"))
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
            raise InputError(Problem(key, NoteText.of("spec.empty_name")))
        node = out
        for i, part in enumerate(parts[:-1]):
            if part not in node:
                if i == 1 and parts[0] == "valves":
                    raise InputError(Problem(key, NoteText.of("spec.no_such_valve", valve=repr(part),
                                                              valves=", ".join(node) or "none")))
                node[part] = {}
            node = node[part]
            if isinstance(node, list):
                raise InputError(Problem(key, NoteText.of("spec.key_in_array", table=".".join(parts[:i + 1]))))
            if not isinstance(node, dict):
                raise InputError(Problem(key, NoteText.of("spec.key_in_value", table=".".join(parts[:i + 1]))))
        if isinstance(node.get(parts[-1]), dict):
            raise InputError(Problem(key, NoteText.of("spec.table_not_value")))
        node[parts[-1]] = value
    return out


def spec_document(spec) -> dict[str, Any]:
    """The document of a :class:`Spec` (a dict of its tables, every default written out) that :func:`validate`
    turns back into the same specification."""
    return {**spec.model_dump(), "source_dir": spec.source_dir}
