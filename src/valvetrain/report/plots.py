"""Plots of every stage of a valve design (matplotlib, written as PNG files)."""

from matplotlib.figure import Figure
import numpy as np

from ..units import DEG, MM, rad_to_deg, to_display
from .i18n import TEXT
from .names import value_text


def _segment_lines(ax, law):
    for a in law.breakpoints[1:-1]:
        ax.axvline(rad_to_deg(a), color="0.75", lw=0.6, ls=":")


def jerk_impulses(ax, law, cam_speed, color="C3", label=None):
    """Mark the jerk impulses of a law on a jerk axis: an arrow at each acceleration step, up for a rise of the
    acceleration and down for a fall, reaching the edge of the axis (an impulse has no finite height), with the step
    written beside it [m/s^2].  Call it after the curves are drawn (the arrows take the axis' extent)."""
    steps = law.acceleration_steps()
    if not steps:
        return
    low, high = ax.get_ylim()
    reach = max(abs(low), abs(high))
    ax.set_ylim(min(low, -0.15 * reach), max(high, 0.15 * reach))
    low, high = ax.get_ylim()
    for n, st in enumerate(steps):
        size = cam_speed**2 * st.size
        tip = 0.92 * (high if size > 0.0 else low)
        x = rad_to_deg(st.angle)
        ax.annotate("", xy=(x, tip), xytext=(x, 0.0), arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.2})
        ax.plot([x], [0.0], marker="o", color=color, ms=4, label=label if n == 0 else None)
        ax.annotate(f"{size:+.4g}", xy=(x, tip), xytext=(3, 0), textcoords="offset points", fontsize=7, color=color,
                    va="top" if size > 0.0 else "bottom")


def kinematics_figure(valve, t):
    """Tappet lift (and valve lift), velocity, acceleration and jerk against camshaft angle."""
    tab = valve.table
    x = rad_to_deg(tab.cam_angle)
    fig = Figure(figsize=(8, 10))
    axes = fig.subplots(4, 1, sharex=True)
    axes[0].plot(x, tab.lift / MM, label=t["tappet_lift"])
    axes[0].plot(x, tab.valve_lift / MM, label=t["valve_lift"])
    axes[0].legend(loc="upper right")
    moving = tab.valve_lift > 0.0
    w = valve.omega_cam
    per_deg = MM / DEG    # a speed-independent derivative in mm/deg^n from m/rad^n: divide by MM / DEG^n
    for n, (ax, y, label) in enumerate(zip(axes, (None, tab.velocity, tab.acceleration, tab.jerk / 1e3),
                                           ("lift", "velocity", "acceleration", "jerk"), strict=True)):
        if y is not None:
            ax.plot(x, y, color="C0", label=t["k_tappet"])
            ax.plot(x, np.where(moving, valve.rocker_ratio * y, np.nan), color="C1", ls="--", lw=1.0,
                    label=t["k_valve"])
            scale = (1e3 if n == 3 else 1.0) / w**n * DEG ** (n - 1) / per_deg
            right = ax.secondary_yaxis("right", functions=(lambda v, s=scale: v * s, lambda v, s=scale: v / s))
            right.set_ylabel(t[f"per_deg{n}"])
        ax.set_ylabel(t[label])
        ax.grid(alpha=0.3)
        ax.axhline(0.0, color="0.5", lw=0.5)
        _segment_lines(ax, valve.law)
    if valve.law.acceleration_steps():
        jerk_impulses(axes[-1], valve.law, valve.omega_cam)
        axes[-1].set_title(t["jerk_impulse"], fontsize=8, color="C3", loc="right")
    axes[1].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel(t["cam_deg"])
    top = axes[0].secondary_xaxis("top", functions=(lambda c: 2 * c + rad_to_deg(valve.nose_crank),
                                                     lambda k: (k - rad_to_deg(valve.nose_crank)) / 2))
    top.set_xlabel(t["crank_deg"])
    fig.suptitle(f"{valve.name}: {value_text(valve.law.name, t['lang'])}")
    fig.tight_layout()
    return fig


