"""sphinx-gallery scraper for the figures coinflight returns.

coinflight's figure functions build :class:`matplotlib.figure.Figure` objects without pyplot
(``coinflight.plotting.style.new_figure``), so sphinx-gallery's matplotlib scraper, which asks
pyplot for its open figures, does not see them. This scraper looks in the example's variables
after each code block for figures it has not shown yet (a figure, or a list or tuple of them)
and saves them the same way; pyplot's own figures are left to the matplotlib scraper, which
must run after this one (it closes them, and a closed pyplot figure looks like a plain one).
"""

from __future__ import annotations

from typing import Any

from sphinx_gallery.scrapers import figure_rst

_SEEN = "_coinflight_figures_shown"


def _figures(value: Any) -> list[Any]:
    from matplotlib.figure import Figure

    if isinstance(value, Figure):
        return [value]
    if isinstance(value, (list, tuple)):
        return [v for v in value if isinstance(v, Figure)]
    return []


class ReturnedFigures:
    """Callable scraper; a class with a fixed repr so that Sphinx can cache the config."""

    def __repr__(self) -> str:
        return "ReturnedFigures"

    def __call__(self, block: Any, block_vars: dict[str, Any], gallery_conf: Any) -> str:
        seen: set[int] = block_vars.setdefault(_SEEN, set())
        paths = []
        for name, value in list(block_vars["example_globals"].items()):
            if name.startswith("__"):
                continue
            for fig in _figures(value):
                if id(fig) in seen:
                    continue
                seen.add(id(fig))
                if getattr(fig.canvas, "manager", None) is not None:
                    continue  # a pyplot figure: the matplotlib scraper shows (and closes) it
                path = next(block_vars["image_path_iterator"])
                fig.savefig(path, dpi=100)
                paths.append(path)
        return figure_rst(paths, gallery_conf["src_dir"])
