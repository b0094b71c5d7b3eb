"""Quasi-one-dimensional unsteady gas flow in the intake and exhaust runners: a finite-volume scheme.

A runner (with its port) is a straight pipe of constant diameter from its plenum (x = 0) to its valve (x = L),
cut into cells of equal length.  Each cell holds the conserved quantities per unit volume
q = (rho, rho u, rho E, rho Y): density, momentum, total energy E = e + u^2/2 and the mass of the tracer Y (the
burned or residual gas); the gas is ideal with ratio of specific heats gamma and gas constant R frozen at the
runner's reference state (:func:`frozen_gas`), its internal energy e = e_0 + p / ((gamma - 1) rho) counted from the
cylinder's sensible zero.

Scheme: the Euler equations with wall friction,

.. math:: q_t + f(q)_x = s,\\quad f = (\\rho u,\\ \\rho u^2 + p,\\ u(\\rho E + p),\\ \\rho u Y),\\quad
          s = (0,\\ -2 c_f \\rho u|u| / D,\\ 0,\\ 0),

in conservation form; the fluxes between cells are the HLLC approximate Riemann solver's (Toro (2009), section
10.4, with the wave speeds of Davis (1988)) on states reconstructed linearly in the primitive variables with the
van Leer limiter (MUSCL, Toro (2009), chapters 13 and 14); the caller advances the cells with the two-stage strong
stability preserving Runge-Kutta (Heun) scheme, second order in time and space away from extrema and shocks.
The friction coefficient is the smooth pipe's, c_f = max(16 / Re, 0.0791 Re^-0.25) (laminar, Blasius (1913)),
with the viscosity of air by Sutherland's law (White (2006), Table 1-2) at the runner's reference temperature.

The ends are the characteristic boundaries of a pipe: the wave arriving from the interior is a simple wave
(its Riemann invariant carried from the end cell, in its pressure form), matched to an open end at a plenum
(isentropic inflow from the plenum's stagnation state; outflow at the plenum pressure, choked where sonic) or to
a valve (quasi-steady compressible flow through the valve's effective area, :mod:`.orifice`; a wall where the
valve is shut).  Benson (1982) matches the same relations with the method of characteristics.
"""

import numpy as np
from numba import njit

from .orifice import mass_flux

WALL = 0
"""Boundary kind of :func:`simulate_pipe`: a closed end."""

PLENUM = 1
"""Boundary kind of :func:`simulate_pipe`: an open end at a plenum of given stagnation pressure and temperature."""

SUTHERLAND = (1.716e-5, 273.0, 111.0)
"""Sutherland's law for air: mu_0 [Pa s] at T_0 [K] and the constant S [K] (White (2006), Table 1-2)."""

CFL = 0.8
"""Courant number of the runners' time step, (|u| + c) dt / dx <= CFL: below the limit 1 of the explicit scheme."""


def quarter_wave_frequency(length, sound_speed) -> float:
    """Fundamental frequency of a pipe closed at one end and open at the other, f = c / (4 L) [Hz].

    Parameters
    ----------
    length : float
        Pipe length L [m] (no end correction).
    sound_speed : float
        Speed of sound c [m/s].

    Notes
    -----
    The open end is a node of the pressure, the closed end a node of the velocity: a quarter of a wavelength
    fits the pipe, :math:`\\lambda = 4L`.

    References
    ----------
    Kinsler et al. (2000), chapter 10; Heywood (1988), chapter 6 (the tuning of intake runners).

    Examples
    --------
    A 0.25 m runner at 347 m/s (air at 300 K):

    >>> quarter_wave_frequency(0.25, 347.0)
    347.0
    """
    return sound_speed / (4.0 * length)


