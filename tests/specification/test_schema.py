"""results.json has a JSON Schema generated from the result types; the shipped file is that schema."""

from importlib.resources import files
import json

import jsonschema
import pytest

from valvetrain.design import results_schema, run
from valvetrain.export import json_text, results_json
from valvetrain.specification import example_spec


def test_the_shipped_schema_is_the_generated_one():
    shipped = json.loads(files("valvetrain").joinpath("data/results.schema.json").read_text(encoding="utf-8"))
    assert shipped == json.loads(json_text(results_schema()))


def test_the_schema_refuses_a_wrong_record():
    """A schema that accepts anything would pass tests/test_outputs.py's validation of every example: a text where a number belongs is refused."""
    results = json.loads(results_json(run(example_spec())))
    results["valves"]["intake"]["flow"]["fullness"] = "high"
    with pytest.raises(jsonschema.ValidationError, match="'high' is not of type"):
        jsonschema.validate(results, results_schema())
    del results["valves"]["intake"]["flow"]
    results["valves"]["intake"]["cam"].pop("rho_min_mm")
    with pytest.raises(jsonschema.ValidationError, match="'rho_min_mm' is a required property"):
        jsonschema.validate(results, results_schema())


def test_a_margin_is_null_exactly_where_there_is_no_distance_to_a_bound():
    """A check without bounds (range 'any': the gas force at the exhaust's opening, an info) has no margin, null in
    results.json, as has a check whose value cannot be evaluated; a check with a bound and a value has a number.  The
    schema says so: a null margin beside a bound and a value, or a number without either, is refused (both were
    accepted before: margin was any number or null)."""
    from valvetrain.checks import check

    schema = results_schema()["properties"]
    full, warning = schema["checks"]["items"], schema["warnings"]["items"]
    source = "Valve-train practical works (n.d.), work 1"
    boundless = check("gas_force.exhaust_opening", 423.6, source=source, unit="N", severity="info")
    bounded = check("flow.throat_velocity", 85.07, 50.0, 80.0, source=source, unit="m/s")
    unevaluated = check("flow.throat_velocity", float("nan"), 50.0, 80.0, source=source, unit="m/s",
                        unevaluated="no flow")
    for record, kind in ((boundless.as_dict(), full), (bounded.as_dict(), full), (unevaluated.as_dict(), full),
                         (bounded.warning(), warning), (unevaluated.warning(), warning)):
        jsonschema.validate(json.loads(json_text(record)), kind)
    assert json.loads(json_text(boundless.as_dict()))["margin"] is None
    for record, kind, margin in ((bounded.as_dict(), full, None), (boundless.as_dict(), full, 0.5),
                                 (bounded.warning(), warning, None), (unevaluated.warning(), warning, -1.0)):
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate({**json.loads(json_text(record)), "margin": margin}, kind)
