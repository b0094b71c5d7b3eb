"""The whole camshaft's physics (valvetrain.camshaft): torque of the lobes, orders, torsion, frequencies, bending."""

import numpy as np
import pytest

from valvetrain import camshaft as shaft

N = 3600
PSI = 2.0 * np.pi * np.arange(N) / N


def test_four_equal_lobes_at_90_cam_deg_keep_only_the_orders_multiple_of_4():
    """An inline four (firing 1-3-4-2, even: 0, 180, 540, 360 crank deg) puts its four lobes 90 cam deg apart, so the
    sum repeats every quarter revolution: only orders 4, 8, ... survive (Fourier series of a function of period
    2 pi / 4).  The lobe: an arbitrary smooth torque over +-60 cam deg."""
    noses = shaft.lobe_noses(np.radians(107.0), np.radians([0.0, 180.0, 540.0, 360.0]), 4)
    theta = np.linspace(-np.pi / 3, np.pi / 3, 801)
    torque = 12.0 * np.sin(3 * theta) * np.cos(1.5 * theta) ** 2 + 2.0 * np.cos(1.5 * theta)
    total = shaft.lobe_torques(PSI, theta, torque, noses).sum(axis=0)
    a = shaft.harmonic_orders(total, 40)
    others = np.delete(a[1:], np.arange(3, 40, 4))
    assert a[4] > 1.0
    assert np.max(others) < 1e-9 * np.max(a)


def test_single_lobe_of_a_harmonic_law_has_the_closed_form_orders():
    """A lobe h = H/2 (1 + cos theta) over the whole revolution with a spring F0 + k h and a mass m at the camshaft
    speed omega: T = (F0 + k h + m omega^2 h'') h'.  By hand, with h' = -(H/2) sin theta, h'' = -(H/2) cos theta:
    T = -(H/2)(F0 + kH/2) sin theta + (m omega^2 - k) H^2/8 sin 2 theta, so order 1 has (H/2)(F0 + kH/2), order 2
    |m omega^2 - k| H^2 / 8, every other order and the mean (the work of conservative forces) nothing."""
    H, F0, k, m, omega = 0.01, 300.0, 3.0e4, 0.4, 400.0
    theta = np.linspace(-np.pi, np.pi, 20001)
    h, dh, d2h = H / 2 * (1 + np.cos(theta)), -H / 2 * np.sin(theta), -H / 2 * np.cos(theta)
    torque = (F0 + k * h + m * omega**2 * d2h) * dh
    total = shaft.lobe_torques(PSI, theta, torque, np.array([0.7])).sum(axis=0)
    a = shaft.harmonic_orders(total, 10)
    assert a[1] == pytest.approx(H / 2 * (F0 + k * H / 2), rel=1e-6)      # 1.65 N m
    assert a[2] == pytest.approx(abs(m * omega**2 - k) * H**2 / 8, rel=1e-6)   # 0.1625 N m
    assert a[0] < 1e-6 * a[1]
    assert np.max(a[3:]) < 1e-6 * a[1]


def test_twist_of_two_sections_in_series_against_a_hand_calculation():
    """Sections 100 mm of d 20 mm and 200 mm of d 30 mm (bore 10 mm), G = 80 GPa; stations at 150 mm (T1 = 10 N m)
    and 300 mm (T2 = 4 N m).  J1 = pi 0.02^4 / 32 = 1.5707963e-8 m^4, J2 = pi (0.03^4 - 0.01^4) / 32 = 7.8539816e-8
    m^4.  The shaft up to 150 mm carries T1 + T2 = 14 N m: 14 (0.1 / (G J1) + 0.05 / (G J2)) = 14 (7.9577472e-5 +
    7.9577472e-6) = 1.2254931e-3 rad; beyond it T2 alone: + 4 x 0.15 / (G J2) = 4 x 2.3873241e-5 = 9.5492966e-5,
    1.3209861e-3 rad at 300 mm."""
    c = shaft.shaft_compliance(np.array([0.15, 0.3]), [0.1, 0.2], [0.02, 0.03], [0.0, 0.01], 80e9)
    phi = shaft.twist(c, np.array([[10.0], [4.0]]))[:, 0]
    assert phi == pytest.approx([1.2254931e-3, 1.3209861e-3], rel=1e-7)


