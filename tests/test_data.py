"""Real flips (Bartoš et al.): reading counts, pooled rates, intervals, tests, and the ψ fit."""

from __future__ import annotations

import math
from importlib.resources import files
from pathlib import Path

import numpy as np
import pytest

from coinflight.model.distributions import Normal
from coinflight.studies import bias as b
from coinflight.studies import data as d

# The counts of Bartoš et al. shipped inside the package (coinflight.datasets), nothing outside.
BARTOS = Path(str(files("coinflight.datasets") / "bartos2023.txt"))

HEADER = "person hsame hdiff tsame tdiff same flips"


@pytest.fixture(scope="module")
def table():
    return d.load_dataset("bartos2023")


def test_pooled_counts(table):
    # REFERENCES §6 / the issue: 178,078 same-side of 350,757 flips by 48 people; 175,420 heads
    # (the sums of the metadat table's columns, as checked when the table was copied in; its
    # SHA-256 is in coinflight/datasets/README.md).
    assert len(table.rows) == 48
    assert table.flips == 350_757
    assert table.same == 178_078
    assert table.heads == 175_420
    # The same totals from the rows one by one (hsame + tsame, hsame + hdiff).
    assert sum(r.hsame + r.tsame for r in table.rows) == 178_078
    assert sum(r.hsame + r.hdiff for r in table.rows) == 175_420
    assert table.source == "bartos2023"


@pytest.mark.parametrize("method", ["exact", "wilson"])
def test_published_intervals_to_the_printed_digits(table, method):
    # Bartoš et al.: P(same side) = 0.508 [0.506, 0.509], P(heads) = 0.500 [0.498, 0.502]
    # (REFERENCES §6), printed to 3 decimals. Both frequentist intervals give these digits.
    s = d.summarize(table, method)
    assert round(s.same_side.estimate, 3) == pytest.approx(0.508, abs=1e-12)
    assert [round(x, 3) for x in s.same_side.ci95] == pytest.approx([0.506, 0.509], abs=1e-12)
    assert round(s.heads.estimate, 3) == pytest.approx(0.500, abs=1e-12)
    assert [round(x, 3) for x in s.heads.ci95] == pytest.approx([0.498, 0.502], abs=1e-12)


def test_clopper_pearson_against_beta_quantiles(table):
    # Clopper & Pearson (1934): [B(α/2; k, n−k+1), B(1−α/2; k+1, n−k)], independent of binomtest.
    from scipy.stats import beta

    k, n = table.same, table.flips
    p = d.proportion(k, n, "exact")
    assert p.ci95[0] == pytest.approx(beta.ppf(0.025, k, n - k + 1), rel=1e-9)
    assert p.ci95[1] == pytest.approx(beta.ppf(0.975, k + 1, n - k), rel=1e-9)


