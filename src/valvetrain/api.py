"""The JSON-in, JSON-out entry point: a specification as a plain dict in, results and plot series as plain data out.

Notebooks, scripts in other languages (through a JSON pipe) and the browser designer (:mod:`valvetrain.web`) call
these functions instead of the batch program's files: nothing is read or written on disk (a lift table or an
indicator diagram named in the specification is read from its ``source_dir``, as ``valvetrain run`` reads it).

* :func:`design` ``(spec) -> {"ok", "errors", "results", "series"}``: the design of ``valvetrain run``;
* :func:`sweep` ``(spec) -> {"ok", "errors", "sweeps"}``: the speed sweep of ``valvetrain sweep`` (jump and bounce
  speeds, seating velocity, contact force and the map of the lift error over angle and speed);
* :func:`toml_text` ``(spec) -> str``: the specification as the TOML that ``valvetrain run`` reads back;
* :func:`report_html` ``(spec, lang) -> str``: the design report (tables and checks) as HTML text.

The dict is the structure of the TOML file (``{"engine": {...}, "valves": {"intake": {...}}, ...}``, as
:func:`tomllib.loads` gives it).  Every number out is a plain float in the display unit named in its key (mm, deg,
rpm, m/s, N); a value that is not finite is ``None``.  A specification that cannot be designed is no exception
here: ``ok`` is false and ``errors`` holds one record per problem, ``{"path", "value", "message", "text"}`` (the
dotted key, the value given as the message shows it or ``None``, what is allowed, and the whole line as the
command line prints it).
"""

import json
import math
from typing import Any

import numpy as np

from .export import json_text
from .specification import SpecError, spec_toml, validate
from .units import MM, rad_to_deg, to_display

def error_records(err) -> list[dict[str, Any]]:
    """The problems of a :class:`~valvetrain.specification.SpecError` as records ``{"path", "value", "message",
    "text"}`` (each :class:`~valvetrain.specification.messages.Problem`'s parts, made where it was found); a problem
    that names no key has the path ``""``."""
    return [{"path": p.path, "value": p.value, "message": p.message, "text": str(p)} for p in err.problems]


def plain(data) -> Any:
    """Nested dicts, lists, numpy arrays and numbers as strict JSON data (a value that is not finite is None)."""
    if isinstance(data, dict):
        return {k: plain(v) for k, v in data.items()}
    if isinstance(data, np.ndarray) and data.dtype.kind == "f":
        finite = np.isfinite(data)
        if finite.all():
            return data.tolist()                 # numpy's own conversion: a tenth of the time of an object array's
        out = data.astype(object)
        out[~finite] = None
        return out.tolist()
    if isinstance(data, (list, tuple, np.ndarray)):
        return [plain(v) for v in data]
    if isinstance(data, np.generic):
        data = data.item()
    if isinstance(data, float):
        return data if math.isfinite(data) else None
    if data is None or isinstance(data, (str, bool, int)):
        return data
    return json.loads(json_text(data))


def _column(x, unit=None):
    return np.asarray(x if unit is None else to_display(np.asarray(x), unit), dtype=float)


def valve_series(v) -> dict[str, Any]:
    """The plot series of one :class:`~valvetrain.design.ValveDesign` (display units in the keys).

    Kinematics against the camshaft angle from the nose (the tappet's lift and the valve's; the tappet's
    velocity, acceleration and jerk at the rated speed times the rocker ratio: the valve's while it is off its
    seat, on a ramp the motion that closes the clearance), the law's segment boundaries, the radius of
    curvature, the curtain area and the running time-area against the crank angle from the gas-exchange TDC, the
    contour (cam frame, nose on +y) with its heel circle, and the spring's required force and chosen line against
    the valve lift; a lost-motion drive's valve lift of the full lift and of each solenoid timing against the cycle
    crank angle (:func:`lost_motion_series`).
    """
    drive = v.drive
    order = np.argsort(drive.lift)
    lift = np.asarray(drive.lift)[order]
    top = np.array([0.0, float(lift.max())])
    chosen = drive.lines.chosen
    return {
        **kinematic_series(v.cam, v.profile),
        "spring_lift_mm": lift / MM,
        "required_force_N": _column(drive.required_force)[order],
        "spring_line_lift_mm": top / MM,
        "spring_line_force_N": _column(chosen.force(top)),
        **(lost_motion_series(v) if v.lost_motion is not None else {}),
    }