def strength_speed_figure(valve, t):
    """The largest cam load and contact stress at each engine speed of the strength checks, the worst points marked."""
    st = valve.drive.strength
    per = st.per_speed
    rpm = to_display(np.asarray(per.speed), "rpm")
    kinds = np.asarray(per.load)
    fig = Figure(figsize=(8, 6.5))
    axes = fig.subplots(2 if per.contact_stress is not None else 1, 1, sharex=True, squeeze=False)[:, 0]
    rows = [(axes[0], np.asarray(per.cam_force_max), t["cam_force_axis"], st.cam_force_max_speed, st.cam_force_max)]
    if per.contact_stress is not None:
        stress = to_display(np.asarray(per.contact_stress), "MPa")
        rows.append((axes[1], stress, t["contact_stress_axis"], st.contact_stress_speed, float(stress.max())))
    for ax, y, ylabel, worst_speed, worst in rows:
        for kind, marker in (("quasi-static", "."), ("dynamic", "x")):
            on = kinds == kind
            if on.any():
                ax.plot(rpm[on], y[on], ls="-" if kind == "quasi-static" else "none", marker=marker,
                        label=t["load_" + kind.replace("-", "_")])
        ax.plot([to_display(worst_speed, "rpm")], [worst], "o", mfc="none", mec="C3", ms=10)
        ax.axvline(to_display(st.rated_speed, "rpm"), color="0.5", lw=0.8, ls="--", label=t["rated_speed"])
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel(t["engine_speed"])
    fig.suptitle(f"{valve.name}: {t['strength_speed_title']}")
    fig.tight_layout()
    return fig


def contour_figure(valve, t):
    """The cam contour to scale, with the heel circle (and the pitch curve of a roller)."""
    fig = Figure(figsize=(7, 7))
    ax = fig.subplots()
    x, y = valve.contour / MM
    ax.plot(np.append(x, x[0]), np.append(y, y[0]), color="k", lw=1.5, label=t["contour"])
    phi = np.linspace(0, 2 * np.pi, 361)
    r = valve.heel_radius / MM
    ax.plot(r * np.cos(phi), r * np.sin(phi), ls="--", color="C2", lw=0.8, label=t["heel_circle"])
    follower = valve.follower_model
    if follower.rolling:
        h, dh, d2h = valve.law.derivatives(valve.contour_angle)[:3]
        px, py = follower.pitch_curve(valve.contour_angle, valve.heel_radius, h, dh, d2h)[0] / MM
        ax.plot(px, py, color="C1", lw=0.8, label=t["pitch_curve"])
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvline(0, color="0.6", lw=0.5)
    ax.set_aspect("equal")
    ax.set_xlabel(t["x_mm"])
    ax.set_ylabel(t["y_mm"])
    ax.legend(loc="lower right")
    ax.grid(alpha=0.3)
    ax.set_title(f"{valve.name}: {t['contour']}")
    fig.tight_layout()
    return fig


def time_area_figure(valve, t):
    """Curtain area and running time-area against crank angle; the valve's own stroke shaded."""
    tab = valve.table
    k = rad_to_deg(valve.nose_crank + 2.0 * tab.cam_angle)
    fig = Figure(figsize=(8, 5))
    ax = fig.subplots()
    ax.plot(k, tab.curtain_area / MM**2, color="C0")
    ax.set_xlabel(t["crank_deg"])
    ax.set_ylabel(t["curtain"], color="C0")
    lo, hi = valve.summary["flow"]["stroke_crank_deg"]
    ax.axvspan(lo, hi, color="C2", alpha=0.1, label=t["stroke"])
    ax.legend(loc="upper left")
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    ax2.plot(k, tab.time_area / MM**2, color="C3")
    ax2.set_ylabel(t["running_ta"], color="C3")
    ax.set_title(f"{valve.name}: {t['time_area'].split('. ', 1)[-1]}")
    fig.tight_layout()
    return fig


