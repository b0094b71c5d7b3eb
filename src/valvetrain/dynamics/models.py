"""Elastic valve-train models: one-mass and multi-mass (4 + N1 + N2) trains as lumped networks.

Coordinates are reduced to the valve (Shang Hanji (1988), section 3.1): a displacement on the tappet side is multiplied by the rocker ratio k (valve
arm / tappet arm), so a tappet-side mass m counts as m / k^2, a tappet-side stiffness c as
c / k^2 and a rocker of inertia J about its shaft as J / l_v^2.  Positive is the opening
direction.  SI units: kg, N/m, N s/m, N, m.

A train becomes a :class:`Network` of masses and elements that the compiled integrator of
:mod:`.kernels` advances: bilateral spring-dampers with a preload (valve-spring coils, the held joints of a
multi-mass drive) and unilateral contacts with a gap (cam contact with the lash, valve seat).  A multi-mass train
starts at rest in its static equilibrium on the base circle (:func:`static_equilibrium`).
"""

from dataclasses import dataclass, field, replace
import functools
from typing import Callable, Optional

import numpy as np

from ..errors import InputError
from ..locale import NoteText, note
from ..strength import STEEL_MODULUS, camshaft_deflection
from .kernels import CAM, GROUND

DAMPING_RATIO = 0.05
"""Damping ratio of the drive, zeta in C = 2 zeta sqrt(c M): the value of the worked examples of
this package's tests (the sources give none; 0.03-0.1 is the usual
range in the valve-train literature)."""

SEAT_STIFFNESS = 2.0e8
"""Stiffness of the valve head on its seat [N/m]: an assumption (the sources give none).  A 30 mm
steel valve head and seat insert deflect some 2-5 um under a 1 kN seating load, i.e. 2e8-5e8
N/m; the seat must be much stiffer than the drive (c ~ 1.5e7 N/m) and resolved by the time step."""

SEAT_DAMPING_RATIO = 0.4
"""Damping ratio of the seat contact, C_s = 2 zeta_s sqrt(c_s M): an assumption (a coefficient of restitution
of exp(-pi zeta / sqrt(1 - zeta^2)) = 0.25 for a free impact).  With it the sweep of this package's worked example
shows its pattern: a few um of bounce at 1500 cam rpm, none at 3000, about 2 mm once the valve floats."""


def _kept(method) -> Callable:
    """A method without arguments of a frozen dataclass whose result is kept on the instance at its first call (its
    fields do not change; :func:`dataclasses.replace` makes a new instance, which computes its own): a train's
    :class:`Network` and its :meth:`Network.highest_frequency` are asked for by every sweep of a design (and its
    refinement, and the check of its size), about 1.5 ms each time for the one-mass train."""
    name = f"_kept_{method.__name__}"

    @functools.wraps(method)
    def wrapper(self):
        try:
            return self.__dict__[name]
        except KeyError:
            value = self.__dict__[name] = method(self)   # a frozen dataclass refuses setattr, not its __dict__
            return value
    return wrapper


@dataclass(frozen=True)
class Adjuster:
    """A hydraulic lash adjuster in series with the cam contact, its plunger extension a state of the integration
    carried from revolution to revolution (:func:`~valvetrain.dynamics.kernels.integrate_block`).  SI units.

    Attributes
    ----------
    motion_ratio : float
        Valve motion per plunger motion i_a (> 0), also the adjuster's force per valve force.
    plunger_spring : float
        Plunger spring force F_s [N].
    area : float
        Plunger area A [m^2].
    supply : float
        Oil supply pressure p_s [Pa, gauge].
    leak : float
        Leak coefficient of the annular clearance, pi d c^3 / (12 mu L) [m^3/(s Pa)]
        (:func:`valvetrain.lash_adjuster.annular_leakage` per pascal).
    refill : float
        Largest extension velocity through the open check valve [m/s].
    stop : float
        The plunger's travel from its working position (z = 0, the valve seated on the base circle) to its stop [m, at
        the adjuster]: it extends no further (inf: no stop).
    """

    motion_ratio: float
    plunger_spring: float
    area: float
    supply: float
    leak: float
    refill: float
    stop: float = np.inf

    @property
    def push(self) -> float:
        """The contact force at the valve at which the check valve opens, (F_s + p_s A) / i_a [N]: at or below it
        the plunger extends after the follower (:func:`~valvetrain.dynamics.kernels.integrate_block`): the chamber
        pressure (i_a F - F_s) / A of a massless plunger down to the supply p_s, the check valve's opening condition
        (Merritt (1967), the valve's pressure balance)."""
        return (self.plunger_spring + self.supply * self.area) / self.motion_ratio

    def array(self) -> np.ndarray:
        """The kernel's parameter array (7,)."""
        return np.array([self.motion_ratio, self.plunger_spring, self.area, self.supply, self.leak, self.refill,
                         self.stop])


