"""Combined-function cams: a sequence of acceleration segments joined with continuous acceleration,
closed at the nose by a linear system (Shang Hanji (1988), section 2.5; the general mechanism, derived in this package).

Shang's FB2 and MFB2 cams are combined-function cams whose definitions are not in any
available source; this module provides the general mechanism they
belong to, and the Kurz cam of Valve-train practical works (n.d.) is one instance of it (see the tests).

Each segment's acceleration (with respect to the camshaft angle) is a linear
combination of known shape functions with unknown amplitudes.  Lift and velocity follow
by exact integration from the ramp's end (h0, v0, zero acceleration).  The unknowns solve:

* continuity of the acceleration at every junction (the ramp's end included);
* zero velocity and the required lift at the nose;
* optional ratios a(end of segment i) = r a(nose) (Kurz's Z).
"""

import numpy as np

from ..errors import InputError
from ..locale import cited, note
from .base import RampedLaw, SymmetricLaw, segment_index
from .errors import LawError
from .ramps import make_ramp

# shape name -> list of basis functions of the local coordinate t = x / L in [0, 1]:
# (acceleration, its first integral, its second integral, its derivative), each scaled to the segment length L.
SHAPES = ("half_sine", "quarter_sine", "quarter_cosine", "constant", "linear", "parabola_to_nose")


def _basis(shape, x, length):
    """Acceleration basis functions of a segment and their integrals, shape (k, 4, n): a, integral of a,
    double integral of a, derivative of a with respect to the angle (jerk)."""
    t = x / length
    L = length
    if shape == "half_sine":          # zero at both ends, maximum in the middle
        w = np.pi / L
        return np.array([[np.sin(w * x), (1 - np.cos(w * x)) / w, (x - np.sin(w * x) / w) / w, w * np.cos(w * x)]])
    if shape == "quarter_sine":       # zero at the start, extremum at the end
        w = np.pi / (2 * L)
        return np.array([[np.sin(w * x), (1 - np.cos(w * x)) / w, (x - np.sin(w * x) / w) / w, w * np.cos(w * x)]])
    if shape == "quarter_cosine":     # extremum at the start, zero at the end
        w = np.pi / (2 * L)
        return np.array([[np.cos(w * x), np.sin(w * x) / w, (1 - np.cos(w * x)) / w**2, -w * np.sin(w * x)]])
    if shape == "constant":
        one = np.ones_like(x)
        return np.array([[one, x, x * x / 2, 0 * x]])
    if shape == "linear":             # two unknowns: a = A + B t
        one = np.ones_like(x)
        return np.array([[one, x, x * x / 2, 0 * x], [t, x * t / 2, x * x * t / 6, one / L]])
    if shape == "parabola_to_nose":   # a = A + B (1 - t)^2: even about the nose, zero jerk there (Kurz Phi3)
        one = np.ones_like(x)
        u = 1 - t
        return np.array([[one, x, x * x / 2, 0 * x],
                         [u**2, L * (1 - u**3) / 3, L * L * (u**4 - 1 + 4 * t) / 12, -2 * u / L]])
    raise InputError(f"segment shape {shape!r}: allowed {', '.join(SHAPES)}")


