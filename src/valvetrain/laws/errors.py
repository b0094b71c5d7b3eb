"""Inputs a lift law cannot be built from: the reason as data, its message built in one place.

A law that refuses its inputs raises :class:`LawError` with a reason code and the values that prove it, in SI
(lengths in m, angles in rad, rates in N/m, shares as fractions); :data:`MESSAGES` words each code once, with the
display unit of each value.  The message is what the user reads (wrapped in a
:class:`valvetrain.specification.SpecError` that names the keys); the code and the values are there for a caller
that words them otherwise.
"""

from ..errors import InputError
from ..units import to_display

MESSAGES = {
    "flanks_lift_differ": (
        "asymmetric cam: the flanks reach different lifts ({opening:.6g} and {closing:.6g} mm)",
        {"opening": "mm", "closing": "mm"}),
    "nose_below_ramp": (
        "dynamic law: the cam would not rise above its ramp (nose {nose:.4g} mm above it): the inertia term M omega^2 "
        "y'' outweighs the drive's deflection (M omega^2 = {inertia_rate:.4g} N/mm against c = {stiffness:.4g} N/mm); "
        "stiffen the drive, lighten the train or lower the design speed",
        {"nose": "mm", "inertia_rate": "N/mm", "stiffness": "N/mm"}),
    "harmonics_deviate": (
        "harmonic law: N = {harmonics} harmonics with junction_order = {junction_order} follow the target only to "
        "{deviation:.3g} mm of its {lift:.4g} mm lift; allowed {most:.0%} of the lift: lower junction_order or change "
        "harmonics",
        {"deviation": "mm", "lift": "mm"}),
    "lift_within_positive_part": (
        "power_polynomial law: the lift {lift:.4g} mm is reached within the positive part (S_e = {positive_lift:.4g} "
        "mm); lower peak_acceleration or phi1",
        {"lift": "mm", "positive_lift": "mm"}),
    "clearance_exceeds_lift": (
        "{law} law: a clearance of {clearance:.4g} mm cannot be taken up by a lift of {lift:.4g} mm",
        {"clearance": "mm", "lift": "mm"}),
    "below_base_circle": (
        "lift_mm = {lift:g} at angle_deg = {angle:g} lies below the base circle; allowed >= {least:g} mm (3 x "
        "accuracy_mm of measurement noise)",
        {"lift": "mm", "angle": "deg", "least": "mm"}),
    "lift_too_small": (
        "the largest lift is {lift:g} mm (angle_deg = {angle:g}); a cam lobe lifts the valve at least {valve_least:g} "
        "mm: allowed >= {least:.4g} mm in this table",
        {"lift": "mm", "angle": "deg", "valve_least": "mm", "least": "mm"}),
    "lift_too_large": (
        "the largest lift is {lift:g} mm (angle_deg = {angle:g}); allowed at most {most:g} mm (is the table in "
        "millimetres?)",
        {"lift": "mm", "angle": "deg", "most": "mm"}),
    "end_row_lifted": (
        "the {end} row, angle_deg = {angle:g}, lifts {lift:g} mm: a table starts and ends on the base circle, allowed "
        "|lift| <= {band:g} mm (3 x accuracy_mm), or covers a whole revolution ({revolution:g} {unit}) around the lobe",
        {"angle": "deg", "lift": "mm", "band": "mm", "revolution": "deg"}),
    "second_lobe": (
        "a second lift region, angle_deg = {start:g} to {end:g} (up to {lift:g} mm), besides the lobe at "
        "{lobe_start:g} to {lobe_end:g}, separated by base-circle rows; a table holds one lobe",
        {"start": "deg", "end": "deg", "lift": "mm", "lobe_start": "deg", "lobe_end": "deg"}),
    "lobe_too_short": (
        "the lobe (lift above {band:g} mm) spans angle_deg = {start:g} to {end:g}, {span:.4g} {unit}; allowed at "
        "least {least:g} {unit} ({cam_least:g} cam deg: no cam lobe is shorter); are the angles in radians?",
        {"band": "mm", "start": "deg", "end": "deg", "span": "deg", "least": "deg"}),
    "too_few_rows": (
        "the lobe (lift above {band:g} mm from angle_deg = {start:g} to {end:g}) has {rows} rows with its margin of "
        "base circle; at least {least} are needed to fit it",
        {"band": "mm", "start": "deg", "end": "deg"}),
    "rows_scatter": (
        "the rows scatter by {scatter:.3g} mm (third differences), {share:.3g} % of the largest lift; allowed up to "
        "{most:g} %: no smooth lobe (a step, a flat top, too few rows?)",
        {"scatter": "mm", "share": "%", "most": "%"}),
    "harmonic_fit_swings": (
        "the N-harmonic fit (N = {harmonics}) swings from {low:.4g} to {high:.4g} mm of tappet lift between the rows; "
        "allowed {least:.4g} to {most:.4g} mm (the table's range, 3 x accuracy_mm and the interpolation error of the "
        "angle step): use fit = \"spline\"",
        {"low": "mm", "high": "mm", "least": "mm", "most": "mm"}),
    "fit_leaves_table": (
        "the {fit} fit runs from {low:.4g} to {high:.4g} mm against the table's 0 to {top:.4g} mm; allowed "
        "{below:.3g} to +{above:.3g} mm beyond them (3 x the noise, the fit's largest residual and the interpolation "
        "error of the angle step): no smooth lobe (a flat top, a step, too few rows?)",
        {"low": "mm", "high": "mm", "top": "mm", "below": "mm", "above": "mm"}),
    "row_off_fit": (
        "the row of {lift:.4g} mm follower lift at {angle:.4g} cam deg (crank deg from the gas-exchange TDC / 2) lies "
        "{off:.3g} mm off the {fit} fit; allowed up to {most:.3g} mm ({times:g} x max(accuracy_mm, scatter), at least "
        "{share:g} % of the lift): a wrong row?",
        {"lift": "mm", "angle": "deg", "off": "mm", "most": "mm", "share": "%"}),
    "valve_never_opens": (
        "the fitted lift never exceeds the clearance taken up by the ramp, {ramp:.4g} mm: the valve does not open",
        {"ramp": "mm"}),
}
"""The message of each reason code and the display unit of each of its values (:data:`valvetrain.units.UNITS`;
``"%"``: a fraction in per cent; a value without a unit is shown as it is)."""


class LawError(InputError):
    """Inputs a lift law cannot be built from: ``code`` (a key of :data:`MESSAGES`) and ``values`` (SI)."""

    def __init__(self, code, **values):
        self.code, self.values = code, values
        template, units = MESSAGES[code]
        super().__init__(template.format(**{k: to_display(v, units[k]) if k in units else v for k, v in values.items()}))
