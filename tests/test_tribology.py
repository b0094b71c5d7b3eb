"""Lubrication and friction of the cam contact (valvetrain.tribology), each against an independent reference: the
geometry of an eccentric circular cam differentiated numerically, a hand calculation of the film formula and the
second published line-contact formula (Pan and Hamrock), the one-dimensional conduction of a fast-moving band source,
the friction moment about the camshaft axis."""

import math
import warnings

import numpy as np
import pytest

from valvetrain import tribology

R_DISK, ECC, OMEGA = 0.020, 0.004, 300.0
"""An eccentric circular cam: disk radius [m], eccentricity [m], camshaft speed [rad/s]."""


def _eccentric_flat(phi):
    """Flat follower on the eccentric disk, from the geometry alone: the face lies at y = R + e cos phi (the disk's
    centre at (-e sin phi, e cos phi) after a rotation phi counter-clockwise); the contact point is the disk's point
    right below the centre: x_c = -e sin phi."""
    y_face = R_DISK + ECC * np.cos(phi)
    x_contact = -ECC * np.sin(phi)
    return y_face, x_contact


def test_flat_follower_velocities_match_the_eccentric_cam_geometry():
    """u_cam = omega rho and u_f = omega h'' against the surface velocities of the eccentric disk relative to its
    contact point, differentiated numerically (central differences, step 1e-6 rad)."""
    phi = np.linspace(-2.5, 2.5, 11)
    d = 1e-6
    y_face, x_c = _eccentric_flat(phi)
    contact_speed = (_eccentric_flat(phi + d)[1] - _eccentric_flat(phi - d)[1]) / (2 * d) * OMEGA
    cam_material = -OMEGA * y_face                      # x-velocity of the disk's material point at (x_c, y_face)
    cam_relative, follower_relative = cam_material - contact_speed, 0.0 - contact_speed
    base = R_DISK - ECC                                 # smallest y_face: the heel circle
    h = y_face - base
    d2h = -ECC * np.cos(phi)                            # h = e (1 + cos phi), h'' = -e cos phi
    u_cam, u_f = tribology.flat_follower_velocities(OMEGA, base, h, d2h)
    # the function's positive direction is the opposite of the x axis here: both signs flip together
    assert np.allclose(-u_cam, cam_relative, rtol=1e-7, atol=1e-9)
    assert np.allclose(-u_f, follower_relative, rtol=1e-7, atol=1e-9)
    assert np.allclose(np.abs(u_cam), OMEGA * R_DISK)   # a circular cam: rho = R everywhere


def test_roller_follower_velocity_is_the_contact_points_speed_along_the_eccentric_cam():
    """u_cam of an in-line roller on the eccentric disk against the speed of the contact point along the disk in
    the cam's frame, from the positions alone (numerical derivative)."""
    r = 0.008

    def contact_in_cam_frame(phi):
        y = ECC * np.cos(phi) + np.sqrt((R_DISK + r) ** 2 - (ECC * np.sin(phi)) ** 2)   # roller centre, fixed frame
        c, s = np.cos(-phi), np.sin(-phi)
        centre = np.array([-s * y, c * y])              # rotated back by -phi into the cam's frame
        disk = np.array([0.0, ECC])[:, None] * np.ones_like(phi)
        v = centre - disk
        return disk + R_DISK * v / np.linalg.norm(v, axis=0), y

    phi = np.linspace(-2.0, 2.0, 9)
    d = 1e-6
    speed = np.linalg.norm(contact_in_cam_frame(phi + d)[0] - contact_in_cam_frame(phi - d)[0], axis=0) / (2 * d)
    y = contact_in_cam_frame(phi)[1]
    base = R_DISK - ECC
    h = y - (base + r)
    dh = (contact_in_cam_frame(phi + d)[1] - contact_in_cam_frame(phi - d)[1]) / (2 * d)
    u_cam, u_roller = tribology.roller_follower_velocities(OMEGA, base, r, h, dh, np.full_like(phi, R_DISK))
    assert np.allclose(u_cam, OMEGA * speed, rtol=1e-6)
    assert np.array_equal(u_roller, u_cam)              # pure rolling
    assert np.allclose(tribology.roller_follower_velocities(OMEGA, base, r, h, dh, R_DISK, slip=0.1)[1], 0.9 * u_cam)