def lost_motion_series(v) -> dict[str, Any]:
    """The series of a lost-motion drive (the report's figure's, :func:`~valvetrain.report.hydraulic_plots.
    lost_motion_data`): ``lost_motion_crank_deg`` the cycle crank angle, ``lost_motion_valve_lift_mm`` the valve
    lift of each run (rows: the full lift, then each solenoid timing), ``lost_motion_opens_crank_deg`` each run's
    solenoid opening (None: the full lift)."""
    from .report.hydraulic_plots import lost_motion_data

    d = lost_motion_data(v)
    return {"lost_motion_crank_deg": d["crank_deg"], "lost_motion_opens_crank_deg": [at for at, _, _ in d["runs"]],
            "lost_motion_valve_lift_mm": [lift for _, lift, _ in d["runs"]]}


def kinematic_series(cam, profile) -> dict[str, Any]:
    """The series of :func:`valve_series` that the kinematic stages give (a valve's
    :class:`~valvetrain.design.valve.CamResult` and :class:`~valvetrain.design.valve.ProfileResult`): all but the
    spring's."""
    tab, i = profile.table, cam.rocker_ratio
    return {
        "cam_deg": rad_to_deg(tab.cam_angle),
        "crank_deg": rad_to_deg(cam.nose + 2.0 * tab.cam_angle),
        "tappet_lift_mm": _column(tab.lift) / MM,
        "valve_lift_mm": _column(tab.valve_lift) / MM,
        "valve_velocity_m_s": i * _column(tab.velocity),
        "valve_acceleration_m_s2": i * _column(tab.acceleration),
        "valve_jerk_m_s3": i * _column(tab.jerk),
        "segments_cam_deg": rad_to_deg(np.asarray(cam.law.breakpoints)),
        "rho_mm": _column(tab.rho) / MM,
        "curtain_area_mm2": _column(tab.curtain_area) / MM**2,
        "time_area_mm2_s": _column(tab.time_area) / MM**2,
        "contour_x_mm": _column(profile.contour[0]) / MM,
        "contour_y_mm": _column(profile.contour[1]) / MM,
        "heel_radius_mm": cam.heel_radius / MM,
    }


def kinematics(spec, name) -> dict[str, Any]:
    """The lift curves and contour of valve ``name`` alone, a fraction of :func:`design`'s time: its law, flow and
    profile stages (:func:`valvetrain.design.valve_kinematics`), validated whole, without its drive, springs and
    checks and without the other valves (the designer's answer while a handle is dragged; :func:`design` may
    still refuse the specification for what these stages do not reach, a spring that does not fit).

    Returns
    -------
    dict
        ``ok``, ``errors`` as for :func:`design`; ``series``: ``{name: series}``, the series of :func:`valve_series`
        but the spring's (:func:`kinematic_series`); ``results``: ``{"valves": {name: {"cam": ..., "flow": ...}}}``,
        the records of the valve's cam and flow in results.json (None when not ok).
    """
    from .design import valve_kinematics
    from .design.results import record

    parsed, errors = _parsed(spec)
    if parsed is None:
        return {"ok": False, "errors": errors, "results": None, "series": None}
    try:
        cam, flow, profile = valve_kinematics(parsed, name)
    except SpecError as err:
        return {"ok": False, "errors": error_records(err), "results": None, "series": None}
    return {"ok": True, "errors": [], "series": plain({name: kinematic_series(cam, profile)}),
            "results": plain({"valves": {name: {"cam": record(cam), "flow": record(flow)}}})}