def curvature_figure(valve, t):
    """Radius of curvature of the profile (and the pressure angle of a roller) against camshaft angle."""
    tab = valve.table
    x = rad_to_deg(tab.cam_angle)
    fig = Figure(figsize=(8, 4.5))
    ax = fig.subplots()
    ax.plot(x, tab.rho / MM, color="C0")
    ax.set_xlabel(t["cam_deg"])
    ax.set_ylabel(t["rho"])
    ax.axhline(0.0, color="0.5", lw=0.5)
    ax.grid(alpha=0.3)
    _segment_lines(ax, valve.law)
    if valve.follower_model.rolling:
        ax2 = ax.twinx()
        ax2.plot(x, rad_to_deg(tab.pressure_angle), color="C1")
        ax2.set_ylabel(t["pressure_angle"], color="C1")
    ax.set_title(f"{valve.name}: {t['rho']}")
    fig.tight_layout()
    return fig


def spring_figure(valve, t):
    """Spring characteristic as Fig. 5.1 of Valve-train practical works (n.d.): inertia force, required force and the chosen lines
    against valve lift."""
    drive = valve.drive
    y = drive.lift / MM
    order = np.argsort(y)
    fig = Figure(figsize=(8, 5))
    ax = fig.subplots()
    ax.plot(y[order], drive.inertia_force[order], color="0.5", ls=":", label=t["inertia_force"])
    ax.plot(y[order], drive.required_force[order], color="C3", label=t["required_force"])
    yy = np.array([0.0, y.max()])
    styles = {"required": ("C3", "--"), "chosen": ("k", "-"), "outer": ("C0", "-."), "inner": ("C2", "-.")}
    for name, line in drive.lines.items():
        color, ls = styles[name]
        ax.plot(yy, line.force(yy * MM), color=color, ls=ls, lw=1.5 if name == "chosen" else 1.0,
                label=t["line_" + name])
    ax.set_xlabel(t["valve_lift_axis"])
    ax.set_ylabel(t["force"])
    ax.set_xlim(0.0, y.max())
    ax.set_ylim(0.0, None)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left")
    ax.set_title(f"{valve.name}: {t['spring_title']}")
    fig.tight_layout()
    return fig


def crank_forces_figure(crank, t):
    """Specific forces against the crank angle, as Fig. 2.6 of Power units manual (n.d.): gas, inertia and total; N, S, K, T."""
    c = crank.columns
    x = rad_to_deg(crank.phi)
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(2, 1, sharex=True)
    for key, label in (("p_gas", t["p_gas"]), ("p_j", t["p_in"]), ("p", t["p_total"])):
        axes[0].plot(x, c[key] * 1e-6, label=label)
    for key, label in (("p_N", "p_N"), ("p_S", "p_S"), ("p_K", "p_K"), ("p_T", "p_T")):
        axes[1].plot(x, c[key] * 1e-6, label=label)
    for ax in axes:
        ax.axhline(0, color="0.5", lw=0.5)
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right")
        ax.set_ylabel(t["specific_force"])
    axes[-1].set_xlabel(t["cycle_deg"])
    axes[-1].set_xticks(np.arange(0, x.max() + 1, 90))
    fig.suptitle(t["crank_forces"])
    fig.tight_layout()
    return fig


def crank_torque_figure(crank, t):
    """Torque of every cylinder and the total over one cycle (Fig. 2.7 of Power units manual (n.d.))."""
    x = rad_to_deg(crank.psi)
    fig = Figure(figsize=(9, 5))
    ax = fig.subplots()
    for i, m in enumerate(crank.cylinder_torques, start=1):
        ax.plot(x, m, lw=0.8, alpha=0.7, label=f"{t['cylinder']} {i}")
    ax.plot(x, crank.total_torque, color="k", lw=1.8, label=t["total"])
    ax.axhline(crank.summary["mean_torque_Nm"], color="C3", ls="--", lw=1.0, label=t["mean"])
    ax.set_xlabel(t["engine_deg"])
    ax.set_ylabel(t["torque"])
    ax.set_xticks(np.arange(0, x.max() + 1, 90))
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    return fig


