"""The designer's speed-sweep panel: the sweep of the valve shown and the whole design's, in a worker thread, the
newest drawn (the smallest contact force and the seating velocity against the speed, the map of the lift error,
the dynamics against the angle at a chosen speed).
"""

from concurrent.futures import ThreadPoolExecutor
from functools import partial

import numpy as np

from ..errors import ValvetrainError
from .draw import PLOT_ROOM, WORDS, problem_text, _array, _array_2d, _count, _fit, _hold, _now, _send
from .session import document_key

SWEEP_WORKERS = ThreadPoolExecutor(max_workers=1, thread_name_prefix="valvetrain-sweep")
"""One thread for the speed sweeps of every tab (2 cores: the kinematics keep the other)."""

class Stale(ValvetrainError):
    """Raised into a speed sweep that a newer change made stale."""


class SweepPanel:
    """The speed sweep of a :class:`~valvetrain.web.app.Designer`: started, drawn, and its speed chosen."""

    def on_drawn(self, attr, old, new) -> None:
        """The page has drawn the kinematics of redraw ``new["n"]``: the sweep of the newest one starts (its thread
        would have held up the sending of the kinematics, and the page's drawing of them)."""
        if self.sweep_due and new["n"][0] == self.kinematic_stamp.data["n"][0]:
            self.sweep_due = False
            self.start_sweep()

    def start_sweep(self, document=None, job=None) -> None:
        """In the worker thread: the speed sweep of the valve shown alone, drawn as soon as it comes
        (:meth:`~valvetrain.web.session.Session.sweep_one`: a fraction of the whole design's time), then the whole
        design of the good document with every valve's sweep (:meth:`~valvetrain.web.session.Session.settle`; the
        valve shown is not swept again: the first's design is kept for it), its checks to the table; a newer change
        stops both at their next speed.  ``document``: a drag's released (default the good one), whose design
        ``job`` (a future of :meth:`~valvetrain.web.session.Session.design`) the whole design waits for: nothing
        more of it is swept when it does not design."""
        self.generation += 1
        generation, seq, valve = self.generation, self.sweep_seq, self.valve
        self.sweep_status.text = WORDS[self.lang]["sweeping"]
        document = self.session.document if document is None else document
        self.sweep_key = document_key(document)

        def progress(name, done, total):
            if generation != self.generation:
                raise Stale

        def work():
            began, memo = _now(), {}
            try:
                first = self.session.sweep_one(document, valve, progress=progress, memo=memo)
                if first is not None:
                    self.doc.add_next_tick_callback(partial(self.draw_sweep_of, generation, valve, first, began, seq))
                if job is not None and not job.result()["ok"]:
                    return
                result = self.session.settle(document, progress=progress, memo=memo)
            except Stale:
                return
            self.doc.add_next_tick_callback(partial(self.draw_sweep, generation, result, began,
                                                    0 if first is not None else seq))

        SWEEP_WORKERS.submit(work)

    def _sweep_curves(self, sw, sources):
        _send(sources["force"], {"x": _array(sw["speed_rpm"]), "y": _array(sw["min_contact_force_N"])})
        _send(sources["seating"], {"x": _array(sw["speed_rpm"]),
                                   "y": np.abs(_array(sw["seating_velocity_m_s"]))})

    def draw_sweep_of(self, generation, valve, sweep, began, seq=0) -> None:
        """Draw the sweep of one valve (:meth:`start_sweep`'s first answer) if it is the newest redraw's; ``began``
        as for :meth:`redraw`, when the worker took it up; ``seq`` the page's request of the design."""
        if generation != self.generation:
            return
        self.sweeps[valve] = sweep
        _hold(self.sweep_hold)
        try:
            self._sweep_panel()
        finally:
            _count(self.sweep_stamp, began, seq)

    def draw_sweep(self, generation, result, began, seq=0) -> None:
        """Keep the whole design of redraw ``generation`` if it is the newest: its checks to the table, its sweeps
        to the sweep panel; ``began`` as for :meth:`redraw`, when the worker took it up; ``seq`` the page's request
        of the design (0: its panel drawn already, from the valve's own sweep)."""
        if generation != self.generation:
            return
        self.finish_edit()                                # the document swept is the good one (its design came)
        if generation != self.generation:
            return
        self.session.settled(result)
        self.sweeps = dict(result.get("sweeps") or {}) if result["ok"] else {}
        if seq:
            _hold(self.sweep_hold)
        try:
            if result["ok"] and result["results"] is not None:
                self._checks()
            self._sweep_panel()
        finally:
            _count(self.sweep_stamp, began, seq)

    def _sweep_panel(self):
        """The sweep panel of the valve shown; without its sweep, its label says that the whole design is to come,
        the problems of the whole design when it did not design, or a dash (the whole design swept no such valve)."""
        sw = self.sweeps.get(self.valve)
        if sw is None:
            full = self.session.full
            self.sweep_status.text = (WORDS[self.lang]["sweeping"] if full is None
                                      else "; ".join(problem_text(p, self.lang) for p in full["errors"]) or "-")
            return
        self._sweep_curves(sw, self.sweep_sources)
        base = (self.base_sweeps or {}).get(self.valve)
        if base is not None:
            self._sweep_curves(base, self.base_sweep_sources)
        for key in ("force", "seating"):
            p = self.figures["sweep_" + key]
            for rng, column_name, room in ((p.x_range, "x", 0.0), (p.y_range, "y", PLOT_ROOM)):
                _fit(rng, [s[key].data[column_name] for s in (self.sweep_sources, self.base_sweep_sources)], room)
        marks = [v for v in (sw["jump_speed_rpm"], sw["bounce_speed_rpm"]) if v is not None]
        for key, values in (("force", sw["min_contact_force_N"]), ("seating", sw["seating_velocity_m_s"])):
            found = np.abs(_array(values))
            found = found[np.isfinite(found)]
            low, high = (float(found.min()), float(found.max())) if found.size else (0.0, 1.0)
            _send(self.sweep_marks[key], {"x": _array(marks), "y0": _array([low] * len(marks)),
                                          "y1": _array([high] * len(marks))})
        # as 32-bit floats (7 digits, more than its colours show): half the bytes of the sweep panel's message (its
        # 0.7 MB were mostly this map's)
        err = (_array_2d(sw["map_lift_error_mm"]) * self.units.mm).astype(np.float32)
        bound = float(np.nanmax(np.abs(err))) if np.isfinite(err).any() else 1.0
        self.mapper.update(low=-(bound or 1.0), high=bound or 1.0)
        x, n = sw["map_cam_deg"], sw["speed_rpm"]
        _send(self.map_source, {"image": [err], "x": [x[0]], "y": [n[0]], "dw": [x[-1] - x[0]], "dh": [n[-1] - n[0]]})
        p = self.figures["sweep_map"]
        _fit(p.x_range, [[x[0], x[-1]]], 0.0)
        _fit(p.y_range, [[n[0], n[-1]]], 0.0)
        speeds = sw["speed_rpm"]
        step = (speeds[-1] - speeds[0]) / max(1, len(speeds) - 1)
        value = self.speed.value if self.speed.visible and speeds[0] <= self.speed.value <= speeds[-1] \
            else sw["rated_speed_rpm"]
        self.speed.update(start=speeds[0], end=speeds[-1], step=step or 1.0, visible=True,
                          value=float(speeds[int(np.argmin(np.abs(np.asarray(speeds) - value)))]))
        self._at_speed(sw)
        t = WORDS[self.lang]
        self.sweep_status.text = ", ".join(f"{t[k]} {v:.5g} rpm" for k, v in (("jump", sw["jump_speed_rpm"]),
                                                                               ("bounce", sw["bounce_speed_rpm"]))
                                           if v is not None) or "-"

    def _at_speed(self, sw):
        """The dynamics against the camshaft angle at the speed chosen (the slider, a speed of the sweep): the cam
        contact force, the valve's acceleration of the elastic train and the rigid one (the kinematic acceleration at
        the rated speed scaled by the square of the speed ratio)."""
        i = int(np.argmin(np.abs(np.asarray(sw["speed_rpm"]) - self.speed.value)))
        series = self.session.good["series"][self.valve]
        x = _array(sw["map_cam_deg"])
        rated = self.session.good["results"]["engine"]["rated_speed_rpm"]
        rigid = np.interp(x, series["cam_deg"], _array(series["valve_acceleration_m_s2"])) \
            * (sw["speed_rpm"][i] / rated) ** 2
        force, acceleration = (_array_2d(sw[k])[i] for k in ("map_contact_force_N", "map_valve_acceleration_m_s2"))
        _send(self.at_speed, {"x": x, "force": force, "acceleration": acceleration, "rigid": rigid})
        p = self.figures["at_speed"]
        _fit(p.x_range, [x], 0.0)
        _fit(p.y_range, [force], PLOT_ROOM)
        _fit(p.extra_y_ranges["acceleration"], [acceleration, rigid], PLOT_ROOM)
        p.title.text = WORDS[self.lang]["at_speed"].format(speed=f"{sw['speed_rpm'][i]:.0f}")

    def on_speed(self, attr, old, new) -> None:
        if self.sweeps.get(self.valve) is not None:
            self._at_speed(self.sweeps[self.valve])
