"""A finger follower's linkage built by hand from its dimensions, the independent reference of the tests of the
stages that take its variable ratio (the camshaft's torque and inertia, the optimiser's cam force): points by
rotation matrices written out here, angles by scipy's brentq, no method of valvetrain.followers.finger."""

from types import SimpleNamespace

import numpy as np
from scipy.optimize import brentq


def cross(u, w):
    """The z component of u x w of two plane vectors."""
    return u[0] * w[1] - u[1] * w[0]


def hand_finger(cam):
    """The finger of a law stage's cam (its dimensions only, SI) as a hand-built linkage: the roller centre C(psi),
    the valve pad's contact X(psi) = B + rho_p a with B = P + R(psi) (L_p, d_p), the valve axis a, the finger angle on
    the heel circle (|C| = R0 + R_r by brentq within +-0.5 rad of the pivot-to-roller line along +x, as the shipped
    finger lies) and psi at a valve lift (brentq on the tip's rise (X - X_0) . a)."""
    f = cam.follower_model
    pivot = np.array([f.pivot_x, f.pivot_y])
    a = np.array([np.sin(f.valve_angle), np.cos(f.valve_angle)])

    def turn(w, angle):
        return np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]) @ w

    def centre(psi):
        return pivot + turn(np.array([f.roller_arm, 0.0]), psi)

    def pad(psi):
        return pivot + turn(np.array([f.pad_arm, f.pad_drop]), psi) + f.pad_radius * a

    psi0 = brentq(lambda p: np.hypot(*centre(p)) - (cam.heel_radius + f.radius), -0.5, 0.5, xtol=1e-15, rtol=1e-15)

    def angle(v):
        return brentq(lambda p: (pad(p) - pad(psi0)) @ a - v, psi0 - 0.6, psi0 + 0.6, xtol=1e-15, rtol=1e-15)

    return SimpleNamespace(pivot=pivot, a=a, centre=centre, pad=pad, psi0=psi0, angle=angle, turn=turn)
