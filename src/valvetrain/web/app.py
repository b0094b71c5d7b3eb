"""The page of the designer: a Bokeh document per browser tab, on a :class:`~valvetrain.web.session.Session`.

The page fits 1400 x 900 px: a bar of commands on top; on the left the specification panel, generated from the
specification's models (:func:`valvetrain.web.form.form`) and grouped as a designer thinks (engine, valve, cam,
spring, drive, dynamics), each input with its name, unit and range; on the right the lift and the acceleration with
their handles, below them the other plots in tabs (velocity and jerk; contour and curvature; time-area and spring;
the dynamics at speed; the breathing's volumetric efficiency against the speed), and at the bottom the checks and
the cam card.

The handles are dragged by the page's own script (``page.js``): one to one with the pointer within their limits,
which the selected handle shows; while the pointer moves, the server works out the kinematics of the handle's
valve at its newest position (one request at a time) and the curves follow; the release draws them at once and
keeps the design when its worker thread has designed it (springs, checks, breathing: an edit that can be undone;
the spring plot is empty until then, the spring being the design's), arrow keys nudge the selected handle, Ctrl-Z
and Ctrl-Y undo and redo.  The plots of the tabs not shown hold their painting until their tab is chosen.  The
speed sweep of a design kept runs in a worker thread and only the newest one is drawn (an older one is stopped at
its next speed).

The page keeps its timings: ``window.vtTimes`` (the release of a drag, a key or an undo to the end of the frame that
painted its curves, ms: :data:`~valvetrain.web.draw.STAMP_JS`), ``window.vtChecksTimes`` (to the frame that shows
its checks, card and panel), ``window.vtSweepTimes`` (to the frame that painted the sweep panel),
``window.vtTimesArrived`` (to the arrival of the redraw), ``window.vtTimesFrames`` (the frames the probe waited for
the paint), ``window.vtMoveTimes`` (a move of the pointer sent to the frame that painted the curves it brought);
``window.vtTimesDone``, ``window.vtSweepTimesDone`` count the redraws painted.

The page is built by :mod:`valvetrain.web.layout`, drawn with the pieces of :mod:`valvetrain.web.draw` (words,
columns, ranges, scripts, units); its sweep panel is :mod:`valvetrain.web.sweep`'s, its panel of variable valve
actuation (a lost-motion drive, a switching finger: where the specification has them) :mod:`valvetrain.web.vva`'s.
"""

import base64
from concurrent.futures import ThreadPoolExecutor
from functools import partial
import hashlib
import json

from bokeh.core.property.descriptors import UnsetValueError
from bokeh.models import BasicTickFormatter, ColorBar, CustomJSTickFormatter, LinearAxis, NumericInput, Select
import numpy as np

from ..locale import number_text
from ..report.html import check_range
from ..report.i18n import TEXT
from ..report.names import label, record_quantity_text, translate
from ..report.russian import citation
from ..specification import SpecError, toml_tables
from ..units import symbol as unit_symbol
from .draw import (AXIS_NUMBERS_JS, CURVES, EVENTS, KINEMATIC_PLOTS, PLOT_BUCKETS, PLOT_ROOM, RANGES, SEVERITY_COLOURS,
                   STATUS_WORDS, VALVE_CARD, WORDS, Units, _array, _count, _fit, _hold, _now, _send, problem_text, thinned)
from .form import form, parse_value, value_at, value_of, value_text
from .layout import Layout
from .session import document_key, has_points
from .sweep import SweepPanel
from .vva import VvaPanel

DESIGN_WORKERS = ThreadPoolExecutor(max_workers=1, thread_name_prefix="valvetrain-design")
"""One thread for the designs of the drags released (their springs, checks and breathing), beside the sweeps': the
page's answer to the release (the valve's kinematics) and to the next move does not wait for them."""


