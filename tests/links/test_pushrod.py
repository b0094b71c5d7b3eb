"""The pushrod (valvetrain.links.pushrod): its buckling margin against Euler's load computed by hand (Valve-train
practical works (n.d.), eq. (7.8)), its head pressure, and the notes of the keys not given."""

import math
from types import SimpleNamespace

import pytest

from valvetrain.links import Pushrod

from link_loads import loads


def parts(**kw):
    return SimpleNamespace(**{"pushrod_length": 0.250, "pushrod_diameter": 0.008, "pushrod_bore": 0.0,
                              "pushrod_modulus": 2.1e11, "ball_radius": None, "socket_radius": None,
                              "pushrod_head_area": 20e-6, **kw})


def test_the_buckling_margin_and_head_pressure_by_hand():
    """J = pi d^4 / 64 = 201.06 mm^4 for 8 mm; P_cr = pi^2 E J / l^2 = 6668 N at E = 2.1e5 MPa, l = 250 mm: a margin of
    6.668 under 1000 N; the head's pressure 1000 N / 20 mm^2 = 50 MPa (hand calculation)."""
    made, notes = loads(parts())
    margin, head = Pushrod().checks(made)
    p_cr = math.pi**2 * 2.1e11 * (math.pi * 0.008**4 / 64.0) / 0.250**2
    assert p_cr == pytest.approx(6668.0, rel=1e-3)
    assert margin.code == "strength.pushrod_buckling_margin" and margin.value == pytest.approx(p_cr / 1000.0)
    assert head.code == "strength.pushrod_head_pressure" and head.value == pytest.approx(50e6)
    assert notes == ["ball_socket_stress: not checked"]


def test_its_stiffness_and_node_by_hand():
    """E A / L = 2.1e11 Pa x pi (8 mm)^2 / 4 / 250 mm = 42.22 N/um; no stiffness without its length; its node on the cam
    side of a rocker of ratio 1.6 is m / k^2 = 0.035 kg / 2.56 = 13.67 g (Valve-train practical works (n.d.), eq. 5.2;
    hand calculation), and a mass of 0 is named as missing."""
    assert Pushrod.elastic and Pushrod().stiffness(parts()) == pytest.approx(42.22e6, rel=1e-4)
    assert Pushrod().stiffness(parts(pushrod_length=None)) is None
    masses = SimpleNamespace(pushrod_kg=0.035)
    assert Pushrod().node(masses, 1.6, None) == ("pushrod", pytest.approx(0.013671875))
    assert Pushrod().missing(masses, None) == [] and Pushrod().missing(SimpleNamespace(pushrod_kg=0.0), 0.04) == [
        "pushrod_kg"]


def test_a_socket_that_conforms_to_the_ball_has_no_stress_from_the_formula():
    """The pushrod's ball of 4 mm in a socket of 4.0001 mm under 1000 N: the formula's 4.65 MPa needs Hertz's contact
    circle a = sqrt(3 P / (2 pi sigma)) = 10.1 mm (hand calculation), wider than the ball: not evaluated (a failure)
    instead of a pass (before: 4.65 MPa against 2000 MPa, passed)."""
    made, _ = loads(parts(ball_radius=0.004, socket_radius=0.0040001))
    ball = next(c for c in Pushrod().checks(made) if c.code == "strength.ball_socket_stress")
    assert not ball.evaluated and not ball.passed and ball.severity == "failure"
    assert "contact circle of 10.1 mm radius would be wider than the ball of 4 mm radius" in ball.unevaluated