NO_ADJUSTER = np.zeros(7)
"""The kernel's parameter array of a train without a lash adjuster (motion ratio 0)."""


@dataclass(frozen=True)
class VariableMass:
    """A node whose mass changes with its own position: a finger follower's inertia about its pivot reduced to the
    valve through its variable ratio (:func:`~valvetrain.dynamics.kernels.integrate_block`).  SI units.

    Attributes
    ----------
    node : str
        The node's name (``"valve"`` of a one-mass train, ``"rocker"`` of a multi-mass one).
    position : ndarray (K,)
        The node's positions x [m], evenly spaced and ascending (K >= 2).
    mass : ndarray (K,)
        The node's whole mass m(x) there [kg].
    slope : ndarray (K,)
        dm/dx [kg/m] there.

    Notes
    -----
    The node's kinetic energy is m(x) x_dot^2 / 2, and Lagrange's equation with the generalised force F of the
    elements on the node gives

    .. math:: m(x)\\,\\ddot x + \\tfrac12\\,m'(x)\\,\\dot x^2 = F

    (the velocity-squared term of a configuration-dependent inertia; with a conservative F it keeps m x_dot^2 / 2 +
    V(x) constant).  Between the positions the kernel takes the cubic Hermite interpolant of m and m', whose slope is
    the interpolated m'; beyond the ends m is held at the end value and m' = 0.

    References
    ----------
    Norton (2009), the chapter on the dynamics of follower trains (the equivalent mass of a linkage of variable
    ratio, its kinetic energy in Lagrange's equation); Wang (2007), the chapter on valvetrain dynamics.
    """

    node: str
    position: np.ndarray
    mass: np.ndarray
    slope: np.ndarray

    def array(self) -> np.ndarray:
        """The kernel's table (3, K): positions, masses and slopes."""
        return np.stack([self.position, self.mass, self.slope]).astype(float)


NO_VARIABLE_MASS = np.zeros((3, 0))
"""The kernel's table of a train whose masses are all constant."""


@dataclass(frozen=True)
class Network:
    """A lumped train ready for :func:`~valvetrain.dynamics.kernels.integrate_block` (SI, valve side).

    Attributes
    ----------
    names : tuple of str
        Node names (``"valve"`` is the valve).
    mass : ndarray (n,)
        Node masses [kg].
    x_init : ndarray (n,)
        Static position on the seat [m].
    elements : tuple of str
        Element names.
    a, b : ndarray (E,) of int
        End nodes (``CAM``, ``GROUND`` or a node index); compression x_a - x_b - gap > 0 pushes b.
    stiffness, damping, gap, preload : ndarray (E,)
        [N/m], [N s/m], [m], [N].
    unilateral : ndarray (E,) of bool
        Compression-only contact.
    clash_gap : ndarray (E,)
        Coil closing distance at the installed length [m] (0: not a coil element).
    surge_weight : ndarray (n,)
        Quasi-static share of the valve motion of each coil node (0: not a coil node).
    rocker_ratio : float
        k, to turn the valve-side cam force into the force at the cam.
    adjuster : ndarray (7,)
        :meth:`Adjuster.array` of a hydraulic lash adjuster in series with the cam contact (:data:`NO_ADJUSTER`).
    variable_node : int
        The node whose mass changes with its position (-1: none); ``mass`` holds its reference value (the modes, the
        element dampings, the perturbation parameter).
    variable_mass : ndarray (3, K)
        :meth:`VariableMass.array` of that node (:data:`NO_VARIABLE_MASS`).
    """

    names: tuple
    mass: np.ndarray
    x_init: np.ndarray
    elements: tuple
    a: np.ndarray
    b: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    gap: np.ndarray
    preload: np.ndarray
    unilateral: np.ndarray
    clash_gap: np.ndarray
    surge_weight: np.ndarray
    rocker_ratio: float
    adjuster: np.ndarray = field(default_factory=NO_ADJUSTER.copy)
    variable_node: int = -1
    variable_mass: np.ndarray = field(default_factory=NO_VARIABLE_MASS.copy)

    @property
    def valve(self) -> int:
        """Index of the valve node."""
        return self.names.index("valve")

    @property
    def cam_element(self) -> int:
        """Index of the cam-follower contact."""
        return int(np.flatnonzero(self.a == CAM)[0])

    @property
    def seat_element(self) -> int:
        """Index of the valve-seat contact."""
        return self.elements.index("seat")

    @property
    def lash(self) -> float:
        """Total clearance of the drive at the valve [m]: the gaps of its unilateral elements."""
        drive = self.unilateral & (np.arange(self.a.size) != self.seat_element)
        return float(self.gap[drive].sum())

    @property
    def spring_elements(self) -> np.ndarray:
        """Indices of the elements that act on the valve from its springs (force on the valve = -their sum)."""
        return np.array([i for i, n in enumerate(self.elements) if n.endswith("spring at valve")], dtype=np.int64)

    def matrix(self, values) -> np.ndarray:
        """Assembled n x n matrix of element values (stiffnesses or dampings) with every contact closed.

        An element between nodes a and b adds its value to M_aa and M_bb and subtracts it from M_ab and M_ba;
        the cam and the ground add to the diagonal only.
        """
        n = self.mass.size
        out = np.zeros((n, n))
        for a, b, value in zip(self.a, self.b, values, strict=True):
            for i, j, sign in ((a, a, 1.0), (b, b, 1.0), (a, b, -1.0), (b, a, -1.0)):
                if i >= 0 and j >= 0:
                    out[i, j] += sign * value
        return out

    @_kept
    def highest_frequency(self) -> float:
        """Spectral radius of the linearised state matrix with every contact closed [1/s].

        The eigenvalues of [[0, I], [-M^-1 K, -M^-1 C]]: closing a contact only adds stiffness and damping,
        so this bounds |lambda| of every contact state; the explicit integrator keeps |lambda| dt <= 1, well
        inside the stability region of RK4.
        """
        n = self.mass.size
        mass = self.mass.copy()
        if self.variable_node >= 0:
            mass[self.variable_node] = min(mass[self.variable_node], self.variable_mass[1].min())
        inv = (1.0 / mass)[:, None]
        state = np.block([[np.zeros((n, n)), np.eye(n)],
                          [-inv * self.matrix(self.stiffness), -inv * self.matrix(self.damping)]])
        return float(np.abs(np.linalg.eigvals(state)).max())




