"""The whole camshaft: drive torque of every lobe, its harmonic orders, torsion, torsional natural frequencies,
bending at the lobes and the load on the timing drive.

SI units: m, rad, N, N m, Pa, kg m^2.  Angles: ``psi`` is the **camshaft** angle [rad] from cylinder 1's
gas-exchange TDC (crank angle 0 is camshaft angle 0); a lobe's own angle ``theta`` is the camshaft angle from its
nose, as the lift laws take it.  A crank angle ``phi`` is ``psi / r`` with ``r`` (:func:`camshaft_ratio`) the
camshaft's revolutions per crank revolution.  The drive end of the shaft (sprocket, pulley or gear) is at axial
position 0.
"""

import numpy as np
from scipy.linalg import eigh

from .errors import InputError
from .strength import camshaft_deflection


def camshaft_ratio(strokes) -> float:
    """Camshaft revolutions per crank revolution: 1/2 for a four-stroke, 1 for a two-stroke.

    >>> camshaft_ratio(4), camshaft_ratio(2)
    (0.5, 1.0)
    """
    return 2.0 / strokes


def lobe_noses(nose_crank, firing, strokes) -> np.ndarray:
    """Camshaft angles of the noses of one valve's lobes on every cylinder [rad, in [0, 2 pi)].

    Parameters
    ----------
    nose_crank : float
        Crank angle of the valve's nose from its own cylinder's gas-exchange TDC [rad].
    firing : ndarray (C,)
        Crank angle at which each cylinder fires after cylinder 1 [rad].
    strokes : int
        2 or 4.

    Notes
    -----
    psi_c = r (phi_nose + phi_fire,c) mod 2 pi, r = 2 / tau: a cylinder's whole cycle is its firing angle later
    than cylinder 1's, and the camshaft turns r times the crank's angle.

    >>> [round(float(np.degrees(a)), 9) for a in lobe_noses(np.radians(100.0), np.radians([0, 180, 540, 360]), 4)]
    [50.0, 140.0, 320.0, 230.0]
    """
    return np.mod(camshaft_ratio(strokes) * (nose_crank + np.asarray(firing, dtype=float)), 2.0 * np.pi)


def wrap(angle) -> np.ndarray:
    """An angle [rad] wrapped into [-pi, pi)."""
    return np.mod(np.asarray(angle, dtype=float) + np.pi, 2.0 * np.pi) - np.pi


def lobe_torques(psi, theta, torque, noses) -> np.ndarray:
    """Drive torque of lobes of one kind at camshaft angles ``psi`` [N m], shape (L, n).

    Parameters
    ----------
    psi : ndarray (n,)
        Camshaft angles [rad].
    theta : ndarray (m,)
        The lobe's own angles [rad from the nose], increasing, within [-pi, pi].
    torque : ndarray (m,)
        The lobe's drive torque at ``theta`` [N m]; zero outside ``theta`` (the base circle lifts nothing).
    noses : ndarray (L,)
        Camshaft angle of each lobe's nose [rad].

    Notes
    -----
    T_l(psi) = T(wrap(psi - psi_l)): every lobe of the kind runs the same torque, its nose psi_l later.
    """
    local = wrap(np.asarray(psi, dtype=float)[None, :] - np.asarray(noses, dtype=float)[:, None])
    return np.interp(local, theta, torque, left=0.0, right=0.0)


def torque_figures(torque) -> dict[str, float]:
    """Peak, lowest, mean and fluctuating torque of a camshaft revolution sampled evenly [N m].

    Returns
    -------
    dict
        ``peak``, ``lowest``, ``mean``, ``fluctuation`` (peak - lowest) and ``rms_fluctuation``
        (sqrt(mean((T - T_mean)^2))).

    >>> f = torque_figures(np.array([1.0, 3.0, 1.0, -1.0]))
    >>> f["peak"], f["lowest"], f["mean"], f["fluctuation"], f["rms_fluctuation"]
    (3.0, -1.0, 1.0, 4.0, 1.4142135623730951)
    """
    t = np.asarray(torque, dtype=float)
    mean = float(t.mean())
    return {"peak": float(t.max()), "lowest": float(t.min()), "mean": mean, "fluctuation": float(t.max() - t.min()),
            "rms_fluctuation": float(np.sqrt(np.mean((t - mean) ** 2)))}


