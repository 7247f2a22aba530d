"""One look for every coinflight figure: colour-blind-safe colours, labels, saving."""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from coinflight._files import check_name, check_writable, replacing_all

if TYPE_CHECKING:
    from matplotlib.figure import Figure

# Okabe & Ito (2008) colour-blind-safe palette.
HEADS_COLOR = "#0072B2"  # blue
TAILS_COLOR = "#E69F00"  # orange
EDGE_COLOR = "#009E73"  # bluish green
LAUNCH_COLOR = "#D55E00"  # vermillion: the coin at launch (red in the paper's figures)
CATCH_COLOR = "#0072B2"  # blue: the coin at catch (as in the paper)
EXACT_COLOR = "#000000"

COLOR_NAMES = {
    "#000000": "black",
    "#E69F00": "orange",
    "#56B4E9": "sky blue",
    "#009E73": "bluish green",
    "#F0E442": "yellow",
    "#0072B2": "blue",
    "#D55E00": "vermillion",
    "#CC79A7": "reddish purple",
}
"""Okabe & Ito's (2008) names of their palette's colours: the words captions use."""


def color_name(color: str) -> str:
    """The palette's name of ``color`` (a hex string, any case), for a caption.

    ValueError for a colour outside the palette (a caption must not guess a name).
    """
    try:
        return COLOR_NAMES[color.upper()]
    except KeyError:
        raise ValueError(
            f"colour {color!r} is not in the Okabe & Ito palette ({', '.join(COLOR_NAMES)})"
        ) from None


class MethodStyle(NamedTuple):
    """How an estimator's series looks in figures."""

    color: str
    marker: str


METHOD_STYLES: dict[str, MethodStyle] = {
    "exact": MethodStyle(EXACT_COLOR, "o"),
    "grid": MethodStyle("#0072B2", "o"),  # method A (blue in the paper)
    "monte-carlo": MethodStyle("#D55E00", "o"),  # method B (red in the paper)
    "qmc": MethodStyle("#009E73", "o"),
}
"""The colour and marker of each built-in estimator in figures. Code that registers an estimator
may add its own entry here; without one it gets a look of its own from :func:`method_style`."""
OTHER_COLORS = ("#CC79A7", "#56B4E9", "#E69F00", "#F0E442")
"""The palette's colours the built-in estimators leave free, in the order other estimators get
them."""
OTHER_MARKERS = ("s", "^", "D", "v", "P")
"""The markers other estimators get, in turn (with four colours, 20 distinct looks)."""


def method_style(method: str) -> MethodStyle:
    """The colour and marker of the estimator ``method`` (a name of
    :func:`coinflight.probability.registry.names`; ValueError naming the choices otherwise).

    Its entry in :data:`METHOD_STYLES`; else, for the k-th registered estimator without one
    (in the order of registration), the k-th of :data:`OTHER_COLORS` and of
    :data:`OTHER_MARKERS`, each taken in turn.
    """
    from coinflight.probability import registry

    registry.get(method)
    if method in METHOD_STYLES:
        return METHOD_STYLES[method]
    k = [name for name in registry.names() if name not in METHOD_STYLES].index(method)
    return MethodStyle(OTHER_COLORS[k % len(OTHER_COLORS)], OTHER_MARKERS[k % len(OTHER_MARKERS)])


def method_color(method: str) -> str:
    """The colour of the estimator ``method`` in figures (:func:`method_style`)."""
    return method_style(method).color


FIGSIZE = (6.4, 4.8)


def new_figure(figsize: tuple[float, float] = FIGSIZE, **kwargs: object) -> Figure:
    """A figure that needs no pyplot state (safe in scripts, tests and notebooks)."""
    from matplotlib.figure import Figure

    return Figure(figsize=figsize, layout="constrained", **kwargs)  # type: ignore[arg-type]


FIRST_FORMATS = ("png", "svg", "pdf")
"""The formats named first in messages and help; matplotlib writes several more."""
NO_SUFFIX = "without a suffix, FILE.png and FILE.svg"
"""What a figure path without a suffix gives (for the options' help)."""


def image_formats() -> list[str]:
    """The image formats (file suffixes without the dot) matplotlib can write, PNG first."""
    from matplotlib.backend_bases import FigureCanvasBase

    known = set(FigureCanvasBase.get_supported_filetypes())
    return [f for f in FIRST_FORMATS if f in known] + sorted(known - set(FIRST_FORMATS))


def figure_paths(
    path: str | os.PathLike[str], option: str = "path", formats: Iterable[str] | None = None
) -> list[Path]:
    """The files a figure saved to ``path`` becomes, checked before anything is computed.

    ``path`` with a suffix is one file in that format; without one, one file per format in
    ``formats`` (default PNG and SVG). ValueError, naming ``option`` (the command-line option,
    such as ``--out``), for a suffix matplotlib cannot write or a location that cannot be
    written.
    """
    target = Path(path)
    check_name(path)  # '.' or '' would otherwise be an internal error of with_suffix
    if formats is None:
        formats = [target.suffix] if target.suffix else ["png", "svg"]
    paths = [target.with_suffix("." + fmt.lstrip(".")) for fmt in formats]
    allowed = image_formats()
    for p in paths:
        fmt = p.suffix.lstrip(".").lower()
        if fmt not in allowed:
            raise ValueError(
                f"{option} {str(target)!r}: cannot write a figure as .{fmt}; the suffix must be "
                f"one of {', '.join('.' + f for f in allowed)} ({NO_SUFFIX})"
            )
    for p in paths:
        check_writable(p)
    return paths


def save_figure(
    fig: Figure, path: str | os.PathLike[str], formats: Iterable[str] | None = None, dpi: int = 150
) -> list[Path]:
    """Save ``fig`` whole or not at all, to the files :func:`figure_paths` names.

    ``path`` with a suffix is written in that format; without one, it is written once per format
    in ``formats`` (default PNG and SVG). The files are staged and renamed into place together
    (:func:`coinflight._files.replacing_all`), so an interrupted run leaves no half-written
    figure, and a PNG never appears without its SVG. PNG, SVG and PDF files say where they
    came from in their metadata (:func:`figure_metadata`).
    """
    paths = figure_paths(path, formats=formats)
    with replacing_all(paths) as temps:
        for p, tmp in zip(paths, temps, strict=True):
            fmt = p.suffix.lstrip(".").lower()
            fig.savefig(tmp, format=fmt, dpi=dpi, metadata=figure_metadata(fmt))
    return paths


def figure_metadata(fmt: str) -> dict[str, str] | None:
    """What a figure file of format ``fmt`` records of where it came from
    (:func:`coinflight._provenance.provenance`): the coinflight version and, when a command
    made it, that command line. PNG: text chunks ``Software`` and ``Command``; SVG: the
    Dublin Core ``Creator`` and ``Source``; PDF: ``Creator`` and ``Subject``. None for the
    formats whose metadata matplotlib does not take the same way (their files carry none)."""
    import matplotlib

    from coinflight._provenance import provenance

    made = provenance()
    creator = f"coinflight {made['coinflight_version']} (Matplotlib {matplotlib.__version__})"
    command = made.get("command")
    keys = {
        "png": ("Software", "Command"),
        "svg": ("Creator", "Source"),
        "pdf": ("Creator", "Subject"),
    }
    if fmt not in keys:
        return None
    who, what = keys[fmt]
    return {who: creator} | ({what: command} if command is not None else {})
