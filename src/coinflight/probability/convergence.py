"""How the estimates approach the exact value as configurations or events grow (Figs 2a-b, 3a-b).

Stefan & Cheche plot, for each setting, method A (grid, against the number of configurations)
and method B (random events from a 100-cell grid, against the number of events) approaching
1/2. :func:`convergence` computes those series (and QMC's), with the exact value as reference.
"""

from __future__ import annotations

import csv
import io
import json
import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from coinflight import _validation as v
from coinflight._files import write_text
from coinflight.model.ensemble import TossDistribution
from coinflight.probability import registry
from coinflight.probability._runner import Executor, Progress, check_count
from coinflight.probability.streams import SeedLike, reported_seed, seed_sequence

DEFAULT_METHODS = ("grid", "monte-carlo")
"""The paper's methods A and B. Each method's default sizes are its registry entry's
``series`` (:mod:`coinflight.probability.registry`)."""
COLUMNS = ("method", "n", "samples", "p_heads", "stderr", "ci95_low", "ci95_high")


@dataclass(frozen=True)
class ConvergencePoint:
    """One estimate of a convergence series."""

    method: str
    n: int
    samples: int
    p_heads: float
    stderr: float | None = None
    ci95: tuple[float, float] | None = None


@dataclass(frozen=True)
class Convergence:
    """Series of estimates against size, with the exact reference (None if not available)."""

    points: tuple[ConvergencePoint, ...]
    exact: float | None
    exact_how: str | None
    seed: int | None
    """The seed of the random series; None when no random method ran."""
    grid_cells: int | None
    description: str = ""
    parameters: dict[str, str] = field(default_factory=dict)
    coarse_limit: float | None = None
    """Method B's limit: the exact count of the ``grid_cells`` grid (None without method B)."""

    def series(self, method: str) -> tuple[ConvergencePoint, ...]:
        """The points of one method, in order of size."""
        return tuple(p for p in self.points if p.method == method)

    @property
    def methods(self) -> tuple[str, ...]:
        return tuple(dict.fromkeys(p.method for p in self.points))

    def rows(self) -> list[dict[str, Any]]:
        """One dictionary per point with the :data:`COLUMNS` (blank where not applicable)."""
        out = []
        for p in self.points:
            lo, hi = p.ci95 if p.ci95 is not None else (None, None)
            out.append(
                {
                    "method": p.method,
                    "n": p.n,
                    "samples": p.samples,
                    "p_heads": p.p_heads,
                    "stderr": p.stderr,
                    "ci95_low": lo,
                    "ci95_high": hi,
                }
            )
        return out

    def to_dict(self) -> dict[str, Any]:
        return {
            "exact": self.exact,
            "exact_how": self.exact_how,
            "seed": self.seed,
            "grid_cells": self.grid_cells,
            "coarse_limit": self.coarse_limit,
            "parameters": self.parameters,
            "points": self.rows(),
        }

    def to_csv(self) -> str:
        buf = io.StringIO()
        writer = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
        writer.writeheader()
        for row in self.rows():
            writer.writerow({k: ("" if v is None else v) for k, v in row.items()})
        return buf.getvalue()

    def write(self, prefix: str | os.PathLike[str]) -> list[Path]:
        """Write ``prefix.csv`` and ``prefix.json`` (with
        :func:`coinflight._provenance.provenance`), each whole or not at all."""
        from coinflight._provenance import provenance

        base = Path(prefix)
        paths = [base.with_name(base.name + ".csv"), base.with_name(base.name + ".json")]
        made = {**self.to_dict(), **provenance()}
        texts = [self.to_csv(), json.dumps(made, indent=2, allow_nan=False) + "\n"]
        for path, text in zip(paths, texts, strict=True):
            write_text(path, text)
        return paths