def crank_pin_figure(crank, t):
    """Polar diagram of the crank-pin load in the crank's frame (tangential against radial, kN)."""
    c = crank.columns
    tang, rad = c["pin_tangential"] * 1e-3, -c["pin_radial"] * 1e-3
    fig = Figure(figsize=(7, 7))
    ax = fig.subplots()
    ax.plot(tang, rad, color="C0")
    for deg in range(0, int(rad_to_deg(crank.phi[-1])) + 1, 180):
        k = int(np.argmin(np.abs(rad_to_deg(crank.phi) - deg)))
        ax.annotate(f"{deg}", (tang[k], rad[k]), fontsize=8)
    ax.axhline(0, color="0.5", lw=0.5)
    ax.axvline(0, color="0.5", lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(t["pin_tangential"])
    ax.set_ylabel(t["pin_radial"])
    ax.grid(alpha=0.3)
    ax.set_title(t["pin_polar"])
    fig.tight_layout()
    return fig


def two_stroke_ports_figure(ports, t):
    """Port areas against the crank angle (Valve-train practical works (n.d.), Fig. 8.1 b)."""
    fig = Figure(figsize=(8, 4.5))
    ax = fig.subplots()
    x = rad_to_deg(ports.phi)
    for name, a in ports.areas.items():
        ax.plot(x, a / MM**2, label=name)
    ax.set_xlabel(t["crank_from_tdc"])
    ax.set_ylabel(t["port_area"])
    ax.set_xticks(np.arange(0, 361, 45))
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    return fig


def two_stroke_speed_figure(ports, t):
    """Time-area of each port against the crank speed, Z = f(n) (Valve-train practical works (n.d.), work 8)."""
    fig = Figure(figsize=(8, 4.5))
    ax = fig.subplots()
    for name, z in ports.time_areas.items():
        ax.plot(to_display(ports.speeds, "rpm"), z / MM**2, label=name)
    ax.set_xlabel(t["speed"])
    ax.set_ylabel(t["port_time_area"])
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    return fig


def timing_figure(valves, t):
    """The valve timing diagram: every valve's lift against the crank angle from the gas-exchange TDC on one axis,
    the overlap of intake and exhaust shaded."""
    fig = Figure(figsize=(9, 4))
    ax = fig.subplots()
    crank = np.radians(np.linspace(-360.0, 360.0, 2881))
    open_by_kind = {}
    for name, v in valves.items():
        theta = (crank - v.nose_crank) / 2.0
        lift = v.law.valve_lift(theta, v.rocker_ratio, v.follower_model)
        ax.plot(rad_to_deg(crank), lift / MM, label=name if name == v.kind else f"{name} ({t[v.kind]})",
                color="C0" if v.kind == "intake" else "C3")
        open_by_kind[v.kind] = open_by_kind.get(v.kind, np.zeros_like(crank, dtype=bool)) | (lift > 0.0)
    if len(open_by_kind) == 2:
        overlap = open_by_kind["intake"] & open_by_kind["exhaust"]
        ax.fill_between(rad_to_deg(crank), 0.0, 1.0, where=overlap, transform=ax.get_xaxis_transform(),
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
    fig.tight_layout()
    return fig


def _event_window(d, margin_deg=10.0):
    """Camshaft angles of the sweep around the event (where any speed or the rigid lift is off the seat)."""
    sw = d.sweep
    open_ = (sw.kinematic_lift > 0.0) | np.any(sw.lift > 1e-6, axis=0)
    idx = np.flatnonzero(open_)
    if idx.size == 0:
        return np.ones(sw.theta.size, dtype=bool)
    lo, hi = sw.theta[idx[0]] - np.radians(margin_deg), sw.theta[idx[-1]] + np.radians(margin_deg)
    return (sw.theta >= lo) & (sw.theta <= hi)


def dynamics_map_figure(name, d, t):
    """Maps over camshaft angle and engine speed: valve lift minus the rigid lift, and the cam contact force."""
    sw = d.sweep
    keep = _event_window(d)
    x = rad_to_deg(sw.theta[keep])
    y = to_display(np.asarray(d.per_speed.speed), "rpm")
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(2, 1, sharex=True)
    err = sw.lift_error[:, keep] / MM
    bound = float(np.abs(err).max()) or 1.0
    for ax, z, label, cmap, kw in ((axes[0], err, t["dyn_lift_error"], "RdBu_r", dict(vmin=-bound, vmax=bound)),
                                   (axes[1], sw.contact_force[:, keep], t["dyn_contact_force"], "viridis", {})):
        mesh = ax.pcolormesh(x, y, z, cmap=cmap, shading="auto", rasterized=True, **kw)
        fig.colorbar(mesh, ax=ax, label=label)
        ax.set_ylabel(t["speed"])
        for value, style in ((d.jump_speed, "--"), (d.bounce_speed, ":")):
            if np.isfinite(value):
                ax.axhline(to_display(value, "rpm"), color="k", lw=0.8, ls=style)
    axes[0].set_title(f"{name}: {t['dyn_lift_error']}")
    axes[1].set_title(t["dyn_contact_force"] + " (" + t["dyn_zero_is_jump"] + ")")
    axes[1].set_xlabel(t["cam_deg"])
    fig.tight_layout()
    return fig


def dynamics_speed_figure(name, d, t):
    """Seating velocity, bounce and the smallest contact force against the engine speed, the headline speeds
    marked."""
    p = d.per_speed
    n = to_display(np.asarray(p.speed), "rpm")
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(3, 1, sharex=True)
    axes[0].plot(n, np.abs(np.array(p.seating_velocity, dtype=float)), color="C3")   # None (no seating): a gap
    axes[0].set_ylabel(t["dyn_seating_velocity"])
    axes[1].plot(n, np.asarray(p.bounce) / MM, color="C1")
    axes[1].set_ylabel(t["dyn_bounce"])
    axes[2].plot(n, p.min_contact_force, color="C0")
    axes[2].set_ylabel(t["dyn_min_force"])
    axes[2].set_xlabel(t["speed"])
    for ax in axes:
        ax.grid(alpha=0.3)
        marks = ((d.jump_speed, t["dyn_jump_speed"], "--"), (d.bounce_speed, t["dyn_bounce_speed"], ":"),
                 (d.at_rated_speed.speed, t["dyn_rated"], "-."))
        for value, label, style in marks:
            if np.isfinite(value):
                ax.axvline(to_display(value, "rpm"), color="0.3", lw=0.8, ls=style, label=label)
    axes[0].legend(fontsize=8)
    axes[0].set_title(f"{name}: {t['dyn_title']}")
    fig.tight_layout()
    return fig


def grinding_figure(valve, t):
    """The cam, the wheel-centre path and the master to scale; the lift error of the worn wheel against cam angle."""
    g = valve.grinding
    fig = Figure(figsize=(12, 5.5))
    left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.3]})
    for pts, label, style in ((g.cam_contour, t["gr_cam"], dict(color="k", lw=1.5)),
                              (g.wheel_path, t["gr_wheel_path"], dict(color="C1", lw=0.8, ls="--")),
                              (g.master_contour, t["gr_master"], dict(color="C0", lw=1.2))):
        if pts is not None:
            x, y = pts / MM
            left.plot(np.append(x, x[0]), np.append(y, y[0]), label=label, **style)
    left.set_aspect("equal")
    left.set_xlabel(t["x_mm"])
    left.set_ylabel(t["y_mm"])
    left.grid(alpha=0.3)
    left.legend(loc="lower right", fontsize=8)
    left.set_title(t["gr_contours"])
    w = g.wear
    if w is not None:
        x = rad_to_deg(w.cam_angle)
        right.plot(x, w.error / MM * 1e3, color="C3", label=t["gr_exact"])
        right.plot(x, w.error_first_order / MM * 1e3, color="C0", ls="--", label=t["gr_first_order"])
        _segment_lines(right, valve.law)
        right.legend(loc="upper right", fontsize=8)
    else:
        right.text(0.5, 0.5, t["gr_not_grindable"], ha="center", va="center", transform=right.transAxes, wrap=True)
    right.axhline(0.0, color="0.5", lw=0.5)
    right.set_xlabel(t["cam_deg"])
    right.set_ylabel(t["gr_error_um"])
    right.grid(alpha=0.3)
    right.set_title(t["gr_error_title"].format(wear=g.wheel_wear / MM))
    fig.suptitle(f"{valve.name}: {t['gr_title']}")
    fig.tight_layout()
    return fig