class _Builder:
    """Collects nodes and elements of a :class:`Network`."""

    def __init__(self):
        self.names, self.mass, self.weight = [], [], []
        self.elements, self.rows = [], []

    def node(self, name, mass, weight=0.0):
        self.names.append(name)
        self.mass.append(float(mass))
        self.weight.append(float(weight))
        return len(self.names) - 1

    def element(self, name, a, b, stiffness, damping, gap=0.0, preload=0.0, unilateral=False, clash=0.0):
        self.elements.append(name)
        self.rows.append((a, b, float(stiffness), float(damping), float(gap), float(preload), bool(unilateral),
                          float(clash)))

    def node_mass(self, i):
        return self.mass[i] if i >= 0 else np.inf

    def pair_mass(self, a, b):
        """Reduced mass of the two ends of an element (the moving one alone against the ground or the cam)."""
        ma, mb = self.node_mass(a), self.node_mass(b)
        return mb if not np.isfinite(ma) else ma if not np.isfinite(mb) else ma * mb / (ma + mb)

    def damped(self, name, a, b, stiffness, ratio, **kw):
        self.element(name, a, b, stiffness, 2.0 * ratio * np.sqrt(stiffness * self.pair_mass(a, b)), **kw)

    def spring(self, tag, spring, valve):
        """The coils of one spring between the valve (retainer) and the head: N masses, N + 1 segments; the
        retainer's end coils on the valve."""
        n = spring.coils
        if n == 0:
            self.mass[valve] += spring.whole_mass / 3.0
            self.element(f"{tag} spring at valve", valve, GROUND, spring.rate, 0.0, preload=spring.preload,
                         clash=spring.closing_gap)
            return
        seg_k = (n + 1) * spring.rate
        seg_gap = spring.closing_gap / (n + 1)
        self.mass[valve] += spring.dead_mass + spring.mass / (2.0 * (n + 1))
        nodes = [self.node(f"{tag} coil {i + 1}", spring.mass / (n + 1), (n - i) / (n + 1)) for i in range(n)]
        ends = [valve] + nodes + [GROUND]
        for i in range(n + 1):
            name = f"{tag} spring at valve" if i == 0 else f"{tag} coil segment {i + 1}"
            self.element(name, ends[i], ends[i + 1], seg_k, spring.segment_damping(), preload=spring.preload,
                         clash=seg_gap)

    def seat(self, valve, stiffness, ratio):
        self.damped("seat", GROUND, valve, stiffness, ratio, unilateral=True)

    def build(self, x_valve, valve, rocker_ratio, adjuster=None, variable=None):
        """The :class:`Network`, at rest with the valve at ``x_valve`` [m] and the drive and the coils at their share
        of it, or (``x_valve`` None) in its :func:`static_equilibrium`."""
        rows = list(zip(*self.rows, strict=True))
        weight = np.array(self.weight)
        x_init = (np.zeros(weight.size) if x_valve is None else
                  x_valve * np.where(weight > 0.0, weight, 1.0))   # drive parts resting on the seated valve
        net = Network(tuple(self.names), np.array(self.mass), x_init, tuple(self.elements),
                       np.array(rows[0], dtype=np.int64), np.array(rows[1], dtype=np.int64), np.array(rows[2]),
                       np.array(rows[3]), np.array(rows[4]), np.array(rows[5]), np.array(rows[6], dtype=np.bool_),
                       np.array(rows[7]), np.array(self.weight), float(rocker_ratio),
                       NO_ADJUSTER.copy() if adjuster is None else adjuster.array(),
                       -1 if variable is None else self.names.index(variable.node),
                       NO_VARIABLE_MASS.copy() if variable is None else variable.array())
        return net if x_valve is not None else replace(net, x_init=static_equilibrium(net))


