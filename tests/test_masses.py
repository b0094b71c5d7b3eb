"""Masses of the train (masses.py): the spring's mass and the masses reduced to the valve and to the tappet."""

from types import SimpleNamespace

import numpy as np
import pytest

from valvetrain import masses
from valvetrain.locale import note_text


def test_spring_mass_and_reduced_masses():
    # rho (pi d^2 / 4) pi D i: 7850 * pi/4 * 0.004^2 * pi * 0.03 * 8
    assert masses.spring_mass(0.03, 0.004, 8, 7850.0) == pytest.approx(7850 * np.pi**2 / 4 * 16e-6 * 0.03 * 8)
    m_v = masses.reduced_mass_at_valve(0.05, 0.02, 0.005, 0.045, 0.06, 0.04, 4e-5, 0.04, 1.6)
    # (5.2) term by term; (7.2) = (5.2) x i_k^2
    assert m_v == pytest.approx(0.05 + 0.02 + 0.005 + 0.015 + 4e-5 / 0.04**2 + 0.1 / 1.6**2)
    assert masses.reduced_mass_at_tappet(m_v, 1.6) == pytest.approx(
        0.06 + 0.04 + 4e-5 / 0.025**2 + (0.05 + 0.02 + 0.005 + 0.015) * 1.6**2)


def test_specific_mass_of_each_layout():
    """m_v = m' f_g (Valve-train practical works (n.d.), work 5) with the package's defaults 125, 105, 135 kg/m^2
    (direct, rocker, pushrod; derived in masses.py from the built-in example's parts) or the one given.  The appendix
    valve, f_g = 1063.6 mm^2, by hand: 0.13295, 0.11168, 0.14359 kg; 450 kg/m^2 gives 0.47862 kg."""
    area = 1063.6e-6
    for layout, expected in (("direct", 0.13295), ("rocker", 0.11168), ("pushrod", 0.14359)):
        mass, how = masses.reduced_mass(area, layout, 1.6)
        assert mass == pytest.approx(expected, abs=5e-6) and f"default for a {layout} drive" in how
    mass, how = masses.reduced_mass(area, "pushrod", 1.6, specific_mass=450.0)
    assert mass == pytest.approx(0.47862, abs=5e-6) and "450 kg/m2 (given)" in how
    # the source is a note of the catalogue (issue 41): the report says it in Russian from its code, the work cited
    # in its bibliography form (the report numbers it)
    assert note_text(masses.reduced_mass(area, "rocker", 1.6)[1].parts, "ru") == (
        "удельная масса 105 кг/м² (по умолчанию для привода с коромыслом), Valve-train practical works (n.d.), работа 5")


def test_part_masses_take_the_designed_spring_when_none_is_given():
    """[drive.masses] without spring_kg: a third of the designed spring's mass moves with the valve, eq. (5.2)."""
    parts = SimpleNamespace(valve_kg=0.05, retainer_kg=0.02, cotters_kg=0.005, spring_kg=None, pushrod_kg=0.0,
                            tappet_kg=0.04, rocker_inertia=0.0)
    mass, how = masses.reduced_mass(1e-3, "direct", 1.0, parts=parts, spring_mass=0.06)
    assert mass == pytest.approx(0.05 + 0.02 + 0.005 + 0.02 + 0.04, rel=1e-12)
    assert how.endswith("; spring mass of the design")
    given, how = masses.reduced_mass(1e-3, "direct", 1.0, parts=SimpleNamespace(**{**vars(parts), "spring_kg": 0.03}),
                                     spring_mass=0.06)
    assert given == pytest.approx(0.05 + 0.02 + 0.005 + 0.01 + 0.04, rel=1e-12) and "design" not in how
