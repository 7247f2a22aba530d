"""Real flips: read per-person same-side counts and compare them with the precession model.

The file format is the one of Bartoš et al. (2023/2025), "Fair coins tend to land on the same
side they started: Evidence from 350,757 flips" (REFERENCES §6), whose counts coinflight ships
as the dataset ``bartos2023`` (:mod:`coinflight.datasets`, :func:`load_dataset`):
whitespace-separated, one header line, columns

    person hsame hdiff tsame tdiff same flips

with ``hsame`` = started heads, landed heads; ``hdiff`` = started tails, landed heads; ``tsame``
= started tails, landed tails; ``tdiff`` = started heads, landed tails; ``same`` = hsame + tsame;
``flips`` = all four. Blank lines and comments (``# ...``: see :func:`parse_counts`) are
skipped; files are UTF-8 and bounded in size before they are read (:data:`MAX_FILE_BYTES`).

Statistics are frequentist: a binomial proportion with a 95 % interval (Clopper-Pearson "exact"
by default, or Wilson), and an exact two-sided binomial test against 1/2 (``scipy.stats``).
Bartoš et al. print Bayesian credible intervals from a hierarchical model; on the pooled counts
both frequentist intervals give the same three printed digits, [0.506, 0.509] and
[0.498, 0.502].

The precession angle that explains a same-side rate is found by inverting Diaconis, Holmes &
Montgomery's p(ψ) (:mod:`coinflight.studies.bias`). It is either a *fixed* angle shared by
every flip (``psi_sd = 0``), or the *mean* of a normal distribution of ψ with a stated spread
``psi_sd``.
"""

from __future__ import annotations

import codecs
import io
import math
import os
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v

COLUMNS = ("person", "hsame", "hdiff", "tsame", "tdiff", "same", "flips")
"""The columns of a counts file, in order (Bartoš et al.; :mod:`coinflight.datasets`)."""

INTERVAL_METHODS = ("exact", "wilson")
"""Binomial interval methods: Clopper-Pearson ("exact") and Wilson score."""
INTERVAL_NAMES = {"exact": "Clopper-Pearson", "wilson": "Wilson"}
"""The printed name of each interval method."""

CONFIDENCE = 0.95

MAX_FILE_BYTES = 16 * 1024 * 1024
"""Largest counts file read, bytes (16 MiB: 250,000 people of Bartoš et al.'s 48-byte lines fill
12 MB). Checked before the file is read whole; a device such as /dev/zero is read no further."""

MAX_LINE_CHARS = 1000
"""Longest line of a counts file, characters."""

MAX_PEOPLE = 250_000
"""Most data lines (people) in a counts table: 5,000 times Bartoš et al.'s 48 people. The JSON
report of that many people takes about 0.5 GB of memory (1.9 GB for a million)."""

MAX_FLIPS = 10**12
"""Most flips of a counts table, all people together (and so of any one count).

A trillion flips, three million times Bartoš et al.'s 350,757: one flip a second for 30,000
years. Beyond about 10¹⁶ a rate's interval is narrower than the spacing of floating-point
numbers near 1, and the exact (Clopper-Pearson) interval cannot be computed: counts of 10¹⁸
ended in SciPy's "brentq raised a ValueError" from ``binomtest``."""


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


