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
from coinflight.probability._runner import Executor, Progress, check_count

DEFAULT_GRID_SIZES = (5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000)
"""Cells per parameter for method A, up to the paper's 5000."""
DEFAULT_EVENT_SIZES = (100, 300, 1000, 3000, 10**4, 3 * 10**4, 10**5, 3 * 10**5, 10**6, 10**7)
DEFAULT_QMC_SIZES = tuple(16 << k for k in range(2, 17))
DEFAULT_METHODS = ("grid", "monte-carlo")
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
        """Write ``prefix.csv`` and ``prefix.json``, each whole or not at all."""
        base = Path(prefix)
        paths = [base.with_name(base.name + ".csv"), base.with_name(base.name + ".json")]
        texts = [self.to_csv(), json.dumps(self.to_dict(), indent=2, allow_nan=False) + "\n"]
        for path, text in zip(paths, texts, strict=True):
            write_text(path, text)
        return paths


def convergence(
    dist: TossDistribution,
    methods: Sequence[str] = DEFAULT_METHODS,
    *,
    grid_sizes: Sequence[int] | None = None,
    event_sizes: Sequence[int] | None = None,
    qmc_sizes: Sequence[int] | None = None,
    seed: int | None = None,
    grid_cells: int | None = 100,
    executor: Executor | None = None,
    threads: int | None = None,
    progress: Progress | None = None,
) -> Convergence:
    """Estimates of P(heads) for growing sizes, per method, and the exact value.

    Parameters
    ----------
    methods : sequence of {"grid", "monte-carlo", "qmc"}
        ``grid`` is method A; ``monte-carlo`` with ``grid_cells=100`` is method B (None: plain
        Monte Carlo).
    grid_sizes, event_sizes, qmc_sizes : sequence of int, optional
        Cells per parameter (grid), events (monte-carlo), points (qmc: 16 × powers of two);
        default :data:`DEFAULT_GRID_SIZES` etc. Sizes for a method not in ``methods`` are a
        TypeError (they would be ignored).
    seed : int, optional
        One seed for all random series. Monte Carlo runs of growing size share their first
        tosses (see :mod:`coinflight.probability.monte_carlo`), so the series is a running
        estimate. A TypeError when no random method (monte-carlo, qmc) is asked for; the
        result's seed is then None.
    """
    from coinflight.probability import estimate
    from coinflight.probability.streams import reported_seed, seed_sequence

    allowed = ("grid", "monte-carlo", "qmc")
    for m in methods:
        if m not in allowed:
            raise ValueError(
                f"unknown method {m!r} for convergence; choose from {', '.join(allowed)}"
            )
    if not methods:
        raise ValueError("give at least one method")
    given = {"grid": grid_sizes, "monte-carlo": event_sizes, "qmc": qmc_sizes}
    names = {"grid": "grid_sizes", "monte-carlo": "event_sizes", "qmc": "qmc_sizes"}
    for m, value in given.items():
        if value is not None and m not in methods:
            raise TypeError(f"{names[m]} given but {m!r} is not among the methods")
    defaults: dict[str, Sequence[int]] = {
        "grid": DEFAULT_GRID_SIZES,
        "monte-carlo": DEFAULT_EVENT_SIZES,
        "qmc": DEFAULT_QMC_SIZES,
    }
    sizes = {m: defaults[m] if value is None else value for m, value in given.items()}
    random_methods = [m for m in methods if m in ("monte-carlo", "qmc")]
    the_seed: int | None = None
    if random_methods:
        the_seed = reported_seed(seed_sequence(seed))
    elif seed is not None:
        raise TypeError(f"seed given but no random method (monte-carlo, qmc) among {methods}")
    for m in methods:
        if not sizes[m]:
            raise ValueError(f"no sizes given for {m}")
        for s in sizes[m]:
            check_count(f"{m} size", s)
    check_work(dist, methods, sizes)
    try:
        ex = estimate(dist, "exact")
        exact, how = ex.p_heads, str(ex.details["how"])
    except ValueError:
        exact, how = None, None
    common: dict[str, Any] = {"executor": executor, "threads": threads, "progress": progress}
    points = []
    for m in methods:
        for s in sorted(sizes[m]):
            if m == "grid":
                r = estimate(dist, "grid", n=s, **common)
            elif m == "monte-carlo":
                r = estimate(dist, m, n=s, seed=the_seed, grid_cells=grid_cells, **common)
            else:
                r = estimate(dist, m, n=s, seed=the_seed, **common)
            points.append(ConvergencePoint(m, s, int(r.samples or s), r.p_heads, r.stderr, r.ci95))
    coarse = None
    if "monte-carlo" in methods and grid_cells:
        coarse = estimate(dist, "grid", n=grid_cells, executor=executor, threads=threads).p_heads
    return Convergence(
        coarse_limit=coarse,
        points=tuple(points),
        exact=exact,
        exact_how=how,
        seed=the_seed,
        grid_cells=grid_cells if "monte-carlo" in methods else None,
        description=dist.describe(),
        parameters={name: d.describe() for name, d in dist.parameters.items()},
    )


def check_work(
    dist: TossDistribution, methods: Sequence[str], sizes: dict[str, Sequence[int]]
) -> None:
    """Refuse, before computing anything, a size no single estimate accepts or a series whose
    sizes add up to more than :data:`coinflight._validation.MAX_RUN_SECONDS` of work."""
    from coinflight.outcomes.base import HAND_CATCH
    from coinflight.probability import grid, monte_carlo, qmc

    seconds = 0.0
    for m in methods:
        for s in sizes[m]:
            check_count(f"{m} size", s)
            if m == "grid":
                seconds += grid.check_work(dist, s)
            elif m == "monte-carlo":
                monte_carlo.check_work(s)
                seconds += s / HAND_CATCH.rate
            else:
                qmc.check_work(s)
                seconds += s / qmc.rate()
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
    if "grid" in methods:
        total += sum(s**k for s in sizes.get("grid_sizes", DEFAULT_GRID_SIZES))
    if "monte-carlo" in methods:
        total += sum(sizes.get("event_sizes", DEFAULT_EVENT_SIZES))
    if "qmc" in methods:
        total += sum(sizes.get("qmc_sizes", DEFAULT_QMC_SIZES))
    return total
