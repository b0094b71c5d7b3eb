"""Design checks as data: one record for every check, passed or failed.

Every computed design is compared with the recommended ranges and the allowable limits of
the sources.  Each comparison is a :class:`Check`: its code, the quantity, its value, the bounds, the
unit they are shown in, the source of the bounds, the severity of a failure and the margin.
A check that fails is not an exception: the report lists every check, ``results.json``
carries them, the failed ones are the design's warnings, and an optimiser takes its
constraints from the margins.

Severity (:data:`SEVERITIES`) says what a failed check means, by the kind of bound:

* ``failure``: an allowable limit of a part or a physical limit -- a stress or a safety factor of the strength
  and spring calculations, an undercut profile (a part that breaks, wears through or cannot be made);
* ``warning``: a recommended band of a textbook -- velocities, accelerations, timing, ratios, curvature (a design
  that works, but outside the experience the source summarises);
* ``info``: an informative comparison -- a value the user chose against what the source calls usual (the seat
  angle), or a default of the source known to be far from today's parts (the specific drive mass).

A check fails when its value lies outside its range, whatever its severity.  A check whose value is not a finite
number cannot be evaluated (the valve has not reseated, so there is no seating velocity): it is a failure, whatever
the severity of its range, and is shown as ``cannot be evaluated: REASON`` in words, never as ``nan``
(:attr:`Check.unevaluated` gives the reason, :data:`UNEVALUATED` where the stage gave none).  :func:`ranked` orders failed checks
for a reader: failures first, then warnings, then info, and within a level the farthest outside first (the most
negative relative :attr:`Check.margin`).  A failed check the user accepted in the specification (``[[accepted]]``,
with a reason) keeps its severity and its record and carries ``accepted`` and ``reason``
(:func:`apply_acceptances`): the report lists it apart, with the reason, and it is no longer an open warning.

A check is identified by its stable code (``tappet_acceleration.max``) and its parameters (the exponent of a
power-polynomial cam: ``{"exponent": "n"}``), never by its text: the English and Russian texts are renderings of the
code from the message catalogue :mod:`valvetrain.locale` (``quantity`` is the English record text, with the valve
or chapter in front).  ``[[accepted]]`` names a check by its code or by that text.

Values and bounds are SI; ``unit`` names the unit they are shown in (see
:func:`valvetrain.units.to_display`), so that conversion happens only when a check is shown.
"""

from dataclasses import dataclass, replace
from decimal import Decimal
import math
from typing import Any

from .errors import InputError
from .locale import Note, NoteText, catalogue, code_of, note, note_text, number_text, record_text
from .units import displayed, to_display

SEVERITIES = ("info", "warning", "failure")
"""What a failed check means: ``info`` a remark, ``warning`` a value outside a recommended range,
``failure`` a limit a part cannot pass (a stress above its allowable, an impossible geometry)."""

UNEVALUATED = NoteText(note("checks.unevaluated"))
"""The reason of a check that cannot be evaluated where the stage that made it gave none (its English, rendered by the
report in its language)."""

_TOL = 1e-9
"""Relative tolerance at a bound, so that a value printed as the bound (0.46 = 36.8/80) is inside."""