@dataclass(frozen=True, eq=False)
class CountsTable:
    """The people of a counts file, their counts and where they came from.

    Held as arrays, so that a million people cost milliseconds; :attr:`rows` gives one
    :class:`PersonCounts` per person. Checked when built: 1 to :data:`MAX_PEOPLE` people, no
    person twice, every count a whole number ≥ 0, every person with at least one flip, at most
    :data:`MAX_FLIPS` flips in all. :meth:`from_rows` builds one from :class:`PersonCounts`.

    Attributes
    ----------
    people : tuple of str
        Each person's name, in file order.
    counts : ndarray of int64, shape (people, 4)
        hsame, hdiff, tsame, tdiff of each person (read-only).
    source : str
        Where the counts came from: a file, or a dataset's name.
    lines : tuple of int
        Each person's line in ``source`` (0 when not read from a file).
    """

    people: tuple[str, ...]
    counts: NDArray[np.int64]
    source: str = "<counts>"
    lines: tuple[int, ...] = ()

    def __post_init__(self) -> None:
        v.instance("people", self.people, tuple, "a tuple of names")
        v.count("number of people", len(self.people), 1, MAX_PEOPLE)
        arr = np.asarray(self.counts)
        if arr.dtype.kind not in "iu" or arr.shape != (len(self.people), 4):
            raise TypeError(
                f"counts must be an integer array of shape ({len(self.people)}, 4) (hsame, "
                f"hdiff, tsame, tdiff of each person), got {arr.dtype} of shape {arr.shape}"
            )
        arr = arr.astype(np.int64)
        bad = np.flatnonzero(((arr < 0) | (arr > MAX_FLIPS)).any(axis=1))
        if bad.size:
            i = int(bad[0])
            raise ValueError(
                f"counts of person {self.people[i]!r} must be between 0 and {MAX_FLIPS:,}, got "
                f"{arr[i].tolist()}"
            )
        per_person = arr.sum(axis=1)  # ≤ 4e12 each: no overflow
        empty = np.flatnonzero(per_person == 0)
        if empty.size:
            raise ValueError(f"person {self.people[int(empty[0])]!r} has no flips")
        total = int(per_person.sum())
        if total > MAX_FLIPS:
            raise ValueError(
                f"flips must be between 1 and {MAX_FLIPS:,} in all (all people together), "
                f"got {total:,}"
            )
        if len(set(self.people)) != len(self.people):
            seen: set[str] = set()
            for name in self.people:
                if name in seen:
                    raise ValueError(f"person {name!r} appears twice")
                seen.add(name)
        lines = tuple(self.lines) or (0,) * len(self.people)
        if len(lines) != len(self.people):
            raise ValueError(f"lines must give one line per person, got {len(lines)}")
        arr.setflags(write=False)
        object.__setattr__(self, "counts", arr)
        object.__setattr__(self, "lines", lines)

    @classmethod
    def from_rows(cls, rows: Iterable[PersonCounts], source: str = "<counts>") -> CountsTable:
        """A table of :class:`PersonCounts` (TypeError if a count is not a whole number)."""
        rows = tuple(rows)
        for r in rows:
            v.instance("a row", r, PersonCounts)
            for name in COLUMNS[1:5]:
                v.count(f"{name} of person {r.person!r}", getattr(r, name), 0, MAX_FLIPS)
        counts = np.array([(r.hsame, r.hdiff, r.tsame, r.tdiff) for r in rows], dtype=np.int64)
        return cls(
            tuple(r.person for r in rows),
            counts.reshape(-1, 4),
            source,
            tuple(r.line for r in rows),
        )

    @cached_property
    def rows(self) -> tuple[PersonCounts, ...]:
        """One :class:`PersonCounts` per person, in file order."""
        return tuple(
            PersonCounts(name, a, b, c, d, line=line)
            for name, (a, b, c, d), line in zip(
                self.people, self.counts.tolist(), self.lines, strict=True
            )
        )

    @property
    def same_by_person(self) -> NDArray[np.int64]:
        """Same-side flips of each person, hsame + tsame."""
        return self.counts[:, 0] + self.counts[:, 2]

    @property
    def flips_by_person(self) -> NDArray[np.int64]:
        """All flips of each person."""
        return self.counts.sum(axis=1)

    @property
    def flips(self) -> int:
        """All flips of all people."""
        return int(self.counts.sum())

    @property
    def same(self) -> int:
        """All same-side flips."""
        return int(self.counts[:, 0].sum() + self.counts[:, 2].sum())

    @property
    def heads(self) -> int:
        """All heads-up landings."""
        return int(self.counts[:, 0].sum() + self.counts[:, 1].sum())


