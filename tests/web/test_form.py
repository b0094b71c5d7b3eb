"""The specification panel's fields without a browser (web/form.py): the bounds, the names, the values parsed."""

import pytest

pytest.importorskip("bokeh")

from valvetrain.web.form import form, parse_value, value_text  # noqa: E402
from valvetrain.web.session import Session  # noqa: E402


def test_panel_fields_carry_the_models_bounds():
    groups = form(Session.start().document, "intake")
    # the groups a designer thinks in, in that order
    assert [g for g, _ in groups] == ["engine", "valve", "cam", "spring", "drive", "dynamics"]
    fields = {f.path: f for _, group in groups for f in group}
    # declared in specification/models.py: bore 5...2000 mm, cylinders 1...64, strokes 2 or 4
    assert (fields["engine.bore_mm"].low, fields["engine.bore_mm"].high) == (5.0, 2000.0)
    assert (fields["engine.cylinders"].kind, fields["engine.cylinders"].low, fields["engine.cylinders"].high) == \
        ("int", 1, 64)
    assert fields["engine.strokes"].options == (2, 4)
    assert fields["valves.intake.cam.phi1_deg"].value == 27.0      # the example's value
    assert fields["valves.intake.drive.masses.valve_kg"].name == "drive.masses.valve_kg"
    assert parse_value(fields["engine.strokes"], "4") == 4
    # lists and texts without TOML's brackets and quotes (with them too)
    wire = fields["valves.intake.spring.wire_diameter_range_mm"]
    assert parse_value(wire, "2.0, 6.0") == parse_value(wire, "[2.0, 6.0]") == [2.0, 6.0]
    assert value_text(wire.value) == "2.0, 7.0"
    material = fields["valves.intake.spring.material"]
    assert value_text(material.value) == "VDSiCr"
    assert parse_value(material, "60S2A") == parse_value(material, '"60S2A"') == "60S2A"
    assert parse_value(material, "VDSiCr, 60S2A") == ["VDSiCr", "60S2A"]
    assert "valves.intake.cam" not in fields                       # the cam's table is its own group


def test_every_field_of_the_panel_has_a_name_in_both_languages():
    # the panel shows the report's names of the keys (report/names.py), never the keys themselves: every key of
    # every section of the panel, the cam's of every law
    from valvetrain.report.names import has_name
    from valvetrain.specification import REGISTRY
    from valvetrain.web.form import GROUPS, _section_fields

    sections = [(path, model) for _, group in GROUPS for path, model in group if model is not None]
    sections += [("valves.{}.cam", model) for model in REGISTRY.values()]
    nameless = {f.name for path, model in sections for f in _section_fields({}, path.format("v"), model)
                if not has_name(f.name)}
    assert nameless == set()
