"""What a lift law adds to the cam's results: typed, frozen records (SI inside) that the report reads by attribute.

:class:`LawRecord` holds the records a cam section gives (:meth:`valvetrain.specification.cam_base._CamBase.records`):
the appendix formulas and junction residuals of a Kurz cam, the responses of a power-polynomial synthesis, the
analysis of a measured lift table.  Their fields are declared with :func:`valvetrain.results.quantity`, so that
results.json shows them under the cam's record with the keys and units it always had.
"""

from dataclasses import dataclass
from typing import Optional

from ..results import quantity


@dataclass(frozen=True)
class SeedFormulas:
    """The closed-form extremes of a Kurz cam, follower side (Valve-train practical works (n.d.), eqs. (2.35)-(2.39))."""

    max_velocity: float = quantity("max_velocity_m_s", "m/s", "largest tappet velocity by the appendix formula")
    max_acceleration: float = quantity("max_acceleration_m_s2", "m/s2",
                                       "largest tappet acceleration by the appendix formula")
    min_acceleration: float = quantity("min_acceleration_m_s2", "m/s2",
                                       "smallest tappet acceleration by the appendix formula")
    rho_min: float = quantity("rho_min_mm", "mm", "smallest radius of curvature by the appendix formula")
    rho_max: float = quantity("rho_max_mm", "mm", "largest radius of curvature by the appendix formula")


@dataclass(frozen=True)
class PowerPolynomialRecord:
    """The responses of a power-polynomial cam synthesis (SI)."""

    phi2: float = quantity("phi2_deg", "deg", "phi_2, end of the positive acceleration [cam deg]")
    dwell: float = quantity("dwell_deg", "deg", "the dwell at the nose [cam deg]")
    end_lift: float = quantity("S_e_mm", "mm", "S_e, tappet lift at the end of the ramp")
    end_velocity: float = quantity("v_e_mm_per_rad", "mm/rad", "v_e, tappet velocity analogue at the end of the ramp")
    tappet_fullness: float = quantity("tappet_fullness", label="fullness of the tappet lift diagram")


@dataclass(frozen=True)
class Duration:
    """The duration of a measured lobe above one checking height."""

    height: float = quantity("height_mm", "mm", "checking height (valve or tappet lift, as in the table)")
    duration: Optional[float] = quantity("duration_deg", "deg", "duration above it in the table's angle units; "
                                         "null where the lift never reaches it")


@dataclass(frozen=True)
class FitQuality:
    """How closely one fit of a measured table follows the table."""

    rms_residual: float = quantity("rms_residual_mm", "mm", "rms residual")
    max_residual: float = quantity("max_residual_mm", "mm", "largest residual")
    jerk_sign_changes: int = quantity("jerk_sign_changes", label="sign changes of the jerk over the lobe")


@dataclass(frozen=True)
class MeasuredRecord:
    """The analysis of a measured lift table (Shang Hanji (1988), sections 5.1-5.3); lifts at the valve or the
    tappet and angles in camshaft or crank degrees as in the table (SI)."""

    max_lift: float = quantity("max_lift_mm", "mm", "largest lift of the lobe")
    lobe_centre: float = quantity("lobe_centre_deg", "deg", "centre of the lobe")
    durations: tuple[Duration, ...] = quantity("durations_deg", label="durations at the checking heights")
    fit: str = quantity("fit", label="the fit used: spline or harmonic")
    fit_reason: str = quantity("fit_reason", label="why that fit")
    fit_reason_code: str = quantity("fit_reason_code", label="code of the reason")
    spline_smoothing: str = quantity("spline_smoothing", label="how the spline's smoothing was chosen: accuracy or gcv")
    gcv_ratio: Optional[float] = quantity("gcv_ratio_harmonic_to_spline",
                                          label="generalised cross-validation score, harmonic over spline")
    harmonics: int = quantity("harmonics", label="harmonic order of the harmonic fit")
    asymmetry_rms: float = quantity("asymmetry_rms_mm", "mm", "rms difference of the flanks")
    accuracy: float = quantity("accuracy_mm", "mm", "accuracy of the table's lifts")
    accuracy_from: str = quantity("accuracy_from", label="the accuracy as stated or from the table")
    fit_quality: dict[str, FitQuality] = quantity("fit_quality", label="closeness of each fit")
    table_angle: str = quantity("table_angle", label="the table's angles: cam or crank")
    table_lift_at: str = quantity("table_lift_at", label="the table's lifts: at the valve or the tappet")
    table_zero: str = quantity("table_zero", label="the table's angle zero")
    opens: Optional[float] = quantity("opens_deg_at_0.1mm", "deg", "where the valve lift rises through 0.1 mm "
                                      "[crank deg from the gas-exchange TDC]")
    closes: Optional[float] = quantity("closes_deg_at_0.1mm", "deg", "where the valve lift falls through 0.1 mm "
                                       "[crank deg from the gas-exchange TDC]")


@dataclass(frozen=True)
class LawRecord:
    """What a law adds to the cam's results, each part where the law gives it (its keys merged into the cam's)."""

    seed_formulas: Optional[SeedFormulas] = quantity("seed_formulas", label="the appendix formulas of a Kurz cam",
                                                     omit_none=True, default=None)
    residuals: Optional[dict[str, float]] = quantity("residuals", label="residuals of the junction conditions, by "
                                                     "equation number", omit_none=True, default=None)
    power_polynomial: Optional[PowerPolynomialRecord] = quantity(
        "power_polynomial", label="the responses of a power-polynomial synthesis", omit_none=True, default=None)
    measured: Optional[MeasuredRecord] = quantity("measured", label="the analysis of a measured lift table",
                                                  omit_none=True, default=None)


__all__ = ["Duration", "FitQuality", "LawRecord", "MeasuredRecord", "PowerPolynomialRecord", "SeedFormulas"]