def _is_comment(fields: list[str]) -> bool:
    """A comment line: its first field is ``#`` alone (``# text``, or ``#`` and nothing)."""
    return fields[0] == "#"


def parse_counts(text: str, source: str = "<counts>") -> CountsTable:
    """Read a counts table from text; ValueError naming ``source``, the line and the fault.

    Every data line must have the 7 columns of :data:`COLUMNS`, non-negative integer counts,
    same = hsame + tsame, flips = hsame + hdiff + tsame + tdiff, and flips > 0; the header must
    name the columns in that order; a person may appear once. Blank lines are skipped, and so
    are comments: lines whose first non-blank character is ``#`` followed by a blank or the end
    of the line (``# a note``). Any other line starting with ``#`` (``#A 1 2 3 4 4 10``) is an
    error, not a comment nor a person: it could be either, and nothing is dropped or read on a
    guess. Lines may be at most :data:`MAX_LINE_CHARS` long, people at most
    :data:`MAX_PEOPLE`, flips in all at most :data:`MAX_FLIPS`.
    """
    v.instance("text", text, str)
    names, values, linenos = _data_lines(text, source)
    counts = _parse_integers(values, linenos, source)
    _check_sums(counts, names, linenos, source)
    _check_unique(names, linenos, source)
    running = np.cumsum(counts[:, :4].sum(axis=1))  # each total ≤ 4e12: no overflow below 2e6 rows
    if running[-1] > MAX_FLIPS:
        i = int(np.argmax(running > MAX_FLIPS))
        raise ValueError(
            f"{source}, line {linenos[i]}: flips must be between 1 and {MAX_FLIPS:,} in all "
            f"(all people together), got {int(running[-1]):.3g}"
        )
    return CountsTable(tuple(names), counts[:, :4], source, tuple(linenos))


def _data_lines(text: str, source: str) -> tuple[list[str], list[list[str]], list[int]]:
    """The people's names, their count fields (as text) and line numbers, after the header; the
    line faults of :func:`parse_counts` (length, '#', header, columns, people) as ValueError."""
    names: list[str] = []
    values: list[list[str]] = []
    linenos: list[int] = []
    header_seen = False
    # One line at a time (universal newlines): a file of 16 MiB of empty lines is not split
    # into eight million strings first.
    for lineno, line in enumerate(io.StringIO(text, newline=None), start=1):
        raw = line.rstrip("\n")
        where = f"{source}, line {lineno}"
        fields = _fields(raw, where)
        if not fields:
            continue
        if not header_seen:
            if tuple(f.lower() for f in fields) != COLUMNS:
                raise ValueError(
                    f"{where}: expected the header '{' '.join(COLUMNS)}', got {raw.strip()!r:.200}"
                )
            header_seen = True
            continue
        if len(fields) != len(COLUMNS):
            raise ValueError(
                f"{where}: expected {len(COLUMNS)} columns ({' '.join(COLUMNS)}), "
                f"got {len(fields)}: {raw.strip()!r:.200}"
            )
        if len(names) == MAX_PEOPLE:
            raise ValueError(
                f"{where}: a counts table may hold at most {v.quantity(MAX_PEOPLE)} people "
                f"(data lines), got more"
            )
        names.append(fields[0])
        values.append(fields[1:])
        linenos.append(lineno)
    if not header_seen:
        raise ValueError(f"{source}: empty, expected the header '{' '.join(COLUMNS)}'")
    if not names:
        raise ValueError(f"{source}: no data lines after the header")
    return names, values, linenos