def hydraulic_figure(valve, t):
    """The pressures at both ends of the pipe and the valve lift against the rigid drive's, against camshaft angle."""
    r = valve.hydraulic.response
    fig = Figure(figsize=(10, 7))
    top, bottom = fig.subplots(2, 1, sharex=True)
    x = rad_to_deg(r.angle)
    top.plot(x, r.pump_pressure / 1e6, color="C0", lw=1.0, label=t["hy_pump"])
    top.plot(x, r.actuator_pressure / 1e6, color="C3", lw=1.0, label=t["hy_actuator"])
    top.axhline(valve.hydraulic.vapour_pressure / 1e6, color="0.5", lw=0.6, ls=":", label=t["hy_vapour"])
    cav = r.cavitation
    if cav.any():
        top.plot(x[cav], np.full(int(cav.sum()), valve.hydraulic.vapour_pressure / 1e6), "x", color="k", ms=3,
                 label=t["hy_cavitation"])
    off = r.lift_off()
    if valve.hydraulic.gas_force is not None and off < r.angle.size:
        top.plot(x[off], r.actuator_pressure[off] / 1e6, "o", color="k", ms=5,
                 label=t["hy_lift_off"].format(force=r.gas_force[off] / 1e3))
    top.set_ylabel(t["hy_pressure"])
    top.grid(alpha=0.3)
    top.legend(loc="upper right", fontsize=8)
    bottom.plot(x, r.valve_lift / MM, color="C2", label=t["hy_valve"])
    bottom.plot(x, r.rigid_lift / MM, color="k", ls="--", lw=0.8, label=t["hy_rigid"])
    bottom.axhline(valve.hydraulic.stop / MM, color="C3", ls=":", lw=1.0, label=t["hy_stop"])
    bottom.set_xlabel(t["cam_deg"])
    bottom.set_ylabel(t["hy_lift"])
    bottom.grid(alpha=0.3)
    bottom.legend(loc="upper right", fontsize=8)
    fig.suptitle(f"{valve.name}: {t['hy_title']}")
    fig.tight_layout()
    return fig


