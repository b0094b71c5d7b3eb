"""The power-polynomial acceleration cam of UkrSURT Proceedings (2019), reconstructed: closure, C2 junctions,
closed-form integrals, symmetry, and the numbers the reconstruction reproduces."""

import numpy as np
import pytest

from valvetrain.laws import PolydyneLaw, PowerPolynomialLaw
from valvetrain.laws.power_polynomial import ramp_coefficients

MM, DEG = 1e-3, np.pi / 180.0


def article(a_qd=135.2, phi1=19.3, x_d=0.2, x_g=0.8, reconstruction="R2", **kw):
    """The 26/27 diesel: S_max 21.1 mm, S_b 0.8 mm, phi_0 12 deg, v_qb 6 mm/rad, half action angle 80.75 deg."""
    return PowerPolynomialLaw(20.3 * MM, (80.75 - 12.0) * DEG, 0.8 * MM, 12.0 * DEG, 6.0 * MM, a_qd * MM, phi1 * DEG,
                              x_d, x_g, reconstruction=reconstruction, **kw)


LAWS = [article(), article(x_d=0.1, x_g=0.9), article(a_qd=100.8, phi1=24.35, x_d=0.02, x_g=0.78),
        article(reconstruction="R1", x_d=0.5, x_g=0.5), article(reconstruction="R1", x_d=0.3, x_g=0.6, sharpness=4.0),
        article(exponents=dict(n=2.0, m=5.0, p=0.7, q=4.0, r=0.5, s=1.0, t=3.0, u=9.0))]


def test_ramp_coefficients():
    A, B, C = (c for c in ramp_coefficients(0.8, 12.0 * DEG, 6.0))
    assert (A, B, C) == pytest.approx((46.966, -15.978, -30.988), abs=5e-4)


@pytest.mark.parametrize("law", LAWS)
def test_closure_at_both_ends(law):
    """Zero lift and velocity at a and a'; the ramp starts with its finite acceleration A_0 (three coefficients for
    a(b) = 0, v(b) = v_qb, S(b) = S_b), zero on the base circle just outside."""
    d = law.derivatives(np.array([law.start, law.end]))
    assert np.abs(d[:2]).max() < 1e-15
    A0 = ramp_coefficients(law.ramp_height, law.ramp_angle, law.v_qb)[0]
    assert d[2] == pytest.approx([A0, A0], rel=1e-12)
    outside = law.derivatives(np.array([law.start - 1e-9, law.end + 1e-9]))
    assert np.all(outside == 0.0)


@pytest.mark.parametrize("law", LAWS)
def test_c2_at_every_junction(law):
    """Lift, velocity and acceleration are continuous at every junction inside the event (b, d, e, g, h, nose).

    Where an exponent below 1 meets a junction (p and r at e) the jerk is infinite there and the acceleration
    approaches its limit like |dtheta|^p: the step across the junction shrinks with the distance to it."""
    inner = law.breakpoints[1:-1]
    scale = np.abs(law.derivatives(np.linspace(law.start, law.end, 2001))[:3]).max(axis=1)

    def step(eps):
        return np.abs(law.derivatives(inner - eps) - law.derivatives(inner + eps))[:3]

    far, near = step(1e-9), step(1e-13)
    assert np.all(near[:2].max(axis=1) < 1e-8 * scale[:2])
    assert near[2].max() < 1e-3 * scale[2]
    assert np.all((near[2] <= far[2] / 5.0) | (far[2] < 1e-6 * scale[2]))


@pytest.mark.parametrize("law", LAWS)
def test_velocity_and_acceleration_are_derivatives(law):
    """The closed-form velocity is the derivative of the lift, the acceleration that of the velocity (central
    differences away from the junctions)."""
    theta = np.linspace(law.start, law.end, 4001)[1:-1]
    theta = theta[np.min(np.abs(theta[:, None] - law.breakpoints[None, :]), axis=1) > 1e-4]
    h = 1e-6
    d, up, down = law.derivatives(theta), law.derivatives(theta + h), law.derivatives(theta - h)
    assert np.abs((up[0] - down[0]) / (2 * h) - d[1]).max() < 1e-6 * np.abs(d[1]).max()
    assert np.abs((up[1] - down[1]) / (2 * h) - d[2]).max() < 1e-5 * np.abs(d[2]).max()


@pytest.mark.parametrize("law", LAWS)
def test_symmetric_about_the_nose(law):
    theta = np.linspace(0.0, law.end, 777)
    a, b = law.derivatives(theta), law.derivatives(-theta)
    assert np.allclose(a[0], b[0], atol=1e-15) and np.allclose(a[2], b[2], atol=1e-12)
    assert np.allclose(a[1], -b[1], atol=1e-15)


@pytest.mark.parametrize("law", LAWS)
def test_reaches_the_lift_and_stops(law):
    """S_h = S_max and v(h) = 0; the lift at the nose is the required one, the lift is monotone on the rise."""
    assert law.S_h == pytest.approx(21.1 * MM, rel=1e-12)
    assert abs(law.v_h) < 1e-12
    assert law.lift(np.array([0.0]))[0] == pytest.approx(21.1 * MM, rel=1e-12)
    assert np.all(np.diff(law.lift(np.linspace(law.start, 0.0, 2001))) >= -1e-15)


