"""The link interface: what a part of the train between the contact and the valve is to the rest of the package.

A drive layout (:mod:`valvetrain.layouts`) is a contact, the follower that touches the cam (:mod:`valvetrain.followers`),
and a chain of links from the cam to the valve: a tappet in its guide, a pushrod, a rocker on its shaft.  The stages
loop over the links instead of asking which layout they are in: the strength stage collects each link's checks
(:meth:`Link.checks`), the dynamics builds the elastic train from each link's node (:meth:`Link.node`), its own
stiffness (:meth:`Link.stiffness`) and the joint of the last one to the valve (:attr:`Link.joint`), the side force of a
roller is carried by the first link (:attr:`Link.carrier`), a flat follower's face is the first link's
(:meth:`Link.face_diameter`).

For the author of a new link
----------------------------
Write one module in this package with a subclass of :class:`Link` decorated ``@register``, import it in
``links/__init__.py``, and name it in a layout's chain (:data:`valvetrain.layouts.LAYOUTS`), or let it join a chain
where the valve gives its keys (:meth:`Link.joins`, the valve bridge of :mod:`.bridge`).  Its dimensions are keys
of ``[valves.NAME.parts]`` (a new pydantic field of ``specification/models.py`` with its README row and report name),
named in its ``part_keys``, its mass a key of ``[drive.masses]`` (its node in the elastic train, :meth:`Link.node`; an elastic member's
stiffness, :meth:`Link.stiffness`); its checks are :func:`valvetrain.strength.verdict` of a new
:data:`valvetrain.strength.LIMITS` row (and its code's texts, ``tools/check_codes.py add``).  Links hold no state;
their methods are pure functions of the loads (:class:`Loads`, SI) and return checks, never sentences.
"""

from dataclasses import dataclass
from typing import Any, Callable, ClassVar, Optional

REGISTRY = {}
"""Link name -> its :class:`Link` instance, in the order of registration."""


def register(cls) -> type:
    """Class decorator: add an instance of a link class to :data:`REGISTRY` under its ``name``."""
    REGISTRY[cls.name] = cls()
    return cls


def given_keys(section, keys) -> list[str]:
    """The ``keys`` a section of the specification (the model, its keys in their units) gives other than their
    defaults, in the order of ``keys``."""
    fields = type(section).model_fields
    return [key for key in keys if getattr(section, key) != fields[key].default]


@dataclass(frozen=True)
class Loads:
    """The loads and dimensions the links' checks take (SI), from the strength stage.

    Attributes
    ----------
    parts : SI view of ``[valves.NAME.parts]``
    cam_force : float
        The largest force between cam and follower along the law's lift, P_T max [N].
    valve_force : float
        The largest force at the valve [N].
    modulus : float
        The contact modulus of the parts [Pa].
    rocker_ratio : float
        The rocker ratio i_k = l_v / l_t (1 without a rocker).
    where : tuple
        The note (:func:`valvetrain.locale.note`) of where (camshaft angle) and at which speed the cam force is
        largest, which each check's note starts with.
    guide_offset : float or None
        The largest distance of the contact from the axis of a face sliding on the cam [m] (a flat follower's
        max dh/dphi); None for a roller.
    need : callable
        ``need(keys, name)``: whether the ``[valves.NAME.parts]`` keys (their names in the file) are given; the
        stage records those missing as the check ``name`` not checked.
    """

    parts: Any
    cam_force: float
    valve_force: float
    modulus: float
    rocker_ratio: float
    where: tuple
    guide_offset: Optional[float]
    need: Callable[[list[str], str], bool]


