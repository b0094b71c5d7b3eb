"""The report's figures (report/plots.py).  Issue 24: the contour drawing, the curvature plot and the timing diagram
of the appendix example (the appendix of Valve-train practical works (n.d.): intake opens 26 deg before the TDC and
closes 78 deg after the BDC, Phi = 27 + 6 + 38 = 71 cam deg from the end of the ramp to the nose).  The jerk plot's
impulses.  The dynamics, grinding and hydraulic-actuation figures are their data and their drawing: the data are plain
numbers and arrays, the same as results.json's, and the drawing takes them alone."""

import itertools
from pathlib import Path
import re

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.text import Text
import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.laws.convex import ThreeArcLaw
from valvetrain.report import hydraulic_plots, plots
from valvetrain.report.i18n import TEXT
from valvetrain.report.plots import jerk_impulses
from valvetrain.specification import load_spec

from appendix import appendix_spec
from figure_checks import all_texts_on_the_figures
from conftest import plain

EXAMPLES = Path(__file__).parents[2] / "examples"


@pytest.fixture(scope="module")
def results():
    return run(appendix_spec())


def test_the_contour_turns_the_way_its_arrow_shows(results):
    """Turned counter-clockwise (the drawn arrow) by its camshaft angle theta, the contour point of theta lies at the
    height r_heel + h_T(theta) above the centre: the follower's face, where the law puts it (Shang Hanji (1988), eq.
    (2.15): p = (r + h) u + h' t, u = (sin theta, cos theta)).  Turned the other way it does not."""
    v = results.valves["intake"]
    d = plots.contour_data(v)
    theta = v.contour_angle
    k = np.flatnonzero((theta > -1.2) & (theta < -0.3))        # the opening flank, before the nose
    x, y = d["x_mm"][k], d["y_mm"][k]
    face = d["heel_mm"] + 1e3 * v.law.lift(theta[k])

    def height(turn):
        return x * np.sin(turn) + y * np.cos(turn)              # y after a counter-clockwise turn by ``turn``

    assert height(theta[k]) == pytest.approx(face, abs=1e-6)
    assert np.max(np.abs(height(-theta[k]) - face)) > 1.0
    assert np.all(x < 0.0)                                      # the opening flank is drawn on the left


def test_the_contour_marks_the_nose_the_events_and_the_tdc(results):
    rays = {key: (cam, crank) for key, cam, crank in plots.contour_data(results.valves["intake"])["rays"]}
    assert rays["opens"] == pytest.approx((-71.0, -26.0))       # the appendix: 26 deg before TDC, Phi = 71 cam deg
    assert rays["closes"] == pytest.approx((71.0, 180.0 + 78.0))
    assert rays["nose"] == pytest.approx((0.0, (258.0 - 26.0) / 2.0))
    assert rays["tdc"] == pytest.approx((-58.0, 0.0))           # (0 - 116) / 2: the timing reference
    fig = plots.draw_contour(plots.contour_data(results.valves["intake"]), TEXT["ru"])
    texts = [t.get_text() for t in fig.axes[0].texts]
    assert "открытие, -26° ПКВ" in texts and TEXT["ru"]["rotation"] in texts


def test_the_curvature_plot_draws_the_limits_the_checks_use(results):
    """The recommended minimum radius 2 mm (Shang Hanji (1988), section 2.1) and the undercut at rho <= 0, as lines;
    the smallest radius marked where the profile has it (11.885 mm at the nose: r0 + h_T max + h'' of the appendix)."""
    d = plots.curvature_data(results.valves["intake"])
    assert d["rho_min_limit_mm"] == 2.0 and d["undercut_mm"] == 0.0
    assert d["rho_min"][1] == pytest.approx(11.885, abs=1e-3) and d["rho_min"][0] == pytest.approx(0.0, abs=1e-6)
    ax = plots.draw_curvature(d, TEXT["en"]).axes[0]
    levels = sorted(line.get_ydata()[0] for line in ax.get_lines() if len(set(line.get_ydata())) == 1
                    and line.get_xdata()[0] == 0 and line.get_xdata()[1] == 1)
    assert levels == [0.0, 2.0]


def test_the_timing_diagram_writes_the_events(results):
    d = plots.timing_data(results.valves)
    assert d["events_crank_deg"]["intake"] == pytest.approx((-26.0, 258.0))
    texts = [t.get_text() for t in plots.draw_timing(d, TEXT["en"]).axes[0].texts]
    assert "-26°" in texts and "258°" in texts


