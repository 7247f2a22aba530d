"""The one result type of every probability method."""

from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, field
from typing import TYPE_CHECKING, Any

from coinflight.probability.streams import reported_seed

if TYPE_CHECKING:
    import numpy as np
    import pandas as pd


@dataclass(frozen=True)
class ProbabilityResult:
    """P(heads), P(tails) (and P(edge), 0 for a hand catch) for a distribution of tosses.

    Attributes
    ----------
    p_heads, p_tails, p_edge : float
        Probabilities of each face up at catch; they sum to 1.
    p_same_side : float
        Probability that the coin shows the face it started with.
    method : str
        ``exact``, ``grid``, ``monte-carlo`` or ``qmc``.
    n : int or None
        The method's size parameter: grid cells per ranged parameter (``grid``), tosses
        (``monte-carlo``), points (``qmc``); None for ``exact``.
    samples : int or None
        Configurations or events actually evaluated (N^k for the grid).
    stderr : float or None
        Standard error of ``p_heads`` (sampling methods); None where there is none.
    ci95 : (float, float) or None
        95 % interval for ``p_heads``: Wilson score interval (Monte Carlo), Student t over the
        randomisations (QMC); None for ``exact`` and ``grid`` (deterministic results).
    error_estimate : float or None
        Estimated bound on the numerical error of ``exact`` (quadrature's estimate; 0 for
        closed forms); not a confidence interval.
    counts : (int, int, int) or None
        (tails, heads, edge) counts for the counting methods.
    seed : int or None
        The seed that reproduces the result (random methods).
    elapsed : float
        Wall time, s.
    details : dict
        Method options (``grid_cells``, ``replicates``, how ``exact`` integrated, …).

    Examples
    --------
    >>> from coinflight import TossDistribution, Uniform, estimate
    >>> spins = {"omega_x": Uniform(60, 90), "omega_y": 10}
    >>> tosses = TossDistribution(**spins, flight_time=Uniform(0.6, 0.9))
    >>> result = estimate(tosses, "exact")  # Stefan & Cheche Fig 3a
    >>> result.describe()
    'P(heads) = 0.497212 (closed form)'
    >>> row = result.to_dict()  # JSON-ready, as coinflight probability --json prints it
    >>> row["method"], round(row["p_tails"], 6), row["ci95"]
    ('exact', 0.502788, None)
    """

    p_heads: float
    p_tails: float
    p_edge: float
    p_same_side: float
    method: str
    n: int | None = None
    samples: int | None = None
    stderr: float | None = None
    ci95: tuple[float, float] | None = None
    error_estimate: float | None = None
    counts: tuple[int, int, int] | None = None
    seed: int | None = None
    elapsed: float = 0.0
    details: dict[str, Any] = field(default_factory=dict, compare=False)

    def to_dict(self) -> dict[str, Any]:
        """Plain JSON-ready dictionary (the CLI's ``--json``)."""
        out = asdict(self)
        if self.ci95 is not None:
            out["ci95"] = list(self.ci95)
        if self.counts is not None:
            out["counts"] = {
                "tails": self.counts[0],
                "heads": self.counts[1],
                "edge": self.counts[2],
            }
        return out

    def to_row(self) -> dict[str, Any]:
        """One flat row for a table: the fields of :meth:`to_dict` with ``ci95`` as
        ``ci95_low``/``ci95_high``, ``counts`` as ``tails``/``heads``/``edge`` and each detail as
        ``details.KEY`` (None where the method has none)."""
        out = self.to_dict()
        ci = out.pop("ci95")
        counts = out.pop("counts")
        details = out.pop("details")
        out["ci95_low"], out["ci95_high"] = ci if ci is not None else (None, None)
        for face in ("tails", "heads", "edge"):
            out[face] = None if counts is None else counts[face]
        out.update({f"details.{key}": value for key, value in details.items()})
        return out

    def to_frame(self) -> pd.DataFrame:
        """A one-row pandas DataFrame of :meth:`to_row` (needs ``pip install pandas``)."""
        return require_pandas().DataFrame([self.to_row()])

    def describe(self) -> str:
        """The probability with its uncertainty, readable at a glance."""
        p = self.p_heads
        if self.stderr is not None and self.ci95 is not None:
            unc = f" ± {self.stderr:.2g} s.e. (95 % CI {self.ci95[0]:.4f} – {self.ci95[1]:.4f})"
        elif self.error_estimate is not None and self.error_estimate > 0:
            unc = f" ± {self.error_estimate:.1g} (quadrature error bound)"
        elif self.method == "exact":
            unc = " (closed form)"
        else:
            unc = ""
        return f"P(heads) = {p:.6f}{unc}"

    def describe_run(self) -> str:
        """How the result was made, one line (the command line's ``method NAME:`` line).

        The integral (exact, with any quadrature warning); the cells and configurations
        (grid); the tosses or points, the variance reduction and the seed (monte-carlo, qmc).
        A method registered from outside gets its size n, the samples where they differ from
        n, and its seed.
        """
        d = self.details
        mode = d.get("variance_reduction")
        if self.method == "exact":
            warning = d.get("warning")
            return str(d["how"]) + (f"; quadrature warning: {warning}" if warning else "")
        if self.method == "grid":
            return f"{self.n} cells per ranged parameter, {self.samples:,} configurations"
        if self.method == "monte-carlo" and mode:
            parts = [f"{self.n:,} spins, {mode} (closed form over T)"]
        elif self.method == "monte-carlo":
            cells = d.get("grid_cells")
            drawn = f" drawn from {cells} cells (method B)" if cells else ""
            parts = [f"{self.n:,} tosses{drawn}"]
        elif self.method == "qmc":
            parts = [f"{self.n:,} Sobol points in {d['replicates']} scramblings"]
            parts += [str(mode)] if mode else []
        else:
            parts = [f"n = {self.n:,}"] if self.n is not None else []
            if self.samples is not None and self.samples != self.n:
                parts.append(f"{self.samples:,} samples")
        if self.seed is not None:
            parts.append(f"seed {self.seed}")
        return ", ".join(parts)


