"""Drive stage of a valve design: reduced masses, spring characteristic and design, strength of the
drive parts (Valve-train practical works (n.d.), works 5-7).

:func:`drive_stage` takes SI inputs (the valve's and ``[gas]``'s SI views,
:func:`valvetrain.specification.si`, and the law stage's :class:`~valvetrain.design.valve.CamResult`) to a
typed, frozen :class:`DriveResult` (masses and springs); :func:`~valvetrain.design.drive_strength.strength_stage`
checks the drive parts over the engine speeds from the lowest to the over-speed, on the dynamics stage's contact
force where it ran; :func:`drive_record` is where they leave SI, as the ``masses``, ``spring`` and ``strength`` records of
results.json.
"""

from dataclasses import dataclass, field, replace
from typing import Any, Optional, Union

import numpy as np

from .. import masses, springs
from ..checks import Check, check
from ..layouts import finger_inertia, layout, train_mass
from ..locale import NoteText, cited, note, note_text, record_text
from ..locale.wording import diagnosis_note, diagnosis_text
from ..spring_materials import grade
from ..units import to_display
from .drive_strength import StrengthResult, strength_record
from .results import quantity, record


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
            "strength": {**record(st), "checks": {c.code.removeprefix("strength."): strength_record(c) for c in st.checks},
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


def _spring_checks(tag, s, note=()):
    """A designed spring's own checks, named after the spring (``spring``, ``outer``, ``inner``); a failed one
    carries ``note`` (the diagnosis, :func:`valvetrain.locale.wording.diagnosis_note`)."""
    return [c.of_spring(tag) if c.passed else replace(c.of_spring(tag), note=note_text(note), note_parts=note)
            for key, c in s.checks.items()
            if key in ("tau_max", "fatigue_safety", "resonance_ratio", "working_coils", "installed_length",
                       "free_length", "coil_gap_at_full_lift")]


def drive_stage(valve, gas, cam, diagnose=True, gas_load=None) -> DriveResult:
    """Stage 6: reduced masses, spring characteristic and design (the strength is :func:`strength_stage`).

    Parameters
    ----------
    valve, gas : SI views of the valve and ``[gas]`` (:func:`valvetrain.specification.si`).
    cam : CamResult
        The law stage: the law, the camshaft speed [rad/s], the heel and roller radii [m], the rocker ratio.
    diagnose : bool
        Where no spring passes, say why and what would make one pass (:func:`valvetrain.springs.diagnose`, a new
        search per remedy: about a second); False leaves the diagnosis out (the designer's first answer to an edit).
    gas_load : (float, Note), optional
        The gas force that tends to open the closed valve [N] and its source (:func:`valvetrain.locale.note`), where
        the breathing gives it
        (:func:`valvetrain.design.breathing.gas_opening_load`); default the sources' from ``[gas]``.

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

    if gas_load is not None:
        p_gas, gas_source = gas_load[0], NoteText(gas_load[1])
    elif valve.kind == "exhaust":
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
    found.append(check("spring.chosen_deflection_ratio", ratio, *springs.DEFLECTION_RATIO_RANGE, source=cited(note("source.chosen_ratio", work="Valve-train practical works (n.d.), work 5"))))
    if sp.count == 2:
        found.append(check("spring.inner_share", sp.inner_share, *springs.INNER_SHARE_RANGE, source="Valve-train practical works (n.d.), work 5"))
    for tag, d in designs.items():
        found += _spring_checks(tag, d, diagnosis_note(diagnosis) if diagnosis else ())
        found.append(check("spring.design_margin", d.design_margin, low=sp.min_margin, unit="%",
                           source=cited(note("source.design_margin"))).of_spring(tag))
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
        NoteText(note("spring.seat_load_given") if sp.min_preload_N is not None else
                 note("spring.seat_load_default", acceleration_m_s2=springs.SEAT_ACCELERATION)),
        ratio, drive.spring_reserve, sp.min_margin, n_pass, search.tried, None if diagnosis is None else diagnosis_record(diagnosis),
        design, **pair)

    train = None
    if drive.stiffness is not None:
        train, train_checks = _train_dynamics(valve, law, omega, m_v, chosen_line.rate)
        found += train_checks
    mass_result = MassResult(m_v, masses.reduced_mass_at_tappet(m_v, i_k), mass_source, layout(valve), train)

    inertia = m_v * np.clip(-j_v, 0.0, None)
    return DriveResult(mass_result, spring_result, None, tuple(found), y, inertia, required, lines, diagnosis)


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
