"""Two-stroke port stage: timing, areas and time-area of the piston-controlled ports (Valve-train practical works (n.d.), work 8)."""

from dataclasses import dataclass
from functools import cached_property
from typing import Any, Union

import numpy as np

from .. import twostroke
from ..checks import Check, check
from ..crank.kinematics import crank_angle_at
from .crank import crank_geometry
from .results import quantity, record


@dataclass(frozen=True)
class SkirtPort:
    """An inlet port opened by the piston skirt (Valve-train practical works (n.d.), eq. 8.4)."""

    kind: str = quantity("kind", label="inlet")
    width: float = quantity("width_mm", "mm", "port width (sum of equal ports)")
    opens: float = quantity("opens_crank_deg", "crank deg", "opens (before TDC: negative)")
    closes: float = quantity("closes_crank_deg", "crank deg", "closes after TDC")
    duration: float = quantity("duration_deg", "crank deg", "open duration")
    height: float = quantity("height_mm", "mm", "port height")
    lower_edge: float = quantity("lower_edge_mm", "mm", "lower edge below the crown at TDC")
    max_area: float = quantity("max_area_mm2", "mm2", "largest open area")
    time_area: float = quantity("time_area_mm2_s", "mm2 s", "time-area at the speed")


@dataclass(frozen=True)
class TopPort:
    """An exhaust or transfer port opened by the piston crown (Valve-train practical works (n.d.), eqs. 8.1-8.3, 8.5-8.7)."""

    kind: str = quantity("kind", label="exhaust or transfer")
    width: float = quantity("width_mm", "mm", "port width (sum of equal ports)")
    height: float = quantity("height_mm", "mm", "port height")
    relative_height: float = quantity("relative_height", label="height / stroke, sigma")
    opens_before_bdc: float = quantity("opens_before_bdc_deg", "crank deg", "opens before BDC")
    opens: float = quantity("opens_crank_deg", "crank deg", "opens after TDC")
    closes: float = quantity("closes_crank_deg", "crank deg", "closes after TDC")
    duration: float = quantity("duration_deg", "crank deg", "open duration")
    opens_before_bdc_series: float = quantity("opens_before_bdc_series_deg", "crank deg",
                                              "opening by the manual's series kinematics")
    time_area_analytic: float = quantity("time_area_analytic_mm2_s", "mm2 s", "time-area, eq. (8.7)")
    max_area: float = quantity("max_area_mm2", "mm2", "largest open area")
    time_area: float = quantity("time_area_mm2_s", "mm2 s", "time-area at the speed")


@dataclass(frozen=True)
class TwoStrokeSummary:
    """The two-stroke chapter's figures."""

    speed: float = quantity("speed_rpm", "rpm", "crank speed")
    lam: float = quantity("lambda", label="lambda = R / L")
    kinematics: str = quantity("kinematics", label="exact or approximate")
    ports: dict[str, Union[TopPort, SkirtPort]] = quantity("ports", label="each port")
    speed_range: tuple[float, float] = quantity("speed_range_rpm", "rpm", "speeds of Z(n)")


@dataclass(frozen=True)
class PortCurves:
    """The curves of one port (SI; Valve-train practical works (n.d.), eqs. 8.1-8.6).

    Attributes
    ----------
    area : ndarray
        Open area of the port at each crank angle of :attr:`TwoStrokeResults.phi` [m^2].
    time_area : ndarray
        Time-area Z = K1 K2 / n at each crank speed of :attr:`TwoStrokeResults.speeds` [m^2 s].
    """

    area: np.ndarray
    time_area: np.ndarray


@dataclass(frozen=True, repr=False)
class TwoStrokeResults:
    """Port areas over a revolution, the time-area against speed, and the summary (SI)."""

    phi: np.ndarray                  # crank angle from TDC [rad]
    speeds: np.ndarray               # [rad/s]
    curves: dict[str, PortCurves]    # port name -> its area and time-area curves
    figures: TwoStrokeSummary
    checks: tuple[Check, ...]        # every check of the chapter

    @cached_property
    def summary(self) -> dict[str, Any]:
        """The chapter's record in results.json (engineering units), made once: read it, don't change it."""
        return record(self.figures)

    def __repr__(self):
        return f"TwoStrokeResults(ports {', '.join(self.curves)}, {len(self.checks)} checks)"


def _skirt_opening(lower, piston_height, radius, lam, exact):
    """Crank angle from TDC [rad] at which the skirt uncovers the inlet port's lower edge (0 if never)."""
    travel = lower - piston_height
    if travel <= 0.0:
        return 0.0
    if travel >= 2.0 * radius:
        return np.pi
    return float(crank_angle_at(travel, radius, lam, exact=exact))


def two_stroke_stage(ts, crank, eng) -> TwoStrokeResults:
    """Run the [two_stroke] chapter from the SI views of [two_stroke], [crank] (or None) and [engine]; returns
    :class:`TwoStrokeResults`."""
    bore, stroke, rod, rated = crank_geometry(crank, eng) if crank is not None else \
        (eng.bore, eng.stroke, eng.rod_length, eng.rated_speed)
    radius = stroke / 2.0
    lam = radius / rod
    speed = ts.speed or rated
    exact = ts.kinematics == "exact"
    n = int(round(2.0 * np.pi / ts.step))
    phi = np.arange(n + 1) * ts.step
    low, high = ts.speed_range or (0.4 * speed, 1.2 * speed)
    speeds = np.linspace(low, high, 21)
    curves, ports, found = {}, {}, []
    for name, port in ts.ports.items():
        if port.kind == "inlet":
            area = twostroke.skirt_port_area(phi, port.lower_edge, port.height, ts.piston_height, port.width,
                                             stroke, lam, exact)
            before_tdc = _skirt_opening(port.lower_edge, ts.piston_height, radius, lam, exact)
            z = twostroke.time_area_numeric(phi, area, speed)
            rec = SkirtPort(port.kind, port.width, -before_tdc, before_tdc, 2.0 * before_tdc, port.height,
                            port.lower_edge, float(area.max()), z)
        else:
            if port.height is not None:
                sigma = port.height / stroke
                angle = twostroke.port_angle(sigma, lam, exact)
            else:
                angle = port.opens_before_bdc
                sigma = twostroke.port_height(angle, lam, exact)
            area = twostroke.top_port_area(phi, sigma * stroke, port.width, stroke, lam, exact)
            z = twostroke.time_area_numeric(phi, area, speed)
            rec = TopPort(port.kind, port.width, sigma * stroke, sigma, angle, np.pi - angle, np.pi + angle,
                          2.0 * angle, twostroke.port_angle_series(sigma, lam),
                          twostroke.time_area_analytic(bore, stroke, sigma, lam, port.width / (np.pi * bore), speed),
                          float(area.max()), z)
            (h_lo, h_hi), (w_lo, w_hi) = twostroke.PORT_SIZE_RANGES[port.kind]
            found.append(check("ports.height_to_stroke", sigma, h_lo, h_hi, source="Valve-train practical works (n.d.), Table 8.1",
                               params={"port": name}))
            found.append(check("ports.width_to_bore", port.width / bore, w_lo, w_hi,
                               source="Valve-train practical works (n.d.), Table 8.1", params={"port": name}))
        ports[name] = rec
        curves[name] = PortCurves(area, z * speed / speeds)    # Z = K / n (8.6)
    figures = TwoStrokeSummary(speed, lam, ts.kinematics, ports, (float(low), float(high)))
    return TwoStrokeResults(phi, speeds, curves, figures, tuple(found))