@dataclass(frozen=True)
class Check:
    """One value against its allowed range.

    Attributes
    ----------
    quantity : str
        What was checked in English, with the part it belongs to (e.g. ``"intake: V' (throat velocity)"``): the
        record text of :attr:`code` (:func:`valvetrain.locale.record_text`).
    value : float
        The computed value, SI.
    low, high : float or None
        Bounds of the allowed or recommended range, SI; None leaves that side open.
    unit : str
        Unit in which value and bounds are shown (``"mm"``, ``"MPa"``, ``"crank deg"``, ``""``).
    source : str
        Where the range comes from.
    severity : {"info", "warning", "failure"}
        What a failure means.
    strict_low : bool
        The lower bound itself fails (``value > low`` required).
    note : str
        How the value was obtained, where that needs saying, in English (``results.json``, the console).
    note_parts : tuple
        The note as codes of the catalogue with their parameters (:func:`valvetrain.locale.note`), from which
        :attr:`note` is rendered and the report renders it in its language; empty for a note given as text.
    accepted : bool
        The user accepted this check in the specification (``[[accepted]]``); meaningful for a failed check.
    reason : str
        The user's reason for the acceptance.
    unevaluated : str
        Why the value cannot be had, for a value that is not a finite number (:func:`check` makes such a check a
        failure and gives :data:`UNEVALUATED` where no reason is given); empty otherwise.
    code : str
        The stable code of the check (``"tappet_acceleration.max"``, :mod:`valvetrain.locale`).
    params : tuple of (str, object)
        The parameters of the code's texts (``(("exponent", "n"),)``).
    valve : str or None
        The valve the check belongs to (None: the engine's, a chapter's).
    """

    quantity: str
    value: float
    low: float = None
    high: float = None
    unit: str = ""
    source: str = ""
    severity: str = "warning"
    strict_low: bool = False
    note: str = ""
    accepted: bool = False
    reason: str = ""
    unevaluated: str = ""
    code: str = ""
    params: tuple = ()
    valve: str = None
    note_parts: Note = ()

    @property
    def passed(self) -> bool:
        """True when the value lies within the bounds (to a relative 1e-9 at a bound)."""
        v = float(self.value)
        if not math.isfinite(v):
            return False
        if self.low is not None:
            if self.strict_low and v <= self.low:
                return False
            if v < self.low - _TOL * max(1.0, abs(self.low)):
                return False
        return self.high is None or v <= self.high + _TOL * max(1.0, abs(self.high))

    @property
    def margin(self) -> float:
        """Relative distance to the nearest bound, >= 0 when the check passes: (value - low)/|low| and
        (high - value)/|high| (a bound of 0 divides by 1 in SI); +inf without bounds, -inf for a value
        that is not finite."""
        v = float(self.value)
        if not math.isfinite(v):
            return -math.inf
        sides = [(v - self.low) / (abs(self.low) or 1.0)] if self.low is not None else []
        if self.high is not None:
            sides.append((self.high - v) / (abs(self.high) or 1.0))
        return min(sides, default=math.inf)

    @property
    def shown_margin(self) -> float:
        """:attr:`margin` of the value and the bounds as the record shows them (:func:`valvetrain.units.displayed`),
        in exact decimal arithmetic: a seat angle of 45 deg against 30 deg has the margin -0.5, not the
        -0.5000000000000001 of its radians.  A bound of 0 keeps the SI side (the value itself), whose computation has
        no difference to round."""
        if not self.evaluated:
            return self.margin
        value = Decimal(repr(displayed(self.value, self.unit)))
        sides = []
        for bound, sign in ((self.low, 1), (self.high, -1)):
            if bound is None:
                continue
            shown = Decimal(repr(displayed(bound, self.unit)))
            side = sign * (float(self.value) if bound == 0.0 else float((value - shown) / abs(shown)))
            sides.append(side + 0.0)   # 0.0, not -0.0, at the upper bound
        return min(sides, default=math.inf)

    @property
    def shown_value(self) -> float:
        """The value in :attr:`unit`."""
        return to_display(self.value, self.unit)

    @property
    def evaluated(self) -> bool:
        """False for a check whose value is not a finite number: it cannot be evaluated."""
        return math.isfinite(float(self.value))

    @property
    def value_text(self) -> str:
        """The value with its unit (``"85.07 m/s"``), or ``"cannot be evaluated: REASON"``."""
        if not self.evaluated:
            return f"cannot be evaluated: {self.unevaluated or UNEVALUATED}"
        return f"{self.shown_value:.6g} {self.unit}".rstrip()

    @property
    def statement(self) -> str:
        """The check's quantity and value as a line says them: ``"intake: V' = 85.07 m/s"``, or ``"intake: valve
        seating velocity cannot be evaluated: the valve has not reseated"``."""
        return f"{self.quantity} {'= ' if self.evaluated else ''}{self.value_text}"

    @property
    def range(self) -> str:
        """The allowed range as text in :attr:`unit` (``"50...80 m/s"``, ``">= 1.3"``, ``"> 0 mm"``)."""
        low = None if self.low is None else to_display(self.low, self.unit)
        high = None if self.high is None else to_display(self.high, self.unit)
        return describe_range(low, high, self.unit, self.strict_low)

    def named(self, prefix, **changes) -> "Check":
        """The same check with ``prefix: `` before its quantity (the chapter it belongs to: ``crank``) and the fields
        ``changes`` (one :func:`dataclasses.replace`)."""
        return replace(self, quantity=f"{prefix}: {self.quantity}", **changes)

    def of_valve(self, name) -> "Check":
        """The same check as a check of the valve ``name`` (``name: `` before its quantity)."""
        return self.named(name, valve=name)

    def of_spring(self, spring) -> "Check":
        """The same check of a spring's own as the check of the drive's ``spring`` (``spring``, ``outer``,
        ``inner``: its name before the quantity)."""
        return replace(self, quantity=f"{spring} {self.quantity}", params=(*self.params, ("spring", spring)))

    @property
    def open(self) -> bool:
        """True for a failed check that the user did not accept: an open warning (or failure, or remark)."""
        return not self.passed and not self.accepted

    def warning(self) -> dict:
        """The record of a failed check in ``results.json`` ``warnings``: quantity, code, valve, parameters, value,
        range, source, unit, severity and margin (and the reason of an acceptance)."""
        return {"quantity": self.quantity, "code": self.code, "valve": self.valve, "params": dict(self.params),
                "value": displayed(self.value, self.unit) if self.evaluated else None, "range": self.range,
                "source": self.source, "unit": self.unit, "severity": self.severity, "margin": self.shown_margin,
                **({} if self.evaluated else {"unevaluated": self.unevaluated or UNEVALUATED}),
                **({"accepted": True, "reason": self.reason} if self.accepted else {})}

    def as_dict(self) -> dict:
        """The full record, in :attr:`unit`: the warning record with the bounds (without the noise of their
        conversion, :func:`valvetrain.units.displayed`), pass, accepted (and reason)."""
        return {**self.warning(),
                "low": None if self.low is None else displayed(self.low, self.unit),
                "high": None if self.high is None else displayed(self.high, self.unit),
                "pass": self.passed, "accepted": self.accepted,
                **({"note": self.note} if self.note else {})}


