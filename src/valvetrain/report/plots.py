"""Plots of every stage of a valve design (matplotlib, written as PNG files); :func:`write_plots` draws them and the
engine chapters' figures (:mod:`.engine_plots`), written by :mod:`.figure`.

A figure is its data and its drawing: ``X_data(result)`` gives the series a figure shows (plain arrays in the
units of its axes, names and angles), ``draw_X(data, t)`` draws them with the texts ``t`` of a language, and
``X_figure(result, t)`` is the two in turn.

Each figure has fixed margins (``subplots_adjust``): those that ``tight_layout`` chose for the widest labels of the
shipped examples in English and Russian, rounded outwards; ``tight_layout`` measured every text of a figure before
drawing it, about a third of the drawing time.
"""

from typing import Any

import io
import itertools

from matplotlib.figure import Figure
import numpy as np

from ..design.dynamics_records import event_window
from ..design.valve import CYCLE_CRANK
from ..design.valve_checks import RHO_MIN
from ..design.results import shown_value
from ..errors import InputError
from ..units import MM, per_cam_degree, rad_to_deg, to_display
from .engine_plots import ENGINE_FIGURES, phaser_figure
from .figure import localised, write_png
from .hydraulic_plots import hydraulic_figure, hydraulic_sweep_figure, lost_motion_figure
from .i18n import TEXT
from .names import value_text
from .numbers import number


def segment_boundaries(law) -> np.ndarray:
    """Camshaft angles of the inner junctions of a law's segments [deg from the nose]."""
    return rad_to_deg(np.asarray(law.breakpoints[1:-1]))


def _boundary_lines(ax, angles_deg):
    for a in angles_deg:
        ax.axvline(a, color="0.75", lw=0.6, ls=":")


def impulse_steps(law, cam_speed) -> list[tuple[float, float]]:
    """The jerk impulses of a law at a camshaft speed [rad/s]: ``(camshaft angle [deg from the nose], step of the
    tappet acceleration [m/s^2])`` at each acceleration step."""
    return [(rad_to_deg(st.angle), cam_speed**2 * st.size) for st in law.acceleration_steps()]


def jerk_impulses(ax, law, cam_speed, color="C3", label=None) -> None:
    """Mark the jerk impulses of a law on a jerk axis (:func:`draw_jerk_impulses` of :func:`impulse_steps`)."""
    draw_jerk_impulses(ax, impulse_steps(law, cam_speed), color, label)


def draw_jerk_impulses(ax, steps, color="C3", label=None, lang="en") -> None:
    """Mark jerk impulses on a jerk axis: an arrow at each acceleration step ``(angle [deg], step [m/s^2])``, up for
    a rise of the acceleration and down for a fall, reaching the edge of the axis (an impulse has no finite height),
    with the step written beside it (by :func:`number`'s rule in ``lang``).  Call it after the curves are drawn (the arrows take the axis' extent)."""
    if not steps:
        return
    low, high = ax.get_ylim()
    reach = max(abs(low), abs(high))
    ax.set_ylim(min(low, -0.15 * reach), max(high, 0.15 * reach))
    low, high = ax.get_ylim()
    for n, (x, size) in enumerate(steps):
        tip = 0.92 * (high if size > 0.0 else low)
        ax.annotate("", xy=(x, tip), xytext=(x, 0.0), arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.2})
        ax.plot([x], [0.0], marker="o", color=color, ms=4, label=label if n == 0 else None)
        ax.annotate(("+" if size > 0.0 else "") + number(size, lang), xy=(x, tip), xytext=(3, 0), textcoords="offset points", fontsize=7, color=color,
                    va="top" if size > 0.0 else "bottom")


