"""Drive stage of a valve design: reduced masses, spring characteristic and design, strength of the
drive parts (Valve-train practical works (n.d.), works 5-7).

:func:`drive_stage` takes SI inputs (the valve's and ``[gas]``'s SI views,
:func:`valvetrain.specification.si`, and the law stage's :class:`~valvetrain.design.valve.CamResult`) to a
typed, frozen :class:`DriveResult` (masses and springs); :func:`strength_stage` checks the drive parts over the
engine speeds from the lowest to the over-speed, on the dynamics stage's contact force where it ran;
:func:`drive_record` is where they leave SI, as the ``masses``, ``spring`` and ``strength`` records of
results.json.
"""

from dataclasses import dataclass, field, replace
from typing import Any, Optional, Union

import numpy as np

from .. import flow, masses, springs, strength
from ..checks import Check, check
from ..layouts import chain, finger_inertia, layout, train_mass
from ..locale import record_text
from ..locale.wording import diagnosis_text
from ..numerics import TIE_RTOL, first_largest
from ..spring_materials import grade
from ..specification.si import si_name
from ..units import to_display
from .dynamics import SPEED_RANGE
from .results import quantity, record


SHANG_2_1 = "Shang Hanji (1988), section 2.1"
NORTON = "Norton (2009)"
WORKS_7_1 = "Valve-train practical works (n.d.), work 7, eq. (7.1)"

IDLE_SPEED_RATIO = SPEED_RANGE[0]
"""Lowest speed of the strength checks as a fraction of the rated speed where neither ``[engine] idle_speed_rpm`` nor
a ``[dynamics]`` section gives one: the dynamics stage's default idle, 0.1.  At or below the idle of engines (700 rpm
idle for 7000 rpm rated is 0.1), and low enough that the inertia of the train is 1 % of its rated value: the spring
alone loads the nose, the worst case of the spring-dominated checks (Valve-train practical works (n.d.), eq. (7.1))."""

STRENGTH_SPEEDS = 41
"""Engine speeds of the quasi-static strength checks, evenly spaced over the range (the rated speed added): the
quasi-static force is linear in the square of the speed, so its extremes at every angle lie at the ends of the
range; the speeds between give the per-speed table."""

LOWEST_SPEED_SOURCES = ("engine.idle_speed_rpm", "the low end of the dynamics speed range",
                        f"{IDLE_SPEED_RATIO:g} x the rated speed (the default idle)")
"""Where the lowest speed of the strength checks comes from (:func:`strength_speed_range`)."""


@dataclass(frozen=True)
class TrainDynamics:
    """The one-mass train with the drive stiffness (Shang Hanji (1988), sections 1 and 3.3)."""

    stiffness: float = quantity("drive_stiffness_N_per_mm", "N/mm", "drive stiffness c at the valve")
    natural_frequency: float = quantity("natural_frequency_Hz", "Hz", "natural frequency sqrt((c + K)/M) / 2 pi")
    epsilon: float = quantity("epsilon", label="perturbation parameter M omega^2 / (c + K)")


@dataclass(frozen=True)
class MassResult:
    """Reduced masses of the train (Valve-train practical works (n.d.), eq. 5.2 or the specific mass of work 5)."""

    at_valve: float = quantity("at_valve_kg", "kg", "reduced mass at the valve m_v")
    at_tappet: float = quantity("at_tappet_kg", "kg", "reduced mass at the tappet m_t = m_v i_k^2")
    source: str = quantity("source", label="how the reduced mass was obtained")
    layout: str = quantity("layout", label="drive layout: direct, rocker or pushrod")
    train: Optional[TrainDynamics] = quantity("train", flatten=True, default=None)


@dataclass(frozen=True)
class SpringRecord:
    """One designed spring: loads, geometry, stresses, frequency and margins (Valve-train practical works (n.d.), works 5-6)."""

    preload: float = quantity("preload_N", "N", "preload P_min at the closed valve")
    max_force: float = quantity("max_force_N", "N", "force P_max at full lift")
    rate: float = quantity("rate_N_per_mm", "N/mm", "rate C")
    wire_diameter: float = quantity("wire_mm", "mm", "wire diameter d")
    mean_diameter: float = quantity("mean_diameter_mm", "mm", "mean coil diameter D")
    outer_diameter: float = quantity("outer_diameter_mm", "mm", "outside diameter D + d")
    active_coils: float = quantity("active_coils", label="working coils i_p")
    total_coils: float = quantity("total_coils", label="total coils i_p + 2")
    free_length: float = quantity("free_length_mm", "mm", "free length")
    installed_length: float = quantity("installed_length_mm", "mm", "length at the closed valve")
    min_length: float = quantity("min_length_mm", "mm", "length at full lift")
    min_pitch: float = quantity("min_pitch_mm", "mm", "pitch at full lift")
    installed_pitch: float = quantity("installed_pitch_mm", "mm", "pitch at the closed valve")
    free_pitch: float = quantity("free_pitch_mm", "mm", "free pitch")
    preload_deflection: float = quantity("preload_deflection_mm", "mm", "f_min, deflection at the closed valve")
    max_deflection: float = quantity("max_deflection_mm", "mm", "f_max, deflection at full lift")
    spring_index: float = quantity("spring_index", label="D / d")
    shape_factor: float = quantity("shape_factor", label="chi from the table of work 6")
    wahl_factor: float = quantity("wahl_factor", label="Wahl factor, for comparison")
    tau_max: float = quantity("tau_max_MPa", "MPa", "largest shear stress")
    tau_min: float = quantity("tau_min_MPa", "MPa", "smallest shear stress")
    safety_factor: float = quantity("safety_factor", label="fatigue safety n (eq. 6.12)")
    natural_frequency: float = quantity("natural_frequency_Hz", "Hz", "first natural frequency")
    resonance_ratio: float = quantity("resonance_ratio", label="omega_c1 / omega_cam")
    mass: float = quantity("mass_kg", "kg", "spring mass")
    material: str = quantity("material", label="wire grade")
    target_deflection_ratio: Optional[float] = quantity("target_deflection_ratio",
                                                        label="f_max / f_min of the line designed for")
    guide_sleeve_needed: bool = quantity("guide_sleeve_needed", label="free length / D > 2.5")
    passes_all_checks: bool = quantity("passes_all_checks", label="every check of the spring passes")
    binding_check: str = quantity("binding_check", label="the check with the smallest margin")
    margins: dict[str, float] = quantity("margins", label="relative margin of each check (>= 0 passes)")
    design_margin: float = quantity("design_margin_percent", "%", "the smaller margin of the fatigue safety and the "
                                    "resonance ratio above their minima")


