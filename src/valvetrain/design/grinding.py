"""The grinding stage of a valve design: the copy grinder's master cam and the lift error of wheel wear
([valves.NAME.grinding]).

From the cam's law and follower (the law stage) and the SI view of the grinding section, the stage gives
the wheel-centre path, the master follower's lift, the master contour (for the master's own manufacture,
also its flat-follower lift for a surface grinder) and the follower lift error of a cam ground by a worn
wheel, exact and first order (:mod:`valvetrain.cam_grinding`).  A wheel that cannot grind a concave
stretch of the cam, or a master its roller cannot follow, is a failure check, and nothing of that
master is written for cam_grinding.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from .. import cam_grinding
from ..checks import Check, check
from ..locale import NoteText, cited, note
from ..errors import InputError
from ..specification.messages import Problem
from ..units import MM
from .results import quantity

SOURCES = cited(note("source.master_cam", work="Shang Hanji (1988), ch. 6"))
"""The works the grinding stage follows, as the report cites them."""

CONCAVE_SOURCE = cited(note("source.wheel_radius", work="UkrSURT Proceedings (2019)"), "Shang Hanji (1988), ch. 6")
MASTER_SOURCE = cited(note("source.master_roller", work="Shang Hanji (1988), eq. (2.7)"))

DENSE = 8192
"""Cam angles over a revolution on which the master contour, its curvature and its flat-follower lift are
computed (the law's breakpoints added)."""

WEAR_STEP = 0.5 * np.pi / 180.0
"""Step of the wear-error table [cam rad]."""


@dataclass(frozen=True)
class MasterTable:
    """The master cam sampled for manufacture (SI): against the spindle (polar) angle psi [rad from the nose]."""

    psi: np.ndarray                 # spindle angles of the export step [rad]
    wheel_centre: np.ndarray        # wheel-centre polar radius L(psi) [m]
    follower_lift: np.ndarray       # master follower lift s_m(psi) = i (L - L_min) [m]
    radius: np.ndarray              # polar radius of the master contour at psi [m]
    flat_lift: np.ndarray           # flat-follower (surface grinder) lift of the master at psi [m]; nan if concave


@dataclass(frozen=True)
class WearTable:
    """The lift error of the cam ground by the worn wheel, against the cam angle (SI)."""

    cam_angle: np.ndarray           # [rad from the nose]
    lift: np.ndarray                # design follower lift [m]
    worn_lift: np.ndarray           # follower lift of the cam ground by the worn wheel [m] (exact, re-enveloped)
    error: np.ndarray               # worn_lift - lift [m]
    error_first_order: np.ndarray   # [m]
    phase_shift: np.ndarray         # delta [rad]


@dataclass(frozen=True)
class GrindingResult:
    """The grinding stage: wheel-centre path, master cam and the lift error of wheel wear (SI)."""

    wheel_radius: float = quantity("wheel_radius_mm", "mm", "grinding wheel radius R_w")
    master_follower_radius: float = quantity("master_follower_radius_mm", "mm", "master follower (roller) radius r_m")
    bar_ratio: float = quantity("bar_ratio", label="bar ratio i: master follower travel / wheel-centre travel")
    master_base_radius: float = quantity("master_base_radius_mm", "mm", "heel circle radius of the master R_m0")
    wheel_centre_min: float = quantity("wheel_centre_min_radius_mm", "mm", "wheel centre's smallest distance from "
                                       "the cam axis, L_min = heel radius + R_w")
    wheel_centre_max: float = quantity("wheel_centre_max_radius_mm", "mm", "wheel centre's largest distance, L_max")
    master_lift: float = quantity("master_follower_lift_mm", "mm", "largest master follower lift i (L_max - L_min)")
    path_factor: float = quantity("wheel_path_factor_min", label="smallest 1 + R_w / rho of the cam contour (> 0: "
                                  "the wheel grinds the whole contour)")
    concave_radius: Optional[float] = quantity("cam_min_concave_radius_mm", "mm",
                                               "cam's concave radius closest to zero (null: no concave stretch)")
    grindable: bool = quantity("grindable", label="the wheel grinds the contour without cutting into it")
    master_rho_min: Optional[float] = quantity("master_rho_min_mm", "mm", "smallest radius of curvature of the "
                                               "master contour (convex stretches; null: not grindable)")
    master_convex: bool = quantity("master_convex", label="the master is convex (a flat wheel face can grind it)")
    master_makeable: bool = quantity("master_makeable", label="a master exists for this wheel and its roller follows "
                                     "it: the master files are written")
    master_flat_lift: Optional[float] = quantity("master_flat_lift_max_mm", "mm", "largest flat-follower lift of "
                                                 "the master (surface grinder; null: the master is not convex)")
    wheel_wear: float = quantity("wheel_wear_mm", "mm", "wheel wear w (radius lost) of the error table")
    wear_compensation: str = quantity("wear_compensation", label="none: the worn wheel on the design centre path; "
                                      "infeed: the head fed in by the wear to restore the base circle")
    max_error: Optional[float] = quantity("max_wear_lift_error_mm", "mm", "largest |lift error| of the worn wheel, "
                                          "exact (null: not grindable)")
    max_error_angle: Optional[float] = quantity("max_wear_lift_error_cam_deg", "cam deg", "where it is largest")
    max_error_first_order: Optional[float] = quantity("max_wear_lift_error_first_order_mm", "mm",
                                                      "largest |lift error|, first order")
    max_phase_shift: Optional[float] = quantity("max_wear_phase_shift_cam_deg", "cam deg",
                                                "largest |phase shift| of the lift, first order")
    wear_table_file: Optional[str] = quantity("wear_table", label="the wear-error table in the output folder",
                                              default=None, omit_none=True)
    master: Optional[MasterTable] = field(default=None, repr=False)
    master_contour: Optional[np.ndarray] = field(default=None, repr=False)    # (2, n) [m], master frame
    master_angle: Optional[np.ndarray] = field(default=None, repr=False)      # cam angle of each point [rad]
    cam_contour: Optional[np.ndarray] = field(default=None, repr=False)       # (2, n) [m]
    wheel_path: Optional[np.ndarray] = field(default=None, repr=False)        # (2, n) [m]
    wear: Optional[WearTable] = field(default=None, repr=False)


def grinding_stage(grinding, cam, name, export_step) -> tuple[GrindingResult, list[Check]]:
    """The master cam and the wear error of one valve's cam.

    Parameters
    ----------
    grinding : SI view of ``[valves.NAME.grinding]``
    cam : CamResult
        The law stage (law, heel radius, follower, roller radius).
    name : str
        The valve's name (the table's file name).
    export_step : float
        Step of the master's tables [rad].

    Returns
    -------
    GrindingResult, list of Check

    References
    ----------
    Shang Hanji (1988), ch. 6; :mod:`valvetrain.cam_grinding`.
    """
    law, heel, follower = cam.law, cam.heel_radius, cam.follower_model
    derivs = law.derivatives
    r_w, r_m, i = grinding.wheel_radius, grinding.master_follower_radius, grinding.bar_ratio
    base = grinding.master_base_radius
    if base is None:
        base = cam_grinding.default_master_base_radius(heel, r_w, i, r_m)
        if base <= 0.0:
            raise InputError(Problem("master_follower_radius_mm", NoteText(note(
                "spec.master_heel", heel=base / MM, most=i * (heel + r_w) / MM)), f"{r_m / MM:g}"))
    theta = np.unique(np.concatenate([np.linspace(-np.pi, np.pi, DENSE, endpoint=False), law.breakpoints]))
    ok, factor = cam_grinding.grindable(derivs, theta, heel, r_w, follower)
    cam_contour, rho = law.profile(theta, heel, follower)[:2]
    # a roller cam is concave where its pitch curve is (rho + R_r < 0); a flat follower's cam is never concave (its
    # rho <= 0 is an undercut, a failure of the profile stage)
    concave = rho[follower.concave(rho)]
    concave_radius = float(np.max(concave)) if concave.size else None
    found = []
    if concave_radius is not None:
        found.append(check("grinding.concave_radius", -concave_radius, low=r_w,
                           strict_low=True, source=CONCAVE_SOURCE, unit="mm", severity="failure",
                           note=note("grinding.wheel_radius", radius_mm=r_w / MM)))
    path, length, _ = cam_grinding.wheel_centre_path(derivs, theta, heel, r_w, follower)
    l_min, l_max = heel + r_w, float(np.max(length))
    args = (heel, r_w, i, base, r_m, follower)
    master_ok, master_rho, convex = False, None, False
    if ok:   # a looped wheel path has no master
        pitch_rho = cam_grinding.master_pitch_curvature(derivs, theta, *args)
        convex = bool(np.all(pitch_rho > r_m))
        master_rho = float(np.min(np.where(pitch_rho > 0.0, pitch_rho, np.inf)) - r_m)
        master_ok = master_rho > 0.0
        found.append(check("grinding.master_undercut", master_rho, low=0.0,
                           strict_low=True, source=MASTER_SOURCE, unit="mm", severity="failure",
                           note=note("grinding.master_roller", roller_mm=r_m / MM, ratio=i)))
    result = dict(wheel_radius=r_w, master_follower_radius=r_m, bar_ratio=i, master_base_radius=base,
                  wheel_centre_min=l_min, wheel_centre_max=l_max, master_lift=i * (l_max - l_min),
                  path_factor=factor, concave_radius=concave_radius, grindable=bool(ok), master_rho_min=master_rho,
                  master_convex=convex, master_makeable=master_ok, master_flat_lift=None,
                  wheel_wear=grinding.wheel_wear, wear_compensation=grinding.wear_compensation, max_error=None,
                  max_error_angle=None, max_error_first_order=None,
                  max_phase_shift=None, cam_contour=cam_contour, wheel_path=path)
    if not ok:
        return GrindingResult(**result), found
    if master_ok:
        psi = np.radians(np.arange(-180.0, 180.0, np.degrees(export_step)))
        wheel = cam_grinding.wheel_centre_radius(derivs, psi, heel, r_w, follower)
        contour = cam_grinding.master_contour(derivs, theta, *args)
        radius = cam_grinding.master_polar_radius(derivs, psi, *args)
        flat = np.full_like(psi, np.nan)
        if convex:
            flat = cam_grinding.master_flat_lift(derivs, psi, *args)
            result["master_flat_lift"] = float(np.max(flat))
        result.update(master=MasterTable(psi, wheel, i * (wheel - l_min), radius, flat), master_contour=contour,
                      master_angle=theta)
    # start + k step: np.arange would step by (start + step) - start, 2e-12 deg off after a few hundred steps
    t = law.start + WEAR_STEP * np.arange(int(np.ceil((law.end - law.start) / WEAR_STEP + 0.5)))
    lift = law.lift(t)
    infeed = grinding.wear_compensation == "infeed"
    worn = cam_grinding.worn_wheel_lift(derivs, t, heel, r_w, grinding.wheel_wear, follower, infeed)
    first, phase = cam_grinding.wear_error_first_order(derivs, t, heel, grinding.wheel_wear, follower, r_w,
                                                      infeed)
    error = worn - lift
    k = int(np.argmax(np.abs(error)))
    result.update(wear=WearTable(t, lift, worn, error, first, phase), max_error=float(np.abs(error[k])),
                  max_error_angle=float(t[k]), max_error_first_order=float(np.max(np.abs(first))),
                  max_phase_shift=float(np.max(np.abs(phase))), wear_table_file=f"tables/{name}_wear_error.csv")
    return GrindingResult(**result), found


WEAR_COLUMNS = [
    ("cam_deg", "camshaft angle from the cam nose [deg]"),
    ("lift_mm", "design follower lift [mm]"),
    ("worn_lift_mm", "follower lift of the cam ground by the worn wheel, from its own base circle (with infeed the "
                     "design base circle) [mm]"),
    ("error_mm", "lift error, exact (re-enveloped) [mm]"),
    ("error_first_order_mm", "lift error, first order [mm]"),
    ("phase_shift_deg", "phase shift of the lift, first order [cam deg]"),
]
"""Columns of ``tables/NAME_wear_error.csv``."""


def wear_columns(g) -> dict[str, np.ndarray]:
    """The wear-error table in the units of :data:`WEAR_COLUMNS`."""
    w = g.wear
    return {"cam_deg": np.degrees(w.cam_angle), "lift_mm": w.lift / MM, "worn_lift_mm": w.worn_lift / MM,
            "error_mm": w.error / MM, "error_first_order_mm": w.error_first_order / MM,
            "phase_shift_deg": np.degrees(w.phase_shift)}


def master_polar_columns(g) -> dict[str, np.ndarray]:
    """The master for manufacture against the spindle angle: wheel-centre radius, master follower lift, master
    polar radius and its flat-follower (surface grinder) lift [deg, mm]."""
    m = g.master
    return {"spindle_deg": np.degrees(m.psi), "wheel_centre_radius_mm": m.wheel_centre / MM,
            "master_follower_lift_mm": m.follower_lift / MM, "master_radius_mm": m.radius / MM,
            "master_flat_lift_mm": m.flat_lift / MM}


def master_cartesian_columns(g) -> dict[str, np.ndarray]:
    """The master contour points [deg, mm] (the cam angle each point grinds)."""
    x, y = g.master_contour / MM
    return {"cam_deg": np.degrees(g.master_angle), "x_mm": x, "y_mm": y}


__all__ = ["GrindingResult", "MasterTable", "WEAR_COLUMNS", "WearTable", "grinding_stage", "master_cartesian_columns",
           "master_polar_columns", "wear_columns"]