def kinematics_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_kinematics`: camshaft angle [deg], tappet and valve lift [mm], tappet velocity
    [m/s], acceleration [m/s^2] and jerk [m/s^3], the segment junctions and jerk impulses, the nose's crank angle
    [deg], the rocker ratio, the camshaft speed [rad/s], the valve's and the law's names."""
    tab = valve.table
    return {"name": valve.name, "law": valve.law.name, "cam_deg": rad_to_deg(tab.cam_angle),
            "tappet_lift_mm": tab.lift / MM, "valve_lift_mm": tab.valve_lift / MM, "velocity": tab.velocity,
            "acceleration": tab.acceleration, "jerk": tab.jerk, "boundaries_deg": segment_boundaries(valve.law),
            "impulses": [(rad_to_deg(st.angle), st.size) for st in valve.cam.acceleration_steps],
            "nose_crank_deg": rad_to_deg(valve.nose_crank),
            "rocker_ratio": valve.rocker_ratio, "cam_speed": valve.omega_cam}


def draw_kinematics(d, t) -> Figure:
    """Tappet lift (and valve lift), velocity, acceleration and jerk against camshaft angle."""
    x = d["cam_deg"]
    fig = Figure(figsize=(8, 10))
    axes = fig.subplots(4, 1, sharex=True)
    axes[0].plot(x, d["tappet_lift_mm"], label=t["tappet_lift"])
    axes[0].plot(x, d["valve_lift_mm"], label=t["valve_lift"])
    axes[0].legend(loc="upper right")
    moving = d["valve_lift_mm"] > 0.0
    w = d["cam_speed"]
    for n, (ax, y, label) in enumerate(zip(axes, (None, d["velocity"], d["acceleration"], d["jerk"] / 1e3),
                                           ("lift", "velocity", "acceleration", "jerk"), strict=True)):
        if y is not None:
            ax.plot(x, y, color="C0", label=t["k_tappet"])
            ax.plot(x, np.where(moving, d["rocker_ratio"] * y, np.nan), color="C1", ls="--", lw=1.0,
                    label=t["k_valve"])
            scale = per_cam_degree(1e3 if n == 3 else 1.0, n, w)    # jerk drawn in km/s3
            right = ax.secondary_yaxis("right", functions=(lambda v, s=scale: v * s, lambda v, s=scale: v / s))
            right.set_ylabel(t[f"per_deg{n}"])
        ax.set_ylabel(t[label])
        ax.grid(alpha=0.3)
        ax.axhline(0.0, color="0.5", lw=0.5)
        _boundary_lines(ax, d["boundaries_deg"])
    if d["impulses"]:
        draw_jerk_impulses(axes[-1], d["impulses"], lang=t["lang"])
        axes[-1].set_title(t["jerk_impulse"], fontsize=8, color="C3", loc="right")
    axes[1].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel(t["cam_deg"])
    nose = d["nose_crank_deg"]
    top = axes[0].secondary_xaxis("top", functions=(lambda c: 2 * c + nose, lambda k: (k - nose) / 2))
    top.set_xlabel(t["crank_deg"])
    fig.suptitle(f"{d['name']}: {value_text(d['law'], t['lang'])}")
    fig.subplots_adjust(left=0.12, right=0.87, bottom=0.07, top=0.9, hspace=0.21)   # the per-degree axes on the right
    return localised(fig, t)


def kinematics_figure(valve, t) -> Figure:
    """:func:`draw_kinematics` of :func:`kinematics_data`."""
    return draw_kinematics(kinematics_data(valve), t)


def strength_speed_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_strength_speed`: engine speed [rpm], the load kind at each, the largest cam force
    [N] and contact stress [MPa] (None without the cam width) with their worst points ``(rpm, value)``, the rated
    speed [rpm] and the valve's name."""
    st = valve.drive.strength
    per = st.per_speed
    stress = None if per.contact_stress is None else to_display(np.asarray(per.contact_stress), "MPa")
    return {"name": valve.name, "rpm": to_display(np.asarray(per.speed), "rpm"), "load": np.asarray(per.load),
            "cam_force_N": np.asarray(per.cam_force_max),
            "cam_force_worst": (to_display(st.cam_force_max_speed, "rpm"), st.cam_force_max), "stress_MPa": stress,
            "stress_worst": None if stress is None else (to_display(st.contact_stress_speed, "rpm"),
                                                         float(stress.max())),
            "rated_rpm": to_display(st.rated_speed, "rpm")}


def draw_strength_speed(d, t) -> Figure:
    """The largest cam load and contact stress at each engine speed of the strength checks, the worst points marked."""
    rpm, kinds = d["rpm"], d["load"]
    fig = Figure(figsize=(8, 6.5))
    axes = fig.subplots(2 if d["stress_MPa"] is not None else 1, 1, sharex=True, squeeze=False)[:, 0]
    rows = [(axes[0], d["cam_force_N"], t["cam_force_axis"], d["cam_force_worst"])]
    if d["stress_MPa"] is not None:
        rows.append((axes[1], d["stress_MPa"], t["contact_stress_axis"], d["stress_worst"]))
    for ax, y, ylabel, (worst_rpm, worst) in rows:
        for kind, marker in (("quasi-static", "."), ("dynamic", "x")):
            on = kinds == kind
            if on.any():
                ax.plot(rpm[on], y[on], ls="-" if kind == "quasi-static" else "none", marker=marker,
                        label=t["load_" + kind.replace("-", "_")])
        ax.plot([worst_rpm], [worst], "o", mfc="none", mec="C3", ms=10)
        ax.axvline(d["rated_rpm"], color="0.5", lw=0.8, ls="--", label=t["rated_speed"])
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel(t["engine_speed"])
    fig.suptitle(f"{d['name']}: {t['strength_speed_title']}")
    fig.subplots_adjust(left=0.12, right=0.95, bottom=0.1, top=0.91)
    return localised(fig, t)


def strength_speed_figure(valve, t) -> Figure:
    """:func:`draw_strength_speed` of :func:`strength_speed_data`."""
    return draw_strength_speed(strength_speed_data(valve), t)