def spring_record(s) -> SpringRecord:
    """The :class:`SpringRecord` of a :class:`valvetrain.springs.SpringDesign`."""
    c, n = s.characteristic, s.lengths
    return SpringRecord(
        c.preload, c.max_force, c.rate, s.wire_diameter, s.mean_diameter, s.mean_diameter + s.wire_diameter, s.coils,
        s.coils + 2.0, n["free_length"], n["installed_length"], n["min_length"], n["min_pitch"], n["installed_pitch"],
        n["free_pitch"], c.preload_deflection, c.max_deflection, s.mean_diameter / s.wire_diameter, s.shape_factor,
        s.wahl, s.tau_max, s.tau_min, s.safety, s.natural_frequency / (2 * np.pi), s.resonance_ratio, s.mass,
        s.material, s.target_ratio, bool(n["free_length"] / s.mean_diameter > 2.5), s.passes, s.binding_check,
        s.margins, s.design_margin)


@dataclass(frozen=True)
class ConflictRecord:
    """A failing check of the best spring candidate (:class:`valvetrain.springs.Conflict`) as results.json gives it:
    value and bound in the check's own display unit."""

    spring: str = quantity("spring", label="spring, or outer / inner of a pair")
    check: str = quantity("check", label="the check's key")
    name: str = quantity("quantity", label="the check's quantity")
    value: float = quantity("value", label="the candidate's value, in unit")
    limit: float = quantity("limit", label="the bound it misses, in unit")
    unit: str = quantity("unit", label="the display unit of value and limit")
    shortfall: float = quantity("shortfall", label="relative distance beyond the bound")


@dataclass(frozen=True)
class StressWindowRecord:
    """The room the resonance check leaves between stress limits (:class:`valvetrain.springs.StressWindow`, SI)."""

    material: str = quantity("material", label="the grade")
    deflection_ratio: float = quantity("deflection_ratio", label="f_max / f_min where the room is largest")
    max_deflection: float = quantity("max_deflection_mm", "mm", "f_max = h r / (r - 1)")
    needed: float = quantity("stress_needed_MPa", "MPa", "tau_max the resonance ratio needs at D/d = 12")
    allowed: float = quantity("stress_allowed_MPa", "MPa", "the largest tau_max the grade allows at the thinnest wire")


@dataclass(frozen=True)
class RemedyRecord:
    """A change tried by a new search (:class:`valvetrain.springs.Remedy`) as results.json gives it: ``to`` in the
    specification's units (the installed length in mm; none where no length was found)."""

    change: str = quantity("change", label="what the remedy changes")
    to: Union[str, int, float, None] = quantity("to", label="the value suggested or the furthest tried",
                                                  omit_none=True)
    spring_mass: Optional[float] = quantity("spring_mass_kg", "kg", "mass of the passing spring(s)", omit_none=True)
    rated_speed: Optional[float] = quantity("rated_speed_rpm", "rpm", "the lowered rated crank speed", omit_none=True)


@dataclass(frozen=True)
class DiagnosisRecord:
    """Why no spring passes and what would help (:class:`valvetrain.springs.Diagnosis`), with its English text."""

    conflicts: tuple[ConflictRecord, ...] = quantity("conflicts", label="failing checks of the best candidate")
    resonance: Optional[StressWindowRecord] = quantity("resonance", label="the stress window of the resonance check",
                                                       omit_none=True)
    remedies: tuple[RemedyRecord, ...] = quantity("remedies", label="changes with which a spring passes")
    tried: tuple[RemedyRecord, ...] = quantity("tried", label="changes tried in vain")
    text: str = quantity("text", label="the diagnosis in English")


def _remedy_record(r) -> RemedyRecord:
    """A remedy as results.json gives it: the value in the specification's units, the spring mass, the speed."""
    to = r.value if r.change != springs.diagnosis.INSTALLED_LENGTH or r.value is None else to_display(r.value, "mm")
    change = "max_installed_length_mm" if r.change == springs.diagnosis.INSTALLED_LENGTH else r.change
    return RemedyRecord(change, to, r.spring_mass, r.rated_speed)


def diagnosis_record(d) -> DiagnosisRecord:
    """The ``spring.diagnosis`` record of results.json of a :class:`valvetrain.springs.Diagnosis`: the conflicts in
    their display units, the stress window, the remedies that help and those tried in vain, the English text
    (:func:`valvetrain.locale.wording.diagnosis_text`)."""
    w = d.window
    return DiagnosisRecord(
        tuple(ConflictRecord(x.spring, x.check, x.quantity, to_display(x.value, x.unit), to_display(x.limit, x.unit),
                             x.unit, x.shortfall) for x in d.conflicts),
        None if w is None else StressWindowRecord(w.material, w.deflection_ratio, w.max_deflection, w.needed,
                                                  w.allowed),
        tuple(_remedy_record(r) for r in d.helped), tuple(_remedy_record(r) for r in d.tried),
        diagnosis_text(d, "en"))


@dataclass(frozen=True)
class SpringResult:
    """The required spring line and the designed spring (or nested pair) (Valve-train practical works (n.d.), works 5-6).

    The designed spring's record (for a pair: the outer spring's, with the pair's loads) is merged into this one.
    """

    count: int = quantity("count", label="springs: 1 or a nested pair")
    material: Union[str, tuple[str, ...]] = quantity("material", label="the grade (or grades) searched")
    preload: float = quantity("preload_N", "N", "preload of the chosen spring(s)")
    max_force: float = quantity("max_force_N", "N", "force at full lift of the chosen spring(s)")
    rate: float = quantity("rate_N_per_mm", "N/mm", "rate of the chosen spring(s)")
    required_preload: float = quantity("required_preload_N", "N", "preload of the required line")
    required_rate: float = quantity("required_rate_N_per_mm", "N/mm", "rate of the required line")
    required_max_force: float = quantity("required_max_force_N", "N", "force at full lift of the required line")
    required_deflection_ratio: float = quantity("required_deflection_ratio", label="f_max / f_min of the required line")
    preload_set_by_gas_force: bool = quantity("preload_set_by_gas_force", label="the gas force sets the preload")
    gas_force: float = quantity("gas_force_N", "N", "gas force that tends to open the closed valve")
    gas_force_source: str = quantity("gas_force_source", label="source of the gas force")
    preload_set_by_seat_load: bool = quantity("preload_set_by_seat_load", label="the seat load sets the preload")
    seat_load: float = quantity("seat_load_N", "N", "smallest preload that holds the valve on its seat")
    seat_load_source: str = quantity("seat_load_source", label="source of the seat load")
    deflection_ratio: float = quantity("deflection_ratio", label="f_max / f_min of the chosen spring(s)")
    spring_reserve: float = quantity("spring_reserve", label="spring reserve K_z")
    min_margin: float = quantity("min_margin_percent", "%", "design margin asked of the fatigue safety and the "
                                 "resonance ratio")
    candidates_passing: int = quantity("candidates_passing", label="candidates that pass every check")
    candidates_tried: int = quantity("candidates_tried", label="candidates tried")
    diagnosis: Optional[DiagnosisRecord] = quantity("diagnosis", label="why no spring passes and what would help",
                                                    omit_none=True)
    design: SpringRecord = quantity("design", flatten=True)
    outer: Optional[SpringRecord] = quantity("outer", label="outer spring of a pair", omit_none=True, default=None)
    inner: Optional[SpringRecord] = quantity("inner", label="inner spring of a pair", omit_none=True, default=None)
    inner_share: Optional[float] = quantity("inner_share", label="share of the force on the inner spring",
                                            omit_none=True, default=None)