def require_pandas() -> Any:
    """The pandas module, or an ImportError saying how to install it (it is optional)."""
    try:
        import pandas
    except ImportError:
        raise ImportError(
            "DataFrames need pandas, which coinflight does not install: pip install pandas"
        ) from None
    return pandas


Z95 = 1.959963984540054
"""z with Φ(z) = 0.975: two-sided 95 % intervals."""


def wilson_interval(successes: int, n: int) -> tuple[float, float]:
    """95 % Wilson score interval for a binomial proportion.

    Notes
    -----
    Wilson (1927), JASA 22:209: centre (p + z²/2n)/(1 + z²/n), half-width
    z sqrt(p(1 − p)/n + z²/4n²)/(1 + z²/n). Written out rather than called from
    ``scipy.stats.binomtest(...).proportion_ci(method="wilson")``, which it equals (tested),
    because importing ``scipy.stats`` costs about 0.7 s, more than a small Monte Carlo run.
    """
    if n <= 0:
        raise ValueError(f"n must be positive, got {n}")
    p = successes / n
    z2 = Z95 * Z95
    denom = 1.0 + z2 / n
    centre = (p + z2 / (2 * n)) / denom
    half = Z95 * math.sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / denom
    return (max(0.0, centre - half), min(1.0, centre + half))


def from_counts(
    counts: tuple[int, int, int],
    start_sign: float,
    method: str,
    **kwargs: Any,
) -> ProbabilityResult:
    """A result from (tails, heads, edge) counts, with Wilson interval and binomial stderr."""
    tails, heads, edge = (int(c) for c in counts)
    n = tails + heads + edge
    same = heads if start_sign > 0 else tails
    return ProbabilityResult(
        p_heads=heads / n,
        p_tails=tails / n,
        p_edge=edge / n,
        p_same_side=same / n,
        method=method,
        counts=(tails, heads, edge),
        **kwargs,
    )


def from_same_side(same: float, start_sign: float, method: str, **kwargs: Any) -> ProbabilityResult:
    """A result with no edge from P(same side) ``same``: P(heads) is ``same`` for tosses
    starting heads up (``start_sign`` > 0), else 1 − ``same``."""
    p = same if start_sign > 0 else 1.0 - same
    return ProbabilityResult(
        p_heads=p, p_tails=1.0 - p, p_edge=0.0, p_same_side=same, method=method, **kwargs
    )


def interval(p: float, half: float) -> tuple[float, float]:
    """The interval ``p`` ± ``half``, within [0, 1]."""
    return (max(0.0, p - half), min(1.0, p + half))


def sampled(
    n: int, stderr: float, ci95: tuple[float, float], root: np.random.SeedSequence, t0: float
) -> dict[str, Any]:
    """What every sampling method reports besides its estimate: its size ``n`` (also its
    samples), standard error, 95 % interval, the seed of ``root`` and the seconds since
    ``t0`` (``time.perf_counter``); keyword arguments of :func:`from_counts` and
    :func:`from_same_side`."""
    return {
        "n": n,
        "samples": n,
        "stderr": stderr,
        "ci95": ci95,
        "seed": reported_seed(root),
        "elapsed": time.perf_counter() - t0,
    }


@dataclass(frozen=True)
class BinomialEstimate:
    """A simulated binomial proportion: ``successes`` of ``n`` random trials.

    The one result type of the studies' simulations (same-side fraction, edge fraction).

    Attributes
    ----------
    successes, n : int
        Trials that succeeded, of ``n``.
    seed : int or None
        The seed that reproduces the trials (:mod:`coinflight.probability.streams`).

    Examples
    --------
    >>> e = BinomialEstimate(successes=60, n=100, seed=1)
    >>> e.p, round(e.stderr, 4), tuple(round(x, 4) for x in e.ci95)
    (0.6, 0.049, (0.502, 0.6906))
    """

    successes: int
    n: int
    seed: int | None = None

    def __post_init__(self) -> None:
        if not 0 <= self.successes <= self.n or self.n < 1:
            raise ValueError(f"need 0 ≤ successes ≤ n and n ≥ 1, got {self.successes} of {self.n}")

    @property
    def p(self) -> float:
        """The fraction of successes."""
        return self.successes / self.n

    @property
    def stderr(self) -> float:
        """Binomial standard error sqrt(p (1 − p) / n)."""
        return math.sqrt(self.p * (1.0 - self.p) / self.n)

    @property
    def ci95(self) -> tuple[float, float]:
        """95 % Wilson score interval (:func:`wilson_interval`)."""
        return wilson_interval(self.successes, self.n)

    def z(self, expected: float) -> float:
        """Standard errors from ``expected`` (0 when the standard error is 0)."""
        return (self.p - expected) / self.stderr if self.stderr > 0 else 0.0

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: successes, n, seed, p, stderr, ci95 (a list)."""
        return {**asdict(self), "p": self.p, "stderr": self.stderr, "ci95": list(self.ci95)}