def contour_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_contour`: the contour and, for a roller, its pitch curve [mm, in the cam's frame:
    nose on +y, the cam turning counter-clockwise (:mod:`valvetrain.geometry`)], the heel radius [mm], and the rays
    of the nose, the valve's opening and closing and the gas-exchange TDC: ``(name, camshaft angle [deg from the
    nose], crank angle [deg from the gas-exchange TDC])``."""
    x, y = valve.contour / MM
    pitch = None
    if np.isfinite(valve.follower_model.radius):    # the path of the centre of the follower's own curvature
        h, dh, d2h = valve.law.derivatives(valve.contour_angle)[:3]
        pitch = valve.follower_model.pitch_curve(valve.contour_angle, valve.heel_radius, h, dh, d2h)[0] / MM
    nose = shown_value(valve.cam, "nose")
    rays = [(key, (crank - nose) / 2.0, crank) for key, crank in (
        ("nose", nose), ("opens", shown_value(valve.cam, "valve_opens")),
        ("closes", shown_value(valve.cam, "valve_closes")), ("tdc", 0.0))]
    return {"name": valve.name, "x_mm": x, "y_mm": y, "pitch_mm": pitch, "heel_mm": valve.heel_radius / MM,
            "rays": rays}


def draw_contour(d, t) -> Figure:
    """The cam contour to scale, with the heel circle (and the pitch curve of a roller), the direction of rotation,
    and rays from the centre to the nose, the valve's opening and closing and the gas-exchange TDC (the timing
    reference), each with its crank angle."""
    fig = Figure(figsize=(7, 7))
    ax = fig.subplots()
    x, y = d["x_mm"], d["y_mm"]
    ax.plot(np.append(x, x[0]), np.append(y, y[0]), color="k", lw=1.5, label=t["contour"])
    phi = np.linspace(0, 2 * np.pi, 361)
    r = d["heel_mm"]
    ax.plot(r * np.cos(phi), r * np.sin(phi), ls="--", color="C2", lw=0.8, label=t["heel_circle"])
    if d["pitch_mm"] is not None:
        ax.plot(*d["pitch_mm"], color="C1", lw=0.8, label=t["pitch_curve"])
    outline = (x, y) if d["pitch_mm"] is None else d["pitch_mm"]
    reach = 1.12 * float(max(np.max(np.hypot(x, y)), np.max(np.hypot(*outline))))
    for key, cam_deg, crank_deg in d["rays"]:
        u = np.array([np.sin(np.radians(cam_deg)), np.cos(np.radians(cam_deg))])
        colour = "C3" if key == "tdc" else "C0"
        end = (1.2 if key == "tdc" else 1.0) * reach * u        # the reference beyond the events: no label on another
        ax.plot([0.0, end[0]], [0.0, end[1]], color=colour, lw=0.7, ls="-." if key == "tdc" else "-")
        ax.annotate(t["ray_" + key].format(crank=number(crank_deg, t["lang"])), end, xytext=(4 * u[0], 4 * u[1]),
                    textcoords="offset points", fontsize=8, color=colour,
                    ha="left" if u[0] > 0.2 else "right" if u[0] < -0.2 else "center",
                    va="bottom" if u[1] > 0.2 else "top" if u[1] < -0.2 else "center")
    arc = np.radians(np.linspace(200.0, 250.0, 30))
    ax.plot(0.8 * reach * np.cos(arc), 0.8 * reach * np.sin(arc), color="0.3", lw=1.0)
    ax.annotate("", xy=(0.8 * reach * np.cos(arc[-1] + 0.08), 0.8 * reach * np.sin(arc[-1] + 0.08)),
                xytext=(0.8 * reach * np.cos(arc[-1]), 0.8 * reach * np.sin(arc[-1])),
                arrowprops={"arrowstyle": "-|>", "color": "0.3", "lw": 1.0})
    ax.annotate(t["rotation"], (0.8 * reach * np.cos(arc[0]), 0.8 * reach * np.sin(arc[0])), xytext=(-4, 4),
                textcoords="offset points", fontsize=8, color="0.3", ha="right", va="bottom")
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvline(0, color="0.6", lw=0.5)
    ax.set_aspect("equal")
    ax.set_xlim(-1.7 * reach, 1.7 * reach)
    ax.set_ylim(-1.25 * reach, 1.4 * reach)
    ax.set_xlabel(t["x_mm"])
    ax.set_ylabel(t["y_mm"])
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(alpha=0.3)
    ax.set_title(f"{d['name']}: {t['contour']}")
    fig.subplots_adjust(left=0.1, right=0.97, bottom=0.09, top=0.94)
    return localised(fig, t)


def contour_figure(valve, t) -> Figure:
    """:func:`draw_contour` of :func:`contour_data`."""
    return draw_contour(contour_data(valve), t)


def time_area_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_time_area`: crank angle [deg from the gas-exchange TDC], curtain area [mm2], running
    time-area [mm2 s], the valve's own stroke (from, to) [crank deg] and the valve's name."""
    tab = valve.table
    return {"name": valve.name, "crank_deg": rad_to_deg(valve.nose_crank + 2.0 * tab.cam_angle),
            "curtain_mm2": tab.curtain_area / MM**2, "time_area_mm2_s": tab.time_area / MM**2,
            "stroke_crank_deg": shown_value(valve.flow, "stroke")}


def draw_time_area(d, t) -> Figure:
    """Curtain area and running time-area against crank angle; the valve's own stroke shaded."""
    k = d["crank_deg"]
    fig = Figure(figsize=(8, 5))
    ax = fig.subplots()
    ax.plot(k, d["curtain_mm2"], color="C0")
    ax.set_xlabel(t["crank_deg"])
    ax.set_ylabel(t["curtain"], color="C0")
    lo, hi = d["stroke_crank_deg"]
    ax.axvspan(lo, hi, color="C2", alpha=0.1, label=t["stroke"])
    ax.legend(loc="upper left")
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    ax2.plot(k, d["time_area_mm2_s"], color="C3")
    ax2.set_ylabel(t["running_ta"], color="C3")
    ax.set_title(f"{d['name']}: {t['time_area'].split('. ', 1)[-1]}")
    fig.subplots_adjust(left=0.12, right=0.9, bottom=0.13, top=0.92)
    return localised(fig, t)