def test_wilson_against_its_formula():
    # Wilson (1927): (p̂ + z²/2n ± z sqrt(p̂(1−p̂)/n + z²/4n²)) / (1 + z²/n).
    from scipy.stats import norm

    k, n = 37, 120
    z = norm.ppf(0.975)
    ph = k / n
    centre = (ph + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(ph * (1 - ph) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    ci = d.proportion(k, n, "wilson").ci95
    assert ci == pytest.approx((centre - half, centre + half), rel=1e-12)


def test_tests_against_one_half(table):
    s = d.summarize(table)
    # 9 standard errors above 1/2: a two-sided p-value far below 1e-15 ...
    assert s.same_side.z == pytest.approx(
        2 * math.sqrt(350_757) * (178_078 / 350_757 - 0.5), rel=1e-12
    )
    assert s.same_side.p_value < 1e-15
    # ... while heads vs tails is consistent with 1/2 (negative case).
    assert s.heads.p_value > 0.5


def test_per_person_rates(table):
    s = d.summarize(table)
    assert len(s.people) == 48
    for (name, p), row in zip(s.people, table.rows, strict=True):
        assert name == row.person
        assert p.estimate == row.same / row.flips
        assert p.ci95[0] < p.estimate < p.ci95[1]
    # Rates "vary widely between people" (REFERENCES §6): some below, some well above 1/2.
    rates = [p.estimate for _, p in s.people]
    assert min(rates) < 0.5 < 0.55 < max(rates)


def test_fixed_psi_reproduces_the_pooled_rate(table):
    s = d.summarize(table)
    fit = s.psi
    assert fit.model == "fixed"
    assert fit.psi is not None
    # The model at the fitted angle gives back the measured rate and the interval ends.
    assert float(b.same_side_probability(fit.psi)) == pytest.approx(s.same_side.estimate, abs=1e-12)
    assert float(b.same_side_probability(fit.ci95[0])) == pytest.approx(
        s.same_side.ci95[1], abs=1e-12
    )
    assert float(b.same_side_probability(fit.ci95[1])) == pytest.approx(
        s.same_side.ci95[0], abs=1e-12
    )
    # REFERENCES §2: p = 0.508 needs ψ ≈ 81°.
    assert math.degrees(fit.psi) == pytest.approx(81.0, abs=0.5)
    assert fit.ci95[0] < fit.psi < fit.ci95[1]
    assert not fit.limited


def test_mean_of_a_normal_psi_reproduces_the_pooled_rate(table):
    sd = math.radians(4.0)
    s = d.summarize(table, psi_sd=sd)
    fit = s.psi
    assert fit.model == "normal"
    assert fit.psi is not None
    assert b.mean_same_side_probability(Normal(fit.psi, sd)) == pytest.approx(
        s.same_side.estimate, abs=1e-9
    )
    # A spread adds bias by itself, so the mean sits closer to 90° than the fixed angle.
    assert d.summarize(table).psi.psi < fit.psi < math.pi / 2


def test_rate_at_or_below_half_has_no_psi():
    fit = d.fit_psi(d.proportion(480, 1000))
    assert fit.psi is None
    assert fit.limited
    assert fit.ci95 is None  # no angle, so no interval about it


def _write(tmp_path, text):
    path = tmp_path / "counts.txt"
    path.write_text(text, encoding="utf-8")
    return path


def test_reads_a_small_file_with_comments_and_blank_lines(tmp_path):
    path = _write(tmp_path, f"# a comment\n{HEADER}\n\nA 1 2 3 4 4 10\nB 5 0 5 0 10 10\n")
    t = d.read_counts(path)
    assert [r.person for r in t.rows] == ["A", "B"]
    assert (t.same, t.flips, t.heads) == (14, 20, 8)
    assert t.rows[1].line == 5


@pytest.mark.parametrize(
    ("body", "line", "message"),
    [
        ("A 1 2 3 4 4\n", 2, "expected 7 columns"),
        ("A 1 2 3 4 4 10 9\n", 2, "expected 7 columns"),
        ("A 1 2 x 4 4 10\n", 2, "tsame must be a non-negative integer, got 'x'"),
        ("A 1 2 3.0 4 4 10\n", 2, "tsame must be a non-negative integer, got '3.0'"),
        ("A -1 2 3 4 2 8\n", 2, "hsame must be a non-negative integer, got -1"),
        ("A 1 2 3 4 4 10\nB 1 2 3 4 5 10\n", 3, r"same = 5 but hsame \+ tsame = 1 \+ 3 = 4"),
        ("A 1 2 3 4 4 11\n", 2, r"flips = 11 but hsame \+ hdiff \+ tsame \+ tdiff = 10"),
        ("A 0 0 0 0 0 0\n", 2, "has no flips"),
        ("A 1 2 3 4 4 10\nA 1 2 3 4 4 10\n", 3, "already appears on line 2"),
    ],
)
def test_malformed_counts_name_the_line(tmp_path, body, line, message):
    path = _write(tmp_path, f"{HEADER}\n{body}")
    with pytest.raises(ValueError, match=rf"counts\.txt, line {line}: .*{message}"):
        d.read_counts(path)


def test_wrong_header_is_an_error(tmp_path):
    path = _write(tmp_path, "name a b c d e f\nA 1 2 3 4 4 10\n")
    with pytest.raises(ValueError, match="line 1: expected the header 'person hsame"):
        d.read_counts(path)


def test_empty_and_header_only_files(tmp_path):
    with pytest.raises(ValueError, match="empty"):
        d.read_counts(_write(tmp_path, "\n"))
    with pytest.raises(ValueError, match="no data lines"):
        d.read_counts(_write(tmp_path, HEADER + "\n"))


def test_missing_file_is_a_value_error(tmp_path):
    with pytest.raises(ValueError, match="cannot read counts file"):
        d.read_counts(tmp_path / "nope.txt")


def test_unknown_interval_method(table):
    with pytest.raises(ValueError, match="interval method must be one of exact, wilson"):
        d.summarize(table, "bayes")


def test_heterogeneity_between_people(table):
    # Pearson's χ² by hand: Σ (O − E)² / E over the people × (same, different) table.
    pooled = table.same / table.flips
    chi2 = 0.0
    for r in table.rows:
        for observed, expected in (
            (r.same, r.flips * pooled),
            (r.flips - r.same, r.flips * (1 - pooled)),
        ):
            chi2 += (observed - expected) ** 2 / expected
    het = d.summarize(table).heterogeneity
    assert het.chi2 == pytest.approx(chi2, rel=1e-10)
    assert het.dof == 47
    # REFERENCES §6: same-side rates "vary widely between people".
    assert het.p_value < 1e-10


def test_heterogeneity_of_identical_people_is_not_detected(tmp_path):
    # Negative case: three people with the same rate give χ² = 0, p = 1.
    body = "A 30 20 30 20 60 100\nB 60 40 60 40 120 200\nC 15 10 15 10 30 50\n"
    het = d.heterogeneity(d.read_counts(_write(tmp_path, f"{HEADER}\n{body}")))
    assert het.chi2 == pytest.approx(0.0, abs=1e-12)
    assert het.p_value == pytest.approx(1.0, abs=1e-12)


# --- the shipped dataset (issue 13) -------------------------------------------------------------


def test_load_dataset_is_what_read_counts_returns():
    from coinflight.datasets import DATASETS

    shipped = d.load_dataset("bartos2023")
    from_file = d.read_counts(BARTOS)
    assert isinstance(shipped, d.CountsTable)
    assert shipped.people == from_file.people
    assert shipped.counts.tolist() == from_file.counts.tolist()
    assert shipped.lines == from_file.lines
    entry = DATASETS["bartos2023"]
    assert entry.doi == "10.1080/01621459.2025.2516210"
    assert "350,757" in entry.citation and "arXiv:2310.04153" in entry.citation
    assert "metadat" in entry.provenance


def test_load_dataset_unknown_name():
    with pytest.raises(ValueError, match="dataset must be one of bartos2023; got 'bartos'"):
        d.load_dataset("bartos")


def test_from_rows_and_the_tables_own_checks():
    rows = [d.PersonCounts("A", 1, 2, 3, 4), d.PersonCounts("B", 5, 0, 5, 0)]
    t = d.CountsTable.from_rows(rows, "mine")
    assert (t.same, t.flips, t.heads) == (14, 20, 8)
    assert t.rows == tuple(rows)
    with pytest.raises(TypeError, match="hsame of person 'A' must be an integer, got bool"):
        d.CountsTable.from_rows([d.PersonCounts("A", True, 2, 3, 4)])  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="tdiff of person 'A' must be between 0 and"):
        d.CountsTable.from_rows([d.PersonCounts("A", 1, 2, 3, -4)])
    with pytest.raises(ValueError, match="person 'A' appears twice"):
        d.CountsTable.from_rows(rows[:1] * 2)
    with pytest.raises(ValueError, match="person 'C' has no flips"):
        d.CountsTable.from_rows([d.PersonCounts("C", 0, 0, 0, 0)])
    with pytest.raises(ValueError, match="number of people must be between 1 and"):
        d.CountsTable.from_rows([])


# --- counts files: encodings, comments, bounds (issue 10 item 8) --------------------------------


def test_utf8_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "bom.txt"
    path.write_bytes(b"\xef\xbb\xbf" + f"{HEADER}\nA 1 2 3 4 4 10\n".encode())
    assert d.read_counts(path).people == ("A",)


@pytest.mark.parametrize("comment", ["# a note", "#", "   #\tindented note", "# A 1 2 3 4 4 10"])
def test_comments_are_hash_then_blank(tmp_path, comment):
    t = d.read_counts(_write(tmp_path, f"{comment}\n{HEADER}\n{comment}\nA 1 2 3 4 4 10\n"))
    assert t.people == ("A",)
    assert t.lines == (4,)


@pytest.mark.parametrize("line", ["#A 1 2 3 4 4 10", "#7 5 0 5 0 10 10", "#note", "  #x y"])
def test_a_line_starting_with_hash_and_text_is_not_dropped(tmp_path, line):
    # Was silently skipped as a comment: a person named '#7' vanished from the totals. Now it is
    # neither a comment nor a person, but an error naming its line.
    path = _write(tmp_path, f"{HEADER}\nA 1 2 3 4 4 10\n{line}\nB 5 0 5 0 10 10\n")
    with pytest.raises(
        ValueError,
        match=r"counts\.txt, line 3: starts with '#.*': a comment is '#' followed by a space",
    ):
        d.read_counts(path)


def test_utf16_and_binary_files_are_named_by_line(tmp_path):
    text = f"{HEADER}\nA 1 2 3 4 4 10\n"
    path = tmp_path / "c.txt"
    path.write_bytes(text.encode("utf-16"))  # with a byte-order mark
    with pytest.raises(ValueError, match="not a UTF-8 text file: it starts with a UTF-16 byte"):
        d.read_counts(path)
    path.write_bytes(text.encode("utf-16-le"))  # none: NUL bytes from the first character
    with pytest.raises(ValueError, match=r"c\.txt, line 1: not a UTF-8 text file: .*NUL"):
        d.read_counts(path)
    path.write_bytes(f"{text}B 1 2 3 4 4 10\n".encode() + b"\xff\xfe garbage\n")
    with pytest.raises(ValueError, match=r"c\.txt, line 4: not a UTF-8 text file: byte 0xff"):
        d.read_counts(path)
    path.write_bytes(text.encode() + b"B \x00\x01\x02\n")
    with pytest.raises(ValueError, match=r"c\.txt, line 3: not a UTF-8 text file: .*NUL"):
        d.read_counts(path)


def test_files_over_the_size_limit_are_refused_before_reading(tmp_path, monkeypatch):
    path = _write(tmp_path, f"{HEADER}\n" + "".join(f"P{i} 1 2 3 4 4 10\n" for i in range(100)))
    monkeypatch.setattr(d, "MAX_FILE_BYTES", 1000)
    # "got N bytes": the size from the file system, known before a byte is read (a device or a
    # pipe, whose size is unknown, says "got more" after reading up to the limit).
    with pytest.raises(ValueError, match=r"may be at most 0 MiB \(1,000 bytes\), got 1,[0-9,]+ b"):
        d.read_counts(path)


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="no /dev/zero")
def test_dev_zero_is_bounded():
    # A device says it has size 0: it is read up to the limit and no further (was: forever).
    with pytest.raises(ValueError, match=r"'/dev/zero' is too large: .* at most 16 MiB"):
        d.read_counts("/dev/zero")


