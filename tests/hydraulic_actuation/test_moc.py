"""The pipe by the method of characteristics (valvetrain.hydraulic_actuation.moc; Wylie and Streeter (1978)):
analytic travelling waves, the Joukowsky pressure rise and column separation at the vapour pressure."""

import numpy as np
import pytest

from valvetrain.hydraulic_actuation import PRESSURE, VELOCITY, pipe_transient


def test_pressure_step_travels_at_the_wave_speed_and_doubles_at_a_closed_end():
    """Analytic travelling wave of a frictionless pipe: a step dp let in at x = 0 at t = 0 travels at a with
    the velocity dp / (rho a) behind it; the closed end at x = L reflects it, doubling the pressure there
    from t = L/a, and the reservoir end sends it back as a relief wave: p(L) is a square wave between 0 and
    2 dp of period 4 L / a.  The method of characteristics at Courant number one is exact here."""
    rho, a, d, n, dp = 870.0, 1300.0, 0.02, 40, 1e5
    dt = 2.0 / (n * a)                                           # L = 2 m
    steps = 8 * n
    left = np.full(steps, dp)                                    # reservoir pressure raised at the first step
    ends, p, u = pipe_transient(np.zeros(n + 1), np.zeros(n + 1), rho, a, d, 0.0, dt, left, np.zeros(steps),
                                PRESSURE, VELOCITY)
    k = np.arange(steps)                                         # steps since the step entered, each row
    expected = np.where(((k - n) // (2 * n)) % 2 == 0, 2 * dp, 0.0) * (k >= n)
    assert ends[:, 2] == pytest.approx(expected, abs=1e-9 * dp)
    # the front m - 1 reaches in after m < N steps: dp and dp / (rho a) behind it (x <= a t), rest in front
    m = n // 2
    ends, p, u = pipe_transient(np.zeros(n + 1), np.zeros(n + 1), rho, a, d, 0.0, dt, left[:m], np.zeros(m),
                                PRESSURE, VELOCITY)
    assert p[:m] == pytest.approx(dp) and u[:m] == pytest.approx(dp / (rho * a))
    assert np.all(p[m:] == 0.0) and np.all(u[m:] == 0.0)


def test_water_hammer_is_the_joukowsky_rise():
    """Joukowsky: a valve at the end of a pipe fed from a reservoir, closed suddenly on a flow u0, raises
    the pressure there by rho a u0 for 2 L / a, then drops it as far below for 2 L / a (frictionless)."""
    rho, a, d, n, u0, p_r = 870.0, 1300.0, 0.02, 20, 2.0, 5e6
    dt = 3.0 / (n * a)
    steps = 4 * n
    ends, _, _ = pipe_transient(np.full(n + 1, p_r), np.full(n + 1, u0), rho, a, d, 0.0, dt,
                                np.full(steps, p_r), np.zeros(steps), PRESSURE, VELOCITY)
    rise = rho * a * u0
    assert ends[:2 * n - 1, 2] == pytest.approx(p_r + rise, rel=1e-12)
    assert ends[2 * n:4 * n - 1, 2] == pytest.approx(p_r - rise, rel=1e-12)
    # friction: the first rise is still rho a u0 above the steady pressure at the valve
    lam = 0.03
    steady = p_r - lam * rho * u0**2 / (2 * d) * 3.0 * np.linspace(0.0, 1.0, n + 1)
    ends, _, _ = pipe_transient(steady, np.full(n + 1, u0), rho, a, d, lam, dt, np.full(steps, p_r),
                                np.zeros(steps), PRESSURE, VELOCITY)
    assert ends[0, 2] - steady[-1] == pytest.approx(rise, rel=1e-3)
    # line packing: a rise of the order of the steady friction loss, not more, while the wave travels
    loss = steady[0] - steady[-1]
    assert np.all(np.diff(ends[:2 * n - 1, 2]) >= 0)
    assert 0.5 * loss < ends[2 * n - 2, 2] - ends[0, 2] <= loss


def test_vapour_pressure_clamps_the_pipe():
    """A relief wave deeper than the pressure: the pressure stays at the vapour pressure (column separation)."""
    rho, a, d, n = 870.0, 1300.0, 0.02, 10
    ends, p, _ = pipe_transient(np.full(n + 1, 2e5), np.full(n + 1, 2.0), rho, a, d, 0.0, 1e-4,
                                np.full(30, 2e5), np.zeros(30), PRESSURE, VELOCITY, vapour_pressure=2e3)
    assert ends[:, 2].min() == pytest.approx(2e3) and p.min() >= 2e3