def frozen_gas(gas_constant, gamma, reference_temperature, reference_enthalpy) -> np.ndarray:
    """The runner's gas constants ``[gamma, R, e_0, mu]``: an ideal gas of constant specific heats whose enthalpy
    e_0 + cp T equals the cylinder gas's sensible enthalpy at the reference temperature, and its viscosity there.

    Parameters
    ----------
    gas_constant : float
        R [J/(kg K)].
    gamma : float
        cp / cv at the reference temperature.
    reference_temperature : float
        [K].
    reference_enthalpy : float
        Sensible enthalpy of the gas at the reference temperature [J/kg].

    Returns
    -------
    ndarray
        ``[gamma, R, e_0, mu]`` with :math:`e_0 = h_{ref} - c_p T_{ref}` [J/kg] and the viscosity of air by
        Sutherland's law (:data:`SUTHERLAND`) at the reference temperature [Pa s], frozen like the gas's heats.

    Examples
    --------
    Air at 273 K has Sutherland's mu_0:

    >>> float(frozen_gas(287.0, 1.4, 273.0, 0.0)[3])
    1.716e-05
    """
    cp = gamma * gas_constant / (gamma - 1.0)
    mu0, t0, s = SUTHERLAND
    mu = mu0 * (reference_temperature / t0) ** 1.5 * (t0 + s) / (reference_temperature + s)
    return np.array([gamma, gas_constant, reference_enthalpy - cp * reference_temperature, mu])


@njit(cache=True, nogil=True)
def primitive(q, gas) -> tuple[float, float, float, float]:
    """Density [kg/m^3], velocity [m/s], pressure [Pa] and tracer fraction of one cell's conserved state ``q``."""
    gamma, e0 = gas[0], gas[2]
    rho = q[0]
    u = q[1] / rho
    p = (gamma - 1.0) * (q[2] - rho * e0 - 0.5 * q[1] * u)
    return rho, u, p, q[3] / rho


@njit(cache=True, nogil=True)
def conserved(rho, u, p, y, gas, out) -> None:
    """Write the conserved state of density, velocity, pressure and tracer fraction into ``out`` (4,)."""
    out[0] = rho
    out[1] = rho * u
    out[2] = rho * gas[2] + p / (gas[0] - 1.0) + 0.5 * rho * u * u
    out[3] = rho * y


@njit(cache=True, nogil=True)
def hllc(rl, ul, pl, yl, rr, ur, pr, yr, gas) -> tuple[float, float, float, float]:
    """HLLC flux per unit area (mass, momentum, energy, tracer) between a left and a right state (density, velocity,
    pressure, tracer).

    Notes
    -----
    Wave speeds :math:`S_L = \\min(u_L - c_L, u_R - c_R)`, :math:`S_R = \\max(u_L + c_L, u_R + c_R)` (Davis (1988)),
    contact :math:`S_* = \\frac{p_R - p_L + \\rho_L u_L (S_L - u_L) - \\rho_R u_R (S_R - u_R)}{\\rho_L (S_L - u_L) -
    \\rho_R (S_R - u_R)}`, star states :math:`q_{*K} = \\rho_K\\frac{S_K - u_K}{S_K - S_*}(1,\\ S_*,\\ E_K +
    (S_* - u_K)(S_* + \\frac{p_K}{\\rho_K (S_K - u_K)}),\\ Y_K)` and :math:`f_{*K} = f_K + S_K (q_{*K} - q_K)`.

    References
    ----------
    Toro (2009), section 10.4; Davis (1988).
    """
    gamma, e0 = gas[0], gas[2]
    cl = np.sqrt(gamma * pl / rl)
    cr = np.sqrt(gamma * pr / rr)
    sl = min(ul - cl, ur - cr)
    sr = max(ul + cl, ur + cr)
    el = e0 + pl / ((gamma - 1.0) * rl) + 0.5 * ul * ul
    er = e0 + pr / ((gamma - 1.0) * rr) + 0.5 * ur * ur
    if sl >= 0.0:
        m = rl * ul
        return m, m * ul + pl, ul * (rl * el + pl), m * yl
    if sr <= 0.0:
        m = rr * ur
        return m, m * ur + pr, ur * (rr * er + pr), m * yr
    dl = rl * (sl - ul)
    dr = rr * (sr - ur)
    s = (pr - pl + rl * ul * (sl - ul) - rr * ur * (sr - ur)) / (dl - dr)
    if s >= 0.0:
        r, u, p, y, e, sk, d = rl, ul, pl, yl, el, sl, dl
    else:
        r, u, p, y, e, sk, d = rr, ur, pr, yr, er, sr, dr
    m = r * u
    factor = d / (sk - s)
    star_e = e + (s - u) * (s + p / d)
    return (m + sk * (factor - r), m * u + p + sk * (factor * s - r * u),
            u * (r * e + p) + sk * (factor * star_e - r * e), m * y + sk * (factor - r) * y)


