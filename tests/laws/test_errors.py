"""Errors of the laws (laws/errors.py): a law that cannot be built is refused with its numbers."""

from laws.test_harmonic import _harmonic


def test_a_harmonic_series_that_cannot_follow_its_target_is_refused(refused):
    """N = 20 with 12 junction conditions leaves 9 free coefficients: 0.45 mm off the 6.5 mm target lift."""
    assert "harmonic law: N = 20 harmonics with junction_order = 10 follow the target only to" in \
        refused(_harmonic(20, 10))
