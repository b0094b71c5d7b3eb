"""An independent reference for the one-mass train: scipy's DOP853 on the same equations of motion, written out here
from the model's definition (Shang Hanji (1988), section 3.1), not from the package's kernel.  The tests and
benchmarks/accuracy_dynamics.py use it."""

import numpy as np
from scipy.integrate import solve_ivp


def seat_crossings(law, train, omega, revolutions=1, steps_per_revolution=7200):
    """Every downward y = 0 crossing of the valve from rest on its seat, by DOP853 (rtol 1e-10, atol 1e-14, the
    largest step one revolution / ``steps_per_revolution``), located by the event finder.

    Returns
    -------
    times : ndarray
        Crossing times [s] from the start, at camshaft angle omega t - pi from the nose.
    states : ndarray (n, 2)
        Lift [m] and velocity [m/s] there.
    """
    k = train.rocker_ratio

    def rhs(t, s):
        d = law.derivatives(np.array([(omega * t) % (2 * np.pi) - np.pi]))[:2, 0] * k
        y, v = s
        gap = d[0] - train.lash - y
        fc = max(0.0, train.stiffness * gap + train.damping * (omega * d[1] - v)) if gap > 0 else 0.0
        fs = max(0.0, -train.seat_stiffness * y - train.seat_damping * v) if y < 0 else 0.0
        return [v, (fc - train.preload - train.spring_rate * y + fs) / train.mass]

    def seat(t, s):
        return s[0]

    seat.direction = -1
    period = 2 * np.pi / omega
    sol = solve_ivp(rhs, (0, revolutions * period), [-train.preload / train.seat_stiffness, 0.0], method="DOP853",
                    rtol=1e-10, atol=1e-14, max_step=period / steps_per_revolution, events=seat)
    return sol.t_events[0], sol.y_events[0]
