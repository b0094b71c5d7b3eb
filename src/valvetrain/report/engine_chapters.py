"""The report's chapters of the engine as a whole: the camshaft, the phasers and the breathing (their contexts for
the template ``templates/report.html``), and a specification section's inputs as rows (:func:`flatten`)."""

from typing import Any, Optional

from ..design.results import shown, shown_value


def flatten(d, prefix="") -> list[tuple[str, object]]:
    """A specification section's values as rows (dotted key, value), a nested table's under its key
    (``cam.phi1_deg``), None left out."""
    rows = []
    for k, v in d.items():
        if isinstance(v, dict):
            rows += flatten(v, f"{prefix}{k}.")
        elif v is not None:
            rows.append((f"{prefix}{k}", v))
    return rows


CAMSHAFT_ROWS = ("lobes", "ratio", "peak", "peak_angle", "lowest", "mean", "fluctuation", "rms_fluctuation", "power",
                 "natural_frequencies", "frequency_ratio", "twist_max", "twist_crank", "deflection_max", "drive_force",
                 "drive_force_mean", "drive_allowable", "drive_windup", "drive_end_inertia")
"""The rows of the report's table of the camshaft's figures (fields of
:class:`~valvetrain.design.camshaft.CamshaftRecord`)."""

CAMSHAFT_RESPONSE = ("damping_ratio", "speed_range", "allowable", "fluctuation", "fluctuation_speed",
                     "fluctuation_cylinder", "drive_force", "drive_force_speed")
"""The rows of the report's table of the camshaft's torsional response (fields of
:class:`~valvetrain.design.camshaft.TorsionalResponse`)."""

CAMSHAFT_RESONANCES = ("mode", "frequency", "order", "speed", "fluctuation", "drive_force")
"""The columns of the report's table of the resonances in the running range (fields of
:class:`~valvetrain.design.camshaft.TorsionalResonance`)."""

CAMSHAFT_STATIONS = ("positions", "station_inertia", "max_twist", "deflection")
"""The columns of the report's table of the lobe stations (fields of
:class:`~valvetrain.design.camshaft.CamshaftRecord`)."""


def camshaft_chapter(results, spec, plots) -> Optional[dict[str, Any]]:
    """The camshaft chapter for the report: its inputs, figures, stations and significant orders."""
    if results.camshaft is None:
        return None
    figures = results.camshaft.figures
    stations = shown(figures, *CAMSHAFT_STATIONS)
    amplitudes, orders, speeds = (shown_value(figures, k) for k in ("orders", "significant_orders", "resonance_speeds"))
    return {"inputs": [(k, v) for k, v in flatten(spec["camshaft"]) if k != "valves"], "valves": figures.valves,
            "rows": shown(figures, *CAMSHAFT_ROWS), "columns": [k for k, _ in stations],
            "stations": list(zip(shown_value(figures, "cylinders"), *(c for _, c in stations), strict=True)),
            "orders": [(k, amplitudes[k], n) for k, n in zip(orders, speeds, strict=True)],
            "response": shown(figures.response, *CAMSHAFT_RESPONSE),
            "resonance_columns": [k for k, _ in shown(figures.response.resonances[0], *CAMSHAFT_RESONANCES)]
            if figures.response.resonances else [],
            "resonances": [[v for _, v in shown(r, *CAMSHAFT_RESONANCES)] for r in figures.response.resonances],
            "table": figures.response.table, "plots": plots.get("camshaft", {})}


PHASER_ROWS = ("advance_range", "cam_range", "torque_peak", "torque_lowest", "torque_mean", "gas_load",
               "gas_load_advance")
"""The rows of the report's table of a phaser's figures (fields of :class:`~valvetrain.design.phaser.PhaserRecord`)."""

PHASER_EVENTS = ("advance", "opens", "closes", "min_gap", "min_gap_angle")
"""The columns of the report's table of the events at the phaser's range ends and at phase 0 (fields of
:class:`~valvetrain.design.phaser.PhasedEvents`)."""

PHASER_BEST = ("speed", "intake_pressure", "advance", "volumetric_efficiency", "residual_gas_fraction", "pmep",
               "torque", "gain", "evaluations")
"""The columns of the report's table of the best phases (fields of :class:`~valvetrain.design.phaser.BestPhase`)."""

PHASER_OPENING = ("advance", "speed", "cylinder_pressure", "port_pressure", "gas_force", "cam_force", "contact_stress")
"""The columns of the report's table of an exhaust valve's opening at the phaser's range ends and at phase 0 (fields
of :class:`~valvetrain.design.phaser.OpeningLoad`)."""