def test_one_grounded_mass_and_two_free_masses_against_their_closed_forms():
    """sqrt(k / J) (Den Hartog (1956)): k = 5e4 N m/rad, J = 2e-4 kg m^2 -> 15811.388 rad/s; two free masses
    J1 = 1e-4, J2 = 3e-4 on k = 5e4: sqrt(k (J1 + J2) / (J1 J2)) = sqrt(5e4 x 4e-4 / 3e-8) = 25819.889 rad/s."""
    assert shaft.torsional_frequencies([5e4], [2e-4])[0] == pytest.approx(15811.388, rel=1e-7)
    free = shaft.torsional_frequencies([5e4], [1e-4, 3e-4], grounded=False)
    assert free.size == 1 and free[0] == pytest.approx(25819.889, rel=1e-7)


def test_two_equal_grounded_masses_against_the_characteristic_equation():
    """Ground -k- J -k- J: det [[2k - w^2 J, -k], [-k, k - w^2 J]] = 0 gives w^2 = (3 -+ sqrt 5)/2 k/J; with k = 1e4,
    J = 1e-4: w = 6180.3399 and 16180.340 rad/s."""
    w = shaft.torsional_frequencies([1e4, 1e4], [1e-4, 1e-4])
    assert w == pytest.approx([6180.3399, 16180.340], rel=1e-7)


def test_stations_stiffness_from_the_compliance_of_the_pieces_between_them():
    """A uniform shaft d 25 mm, G = 81 GPa: the piece of 40 mm to the first station k = G J / l = 81e9 x 3.8349520e-8
    / 0.04 = 77657.78 N m/rad, the next piece of 90 mm 34514.57 N m/rad."""
    c = shaft.shaft_compliance(np.array([0.04, 0.13]), [0.3], [0.025], [0.0], 81e9)
    assert shaft.station_stiffness(c) == pytest.approx([77657.78, 34514.57], rel=1e-6)


def test_lumped_shaft_inertia_of_a_uniform_shaft():
    """Uniform shaft 300 mm, d 20 mm, rho 7850: rho J = 7850 x 1.5707963e-8 = 1.2330751e-4 kg m^2 per m.  Stations
    at 100 and 200 mm: the first gets half of 0-100 and half of 100-200 (100 mm: 1.2330751e-5), the second half of
    100-200 and all of 200-300 (150 mm: 1.8496127e-5); the half of 0-100 at the held drive end is left out."""
    inertia = shaft.lumped_shaft_inertia(np.array([0.1, 0.2]), [0.3], [0.02], [0.0], 7850.0)
    assert inertia == pytest.approx([1.2330751e-5, 1.8496127e-5], rel=1e-7)


def test_bending_deflection_on_the_span_between_its_journals():
    """Journals at 0, 100, 250 mm; a lobe at 160 mm lies on the span 100-250 mm: a = 60, b = 90 mm, l = 150 mm.
    P = 3000 N, d = 30 mm solid, E = 210 GPa, I = pi 0.03^4 / 64 = 3.9760782e-8 m^4: f = P a^2 b^2 / (3 E I l) =
    3000 x 0.0036 x 0.0081 / (3 x 210e9 x 3.9760782e-8 x 0.15) = 2.3280e-5 m (Shigley (2011), table A-9, case 6)."""
    f = shaft.lobe_deflection(np.array([3000.0]), np.array([0.16]), np.array([0.0, 0.1, 0.25]), np.array([0.03]),
                              np.array([0.0]), 210e9)
    assert f[0] == pytest.approx(3000 * 0.0036 * 0.0081 / (3 * 210e9 * 3.9760782e-8 * 0.15), rel=1e-7)
    assert f[0] == pytest.approx(2.3280e-5, rel=1e-4)


