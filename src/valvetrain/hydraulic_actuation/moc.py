"""One-dimensional transient pipe flow by the method of characteristics, with friction.

The pipe equations p_t + rho a^2 u_x = 0 and u_t + p_x / rho + lambda u|u| / (2 d) = 0 are integrated
along the characteristics C+ and C- (dx/dt = +a, -a) on a grid of N reaches with dx = a dt (Courant number
one, so that a frictionless pipe is solved without numerical error):

    C+:  p_P + rho a u_P = p_A + rho a u_A - rho a dt lambda u_A |u_A| / (2 d)
    C-:  p_P - rho a u_P = p_B - rho a u_B + rho a dt lambda u_B |u_B| / (2 d)

where A and B are the neighbouring nodes at the previous time step (friction taken there, first order).
Pressures below the vapour pressure are clamped to it: a simple column-separation model that flags the
cavitation but does not track the cavity volume (mass is not conserved while a node is clamped).  The scheme is
the method of characteristics of Wylie and Streeter (1978).
"""

import numpy as np
from numba import njit

from ..errors import InputError

PRESSURE = 0
"""Boundary kind: the pressure at the pipe end is prescribed."""

VELOCITY = 1
"""Boundary kind: the velocity at the pipe end is prescribed (0: a closed end)."""


@njit(cache=True)
def characteristics(p, u, impedance, friction) -> tuple[np.ndarray, np.ndarray]:
    """The right-hand sides C+ (from the left neighbour) and C- (from the right neighbour) of every node.

    Parameters
    ----------
    p, u : ndarray
        Pressure [Pa] and velocity [m/s] at the N + 1 nodes at the previous time step.
    impedance : float
        rho a [Pa s/m].
    friction : float
        rho a dt lambda / (2 d) [Pa s^2/m^2].

    Returns
    -------
    (ndarray, ndarray)
        C+ and C- [Pa]; C+[0] and C-[N] are unused (nan).

    References
    ----------
    Wylie and Streeter (1978), method of characteristics.
    """
    n = p.size
    cp = np.full(n, np.nan)
    cm = np.full(n, np.nan)
    for i in range(1, n):
        cp[i] = p[i - 1] + impedance * u[i - 1] - friction * u[i - 1] * abs(u[i - 1])
    for i in range(n - 1):
        cm[i] = p[i + 1] - impedance * u[i + 1] + friction * u[i + 1] * abs(u[i + 1])
    return cp, cm


@njit(cache=True)
def interior(p, u, cp, cm, impedance, vapour_pressure) -> bool:
    """Update the interior nodes in place from C+ and C-; returns True where a node was clamped."""
    clamped = False
    for i in range(1, p.size - 1):
        u[i] = (cp[i] - cm[i]) / (2.0 * impedance)
        p[i] = 0.5 * (cp[i] + cm[i])
        if p[i] < vapour_pressure:
            p[i] = vapour_pressure
            clamped = True
    return clamped


@njit(cache=True)
def _pipe_kernel(p, u, impedance, friction, vapour_pressure, left_kind, left, right_kind, right):
    steps = left.size
    n = p.size - 1
    ends = np.empty((steps, 4))
    for k in range(steps):
        cp, cm = characteristics(p, u, impedance, friction)
        interior(p, u, cp, cm, impedance, vapour_pressure)
        if left_kind == PRESSURE:
            p[0] = left[k]
            u[0] = (p[0] - cm[0]) / impedance
        else:
            u[0] = left[k]
            p[0] = max(cm[0] + impedance * u[0], vapour_pressure)
        if right_kind == PRESSURE:
            p[n] = right[k]
            u[n] = (cp[n] - p[n]) / impedance
        else:
            u[n] = right[k]
            p[n] = max(cp[n] - impedance * u[n], vapour_pressure)
        ends[k, 0] = p[0]
        ends[k, 1] = u[0]
        ends[k, 2] = p[n]
        ends[k, 3] = u[n]
    return ends


def pipe_transient(pressure, velocity, density, wave_speed, diameter, friction_factor, time_step,
                   left, right, left_kind=PRESSURE, right_kind=VELOCITY, vapour_pressure=-np.inf) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Transient flow in a single pipe with prescribed end conditions, by the method of characteristics.

    Parameters
    ----------
    pressure, velocity : array_like
        Initial pressure [Pa] and velocity [m/s] at the N + 1 nodes (N reaches of a wave_speed time_step).
    density : float
        rho [kg/m^3].
    wave_speed : float
        a [m/s].
    diameter : float
        d [m].
    friction_factor : float
        Darcy lambda [-].
    time_step : float
        dt [s]; the reach length is a dt.
    left, right : array_like
        The prescribed end values at the time steps 1, 2, ...: pressure [Pa] or velocity [m/s] by kind.
    left_kind, right_kind : int
        :data:`PRESSURE` or :data:`VELOCITY`.
    vapour_pressure : float
        Pressures below it are clamped to it [Pa] (-inf: no cavitation model).

    Returns
    -------
    ends : ndarray, shape (steps, 4)
        p(0), u(0), p(L), u(L) after each step [Pa, m/s].
    pressure, velocity : ndarray
        The fields after the last step [Pa, m/s].

    Notes
    -----
    See the module docstring for the characteristic equations; the unknown at a pipe end follows from the
    one characteristic that reaches it and the prescribed value.

    References
    ----------
    Wylie and Streeter (1978), method of characteristics.
    """
    p = np.array(pressure, dtype=float)
    u = np.array(velocity, dtype=float)
    left = np.asarray(left, dtype=float)
    right = np.asarray(right, dtype=float)
    if left.shape != right.shape:
        raise InputError("the left and right end conditions need one value per time step each")
    impedance = density * wave_speed
    friction = impedance * time_step * friction_factor / (2.0 * diameter)
    ends = _pipe_kernel(p, u, impedance, friction, float(vapour_pressure), int(left_kind), left,
                        int(right_kind), right)
    return ends, p, u