@dataclass(frozen=True)
class StrengthPerSpeed:
    """The largest cam force and contact stress at each engine speed of the strength checks (SI)."""

    speed: tuple[float, ...] = quantity("speed_rpm", "rpm", "engine speed")
    load: tuple[str, ...] = quantity("load", label="the cam force at that speed: quasi-static or dynamic")
    cam_force_max: tuple[float, ...] = quantity("cam_force_max_N", "N", "largest cam force")
    cam_force_max_angle: tuple[float, ...] = quantity("cam_force_max_cam_deg", "cam deg", "where, from the nose")
    contact_stress: Optional[tuple[float, ...]] = quantity("cam_contact_stress_MPa", "MPa", "largest Hertz stress "
                                                           "of the cam contact", omit_none=True)
    contact_stress_angle: Optional[tuple[float, ...]] = quantity("cam_contact_stress_cam_deg", "cam deg",
                                                                 "where, from the nose", omit_none=True)


@dataclass(frozen=True)
class FingerLoads:
    """The largest loads of a finger follower over the speed range (:meth:`valvetrain.followers.PivotedFollower.loads`;
    Norton (2009))."""

    roller_load_max: float = quantity("finger_roller_load_max_N", "N", "largest load on the roller and its bearing")
    pivot_load_max: float = quantity("finger_pivot_load_max_N", "N", "largest load on the pivot (the lash adjuster)")
    bending_moment_max: float = quantity("finger_bending_moment_max_Nm", "N m",
                                         "largest bending moment of the finger at its critical section")
    bending_stress_max: Optional[float] = quantity("finger_bending_stress_max_MPa", "MPa", "largest bending stress of "
                                                   "the finger at its critical section", omit_none=True, default=None)


@dataclass(frozen=True)
class StrengthResult:
    """The cam load over the speed range and the strength checks of the drive parts at their worst (Valve-train
    practical works (n.d.), work 7)."""

    speed_range: tuple[float, ...] = quantity("speed_range_rpm", "rpm", "engine speeds checked: the lowest to the "
                                              "over-speed")
    lowest_speed_source: str = quantity("lowest_speed_source", label="where the lowest speed comes from")
    cam_force_max: float = quantity("cam_force_max_N", "N", "largest force between cam and follower P_T max")
    cam_force_max_angle: float = quantity("cam_force_max_cam_deg", "cam deg", "where the cam force is largest")
    cam_force_max_speed: float = quantity("cam_force_max_speed_rpm", "rpm", "engine speed of the largest cam force")
    valve_force_max: float = quantity("valve_force_max_N", "N", "P_T max / i_k")
    gas_force_at_opening: float = quantity("gas_force_at_opening_N", "N", "gas force on the exhaust valve head at "
                                           "opening (eq. 7.1)")
    contact_stress_angle: Optional[float] = quantity("cam_contact_stress_cam_deg", "cam deg",
                                                     "where the contact stress is largest", omit_none=True)
    contact_stress_speed: Optional[float] = quantity("cam_contact_stress_speed_rpm", "rpm",
                                                     "engine speed of the largest contact stress", omit_none=True)
    side_force_max: Optional[float] = quantity("roller_side_force_max_N", "N", "largest side force of the roller "
                                               "follower on its guide, P_T tan(alpha)", omit_none=True)
    side_force_angle: Optional[float] = quantity("roller_side_force_cam_deg", "cam deg",
                                                 "where the side force is largest", omit_none=True)
    side_force_speed: Optional[float] = quantity("roller_side_force_speed_rpm", "rpm",
                                                 "engine speed of the largest side force", omit_none=True)
    per_speed: StrengthPerSpeed = quantity("per_speed", label="the largest cam force and contact stress at each speed")
    checks: tuple[Check, ...] = ()     # the strength checks (quantity with underscores)
    not_checked: tuple[str, ...] = ()  # the checks whose parts are not given, each with the keys missing
    rated_speed: float = 0.0       # the engine's rated speed [rad/s] (for the plot)
    finger: Optional[FingerLoads] = quantity("finger", flatten=True, default=None)
    contact_force: Optional[float] = quantity("cam_contact_force_N", "N", "cam force where the contact stress is "
                                              "largest", omit_none=True, default=None)


@dataclass(frozen=True)
class LoadMap:
    """The force between cam and follower over engine speeds x camshaft angles (SI)."""

    kind: str                      # "quasi-static" or "dynamic"
    speeds: np.ndarray             # engine speeds [rad/s], (S,)
    theta: np.ndarray              # camshaft angles [rad from the nose], (n,)
    force: np.ndarray              # force at the cam [N], (S, n)


@dataclass(frozen=True)
class Worst:
    """The largest value of a quantity over the load maps, and where: engine speed [rad/s], cam angle [rad]; the cam
    force there [N]."""

    value: float
    speed: float
    angle: float
    kind: str
    force: float


@dataclass(frozen=True)
class SpringLines:
    """The spring characteristics at the valve, P(y) = P_min + C y (:class:`valvetrain.springs.Characteristic`:
    preload [N], rate [N/m], valve lift [m]; Valve-train practical works (n.d.), eqs. 5.6-5.9).

    Attributes
    ----------
    required : Characteristic
        The required line: the least spring force over the lift with the reserve K_z.
    chosen : Characteristic
        The designed spring, or the pair's sum.
    outer, inner : Characteristic or None
        Each spring of a nested pair (None for one spring).
    """

    required: springs.Characteristic
    chosen: springs.Characteristic
    outer: Optional[springs.Characteristic] = None
    inner: Optional[springs.Characteristic] = None

    def named(self) -> tuple[tuple[str, springs.Characteristic], ...]:
        """``(name, line)`` of the lines there are, in drawing order: required, outer, inner, chosen."""
        lines = (("required", self.required), ("outer", self.outer), ("inner", self.inner), ("chosen", self.chosen))
        return tuple((name, line) for name, line in lines if line is not None)


