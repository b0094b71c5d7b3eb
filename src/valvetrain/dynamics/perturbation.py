"""Perturbation view of the one-mass train (Shang Hanji (1988), section 3.3).

With the valve open the one-mass equation divided by c + K reads epsilon y'' + y = G in the
camshaft angle, with the quasi-static lift G = (c u - F0)/(c + K), u = k h - x0, and the
perturbation parameter epsilon = M omega^2 / (c + K).  Its outer (asymptotic) solution is
y = G - epsilon G'' + epsilon^2 G'''' - ...  The lift laws give h up to h''', so the outer
solution here is taken to first order, y = G - epsilon G''; a higher order needs the even
derivatives of G from elsewhere (:func:`outer_solution` sums any given list).
"""

import numpy as np


def perturbation_parameter(mass, stiffness, spring_rate, cam_speed) -> float | np.ndarray:
    """epsilon = M omega^2 / (c + K), dimensionless.

    Parameters
    ----------
    mass : float
        M reduced to the valve [kg].
    stiffness, spring_rate : float
        Drive stiffness c and spring rate K at the valve [N/m].
    cam_speed : float or ndarray
        Camshaft speed omega [rad/s].

    Notes
    -----
    Equal to (omega / omega_n)^2 with omega_n = sqrt((c + K)/M).  Shang Hanji (1988) prints M omega^3 / c, which is not
    dimensionless (corrections note 30); with K << c the corrected form is Shang's M omega^2 / c.

    References
    ----------
    Shang Hanji (1988), chapter 1 and section 3.3 (corrected: corrections note 30).

    Examples
    --------
    A worked example (M = 0.25 kg, c = 15000 N/mm, K = 67.5 N/mm) at 3000 cam rpm: 0.00164.

    >>> round(float(perturbation_parameter(0.25, 15e6, 67.5e3, 3000 * np.pi / 30)), 5)
    0.00164
    """
    return mass * np.asarray(cam_speed, dtype=float) ** 2 / (stiffness + spring_rate)


def quasi_static_lift(cam_lift, train) -> np.ndarray:
    """G = (c (k h - x0) - F0) / (c + K) and its angle derivatives [m, m/rad^n].

    Parameters
    ----------
    cam_lift : ndarray (m, n)
        Tappet lift h and its first m - 1 derivatives with respect to the camshaft angle (``law.derivatives``).
    train : OneMassTrain
        c, K, F0, k and x0.

    Returns
    -------
    ndarray (m, n)
        G and its derivatives (the derivatives are c k h^(j) / (c + K)).  G is the valve lift of the stiff,
        slow limit: the drive deflection (F0 + K y)/c subtracted from the rigid lift.

    References
    ----------
    Shang Hanji (1988), section 3.3 (perturbation method).
    """
    cam_lift = np.asarray(cam_lift, dtype=float)
    scale = train.stiffness * train.rocker_ratio / (train.stiffness + train.spring_rate)
    g = scale * cam_lift
    g[0] -= (train.stiffness * train.lash + train.preload) / (train.stiffness + train.spring_rate)
    return g


def outer_solution(even_derivatives, epsilon) -> np.ndarray:
    """Outer solution y = sum_j (-epsilon)^j G^(2j) [m].

    Parameters
    ----------
    even_derivatives : sequence of ndarray
        G, G'', G'''', ... with respect to the camshaft angle [m, m/rad^2, ...].
    epsilon : float
        Perturbation parameter.

    Notes
    -----
    The series is asymptotic, not convergent; a jump of G^(j) excites a free vibration of order
    epsilon^(j/2) that the outer solution does not contain.

    References
    ----------
    Shang Hanji (1988), section 3.3.

    Examples
    --------
    G = cos(2 theta) solves epsilon y'' + y = G with y = G / (1 - 4 epsilon) = G (1 + 4 eps + 16 eps^2 + ...);
    two terms give 1 + 4 eps:

    >>> float(outer_solution([np.array(1.0), np.array(-4.0)], 0.01))
    1.04
    """
    return sum((-epsilon) ** j * np.asarray(g, dtype=float) for j, g in enumerate(even_derivatives))


def outer_lift(law, train, theta, cam_speed) -> np.ndarray:
    """First-order outer solution of a train on a law, G - epsilon G'', clipped at the seat [m].

    Parameters
    ----------
    law : valvetrain.laws.base.LiftLaw
    train : OneMassTrain
    theta : ndarray
        Camshaft angle [rad from the nose].
    cam_speed : float
        [rad/s].
    """
    g = quasi_static_lift(law.derivatives(theta)[:3], train)
    eps = perturbation_parameter(train.mass, train.stiffness, train.spring_rate, cam_speed)
    return np.maximum(outer_solution([g[0], g[2]], eps), 0.0)


def kinetostatic_force(law, train, theta, cam_speed) -> np.ndarray:
    """Kinetostatic cam contact force at the valve, F0 + K G + M omega^2 G'' where G > 0, else nan [N].

    The rigid-train criterion (jump when negative) written with the quasi-static lift G,
    which includes the drive's deflection; multiply by the rocker ratio for the force at the cam.

    References
    ----------
    Shang Hanji (1988), sections 3.1 and 3.3 (the cam contact force of the rigid train).
    """
    g = quasi_static_lift(law.derivatives(theta)[:3], train)
    force = train.preload + train.spring_rate * g[0] + train.mass * cam_speed**2 * g[2]
    return np.where(g[0] > 0.0, force, np.nan)