def describe_range(low=None, high=None, unit="", strict_low=False, lang="en") -> str:
    """Text of a range ``low...high`` (either side may be open) with its unit, its numbers by the rule of ``lang``
    (:func:`~valvetrain.locale.number_text`).

    >>> describe_range(50, 80, "m/s"), describe_range(low=0, unit="mm", strict_low=True)
    ('50...80 m/s', '> 0 mm')
    >>> describe_range(0.25, 0.4, lang="ru")
    '0,25...0,4'
    """
    suffix = f" {unit}" if unit else ""
    a, b = (None if x is None else number_text(x, "g", lang) for x in (low, high))
    if low is not None and low == high:
        return f"{a}{suffix}"
    if low is not None and high is not None:
        return f"{a}...{b}{suffix}"
    if low is not None:
        return f"{'>' if strict_low else '>='} {a}{suffix}"
    if high is not None:
        return f"<= {b}{suffix}"
    return "any"


def check(code, value, low=None, high=None, *, source, unit="", severity="warning", strict_low=False, note="",
          unevaluated="", params=None) -> Check:
    """A :class:`Check` of ``value`` (SI) against ``low``/``high`` (SI); see :class:`Check` for the fields.

    ``code`` is the check's code in the catalogue (:mod:`valvetrain.locale`; a code without texts is refused),
    ``params`` the values of its parameters (a dict), from which the quantity's text is made.  ``note`` is a text or
    the parts of :func:`valvetrain.locale.note` (kept as :attr:`Check.note_parts`, rendered in English as the note).

    A ``value`` that is None or not a finite number makes a check that cannot be evaluated: a failure, whatever
    ``severity`` says, with ``unevaluated`` (why the value cannot be had; :data:`UNEVALUATED` if empty) in words.

    Examples
    --------
    >>> c = check("flow.throat_velocity", 85.07, 50, 80, source="Valve-train practical works (n.d.), work 1",
    ...           unit="m/s")
    >>> c.quantity, c.passed, c.range, round(c.margin, 4)
    ("V' (throat velocity)", False, '50...80 m/s', -0.0634)
    >>> check("profile.rho_min", 11.885e-3, low=2e-3, source="Shang Hanji (1988)", unit="mm").warning()["range"]
    '>= 2 mm'
    >>> c = check("dynamics.seating_velocity", float("nan"), high=0.5, source="s", unit="m/s",
    ...           unevaluated="the valve has not reseated")
    >>> c.severity, c.passed, c.statement
    ('failure', False, 'largest dynamic seating velocity up to the rated speed cannot be evaluated: the valve has not reseated')
    """
    if severity not in SEVERITIES:
        raise InputError(f"severity = {severity!r}: allowed {SEVERITIES}")
    value = float("nan") if value is None else float(value)
    if math.isfinite(value):
        unevaluated = ""
    else:
        severity, unevaluated = "failure", unevaluated or UNEVALUATED
    params = tuple((params or {}).items())
    parts = () if isinstance(note, str) else tuple(note)
    return Check(record_text(code, params), value, None if low is None else float(low),
                 None if high is None else float(high), unit, source, severity, strict_low,
                 note_text(parts) if parts else note, unevaluated=unevaluated, code=code, params=params,
                 note_parts=parts)


def failed(checks) -> list[Check]:
    """The checks of a sequence that fail, in order."""
    return [c for c in checks if not c.passed]