def convergence(
    dist: TossDistribution,
    methods: Sequence[str] = DEFAULT_METHODS,
    *,
    seed: SeedLike = None,
    grid_cells: int | None = 100,
    executor: Executor | None = None,
    threads: int | None = None,
    progress: Progress | None = None,
    **sizes: Sequence[int] | None,
) -> Convergence:
    """Estimates of P(heads) for growing sizes, per method, and the exact value.

    Parameters
    ----------
    methods : sequence of str
        Methods with a series in :mod:`coinflight.probability.registry` (built in: grid,
        monte-carlo, qmc). ``grid`` is method A; ``monte-carlo`` with ``grid_cells=100`` is
        method B (None: plain Monte Carlo).
    seed : int, optional
        One seed for all random series (None: a fresh one, reported). Monte Carlo runs of
        growing size share their first tosses (:mod:`coinflight.probability.streams`), so the
        series is a running estimate. A TypeError when no seeded method is asked for; the
        result's seed is then None.
    grid_cells : int, optional
        Passed to the methods that take it (monte-carlo: method B's cells per parameter).
    **sizes : sequence of int
        Per method, its sizes under its ``series_option``: ``grid_sizes`` (cells per
        parameter), ``event_sizes`` (monte-carlo events), ``qmc_sizes`` (points: 16 × powers
        of two), ``NAME_sizes`` for a registered NAME; default the entry's ``series``. Sizes
        for a method not in ``methods`` are a TypeError (they would be ignored).
    """
    from coinflight.probability import estimate

    with_series = registry.names(series=True)
    chosen = [registry.get(m, with_series, " for convergence") for m in methods]
    if not chosen:
        raise ValueError("give at least one method")
    by_option = {e.series_option: e for e in registry.estimators() if e.series}
    for option, value in sizes.items():
        if option not in by_option:
            raise TypeError(
                f"convergence() got an unexpected keyword argument {option!r}; sizes are "
                f"{', '.join(by_option)}"
            )
        if value is not None and by_option[option] not in chosen:
            raise TypeError(
                f"{option} given but {by_option[option].name!r} is not among the methods"
            )
    series = {e.name: sizes.get(e.series_option) or e.series for e in chosen}
    for e in chosen:
        if sizes.get(e.series_option) is not None and not sizes[e.series_option]:
            raise ValueError(f"no sizes given for {e.name}")
    the_seed: int | None = None
    if any(e.seeded for e in chosen):
        the_seed = reported_seed(seed_sequence(seed))
    elif seed is not None:
        seeded = ", ".join(registry.names(seeded=True))
        raise TypeError(f"seed given but no random method ({seeded}) among {methods}")
    check_work(dist, [e.name for e in chosen], series)
    try:
        ex = estimate(dist, "exact")
        exact, how = ex.p_heads, str(ex.details["how"])
    except ValueError:
        exact, how = None, None
    common: dict[str, Any] = {"executor": executor, "threads": threads, "progress": progress}
    points = []
    takes_cells = [e for e in chosen if "grid_cells" in e.options]
    for e in chosen:
        options = dict(common)
        if e.seeded:
            options["seed"] = the_seed
        if e in takes_cells:
            options["grid_cells"] = grid_cells
        for s in sorted(series[e.name]):
            r = estimate(dist, e.name, n=s, **options)
            points.append(
                ConvergencePoint(e.name, s, int(r.samples or s), r.p_heads, r.stderr, r.ci95)
            )
    coarse = None
    if takes_cells and grid_cells:  # method B converges to the exact count of its coarse grid
        coarse = estimate(dist, "grid", n=grid_cells, executor=executor, threads=threads).p_heads
    return Convergence(
        coarse_limit=coarse,
        points=tuple(points),
        exact=exact,
        exact_how=how,
        seed=the_seed,
        grid_cells=grid_cells if takes_cells else None,
        description=dist.describe(),
        parameters={name: d.describe() for name, d in dist.parameters.items()},
    )


def check_work(
    dist: TossDistribution, methods: Sequence[str], sizes: dict[str, Sequence[int]]
) -> None:
    """Refuse, before computing anything, a size no single estimate accepts or a series whose
    sizes add up to more than :data:`coinflight._validation.MAX_RUN_SECONDS` of work."""
    from coinflight.outcomes.hand import HAND_CATCH

    seconds = 0.0
    for m in methods:
        e = registry.get(m)
        for s in sizes[m]:
            check_count(f"{m} size", s)
            if e.work is not None:
                seconds += e.work(dist, s, HAND_CATCH)
    v.work_bound(
        f"the convergence series ({', '.join(methods)})",
        seconds,
        v.MAX_RUN_SECONDS,
        "s of work",
        "give fewer or smaller sizes",
    )


def work_total(dist: TossDistribution, methods: Sequence[str], **sizes: Sequence[int]) -> int:
    """Work units :func:`convergence` reports through ``progress`` (for progress bars)."""
    k = len(dist.ranged)
    total = 0
    for m in methods:
        e = registry.get(m)
        total += sum(e.work_units(k, s) for s in sizes.get(e.series_option, e.series))
    return total


_SERIES_CONSTANTS = {
    "DEFAULT_GRID_SIZES": "grid",
    "DEFAULT_EVENT_SIZES": "monte-carlo",
    "DEFAULT_QMC_SIZES": "qmc",
}


def __getattr__(name: str) -> Any:
    """The former constants of the default sizes, now each estimator's ``series``."""
    if name in _SERIES_CONSTANTS:
        return registry.get(_SERIES_CONSTANTS[name]).series
    raise AttributeError(name)
