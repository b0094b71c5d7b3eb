// The designer's page: the handles dragged one to one with the pointer within their limits, the arrow keys, undo and
// redo, the probe of the redraw times and the edits kept across a reload.  Run once when the document is ready
// (valvetrain.web.app.Designer: a CustomJS with the args named below, after app.VIEW_JS: view(model)).
if (window.vt !== undefined) {
  return;
}
const vt = window.vt = {plots, sources, limits, options, request, drag: null, selected: null, tap: null, seq: 0,
                        inflight: 0, pending: false, release: 0, sent: {}, key};
const RADIUS = 9;         // px: a press this near a handle's centre takes it
const GAP = 12;           // px: the least distance sideways between two handles of a plot (their diameter)
const TAP = 5;            // px: a press and release this near each other on a table's lift plot adds a point

const column = (source, name) => (source.data instanceof Map ? source.data.get(name) : source.data[name]);
const clamp = (v, lo, hi) => Math.min(Math.max(v, lo), hi);

function frame(plot) {
  // the plot's view, its canvas's place on the page and its scales
  const found = view(vt.plots[plot]);
  if (found == null) {
    return null;
  }
  return {view: found, rect: found.canvas_view.el.getBoundingClientRect(), xs: found.frame.x_scale,
          ys: found.frame.y_scale};
}

function pressed(event) {
  // the plot under the pointer and the handle nearest it within RADIUS (-1: none)
  const path = event.composedPath();
  for (const plot of Object.keys(vt.plots)) {
    const f = frame(plot);
    if (f == null || !path.includes(f.view.canvas_view.events_el)) {
      continue;
    }
    const sx = event.clientX - f.rect.left, sy = event.clientY - f.rect.top;
    const x = column(vt.sources[plot], "x"), y = column(vt.sources[plot], "y");
    let index = -1, best = RADIUS;
    for (let i = 0; i < x.length; i++) {
      const d = Math.hypot(f.xs.compute(x[i]) - sx, f.ys.compute(y[i]) - sy);
      if (d <= best) {
        index = i;
        best = d;
      }
    }
    return {plot, f, sx, sy, index};
  }
  return null;
}

function bounds(plot, i, f) {
  // where handle i may go: its limits, and GAP px from its neighbours sideways (no nearer than it is)
  const s = vt.sources[plot];
  const x = column(s, "x");
  const px = f.xs.compute(x[i]);
  let left = -Infinity, right = Infinity;
  for (let j = 0; j < x.length; j++) {
    const pj = f.xs.compute(x[j]);
    if (j !== i && pj < px) {
      left = Math.max(left, pj);
    } else if (j !== i && pj > px) {
      right = Math.min(right, pj);
    }
  }
  const lo = f.xs.invert(left + Math.min(GAP, px - left)), hi = f.xs.invert(right - Math.min(GAP, right - px));
  return [Math.max(column(s, "x_lo")[i], lo), Math.min(column(s, "x_hi")[i], hi), column(s, "y_lo")[i],
          column(s, "y_hi")[i]];
}

function show_limits() {
  // the selected handle's limits: a line across each range it moves in (clipped to the plot), the handle ringed
  for (const plot of Object.keys(vt.plots)) {
    const src = vt.limits[plot];
    const [x0, x1, y0, y1, sx, sy] = ["x0", "x1", "y0", "y1", "sx", "sy"].map((k) => column(src, k));
    x0.fill(NaN); x1.fill(NaN); y0.fill(NaN); y1.fill(NaN); sx.fill(NaN); sy.fill(NaN);
    const sel = vt.drag || vt.selected;
    const f = frame(plot);
    if (sel != null && sel.plot === plot && f != null) {
      const [xlo, xhi, ylo, yhi] = sel.bounds;
      const xr = vt.plots[plot].x_range, yr = vt.plots[plot].y_range;
      const x = column(vt.sources[plot], "x")[sel.i], y = column(vt.sources[plot], "y")[sel.i];
      if (xhi > xlo) {
        x0[0] = clamp(xlo, xr.start, xr.end); x1[0] = clamp(xhi, xr.start, xr.end); y0[0] = y; y1[0] = y;
      }
      if (yhi > ylo) {
        x0[1] = x; x1[1] = x; y0[1] = clamp(ylo, yr.start, yr.end); y1[1] = clamp(yhi, yr.start, yr.end);
      }
      sx[0] = x; sy[0] = y;
    }
    src.change.emit();
  }
}