class Link:
    """A link of the train between the contact and the valve (SI throughout).

    Class attributes
    ----------------
    name : str
        Its name in a layout's chain (:data:`valvetrain.layouts.LAYOUTS`).
    mass_key : str or None
        The ``[drive.masses]`` key of its mass (or inertia) in a multi-mass train; None for a link that does not
        move (a rocker's pivot).
    mass_attr : str
        The attribute of the SI view of ``[drive.masses]`` that holds the mass (or inertia) of ``mass_key``.
    carrier : str
        The note code (:mod:`valvetrain.locale`) of the link as the carrier of a roller's side force, where it is
        the first link from the cam.
    elastic : bool
        Whether the link is an elastic member of the drive (a pushrod): its mass sits at its middle between two
        halves of twice its stiffness (:meth:`stiffness`); the other links are rigid bodies between the joints.
    joint : str
        The name of the joint between the link and the valve in the drive's stiffness, where it is the last moving
        link of the chain ("" for a link that never is).
    at_valve : bool
        Whether the link moves with the valve, beyond the joint of the last lever (a valve bridge): its mass and
        stiffness are already at the valve (ratio 1), and the chain's joint to the valve (:attr:`joint`) lies between
        the cam side and it.
    lever : bool
        Whether the link is a lever whose arms set the rocker ratio i_k = l_v / l_t: a chain without one moves the
        valve as the cam lifts it (i_k = 1).
    part_keys : tuple of str
        The ``[valves.NAME.parts]`` keys the link reads (its dimensions): given for a layout without the link, they
        are a warning of the design (:func:`valvetrain.layouts.unused_part_keys`).
    """

    name: ClassVar[str]
    mass_key: ClassVar[Optional[str]] = None
    mass_attr: ClassVar[str] = ""
    carrier: ClassVar[str] = ""
    elastic: ClassVar[bool] = False
    joint: ClassVar[str] = ""
    at_valve: ClassVar[bool] = False
    lever: ClassVar[bool] = False
    part_keys: ClassVar[tuple[str, ...]] = ()

    @property
    def label(self) -> str:
        """The link's name in the drive's stiffnesses (the notes, the records): its :attr:`name` in words, the key of
        its name in the catalogues' ``[links]``."""
        return self.name.replace("_", " ")

    def given(self, section) -> bool:
        """Whether a ``[valves.NAME.parts]`` section (the model, its keys in their units) gives one of the link's
        :attr:`part_keys` (:func:`given_keys`)."""
        return bool(given_keys(section, self.part_keys))

    def joins(self, links, valve) -> bool:
        """Whether the link joins a layout's chain ``links`` (:class:`Link` objects) for the valve (SI view) beyond
        it, after its last link (a valve bridge where its keys are given): no link of the layouts' own chains
        does."""
        return False

    def valve_mass(self, masses) -> float:
        """The mass a link that joins a chain (:meth:`joins`) adds to the train's mass reduced to the valve [kg]
        (``masses``: SI view of ``[drive.masses]``; :func:`valvetrain.layouts.train_mass`): none."""
        return 0.0

    def checks(self, loads) -> list:
        """The strength checks of the link under ``loads`` (:class:`Loads`), those whose keys are given: none."""
        return []

    def face_diameter(self, parts) -> Optional[float]:
        """The diameter of the face the link offers a flat follower [m] (``parts``: SI view of
        ``[valves.NAME.parts]``), or None where its face is not known."""
        return None

    def stiffness(self, parts) -> Optional[float]:
        """The link's own stiffness along the train [N/m] (at the link, not reduced to the valve) from ``parts`` (SI
        view of ``[valves.NAME.parts]``), None where its geometry is not given; only an :attr:`elastic` link has
        one."""
        return None

    def node(self, masses, ratio, arm) -> Optional[tuple[str, float]]:
        """The link's node in a multi-mass train: its name and its mass reduced to the valve [kg], m / i_k^2 (Valve-train
        practical works (n.d.), eq. 5.2); None for a link without a mass (:attr:`mass_key` None).

        Parameters
        ----------
        masses : SI view of ``[drive.masses]``
        ratio : float
            The valve's travel per the link's, i_k = l_v / l_t for a link on the cam side of a rocker (1 without one).
        arm : float or None
            The valve arm that reduces a rocker's inertia to the valve [m].
        """
        if self.mass_key is None:
            return None
        return self.name, getattr(masses, self.mass_attr) / ratio**2

    def missing(self, masses, arm) -> list[str]:
        """The keys a multi-mass train needs of the link and the specification does not give (``[drive.masses]``
        keys whose value is not given or not positive), for the refusal that names them."""
        if self.mass_key is None or (getattr(masses, self.mass_attr) or 0.0) > 0.0:
            return []
        return [self.mass_key]
