"""The sections of a specification for the engine's further stages: the whole camshaft (``[camshaft]``), the gas load
(``[gas]``), the crank mechanism and its cycle (``[crank]``, ``[crank.cycle]``), the two-stroke ports
(``[two_stroke]``) and the breathing (``[breathing]``); and :func:`resolve_path`, a file the specification names.

Units are in the key names; :mod:`.si` converts them.  The engine, the valves and the specification itself are in
:mod:`.models`.
"""

from pathlib import Path
from typing import Annotated, ClassVar, Literal, Optional

from pydantic import Field, model_validator

from ..errors import InputError
from ..locale import NoteText, note
from ..files import read_cd_table, read_indicator, read_valve_lift
from .fields import Length, Pair, _bounded, Whole, _Model


CAMSHAFT_MIN_WALL = 0.05
"""The thinnest wall of a hollow camshaft section, a share of its diameter (D/t <= 20): an engineering limit of this
package, not a published one.  Hollow camshafts are drawn or machined tubes of D/t about 5-10; the section's torsion
and bending are those of a thick tube (J = pi (D^4 - d^4) / 32), which a wall thinner than this cannot promise (it
buckles locally, as a sheet does, long before the shaft twists by its formula)."""


class Camshaft(_Model):
    """[camshaft]: the whole camshaft, its shaft and its timing drive (positions from the drive end, where the
    sprocket, pulley or gear sits); the lobes of the named valves of the named cylinders, in the engine's firing
    order.  ``drive_stiffness_N_per_mm`` (the drive's tangential stiffness at the pitch radius; absent: the drive
    end held) and ``sprocket_inertia_kg_mm2`` put the timing drive into the torsion.  The limits
    ``max_twist_cam_deg`` and ``min_frequency_ratio`` are engineering assumptions (no published camshaft limit was
    found); ``drive_allowable_force_N`` is the maker's allowable of the chain, belt or gears.

    The torsional response over the running range: every mode damped by ``torsional_damping_ratio`` (default 0.05,
    [0.001, 0.5]: an engineering assumption, the valve train's own default damping ratio of ``[dynamics]``; no
    published damping of a camshaft's torsional modes was found; at 0.001 a resonance's steady response, the static
    one over 2 zeta, is 500 times the static, the pushrod example's timing fluctuating by 15 cam deg at its chain
    resonance, and below it the linear model's answer means nothing: near zero it overflows), and the fluctuation of each lobe's timing graded against
    ``max_timing_play_mm`` (default 3.175 mm, the movement of the cam sprocket against the crankshaft along its pitch
    circle that a maker accepts in service before replacing the chain, DaimlerChrysler (2002)) over the pitch
    radius."""

    valves: Optional[list[str]] = None
    cylinders: Optional[list[Whole(1, 64)]] = None
    cylinder_positions_mm: list[Length(0.0, 10000.0)]
    section_lengths_mm: list[Length(0.5, 10000.0, low_open=False)]
    section_diameters_mm: list[Length(2.0, 500.0, low_open=False)]
    section_bores_mm: Optional[list[Length(0.0, 500.0, low_open=False)]] = None
    journal_positions_mm: list[Length(0.0, 10000.0, low_open=False)]
    shear_modulus_MPa: _bounded(1e3, 1e6, "MPa") = 8.1e4
    modulus_MPa: _bounded(1e3, 1e6, "MPa") = 2.1e5
    density_kg_m3: _bounded(500.0, 25000.0, "kg/m3") = 7850.0
    lobe_inertia_kg_mm2: _bounded(0.0, 1e6, "kg mm2", low_open=False) = 20.0
    max_twist_cam_deg: _bounded(0.01, 10.0, "deg") = 0.5
    max_deflection_mm: Length(0.001, 1.0) = 0.05
    min_frequency_ratio: _bounded(1.0, 10.0, low_open=False) = 1.25
    significant_order_share: _bounded(0.001, 1.0) = 0.05
    drive: Literal["chain", "belt", "gears"] = "chain"
    drive_pitch_radius_mm: Length(2.0, 1000.0, low_open=False)
    drive_allowable_force_N: _bounded(1.0, 1e8, "N")
    drive_stiffness_N_per_mm: Optional[_bounded(10.0, 1e7, "N/mm", low_open=False)] = None
    sprocket_inertia_kg_mm2: _bounded(0.0, 1e7, "kg mm2", low_open=False) = 0.0
    torsional_damping_ratio: _bounded(0.001, 0.5, low_open=False) = 0.05
    max_timing_play_mm: Length(0.01, 100.0) = 3.175

    @model_validator(mode="after")
    def _consistent(self):
        problems = []
        n = len(self.section_lengths_mm)
        for key in ("section_diameters_mm", "section_bores_mm"):
            value = getattr(self, key)
            if value is not None and len(value) != n:
                problems.append(note("spec.per_section", key=key, entries=len(value), count=n))
        if self.section_bores_mm is not None and len(self.section_bores_mm) == n:
            share = 1.0 - 2.0 * CAMSHAFT_MIN_WALL
            thin = [(i, b, d) for i, (b, d) in enumerate(zip(self.section_bores_mm, self.section_diameters_mm))
                    if b > share * d * (1.0 + 1e-12)]
            if thin:
                i, b, d = thin[0]
                problems.append(note("spec.thin_bore", i=i, bore=b, most=share * d, share=share, wall=CAMSHAFT_MIN_WALL)
                                + (note("spec.more_thin", count=len(thin) - 1) if len(thin) > 1 else ()))
        length = sum(self.section_lengths_mm)
        positions = self.cylinder_positions_mm
        if sorted(positions) != positions or len(set(positions)) != len(positions):
            problems.append(note("spec.positions_increase", positions=f"{positions}"))
        journals = self.journal_positions_mm
        if len(journals) < 2 or sorted(journals) != journals or len(set(journals)) != len(journals):
            problems.append(note("spec.journals", journals=f"{journals}"))
        elif positions and (positions[0] <= journals[0] or positions[-1] >= journals[-1]):
            problems.append(note("spec.lobes_between", positions=f"{positions}", first=journals[0], last=journals[-1]))
        if max(positions + journals, default=0.0) > length:
            problems.append(note("spec.beyond_shaft", length=length))
        if self.cylinders is not None and len(self.cylinders) != len(positions):
            problems.append(note("spec.positions_cylinders", entries=len(positions), count=len(self.cylinders)))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