def ranked(checks) -> list[Check]:
    """Checks in the order a reader needs them: failures, warnings, info; within a severity the farthest outside its
    range first (smallest :attr:`Check.margin`), then in the given order.

    >>> a = check("flow.throat_velocity", 85.0, 50, 80, source="s")              # 6 % over: a warning
    >>> b = check("flow.curtain_velocity", 120.0, 50, 80, source="s")            # 50 % over: a warning
    >>> c = check("spring.tau_max", 1.0, high=0.9, source="s", severity="failure")  # 11 % over: a failure
    >>> [x.code for x in ranked([a, b, c])]
    ['spring.tau_max', 'flow.curtain_velocity', 'flow.throat_velocity']
    """
    order = {s: i for i, s in enumerate(reversed(SEVERITIES))}
    return sorted(checks, key=lambda c: (order[c.severity], c.margin))


def tally(checks) -> dict[str, int]:
    """The verdict of a design in counts: every check, the open ones by severity, the accepted ones.

    One tally for the command line, the report and ``repr`` (the same words everywhere, see
    ``valvetrain.report.i18n`` ``verdict``).

    Parameters
    ----------
    checks : sequence of Check

    Returns
    -------
    dict
        ``checks`` (all), ``failure``, ``warning``, ``info`` (failed and not accepted), ``accepted`` (failed and
        accepted in the specification).

    >>> a = check("flow.throat_velocity", 85.0, 50, 80, source="s")
    >>> b = check("dynamics.seating_velocity", 1.0, high=0.9, source="s", severity="failure")
    >>> tally([a, b, check("flow.throat_velocity", 60.0, 50, 80, source="s")])
    {'checks': 3, 'failure': 1, 'warning': 1, 'info': 0, 'accepted': 0}
    """
    out = {"checks": len(checks), **{s: 0 for s in reversed(SEVERITIES)}, "accepted": 0}
    for c in failed(checks):
        out["accepted" if c.accepted else c.severity] += 1
    return out


def _norm(text):
    return " ".join(text.split()).casefold()


def resolve(acceptance, valves) -> tuple[str | None, str, dict[str, Any] | None]:
    """What an acceptance names: ``(valve, code, params)``, ``params`` None for every check of the code; None when
    its ``quantity`` is neither a code nor the English text of a check.

    ``quantity`` is a check code (``"law.kurz.phi2_to_phi3"``) or, as printed before the codes, the check's text
    (``"intake: Phi2/Phi3"``, or without the valve ``"Phi2/Phi3"``): the text is mapped to its code and
    parameters (:func:`valvetrain.locale.code_of`).  ``valve`` (None: any) limits it to one valve's checks.
    """
    wanted = _norm(acceptance.quantity)
    found = {c.casefold(): c for c in catalogue("en")["record"]}.get(wanted)
    if found is not None:
        return acceptance.valve, found, None
    head, sep, rest = acceptance.quantity.partition(": ")
    valve = head.strip() if sep and head.strip() in valves else None
    if valve is not None and acceptance.valve not in (None, valve):
        return None
    for text in (acceptance.quantity, rest) if sep else (acceptance.quantity,):
        named = code_of(text) or _spring_code(text)
        if named is not None:
            return valve or acceptance.valve, named[0], named[1]
    return None


def _spring_code(text):
    """The code and parameters of a spring's own check named after its spring (``"spring tau_max"``), or None."""
    spring, _, rest = " ".join(text.split()).partition(" ")
    if spring.casefold() not in {s.casefold() for s in catalogue("en")["springs"]}:
        return None
    named = code_of(rest)
    if named is None or not named[0].startswith("spring."):
        return None
    return named[0], {**named[1], "spring": spring.casefold()}


def matches(target, c) -> bool:
    """True when a resolved acceptance ``(valve, code, params)`` (:func:`resolve`) names the check ``c``."""
    valve, code, params = target
    return (c.code == code and (valve is None or c.valve == valve)
            and (params is None or {k: str(v).casefold() for k, v in c.params}
                 == {k: str(v).casefold() for k, v in params.items()}))


def apply_acceptances(checks, acceptances, valves=()) -> tuple[list[Check], list[int]]:
    """The checks with ``accepted`` and ``reason`` set where an acceptance of the specification names them, and the
    indices of the acceptances that name no check.

    Parameters
    ----------
    checks : sequence of Check
    acceptances : sequence
        Objects with ``quantity`` (a check code or text, :func:`resolve`), ``valve`` (None: any) and ``reason`` (the
        ``[[accepted]]`` tables); the first that names a check gives its reason.
    valves : collection of str
        The valve names.

    Returns
    -------
    checks : list of Check
    unmatched : list of int
    """
    targets = [resolve(a, valves) for a in acceptances]
    used = set()
    out = []
    for c in checks:
        hits = [i for i, t in enumerate(targets) if t is not None and matches(t, c)]
        if not hits:
            out.append(c)
        else:
            used.update(hits)
            out.append(replace(c, accepted=True, reason=acceptances[hits[0]].reason))
    return out, [i for i in range(len(acceptances)) if i not in used]
