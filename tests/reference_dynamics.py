"""The one-mass train's worked example (spec sections 2, 8 and 12) and an independent reference for it: scipy's DOP853
on the same equations of motion, written out here from the model's definition (Shang Hanji (1988), section 3.1), not
from the package's kernel; and the closed-form jump speed of a harmonic cam.  The tests and
benchmarks/accuracy_dynamics.py use them."""

from types import SimpleNamespace

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from valvetrain.dynamics.models import one_mass_train
from valvetrain.laws import DynamicLaw

RPM = np.pi / 30.0


def spec12():
    """The worked example of spec sections 2, 8 and 12: the dynamic cam of tests/laws/test_dynamic.py (c = 15000
    N/mm, M = 0.25 kg, K = 67.5 N/mm, F0 = 400 N, k = 1.5, x0 = 0.30 mm, designed for 3000 cam rpm) and its
    one-mass train with zeta = 0.05."""
    omega = 3000 * RPM
    law = DynamicLaw(8e-3, np.radians(55), [2, 10, 18, 26, 34], 0.3 / omega, 15e6, 0.25, 67.5e3, 400.0, omega,
                     1.5, 0.3e-3, "constant_acceleration", 0.5)
    return law, one_mass_train(0.25, 15e6, 67.5e3, 400.0, 1.5, 0.3e-3, damping_ratio=0.05)


def appendix_train():
    """The built-in example's intake train, rounded (M = 0.138 kg, c = 12930 N/mm, K = 66.5 N/mm, F0 = 274.5 N, k =
    1.6, lash 0.4 mm, zeta 0.05, the default seat), on the Kurz cam of the appendix of Valve-train practical works
    (n.d.) (tests/conftest.py): (law, train).  Its valve bounces 1-2.5 um off its seat from 5331 engine rpm and leaves
    its cam at 7953 rpm."""
    from conftest import seed000_law

    return seed000_law(), one_mass_train(0.138, 1.293e7, 66.5e3, 274.5, 1.6, 0.4e-3)


def one_mass_rhs(law, train, omega, mass=None):
    """The one-mass train's equations of motion as scipy's ``rhs(t, (y, y_dot))``, at camshaft angle omega t - pi from
    the nose: M y_ddot = F_c - (F_0 + K y) + F_s with the contact F_c = max(0, c delta + C delta_dot) where delta =
    k h - x_0 - y > 0 and the seat F_s = max(0, -c_s y - C_s y_dot) where y < 0 (Shang Hanji (1988), section 3.1).
    ``mass(y) -> (m, dm/dy)``: a mass that changes with the lift, m y_ddot + (1/2) m' y_dot^2 = F (Lagrange's equation
    of T = m(y) y_dot^2 / 2); default the train's M."""
    k = train.rocker_ratio

    def rhs(t, s):
        d = law.derivatives(np.array([(omega * t) % (2 * np.pi) - np.pi]))[:2, 0] * k
        y, v = s
        gap = d[0] - train.lash - y
        fc = max(0.0, train.stiffness * gap + train.damping * (omega * d[1] - v)) if gap > 0 else 0.0
        fs = max(0.0, -train.seat_stiffness * y - train.seat_damping * v) if y < 0 else 0.0
        m, dm = (train.mass, 0.0) if mass is None else mass(y)
        return [v, (fc - train.preload - train.spring_rate * y + fs - 0.5 * dm * v**2) / m]

    return rhs


def seat_crossings(law, train, omega, revolutions=1, steps_per_revolution=7200, first=False):
    """Every downward y = 0 crossing of the valve from rest on its seat, by DOP853 (rtol 1e-10, atol 1e-14, the
    largest step one revolution / ``steps_per_revolution``), located by the event finder.  With ``first`` only the
    first (the first seating), integrated from the last sample of a 0.01 cam deg grid before the cam reaches the
    valve: until then the valve rests on its seat in equilibrium (no contact force, the seat's force the preload),
    so the motion is the same as from the revolution's start.

    Returns
    -------
    times : ndarray
        Crossing times [s] from the start, at camshaft angle omega t - pi from the nose.
    states : ndarray (n, 2)
        Lift [m] and velocity [m/s] there.
    """
    rhs = one_mass_rhs(law, train, omega)

    def seat(t, s):
        return s[0]

    seat.direction = -1
    seat.terminal = first
    period = 2 * np.pi / omega
    rest = -train.preload / train.seat_stiffness
    start = 0.0
    if first:
        angles = np.linspace(-np.pi, np.pi, 36001)
        reached = np.flatnonzero(law.derivatives(angles)[0] * train.rocker_ratio - train.lash > rest)
        start = max(int(reached[0]) - 1, 0) * (angles[1] - angles[0]) / omega
    sol = solve_ivp(rhs, (start, revolutions * period), [rest, 0.0], method="DOP853",
                    rtol=1e-10, atol=1e-14, max_step=period / steps_per_revolution, events=seat)
    return sol.t_events[0], sol.y_events[0]