class CombinedLaw(RampedLaw, SymmetricLaw):
    """A combined-function cam built from acceleration segments.

    Parameters
    ----------
    lift : float
        Tappet lift above the ramp h_T max [m].
    ramp_height, ramp_velocity : float
        Ramp height h0 [m] and end velocity [m/rad].
    segments : sequence of (str, float)
        (shape, length [rad]) from the ramp's end to the nose; shapes of :data:`SHAPES`.
    ratios : sequence of (int, float)
        Extra conditions a(end of segment i) = r a(nose) (segment index from 0).
    ramp_kind, ramp_fraction
        The ramp (see :mod:`.ramps`).

    Raises
    ------
    ValueError
        When the conditions do not fix the amplitudes (a singular or non-square system:
        the number of unknown amplitudes must equal the junction conditions the shapes do
        not meet by themselves + 2 + ratios).

    Examples
    --------
    Kurz's cam of the appendix of Valve-train practical works (n.d.) rebuilt: half-sine, quarter-sine and a parabola to the
    nose with Z = 5/8 give c12 (pi/Phi1)^2 as the first amplitude (0.584172 x 44.444 = 25.963 mm/rad^2).

    >>> law = CombinedLaw(6.25, 0.25, 0.02 * 180 / np.pi, [("half_sine", np.radians(27)), ("quarter_sine",
    ...                   np.radians(6)), ("parabola_to_nose", np.radians(38))], ratios=[(1, 0.625)])
    >>> round(float(law.amplitude(0)[0]), 3)
    25.963

    References
    ----------
    Shang Hanji (1988), section 2.5 (names the FB2/MFB2 cams, whose definitions are not available); the
    general mechanism is derived in this package.
    """

    name = "combined"
    source = cited("Shang Hanji (1988), section 2.5", note("source.combined"))

    def __init__(self, lift, ramp_height, ramp_velocity, segments, ratios=(), ramp_kind="cosine", ramp_fraction=0.5):
        self._lift = float(lift)
        self.ramp = make_ramp(ramp_kind, ramp_height, ramp_velocity, ramp_fraction)
        self.shapes = [s for s, _ in segments]
        self.lengths = np.array([float(L) for _, L in segments])
        if np.any(self.lengths <= 0):
            raise InputError("combined law: every segment length must be positive")
        self._edges = np.concatenate([[0.0, self.ramp.length], self.ramp.length + np.cumsum(self.lengths)])
        self._amplitudes = self._solve(list(ratios))

    def _segment_basis(self, i, x):
        return _basis(self.shapes[i], np.asarray(x, dtype=float), self.lengths[i])

    def _solve(self, ratios):
        sizes = [self._segment_basis(i, np.zeros(1)).shape[0] for i in range(len(self.shapes))]
        offsets = np.concatenate([[0], np.cumsum(sizes)])
        n = int(offsets[-1])
        rows, rhs = [], []
        ends = [self._segment_basis(i, np.array([self.lengths[i]]))[:, :, 0] for i in range(len(self.shapes))]
        starts = [self._segment_basis(i, np.zeros(1))[:, :, 0] for i in range(len(self.shapes))]
        # acceleration continuity: ramp end (zero) -> segment 0, and every junction
        row = np.zeros(n)
        row[offsets[0]:offsets[1]] = starts[0][:, 0]
        rows.append(row)
        rhs.append(0.0)
        for i in range(len(self.shapes) - 1):
            row = np.zeros(n)
            row[offsets[i]:offsets[i + 1]] = ends[i][:, 0]
            row[offsets[i + 1]:offsets[i + 2]] = -starts[i + 1][:, 0]
            rows.append(row)
            rhs.append(0.0)
        # velocity zero and lift h0 + h at the nose: v_nose = v0 + sum of integrals; h_nose = h0 + v0 T + ...
        total = float(self.lengths.sum())
        vrow, hrow = np.zeros(n), np.zeros(n)
        for i in range(len(self.shapes)):
            after = float(self.lengths[i + 1:].sum())
            vrow[offsets[i]:offsets[i + 1]] = ends[i][:, 1]
            hrow[offsets[i]:offsets[i + 1]] = ends[i][:, 2] + ends[i][:, 1] * after
        rows += [vrow, hrow]
        rhs += [-self.ramp.end_velocity, self._lift - self.ramp.end_velocity * total]
        nose = np.zeros(n)
        nose[offsets[-2]:offsets[-1]] = ends[-1][:, 0]
        for i, r in ratios:
            row = np.zeros(n)
            row[offsets[i]:offsets[i + 1]] = ends[i][:, 0]
            rows.append(row - r * nose)
            rhs.append(0.0)
        a, b = np.array(rows), np.array(rhs)
        needed = np.any(np.abs(a) > 1e-14 * np.abs(a).max(), axis=1)   # shapes meet some junctions by themselves
        a, b = a[needed], b[needed]
        if a.shape[0] != n:
            raise LawError("combined_conditions", unknowns=n, conditions=a.shape[0])
        try:
            x = np.linalg.solve(a, b)
        except np.linalg.LinAlgError:
            raise LawError("combined_singular") from None
        self._offsets = offsets
        return x

    def amplitude(self, i) -> np.ndarray:
        """Amplitudes of segment i [m/rad^2]."""
        return self._amplitudes[self._offsets[i]:self._offsets[i + 1]]

    @property
    def main_half_angle(self) -> float:
        return float(self.lengths.sum())

    @property
    def half_angle(self) -> float:
        return float(self._edges[-1])

    def _rise_segments(self):
        e = self._edges
        return [("ramp", e[0], e[1])] + [(f"S{i + 1} {s}", e[i + 1], e[i + 2]) for i, s in enumerate(self.shapes)]

    def _rise(self, phi):
        out = np.empty((4, phi.size))
        seg = segment_index(phi, self._edges)
        ramp = seg == 0
        out[:, ramp] = self.ramp.evaluate(phi[ramp])
        h, v = self.ramp.height, self.ramp.end_velocity
        for i in range(len(self.shapes)):
            m = seg == i + 1
            x = phi[m] - self._edges[i + 1]
            b = self._segment_basis(i, x)
            amp = self.amplitude(i)[:, None]
            a_, ia, iia, ja = ((amp * b[:, k]).sum(0) for k in range(4))
            out[:, m] = [h + v * x + iia, v + ia, a_, ja]
            end = self._segment_basis(i, np.array([self.lengths[i]]))[:, :, 0]
            amp0 = self.amplitude(i)
            h, v = h + v * self.lengths[i] + amp0 @ end[:, 2], v + amp0 @ end[:, 1]
        return out

    def coefficients(self) -> dict:
        """Amplitudes of every segment [mm/rad^2] keyed by segment."""
        return {f"S{i + 1}_{s}": [float(a) * 1e3 for a in self.amplitude(i)] for i, s in enumerate(self.shapes)}