def test_the_jerk_impulses_are_written_with_a_decimal_comma_in_russian(results):
    """The kinematics figure writes each acceleration step of the Kurz law beside its arrow (the appendix's law has
    steps): '+1234,5'-like in Russian, '+1234.5'-like in English."""
    v = results.valves["intake"]
    texts = {lang: [text.get_text() for text in plots.kinematics_figure(v, TEXT[lang]).findobj(Text)
                    if re.fullmatch(r"[+-][\d.,·⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+", text.get_text())] for lang in ("en", "ru")}
    assert texts["en"] and len(texts["en"]) == len(texts["ru"])
    assert [text.replace(".", ",") for text in texts["en"]] == texts["ru"]


@pytest.mark.parametrize("x", [[0.0, 1.0, 2.0, 3.0, 4.0], [0.0, 1.0, 3.0, 4.0, 7.0]])
def test_the_dynamics_maps_cells_are_those_of_pcolormesh(x):
    """The dynamics map draws its grid with pcolorfast on the cell edges of ``_cell_edges``; matplotlib's own
    pcolormesh(shading="auto"), which puts the edges between the centres itself, draws the same pixels (within one
    level of 255: rounding) on equal cells (the sweep's speeds and angles), and on unequal ones but for a seam of
    pixels where an edge falls between two (under 1 % of them).  Hand calculation: centres 0, 1, 3 have the edges
    -0.5, 0.5, 2, 4."""
    assert list(plots._cell_edges([0.0, 1.0, 3.0])) == [-0.5, 0.5, 2.0, 4.0]
    x, y, z = np.array(x), np.array([10.0, 20.0, 30.0, 40.0]), np.arange(20.0).reshape(4, 5)

    def pixels(draw):
        fig = plots.Figure(figsize=(4, 3))
        draw(fig.subplots())
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        return np.asarray(canvas.buffer_rgba()).astype(int)

    fast = pixels(lambda ax: ax.pcolorfast(plots._cell_edges(x), plots._cell_edges(y), z, cmap="viridis"))
    mesh = pixels(lambda ax: ax.pcolormesh(x, y, z, cmap="viridis", shading="auto"))
    apart = np.abs(fast - mesh).max(axis=2) > 1
    assert not apart.any() if np.ptp(np.diff(x)) == 0.0 else apart.mean() < 0.01


def test_a_drawer_draws_the_figures_it_claims(results):
    """write_plots numbers the figures in the order drawn; a drawer draws those whose numbers its ``claim`` gives (the
    drawers of a run share one counter): claiming 1 and 3 draws the second and the fourth figure of a drawer that draws
    every one, byte for byte, and two drawers claiming the even and the odd numbers draw every figure once between
    them; each returns the names of them all."""
    every, odd, even = {}, {}, {}
    names = plots.write_plots(results, every, figures="all")
    order = list(every)
    assert len(order) == 10
    assert plots.write_plots(results, odd, figures="all", claim=iter([1, 3, 10**6]).__next__) == names
    assert list(odd) == [order[1], order[3]] and all(odd[f] == every[f] for f in odd)
    odd.clear()
    plots.write_plots(results, odd, figures="all", claim=itertools.count(1, 2).__next__)
    plots.write_plots(results, even, figures="all", claim=itertools.count(0, 2).__next__)
    assert not set(odd) & set(even)
    assert sorted([*odd, *even]) == sorted(order)


def test_every_text_of_a_figure_lies_on_it(results):
    """Every text a figure draws (tick labels, axis labels, titles, legends, of the secondary axes too: matplotlib's
    tight bounding box of the drawn figure) lies inside the figure, in English and Russian: the fixed margins leave
    room for the widest labels.  (The kinematics figure's per-degree axes on the right were cut off by the figure's
    edge, their label drawn outside it.)"""
    figures = [(kind, lambda t, make=make: make(results.valves["intake"], t)) for kind, make in plots.FIGURES.items()]
    all_texts_on_the_figures([*figures, ("timing", lambda t: plots.timing_figure(results.valves, t))])


