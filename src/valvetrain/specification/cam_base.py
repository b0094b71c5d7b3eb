"""The parts every cam section shares: the registry of the cam models (:func:`register`), the base model
:class:`_CamBase` (the follower, the ramps, the records every law gives), the ramp and closing-side keys, the
segment angles and their sums, and the half-angles of a valve's main event.

The models of the laws themselves are in :mod:`valvetrain.specification.cams`.  Timing angles are crank angles,
segment angles camshaft angles.
"""


from dataclasses import replace
from typing import ClassVar, Literal, Optional

import numpy as np
from pydantic import ValidationError, model_validator

from ..errors import InputError
from ..locale import NoteText, note
from ..followers import REGISTRY as FOLLOWERS
from ..laws import AsymmetricLaw
from ..laws.records import LawRecord
from ..units import cam_per_crank
from .fields import Length, _bounded, _Model
from .messages import Problem, message
from .si import si

REGISTRY = {}
"""``law`` name -> its cam model, in the order of registration."""


def register(model) -> type:
    """Class decorator: add a cam model to :data:`REGISTRY` under its ``law`` literal."""
    REGISTRY[model.model_fields["law"].annotation.__args__[0]] = model
    return model


def main_half_angle(valve, strokes) -> float:
    """phi_p0 [rad camshaft]: half the main event (ramps excluded), (opens + pi + closes)/2 crank angle on the
    camshaft (Valve-train practical works (n.d.), work 2, corrected phi_p0 formula, corrections note 1); ``valve`` is an SI view."""
    return (valve.opens + np.pi + valve.closes) / 2.0 * cam_per_crank(strokes)


def main_half_angle_deg(valve, strokes) -> float:
    """phi_p0 [cam deg] from a valve section in degrees (see :func:`main_half_angle`)."""
    return (valve.opens_deg + 180.0 + valve.closes_deg) / 2.0 * cam_per_crank(strokes)


def symmetric_nose(valve) -> float:
    """Crank angle of the nose of a symmetric lobe from the gas-exchange TDC [rad] (four-stroke), SI view.

    Intake: the main lift opens ``opens`` before TDC (crank 0) and closes ``closes`` after BDC (crank pi).
    Exhaust: opens ``opens`` before BDC (crank -pi) and closes ``closes`` after TDC (crank 0).
    """
    if valve.kind == "intake":
        return (np.pi + valve.closes - valve.opens) / 2.0
    return (valve.closes - np.pi - valve.opens) / 2.0


def _finite(x):
    """A float, or None where it is not defined (a checking height the lift never reaches)."""
    return float(x) if np.isfinite(x) else None


FINGER_VALVE_ANGLE = _bounded(-180.0, 180.0, "deg", low_open=False)
"""The bounds of ``finger_valve_angle_deg``: the direction the valve opens, from the follower's (+y) clockwise."""