def _fields(raw: str, where: str) -> list[str]:
    """The fields of one line, none for a blank line or a comment; ValueError for a line too
    long or one starting with a '#' that is not a comment."""
    if len(raw) > MAX_LINE_CHARS:
        raise ValueError(
            f"{where}: lines must be at most {MAX_LINE_CHARS} characters, got {len(raw):,}"
        )
    fields = raw.split()
    if not fields or _is_comment(fields):
        return []
    if fields[0].startswith("#"):
        raise ValueError(
            f"{where}: starts with {fields[0]!r}: a comment is '#' followed by a space, and "
            f"a person's name may not start with '#'"
        )
    return fields


def _check_sums(
    counts: NDArray[np.int64], names: list[str], linenos: list[int], source: str
) -> None:
    """ValueError at the first line whose same ≠ hsame + tsame, flips ≠ the sum of the four
    counts, or flips = 0."""
    hsame, hdiff, tsame, tdiff, same, flips = counts.T
    total = hsame + hdiff + tsame + tdiff
    for bad, what in (
        (same != hsame + tsame, "same"),
        (flips != total, "flips"),
        (total == 0, "none"),
    ):
        if bad.any():
            i = int(np.argmax(bad))
            where = f"{source}, line {linenos[i]}"
            if what == "same":
                raise ValueError(
                    f"{where}: same = {same[i]} but hsame + tsame = {hsame[i]} + {tsame[i]} "
                    f"= {hsame[i] + tsame[i]}"
                )
            if what == "flips":
                raise ValueError(
                    f"{where}: flips = {flips[i]} but hsame + hdiff + tsame + tdiff = {total[i]}"
                )
            raise ValueError(f"{where}: person {names[i]!r} has no flips")


def _check_unique(names: list[str], linenos: list[int], source: str) -> None:
    """ValueError at the second line of a person who appears twice."""
    if len(set(names)) != len(names):
        seen: dict[str, int] = {}
        for name, lineno in zip(names, linenos, strict=True):
            if name in seen:
                raise ValueError(
                    f"{source}, line {lineno}: person {name!r} already appears on line {seen[name]}"
                )
            seen[name] = lineno


def _parse_integers(values: list[list[str]], linenos: list[int], source: str) -> NDArray[np.int64]:
    """The count columns as an (n, 6) int64 array, each in [0, MAX_FLIPS]; else ValueError
    naming the line, the column and the text."""
    try:
        counts = np.array(values, dtype=np.int64)  # Python's int() rules, as one array
    except (ValueError, OverflowError):
        pass  # the slow path below names the fault
    else:
        if not ((counts < 0) | (counts > MAX_FLIPS)).any():
            return counts
    for row, lineno in zip(values, linenos, strict=True):  # the slow path: find the fault
        for name, text_value in zip(COLUMNS[1:], row, strict=True):
            where = f"{source}, line {lineno}"
            shown = text_value
            if len(text_value) > 40:
                shown = f"{text_value[:40]}… ({len(text_value)} characters)"
            try:
                value = int(text_value)  # ≤ MAX_LINE_CHARS digits: below int()'s own limit
            except ValueError:
                raise ValueError(
                    f"{where}: {name} must be a non-negative integer, got {shown!r}"
                ) from None
            if value < 0:
                raise ValueError(f"{where}: {name} must be a non-negative integer, got {shown}")
            if value > MAX_FLIPS:
                raise ValueError(
                    f"{where}: {name} must be between 0 and {MAX_FLIPS:,}, got {shown}"
                )
    raise AssertionError("unreachable: numpy refused counts that int() accepts")


def read_counts(path: str | os.PathLike[str]) -> CountsTable:
    """Read a counts file (see :func:`parse_counts`); ValueError if it cannot be read.

    The file must be UTF-8 text (a byte-order mark is allowed) of at most
    :data:`MAX_FILE_BYTES`, checked before it is read whole. A binary or UTF-16 file is
    reported by line.
    """
    p = Path(path)
    try:
        with p.open("rb") as f:
            size = os.fstat(f.fileno()).st_size
            if size > MAX_FILE_BYTES:
                raise ValueError(_too_big(p, f"{size:,} bytes"))
            data = f.read(MAX_FILE_BYTES + 1)  # a device or pipe may say size 0: read no more
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise ValueError(f"cannot read counts file {str(p)!r}: {reason}") from None
    if len(data) > MAX_FILE_BYTES:
        raise ValueError(_too_big(p, "more"))
    return parse_counts(_decode(data, str(p)), source=str(p))