@dataclass(frozen=True)
class DriveResult:
    """The drive stage of one valve: masses, springs, strength (SI), every check and the curves for the report."""

    masses: MassResult
    spring: SpringResult
    strength: Optional[StrengthResult]             # set by :func:`strength_stage` (None from drive_stage alone)
    checks: tuple[Check, ...]      # every check of the drive, passed or not
    lift: np.ndarray = field(repr=False)             # valve lift along the open event [m]
    inertia_force: np.ndarray = field(repr=False)    # m_v |j_v| where j_v < 0 (a finger's by its variable ratio) [N]
    required_force: np.ndarray = field(repr=False)   # K_z m_v |j_v| [N]
    lines: SpringLines = field(repr=False)   # required, chosen and a pair's outer and inner spring lines
    diagnosis: Optional[springs.Diagnosis] = None   # why no spring passes, where none does


def drive_record(drive) -> dict[str, Any]:
    """The ``masses``, ``spring`` and ``strength`` records of results.json (engineering units)."""
    st = drive.strength
    return {"masses": record(drive.masses), "spring": record(drive.spring),
            "strength": {**record(st), "checks": {c.code.removeprefix("strength."): _strength_record(c) for c in st.checks},
                         "not_checked": list(st.not_checked)}}


def spring_options(sp) -> springs.SpringOptions:
    """The spring search of a spring section's SI view (grades, overrides, ranges, arrangement); the wire series
    is a catalogue grid in mm (:func:`valvetrain.springs.wire_series`)."""
    names = (sp.material,) if isinstance(sp.material, str) else sp.material
    materials = tuple(springs.SpringMaterial(
        grade=grade(name).name, shear_modulus=sp.shear_modulus, density=sp.density_kg_m3,
        allowable_stress=sp.allowable_stress, endurance_limit=sp.endurance_limit,
        mean_stress_factor=sp.mean_stress_factor, min_safety=sp.min_safety_factor,
        min_resonance_ratio=sp.min_resonance_ratio, design_margin=sp.min_margin, gap_factor=sp.coil_gap_factor)
        for name in names)
    return springs.SpringOptions(
        materials=materials, count=sp.count, inner_share=sp.inner_share, diameter_range=sp.mean_diameter_ratio,
        wire_range_mm=tuple(to_display(x, "mm") for x in sp.wire_diameter_range),
        wire_step_mm=to_display(sp.wire_step, "mm"), ratio_range=sp.deflection_ratio_range,
        installed_length_range=sp.installed_length, max_free_length=sp.max_free_length, radial_gap=sp.radial_gap,
        min_frequency_difference=sp.min_frequency_difference)


def _spring_checks(tag, s, note=""):
    """A designed spring's own checks, named after the spring (``spring``, ``outer``, ``inner``); a failed one
    carries ``note`` (the diagnosis)."""
    return [replace(c.of_spring(tag), note=c.note if c.passed else note) for key, c in s.checks.items()
            if key in ("tau_max", "fatigue_safety", "resonance_ratio", "working_coils", "installed_length",
                       "free_length", "coil_gap_at_full_lift")]


def drive_stage(valve, gas, cam, diagnose=True) -> DriveResult:
    """Stage 6: reduced masses, spring characteristic and design (the strength is :func:`strength_stage`).

    Parameters
    ----------
    valve, gas : SI views of the valve and ``[gas]`` (:func:`valvetrain.specification.si`).
    cam : CamResult
        The law stage: the law, the camshaft speed [rad/s], the heel and roller radii [m], the rocker ratio.
    diagnose : bool
        Where no spring passes, say why and what would make one pass (:func:`valvetrain.springs.diagnose`, a new
        search per remedy: about a second); False leaves the diagnosis out (the designer's first answer to an edit).

    Returns
    -------
    DriveResult

    Raises
    ------
    valvetrain.springs.NoSpringFits
        No spring of the wire range can be wound within the given diameters.

    Notes
    -----
    The spring must hold the train on the cam, :math:`P_{spr} \\ge K_z m_v |j_v|` where :math:`j_v < 0`
    (5.1)-(5.3); the reduced mass includes a third of the designed spring's mass where the part masses leave it
    to the design, so the search is repeated until that mass settles.

    References
    ----------
    Valve-train practical works (n.d.), works 5-6, eqs. (5.1)-(5.14), (6.1)-(6.14).
    """
    law, omega, i_k = cam.law, cam.cam_speed, cam.rocker_ratio
    d_g = valve.throat_diameter
    found = []

    theta = np.unique(np.concatenate([np.linspace(law.valve_opens, law.valve_closes, 2001), law.breakpoints]))
    theta = theta[(theta >= law.valve_opens) & (theta <= law.valve_closes)]
    y = cam.valve_lift(theta)
    a_v = i_k * omega**2 * law.derivatives(theta)[2]
    finger = omega**2 * finger_inertia(valve, law, theta)
    lift = law.lift_max * i_k

    if valve.kind == "exhaust":
        p_gas = springs.gas_opening_force(d_g, gas.exhaust_back_pressure, gas.cylinder_intake_pressure)
        gas_source = "Valve-train practical works (n.d.), eq. (5.4)"
    else:
        p_gas = springs.gas_opening_force(d_g, gas.intake_port_pressure, gas.cylinder_exhaust_pressure)
        gas_source = "Valve-train practical works (n.d.), eq. (5.5)"

    sp, drive = valve.spring, valve.drive
    options = spring_options(sp)
    spring_total_mass = 0.0
    for _ in range(20):
        m_v, mass_source = train_mass(valve, spring_total_mass)
        j_v = a_v + finger / m_v    # a finger's inertia by its variable ratio, as an acceleration of m_v
        required = springs.required_spring_force(m_v, j_v, drive.spring_reserve)
        seat = springs.seat_load(m_v) if sp.min_preload_N is None else sp.min_preload_N
        requirement = springs.Requirement(y, required, max(p_gas, seat))
        search = springs.design_springs(requirement, d_g, omega, options)
        line, designs, n_pass = search.line, search.designs, search.passing
        raised = line.preload <= requirement.min_preload * (1.0 + 1e-9) and requirement.min_preload > 0.0
        new_mass = sum(d.mass for d in designs.values())
        if drive.masses is None or drive.masses.spring_kg is not None or abs(new_mass - spring_total_mass) < 1e-7:
            break
        spring_total_mass = new_mass
    diagnosis = None if search.passes or not diagnose else springs.diagnose(requirement, d_g, omega, options, search,
                                                            2.0 * omega)

    chosen_line = springs.Characteristic(sum(d.characteristic.preload for d in designs.values()),
                                         sum(d.characteristic.rate for d in designs.values()), lift)
    lines = SpringLines(line, chosen_line, *((designs["outer"].characteristic, designs["inner"].characteristic)
                                             if sp.count == 2 else ()))
    ratio = chosen_line.max_deflection / chosen_line.preload_deflection
    found.append(check("spring.reserve", drive.spring_reserve, *springs.SPRING_RESERVE_RANGE,
                       source="Valve-train practical works (n.d.), eq. (5.3)"))
    found.append(check("spring.chosen_deflection_ratio", ratio, *springs.DEFLECTION_RATIO_RANGE, source="Valve-train practical works (n.d.), work 5 "
                       "(the chosen springs' rounded coils can move it off the required line's ratio)"))
    if sp.count == 2:
        found.append(check("spring.inner_share", sp.inner_share, *springs.INNER_SHARE_RANGE, source="Valve-train practical works (n.d.), work 5"))
    for tag, d in designs.items():
        found += _spring_checks(tag, d, diagnosis_text(diagnosis, "en") if diagnosis else "")
        found.append(check("spring.design_margin", d.design_margin, low=sp.min_margin, unit="%",
                           source="min_margin_percent of the specification: the smaller margin of the fatigue safety "
                                  "and the resonance ratio above their minima (eqs. 6.12, 6.14)").of_spring(tag))
    if sp.count == 2:
        difference = designs["inner"].checks["frequency_difference"]
        found.append(replace(difference, quantity=record_text("spring.pair_frequency_difference"),
                             code="spring.pair_frequency_difference"))

    if sp.count == 1:
        design, pair = spring_record(designs["spring"]), {}
    else:
        outer = spring_record(designs["outer"])
        design = replace(outer, preload=chosen_line.preload, max_force=chosen_line.max_force, rate=chosen_line.rate,
                         passes_all_checks=search.passes)
        pair = {"outer": outer, "inner": spring_record(designs["inner"]), "inner_share": sp.inner_share}
    spring_result = SpringResult(
        sp.count, sp.material, chosen_line.preload, chosen_line.max_force, chosen_line.rate, line.preload, line.rate,
        line.max_force, line.max_deflection / line.preload_deflection, bool(raised and p_gas >= seat), p_gas,
        gas_source, bool(raised and seat > p_gas), seat,
        "min_preload_N of the specification" if sp.min_preload_N is not None else
        f"m_v x {springs.SEAT_ACCELERATION:.5g} m/s2 (100 g, a stated default)",
        ratio, drive.spring_reserve, sp.min_margin, n_pass, search.tried, None if diagnosis is None else diagnosis_record(diagnosis),
        design, **pair)

    train = None
    if drive.stiffness is not None:
        train, train_checks = _train_dynamics(valve, law, omega, m_v, chosen_line.rate)
        found += train_checks
    mass_result = MassResult(m_v, masses.reduced_mass_at_tappet(m_v, i_k), mass_source, layout(valve), train)

    inertia = m_v * np.clip(-j_v, 0.0, None)
    return DriveResult(mass_result, spring_result, None, tuple(found), y, inertia, required, lines, diagnosis)