class _CamBase(_Model):
    base_radius_mm: Length(2.0, 500.0, low_open=False)
    follower: Literal[tuple(FOLLOWERS)] = "flat"
    roller_radius_mm: Optional[Length(1.0, 200.0, low_open=False)] = None
    finger_pivot_x_mm: Optional[Length(-500.0, 500.0, low_open=False)] = None
    finger_pivot_y_mm: Optional[Length(-500.0, 500.0, low_open=False)] = None
    finger_roller_arm_mm: Optional[Length(2.0, 500.0, low_open=False)] = None
    finger_pad_arm_mm: Optional[Length(-500.0, 500.0, low_open=False)] = None
    finger_pad_drop_mm: Optional[Length(-200.0, 200.0, low_open=False)] = None
    finger_pad_radius_mm: Optional[Length(1.0, 1000.0, low_open=False)] = None
    finger_valve_angle_deg: Optional[FINGER_VALVE_ANGLE] = None
    finger_tip_offset_mm: Optional[Length(-50.0, 50.0, low_open=False)] = None

    @model_validator(mode="after")
    def _follower_keys(self):
        missing = FOLLOWERS[self.follower].missing_key(self)
        if missing:
            raise InputError(missing)
        return self

    needs_timing: ClassVar[bool] = True
    """Whether the valve's ``max_lift_mm``, ``opens_deg`` and ``closes_deg`` are required (a measured table sets
    its own)."""

    def build(self, valve, engine):
        """The lift law of this cam (tappet side, SI).

        Parameters
        ----------
        valve : the valve's SI view; ``valve.cam`` is this cam's SI view.
        engine : the engine's SI view.

        Raises
        ------
        ValueError
            Inputs that pass their bounds but admit no cam; the message names the keys.
        """
        raise NotImplementedError

    def problems(self, at, valve, engine):
        """Cross-checks of the cam's keys against the valve's timing and clearance, one message each ([] if none);
        ``at`` is the key path of the valve, ``valve`` and ``engine`` the specification's sections."""
        return []

    def nose_crank(self, valve, law):
        """Crank angle of the cam nose from the gas-exchange TDC [rad]; ``valve`` is the SI view."""
        return symmetric_nose(valve)

    def records(self, law, valve, engine, nose):
        """What the law adds to the cam's results: ``(LawRecord, list of Check)`` (SI views)."""
        return LawRecord(), []

    def timing(self, valve, record):
        """Opening advance and closing lag [crank rad] of the main lift for the recommended ranges (SI view; a
        measured table's from its ``record``); None where not defined."""
        return valve.opens, valve.closes

    varies_ramp_and_spring: ClassVar[bool] = True
    """Whether a cam synthesis varies the ramp end velocity and the spring reserve beside :meth:`search_variables`."""

    derived_keys: ClassVar[dict] = {}
    """Keys of the cam derived from others when absent: ``key -> the dotted variables it follows``; a synthesis that
    varies one of those drops the key."""

    def search_variables(self, valve, engine):
        """The law's default design variables of a cam synthesis: ``[(dotted key under [valves.NAME], low, high)]`` in
        the keys' units, or None where the law has none (the synthesis then asks for them by name).

        ``valve`` and ``engine`` are the specification's sections.

        Raises
        ------
        ValueError
            The cam's keys leave nothing to vary; the message says what to name instead.
        """
        return None


def _tappet_lift(valve):
    return valve.max_lift / valve.rocker_ratio


def _ramp(cam):
    return dict(ramp_kind=cam.ramp_type, ramp_fraction=cam.ramp_acceleration_fraction)


def _closing_problem(at, problem):
    """A problem of the closing flank's own table, its key under ``{at}.cam.closing``."""
    return Problem(f"{at}.cam.closing.{problem.path}", problem.message, problem.value,
                   text=f"{at}.cam.closing: {problem}")


HYDRAULIC_NO_RAMP = NoteText(note("spec.hydraulic_no_ramp"))
"""Why a cam with a ramp is refused on a valve with a hydraulic lash adjuster without ``ramp_height_mm``: the ramps of
this package take up a mechanical clearance (their height is ``clearance_mm``), and a hydraulic train has none to take
up; its quieting ramp is given by ``[lash_adjuster] ramp_height_mm`` (:func:`ramp_height`)."""


def ramp_height(valve) -> float:
    """The height of the cam's ramps [m, at the cam] of a valve's SI view: the clearance they take up
    (``clearance_mm``), or with a lash adjuster its quieting ramp (``[lash_adjuster] ramp_height_mm``, 0 without), which
    lifts the valve (a hydraulic train has no clearance to take up)."""
    la = valve.lash_adjuster
    if la is None:
        return valve.clearance
    return 0.0 if la.ramp_height is None else la.ramp_height


def _clearance_problem(at, valve, what="spec.ramp_takes_clearance", key="law"):
    """The problem of a cam whose ramp takes up the clearance ([] if none): a clearance not in [0.01, 5] mm, or a ramp
    on a valve with a lash adjuster that gives no quieting ramp height ``ramp_height_mm`` (named by the cam's ``key``:
    ``law`` where the law always has a ramp, ``ramp`` where it is chosen)."""
    if valve.lash_adjuster is not None:
        if valve.lash_adjuster.ramp_height_mm is not None:
            return []
        value = f'"{valve.cam.law}"' if key == "law" else "true"
        return [Problem(f"{at}.cam.{key}", HYDRAULIC_NO_RAMP, value)]
    return [Problem(f"{at}.clearance_mm", NoteText(note("spec.clearance_range", what=note(what))),
                    f"{valve.clearance_mm:g}")] \
        if valve.clearance_mm <= 0.0 else []


class _RampKeys(_Model):
    ramp_type: Literal["cosine", "constant_velocity", "constant_acceleration"] = "cosine"
    ramp_acceleration_fraction: _bounded(0.01, 1.0, low_open=False) = 0.5


