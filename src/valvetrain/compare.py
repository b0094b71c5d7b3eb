"""Side-by-side comparison of lift laws (issue 5: ``valvetrain compare``).

Each valve of each specification becomes one column: time-area, fullness, extreme
kinematics, curvature, contact stress and the required spring, computed by the same
design chain as ``valvetrain run``.  The laws should be compared at equal lift and
duration (Valve-train dynamics article (n.d.) compares its three profiles so); the table states both, and
:func:`comparison` flags entries that differ by more than 1 % in lift or by more than 1 deg in
the duration at 1 mm valve lift (a checking height that every law, measured ones included,
defines the same way).

The dynamics rows (Valve-train dynamics article (n.d.): the comparative dynamics of cam profiles) put each
valve's elastic train beside its cam: the maximum drive load, the spring, the reduced mass, the drive
stiffness, the natural frequency, the resonant harmonic k and the distortion delta at the rated speed,
and the jump speed of a short one-mass sweep (:data:`COMPARE_SPEEDS` speeds over the valve's
``[dynamics]`` range, or the default range).  :func:`with_dynamics` sets that sweep up.
"""

from typing import Any

import numpy as np

from .specification.models import Spec
from .units import MM, rad_to_deg, rpm_to_rad_s

METRICS = [
    ("law", "law"),
    ("valve_lift_mm", "valve lift, mm"),
    ("duration_cam_deg", "valve-open duration, cam deg"),
    ("duration_1mm_cam_deg", "duration at 1 mm valve lift, cam deg"),
    ("time_area_mm2_s", "time-area over the stroke, mm2 s"),
    ("time_area_open_mm2_s", "time-area over the opening, mm2 s"),
    ("fullness", "fullness"),
    ("max_velocity_m_s", "max tappet velocity, m/s"),
    ("max_acceleration_m_s2", "max tappet acceleration, m/s2"),
    ("min_acceleration_m_s2", "min tappet acceleration, m/s2"),
    ("max_jerk_m_s3", "max |tappet jerk|, m/s3 (∞ where the acceleration steps: the jerk is an impulse there)"),
    ("acceleration_steps", "steps of the tappet acceleration, m/s2 at cam deg from the nose"),
    ("rho_min_mm", "min radius of curvature, mm"),
    ("max_pressure_angle_deg", "max pressure angle, deg"),
    ("max_contact_stress_MPa", "max cam contact stress, MPa (empty: not computed, no parts.cam_width_mm)"),
    ("required_spring_max_N", "required spring force at full lift, N"),
    ("required_spring_preload_N", "required preload, N"),
]
"""Rows of the comparison of the cams, with their labels."""

DYNAMICS_METRICS = [
    ("max_drive_load_N", "max drive load F0 + K y + M j at the rated speed (kinetostatic, at the valve), N"),
    ("max_dynamic_contact_force_N", "max cam contact force at the rated speed (simulated, at the cam), N"),
    ("spring_preload_N", "spring preload F0 of the train, N"),
    ("spring_rate_N_per_mm", "spring rate K of the train, N/mm"),
    ("reduced_mass_kg", "reduced mass M at the valve, kg"),
    ("drive_stiffness_N_per_mm", "drive stiffness c at the valve, N/mm"),
    ("natural_frequency_Hz", "natural frequency f0 = sqrt((K + c)/M) / 2 pi, Hz"),
    ("harmonic_k", "resonant harmonic k at the rated speed"),
    ("harmonic_force_N", "harmonic force F_k, N"),
    ("amplitude_mm", "elastic amplitude Delta, mm"),
    ("distortion_percent", "distortion delta, %"),
    ("jump_speed_rpm", "jump (float) speed of the one-mass sweep, engine rpm (empty: none in the range)"),
    ("sweep_speed_range_rpm", "speeds swept, engine rpm"),
]
"""Rows of the comparative dynamics (Valve-train dynamics article (n.d.)), with their labels."""

COMPARE_PLOTS = (("lift", 1.0 / MM, "tappet lift, mm"), ("velocity", 1.0, "tappet velocity, m/s"),
                 ("acceleration", 1.0, "tappet acceleration, m/s²"), ("jerk", 1.0, "tappet jerk, m/s³"))
"""The overlaid plots of the cams (``plots/compare_NAME.png``): quantity, scale from SI and axis label."""

COMPARE_SPEEDS = 40
"""Speeds of the one-mass sweep of each compared valve (fewer if its [dynamics] section asks fewer)."""