def static_equilibrium(network, cam=0.0) -> np.ndarray:
    r"""Node positions of a network at rest [m]: every node's forces in balance with the cam at ``cam`` [m at the
    valve; 0: the base circle], each contact closed exactly where it is compressed.

    Parameters
    ----------
    network : Network
    cam : float
        The cam's displacement at the valve [m].

    Returns
    -------
    ndarray (n,)

    Raises
    ------
    ValueError
        A node that nothing holds with its open contacts (no unique rest position).

    Notes
    -----
    With the set A of the closed elements (the bilateral ones and the contacts closed) every element's force
    :math:`f_e = F_{0,e} + k_e (x_a - x_b - g_e)` is linear in the positions, and the balance of the nodes is

    .. math:: \mathbf K_A \mathbf x = \mathbf r_A,\quad r_i = \sum_{e:\,b_e = i} c_e - \sum_{e:\,a_e = i} c_e,\quad
              c_e = F_{0,e} - k_e g_e + k_e (u_a - u_b)

    with :math:`\mathbf K_A` the stiffness matrix of A (:meth:`Network.matrix`) and u the cam's or the ground's
    displacement at a fixed end (0 at a node).  A is found by iteration from the contacts without a gap: solve, then
    close every open contact the solution compresses and open every closed one in tension, until A repeats (the
    active-set method of the linear complementarity problem of contacts; a train's contacts settle in two or three
    passes).

    References
    ----------
    Cottle, Pang and Stone (1992), the chapter on pivoting methods (the active set of a linear complementarity
    problem).

    Examples
    --------
    The one-mass train on its seat: the spring's preload on the seat and the spring in parallel,
    x = -F_0 / (c_s + K).

    >>> net = one_mass_train(0.25, 15e6, 67.5e3, 400.0, lash=3e-4, seat_stiffness=2e8).network()
    >>> bool(np.isclose(static_equilibrium(net)[0], -400.0 / (2e8 + 67.5e3), rtol=1e-12))
    True
    """
    fixed = {CAM: float(cam), GROUND: 0.0}
    ua = np.array([fixed.get(int(a), 0.0) for a in network.a])
    ub = np.array([fixed.get(int(b), 0.0) for b in network.b])
    const = network.preload - network.stiffness * (network.gap - ua + ub)
    n = network.mass.size
    closed = ~network.unilateral | (network.gap <= 0.0)
    for _ in range(2 * int(network.unilateral.sum()) + 2):
        r = np.zeros(n)
        on = closed & (network.b >= 0)
        np.add.at(r, network.b[on], const[on])
        on = closed & (network.a >= 0)
        np.add.at(r, network.a[on], -const[on])
        k = network.matrix(np.where(closed, network.stiffness, 0.0))
        try:
            x = np.linalg.solve(k, r)
        except np.linalg.LinAlgError:
            raise InputError(NoteText(note("dynamics.unheld_node"))) from None
        xa = np.where(network.a >= 0, x[np.maximum(network.a, 0)], ua)
        xb = np.where(network.b >= 0, x[np.maximum(network.b, 0)], ub)
        now = ~network.unilateral | (xa - xb - network.gap > 0.0)
        if np.array_equal(now, closed):
            return x
        closed = now
    raise InputError(NoteText(note("dynamics.unsettled_contacts")))