def test_lobe_noses_of_a_four_stroke_turn_at_half_the_crank_angle():
    """Crank 100 deg + firing 540 deg = 640 crank deg -> 320 cam deg."""
    assert np.degrees(shaft.lobe_noses(np.radians(100.0), np.radians([540.0]), 4)) == pytest.approx([320.0])


def test_too_many_orders_are_refused():
    with pytest.raises(ValueError, match="orders = 8: allowed 0 ... 7"):
        shaft.harmonic_orders(np.zeros(16), 8)


def test_drive_torsional_stiffness_is_the_span_stiffness_at_the_pitch_radius():
    """A span of 2000 N/mm (2e6 N/m) at r_p = 60 mm: k r_p^2 = 2e6 x 0.0036 = 7200 N m/rad."""
    assert shaft.drive_torsional_stiffness(2.0e6, 0.06) == pytest.approx(7200.0, rel=1e-12)


def test_sprocket_on_the_drive_with_a_rigid_shaft_is_one_mass_on_the_drive_spring():
    """Ground -k_d- J_s =rigid shaft= J_1: the sprocket and the shaft turn as one, sqrt(k_d / (J_s + J_1)) (Den Hartog
    (1956)); k_d = 7200 N m/rad, J_s = 2.2e-3, J_1 = 1.0e-3 kg m^2: sqrt(7200 / 3.2e-3) = 1500 rad/s.  The shaft's
    spring 1e12 N m/rad stands for rigid (its own mode near sqrt(1e12 / 6.875e-4), far above)."""
    w = shaft.torsional_frequencies(*shaft.with_drive_end(np.array([1e12]), np.array([1.0e-3]), 7200.0, 2.2e-3))
    assert w.size == 2
    assert w[0] == pytest.approx(1500.0, rel=1e-6)


def test_sprocket_drive_and_an_elastic_shaft_against_the_two_mass_characteristic_equation():
    """Ground -k_d- J_s -k_1- J_1: det [[k_d + k_1 - w^2 J_s, -k_1], [-k_1, k_1 - w^2 J_1]] = 0, i.e.
    J_s J_1 w^4 - (J_s k_1 + J_1 (k_d + k_1)) w^2 + k_d k_1 = 0.  k_d = 7200, k_1 = 1.3e5 N m/rad, J_s = 2.2e-3,
    J_1 = 1.0e-3 kg m^2: b = 2.2e-3 x 1.3e5 + 1e-3 x 1.372e5 = 423.2, a = 2.2e-6, c = 9.36e8;
    w^2 = (b -+ sqrt(b^2 - 4 a c)) / (2 a) = (423.2 -+ sqrt(179098.24 - 8236.8)) / 4.4e-6 = (423.2 -+ 413.353892)
    / 4.4e-6 = 2.2377518e6 and 1.9012588e8 -> w = 1495.9117 and 13788.614 rad/s."""
    w = shaft.torsional_frequencies(*shaft.with_drive_end(np.array([1.3e5]), np.array([1.0e-3]), 7200.0, 2.2e-3))
    a, b, c = 2.2e-6, 2.2e-3 * 1.3e5 + 1.0e-3 * (7200.0 + 1.3e5), 7200.0 * 1.3e5
    roots = np.sqrt((b + np.array([-1.0, 1.0]) * np.sqrt(b * b - 4 * a * c)) / (2 * a))
    assert w == pytest.approx(roots, rel=1e-9)
    assert w == pytest.approx([1495.9117, 13788.614], rel=1e-7)


def test_three_masses_with_the_drive_against_numpys_eigenvalues_of_the_hand_written_matrices():
    """Ground -k_d- J_s -k_1- J_1 -k_2- J_2, the matrices written out by hand: K = [[k_d + k_1, -k_1, 0],
    [-k_1, k_1 + k_2, -k_2], [0, -k_2, k_2]], M = diag(J_s, J_1, J_2); w^2 are the eigenvalues of the symmetric
    M^-1/2 K M^-1/2 (numpy.linalg.eigvalsh, a solver independent of scipy's generalised eigh)."""
    kd, k1, k2 = 7200.0, 1.3e5, 9.0e4
    js, j1, j2 = 2.2e-3, 1.0e-3, 1.4e-3
    K = np.array([[kd + k1, -k1, 0.0], [-k1, k1 + k2, -k2], [0.0, -k2, k2]])
    s = 1.0 / np.sqrt([js, j1, j2])
    expected = np.sqrt(np.linalg.eigvalsh(s[:, None] * K * s[None, :]))
    w = shaft.torsional_frequencies(*shaft.with_drive_end(np.array([k1, k2]), np.array([j1, j2]), kd, js))
    assert w == pytest.approx(expected, rel=1e-10)