def duration_at(valve, height) -> float:
    """Camshaft angle [rad] over which the valve lift exceeds ``height`` [m], by root finding on the law."""
    return valve.law.duration(valve.law.ramp_height + height / valve.rocker_ratio)


def step_text(step) -> str:
    """An acceleration step (:class:`valvetrain.design.valve.StepRecord`) for the comparison table."""
    ramp = ", on the ramp" if step.on_ramp else ""
    return f"{step.size:+.4g} m/s2 at {rad_to_deg(step.angle):.4g} cam deg{ramp}"


def max_jerk(valve, theta) -> float | str:
    """The largest |tappet jerk| [m/s^3] on the angles ``theta`` [rad]; where the acceleration steps, the jerk is an
    impulse: ``"∞ (step of ...)"`` with the largest step (the valve's ``cam.acceleration_steps``)."""
    steps = valve.cam.acceleration_steps
    if steps:
        return f"∞ (step of {step_text(max(steps, key=lambda st: abs(st.size)))})"
    return float(np.abs(valve.law.jerk(theta, valve.omega_cam)).max())


def entry(valve) -> dict[str, Any]:
    """The comparison figures of one designed valve (a :class:`valvetrain.design.ValveDesign`)."""
    s = valve.summary
    law = valve.law
    theta = np.linspace(law.start, law.end, 4001)
    stress = s["strength"]["checks"].get("cam_contact_stress")
    return {
        "law": law.name,
        "valve_lift_mm": s["flow"]["valve_lift_mm"],
        "duration_cam_deg": rad_to_deg(law.valve_closes - law.valve_opens),
        "duration_1mm_cam_deg": rad_to_deg(duration_at(valve, 1.0 * MM)),
        "time_area_mm2_s": s["flow"]["time_area_mm2_s"],
        "time_area_open_mm2_s": s["flow"]["time_area_open_mm2_s"],
        "fullness": s["flow"]["fullness"],
        "max_velocity_m_s": s["cam"]["max_velocity_m_s"],
        "max_acceleration_m_s2": s["cam"]["max_acceleration_m_s2"],
        "min_acceleration_m_s2": s["cam"]["min_acceleration_m_s2"],
        "max_jerk_m_s3": max_jerk(valve, theta),
        "acceleration_steps": "; ".join(step_text(st) for st in valve.cam.acceleration_steps) or "none",
        "rho_min_mm": s["cam"]["rho_min_mm"],
        "max_pressure_angle_deg": s["cam"].get("max_pressure_angle_deg", 0.0),
        "max_contact_stress_MPa": stress["value"] if stress else None,
        "required_spring_max_N": s["spring"]["required_max_force_N"],
        "required_spring_preload_N": s["spring"]["required_preload_N"],
    }


def with_dynamics(spec, speeds=COMPARE_SPEEDS) -> Spec:
    """The specification with every valve's ``[dynamics]`` section (or the default one) turned into a short
    one-mass sweep of at most ``speeds`` speeds, for the dynamics rows of the comparison."""
    from .specification.models import Dynamics

    valves = {}
    for name, v in spec.valves.items():
        dyn = v.dynamics if v.dynamics is not None else Dynamics()
        dyn = dyn.model_copy(update={"model": "1dof", "speeds": min(dyn.speeds, speeds)})
        valves[name] = v.model_copy(update={"dynamics": dyn})
    return spec.model_copy(update={"valves": valves})


def max_drive_load(law, cam_speed, rocker_ratio, mass, rate, preload, points=3601) -> float:
    """Largest kinetostatic load of the drive at the valve over the event, max(F0 + K y + M j) [N].

    Parameters
    ----------
    law : valvetrain.laws.base.LiftLaw
        The cam (tappet lift h, rad from the nose).
    cam_speed : float
        Camshaft speed [rad/s].
    rocker_ratio : float
        i_k; the valve lift is y = i_k h and its acceleration j = i_k omega^2 h''.
    mass, rate, preload : float
        Reduced mass M [kg], spring rate K [N/m] and preload F0 [N] at the valve.

    Notes
    -----
    The spring force plus the inertia force of the rigid train (Shang Hanji (1988), eqs. (2.8)-(2.9)); the
    largest value falls in the positive-acceleration phase, the load the article compares the profiles by
    (Valve-train dynamics article (n.d.), aim of the work).

    Examples
    --------
    At rest the load is the spring force at full lift, F0 + K y_max:

    >>> from valvetrain.laws import PolydyneLaw
    >>> law = PolydyneLaw(6e-3, 1.0, 10)
    >>> round(max_drive_load(law, 0.0, 1.5, 0.25, 70e3, 200.0), 6)
    830.0
    """
    theta = np.linspace(law.start, law.end, points)
    h, _, d2h = law.derivatives(theta)[:3]
    return float(np.max(preload + rate * rocker_ratio * h + mass * rocker_ratio * cam_speed**2 * d2h))


