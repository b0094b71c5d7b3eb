"""A pivoted follower: an end-pivot finger or a centre-pivot rocker whose roller (or curved sliding pad) rides on
the cam and whose curved pad pushes the valve's flat tip.  Its lever ratio changes with the lift.

The follower's law is the VALVE lift law: the cam is synthesised through the linkage (the inverse problem,
:meth:`PivotedFollower.pitch_points`), and the valve lift of a given cam is found by the loop closure
(the forward problem, :meth:`PivotedFollower.lift_on_path`).

Frame and geometry (SI).  The fixed frame has the cam centre at the origin and the follower on +y, as
:mod:`valvetrain.geometry`'s cam frame at theta = 0; a point X of the fixed frame is ``R(-theta) X`` in the cam
frame at camshaft angle theta (the cam turns counter-clockwise as theta grows).  The finger is a rigid body turning
about its pivot P by the angle psi (counter-clockwise, from the +x axis to the pivot-to-roller line); in its own
frame (x from the pivot to the roller centre, y 90 deg counter-clockwise) the roller (or the cam pad's centre of
curvature) is at ``(L_r, 0)`` and the centre of the valve pad's arc at ``(L_p, d_p)``.  The valve opens along
``a = (sin alpha, cos alpha)``; its tip is a plane square to a, touched by the pad of radius rho_p.  With zero lash
(a hydraulic adjuster) the roller sits on the heel circle, ``|C(psi_0)| = R_0 + R_r``.

Notes
-----
Roller centre and pad centre, with :math:`\\mathbf e = (\\cos\\psi, \\sin\\psi)`,
:math:`\\mathbf e_\\perp = (-\\sin\\psi, \\cos\\psi)`:

.. math:: \\mathbf C = \\mathbf P + L_r\\mathbf e, \\qquad \\mathbf B = \\mathbf P + L_p\\mathbf e + d_p\\mathbf e_\\perp

The tip plane is where the pad touches it, :math:`t = \\mathbf B\\cdot\\mathbf a + \\rho_p`, so the valve lift and
the effective valve arm are, with :math:`L_b = \\sqrt{L_p^2 + d_p^2}`, :math:`\\chi = \\psi + \\alpha +
\\operatorname{atan2}(d_p, L_p)`:

.. math:: v = L_b(\\sin\\chi - \\sin\\chi_0), \\qquad G = \\frac{dv}{d\\psi} = L_b\\cos\\chi

(the pad's radius moves the contact point across the tip, not the lift).  The instantaneous ratio of the valve lift
to the roller centre's travel on its arc is :math:`i = G / L_r`; the contact point on the tip is
:math:`\\mathbf B\\cdot\\mathbf a_\\perp` across the valve axis.  The roller centre in the cam frame is the pitch
curve :math:`\\mathbf q(\\theta) = R(-\\theta)\\,\\mathbf C(\\psi(\\theta))`, with :math:`J` the quarter turn:

.. math:: \\mathbf q' = R(-\\theta)\\mathbf W,\\quad \\mathbf W = -J\\mathbf C + \\mathbf C_\\psi\\psi', \\qquad
          \\mathbf q'' = R(-\\theta)(-J\\mathbf W + \\mathbf W'),\\quad
          \\mathbf W' = -J\\mathbf C_\\psi\\psi' + \\mathbf C_{\\psi\\psi}\\psi'^2 + \\mathbf C_\\psi\\psi''

with :math:`\\psi' = v'/G`, :math:`\\psi'' = (v'' + L_b\\sin\\chi\\,\\psi'^2)/G`.  The cam contour is the envelope
of the roller circles, the pitch curve offset inwards by R_r along :math:`\\mathbf n = J\\mathbf q'/|\\mathbf q'|`.
The pressure angle is the angle between the contact normal :math:`J\\mathbf W/|\\mathbf W|` (fixed frame) and the
roller centre's velocity :math:`\\mathbf e_\\perp`; the contact force N that a force F at the valve needs follows from
the virtual work, :math:`N L_r \\cos\\beta = F G`.

References
----------
Norton (2009), the chapter on follower trains (the pivoted roller follower, its loop closure and pressure angle);
Wang (2007), the chapter on valvetrain kinematics (the instantaneous rocker ratio of a finger follower, the contact
travel on the valve tip).
"""

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..locale import NoteText, note
from ..numerics import bracketed_roots
from ..results import quantity
from .base import ROLLER_LAWS, register
from .roller import RollerFollower

