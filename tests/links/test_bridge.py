"""The valve bridge of a pair of valves driven by one rocker (valvetrain.links.bridge): its bending stress and
stiffness against a hand calculation of a simply supported beam loaded at mid-span (Shigley's Mechanical Engineering
Design, 9th ed. (2011), Table A-9), the chains it joins and its mass at the valve (its design: in
tests/links/test_rocker_pivot.py, which designs the appendix example once)."""

import re
from types import SimpleNamespace

import pytest

from valvetrain.design.dynamics import _link_estimates, _multi_train
from valvetrain.dynamics.coils import CoilSpring
from valvetrain.layouts import chain, train_mass, unused_part_keys
from valvetrain.links import ValveBridge
from valvetrain.locale import note_text
from valvetrain.report.html import numbered_citations
from valvetrain.report.names import translate
from valvetrain.report.russian import russian_citations
from valvetrain.specification import example_spec
from valvetrain.specification.messages import SpecError
from valvetrain.specification.reading import parse_spec
from valvetrain.specification.si import si
from valvetrain.specification import example_text

from link_loads import loads


def test_its_bending_stress_and_stiffness_by_hand():
    """Span 40 mm, section 14 x 12 mm, 600 N at each valve: the rocker pushes 1200 N at mid-span, M = 1200 x 0.040 / 4
    = 12 N m, W = 14 x 12^2 / 6 = 336 mm^3, sigma = 12 / 336e-9 = 35.714 MPa; I = 14 x 12^3 / 12 = 2016 mm^4, a valve's
    600 N deflects the middle by 1200 x 40^3 / (48 x 2.1e5 x 2016) = 0.0037793 mm: 158760 N/mm per valve (hand
    calculation); without its section, not checked."""
    parts = SimpleNamespace(bridge_span=0.040, bridge_width=0.014, bridge_height=0.012)
    made, notes = loads(parts, valve_force=600.0)
    (c,) = ValveBridge().checks(made)
    assert c.code == "strength.bridge_bending" and c.value == pytest.approx(35.714286e6, rel=1e-7)
    assert c.high == 150e6 and c.severity == "failure" and notes == []
    deflection = 1200.0 * 40.0**3 / (48.0 * 2.1e5 * 2016.0)
    assert c.note.endswith(f"= {600.0 / deflection:.0f} N/mm") and "158760 N/mm" in c.note
    assert "жёсткость на один клапан 24 E I / l^3 = 158760 Н/мм" in note_text(c.note_parts, "ru")
    made, notes = loads(SimpleNamespace(bridge_span=0.040, bridge_width=None, bridge_height=0.012))
    assert ValveBridge().checks(made) == [] and notes == ["bridge_bending: not checked"]
    # the Russian report says its source's words in Russian (ru.toml source.bridge_bending), as numbered in the report
    page = russian_citations(numbered_citations(f'<span class="cite">{translate(c.source, "ru")}</span>', "ru"))
    assert "траверсы клапанов; σ = M / W, M = F l / 4 в среднем сечении, [2, таблица A-9]" in page
    assert not re.search("taken|bridge|mid-span", page)


def test_it_joins_a_chain_with_a_lever_and_adds_its_mass_at_the_valve():
    """The built-in example's intake (pushrod layout) given a bridge: the bridge joins its chain after the rocker, and
    the reduced mass at the valve grows by bridge_kg (ratio 1: it moves with the valve); made direct (no lever) it
    joins nothing and its keys are named unused."""
    spec = example_spec()
    plain = si(spec.valves["intake"])
    bridged = si(spec.replace({"valves.intake.parts.bridge_span_mm": 40.0,
                               "valves.intake.drive.masses.bridge_kg": 0.03}).valves["intake"])
    assert chain(plain).parts == ("tappet", "pushrod", "rocker", "rocker_pivot")
    assert chain(bridged).parts == ("tappet", "pushrod", "rocker", "rocker_pivot", "valve_bridge")
    assert train_mass(bridged, 0.0)[0] - train_mass(plain, 0.0)[0] == pytest.approx(0.03, rel=1e-12)
    direct = si(spec.replace({"valves.intake.parts.bridge_span_mm": 40.0, "valves.intake.drive.layout": "direct",
                              "valves.intake.rocker_ratio": 1.0}).valves["intake"])
    assert "valve_bridge" not in chain(direct).parts and "bridge_span_mm" in unused_part_keys(direct)