@dataclass(frozen=True)
class OneMassTrain:
    """Single-degree-of-freedom train (Shang Hanji (1988), section 3.1).

    Attributes
    ----------
    mass : float
        Mass reduced to the valve M [kg].
    stiffness : float
        Drive stiffness between cam and valve reduced to the valve c [N/m].
    damping : float
        Drive damping C [N s/m].
    spring_rate, preload : float
        Valve spring K [N/m] and installed force F0 [N].
    rocker_ratio : float
        k = valve arm / tappet arm.
    lash : float
        Valve clearance at the valve x0 [m].
    seat_stiffness, seat_damping : float
        Valve seat contact c_s [N/m], C_s [N s/m].
    notes : tuple of str
        How each value was obtained.
    adjuster : Adjuster, optional
        A hydraulic lash adjuster in series with the cam contact.
    variable_mass : VariableMass, optional
        The valve node's mass as a function of its lift (a finger follower's inertia by its variable ratio); M is
        then its reference value.

    Notes
    -----
    .. math:: M\\ddot y = F_c - (F_0 + K y) + F_{seat},\\quad
              F_c = \\max(0,\\,c\\,\\delta + C\\dot\\delta)\\ \\text{if}\\ \\delta = k h - x_0 - y > 0,

    :math:`F_{seat} = \\max(0, -c_s y - C_s\\dot y)` for y < 0.
    """

    mass: float
    stiffness: float
    damping: float
    spring_rate: float
    preload: float
    rocker_ratio: float = 1.0
    lash: float = 0.0
    seat_stiffness: float = SEAT_STIFFNESS
    seat_damping: float = 0.0
    notes: tuple = ()
    adjuster: Optional[Adjuster] = None
    variable_mass: Optional[VariableMass] = None

    @_kept
    def network(self) -> Network:
        """The train as a :class:`Network`: one node, cam contact with the lash, spring, seat."""
        net = _Builder()
        valve = net.node("valve", self.mass)
        net.element("cam contact", CAM, valve, self.stiffness, self.damping, gap=self.lash, unilateral=True)
        net.element("spring at valve", valve, GROUND, self.spring_rate, 0.0, preload=self.preload)
        net.element("seat", GROUND, valve, self.seat_stiffness, self.seat_damping, unilateral=True)
        return net.build(-self.preload / self.seat_stiffness, valve, self.rocker_ratio, self.adjuster,
                         self.variable_mass)


def one_mass_train(mass, stiffness, spring_rate, preload, rocker_ratio=1.0, lash=0.0, damping_ratio=DAMPING_RATIO,
                   seat_stiffness=SEAT_STIFFNESS, seat_damping_ratio=SEAT_DAMPING_RATIO) -> OneMassTrain:
    """A :class:`OneMassTrain` with the damping given by damping ratios.

    Parameters
    ----------
    mass : float
        M [kg] at the valve (Valve-train practical works (n.d.) eq. 5.2, :func:`valvetrain.masses.reduced_mass_at_valve`).
    stiffness : float
        c [N/m] at the valve.
    spring_rate, preload : float
        K [N/m], F0 [N].
    rocker_ratio, lash : float
        k and x0 [m].
    damping_ratio, seat_damping_ratio : float
        zeta of C = 2 zeta sqrt(c M) and of C_s = 2 zeta_s sqrt(c_s M).
    seat_stiffness : float
        c_s [N/m].
    """
    notes = (f"drive damping C = 2 zeta sqrt(c M) with zeta = {damping_ratio:g}",
             f"seat: c_s = {seat_stiffness:.3g} N/m, zeta_s = {seat_damping_ratio:g} (assumed, see SEAT_STIFFNESS)")
    return OneMassTrain(float(mass), float(stiffness), 2.0 * damping_ratio * np.sqrt(stiffness * mass),
                        float(spring_rate), float(preload), float(rocker_ratio), float(lash), float(seat_stiffness),
                        2.0 * seat_damping_ratio * np.sqrt(seat_stiffness * mass), notes)


