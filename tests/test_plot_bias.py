""":func:`coinflight.plotting.bias.plot_bias`: the region that matters, the mirror solution."""

from __future__ import annotations

import pytest

from coinflight.plotting.bias import ZOOM_P, ZOOM_PSI, plot_bias, zoom_limits
from coinflight.studies.bias import psi_for_probability, same_side_probability

MEASURED = 0.5077  # Bartoš et al.: 178,078 same-side of 350,757 flips (0.50770)


def _vertical_lines(ax):
    return {
        ln.get_label(): float(ln.get_xdata()[0])
        for ln in ax.get_lines()
        if len(ln.get_xdata()) == 2 and ln.get_xdata()[0] == ln.get_xdata()[1]
    }


def test_zoom_on_the_measured_band_and_both_solutions():
    psi = float(psi_for_probability(MEASURED, degrees=True))
    fig = plot_bias(measured=MEASURED, psi_measured=psi, measured_interval=(0.5061, 0.5094))
    full, zoom = fig.axes
    assert full.get_xlim() == (0.0, 180.0)
    assert zoom.get_xlim() == ZOOM_PSI and zoom.get_ylim() == ZOOM_P
    marks = _vertical_lines(zoom)
    mirror = marks[f"its mirror 180° − ψ = {180 - psi:.2f}° (same p)"]
    assert marks[f"ψ = {psi:.2f}°"] == pytest.approx(psi)
    assert mirror == pytest.approx(180.0 - psi)
    # p(ψ) = p(180° − ψ): both explain the measured rate.
    for angle in (psi, mirror):
        assert same_side_probability(angle, degrees=True) == pytest.approx(MEASURED, abs=1e-9)
    labels = zoom.get_legend_handles_labels()[1]
    assert "measured interval [0.5061, 0.5094]" in labels and "measured 0.5077" in labels
    # The zoomed panel is the taller one: most of the figure shows P within 0.49-0.53.
    assert zoom.get_position().height > 2 * full.get_position().height
    # both panels say what their x axis is; the legend lies below them, over no curve
    assert full.get_xlabel() and zoom.get_xlabel()
    assert zoom.get_legend() is None and len(fig.legends) == 1
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg(fig).draw()
    legend = fig.legends[0].get_window_extent()
    assert legend.y1 < zoom.get_window_extent().y0


def test_zoom_widens_only_to_show_what_was_asked():
    assert zoom_limits(None, None) == (ZOOM_PSI, ZOOM_P)
    assert zoom_limits(MEASURED, 81.16) == (ZOOM_PSI, ZOOM_P)
    (lo_psi, hi_psi), (lo_p, hi_p) = zoom_limits(0.6, 50.0)
    assert (lo_psi, hi_psi) == (45.0, 135.0) and hi_p == pytest.approx(0.605)
    assert lo_p == ZOOM_P[0]