class Designer(Layout, SweepPanel, VvaPanel):
    """The widgets, plots and callbacks of one browser tab."""

    def __init__(self, doc, session, key=""):
        self.doc, self.session, self.lang = doc, session, "en"
        self.names = list(session.document.get("valves") or {})
        self.valve = self.names[0] if self.names else None
        self.units = Units()
        self.generation = 0
        self._syncing = False
        self.downloads = 0
        self.sweeps, self.base_sweeps = {}, None        # the valves' sweep series drawn, the baseline's
        self.sweep_due = False
        self.sweep_seq = 0
        self.sweep_key = None            # the document whose sweep was started last (document_key)
        self.shown = None                # a drag's preview drawn: (document, result), else the good design
        self.pending = None              # the design of a drag released, in the worker: (future, keys set, seq)
        self.fields, self.widgets = {}, {}
        self.refused_paths = set()
        self.key = key
        self.changes = 0                 # the document's changes made (a redraw's: did it change anything?)
        self._build()
        doc.on_change(self._changed)
        self._texts()
        self.redraw(sweep=bool(self.names))
        self.show_problems()

    # --- drawing ---------------------------------------------------------------------------------------------------
    def _changed(self, event) -> None:
        self.changes += 1

    def _shown(self):
        """The document and the design drawn: a drag's preview while the pointer moves, else the good design."""
        return self.shown or (self.session.document, self.session.good)

    def _omega(self, result):
        return result["results"]["valves"][self.valve]["cam"]["camshaft_speed_rad_s"]

    def _curves(self, result) -> dict:
        """The columns of a design's curves in the units shown, NaN-padded to one length, as 32-bit floats (7 digits:
        more than a plot shows, half the bytes to send); the spring's required force thinned (:func:`thinned`), the
        contour to about as many points as the other curves (every k-th point, closed), the curvature 1/rho with its
        limit, 1/rho_min of the check of the smallest convex radius."""
        series, omega, u = result["series"][self.valve], self._omega(result), self.units
        xs, x0 = u.of(series, omega)
        out = {"x": xs * _array(series["cam_deg"]) + x0, **{key: _array(series[name]) for key, name in CURVES.items()}}
        for name, key, order in KINEMATIC_PLOTS:
            out[name] = u.of(series, omega, order)[0] * _array(series[key])
        with np.errstate(divide="ignore"):
            out["curvature"] = 1.0 / (u.mm * _array(series["rho_mm"]))
        limit = next((c["low"] for c in result["results"]["checks"] if c["code"] == "profile.rho_min"
                      and c["valve"] == self.valve and c["low"]), None)
        out["curvature_limit"] = np.full(len(out["x"]), np.nan if limit is None else 1.0 / (u.mm * limit))
        out["spring_x"], out["spring_y"] = thinned(u.mm * _array(series["spring_lift_mm"]),
                                                   _array(series["required_force_N"]))
        out["spring_line_x"] = u.mm * _array(series["spring_line_lift_mm"])
        out["spring_line_y"] = _array(series["spring_line_force_N"])
        step = -(-len(series["contour_x_mm"]) // (2 * PLOT_BUCKETS))
        for axis in ("x", "y"):
            contour = u.mm * _array(series[f"contour_{axis}_mm"])
            out[f"contour_{axis}"] = np.append(contour[::step], contour[0])
        n = max(len(v) for v in out.values())
        return {k: np.pad(v, (0, n - len(v)), constant_values=np.nan).astype(np.float32) for k, v in out.items()}

    def _ranges(self, with_base, live):
        """Each fixed range of the plots kept or fitted to the curves of the design and the baseline
        (:func:`kept_range`; ``live``: a drag's preview, the handle kept under the pointer); a range changed only
        when it moves (a change lays its plot out again)."""
        for key, (names, room) in RANGES.items():
            _fit(self.ranges[key], [source.data[name] for source in (self.curves, self.base_curves)[:1 + with_base]
                                    for name in names], room, live)

    def redraw(self, sweep=True, began=None, seq=0, live=False, curves_seq=None) -> None:
        """Draw the design shown (and the baseline), its handles and, unless ``live`` (a drag's preview), its checks,
        card, panel and breathing; start its speed sweep (``sweep``) or draw the last one again.  ``began``:
        :func:`_now` when the change came (default now); ``seq`` the page's request it answers (the stamp of the
        curves and, unless ``live``, that of the checks); ``curves_seq`` the curves' stamp's instead (0: the curves
        of the request drawn before, :meth:`_release`)."""
        began = _now() if began is None else began
        _hold(self.kinematic_hold)
        before = self.changes
        try:
            if self.valve is not None:
                self._draw_valve(live)
            if not live:
                self._checks()
                self._card()
                self._breathing()
                self._vva()
                self._sync_fields()
                _send(self.saved, {"document": [json.dumps(self.session.document)]})
        finally:
            _count(self.kinematic_stamp, began, seq if curves_seq is None else curves_seq,
                   changed=self.changes > before)
        if live:
            return
        _count(self.checks_stamp, began, seq)
        if sweep and self.sweep_key == document_key(self.session.document):
            sweep = False                                 # its sweep started at the release (_launch)
        if sweep:
            self.sweeps = {}                              # the sweeps of the design before: drawn no more
        self.sweep_due = self.sweep_due or sweep          # a switch of language before the page drew keeps it due
        self.sweep_seq = seq if sweep else self.sweep_seq
        if self.sweeps or self.session.full is not None:
            self._sweep_panel()

    def _draw_valve(self, live):
        s = self.session
        document, result = self._shown()
        series = result["series"][self.valve]
        _send(self.curves, self._curves(result))
        phi = np.linspace(0.0, 2.0 * np.pi, 181)
        r = self.units.mm * series["heel_radius_mm"]
        _send(self.heel, {"x": r * np.cos(phi), "y": r * np.sin(phi)})
        base = s.baseline["series"].get(self.valve) if s.baseline else None
        if base is not None:
            _send(self.base_curves, self._curves(s.baseline))
        elif len(self.base_curves.data["x"]):
            self.base_curves.data = {k: [] for k in self.base_curves.data}
        self._ranges(base is not None, live)
        xs, x0 = self.units.of(series, self._omega(result))
        edges = xs * np.asarray(series["segments_cam_deg"]) + x0
        acc = self.ranges["acceleration"]
        _send(self.segments, {"x": edges, "y0": [acc.start] * len(edges), "y1": [acc.end] * len(edges)})
        ta = self.ranges["time_area"]
        self.fullness.update(x=self.ranges["crank_x"].start, y=ta.end - 0.02 * (ta.end - ta.start),
                             text=f"{TEXT[self.lang]['s_fullness']} "
                                  f"{result['results']['valves'][self.valve]['flow']['fullness']:.4g}")
        self._handles(document, result)

    def _handles(self, document, result):
        """The handles of the design shown in the units shown, with their limits (infinite: none)."""
        # the points of an inline lift table are added (a tap) and removed (selected, Delete) on the lift plot
        _send(self.options, {"add": [has_points(document["valves"][self.valve].get("cam", {}))]})
        series, omega = result["series"][self.valve], self._omega(result)
        xs, x0 = self.units.of(series, omega)
        for plot, src in self.handles.items():
            ys = self.units.of(series, omega, 0 if plot == "lift" else 2)[0]
            mine = [h for h in self.session.handles(self.valve, document, result) if h.plot == plot]
            _send(src, {"x": _array([xs * h.x + x0 for h in mine]), "y": _array([ys * h.y for h in mine]),
                        "name": [h.name for h in mine],
                        "x_lo": _array([xs * h.x_limits[0] + x0 for h in mine]),
                        "x_hi": _array([xs * h.x_limits[1] + x0 for h in mine]),
                        "y_lo": _array([ys * h.y_limits[0] for h in mine]),
                        "y_hi": _array([ys * h.y_limits[1] for h in mine])})

    def _checks(self):
        """The checks table: the whole design's checks when they have come, else the good design's and, pending, the
        ones of the last whole design that only the speed sweeps give; each row's status in words and colour."""
        s = self.session
        base = {c["quantity"]: c for c in (s.baseline or {"results": {"checks": []}})["results"]["checks"]}
        out = {k: [] for k in self.checks.data}
        for c in sorted(s.checked["checks"], key=lambda c: (c["pass"], c["accepted"],
                                                            {"failure": 0, "warning": 1}.get(c["severity"], 2),
                                                            c["margin"] if c["margin"] is not None else 1e300)):
            status = "pass" if c["pass"] else "accepted" if c["accepted"] else c["severity"]
            self._check_row(out, c, base, status)
            out["value"].append("-" if c["value"] is None else
                                f"{number_text(c['value'], '.5g', self.lang)} {unit_symbol(c['unit'], self.lang)}".rstrip())
            out["margin"].append("" if c["margin"] is None else number_text(c["margin"], "+.3g", self.lang))
        for c in s.pending:
            self._check_row(out, c, base, "pending")
            out["value"].append("…")
            out["margin"].append("")
        _send(self.checks, out)

    def _check_row(self, out, c, base, status):
        """The columns of a check's row that do not wait for its value: its status, name, baseline, range and
        source (in Russian its words from the catalogue, its locators in the words of the report's citations)."""
        out["key"].append(c["quantity"])
        out["status"].append(WORDS[self.lang][STATUS_WORDS[status]])
        out["colour"].append(SEVERITY_COLOURS[status])
        out["quantity"].append(record_quantity_text(c, self.lang))
        b = base.get(c["quantity"])
        out["baseline"].append("" if b is None or b["value"] is None else number_text(b["value"], ".5g", self.lang)
                               + ("" if b["pass"] else " ✗"))
        out["allowed"].append(check_range(c, self.lang))
        out["source"].append(citation(translate(c["source"], "ru")) if self.lang == "ru" else c["source"])

    def _card(self):
        """The cam card of the good design: each valve's events at the checking heights (crank deg from the
        gas-exchange TDC), its lobe centre and lift at TDC, the lobe separation and the overlaps, and the valves'
        accelerations, smallest radius, time-area and fullness."""
        t, mm = TEXT[self.lang], self.units.mm
        results = self.session.good["results"]
        card = (results.get("cam_card") or {})
        valves = card.get("valves") or {}
        rows = {k: [] for k in self.card.data}

        def add(name, values):
            rows["quantity"].append(name)
            for n in self.names:
                v = values.get(n)
                rows[n].append("" if v is None else number_text(v, ".5g", self.lang))

        crank = WORDS[self.lang]["unit_crank"]
        for group, keys in EVENTS:
            for word, key in zip(("cc_opens", "cc_closes", "cc_duration"), keys, strict=True):
                add(f"{t[group]}: {t[word]}, {crank}", {n: c.get(f"{key}_crank_deg") for n, c in valves.items()})
        if valves:
            add(f"{t['cc_centre']}, {crank}", {n: c.get("lobe_centre_crank_deg") for n, c in valves.items()})
            add(t["cc_lift_tdc"].replace("mm", WORDS[self.lang][f"unit_{self.units.length}"]),
                {n: None if c.get("lift_at_tdc_mm") is None else mm * c["lift_at_tdc_mm"]
                 for n, c in valves.items()})
        w = WORDS[self.lang]
        for key, word, unit, scale in (("lobe_separation_cam_deg", "cc_separation", w["unit_cam"], 1.0),
                                       ("overlap_crank_deg", "cc_overlap", crank, 1.0),
                                       ("overlap_at_0_050in_crank_deg", "cc_overlap_050", crank, 1.0),
                                       ("overlap_area_mm_crank_deg", "cc_overlap_area",
                                        f"{w[f'unit_{self.units.length}']}·{crank}", mm)):
            if card.get(key) is not None:
                add(f"{t[word]}, {unit}", dict.fromkeys(self.names, scale * card[key]))
        for key in VALVE_CARD:
            group, leaf = key.split(".")
            add(label(key, self.lang), {n: results["valves"][n].get(group, {}).get(leaf) for n in self.names})
        _send(self.card, rows)

    def _breathing(self):
        """The breathing of the good design: the volumetric efficiency against the speed along [breathing.curve]
        (a line) and at each [[breathing.conditions]] (points), the indicated torque on the right axis where the
        engine is fired; a cam phaser's (of the valve shown, else the first valve's) best phase at each condition
        (hollow diamonds: the breathing there) and its advance in the label; without [breathing], a line that says
        so."""
        results = self.session.good["results"]
        chapter = results.get("breathing")
        phasers = results.get("phasers") or {}
        phaser = phasers.get(self.valve) or next(iter(phasers.values()), None)
        t = WORDS[self.lang]
        self.breathing_status.text = "" if chapter else t["no_breathing"]
        if chapter and phaser and phaser["best"]:
            self.breathing_status.text = t["phased"].format(valve=phaser["valve"], best=", ".join(
                t["phased_at"].format(advance=f"{b['advance_crank_deg']:.3g}", speed=f"{b['speed_rpm']:.0f}")
                for b in phaser["best"]))
        fired = bool(chapter) and chapter["mode"] == "fired"
        for key, source in self.breathing.items():
            records = (((chapter or {}).get(key) if key != "phased" else (phaser or {}).get("best")) or [])
            _send(source, {"speed": _array([r["speed_rpm"] for r in records]),
                           "ve": _array([r["volumetric_efficiency"] for r in records]),
                           "torque": _array([r.get("torque_Nm") if fired else None for r in records])})
        self.torque_axis.visible = fired
        p = self.figures["breathing"]
        for rng, name, room in ((p.x_range, "speed", PLOT_ROOM), (p.y_range, "ve", PLOT_ROOM),
                                (p.extra_y_ranges["torque"], "torque", PLOT_ROOM)):
            _fit(rng, [source.data[name] for source in self.breathing.values()], room)

    def _sync_fields(self):
        """The panel's inputs show the good design's values (those an edit refused, a drag or an undo changed); the
        cam's group of a valve whose law changed is built again (its keys are the law's)."""
        document = self.session.document
        for valve in self.names:
            if value_at(document, f"valves.{valve}.cam.law") != self.laws[valve]:
                self.laws[valve] = value_at(document, f"valves.{valve}.cam.law")
                before = {path: (self.fields.pop(path), self.widgets.pop(path))
                          for path in [p for p in self.widgets if p.startswith(f"valves.{valve}.cam.")]}
                fields = dict(form(document, valve)).get("cam", [])
                self.group_columns[("cam", valve)].children = [self._widget(f, before.get(f.path)) for f in fields]
        self._syncing = True
        try:
            for path, w in self.widgets.items():
                value = value_of(document, self.fields[path])
                shown = (value if isinstance(w, NumericInput) else "" if value is None
                         else str(value) if isinstance(w, Select) else value_text(value))
                if w.value != shown:
                    w.value = shown
        finally:
            self._syncing = False

    def show_problems(self, kind="field") -> None:
        """The problems of the last edit refused in the status line, each with the value tried and the value the
        design drawn keeps, its input marked; nothing when it designed."""
        s, w = self.session, WORDS[self.lang]
        marked = {p for p in s.refused if p in self.widgets}
        for path in self.refused_paths | marked:
            self.widgets[path].css_classes = ["vt-refused"] if path in marked else []
        self.refused_paths = marked
        lines = []
        for p in s.problems:
            message = translate(p["message"], self.lang) if p["path"] in s.refused else problem_text(p, self.lang)
            if kind == "field" and p["path"] in self.fields:
                f = self.fields[p["path"]]
                lines.append(w["refused"].format(what=label(f.name, self.lang),
                                                 value=_shown(s.refused.get(p["path"], p["value"])),
                                                 message=message, kept=_shown(f.value)))
            else:
                lines.append(w["refused_point" if kind == "point" else "refused_drag" if kind == "drag"
                               else "refused_edit"].format(message=problem_text(p, self.lang)))
        self.status.text = "<br>".join(lines) or ("" if self.names else w["no_valves"])

    # --- callbacks -------------------------------------------------------------------------------------------------
    def on_field(self, f, attr, old, new) -> None:
        began = _now()
        if self._syncing:
            return
        self.finish_edit()
        try:
            value = parse_value(f, new)
        except ValueError as exc:
            self.session.problems = [{"path": f.path, "value": new, "message": str(exc), "text": str(exc)}]
            self.session.refused = {f.path: new}
            self._answer(False, began, "field")
            return
        self._answer(self.session.edit({f.path: value}), began, "field")

    def _answer(self, designed, began, kind, seq=0, curves_seq=None):
        """After an edit (``designed`` or refused): the good design drawn (the panel shows it: a refused value's
        input goes back to the good design's, its message says why) and its sweep started; ``curves_seq`` as for
        :meth:`redraw`."""
        self.shown = None
        self.redraw(sweep=designed, began=began, seq=seq, curves_seq=curves_seq)
        self.show_problems(kind)

    def _release(self, values, began, seq):
        """A handle released or nudged (the keys it sets): its valve's kinematics drawn at once
        (:meth:`~valvetrain.web.session.Session.preview`, the page's probe times them), its design in the worker
        thread, kept when it comes (:meth:`finish_edit`); a sketch that does not design is answered as an edit."""
        try:
            document, sketch = self.session.preview(values, self.valve)
        except ValueError:
            sketch = {"ok": False}
        if not sketch["ok"]:
            self._answer(self.session.edit(values), began, "drag", seq)
            return
        self.generation += 1                              # the sweep of the design before: stale, stopped
        self.shown = (document, sketch)
        self.redraw(began=began, seq=seq, live=True)
        self.pending = [None, values, seq, document]
        # after this answer has gone: the two threads would hold up its sending
        self.doc.add_next_tick_callback(partial(self._launch, self.pending))

    def _launch(self, pending) -> None:
        """The design of a drag released (:meth:`_release`) in its worker thread and, beside it, the sweep of the
        valve shown (:meth:`start_sweep`: its document's sweep does not wait for its design; the whole design's
        sweeps do), unless an edit kept it before."""
        if self.pending is not pending:
            return
        document = pending[3]
        self.sweeps = {}                                  # the sweeps of the design before: drawn no more
        job = pending[0] = DESIGN_WORKERS.submit(self.session.design, document)
        job.add_done_callback(lambda _: self.doc.add_next_tick_callback(partial(self._designed, job)))
        self.sweep_seq = pending[2]
        self.start_sweep(document, job)

    def _designed(self, job) -> None:
        """The design of a drag released has come (:meth:`_launch`): kept, unless an edit kept it before."""
        if self.pending is not None and self.pending[0] is job:
            self.finish_edit()

    def finish_edit(self) -> None:
        """Keep the design of the drag released last (waited for when it has not come: every other edit applies to
        it): the good design, drawn with its checks, card, panel and breathing, its sweep started; or, refused, the
        good design before it drawn again with the reason.  Nothing when no drag's design is pending."""
        if self.pending is None:
            return
        job, values, seq, document = self.pending
        self.pending = None
        if job is not None:
            job.result()                                  # kept by the session: the edit below designs nothing
        designed = self.session.edit(values)
        if not designed and self.sweep_key == document_key(document):
            self.sweep_key = None                         # the refused design's sweep: the good design's again
            designed = True
        self._answer(designed, _now(), "drag", seq, curves_seq=0)

    def on_request(self, attr, old, new) -> None:
        """A request of the page (page.js): a handle moved (``move``: designed and drawn, not kept), released
        (``end``) or nudged (``key``), a table's point added (``add``) or removed (``remove``), ``undo``, ``redo``,
        or the document the page kept across a reload (``restore``)."""
        began = _now()
        if not new.get("kind"):
            return
        kind, seq, plot, name, x, y, text = (new[k][0] for k in ("kind", "seq", "plot", "name", "x", "y", "text"))
        self.finish_edit()
        if kind in ("undo", "redo"):
            done = self.session.undo() if kind == "undo" else self.session.redo()
            self._answer(done, began, "field", seq)
            return
        if kind == "restore":
            self._restore(text, began, seq)
            return
        if self.valve is None:
            return
        if kind in ("add", "remove"):
            self._points(kind, name, x, y, began, seq)
            return
        x, y = self._to_session(plot, x, y)
        try:
            values = self.session.moved(self.valve, name, x, y)
        except ValueError:      # a handle the valve no longer has (the page drawn before its law changed)
            self.shown = None
            self.redraw(sweep=False, began=began, seq=seq)
            return
        if kind == "move":
            try:
                document, result = self.session.preview(values, self.valve)
            except ValueError:
                return
            if result["ok"]:
                self.shown = (document, result)
                self.redraw(began=began, seq=seq, live=True)
            else:
                _count(self.kinematic_stamp, began, seq, changed=False)
            return
        self._release(values, began, seq)

    def _to_session(self, plot, x, y):
        """A point of a handle's plot in the session's units (cam deg from the nose; mm or m/s²)."""
        result = self.session.good
        series, omega = result["series"][self.valve], self._omega(result)
        xs, x0 = self.units.of(series, omega)
        ys = self.units.of(series, omega, 0 if plot == "lift" else 2)[0]
        return (x - x0) / xs, y / ys

    def _points(self, kind, name, x, y, began, seq):
        """A point added to an inline lift table at (x, y) of the lift plot, or point ``name`` removed; nothing but
        the good design drawn again for a valve without such a table (a page drawn before its law changed)."""
        if not has_points(self.session.good_document["valves"][self.valve]["cam"]):
            self.shown = None
            self.redraw(sweep=False, began=began, seq=seq)
            return
        handles = [h for h in self.session.handles(self.valve) if h.plot == "lift"]
        xs, ys = [h.x for h in handles], [h.y for h in handles]
        if kind == "add":
            x, y = self._to_session("lift", x, y)
            xs, ys = [*xs, x], [*ys, y]
        else:
            keep = [h.name != name for h in handles]
            xs, ys = [v for v, k in zip(xs, keep, strict=True) if k], [v for v, k in zip(ys, keep, strict=True) if k]
        self._answer(self.session.edit(self.session.points(self.valve, xs, ys)), began, "point", seq)

    def _restore(self, text, began, seq):
        """The document the page kept across a reload designed again (an edit that can be undone), or the
        file's design kept with a message."""
        try:
            document = json.loads(text)
        except (ValueError, RecursionError):       # not JSON, or nested deeper than the parser's recursion
            return
        if not isinstance(document, dict):
            return
        designed = self.session.restore(document)
        self._answer(designed, began, "field", seq)
        w = WORDS[self.lang]
        self.status.text = (w["restored"] if designed else
                            w["restore_refused"].format(message="; ".join(problem_text(p, self.lang)
                                                                          for p in self.session.problems)))

    def on_undo(self) -> None:
        began = _now()
        self.finish_edit()
        self._answer(self.session.undo(), began, "field")

    def on_redo(self) -> None:
        began = _now()
        self.finish_edit()
        self._answer(self.session.redo(), began, "field")

    def on_language(self, attr, old, new) -> None:
        self.lang = new
        self._retitle()
        self._texts()
        self._axis_numbers()
        self.redraw(sweep=False)
        self.show_problems()

    def _axis_numbers(self) -> None:
        """Every plot's axes and colour bars with the numbers of the page's language (``[designer] numbers``: the
        browser's number format of that locale, a decimal comma in Russian, up to four decimals; Bokeh's own rule in
        English)."""
        language = WORDS[self.lang]["numbers"]
        formatter = BasicTickFormatter() if language == "en" else CustomJSTickFormatter(
            args={"locale": language}, code=AXIS_NUMBERS_JS)
        with self.doc.models.freeze():       # one recomputation of the document's models, not one per axis
            for axis in (m for root in self.doc.roots for m in root.references()
                         if isinstance(m, (LinearAxis, ColorBar))):
                axis.formatter = formatter

    def on_units(self, attr, old, new) -> None:
        self.units = Units(self.length_select.value, self.angle_select.value, self.derivative_select.value)
        self._texts()
        self.redraw(sweep=False)

    def on_valve(self, attr, old, new) -> None:
        self.finish_edit()
        self.valve = new
        for (group, valve), box in self.group_columns.items():
            box.visible = valve in (None, new)
        self.redraw(sweep=False)

    def on_overlay(self, attr, old, new) -> None:
        """A specification file overlaid: designed and pinned as the baseline that the plots and the checks
        compare with (its message in the status line when it does not design)."""
        try:
            name = self.overlay.filename            # the page may send the file's name after its content
        except UnsetValueError:
            name = "overlay.toml"
        try:
            document = toml_tables(base64.b64decode(new).decode("utf-8"), name)
        except SpecError as err:
            self.status.text = WORDS[self.lang]["overlay_refused"].format(name=name, message="; ".join(
                p.message for p in err.problems))
            return
        except (ValueError, UnicodeDecodeError) as exc:
            self.status.text = WORDS[self.lang]["overlay_refused"].format(name=name, message=exc)
            return
        self.finish_edit()
        if "source_dir" in self.session.document:
            document["source_dir"] = self.session.document["source_dir"]
        result = self.session.design(document)
        if not result["ok"]:
            self.status.text = WORDS[self.lang]["overlay_refused"].format(
                name=name, message="; ".join(problem_text(p, self.lang) for p in result["errors"]))
            return
        self.session.baseline = result
        self.base_sweeps = None
        self.status.text = ""
        self.redraw(sweep=False)

    def on_download(self, event) -> None:
        self.finish_edit()
        {"toml": self.on_toml, "dxf": self.on_dxf, "report": self.on_report}[event.item]()

    def on_report(self) -> None:
        """The report of the good design, to the page, which saves it (a comment makes every one a change)."""
        self.downloads += 1
        self.downloaded["report"].text = self.session.report(self.lang) + f"<!-- download {self.downloads} -->\n"

    def on_toml(self) -> None:
        """The specification of the good design, to the page, which saves it (a comment makes every one a change)."""
        self.downloads += 1
        self.downloaded["toml"].text = self.session.toml() + f"# download {self.downloads}\n"

    def on_dxf(self) -> None:
        """The contour of the valve shown as DXF (``valvetrain run``'s), to the page, which saves it."""
        if self.valve is None:
            return
        self.downloads += 1
        data = self.session.dxf(self.valve)
        # a DXF comment (group code 999) makes every download a change
        self.downloaded["dxf"].text = base64.b64encode(data + f"999\ndownload {self.downloads}\n".encode()).decode()

    def on_pin(self) -> None:
        self.finish_edit()
        self.session.pin()
        self.base_sweeps = dict(self.sweeps)
        self.redraw(sweep=False)


def _shown(value) -> str:
    """A value in a message: a number as ``%g``, anything else as its input shows it."""
    return f"{value:g}" if isinstance(value, (int, float)) and not isinstance(value, bool) else value_text(value)


def page_key(text) -> str:
    """The key under which the page keeps the edits of a file's design across a reload: the file's text hashed."""
    return "valvetrain:" + hashlib.sha256((text or "").encode("utf-8")).hexdigest()[:16]
