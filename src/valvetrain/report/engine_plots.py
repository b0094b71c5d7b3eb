"""The figures of the engine's chapters: the crank mechanism's forces, torque and pin load, the two-stroke ports, the
whole camshaft's torque and torsion, the breathing's indicator diagrams and curve, a cam phaser's map.

Each is its data and its drawing, as those of :mod:`valvetrain.report.plots` (which draws them, :data:`ENGINE_FIGURES`
by the stage of the results they show)."""

from typing import Any

from matplotlib.figure import Figure
from matplotlib.ticker import NullFormatter, ScalarFormatter
import numpy as np

from ..design.results import shown_value
from ..units import MM, rad_to_deg, to_display
from .figure import localised
from .numbers import number


def crank_forces_data(crank) -> dict[str, Any]:
    """The series of :func:`draw_crank_forces`: the cycle angle [deg] and the specific forces [MPa] of
    :class:`~valvetrain.design.crank.CrankColumns` (gas, inertia, total; N, S, K, T)."""
    c = crank.columns
    return {"crank_deg": rad_to_deg(crank.phi), "p_gas": c.p_gas * 1e-6, "p_j": c.p_j * 1e-6, "p": c.p * 1e-6,
            "p_N": c.p_N * 1e-6, "p_S": c.p_S * 1e-6, "p_K": c.p_K * 1e-6, "p_T": c.p_T * 1e-6}


def _cycle_axis(ax, x) -> None:
    """An axis of the cycle's angle: from 0 to the cycle's end (720 deg for a four-stroke), a tick every 90 deg."""
    period = float(x[-1] + (x[1] - x[0]))
    ax.set_xlim(0.0, period)
    ax.set_xticks(np.arange(0.0, period + 1.0, 90.0))