def hydraulic_sweep_figure(valve, t):
    """The largest pressure, the lift loss and the delays of the hydraulic drive against the engine speed, the
    simulated speed marked."""
    h = valve.hydraulic
    p = h.per_speed
    n = to_display(np.asarray(p.speed), "rpm")
    fig = Figure(figsize=(9, 8))
    axes = fig.subplots(3, 1, sharex=True)
    axes[0].plot(n, np.asarray(p.max_pressure) / 1e6, "o-", color="C3", ms=3)
    axes[0].set_ylabel(t["hy_max_pressure"])
    axes[1].plot(n, np.asarray(p.lift_loss) / MM, "o-", color="C1", ms=3)
    axes[1].set_ylabel(t["hy_lift_loss"])
    for values, label, color in ((p.opening_delay, t["hy_opening_delay"], "C0"),
                                 (p.closing_delay, t["hy_closing_delay"], "C2")):
        axes[2].plot(n, rad_to_deg(np.array(values, dtype=float)), "o-", color=color, ms=3, label=label)  # None: a gap
    axes[2].set_ylabel(t["hy_delay"])
    axes[2].legend(fontsize=8)
    axes[2].set_xlabel(t["speed"])
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.axvline(to_display(h.speed, "rpm"), color="0.3", lw=0.8, ls="-.")
    cav = np.asarray(p.cavitation)
    if cav.any():
        axes[0].plot(n[cav], np.asarray(p.max_pressure)[cav] / 1e6, "x", color="k", ms=6, label=t["hy_cavitation"])
        axes[0].legend(fontsize=8)
    axes[0].set_title(f"{valve.name}: {t['hy_sweep_title']}")
    fig.tight_layout()
    return fig