def _too_big(path: Path, got: str) -> str:
    return (
        f"counts file {str(path)!r} is too large: counts files may be at most "
        f"{MAX_FILE_BYTES // 2**20} MiB ({MAX_FILE_BYTES:,} bytes), got {got}"
    )


def _decode(data: bytes, source: str) -> str:
    """UTF-8 text (without a leading byte-order mark), or ValueError naming the line."""
    for bom, name in (
        (codecs.BOM_UTF32_LE, "UTF-32"),
        (codecs.BOM_UTF32_BE, "UTF-32"),
        (codecs.BOM_UTF16_LE, "UTF-16"),
        (codecs.BOM_UTF16_BE, "UTF-16"),
    ):
        if data.startswith(bom):
            raise ValueError(
                f"{source}: not a UTF-8 text file: it starts with a {name} byte-order mark; "
                f"save it as UTF-8"
            )
    nul = data.find(b"\0")
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise ValueError(
            f"{source}, line {line}: not a UTF-8 text file: it holds a NUL byte (binary, or "
            f"UTF-16 without a byte-order mark); save it as UTF-8 text"
        )
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise ValueError(
            f"{source}, line {line}: not a UTF-8 text file: byte 0x{data[exc.start]:02x} is not "
            f"UTF-8; save it as UTF-8 text"
        ) from None


def load_dataset(name: str = "bartos2023") -> CountsTable:
    """A dataset shipped with coinflight, as :func:`read_counts` would return it.

    Parameters
    ----------
    name : str
        A name of :data:`coinflight.datasets.DATASETS` (``"bartos2023"``: Bartoš et al.'s
        350,757 flips; its citation and provenance are in the registry).
    """
    from coinflight.datasets import DATASETS

    v.choice("dataset", name, tuple(DATASETS))
    return parse_counts(DATASETS[name].read_text(), source=name)


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
    """Proportion, 95 % interval and exact binomial test against 1/2 (see :func:`proportions`)."""
    return proportions([successes], [trials], method)[0]