def dynamics_entry(valve) -> dict[str, Any]:
    """The comparative-dynamics figures of one designed valve whose ``dynamics`` is set (SI in, display units out)."""
    d = valve.dynamics
    p = d.parameters
    r = d.resonance
    return {
        "max_drive_load_N": max_drive_load(valve.law, valve.omega_cam, p.rocker_ratio, p.mass, p.spring_rate,
                                           p.preload),
        "max_dynamic_contact_force_N": d.at_rated_speed.max_contact_force,
        "spring_preload_N": p.preload,
        "spring_rate_N_per_mm": p.spring_rate * MM,
        "reduced_mass_kg": p.mass,
        "drive_stiffness_N_per_mm": p.drive_stiffness * MM,
        "natural_frequency_Hz": r.natural_frequency,
        "harmonic_k": int(r.order),
        "harmonic_force_N": r.force,
        "amplitude_mm": r.amplitude / MM,
        "distortion_percent": r.distortion,
        "jump_speed_rpm": None if not np.isfinite(d.jump_speed) else d.jump_speed / rpm_to_rad_s(1.0),
        "sweep_speed_range_rpm": f"{d.speed_range[0] / rpm_to_rad_s(1.0):.0f}-{d.speed_range[1] / rpm_to_rad_s(1.0):.0f}"
                                 f" ({d.speeds})",
    }


def comparison(designs) -> tuple[dict[str, dict[str, Any]], list[str]]:
    """Compare designed valves.

    Parameters
    ----------
    designs : dict
        ``label -> ValveDesign``.

    Returns
    -------
    (dict, list of str)
        ``label -> entry`` and notes on entries that are not at equal lift and duration
        with the first one.
    """
    rows = {label: entry(v) | (dynamics_entry(v) if v.dynamics is not None else {}) for label, v in designs.items()}
    notes = []
    first_label, first = next(iter(rows.items()))
    for label, row in rows.items():
        if abs(row["valve_lift_mm"] / first["valve_lift_mm"] - 1.0) > 0.01:
            notes.append(f"{label}: valve lift {row['valve_lift_mm']:.4g} mm differs from {first_label}'s "
                         f"{first['valve_lift_mm']:.4g} mm by more than 1 %")
        if abs(row["duration_1mm_cam_deg"] - first["duration_1mm_cam_deg"]) > 1.0:
            notes.append(f"{label}: duration at 1 mm {row['duration_1mm_cam_deg']:.4g} cam deg differs from "
                         f"{first_label}'s {first['duration_1mm_cam_deg']:.4g} by more than 1 deg")
    return rows, notes


BREATHING_KEYS = ("speed_rpm", "intake_pressure_kPa", "air_mass_flow_g_s", "volumetric_efficiency", "trapped_mass_mg",
                  "residual_gas_fraction", "imep_kPa", "imep_gross_kPa", "pmep_kPa", "peak_pressure_kPa",
                  "peak_pressure_crank_deg", "torque_Nm", "power_kW")
"""Columns of ``compare_breathing.csv``: each condition's figures of the breathing (results.json's keys)."""


def breathing_rows(breathing) -> dict[str, list]:
    """The breathing of each compared specification as the columns of ``compare_breathing.csv``: one row a condition
    (the conditions, then the curve's speeds) of each label, side by side.

    Parameters
    ----------
    breathing : dict
        ``label -> BreathingResults`` (:mod:`valvetrain.design.breathing`).

    Returns
    -------
    dict
        ``column -> values``: ``label``, ``part`` (``conditions`` or ``curve``) and :data:`BREATHING_KEYS` (empty
        where a record has none: the torque of a motored engine).
    """
    out = {"label": [], "part": [], **{k: [] for k in BREATHING_KEYS}}
    for label, b in breathing.items():
        for part in ("conditions", "curve"):
            for record in b.summary[part]:
                out["label"].append(label)
                out["part"].append(part)
                for k in BREATHING_KEYS:
                    out[k].append(record.get(k))
    return out


