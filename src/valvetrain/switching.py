"""The switching roller finger follower: a finger (the outer body, on the lash adjuster and the valve) with an inner
arm that carries the roller, pivoted in the body and held against the cam by a lost-motion spring; a latch locks
the inner arm to the body.

Latched, the finger is the rigid :class:`~valvetrain.followers.PivotedFollower`: the cam lifts the valve.  Unlatched
(deactivation), the body stays on its lash adjuster and the shut valve, and the inner arm turns about its pivot O_i
in the body, following the cam against the lost-motion spring: the valve stays shut, and the cam's motion is lost in
the arm.

Model and its approximation.  The roller centre's travel along its arc is the same in both modes to first order:
latched it turns about the finger's pivot P (travel u = L_r (psi - psi_0)), unlatched about the inner arm's pivot O_i
(u = L_i phi); both arcs leave the heel circle square to the same pivot-to-roller line where O_i lies on the line
from P through the roller centre (the usual layout, the inner arm's pivot at the valve end of the body), so the
unlatched arm turns by phi = u / L_i with u the latched finger's travel (:meth:`PivotedFollower.travel_acceleration`).
The arcs differ by their curvature: the error is of the second order in the swing.

SI units: m, rad, s, N, N m, kg m^2, Pa.  Pure functions over numpy arrays.

References
----------
Hendriksma, Kunz, Greene (2007) (the 2-step roller finger follower: the inner arm, its lost-motion spring and latch,
the lost-motion spring sized to keep the arm on its cam up to the over-speed); Norton (2009), the chapter on the
dynamics of follower trains (the follower spring's requirement, F >= m (-a) with a margin, and the jump speed);
Wahl (1944) (the helical torsion spring: its rate and the curvature factor of its bending stress); Johnson (1985),
ch. 4 and Hertz (1882) (the latch's line contact); Merritt (1967) (the orifice equation of the latch pin's oil
passage); Heywood (1988), section 12.4 and Woschni (1967) (the deactivated
cylinder's trapped charge and its heat transfer).  The literature found gives no allowable for the latch's contact
and no range for the lost-motion spring's force ratio: this package's choices are stated where they are used.
"""

from dataclasses import dataclass

import numpy as np

from scipy.integrate import solve_ivp
from scipy.optimize import root_scalar

from .breathing.heat_transfer import WOSCHNI_C1, wall_area, woschni_coefficient
from .crank.kinematics import displacement, velocity as piston_velocity
from .dynamics.models import OneMassTrain, one_mass_train
from .errors import InputError
from .locale import NoteText, note
from .strength import hertz_line_stress


@dataclass(frozen=True, eq=False)
class ArmTravel:
    """The unlatched inner arm's motion on the cam as a lift law of the dynamics' sweep: the roller centre's travel
    u(theta) [m] along its arc with the body at rest (:func:`roller_travel`), from the finger ``follower`` (a
    :class:`~valvetrain.followers.PivotedFollower`) on the valve law ``law`` with the heel radius ``heel`` [m].

    Only :meth:`derivatives` is a law's (the sweep's :func:`~valvetrain.dynamics.sweep.cam_excitation` reads it);
    compared by identity, so that the sweep keeps its samples while it lives.
    """

    law: object
    follower: object
    heel: float

    def derivatives(self, theta) -> np.ndarray:
        """u, u' [m/rad], u'' [m/rad^2] and 0 in place of u''' at camshaft angles ``theta`` [rad from the nose],
        shape (4, n)."""
        d = self.law.derivatives(theta)
        u, du, d2u = roller_travel(self.follower, self.heel, d[0], d[1], d[2])
        return np.stack([u, du, d2u, np.zeros_like(u)])


