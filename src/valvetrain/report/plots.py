"""Plots of every stage of a valve design (matplotlib, written as PNG files)."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..units import MM, rad_to_deg  # noqa: E402
from .i18n import TEXT  # noqa: E402


def _segment_lines(ax, law):
    for a in law.breakpoints[1:-1]:
        ax.axvline(rad_to_deg(a), color="0.75", lw=0.6, ls=":")


def kinematics_figure(valve, t):
    """Tappet lift (and valve lift), velocity, acceleration and jerk against camshaft angle."""
    tab = valve.table
    x = rad_to_deg(tab.cam_angle)
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    axes[0].plot(x, tab.lift / MM, label=t["tappet_lift"])
    axes[0].plot(x, tab.valve_lift / MM, label=t["valve_lift"])
    axes[0].legend(loc="upper right")
    for ax, y, label in zip(axes, (None, tab.velocity, tab.acceleration, tab.jerk),
                            ("lift", "velocity", "acceleration", "jerk")):
        if y is not None:
            ax.plot(x, y, color="C0")
        ax.set_ylabel(t[label])
        ax.grid(alpha=0.3)
        ax.axhline(0.0, color="0.5", lw=0.5)
        _segment_lines(ax, valve.law)
    axes[-1].set_xlabel(t["cam_deg"])
    top = axes[0].secondary_xaxis("top", functions=(lambda c: 2 * c + rad_to_deg(valve.nose_crank),
                                                     lambda k: (k - rad_to_deg(valve.nose_crank)) / 2))
    top.set_xlabel(t["crank_deg"])
    fig.suptitle(f"{valve.name}: {valve.law.name}")
    fig.tight_layout()
    return fig


def contour_figure(valve, t):
    """The cam contour to scale, with the heel circle (and the pitch curve of a roller)."""
    fig, ax = plt.subplots(figsize=(7, 7))
    x, y = valve.contour / MM
    ax.plot(np.append(x, x[0]), np.append(y, y[0]), color="k", lw=1.5, label=t["contour"])
    phi = np.linspace(0, 2 * np.pi, 361)
    r = valve.heel_radius / MM
    ax.plot(r * np.cos(phi), r * np.sin(phi), ls="--", color="C2", lw=0.8, label=t["heel_circle"])
    if valve.follower == "roller":
        h = valve.law.lift(valve.contour_angle)
        g = (valve.heel_radius + valve.roller_radius + h) / MM
        ax.plot(g * np.sin(valve.contour_angle), g * np.cos(valve.contour_angle), color="C1", lw=0.8,
                label=t["pitch_curve"])
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvline(0, color="0.6", lw=0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
    ax.legend(loc="lower right")
    ax.grid(alpha=0.3)
    ax.set_title(f"{valve.name}: {t['contour']}")
    fig.tight_layout()
    return fig


def time_area_figure(valve, t):
    """Curtain area and running time-area against crank angle; the valve's own stroke shaded."""
    tab = valve.table
    k = rad_to_deg(valve.nose_crank + 2.0 * tab.cam_angle)
    fig, ax = plt.subplots(figsize=(8, 5))
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
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(x, tab.rho / MM, color="C0")
    ax.set_xlabel(t["cam_deg"])
    ax.set_ylabel(t["rho"])
    ax.axhline(0.0, color="0.5", lw=0.5)
    ax.grid(alpha=0.3)
    _segment_lines(ax, valve.law)
    if valve.follower == "roller":
        ax2 = ax.twinx()
        ax2.plot(x, rad_to_deg(tab.pressure_angle), color="C1")
        ax2.set_ylabel(t["pressure_angle"], color="C1")
    ax.set_title(f"{valve.name}: {t['rho']}")
    fig.tight_layout()
    return fig


def spring_figure(valve, t):
    """Spring characteristic as Fig. 5.1 of seed 000: inertia force, required force and the chosen lines
    against valve lift."""
    drive = valve.drive
    y = drive.lift / MM
    order = np.argsort(y)
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(y[order], drive.inertia_force[order], color="0.5", ls=":", label=t["inertia_force"])
    ax.plot(y[order], drive.required_force[order], color="C3", label=t["required_force"])
    yy = np.array([0.0, y.max()])
    styles = {"required": ("C3", "--"), "chosen": ("k", "-"), "outer": ("C0", "-."), "inner": ("C2", "-.")}
    for name, line in drive.lines.items():
        color, ls = styles[name]
        ax.plot(yy, line.force(yy * MM), color=color, ls=ls, lw=1.5 if name == "chosen" else 1.0,
                label=t["line_" + name])
    ax.set_xlabel(t["valve_lift"] + ", mm")
    ax.set_ylabel(t["force"])
    ax.set_xlim(0.0, y.max())
    ax.set_ylim(0.0, None)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left")
    ax.set_title(f"{valve.name}: {t['spring_title']}")
    fig.tight_layout()
    return fig


FIGURES = {"kinematics": kinematics_figure, "contour": contour_figure, "time_area": time_area_figure,
           "curvature": curvature_figure, "spring": spring_figure}


def write_plots(results, folder, lang="en"):
    """Write every figure of every valve as ``folder/NAME_KIND.png``; return ``{name: {kind: filename}}``."""
    t = TEXT[lang]
    written = {}
    for name, valve in results.valves.items():
        written[name] = {}
        for kind, make in FIGURES.items():
            fig = make(valve, t)
            fname = f"{name}_{kind}.png"
            fig.savefig(folder / fname, dpi=110)
            plt.close(fig)
            written[name][kind] = fname
    return written