KEYS = ("finger_pivot_x_mm", "finger_pivot_y_mm", "finger_roller_arm_mm", "finger_pad_arm_mm", "finger_pad_radius_mm")
"""The cam section's keys a finger needs beside ``roller_radius_mm`` (``finger_pad_drop_mm``,
``finger_valve_angle_deg`` and ``finger_tip_offset_mm`` are 0 where not given)."""



@dataclass(frozen=True)
class FingerKinematics:
    """The linkage of a finger follower over the valve's lift (:mod:`valvetrain.followers.finger`; Norton (2009),
    Wang (2007)).  The ratio is the valve lift per unit travel of the roller centre on its arc about the pivot."""

    rest_ratio: float = quantity("ratio_at_rest", label="lever ratio on the heel circle")
    min_ratio: float = quantity("ratio_min", label="smallest instantaneous lever ratio over the lift")
    max_ratio: float = quantity("ratio_max", label="largest instantaneous lever ratio over the lift")
    nose_ratio: float = quantity("ratio_at_full_lift", label="lever ratio at the full valve lift")
    swing: float = quantity("swing_deg", "deg", "the finger's turn from the heel circle to the full lift")
    roller_lift: float = quantity("roller_lift_mm", "mm",
                                  "lift of the roller centre from the cam centre (the synthesised cam's lift)")
    tip_contact: tuple[float, float] = quantity("tip_contact_mm", "mm",
                                                "where the pad touches the valve tip across its axis: shut, full lift")
    scrub: float = quantity("tip_scrub_mm", "mm", "travel of the contact point across the valve tip over the lift")
    tip_reach: float = quantity("tip_contact_max_mm", "mm",
                                "largest distance of the contact point from the valve axis over the lift")
    rest_pressure_angle: float = quantity("pressure_angle_at_rest_deg", "deg",
                                          "pressure angle on the heel circle (the pivot's offset)")


def _e(psi):
    """e = (cos psi, sin psi) and e_perp = (-sin psi, cos psi), each (2, n)."""
    c, s = np.cos(psi), np.sin(psi)
    return np.stack([c, s]), np.stack([-s, c])


def _quarter(w):
    """J w: w turned by 90 deg counter-clockwise."""
    return np.stack([-w[1], w[0]])


def _turn(w, angle):
    """R(angle) w: w turned by ``angle`` [rad] counter-clockwise."""
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * w[0] - s * w[1], s * w[0] + c * w[1]])


def _cross(a, b):
    """The z component of a x b."""
    return a[0] * b[1] - a[1] * b[0]