def test_the_article_positive_part():
    """At the article's a_qd = 135.2 mm/rad2, phi_1 = 19.3 deg (n = 1, m = 4, p = 0.5, q = 4.5) and x_d = 0.2:
    S_e = 8.65 mm, v_e = 37.96 mm/rad; with phi_2 = 31.4 deg as printed the dwell lift would be 18.57 mm."""
    law = article()
    assert law.S_e / MM == pytest.approx(8.65, abs=0.005)
    assert law.v_e / MM == pytest.approx(37.96, abs=0.005)
    # the lift gained over e-h is proportional to phi_2 at a given shape
    gain_per_phi2 = (21.1 * MM - law.S_e) / law.phi2
    assert (law.S_e + gain_per_phi2 * 31.4 * DEG) / MM == pytest.approx(18.57, abs=0.005)


@pytest.mark.parametrize("x_d, x_g, phi2, eta", [(0.1, 0.9, 34.8, 0.679), (0.2, 0.8, 39.4, 0.668),
                                                 (0.9, 0.9, 48.4, 0.598)])
def test_phi2_and_fullness_at_the_lift(x_d, x_g, phi2, eta):
    """phi_2 solved for S_h = 21.1 mm and the fullness of the tappet lift over the valve-open part."""
    law = article(x_d=x_d, x_g=x_g)
    assert np.degrees(law.phi2) == pytest.approx(phi2, abs=0.05)
    assert law.fullness() == pytest.approx(eta, abs=5e-4)


def test_fullness_is_the_integral():
    law = article()
    phi = np.linspace(law.start + law.ramp_angle, law.end - law.ramp_angle, 400001)
    s = law.lift(phi)
    numeric = np.sum((s[1:] + s[:-1]) / 2 * np.diff(phi)) / (law.S_h * 2 * law.main_half_angle)
    assert law.fullness() == pytest.approx(numeric, rel=1e-8)


def test_more_fullness_than_the_polydyne():
    """The reconstruction's optimum (a_qd = 100.8 mm/rad2, phi_1 = 24.35 deg, x_d = 0.02, x_g = 0.78) against the
    polydyne (2, 10, 18, 26, 34) of the same lift, ramp and angle."""
    law = article(a_qd=100.8, phi1=24.35, x_d=0.02, x_g=0.78)
    assert law.fullness() == pytest.approx(0.660, abs=1e-3)
    poly = PolydyneLaw(20.3 * MM, 68.75 * DEG, 10, ramp_height=0.8 * MM, ramp_velocity=6 * MM)
    assert poly.ramp_angle == pytest.approx(12 * DEG, rel=1e-9)
    phi = np.linspace(poly.start + poly.ramp_angle, poly.end - poly.ramp_angle, 200001)
    s = poly.lift(phi)
    eta_poly = np.sum((s[1:] + s[:-1]) / 2 * np.diff(phi)) / (21.1 * MM * 2 * poly.main_half_angle)
    assert eta_poly == pytest.approx(0.578, abs=1e-3)
    assert law.fullness() / eta_poly > 1.12


def test_refusals():
    with pytest.raises(ValueError, match="within the positive part"):
        article(a_qd=2000.0, phi1=60.0)
    with pytest.raises(ValueError, match="exceeds the main half angle"):
        article(a_qd=20.0)
    with pytest.raises(ValueError, match="different"):
        article(exponents=dict(n=2.0, m=2.0))
    with pytest.raises(ValueError, match="reconstruction"):
        article(reconstruction="R3")


def _spec_text(**keys):
    from pathlib import Path
    text = (Path(__file__).parents[2] / "examples" / "ukrsurt2019-diesel.toml").read_text()
    for k, v in keys.items():
        text = "\n".join(f"{k} = {v}" if line.split("=")[0].strip() == k else line for line in text.splitlines())
    return text


@pytest.mark.parametrize("keys, words", [
    (dict(n=4.0), "n = m = 4"),
    (dict(peak_position=1.0), "peak_position"),
    (dict(phi1_deg=70.0), "phi1_deg = 70 leaves no room"),
    (dict(ramp_end_velocity_mm_per_rad=100.0), "ramp_end_velocity_mm_per_rad"),
])
def test_specification_refusals(keys, words):
    """Keys out of their bounds or that admit no cam are refused with a message that names them."""
    from valvetrain.specification.messages import SpecError
    from valvetrain.specification.reading import parse_spec
    with pytest.raises(SpecError) as err:
        parse_spec(_spec_text(**keys))
    assert words in str(err.value)


def test_no_room_for_the_dwell_is_refused_at_the_design():
    """A weak positive part needs a phi_2 beyond the half angle: the design refuses it naming the keys."""
    from valvetrain.design import run
    from valvetrain.specification.messages import SpecError
    from valvetrain.specification.reading import parse_spec
    with pytest.raises(SpecError, match="peak_acceleration_mm_per_rad2"):
        run(parse_spec(_spec_text(peak_acceleration_mm_per_rad2=20.0)))


def test_the_spec_builds_the_article_law():
    from valvetrain.design import run
    from valvetrain.specification.reading import parse_spec
    law = run(parse_spec(_spec_text())).valves["intake"].law
    assert isinstance(law, PowerPolynomialLaw)
    assert np.degrees(law.phi2) == pytest.approx(39.40, abs=0.01)
    assert law.half_angle / DEG == pytest.approx(80.75, abs=1e-9)
    r1 = run(parse_spec(_spec_text(reconstruction='"R1"'))).valves["intake"].law
    assert r1.reconstruction == "R1" and r1.S_h == pytest.approx(21.1 * MM, rel=1e-12)
