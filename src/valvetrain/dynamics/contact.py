"""Cam-follower contact under the dynamic force: Hertz stress and the lubrication characteristic.

Shang Hanji (1988), section 3.4, computes the contact stress (2.5) with the force of the elastic train
instead of the kinetostatic one; the curvature comes from the law's profile (2.6)/(2.7) and the
lubrication characteristic gamma = rho / (R0 + h) from (2.12).  The formulas live in
:mod:`valvetrain.followers`; this module only feeds them the
simulated force.
"""

import numpy as np

from ..followers import FLAT


def dynamic_contact_stress(law, theta, force, base_radius, width, modulus, follower=FLAT) -> np.ndarray:
    """Hertz stress between cam and follower under the dynamic contact force [Pa].

    Parameters
    ----------
    law : valvetrain.laws.base.LiftLaw
    theta : ndarray (n,)
        Camshaft angle [rad from the nose].
    force : ndarray (..., n)
        Contact force at the cam [N] (e.g. ``SweepResult.contact_force``, one row per speed).
    base_radius, width : float
        Heel-circle radius and cam width [m].
    modulus : float
        Effective modulus E_m [Pa] (:func:`valvetrain.strength.effective_modulus`).
    follower : valvetrain.followers.Follower
        The follower (default flat: 1/rho_2 = 0, eq. 2.11).

    Notes
    -----
    .. math:: \\sigma = 0.418\\sqrt{\\frac{F E_m}{b}\\left(\\frac1{\\rho_1} + \\frac1{\\rho_2}\\right)}

    References
    ----------
    Shang Hanji (1988), eqs. (2.5), (2.11) and section 3.4 (the force of the dynamic calculation).
    """
    return follower.contact_stress(force, law.curvature(theta, base_radius, follower), width, modulus)


def lubrication_characteristic(law, theta, base_radius, follower=FLAT) -> np.ndarray:
    """gamma = rho / (R0 + h), the hydrodynamic lubrication characteristic of a flat follower; None for a follower
    without one (:meth:`valvetrain.followers.Follower.lubrication`).

    Parameters
    ----------
    law : valvetrain.laws.base.LiftLaw
    theta : ndarray
        Camshaft angle [rad from the nose].
    base_radius : float
        Heel-circle radius [m].
    follower : valvetrain.followers.Follower
        Default flat.

    Notes
    -----
    Eq. (2.12) gives h_min = k (R0 + h) sqrt(2 gamma^2 - gamma), zero at gamma = 0 and 0.5 (imaginary
    between as printed, corrections note 34), so only gamma is returned: the film is poor near
    gamma = 0.5, and 0.15-0.25 is recommended on the nose; on the base circle rho = R0 and gamma = 1.  The
    force does not enter (2.12); the dynamic force enters the stress of :func:`dynamic_contact_stress`.

    References
    ----------
    Shang Hanji (1988), eq. (2.12) (corrections note 34).
    """
    return follower.lubrication(base_radius, law.lift(theta), law.curvature(theta, base_radius, follower))