def proportions(successes: ArrayLike, trials: ArrayLike, method: str = "exact") -> list[Proportion]:
    """:class:`Proportion` of each (successes, trials) pair, computed as arrays.

    Parameters
    ----------
    successes, trials : array_like of int
        Counts, 0 ≤ successes ≤ trials, 1 ≤ trials ≤ :data:`MAX_FLIPS`.
    method : {"exact", "wilson"}
        Interval method.

    Notes
    -----
    The same numbers as ``scipy.stats.binomtest(k, n, 0.5)`` and its ``proportion_ci`` (tested
    against them), one array operation for all pairs instead of one root search per pair:

    - Clopper & Pearson (1934) exact interval: [B(α/2; k, n−k+1), B(1−α/2; k+1, n−k)], the
      quantiles of beta distributions (``scipy.stats.beta.ppf``), 0 at k = 0 and 1 at k = n;
    - Wilson (1927) score interval, as Newcombe (1998) writes it (SciPy's formula):
      (2k + z² ± z √(4k(n−k)/n + z²)) / (2(n + z²)), 0 at k = 0 and 1 at k = n;
    - the two-sided exact test against 1/2: with a symmetric binomial the outcomes as or less
      likely than k are the two tails beyond k and n − k, so p = min(1, 2 F(min(k, n−k))) with
      F the binomial distribution function (``scipy.stats.binom.cdf``), and p = 1 at k = n/2.
    """
    from scipy.special import ndtri
    from scipy.stats import beta, binom

    v.choice("interval method", method, INTERVAL_METHODS)
    k_list, n_list = _int_list("successes", successes), _int_list("trials", trials)
    if len(k_list) != len(n_list):
        raise ValueError(
            f"successes and trials must have the same length, got {len(k_list)} and {len(n_list)}"
        )
    for k_i, n_i in zip(k_list, n_list, strict=True):
        if not (1 <= n_i <= MAX_FLIPS and 0 <= k_i <= n_i):
            raise ValueError(
                f"need 0 ≤ successes ≤ trials and trials between 1 and {MAX_FLIPS:,}, got "
                f"{k_i}/{n_i}"
            )
    if not k_list:
        return []
    k = np.array(k_list, dtype=float)  # exact: both ≤ 1e12 < 2⁵³
    n = np.array(n_list, dtype=float)
    alpha = 1.0 - CONFIDENCE
    with np.errstate(invalid="ignore", divide="ignore"):
        if method == "exact":
            low = np.where(k > 0, beta.ppf(alpha / 2, k, n - k + 1), 0.0)
            high = np.where(k < n, beta.ppf(1 - alpha / 2, k + 1, n - k), 1.0)
        else:
            z = float(ndtri(1 - alpha / 2))
            centre = (2 * k + z * z) / (2 * (n + z * z))
            delta = z / (2 * (n + z * z)) * np.sqrt(4 * k * (n - k) / n + z * z)
            low = np.where(k > 0, centre - delta, 0.0)
            high = np.where(k < n, centre + delta, 1.0)
        tail = binom.cdf(np.minimum(k, n - k), n, 0.5)
    p_value = np.where(2 * k == n, 1.0, np.minimum(1.0, 2 * tail))
    if not (np.isfinite(low).all() and np.isfinite(high).all() and np.isfinite(p_value).all()):
        raise ArithmeticError("a binomial interval or test did not evaluate to a finite number")
    return [
        Proportion(
            successes=k_i,
            trials=n_i,
            estimate=k_i / n_i,
            ci95=(lo, hi),
            method=method,
            p_value=pv,
        )
        for k_i, n_i, lo, hi, pv in zip(
            k_list, n_list, low.tolist(), high.tolist(), p_value.tolist(), strict=True
        )
    ]


def _int_list(name: str, value: ArrayLike) -> list[int]:
    """Whole numbers as Python ints, or TypeError naming ``name``."""
    arr = np.asarray(value)
    if arr.ndim != 1:
        arr = arr.reshape(-1)
    if arr.dtype.kind in "iu":
        return [int(x) for x in arr.tolist()]
    out = []
    for x in arr.tolist():
        v.count(name, x, minimum=-(2**63))
        out.append(int(x))
    return out


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
    :func:`coinflight.studies.bias.psi_mean_for_probability`.
    """
    from scipy.special import ndtri

    from coinflight.model.distributions import Normal
    from coinflight.studies.bias import (
        TAIL_MASS,
        mean_same_side_probability,
        psi_mean_for_probability,
    )

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
    i2 : float
        Higgins & Thompson's I² = max(0, (χ² − dof) / χ²): the share of the spread of the
        observed rates that is not binomial sampling (0 when χ² ≤ dof).
    tau : float
        DerSimonian & Laird's moment estimate of the standard deviation of the people's true
        same-side rates, with weights n / (p̄ (1 − p̄)) (p̄ the pooled rate); 0 when χ² ≤ dof.
    """

    chi2: float
    dof: int
    p_value: float
    i2: float = 0.0
    tau: float = 0.0


