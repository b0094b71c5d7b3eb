"""The cam card of a design: each valve's events at the checking heights, its lobe centre and lift at TDC, and the
pair's lobe separation and overlap (:mod:`valvetrain.camcard`)."""

from dataclasses import dataclass
from typing import Optional

from .. import camcard
from .results import quantity


@dataclass(frozen=True)
class CamCardValve:
    """One valve's line of the cam card (crank angles from the gas-exchange TDC)."""

    opens: float = quantity("seat_opens_crank_deg", "crank deg", "valve leaves its seat")
    closes: float = quantity("seat_closes_crank_deg", "crank deg", "valve meets its seat")
    duration: float = quantity("seat_duration_crank_deg", "crank deg", "duration seat to seat")
    opens_1mm: float = quantity("opens_at_1mm_crank_deg", "crank deg", "opening at 1 mm valve lift (null: the "
                                "valve lift never reaches 1 mm)")
    closes_1mm: float = quantity("closes_at_1mm_crank_deg", "crank deg", "closing at 1 mm valve lift (null: the "
                                 "valve lift never reaches 1 mm)")
    duration_1mm: float = quantity("duration_at_1mm_crank_deg", "crank deg", "duration at 1 mm valve lift (null: the "
                                   "valve lift never reaches 1 mm)")
    opens_050: float = quantity("opens_at_0_050in_crank_deg", "crank deg", "opening at 0.050 in tappet lift (null: "
                                "the tappet lift never reaches 0.050 in)")
    closes_050: float = quantity("closes_at_0_050in_crank_deg", "crank deg", "closing at 0.050 in tappet lift "
                                 "(null: the tappet lift never reaches 0.050 in)")
    duration_050: float = quantity("duration_at_0_050in_crank_deg", "crank deg", "duration at 0.050 in tappet lift "
                                   "(null: the tappet lift never reaches 0.050 in)")
    centre: float = quantity("lobe_centre_crank_deg", "crank deg", "lobe centre (the nose)")
    lift_at_tdc: float = quantity("lift_at_tdc_mm", "mm", "valve lift at the gas-exchange TDC")


@dataclass(frozen=True)
class CamCard:
    """The cam card: a line per valve and, with an intake and an exhaust valve, the pair's figures (the first valve
    of each kind)."""

    valves: dict[str, CamCardValve] = quantity("valves", label="a line per valve")
    separation: Optional[float] = quantity("lobe_separation_cam_deg", "cam deg", "lobe separation angle", default=None,
                                 omit_none=True)
    overlap: Optional[float] = quantity("overlap_crank_deg", "crank deg", "overlap seat to seat (negative: none)",
                              default=None, omit_none=True)
    overlap_050: Optional[float] = quantity("overlap_at_0_050in_crank_deg", "crank deg",
                                  "overlap at 0.050 in tappet lift (negative: none; null: a valve's tappet lift never reaches "
                                  "0.050 in)", default=None, omit_none=True)
    overlap_area: Optional[float] = quantity("overlap_area_mm_crank_deg", "mm crank deg",
                                   "area under the lower valve lift over the overlap", default=None, omit_none=True)


def valve_line(cam) -> CamCardValve:
    """The cam card line of a valve's cam stage (:class:`~valvetrain.design.valve.CamResult`)."""
    law, ik, nose = cam.law, cam.rocker_ratio, cam.nose
    opens, closes = (float(c) for c in camcard.crank_events((law.valve_opens, law.valve_closes), nose))
    o1, c1 = camcard.valve_events(law, ik, nose)
    o5, c5 = camcard.tappet_events(law, nose)
    return CamCardValve(opens, closes, closes - opens, o1, c1, c1 - o1, o5, c5, c5 - o5, nose,
                        float(camcard.lift_at(law, ik, nose, 0.0)))


def cam_card_stage(valves) -> CamCard:
    """The cam card of the designed valves (``name -> ValveDesign``) of a four-stroke."""
    lines = {name: valve_line(v.cam) for name, v in valves.items()}
    first = {kind: next((name for name, v in valves.items() if v.kind == kind), None) for kind in ("intake", "exhaust")}
    if None in first.values():
        return CamCard(lines)
    i, e = lines[first["intake"]], lines[first["exhaust"]]
    ci, ce = valves[first["intake"]].cam, valves[first["exhaust"]].cam
    area = camcard.overlap_area((ci.law, ci.rocker_ratio, ci.nose), (ce.law, ce.rocker_ratio, ce.nose))
    return CamCard(lines, camcard.lobe_separation(i.centre, e.centre), camcard.overlap(i.opens, e.closes),
                   camcard.overlap(i.opens_050, e.closes_050), area)
