"""Published edge landings of thick coins (cylinders), with their provenance.

One record per reported point: :func:`edge_experiments` reads ``thick_coin_edges.txt`` (shipped
beside this module; the provenance of each row is in ``README.md``) into frozen
:class:`EdgeExperiment` records. :data:`EDGE_SOURCES` gives each ``source`` key's citation.

What is here, and what is not (searched 2026-11-23, see ``README.md``):

- ``standup_maths_2018``: hand flips, 1,000 per cylinder, at h/d = 1/(2√2) and 1/√3. Only the
  edge fractions (0.132, 0.410) are known, from a secondary table, not the counts: weak
  provenance.
- ``murray_teare_1993``: the US nickel's "about 1 in 6000", a model extrapolation
  (``kind="extrapolated"``), not a measurement.
- Not here because their numbers could not be read: Murray & Teare's own drop experiments,
  Yong & Mahadevan's (2011) tossing experiments, Gaek & Sukhov's (2024) robot launches,
  the experimental and simulated points Hernández-Navarro & Piñero (2021) compare with.

Examples
--------
>>> rows = edge_experiments(kind="measured")
>>> [(r.source, round(r.ratio, 3), r.n, r.fraction) for r in rows]
[('standup_maths_2018', 0.354, 1000, 0.132), ('standup_maths_2018', 0.577, 1000, 0.41)]
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from importlib.resources import files

from coinflight import _validation as v

EDGE_FILE = "thick_coin_edges.txt"
"""The file inside :mod:`coinflight.datasets` holding the rows."""

COLUMNS = ("source", "ratio", "n", "edges", "fraction", "kind", "setting", "how_read")
"""The CSV header of :data:`EDGE_FILE`, in order."""

KINDS: tuple[str, ...] = ("measured", "extrapolated")
"""What a row's number is: a count of real throws, or a model's extrapolation."""

EDGE_SOURCES: dict[str, str] = {
    "standup_maths_2018": (
        "Parker, M. and Hunt, H. (2018). How thick is a three-sided coin? Stand-up Maths "
        "(YouTube video). Fractions as tabulated in the README of github.com/iaroslav-ai/"
        "coin-experiment (2018); the video was not read."
    ),
    "murray_teare_1993": (
        "Murray, D. B. and Teare, S. W. (1993). Probability of a tossed coin landing on edge. "
        "Physical Review E 48, 2547-2552. doi:10.1103/PhysRevE.48.2547"
    ),
}
"""The citation of each ``source`` key used in the rows."""


@dataclass(frozen=True)
class EdgeExperiment:
    """One reported edge-landing point of a thick coin.

    Attributes
    ----------
    source : str
        The key of :data:`EDGE_SOURCES` (``"standup_maths_2018"``, ``"murray_teare_1993"``).
    ratio : float
        Thickness / diameter h/d of the object (nominal, as reported).
    n : int or None
        Number of throws, or None when the source does not give it.
    edges : int or None
        Number of edge landings, or None when only a fraction is given.
    fraction : float
        Edge fraction as reported (edges / n when both counts are given).
    kind : str
        ``"measured"`` (real throws) or ``"extrapolated"`` (a model's number, not data).
    setting : str
        How the objects were thrown: drop or toss, height, surface, object, as far as known.
    how_read : str
        Where the number comes from and how it was read (printed, read off a figure,
        secondary quotation) and how much to trust it.
    """

    source: str
    ratio: float
    n: int | None
    edges: int | None
    fraction: float
    kind: str
    setting: str
    how_read: str

    @property
    def citation(self) -> str:
        """The publication of :attr:`source`."""
        return EDGE_SOURCES[self.source]

    @property
    def stderr(self) -> float | None:
        """Binomial standard error sqrt(p (1 − p) / n) of :attr:`fraction`, None without n."""
        if self.n is None:
            return None
        return math.sqrt(self.fraction * (1.0 - self.fraction) / self.n)


def _number(name: str, text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{name} must be a number, got {text!r}") from None


def _whole(name: str, text: str) -> int | None:
    if not text.strip():
        return None
    try:
        return int(text)
    except ValueError:
        raise ValueError(f"{name} must be an integer, got {text!r}") from None


def _record(row: dict[str, str]) -> EdgeExperiment:
    """One row's record, each number checked in :mod:`coinflight._validation`'s words."""
    n = _whole("n", row["n"])
    if n is not None:
        v.count("n", n, minimum=1)
    edges = _whole("edges", row["edges"])
    if edges is not None:
        v.count("edges", edges, minimum=0, maximum=n)  # at most the throws, when known
    record = EdgeExperiment(
        source=row["source"],
        ratio=float(v.positive("ratio", _number("ratio", row["ratio"]))),
        n=n,
        edges=edges,
        fraction=float(v.in_range("fraction", _number("fraction", row["fraction"]), 0.0, 1.0)),
        kind=row["kind"],
        setting=row["setting"],
        how_read=row["how_read"],
    )
    v.choice("edge dataset source", record.source, EDGE_SOURCES)
    v.choice("edge dataset kind", record.kind, KINDS)
    return record


def parse_edge_experiments(text: str, where: str = EDGE_FILE) -> tuple[EdgeExperiment, ...]:
    """The records of a text in the layout of ``thick_coin_edges.txt``.

    Lines starting with ``#`` are comments; then a CSV header
    (source, ratio, n, edges, fraction, kind, setting, how_read) and one row per point. A row
    that does not read is refused in one line naming ``where`` (the file), its line and the
    value: a ratio h/d must be positive, n at least 1, edges between 0 and n, a fraction between
    0 and 1 (``thick_coin_edges.txt line 8: fraction must be between 0 and 1, got 1.5``).
    """
    lines = ("" if line.startswith("#") else line for line in text.splitlines())
    reader = csv.reader(lines)
    header: list[str] | None = None
    rows = []
    for values in reader:
        if not values:  # a comment or a blank line
            continue
        if header is None:
            header = values
            if tuple(header) != COLUMNS:
                raise ValueError(
                    f"{where} line {reader.line_num}: the header must be {','.join(COLUMNS)}, "
                    f"got {','.join(header)!r}"
                )
            continue
        try:
            if len(values) != len(header):
                raise ValueError(f"a row must have {len(header)} fields, got {len(values)}")
            rows.append(_record(dict(zip(header, values, strict=True))))
        except (TypeError, ValueError) as err:
            raise ValueError(f"{where} line {reader.line_num}: {err}") from None
    return tuple(rows)


def edge_experiments(kind: str | None = None) -> tuple[EdgeExperiment, ...]:
    """The shipped thick-coin edge points, in file order.

    Parameters
    ----------
    kind : {None, "measured", "extrapolated"}
        None: every row; ``"measured"``: only counts of real throws (what a simulation is
        compared with); ``"extrapolated"``: only models' numbers quoted by a source.
    """
    if kind is not None:
        v.choice("edge dataset kind", kind, KINDS)
    text = files("coinflight.datasets").joinpath(EDGE_FILE).read_text(encoding="utf-8")
    rows = parse_edge_experiments(text)
    return rows if kind is None else tuple(r for r in rows if r.kind == kind)


__all__ = [
    "COLUMNS",
    "EDGE_FILE",
    "EDGE_SOURCES",
    "KINDS",
    "EdgeExperiment",
    "edge_experiments",
    "parse_edge_experiments",
]
