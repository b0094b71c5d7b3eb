"""The lubrication stage of a valve ([valves.NAME.lubrication]) over the strength speed range: energy balance of the
drive torque, the regimes against the film parameter, the refusals, and a flat follower's zero entrainment against
the cam's own curvature."""

import json

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.export import results_json
from valvetrain.specification import SpecError, parse_spec

from appendix import appendix_text


def example(lubrication="", parts=True):
    """The built-in example (pushrod intake valve, flat follower, 7000 rpm) with a [lubrication] section."""
    text = appendix_text() + f"\n[valves.intake.lubrication]\n{lubrication}\n"
    if not parts:
        text = text.replace("cam_width_mm = 16.0\n", "")
    return parse_spec(text)


@pytest.fixture(scope="module")
def flat():
    design = run(example())
    return design.valves["intake"], json.loads(results_json(design))["valves"]["intake"]["lubrication"]


def test_mean_drive_torque_is_the_mean_friction_torque(flat):
    """Energy balance: over a camshaft revolution the spring and the rigid train's inertia do no net work, so the
    frictionless part F dh/dtheta of the quasi-static drive torque averages to zero and the mean drive torque with
    friction is the mean friction torque (to the quadrature of the open event, 1e-3 of the friction)."""
    per = flat[1]["per_speed"]
    assert np.allclose(per["mean_drive_torque_N_m"], per["mean_friction_torque_N_m"], rtol=1e-3)
    # and the friction power is that torque times the camshaft speed (half the engine speed of a four-stroke)
    omega_cam = np.array(per["speed_rpm"]) * np.pi / 30.0 / 2.0
    assert np.allclose(per["friction_power_W"], np.array(per["mean_friction_torque_N_m"]) * omega_cam, rtol=1e-12)


def test_regimes_cover_the_open_event(flat):
    """Every angle of the open event is in exactly one regime: the three angles add up to the event, 2 x 71 cam deg
    of the example's Kurz cam with its ramps (phi1 + phi2 + phi3 = 27 + 6 + 38)."""
    per = flat[1]["per_speed"]
    total = np.add(np.add(per["boundary_cam_deg"], per["mixed_cam_deg"]), per["full_film_cam_deg"])
    assert np.allclose(total, 142.0, rtol=1e-12)
    # the film thickens with speed (h ~ u^0.7): the full-film angle does not shrink as the speed rises
    assert np.all(np.diff(per["full_film_cam_deg"]) >= -1e-9)


def test_flat_follower_zero_entrainment_where_rho_plus_d2h_vanishes(flat):
    """A flat follower's entraining velocity omega (R0 + h + 2h'')/2 changes sign where rho + h'' = 0, rho the cam's
    radius of curvature from the profile stage's own function (law.curvature): found here by a root finder on the
    law, to the sampling step of the stage (0.1 cam deg)."""
    from scipy.optimize import brentq

    valve, rec = flat
    law, heel = valve.law, valve.heel_radius

    def f(t):
        return float(law.curvature(np.array([t]), heel)[0] + law.derivatives(np.array([t]))[2][0])

    roots = [brentq(f, -0.6, -0.05), brentq(f, 0.05, 0.6)]
    assert np.allclose(rec["zero_entrainment_cam_deg"], np.degrees(roots), atol=0.1)
    # there the film parameter is smallest and the contact is in boundary lubrication
    assert rec["min_film_parameter"] < 0.01


def test_checks_and_their_limits():
    design = run(example("min_film_parameter = 0.0001\nmax_contact_temperature_C = 400\n"))
    checks = {c.quantity: c for c in design.valves["intake"].checks}
    film = checks["intake: cam contact: smallest film parameter lambda = h_min / sqrt(Rq1^2 + Rq2^2)"]
    heat = checks["intake: cam contact: largest contact temperature (oil + Blok's flash temperature)"]
    assert film.passed and film.low == 0.0001 and film.severity == "warning"
    assert heat.passed and heat.high == 400.0 and heat.severity == "failure"
    strict = run(example("max_contact_temperature_C = 101\n"))
    assert not {c.quantity: c for c in strict.valves["intake"].checks}[heat.quantity].passed


def test_without_a_section_there_is_no_lubrication_record():
    assert "lubrication" not in json.loads(results_json(run(parse_spec(appendix_text()))))["valves"]["intake"]


@pytest.mark.parametrize("lubrication, parts, words", [
    ("", False, "valves.intake.lubrication needs valves.intake.parts.cam_width_mm"),
    ("full_film_friction = 0.2\nboundary_friction = 0.1\n", True, "full_film_friction = 0.2 must not exceed"),
    ("oil_temperature_C = 160\n", True, "max_contact_temperature_C = 150 must exceed oil_temperature_C = 160"),
    ("roller_slip = 1.5\n", True, "roller_slip"),
])
def test_refusals_name_the_key(lubrication, parts, words):
    with pytest.raises(SpecError, match=words.replace("(", r"\(").replace(")", r"\)")):
        run(example(lubrication, parts))


def test_a_section_without_the_cam_width_is_refused_with_the_specification():
    """Refused by the specification's validation (``valvetrain validate``), before any stage runs: it was refused by
    the lubrication stage, after the valve's dynamics sweep (a fuzz finding; fails before: parse_spec passed it)."""
    with pytest.raises(SpecError, match=r"valves\.intake\.lubrication needs valves\.intake\.parts\.cam_width_mm"):
        example(parts=False)


def test_an_undercut_cam_is_a_failure_not_a_refusal_of_its_lubrication():
    """A polydyne exponent p = 3 on the shipped finger undercuts the intake cam.  The profile stage grades that a
    failure (profile.undercut_roller; nothing for its manufacture is written): the cam has no line contact, so the
    oil film is not computed, and the design still runs with every other check (before the fix the [lubrication]
    section turned the whole design into a refusal naming valves.intake.lubrication, not the cam)."""
    from pathlib import Path

    path = Path(__file__).parents[2] / "examples" / "modern-dohc-roller-finger.toml"
    text = path.read_text(encoding="utf-8").replace("p = 8\nfollower", "p = 3\nfollower", 1)
    design = run(parse_spec(text)).valves["intake"]
    undercut = [c for c in design.checks if c.code == "profile.undercut_roller"]
    assert design.profile.undercut and len(undercut) == 1 and not undercut[0].passed
    assert undercut[0].severity == "failure"
    assert design.lubrication is None