class Gas(_Model):
    """[gas]: absolute pressures for the closed-valve spring check and the cam load (Valve-train practical works (n.d.), works 5, 7)."""

    exhaust_back_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.106
    cylinder_intake_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.085
    intake_port_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.1
    cylinder_exhaust_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.115
    exhaust_opening_pressure_MPa: _bounded(0.001, 50.0, "MPa", low_open=False) = 0.5


class Cycle(_Model):
    """[crank.cycle]: the Wiebe cycle model used when no pressure_file is given."""

    heat_input_J: _bounded(0.01, 1e8, "J", low_open=False)
    intake_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.09
    exhaust_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.11
    combustion_start_deg: _bounded(-90.0, 90.0, "deg") = -15.0
    combustion_duration_deg: _bounded(1.0, 180.0, "deg", low_open=False) = 60.0
    wiebe_a: _bounded(0.01, 50.0, low_open=False) = 6.908
    wiebe_m: _bounded(-1.0, 10.0) = 2.0
    gamma: _bounded(1.0, 2.0) = 1.33


class CrankSpec(_Model):
    """[crank]: the crank mechanism (Power units manual (n.d.)).  bore, stroke, rod length and speed default to [engine]."""

    bore_mm: Optional[Length(5.0, 2000.0, low_open=False)] = None
    stroke_mm: Optional[Length(5.0, 4000.0, low_open=False)] = None
    rod_length_mm: Optional[Length(5.0, 10000.0, low_open=False)] = None
    offset_mm: _bounded(-1000.0, 1000.0, "mm", low_open=False) = 0.0
    speed_rpm: Optional[_bounded(10.0, 30000.0, "rpm", low_open=False)] = None
    kinematics: Literal["exact", "approximate"] = "exact"
    pressure_file: Optional[str] = None
    pv_method: Literal["exact", "brix"] = "exact"
    compression_ratio: Optional[_bounded(1.0, 60.0)] = None
    ambient_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.1
    step_deg: _bounded(0.1, 10.0, "deg", low_open=False) = 1.0
    piston_kg: Optional[_bounded(0.001, 1e4, "kg", low_open=False)] = None
    rod_kg: Optional[_bounded(0.001, 1e4, "kg", low_open=False)] = None
    crank_kg: Optional[_bounded(0.0, 1e4, "kg", low_open=False)] = None
    specific_piston_kg_m2: Optional[_bounded(1.0, 1e4, "kg/m2", low_open=False)] = None
    specific_rod_kg_m2: Optional[_bounded(1.0, 1e4, "kg/m2", low_open=False)] = None
    specific_crank_kg_m2: Optional[_bounded(0.0, 1e4, "kg/m2", low_open=False)] = None
    rod_pin_fraction: _bounded(0.01, 0.99, low_open=False) = 0.275
    cycle: Optional[Cycle] = None

    si_extras: ClassVar[tuple] = ("indicator",)

    def read_extras(self, root) -> dict:
        """The indicator diagram of ``pressure_file`` as read (:func:`valvetrain.files.read_indicator`), or None."""
        if self.pressure_file is None:
            return {"indicator": None}
        return {"indicator": read_indicator(resolve_path(root, self.pressure_file), root.engine.strokes)}

    @model_validator(mode="after")
    def _masses_and_pressure(self):
        problems = []
        for part in ("piston", "rod", "crank"):
            given = getattr(self, f"{part}_kg") is not None, getattr(self, f"specific_{part}_kg_m2") is not None
            if all(given):
                problems.append(note("spec.mass_not_both", part=part))
            elif not any(given):
                problems.append(note("spec.mass_required", part=part))
        if self.pressure_file is None and self.cycle is None:
            problems.append(note("spec.pressure_needed"))
        if self.cycle is not None and self.compression_ratio is None:
            problems.append(note("spec.cycle_ratio"))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


