"""Hypothesis strategies: lift laws drawn from the recommended ranges of the sources."""

import numpy as np
from hypothesis import assume, strategies as st

from valvetrain.laws import (ConstantAccelerationLaw, KurzLaw, PolydyneLaw, PolynomialLaw, TangentLaw,
                             ThreeArcLaw)

DEG = np.pi / 180


@st.composite
def kurz_params(draw):
    """Kurz inputs inside Valve-train practical works (n.d.), work 2's recommended ranges.

    h_T max 4-8 mm; h0 0.25-0.50 mm; w' 0.008-0.022 mm/deg; phi_p0 = (phi_op + 180 + phi_zap)/4 with
    phi_op 20-30, phi_zap 40-78 crank deg (78: the appendix); (Phi2+Phi3)/Phi1 1.5-3.0 (2.4);
    Phi2/Phi3 0.10-0.25 (2.3); Z around the recommended 5/8.
    """
    lift = draw(st.floats(4.0, 8.0)) * 1e-3
    h0 = draw(st.floats(0.25, 0.50)) * 1e-3
    w = draw(st.floats(0.008, 0.022)) * 1e-3 / DEG
    phi_p0 = (draw(st.floats(20.0, 30.0)) + 180.0 + draw(st.floats(40.0, 78.0))) / 4.0 * DEG
    q = draw(st.floats(1.5, 3.0))
    s = draw(st.floats(0.10, 0.25))
    phi1 = phi_p0 / (1.0 + q)
    phi3 = (phi_p0 - phi1) / (1.0 + s)
    return dict(lift=lift, clearance=h0, ramp_velocity=w, phi1=phi1, phi2=s * phi3, phi3=phi3,
                shape_factor=draw(st.floats(0.55, 0.70)))


@st.composite
def polydyne_params(draw):
    """Polydyne inputs: p 6-16 (Valve-train practical works (n.d.), work 3), phi_p0 as for Kurz, with or without a cosine ramp."""
    ramp = draw(st.booleans())
    return dict(lift=draw(st.floats(4.0, 8.0)) * 1e-3,
                main_half_angle=(draw(st.floats(20.0, 30.0)) + 180.0 + draw(st.floats(40.0, 78.0))) / 4.0 * DEG,
                p=draw(st.sampled_from([6, 8, 10, 12, 14, 16])),
                ramp_height=draw(st.floats(0.25, 0.50)) * 1e-3 if ramp else 0.0,
                ramp_velocity=draw(st.floats(0.008, 0.022)) * 1e-3 / DEG if ramp else 0.0)


RAMP_KINDS = st.sampled_from(["cosine", "constant_velocity", "constant_acceleration"])


@st.composite
def constant_acceleration_laws(draw):
    half = draw(st.floats(55.0, 75.0)) * DEG
    f1 = draw(st.floats(0.3, 0.45)) * half
    f3 = draw(st.floats(0.0, 0.3)) * half
    return ConstantAccelerationLaw(draw(st.floats(4.0, 8.0)) * 1e-3, draw(st.floats(0.25, 0.5)) * 1e-3,
                                   draw(st.floats(0.008, 0.022)) * 1e-3 / DEG, f1, half - f1 - f3, f3,
                                   draw(st.floats(0.4, 1.0)), draw(RAMP_KINDS))


@st.composite
def polynomial_laws(draw):
    p = draw(st.integers(4, 12))
    step = draw(st.integers(2, 8))
    n = draw(st.integers(3, 6))
    ramp = draw(st.booleans())
    return PolynomialLaw(draw(st.floats(4.0, 8.0)) * 1e-3, draw(st.floats(55.0, 75.0)) * DEG,
                         [2] + [p + i * step for i in range(n - 1)],
                         draw(st.floats(0.25, 0.5)) * 1e-3 if ramp else 0.0,
                         draw(st.floats(0.008, 0.022)) * 1e-3 / DEG if ramp else 0.0, draw(RAMP_KINDS))


@st.composite
def arc_laws(draw):
    r0, lift, half = draw(st.floats(15.0, 25.0)) * 1e-3, draw(st.floats(5.0, 9.0)) * 1e-3, draw(
        st.floats(55.0, 75.0)) * DEG
    try:
        if draw(st.booleans()):
            return ThreeArcLaw.from_flank_angle(r0, lift, half, draw(st.floats(0.25, 0.45)) * half)
        return TangentLaw(r0, lift, half, draw(st.floats(6.0, 14.0)) * 1e-3)
    except ValueError:  # not every draw admits an arc cam (the spec's validity conditions)
        assume(False)


def laws():
    return st.one_of(kurz_params().map(lambda p: KurzLaw(**p)), polydyne_params().map(lambda p: PolydyneLaw(**p)),
                     constant_acceleration_laws(), polynomial_laws(), arc_laws())