def test_dowson_higginson_film_by_hand():
    """R = 10 mm, u = 1 m/s, eta0 = 10 mPa s, alpha = 20 1/GPa, E' = 220 GPa, w' = 100 N/mm, worked by hand:
    U = 0.01 x 1 / (2.2e11 x 0.01) = 4.5455e-12, U^0.70 = 1.14896e-8; G = 2e-8 x 2.2e11 = 4400, G^0.54 = 92.782;
    W = 1e5 / (2.2e11 x 0.01) = 4.5455e-5, W^-0.13 = 3.66872; h = 2.65 x 1.14896e-8 x 92.782 x 3.66872 x 0.01 m
    = 0.10364 um."""
    h = tribology.film_thickness_line(1.0, 0.01, 1e5, 0.01, 2e-8, 2.2e11)
    assert h == pytest.approx(0.10364e-6, rel=1e-4)
    # the same contact by Pan and Hamrock's regression, H = 1.714 W^-0.128 U^0.694 G^0.568 (Hamrock, Schmid and
    # Jacobson (2004), ch. 21): 0.0972 um, within 7 %
    assert h == pytest.approx(1.714 * 4.5455e-5**-0.128 * 4.5455e-12**0.694 * 4400**0.568 * 0.01, rel=0.07)


def test_film_parameter_regimes_and_friction():
    """lambda = 0.3 um / sqrt(0.3^2 + 0.4^2) um = 0.6 (a 3-4-5 triangle); regime bands 1 and 3."""
    assert tribology.film_parameter(0.3e-6, 0.3e-6, 0.4e-6) == pytest.approx(0.6)
    assert tribology.regime(np.array([0.6, 1.5, 3.5])).tolist() == [0, 1, 2]
    # halfway across the mixed band the coefficient is the mean of the two ends: (0.12 + 0.04) / 2
    assert tribology.friction_coefficient(2.0, 0.12, 0.04) == pytest.approx(0.08)


def test_blok_flash_temperature_against_a_uniform_band_source():
    """A uniform heat flux q over a band 2a moving fast over a half-space heats a surface point as 1-D conduction,
    theta(t) = 2 q sqrt(t / pi) / beta (beta = sqrt(k rho c)), most at the trailing edge, t = 2a/u.  With the heat
    shared so that both surfaces reach the same temperature, theta = 2 sqrt(2a/pi) q_total / (beta_1 sqrt(u_1)
    + beta_2 sqrt(u_2)), q_total = mu w' |u_1 - u_2| / 2a, i.e. 2 / sqrt(pi) = 1.128 in place of Blok's 1.11 over
    sqrt(2a): Blok's semi-elliptic (Hertzian) source peaks 1.6 % below the uniform one (1.11 / 1.128 = 0.984)."""
    mu, w, a, beta = 0.1, 1e5, 0.2e-3, 1.3e4
    u1, u2 = 8.0, 2.0
    q = mu * w * abs(u1 - u2) / (2 * a)
    uniform = 2.0 * math.sqrt(2 * a / math.pi) * q / (beta * math.sqrt(u1) + beta * math.sqrt(u2))
    blok = tribology.flash_temperature(mu, w, u1, u2, a, beta, beta)
    assert blok == pytest.approx(uniform, rel=0.025)
    assert blok < uniform
    assert tribology.flash_temperature(mu, w, 3.0, 3.0, a, beta, beta) == 0.0    # pure rolling: no heat


def test_flat_follower_friction_torque_is_the_friction_moment_about_the_camshaft():
    """The friction force mu F lies along the face, R0 + h from the camshaft axis: T = mu F (R0 + h)."""
    base, h, force, mu = 0.018, 0.004, 1500.0, 0.1
    u_cam, u_f = tribology.flat_follower_velocities(OMEGA, base, h, -0.002)
    torque = tribology.friction_torque(force, mu, u_cam - u_f, 0.0, 0.0, OMEGA)
    assert torque == pytest.approx(mu * force * (base + h), rel=1e-12)


def test_on_a_straight_flank_the_roller_s_contact_runs_at_the_pitch_curve_s_speed():
    """A tangent cam's flank is straight (rho infinite): the contact point and the roller's centre move alike,
    u_cam = omega sqrt(g^2 + h'^2) (the limit rho / (rho + R_r) -> 1); the former rho / (rho + R_r) gave inf / inf,
    NaN with a RuntimeWarning (the fuzzer's tangent cam on examples/phaser.toml's roller)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        u_cam, _ = tribology.roller_follower_velocities(OMEGA, 0.02, 0.008, np.array([0.003]), np.array([0.01]),
                                                         np.array([np.inf]))
    assert u_cam[0] == pytest.approx(OMEGA * np.hypot(0.02 + 0.008 + 0.003, 0.01), rel=1e-15)