def test_jerk_plot_marks_each_impulse():
    """The jerk plot draws an arrow and a marker at each step, pointing the way the acceleration jumps."""
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    ax = Figure().subplots()
    theta = np.linspace(law.start, law.end, 201)
    ax.plot(np.degrees(theta), law.jerk(theta, 100.0))
    jerk_impulses(ax, law, 100.0)
    arrows = [a for a in ax.texts if a.arrow_patch is not None]
    assert len(arrows) == 4
    assert [np.sign(a.xy[1]) for a in arrows] == [1.0, -1.0, 1.0, -1.0]
    assert [a.xy[0] for a in arrows] == pytest.approx([np.degrees(s.angle) for s in law.acceleration_steps()])


def _drawn(data, draw):
    assert plain(data), draw.__name__
    assert isinstance(draw(data, TEXT["en"]), Figure)


@pytest.fixture(scope="module")
def designs():
    return {name: run(load_spec(EXAMPLES / name)) for name in
            ("pushrod-dynamics.toml", "seed000-polydyne.toml", "marine-hydraulic-exhaust.toml")}


def test_dynamics_figures(designs):
    v = designs["pushrod-dynamics.toml"].valves["intake"]
    record = v.summary["dynamics"]
    speed = plots.dynamics_speed_data(v.name, v.dynamics)
    _drawn(speed, plots.draw_dynamics_speed)
    _drawn(plots.dynamics_map_data(v.name, v.dynamics), plots.draw_dynamics_map)
    # the marked speeds are results.json's (a speed not reached is null there and no mark here)
    assert [speed["jump_rpm"], speed["bounce_rpm"]] == pytest.approx(
        [record["jump_speed_rpm"], record["bounce_speed_rpm"]], rel=1e-12, nan_ok=True)
    assert speed["rpm"] == pytest.approx(record["per_speed"]["speed_rpm"], rel=1e-12)


def test_grinding_figure(designs):
    v = designs["seed000-polydyne.toml"].valves["intake"]
    data = plots.grinding_data(v)
    _drawn(data, plots.draw_grinding)
    assert data["wheel_wear_mm"] == pytest.approx(v.summary["grinding"]["wheel_wear_mm"], rel=1e-12)


def test_hydraulic_figures(designs):
    v = designs["marine-hydraulic-exhaust.toml"].valves["exhaust"]
    record = v.summary["hydraulic"]
    data = hydraulic_plots.hydraulic_data(v)
    _drawn(data, hydraulic_plots.draw_hydraulic)
    sweep = hydraulic_plots.hydraulic_sweep_data(v)
    _drawn(sweep, hydraulic_plots.draw_hydraulic_sweep)
    assert data["stop_mm"] == pytest.approx(record["stop_mm"], rel=1e-12)
    assert sweep["simulated_rpm"] == pytest.approx(record["speed_rpm"], rel=1e-12)


def test_every_text_of_the_stages_figures_lies_on_them(designs):
    """As test_every_text_of_a_figure_lies_on_it, for the figures of the dynamics, the grinding and the hydraulic
    drive."""
    dynamics = designs["pushrod-dynamics.toml"].valves["intake"]
    ground = designs["seed000-polydyne.toml"].valves["intake"]
    hydraulic = designs["marine-hydraulic-exhaust.toml"].valves["exhaust"]
    all_texts_on_the_figures(
        [*((kind, lambda t, make=make: make(dynamics.name, dynamics.dynamics, t))
           for kind, make in plots.DYNAMICS_FIGURES.items()),
         ("grinding", lambda t: plots.grinding_figure(ground, t)),
         ("hydraulic", lambda t: hydraulic_plots.hydraulic_figure(hydraulic, t)),
         ("hydraulic_sweep", lambda t: hydraulic_plots.hydraulic_sweep_figure(hydraulic, t))])


def test_a_symbols_index_is_a_subscript_in_every_figure(results):
    """Issue 39: no figure prints a symbol with an underscore (h_T): its index is a subscript (mathtext $h_{T}$)."""
    v = results.valves["intake"]
    figures = [make(v, TEXT[lang]) for make in plots.FIGURES.values() for lang in ("en", "ru")]
    figures += [make(results.crank, TEXT[lang]) for make in plots.ENGINE_FIGURES["crank"].values()
                for lang in ("en", "ru")]
    texts = [text.get_text() for fig in figures for text in fig.findobj(Text)]
    assert [text for text in texts if re.search(r"[^\\{\s$]_[^{]", text)] == []
    assert any("$h_{T}$" in text for text in texts) and any("$p_{N}$" in text for text in texts)