def test_line_length_and_people_limits(tmp_path, monkeypatch):
    long_name = "x" * d.MAX_LINE_CHARS
    with pytest.raises(ValueError, match=r"line 2: lines must be at most 1000 characters, got 1,"):
        d.read_counts(_write(tmp_path, f"{HEADER}\n{long_name} 1 2 3 4 4 10\n"))
    monkeypatch.setattr(d, "MAX_PEOPLE", 3)
    body = "".join(f"P{i} 1 2 3 4 4 10\n" for i in range(4))
    with pytest.raises(ValueError, match=r"line 5: a counts table may hold at most 3 people"):
        d.read_counts(_write(tmp_path, f"{HEADER}\n{body}"))


@pytest.mark.parametrize(
    ("body", "line", "message"),
    [
        # Issue 10: counts of 1e18 ended in SciPy's "brentq raised a ValueError" (the exact
        # interval of a rate finer than the float spacing near 1 has no root to find).
        (
            "A 1000000000000000000 1 1000000000000000000 1 2000000000000000000 "
            "2000000000000000002\n",
            2,
            "hsame must be between 0 and 1,000,000,000,000, got 1000000000000000000",
        ),
        ("A 1 2 3 " + "9" * 400 + " 4 10\n", 2, "tdiff must be between 0 and 1,000,000,000,000"),
        (
            "A 300000000000 0 300000000000 0 600000000000 600000000000\n"
            "B 300000000000 0 300000000000 0 600000000000 600000000000\n",
            3,
            "flips must be between 1 and 1,000,000,000,000 in all",
        ),
    ],
)
def test_counts_beyond_the_stated_maximum(tmp_path, body, line, message):
    with pytest.raises(ValueError, match=rf"counts\.txt, line {line}: {message}"):
        d.read_counts(_write(tmp_path, f"{HEADER}\n{body}"))


