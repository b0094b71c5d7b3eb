"""The pieces the designer's page is drawn with (web/draw.py): the units shown, the plots' ranges kept, the curves
thinned to what a plot shows."""

import numpy as np
import pytest

pytest.importorskip("bokeh")

from valvetrain.web.draw import INCH, kept_range, thinned  # noqa: E402

from designer_page import _designer, _request  # noqa: E402


def test_units_lengths_in_inches_angles_in_crank_degrees():
    d = _designer()
    series = d.session.good["series"]["intake"]
    d.length_select.value, d.angle_select.value = "in", "crank"
    curves = d.curves.data
    n = len(series["cam_deg"])
    assert np.nanmax(curves["lift"]) == pytest.approx(max(series["valve_lift_mm"]) / INCH, rel=1e-6)
    # crank deg from the gas-exchange TDC: the nose of the intake at 116 crank deg (the cam card's lobe centre)
    assert np.asarray(curves["x"][:n]) == pytest.approx(np.asarray(series["crank_deg"]), rel=1e-6)
    assert d.handles["lift"].data["x"][0] == pytest.approx(116.0)
    assert d.handles["lift"].data["y"][0] == pytest.approx(9.0 / INCH)
    assert d.figures["lift"].yaxis.axis_label == "lift, in"
    # per crank degree: half the slope per cam degree; in inches
    d.derivative_select.value = "deg"
    v = np.asarray(d.curves.data["velocity"][:n], dtype=float)
    slope = np.gradient(np.asarray(series["valve_lift_mm"]) / INCH, np.asarray(series["crank_deg"]))
    off = np.asarray(series["valve_lift_mm"]) > 0.5
    assert np.max(np.abs(v[off] - slope[off])) < 0.01 * np.max(np.abs(slope))
    # a handle dragged in these units: the nose to 0.4 in = 10.16 mm
    _request(d, "end", "nose", 116.0, 0.4)
    assert d.session.document["valves"]["intake"]["max_lift_mm"] == pytest.approx(10.16)


def test_plot_ranges_are_kept_while_the_curves_keep_half_their_room():
    # a lift from 0 to 10 mm with a quarter of its span as room: (-2.5, 12.5) mm.  Raised to 11 mm it still has
    # 12.5 - 11 = 1.5 mm >= 2.75 / 2 above it: kept (no new ticks, no new layout).  Raised to 12 mm, 0.5 mm < 3 / 2:
    # refitted to (-3, 15).  Cut to 2 mm the range 18 mm wide is more than twice the 2 + 2 x 0.5 = 3 mm it wants:
    # refitted to (-0.5, 2.5)
    assert kept_range(0.0, 1.0, 0.0, 10.0, 0.25) == (-2.5, 12.5)
    assert kept_range(-2.5, 12.5, 0.0, 11.0, 0.25) == (-2.5, 12.5)
    assert kept_range(-2.5, 12.5, 0.0, 12.0, 0.25) == (-3.0, 15.0)
    assert kept_range(-3.0, 15.0, 0.0, 2.0, 0.25) == (-0.5, 2.5)
    # while a handle is dragged the range is kept as long as the curves lie inside it: 12 mm is inside (-2.5, 12.5);
    # 13 mm is not: refitted to (-3.25, 16.25)
    assert kept_range(-2.5, 12.5, 0.0, 12.0, 0.25, dragged=True) == (-2.5, 12.5)
    assert kept_range(-2.5, 12.5, 0.0, 13.0, 0.25, dragged=True) == (-3.25, 16.25)
    # the redraws of a drag change a range only when it moves: the nose 0.1 mm higher leaves the lift plot's
    d = _designer()
    lift = d.figures["lift"].y_range
    before = (lift.start, lift.end)
    _request(d, "end", "nose", 0.0, 9.1)
    assert d.session.document["valves"]["intake"]["max_lift_mm"] == pytest.approx(9.1)
    assert (lift.start, lift.end) == before
    # the moves of a drag keep it while the lift stays inside it (the handle under the pointer: a CI run's drag to
    # 10.0025 mm refitted the 9 mm lift's (-2.25, 11.25) mm under the pointer, 10.0025 x 1.125 > 11.25); the release
    # refits it: 10.2 mm with a quarter of its span of room, (-2.55, 12.75)
    _request(d, "move", "nose", 0.0, 10.2, seq=2, finish=False)
    assert np.nanmax(d.curves.data["lift"]) == pytest.approx(10.2, abs=1e-3)
    assert (lift.start, lift.end) == before
    _request(d, "end", "nose", 0.0, 10.2, seq=3)
    assert (lift.start, lift.end) == pytest.approx((-2.55, 12.75), abs=1e-3)


def test_thinned_curve_keeps_what_a_plot_shows():
    # sin x on [0, 2 pi] in 2001 samples with one sample raised by 5 (a spike a plot must show): every-k-th sampling
    # drops it; the thinned curve keeps it, the ends, and the extremes of sin x (1 at pi/2, -1 at 3 pi/2, samples
    # pi/1000 apart: within 1 - cos(pi/2000) = 1.2e-6 of the closed form's)
    x = np.linspace(0.0, 2.0 * np.pi, 2001)
    y = np.sin(x)
    y[777] += 5.0
    tx, ty = thinned(x, y, buckets=100)
    assert len(tx) <= 202 and np.all(np.diff(tx) > 0.0)
    assert (tx[0], ty[0], tx[-1], ty[-1]) == (x[0], y[0], x[-1], y[-1])
    assert (x[777], y[777]) in set(zip(tx, ty, strict=True))
    spikeless = np.delete(np.arange(len(tx)), np.flatnonzero(tx == x[777]))
    assert ty[spikeless].max() == pytest.approx(1.0, abs=1.3e-6)
    assert ty.min() == pytest.approx(-1.0, abs=1.3e-6)
    # every sample between two kept points lies within their span of a bucket: no sample above the kept maximum or
    # below the kept minimum of its bucket (the line covers the pixels the whole curve covers)
    bucket = np.minimum((x / (2.0 * np.pi) * 100).astype(int), 99)
    kept_bucket = np.minimum((tx / (2.0 * np.pi) * 100).astype(int), 99)
    for b in range(100):
        assert y[bucket == b].max() == ty[kept_bucket == b].max()
        assert y[bucket == b].min() == ty[kept_bucket == b].min()
    # a short curve and one with a gap as they are
    assert thinned(x[:150], y[:150], buckets=100)[0].size == 150
    gap = y.copy()
    gap[10] = np.nan
    assert thinned(x, gap, buckets=100)[1].size == 2001
