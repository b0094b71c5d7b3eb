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
