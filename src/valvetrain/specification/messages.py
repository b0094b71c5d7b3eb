"""Messages of a specification that cannot be used: one per problem, naming the key, the value and what is allowed."""


class SpecError(Exception):
    """A specification that cannot be used; ``problems`` holds one message per problem."""

    def __init__(self, problems):
        self.problems = list(problems)
        super().__init__("\n".join(self.problems))


def shown(value, limit=60):
    """A value as echoed in a message: its repr, cut to ``limit`` characters."""
    text = repr(value)
    return text if len(text) <= limit else f"{text[:limit - 5]}...{text[-2:]}"


def location(err, laws=()):
    """The key path of a pydantic error without the law tags pydantic inserts after a cam (``cam.kurz.phi1_deg``);
    long keys are cut."""
    loc = err["loc"]
    parts = [str(p) if len(str(p)) <= 40 else f"{str(p)[:35]}..." for i, p in enumerate(loc)
             if not (p in laws and i > 0 and loc[i - 1] in ("cam", "target"))]
    return ".".join(parts) if parts else "(file)"


def message(err, laws=()):
    """One line for one pydantic error: the key path, the value given and what is allowed."""
    loc = location(err, laws)
    kind = err["type"]
    if kind == "missing":
        return f"{loc}: required key is missing"
    if kind == "extra_forbidden":
        return f"{loc}: unknown key (value {shown(err['input'])}); check the spelling against `valvetrain example`"
    if kind == "union_tag_invalid":
        return f"{loc}.law = {shown(err['ctx']['tag'])}: allowed {err['ctx']['expected_tags']}"
    if kind == "union_tag_not_found":
        return f"{loc}.law: required key is missing; allowed {', '.join(repr(law) for law in laws)}"
    msg = err["msg"].removeprefix("Value error, ")
    if isinstance(err["input"], dict):
        return f"{loc}: {msg}"
    return f"{loc} = {shown(err['input'])}: {msg}"
