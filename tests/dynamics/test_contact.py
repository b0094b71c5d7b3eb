"""The dynamic contact of cam and follower (valvetrain.dynamics.contact): the Hertz stress under the simulated force
and the lubrication characteristic, by hand (Shang Hanji (1988))."""

import numpy as np
import pytest

from valvetrain.dynamics.contact import dynamic_contact_stress, lubrication_characteristic
from valvetrain.dynamics.sweep import simulate

from reference_dynamics import RPM, spec12


def test_dynamic_contact_stress_and_lubrication():
    """Shang Hanji (1988), (2.5) with the dynamic force (section 3.4): at the nose sigma = 0.418 sqrt(F E / (b rho)) with
    rho = R0 + h + h'' (2.6).  The lubrication characteristic (2.12) gamma = rho / (R0 + h) is 1 on the base
    circle.  Hand computations on a simulated force."""
    law, train = spec12()
    r = simulate(law, train, 2000 * RPM)
    r0, width, modulus = 20e-3, 15e-3, 2.1e11
    sigma = dynamic_contact_stress(law, r.theta, r.contact_force, r0, width, modulus)
    nose = int(np.argmin(np.abs(r.theta)))
    h, _, d2h = law.derivatives(r.theta[nose])[:3]
    assert sigma[nose] == pytest.approx(0.418 * np.sqrt(r.contact_force[nose] * modulus / (width * (r0 + h + d2h))))
    assert r.contact_force[nose] > 100.0
    base = 0
    assert law.lift(r.theta[base]) == 0.0
    gamma = lubrication_characteristic(law, r.theta[[base, nose]], r0)
    assert gamma[0] == 1.0 and gamma[1] == pytest.approx((r0 + h + d2h) / (r0 + h))
