"""An independent reference for the multi-mass pushrod train: its equations of motion written out here from the
model's definition (Shang Hanji (1988), section 3.2; valvetrain.dynamics.models.MultiMassTrain's docstring) and
integrated by scipy's DOP853, each contact state a smooth segment ended by its events (switched with a hysteresis of
:data:`SWITCH_FORCE`), not by the package's kernel nor from its assembled network.

The train (every value at the valve, positive opening): tappet m_t / k^2, pushrod m_p / k^2, rocker J / l_v^2 and
valve m_v with the retainer's end coils m_e and half a coil mass; N coil masses m_s / (N + 1).  The cam pushes the
tappet through c_cam / k^2 past the clearance x0 (compression only); tappet, pushrod, rocker and valve are joined by
held links 2 c_p / k^2, 2 c_p / k^2 and c_r, each damped by 2 zeta sqrt(c m_ab) on the reduced mass of its two ends
(the cam's link on the tappet alone); the N + 1 coil segments (N + 1) K carry the preload F0, damped by
2 zeta_1 (N + 1) K / omega_1 with omega_1 = 2 (N + 1) sqrt(K / m_s) sin(pi / (2 (N + 1))); the seat c_s (compression
only) is damped by 2 zeta_s sqrt(c_s M_valve).  At rest on the base circle the clearance is open and the valve sits
on its seat under the preload and the spring in parallel, y = -F0 / (c_s + K), the drive with it, the coils at their
share of it.
"""

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

SWITCH_FORCE = 1e-6
"""The force [N] past zero at which a contact's state switches (a closed contact opens at -SWITCH_FORCE, an open one
closes at +SWITCH_FORCE): a segment starts strictly on its own side of its events.  Switched at zero, a segment began
at its event function's root as the root finder left it, within about 1e-10 N of zero on either side; where the
contact opened at the crest of its force (the cam's at 7000 rpm) an open segment that began a hair above zero saw no
rising crossing and let the tappet sink 8 mm into the cam, with one BLAS kernel of the processor and not another
(AVX-512's against OPENBLAS_CORETYPE=Haswell).  1e-6 N moves a switch by about 1e-13 s at the 1e7 N/s the forces
change there."""


@dataclass(frozen=True)
class PushrodParts:
    """The parts of a pushrod train (SI; tappet-side values on the tappet side)."""

    tappet_mass: float
    pushrod_mass: float
    rocker_inertia: float
    valve_mass: float
    valve_arm: float
    rocker_ratio: float
    cam_stiffness: float
    pushrod_stiffness: float
    rocker_stiffness: float
    rate: float
    preload: float
    spring_mass: float          # the whole spring, active and end coils
    active_coils: float
    end_coils: float
    coils: int
    lash: float                 # at the valve
    zeta: float = 0.05
    coil_zeta: float = 0.02
    seat_stiffness: float = 2e8
    seat_zeta: float = 0.4