def _parsed(spec):
    """The validated :class:`~valvetrain.specification.Spec` of a dict, or the error records."""
    if not isinstance(spec, dict):
        return None, [{"path": "", "value": None, "message": f"a dict of the specification's tables is needed, not a "
                       f"{type(spec).__name__}", "text": ""}]
    try:
        return validate(spec), []
    except SpecError as err:
        return None, error_records(err)


def without_dynamics(spec, parsed) -> dict[str, Any]:
    """A specification dict without its valves' ``[dynamics]`` sections and without the acceptances of the dynamics
    checks (which would name no check of it); ``parsed`` is its validated :class:`~valvetrain.specification.Spec`."""
    from .checks import resolve
    from .design.dynamics_checks import CHECK_CODES

    kept = [a for a, p in zip(spec.get("accepted", []), parsed.accepted, strict=True)
            if (resolve(p, parsed.valves) or (None, None, None))[1] not in CHECK_CODES]
    out = {**spec, "valves": {n: {k: v for k, v in valve.items() if k != "dynamics"}
                              for n, valve in spec.get("valves", {}).items()}}
    if "accepted" in spec:
        out["accepted"] = kept
    return out


def design(spec, dynamics=True, sweeps=False, progress=None, diagnose=True, memo=None) -> dict[str, Any]:
    """Design a specification given as a dict: what ``valvetrain run`` computes, as plain data.

    Parameters
    ----------
    spec : dict
        The tables of a specification, as :func:`tomllib.loads` gives them (lengths in mm, angles in deg, speeds
        in rpm, as the keys say).
    dynamics : bool
        False: validated whole, designed without the valves' ``[dynamics]`` sections (:func:`without_dynamics`):
        the kinematics, springs and checks without the speed sweeps, whose time they spare (the strength then
        rests on the quasi-static loads); the designer's first answer to an edit.
    sweeps : bool
        Add ``sweeps``: the speed-sweep series (:func:`sweep_series`) of each valve designed with its
        ``[dynamics]`` section, the same as :func:`sweep` gives for it, from the same run.
    progress : callable, optional
        ``progress(valve name, done, total)`` between speeds of a sweep; an exception it raises ends the design.
    diagnose : bool
        False: springs that do not pass are not diagnosed (:func:`valvetrain.design.run`; their checks fail the
        same, without the diagnosis and its remedies, each a new spring search: about a second).
    memo : dict, optional
        The valves' designs kept between calls (:func:`valvetrain.design.run`): an unchanged valve is not designed
        again.

    Returns
    -------
    dict
        ``ok`` (bool); ``errors`` (list of ``{"path", "value", "message", "text"}``, empty when ok); ``results``
        (the dictionary of results.json, None when not ok); ``series`` (``valve name -> plot series``, see
        :func:`valve_series`; None when not ok); with ``sweeps``, ``sweeps`` (None when not ok).
    """
    from .design import run

    parsed, errors = _parsed(spec)
    if parsed is not None and not dynamics:
        parsed, errors = _parsed(without_dynamics(spec, parsed))
    extra = {"sweeps": None} if sweeps else {}
    if parsed is None:
        return {"ok": False, "errors": errors, "results": None, "series": None, **extra}
    try:
        results = run(parsed, progress=progress, diagnose=diagnose, memo=memo)
    except SpecError as err:
        return {"ok": False, "errors": error_records(err), "results": None, "series": None, **extra}
    if sweeps:
        extra["sweeps"] = plain({n: sweep_series(v.dynamics) for n, v in results.valves.items()
                                 if v.dynamics is not None})
    return {"ok": True, "errors": [], "results": plain(results.to_dict()),
            "series": plain({name: valve_series(v) for name, v in results.valves.items()}), **extra}


MAP_COLUMNS = 400
"""About how many camshaft angles the map of the lift error keeps (every k-th of the sweep's grid): a picture's width."""