def strength_speed_range(engine, swept=None) -> tuple[float, float, str]:
    """The engine speeds the strength is checked over [rad/s]: the lowest, the highest and where the lowest comes from.

    The highest is the over-speed, ``[engine] over_speed_ratio`` x the rated speed.  The lowest is ``[engine]
    idle_speed_rpm``; without it the low end of ``swept``, the valve's ``[dynamics]`` speed range (low, high)
    [rad/s], else :data:`IDLE_SPEED_RATIO` x the rated speed (the dynamics stage's default idle).  Never above the
    rated speed.
    """
    if engine.idle_speed is not None:
        low, source = engine.idle_speed, LOWEST_SPEED_SOURCES[0]
    elif swept is not None:
        low, source = swept[0], LOWEST_SPEED_SOURCES[1]
    else:
        low, source = IDLE_SPEED_RATIO * engine.rated_speed, LOWEST_SPEED_SOURCES[2]
    return min(low, engine.rated_speed), engine.over_speed_ratio * engine.rated_speed, source


def quasi_static_loads(law, rocker_ratio, theta, spring_force, mass, speeds, to_cam, finger=0.0) -> LoadMap:
    """The quasi-static cam force over engine speeds x camshaft angles, :class:`LoadMap`.

    Parameters
    ----------
    law : LiftLaw
    rocker_ratio : float
        i_k.
    theta : ndarray (n,)
        Camshaft angles of the open event [rad from the nose].
    spring_force : ndarray (n,)
        Spring force at the valve at those angles [N].
    mass : float
        Reduced mass at the valve m_v [kg].
    finger : ndarray (n,) or float
        What a finger's inertia by its variable ratio adds at those angles per camshaft speed squared
        [N s^2/rad^2] (:func:`~valvetrain.layouts.finger_inertia`).
    speeds : ndarray (S,)
        Engine speeds [rad/s].
    to_cam : float
        Camshaft per crank revolution (1/2 for a four-stroke).

    Notes
    -----
    :math:`P_T(n, \\theta) = i_k\\,(P_{spr}(\\theta) + m_v\\,i_k\\,\\omega_{cam}(n)^2\\,h''(\\theta))`, (7.1) at every
    speed (and a finger's ``finger`` omega_cam^2 at the valve, its inertia by its variable ratio): the inertia of the
    rigid train grows with the square of the speed, so the spring carries the nose alone at low speed.

    References
    ----------
    Valve-train practical works (n.d.), work 7, eqs. (7.1)-(7.2).
    """
    omega = np.asarray(speeds, dtype=float)[:, None] * to_cam
    inertia = mass * rocker_ratio * omega**2 * law.derivatives(theta)[2]
    inertia += omega**2 * finger     # in place: a load map's array is large (strength.hertz_line_stress)
    force = strength.cam_force(spring_force, inertia, rocker_ratio)
    return LoadMap("quasi-static", np.asarray(speeds, dtype=float), theta, force)


def dynamic_loads(dynamics, low, high) -> Optional[LoadMap]:
    """The dynamics stage's simulated cam force at its speeds within [low, high] (and the rated speed), a
    :class:`LoadMap`, or None where none of its speeds lies in the range."""
    speeds = np.append(np.asarray(dynamics.per_speed.speed, dtype=float), dynamics.at_rated_speed.speed)
    force = np.vstack([dynamics.sweep.contact_force, dynamics.rated.contact_force[None, :]])
    keep = (speeds >= low * (1.0 - 1e-12)) & (speeds <= high * (1.0 + 1e-12))
    if not keep.any():
        return None
    rows = np.flatnonzero(keep)[np.argsort(speeds[keep], kind="stable")]    # one copy of the large force map
    return LoadMap("dynamic", speeds[rows], dynamics.sweep.theta, force[rows])


