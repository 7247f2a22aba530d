"""Real flips: read per-person same-side counts and compare them with the precession model.

The file format is the one of Bartoš et al. (2023/2025), "Fair coins tend to land on the same
side they started: Evidence from 350,757 flips" (REFERENCES §6; ``../shared/data/README.md``):
whitespace-separated, one header line, columns

    person hsame hdiff tsame tdiff same flips

with ``hsame`` = started heads, landed heads; ``hdiff`` = started tails, landed heads; ``tsame``
= started tails, landed tails; ``tdiff`` = started heads, landed tails; ``same`` = hsame + tsame;
``flips`` = all four. Blank lines and lines starting with ``#`` are skipped.

Statistics are frequentist: a binomial proportion with a 95 % interval (Clopper-Pearson "exact"
by default, or Wilson), and an exact two-sided binomial test against 1/2 (``scipy.stats``).
Bartoš et al. print Bayesian credible intervals from a hierarchical model; on the pooled counts
both frequentist intervals give the same three printed digits, [0.506, 0.509] and
[0.498, 0.502].

The precession angle that explains a same-side rate is found by inverting Diaconis, Holmes &
Montgomery's p(ψ) (:mod:`coinflight.bias`). It is either a *fixed* angle shared by every flip
(``psi_sd = 0``), or the *mean* of a normal distribution of ψ with a stated spread ``psi_sd``.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

from coinflight import _validation as v

COLUMNS = ("person", "hsame", "hdiff", "tsame", "tdiff", "same", "flips")
"""The columns of a counts file, in order (Bartoš et al.; ``../shared/data/README.md``)."""

INTERVAL_METHODS = ("exact", "wilson")
"""Binomial interval methods: Clopper-Pearson ("exact") and Wilson score, both scipy's."""

CONFIDENCE = 0.95


@dataclass(frozen=True)
class PersonCounts:
    """One line of a counts file: one person's flips, by starting and landing face."""

    person: str
    hsame: int
    hdiff: int
    tsame: int
    tdiff: int
    line: int = 0

    @property
    def same(self) -> int:
        """Flips landing on the side they started: hsame + tsame."""
        return self.hsame + self.tsame

    @property
    def heads(self) -> int:
        """Flips landing heads up: hsame + hdiff."""
        return self.hsame + self.hdiff

    @property
    def flips(self) -> int:
        """All flips: hsame + hdiff + tsame + tdiff."""
        return self.hsame + self.hdiff + self.tsame + self.tdiff


@dataclass(frozen=True)
class CountsTable:
    """The rows of a counts file and where they came from."""

    rows: tuple[PersonCounts, ...]
    source: str = "<counts>"

    @property
    def flips(self) -> int:
        """All flips of all people."""
        return sum(r.flips for r in self.rows)

    @property
    def same(self) -> int:
        """All same-side flips."""
        return sum(r.same for r in self.rows)

    @property
    def heads(self) -> int:
        """All heads-up landings."""
        return sum(r.heads for r in self.rows)


def parse_counts(text: str, source: str = "<counts>") -> CountsTable:
    """Read a counts table from text; ValueError naming ``source``, the line and the fault.

    Every data line must have the 7 columns of :data:`COLUMNS`, non-negative integer counts,
    same = hsame + tsame, flips = hsame + hdiff + tsame + tdiff, and flips > 0; the header must
    name the columns in that order; a person may appear once.
    """
    rows: list[PersonCounts] = []
    seen: dict[str, int] = {}
    header_seen = False
    for lineno, raw in enumerate(text.splitlines(), start=1):
        fields = raw.split()
        if not fields or fields[0].startswith("#"):
            continue
        where = f"{source}, line {lineno}"
        if not header_seen:
            if tuple(f.lower() for f in fields) != COLUMNS:
                raise ValueError(
                    f"{where}: expected the header '{' '.join(COLUMNS)}', got {raw.strip()!r}"
                )
            header_seen = True
            continue
        if len(fields) != len(COLUMNS):
            raise ValueError(
                f"{where}: expected {len(COLUMNS)} columns ({' '.join(COLUMNS)}), "
                f"got {len(fields)}: {raw.strip()!r}"
            )
        person = fields[0]
        counts: list[int] = []
        for name, text_value in zip(COLUMNS[1:], fields[1:], strict=True):
            try:
                value = int(text_value)
            except ValueError:
                raise ValueError(
                    f"{where}: {name} must be a non-negative integer, got {text_value!r}"
                ) from None
            if value < 0:
                raise ValueError(f"{where}: {name} must be a non-negative integer, got {value}")
            counts.append(value)
        hsame, hdiff, tsame, tdiff, same, flips = counts
        row = PersonCounts(person, hsame, hdiff, tsame, tdiff, line=lineno)
        if same != row.same:
            raise ValueError(
                f"{where}: same = {same} but hsame + tsame = {hsame} + {tsame} = {row.same}"
            )
        if flips != row.flips:
            raise ValueError(
                f"{where}: flips = {flips} but hsame + hdiff + tsame + tdiff = {row.flips}"
            )
        if flips == 0:
            raise ValueError(f"{where}: person {person!r} has no flips")
        if person in seen:
            raise ValueError(f"{where}: person {person!r} already appears on line {seen[person]}")
        seen[person] = lineno
        rows.append(row)
    if not header_seen:
        raise ValueError(f"{source}: empty, expected the header '{' '.join(COLUMNS)}'")
    if not rows:
        raise ValueError(f"{source}: no data lines after the header")
    return CountsTable(tuple(rows), source)