@dataclass(frozen=True)
class MultiMassTrain:
    """Multi-degree-of-freedom train, 4 + N1 + N2 masses (Shang Hanji (1988), section 3.2).

    Attributes
    ----------
    layout : str
        ``"pushrod"`` (cam - tappet - pushrod - rocker - valve), ``"rocker"`` (overhead cam: cam - rocker -
        valve) or ``"direct"`` (overhead cam on a bucket tappet: cam - tappet - valve).
    drive : tuple of (str, float)
        Drive masses from the cam to the valve, reduced to the valve [kg] (the valve last).
    links : tuple of float
        Stiffnesses reduced to the valve [N/m]: cam to the first mass, then between successive masses.
    springs : tuple of CoilSpring
        Outer and inner spring (one or two).
    rocker_ratio, lash : float
        k and the valve clearance x0 [m] at the valve, taken up at the cam contact.
    damping_ratio : float
        Of every drive link on the reduced mass of its two ends.
    seat_stiffness, seat_damping_ratio : float
        Valve seat contact.
    notes : tuple of str
        How each value was obtained.
    adjuster : Adjuster, optional
        A hydraulic lash adjuster in series with the cam contact.
    variable_mass : VariableMass, optional
        A drive node's mass as a function of its position (a finger's inertia by its variable ratio); ``drive``
        holds its reference value.

    Notes
    -----
    :math:`\\mathbf M\\ddot{\\mathbf x} + \\mathbf C\\dot{\\mathbf x} + \\mathbf K\\mathbf x = \\mathbf f(h,
    \\text{contacts})`, the train at rest in its :func:`static_equilibrium` on the base circle at the start.

    Contacts (the convention of this model).  The cam contact is compression-only and holds the clearance x0, as the
    specification states it (the clearance h0 at the cam that the ramp takes up, Valve-train practical works (n.d.),
    work 2) and as the one-mass train has it; the valve seat is compression-only.  The drive joints are held
    (bilateral): the drive parts stay together and with the valve, so between the lifts they rest with the valve on
    its seat, the clearance open at the cam, and start each lift from rest.  In an engine the clearance of a pushrod
    train sits at the rocker's adjusting screw and the parts are kept together only by their weight and the oil of
    their joints and of the tappet's bore, forces this model does not have: with bare compression-only joints
    nothing brings the drive parts to rest between the lifts, they float in the clearance after the first seating,
    rattle and meet the cam at random, and the motion never repeats.  Under the spring the cam contact carries the
    least force of the chain (the joint between nodes j and j + 1 carries the spring force less the inertia of the
    nodes from j + 1 to the valve, the cam contact that of them all), so while the cam decelerates the chain the cam
    contact parts first, and the follower's separation (the jump) is the loss of the cam contact while the valve is
    off its seat; a held joint would carry tension only where the chain's own vibration outruns that order (none of
    the pushrod example's joints does while its valve is off its seat, up to 8000 rpm).

    Coils.  A spring of N coil masses is N + 1 segments of rate (N + 1) K between the retainer and the head, masses
    m_s / (N + 1) of its active coils inside and half of one on the valve, with its end coils at the retainer on
    the valve (:func:`.coils.coil_spring`): a lumped-mass discretisation of the wave equation of the coil.  With the valve
    held, its modes are those of a uniform fixed-fixed chain,

    .. math:: \\omega_j = 2 (N + 1) \\sqrt{K / m_s}\\,\\sin\\frac{j \\pi}{2 (N + 1)},

    below the continuous spring's :math:`j \\pi \\sqrt{K / m_s}` (Valve-train practical works (n.d.), eq. 6.13 for
    j = 1) by the factor :math:`(2 (N + 1) / \\pi) \\sin(\\pi / (2 (N + 1)))`, 0.9949 at N = 8.
    """

    layout: str
    drive: tuple
    links: tuple
    springs: tuple
    rocker_ratio: float = 1.0
    lash: float = 0.0
    damping_ratio: float = DAMPING_RATIO
    seat_stiffness: float = SEAT_STIFFNESS
    seat_damping_ratio: float = SEAT_DAMPING_RATIO
    notes: tuple = field(default=())
    adjuster: Optional[Adjuster] = None
    variable_mass: Optional[VariableMass] = None

    @_kept
    def network(self) -> Network:
        """The train as a :class:`Network`."""
        net = _Builder()
        nodes = [net.node(name, m) for name, m in self.drive]
        valve = nodes[-1]
        for s, tag in zip(self.springs, ("outer", "inner"), strict=False):
            net.spring(tag, s, valve)
        ends = [CAM] + nodes
        net.damped("cam contact", CAM, nodes[0], self.links[0], self.damping_ratio, unilateral=True, gap=self.lash)
        for i, c in enumerate(self.links[1:], start=1):
            net.damped(f"{self.drive[i - 1][0]}-{self.drive[i][0]} joint", ends[i], ends[i + 1], c,
                       self.damping_ratio)
        net.seat(valve, self.seat_stiffness, self.seat_damping_ratio)
        return net.build(None, valve, self.rocker_ratio, self.adjuster, self.variable_mass)


def natural_modes(network, held=(), opened=()) -> tuple[np.ndarray, np.ndarray]:
    r"""Natural frequencies [rad/s, ascending] and mode shapes of a network without damping.

    Parameters
    ----------
    network : Network
    held : sequence of str
        Names of nodes held fixed (e.g. ``("valve",)`` for the surge modes of the springs alone).
    opened : sequence of str
        Names of elements left open (e.g. ``("seat",)`` for the train with the valve off its seat); every other
        contact is closed.

    Returns
    -------
    frequencies : ndarray (m,)
    shapes : ndarray (n, m)
        Column j: the displacement of every node in mode j (0 on a held node), the largest 1 in magnitude.

    Notes
    -----
    Eigenpairs of :math:`\mathbf M^{-1/2}\mathbf K\mathbf M^{-1/2}` with K from :meth:`Network.matrix`; a shape
    is :math:`\mathbf M^{-1/2}` times the eigenvector.
    """
    k = network.matrix(np.where(np.isin(network.elements, opened), 0.0, network.stiffness))
    free = np.array([name not in held for name in network.names])
    scale = 1.0 / np.sqrt(network.mass[free])
    values, vectors = np.linalg.eigh(scale[:, None] * k[np.ix_(free, free)] * scale[None, :])
    shapes = np.zeros((network.mass.size, values.size))
    shapes[free] = scale[:, None] * vectors
    peak = shapes[np.abs(shapes).argmax(axis=0), np.arange(values.size)]
    return np.sqrt(np.clip(values, 0.0, None)), shapes / peak