def roller_travel(follower, heel, h, dh, d2h) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The roller centre's travel along its arc u [m] and its derivatives u' [m/rad], u'' [m/rad^2] by the camshaft
    angle, from the valve law's lift h [m], h' [m/rad], h'' [m/rad^2] through the finger ``follower`` on the heel
    radius ``heel`` [m]: u = L_r (psi - psi_0), u' = L_r psi', u'' = L_r psi''
    (:meth:`~valvetrain.followers.PivotedFollower.angle_derivatives`).

    Examples
    --------
    A finger whose pad is square to the valve at rest, G_0 = L_b = 36 mm, roller arm 22.5 mm: a small valve lift v is
    the travel times G_0 / L_r, so u = v L_r / G_0.

    >>> from valvetrain.followers import PivotedFollower
    >>> f = PivotedFollower(0.00875, -0.022, 0.027, 0.0225, 0.036, 0.0, 0.012, 0.0, 0.0)
    >>> heel = 0.017
    >>> f = PivotedFollower(0.00875, -0.022, 0.027, 0.0225, 0.036, 0.0, 0.012, -f.base_angle(heel), 0.0)
    >>> u = roller_travel(f, heel, np.array([1e-6]), np.zeros(1), np.zeros(1))[0]
    >>> round(float(u[0]) / 1e-6, 4), round(0.0225 / 0.036, 4)
    (0.625, 0.625)
    """
    psi, d1, d2 = follower.angle_derivatives(heel, h, dh, d2h)
    arm = follower.roller_arm
    return arm * (psi - follower.base_angle(heel)), arm * d1, arm * d2


def required_torque(inertia, arm_acceleration, cam_speed, reserve) -> np.ndarray:
    """The lost-motion spring's torque that keeps the unlatched arm on its cam, T = K J omega^2 max(0, -phi'') [N m].

    Parameters
    ----------
    inertia : float
        J_i, the inner arm's moment of inertia about its pivot, its roller included [kg m^2].
    arm_acceleration : ndarray
        phi'' = u'' / L_i, the arm's angular acceleration per camshaft angle squared [rad/rad^2].
    cam_speed : float
        omega, the camshaft speed the arm must follow at (the over-speed) [rad/s].
    reserve : float
        K, the margin over the inertia torque.

    Notes
    -----
    Where the cam decelerates the arm (phi'' < 0) only the spring pushes it on: the contact holds while
    :math:`T(\\phi) \\ge -J\\ddot\\phi`, and the spring is drawn with a margin K over it, as a valve spring over its
    train's inertia force (Norton (2009), the chapter on the dynamics of follower trains; Hendriksma, Kunz, Greene
    (2007), the lost-motion spring of the inner arm).

    >>> float(required_torque(2e-6, np.array([-1.0]), 300.0, 1.5)[0])
    0.27
    """
    return reserve * inertia * cam_speed ** 2 * np.clip(-np.asarray(arm_acceleration, dtype=float), 0.0, None)


def curvature_factor(index) -> float | np.ndarray:
    """K_b = (4C^2 - C - 1) / (4C (C - 1)): the inner fibre's bending stress of a helical torsion spring over the
    straight wire's, C = D / d the spring index (Wahl (1944)).

    >>> round(curvature_factor(8.0), 4)
    1.1027
    """
    c = np.asarray(index, dtype=float)
    out = (4.0 * c ** 2 - c - 1.0) / (4.0 * c * (c - 1.0))
    return out if out.ndim else float(out)


def torsion_rate(modulus, wire_diameter, mean_diameter, coils) -> float | np.ndarray:
    """Rate of a helical torsion spring, k = E d^4 / (64 D N) [N m/rad] (Wahl (1944); the arms' own bending
    neglected).

    >>> round(torsion_rate(2.06e11, 1.5e-3, 12e-3, 4.0), 4)
    0.3395
    """
    return modulus * wire_diameter ** 4 / (64.0 * mean_diameter * coils)


def torsion_coils(modulus, wire_diameter, mean_diameter, rate) -> float | np.ndarray:
    """The active coils N = E d^4 / (64 D k) of a helical torsion spring of rate ``rate`` [N m/rad]
    (:func:`torsion_rate` solved for N)."""
    return modulus * wire_diameter ** 4 / (64.0 * mean_diameter * rate)


def torsion_stress(torque, wire_diameter, mean_diameter) -> float | np.ndarray:
    """Bending stress of a helical torsion spring's wire at its inner fibre, sigma = K_b 32 T / (pi d^3) [Pa]
    (:func:`curvature_factor`; Wahl (1944))."""
    return curvature_factor(mean_diameter / wire_diameter) * 32.0 * np.asarray(torque) / (np.pi * wire_diameter ** 3)


def arm_frequency(rate, inertia) -> float:
    """The inner arm's natural frequency on its lost-motion spring, off the cam, f = sqrt(k / J) / (2 pi) [Hz].

    Parameters
    ----------
    rate : float
        k, the lost-motion spring's torsional rate about the arm's pivot [N m/rad].
    inertia : float
        J_i, the arm's moment of inertia about its pivot [kg m^2].

    Notes
    -----
    :math:`J\\ddot\\phi + k\\phi = 0` gives :math:`f = \\frac{1}{2\\pi}\\sqrt{k / J}`.

    >>> round(arm_frequency(0.5, 2e-6), 2)
    79.58
    """
    return float(np.sqrt(rate / inertia) / (2.0 * np.pi))


def arm_train(inertia, inner_arm, rate, preload, stiffness) -> OneMassTrain:
    """The unlatched inner arm as a one-mass train at the roller's travel (:class:`~valvetrain.dynamics.models.
    OneMassTrain`): mass J / L_i^2 [kg], the lost-motion spring's rate k / L_i^2 [N/m] and preload T_0 / L_i [N], the
    contact stiffness c [N/m] between cam and arm; the arm's rest on its stop in the body is the train's seat.

    Parameters
    ----------
    inertia : float
        J_i [kg m^2].
    inner_arm : float
        L_i, the arm's pivot to its roller centre [m].
    rate, preload : float
        k [N m/rad] and T_0 [N m] of the lost-motion spring about the arm's pivot.
    stiffness : float
        c [N/m] of the arm at its roller: the cam contact and the arm's bending in series.
    """
    return one_mass_train(inertia / inner_arm ** 2, stiffness, rate / inner_arm ** 2, preload / inner_arm)


def quasi_static_jump_speed(mass, preload, rate, travel, acceleration) -> float:
    """The camshaft speed at which a rigid follower leaves its cam, min sqrt((F_0 + K u) / (m (-a))) over the
    angles where a < 0 [rad/s] (inf where the cam never decelerates it, 0 where the spring's force F_0 + K u is
    nowhere positive enough to hold it even at rest).

    Parameters
    ----------
    mass : float
        m [kg] at the travel u.
    preload : float or ndarray
        F_0 [N] of the spring that holds it on (an array: a force of its own at each angle, another spring's load
        subtracted).
    rate : float
        K [N/m] of that spring.
    travel : ndarray
        u [m], the spring's deflection from F_0 over the cam.
    acceleration : ndarray
        a [m/rad^2], the follower's acceleration by the camshaft angle over the cam: u'' where the spring's seat is
        fixed; the follower's own where the seat moves (the two-step finger's arm, its spring on the moving body).

    Notes
    -----
    The contact force of a rigid train is :math:`F = F_0 + K u + m\\omega^2 a`; it first reaches zero where
    :math:`\\omega^2 = (F_0 + K u) / (m(-a))` is smallest, or at rest where :math:`F_0 + K u \\le 0` (Norton (2009),
    the chapter on the dynamics of follower trains: the follower jump of a force-closed cam).

    >>> round(quasi_static_jump_speed(0.01, 10.0, 0.0, np.zeros(2), np.array([1.0, -0.001])), 3)
    1000.0
    >>> quasi_static_jump_speed(0.01, np.array([10.0, -1.0]), 0.0, np.zeros(2), np.array([-0.001, 0.0]))
    0.0
    """
    u = np.asarray(travel, dtype=float)
    a = np.asarray(acceleration, dtype=float)
    static = np.broadcast_to(preload + rate * u, u.shape)
    if static.min() <= 0.0:
        return 0.0
    down = a < 0.0
    if not down.any():
        return float("inf")
    return float(np.sqrt(np.min(static[down] / (mass * -a[down]))))


def latch_force(cam_force, inner_arm, latch_arm) -> float | np.ndarray:
    """The force the latch carries in the latched mode, P = N L_i / L_l [N]: the cam's force ``cam_force`` N [N] at
    the roller, ``inner_arm`` L_i [m] from the arm's pivot, held by the latch ``latch_arm`` L_l [m] from it.

    Notes
    -----
    The inner arm's moments about its pivot O_i: the cam's force at the roller against the latch's; the arm is taken
    square to the cam's force (its moment arm L_i, the largest) and the lost-motion spring's torque, which helps the
    latch, is left out: both make P an upper bound.

    >>> latch_force(1500.0, 0.02, 0.01)
    3000.0
    """
    return cam_force * inner_arm / latch_arm


def latch_curvature(pin_diameter, seat_radius=None) -> float:
    """The curvature sum of the latch pin on its seat, 2 / d - 1 / R [1/m]: a pin of diameter d in a concave seat of
    radius R > d / 2 (None: a flat seat)."""
    return 2.0 / pin_diameter - (0.0 if seat_radius is None else 1.0 / seat_radius)


def latch_stress(force, width, pin_diameter, modulus, seat_radius=None) -> float | np.ndarray:
    """Hertz stress of the latch pin on its seat, a line contact [Pa] (:func:`valvetrain.strength.hertz_line_stress`
    with :func:`latch_curvature`; Hertz (1882), Johnson (1985), ch. 4).

    Parameters
    ----------
    force : float or ndarray
        P [N] (:func:`latch_force`).
    width : float
        b, the contact's length along the pin [m].
    pin_diameter : float
        d [m].
    modulus : float
        E_m of the pair [Pa] (equal steels: E).
    seat_radius : float, optional
        R [m] of a concave seat; None: flat.
    """
    return hertz_line_stress(force, width, latch_curvature(pin_diameter, seat_radius), modulus)


def valve_force_of_arm(arm_force, roller_arm, rest_arm) -> float | np.ndarray:
    """The force at the shut valve that the unlatched arm's contact force ``arm_force`` N [N] makes through the body,
    N L_r / G_0 [N] (``roller_arm`` L_r, ``rest_arm`` G_0 = dv/dpsi at rest [m]).

    Notes
    -----
    The lost-motion spring acts between arm and body: on the body the pair is the cam's force at the roller, as if
    latched; the virtual work of the body about its pivot P, :math:`N L_r\\cos\\beta = F G_0`, gives the force at
    the valve, here with cos beta = 1 (an upper bound).  The valve stays shut while F stays below the valve spring's
    installed force (Hendriksma, Kunz, Greene (2007): the lost-motion spring must not open the deactivated valve).

    >>> valve_force_of_arm(60.0, 0.0225, 0.036)
    37.5
    """
    return arm_force * roller_arm / rest_arm


def latch_travel_time(mass, area, stroke, preload, rate, supply, passage_area, density, discharge_coefficient,
                      engage=True) -> float:
    """The time [s] the latch pin takes over its stroke: pushed by the oil against its return spring (``engage``), or
    pushed back by the spring while its oil drains through the same passage.

    Parameters
    ----------
    mass : float
        m, the pin [kg].
    area : float
        A, the pin's face under the oil [m^2].
    stroke : float
        s [m].
    preload, rate : float
        F_0 [N] at the pin's home and k [N/m] of its return spring, F = F_0 + k x.
    supply : float
        p_s, the oil's gauge pressure at the passage [Pa] (draining: to 0).
    passage_area, density, discharge_coefficient : float
        A_o [m^2] of the oil passage to the pin's chamber, the oil's rho [kg/m^3], its C_d.
    engage : bool
        True: from home (x = 0) to the stroke's end under the oil; False: back from the stroke's end to home.

    Returns
    -------
    float
        The time from rest to the stroke's end; inf where the pin stops short of it (engaging: p_s A <= F_0 + k s).

    Notes
    -----
    The pin's motion with the pressure in its chamber set by the flow through the passage, the orifice equation
    Q = C_d A_o sign(dp) sqrt(2 |dp| / rho) (Merritt (1967)) solved for the chamber's pressure at the pin's flow
    Q = A v (the oil's compressibility and the passage's own inertia left out):

    .. math:: m\\ddot x = p_c A - (F_0 + k x), \\qquad
              p_c = p_0 - \\operatorname{sign}(\\dot x)\\,\\frac{\\rho}{2}\\left(\\frac{A\\dot x}{C_d A_o}\\right)^2

    with p_0 = p_s engaging and 0 draining, integrated from rest until the pin reaches the stroke's end.  Without
    mass it is first order, the orifice-limited speed; without the passage's drop, the pin under a constant net force
    reaches the end in sqrt(2 s m / (p_s A - F_0)) (the tests' two limits).

    Examples
    --------
    A 2 g pin of 4 mm over 1.5 mm, its passage wide open: the inertial limit sqrt(2 s m / (p_s A - F_0)).

    >>> a = np.pi * 0.004 ** 2 / 4
    >>> t = latch_travel_time(0.002, a, 1.5e-3, 1.5, 0.0, 0.3e6, 1.0, 870.0, 0.7)
    >>> round(float(t / np.sqrt(2 * 1.5e-3 * 0.002 / (0.3e6 * a - 1.5))), 6)
    1.0
    """
    if engage and supply * area <= preload + rate * stroke:
        return float("inf")
    head = supply if engage else 0.0
    resist = 0.5 * density * (area / (discharge_coefficient * passage_area)) ** 2 * area

    def motion(t, y):
        x, v = y
        return [v, (head * area - np.sign(v) * resist * v * v - preload - rate * x) / mass]

    def arrives(t, y):
        return y[0] - (stroke if engage else 0.0)

    arrives.terminal = True
    # a first bound: the time of the orifice-limited speed at the smallest driving force, times ten, or the inertial
    driving = (supply * area - preload - rate * stroke) if engage else preload
    bound = 10.0 * (stroke / np.sqrt(driving / resist) + np.sqrt(2.0 * stroke * mass / driving))
    sol = solve_ivp(motion, (0.0, bound), [0.0 if engage else stroke, 0.0], method="LSODA", events=arrives,
                    rtol=1e-10, atol=[1e-12 * stroke, 1e-12])
    return float(sol.t_events[0][0]) if sol.t_events[0].size else float("inf")


@dataclass(frozen=True)
class AirSpring:
    """The steady cycle of a deactivated cylinder's trapped charge (:func:`air_spring`).

    Attributes (SI)
    ---------------
    crank : ndarray
        Crank angles of the last revolution [rad from TDC].
    pressure, temperature : ndarray
        The charge's pressure [Pa] and temperature [K] there.
    work : float
        Its work on the piston over a revolution, the integral of p dV [J] (negative: the crank works on it).
    heat : float
        The heat it takes from the walls over the revolution [J].
    revolutions : int
        Revolutions integrated: the secant steps to the temperature at the bottom dead centre that repeats, and the
        last.
    """

    crank: np.ndarray
    pressure: np.ndarray
    temperature: np.ndarray
    work: float
    heat: float
    revolutions: int


def air_spring(bore, stroke, rod_length, compression_ratio, mass, temperature, wall_temperature, speed, gas_constant,
               gamma, heat_transfer=True, tolerance=1e-6, most=40) -> AirSpring:
    """The trapped charge of a deactivated cylinder (both valves shut all cycle) compressed and expanded by its piston,
    with the heat it exchanges with the walls, in the revolution that repeats (its temperature at the bottom dead
    centre found by the secant method, each step a revolution).

    Parameters
    ----------
    bore, stroke, rod_length : float
        [m].
    compression_ratio : float
        epsilon = V_max / V_min.
    mass : float
        The trapped charge [kg] (leakage past the rings is left out).
    temperature : float
        Its temperature at the bottom dead centre, the first guess of the repeating revolution's [K].
    wall_temperature : float
        [K].
    speed : float
        Crank speed [rad/s].
    gas_constant, gamma : float
        R [J/(kg K)] and c_p / c_v of the charge, taken constant.
    heat_transfer : bool
        False: adiabatic (the reference: no net work).
    tolerance : float
        Largest relative change of the temperature at the bottom dead centre over a revolution at which it repeats.
    most : int
        Most secant steps to the repeating revolution's temperature at the bottom dead centre (each one revolution).

    Notes
    -----
    The first law of the closed charge, c_v constant, by the crank angle theta:

    .. math:: m c_v \\frac{dT}{d\\theta} = -p\\frac{dV}{d\\theta} + \\frac{h A (T_w - T)}{\\omega},
              \\qquad p = \\frac{m R T}{V}

    with Woschni's coefficient h of the closed period (C_1 = 2.28, no combustion term) and the pancake chamber's wall
    area A (:mod:`valvetrain.breathing.heat_transfer`).  The work over a repeating revolution is the heat taken in,
    :math:`\\oint p\\,dV = \\oint \\delta Q` (the test of the integration); adiabatic, the charge follows
    :math:`TV^{\\gamma - 1}` = const both ways and :math:`\\oint p\\,dV = 0`: the air spring returns its work, and
    with the walls the loss is the heat's irreversibility (Heywood (1988), section 12.4; Woschni (1967)).

    Examples
    --------
    Adiabatic: the pressure at TDC is p_BDC epsilon^gamma.

    >>> s = air_spring(0.086, 0.086, 0.145, 10.0, 5.8e-4, 300.0, 400.0, 300.0, 287.0, 1.4, heat_transfer=False)
    >>> p0 = 5.8e-4 * 287.0 * 300.0 / (np.pi * 0.086**2 / 4 * 0.086 * 10.0 / 9.0)
    >>> round(float(s.pressure.max() / (p0 * 10.0 ** 1.4)), 4)
    1.0
    """
    area = np.pi * bore ** 2 / 4.0
    swept = area * stroke
    clearance = swept / (compression_ratio - 1.0)
    radius, lam = stroke / 2.0, stroke / (2.0 * rod_length)
    cv = gas_constant / (gamma - 1.0)
    piston_speed = 2.0 * stroke * speed / (2.0 * np.pi)
    coefficient = WOSCHNI_C1["compression"] * piston_speed if heat_transfer else 0.0

    def volume(theta):
        """V [m^3] and dV/dtheta [m^3/rad] of the exact slider-crank."""
        return (clearance + area * displacement(theta, radius, lam),
                area * piston_velocity(theta, radius, lam, 1.0))

    def rates(theta, y):
        v, dv = volume(theta)
        t = y[0]
        p = mass * gas_constant * t / v
        h = woschni_coefficient(bore, p, t, coefficient) if heat_transfer else 0.0
        q = h * wall_area(v, bore) * (wall_temperature - t) / speed
        return [(q - p * dv) / (mass * cv), p * dv, q]

    start = np.pi
    grid = start + np.linspace(0.0, 2.0 * np.pi, 721)

    def revolution(t0):
        return solve_ivp(rates, (start, start + 2.0 * np.pi), [t0, 0.0, 0.0], method="DOP853", t_eval=grid,
                         rtol=1e-10, atol=[1e-9, 1e-12, 1e-12])

    if heat_transfer:    # adiabatic, every revolution repeats: the one from ``temperature``
        found = root_scalar(lambda t0: float(revolution(t0).y[0, -1]) - t0, x0=temperature,
                            x1=0.95 * temperature, method="secant", xtol=tolerance * temperature,
                            maxiter=most)
        if not found.converged:
            raise InputError(NoteText(note("switching.charge_unsettled", revolutions=most)))
        temperature, n = found.root, found.function_calls + 1
    else:
        n = 1
    sol = revolution(temperature)
    v, _ = volume(sol.t)
    return AirSpring(sol.t - 2.0 * np.pi, mass * gas_constant * sol.y[0] / v, sol.y[0], float(sol.y[1, -1]),
                     float(sol.y[2, -1]), n)