def time_area_figure(valve, t) -> Figure:
    """:func:`draw_time_area` of :func:`time_area_data`."""
    return draw_time_area(time_area_data(valve), t)


def curvature_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_curvature`: camshaft angle [deg from the nose], the profile's radius of curvature
    [mm] (and a roller's pressure angle [deg], else None), the junctions of the law's segments [deg], the limits the
    checks apply [mm]: the smallest recommended radius and the undercut (a radius at or below 0: a flat face
    cannot follow it, a roller's pitch curve is then no wider than the roller), and the smallest radius (angle [deg],
    radius [mm])."""
    tab = valve.table
    limited = valve.follower_model.limited_contact(valve.profile.contact) is not None
    beta = rad_to_deg(tab.pressure_angle) if limited else None
    return {"name": valve.name, "cam_deg": rad_to_deg(tab.cam_angle), "rho_mm": tab.rho / MM, "pressure_deg": beta,
            "boundaries_deg": segment_boundaries(valve.law), "rho_min_limit_mm": RHO_MIN / MM,
            "undercut_mm": 0.0, "rho_min": (shown_value(valve.profile, "rho_min_angle"),
                                            shown_value(valve.profile, "rho_min"))}


def draw_curvature(d, t) -> Figure:
    """Radius of curvature of the profile (and the pressure angle of a roller) against camshaft angle, with the
    recommended minimum radius and the undercut limit as lines and the smallest radius marked."""
    x = d["cam_deg"]
    fig = Figure(figsize=(8, 4.5))
    ax = fig.subplots()
    ax.plot(x, d["rho_mm"], color="C0")
    ax.set_xlabel(t["cam_deg"])
    ax.set_ylabel(t["rho"])
    ax.axhline(d["undercut_mm"], color="C3", lw=1.0, label=t["undercut_limit"])
    ax.axhline(d["rho_min_limit_mm"], color="C1", lw=1.0, ls="--",
               label=t["rho_min_limit"].format(rho=number(d["rho_min_limit_mm"], t["lang"])))
    angle, rho = d["rho_min"]
    if rho is not None and angle is not None:
        ax.plot([angle], [rho], marker="o", color="C0", ms=5, ls="none",
                label=t["rho_min_point"].format(rho=number(rho, t["lang"]), angle=number(angle, t["lang"])))
    finite = d["rho_mm"][np.isfinite(d["rho_mm"])]
    if finite.size:
        top = max(float(np.percentile(finite, 98)), 2.0 * d["rho_min_limit_mm"])
        ax.set_ylim(min(float(finite.min()), 0.0) - 0.08 * top, 1.1 * top)
    ax.grid(alpha=0.3)
    _boundary_lines(ax, d["boundaries_deg"])
    ax.legend(loc="best", fontsize=8)
    if d["pressure_deg"] is not None:
        ax2 = ax.twinx()
        ax2.plot(x, d["pressure_deg"], color="C2")
        ax2.set_ylabel(t["pressure_angle"], color="C2")
    ax.set_title(f"{d['name']}: {t['rho']}")
    fig.subplots_adjust(left=0.13, right=0.9, bottom=0.14, top=0.91)
    return localised(fig, t)


def curvature_figure(valve, t) -> Figure:
    """:func:`draw_curvature` of :func:`curvature_data`."""
    return draw_curvature(curvature_data(valve), t)


def spring_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_spring`: valve lift [mm, ascending], the inertia force and the required force [N]
    there, each spring line's force [N] at no lift and at full lift, and the valve's name."""
    drive = valve.drive
    y = drive.lift / MM
    order = np.argsort(y)
    ends = np.array([0.0, y.max()])
    return {"name": valve.name, "lift_mm": y[order], "inertia_force_N": drive.inertia_force[order],
            "required_force_N": drive.required_force[order], "line_ends_mm": ends,
            "lines_N": {name: line.force(ends * MM) for name, line in drive.lines.named()}}


def draw_spring(d, t) -> Figure:
    """Spring characteristic as Fig. 5.1 of Valve-train practical works (n.d.): inertia force, required force and the chosen lines
    against valve lift."""
    y = d["lift_mm"]
    fig = Figure(figsize=(8, 5))
    ax = fig.subplots()
    ax.plot(y, d["inertia_force_N"], color="0.5", ls=":", label=t["inertia_force"])
    ax.plot(y, d["required_force_N"], color="C3", label=t["required_force"])
    styles = {"required": ("C3", "--"), "chosen": ("k", "-"), "outer": ("C0", "-."), "inner": ("C2", "-.")}
    for name, force in d["lines_N"].items():
        color, ls = styles[name]
        ax.plot(d["line_ends_mm"], force, color=color, ls=ls, lw=1.5 if name == "chosen" else 1.0,
                label=t["line_" + name])
    ax.set_xlabel(t["valve_lift_axis"])
    ax.set_ylabel(t["force"])
    ax.set_xlim(0.0, y.max())
    ax.set_ylim(0.0, None)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left")
    ax.set_title(f"{d['name']}: {t['spring_title']}")
    fig.subplots_adjust(left=0.11, right=0.96, bottom=0.13, top=0.92)
    return localised(fig, t)


def spring_figure(valve, t) -> Figure:
    """:func:`draw_spring` of :func:`spring_data`."""
    return draw_spring(spring_data(valve), t)


def timing_data(valves) -> dict[str, Any]:
    """The series of :func:`draw_timing`: crank angle [deg from the gas-exchange TDC], each valve's kind and lift
    [mm] there, its opening and closing [crank deg], and where intake and exhaust are open together (None without
    both kinds)."""
    lifts, events, open_by_kind = {}, {}, {}
    for name, v in valves.items():
        lift = v.cycle_lift
        lifts[name] = (v.kind, lift / MM)
        events[name] = (shown_value(v.cam, "valve_opens"), shown_value(v.cam, "valve_closes"))
        open_by_kind[v.kind] = open_by_kind.get(v.kind, np.zeros_like(CYCLE_CRANK, dtype=bool)) | (lift > 0.0)
    overlap = open_by_kind["intake"] & open_by_kind["exhaust"] if len(open_by_kind) == 2 else None
    return {"crank_deg": rad_to_deg(CYCLE_CRANK), "lifts_mm": lifts, "events_crank_deg": events, "overlap": overlap}


def draw_timing(d, t) -> Figure:
    """The valve timing diagram: every valve's lift against the crank angle from the gas-exchange TDC on one axis,
    its opening and closing angles written at the axis, the overlap of intake and exhaust shaded."""
    fig = Figure(figsize=(9, 4))
    ax = fig.subplots()
    for name, (kind, lift) in d["lifts_mm"].items():
        colour = "C0" if kind == "intake" else "C3"
        ax.plot(d["crank_deg"], lift, label=name if name == kind else f"{name} ({t[kind]})", color=colour)
        for angle in d["events_crank_deg"][name]:
            shown = (angle + 360.0) % 720.0 - 360.0
            ax.plot([shown], [0.0], marker="|", ms=10, color=colour)
            ax.annotate(f"{number(angle, t['lang'])}°", (shown, 0.0), xytext=(0, 6), textcoords="offset points",
                        rotation=90, fontsize=7, color=colour, ha="center", va="bottom")
    if d["overlap"] is not None:
        ax.fill_between(d["crank_deg"], 0.0, 1.0, where=d["overlap"], transform=ax.get_xaxis_transform(),
                        color="0.85", label=t["overlap"])
    for angle, label in ((-180, t["bdc"]), (0, t["tdc"]), (180, t["bdc"])):
        ax.axvline(angle, color="0.5", lw=0.6, ls="--")
        ax.annotate(label, (angle, 1.0), xycoords=("data", "axes fraction"), ha="center", va="bottom", fontsize=8)
    ax.set_xlim(-360, 360)
    ax.set_xticks(np.arange(-360, 361, 60))
    ax.set_xlabel(t["crank_deg"])
    ax.set_ylabel(t["valve_lift_mm"])
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.subplots_adjust(left=0.09, right=0.96, bottom=0.16, top=0.92)
    return localised(fig, t)


def timing_figure(valves, t) -> Figure:
    """:func:`draw_timing` of :func:`timing_data`."""
    return draw_timing(timing_data(valves), t)


def _speed_marks(values) -> list[Any]:
    """Engine speeds [rad/s] in rpm for the marks of a figure, None where not defined (not finite)."""
    return [to_display(v, "rpm") if np.isfinite(v) else None for v in values]


def dynamics_map_data(name, d) -> dict[str, Any]:
    """The series of :func:`draw_dynamics_map`: camshaft angles of the event window [deg from the nose], engine
    speeds [rpm], the maps of valve lift minus the rigid lift [mm] and of the cam contact force [N] (speeds x
    angles), the jump and bounce speeds [rpm] (None: none) and the valve's name."""
    sw = d.sweep
    keep = event_window(d)
    return {"name": name, "cam_deg": rad_to_deg(sw.theta[keep]), "rpm": to_display(np.asarray(d.per_speed.speed), "rpm"),
            "lift_error_mm": sw.lift_error[:, keep] / MM, "contact_force_N": sw.contact_force[:, keep],
            "jump_rpm": _speed_marks([d.jump_speed])[0], "bounce_rpm": _speed_marks([d.bounce_speed])[0]}