def reference_events(law, train, omega, revolutions=1, steps_per_revolution=360, points=40001):
    """The events of the last of ``revolutions`` camshaft revolutions from rest on the seat, by DOP853 (rtol 1e-10,
    atol 1e-14, the largest step one revolution / ``steps_per_revolution``), its crossings of y = 0 and of dy/dt = 0
    located by the event finder.

    Returns
    -------
    dict
        ``seating_velocity``: dy/dt at the first downward crossing of y = 0 after the largest lift [m/s];
        ``bounce_height``: the largest lift after it, at a located dy/dt = 0 or at the end of the revolution, not below
        0 [m]; ``min_force``: the smallest of k (c delta + C d(delta)/dt) (the contact law at the cam without its clamp
        at zero: negative once the valve has left the cam) where the cam lifts the open valve before that seating, on
        ``points`` angles of the lift [N] (the zero of this signed force in the speed is the jump speed).
    """
    rhs = one_mass_rhs(law, train, omega)

    def seat(t, s):
        return s[0]

    def top(t, s):
        return s[1]

    seat.direction, top.direction = -1, -1
    period = 2 * np.pi / omega
    sol = solve_ivp(rhs, (0, revolutions * period), [-train.preload / train.seat_stiffness, 0.0], method="DOP853",
                    rtol=1e-10, atol=1e-14, max_step=period / steps_per_revolution, events=(seat, top),
                    dense_output=True)
    start = (revolutions - 1) * period
    tops, lifts = sol.t_events[1], sol.y_events[1][:, 0]
    lifts, tops = lifts[tops >= start], tops[tops >= start]
    highest = tops[np.argmax(lifts)]
    seats = sol.t_events[0] > highest
    landing, velocity = sol.t_events[0][seats][0], sol.y_events[0][seats][0, 1]
    after = lifts[tops > landing]
    height = max(after.max() if after.size else 0.0, float(sol.sol(revolutions * period)[0]), 0.0)
    k = train.rocker_ratio
    t = np.linspace(start, landing, points)
    y, v = sol.sol(t)
    d = law.derivatives((omega * t) % (2 * np.pi) - np.pi)[:2] * k
    delta = d[0] - train.lash - y
    lifting = (d[0] - train.lash > 0.0) & (y > 0.0)
    force = train.stiffness * delta + train.damping * (omega * d[1] - v)
    return {"seating_velocity": float(velocity), "bounce_height": float(height),
            "min_force": float(k * force[lifting].min())}


def harmonic_cam(lift, half_angle):
    """A harmonic (1 - cos) cam: h = L/2 (1 + cos(pi theta / phi)) for |theta| < phi, 0 on the base circle."""
    def derivatives(theta):
        on = np.abs(theta) < half_angle
        w = np.pi / half_angle
        return np.array([np.where(on, 0.5 * lift * (1 + np.cos(w * theta)), 0.0),
                         np.where(on, -0.5 * lift * w * np.sin(w * theta), 0.0),
                         np.where(on, -0.5 * lift * w * w * np.cos(w * theta), 0.0)])
    return SimpleNamespace(derivatives=derivatives)


def harmonic_jump_speed(lift, half_angle, train):
    """The jump speed [rad/s camshaft] of a one-mass train (no lash, rocker ratio 1) on a harmonic cam
    h = L/2 (1 + cos(pi theta / phi)) for |theta| < phi, in closed form.

    While the cam carries the valve, M y'' + C y' + (c + K) y = c h + C h' - F0, a linear oscillator driven by the
    constant L/2 and the harmonic (L/2) cos(Omega t) of frequency Omega = pi omega / phi.  Its steady response is
    y = y_bar + (L/2) Re(G e^(i Omega t)) with y_bar = (c L/2 - F0) / (c + K) and G = (c + i Omega C) /
    (c + K - M Omega^2 + i Omega C), so the contact force F = F0 + K y + M y'' = F0 + K y_bar + (L/2) Re((K - M Omega^2)
    G e^(i Omega t)) is least, over the lift's whole period of the harmonic, at F0 + K y_bar - (L/2) |K - M Omega^2| |G|;
    the jump speed is its zero (solved by brentq to 1e-14).  The free vibration started as the valve leaves its
    seat, which this leaves out, has decayed by exp(-C t / 2M) at the nose, t = phi / omega: to below 1e-6 on the
    trains of the tests (the rigid drive, c -> oo, gives sqrt(2 (F0 + K L) / (M L (pi / phi)^2)); Den Hartog (1956), the forced
    vibration of a damped system of one degree of freedom)."""
    m, c, damping, rate, preload = train.mass, train.stiffness, train.damping, train.spring_rate, train.preload

    def least(omega):
        w = np.pi * omega / half_angle
        gain = (c + 1j * w * damping) / (c + rate - m * w**2 + 1j * w * damping)
        mean = (c * lift / 2 - preload) / (c + rate)
        return preload + rate * mean - lift / 2 * abs(rate - m * w**2) * abs(gain)

    rigid = np.sqrt(2 * (preload + rate * lift) / (m * lift * (np.pi / half_angle) ** 2))
    return brentq(least, 0.5 * rigid, 1.5 * rigid, xtol=1e-14 * rigid)