class Port(_Model):
    """[two_stroke.ports.NAME]: one piston-controlled port (or a group of equal ports: width is their sum)."""

    kind: Literal["exhaust", "transfer", "inlet"]
    width_mm: Length(0.5, 10000.0, low_open=False)
    height_mm: Optional[Length(0.1, 3000.0, low_open=False)] = None
    opens_before_bdc_deg: Optional[_bounded(0.1, 180.0, "deg", low_open=False, high_open=True)] = None
    lower_edge_mm: Optional[Length(0.0, 5000.0, low_open=False)] = None

    @model_validator(mode="after")
    def _geometry(self):
        if self.kind == "inlet":
            if self.lower_edge_mm is None or self.height_mm is None:
                raise InputError(NoteText(note("spec.inlet_port")))
        elif (self.height_mm is None) == (self.opens_before_bdc_deg is None):
            raise InputError(NoteText(note("spec.port_height_or_timing")))
        return self


class TwoStroke(_Model):
    """[two_stroke]: port timing of a piston-ported two-stroke (Valve-train practical works (n.d.), work 8)."""

    speed_rpm: Optional[_bounded(10.0, 30000.0, "rpm", low_open=False)] = None
    speed_range_rpm: Optional[Pair(10.0, 30000.0, "rpm")] = None
    kinematics: Literal["exact", "approximate"] = "exact"
    piston_height_mm: Optional[Length(1.0, 3000.0, low_open=False)] = None
    step_deg: _bounded(0.05, 10.0, "deg", low_open=False) = 0.5
    ports: dict[str, Port]


class BreathingSide(_Model):
    """[breathing.intake], [breathing.exhaust]: one side's valves, their discharge coefficients and runner.

    The lift is the designed valves' of the kind (every ``[valves.NAME]`` of ``kind``): their cam's
    (``lift = "designed"``, the default) or, with ``lift = "dynamics"``, the valve motion of each one's ``[dynamics]`` train at each
    condition's speed (the steady revolution, with its deflection, separation and bounce); or a measured one
    (``lift_file``: ``crank_deg,lift_mm``, crank degrees from the gas-exchange TDC, the valve shut outside the rows;
    ``valves`` of them).  The effective area is C_D(L/D) of ``cd_file`` (``l_over_d,cd_forward,cd_reverse``, forward
    into the cylinder for the intake, out of it for the exhaust) on the reference area of ``cd_reference`` (the port,
    pi D^2 / 4, or the curtain, pi D L; D = ``cd_diameter_mm``), or without a file the default C_D on the valves'
    flow section.  ``runner_length_mm`` and ``runner_diameter_mm``: the runner with its port from the plenum to the
    valve (none: the valve opens straight into the plenum); at least 10 mm, the port of a small engine's valve
    alone being longer, and its grid's four cells setting the time step (a runner of 10 mm asks about as many
    cell-steps as :data:`~valvetrain.breathing.cycle.MAX_WORK` allows for examples/tcc3-motored.toml's three
    conditions)."""

    lift: Optional[Literal["designed", "dynamics"]] = None
    lift_file: Optional[str] = None
    valves: Whole(1, 8) = 1
    cd_file: Optional[str] = None
    cd_diameter_mm: Optional[Length(1.0, 1000.0)] = None
    cd_reference: Literal["port", "curtain"] = "port"
    runner_length_mm: Optional[Length(10.0, 20000.0, low_open=False)] = None
    runner_diameter_mm: Optional[Length(1.0, 1000.0)] = None

    si_extras: ClassVar[tuple] = ("measured_lift", "cd")

    def read_extras(self, root) -> dict:
        """The measured lift (crank deg, mm) and the C_D table (L/D, forward, reverse) as read
        (:func:`valvetrain.files.read_valve_lift`, :func:`valvetrain.files.read_cd_table`), or None."""
        return {"measured_lift": (None if self.lift_file is None
                                  else read_valve_lift(resolve_path(root, self.lift_file))),
                "cd": None if self.cd_file is None else read_cd_table(resolve_path(root, self.cd_file))}

    @model_validator(mode="after")
    def _pairs(self):
        problems = []
        if (self.runner_length_mm is None) != (self.runner_diameter_mm is None):
            problems.append(note("spec.runner_pair"))
        if self.cd_file is not None and self.cd_diameter_mm is None:
            problems.append(note("spec.cd_diameter"))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