def draw_dynamics_map(d, t) -> Figure:
    """Maps over camshaft angle and engine speed: valve lift minus the rigid lift, and the cam contact force."""
    x, y, err = d["cam_deg"], d["rpm"], d["lift_error_mm"]
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(2, 1, sharex=True)
    bound = float(np.abs(err).max()) or 1.0
    for ax, z, label, cmap, kw in ((axes[0], err, t["dyn_lift_error"], "RdBu_r", dict(vmin=-bound, vmax=bound)),
                                   (axes[1], d["contact_force_N"], t["dyn_contact_force"], "viridis", {})):
        mesh = ax.pcolorfast(_cell_edges(x), _cell_edges(y), z, cmap=cmap, **kw)
        fig.colorbar(mesh, ax=ax, label=label)
        ax.set_ylabel(t["speed"])
        for value, style in ((d["jump_rpm"], "--"), (d["bounce_rpm"], ":")):
            if value is not None:
                ax.axhline(value, color="k", lw=0.8, ls=style)
    axes[0].set_title(f"{d['name']}: {t['dyn_lift_error']}")
    axes[1].set_title(t["dyn_contact_force"] + " (" + t["dyn_zero_is_jump"] + ")")
    axes[1].set_xlabel(t["cam_deg"])
    fig.subplots_adjust(left=0.1, right=0.97, bottom=0.08, top=0.94, hspace=0.13)
    return localised(fig, t)