def test_it_is_an_elastic_link_at_the_valve():
    """The example's intake given the bridge of the hand calculation (40 mm span, 14 x 12 mm): the drive's links from
    the cam are the camshaft, the pushrod (E A / L over k^2), the rocker's joint to the valve and the bridge at its
    158760 N/mm per valve (not divided by k^2: it moves with the valve).  Its multi-mass train has the bridge's
    node, 0.03 kg, between the rocker and the valve, joined to the rocker by the joint in series with half the bridge
    (twice its stiffness) and to the valve by the other half; the valve node and the nodes before are those without
    the bridge, and the compliances of the links add up to those given (the identity of springs in series)."""
    keys = {"valves.intake.parts.bridge_span_mm": 40.0, "valves.intake.parts.bridge_width_mm": 14.0,
            "valves.intake.parts.bridge_height_mm": 12.0}
    valve = si(example_spec().replace(keys).valves["intake"])
    k = valve.rocker_ratio
    estimates = _link_estimates(valve, k)
    plain = _link_estimates(si(example_spec().valves["intake"]), k)
    assert [name for name, _ in estimates] == [name for name, _ in plain] + ["valve bridge"]
    assert estimates[:-1] == plain and estimates[-1][1] == pytest.approx(158760e3, rel=1e-12)
    text = example_text().replace('model = "1dof"', 'model = "multi"', 1)
    args = ([CoilSpring(4e4, 300.0, 0.03, 0.0, 4)], 2e-4, {"damping_ratio": 0.05}, "valves.intake", 0.04)
    without = _multi_train(si(parse_spec(text).valves["intake"]), (3.6e8, 3.8e7, 4.5e7), *args)
    bridged = parse_spec(text.replace("rocker_inertia_kg_mm2 = 25.0", "rocker_inertia_kg_mm2 = 25.0\nbridge_kg = 0.03", 1))
    with_bridge = _multi_train(si(bridged.replace(keys).valves["intake"]), (3.6e8, 3.8e7, 4.5e7, 1.5876e8), *args)
    assert [name for name, _ in with_bridge.drive] == ["tappet", "pushrod", "rocker", "valve_bridge", "valve"]
    assert with_bridge.drive[3] == ("valve_bridge", 0.03)
    assert with_bridge.drive[:3] == without.drive[:3] and with_bridge.drive[4] == without.drive[3]
    assert with_bridge.links[:3] == without.links[:3]
    assert with_bridge.links[3:] == pytest.approx([1.0 / (1.0 / 4.5e7 + 1.0 / 3.1752e8), 3.1752e8], rel=1e-15)
    assert sum(1.0 / c for c in with_bridge.links) == pytest.approx(
        sum(1.0 / c for c in (3.6e8, 3.8e7, 4.5e7, 1.5876e8)), rel=1e-14)


def test_a_multi_mass_train_needs_its_mass():
    """Its geometry given without bridge_kg, a multi-mass train is refused naming the key (the bridge is a node)."""
    text = example_text().replace('model = "1dof"', 'model = "multi"', 1)
    valve = si(parse_spec(text).replace({"valves.intake.parts.bridge_span_mm": 40.0}).valves["intake"])
    with pytest.raises(SpecError, match="needs positive drive.masses.bridge_kg"):
        _multi_train(valve, (3.6e8, 3.8e7, 4.5e7, 1e8), [CoilSpring(4e4, 300.0, 0.03, 0.0, 4)], 2e-4, {},
                     "valves.intake", 0.04)
