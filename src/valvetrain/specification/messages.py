"""Messages of a specification that cannot be used: one per problem, naming the key, the value and what is allowed."""

from typing import Optional

from ..errors import ValvetrainError
from ..locale import NoteText, note


class Problem(str):
    """One problem of a specification: the line printed (the string itself) and its parts, made where the problem is
    found: ``path`` the dotted key (``""`` where the problem names none), ``value`` the value given as echoed (None
    where none is echoed), ``message`` what is wrong or what is allowed.

    >>> p = Problem("engine.bore_mm", "allowed [5, 2000] mm", "-3.0")
    >>> p, p.path, p.value, p.message
    ('engine.bore_mm = -3.0: allowed [5, 2000] mm', 'engine.bore_mm', '-3.0', 'allowed [5, 2000] mm')
    >>> Problem("crank.step_deg", "must divide the 720 deg cycle into whole steps", "7", joiner=" ")
    'crank.step_deg = 7 must divide the 720 deg cycle into whole steps'
    """

    path: str
    value: Optional[str]
    message: str

    def __new__(cls, path, message, value=None, joiner=": ", text=None):
        """The line is ``path = value`` (or ``path``), ``joiner``, ``message``; or ``text`` where it reads otherwise."""
        if text is None:
            head = path if value is None else f"{path} = {value}"
            text = f"{head}{joiner}{message}" if head else message
        self = super().__new__(cls, text)
        self.path, self.value, self.message = path, value, message
        return self

    def within(self, prefix) -> "Problem":
        """The problem with its key under ``prefix`` (a valve's ``valves.NAME``), its line led by ``prefix.``."""
        return Problem(f"{prefix}.{self.path}" if self.path else prefix, self.message, self.value,
                       text=f"{prefix}.{self}")

    def note(self) -> tuple:
        """The line as a note (:func:`valvetrain.locale.note`): its key and value as written, its message in every
        language where it is a :class:`~valvetrain.locale.NoteText`; parts joined by ``""``."""
        text = str(self)
        if isinstance(self.message, NoteText) and text.endswith(self.message):
            return note("plain", text=text[:len(text) - len(self.message)]) + self.message.parts
        return note("plain", text=text)

    def __reduce__(self):
        return Problem, (self.path, self.message, self.value, "", str(self))


class SpecError(ValvetrainError):
    """A specification that cannot be used; ``problems`` holds one :class:`Problem` per problem (a line given as
    plain text is a problem that names no key)."""

    def __init__(self, problems):
        self.problems = [p if isinstance(p, Problem) else Problem("", p) for p in problems]
        super().__init__("\n".join(self.problems))


def said(exc) -> str:
    """An error's message as raised: the note it was raised with (:class:`~valvetrain.locale.NoteText`, said in every
    language), else its text."""
    return exc.args[0] if exc.args and isinstance(exc.args[0], NoteText) else str(exc)


def shown(value, limit=60) -> str:
    """A value as echoed in a message: its repr, cut to ``limit`` characters."""
    text = repr(value)
    return text if len(text) <= limit else f"{text[:limit - 5]}...{text[-2:]}"


WHOLE_FILE = "(file)"
"""The key of a problem of the whole document (no section to design); :func:`~.reading.parse_spec` writes the file's
name there."""


def location(err, laws=()) -> str:
    """The key path of a pydantic error without the law tags pydantic inserts after a cam (``cam.kurz.phi1_deg``);
    long keys are cut, an empty key is written as TOML writes it (``""``)."""
    loc = err["loc"]
    parts = [(str(p) or '""') if len(str(p)) <= 40 else f"{str(p)[:35]}..." for i, p in enumerate(loc)
             if not (p in laws and i > 0 and loc[i - 1] in ("cam", "target"))]
    return ".".join(parts) if parts else WHOLE_FILE


def message(err, laws=()) -> Problem:
    """One problem for one pydantic error: the key path, the value given and what is allowed (the note the
    validator raised, :class:`~valvetrain.locale.NoteText`, where it raised one: said in every language)."""
    loc = location(err, laws)
    kind = err["type"]
    if kind == "missing":
        return Problem(loc, NoteText(note("spec.missing")))
    if kind == "extra_forbidden":
        return Problem(loc, NoteText(note("spec.unknown_key", value=shown(err["input"]))))
    if kind == "union_tag_invalid":
        return Problem(f"{loc}.law", NoteText(note("spec.allowed_names", names=err["ctx"]["expected_tags"])),
                       shown(err["ctx"]["tag"]))
    if kind == "literal_error":
        return Problem(loc, NoteText(note("spec.allowed_names", names=err["ctx"]["expected"])), shown(err["input"]))
    if kind == "union_tag_not_found":
        return Problem(f"{loc}.law", NoteText(note("spec.missing_law", laws=", ".join(repr(law) for law in laws))))
    error = err.get("ctx", {}).get("error")
    msg = said(error) if isinstance(error, Exception) else err["msg"].removeprefix("Value error, ")
    if isinstance(err["input"], dict):
        return Problem(loc, msg)
    return Problem(loc, msg, shown(err["input"]))