def heterogeneity(table: CountsTable) -> Heterogeneity:
    """χ² test of homogeneity of the same-side rates across people (``scipy.stats``).

    Notes
    -----
    Pearson's χ² on the k × 2 contingency table, no continuity correction
    (``scipy.stats.chi2_contingency``). Bartoš et al. (REFERENCES §6) report that same-side
    rates "vary widely between people"; this is the frequentist check of that statement.

    Pearson's χ² on this table is Cochran's Q of the people's rates with weights
    w = n / (p̄ (1 − p̄)), so that I² (Higgins & Thompson 2002, "Quantifying heterogeneity in a
    meta-analysis", Stat. Med. 21, 1539) and τ² = (Q − dof) / (Σw − Σw² / Σw) (DerSimonian &
    Laird 1986, "Meta-analysis in clinical trials", Control. Clin. Trials 7, 177) follow from it.
    """
    from scipy.stats import chi2_contingency

    if len(table.people) < 2:
        return Heterogeneity(chi2=0.0, dof=0, p_value=1.0)
    same = table.same_by_person
    flips = table.flips_by_person
    counts = np.column_stack([same, flips - same])
    if table.same in (0, table.flips):
        return Heterogeneity(chi2=0.0, dof=len(counts) - 1, p_value=1.0)
    res = chi2_contingency(counts, correction=False)
    q, dof = float(res.statistic), int(res.dof)
    pooled = table.same / table.flips
    w = flips.astype(float) / (pooled * (1.0 - pooled))
    excess = max(0.0, q - dof)
    tau2 = excess / float(w.sum() - (w * w).sum() / w.sum())
    return Heterogeneity(
        chi2=q,
        dof=dof,
        p_value=float(res.pvalue),
        i2=excess / q if excess > 0.0 else 0.0,
        tau=math.sqrt(tau2),
    )


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

    def to_dict(self, psi_sd_deg: float) -> dict[str, Any]:
        """The pooled and per-person statistics as JSON-ready values (ψ in degrees).

        ``psi_sd_deg`` is the spread of ψ as the caller gave it, degrees (the fit keeps
        radians, and degrees → radians → degrees need not round-trip exactly).
        """
        same, heads, fit = self.same_side, self.heads, self.psi
        return {
            "people": len(self.people),
            "flips": self.flips,
            "same": same.successes,
            "p_same_side": same.estimate,
            "ci95": list(same.ci95),
            "p_value": same.p_value,
            "z": same.z,
            "heads": heads.successes,
            "p_heads": heads.estimate,
            "ci95_heads": list(heads.ci95),
            "p_value_heads": heads.p_value,
            "interval": INTERVAL_NAMES[same.method],
            "psi_deg": None if fit.psi is None else math.degrees(fit.psi),
            "psi_ci95_deg": None if fit.ci95 is None else [math.degrees(x) for x in fit.ci95],
            "psi_model": fit.model,
            "psi_sd_deg": psi_sd_deg,
            "psi_ci95_limited": fit.limited,
            "heterogeneity": {
                "chi2": self.heterogeneity.chi2,
                "dof": self.heterogeneity.dof,
                "p_value": self.heterogeneity.p_value,
                "i2": self.heterogeneity.i2,
                "tau": self.heterogeneity.tau,
            },
            "p_same_side_floor": fit.floor,
            "per_person": [
                {
                    "person": name,
                    "same": p.successes,
                    "flips": p.trials,
                    "p_same_side": p.estimate,
                    "ci95": list(p.ci95),
                    "p_value": p.p_value,
                }
                for name, p in self.people
            ],
        }

    def report(self, source: str, psi_sd_deg: float) -> list[str]:
        """The text report, one line each: the pooled rates and tests, ψ, the heterogeneity
        test and the per-person rates (``psi_sd_deg`` as in :meth:`to_dict`)."""
        method = INTERVAL_NAMES[self.same_side.method]
        lines = [f"{source}: {len(self.people)} people, {self.flips:,} flips"]
        for label, p in (("same side:", self.same_side), ("heads:    ", self.heads)):
            lines.append(
                f"{label} {p.successes:,} of {p.trials:,} = {p.estimate:.5f}, "
                f"95% {method} interval [{p.ci95[0]:.5f}, {p.ci95[1]:.5f}]; "
                f"test against 1/2: p = {p.p_value:.2g} (z = {p.z:.2f})"
            )
        lines.append(self._psi_line(psi_sd_deg))
        het = self.heterogeneity
        lines.append(
            f"between people: χ² = {het.chi2:.1f} on {het.dof} degrees of freedom, p = "
            f"{het.p_value:.2g} (test that everyone has the same same-side rate)"
        )
        lines.append("per person (same side of flips, rate, 95% interval):")
        width = max(len(name) for name, _ in self.people)
        lines.extend(
            f"  {name:<{width}} {p.successes:>7,} of {p.trials:>7,}  {p.estimate:.4f}  "
            f"[{p.ci95[0]:.4f}, {p.ci95[1]:.4f}]"
            for name, p in self.people
        )
        return lines

    def _psi_line(self, psi_sd_deg: float) -> str:
        fit = self.psi
        what = (
            "a fixed ψ for every flip"
            if fit.model == "fixed"
            else f"the mean of a normal ψ distribution with sd {psi_sd_deg:g}°"
        )
        if fit.psi is None or fit.ci95 is None:
            return (
                f"precession (Diaconis et al. 2007, {what}): no ψ gives this same-side rate; "
                f"the model gives at least {fit.floor:.5f}"
            )
        lo, hi = (math.degrees(x) for x in fit.ci95)
        limit = " (an end capped at 90°: that rate is not reached)" if fit.limited else ""
        return (
            f"precession (Diaconis et al. 2007, {what}): ψ = {math.degrees(fit.psi):.2f}°, "
            f"95% interval [{lo:.2f}°, {hi:.2f}°]{limit}"
        )