def order_phasors(values, orders) -> np.ndarray:
    """Complex amplitudes of the orders of the camshaft speed in a quantity sampled evenly over one camshaft revolution.

    Parameters
    ----------
    values : ndarray (..., n)
        At psi_j = 2 pi j / n, j = 0 ... n - 1, along the last axis (a torque [N m], a twist [rad]).
    orders : int
        Orders 0 ... orders (< n / 2).

    Returns
    -------
    ndarray (..., orders + 1) of complex
        c_k with values(psi) = Re sum_k c_k exp(i k psi): c_0 = C_0, c_k = 2 C_k (k >= 1), C_k = (1/n) sum_j
        values_j exp(-2 pi i j k / n), the discrete Fourier transform (numpy's rfft).

    >>> psi = 2 * np.pi * np.arange(8) / 8
    >>> [(round(float(c.real), 12) + 0.0, round(float(c.imag), 12) + 0.0)
    ...  for c in order_phasors(1.0 + 3.0 * np.cos(2 * psi) + 0.5 * np.sin(psi), 3)]
    [(1.0, 0.0), (0.0, -0.5), (3.0, 0.0), (0.0, 0.0)]
    """
    t = np.asarray(values, dtype=float)
    n = t.shape[-1]
    if not 0 <= orders < n / 2:
        raise InputError(f"orders = {orders}: allowed 0 ... {(n - 1) // 2} for {n} samples")
    c = np.fft.rfft(t, axis=-1)[..., : orders + 1] / n
    c[..., 1:] *= 2.0
    return c