def test_an_infinitely_stiff_drive_holds_the_drive_end():
    """Limit: k_d = inf returns the shaft held at its drive end (the chain unchanged, the sprocket's inertia
    irrelevant); a drive 1e6 times stiffer than the shaft gives the held shaft's two frequencies to 1e-6 with its
    third, the sprocket's, far above (sqrt(1e10 / 5e-3) = 1.41e6 rad/s; Ground -k- J -k- J with k = 1e4, J = 1e-4: 6180.3399 and 16180.340 rad/s, as
    test_two_equal_grounded_masses_against_the_characteristic_equation)."""
    k, j = np.array([1e4, 1e4]), np.array([1e-4, 1e-4])
    held = shaft.torsional_frequencies(k, j)
    k_held, j_held = shaft.with_drive_end(k, j, np.inf, 5e-3)
    assert np.array_equal(k_held, k) and np.array_equal(j_held, j)
    stiff = shaft.torsional_frequencies(*shaft.with_drive_end(k, j, 1e10, 5e-3))
    assert stiff[:2] == pytest.approx(held, rel=1e-6)
    assert stiff[:2] == pytest.approx([6180.3399, 16180.340], rel=1e-6)
    assert stiff[2] > 50.0 * held[1]


def test_the_shaft_piece_before_the_first_station_goes_half_to_the_drive_end():
    """A station at position 0 (the drive end) takes half the piece 0-100 mm: uniform d 20 mm, rho 7850,
    rho J = 1.2330751e-4 kg m^2 per m: 0.05 m x 1.2330751e-4 = 6.1653755e-6 kg m^2; the stations keep their shares
    (as test_lumped_shaft_inertia_of_a_uniform_shaft)."""
    inertia = shaft.lumped_shaft_inertia(np.array([0.0, 0.1, 0.2]), [0.3], [0.02], [0.0], 7850.0)
    assert inertia == pytest.approx([6.1653755e-6, 1.2330751e-5, 1.8496127e-5], rel=1e-7)


KD, K1, JS, J1 = 7200.0, 1.3e5, 2.2e-3, 1.0e-3
"""The two-mass chain of the closed-form tests: ground -k_d- J_s -k_1- J_1 [N m/rad, kg m^2]."""


def two_mass_by_hand(omega, torque, zeta):
    """The steady twist (phi_s, phi_1) of ground -k_d- J_s -k_1- J_1 under a torque T exp(i W t) on J_1, by hand:
    the modes from the characteristic equation J_s J_1 w^4 - (J_s k_1 + J_1 (k_d + k_1)) w^2 + k_d k_1 = 0, the shape
    of mode j phi_1 / phi_s = (k_d + k_1 - w_j^2 J_s) / k_1 from the first row of (K - w^2 M) u = 0, scaled to
    u^T M u = 1; the damping matrix C = M U diag(2 zeta w_j) U^T M; and the 2 x 2 complex system
    (K - W^2 M + i W C) phi = (0, T) solved by Cramer's rule."""
    a, b, c = JS * J1, JS * K1 + J1 * (KD + K1), KD * K1
    w2 = (b + np.array([-1.0, 1.0]) * np.sqrt(b * b - 4 * a * c)) / (2 * a)
    ratio = (KD + K1 - w2 * JS) / K1
    u = np.vstack([np.ones(2), ratio]) / np.sqrt(JS + J1 * ratio**2)
    m = np.diag([JS, J1])
    damping = m @ u @ np.diag(2.0 * zeta * np.sqrt(w2)) @ u.T @ m
    z = np.array([[KD + K1, -K1], [-K1, K1]]) - omega**2 * m + 1j * omega * damping
    det = z[0, 0] * z[1, 1] - z[0, 1] * z[1, 0]
    return np.array([-z[0, 1] * torque, z[0, 0] * torque]) / det, np.sqrt(w2)