def load_maps(valve, engine, cam, theta, spring_force, mass, dynamics=None) -> tuple[list[LoadMap], tuple[float, float, str]]:
    """The cam force over the strength speed range, a list of :class:`LoadMap`, and the range (low, high, source).

    With the dynamics stage, its simulated force at its speeds in the range and the quasi-static force at the
    speeds of the range it does not sweep; without it, the quasi-static force at :data:`STRENGTH_SPEEDS` speeds
    and the rated speed.
    """
    low, high, source = strength_speed_range(engine, None if dynamics is None else dynamics.speed_range)
    speeds = np.unique(np.append(np.linspace(low, high, STRENGTH_SPEEDS), engine.rated_speed))
    maps = []
    if dynamics is not None:
        swept = dynamics.speed_range
        maps.append(dynamic_loads(dynamics, low, high))
        speeds = speeds[(speeds < swept[0]) | (speeds > swept[1])]
    if speeds.size:
        to_cam = cam.cam_speed / engine.rated_speed
        maps.append(quasi_static_loads(cam.law, cam.rocker_ratio, theta, spring_force, mass, speeds, to_cam,
                                       finger_inertia(valve, cam.law, theta)))
    return [m for m in maps if m is not None], (low, high, source)


def event_load_maps(valve, engine, cam, drive, dynamics=None) -> tuple[np.ndarray, list[LoadMap],
                                                                  tuple[float, float, str]]:
    """The cam force over the strength speed range on the open event: its camshaft angles [rad from the nose] (2001
    and the law's breakpoints), the list of :class:`LoadMap` and the range (low, high, source) of :func:`load_maps`
    with the drive stage's chosen spring and reduced mass."""
    law = cam.law
    theta = np.unique(np.concatenate([np.linspace(law.valve_opens, law.valve_closes, 2001), law.breakpoints]))
    theta = theta[(theta >= law.valve_opens) & (theta <= law.valve_closes)]
    maps, span = load_maps(valve, engine, cam, theta, drive.lines.chosen.force(cam.valve_lift(theta)),
                           drive.masses.at_valve, dynamics)
    return theta, maps, span


def contact_loads(cam, maps) -> list[LoadMap]:
    """The load maps as the force between cam and follower: each map's force (along the law's lift) times the
    follower's :meth:`~valvetrain.followers.Follower.force_ratio` at its angles (1 for a translating follower; a
    finger's cam carries G / (L_r cos beta) of the force at the valve, Norton (2009))."""
    follower = cam.follower_model
    out = []
    for m in maps:
        h, dh = cam.law.derivatives(m.theta)[:2]
        out.append(replace(m, force=m.force * follower.force_ratio(cam.heel_radius, h, dh)))
    return out


def _worst(maps, values):
    """The largest of ``values`` (one array (S, n) per load map) over every map: a :class:`Worst`; of values equal
    to round-off (a symmetric cam's two flanks) the first map's, at the lowest speed, at the smallest angle
    (:func:`~valvetrain.numerics.first_largest`)."""
    best = None
    for m, q in zip(maps, values, strict=True):
        i, j = np.unravel_index(first_largest(q), q.shape)
        if best is None or q[i, j] > best.value + TIE_RTOL * abs(best.value):
            best = Worst(float(q[i, j]), float(m.speeds[i]), float(m.theta[j]), m.kind, float(m.force[i, j]))
    return best


def strength_stage(valve, gas, engine, cam, drive, dynamics=None) -> tuple[StrengthResult, list[Check]]:
    """Work 7 over the speed range: every strength check the layout and the given dimensions allow, at its worst.

    Parameters
    ----------
    valve, gas, engine : SI views of the valve, ``[gas]`` and ``[engine]``.
    cam : CamResult
        The law stage.
    drive : DriveResult
        The drive stage (reduced mass, chosen spring line).
    dynamics : DynamicsResult, optional
        The dynamics stage: its simulated contact force replaces the quasi-static one at its speeds.

    Returns
    -------
    (StrengthResult, list of Check)
        The strength checks (quantity with spaces) and the follower checks.

    Notes
    -----
    The cam force :math:`P_T(n, \\theta)` is evaluated on a grid of engine speeds x camshaft angles from the lowest
    speed to the over-speed (:func:`strength_speed_range`); each check takes its worst point.  The checks loaded by
    :math:`P_{T\\,max}` (camshaft deflection, tappet side pressure, pushrod buckling and ball, rocker pad and shaft)
    follow the largest force, on the opening flank at the highest speed for a rigid train; the Hertz stress follows
    force and curvature together, at the nose at the lowest speed, where the inertia no longer unloads the nose.

    References
    ----------
    Valve-train practical works (n.d.), work 7, eqs. (7.1)-(7.18); Shang Hanji (1988), eq. (2.5) and section 3.4
    (the contact stress under the dynamic force).
    """
    law = cam.law
    theta, maps, (low, high, source) = event_load_maps(valve, engine, cam, drive, dynamics)
    found = []
    p_open = 0.0
    if valve.kind == "exhaust":
        p_open, gas_check = _exhaust_gas_force(valve, gas)
        found.append(gas_check)
        for m in maps:
            # the nearest angle; of two as near to the round-off of the angles, the first
            m.force[:, first_largest(-np.abs(m.theta - law.valve_opens), atol=TIE_RTOL * np.pi)] += \
                cam.rocker_ratio * p_open
    result, checks = _strength(valve, cam, theta, contact_loads(cam, maps), p_open, _worst(maps, [m.force for m in maps]))
    if cam.follower_model.law_at_valve:
        finger, bending = finger_bending(valve.parts, *finger_loads(cam, maps))
        result = replace(result, finger=finger, checks=result.checks + bending[0], not_checked=result.not_checked
                         + bending[1])
    result = replace(result, speed_range=(float(low), float(high)), lowest_speed_source=source,
                     rated_speed=engine.rated_speed)
    return result, list(result.checks) + found + checks


def _where(w):
    """Where a worst value occurs, for a check's note."""
    return (f"at {to_display(w.speed, 'rpm'):.0f} rpm, {to_display(w.angle, 'cam deg'):.4g} cam deg from the nose "
            f"({w.kind} force)")


def finger_loads(cam, maps) -> tuple[FingerLoads, Worst]:
    """The :class:`FingerLoads` of a finger under the force at the valve of the load maps (before
    :func:`contact_loads`), at their worst, and where its bending moment is largest (:class:`Worst`)."""
    follower, heel = cam.follower_model, cam.heel_radius
    found = []
    for m in maps:
        h, dh = cam.law.derivatives(m.theta)[:2]
        found.append(follower.loads(m.force, heel, h, dh))
    return (FingerLoads(*(max(float(np.max(f[k])) for f in found) for k in range(3))),
            _worst(maps, [f[2] for f in found]))