def _breathing_plot(breathing, path):
    """Volumetric efficiency (and a fired engine's torque) against the speed, one line per compared specification."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8, 6.5))
    top, bottom = fig.subplots(2, 1, sharex=True)
    for label, b in breathing.items():
        records = b.summary["curve"] or b.summary["conditions"]
        speed = [r["speed_rpm"] for r in records]
        style = dict(marker="o", ls="-" if b.summary["curve"] else "none")
        top.plot(speed, [r["volumetric_efficiency"] for r in records], label=label, **style)
        if records and "torque_Nm" in records[0]:
            bottom.plot(speed, [r["torque_Nm"] for r in records], label=label, **style)
    _save_against_speed(fig, top, bottom, "volumetric efficiency", "indicated torque, N m (fired)", path)


def _save_against_speed(fig, top, bottom, top_label, bottom_label, path):
    """Label, grid and save a figure of two quantities against the engine speed."""
    top.set_ylabel(top_label)
    bottom.set_ylabel(bottom_label)
    bottom.set_xlabel("engine speed, rpm")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    top.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def write_comparison(designs, out, inputs=(), force=False, breathing=None) -> tuple[dict[str, dict[str, Any]], list[str]]:
    """Write ``compare.csv``, ``compare.json`` and the overlaid plots into ``out`` atomically; with ``breathing``
    (``label -> BreathingResults`` of the specifications with a [breathing] section) also ``compare_breathing.csv``
    and ``plots/compare_breathing.png``, and the records in ``compare.json``.

    ``inputs`` (the files read) and ``force`` are those of :func:`valvetrain.outfolder.atomic_folder`.
    """
    from matplotlib.figure import Figure

    from .export import json_text, write_csv
    from .outfolder import atomic_folder
    from .report.plots import jerk_impulses

    rows, notes = comparison(designs) if designs else ({}, [])
    with atomic_folder(out, inputs, force) as tmp:
        (tmp / "plots").mkdir()
        labels = list(rows)
        metrics = shown_metrics(rows)
        table = {"quantity": [label for _, label in metrics]}
        table.update({lab: [table_cell(rows[lab].get(key)) for key, _ in metrics] for lab in labels})
        if rows:
            write_csv(tmp / "compare.csv", table)
        record = {"entries": rows, "notes": notes}
        if breathing:
            write_csv(tmp / "compare_breathing.csv", breathing_rows(breathing))
            _breathing_plot(breathing, tmp / "plots" / "compare_breathing.png")
            record["breathing"] = {label: b.summary for label, b in breathing.items()}
        (tmp / "compare.json").write_text(json_text(record), encoding="utf-8")
        for i, (name, scale, ylabel) in enumerate(COMPARE_PLOTS if designs else ()):
            fig = Figure(figsize=(8, 4.5))
            ax = fig.subplots()
            for label, v in designs.items():
                theta = np.linspace(v.law.start, v.law.end, 2001)
                d = v.law.derivatives(theta)[i] * v.omega_cam**i
                ax.plot(rad_to_deg(theta), d * scale, label=f"{label} ({v.law.name})")
            if name == "jerk":
                for n, (label, v) in enumerate(designs.items()):
                    jerk_impulses(ax, v.law, v.omega_cam, color=f"C{n}", label=f"{label}: jerk impulse (acceleration "
                                  "step, m/s²)")
            ax.set_xlabel("camshaft angle from the nose, deg")
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8)
            fig.tight_layout()
            fig.savefig(tmp / "plots" / f"compare_{name}.png", dpi=110)
        with_dyn = {label: v for label, v in designs.items() if v.dynamics is not None}
        if with_dyn:
            _dynamics_plot(with_dyn, tmp / "plots" / "compare_dynamics.png")
    return rows, notes


def shown_metrics(rows) -> list[tuple[str, str]]:
    """The rows of :data:`METRICS` and of :data:`DYNAMICS_METRICS` that some entry has."""
    return METRICS + [(key, label) for key, label in DYNAMICS_METRICS if any(key in r for r in rows.values())]


def table_cell(value) -> str | float:
    """A table cell: a text as it is, a number as a float, a missing value (None) empty."""
    return "" if value is None else value if isinstance(value, str) else float(value)


def _dynamics_plot(designs, path):
    """Smallest cam contact force and seating velocity against the engine speed, one line per valve."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8, 6.5))
    top, bottom = fig.subplots(2, 1, sharex=True)
    for label, v in designs.items():
        t = v.dynamics.per_speed
        rpm = np.asarray(t.speed) / rpm_to_rad_s(1.0)
        top.plot(rpm, t.min_contact_force, marker=".", label=f"{label} ({v.law.name})")
        bottom.plot(rpm, t.seating_velocity, marker=".", label=f"{label} ({v.law.name})")
    _save_against_speed(fig, top, bottom, "min cam contact force, N", "seating velocity, m/s", path)
