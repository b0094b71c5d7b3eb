"""Drive layouts: the chain of parts between the cam and the valve, and the train's mass reduced to the valve.

``direct``: the cam acts on the valve through a tappet (an overhead camshaft on a bucket tappet, or the lower
camshaft of a side-valve engine); ``rocker``: an overhead camshaft on a rocker or finger follower; ``pushrod``: a
lower camshaft moving tappet, pushrod and rocker of overhead valves (OHV).  The functions take a valve's SI view (or
its ``[valves.NAME]`` section where said): anything with ``drive`` and ``rocker_ratio``.

References
----------
Valve-train practical works (n.d.), works 5 and 7.
"""

from dataclasses import dataclass, replace
from typing import Optional

import numpy as np

from . import flow, masses
from .checks import Check, check
from .followers import REGISTRY as FOLLOWERS, follower_of
from .links import REGISTRY as LINKS
from .links.base import given_keys
from .locale import note


@dataclass(frozen=True)
class Layout:
    """A drive layout: its name and the chain of links from the contact to the valve.

    Attributes
    ----------
    name : str
        The ``[valves.NAME.drive] layout`` value.
    parts : tuple of str
        The names of the links between cam and valve in order from the cam (:data:`valvetrain.links.REGISTRY`):
        ``"tappet"`` (in a guide, under the cam), ``"pushrod"``, ``"rocker"`` (on its shaft, the valve arm at the
        valve), ``"rocker_pivot"`` (the pivot ball of a stud-mounted rocker, where its keys are given).
    """

    name: str
    parts: tuple

    @property
    def links(self) -> tuple:
        """The :class:`~valvetrain.links.Link` objects of the chain, from the cam."""
        return tuple(LINKS[p] for p in self.parts)

    @property
    def train_masses(self) -> tuple[str, ...]:
        """The ``[drive.masses]`` keys of the links a multi-mass train of this layout needs, from the cam."""
        return tuple(link.mass_key for link in self.links if link.mass_key is not None)

    def valve_mass(self, masses) -> float:
        """What the chain's links add to the mass reduced to the valve [kg] (``masses``: SI view of
        ``[drive.masses]``): a link that joins the chain its share (:meth:`~valvetrain.links.Link.valve_mass`, a valve
        bridge's), the others nothing."""
        return sum(link.valve_mass(masses) for link in self.links)

    @property
    def valve_joint(self) -> str:
        """The name of the joint between the last moving link and the valve (:attr:`~valvetrain.links.Link.joint`)."""
        return [link.joint for link in self.links if link.joint][-1]


LAYOUTS = {"direct": Layout("direct", ("tappet",)), "rocker": Layout("rocker", ("rocker",)),
           "pushrod": Layout("pushrod", ("tappet", "pushrod", "rocker", "rocker_pivot"))}
"""Drive layouts by name (``[valves.NAME.drive] layout``), see the module's text."""


def layout(valve) -> str:
    """Drive layout of a valve (SI view or section): as given, else direct for rocker ratio 1 and pushrod otherwise."""
    if valve.drive.layout is not None:
        return valve.drive.layout
    return "direct" if valve.rocker_ratio == 1.0 else "pushrod"


def chain(valve) -> Layout:
    """The :class:`Layout` of a valve (SI view), by :func:`layout`: its chain, and after it every link that joins it
    for the valve (:meth:`~valvetrain.links.Link.joins`: a valve bridge where its keys are given)."""
    own = LAYOUTS[layout(valve)]
    joined = tuple(name for name, link in LINKS.items() if link.joins(own.links, valve))
    return replace(own, parts=own.parts + joined) if joined else own


def unused_part_keys(valve) -> list[str]:
    """The ``[valves.NAME.parts]`` keys a valve's section gives (other than their defaults) that only parts it does
    not have read: a link's outside its layout's chain (:attr:`~valvetrain.links.Link.part_keys`) or another
    follower's (:attr:`~valvetrain.followers.Follower.part_keys`), in the section's order (SI view of the valve).

    Examples
    --------
    The built-in example's intake (a pushrod layout, a flat follower) given a finger's section:

    >>> from valvetrain.specification import example_spec
    >>> from valvetrain.specification.si import si
    >>> spec = example_spec().replace({"valves.intake.parts.finger_section_width_mm": 6.0})
    >>> unused_part_keys(si(spec.valves["intake"]))
    ['finger_section_width_mm']
    """
    section = valve.parts.section
    own = [part.part_keys for part in (*chain(valve).links, FOLLOWERS[valve.cam.follower])]
    owned = {key for part in (*LINKS.values(), *FOLLOWERS.values()) for key in part.part_keys}
    return [key for key in given_keys(section, type(section).model_fields) if key in owned.difference(*own)]