def finger_bending(parts, loads, moment) -> tuple[FingerLoads, tuple[tuple[Check, ...], tuple[str, ...]]]:
    """The finger's bending stress at its critical section under its largest bending moment ``moment``
    (:class:`Worst`, :meth:`~valvetrain.followers.PivotedFollower.loads`) on the rectangular section of
    ``parts.finger_section_width_mm`` x ``finger_section_height_mm``
    (:func:`valvetrain.strength.rectangle_bending_stress`): ``loads`` with the stress, and (its check,) or the note that the section is not given."""
    keys = ("finger_section_width_mm", "finger_section_height_mm")
    missing = [key for key in keys if getattr(parts, si_name(key)[0]) is None]
    if missing:
        return loads, ((), (f"finger_bending: not checked, parts.{', parts.'.join(missing)} not given",))
    stress = strength.rectangle_bending_stress(moment.value, parts.finger_section_width, parts.finger_section_height)
    width, height = (to_display(x, "mm") for x in (parts.finger_section_width, parts.finger_section_height))
    note = f"{_where(moment)}; M = {moment.value:.4g} N m, b x h = {width:g} x {height:g} mm"
    return (replace(loads, bending_stress_max=float(stress)),
            ((strength.verdict("finger_bending", float(stress), note),), ()))


def _strength(valve, cam, theta, maps, p_open, valve_load):
    """Work 7 on the load maps (the force at the cam): every check the layout and the given dimensions allow, at its
    worst point; ``valve_load`` is the largest force along the law's lift (:class:`Worst`), which i_k takes to the
    valve."""
    i_k = cam.rocker_ratio
    parts, drive, follower = valve.parts, chain(valve), cam.follower_model
    notes, verdicts = [], []
    load = _worst(maps, [m.force for m in maps])
    p_max, at_load = load.value, _where(load)

    def need(keys, name):
        """Whether the parts' keys (spec names) are given; a note names those missing."""
        missing = [key for key in keys if getattr(parts, si_name(key)[0]) is None]
        if missing:
            notes.append(f"{name}: not checked, parts.{', parts.'.join(missing)} not given")
        return not missing

    def joined(*texts):
        return "; ".join(t for t in texts if t)

    e_contact = parts.contact_modulus
    width = stress = stresses = None
    if need(["camshaft_diameter_mm", "camshaft_span_mm", "cam_to_bearing_mm"], "camshaft_deflection"):
        l1 = parts.cam_to_bearing
        f = strength.camshaft_deflection(p_max, l1, parts.camshaft_span - l1, parts.camshaft_diameter,
                                         parts.camshaft_bore, parts.camshaft_modulus,
                                         parts.camshaft_deflection_coefficient)
        verdicts.append(strength.verdict("camshaft_deflection", f, joined(
            at_load, f"coefficient {parts.camshaft_deflection_coefficient:.4g} (corrections note 20: not 0.8)")))
    if need(["cam_width_mm"], "cam_contact_stress"):
        # Shang Hanji (1988), eqs. (2.6)-(2.7): the profile's radius of curvature along the open event
        if not np.all(follower.line_contact(cam.law.curvature(theta, cam.heel_radius, follower))):
            notes.append("cam_contact_stress: not checked, the profile is undercut (no line contact)")
        else:
            width = parts.cam_width
            stresses = [follower.contact_stress(m.force, cam.law.curvature(m.theta, cam.heel_radius, follower), width,
                                                e_contact) for m in maps]
            stress = _worst(maps, stresses)
            verdicts.append(strength.verdict("cam_contact_stress", stress.value, joined(
                _where(stress), "along the profile with the instantaneous force and radius (Shang Hanji (1988), "
                "eq. 2.5)")))
    if drive.tappet and not follower.rolling and \
            need(["tappet_diameter_mm", "tappet_guide_length_mm"], "tappet_side_pressure"):
        b = float(np.max(np.abs(cam.law.derivatives(theta)[1])))
        q = strength.tappet_side_pressure(p_max, b, parts.tappet_diameter, parts.tappet_guide_length)
        verdicts.append(strength.verdict("tappet_side_pressure", q, joined(
            at_load, f"offset b = {to_display(b, 'mm'):.4g} mm = max dh/dphi (7.7)")))
    if drive.pushrod:
        if need(["pushrod_length_mm", "pushrod_diameter_mm"], "pushrod_buckling_margin"):
            inertia = strength.second_moment(parts.pushrod_diameter, parts.pushrod_bore)
            p_cr = strength.euler_load(parts.pushrod_modulus, inertia, parts.pushrod_length)
            verdicts.append(strength.verdict("pushrod_buckling_margin", p_cr / p_max, joined(
                at_load, f"Euler load {p_cr:.5g} N; E = {to_display(parts.pushrod_modulus, 'MPa'):g} MPa "
                "(corrections note 21)")))
        if need(["ball_radius_mm", "socket_radius_mm"], "ball_socket_stress"):
            verdicts.append(strength.verdict("ball_socket_stress", strength.sphere_socket_stress(
                p_max, e_contact, parts.ball_radius, parts.socket_radius), at_load))
        if need(["pushrod_head_area_mm2"], "pushrod_head_pressure"):
            verdicts.append(strength.verdict("pushrod_head_pressure", p_max / parts.pushrod_head_area, at_load))
    if drive.rocker:
        if need(["rocker_pad_width_mm", "rocker_pad_radius_mm"], "rocker_pad_stress"):
            verdicts.append(strength.verdict("rocker_pad_stress", strength.rocker_pad_stress(
                valve_load.value / i_k, e_contact, parts.rocker_pad_width, parts.rocker_pad_radius), at_load))
        if need(["rocker_shaft_span_mm", "rocker_shaft_diameter_mm", "rocker_width_mm"], "rocker_shaft"):
            st = strength.rocker_shaft_stresses(p_max, parts.rocker_shaft_span, parts.rocker_width,
                                                parts.rocker_shaft_diameter, parts.rocker_shaft_bore)
            verdicts.append(strength.verdict("rocker_shaft_bending", st["bending"], joined(
                at_load, f"built-in beam (7.15, corrections note 48); simply supported: "
                f"{to_display(st['bending_simply_supported'], 'MPa'):.4g} MPa; load P_T max (corrections note 25)")))
            verdicts.append(strength.verdict("rocker_shaft_shear", st["shear"], at_load))
            verdicts.append(strength.verdict("rocker_shaft_bearing", st["bearing"], at_load))
    side, found = None, []
    if follower.rolling and not follower.law_at_valve:   # a finger has no guide: its pivot carries the side load
        side, side_check = _roller_side_force(cam, follower, maps, drive)
        found.append(side_check)
    else:
        found += _edge_loading(parts, drive, cam, follower, maps, width, notes)
    return StrengthResult(
        (0.0, 0.0), "", load.value, load.angle, load.speed, valve_load.value / i_k, p_open,
        None if stress is None else stress.angle, None if stress is None else stress.speed,
        None if side is None else side.value, None if side is None else side.angle,
        None if side is None else side.speed, _per_speed(maps, stresses),
        tuple(verdicts), tuple(notes), contact_force=None if stress is None else stress.force), found