def order_series(phasors, n) -> np.ndarray:
    """The values at psi_j = 2 pi j / n of Re sum_k c_k exp(i k psi), the orders' phasors ``phasors`` (..., K) summed
    (the inverse of :func:`order_phasors`; n > 2 (K - 1)), (..., n).

    >>> psi = 2 * np.pi * np.arange(8) / 8
    >>> x = 1.0 + 2.0 * np.cos(psi) - np.sin(3 * psi)
    >>> bool(np.allclose(order_series(order_phasors(x, 3), 8), x, rtol=0.0, atol=1e-12))
    True
    """
    c = np.asarray(phasors, dtype=complex)
    if n <= 2 * (c.shape[-1] - 1):
        raise InputError(f"n = {n}: more than {2 * (c.shape[-1] - 1)} samples are needed for {c.shape[-1] - 1} orders")
    spectrum = np.zeros(c.shape[:-1] + (n // 2 + 1,), dtype=complex)
    spectrum[..., : c.shape[-1]] = c * n / 2.0
    spectrum[..., 0] = c[..., 0] * n
    return np.fft.irfft(spectrum, n, axis=-1)


def harmonic_orders(torque, orders) -> np.ndarray:
    """Amplitudes of the orders of the camshaft speed in a torque sampled evenly over one camshaft revolution [N m].

    Parameters
    ----------
    torque : ndarray (n,)
        At psi_j = 2 pi j / n, j = 0 ... n - 1 [N m].
    orders : int
        Orders 0 ... orders (< n / 2).

    Notes
    -----
    T(psi) = A_0 + sum_k A_k cos(k psi + alpha_k); A_k = |c_k| of :func:`order_phasors`.

    >>> psi = 2 * np.pi * np.arange(64) / 64
    >>> np.round(harmonic_orders(1.0 + 3.0 * np.cos(2 * psi) + 0.5 * np.sin(5 * psi), 6), 12).tolist()
    [1.0, 0.0, 3.0, 0.0, 0.0, 0.5, 0.0]
    """
    return np.abs(order_phasors(torque, orders))


def polar_moment(diameter, bore=0.0) -> np.ndarray:
    """Polar second moment of area of a round (hollow) shaft J = pi (d^4 - delta^4) / 32 [m^4]."""
    return np.pi * (np.asarray(diameter, dtype=float) ** 4 - np.asarray(bore, dtype=float) ** 4) / 32.0


def piecewise_integral(x, lengths, values) -> np.ndarray:
    """Integral from the drive end to positions ``x`` of a quantity constant on each shaft section.

    Parameters
    ----------
    x : ndarray
        Axial positions from the drive end [m], within the shaft.
    lengths : ndarray (S,)
        Section lengths from the drive end [m].
    values : ndarray (S,)
        The quantity on each section (per m).

    >>> float(piecewise_integral(0.25, [0.1, 0.2], [1.0, 10.0]))
    1.6
    """
    ends = np.concatenate([[0.0], np.cumsum(lengths)])
    x = np.asarray(x, dtype=float)
    inside = np.clip(x[..., None] - ends[:-1], 0.0, np.asarray(lengths, dtype=float))
    return np.sum(inside * np.asarray(values, dtype=float), axis=-1)


def shaft_compliance(x, lengths, diameters, bores, shear_modulus) -> np.ndarray:
    """Torsional compliance of the shaft from the drive end to positions ``x`` [rad / (N m)].

    Parameters
    ----------
    x : ndarray
        Axial positions from the drive end [m].
    lengths, diameters, bores : ndarray (S,)
        Sections from the drive end [m] (bore 0: solid).
    shear_modulus : float
        G [Pa].

    Notes
    -----
    Sections in series: c(x) = sum_s l_s(x) / (G J_s), l_s(x) the part of section s between the drive end and x;
    the twist of a section under a torque T is T l / (G J).

    References
    ----------
    Shigley's Mechanical Engineering Design, 9th ed. (2011), chapter 3 (the angle of twist of a round bar in torsion).
    """
    return piecewise_integral(x, lengths, 1.0 / (shear_modulus * polar_moment(diameters, bores)))


def flexibility(compliance) -> np.ndarray:
    """Flexibility matrix of stations on a shaft held at its drive end [rad / (N m)], (L, L).

    Parameters
    ----------
    compliance : ndarray (L,)
        Compliance from the drive end to each station, :func:`shaft_compliance`.

    Notes
    -----
    A torque T_j at station j twists every station i by c(min(x_i, x_j)) T_j: the shaft between the drive end and
    station j carries T_j, beyond it nothing.  F_ij = min(c_i, c_j) (c grows along the shaft).
    """
    c = np.asarray(compliance, dtype=float)
    return np.minimum(c[:, None], c[None, :])


def twist(compliance, station_torques) -> np.ndarray:
    """Quasi-static twist of each station behind the drive end [rad] (positive: the station lags), (L, n).

    Parameters
    ----------
    compliance : ndarray (L,)
        Compliance from the drive end to each station [rad / (N m)].
    station_torques : ndarray (L, n)
        Drive torque of each station's lobes at each camshaft angle [N m].

    Notes
    -----
    phi_i = sum_j min(c_i, c_j) T_j (:func:`flexibility`); the shaft's inertia is left out (quasi-static).  A
    compliant timing drive carries the torque of every station: its compliance 1 / k_t
    (:func:`drive_torsional_stiffness`) added to every c_i gives the lag behind the crankshaft.
    """
    return flexibility(compliance) @ np.asarray(station_torques, dtype=float)


def chain_stiffness(stiffness, grounded=True) -> np.ndarray:
    """Stiffness matrix of a chain of masses joined by torsion springs [N m / rad], (L, L).

    Parameters
    ----------
    stiffness : ndarray (L,) or (L - 1,)
        Grounded: k_1 joins mass 1 to the ground (the drive end), k_i masses i - 1 and i.  Free: k_i joins masses
        i and i + 1.
    grounded : bool
    """
    k = np.asarray(stiffness, dtype=float)
    n = k.size if grounded else k.size + 1
    links = [(-1, 0, k[0])] + [(i - 1, i, k[i]) for i in range(1, n)] if grounded else \
        [(i, i + 1, k[i]) for i in range(n - 1)]
    matrix = np.zeros((n, n))
    for a, b, kk in links:
        matrix[b, b] += kk
        if a >= 0:
            matrix[a, a] += kk
            matrix[a, b] -= kk
            matrix[b, a] -= kk
    return matrix


def torsional_modes(stiffness, inertias, grounded=True) -> tuple[np.ndarray, np.ndarray]:
    """Natural angular frequencies [rad/s, lowest first] and mass-normalised mode shapes of a chain of torsion springs
    and masses.

    Parameters
    ----------
    stiffness : ndarray
        Spring rates [N m / rad], :func:`chain_stiffness`.
    inertias : ndarray (L,)
        Mass moments of inertia [kg m^2].
    grounded : bool
        The first spring holds the chain to the ground (the drive end); a free chain's rigid-body mode (0) is left
        out.

    Returns
    -------
    omega : ndarray (m,)
    shapes : ndarray (L, m)
        Column j the twist of every mass in mode j, scaled so that u_j^T J u_j = 1 [1 / sqrt(kg m^2)].

    Notes
    -----
    det(K - omega^2 J) = 0, the generalised symmetric eigenproblem (scipy.linalg.eigh, whose eigenvectors are
    J-orthonormal).  One grounded mass: omega = sqrt(k / J); two free masses: omega = sqrt(k (J_1 + J_2) / (J_1 J_2)).

    References
    ----------
    Den Hartog (1956), chapter 5 (torsional vibration of multi-mass shafts).
    """
    values, shapes = eigh(chain_stiffness(stiffness, grounded), np.diag(np.asarray(inertias, dtype=float)))
    order = np.argsort(values)
    values, shapes = values[order], shapes[:, order]
    if not grounded:
        values, shapes = values[1:], shapes[:, 1:]
    return np.sqrt(np.clip(values, 0.0, None)), shapes


def torsional_frequencies(stiffness, inertias, grounded=True) -> np.ndarray:
    """Natural angular frequencies of a chain of torsion springs and masses [rad/s], lowest first
    (:func:`torsional_modes`).

    >>> round(float(torsional_frequencies([400.0], [4.0])[0]), 12)
    10.0
    """
    return torsional_modes(stiffness, inertias, grounded)[0]


def forced_response(omega, shapes, damping_ratio, torques, frequency) -> np.ndarray:
    """Steady twist of a grounded torsional chain under harmonic torques, by modal superposition [rad, complex].

    Parameters
    ----------
    omega, shapes : ndarray (m,), (L, m)
        :func:`torsional_modes` of the chain (every mode, omega > 0).
    damping_ratio : float
        zeta of every mode (modal damping: its share of the critical damping 2 omega_j of the mass-normalised mode).
    torques : ndarray (..., L) of complex
        Phasors of the torque on each mass [N m], T(t) = Re(T exp(i Omega t)).
    frequency : ndarray (...)
        Omega of each set of torques [rad/s] (0: a steady torque).

    Returns
    -------
    ndarray (..., L) of complex
        The twist phasors phi, phi(t) = Re(phi exp(i Omega t)), positive where the torque's sense.

    Notes
    -----
    J phi'' + C phi' + K phi = T with U^T C U = diag(2 zeta omega_j), U the mass-normalised shapes:

    .. math:: \\boldsymbol\\phi = \\sum_j \\frac{\\mathbf u_j\\,\\mathbf u_j^T\\mathbf T}
              {\\omega_j^2 - \\Omega^2 + 2 i \\zeta \\omega_j \\Omega}

    At Omega = 0 it is K^-1 T, the quasi-static twist (:func:`twist`).

    References
    ----------
    Den Hartog (1956), chapters 2 and 5 (the forced vibration of a damped system, the normal modes of a shaft).

    >>> w, u = torsional_modes([400.0], [4.0])
    >>> complex(np.round(forced_response(w, u, 0.05, np.array([2.0 + 0j]), np.array(10.0))[0], 12))
    -0.05j
    """
    omega = np.asarray(omega, dtype=float)
    big = np.asarray(frequency, dtype=float)[..., None]
    modal = (np.asarray(torques, dtype=complex) @ shapes) / (omega**2 - big**2 + 2j * damping_ratio * omega * big)
    return modal @ shapes.T


def station_stiffness(compliance) -> np.ndarray:
    """Spring rates between the drive end and the first station and between successive stations [N m / rad].

    The compliances of the pieces between the stations, inverted: k_i = 1 / (c_i - c_(i-1)), c_0 = 0.
    """
    return 1.0 / np.diff(np.concatenate([[0.0], np.asarray(compliance, dtype=float)]))


def drive_torsional_stiffness(span_stiffness, pitch_radius) -> float:
    """Torsional stiffness of the timing drive at the camshaft [N m / rad]: k_t = k r_p^2.

    Parameters
    ----------
    span_stiffness : float
        Tangential stiffness of the drive at the pitch radius [N/m]: the tight span of the chain or belt (its force
        per unit strain over the span's length) or the gear mesh; ``inf``: a rigid drive.
    pitch_radius : float
        Pitch radius of the camshaft's sprocket, pulley or gear r_p [m].

    Notes
    -----
    A turn delta of the sprocket against the crankshaft's stretches the span by r_p delta, which pulls with
    k r_p delta at the arm r_p.

    >>> drive_torsional_stiffness(8.0e5, 0.25)
    50000.0
    """
    return span_stiffness * pitch_radius**2


def with_drive_end(stiffness, inertias, drive_stiffness, sprocket_inertia) -> tuple[np.ndarray, np.ndarray]:
    """The grounded chain of :func:`torsional_frequencies` with the timing drive at its head [N m / rad], [kg m^2].

    Parameters
    ----------
    stiffness : ndarray (L,)
        Spring rates of the shaft held at its drive end, :func:`station_stiffness`.
    inertias : ndarray (L,)
        Inertias of the stations [kg m^2].
    drive_stiffness : float
        Torsional stiffness of the timing drive [N m / rad], :func:`drive_torsional_stiffness`; ``inf``: the drive end
        held (the chain returned as given).
    sprocket_inertia : float
        Inertia at the drive end [kg m^2], > 0: the sprocket, pulley or gear with its share of the shaft.

    Returns
    -------
    stiffness, inertias : ndarray
        The ground (the crankshaft, turning evenly) -k_d- J_s -k_1- J_1 ...

    Notes
    -----
    The crankshaft's inertia is far larger than the camshaft's: it is taken as turning evenly, the drive's far end
    held.

    >>> k, j = with_drive_end(np.array([4.0, 2.0]), np.array([1.0, 1.0]), 3.0, 0.5)
    >>> k.tolist(), j.tolist()
    ([3.0, 4.0, 2.0], [0.5, 1.0, 1.0])
    """
    stiffness, inertias = np.asarray(stiffness, dtype=float), np.asarray(inertias, dtype=float)
    if np.isinf(drive_stiffness):
        return stiffness, inertias
    return np.concatenate([[drive_stiffness], stiffness]), np.concatenate([[sprocket_inertia], inertias])


def lumped_shaft_inertia(positions, lengths, diameters, bores, density) -> np.ndarray:
    """The shaft's own polar mass inertia lumped at stations [kg m^2], (L,).

    Parameters
    ----------
    positions : ndarray (L,)
        Stations from the drive end [m], increasing.
    lengths, diameters, bores : ndarray (S,)
        Sections [m].
    density : float
        [kg/m^3].

    Notes
    -----
    The piece between two stations (rho int J dx) goes half to each; the piece before the first station half to it
    (the other half to the drive end: a station at position 0 receives it), the piece beyond the last station wholly
    to it.
    """
    ends = np.concatenate([[0.0], np.asarray(positions, dtype=float), [float(np.sum(lengths))]])
    pieces = np.diff(density * piecewise_integral(ends, lengths, polar_moment(diameters, bores)))
    inertia = (pieces[:-1] + pieces[1:]) / 2.0
    inertia[-1] += pieces[-1] / 2.0
    return inertia


def resonance_speeds(natural_frequency, orders, ratio) -> np.ndarray:
    """Engine speeds at which orders of the camshaft speed excite a natural frequency [rad/s].

    Notes
    -----
    k omega_cam = omega_n with omega_cam = r n: n_k = omega_n / (k r).

    >>> round(float(resonance_speeds(1000.0, np.array([4]), 0.5)[0]), 12)
    500.0
    """
    return natural_frequency / (np.asarray(orders, dtype=float) * ratio)


def section_at(x, lengths) -> np.ndarray:
    """Index of the shaft section at axial positions ``x`` [m] (the last one at the far end)."""
    ends = np.cumsum(lengths)
    return np.minimum(np.searchsorted(ends, np.asarray(x, dtype=float), side="right"), len(ends) - 1)


def lobe_deflection(force, x, journals, diameter, bore, modulus) -> np.ndarray:
    """Bending deflection of the shaft at lobes under their cam force, each between its two journals [m].

    Parameters
    ----------
    force : ndarray (L,)
        Largest cam force of each lobe station [N].
    x : ndarray (L,)
        Lobe positions from the drive end [m], between the first and the last journal.
    journals : ndarray (B,)
        Journal (bearing) positions [m], increasing.
    diameter, bore : ndarray (L,)
        The shaft's outer and inner diameter at each lobe [m].
    modulus : float
        Young's modulus [Pa].

    Notes
    -----
    Each lobe on a simply supported span between the journals either side of it, loaded alone:
    f = P a^2 b^2 / (3 E I l), a, b its distances from the journals, l = a + b, I = pi (d^4 - delta^4) / 64
    (:func:`valvetrain.strength.camshaft_deflection`).  Shaft continuity over the journals stiffens it: this is the
    larger (safe-side) value.

    References
    ----------
    Shigley's Mechanical Engineering Design, 9th ed. (2011), table A-9, case 6 (simple supports, intermediate load);
    Valve-train practical works (n.d.), work 7, eq. (7.3).
    """
    j = np.asarray(journals, dtype=float)
    x = np.asarray(x, dtype=float)
    right = np.clip(np.searchsorted(j, x, side="right"), 1, j.size - 1)
    a, b = x - j[right - 1], j[right] - x
    return camshaft_deflection(np.asarray(force, dtype=float), a, b, np.asarray(diameter, dtype=float),
                               np.asarray(bore, dtype=float), modulus)


def drive_force(torque, pitch_radius) -> np.ndarray:
    """Tangential force of the timing drive at the camshaft's sprocket, pulley or gear [N]: F = T / r_p.

    The force the belt's or chain's tight side (or the gear mesh) carries above its preload to turn the camshaft
    against the torque T [N m] at the pitch radius r_p [m].
    """
    return np.asarray(torque, dtype=float) / pitch_radius