def phaser_chapters(results, spec, plots, checks) -> list[dict[str, Any]]:
    """The phaser chapters: each phased valve's figures, events at its range's ends, best phases, the objective's
    map (one row a phase, one column a condition), its figure and its checks."""
    out = []
    for name, p in results.phasers.items():
        f = p.figures
        events = [e for e in PHASER_EVENTS if getattr(f.events[0], e) is not None]
        best = [b for b in PHASER_BEST if f.best and getattr(f.best[0], b) is not None]
        opening = [o for o in PHASER_OPENING if f.opening and getattr(f.opening[0], o) is not None]
        n = len(f.best)
        values = [shown_value(point, f.objective) for point in f.map] if f.map else []
        out.append({"name": name, "rows": shown(f, *(k for k in PHASER_ROWS if getattr(f, k) is not None)),
                    "objective": f.objective,
                    "on_camshaft": results.camshaft is not None and name in results.camshaft.figures.valves,
                    "tolerance": spec["valves"][name]["phaser"]["tolerance_crank_deg"],
                    "event_columns": [k for k, _ in shown(f.events[0], *events)],
                    "events": [[v for _, v in shown(e, *events)] for e in f.events],
                    "opening_columns": [k for k, _ in shown(f.opening[0], *opening)] if f.opening else [],
                    "opening": [[v for _, v in shown(o, *opening)] for o in f.opening or ()],
                    "best_columns": [k for k, _ in shown(f.best[0], *best)] if f.best else [],
                    "best": [[v for _, v in shown(b, *best)] for b in f.best],
                    "conditions": [(shown_value(b, "speed"), shown_value(b, "intake_pressure")) for b in f.best],
                    "map": [(shown_value(f.map[i], "advance"), values[i:i + n]) for i in range(0, len(values), n)],
                    "plot": plots.get(name, {}).get("phaser"), "checks": checks[name].get("phaser", [])})
    return out


BREATHING_FIELDS = ("speed", "intake_pressure", "intake_temperature", "exhaust_pressure", "wall_temperature",
                    "air_mass_flow", "volumetric_efficiency", "trapped_mass", "residual_gas_fraction",
                    "intake_backflow", "exhaust_backflow", "imep", "imep_gross", "pmep", "peak_pressure",
                    "peak_pressure_angle", "exhaust_temperature", "torque", "power", "cycles")
"""The rows of the breathing chapter's table of conditions (the torque and power of a fired engine)."""

BREATHING_CURVE_FIELDS = ("speed", "air_mass_flow", "volumetric_efficiency", "residual_gas_fraction", "imep", "pmep",
                          "peak_pressure", "torque", "power")
"""The columns of the breathing chapter's table of the speed curve."""


def breathing_chapter(results, spec, plots) -> Optional[dict[str, Any]]:
    """The breathing chapter's context: its inputs, the conditions' figures as rows (one column a condition), the
    curve's as columns (one row a speed), the figures and the tables' files."""
    b = results.breathing
    if b is None:
        return None

    def table(records, keys) -> tuple[list[str], list[list[Any]]]:
        keys = [k for k in keys if all(getattr(r, k) is not None for r in records)]
        return keys, [[value for _, value in shown(r, *keys)] for r in records]

    conditions = [r.figures for r in b.conditions]
    keys, rows = table(conditions, BREATHING_FIELDS) if conditions else ([], [])
    curve_keys, curve_rows = table([r.figures for r in b.curve], BREATHING_CURVE_FIELDS) if b.curve else ([], [])
    return {"inputs": [(k, v) for k, v in flatten(spec["breathing"]) if not k.startswith(("conditions", "curve"))],
            "curve_inputs": flatten(spec["breathing"]["curve"]) if spec["breathing"].get("curve") else [],
            "names": [shown(conditions[0], k)[0][0] for k in keys] if conditions else [],
            "rows": [list(col) for col in zip(*rows, strict=True)] if rows else [],
            "curve_keys": [shown(b.curve[0].figures, k)[0][0] for k in curve_keys] if b.curve else [],
            "curve_rows": curve_rows, "plots": plots.get("breathing", {}),
            "files": [f"breathing_condition_{i}.csv" for i in range(1, len(b.conditions) + 1)]
            + ["breathing_conditions.csv"] * bool(b.conditions) + ["breathing_curve.csv"] * bool(b.curve)}


__all__ = ["BREATHING_CURVE_FIELDS", "BREATHING_FIELDS", "CAMSHAFT_RESONANCES", "CAMSHAFT_RESPONSE", "CAMSHAFT_ROWS",
           "CAMSHAFT_STATIONS", "PHASER_BEST", "PHASER_EVENTS", "PHASER_OPENING", "PHASER_ROWS", "breathing_chapter",
           "camshaft_chapter", "flatten", "phaser_chapters"]
