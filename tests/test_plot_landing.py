"""The landing report's (e, μ) maps (coinflight.plotting.landing.plot_contact_maps): axes within
the physical ranges, each cell's value legible on its colour."""

from __future__ import annotations

import numpy as np

from coinflight.plotting.landing import plot_contact_maps
from coinflight.studies.landing import ContactMaps


def _maps() -> ContactMaps:
    e = np.linspace(0.0, 0.9, 10)  # the report's grid: e in [0, 0.9], μ in [0, 1]
    mu = np.linspace(0.0, 1.0, 11)
    same = 0.5 + 0.3 * np.sin(np.add.outer(3 * mu, 5 * e))  # both ends of the diverging map
    edge = np.outer(mu, e) / 0.9 * 0.2
    return ContactMaps(
        restitution=e,
        friction=mu,
        same=same,
        edge=edge,
        unsettled=np.zeros(same.shape, dtype=np.int64),
        n=400,
        seed=1,
        elapsed=0.0,
    )


def test_maps_show_only_the_values_computed():
    """One cell per computed (e, μ), its axis ticks those values: nothing below e = 0 or
    μ = 0 (the cells used to run half a cell beyond, to e = −0.05 and μ = −0.05)."""
    maps = _maps()
    for ax in plot_contact_maps(maps).axes[:2]:
        assert ax.get_xlim() == (0.0, 10.0) and ax.get_ylim() == (0.0, 11.0)
        xticks = [t.get_text() for t in ax.get_xticklabels()]
        yticks = [t.get_text() for t in ax.get_yticklabels()]
        assert xticks == [f"{e:g}" for e in maps.restitution]
        assert yticks == [f"{m:g}" for m in maps.friction]
        assert all(float(t) >= 0 for t in xticks + yticks)


def test_white_labels_on_dark_cells_black_on_light():
    """Each label's ink is the one of black and white with the greater WCAG contrast on its
    cell: the darkest cells of each map carry white labels, the lightest black ones."""
    maps = _maps()
    fig = plot_contact_maps(maps)
    for ax, values in zip(fig.axes[:2], (maps.same, maps.edge), strict=True):
        ink = {t.get_text(): t.get_color() for t in ax.texts}
        assert len(ax.texts) == values.size
        mesh = ax.collections[0]
        colours = mesh.cmap(mesh.norm(values.ravel()))
        luminance = colours[:, :3] @ [0.2126, 0.7152, 0.0722]  # a rough order, enough here
        darkest, lightest = (
            values.ravel()[np.argmin(luminance)],
            values.ravel()[np.argmax(luminance)],
        )
        assert ink[f"{darkest:.3f}"] == "white" and ink[f"{lightest:.3f}"] == "black"