class _ClosingSide(_Model):
    """Laws that may give the closing flank its own angles and ramp: ``[valves.NAME.cam.closing]``."""

    closing: Optional[dict] = None
    """[valves.NAME.cam.closing]: the closing flank's own keys (same law; angles and ramp may differ)."""

    def closing_cam(self):
        """The closing flank as a cam of the same law (the keys not given are the opening flank's)."""
        if self.closing is None:
            return None
        data = {**self.model_dump(exclude={"closing"}), **self.closing, "law": self.law}
        return type(self).model_validate(data)

    def flank_angle_deg(self):
        """Main angle of one flank [cam deg]: the sum of its segment angles."""
        raise NotImplementedError

    def build(self, valve, engine):
        if self.closing is None:
            return self.build_flank(valve, engine)
        closing = self.closing_cam()
        opening = self.model_copy(update={"closing": None})
        return AsymmetricLaw(opening.build_flank(_with_cam(valve, si(opening)), engine),
                             closing.build_flank(_with_cam(valve, si(closing)), engine))

    def problems(self, at, valve, engine):
        if self.closing is None:
            return self.flank_problems(at, valve, engine)
        out = _clearance_problem(at, valve)
        try:
            closing = self.closing_cam()
        except ValidationError as exc:
            return out + [_closing_problem(at, message(err)) for err in exc.errors()]
        total = self.flank_angle_deg() + closing.flank_angle_deg()
        event = 2.0 * main_half_angle_deg(valve, engine.strokes)
        if abs(total - event) > 1e-6:
            out.append(Problem(f"{at}.cam", NoteText(note("spec.flanks_event", total=total, event=event))))
        return out + self.asymmetric_problems(at, closing)

    def asymmetric_problems(self, at, closing):
        return []

    def nose_crank(self, valve, law):
        if self.closing is None:
            return symmetric_nose(valve)
        # the main lift starts where the specification says, the nose follows it
        start = -valve.opens if valve.kind == "intake" else -np.pi - valve.opens
        return start + 2.0 * law.main_half_angle


def _with_cam(valve, cam):
    """The valve's SI view with another cam."""
    return replace(valve, cam=cam)


class _SegmentAngles(_ClosingSide):
    """Kurz and constant-acceleration cams: Phi1 + Phi2 + Phi3 = phi_p0, Phi3 may be left to the remainder."""

    def third_angle_deg(self, valve, strokes):
        """Phi3 [cam deg]: given, or the remainder phi_p0 - Phi1 - Phi2 (Valve-train practical works (n.d.), eq. 2.2)."""
        if self.phi3_deg is not None:
            return self.phi3_deg
        return main_half_angle_deg(valve, strokes) - self.phi1_deg - self.phi2_deg

    def flank_angle_deg(self):
        return self.phi1_deg + self.phi2_deg + (self.phi3_deg or 0.0)

    derived_keys: ClassVar[dict] = {"phi3_deg": ("cam.phi1_deg", "cam.phi2_deg", "opens_deg", "closes_deg")}

    def segment_variables(self, valve, engine):
        """phi1, phi2 of the synthesis (phi3 the remainder) [cam deg]."""
        half = main_half_angle_deg(valve, engine.strokes)
        return [("cam.phi1_deg", 0.15 * half, 0.75 * half), ("cam.phi2_deg", 0.02 * half, 0.45 * half)]

    def _phi3(self, valve, engine):
        """Phi3 [rad]: given, or the remainder of the half angle (SI view)."""
        cam = valve.cam
        return cam.phi3 if cam.phi3 is not None else main_half_angle(valve, engine.strokes) - cam.phi1 - cam.phi2

    def flank_problems(self, at, valve, engine):
        out = _clearance_problem(at, valve)
        half = main_half_angle_deg(valve, engine.strokes)
        phi3 = self.third_angle_deg(valve, engine.strokes)
        total = self.phi1_deg + self.phi2_deg + phi3
        empty = phi3 < 0.0 or (self.law == "kurz" and phi3 == 0.0)
        if self.phi3_deg is None and empty:
            out.append(Problem(f"{at}.cam", NoteText(note("spec.no_phi3", sum=self.phi1_deg + self.phi2_deg,
                                                          half=half))))
        elif abs(total - half) > 1e-6:
            out.append(Problem(f"{at}.cam", NoteText(note("spec.phi_sum", total=total, half=half))))
        return out