def unused_part_checks(valve) -> list[Check]:
    """A warning for every key of :func:`unused_part_keys`: the number of the valve's parts that read it, 0, against
    at least 1 (legal input, but a dimension of a part the train does not have is doubtful: a wrong layout or a key
    left from another design)."""
    layout_name, follower = chain(valve).name, valve.cam.follower
    return [check("parts.unused_key", 0, low=1, params={"key": key, "layout": layout_name},
                  source="Valve-train practical works (n.d.), work 7",
                  note=note("parts.unused_key", layout=layout_name, follower=follower))
            for key in unused_part_keys(valve)]


def valve_arm(valve) -> Optional[float]:
    """The valve-side arm that reduces the rocker's inertia to the valve [m] (SI view): ``[drive] valve_arm_mm``, or
    a finger's effective arm G(psi_0) = dv/dpsi with its roller on the heel circle r0 - clearance, from its geometry
    (:meth:`~valvetrain.followers.PivotedFollower.valve_arm`; None where neither applies)."""
    arm = follower_of(valve.cam).heel_valve_arm(valve.cam.base_radius - valve.clearance)
    return valve.drive.valve_arm if arm is None else arm


def train_mass(valve, spring_mass) -> tuple[float, str]:
    """Reduced mass of a valve's train at the valve [kg] and how it was obtained (SI view; Valve-train practical works (n.d.), eq. 5.2 or the
    specific mass of work 5); ``spring_mass`` [kg] where the part masses leave it to the designed spring.  A finger's
    inertia counts J / G(psi_0)^2, its value on the heel circle (:func:`valve_arm`); a link that joins the chain adds
    its mass at the valve (:meth:`~valvetrain.links.Link.valve_mass`: a valve bridge's share)."""
    d = valve.drive
    mass, source = masses.reduced_mass(float(flow.circle_area(valve.throat_diameter)), layout(valve),
                                       valve.rocker_ratio, parts=d.masses, specific_mass=d.specific_mass_kg_m2,
                                       valve_arm=valve_arm(valve), spring_mass=spring_mass)
    if d.masses is not None:
        mass += chain(valve).valve_mass(d.masses)
    return mass, source


def _inertia(valve) -> float:
    """J [kg m^2] of the valve's rocker or finger (SI view): ``[drive.masses] rocker_inertia_kg_mm2``, 0 not given."""
    parts = valve.drive.masses
    return 0.0 if parts is None else parts.rocker_inertia


def finger_inertia(valve, law, theta) -> np.ndarray:
    """What a finger's inertia by its variable ratio adds to the train's m_v h'' (:func:`train_mass` counts its
    J / G_0^2 at the ratio of the heel circle), per camshaft speed squared, at the camshaft angles ``theta`` [rad from
    the nose] of the lift law ``law`` [N s^2/rad^2] (SI view of the valve): :func:`finger_inertia_force` on the heel
    circle r0 - the ramp height."""
    return finger_inertia_force(valve, valve.cam.base_radius - law.ramp_height, *law.derivatives(theta)[:3])


def finger_inertia_force(valve, heel, h, dh, d2h) -> np.ndarray:
    """:func:`finger_inertia` at the valve lifts ``h`` [m], ``dh`` [m/rad], ``d2h`` [m/rad^2] of a law on the heel
    circle ``heel`` [m]: J psi'' / G - J h'' / G_0^2 (:meth:`~valvetrain.followers.PivotedFollower.inertia_force`;
    Norton (2009)); zero for another follower or without the finger's inertia."""
    inertia = _inertia(valve)
    if inertia == 0.0:
        return np.zeros_like(d2h)
    return follower_of(valve.cam).variable_inertia_force(inertia, valve_arm(valve), heel, h, dh, d2h)


def finger_mass_change(valve, law, theta) -> np.ndarray:
    """What a finger's inertia by its variable ratio adds to the train's mass at the valve [kg] at the camshaft angles
    ``theta`` [rad from the nose] of the lift law ``law`` (SI view of the valve): J / G(psi)^2 - J / G_0^2
    (:meth:`~valvetrain.followers.PivotedFollower.reduced_inertia`; :func:`train_mass` counts J / G_0^2; Norton
    (2009)), on the heel circle r0 - the ramp height; zero for another follower or without the finger's inertia."""
    h, inertia = law.lift(theta), _inertia(valve)
    if inertia == 0.0:
        return np.zeros_like(h)
    return follower_of(valve.cam).variable_mass(inertia, valve_arm(valve), valve.cam.base_radius - law.ramp_height, h)
