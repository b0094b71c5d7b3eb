"""The variables of the cam synthesis (valvetrain.synthesis.variables): each law's default set, the command line's
bounds."""

from pathlib import Path

import pytest

from valvetrain.specification.reading import load_spec
from valvetrain.synthesis.variables import Variable, default_variables, parse_variables

from appendix import appendix_spec

EXAMPLES = Path(__file__).parents[2] / "examples"


def test_default_variables_per_law():
    kurz = appendix_spec()
    paths = [v.path for v in default_variables(kurz.valves["intake"], kurz.engine)]
    assert paths == ["cam.phi1_deg", "cam.phi2_deg", "cam.shape_factor", "cam.ramp_end_velocity_mm_per_deg",
                     "drive.spring_reserve"]
    poly = load_spec(EXAMPLES / "seed000-polydyne.toml")
    # the example gives p alone: q, r, s follow from it (Valve-train practical works (n.d.), work 3)
    assert [v.path for v in default_variables(poly.valves["intake"], poly.engine)][0] == "cam.p"
    measured = load_spec(EXAMPLES / "measured-lobe.toml")
    with pytest.raises(ValueError, match="--vary"):
        default_variables(measured.valves["intake"], measured.engine)


def test_parse_variables_refuses_bad_bounds():
    assert parse_variables(["cam.phi1_deg=20,35"]) == [Variable("cam.phi1_deg", 20.0, 35.0)]
    for bad in ("cam.phi1_deg=35,20", "cam.phi1_deg", "cam.phi1_deg=a,b", "=1,2", "cam.phi1_deg=1,nan"):
        with pytest.raises(ValueError, match="KEY=LOW,HIGH"):
            parse_variables([bad])
