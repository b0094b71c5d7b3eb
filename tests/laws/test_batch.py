"""Several laws sampled as one batch (laws.base.batch_derivatives) equal each law sampled on its own, and each
member keeps its own closed-form values."""

import numpy as np

from valvetrain.laws import KurzLaw, PowerPolynomialLaw
from valvetrain.laws.base import batch_derivatives

from laws.test_power_polynomial import LAWS, MM, article


def members(n=24, seed=3):
    """n power-polynomial cams of the 26/27 diesel with a_qd, phi_1, x_d, x_g drawn in the optimiser's box (the
    parameters that admit no cam skipped): one batch key, pieces of different lengths and amplitudes."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        try:
            out.append(article(rng.uniform(60.0, 400.0), rng.uniform(8.0, 45.0), rng.uniform(0.02, 0.98),
                               rng.uniform(0.02, 0.98)))
        except ValueError:
            continue
    return out


def sampled_both_ways(laws, seed=4):
    """(batch, one by one) of the laws each at its own angles: a random count of random angles over and beyond the
    event, the junctions and the nose among them."""
    rng = np.random.default_rng(seed)
    thetas = [np.concatenate([np.sort(rng.uniform(law.start - 0.1, law.end + 0.1, rng.integers(50, 900))),
                              law.breakpoints, [0.0]]) for law in laws]
    member = np.repeat(np.arange(len(laws)), [t.size for t in thetas])
    return (batch_derivatives(laws, np.concatenate(thetas), member),
            np.concatenate([law.derivatives(t) for law, t in zip(laws, thetas, strict=True)], axis=1))


def test_a_batch_of_power_polynomial_cams_equals_each_cam():
    laws = members()
    assert len({law.batch_key() for law in laws}) == 1
    batch, single = sampled_both_ways(laws)
    np.testing.assert_allclose(batch, single, rtol=1e-12, atol=0.0)
    # each member's own closed-form values: the nose lift S_max = lift + S_b with zero velocity, the ramp's end at
    # S_b with the velocity analogue v_qb on the opening flank (the law's parameters, not its pieces)
    d = batch_derivatives(laws, np.array([t for law in laws for t in (0.0, law.valve_opens)]),
                          np.repeat(np.arange(len(laws)), 2))
    np.testing.assert_allclose(d[0, ::2], 21.1 * MM, rtol=1e-12)
    np.testing.assert_allclose(d[1, ::2], 0.0, atol=0.0)
    np.testing.assert_allclose(d[0, 1::2], 0.8 * MM, rtol=1e-12)
    np.testing.assert_allclose(d[1, 1::2], 6.0 * MM, rtol=1e-12)


def test_a_batch_of_mixed_laws_samples_each_group_together():
    """The R2 and R1 readings, other exponents and a Kurz cam (no batch of its own) in one batch."""
    kurz = KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27.0, 6.0, 38.0]), 0.625)
    laws = [*LAWS, kurz, *members(4), LAWS[3]]
    assert len({(type(law), law.batch_key()) for law in laws}) == 5
    batch, single = sampled_both_ways(laws)
    np.testing.assert_allclose(batch, single, rtol=1e-12, atol=0.0)
    assert isinstance(laws[0], PowerPolynomialLaw)
