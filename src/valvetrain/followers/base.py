"""The follower interface: what a cam follower is to the rest of the package, and the registry by name.

A follower is the part that touches the cam and turns its lift into the motion of the train.  Every place
that depends on the kind of follower (the contour and its curvature in the profile stage, the undercut and
pressure-angle checks, the Hertz stress in the strength stage, the synthesis and the dynamics, the grinding of
the cam, the figures) asks the follower object through the methods of :class:`Follower`, never its name.  The
specification's ``[valves.NAME.cam] follower = "NAME"`` selects the class registered under that name
(:data:`REGISTRY`, :func:`register`), and :func:`follower_of` builds it from the cam's SI view (or the law
stage's ``CamResult``).

For the author of a new follower (a finger follower, a follower on a lash adjuster)
-------------------------------------------------------------------------------------
Write one module in this package with a subclass of :class:`Follower` decorated ``@register``, import it in
``followers/__init__.py``, and give it:

- ``name`` (the ``follower`` value of the specification) and the class attributes below;
- :meth:`from_cam`: the instance from the cam's SI view (SI lengths; a key the follower needs that the cam
  section lacks is a new pydantic field of ``specification/cams.py`` and a README row, and :meth:`missing_key`
  names it when it is absent);
- the geometry, each a pure function of SI arrays of equal shape: camshaft angle ``theta`` [rad from the nose,
  camshaft], the law's lift ``h`` [m] and its derivatives ``dh`` [m/rad], ``d2h`` [m/rad^2] at those angles,
  and the cam's heel radius ``heel`` [m] (the radius the law's lift starts from).  The cam frame is that of
  :mod:`valvetrain.geometry`: the follower's line of action along ``u = (sin theta, cos theta)``, nose on +y.

  ============================  =======================================================================
  :meth:`contour`               contact points, shape (2, n) [m]
  :meth:`curvature`             radius of curvature of the cam profile rho [m] (negative: concave)
  :meth:`pitch_curve`           the curve the contour is an offset of, for grinding and the figure
  :meth:`pressure_angle`        angle between the contact normal and the line of action [rad]
  :meth:`contact_offset`        distance of the contact point from the line of action [m]
  :meth:`convex_radius`         rho where the profile is convex to the follower, +inf elsewhere [m]
  :meth:`concave`               mask of the concave stretches it follows
  :meth:`undercut`              whether the smallest convex radius makes the profile unfollowable
  :meth:`line_contact`          mask of the angles with Hertz line contact
  :meth:`contact_curvature`     1/rho_1 + 1/rho_2 of the contact [1/m] (the follower's own radius in it)
  :meth:`contact_stress`        Hertz line stress under a cam force [Pa]
  :meth:`lift_on_path`          the follower's lift read off a cam given by a wheel-centre path (grinding)
  :meth:`wear_error`            first-order lift error of a cam ground by a worn wheel
  :meth:`lubrication`           the film characteristic of the contact, or None where none is defined
  :meth:`surface_velocities`    the velocities of cam and follower surfaces relative to the contact [m/s]
  :meth:`ratio`                 the follower's own lever ratio as a function of the lift [-]
  :meth:`rest_ratio`            its lever ratio on the heel circle [-] (a lash adjuster's motion ratio)
  :meth:`force_ratio`           the cam's force per unit force along the law's lift [-]
  :meth:`travel_acceleration`   the follower's acceleration on the cam per camshaft angle squared [m/rad^2]
  :meth:`acceleration_range`    its extremes at the rated speed [m/s^2] (the tappet-acceleration checks)
  :meth:`profile_contact`       the profile stage's contact record (flat: contact offset; roller: pressure angle)
  :meth:`profile_checks`        the checks of that record (a roller's largest pressure angle)
  :meth:`limited_contact`       what a cam synthesis limits in it (a roller's pressure angle, concave radius), or None
  :meth:`admits`                whether a cam of a lift law can drive the follower (the tangent cam: a roller's)
  :meth:`kinematics`            the record of a linkage over the lift (a finger's), or None
  :meth:`geometry_problem`      what makes a linkage unworkable for a lift, or None
  :meth:`rolling_losses`        a roller's slip and rolling resistance in the friction torque
  :meth:`face_offset`           a sliding face's contact offset (edge loading, the tappet's side pressure), or None
  :meth:`side_force`            a roller's side force on its carrier, or None
  :meth:`loads`                 a lever's loads (bearing, pivot, bending moment), or None
  :meth:`heel_valve_arm`        a lever's own valve arm on the heel circle (and :meth:`valve_arms` over the lift)
  :meth:`variable_mass`         what its inertia adds by a varying ratio (and :meth:`variable_inertia_force`)
  :meth:`pivot_linkage`         the linkage of a lash adjuster at its own pivot, or None
  ============================  =======================================================================

  A follower whose lever ratio varies with the lift may return it from :meth:`ratio`; ``LiftLaw.valve_lift``
  multiplies the valve's rocker ratio by it.  The finger (:mod:`.finger`) takes the other way: its law is the
  valve's (``geometric_lever``, rocker ratio 1), its geometry methods synthesise the cam through its linkage, and it
  brings the stages its ratio where they reduce through the drive: :meth:`force_ratio` (the cam's normal force per
  unit force at the valve, for the strength and lubrication loads) and :meth:`rest_ratio` (the lash adjuster's motion
  ratio, the dynamics' camshaft link, the rocker-ratio band).  Today's other followers translate on their line of
  action: ratio 1, contact on the line u.

- in the dynamics network the follower contributes its contact (the stress under the simulated force,
  :meth:`contact_stress`, and the film, :meth:`lubrication`); its mass is today the tappet's of the layout's
  train (``[drive.masses] tappet_kg``, :mod:`valvetrain.layouts`).  A follower with an inertia of its own (a
  finger about its pivot) adds its node where the layout's train is built (``design/dynamics.py``,
  ``_multi_train``), reading its mass from ``[drive.masses]``; a reduced inertia that changes with the lift is
  that node's :class:`~valvetrain.dynamics.models.VariableMass` (``design/dynamics.py``, ``finger_mass``).

- the stages, the synthesis, the report and the specification never read ``rolling``: what differs between a
  rolling and a sliding follower (its profile record and checks, what a synthesis limits, its rolling losses, its
  side load, the laws it admits) is a method here; what the specification's rules need of a follower is a class
  attribute named by the rule's question (``geometric_lever``, ``pivot_axis``, ``switchable``).

Methods return numpy arrays (floats where the argument is a scalar); none of them mutates its arguments or
the follower, and they hold no state beyond the follower's dimensions.  Each follower's module has its tests,
against hand calculations, in the file of its name under ``tests/followers/`` (``test_flat.py``,
``test_roller.py``); a new follower's tests go beside them.
"""