DYNAMICS_FIGURES = {"dynamics_map": dynamics_map_figure, "dynamics_speed": dynamics_speed_figure}


def write_dynamics_plots(name, d, folder, t):
    """Write the dynamics figures of one valve as PNG; return ``{kind: filename}``."""
    out = {}
    for kind, make in DYNAMICS_FIGURES.items():
        fname = f"{name}_{kind}.png"
        make(name, d, t).savefig(folder / fname, dpi=110)
        out[kind] = fname
    return out


ENGINE_FIGURES = {"crank": {"crank_forces": crank_forces_figure, "crank_torque": crank_torque_figure,
                            "crank_pin_polar": crank_pin_figure},
                  "two_stroke": {"two_stroke_ports": two_stroke_ports_figure,
                                 "two_stroke_time_area": two_stroke_speed_figure}}


FIGURES = {"kinematics": kinematics_figure, "contour": contour_figure, "time_area": time_area_figure,
           "curvature": curvature_figure, "spring": spring_figure, "strength_speed": strength_speed_figure}

FIGURE_SETS = ("main", "all", "none")
"""Which figures :func:`write_plots` draws (``valvetrain run --figures``): ``main`` all but
:data:`FIGURES_ON_REQUEST`, ``all`` every one, ``none`` none."""

FIGURES_ON_REQUEST = frozenset({"time_area", "curvature", "crank_forces", "crank_pin_polar", "two_stroke_time_area"})
"""The figures drawn only on request (``figures="all"``): each draws quantities whose extremes the report's tables
give (the time-area, the radius of curvature, the crank forces and pin load, the ports' time-area); drawing a figure
costs about 0.1 s, a design's numbers a few milliseconds."""


def write_plots(results, folder, lang="en", figures="main"):
    """Write the figures of ``figures`` (one of :data:`FIGURE_SETS`) as PNG; return ``{valve name or
    "crank"/"two_stroke": {kind: filename}}`` (and ``"(timing)"``: the timing diagram's filename) of those written."""
    if figures not in FIGURE_SETS:
        raise ValueError(f"figures = {figures!r}; allowed: {', '.join(FIGURE_SETS)}")
    t = TEXT[lang]
    written = {}

    def wanted(kind):
        return figures == "all" or (figures == "main" and kind not in FIGURES_ON_REQUEST)

    def save(fig, fname):
        fig.savefig(folder / fname, dpi=110)
        return fname

    for name, valve in results.valves.items():
        written[name] = {kind: save(make(valve, t), f"{name}_{kind}.png") for kind, make in FIGURES.items()
                         if wanted(kind)}
        if valve.dynamics is not None and figures != "none":
            written[name].update(write_dynamics_plots(name, valve.dynamics, folder, t))
        if valve.grinding is not None and wanted("grinding"):
            written[name]["grinding"] = save(grinding_figure(valve, t), f"{name}_grinding.png")
        if valve.hydraulic is not None:
            if wanted("hydraulic"):
                written[name]["hydraulic"] = save(hydraulic_figure(valve, t), f"{name}_hydraulic.png")
            if wanted("hydraulic_sweep"):
                written[name]["hydraulic_sweep"] = save(hydraulic_sweep_figure(valve, t),
                                                        f"{name}_hydraulic_sweep.png")
    if results.valves and wanted("timing"):
        written["(timing)"] = save(timing_figure(results.valves, t), "valve_timing.png")
    for stage, figures_of_stage in ENGINE_FIGURES.items():
        data = getattr(results, stage)
        if data is not None:
            written[stage] = {kind: save(make(data, t), f"{kind}.png") for kind, make in figures_of_stage.items()
                              if wanted(kind)}
    return written