class PlenumState(_Model):
    """The plenums and the walls of a breathing condition (absolute pressures)."""

    intake_pressure_kPa: _bounded(1.0, 10000.0, "kPa", low_open=False)
    intake_temperature_C: _bounded(-60.0, 500.0, "degC", low_open=False)
    exhaust_pressure_kPa: _bounded(1.0, 10000.0, "kPa", low_open=False)
    exhaust_temperature_C: Optional[_bounded(-60.0, 1500.0, "degC", low_open=False)] = None
    wall_temperature_C: Optional[_bounded(-60.0, 1000.0, "degC", low_open=False)] = None


class BreathingCondition(PlenumState):
    """[[breathing.conditions]]: one speed and plenum state (the exhaust plenum's temperature, when not given, is
    the mean of the gas that flows into it; the wall temperature defaults to [breathing]'s)."""

    speed_rpm: _bounded(10.0, 30000.0, "rpm", low_open=False)


class BreathingCurve(PlenumState):
    """[breathing.curve]: the breathing at ``points`` speeds evenly over ``speed_range_rpm``, one plenum state."""

    speed_range_rpm: Pair(10.0, 30000.0, "rpm")
    points: Whole(2, 200) = 20


class Breathing(_Model):
    """[breathing]: the gas exchange of the engine's cylinders through its valves, converged over cycles at each
    condition, motored or fired (the Wiebe heat release of [crank.cycle], its fuel the trapped air's).

    ``compression_ratio`` defaults to [crank]'s; ``wall_temperature_C`` is the conditions' default;
    ``heat_transfer``: Woschni (1967) or none; ``cell_mm`` the runners' longest cell; the cycles repeat when the
    trapped mass, the delivered mass and the pressure at the intake valve's closing change by less than
    ``cycle_tolerance`` (at most ``max_cycles``)."""

    mode: Literal["motored", "fired"] = "motored"
    compression_ratio: Optional[_bounded(1.0, 60.0)] = None
    wall_temperature_C: Optional[_bounded(-60.0, 1000.0, "degC", low_open=False)] = None
    heat_transfer: Literal["woschni", "adiabatic"] = "woschni"
    fuel: Literal["isooctane", "n-heptane", "methane", "propane", "ethanol"] = "isooctane"
    equivalence_ratio: _bounded(0.1, 1.0, low_open=False) = 1.0
    combustion_efficiency: _bounded(0.1, 1.0, low_open=False) = 1.0
    cell_mm: _bounded(2.0, 500.0, "mm", low_open=False) = 40.0
    cycle_tolerance: _bounded(1e-6, 0.1, low_open=False) = 1e-3
    max_cycles: Whole(2, 1000) = 60
    intake: BreathingSide = BreathingSide()
    exhaust: BreathingSide = BreathingSide()
    conditions: list[BreathingCondition] = []
    curve: Optional[BreathingCurve] = None

    @model_validator(mode="after")
    def _something_to_run(self):
        if not self.conditions and self.curve is None:
            raise InputError(NoteText(note("spec.no_conditions")))
        if self.curve is not None and self.curve.speed_range_rpm[0] >= self.curve.speed_range_rpm[1]:
            raise InputError(NoteText(note("spec.curve_range", pair=f"{list(self.curve.speed_range_rpm)}")))
        return self


def resolve_path(spec, name) -> Path:
    """A file named in the specification, relative to the specification file's folder."""
    path = Path(name)
    return path if path.is_absolute() or spec.source_dir is None else Path(spec.source_dir) / path
