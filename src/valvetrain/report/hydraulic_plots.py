"""Figures of a valve's hydraulic actuation (:mod:`valvetrain.hydraulic_actuation`): the drive's response at its
speed, its lost-motion closings and its speed sweep; data and drawing apart, as in :mod:`.plots`."""

from typing import Any

from matplotlib.figure import Figure
import numpy as np

from ..units import MM, rad_to_deg, to_display
from .figure import localised
from .numbers import number


def hydraulic_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_hydraulic` against the camshaft angle [deg from the nose]: the pressures at the pump
    and the actuator [MPa], where the liquid cavitates, the valve lift and the rigid drive's [mm]; the vapour pressure
    [MPa], the stop [mm], the lift-off point ``(angle [deg], pressure [MPa], gas force [kN])`` (None where the gas
    force is not simulated or the valve does not lift off) and the valve's name."""
    h = valve.hydraulic
    r = h.response
    x = rad_to_deg(r.angle)
    off = r.lift_off()
    lift_off = None
    if h.gas_force is not None and off < r.angle.size:
        lift_off = (float(x[off]), float(r.actuator_pressure[off] / 1e6), float(r.gas_force[off] / 1e3))
    return {"name": valve.name, "cam_deg": x, "pump_MPa": r.pump_pressure / 1e6,
            "actuator_MPa": r.actuator_pressure / 1e6, "cavitation": np.asarray(r.cavitation),
            "vapour_MPa": h.vapour_pressure / 1e6, "lift_off": lift_off, "valve_lift_mm": r.valve_lift / MM,
            "rigid_lift_mm": r.rigid_lift / MM, "stop_mm": h.stop / MM}


def draw_hydraulic(d, t) -> Figure:
    """The pressures at both ends of the pipe and the valve lift against the rigid drive's, against camshaft angle."""
    fig = Figure(figsize=(10, 7))
    top, bottom = fig.subplots(2, 1, sharex=True)
    x = d["cam_deg"]
    top.plot(x, d["pump_MPa"], color="C0", lw=1.0, label=t["hy_pump"])
    top.plot(x, d["actuator_MPa"], color="C3", lw=1.0, label=t["hy_actuator"])
    top.axhline(d["vapour_MPa"], color="0.5", lw=0.6, ls=":", label=t["hy_vapour"])
    cav = d["cavitation"]
    if cav.any():
        top.plot(x[cav], np.full(int(cav.sum()), d["vapour_MPa"]), "x", color="k", ms=3, label=t["hy_cavitation"])
    if d["lift_off"] is not None:
        angle, pressure, force = d["lift_off"]
        top.plot(angle, pressure, "o", color="k", ms=5, label=t["hy_lift_off"].format(force=number(force, t["lang"])))
    top.set_ylabel(t["hy_pressure"])
    top.grid(alpha=0.3)
    top.legend(loc="upper right", fontsize=8)
    bottom.plot(x, d["valve_lift_mm"], color="C2", label=t["hy_valve"])
    bottom.plot(x, d["rigid_lift_mm"], color="k", ls="--", lw=0.8, label=t["hy_rigid"])
    bottom.axhline(d["stop_mm"], color="C3", ls=":", lw=1.0, label=t["hy_stop"])
    bottom.set_xlabel(t["cam_deg"])
    bottom.set_ylabel(t["hy_lift"])
    bottom.grid(alpha=0.3)
    bottom.legend(loc="upper right", fontsize=8)
    fig.suptitle(f"{d['name']}: {t['hy_title']}")
    fig.subplots_adjust(left=0.07, right=0.98, bottom=0.09, top=0.92, hspace=0.08)
    return localised(fig, t)


def hydraulic_figure(valve, t) -> Figure:
    """:func:`draw_hydraulic` of :func:`hydraulic_data`."""
    return draw_hydraulic(hydraulic_data(valve), t)


def lost_motion_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_lost_motion` against the cycle crank angle [deg from the gas-exchange TDC]: the valve
    lift [mm] and the pressure under the brake piston [MPa] of the full lift and of each solenoid timing (labelled by
    its crank angle), the pump piston's lift [mm]; the valve's name."""
    lm = valve.lost_motion
    full = lm.full
    lifted = np.flatnonzero(full.plunger_lift > 0.0)
    margin = (lifted[-1] - lifted[0]) // 5
    rows = slice(max(lifted[0] - margin, 0), lifted[-1] + margin)         # the cam's lift and a fifth of it each side
    x = rad_to_deg(full.angle[rows]) * lm.strokes / 2.0 + rad_to_deg(lm.nose)   # unwrapped about the nose
    runs = [(None, full)] + [(rad_to_deg(c.solenoid_opens), r) for c, r in zip(lm.closings, lm.responses, strict=True)]
    return {"name": valve.name, "crank_deg": x, "pump_lift_mm": full.plunger_lift[rows] / MM,
            "runs": [(at, r.valve_lift[rows] / MM, r.brake_pressure[rows] / 1e6) for at, r in runs]}


def draw_lost_motion(d, t) -> Figure:
    """The valve lift and the pressure under the brake piston of the full lift and of each solenoid timing, against
    the cycle crank angle."""
    fig = Figure(figsize=(10, 7))
    top, bottom = fig.subplots(2, 1, sharex=True)
    x = d["crank_deg"]
    top.plot(x, d["pump_lift_mm"], color="k", ls="--", lw=0.8, label=t["lm_pump"])
    for i, (at, lift, pressure) in enumerate(d["runs"]):
        label = t["lm_full"] if at is None else t["lm_at"].format(at=number(at, t["lang"]))
        top.plot(x, lift, color=f"C{i}", lw=1.0, label=label)
        bottom.plot(x, pressure, color=f"C{i}", lw=0.8, label=label)
    top.set_ylabel(t["hy_lift"])
    bottom.set_ylabel(t["lm_pressure"])
    bottom.set_xlabel(t["lm_crank"])
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right", fontsize=8)
    fig.suptitle(f"{d['name']}: {t['lm_title']}")
    fig.subplots_adjust(left=0.07, right=0.98, bottom=0.09, top=0.92, hspace=0.08)
    return localised(fig, t)


def lost_motion_figure(valve, t) -> Figure:
    """:func:`draw_lost_motion` of :func:`lost_motion_data`."""
    return draw_lost_motion(lost_motion_data(valve), t)


def hydraulic_sweep_data(valve) -> dict[str, Any]:
    """The series of :func:`draw_hydraulic_sweep` against the engine speed [rpm]: the largest pressure [MPa], the
    lift loss [mm], the opening and closing delays [cam deg] (NaN: not defined), where the liquid cavitates; the
    simulated speed [rpm] and the valve's name."""
    h = valve.hydraulic
    p = h.per_speed
    return {"name": valve.name, "rpm": to_display(np.asarray(p.speed), "rpm"),
            "max_pressure_MPa": np.asarray(p.max_pressure) / 1e6, "lift_loss_mm": np.asarray(p.lift_loss) / MM,
            "opening_delay_deg": rad_to_deg(np.array(p.opening_delay, dtype=float)),
            "closing_delay_deg": rad_to_deg(np.array(p.closing_delay, dtype=float)),
            "cavitation": np.asarray(p.cavitation), "simulated_rpm": to_display(h.speed, "rpm")}


