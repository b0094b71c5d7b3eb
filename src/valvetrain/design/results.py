"""The typed-results machinery the design stages declare their results with (:mod:`valvetrain.results`, which
lies below the specification and the laws so that their records can be typed the same way)."""

from ..results import NamedValues, json_schema, quantity, record, shown, shown_value

__all__ = ["NamedValues", "json_schema", "quantity", "record", "shown", "shown_value"]