function put(sel, x, y) {
  // the handle where the pointer (or a key) took it, in the page at once
  const s = vt.sources[sel.plot];
  column(s, "x")[sel.i] = x;
  column(s, "y")[sel.i] = y;
  sel.x = x;
  sel.y = y;
  s.change.emit();
  show_limits();
}

function send(kind, sel, text) {
  // a request to the server: one move at a time while the pointer moves (the newest kept for when it answers)
  if (kind === "move" && vt.inflight) {
    vt.pending = true;
    return;
  }
  vt.seq += 1;
  vt.sent[vt.seq] = performance.now();
  if (kind === "move") {
    vt.inflight = vt.seq;
  }
  if (kind !== "move") {
    vt.release = vt.seq;
  }
  vt.request.data = {kind: [kind], seq: [vt.seq], plot: [sel ? sel.plot : ""], name: [sel ? sel.name : ""],
                     x: [sel && sel.x !== undefined ? sel.x : 0], y: [sel && sel.y !== undefined ? sel.y : 0],
                     text: [text || ""]};
}

vt.send_move = () => send("move", vt.drag);

function blur() {
  // the input being typed in gives up the keys (its value committed): the arrows and Ctrl-Z go to the handles
  let active = document.activeElement;
  while (active != null && active.shadowRoot != null && active.shadowRoot.activeElement != null) {
    active = active.shadowRoot.activeElement;
  }
  if (active != null && active !== document.body) {
    active.blur();
  }
}

function select(plot, i, f) {
  vt.selected = plot == null ? null : {plot, i, name: column(vt.sources[plot], "name")[i], bounds: bounds(plot, i, f)};
  show_limits();
}

window.addEventListener("pointerdown", (event) => {
  if (event.button !== 0) {
    return;
  }
  const at = pressed(event);
  if (at == null) {
    return;
  }
  if (at.index < 0) {
    vt.tap = column(vt.options, "add")[0] && at.plot === "lift" ? {at, t: event.timeStamp} : null;
    if (vt.selected != null) {
      select(null);
    }
    return;
  }
  event.stopPropagation();
  event.preventDefault();
  blur();
  const s = vt.sources[at.plot], i = at.index;
  const x = column(s, "x")[i], y = column(s, "y")[i];
  select(at.plot, i, at.f);
  vt.drag = {...vt.selected, x, y, moved: false, dx: at.f.xs.compute(x) - at.sx, dy: at.f.ys.compute(y) - at.sy};
  vt.drag.grab = [event.clientX, event.clientY];
}, true);

window.addEventListener("pointermove", (event) => {
  const d = vt.drag;
  if (d == null) {
    return;
  }
  event.stopPropagation();
  event.preventDefault();
  if (event.clientX === d.grab[0] && event.clientY === d.grab[1]) {
    return;
  }
  const f = frame(d.plot);
  const [xlo, xhi, ylo, yhi] = d.bounds;
  const x = clamp(f.xs.invert(event.clientX - f.rect.left + d.dx), xlo, xhi);
  const y = clamp(f.ys.invert(event.clientY - f.rect.top + d.dy), ylo, yhi);
  d.moved = true;
  put(d, x, y);
  send("move", d);
}, true);

