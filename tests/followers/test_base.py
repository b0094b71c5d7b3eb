"""The follower interface (valvetrain.followers.base): the registry behind the specification's ``follower`` key, the
Hertz contact of the interface against hand calculations, and a follower of the caller's own (a lever ratio) reaching
the valve lift (each follower's own geometry: tests/followers/test_flat.py, test_roller.py, test_finger.py)."""

import numpy as np
import pytest

from valvetrain.followers import FLAT, REGISTRY, FlatFollower, Follower, PivotedFollower, RollerFollower, follower_of
from valvetrain.specification.cam_base import _CamBase

from conftest import seed000_law

E = 2.1e11
"""Steel on steel [Pa]."""


def test_the_specification_offers_the_registered_followers():
    """The ``follower`` key allows exactly the registry's names, each mapped to its class."""
    assert set(_CamBase.model_fields["follower"].annotation.__args__) == set(REGISTRY) == {"flat", "roller", "finger"}
    assert REGISTRY["flat"] is FlatFollower and REGISTRY["roller"] is RollerFollower
    assert REGISTRY["finger"] is PivotedFollower


def test_a_follower_is_built_from_the_cam():
    class Cam:
        follower, roller_radius = "roller", 0.012

    built = follower_of(Cam())
    assert isinstance(built, RollerFollower) and built.radius == 0.012
    Cam.follower = "flat"
    assert isinstance(follower_of(Cam()), FlatFollower)


def test_hertz_stress_on_the_heel_circle_by_hand():
    """On the heel circle (R0 = 20 mm: rho = R0 for either follower) under F = 1000 N, b = 10 mm, E = 210 GPa (Hertz
    line contact, 0.418 for Poisson 0.3, Valve-train practical works (n.d.), eq. 7.4), written out:
    F E / b = 1000 x 2.1e11 / 0.01 = 2.1e16 N/m^2 per m;
    flat:                 x (1/0.020)           = 1.05e18, sigma = 0.418 x 1.0247e9 = 428.3 MPa;
    roller (R_r = 10 mm): x (1/0.020 + 1/0.010) = 3.15e18, sigma = 0.418 x 1.7748e9 = 741.9 MPa."""
    law = seed000_law()
    rho_flat = law.curvature(np.array([np.pi]), 0.020, FLAT)
    rho_roller = law.curvature(np.array([np.pi]), 0.020, RollerFollower(0.010))
    assert rho_flat == pytest.approx(0.020, abs=1e-15) and rho_roller == pytest.approx(0.020, abs=1e-15)
    flat = FLAT.contact_stress(1000.0, rho_flat, 0.010, E)
    roller = RollerFollower(0.010).contact_stress(1000.0, rho_roller, 0.010, E)
    assert flat == pytest.approx(0.418 * np.sqrt(1.05e18), rel=1e-12)
    assert roller == pytest.approx(0.418 * np.sqrt(3.15e18), rel=1e-12)
    assert float(flat[0]) == pytest.approx(428.3e6, rel=1e-4) and float(roller[0]) == pytest.approx(741.9e6, rel=1e-4)


class _Lever(FlatFollower):
    """A flat pad on a lever of constant ratio 1.5 (a follower of the caller's own)."""

    def ratio(self, h):
        return np.full_like(np.asarray(h, dtype=float), 1.5)


def test_a_followers_own_ratio_reaches_the_valve_lift():
    """Valve lift = i_k x i_f x (h - h0): with i_k = 1.2 and i_f = 1.5, 1.8 (h - h0) (hand calculation)."""
    law = seed000_law()
    theta = np.linspace(-0.6, 0.0, 7)
    expected = 1.8 * np.clip(law.lift(theta) - law.ramp_height, 0.0, None)
    assert law.valve_lift(theta, 1.2, _Lever()) == pytest.approx(expected, rel=1e-15, abs=1e-18)
    assert law.valve_lift(theta, 1.2) == pytest.approx(expected / 1.5, rel=1e-15, abs=1e-18)


def test_the_interface_leaves_nothing_silently_flat():
    """A follower that does not give its geometry fails loudly rather than being taken for a flat face."""
    bare = Follower()
    with pytest.raises(NotImplementedError):
        bare.curvature(0.02, 0.0, 0.0, 0.0)
    with pytest.raises(NotImplementedError):
        bare.line_contact(0.02)


def test_what_a_synthesis_limits_and_the_laws_admitted_are_asked_of_the_follower():
    """Issue 41: the synthesis, the report and the cam sections ask the follower, not its ``rolling`` flag: a roller's contact record gives its pressure angle and concave radius to limit, a flat
    face's nothing; the tangent cam (drawn for a roller on its line, Kolchin and Demidov (1980)) drives the roller
    alone, every other law each follower."""
    from valvetrain.followers.flat import FlatContact
    from valvetrain.followers.roller import RollerContact

    roller = RollerFollower(0.012)
    assert roller.limited_contact(RollerContact(0.012, 0.4, -0.2)) == (0.4, -0.2)
    assert roller.limited_contact(RollerContact(0.012, 0.4, None)) == (0.4, None)
    assert FLAT.limited_contact(FlatContact(0.01)) is None
    assert [name for name, cls in REGISTRY.items() if cls.admits("tangent")] == ["roller"]
    assert all(cls.admits("kurz") and cls.admits("polydyne") for cls in REGISTRY.values())
    # the specification's rules ask each its own question (specification/validate.py): the finger alone answers yes
    for question in ("geometric_lever", "pivot_axis", "switchable"):
        assert [name for name, cls in REGISTRY.items() if getattr(cls, question)] == ["finger"], question
