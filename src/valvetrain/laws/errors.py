"""Inputs a lift law cannot be built from: the reason as data, its message built in one place.

A law that refuses its inputs raises :class:`LawError` with a reason code and the values that prove it, in SI
(lengths in m, angles in rad, rates in N/m, shares as fractions); the catalogue words each code once in every
language (``[notes]`` ``law_error.CODE``: a :class:`~valvetrain.locale.NoteText`), :data:`DISPLAY_UNITS` gives the
display unit of each value.  The message is what the user reads (wrapped in a
:class:`valvetrain.specification.SpecError` that names the keys); the code and the values are there for a caller
that words them otherwise.
"""

from ..errors import InputError
from ..locale import NoteText, note
from ..units import to_display

DISPLAY_UNITS = {
    "law_error.flanks_lift_differ": {"opening": "mm", "closing": "mm"},
    "law_error.nose_below_ramp": {"nose": "mm", "inertia_rate": "N/mm", "stiffness": "N/mm"},
    "law_error.harmonics_deviate": {"deviation": "mm", "lift": "mm"},
    "law_error.lift_within_positive_part": {"lift": "mm", "positive_lift": "mm"},
    "law_error.clearance_exceeds_lift": {"clearance": "mm", "lift": "mm"},
    "law_error.below_base_circle": {"lift": "mm", "angle": "deg", "least": "mm"},
    "law_error.lift_too_small": {"lift": "mm", "angle": "deg", "valve_least": "mm", "least": "mm"},
    "law_error.lift_too_large": {"lift": "mm", "angle": "deg", "most": "mm"},
    "law_error.end_row_lifted": {"angle": "deg", "lift": "mm", "band": "mm", "revolution": "deg"},
    "law_error.second_lobe": {"start": "deg", "end": "deg", "lift": "mm", "lobe_start": "deg", "lobe_end": "deg"},
    "law_error.lobe_too_short": {"band": "mm", "start": "deg", "end": "deg", "span": "deg", "least": "deg"},
    "law_error.too_few_rows": {"band": "mm", "start": "deg", "end": "deg"},
    "law_error.rows_scatter": {"scatter": "mm", "share": "%", "most": "%"},
    "law_error.harmonic_fit_swings": {"low": "mm", "high": "mm", "least": "mm", "most": "mm"},
    "law_error.fit_leaves_table": {"low": "mm", "high": "mm", "top": "mm", "below": "mm", "above": "mm"},
    "law_error.row_off_fit": {"lift": "mm", "angle": "deg", "off": "mm", "most": "mm", "share": "%"},
    "law_error.valve_never_opens": {"ramp": "mm"},
    "law_error.three_arc_nose": {},
    "law_error.three_arc_junction": {},
    "law_error.three_arc_no_nose": {},
    "law_error.tangent_nose": {},
    "law_error.combined_conditions": {},
    "law_error.combined_singular": {},
    "law_error.phases_exceed_half": {"phases": "deg", "half": "deg"},
    "law_error.table_span": {"start": "deg", "end": "deg", "span": "deg", "revolution": "deg"},
}
"""The display unit of each value of a reason's message, by the message's code in the catalogue's ``[notes]``
(:data:`valvetrain.units.UNITS`; ``"%"``: a fraction in per cent; a value without a unit is shown as it is)."""


class LawError(InputError):
    """Inputs a lift law cannot be built from: ``code`` (``law_error.CODE`` of the catalogue's ``[notes]``) and ``values`` (SI)."""

    def __init__(self, code, **values):
        self.code, self.values = code, values
        units = DISPLAY_UNITS[f"law_error.{code}"]
        super().__init__(NoteText(note(f"law_error.{code}", **{k: to_display(v, units[k]) if k in units else v
                                                             for k, v in values.items()})))
