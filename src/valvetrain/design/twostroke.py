"""Two-stroke port stage: timing, areas and time-area of the piston-controlled ports (seed 000, work 8)."""

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from .. import twostroke
from ..checks import check
from ..crank.kinematics import displacement
from ..specification import crank_geometry
from ..units import DEG, MM, rad_to_deg


@dataclass
class TwoStrokeResults:
    """Port areas over a revolution, the time-area against speed, and the summary (SI)."""

    phi: np.ndarray          # crank angle from TDC [rad]
    areas: dict              # port name -> area [m^2]
    speeds: np.ndarray       # [rpm]
    time_areas: dict         # port name -> Z(n) [m^2 s]
    summary: dict
    checks: list                    # every valvetrain.checks.Check of the chapter


def _skirt_opening(lower, piston_height, radius, lam, exact):
    """Crank angle from TDC [rad] at which the skirt uncovers the inlet port's lower edge (0 if never)."""
    travel = lower - piston_height
    if travel <= 0.0:
        return 0.0
    if travel >= 2.0 * radius:
        return np.pi
    return brentq(lambda a: displacement(a, radius, lam, exact=exact) - travel, 0.0, np.pi, xtol=1e-14)


def two_stroke_stage(spec):
    """Run the [two_stroke] chapter; returns :class:`TwoStrokeResults`."""
    ts = spec.two_stroke
    bore_mm, stroke_mm, rod_mm, rated = crank_geometry(spec)
    bore, stroke, radius = bore_mm * MM, stroke_mm * MM, stroke_mm * MM / 2.0
    lam = radius / (rod_mm * MM)
    speed = ts.speed_rpm or rated
    exact = ts.kinematics == "exact"
    n = int(round(360.0 / ts.step_deg))
    phi = np.arange(n + 1) * (ts.step_deg * DEG)
    low, high = ts.speed_range_rpm or (0.4 * speed, 1.2 * speed)
    speeds = np.linspace(low, high, 21)
    areas, curves, ports, found = {}, {}, {}, []
    for name, port in ts.ports.items():
        width = port.width_mm * MM
        rec = {"kind": port.kind, "width_mm": port.width_mm}
        if port.kind == "inlet":
            height = port.height_mm * MM
            area = twostroke.skirt_port_area(phi, port.lower_edge_mm * MM, height, ts.piston_height_mm * MM, width,
                                             stroke, lam, exact)
            before_tdc = _skirt_opening(port.lower_edge_mm * MM, ts.piston_height_mm * MM, radius, lam, exact)
            rec.update(opens_crank_deg=-rad_to_deg(before_tdc), closes_crank_deg=rad_to_deg(before_tdc),
                       duration_deg=2.0 * rad_to_deg(before_tdc), height_mm=port.height_mm,
                       lower_edge_mm=port.lower_edge_mm)
        else:
            if port.height_mm is not None:
                sigma = port.height_mm / stroke_mm
                angle = twostroke.port_angle(sigma, lam, exact)
            else:
                angle = port.opens_before_bdc_deg * DEG
                sigma = twostroke.port_height(angle, lam, exact)
            height = sigma * stroke
            area = twostroke.top_port_area(phi, height, width, stroke, lam, exact)
            rec.update(height_mm=height / MM, relative_height=sigma, opens_before_bdc_deg=rad_to_deg(angle),
                       opens_crank_deg=180.0 - rad_to_deg(angle), closes_crank_deg=180.0 + rad_to_deg(angle),
                       duration_deg=2.0 * rad_to_deg(angle),
                       opens_before_bdc_series_deg=rad_to_deg(twostroke.port_angle_series(sigma, lam)),
                       time_area_analytic_mm2_s=twostroke.time_area_analytic(
                           bore, stroke, sigma, lam, width / (np.pi * bore), speed) / MM**2)
            (h_lo, h_hi), (w_lo, w_hi) = twostroke.PORT_SIZE_RANGES[port.kind]
            found.append(check(f"{name} port height / stroke", sigma, h_lo, h_hi, source="seed 000, Table 8.1"))
            found.append(check(f"{name} port width / bore", width / bore, w_lo, w_hi, source="seed 000, Table 8.1"))
        z = twostroke.time_area_numeric(phi, area, speed)
        rec.update(max_area_mm2=float(area.max()) / MM**2, time_area_mm2_s=z / MM**2)
        areas[name], ports[name] = area, rec
        curves[name] = z * speed / speeds                       # Z = K / n (8.6)
    summary = {"speed_rpm": speed, "lambda": lam, "kinematics": ts.kinematics, "ports": ports,
               "speed_range_rpm": [float(low), float(high)]}
    return TwoStrokeResults(phi, areas, speeds, curves, summary, found)