def _legend_outside(ax, fontsize=8) -> None:
    """The legend of ``ax`` right of it, where it covers no curve (the figure's right margin leaves room)."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=fontsize, borderaxespad=0.0)


def draw_crank_forces(d, t) -> Figure:
    """Specific forces against the crank angle, as Fig. 2.6 of Power units manual (n.d.): gas, inertia and total; N, S, K,
    T; the legends right of the axes, the angle over the whole cycle."""
    x = d["crank_deg"]
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(2, 1, sharex=True)
    for key, label in (("p_gas", t["p_gas"]), ("p_j", t["p_in"]), ("p", t["p_total"])):
        axes[0].plot(x, d[key], label=label)
    for key, label in (("p_N", "p_N"), ("p_S", "p_S"), ("p_K", "p_K"), ("p_T", "p_T")):
        axes[1].plot(x, d[key], label=label)
    for ax in axes:
        ax.axhline(0, color="0.5", lw=0.5)
        ax.grid(alpha=0.3)
        _legend_outside(ax)
        ax.set_ylabel(t["specific_force"])
    axes[-1].set_xlabel(t["cycle_deg"])
    _cycle_axis(axes[-1], x)
    fig.suptitle(t["crank_forces"])
    fig.subplots_adjust(left=0.09, right=0.82, bottom=0.08, top=0.93, hspace=0.08)
    return localised(fig, t)


def crank_forces_figure(crank, t) -> Figure:
    """:func:`draw_crank_forces` of :func:`crank_forces_data`."""
    return draw_crank_forces(crank_forces_data(crank), t)


def crank_torque_data(crank) -> dict[str, Any]:
    """The series of :func:`draw_crank_torque`: the engine angle over one cycle [deg], each cylinder's torque, the
    total and the mean torque [N m]."""
    return {"engine_deg": rad_to_deg(crank.psi), "cylinders_Nm": crank.cylinder_torques,
            "total_Nm": crank.total_torque, "mean_Nm": shown_value(crank.figures, "mean_torque")}


def draw_crank_torque(d, t) -> Figure:
    """Torque of every cylinder and the total over one cycle (Fig. 2.7 of Power units manual (n.d.)), the mean torque
    with its value; the legend right of the axes, the angle over the whole cycle."""
    x = d["engine_deg"]
    fig = Figure(figsize=(9, 5))
    ax = fig.subplots()
    for i, m in enumerate(d["cylinders_Nm"], start=1):
        ax.plot(x, m, lw=0.8, alpha=0.7, label=f"{t['cylinder']} {i}")
    ax.plot(x, d["total_Nm"], color="k", lw=1.8, label=t["total"], zorder=3)
    ax.axhline(d["mean_Nm"], color="C3", ls="--", lw=1.0, label=f"{t['mean']} {number(d['mean_Nm'], t['lang'])}")
    ax.axhline(0, color="0.5", lw=0.5)
    ax.set_xlabel(t["engine_deg"])
    ax.set_ylabel(t["torque"])
    _cycle_axis(ax, x)
    ax.grid(alpha=0.3)
    _legend_outside(ax)
    fig.subplots_adjust(left=0.11, right=0.82, bottom=0.11, top=0.96)
    return localised(fig, t)


def crank_torque_figure(crank, t) -> Figure:
    """:func:`draw_crank_torque` of :func:`crank_torque_data`."""
    return draw_crank_torque(crank_torque_data(crank), t)


def crank_pin_data(crank) -> dict[str, Any]:
    """The series of :func:`draw_crank_pin`: the crank-pin load, tangential and radial (outwards negative) [kN], and
    the cycle angle [deg]."""
    c = crank.columns
    return {"tangential_kN": c.pin_tangential * 1e-3, "radial_kN": -c.pin_radial * 1e-3,
            "crank_deg": rad_to_deg(crank.phi)}


def draw_crank_pin(d, t) -> Figure:
    """Polar diagram of the crank-pin load in the crank's frame (tangential against radial, kN)."""
    tang, rad, angle = d["tangential_kN"], d["radial_kN"], d["crank_deg"]
    fig = Figure(figsize=(7, 7))
    ax = fig.subplots()
    ax.plot(tang, rad, color="C0")
    near = 0.03 * max(np.ptp(tang), np.ptp(rad))
    marks = []                                     # (point, the cycle angles there): angles at one point together
    for deg in range(0, int(angle[-1]) + 1, 90):
        k = int(np.argmin(np.abs(angle - deg)))
        point = np.array([tang[k], rad[k]])
        same = next((m for m in marks if np.hypot(*(m[0] - point)) < near), None)
        marks.append((point, [deg])) if same is None else same[1].append(deg)
    for point, degs in marks:
        ax.plot(*point, "o", color="C3", ms=3)
        ax.annotate(", ".join(f"{deg}°" for deg in degs), point, xytext=(4, 4), textcoords="offset points",
                    fontsize=8, color="C3")
    ax.axhline(0, color="0.5", lw=0.5)
    ax.axvline(0, color="0.5", lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(t["pin_tangential"])
    ax.set_ylabel(t["pin_radial"])
    ax.grid(alpha=0.3)
    ax.set_title(t["pin_polar"])
    fig.subplots_adjust(left=0.14, right=0.95, bottom=0.09, top=0.94)
    return localised(fig, t)


def crank_pin_figure(crank, t) -> Figure:
    """:func:`draw_crank_pin` of :func:`crank_pin_data`."""
    return draw_crank_pin(crank_pin_data(crank), t)


def two_stroke_ports_data(ports) -> dict[str, Any]:
    """The series of :func:`draw_two_stroke_ports`: crank angle from TDC [deg] and each port's area [mm2]."""
    return {"crank_deg": rad_to_deg(ports.phi), "areas_mm2": {name: c.area / MM**2 for name, c in ports.curves.items()}}


def draw_two_stroke_ports(d, t) -> Figure:
    """Port areas against the crank angle (Valve-train practical works (n.d.), Fig. 8.1 b)."""
    fig = Figure(figsize=(8, 4.5))
    ax = fig.subplots()
    x = d["crank_deg"]
    for name, a in d["areas_mm2"].items():
        ax.plot(x, a, label=name)
    ax.set_xlabel(t["crank_from_tdc"])
    ax.set_ylabel(t["port_area"])
    ax.set_xticks(np.arange(0, 361, 45))
    ax.grid(alpha=0.3)
    ax.legend()
    fig.subplots_adjust(left=0.1, right=0.97, bottom=0.14, top=0.96)
    return localised(fig, t)


def two_stroke_ports_figure(ports, t) -> Figure:
    """:func:`draw_two_stroke_ports` of :func:`two_stroke_ports_data`."""
    return draw_two_stroke_ports(two_stroke_ports_data(ports), t)


def two_stroke_speed_data(ports) -> dict[str, Any]:
    """The series of :func:`draw_two_stroke_speed`: crank speed [rpm] and each port's time-area [mm2 s]."""
    return {"rpm": to_display(ports.speeds, "rpm"),
            "time_areas_mm2_s": {name: c.time_area / MM**2 for name, c in ports.curves.items()}}


def draw_two_stroke_speed(d, t) -> Figure:
    """Time-area of each port against the crank speed, Z = f(n) (Valve-train practical works (n.d.), work 8)."""
    fig = Figure(figsize=(8, 4.5))
    ax = fig.subplots()
    for name, z in d["time_areas_mm2_s"].items():
        ax.plot(d["rpm"], z, label=name)
    ax.set_xlabel(t["speed"])
    ax.set_ylabel(t["port_time_area"])
    ax.grid(alpha=0.3)
    ax.legend()
    fig.subplots_adjust(left=0.1, right=0.97, bottom=0.14, top=0.95)
    return localised(fig, t)


def two_stroke_speed_figure(ports, t) -> Figure:
    """:func:`draw_two_stroke_speed` of :func:`two_stroke_speed_data`."""
    return draw_two_stroke_speed(two_stroke_speed_data(ports), t)


def camshaft_torque_data(shaft) -> dict[str, Any]:
    """The series of :func:`draw_camshaft_torque`: the camshaft angle [cam deg from cylinder 1's gas-exchange TDC],
    the drive torque of the whole camshaft and its mean [N m], the orders 1, 2, ... and their amplitudes [N m]."""
    orders = np.asarray(shaft.figures.orders)
    return {"cam_deg": rad_to_deg(shaft.psi), "torque_Nm": shaft.torque, "mean_Nm": shaft.figures.mean,
            "orders": np.arange(1, orders.size), "amplitudes_Nm": orders[1:]}


def draw_camshaft_torque(d, t) -> Figure:
    """The camshaft's drive torque over a revolution and its orders of the camshaft speed."""
    fig = Figure(figsize=(9, 7))
    top, bottom = fig.subplots(2, 1)
    top.plot(d["cam_deg"], d["torque_Nm"], color="k", lw=1.2, label=t["total"])
    top.axhline(d["mean_Nm"], color="C3", ls="--", lw=1.0, label=t["mean"])
    top.axhline(0, color="0.5", lw=0.5)
    top.set_xlabel(t["cs_cam_deg"])
    top.set_ylabel(t["torque"])
    top.set_xticks(np.arange(0, 361, 45))
    top.grid(alpha=0.3)
    top.legend(loc="upper right", fontsize=8)
    bottom.bar(d["orders"], d["amplitudes_Nm"], color="C0")
    bottom.set_xlabel(t["cs_order"])
    bottom.set_ylabel(t["cs_amplitude"])
    bottom.grid(alpha=0.3, axis="y")
    fig.suptitle(t["cs_torque_title"])
    fig.subplots_adjust(left=0.1, right=0.97, bottom=0.08, top=0.93, hspace=0.3)
    return localised(fig, t)


def camshaft_torque_figure(shaft, t) -> Figure:
    """:func:`draw_camshaft_torque` of :func:`camshaft_torque_data`."""
    return draw_camshaft_torque(camshaft_torque_data(shaft), t)


def camshaft_torsion_data(shaft) -> dict[str, Any]:
    """The series of :func:`draw_camshaft_torsion`: the engine speed [rpm], the fluctuation of each cylinder's lobe
    timing [cam deg] and its allowable, the largest force of the timing drive [N] and its allowable, the cylinders and
    the speeds of the resonances in the running range [rpm]."""
    f, t = shaft.figures, shaft.figures.response
    return {"speed_rpm": to_display(shaft.speeds, "rpm"), "fluctuation_deg": rad_to_deg(shaft.fluctuation),
            "allowable_deg": float(rad_to_deg(t.allowable)), "force_N": shaft.drive_forces,
            "force_allowable_N": f.drive_allowable, "cylinders": f.cylinders,
            "resonances_rpm": [float(to_display(r.speed, "rpm")) for r in t.resonances]}


def draw_camshaft_torsion(d, t) -> Figure:
    """The steady torsional response of the camshaft against the engine speed: the fluctuation of each cylinder's lobe
    timing and the largest force of the timing drive, each with its allowable, the resonances marked."""
    fig = Figure(figsize=(9, 7))
    top, bottom = fig.subplots(2, 1, sharex=True)
    for i, cylinder in enumerate(d["cylinders"]):
        top.plot(d["speed_rpm"], d["fluctuation_deg"][:, i], lw=1.0, label=f"{t['cs_cylinder']} {cylinder}")
    top.axhline(d["allowable_deg"], color="C3", ls="--", lw=1.0, label=t["cs_allowable"])
    bottom.plot(d["speed_rpm"], d["force_N"], color="k", lw=1.2)
    bottom.axhline(d["force_allowable_N"], color="C3", ls="--", lw=1.0, label=t["cs_allowable"])
    for ax in (top, bottom):
        for n in d["resonances_rpm"]:
            ax.axvline(n, color="0.6", ls=":", lw=0.8)
        ax.grid(alpha=0.3)
        ax.legend(loc="upper left", fontsize=8)
    top.set_ylabel(t["cs_fluctuation"])
    bottom.set_ylabel(t["cs_drive_force"])
    bottom.set_xlabel(t["cs_speed"])
    fig.suptitle(t["cs_torsion_title"])
    fig.subplots_adjust(left=0.1, right=0.97, bottom=0.08, top=0.93, hspace=0.12)
    return localised(fig, t)


def camshaft_torsion_figure(shaft, t) -> Figure:
    """:func:`draw_camshaft_torsion` of :func:`camshaft_torsion_data`."""
    return draw_camshaft_torsion(camshaft_torsion_data(shaft), t)


def _condition_label(record, t):
    """A condition's legend: its speed and intake plenum pressure."""
    return t["br_condition"].format(speed=number(shown_value(record, "speed"), t["lang"]),
                                    pressure=number(shown_value(record, "intake_pressure"), t["lang"]))


def breathing_pv_data(breathing, t) -> dict[str, Any]:
    """The series of :func:`draw_breathing_pv`: each condition's legend, cylinder volume [cm3] and pressure [kPa] over
    its converged cycle."""
    return {"cycles": [(_condition_label(r.figures, t), r.columns.volume * 1e6, r.columns.pressure * 1e-3)
                       for r in breathing.conditions]}


def draw_breathing_pv(d, t) -> Figure:
    """The indicator diagrams of the breathing's conditions: p-V and log p - log V (the compression and expansion
    straight lines of slope -n, the pumping loop at the bottom)."""
    fig = Figure(figsize=(11, 5))
    linear, logs = fig.subplots(1, 2)
    for label, v, p in d["cycles"]:
        linear.plot(v, p, lw=1.0, label=label)
        logs.loglog(v, p, lw=1.0, label=label)
    for ax in (linear, logs):
        ax.set_xlabel(t["br_volume"])
        ax.set_ylabel(t["br_pressure"])
        ax.grid(alpha=0.3, which="both")
    for axis in (logs.xaxis, logs.yaxis):       # plain numbers at the decades, none between them
        axis.set_major_formatter(ScalarFormatter())
        axis.set_minor_formatter(NullFormatter())
    linear.legend(loc="upper right", fontsize=8)
    linear.set_title(t["br_pv"])
    logs.set_title(t["br_log_pv"])
    fig.subplots_adjust(left=0.07, right=0.98, bottom=0.12, top=0.92, wspace=0.25)
    return localised(fig, t)


def breathing_pv_figure(breathing, t) -> Figure:
    """:func:`draw_breathing_pv` of :func:`breathing_pv_data`."""
    return draw_breathing_pv(breathing_pv_data(breathing, t), t)


def breathing_speed_data(breathing) -> dict[str, Any]:
    """The series of :func:`draw_breathing_speed`: the curve's speeds [rpm] (else the conditions'), volumetric
    efficiency and, fired, the indicated torque [N m]."""
    records = [r.figures for r in (breathing.curve or breathing.conditions)]
    torque = [shown_value(r, "torque") for r in records] if records[0].torque is not None else None
    return {"speed_rpm": [shown_value(r, "speed") for r in records],
            "efficiency": [r.volumetric_efficiency for r in records], "torque_Nm": torque,
            "curve": bool(breathing.curve)}


def draw_breathing_speed(d, t) -> Figure:
    """Volumetric efficiency (and the indicated torque of a fired engine) against the speed."""
    fig = Figure(figsize=(9, 5))
    ax = fig.subplots()
    style = dict(marker="o", lw=1.2) if d["curve"] else dict(marker="o", ls="none")
    ax.plot(d["speed_rpm"], d["efficiency"], color="C0", label=t["br_efficiency"], **style)
    ax.set_xlabel(t["speed"])
    ax.set_ylabel(t["br_efficiency"])
    ax.grid(alpha=0.3)
    if d["torque_Nm"] is not None:
        right = ax.twinx()
        right.plot(d["speed_rpm"], d["torque_Nm"], color="C3", label=t["br_torque"], **style)
        right.set_ylabel(t["br_torque"])
    ax.set_title(t["br_speed_title"])
    fig.subplots_adjust(left=0.1, right=0.9, bottom=0.12, top=0.92)
    return localised(fig, t)


def breathing_speed_figure(breathing, t) -> Figure:
    """:func:`draw_breathing_speed` of :func:`breathing_speed_data`."""
    return draw_breathing_speed(breathing_speed_data(breathing), t)


def phaser_data(phaser) -> dict[str, Any]:
    """The series of :func:`draw_phaser`: the map's phases [crank deg, an advance positive], each condition's
    objective over them (the indicated torque [N m] of a fired engine, else the volumetric efficiency), its speed
    [rpm] and intake pressure [kPa], and the best phase and its objective at each condition."""
    f = phaser.figures
    key = f.objective
    n = len(f.best)
    values = [shown_value(p, key) for p in f.map]
    return {"advance_deg": [shown_value(p, "advance") for p in f.map[::n]],
            "values": [values[j::n] for j in range(n)],
            "speed_rpm": [shown_value(b, "speed") for b in f.best],
            "pressure_kPa": [shown_value(b, "intake_pressure") for b in f.best],
            "best_deg": [shown_value(b, "advance") for b in f.best],
            "best_values": [shown_value(b, key) for b in f.best], "objective": key, "valve": f.valve}


def draw_phaser(d, t) -> Figure:
    """The phaser's map, the objective against the phase at each condition with its best phase marked, and the best
    phase against the speed, a line for each intake plenum pressure."""
    fig = Figure(figsize=(11, 5))
    left, right = fig.subplots(1, 2)
    label = t["br_torque"] if d["objective"] == "torque" else t["br_efficiency"]
    for j, values in enumerate(d["values"]):
        color = f"C{j % 10}"
        left.plot(d["advance_deg"], values, color=color, marker="o", ms=3, lw=1.0,
                  label=t["br_condition"].format(speed=number(d["speed_rpm"][j], t["lang"]),
                                                 pressure=number(d["pressure_kPa"][j], t["lang"])))
        left.plot(d["best_deg"][j], d["best_values"][j], color=color, marker="*", ms=11, ls="none")
    left.set_xlabel(t["ph_advance"])
    left.set_ylabel(label)
    left.grid(alpha=0.3)
    left.legend(loc="best", fontsize=7)
    left.set_title(t["ph_map_title"])
    for pressure in sorted(set(d["pressure_kPa"]), reverse=True):
        points = sorted((n, a) for n, a, p in zip(d["speed_rpm"], d["best_deg"], d["pressure_kPa"], strict=True)
                        if p == pressure)
        right.plot(*zip(*points, strict=True), marker="*", ms=9, lw=1.2,
                   label=t["ph_pressure"].format(pressure=number(pressure, t["lang"])))
    right.legend(loc="best", fontsize=7)
    right.set_xlabel(t["speed"])
    right.set_ylabel(t["ph_best"])
    right.grid(alpha=0.3)
    right.set_title(t["ph_best_title"])
    fig.suptitle(t["ph_title"].format(valve=d["valve"]))
    fig.subplots_adjust(left=0.07, right=0.98, bottom=0.12, top=0.86, wspace=0.25)
    return localised(fig, t)


def phaser_figure(phaser, t) -> Figure:
    """:func:`draw_phaser` of :func:`phaser_data`."""
    return draw_phaser(phaser_data(phaser), t)


ENGINE_FIGURES = {"crank": {"crank_forces": crank_forces_figure, "crank_torque": crank_torque_figure,
                            "crank_pin_polar": crank_pin_figure},
                  "two_stroke": {"two_stroke_ports": two_stroke_ports_figure,
                                 "two_stroke_time_area": two_stroke_speed_figure},
                  "camshaft": {"camshaft_torque": camshaft_torque_figure, "camshaft_torsion": camshaft_torsion_figure},
                  "breathing": {"breathing_pv": breathing_pv_figure, "breathing_speed": breathing_speed_figure}}