def counts_source(
    dataset: str | None = None, counts: str | os.PathLike[str] | None = None
) -> tuple[CountsTable, str, dict[str, Any]]:
    """The counts to summarize: a shipped dataset or a file.

    The dataset defaults to :data:`coinflight.datasets.DEFAULT_DATASET`. Returns the table, a
    one-line label of its source (name, citation key and DOI, or the path) and its description
    as JSON-ready values (``dataset`` is None for a file).
    """
    if dataset is not None and counts is not None:
        raise ValueError(
            f"give either --dataset or --counts, not both (got --dataset {dataset} and "
            f"--counts {counts})"
        )
    if counts is not None:
        return read_counts(counts), str(counts), {"dataset": None, "source": str(counts)}
    from coinflight.datasets import DATASETS, DEFAULT_DATASET

    name = DEFAULT_DATASET if dataset is None else dataset
    table = load_dataset(name)
    shipped = DATASETS[name]
    described: dict[str, Any] = {
        "dataset": name,
        "source": name,
        "title": shipped.title,
        "citation": shipped.citation,
        "doi": shipped.doi,
        "provenance": shipped.provenance,
    }
    return table, f"{name} ({shipped.short}, doi:{shipped.doi})", described


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
        people=tuple(
            zip(
                table.people,
                proportions(table.same_by_person, table.flips_by_person, method),
                strict=True,
            )
        ),
        psi=fit_psi(same, psi_sd),
        heterogeneity=heterogeneity(table),
    )


__all__ = [
    "COLUMNS",
    "INTERVAL_METHODS",
    "INTERVAL_NAMES",
    "MAX_FILE_BYTES",
    "MAX_FLIPS",
    "MAX_LINE_CHARS",
    "MAX_PEOPLE",
    "CountsSummary",
    "CountsTable",
    "Heterogeneity",
    "PersonCounts",
    "Proportion",
    "PsiFit",
    "counts_source",
    "fit_psi",
    "heterogeneity",
    "load_dataset",
    "parse_counts",
    "proportion",
    "proportions",
    "read_counts",
    "summarize",
]