@njit(cache=True, nogil=True)
def _van_leer(a, b):
    """Van Leer's limited slope of two one-sided differences (Toro (2009), chapter 14)."""
    if a * b <= 0.0:
        return 0.0
    return 2.0 * a * b / (a + b)


@njit(cache=True, nogil=True)
def friction_coefficient(rho, u, viscosity, diameter) -> float:
    """Fanning friction coefficient of a smooth pipe: max(16 / Re, 0.0791 Re^-0.25), laminar and Blasius (1913),
    Re = rho |u| D / mu; 0 for a fluid at rest."""
    re = rho * abs(u) * diameter / viscosity
    if re < 1e-12:
        return 0.0
    return max(16.0 / re, 0.0791 / np.sqrt(np.sqrt(re)))


@njit(cache=True, nogil=True)
def pipe_rates(q, gas, dx, diameter, friction, left, right, rate, work) -> None:
    """Time derivative of every cell's conserved state, ``rate`` (n, 4), from the interior fluxes and the end faces'.

    Parameters
    ----------
    q : ndarray
        (n, 4) conserved states.
    gas : ndarray
        ``[gamma, R, e_0, mu]`` (:func:`frozen_gas`).
    dx, diameter : float
        Cell length and pipe diameter [m].
    friction : bool
        Whether the wall friction acts.
    left, right : ndarray
        (4,) fluxes per unit area through the faces at x = 0 and x = L (positive towards +x).
    rate : ndarray
        (n, 4) output.
    work : ndarray
        (3, n + 1, 4) scratch: the faces' fluxes, the cells' primitive states and their limited slopes.
    """
    n = q.shape[0]
    viscosity = gas[3]
    faces, prim, slope = work[0], work[1], work[2]
    for k in range(4):
        faces[0, k] = left[k]
        faces[n, k] = right[k]
    for i in range(n):
        rho, u, p, y = primitive(q[i], gas)
        prim[i, 0], prim[i, 1], prim[i, 2], prim[i, 3] = rho, u, p, y
    # limited slopes; the end cells and a cell whose reconstruction would not stay positive are first order
    for k in range(4):
        slope[0, k] = 0.0
        slope[n - 1, k] = 0.0
    for i in range(1, n - 1):
        for k in range(4):
            slope[i, k] = _van_leer(prim[i, k] - prim[i - 1, k], prim[i + 1, k] - prim[i, k])
        if prim[i, 0] - 0.5 * abs(slope[i, 0]) <= 0.0 or prim[i, 2] - 0.5 * abs(slope[i, 2]) <= 0.0:
            for k in range(4):
                slope[i, k] = 0.0
    for i in range(n - 1):
        f0, f1, f2, f3 = hllc(prim[i, 0] + 0.5 * slope[i, 0], prim[i, 1] + 0.5 * slope[i, 1],
                              prim[i, 2] + 0.5 * slope[i, 2], prim[i, 3] + 0.5 * slope[i, 3],
                              prim[i + 1, 0] - 0.5 * slope[i + 1, 0], prim[i + 1, 1] - 0.5 * slope[i + 1, 1],
                              prim[i + 1, 2] - 0.5 * slope[i + 1, 2], prim[i + 1, 3] - 0.5 * slope[i + 1, 3], gas)
        faces[i + 1, 0], faces[i + 1, 1], faces[i + 1, 2], faces[i + 1, 3] = f0, f1, f2, f3
    for i in range(n):
        for k in range(4):
            rate[i, k] = (faces[i, k] - faces[i + 1, k]) / dx
        if friction:
            rho, u = prim[i, 0], prim[i, 1]
            cf = friction_coefficient(rho, u, viscosity, diameter)
            rate[i, 1] -= 2.0 * cf * rho * u * abs(u) / diameter


@njit(cache=True, nogil=True)
def _face_flux(rho, u, p, y, gas, flux):
    """The Euler flux of a face state (density, velocity, pressure, tracer) per unit area, into ``flux``."""
    gamma, e0 = gas[0], gas[2]
    m = rho * u
    flux[0] = m
    flux[1] = m * u + p
    flux[2] = m * (e0 + gamma / (gamma - 1.0) * p / rho + 0.5 * u * u)
    flux[3] = m * y