def _cell_edges(centres):
    """The edges of the cells around ``centres`` (n,): the midpoints between them and the outer ones as far again,
    (n + 1,) (what ``pcolormesh``'s ``shading="auto"`` takes).  ``pcolorfast`` draws a grid of equal cells as one
    image, a third of the time of a mesh of 330,000 quadrilaterals (200 speeds x 1,653 angles), and the same pixels."""
    c = np.asarray(centres, dtype=float)
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[2.0 * c[0] - mid[0]], mid, [2.0 * c[-1] - mid[-1]]])


def dynamics_map_figure(name, d, t) -> Figure:
    """:func:`draw_dynamics_map` of :func:`dynamics_map_data`."""
    return draw_dynamics_map(dynamics_map_data(name, d), t)


def dynamics_speed_data(name, d) -> dict[str, Any]:
    """The series of :func:`draw_dynamics_speed`: engine speed [rpm], |seating velocity| [m/s] (NaN: no seating),
    bounce [mm], the smallest contact force [N], the jump, bounce and rated speeds [rpm] (None: none) and the
    valve's name."""
    p = d.per_speed
    jump, bounce, rated = _speed_marks([d.jump_speed, d.bounce_speed, d.at_rated_speed.speed])
    return {"name": name, "rpm": to_display(np.asarray(p.speed), "rpm"),
            "seating_velocity_m_s": np.abs(np.array(p.seating_velocity, dtype=float)),
            "bounce_mm": np.asarray(p.bounce) / MM, "min_contact_force_N": np.asarray(p.min_contact_force),
            "jump_rpm": jump, "bounce_rpm": bounce, "rated_rpm": rated}


def draw_dynamics_speed(d, t) -> Figure:
    """Seating velocity, bounce and the smallest contact force against the engine speed, the headline speeds
    marked."""
    n = d["rpm"]
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(3, 1, sharex=True)
    axes[0].plot(n, d["seating_velocity_m_s"], color="C3")   # NaN (no seating): a gap
    axes[0].set_ylabel(t["dyn_seating_velocity"])
    axes[1].plot(n, d["bounce_mm"], color="C1")
    axes[1].set_ylabel(t["dyn_bounce"])
    axes[2].plot(n, d["min_contact_force_N"], color="C0")
    axes[2].set_ylabel(t["dyn_min_force"])
    axes[2].set_xlabel(t["speed"])
    for ax in axes:
        ax.grid(alpha=0.3)
        marks = ((d["jump_rpm"], t["dyn_jump_speed"], "--"), (d["bounce_rpm"], t["dyn_bounce_speed"], ":"),
                 (d["rated_rpm"], t["dyn_rated"], "-."))
        for value, label, style in marks:
            if value is not None:
                ax.axvline(value, color="0.3", lw=0.8, ls=style, label=label)
    axes[0].legend(fontsize=8)
    axes[0].set_title(f"{d['name']}: {t['dyn_title']}")
    fig.subplots_adjust(left=0.1, right=0.97, bottom=0.08, top=0.94, hspace=0.1)
    return localised(fig, t)