window.addEventListener("pointerup", (event) => {
  const d = vt.drag;
  if (d == null) {
    const tap = vt.tap;
    vt.tap = null;
    if (tap != null && Math.hypot(event.clientX - tap.at.f.rect.left - tap.at.sx,
                                  event.clientY - tap.at.f.rect.top - tap.at.sy) <= TAP) {
      window.vtRelease = performance.now();
      send("add", {plot: "lift", name: "", x: tap.at.f.xs.invert(tap.at.sx), y: tap.at.f.ys.invert(tap.at.sy)});
    }
    return;
  }
  event.stopPropagation();
  event.preventDefault();
  vt.drag = null;
  vt.pending = false;
  if (d.moved) {
    window.vtRelease = performance.now();
    send("end", d);
  }
  vt.selected = {plot: d.plot, i: d.i, name: d.name, bounds: d.bounds};
  show_limits();
}, true);

window.addEventListener("keydown", (event) => {
  const target = event.composedPath()[0];
  if (target != null && ["INPUT", "TEXTAREA", "SELECT"].includes(target.tagName)) {
    return;
  }
  const key = event.key.toLowerCase();
  if ((event.ctrlKey || event.metaKey) && (key === "z" || key === "y")) {
    event.preventDefault();
    window.vtRelease = performance.now();
    send(key === "y" || event.shiftKey ? "redo" : "undo");
    return;
  }
  const sel = vt.selected;
  if (sel == null || vt.drag != null) {
    return;
  }
  if (event.key === "Escape") {
    select(null);
    return;
  }
  if ((event.key === "Delete" || event.key === "Backspace") && column(vt.options, "add")[0] && sel.plot === "lift") {
    event.preventDefault();
    window.vtRelease = performance.now();
    send("remove", sel);
    select(null);
    return;
  }
  const step = {ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1]}[event.key];
  if (step === undefined) {
    return;
  }
  event.preventDefault();
  const f = frame(sel.plot);
  const s = vt.sources[sel.plot];
  const times = event.shiftKey ? 10 : 1;
  const pixel = Math.abs(f.ys.invert(0) - f.ys.invert(1));
  const [xlo, xhi, ylo, yhi] = sel.bounds;
  const x = clamp(column(s, "x")[sel.i] + step[0] * 0.1 * times, xlo, xhi);
  const y = clamp(column(s, "y")[sel.i] + step[1] * pixel * times, ylo, yhi);
  put(sel, x, y);
  window.vtRelease = performance.now();
  send("key", sel);
}, true);

for (const plot of Object.keys(vt.plots)) {
  // a range refitted by a redraw (the release's, after the drag's kept it): the limits clipped to it again
  for (const range of [vt.plots[plot].x_range, vt.plots[plot].y_range]) {
    range.connect(range.change, show_limits);
  }
}

for (const plot of Object.keys(vt.sources)) {
  // new handles from the server: the one dragged stays under the pointer, the selection follows its handle
  vt.sources[plot].connect(vt.sources[plot].properties.data.change, () => {
    const names = column(vt.sources[plot], "name");
    for (const sel of [vt.drag, vt.selected]) {
      if (sel != null && sel.plot === plot) {
        sel.i = names.indexOf(sel.name);
      }
    }
    if (vt.selected != null && vt.selected.plot === plot && vt.selected.i < 0) {
      vt.selected = null;
    }
    const d = vt.drag;
    if (d != null && d.plot === plot && d.i >= 0 && d.moved) {
      column(vt.sources[plot], "x")[d.i] = d.x;
      column(vt.sources[plot], "y")[d.i] = d.y;
      vt.sources[plot].change.emit();
    } else if (vt.selected != null && vt.selected.plot === plot) {
      const f = frame(plot);
      vt.selected.bounds = f == null ? vt.selected.bounds : bounds(plot, vt.selected.i, f);
    }
    show_limits();
  });
}

const kept = window.sessionStorage.getItem(vt.key);
if (kept != null && kept !== column(saved, "document")[0]) {
  send("restore", null, kept);
}
saved.connect(saved.properties.data.change, () => {
  window.sessionStorage.setItem(vt.key, column(saved, "document")[0]);
});