@njit(cache=True, nogil=True)
def _solve(kind, lo, hi, guess, args):
    """Root of :func:`_residual` ``kind`` in [lo, hi] (where it changes sign): the secant method from ``guess`` (the
    previous step's root) while it stays in the bracket and converges within a few steps, else Brent's method
    (:func:`_root`) on the whole bracket."""
    x0 = min(max(guess, lo), hi)
    f0 = _residual(kind, x0, args)
    if f0 == 0.0:
        return x0
    delta = 1e-7 * (hi - lo)
    x1 = x0 + delta if x0 + delta <= hi else x0 - delta
    f1 = _residual(kind, x1, args)
    for _ in range(6):
        if f1 == f0:
            break
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        if not lo <= x2 <= hi:
            break
        x0, f0 = x1, f1
        x1 = x2
        f1 = _residual(kind, x1, args)
        if abs(x1 - x0) <= 1e-10 * abs(x1) or f1 == 0.0:
            return x1
    return _root(kind, lo, hi, _residual(kind, lo, args), _residual(kind, hi, args), args)


@njit(cache=True, nogil=True)
def _matched(kind, edge, lo, hi, roots, args):
    """The root of :func:`_residual` ``kind`` in [lo, hi] (:func:`_solve` from the end's previous root, kept in
    ``roots``), or ``edge`` where the residual is not positive there: the flow is sonic (choked) at that end of the
    bracket."""
    if _residual(kind, edge, args) <= 0.0:
        return edge
    x = _solve(kind, lo, hi, roots[kind], args)
    roots[kind] = x
    return x


