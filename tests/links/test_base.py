"""The link interface (valvetrain.links.base): the registry the layouts' chains name, and the loads a link's checks
take, with the bookkeeping of the keys they need (each link's checks: tests/links/test_tappet.py, test_pushrod.py,
test_rocker.py)."""

from dataclasses import replace
from types import SimpleNamespace

from valvetrain.followers import REGISTRY as FOLLOWERS
from valvetrain.layouts import LAYOUTS, unused_part_checks, unused_part_keys
from valvetrain.links import REGISTRY, Link, Pushrod, Rocker, Tappet
from valvetrain.locale import check_text, note_text
from valvetrain.specification import example_spec
from valvetrain.specification.models import Parts
from valvetrain.specification.si import si

from link_loads import loads


def test_every_layout_is_a_chain_of_registered_links():
    """The layouts name only registered links; their mass keys are the [drive.masses] keys in the chain's order."""
    assert isinstance(REGISTRY["tappet"], Tappet) and isinstance(REGISTRY["pushrod"], Pushrod)
    assert isinstance(REGISTRY["rocker"], Rocker)
    for layout in LAYOUTS.values():
        assert all(isinstance(link, Link) for link in layout.links)
    assert LAYOUTS["pushrod"].train_masses == ("tappet_kg", "pushrod_kg", "rocker_inertia_kg_mm2")


def test_a_link_without_checks_checks_nothing():
    """The interface's defaults: no checks, no face for a flat follower."""
    class Bare(Link):
        name, mass_key = "bare", "bare_kg"

    made, notes = loads(SimpleNamespace())
    assert Bare().checks(made) == [] and Bare().face_diameter(SimpleNamespace()) is None and notes == []


def test_each_part_declares_the_keys_its_checks_read():
    """A link's checks ask for their keys by name (``Loads.need``): every key asked with none given is one of its
    ``part_keys``, and every declared key (links and followers) is a key of [valves.NAME.parts]."""
    bare = SimpleNamespace(**{key.rsplit("_", 1)[0]: None for key in Parts.model_fields})
    for link in REGISTRY.values():
        asked = []
        link.checks(replace(loads(bare)[0], need=lambda keys, name: asked.extend(keys) or False, guide_offset=1e-3))
        assert set(asked) <= set(link.part_keys), link.name
    declared = [key for part in (*REGISTRY.values(), *FOLLOWERS.values()) for key in part.part_keys]
    assert set(declared) <= set(Parts.model_fields) and len(declared) == len(set(declared))


def test_part_keys_of_parts_outside_the_layout_are_a_warning():
    """Fuzz finding: [parts] keys of a link the layout does not have were ignored without a word.  The built-in
    example's intake (pushrod layout: tappet, pushrod, rocker) made direct (a tappet alone, rocker ratio 1): its
    pushrod's and rocker's keys are named, each a warning (legal but doubtful input) naming key and layout in both
    languages; its own layout reads them all."""
    spec = example_spec()
    given = [key for key in Parts.model_fields if key in spec.valves["intake"].parts.model_fields_set]
    assert unused_part_keys(si(spec.valves["intake"])) == []
    direct = si(spec.replace({"valves.intake.drive.layout": "direct", "valves.intake.rocker_ratio": 1.0}).valves["intake"])
    expected = [key for key in given if key.startswith(("pushrod_", "ball_", "socket_", "rocker_"))]
    assert expected and unused_part_keys(direct) == expected
    found = unused_part_checks(direct)
    assert [c.code for c in found] == ["parts.unused_key"] * len(expected)
    c = found[0]
    assert (c.severity, c.passed, dict(c.params)) == ("warning", False, {"key": expected[0], "layout": "direct"})
    assert c.note == "key not used by this layout: no part of the direct layout with the flat follower reads it"
    assert note_text(c.note_parts, "ru") == ("ключ не используется этой схемой привода (схема: непосредственный; "
                                             "толкатель: плоский): его не читает ни одна её деталь")
    assert check_text(c.code, dict(c.params), "ru").endswith(f"[parts] {expected[0]}")
