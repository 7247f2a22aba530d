"""One look for every coinflight figure: colour-blind-safe colours, labels, saving."""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from coinflight._files import replacing

if TYPE_CHECKING:
    from matplotlib.figure import Figure

# Okabe & Ito (2008) colour-blind-safe palette.
HEADS_COLOR = "#0072B2"  # blue
TAILS_COLOR = "#E69F00"  # orange
EDGE_COLOR = "#009E73"  # bluish green
LAUNCH_COLOR = "#D55E00"  # vermillion: the coin at launch ("red" in the paper's figures)
CATCH_COLOR = "#0072B2"  # blue: the coin at catch (as in the paper)
EXACT_COLOR = "#000000"
METHOD_COLORS = {
    "grid": "#0072B2",  # method A (blue in the paper)
    "monte-carlo": "#D55E00",  # method B (red in the paper)
    "qmc": "#009E73",
    "exact": "#000000",
}
FIGSIZE = (6.4, 4.8)


def new_figure(figsize: tuple[float, float] = FIGSIZE, **kwargs: object) -> Figure:
    """A figure that needs no pyplot state (safe in scripts, tests and notebooks)."""
    from matplotlib.figure import Figure

    return Figure(figsize=figsize, layout="constrained", **kwargs)  # type: ignore[arg-type]


def save_figure(
    fig: Figure, path: str | os.PathLike[str], formats: Iterable[str] | None = None, dpi: int = 150
) -> list[Path]:
    """Save ``fig`` whole or not at all.

    ``path`` with a suffix is written in that format; without one, it is written once per format
    in ``formats`` (default PNG and SVG). Each file is written to a temporary name in the same
    folder and renamed into place, so an interrupted run leaves no half-written figure.
    """
    target = Path(path)
    if formats is None:
        paths = (
            [target] if target.suffix else [target.with_suffix(".png"), target.with_suffix(".svg")]
        )
    else:
        paths = [target.with_suffix("." + fmt.lstrip(".")) for fmt in formats]
    for p in paths:
        fmt = p.suffix.lstrip(".").lower()
        if not fmt:
            raise ValueError(
                f"cannot tell the image format of {str(p)!r}: give a suffix such as .png"
            )
    for p in paths:
        with replacing(p) as tmp:
            fig.savefig(tmp, format=p.suffix.lstrip(".").lower(), dpi=dpi)
    return paths