@njit(cache=True, nogil=True)
def _root(kind, a, b, fa, fb, args):
    """Root of :func:`_residual` ``kind`` between ``a`` and ``b`` whose residuals ``fa``, ``fb`` have opposite
    signs: Brent's method (inverse quadratic interpolation, secant and bisection; Brent (1973), chapter 4), to
    1e-10 of the root's size."""
    c, fc = a, fa
    d = e = b - a
    for _ in range(100):
        if (fb > 0.0) == (fc > 0.0):
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 1e-10 * abs(b) + 1e-300
        m = 0.5 * (c - b)
        if abs(m) <= tol or fb == 0.0:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:
                p = 2.0 * m * s
                q = 1.0 - s
            else:
                q = fa / fc
                r = fb / fc
                p = s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0))
                q = (q - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0.0:
                q = -q
            else:
                p = -p
            if 2.0 * p < min(3.0 * m * q - abs(tol * q), abs(e * q)):
                e = d
                d = p / q
            else:
                d = m
                e = m
        else:
            d = m
            e = m
        a, fa = b, fb
        b += d if abs(d) > tol else (tol if m > 0.0 else -tol)
        fb = _residual(kind, b, args)
    return b


@njit(cache=True, nogil=True)
def _residual(kind, x, a):
    """Residual of the end-face matching conditions (see :func:`plenum_face` and :func:`valve_face`).

    ``a`` = [rho_c, u_c, p_c, c_c, gamma, R, e_0, p_other, T_other, area_ratio, h_other, gamma_other, R_other]:
    the end cell's state, the runner's gas, the far side's pressure and temperature (plenum or cylinder), the
    effective area over the pipe area, the far side's enthalpy in the cylinder's terms and its gas.
    """
    rho_c, u_c, p_c, c_c, gamma = a[0], a[1], a[2], a[3], a[4]
    r, e0 = a[5], a[6]
    g1 = 0.5 * (gamma - 1.0)
    cp = gamma * r / (gamma - 1.0)
    if kind == 0:
        # plenum inflow, x = face velocity: the simple wave's pressure less the plenum isentrope's
        t0 = a[8]
        wave = p_c * max(1.0 + g1 * (x - u_c) / c_c, 1e-9) ** (gamma / g1)
        return wave - a[7] * (1.0 - x * x / (2.0 * cp * t0)) ** (gamma / (gamma - 1.0))
    if kind == 1:
        # flow out of the pipe into the cylinder, x = z = (p_b / p_c)^((gamma-1)/(2 gamma)): pipe flux less valve flux
        u = u_c - c_c * (x - 1.0) / g1
        rho = rho_c * x ** (1.0 / g1)
        t_c = p_c / (rho_c * r)
        t0 = t_c * x * x + u * u / (2.0 * cp)
        # isentropic from the cell to the face and on to its stagnation state: p0 = p_c (T0 / T_c)^(gamma/(gamma-1))
        p0 = p_c * (t0 / t_c) ** (gamma / (gamma - 1.0))
        return rho * u - a[9] * mass_flux(p0, t0, a[7], gamma, r)
    # flow from the cylinder into the pipe, x = face pressure: pipe flux less valve flux
    z = (x / p_c) ** (g1 / gamma)
    u = u_c - c_c * (z - 1.0) / g1
    t = (a[10] - e0 - 0.5 * u * u) / cp
    if t <= 0.0:
        return 1e30     # the face could not reach this velocity: the pipe would carry any flow
    return -x / (r * t) * u - a[9] * mass_flux(a[7], a[8], x, a[11], a[12])


SCRATCH = 16
"""Length of an end's scratch array: its roots of the previous step (one per kind of :func:`_residual`) and the
residual's 13 arguments."""


@njit(cache=True, nogil=True)
def _arguments(scratch, a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12):
    """The residual's arguments written into ``scratch[3:]`` (no allocation in the step), returned as a view."""
    args = scratch[3:]
    args[0], args[1], args[2], args[3], args[4], args[5], args[6] = a0, a1, a2, a3, a4, a5, a6
    args[7], args[8], args[9], args[10], args[11], args[12] = a7, a8, a9, a10, a11, a12
    return args


@njit(cache=True, nogil=True)
def plenum_face(rho_c, u_c, p_c, y_c, gas, p0, t0, y0, flux, roots) -> None:
    """Flux per unit area through the face at x = 0 where the runner opens into a plenum, into ``flux`` (4,).

    Parameters
    ----------
    rho_c, u_c, p_c, y_c : float
        The first cell's density, velocity, pressure and tracer.
    gas : ndarray
        ``[gamma, R, e_0, mu]``.
    p0, t0, y0 : float
        The plenum's pressure [Pa], temperature [K] and tracer (its gas at rest).
    flux : ndarray
        (4,) output, positive into the pipe.
    roots : ndarray
        (:data:`SCRATCH`,) the end's scratch: its roots of the previous step (the starting guesses, updated) and
        room for the residual's arguments.

    Notes
    -----
    The wave arriving from the interior relates the face's velocity and pressure,
    :math:`u_b = u_c + \\frac{2 c_c}{\\gamma - 1}\\left[(p_b / p_c)^{(\\gamma-1)/(2\\gamma)} - 1\\right]`
    (its Riemann invariant :math:`u - 2c/(\\gamma-1)`, isentropic from the cell).  Outflow: :math:`p_b = p_0`
    (the jet leaves at the plenum pressure), sonic at most.  Inflow: the gas accelerates isentropically from the
    plenum, :math:`T_b = T_0 - u_b^2 / (2 c_p)`, :math:`p_b = p_0 (T_b / T_0)^{\\gamma/(\\gamma-1)}`, matched to the
    wave's pressure (a root in :math:`u_b`), sonic at most.

    References
    ----------
    Benson (1982) (the open-end boundary); Toro (2009), chapter 4 (the rarefaction's relations).
    """
    gamma, r = gas[0], gas[1]
    g1 = 0.5 * (gamma - 1.0)
    c_c = np.sqrt(gamma * p_c / rho_c)
    z = (p0 / p_c) ** (g1 / gamma)
    u = u_c + c_c * (z - 1.0) / g1
    if u <= 0.0:
        c = c_c * z
        if -u > c:
            z = (1.0 - g1 * u_c / c_c) / (1.0 + g1)
            u = -c_c * z
        _face_flux(rho_c * z ** (1.0 / g1), u, p_c * z ** (gamma / g1), y_c, gas, flux)
        return
    args = _arguments(roots, rho_c, u_c, p_c, c_c, gamma, r, gas[2], p0, t0, 0.0, 0.0, 0.0, 0.0)
    sonic = np.sqrt(2.0 * gamma * r * t0 / (gamma + 1.0))
    u = _matched(0, sonic, 0.0, sonic, roots, args)
    cp = gamma * r / (gamma - 1.0)
    t = t0 - u * u / (2.0 * cp)
    p = p0 * (t / t0) ** (gamma / (gamma - 1.0))
    _face_flux(p / (r * t), u, p, y0, gas, flux)


@njit(cache=True, nogil=True)
def valve_face(rho_c, u_c, p_c, y_c, gas, pipe_area, area_out, area_in, p_cyl, t_cyl, h_cyl, gamma_cyl, r_cyl,
               y_cyl, flux, roots) -> None:
    """Flux through the face at x = L where the runner meets its valve, into ``flux`` (4,) [kg/s, N, W, kg/s].

    Parameters
    ----------
    rho_c, u_c, p_c, y_c : float
        The last cell's density, velocity, pressure and tracer.
    gas : ndarray
        The runner's ``[gamma, R, e_0, mu]``.
    pipe_area : float
        [m^2].
    area_out, area_in : float
        Effective areas of the valve for flow out of the pipe into the cylinder and back [m^2].
    p_cyl, t_cyl, h_cyl, gamma_cyl, r_cyl, y_cyl : float
        The cylinder's pressure [Pa], temperature [K], sensible enthalpy [J/kg], ratio of specific heats, gas constant
        [J/(kg K)] and tracer.
    flux : ndarray
        (4,) output: mass, momentum, energy and tracer flows through the face, positive out of the pipe (into the
        cylinder); the cylinder gains mass ``flux[0]``, energy ``flux[2]`` and tracer ``flux[3]``.
    roots : ndarray
        (:data:`SCRATCH`,) the end's scratch (see :func:`plenum_face`).

    Notes
    -----
    The wave arriving from the interior gives :math:`u_b = u_c - \\frac{2c_c}{\\gamma-1}(z - 1)`,
    :math:`z = (p_b/p_c)^{(\\gamma-1)/(2\\gamma)}`; the valve passes the quasi-steady compressible flow
    (:func:`~valvetrain.breathing.orifice.mass_flux`) of its upstream side's stagnation state.  Out of the pipe:
    the face state isentropic from the cell, its stagnation state upstream, its mass flux equal to the valve's (a
    root in z; sonic at most).  Into the pipe: the cylinder upstream at rest, the face's total enthalpy the
    cylinder's (adiabatic), its pressure the root where the pipe carries the valve's flow.  With the valve shut the
    face is a wall at the pressure where u_b = 0.  The energy that crosses is counted once for both sides, so the
    sum of runner and cylinder conserves it to round-off.

    References
    ----------
    Benson (1982) (the partially open end at a valve); Heywood (1988), Appendix C.
    """
    gamma, r, e0 = gas[0], gas[1], gas[2]
    g1 = 0.5 * (gamma - 1.0)
    cp = gamma * r / (gamma - 1.0)
    c_c = np.sqrt(gamma * p_c / rho_c)
    z_hi = max(1.0 + g1 * u_c / c_c, 1e-6)
    p_hi = p_c * z_hi ** (gamma / g1)
    ratio_out, ratio_in = area_out / pipe_area, area_in / pipe_area
    if p_hi > p_cyl and ratio_out > 0.0:
        args = _arguments(roots, rho_c, u_c, p_c, c_c, gamma, r, e0, p_cyl, t_cyl, ratio_out, 0.0, 0.0, 0.0)
        z_lo = z_hi / (1.0 + g1)
        z = _matched(1, z_lo, z_lo, z_hi, roots, args)
        u = u_c - c_c * (z - 1.0) / g1
        rho = rho_c * z ** (1.0 / g1)
        t = p_c / (rho_c * r) * z * z
        m = rho * u * pipe_area
        flux[0] = m
        flux[1] = (rho * u * u + p_c * z ** (gamma / g1)) * pipe_area
        flux[2] = m * (e0 + cp * t + 0.5 * u * u)
        flux[3] = m * y_c
        return
    if p_hi < p_cyl and ratio_in > 0.0:
        args = _arguments(roots, rho_c, u_c, p_c, c_c, gamma, r, e0, p_cyl, t_cyl, ratio_in, h_cyl, gamma_cyl, r_cyl)
        p = _matched(2, p_cyl, p_hi, p_cyl, roots, args)
        z = (p / p_c) ** (g1 / gamma)
        u = u_c - c_c * (z - 1.0) / g1
        t = (h_cyl - e0 - 0.5 * u * u) / cp
        m = p / (r * t) * u * pipe_area
        flux[0] = m
        flux[1] = (m * u / pipe_area + p) * pipe_area
        flux[2] = m * h_cyl
        flux[3] = m * y_cyl
        return
    flux[0] = 0.0
    flux[1] = p_hi * pipe_area
    flux[2] = 0.0
    flux[3] = 0.0


@njit(cache=True, nogil=True)
def _end_flux(kind, q_end, gas, data, flux, roots):
    """Flux per unit area through an end face of :func:`simulate_pipe` (positive into the pipe)."""
    if kind == WALL:
        rho, u, p, y = primitive(q_end, gas)
        g1 = 0.5 * (gas[0] - 1.0)
        c = np.sqrt(gas[0] * p / rho)
        flux[0] = 0.0
        flux[1] = p * max(1.0 - g1 * u / c, 1e-6) ** (gas[0] / g1)
        flux[2] = 0.0
        flux[3] = 0.0
    else:
        rho, u, p, y = primitive(q_end, gas)
        plenum_face(rho, u, p, y, gas, data[0], data[1], data[2], flux, roots)


@njit(cache=True, nogil=True)
def _mirror(q, out):
    """The state seen from the other end: the pipe reversed (velocities change sign)."""
    n = q.shape[0]
    for i in range(n):
        out[i, 0] = q[n - 1 - i, 0]
        out[i, 1] = -q[n - 1 - i, 1]
        out[i, 2] = q[n - 1 - i, 2]
        out[i, 3] = q[n - 1 - i, 3]


@njit(cache=True, nogil=True)
def simulate_pipe(q, gas, dx, diameter, friction, dt, steps, left_kind, left_data, right_kind, right_data,
                  probe) -> np.ndarray:
    """Advance a pipe alone with closed or open ends (:data:`WALL`, :data:`PLENUM`), for the closed-form checks.

    Parameters
    ----------
    q : ndarray
        (n, 4) conserved states, advanced in place.
    gas : ndarray
        ``[gamma, R, e_0, mu]``.
    dx, diameter : float
        [m].
    friction : bool
    dt : float
        Time step [s] (the caller keeps (|u| + c) dt / dx below 1).
    steps : int
    left_kind, right_kind : int
        :data:`WALL` or :data:`PLENUM`.
    left_data, right_data : ndarray
        A plenum's ``[p0 [Pa], T0 [K], Y]`` (unused for a wall).
    probe : int
        Cell whose pressure is recorded after every step.

    Returns
    -------
    ndarray
        (steps,) pressure of the probe cell [Pa].
    """
    n = q.shape[0]
    rate = np.empty((n, 4))
    work = np.empty((3, n + 1, 4))
    stage = np.empty((n, 4))
    left = np.empty(4)
    right = np.empty(4)
    mirrored = np.empty((n, 4))
    roots = np.zeros((2, SCRATCH))
    out = np.empty(steps)
    for s in range(steps):
        for st in range(2):
            src = q if st == 0 else stage
            _end_flux(left_kind, src[0], gas, left_data, left, roots[0])
            _mirror(src, mirrored)
            _end_flux(right_kind, mirrored[0], gas, right_data, right, roots[1])
            right[0] = -right[0]
            right[2] = -right[2]
            right[3] = -right[3]
            pipe_rates(src, gas, dx, diameter, friction, left, right, rate, work)
            if st == 0:
                for i in range(n):
                    for k in range(4):
                        stage[i, k] = q[i, k] + dt * rate[i, k]
            else:
                for i in range(n):
                    for k in range(4):
                        q[i, k] = 0.5 * (q[i, k] + stage[i, k] + dt * rate[i, k])
        out[s] = primitive(q[probe], gas)[2]
    return out
