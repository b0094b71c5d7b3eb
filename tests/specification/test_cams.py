"""The cam sections (specification/cams.py): the registry of the laws' models, and the Kurz cam of the appendix of Valve-train practical works
(n.d.) built from its keys (timing 26 deg before TDC and 78 deg after BDC, 10 mm valve lift, rocker ratio 1.6,
clearance 0.25 mm taken up by a cosine ramp ending at 0.02 mm/deg; Phi = 27 + 6 + 38 = 71 cam deg)."""

import math

import numpy as np
import pytest

from valvetrain.laws.kurz import KurzLaw
from valvetrain.specification import si
from valvetrain.specification.cams import REGISTRY

from appendix import appendix_spec


def test_each_law_s_model_is_registered_under_its_law():
    assert {"kurz", "polydyne", "polynomial", "constant_acceleration", "combined", "dynamic", "power_polynomial",
            "harmonic", "three_arc", "tangent", "table"} <= set(REGISTRY)
    for name, model in REGISTRY.items():
        assert model.model_fields["law"].annotation.__args__ == (name,)


def test_the_appendix_kurz_cam_built_from_its_keys():
    """Tappet-side nose lift 10 / 1.6 + 0.25 = 6.5 mm; main half angle 71 cam deg; the cosine ramp lasts
    pi h0 / (2 w') = pi x 0.25 / (2 x 0.02) = 19.635 cam deg (Valve-train practical works (n.d.), eq. (2.1)); the nose
    at 116 crank deg; the timing as given."""
    spec = appendix_spec()
    valve, engine = si(spec.valves["intake"]), si(spec.engine)
    law = valve.cam.section.build(valve, engine)
    assert isinstance(law, KurzLaw)
    assert law.lift(0.0) == pytest.approx(6.5e-3, rel=1e-12) and law.ramp_height == pytest.approx(0.25e-3)
    assert np.degrees(law.main_half_angle) == pytest.approx(71.0, rel=1e-12)
    assert np.degrees(law.ramp_angle) == pytest.approx(math.pi * 0.25 / (2 * 0.02), rel=1e-9)
    assert np.degrees(valve.cam.section.nose_crank(valve, law)) == pytest.approx(116.0, rel=1e-12)
    assert np.degrees(valve.cam.section.timing(valve, None)) == pytest.approx((26.0, 78.0), rel=1e-12)


def test_a_kurz_synthesis_varies_the_segment_angles_and_the_shape_factor():
    """The default variables of a Kurz cam's synthesis are its keys phi1, phi2 and Z, each range holding the
    appendix's value (27 deg, 6 deg, 0.625) inside the main half angle of 71 cam deg."""
    spec = appendix_spec()
    variables = {key: (low, high) for key, low, high in spec.valves["intake"].cam.search_variables(
        spec.valves["intake"], spec.engine)}
    assert set(variables) == {"cam.phi1_deg", "cam.phi2_deg", "cam.shape_factor"}
    for key, value in (("cam.phi1_deg", 27.0), ("cam.phi2_deg", 6.0), ("cam.shape_factor", 0.625)):
        low, high = variables[key]
        assert 0.0 < low < value < high
    assert variables["cam.phi1_deg"][1] < 71.0 and variables["cam.shape_factor"][1] < 1.0