def slowest_decay(network, opened=()) -> tuple[float, float]:
    r"""The least damped vibration of a network with the elements ``opened`` open and every other contact closed:
    its damped frequency [rad/s] and its decay rate sigma [1/s] (its amplitude falls by exp(-sigma t) in t seconds).

    Notes
    -----
    The eigenvalues :math:`\lambda = -\sigma \pm i \omega_d` of the linearised state matrix
    :math:`[[0, I], [-M^{-1} K, -M^{-1} C]]` (:meth:`Network.highest_frequency`'s), the one of the smallest sigma.

    Examples
    --------
    One mass on a spring and a damper of ratio zeta: sigma = zeta omega_n, omega_d = omega_n sqrt(1 - zeta^2).

    >>> net = one_mass_train(0.25, 15e6, 67.5e3, 400.0, damping_ratio=0.05).network()
    >>> w, sigma = slowest_decay(net, opened=("seat",))
    >>> wn = np.sqrt((15e6 + 67.5e3) / 0.25)
    >>> bool(np.isclose(sigma, net.damping[0] / 0.5) and np.isclose(w, np.sqrt(wn**2 - sigma**2)))
    True
    """
    closed = ~np.isin(network.elements, opened)
    n = network.mass.size
    inv = (1.0 / network.mass)[:, None]
    state = np.block([[np.zeros((n, n)), np.eye(n)],
                      [-inv * network.matrix(np.where(closed, network.stiffness, 0.0)),
                       -inv * network.matrix(np.where(closed, network.damping, 0.0))]])
    values = np.linalg.eigvals(state)
    slowest = values[np.argmax(values.real)]
    return float(abs(slowest.imag)), float(-slowest.real)


def natural_frequencies(network, held=()) -> np.ndarray:
    """Natural frequencies of a network with every contact closed and no damping [rad/s], ascending
    (:func:`natural_modes`).

    Examples
    --------
    The one-mass train with its seat closed: sqrt((c + K + c_s) / M).

    >>> net = one_mass_train(0.25, 15e6, 67.5e3, 400.0, seat_stiffness=2e8).network()
    >>> bool(np.isclose(natural_frequencies(net)[0], np.sqrt((15e6 + 67.5e3 + 2e8) / 0.25)))
    True
    """
    return natural_modes(network, held)[0]


def pushrod_stiffness(length, diameter, bore=0.0, modulus=STEEL_MODULUS) -> float:
    """Axial stiffness of a pushrod, E A / L [N/m] (a tube of outer ``diameter`` and inner ``bore``)."""
    return modulus * np.pi * (diameter**2 - bore**2) / 4.0 / length


def rocker_stiffness(arm, width, height, modulus=STEEL_MODULUS) -> float:
    """Bending stiffness of a rocker arm at its tip, 3 E I / l^3 with I = b h^3 / 12 [N/m] (a cantilever
    from the shaft; engineering estimate, the sources give none)."""
    return 3.0 * modulus * width * height**3 / 12.0 / arm**3


def camshaft_stiffness(l1, l2, diameter, bore=0.0, modulus=STEEL_MODULUS) -> float:
    """Stiffness of the camshaft under its cam, force / deflection of Valve-train practical works (n.d.) eq. (7.3) [N/m]."""
    return 1.0 / camshaft_deflection(1.0, l1, l2, diameter, bore, modulus)


def series(*stiffnesses) -> float:
    """Stiffness of springs in series, 1 / sum(1/c_i) [N/m]."""
    return 1.0 / sum(1.0 / c for c in stiffnesses)