def _per_speed(maps, stresses=None):
    """The largest cam force and contact stress (``stresses``: one array (S, n) per load map, None: not checked) at
    every speed of the load maps, a :class:`StrengthPerSpeed` in increasing speed; of values equal to round-off the
    one at the smallest angle (:func:`~valvetrain.numerics.first_largest`)."""
    def largest(m, values):
        j = first_largest(values, axis=1)
        return values[np.arange(j.size), j], m.theta[j]

    def column(rows):
        return tuple(float(x) for x in np.concatenate(rows)[order])

    speeds = np.concatenate([m.speeds for m in maps])
    order = np.argsort(speeds, kind="stable")
    kinds = tuple(np.concatenate([[m.kind] * m.speeds.size for m in maps])[order])
    force, force_at = zip(*(largest(m, m.force) for m in maps), strict=True)
    stress = (None, None)
    if stresses is not None:
        stress = [column(c) for c in zip(*(largest(m, q) for m, q in zip(maps, stresses, strict=True)), strict=True)]
    return StrengthPerSpeed(column([speeds]), kinds, column(force), column(force_at), *stress)


def _exhaust_gas_force(valve, gas):
    """Gas force on the closed exhaust valve head as it opens [N] (7.1) and its record.

    Without ``parts.head_diameter_mm`` the throat diameter stands in for the head's: the head is larger than
    the throat, so the force is a lower bound, and the record says so.
    """
    head = valve.parts.head_diameter
    diameter = valve.throat_diameter if head is None else head
    force = float(flow.circle_area(diameter)) * max(gas.exhaust_opening_pressure - gas.exhaust_back_pressure, 0.0)
    note = (f"on the head diameter d_n = {to_display(head, 'mm'):g} mm" if head is not None else
            "parts.head_diameter_mm not given: computed on the throat diameter "
            f"{to_display(diameter, 'mm'):g} mm, a lower bound (the head is larger than the throat)")
    return force, check("gas_force.exhaust_opening", force, unit="N", severity="info",
                        source=WORKS_7_1, note=note)


def _edge_loading(parts, drive, cam, follower, maps, width, notes):
    """The flat follower's contact against the edge of its face: max(|dh/dphi| + Hertz half-width) <= face radius.

    The contact point of a flat follower lies dh/dphi from its axis (Shang's contour, eq. 2.15); the contact
    band reaches a half-width further where the cam width is given (``width`` [m], None: not given or undercut),
    under the force of each speed.  The face is ``tappet_face_diameter_mm``, else, for a tappet in a guide,
    ``tappet_diameter_mm`` (a bucket tappet's face is its diameter).
    """
    if parts.tappet_face_diameter is not None:
        face, key = parts.tappet_face_diameter, "tappet_face_diameter_mm"
    elif drive.tappet and parts.tappet_diameter is not None:
        face, key = parts.tappet_diameter, "tappet_diameter_mm (no tappet_face_diameter_mm: a bucket tappet)"
    else:
        notes.append("flat_follower_edge_loading: not checked, parts.tappet_face_diameter_mm not given")
        return []

    def reach(m):
        offset = np.abs(cam.law.derivatives(m.theta)[1])
        if width is None:
            return np.broadcast_to(offset, m.force.shape)
        curvature = follower.contact_curvature(cam.law.curvature(m.theta, cam.heel_radius, follower))
        reach = strength.hertz_half_width(m.force, width, curvature, parts.contact_modulus)
        reach += offset     # in place: a load map's array is large (strength.hertz_line_stress)
        return reach

    w = _worst(maps, [reach(m) for m in maps])
    offset = abs(float(cam.law.derivatives(np.array([w.angle]))[1, 0]))
    band = ("with the Hertz half-width " f"{to_display(w.value - offset, 'mm'):.3g} mm" if width is not None
            else "without the Hertz half-width (parts.cam_width_mm not given)")
    return [check("follower.edge_loading", w.value, high=face / 2.0, unit="mm",
                  severity="failure", source=f"{SHANG_2_1}, eq. (2.15); {NORTON} (flat-faced follower face width)",
                  note=f"contact offset |dh/dphi| {to_display(offset, 'mm'):.4g} mm {_where(w)} {band}; face radius "
                       f"from parts.{key}")]


def _roller_side_force(cam, follower, maps, drive):
    """The largest side force of a roller follower over the speeds, P_T tan(alpha): a :class:`Worst` and its (info)
    record."""
    def side(m):
        h, dh = cam.law.derivatives(m.theta)[:2]
        return strength.roller_side_force(m.force, follower.pressure_angle(cam.heel_radius, h, dh))

    w = _worst(maps, [side(m) for m in maps])
    h, dh = cam.law.derivatives(np.array([w.angle]))[:2]
    beta = abs(float(follower.pressure_angle(cam.heel_radius, h, dh)[0]))
    carrier = "the tappet guide" if drive.tappet else "the rocker and its shaft"
    return w, check(
        "follower.roller_side_force", w.value, unit="N", severity="info",
        source=f"{NORTON} (pressure angle: side load F_n sin(alpha)); no source gives an allowable",
        note=f"{_where(w)}, pressure angle {to_display(beta, 'deg'):.3g} deg; carried by {carrier}")


def strength_limit(c) -> tuple[str, float]:
    """The side and the bound of a strength check in its display unit: ``("<=", high)`` or ``(">=", low)``."""
    return ("<=", to_display(c.high, c.unit)) if c.high is not None else (">=", to_display(c.low, c.unit))


def strength_allowed(c) -> str:
    """The allowed range of a strength check as results.json and the report write it (``"<= 1200"``)."""
    side, limit = strength_limit(c)
    return f"{side} {limit:g}"


def _strength_record(c):
    """results.json record of a strength check: value and limit in its unit, pass, source (and a note)."""
    out = {"value": c.shown_value, "allowed": strength_allowed(c), "limit": strength_limit(c)[1], "unit": c.unit,
           "pass": c.passed, "source": c.source}
    if c.note:
        out["note"] = c.note
    return out


def _train_dynamics(valve, law, omega, mass, spring_rate):
    """Natural frequency of the one-mass train and the perturbation parameter (Shang Hanji (1988), sections 1 and 3.3).

    omega_n = sqrt((c + K) / M) with the drive stiffness c and the spring rate K at the valve;
    epsilon = M omega^2 / (c + K) (the printed M omega^3 / c is dimensionally wrong, corrections note 30); and the law's own
    checks against the train (:meth:`valvetrain.laws.LiftLaw.train_checks`).
    """
    c = valve.drive.stiffness
    omega_n = float(np.sqrt((c + spring_rate) / mass))
    return (TrainDynamics(c, omega_n / (2 * np.pi), mass * omega**2 / (c + spring_rate)),
            law.train_checks(omega_n, omega))