def dynamics_speed_figure(name, d, t) -> Figure:
    """:func:`draw_dynamics_speed` of :func:`dynamics_speed_data`."""
    return draw_dynamics_speed(dynamics_speed_data(name, d), t)


def grinding_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_grinding`: the cam contour, the wheel-centre path and the master contour [mm]
    (``(x, y)``, None where there is none), the lift error of the worn wheel exact and to first order [um] against
    the camshaft angle [deg from the nose] (None where the cam cannot be ground), the law's segment boundaries
    [deg], the wheel wear [mm] and the valve's name."""
    g = valve.grinding
    w = g.wear
    return {"name": valve.name,
            "contours": [(kind, None if pts is None else pts / MM) for kind, pts in
                         (("cam", g.cam_contour), ("wheel_path", g.wheel_path), ("master", g.master_contour))],
            "cam_deg": None if w is None else rad_to_deg(w.cam_angle),
            "error_um": None if w is None else w.error / MM * 1e3,
            "error_first_order_um": None if w is None else w.error_first_order / MM * 1e3,
            "boundaries_deg": segment_boundaries(valve.law), "wheel_wear_mm": g.wheel_wear / MM}


GRINDING_STYLES = {"cam": ("gr_cam", dict(color="k", lw=1.5)), "wheel_path": ("gr_wheel_path", dict(color="C1", lw=0.8, ls="--")),
                   "master": ("gr_master", dict(color="C0", lw=1.2))}
"""The text key and line style of each contour of the grinding figure."""


def draw_grinding(d, t) -> Figure:
    """The cam, the wheel-centre path and the master to scale; the lift error of the worn wheel against cam angle."""
    fig = Figure(figsize=(12, 5.5))
    left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.3]})
    for kind, pts in d["contours"]:
        if pts is not None:
            x, y = pts
            label, style = GRINDING_STYLES[kind]
            left.plot(np.append(x, x[0]), np.append(y, y[0]), label=t[label], **style)
    left.set_aspect("equal")
    left.set_xlabel(t["x_mm"])
    left.set_ylabel(t["y_mm"])
    left.grid(alpha=0.3)
    left.legend(loc="lower right", fontsize=8)
    left.set_title(t["gr_contours"])
    if d["cam_deg"] is not None:
        x = d["cam_deg"]
        right.plot(x, d["error_um"], color="C3", label=t["gr_exact"])
        right.plot(x, d["error_first_order_um"], color="C0", ls="--", label=t["gr_first_order"])
        _boundary_lines(right, d["boundaries_deg"])
        right.legend(loc="upper right", fontsize=8)
    else:
        right.text(0.5, 0.5, t["gr_not_grindable"], ha="center", va="center", transform=right.transAxes, wrap=True)
    right.axhline(0.0, color="0.5", lw=0.5)
    right.set_xlabel(t["cam_deg"])
    right.set_ylabel(t["gr_error_um"])
    right.grid(alpha=0.3)
    right.set_title(t["gr_error_title"].format(wear=number(d["wheel_wear_mm"], t["lang"])))
    fig.suptitle(f"{d['name']}: {t['gr_title']}")
    fig.subplots_adjust(left=0.08, right=0.98, bottom=0.12, top=0.87, wspace=0.16)
    return localised(fig, t)


def grinding_figure(valve, t) -> Figure:
    """:func:`draw_grinding` of :func:`grinding_data`."""
    return draw_grinding(grinding_data(valve), t)


DYNAMICS_FIGURES = {"dynamics_map": dynamics_map_figure, "dynamics_speed": dynamics_speed_figure}


def write_dynamics_plots(name, d, folder, t, save=None, wanted=None) -> dict[str, str]:
    """Write the dynamics figures of one valve as PNG; return ``{kind: filename}``.  ``save(draw, filename)`` draws
    and writes one figure (``draw()`` makes it), by default at once (:func:`write_plots` passes its own);
    ``wanted(kind)`` says which are drawn (default: both)."""
    save = save or _saver(folder)
    return {kind: save(lambda make=make: make(name, d, t), f"{name}_{kind}.png")
            for kind, make in DYNAMICS_FIGURES.items() if wanted is None or wanted(kind)}


def _saver(folder, claim=None):
    """``save(draw, filename)``: draw the figure and write it into ``folder`` if this drawer has claimed it; return
    the filename either way.  The figures are numbered 0, 1, ... in the order drawn; ``claim()`` gives the number of
    the next figure this drawer is to draw, a larger one each call (several drawers draw a share each: each claims
    the next figure not yet taken from a counter they share, so that a drawer done with a cheap figure takes the
    next while another draws an expensive one); by default every figure in turn.  A dict as ``folder`` receives
    ``{filename: PNG bytes}`` (nothing written to disk)."""
    turn = itertools.count()
    claim = claim or itertools.count().__next__
    claimed = [claim()]

    def save(draw, fname):
        if next(turn) == claimed[0]:
            if isinstance(folder, dict):
                png = io.BytesIO()
                write_png(draw(), png)
                folder[fname] = png.getvalue()
            else:
                write_png(draw(), folder / fname)
            claimed[0] = claim()
        return fname
    return save



FIGURES = {"kinematics": kinematics_figure, "contour": contour_figure, "time_area": time_area_figure,
           "curvature": curvature_figure, "spring": spring_figure, "strength_speed": strength_speed_figure}

FIGURE_SETS = ("main", "all", "none")
"""Which figures :func:`write_plots` draws (``valvetrain run --figures``): ``main`` those of :data:`MAIN_FIGURES`,
``all`` every one, ``none`` none."""

MAIN_FIGURES = frozenset({"kinematics", "contour", "dynamics_speed", "grinding", "hydraulic", "timing",
                          "crank_torque", "two_stroke_ports", "camshaft_torque", "camshaft_torsion", "breathing_pv",
                          "breathing_speed", "phaser", "lost_motion"})
"""The figures drawn by default (``figures="main"``): the valve's lift law and its cam, one figure of each further
stage that a section asks for (the dynamics' seating velocity, bounce and contact force against the speed; the
grinding; the hydraulic drive over a revolution; the crank and camshaft torques; the ports) and the timing diagram.
The others are drawn on request (``figures="all"``): the time-area, the radius of curvature, the spring
characteristic, the stresses against the speed, the dynamics' maps over angle and speed, the hydraulic drive
against the speed, the crank forces and pin load, the ports' time-area, whose extremes the report's tables give.
A phased valve's map and best phase (``phaser``) is drawn by default where the breathing made its map.
A figure costs 0.1-0.4 s of processor time, the design of a valve's numbers a few milliseconds to a few tenths of
a second."""


def drawn(stage, kind, data) -> bool:
    """Whether an engine chapter's figure has something to show: the breathing's speed figure needs its curve or
    two conditions or more."""
    return not (kind == "breathing_speed" and not data.curve and len(data.conditions) < 2)


def write_plots(results, folder, lang="en", figures="main", claim=None) -> dict[str, Any]:
    """Write the figures of ``figures`` (one of :data:`FIGURE_SETS`) as PNG; return ``{valve name or
    "crank"/"two_stroke": {kind: filename}}`` (and ``"(timing)"``: the timing diagram's filename) of those written.

    ``claim`` shares the figures among several drawers (:func:`_saver`): each draws those it claims and returns the
    whole dict."""
    if figures not in FIGURE_SETS:
        raise InputError(f"figures = {figures!r}; allowed: {', '.join(FIGURE_SETS)}")
    t = TEXT[lang]
    written = {}
    save = _saver(folder, claim)

    def wanted(kind):
        return figures == "all" or (figures == "main" and kind in MAIN_FIGURES)

    for name, valve in results.valves.items():
        written[name] = {kind: save(lambda make=make: make(valve, t), f"{name}_{kind}.png")
                         for kind, make in FIGURES.items() if wanted(kind)}
        if valve.dynamics is not None:
            written[name].update(write_dynamics_plots(name, valve.dynamics, folder, t, save, wanted))
        if valve.grinding is not None and wanted("grinding"):
            written[name]["grinding"] = save(lambda: grinding_figure(valve, t), f"{name}_grinding.png")
        if valve.hydraulic is not None:
            if wanted("hydraulic"):
                written[name]["hydraulic"] = save(lambda: hydraulic_figure(valve, t), f"{name}_hydraulic.png")
            if wanted("hydraulic_sweep"):
                written[name]["hydraulic_sweep"] = save(lambda: hydraulic_sweep_figure(valve, t),
                                                        f"{name}_hydraulic_sweep.png")
        if valve.lost_motion is not None and wanted("lost_motion"):
            written[name]["lost_motion"] = save(lambda: lost_motion_figure(valve, t), f"{name}_lost_motion.png")
    for name, phaser in results.phasers.items():
        if phaser.figures.map and wanted("phaser"):
            written.setdefault(name, {})["phaser"] = save(lambda phaser=phaser: phaser_figure(phaser, t),
                                                          f"{name}_phaser.png")
    if results.valves and wanted("timing"):
        written["(timing)"] = save(lambda: timing_figure(results.valves, t), "valve_timing.png")
    for stage, figures_of_stage in ENGINE_FIGURES.items():
        data = getattr(results, stage)
        if data is not None:
            written[stage] = {kind: save(lambda make=make: make(data, t), f"{kind}.png")
                              for kind, make in figures_of_stage.items() if wanted(kind) and drawn(stage, kind, data)}
    return written