def test_proportions_at_the_largest_counts_allowed():
    n = d.MAX_FLIPS
    for k in (0, 1, n // 2, n - 1, n):
        for method in d.INTERVAL_METHODS:
            p = d.proportion(k, n, method)
            assert 0.0 <= p.ci95[0] <= p.estimate <= p.ci95[1] <= 1.0
            assert 0.0 <= p.p_value <= 1.0
            d.fit_psi(p)  # no SciPy error at either end
    with pytest.raises(ValueError, match="trials between 1 and 1,000,000,000,000, got 1/10"):
        d.proportion(1, 10**17)


_PAIRS = [
    (k, n)
    for n in (1, 2, 3, 10, 37, 100, 1001, 10_000, 123_457)
    for k in sorted({0, 1, n // 3, n // 2 - 1, n // 2, (n + 1) // 2, n // 2 + 1, n - 1, n})
    if 0 <= k <= n
]


@pytest.mark.parametrize("method", ["exact", "wilson"])
def test_array_proportions_equal_scipy_binomtest(method):
    # The vectorized intervals and test against scipy.stats.binomtest, the reference, one pair
    # at a time: the same numbers to 1e-9 (binomtest finds Clopper-Pearson ends by root search).
    from scipy.stats import binomtest

    got = d.proportions([k for k, _ in _PAIRS], [n for _, n in _PAIRS], method)
    for (k, n), p in zip(_PAIRS, got, strict=True):
        ref = binomtest(k, n, 0.5)
        ci = ref.proportion_ci(confidence_level=0.95, method=method)
        assert p.ci95 == pytest.approx((ci.low, ci.high), rel=1e-9, abs=1e-12), (k, n)
        assert p.p_value == pytest.approx(ref.pvalue, rel=1e-9, abs=1e-300), (k, n)


def test_many_people_are_summarized_as_arrays():
    # Issue 10: 200,000 people took over 40 s (one binomtest per person, ~2 ms each; 50,000
    # would take ~100 s). Now the per-person work is array work: 50,000 people (parsed and
    # summarized) take well under a second of CPU; the bound leaves room for a slow machine.
    import time

    rng = np.random.default_rng(5)
    c = rng.integers(0, 500, size=(50_000, 4))
    c[:, 0] += 1
    lines = [HEADER] + [
        f"P{i} {a} {b_} {t} {u} {a + t} {a + b_ + t + u}" for i, (a, b_, t, u) in enumerate(c)
    ]
    start = time.process_time()
    s = d.summarize(d.parse_counts("\n".join(lines)))
    elapsed = time.process_time() - start
    assert len(s.people) == 50_000
    assert s.flips == int(c.sum())
    assert elapsed < 10.0, f"{elapsed:.1f} s of CPU for 50,000 people"
    # A few people against their one-at-a-time numbers.
    from scipy.stats import binomtest

    for i in (0, 12_345, 49_999):
        same, flips = int(c[i, 0] + c[i, 2]), int(c[i].sum())
        name, p = s.people[i]
        assert name == f"P{i}"
        ref = binomtest(same, flips, 0.5).proportion_ci(confidence_level=0.95)
        assert p.ci95 == pytest.approx((ref.low, ref.high), rel=1e-9)


def test_windows_and_old_mac_line_ends_keep_line_numbers():
    text = f"{HEADER}\r\nA 1 2 3 4 4 10\r\n\rB 1 2 3 4 4 10\rC 1 1 1 1 2 4"
    assert d.parse_counts(text).lines == (2, 4, 5)