def pushrod_train(tappet_mass, pushrod_mass, rocker_inertia, valve_mass, valve_arm, rocker_ratio, cam_stiffness,
                  pushrod_stiffness, rocker_stiffness, valve_stiffness, springs, lash=0.0, **kw) -> MultiMassTrain:
    """A pushrod (cam-in-block) :class:`MultiMassTrain`: cam - tappet - pushrod - rocker - valve.

    Used by the tests alone, as the independent reference for the pushrod layout (tests/dynamics/test_models.py,
    tests/design/test_dynamics.py): the package builds its trains from the layout's links
    (:func:`valvetrain.design.dynamics.build_train`).

    Parameters
    ----------
    tappet_mass, pushrod_mass : float
        [kg], on the tappet side.
    rocker_inertia : float
        J about the rocker shaft [kg m^2].
    valve_mass : float
        Valve with retainer and cotters [kg].
    valve_arm : float
        l_v [m]; ``rocker_ratio`` k = l_v / l_t.
    cam_stiffness : float
        Camshaft bending with the cam-tappet contact, tappet side [N/m] (e.g. :func:`camshaft_stiffness`).
    pushrod_stiffness : float
        Axial, tappet side [N/m] (e.g. :func:`pushrod_stiffness`).
    rocker_stiffness : float
        At the valve tip, valve side [N/m] (e.g. :func:`rocker_stiffness`).
    valve_stiffness : float
        Valve stem between the rocker and the retainer [N/m] (a large value if the stem is rigid).
    springs : sequence of CoilSpring
    lash : float
        Valve clearance at the valve [m] (taken up at the cam contact).
    **kw
        ``damping_ratio``, ``seat_stiffness``, ``seat_damping_ratio`` of :class:`MultiMassTrain`.

    Notes
    -----
    Masses at the valve: tappet m_t / k^2, pushrod m_p / k^2 at its middle, rocker J / l_v^2, valve.  The
    pushrod is split into two halves of stiffness 2 c_p / k^2 each side of its mass; the camshaft c_cam / k^2.
    """
    k2 = rocker_ratio**2
    drive = (("tappet", tappet_mass / k2), ("pushrod", pushrod_mass / k2), ("rocker", rocker_inertia / valve_arm**2),
             ("valve", valve_mass))
    links = (cam_stiffness / k2, 2.0 * pushrod_stiffness / k2, 2.0 * pushrod_stiffness / k2,
             series(rocker_stiffness, valve_stiffness))
    notes = ("masses at the valve: m_t/k^2, m_p/k^2, J/l_v^2, valve (Valve-train practical works (n.d.) eq. 5.2)",
             "pushrod mass lumped at its middle between two halves of stiffness 2 c_p",
             "rocker tip and valve stem stiffness in series between rocker and valve")
    return MultiMassTrain("pushrod", drive, links, tuple(springs), float(rocker_ratio), float(lash), notes=notes, **kw)


def rocker_train(rocker_inertia, valve_mass, valve_arm, rocker_ratio, cam_stiffness, rocker_stiffness,
                 valve_stiffness, springs, lash=0.0, **kw) -> MultiMassTrain:
    """An overhead-cam rocker (finger follower) :class:`MultiMassTrain`: cam - rocker - valve.

    Used by the tests alone, as the independent reference for the rocker layout (tests/dynamics/test_models.py,
    tests/design/test_dynamics.py): the package builds its trains from the layout's links
    (:func:`valvetrain.design.dynamics.build_train`).

    The rocker inertia about its pivot gives J / l_v^2 at the valve; the cam stiffness (camshaft and contact,
    cam side) counts c / k^2.
    """
    drive = (("rocker", rocker_inertia / valve_arm**2), ("valve", valve_mass))
    links = (cam_stiffness / rocker_ratio**2, series(rocker_stiffness, valve_stiffness))
    notes = ("masses at the valve: J/l_v^2, valve",)
    return MultiMassTrain("rocker", drive, links, tuple(springs), float(rocker_ratio), float(lash), notes=notes, **kw)


def direct_train(tappet_mass, valve_mass, cam_stiffness, valve_stiffness, springs, lash=0.0, **kw) -> MultiMassTrain:
    """A direct-acting overhead-cam :class:`MultiMassTrain`: cam - bucket tappet - valve (k = 1).

    Used by the tests alone, as the independent reference for the direct layout (tests/dynamics/test_models.py,
    tests/design/test_dynamics.py): the package builds its trains from the layout's links
    (:func:`valvetrain.design.dynamics.build_train`).

    The clearance is between the cam and the bucket (shim).
    """
    drive = (("tappet", tappet_mass), ("valve", valve_mass))
    links = (cam_stiffness, valve_stiffness)
    notes = ("bucket tappet on the valve stem",)
    return MultiMassTrain("direct", drive, links, tuple(springs), 1.0, float(lash), notes=notes, **kw)


def rocker_arm_inertia(mass, arm_valve, arm_tappet) -> float:
    """Moment of inertia of a rocker about its shaft [kg m^2], two slender arms of total mass ``mass`` split in
    proportion to their lengths: J = m (l_v^3 + l_t^3) / (3 (l_v + l_t)) (engineering estimate)."""
    return mass * (arm_valve**3 + arm_tappet**3) / (3.0 * (arm_valve + arm_tappet))