def draw_hydraulic_sweep(d, t) -> Figure:
    """The largest pressure, the lift loss and the delays of the hydraulic drive against the engine speed, the
    simulated speed marked."""
    n = d["rpm"]
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(3, 1, sharex=True)
    axes[0].plot(n, d["max_pressure_MPa"], "o-", color="C3", ms=3)
    axes[0].set_ylabel(t["hy_max_pressure"])
    axes[1].plot(n, d["lift_loss_mm"], "o-", color="C1", ms=3)
    axes[1].set_ylabel(t["hy_lift_loss"])
    for values, label, color in ((d["opening_delay_deg"], t["hy_opening_delay"], "C0"),
                                 (d["closing_delay_deg"], t["hy_closing_delay"], "C2")):
        axes[2].plot(n, values, "o-", color=color, ms=3, label=label)  # NaN: a gap
    axes[2].set_ylabel(t["hy_delay"])
    axes[2].legend(fontsize=8)
    axes[2].set_xlabel(t["speed"])
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.axvline(d["simulated_rpm"], color="0.3", lw=0.8, ls="-.")
    cav = d["cavitation"]
    if cav.any():
        axes[0].plot(n[cav], d["max_pressure_MPa"][cav], "x", color="k", ms=6, label=t["hy_cavitation"])
        axes[0].legend(fontsize=8)
    axes[0].set_title(f"{d['name']}: {t['hy_sweep_title']}")
    fig.subplots_adjust(left=0.08, right=0.97, bottom=0.08, top=0.94, hspace=0.12)
    return localised(fig, t)


def hydraulic_sweep_figure(valve, t) -> Figure:
    """:func:`draw_hydraulic_sweep` of :func:`hydraulic_sweep_data`."""
    return draw_hydraulic_sweep(hydraulic_sweep_data(valve), t)