def sweep_series(d) -> dict[str, Any]:
    """The speed-sweep series of one valve's :class:`~valvetrain.design.dynamics_records.DynamicsResult`: per speed the
    smallest contact force, the seating velocity (None where the valve did not seat), the bounce; the headline
    speeds; the maps of the valve-lift error (valve lift minus the rigid lift, mm), the cam contact force (N) and
    the valve's acceleration (m/s²) over the camshaft angles of the event (every speed's open stretch and 10 cam
    deg either side, thinned to about :data:`MAP_COLUMNS`) and the speeds."""
    from .design.dynamics_records import event_window

    sw, keep = d.sweep, event_window(d)
    step = max(1, int(np.count_nonzero(keep)) // MAP_COLUMNS)
    p = d.per_speed
    return {
        "speed_rpm": to_display(np.asarray(p.speed), "rpm"),
        "min_contact_force_N": list(p.min_contact_force),
        "seating_velocity_m_s": list(p.seating_velocity),
        "bounce_mm": np.asarray(p.bounce) / MM,
        "jump_speed_rpm": to_display(d.jump_speed, "rpm"),
        "bounce_speed_rpm": to_display(d.bounce_speed, "rpm"),
        "rated_speed_rpm": to_display(d.at_rated_speed.speed, "rpm"),
        "map_cam_deg": rad_to_deg(sw.theta[keep][::step]),
        "map_lift_error_mm": sw.lift_error[:, keep][:, ::step] / MM,
        "map_contact_force_N": sw.contact_force[:, keep][:, ::step],
        "map_valve_acceleration_m_s2": sw.acceleration[:, keep][:, ::step],
    }


def sweep(spec, progress=None, names=None, memo=None) -> dict[str, Any]:
    """The speed sweep of a specification given as a dict: what ``valvetrain sweep`` computes, as plain data.

    Parameters
    ----------
    spec : dict
        As for :func:`design`.  The valves with a ``[dynamics]`` section are swept (every valve with the default
        section where none has one).
    progress : callable, optional
        ``progress(valve name, done, total)`` between speeds; an exception it raises ends the sweep (the
        designer's way of dropping a sweep that a newer change made stale).
    names : sequence of str, optional
        Sweep these valves only (``valvetrain sweep --valve``), each with its section or the default one.
    memo : dict, optional
        The valves' designs kept between calls (:func:`valvetrain.design.sweep_designs`): a valve swept before with
        the same inputs is not swept again; a :func:`design` with ``sweeps`` and this memo takes the valves swept.

    Returns
    -------
    dict
        ``ok``, ``errors`` as for :func:`design`; ``sweeps``: ``valve name -> series`` (:func:`sweep_series`).
    """
    from .design import sweep_designs

    parsed, errors = _parsed(spec)
    if parsed is None:
        return {"ok": False, "errors": errors, "sweeps": None}
    try:
        valves = sweep_designs(parsed, names, progress=progress, memo=memo)
    except SpecError as err:
        return {"ok": False, "errors": error_records(err), "sweeps": None}
    return {"ok": True, "errors": [], "sweeps": plain({n: sweep_series(v.dynamics) for n, v in valves.items()})}


def report_html(spec, lang="en", figures="none") -> str:
    """The design report of a specification (a dict) as HTML text, in ``lang`` ("en" or "ru"): the report that
    ``valvetrain run`` writes, its tables and checks, with the figures of ``figures`` (as ``valvetrain run
    --figures``: "main", "all" or "none") drawn in memory and embedded (nothing is written to disk; without them the
    report names the command that draws them).

    Raises
    ------
    SpecError
        The specification does not validate or does not design.
    """
    from .design import run
    from .report.html import render_report
    from .report.plots import write_plots

    results = run(validate(spec))
    images = {}
    return render_report(results, write_plots(results, images, lang, figures), lang, images)


def toml_text(spec) -> str:
    """The specification (a dict) as TOML text, every default written out: ``valvetrain run`` reads it back to the
    same design.

    Raises
    ------
    SpecError
        The specification does not validate.
    """
    return spec_toml(validate(spec))