class PushrodReference:
    """The equations of motion of :class:`PushrodParts` and their integration."""

    def __init__(self, law, parts):
        p = self.p = parts
        k = p.rocker_ratio
        n = p.coils
        m_s = p.spring_mass * p.active_coils / (p.active_coils + p.end_coils)
        m_e = p.spring_mass * p.end_coils / 2.0 / (p.active_coils + p.end_coils)
        self.mass = np.array([p.tappet_mass / k**2, p.pushrod_mass / k**2, p.rocker_inertia / p.valve_arm**2,
                              p.valve_mass + m_e + m_s / (2 * (n + 1))] + [m_s / (n + 1)] * n)
        self.links = np.array([2 * p.pushrod_stiffness / k**2, 2 * p.pushrod_stiffness / k**2, p.rocker_stiffness])
        m = self.mass
        pairs = np.array([m[i] * m[i + 1] / (m[i] + m[i + 1]) for i in range(3)])
        self.link_damping = 2 * p.zeta * np.sqrt(self.links * pairs)
        self.cam = p.cam_stiffness / k**2
        self.cam_damping = 2 * p.zeta * np.sqrt(self.cam * m[0])
        self.segment = (n + 1) * p.rate
        omega1 = 2 * (n + 1) * np.sqrt(p.rate / m_s) * np.sin(np.pi / (2 * (n + 1)))
        self.segment_damping = 2 * p.coil_zeta * (n + 1) * p.rate / omega1
        self.seat_damping = 2 * p.seat_zeta * np.sqrt(p.seat_stiffness * m[3])
        self.law = law

    def rest(self):
        """The state at rest on the base circle (positions, then velocities)."""
        p = self.p
        y = -p.preload / (p.seat_stiffness + p.rate)
        n = p.coils
        x = np.concatenate([np.full(4, y), y * (n + 1 - np.arange(1, n + 1)) / (n + 1)])
        return np.concatenate([x, np.zeros(x.size)])

    def cam_motion(self, t, omega):
        d = self.law.derivatives(np.array([(omega * t) % (2 * np.pi) - np.pi]))[:2, 0] * self.p.rocker_ratio
        return d[0], omega * d[1]

    def contacts(self, t, s, omega):
        """The force of the cam contact and of the seat were they closed [N], and their closing functions
        min(c delta, force) [N], positive exactly where the contact carries a force (delta > 0 and force > 0)."""
        n = self.mass.size
        x, v = s[:n], s[n:]
        u, du = self.cam_motion(t, omega)
        cam, seat = u - self.p.lash - x[0], -x[3]
        forces = (self.cam * cam + self.cam_damping * (du - v[0]),
                  self.p.seat_stiffness * seat - self.seat_damping * v[3])
        return forces, (min(self.cam * cam, forces[0]), min(self.p.seat_stiffness * seat, forces[1]))

    def rhs(self, t, s, omega, closed):
        n = self.mass.size
        x, v = s[:n], s[n:]
        f = np.zeros(n)
        chain = self.links * (x[:3] - x[1:4]) + self.link_damping * (v[:3] - v[1:4])
        f[1:4] += chain
        f[:3] -= chain
        coil = np.full(n - 3, self.p.preload)                 # segment j from node 3 + j to the next (the head: 0)
        coil[:-1] += self.segment * (x[3:-1] - x[4:]) + self.segment_damping * (v[3:-1] - v[4:])
        coil[-1] += self.segment * x[-1] + self.segment_damping * v[-1]
        f[3:] -= coil
        f[4:] += coil[:-1]
        cam, seat = self.contacts(t, s, omega)[0]
        f[0] += cam if closed[0] else 0.0
        f[3] += seat if closed[1] else 0.0
        return np.concatenate([v, f / self.mass])

    def run(self, omega, revolutions, angles):
        """Integrate ``revolutions`` camshaft revolutions from rest at the angle -pi from the nose.

        Returns the valve lift [m], the tappet's position [m] and the cam contact force at the cam [N] at the camshaft
        ``angles`` [rad from the nose, -pi...pi] of the last revolution, and the valve's velocity at each downward
        seat crossing of that revolution (angle [rad], velocity [m/s]) located by the event finder."""
        period = 2 * np.pi / omega
        t0, t_end = 0.0, revolutions * period
        state = self.rest()
        closed = [False, True]
        pieces, seatings = [], []
        while t0 < t_end:
            events = []
            for j in range(2):
                def event(t, s, *args, j=j, side=1.0 if closed[j] else -1.0):
                    return self.contacts(t, s, omega)[1][j] + side * SWITCH_FORCE
                event.terminal = True
                event.direction = -1.0 if closed[j] else 1.0
                events.append(event)
            sol = solve_ivp(self.rhs, (t0, t_end), state, method="DOP853", rtol=1e-10, atol=1e-13,
                            max_step=period / 720, args=(omega, tuple(closed)), events=events, dense_output=True)
            pieces.append((sol.t[0], sol.t[-1], sol.sol, tuple(closed)))
            if sol.status != 1:
                break
            hit = [j for j in range(2) if sol.t_events[j].size]
            j = min(hit, key=lambda i: sol.t_events[i][0])
            t0, state = sol.t_events[j][0], sol.y_events[j][0]
            if j == 1 and not closed[1] and t0 >= t_end - period:
                seatings.append(((omega * t0) % (2 * np.pi) - np.pi, state[self.mass.size + 3]))
            closed[j] = not closed[j]
        times = t_end - period + (np.asarray(angles) + np.pi) / omega
        n = self.mass.size
        lift, tappet, force = (np.empty(times.size) for _ in range(3))
        for a, b, dense, on in pieces:
            inside = (times >= a) & (times <= b)
            for i in np.flatnonzero(inside):
                s = dense(times[i])
                lift[i], tappet[i] = s[3], s[0]
                force[i] = self.contacts(times[i], s, omega)[0][0] * self.p.rocker_ratio if on[0] else 0.0
        return lift, tappet, force, seatings