@pytest.mark.parametrize("omega, zeta", [(300.0, 0.0), (1400.0, 0.0), (5000.0, 0.0), (300.0, 0.05),
                                         (1400.0, 0.05), (1495.9117, 0.05), (5000.0, 0.05), (13788.614, 0.05)])
def test_the_forced_response_of_two_masses_is_the_closed_form(omega, zeta):
    """Modal superposition against the closed form of the damped two-mass torsional system (two_mass_by_hand):
    its natural frequencies 1495.9117 and 13788.614 rad/s (test_sprocket_drive_and_an_elastic_shaft_...) and the
    steady amplitude under 10 N m on the far mass, undamped (Cramer's rule on K - W^2 M; no steady amplitude at
    its resonances) and with 5 % modal damping, below, at and above both resonances, to 1e-9."""
    expected, w = two_mass_by_hand(omega, 10.0, zeta)
    modes, shapes = shaft.torsional_modes(*shaft.with_drive_end(np.array([K1]), np.array([J1]), KD, JS))
    assert modes == pytest.approx(w, rel=1e-12)
    phi = shaft.forced_response(modes, shapes, zeta, np.array([0.0, 10.0 + 0j]), np.array(omega))
    assert phi == pytest.approx(expected, rel=1e-9)


def test_at_resonance_the_damped_amplitude_is_the_static_one_over_two_zeta_of_its_mode():
    """A torque in the shape of mode 1 (T = M u_1 t) drives mode 1 alone: at W = w_1 its amplitude is the static
    u_1 t / w_1^2 over 2 zeta, with the phase -90 deg (Den Hartog (1956), the single-degree system's resonance)."""
    modes, shapes = shaft.torsional_modes(*shaft.with_drive_end(np.array([K1]), np.array([J1]), KD, JS))
    torque = np.diag([JS, J1]) @ shapes[:, 0] * 3.0
    phi = shaft.forced_response(modes, shapes, 0.02, torque.astype(complex), np.array(modes[0]))
    assert phi == pytest.approx(-1j * shapes[:, 0] * 3.0 / modes[0] ** 2 / (2 * 0.02), rel=1e-10)


def test_a_steady_torque_twists_the_shaft_as_its_flexibility_matrix():
    """W = 0: modal superposition gives K^-1 T, here against the flexibility of the shaft held at its drive end,
    phi_i = sum_j min(c_i, c_j) T_j (:func:`valvetrain.camshaft.twist`, a formula of its own): three stations of a
    stepped shaft."""
    compliance = shaft.shaft_compliance(np.array([0.065, 0.155, 0.245]), np.array([0.02, 0.38]),
                                        np.array([0.025, 0.032]), np.zeros(2), 8.1e10)
    torque = np.array([3.0, -1.5, 2.25])
    modes, shapes = shaft.torsional_modes(shaft.station_stiffness(compliance), np.array([1e-4, 2e-4, 3e-4]))
    phi = shaft.forced_response(modes, shapes, 0.05, torque.astype(complex), np.array(0.0))
    assert phi.real == pytest.approx(shaft.twist(compliance, torque[:, None])[:, 0], rel=1e-10)
    assert np.abs(phi.imag).max() == 0.0


def test_orders_round_trip():
    """order_series undoes order_phasors for a signal of orders below the cut, at any length above twice it."""
    x = 0.7 + np.cos(PSI) * 2.0 - 0.3 * np.sin(7 * PSI) + 0.05 * np.cos(12 * PSI + 0.4)
    c = shaft.order_phasors(x, 20)
    assert shaft.order_series(c, N) == pytest.approx(x, abs=1e-12)
    assert shaft.order_series(c, 72) == pytest.approx(x[:: N // 72], abs=1e-12)
    with pytest.raises(ValueError, match="more than 40 samples"):
        shaft.order_series(c, 40)
