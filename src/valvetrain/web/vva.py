"""The designer's panel of variable valve actuation, where the specification has it: a lost-motion hydraulic drive's
valve lift of the full lift and of each solenoid timing (:func:`valvetrain.api.lost_motion_series`) and a switching
finger's valve lift latched and unlatched, against the cycle crank angle, with their figures in a table (each
timing's lift, closing, landing velocity and brake pressure; each mode's lift, the unlatched arm's jump speed, the
force it leaves at the shut valve, the stresses of its spring and latch).  Their checks are in the checks table;
their keys in the panel's group of variable valve actuation (:data:`~valvetrain.web.form.WHERE_PRESENT`).
"""

from bokeh.models import ColumnDataSource, DataTable, Range1d, TableColumn
from bokeh.palettes import Category10_10
from bokeh.plotting import figure
import numpy as np

from ..locale import catalogue
from ..report.i18n import TEXT
from .draw import PLOT_ROOM, PLOT_WIDTH, WORDS, _array, _fit, _send, thinned
from .form import WHERE_PRESENT, value_at

LOST_MOTION_ROWS = ("valve_lift_mm", "valve_closes_crank_deg", "seating_velocity_m_s", "max_brake_pressure_MPa")
"""The table's figures of each solenoid timing of a lost-motion drive (keys of its record's closings)."""

SWITCHING_ROWS = ("jump_speed_rpm", "over_speed_rpm", "valve_force_unlatched_N", "valve_spring_preload_N",
                  "arm_frequency_Hz", "spring_stress_max_MPa", "latch_stress_max_MPa")
"""The table's figures of a switching finger besides its modes' lifts (keys of its record)."""


def has_vva(document, names) -> bool:
    """Whether a valve of the document has a lost-motion drive or a switching finger."""
    return any(isinstance(value_at(document, p.format(n)), dict) for n in names for p in WHERE_PRESENT)


class VvaPanel:
    """The variable valve actuation of a :class:`~valvetrain.web.app.Designer`: built where the document has it,
    drawn with the checks (the good design's)."""

    def _vva_build(self, tools):
        """The panel's plot and table in a row, or None where no valve has a lost-motion drive or a switching
        finger (``self.vva`` the plot's source, None then)."""
        self.vva, self.vva_of = None, None
        if not has_vva(self.session.document, self.names):
            return None
        self.vva = ColumnDataSource({"xs": [], "ys": [], "colour": [], "dash": [], "label": []}, name="vva")
        p = figure(tools=tools, name="plot-vva", height=230, width=PLOT_WIDTH, x_range=Range1d(0, 1),
                   y_range=Range1d(0, 1))
        p.multi_line("xs", "ys", source=self.vva, line_color="colour", line_dash="dash", line_width=1.5,
                     legend_field="label")
        p.legend.location = "top_right"
        p.legend.label_text_font_size = "10px"
        p.legend.spacing = 0
        p.legend.padding = 4
        p.toolbar.logo = None
        self.figures["vva"] = p
        self.vva_rows = ColumnDataSource({"item": [], "quantity": [], "value": []}, name="vva-rows")
        self.vva_columns = [TableColumn(field="item", title="", width=190),
                            TableColumn(field="quantity", title="", width=250),
                            TableColumn(field="value", title="", width=70)]
        self.vva_table = DataTable(source=self.vva_rows, columns=self.vva_columns, width=520, height=230,
                                   index_position=None, autosize_mode="none", row_height=22, name="vva-table")
        return [p, self.vva_table]

    def _vva(self):
        """Draw the good design's variable valve actuation (nothing where the page has no such panel)."""
        good = self.session.good
        if self.vva is None or self.vva_of == (good, self.lang, self.units):
            return
        self.vva_of = (good, self.lang, self.units)
        results, series = good["results"], good["series"]
        t, w, names = TEXT[self.lang], WORDS[self.lang], catalogue(self.lang)["switching"]["names"]
        mm = self.units.mm
        lines = {k: [] for k in self.vva.data}
        rows = {k: [] for k in self.vva_rows.data}

        def line(x, y, label, dash="solid"):
            x, y = thinned(np.asarray(x, dtype=float), mm * _array(y))
            lines["xs"].append(x)
            lines["ys"].append(y)
            lines["colour"].append(Category10_10[(len(lines["xs"]) - 1) % 10])
            lines["dash"].append(dash)
            lines["label"].append(label)

        def row(item, quantity, value):
            rows["item"].append(item)
            rows["quantity"].append(quantity)
            rows["value"].append("" if value is None else f"{value:.4g}")

        for name in self.names:
            lost = results["valves"][name].get("lost_motion")
            if lost is not None:
                s = series[name]
                for at, lift in zip(s["lost_motion_opens_crank_deg"], s["lost_motion_valve_lift_mm"], strict=True):
                    label = f"{name}: " + (t["lm_full"] if at is None else t["lm_at"].format(at=f"{at:g}"))
                    line(s["lost_motion_crank_deg"], lift, label, "dashed" if at is None else "solid")
                full = {k: lost[f"full_lift_{k}"] for k in LOST_MOTION_ROWS if f"full_lift_{k}" in lost}
                for label, record in [(t["lm_full"], full)] + [
                        (t["lm_at"].format(at=f"{c['solenoid_opens_crank_deg']:g}"), c) for c in lost["closings"]]:
                    for key in LOST_MOTION_ROWS:
                        if key in record:
                            row(f"{name}: {label}", t["lm_names"][key], record[key])
            switching = (results.get("switching") or {}).get(name)
            if switching is not None:
                s = series[name]
                line(s["crank_deg"], s["valve_lift_mm"], f"{name}: {w['vva_latched']}")
                line(s["crank_deg"], np.full(len(s["crank_deg"]), switching["unlatched_valve_lift_mm"]),
                     f"{name}: {w['vva_unlatched']}", "dashed")
                row(f"{name}: {w['vva_latched']}", names["latched_valve_lift_mm"], switching["latched_valve_lift_mm"])
                row(f"{name}: {w['vva_unlatched']}", names["unlatched_valve_lift_mm"],
                    switching["unlatched_valve_lift_mm"])
                for key in SWITCHING_ROWS:
                    row(f"{name}: {w['vva_unlatched']}", names[key], switching.get(key))
        self.vva.data = lines
        _send(self.vva_rows, rows)
        p = self.figures["vva"]
        _fit(p.x_range, lines["xs"], 0.0)
        _fit(p.y_range, lines["ys"], PLOT_ROOM)
        p.xaxis.axis_label = t["lm_crank"]
        p.yaxis.axis_label = f"{w['lift_mm'].split(',')[0]}, {w[f'unit_{self.units.length}']}"
        self.vva_columns[1].title = t["quantity"]
        self.vva_columns[2].title = t["value"]