from typing import ClassVar

import numpy as np

from .. import strength

REGISTRY = {}
"""``follower`` name -> its :class:`Follower` subclass, in the order of registration."""


ROLLER_LAWS = ("tangent",)
"""The lift laws whose cam is drawn for a roller translating on its line: the tangent cam's straight flanks and nose
arc (Kolchin and Demidov (1980)); a flat face on them is degenerate."""


def register(cls) -> type:
    """Class decorator: add a follower class to :data:`REGISTRY` under its ``name``."""
    REGISTRY[cls.name] = cls
    return cls


def follower_of(cam) -> "Follower":
    """The follower of a cam: the class registered under ``cam.follower`` built by its :meth:`Follower.from_cam`.

    ``cam`` is the cam's SI view or the law stage's ``CamResult`` (attributes ``follower`` and the follower's
    dimensions in SI, e.g. ``roller_radius`` [m])."""
    return REGISTRY[cam.follower].from_cam(cam)


class Follower:
    """A cam follower: the geometry and contact of the cam as this follower sees it (SI throughout).

    Class attributes
    ----------------
    name : str
        The specification's ``follower`` value.
    rolling : bool
        True where a roller touches the cam: a pitch curve apart from the contour, a pressure angle, concave
        stretches the roller can follow (and a side force on its carrier); False for a sliding face.
    radius : float
        The follower's own radius of curvature at the contact [m] (inf for a flat face).
    undercut_code, undercut_source : str
        The code (:mod:`valvetrain.locale`) and the source of the undercut check of the profile (a failure where
        :meth:`undercut`).
    geometric_lever : bool
        True where the follower's own geometry is the lever between cam and valve (a finger): its law is the valve's
        lift and the cam is synthesised through its linkage, so the specification's ``rocker_ratio`` is 1, its valve
        arm is its geometry's (no ``[drive] valve_arm_mm``) and its inertia about its pivot is the ``rocker``
        layout's; False where the law is the follower's own lift and the drive's rocker ratio takes it to the valve.
    pivot_axis : bool
        True where the follower turns about a pivot its geometry places (a finger), so that a lash adjuster at that
        pivot may be given an axis of its own (``[lash_adjuster] axis_angle_deg``, :meth:`pivot_linkage`).
    switchable : bool
        True where the follower can be the outer body of a switching follower (``[valves.NAME.switching]``): an
        inner arm of its own carries its roller (a finger).
    part_keys : tuple of str
        The ``[valves.NAME.parts]`` keys the follower reads (a flat face's diameter, a finger's section): given with
        another follower, they are a warning of the design (:func:`valvetrain.layouts.unused_part_keys`).
    """

    name: ClassVar[str]
    rolling: ClassVar[bool] = False
    radius: float = np.inf
    undercut_code: ClassVar[str]
    undercut_source: ClassVar[str]
    geometric_lever: ClassVar[bool] = False
    pivot_axis: ClassVar[bool] = False
    switchable: ClassVar[bool] = False
    part_keys: ClassVar[tuple[str, ...]] = ()

    @classmethod
    def from_cam(cls, cam) -> "Follower":
        """The follower of a cam's SI view (or ``CamResult``)."""
        return cls()

    @classmethod
    def missing_key(cls, cam) -> str | None:
        """The message for a key of the cam section (``[valves.NAME.cam]``, in its units) that this follower needs
        and that is not given, or None."""
        return None

    def contour(self, theta, heel, h, dh) -> np.ndarray:
        """Contact points of the cam contour, shape (2, n) [m], at camshaft angles ``theta`` [rad]."""
        raise NotImplementedError

    def curvature(self, heel, h, dh, d2h) -> float | np.ndarray:
        """Radius of curvature of the cam profile [m]: positive convex, negative concave, inf straight."""
        raise NotImplementedError

    def pitch_curve(self, theta, heel, h, dh, d2h) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float]:
        """The curve the contour is the inner offset of by ``depth``: ``(points (2, n) [m], d points / d theta
        (2, n) [m/rad], its radius of curvature [m], outward unit normal (2, n), depth [m])`` (for a roller its
        centre's path, depth -R_r; for a flat face the contour itself, depth 0)."""
        raise NotImplementedError

    def pressure_angle(self, heel, h, dh) -> float | np.ndarray:
        """Angle between the contact normal and the follower's line of action [rad]."""
        raise NotImplementedError

    def contact_offset(self, dh) -> float | np.ndarray:
        """Distance of the contact point from the follower's line of action [m]."""
        raise NotImplementedError

    def convex_radius(self, rho) -> float | np.ndarray:
        """The profile radius ``rho`` [m] where the profile is convex to the follower, +inf elsewhere."""
        raise NotImplementedError

    def concave(self, rho) -> np.ndarray:
        """Mask of the profile radii ``rho`` [m] of concave stretches the follower follows (not an undercut)."""
        raise NotImplementedError

    def undercut(self, rho_min) -> bool:
        """Whether a profile whose smallest convex radius is ``rho_min`` [m] cannot be followed (bool)."""
        raise NotImplementedError

    def line_contact(self, rho) -> np.ndarray:
        """Mask of the profile radii ``rho`` [m] at which cam and follower touch along a line (Hertz)."""
        raise NotImplementedError

    def contact_curvature(self, rho) -> float | np.ndarray:
        """1/rho_1 + 1/rho_2 of the contact [1/m]: the profile's curvature and the follower's own.

        References
        ----------
        Shang Hanji (1988), eq. (2.11); Valve-train practical works (n.d.), eqs. (7.4)-(7.5).
        """
        return 1.0 / rho + (0.0 if np.isinf(self.radius) else 1.0 / self.radius)

    def contact_stress(self, force, rho, width, modulus) -> float | np.ndarray:
        """Hertz line stress between cam and follower [Pa]; 0 where the profile gives no line contact.

        Parameters
        ----------
        force : ndarray
            Cam force [N] (a negative force is no load).
        rho : ndarray
            Profile radius of curvature [m], broadcastable against ``force``.
        width, modulus : float
            Contact (cam) width b [m] and effective modulus E_m [Pa].

        Notes
        -----
        .. math:: \\sigma = 0.418\\sqrt{\\frac{P E_m}{b}\\left(\\frac1{\\rho_1} + \\frac1{\\rho_2}\\right)}

        Line contact needs a convex profile, or a concave one wider than a roller (:meth:`line_contact`);
        elsewhere (an undercut) the smallest-radius check fails instead.

        References
        ----------
        Shang Hanji (1988), eqs. (2.5), (2.11); Valve-train practical works (n.d.), eqs. (7.4)-(7.5).
        """
        rho = np.asarray(rho, dtype=float)
        contact = self.line_contact(rho)
        curvature = self.contact_curvature(np.where(contact, rho, 1.0))
        sigma = np.asarray(strength.hertz_line_stress(force, width, np.where(contact, curvature, 1.0), modulus))
        np.copyto(sigma, 0.0, where=~contact)     # in place: a load map's array is large (hertz_line_stress)
        return sigma

    def lift_on_path(self, path, theta, base) -> np.ndarray:
        """The follower's lift [m] at camshaft angles ``theta`` [rad] on a cam enveloped by a wheel.

        ``path(tau) -> (E, n)`` gives, at the path parameter tau (the design cam's angle), the envelope's point E
        (2, n) [m] and its outward unit normal n; ``base`` [m] is the heel radius the lift is measured from.
        Solved on the path (by inverting an angle of it), not interpolated."""
        raise NotImplementedError

    def wear_error(self, offset, base, heel, h, dh) -> tuple[float | np.ndarray, float | np.ndarray]:
        """First-order lift error [m] and phase shift [rad] of a cam offset outwards by ``offset`` [m] (a worn
        wheel's cam) whose heel circle grew by ``base`` [m], at the design lift ``h``, ``dh``."""
        raise NotImplementedError

    def lubrication(self, heel, h, rho) -> float | np.ndarray | None:
        """The hydrodynamic lubrication characteristic of the contact [-], or None where no source defines one."""
        return None

    def surface_velocities(self, omega, heel, h, dh, d2h, rho) -> tuple[np.ndarray, np.ndarray]:
        """Velocities of the cam's and the follower's surface relative to the contact point along the common
        tangent [m/s], at camshaft speed ``omega`` [rad/s] and the profile radius ``rho`` [m] (:meth:`curvature`):
        their mean entrains the oil film, their difference slides (:mod:`valvetrain.tribology`)."""
        raise NotImplementedError

    def rest_ratio(self, heel) -> float:
        """The follower's own lever ratio with the follower on the heel circle of radius ``heel`` [m] [-]: 1 for a
        follower translating on its line of action."""
        return 1.0

    def force_ratio(self, heel, h, dh) -> np.ndarray:
        """The force the cam carries per unit force along the law's lift [-] (1 for a translating follower, whose law
        is its own lift; a finger's law is the valve's, and its cam carries G / (L_r cos beta) of the valve force)."""
        return np.ones_like(np.asarray(h, dtype=float))

    def face_offset(self, dh) -> np.ndarray | None:
        """The distance of the contact from the axis of a face sliding on the cam [m] at the law's ``dh`` [m/rad]
        (a flat face's edge loading and its tappet's side pressure), or None where no face slides on the cam."""
        return None

    def side_force(self, force, heel, h, dh) -> np.ndarray | None:
        """The side force on the follower's carrier under the cam force ``force`` [N] at the law's ``h`` [m],
        ``dh`` [m/rad] on the heel circle ``heel`` [m], or None where none is reported (a flat face: its offset
        loads its guide, :meth:`face_offset`)."""
        return None

    def loads(self, force, heel, h, dh) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """The loads of a follower that is a lever (its bearing's, its pivot's, its bending moment) under the force
        ``force`` [N] at the valve, or None: a translating follower is no lever
        (:meth:`~valvetrain.followers.PivotedFollower.loads`)."""
        return None

    def heel_valve_arm(self, heel) -> float | None:
        """The valve-side arm of the follower's own lever on the heel circle ``heel`` [m] (a finger's G(psi_0)), or
        None: a translating follower has none (the layout's ``[drive] valve_arm_mm`` is the rocker's)."""
        return None

    def valve_arms(self, lift, heel) -> np.ndarray | None:
        """That arm at the valve lifts ``lift`` [m] on the heel circle ``heel`` [m], or None (no lever of its own)."""
        return None

    def variable_inertia_force(self, inertia, arm0, heel, h, dh, d2h) -> np.ndarray:
        """What the follower's own inertia ``inertia`` [kg m^2] adds by a lever ratio that varies with the lift to the
        train's m_v h'' at its ratio on the heel circle (arm ``arm0`` [m]), per camshaft speed squared [N s^2/rad^2]:
        zero for a follower of constant ratio (the law's lifts ``h`` [m], ``dh`` [m/rad], ``d2h`` [m/rad^2] on the
        heel circle ``heel`` [m])."""
        return np.zeros_like(d2h)

    def variable_mass(self, inertia, arm0, heel, h) -> np.ndarray:
        """What that inertia adds to the train's mass at the valve by its varying ratio [kg] at the lifts ``h`` [m]:
        zero for a follower of constant ratio."""
        return np.zeros_like(h)

    def pivot_linkage(self, heel, axis_angle=None) -> tuple | None:
        """The arguments of :func:`valvetrain.lash_adjuster.pivot_motion_ratio` for a lash adjuster at the follower's
        own pivot on the heel circle ``heel`` [m], its axis at ``axis_angle`` [rad] (None: the valve's), or None: a
        follower without a pivot of its own (the lever ratio decides, :func:`valvetrain.lash_adjuster.motion_ratio`)."""
        return None

    def geometry_problem(self, heel, lift) -> tuple[str, str, str, str] | None:
        """What makes the follower's geometry unworkable on the heel circle ``heel`` [m] up to the lift ``lift`` [m]
        (the key within the cam section, its value, the message and its joiner), or None: a translating follower
        has no linkage to fail."""
        return None

    def travel_acceleration(self, heel, h, dh, d2h) -> np.ndarray:
        """The follower's acceleration on the cam per camshaft angle squared [m/rad^2]: the law's h'' for a follower
        whose law is its own lift."""
        return d2h

    def acceleration_range(self, cam, samples=4001) -> tuple[float, float]:
        """The smallest and largest acceleration of the follower on the cam at the rated speed [m/s^2]: the law's own
        extremes (``cam`` is the law stage's ``CamResult``: ``min_acceleration``, ``max_acceleration``)."""
        return cam.min_acceleration, cam.max_acceleration

    def kinematics(self, heel, lift) -> None:
        """The record of the follower's linkage over the lift (heel circle ``heel``, lift ``lift`` [m]), or None for a
        follower without one (a finger's: :meth:`~valvetrain.followers.PivotedFollower.kinematics`)."""
        return None

    def profile_checks(self, contact) -> list:
        """The checks of the follower's contact record (:meth:`profile_contact`): none for a sliding face."""
        return []

    def limited_contact(self, contact) -> tuple[float, float | None] | None:
        """What a cam synthesis limits in the follower's contact record (:meth:`profile_contact`) beyond the profile's
        radius: its largest pressure angle [rad] and its concave radius closest to zero [m] (None: no concave
        stretch), or None where the follower has neither (a sliding face: its contact normal is its line of action,
        and a concave stretch under it is an undercut)."""
        return None

    @classmethod
    def admits(cls, law) -> bool:
        """Whether a cam of the lift law ``law`` (the specification's ``law``) can drive the follower: every law but
        those drawn for a roller translating on its line (:data:`ROLLER_LAWS`)."""
        return law not in ROLLER_LAWS

    def rolling_losses(self, u_follower, slip, resistance) -> tuple:
        """The follower surface's velocity [m/s], its rolling-resistance coefficient and its rolling velocity in the
        friction torque (:func:`valvetrain.tribology.friction_torque`): a sliding face has no rolling, so its
        velocity as it is and no rolling terms (``slip``, ``resistance``: a roller's, unused)."""
        return u_follower, 0.0, 0.0

    def ratio(self, h) -> np.ndarray:
        """The follower's own lever ratio (valve-side motion / cam lift) at the lifts ``h`` [m]: 1 for a
        follower translating on its line of action."""
        return np.ones_like(np.asarray(h, dtype=float))