@register
@dataclass(frozen=True)
class PivotedFollower(RollerFollower):
    """An end-pivot finger or centre-pivot rocker on the cam through a roller (or curved pad) of radius ``radius``.

    Attributes (SI)
    ---------------
    radius : float
        Radius R_r of the roller, or of the sliding pad's arc on the cam [m].
    pivot_x, pivot_y : float
        The pivot P relative to the cam centre [m] (the follower on +y).
    roller_arm : float
        L_r, pivot to roller centre [m].
    pad_arm, pad_drop : float
        L_p, d_p: the valve pad's centre of curvature in the finger's frame [m] (L_p > L_r: an end-pivot finger;
        L_p < 0: a centre-pivot rocker).
    pad_radius : float
        rho_p, the valve pad's radius [m].
    valve_angle : float
        alpha, the direction the valve opens, from +y clockwise [rad].
    tip_offset : float
        Where the pad touches the valve tip with the valve shut, across the valve axis [m].
    """

    pivot_x: float = 0.0
    pivot_y: float = 0.0
    roller_arm: float = 0.0
    pad_arm: float = 0.0
    pad_drop: float = 0.0
    pad_radius: float = 0.0
    valve_angle: float = 0.0
    tip_offset: float = 0.0
    name = "finger"
    geometric_lever = pivot_axis = switchable = True
    part_keys = ("finger_section_width_mm", "finger_section_height_mm")
    undercut_source = "Shang Hanji (1988), eq. (2.7); Norton (2009)"

    @classmethod
    def admits(cls, law) -> bool:
        """Every law but those drawn for a translating roller (:data:`~valvetrain.followers.base.ROLLER_LAWS`): a
        finger's law is the valve's, not the cam's."""
        return law not in ROLLER_LAWS

    @classmethod
    def from_cam(cls, cam) -> "PivotedFollower":
        """The finger of the cam's SI view (``roller_radius`` and the ``finger_*`` keys in SI)."""
        return cls(cam.roller_radius, cam.finger_pivot_x, cam.finger_pivot_y, cam.finger_roller_arm,
                   cam.finger_pad_arm, cam.finger_pad_drop or 0.0, cam.finger_pad_radius, cam.finger_valve_angle or 0.0,
                   cam.finger_tip_offset or 0.0)

    @classmethod
    def missing_key(cls, cam) -> str | None:
        """The first of ``roller_radius_mm`` and :data:`KEYS` the cam section does not give."""
        missing = [k for k in ("roller_radius_mm",) + KEYS if getattr(cam, k) is None]
        if missing:
            return (f"{missing[0]} is required when follower = \"finger\" (the finger's geometry: "
                    f"{', '.join(('roller_radius_mm',) + KEYS)})")
        return None

    def geometry_problem(self, heel, lift) -> tuple[str, str, str, str] | None:
        """Where the finger cannot sit on the heel circle of radius ``heel`` [m] or cannot give the valve lift ``lift``
        [m]: ``(key of the cam section, its value as given, what is wrong (a note, lengths in mm), joiner)`` for a
        :class:`~valvetrain.specification.messages.Problem`; else None."""
        p = np.hypot(self.pivot_x, self.pivot_y)
        g0 = heel + self.radius
        if not abs(p - self.roller_arm) <= g0 <= p + self.roller_arm:
            return ("finger_roller_arm_mm", f"{self.roller_arm * 1e3:g}",
                    NoteText(note("spec.finger_reach", pivot=p * 1e3, heel=g0 * 1e3)), " ")
        lb = self._pad[0]
        reach = self.reach(heel)
        if lift >= reach:
            return ("finger_valve_angle_deg", f"{np.degrees(self.valve_angle):g}",
                    NoteText(note("spec.finger_pad", pad=lb * 1e3, reach=reach * 1e3, lift=lift * 1e3)), ": ")
        psi = np.linspace(self.base_angle(heel), float(self.angle_of(lift, heel)), 201)
        radius = np.hypot(*self.centre(psi))
        if not np.all(np.diff(radius) > 0.0):
            return ("finger_valve_angle_deg", f"{np.degrees(self.valve_angle):g}",
                    NoteText(note("spec.finger_inwards", start=radius[0] * 1e3, end=radius[-1] * 1e3)), ": ")
        ratio = self.lever_ratio(psi)
        if not np.all(ratio > 0.0):
            return ("finger_pivot_x_mm", f"{self.pivot_x * 1e3:g}",
                    NoteText(note("spec.finger_clockwise", start=ratio[0], end=ratio[-1])), ": ")
        return None

    def reach(self, heel) -> float:
        """The largest valve lift the pad gives [m], L_b (1 - sin chi_0) (the pad's centre square to the valve axis
        from the pivot), with the roller on the heel circle of radius ``heel`` [m]."""
        return self._pad[0] * (1.0 - np.sin(self._chi0(heel)))

    def reach_below(self, heel) -> float:
        """The deepest the pad presses the valve below its shut position [m], L_b (1 + sin chi_0) (the pad's centre
        square to the valve axis from the pivot on the other side), with the roller on the heel circle of radius
        ``heel`` [m]: below it no finger angle gives the valve's position."""
        return self._pad[0] * (1.0 + np.sin(self._chi0(heel)))

    def rest_ratio(self, heel) -> float:
        """The lever ratio i_0 = G(psi_0) / L_r with the roller on the heel circle of radius ``heel`` [m]."""
        return float(self.lever_ratio(np.array(self.base_angle(heel))))

    def force_ratio(self, heel, h, dh) -> float | np.ndarray:
        """N / F = G / (L_r cos beta): the cam's normal force per unit force at the valve (:meth:`contact_force`)."""
        return self.contact_force(1.0, heel, h, dh)

    @property
    def _pivot(self):
        return np.array([self.pivot_x, self.pivot_y])

    @property
    def _pad(self):
        """L_b and the angle of the pad centre from the pivot-to-roller line, atan2(d_p, L_p)."""
        return np.hypot(self.pad_arm, self.pad_drop), np.arctan2(self.pad_drop, self.pad_arm)

    def base_angle(self, heel) -> float:
        """psi_0 [rad]: the finger's angle with the roller on the heel circle of radius ``heel`` [m].

        ``P.e(psi) = (g_0^2 - |P|^2 - L_r^2) / (2 L_r)`` with g_0 = R_0 + R_r; of its two roots the one whose roller
        centre lies higher (on the follower's side, +y).  Refused (ValueError) where the arm cannot reach the circle.
        """
        p = np.hypot(self.pivot_x, self.pivot_y)
        g0 = heel + self.radius
        k = (g0 ** 2 - p ** 2 - self.roller_arm ** 2) / (2.0 * self.roller_arm * p)
        if abs(k) > 1.0:
            raise InputError(f"the finger's roller arm {self.roller_arm:g} m from the pivot at {p:g} m from the cam "
                             f"centre cannot reach the heel circle of the roller centre, radius {g0:g} m")
        roots = np.arctan2(self.pivot_y, self.pivot_x) + np.array([1.0, -1.0]) * np.arccos(k)
        return float(roots[np.argmax(self.pivot_y + self.roller_arm * np.sin(roots))])

    def _chi0(self, heel):
        return self.base_angle(heel) + self.valve_angle + self._pad[1]

    def valve_lift_of(self, psi, heel) -> float | np.ndarray:
        """Valve lift v [m] at the finger angles ``psi`` [rad]: L_b (sin chi - sin chi_0)."""
        lb, beta = self._pad
        return lb * (np.sin(psi + self.valve_angle + beta) - np.sin(self._chi0(heel)))

    def angle_of(self, v, heel) -> float | np.ndarray:
        """The finger angle psi [rad] at the valve lifts ``v`` [m] (:meth:`valve_lift_of` inverted on the branch of
        psi_0); ValueError where the pad cannot reach the lift (|sin chi| > 1)."""
        lb, beta = self._pad
        chi0 = self._chi0(heel)
        s = np.sin(chi0) + np.asarray(v, dtype=float) / lb
        if np.any(np.abs(s) > 1.0):
            raise InputError(f"the valve pad at {lb:g} m from the pivot cannot give a valve lift of "
                             f"{float(np.max(v)):g} m")
        chi = np.arcsin(s)
        return np.where(np.cos(chi0) >= 0.0, chi, np.pi - chi) - self.valve_angle - beta

    def valve_arm(self, psi) -> float | np.ndarray:
        """G = dv/dpsi = L_b cos chi [m/rad]: the effective valve arm."""
        lb, beta = self._pad
        return lb * np.cos(psi + self.valve_angle + beta)

    def lever_ratio(self, psi) -> float | np.ndarray:
        """i = G / L_r [-]: valve lift per unit travel of the roller centre on its arc."""
        return self.valve_arm(psi) / self.roller_arm

    def tip_contact(self, psi, heel) -> float | np.ndarray:
        """The pad's contact point on the valve tip across the valve axis [m], ``tip_offset`` with the valve shut:
        (B(psi) - B(psi_0)) . a_perp + tip_offset = L_b (cos chi - cos chi_0) + tip_offset, a_perp = (cos alpha,
        -sin alpha)."""
        lb, beta = self._pad
        return lb * (np.cos(psi + self.valve_angle + beta) - np.cos(self._chi0(heel))) + self.tip_offset

    def angle_derivatives(self, heel, h, dh, d2h) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """psi, psi' [rad/rad], psi'' [rad/rad^2] from the valve law's h, h', h'' (camshaft angle)."""
        lb, beta = self._pad
        psi = self.angle_of(h, heel)
        arm = self.valve_arm(psi)
        d1 = dh / arm
        d2 = (d2h + lb * np.sin(psi + self.valve_angle + beta) * d1 ** 2) / arm
        return psi, d1, d2

    def reduced_inertia(self, inertia, heel, h) -> float | np.ndarray:
        """J / G(psi)^2 [kg]: the finger's moment of inertia ``inertia`` J [kg m^2] about its pivot reduced to the
        valve at the valve lifts ``h`` [m] (the kinetic energy J psi_dot^2 / 2 = (J / G^2) v_dot^2 / 2; Norton (2009),
        the chapter on the dynamics of follower trains)."""
        return inertia / self.valve_arm(self.angle_of(h, heel)) ** 2

    def reduced_inertia_slope(self, inertia, heel, h) -> float | np.ndarray:
        """d(J / G^2)/dv = 2 J L_b sin(chi) / G^4 [kg/m]: how the reduced inertia (:meth:`reduced_inertia`) changes
        with the valve lift at the lifts ``h`` [m] (G_psi = dG/dpsi = -L_b sin chi and dpsi/dv = 1 / G; Norton (2009),
        the chapter on the dynamics of follower trains)."""
        lb, beta = self._pad
        psi = self.angle_of(h, heel)
        return 2.0 * inertia * lb * np.sin(psi + self.valve_angle + beta) / self.valve_arm(psi) ** 4

    def inertia_force(self, inertia, heel, h, dh, d2h) -> float | np.ndarray:
        """The force at the valve that turns the finger, per camshaft speed squared [N s^2/rad^2 = kg m/rad^2]:
        J psi'' / G, psi'' from the valve law's h, h', h'' (camshaft angle) by :meth:`angle_derivatives`.

        Parameters
        ----------
        inertia : float
            J, the finger's moment of inertia about its pivot [kg m^2].
        heel : float
            Heel radius of the cam [m].
        h, dh, d2h : ndarray
            Valve lift [m] and its first two derivatives [m/rad, m/rad^2] by the camshaft angle.

        Notes
        -----
        The finger is a mass of the variable ratio: its kinetic energy at the valve is m_r(v) v_dot^2 / 2 with
        m_r = J / G(psi(v))^2, and Lagrange's equation gives the force at the valve

        .. math:: F = m_r(v)\\,\\ddot v + \\tfrac12\\,\\frac{dm_r}{dv}\\,\\dot v^2
                    = \\frac{J}{G^2}\\ddot v - \\frac{J\\,G_\\psi}{G^4}\\dot v^2 = \\frac{J\\ddot\\psi}{G},
                  \\qquad G_\\psi = \\frac{dG}{d\\psi} = -L_b\\sin\\chi

        (the last form is the torque J psi_ddot about the pivot taken to the valve by the virtual work F G = T).  At a
        constant camshaft speed omega, v_dot = omega v', v_ddot = omega^2 v'', so F = omega^2 J psi'' / G.

        References
        ----------
        Norton (2009), the chapter on the dynamics of follower trains (the equivalent mass of a linkage of variable
        ratio); Wang (2007), the chapter on valvetrain dynamics (the rocker's inertia at the valve).
        """
        psi, _, d2 = self.angle_derivatives(heel, h, dh, d2h)
        return inertia * d2 / self.valve_arm(psi)

    def travel_acceleration(self, heel, h, dh, d2h) -> float | np.ndarray:
        """L_r psi'' [m/rad^2]: the roller centre's acceleration along its arc per camshaft angle squared."""
        return self.roller_arm * self.angle_derivatives(heel, h, dh, d2h)[2]

    def heel_valve_arm(self, heel) -> float:
        """G(psi_0) [m]: :meth:`valve_arm` with the roller on the heel circle ``heel`` [m]."""
        return float(self.valve_arm(np.array(self.base_angle(heel))))

    def valve_arms(self, lift, heel) -> np.ndarray:
        """G(psi) [m] at the valve lifts ``lift`` [m] on the heel circle ``heel`` [m]."""
        return self.valve_arm(self.angle_of(lift, heel))

    def variable_inertia_force(self, inertia, arm0, heel, h, dh, d2h) -> np.ndarray:
        """J psi'' / G - J h'' / G_0^2 (:meth:`inertia_force`; the train counts J / G_0^2, ``arm0`` = G_0 [m])."""
        return self.inertia_force(inertia, heel, h, dh, d2h) - inertia / arm0 ** 2 * d2h

    def variable_mass(self, inertia, arm0, heel, h) -> np.ndarray:
        """J / G(psi)^2 - J / G_0^2 [kg] (:meth:`reduced_inertia`; ``arm0`` = G_0 [m])."""
        return self.reduced_inertia(inertia, heel, h) - inertia / arm0 ** 2

    def pivot_linkage(self, heel, axis_angle=None) -> tuple:
        """(pivot, roller centre, G(psi_0), L_r, valve angle, adjuster axis) on the heel circle ``heel`` [m], the axis
        ``axis_angle`` [rad] or else the valve's."""
        psi = self.base_angle(heel)
        axis = self.valve_angle if axis_angle is None else axis_angle
        return (np.array([self.pivot_x, self.pivot_y]), self.centre(psi), float(self.valve_arm(psi)), self.roller_arm,
                self.valve_angle, axis)

    def side_force(self, force, heel, h, dh) -> None:
        """None: a finger has no guide, its pivot carries the side load."""
        return None

    def acceleration_range(self, cam, samples=4001) -> tuple[float, float]:
        """The smallest and largest acceleration of the roller centre on its arc at the rated speed [m/s^2]: omega^2
        :meth:`travel_acceleration` over ``samples`` angles of the event of the law stage's ``CamResult`` ``cam``
        (its law is the valve's, not the roller's)."""
        law = cam.law
        theta = np.unique(np.concatenate([np.linspace(law.start, law.end, samples), law.breakpoints]))
        acc = cam.cam_speed ** 2 * self.travel_acceleration(cam.heel_radius, *law.derivatives(theta)[:3])
        return float(acc.min()), float(acc.max())

    def kinematics(self, heel, lift, samples=2001) -> FingerKinematics:
        """The :class:`FingerKinematics` on the heel circle ``heel`` [m] up to the valve lift ``lift`` [m]: its ratio,
        contact and roller centre are functions of the finger's angle alone, sampled at ``samples`` angles from
        psi_0 to the full lift's."""
        psi0, top = self.base_angle(heel), float(self.angle_of(np.array(lift), heel))
        psi = np.linspace(psi0, top, samples)
        ratio, tip = self.lever_ratio(psi), self.tip_contact(psi, heel)
        zero = np.zeros(1)
        return FingerKinematics(self.rest_ratio(heel), float(ratio.min()), float(ratio.max()), float(ratio[-1]),
                                abs(top - psi0), float(np.hypot(*self.centre(psi)).max() - heel - self.radius),
                                (float(tip[0]), float(tip[-1])), float(tip.max() - tip.min()),
                                float(np.abs(tip).max()), float(self.pressure_angle(heel, zero, zero)[0]))

    def centre(self, psi) -> np.ndarray:
        """The roller centre C(psi) in the fixed frame (2, n) [m]."""
        e, _ = _e(psi)
        return self._pivot.reshape((2,) + (1,) * np.ndim(psi)) + self.roller_arm * e

    def _w(self, heel, h, dh, d2h):
        """C, W = -J C + C_psi psi' and W' in the fixed frame, and e_perp."""
        psi, d1, d2 = self.angle_derivatives(heel, h, dh, d2h)
        e, ep = _e(psi)
        c = self.centre(psi)
        c_psi = self.roller_arm * ep
        w = -_quarter(c) + c_psi * d1
        dw = -_quarter(c_psi) * d1 - self.roller_arm * e * d1 ** 2 + c_psi * d2
        return c, w, dw, ep

    def pitch_points(self, theta, heel, h, dh, d2h=None) -> tuple[np.ndarray, np.ndarray]:
        """The roller centre's path in the cam frame: q (2, n) [m] and q' = dq/dtheta (2, n) [m/rad]."""
        c, w, _, _ = self._w(heel, h, dh, np.zeros_like(h) if d2h is None else d2h)
        return _turn(c, -theta), _turn(w, -theta)

    def pitch_radius(self, heel, h, dh, d2h) -> float | np.ndarray:
        """Radius of curvature of the pitch curve [m], positive convex: -|W|^3 / (W x W_theta), W_theta = -J W + W'
        (the curve runs clockwise as theta grows)."""
        _, w, dw, _ = self._w(heel, h, dh, d2h)
        return -np.hypot(*w) ** 3 / _cross(w, -_quarter(w) + dw)

    def contour(self, theta, heel, h, dh) -> np.ndarray:
        """The envelope of the roller circles: q - R_r n, n = J q' / |q'| (2, n) [m]."""
        q, dq = self.pitch_points(theta, heel, h, dh)
        return q - self.radius * _quarter(dq) / np.hypot(*dq)

    def curvature(self, heel, h, dh, d2h) -> float | np.ndarray:
        """rho = rho_pitch - R_r [m] (:meth:`pitch_radius`)."""
        return self.pitch_radius(heel, h, dh, d2h) - self.radius

    def pitch_curve(self, theta, heel, h, dh, d2h) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float]:
        """The roller centre's path, its derivative, radius of curvature and outward normal; depth -R_r."""
        q, dq = self.pitch_points(theta, heel, h, dh, d2h)
        return q, dq, self.pitch_radius(heel, h, dh, d2h), _quarter(dq) / np.hypot(*dq), -self.radius

    def pressure_angle(self, heel, h, dh) -> float | np.ndarray:
        """beta [rad]: the contact normal J W / |W| against the roller centre's velocity e_perp (Norton (2009))."""
        _, w, _, ep = self._w(heel, h, dh, np.zeros_like(h))
        n = _quarter(w)
        dot = np.sum(ep * n, axis=0)
        return np.arctan2(_cross(ep, n) * np.sign(dot), np.abs(dot))

    def contact_force(self, force, heel, h, dh) -> float | np.ndarray:
        """The cam's normal force N [N] that a force ``force`` [N] at the valve needs: F G / (L_r cos beta)."""
        psi = self.angle_of(h, heel)
        return force * self.valve_arm(psi) / (self.roller_arm * np.cos(self.pressure_angle(heel, h, dh)))

    def loads(self, force, heel, h, dh) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The finger's loads under a force ``force`` [N] at the valve (along its axis), at the valve lifts ``h`` [m],
        ``dh`` [m/rad] (``force`` broadcasts against them): the roller's (its bearing's) load N [N], the pivot's
        load |R| [N] and the bending moment at the finger's critical section M [N m].

        Notes
        -----
        The finger in equilibrium under the cam's force N n at the roller centre C (n the contact normal, from the cam
        to the roller), the valve tip's -F a at the pad's contact X = B + rho_p a and the pivot's reaction R:

        .. math:: N = \\frac{F G}{L_r\\cos\\beta}, \\qquad \\mathbf R = F\\mathbf a - N\\mathbf n

        A beam under three forces bends most at the middle one's point, where the moment is that of an end force
        about it: at the roller centre of an end-pivot finger (0 < L_r < L_p), :math:`M = F|(\\mathbf B - \\mathbf
        C)\\times\\mathbf a|`; at the pivot of a centre-pivot rocker (L_p < 0), :math:`M = F|(\\mathbf B - \\mathbf
        P)\\times\\mathbf a| = F|G|`; at the pad of a finger whose valve lies between pivot and roller (0 < L_p <
        L_r), the pivot's reaction about the pad's contact, :math:`M = |(\\mathbf P - \\mathbf X)\\times\\mathbf R|`.

        References
        ----------
        Norton (2009), the chapter on follower trains (the forces of a pivoted follower).
        """
        psi = self.angle_of(h, heel)
        _, w, _, _ = self._w(heel, h, dh, np.zeros_like(h))
        n = _quarter(w) / np.hypot(*w)
        a = np.array([np.sin(self.valve_angle), np.cos(self.valve_angle)])
        normal = self.contact_force(force, heel, h, dh)
        reaction = np.stack([force * a[0] - normal * n[0], force * a[1] - normal * n[1]])
        lb, beta = self._pad
        arm = self.centre(psi) - self._pivot.reshape((2,) + (1,) * np.ndim(psi))
        pad = lb * np.stack([np.cos(psi + beta), np.sin(psi + beta)])
        if self.pad_arm < 0.0:
            moment = force * _cross(pad, a)
        elif self.pad_arm < self.roller_arm:
            moment = _cross(-(pad + self.pad_radius * a.reshape((2,) + (1,) * np.ndim(psi))), reaction)
        else:
            moment = force * _cross(pad - arm, a)
        return normal, np.hypot(*reaction), np.abs(moment)

    def surface_velocities(self, omega, heel, h, dh, d2h, rho) -> tuple[np.ndarray, np.ndarray]:
        """Both surfaces at the contact point's speed along the profile, omega |q'| rho / (rho + R_r): pure rolling
        (as :func:`valvetrain.tribology.roller_follower_velocities`, the pitch speed |q'| of this linkage)."""
        _, w, _, _ = self._w(heel, h, dh, d2h)
        u = omega * np.hypot(*w) * rho / (rho + self.radius)
        return u, u

    def lift_on_path(self, path, theta, base, samples=721) -> np.ndarray:
        """The forward problem: the valve lift [m] at camshaft angles ``theta`` [rad] of a cam given by its contour.

        ``path(tau) -> (E, n)``: contour points and outward unit normals in the cam frame (2, m); the roller centre
        Q = E + R_r n runs on the pitch curve.  At each theta the roller centre is the point of that curve at L_r
        from the pivot R(-theta) P: the root of |Q(tau) - R(-theta) P|^2 - L_r^2 bracketed on ``samples``
        parameters over the turn and a little beyond (``path`` is periodic; of the two roots, the one on the side of
        the line from the pivot through the cam centre where the roller sits on the heel circle, nearest psi_0) and
        refined by :func:`valvetrain.numerics.bracketed_roots`; then psi = angle of R(theta) Q - P and the lift
        from ``base`` [m], the heel radius of the cam (:meth:`valve_lift_of`).
        """
        theta = np.asarray(theta, dtype=float)
        flat = theta.ravel()
        pivot = _turn(self._pivot[:, None] * np.ones_like(flat), -flat)

        def centre(tau):
            e, n = path(tau)
            return e + self.radius * n

        def miss(tau):
            q = centre(tau)
            return np.sum((q - pivot) ** 2, axis=0) - self.roller_arm ** 2

        grid = np.linspace(-np.pi, np.pi, samples)
        grid = np.concatenate([grid[-3:-1] - 2.0 * np.pi, grid, grid[1:3] + 2.0 * np.pi])
        q = centre(grid)
        f = np.sum((q[:, None, :] - pivot[:, :, None]) ** 2, axis=0) - self.roller_arm ** 2
        arm = q[:, None, :] - pivot[:, :, None]
        side = _cross(-pivot[:, :, None], arm)
        psi0 = self.base_angle(base)
        side0 = np.sign(_cross(-self._pivot, self.centre(np.array(psi0)) - self._pivot))
        swing = np.abs(np.angle(np.exp(1j * (np.arctan2(arm[1], arm[0]) + flat[:, None] - psi0))))
        change = (np.sign(f[:, :-1]) != np.sign(f[:, 1:])) & (np.sign(side[:, :-1]) == side0)
        k = np.argmax(np.where(change, -swing[:, :-1], -np.inf), axis=1)
        lo, hi = grid[k], grid[k + 1]
        tau = bracketed_roots(miss, lo, hi, miss(lo), miss(hi))
        c = _turn(centre(tau), flat) - self._pivot[:, None]
        psi = np.arctan2(c[1], c[0])
        psi = psi0 + np.angle(np.exp(1j * (psi - psi0)))
        return self.valve_lift_of(psi, base).reshape(theta.shape)

    def wear_error(self, offset, base, heel, h, dh) -> tuple[float | np.ndarray, float | np.ndarray]:
        """A pitch curve offset outwards by d moves the roller centre d / cos beta along its arc: lift error
        G d / (L_r cos beta) less that of the heel circle grown by ``base``; phase shift d tan beta / |q'|."""
        beta = self.pressure_angle(heel, h, dh)
        psi = self.angle_of(h, heel)
        beta0 = self.pressure_angle(heel, np.zeros(1), np.zeros(1))
        arm0 = self.valve_arm(np.array([self.base_angle(heel)]))
        error = self.valve_arm(psi) * offset / (self.roller_arm * np.cos(beta))
        error0 = arm0 * base / (self.roller_arm * np.cos(beta0))
        _, w, _, _ = self._w(heel, h, dh, np.zeros_like(h))
        return error - error0, offset * np.tan(beta) / np.hypot(*w)