def read_counts(path: str | os.PathLike[str]) -> CountsTable:
    """Read a counts file (see :func:`parse_counts`); ValueError if it cannot be read."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)
        raise ValueError(f"cannot read counts file {str(p)!r}: {reason}") from None
    return parse_counts(text, source=str(p))


@dataclass(frozen=True)
class Proportion:
    """A binomial proportion with its 95 % interval and a test against 1/2.

    Attributes
    ----------
    successes, trials : int
        Counts.
    estimate : float
        successes / trials.
    ci95 : (float, float)
        95 % confidence interval, by ``method``.
    method : str
        "exact" (Clopper-Pearson) or "wilson".
    p_value : float
        Two-sided exact binomial test of the hypothesis that the probability is 1/2.
    """

    successes: int
    trials: int
    estimate: float
    ci95: tuple[float, float]
    method: str
    p_value: float

    @property
    def stderr(self) -> float:
        """Binomial standard error sqrt(p (1 − p) / n)."""
        return math.sqrt(self.estimate * (1.0 - self.estimate) / self.trials)

    @property
    def z(self) -> float:
        """Distance from 1/2 in standard errors under the hypothesis p = 1/2: 2 √n (p − 1/2)."""
        return 2.0 * math.sqrt(self.trials) * (self.estimate - 0.5)


def proportion(successes: int, trials: int, method: str = "exact") -> Proportion:
    """Proportion, 95 % interval and exact binomial test against 1/2 (``scipy.stats.binomtest``).

    Notes
    -----
    Clopper & Pearson (1934) exact interval, or Wilson (1927) score interval, as computed by
    ``scipy.stats.binomtest(...).proportion_ci``.
    """
    from scipy.stats import binomtest

    v.choice("interval method", method, INTERVAL_METHODS)
    if trials < 1 or not 0 <= successes <= trials:
        raise ValueError(f"need 0 ≤ successes ≤ trials and trials ≥ 1, got {successes}/{trials}")
    test = binomtest(int(successes), int(trials), p=0.5)
    ci = test.proportion_ci(confidence_level=CONFIDENCE, method=method)
    return Proportion(
        successes=int(successes),
        trials=int(trials),
        estimate=successes / trials,
        ci95=(float(ci.low), float(ci.high)),
        method=method,
        p_value=float(test.pvalue),
    )


@dataclass(frozen=True)
class PsiFit:
    """The precession angle that reproduces a same-side rate, and its interval.

    Attributes
    ----------
    psi : float or None
        A fixed ψ (``sd == 0``) or the mean of a normal ψ distribution of spread ``sd``, rad, on
        the branch below π/2; None if the rate cannot be reached (at or below the least
        same-side probability of the model, 1/2 for a fixed ψ).
    ci95 : (float, float) or None
        ψ at the upper and lower ends of the rate's interval (p grows as ψ falls); an end whose
        rate cannot be reached is π/2, the angle of least bias, and ``limited`` says so. None
        when ``psi`` is None: no angle, no interval about it.
    sd : float
        Spread of the ψ distribution, rad (0: fixed angle).
    limited : bool
        True when an end of ``ci95`` was set to π/2 because its rate cannot be reached.
    floor : float
        The least same-side probability of the model: 1/2 for a fixed ψ, more with a spread.
    """

    psi: float | None
    ci95: tuple[float, float] | None
    sd: float
    limited: bool
    floor: float = 0.5

    @property
    def model(self) -> str:
        """ "fixed" (one ψ for every flip) or "normal" (ψ ~ Normal(psi, sd))."""
        return "fixed" if self.sd == 0.0 else "normal"


def fit_psi(rate: Proportion, sd: float = 0.0) -> PsiFit:
    """ψ that gives the same-side rate, and the ψ interval from the rate's interval ends.

    Parameters
    ----------
    rate : Proportion
        A same-side proportion.
    sd : float
        Spread of ψ, rad: 0 for a fixed angle, > 0 for the mean of a normal distribution.

    Notes
    -----
    Inverts p(ψ) (Diaconis, Holmes & Montgomery 2007), see
    :func:`coinflight.bias.psi_mean_for_probability`.
    """
    from scipy.special import ndtri

    from coinflight.bias import (
        TAIL_MASS,
        mean_same_side_probability,
        psi_mean_for_probability,
    )
    from coinflight.distributions import Normal

    spread = float(v.non_negative("spread of psi", sd, "rad"))
    widest = 0.5 * math.pi / -float(ndtri(TAIL_MASS))
    if spread >= widest:
        raise ValueError(
            f"a spread of psi of {math.degrees(spread):.4g}° is too wide: a "
            f"normal distribution of psi about 90° must stay within [0°, 180°], so the spread "
            f"must be below {math.degrees(widest):.4g}°"
        )
    least = 0.5
    if spread > 0.0:
        least = mean_same_side_probability(Normal(0.5 * math.pi, spread))

    def solve(p: float) -> float | None:
        if p <= least:
            return None
        return psi_mean_for_probability(min(p, 1.0), spread)

    psi = solve(rate.estimate)
    ends = [solve(rate.ci95[1]), solve(rate.ci95[0])]
    limited = any(e is None for e in ends)
    lo, hi = (0.5 * math.pi if e is None else e for e in ends)
    ci95 = None if psi is None else (lo, hi)
    return PsiFit(psi=psi, ci95=ci95, sd=spread, limited=limited, floor=least)


@dataclass(frozen=True)
class Heterogeneity:
    """Pearson's χ² test that every person has the same same-side probability.

    Attributes
    ----------
    chi2 : float
        The statistic over the people × (same, different) table.
    dof : int
        Degrees of freedom, people − 1.
    p_value : float
        Upper tail of χ²(dof).
    """

    chi2: float
    dof: int
    p_value: float


def heterogeneity(table: CountsTable) -> Heterogeneity:
    """χ² test of homogeneity of the same-side rates across people (``scipy.stats``).

    Notes
    -----
    Pearson's χ² on the k × 2 contingency table, no continuity correction
    (``scipy.stats.chi2_contingency``). Bartoš et al. (REFERENCES §6) report that same-side
    rates "vary widely between people"; this is the frequentist check of that statement.
    """
    from scipy.stats import chi2_contingency

    if len(table.rows) < 2:
        return Heterogeneity(chi2=0.0, dof=0, p_value=1.0)
    counts = [[r.same, r.flips - r.same] for r in table.rows]
    if sum(c[0] for c in counts) in (0, table.flips):
        return Heterogeneity(chi2=0.0, dof=len(counts) - 1, p_value=1.0)
    res = chi2_contingency(counts, correction=False)
    return Heterogeneity(chi2=float(res.statistic), dof=int(res.dof), p_value=float(res.pvalue))


@dataclass(frozen=True)
class CountsSummary:
    """Pooled and per-person statistics of a counts table."""

    source: str
    flips: int
    same_side: Proportion
    heads: Proportion
    people: tuple[tuple[str, Proportion], ...]
    psi: PsiFit
    heterogeneity: Heterogeneity


def summarize(table: CountsTable, method: str = "exact", psi_sd: float = 0.0) -> CountsSummary:
    """Pooled same-side and heads rates with intervals and tests, per-person rates and their
    heterogeneity, and ψ.

    Parameters
    ----------
    table : CountsTable
        From :func:`read_counts`.
    method : {"exact", "wilson"}
        Interval method.
    psi_sd : float
        Spread of ψ for :func:`fit_psi`, rad.
    """
    same = proportion(table.same, table.flips, method)
    return CountsSummary(
        source=table.source,
        flips=table.flips,
        same_side=same,
        heads=proportion(table.heads, table.flips, method),
        people=tuple((r.person, proportion(r.same, r.flips, method)) for r in table.rows),
        psi=fit_psi(same, psi_sd),
        heterogeneity=heterogeneity(table),
    )


__all__ = [
    "COLUMNS",
    "INTERVAL_METHODS",
    "CountsSummary",
    "CountsTable",
    "Heterogeneity",
    "PersonCounts",
    "Proportion",
    "PsiFit",
    "fit_psi",
    "heterogeneity",
    "parse_counts",
    "proportion",
    "read_counts",
    "summarize",
]
