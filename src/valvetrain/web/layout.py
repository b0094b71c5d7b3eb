"""The designer's page built: the command bar, the specification panel, the plots with their handles, the tabs, the
checks and the cam card, the stamps that time a redraw in the page, and their words in the page's language.
"""

from functools import partial
import json

from bokeh.layouts import column, row
from bokeh.models import (Button, ColorBar, ColumnDataSource, CustomJS, DataTable, Div, Dropdown, FileInput,
                          HTMLTemplateFormatter, InlineStyleSheet, Label, LinearAxis, LinearColorMapper, NumericInput,
                          Range1d, Select, Slider, TableColumn, TabPanel, Tabs, TextInput)
from bokeh.plotting import figure
import numpy as np

from ..languages import LANGS
from ..report.i18n import TEXT
from ..report.names import label, value_text as value_name
from .draw import (BAR_CSS, CURVES, DOWNLOAD_JS, DRAWN_JS, INPUT_CSS, KINEMATIC_PLOTS, PAGE_JS, PAINTED_JS, PANEL_WIDTH,
                   PLOT_WIDTH, PLOTS, SAME_STYLE_JS, STAMP_JS, TABS_JS, WIDTH, WORDS, _held, _rows_follow, _stamp)
from .form import GROUPS, form, value_at, value_text


