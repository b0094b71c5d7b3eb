"""The link interface (valvetrain.links.base): the registry the layouts' chains name, and the loads a link's checks
take, with the bookkeeping of the keys they need (each link's checks: tests/links/test_tappet.py, test_pushrod.py,
test_rocker.py)."""

from types import SimpleNamespace

from valvetrain.layouts import LAYOUTS
from valvetrain.links import REGISTRY, Link, Pushrod, Rocker, Tappet

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
