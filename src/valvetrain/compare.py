"""Side-by-side comparison of lift laws (issue 5: ``valvetrain compare``).

Each valve of each specification becomes one column: time-area, fullness, extreme
kinematics, curvature, contact stress and the required spring, computed by the same
design chain as ``valvetrain run``.  The laws should be compared at equal lift and
duration (Valve-train dynamics article (n.d.) compares its three profiles so); the table states both, and
:func:`comparison` flags entries that differ by more than 1 % in lift or by more than 1 deg in
the duration at 1 mm valve lift (a checking height that every law, measured ones included,
defines the same way).
"""

import numpy as np

from .units import MM, rad_to_deg

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
    ("max_jerk_m_s3", "max |tappet jerk|, m/s3"),
    ("rho_min_mm", "min radius of curvature, mm"),
    ("max_pressure_angle_deg", "max pressure angle, deg"),
    ("max_contact_stress_MPa", "max cam contact stress, MPa"),
    ("required_spring_max_N", "required spring force at full lift, N"),
    ("required_spring_preload_N", "required preload, N"),
]
"""Rows of the comparison, with their labels."""


def duration_at(valve, height):
    """Camshaft angle [rad] over which the valve lift exceeds ``height`` [m], by root finding on the law."""
    return valve.law.duration(valve.law.ramp_height + height / valve.rocker_ratio)


def entry(valve):
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
        "max_jerk_m_s3": float(np.abs(law.jerk(theta, valve.omega_cam)).max()),
        "rho_min_mm": s["cam"]["rho_min_mm"],
        "max_pressure_angle_deg": s["cam"].get("max_pressure_angle_deg", 0.0),
        "max_contact_stress_MPa": stress["value"] if stress else float("nan"),
        "required_spring_max_N": s["spring"]["required_max_force_N"],
        "required_spring_preload_N": s["spring"]["required_preload_N"],
    }


def comparison(designs):
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
    rows = {label: entry(v) for label, v in designs.items()}
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


def write_comparison(designs, out, inputs=(), force=False):
    """Write ``compare.csv``, ``compare.json`` and the overlaid plots into ``out`` atomically.

    ``inputs`` (the files read) and ``force`` are those of :func:`valvetrain.outfolder.atomic_folder`.
    """
    from matplotlib.figure import Figure

    from .export import json_text, write_csv
    from .outfolder import atomic_folder

    rows, notes = comparison(designs)
    with atomic_folder(out, inputs, force) as tmp:
        (tmp / "plots").mkdir()
        labels = list(rows)
        table = {"quantity": [label for _, label in METRICS]}
        table.update({lab: [rows[lab][key] if isinstance(rows[lab][key], str) else float(rows[lab][key])
                            for key, _ in METRICS] for lab in labels})
        write_csv(tmp / "compare.csv", table)
        (tmp / "compare.json").write_text(json_text({"entries": rows, "notes": notes}), encoding="utf-8")
        quantities = (("lift", 1.0 / MM, "tappet lift, mm"), ("velocity", 1.0, "tappet velocity, m/s"),
                      ("acceleration", 1.0, "tappet acceleration, m/s²"), ("jerk", 1.0, "tappet jerk, m/s³"))
        for i, (name, scale, ylabel) in enumerate(quantities):
            fig = Figure(figsize=(8, 4.5))
            ax = fig.subplots()
            for label, v in designs.items():
                theta = np.linspace(v.law.start, v.law.end, 2001)
                d = v.law.derivatives(theta)[i] * v.omega_cam**i
                ax.plot(rad_to_deg(theta), d * scale, label=f"{label} ({v.law.name})")
            ax.set_xlabel("camshaft angle from the nose, deg")
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8)
            fig.tight_layout()
            fig.savefig(tmp / "plots" / f"compare_{name}.png", dpi=110)
    return rows, notes
