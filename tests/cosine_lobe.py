"""Two cosine lobes written in closed form, the cam card's hand-calculated case (tests/test_camcard.py works it out):
h(theta) = H/2 (1 + cos(pi theta / Phi)) for |theta| <= Phi, H = 10 mm, Phi = 60 cam deg, no ramp; the intake nose at
+110 crank deg, the exhaust nose at -110 crank deg from the gas-exchange TDC."""

import math

import numpy as np

H, PHI = 10e-3, math.radians(60.0)


class CosineLobe:
    """The duck-typed part of a LiftLaw that the cam card reads, written in closed form."""

    ramp_height = 0.0
    start, end = -PHI, PHI
    valve_opens, valve_closes = -PHI, PHI

    def valve_lift(self, theta, rocker_ratio=1.0):
        return rocker_ratio * H / 2.0 * (1.0 + np.cos(np.pi * np.asarray(theta) / PHI))

    def crossings(self, height):
        theta = PHI / np.pi * math.acos(2.0 * height / H - 1.0)
        return (-theta, theta)


NOSE_IN, NOSE_EX = math.radians(110.0), math.radians(-110.0)