class Layout:
    """The widgets and plots of a :class:`~valvetrain.web.app.Designer`, built once, and their words.

    Notes
    -----
    An input or a plot is changed in place, never built again while it shows the same thing: BokehJS drops the models
    that left the document only 30 s after the last new one came, so a panel built again (for another language) left
    its old inputs in the page beside the new ones, and a look-up of an input by its name found two.
    """

    def _title(self, f):
        """The name of a field's input with its unit and range, in the page's language."""
        bounds = f" ({f.low:g} … {f.high:g})" if f.low is not None and f.high is not None else ""
        return label(f.name, self.lang) + bounds

    def _widget(self, f, kept=None):
        """The input of a field of the panel: its name with its unit and range in the page's language, the key in
        its description (a hover on its mark); ``kept``, the field and input the key had before (a law changed),
        kept when they take the same values."""
        if kept is not None and _same_input(kept[0], f):
            self.fields[f.path], self.widgets[f.path] = kept
            return kept[1]
        common = {"title": self._title(f), "stylesheets": [self.input_css], "description": f.path,
                  "width": PANEL_WIDTH - 40, "name": f.path}
        if f.kind in ("float", "int"):
            w = NumericInput(value=f.value, mode=f.kind, **common)
        elif f.kind == "choice":
            w = Select(value="" if f.value is None else str(f.value), options=self._options(f), **common)
        else:
            w = TextInput(value=value_text(f.value), **common)
        w.on_change("value", partial(self.on_field, f))
        self.fields[f.path], self.widgets[f.path] = f, w
        return w

    def _panel(self) -> Tabs:
        """The specification panel in the page's language: a tab per group
        (:data:`~valvetrain.web.form.GROUPS`), in each the inputs of every valve, those of the valve shown
        visible; its words set again for another language (:meth:`_retitle`)."""
        document = self.session.document
        self.group_columns, self.fields, self.widgets = {}, {}, {}
        self.laws = {valve: value_at(document, f"valves.{valve}.cam.law") for valve in self.names}
        tabs, self.tab_groups = [], []
        for group, _ in GROUPS:
            if group != "engine" and not self.names:
                continue
            parts = []
            valves = [None] if group == "engine" else self.names
            shown = {valve: dict(form(document, valve)).get(group, []) for valve in valves}
            if not any(shown.values()):            # a group of sections where present (form.WHERE_PRESENT): none
                continue
            for valve in valves:
                fields = shown[valve]
                box = column(*[self._widget(f) for f in fields], visible=valve in (None, self.valve),
                             width=PANEL_WIDTH - 30)
                self.group_columns[(group, valve)] = box
                parts.append(box)
            self.tab_groups.append(group)
            tabs.append(TabPanel(title=WORDS[self.lang][f"group_{group}"],
                                 child=column(*parts, height=740, width=PANEL_WIDTH - 10,
                                              styles={"overflow-y": "auto", "overflow-x": "hidden"})))
        self.spec_tabs = Tabs(tabs=tabs, width=PANEL_WIDTH, name="panel")
        return self.spec_tabs

    def _options(self, f) -> list[tuple[str, str]]:
        """The options of a choice field, each its value in the file and its name in the page's language (the
        catalogue's ``[values]``: ``("pushrod", "со штангой и коромыслом")``); an optional key's first, empty."""
        return ([("", "")] if f.optional else []) + [(str(o), value_name(str(o), self.lang)) for o in f.options]

    def _retitle(self):
        """The panel's words in the page's language: each input's name, a choice's options and each tab's name, set
        in place."""
        for path, w in self.widgets.items():
            w.title = self._title(self.fields[path])
            if self.fields[path].kind == "choice":
                w.options = self._options(self.fields[path])
        for tab, group in zip(self.spec_tabs.tabs, self.tab_groups, strict=True):
            tab.title = WORDS[self.lang][f"group_{group}"]

    def _build(self):
        t = WORDS["en"]
        # one style sheet for every input of the panel, one for the bar's (a model of this document)
        self.input_css, self.bar_css = InlineStyleSheet(css=INPUT_CSS), InlineStyleSheet(css=BAR_CSS)
        self.language = Select(value="en", options=[(lang, WORDS[lang]["language"]) for lang in LANGS],
                               name="language", width=95, stylesheets=[self.bar_css])
        self.language.on_change("value", self.on_language)
        self.valve_select = Select(value=self.valve or "", options=self.names, width=140, name="valve",
                                   stylesheets=[self.bar_css], visible=bool(self.names))
        self.valve_select.on_change("value", self.on_valve)
        self.length_select = Select(value="mm", width=70, name="length", stylesheets=[self.bar_css])
        self.angle_select = Select(value="cam", width=170, name="angle", stylesheets=[self.bar_css])
        self.derivative_select = Select(value="rated", width=200, name="derivative", stylesheets=[self.bar_css])
        for w in (self.length_select, self.angle_select, self.derivative_select):
            w.on_change("value", self.on_units)
        self.buttons = {}
        for key, handler in (("undo", self.on_undo), ("redo", self.on_redo), ("pin", self.on_pin)):
            b = Button(label=t[key], name=f"button-{key}", width=len(t[key]) * 7 + 30, height=28)
            b.on_click(handler)
            self.buttons[key] = b
        self.download = Dropdown(label=t["download"], name="download", width=110, height=28,
                                 menu=[(t[k], k) for k in ("toml", "dxf", "report")])
        self.download.on_click(self.on_download)
        self.downloaded = {}
        for key, mime, name, binary in (("toml", "application/toml", "valvetrain.toml", False),
                                        ("dxf", "image/vnd.dxf", "cam.dxf", True),
                                        ("report", "text/html", "report.html", False)):
            div = Div(text="", visible=False)
            div.js_on_change("text", CustomJS(args={"div": div, "mime": mime, "name": name, "binary": binary},
                                              code=DOWNLOAD_JS))
            self.downloaded[key] = div
        self.overlay = FileInput(accept=".toml", width=210, name="overlay", stylesheets=[self.bar_css])
        self.overlay.on_change("value", self.on_overlay)
        self.status = Div(text="", name="status", styles={"color": "#b00020", "font-size": "12px"},
                          width=PANEL_WIDTH - 10)
        self.panel_box = column(self.status, self._panel())

        tools = "pan,wheel_zoom,box_zoom,reset,save"
        empty = {k: [] for k in ("x", "curvature", "curvature_limit", "spring_x", "spring_y", "spring_line_x",
                                 "spring_line_y", "contour_x", "contour_y", *CURVES, *(p[0] for p in KINEMATIC_PLOTS))}
        self.curves, self.base_curves = (ColumnDataSource(empty, name="curves"),
                                         ColumnDataSource(empty, name="base-curves"))
        self.figures = {}
        big = {"height": 250, "width": PLOT_WIDTH}
        for name, *_ in KINEMATIC_PLOTS:
            self.figures[name] = self._plot(figure(tools=tools, name=f"plot-{name}", x_range=Range1d(0, 1),
                                                   y_range=Range1d(0, 1), **big), name)
        for name in ("velocity", "jerk"):
            self.figures[name].height = 230
        self.figures["lift"].line("x", "tappet", source=self.curves, color="#2ca02c", line_width=1)
        self.segments = ColumnDataSource({"x": [], "y0": [], "y1": []})
        self.figures["acceleration"].segment("x", "y0", "x", "y1", source=self.segments, color="#bbbbbb",
                                             line_dash="dotted")
        self.handles, self.limits = {}, {}
        for plot in ("lift", "acceleration"):
            src = ColumnDataSource({k: [] for k in ("x", "y", "name", "x_lo", "x_hi", "y_lo", "y_hi")},
                                   name=f"handles-{plot}")
            lim = ColumnDataSource({k: [np.nan, np.nan] for k in ("x0", "y0", "x1", "y1", "sx", "sy")},
                                   name=f"limits-{plot}")
            fig = self.figures[plot]
            fig.segment("x0", "y0", "x1", "y1", source=lim, color="#d62728", line_width=3, line_alpha=0.35)
            fig.scatter("sx", "sy", source=lim, size=19, fill_alpha=0.0, line_color="#d62728", line_width=2)
            fig.scatter("x", "y", source=src, size=13, color="#d62728", marker="circle")
            self.handles[plot], self.limits[plot] = src, lim
        for name in ("lift", "velocity", "acceleration"):
            self.figures[name].x_range = self.figures["jerk"].x_range
        self.request = ColumnDataSource({k: [] for k in ("kind", "seq", "plot", "name", "x", "y", "text")},
                                        name="request")
        self.request.on_change("data", self.on_request)
        self.options = ColumnDataSource({"add": [False]}, name="options")
        self.saved = ColumnDataSource({"document": [json.dumps(self.session.document)]}, name="saved")

        self.figures["contour"] = self._plot(figure(height=230, width=230, tools=tools, name="plot-contour",
                                                    match_aspect=True), "contour")
        for name in ("curvature", "time_area", "spring"):
            self.figures[name] = self._plot(figure(height=230, width=PLOT_WIDTH if name != "curvature" else 790,
                                                   tools=tools, name=f"plot-{name}", x_range=Range1d(0, 1),
                                                   y_range=Range1d(0, 1)), name)
        self.figures["curvature"].x_range = self.figures["jerk"].x_range
        self.heel = ColumnDataSource({"x": [], "y": []})
        self.figures["contour"].line("x", "y", source=self.heel, color="#2ca02c", line_dash="dashed")
        self.figures["curvature"].line("x", "curvature_limit", source=self.curves, color="#b00020", line_dash="dashed")
        self.figures["spring"].line("spring_line_x", "spring_line_y", source=self.curves, color="black", line_width=2)
        ta = self.figures["time_area"]
        ta.line("crank_x", "curtain", source=self.curves, color="#ff7f0e", y_range_name="curtain")
        ta.extra_y_ranges = {"curtain": Range1d(0, 1)}
        # the fullness in the plot, not in its title: a title's new text lays the plot out again
        self.fullness = Label(x=0, y=0, text="", text_font_size="11px", text_baseline="top")
        ta.add_layout(self.fullness)
        f = self.figures
        self.ranges = {"x": f["jerk"].x_range, "crank_x": ta.x_range, "spring_x": f["spring"].x_range,
                       "curtain": ta.extra_y_ranges["curtain"],
                       **{name: f[name].y_range for name in ("lift", "velocity", "acceleration", "jerk", "curvature",
                                                             "time_area", "spring")}}
        self.curtain_axis = LinearAxis(y_range_name="curtain", axis_label_text_color="#ff7f0e")
        ta.add_layout(self.curtain_axis, "right")

        self.checks = ColumnDataSource({k: [] for k in ("key", "status", "quantity", "value", "allowed", "margin",
                                                        "source", "colour", "baseline")})
        fmt = HTMLTemplateFormatter(template='<div style="background:<%= colour %>; padding-left:3px"><%= value %></div>')
        self.check_columns = [TableColumn(field="status", title="", formatter=fmt, width=95),
                              TableColumn(field="quantity", title="", width=270),
                              TableColumn(field="value", title="", width=95),
                              TableColumn(field="baseline", title="", width=80),
                              TableColumn(field="allowed", title="", width=105),
                              TableColumn(field="margin", title="", width=55),
                              TableColumn(field="source", title="", width=300)]
        # the columns keep their widths: fitted to the table (autosized), they would be measured again on every change
        # of the rows
        self.table = DataTable(source=self.checks, columns=self.check_columns, width=WIDTH - PANEL_WIDTH - 330,
                               height=300, index_position=None, name="checks", autosize_mode="none", row_height=22)
        _rows_follow(self.table)
        # the cam card is a table: new rows leave the page's layout (a Div's new text lays the page out again)
        self.card = ColumnDataSource({k: [] for k in ("quantity", *self.names)}, name="card")
        self.card_columns = [TableColumn(field="quantity", title="", width=180)] + [
            TableColumn(field=n, title=n, width=max(60, 130 // max(1, len(self.names)))) for n in self.names]
        self.card_table = DataTable(source=self.card, columns=self.card_columns, width=320, height=300,
                                    index_position=None, autosize_mode="none", row_height=22, name="card-table")
        _rows_follow(self.card_table)

        # the dynamics at speed
        # the sweep's state inside its plot, not in a title: a title's new text lays the plot out again
        self.sweep_status = Label(x=6, y=6, x_units="screen", y_units="screen", text="", name="sweep-status",
                                  text_font_size="11px", background_fill_color="white", background_fill_alpha=0.8)
        self.sweep_sources = {k: ColumnDataSource({"x": [], "y": []}, name=f"sweep-{k}") for k in ("force", "seating")}
        self.base_sweep_sources = {k: ColumnDataSource({"x": [], "y": []}) for k in ("force", "seating")}
        self.sweep_marks = {k: ColumnDataSource({"x": [], "y0": [], "y1": []}) for k in ("force", "seating")}
        for key in ("force", "seating"):
            p = figure(tools=tools, name=f"plot-sweep-{key}", height=200, width=245, x_range=Range1d(0, 1),
                       y_range=Range1d(0, 1))
            p.line("x", "y", source=self.base_sweep_sources[key], color="#999999", line_dash="dashed", line_width=1.5)
            p.line("x", "y", source=self.sweep_sources[key], color="#1f77b4", line_width=2)
            p.segment("x", "y0", "x", "y1", source=self.sweep_marks[key], color="#d62728", line_dash="dashed")
            self.figures["sweep_" + key] = p
        self.figures["sweep_force"].add_layout(self.sweep_status)
        self.map_source = ColumnDataSource({"image": [], "x": [], "y": [], "dw": [], "dh": []}, name="sweep-map")
        self.mapper = LinearColorMapper(palette="RdBu11", low=-1.0, high=1.0)
        p = figure(tools=tools, name="plot-sweep-map", height=200, width=285, x_range=Range1d(0, 1),
                   y_range=Range1d(0, 1))
        p.image("image", x="x", y="y", dw="dw", dh="dh", source=self.map_source, color_mapper=self.mapper)
        p.xaxis.ticker.desired_num_ticks = 4
        self.colour_bar = ColorBar(color_mapper=self.mapper, width=10, name="map-colour-bar", label_standoff=4,
                                   major_label_text_font_size="10px")
        p.add_layout(self.colour_bar, "right")
        self.figures["sweep_map"] = p
        self.at_speed = ColumnDataSource({"x": [], "force": [], "acceleration": [], "rigid": []}, name="at-speed")
        p = figure(tools=tools, name="plot-at-speed", height=200, width=265, x_range=Range1d(-1, 1),
                   y_range=Range1d(0, 1))
        p.line("x", "force", source=self.at_speed, color="#1f77b4", line_width=2)
        p.extra_y_ranges = {"acceleration": Range1d(-1, 1)}
        p.line("x", "rigid", source=self.at_speed, color="#999999", line_dash="dashed", y_range_name="acceleration")
        p.line("x", "acceleration", source=self.at_speed, color="#ff7f0e", y_range_name="acceleration")
        p.xaxis.ticker.desired_num_ticks = 4
        self.acceleration_axis = LinearAxis(y_range_name="acceleration", axis_label_text_color="#ff7f0e")
        p.add_layout(self.acceleration_axis, "right")
        self.figures["at_speed"] = p
        # the breathing: the volumetric efficiency (and the torque, fired) against the speed, redrawn with the checks
        self.breathing = {k: ColumnDataSource({"speed": [], "ve": [], "torque": []}, name=f"breathing-{k}")
                          for k in ("curve", "conditions", "phased")}
        p = figure(tools=tools, name="plot-breathing", height=230, width=PLOT_WIDTH, x_range=Range1d(0, 1),
                   y_range=Range1d(0, 1))
        p.extra_y_ranges = {"torque": Range1d(0, 1)}
        p.line("speed", "ve", source=self.breathing["curve"], color="#1f77b4", line_width=2)
        p.scatter("speed", "ve", source=self.breathing["conditions"], color="#1f77b4", size=8)
        p.line("speed", "torque", source=self.breathing["curve"], color="#ff7f0e", y_range_name="torque")
        p.scatter("speed", "torque", source=self.breathing["conditions"], color="#ff7f0e", size=8, marker="square",
                  y_range_name="torque")
        # a cam phaser's best phase at each condition: the breathing there, hollow marks over the phase-0 points
        p.scatter("speed", "ve", source=self.breathing["phased"], line_color="#1f77b4", fill_color=None, size=14,
                  marker="diamond", line_width=2)
        p.scatter("speed", "torque", source=self.breathing["phased"], line_color="#ff7f0e", fill_color=None, size=14,
                  marker="diamond", line_width=2, y_range_name="torque")
        self.torque_axis = LinearAxis(y_range_name="torque", axis_label_text_color="#ff7f0e")
        p.add_layout(self.torque_axis, "right")
        self.breathing_status = Label(x=6, y=6, x_units="screen", y_units="screen", text="", name="breathing-status",
                                      text_font_size="11px", background_fill_color="white", background_fill_alpha=0.8)
        p.add_layout(self.breathing_status)
        self.figures["breathing"] = p
        vva = self._vva_build(tools)
        self.speed = Slider(start=0, end=1, value=0, step=1, width=1020, name="speed", visible=False)
        self.speed.on_change("value_throttled", self.on_speed)

        # the stamps are data sources, not widgets: a widget's change lays the whole page out again (~100 ms)
        self.kinematic_stamp = _stamp("kinematic-stamp")
        self.kinematic_hold = _held([self.figures[k] for k in PLOTS], self.kinematic_stamp, "vtPausedKinematics")
        self.kinematic_stamp.js_on_change("data", CustomJS(args={"key": "vtTimes", "plots": [
            self.figures[k] for k in ("lift", "acceleration")]}, code=STAMP_JS))
        # the page says when it has drawn the kinematics of a design kept: its sweep starts then
        self.drawn = ColumnDataSource({"n": [0]}, name="drawn")
        self.drawn.on_change("data", self.on_drawn)
        self.kinematic_stamp.js_on_change("data", CustomJS(args={"stamp": self.kinematic_stamp, "drawn": self.drawn},
                                                           code=DRAWN_JS))
        # the checks, card and panel of a design kept: with the curves, or after them (a drag released)
        self.checks_stamp = _stamp("checks-stamp")
        self.checks_stamp.js_on_change("data", CustomJS(args={"key": "vtChecksTimes", "plots": []}, code=STAMP_JS))
        self.sweep_stamp = _stamp("sweep-stamp")
        self.sweep_hold = _held([self.figures[k] for k in ("sweep_force", "sweep_seating", "sweep_map", "at_speed")],
                                self.sweep_stamp, "vtPausedSweep")
        self.sweep_stamp.js_on_change("data", CustomJS(args={"key": "vtSweepTimes", "plots": [
            self.figures[k] for k in ("sweep_force", "sweep_seating", "sweep_map", "at_speed")]}, code=STAMP_JS))

        f = self.figures
        self.plot_tabs = Tabs(name="plots", width=WIDTH - PANEL_WIDTH - 10, active=3, tabs=[
            TabPanel(title="", child=row(f["velocity"], f["jerk"])),
            TabPanel(title="", child=row(f["contour"], f["curvature"])),
            TabPanel(title="", child=row(f["time_area"], f["spring"])),
            TabPanel(title="", child=column(self.speed, row(f["sweep_force"], f["sweep_seating"], f["sweep_map"],
                                                            f["at_speed"]))),
            TabPanel(title="", child=row(f["breathing"])),
            *([TabPanel(title="", child=row(*vva))] if vva is not None else [])])
        bar = row(self.valve_select, self.length_select, self.angle_select, self.derivative_select,
                  *self.buttons.values(), self.overlay, self.download, self.language, width=WIDTH, height=34)
        main = column(row(f["lift"], f["acceleration"]), self.plot_tabs, row(self.table, self.card_table))
        with self.doc.models.freeze():          # the document's models collected once, not once per root
            self._add_roots(bar, main)

    def _add_roots(self, bar, main):
        f = self.figures
        # the bar a root of its own: nested one level deeper, the plots of the tabs were laid out with no size
        # (Bokeh 3.9: a column holding a row holding a column of plots and tabs)
        self.doc.add_root(bar)
        self.doc.add_root(row(self.panel_box, main, name="page"))
        self.doc.js_on_event("document_ready", CustomJS(code=SAME_STYLE_JS))
        self.doc.js_on_event("document_ready", CustomJS(code=PAINTED_JS))
        # the first design drawn: its sweep starts
        self.doc.js_on_event("document_ready", CustomJS(args={"stamp": self.kinematic_stamp, "drawn": self.drawn},
                                                        code=DRAWN_JS))
        self.doc.js_on_event("document_ready", CustomJS(
            args={"plots": {k: f[k] for k in self.handles}, "sources": self.handles, "limits": self.limits,
                  "options": self.options, "request": self.request, "saved": self.saved, "key": self.key},
            code=PAGE_JS))
        tabs = CustomJS(args={"tabs": self.plot_tabs, "plots": [[p for p in panel.select({"type": figure})]
                                                                 for panel in self.plot_tabs.tabs]}, code=TABS_JS)
        self.doc.js_on_event("document_ready", tabs)
        self.plot_tabs.js_on_change("active", tabs)
        for model in (*self.downloaded.values(), self.kinematic_stamp, self.checks_stamp, self.sweep_stamp, self.drawn, self.kinematic_hold,
                      self.sweep_hold, self.request, self.options, self.saved):
            self.doc.add_root(model)

    def _plot(self, p, name):
        """Plot ``name`` on figure ``p``: the baseline dashed under the current design."""
        x, y = PLOTS[name]
        p.line(x, y, source=self.base_curves, color="#999999", line_dash="dashed", line_width=1.5)
        p.line(x, y, source=self.curves, color="#1f77b4", line_width=2)
        p.toolbar.logo = None
        return p

    def _texts(self):
        t, w = TEXT[self.lang], WORDS[self.lang]
        u = self.units
        length, angle = w[f"unit_{u.length}"], w[f"unit_{u.angle}"]
        orders = {1: "", 2: "²", 3: "³"}
        derivative = {name: (w[f"{name}_valve"] if u.derivative == "rated" else
                             f"{w[f'{name}_valve'].split(',')[0]}, {length}/{angle}{orders[order]}")
                      for name, _, order in KINEMATIC_PLOTS[1:]}
        axes = {"lift": f"{w['lift_mm'].split(',')[0]}, {length}", **derivative}
        x_axis = w[f"angle_{u.angle}"]
        for name, words in axes.items():
            self.figures[name].yaxis.axis_label = words
            self.figures[name].xaxis.axis_label = x_axis
        self.figures["contour"].title.text = t["contour"]
        self.figures["curvature"].yaxis.axis_label = f"{w['curvature']}, 1/{length}"
        self.figures["curvature"].xaxis.axis_label = x_axis
        self.figures["time_area"].xaxis.axis_label = t["crank_deg"]
        self.figures["time_area"].yaxis.axis_label = t["running_ta"]
        self.curtain_axis.axis_label = t["curtain"]
        self.figures["spring"].xaxis.axis_label = f"{w['lift_mm'].split(',')[0]}, {length}"
        self.figures["spring"].yaxis.axis_label = t["force"]
        self.figures["sweep_force"].yaxis.axis_label = w["min_force"]
        self.figures["sweep_seating"].yaxis.axis_label = w["seating"]
        self.figures["sweep_map"].title.text = w["map"]
        for key in ("sweep_force", "sweep_seating", "sweep_map"):
            self.figures[key].xaxis.axis_label = t["speed"] if key != "sweep_map" else t["cam_deg"]
        self.figures["sweep_map"].yaxis.axis_label = t["speed"]
        self.figures["at_speed"].xaxis.axis_label = t["cam_deg"]
        self.figures["at_speed"].yaxis.axis_label = w["contact_force"]
        self.acceleration_axis.axis_label = w["acceleration_valve"]
        self.speed.title = w["speed"]
        self.figures["breathing"].xaxis.axis_label = t["speed"]
        self.figures["breathing"].yaxis.axis_label = w["volumetric_efficiency"]
        self.torque_axis.axis_label = w["torque"]
        for panel, key in zip(self.plot_tabs.tabs, ("tab_derivatives", "tab_cam", "tab_flow", "tab_speed",
                                                    "tab_breathing", "tab_vva")[:len(self.plot_tabs.tabs)],
                              strict=True):
            panel.title = w[key]
        for c, key in zip(self.check_columns, ("status", "quantity", "value", "baseline", "allowed", "margin", "source"),
                          strict=True):
            c.title = {"status": w["status"], "value": t["value"] + f" ({w['current']})", "baseline": w["baseline"],
                       "margin": w["margin"]}.get(key) or t[key]
        self.card_columns[0].title = t["cam_card"]
        self.valve_select.title = w["valve"]
        self.length_select.options = [("mm", w["unit_mm"]), ("in", w["unit_in"])]
        self.angle_select.options = [("cam", w["angle_cam"]), ("crank", w["angle_crank"])]
        self.derivative_select.options = [("rated", w["rated"]), ("deg", w["deg"])]
        for key, b in self.buttons.items():
            b.label = w[key]
        self.download.label = w["download"]
        self.download.menu = [(w[k], k) for k in ("toml", "dxf", "report")]
        self.overlay.title = w["overlay"]


def _same_input(old, new) -> bool:
    """Whether an input made for field ``old`` takes the values of field ``new`` (the same key, kind, bounds, unit
    and options): its value alone may differ."""
    keys = ("path", "kind", "low", "high", "unit", "options", "optional")
    return all(getattr(old, k) == getattr(new, k) for k in keys)
