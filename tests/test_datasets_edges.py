"""The shipped thick-coin edge dataset (coinflight.datasets.edges): rows, provenance, loader."""

from __future__ import annotations

import csv
import dataclasses
import io
import math

import pytest

from coinflight.datasets import EDGE_SOURCES, EdgeExperiment, edge_experiments
from coinflight.datasets.edges import COLUMNS, EDGE_FILE, KINDS, parse_edge_experiments


def test_every_row_is_sourced_and_consistent():
    rows = edge_experiments()
    assert len(rows) == 3
    for r in rows:
        assert r.source in EDGE_SOURCES and r.citation == EDGE_SOURCES[r.source]
        assert r.kind in KINDS
        assert r.ratio > 0.0 and 0.0 < r.fraction < 1.0
        assert r.setting and r.how_read
        if r.edges is not None:
            # a fraction must be the counts' when both are given
            assert r.n is not None and r.fraction == pytest.approx(r.edges / r.n, abs=5e-5)


def test_the_measured_points_and_their_binomial_error():
    rows = edge_experiments(kind="measured")
    assert [(r.source, r.n, r.edges, r.fraction) for r in rows] == [
        ("standup_maths_2018", 1000, None, 0.132),
        ("standup_maths_2018", 1000, None, 0.41),
    ]
    # the two nominal ratios are 1/(2 sqrt 2) and 1/sqrt 3 (5 decimals in the file)
    assert rows[0].ratio == pytest.approx(1 / (2 * math.sqrt(2)), abs=5e-6)
    assert rows[1].ratio == pytest.approx(1 / math.sqrt(3), abs=5e-6)
    assert rows[0].stderr == pytest.approx(math.sqrt(0.132 * 0.868 / 1000), rel=1e-12)


def test_the_extrapolation_is_not_data():
    (nickel,) = edge_experiments(kind="extrapolated")
    assert nickel.source == "murray_teare_1993" and nickel.n is None and nickel.stderr is None
    assert nickel.fraction == pytest.approx(1 / 6000, rel=1e-4)
    assert nickel.ratio == pytest.approx(1.95 / 21.21, abs=5e-5)  # US Mint nickel
    assert "10.1103/PhysRevE.48.2547" in nickel.citation


def test_records_are_frozen():
    row = edge_experiments()[0]
    assert isinstance(row, EdgeExperiment)
    with pytest.raises(dataclasses.FrozenInstanceError):
        row.fraction = 0.5  # type: ignore[misc]


def test_bad_kind_and_bad_rows():
    with pytest.raises(ValueError, match="edge dataset kind must be one of measured, extrapol"):
        edge_experiments(kind="simulated")
    header = "source,ratio,n,edges,fraction,kind,setting,how_read\n"
    with pytest.raises(ValueError, match="edge dataset source must be one of"):
        parse_edge_experiments(header + "nobody,0.3,10,1,0.1,measured,x,y\n")
    with pytest.raises(ValueError, match="edge dataset kind must be one of"):
        parse_edge_experiments(header + "murray_teare_1993,0.3,10,1,0.1,guessed,x,y\n")
    # comments are skipped; empty counts read as None
    (row,) = parse_edge_experiments(
        "# note\n" + header + "murray_teare_1993,0.3,,,0.1,measured,x,y"
    )
    assert (row.n, row.edges) == (None, None)


@pytest.mark.parametrize(
    ("field", "value", "said"),
    [
        ("ratio", "0.3x", "ratio must be a number, got '0.3x'"),
        ("ratio", "0", "ratio must be positive and finite, got 0.0"),
        ("ratio", "-0.3", "ratio must be positive and finite, got -0.3"),
        ("ratio", "nan", "ratio must be positive and finite, got nan"),
        ("n", "1000.5", "n must be an integer, got '1000.5'"),
        ("n", "0", "n must be at least 1, got 0"),
        ("n", "-5", "n must be at least 1, got -5"),
        ("edges", "1001", "edges must be between 0 and 1000, got 1001"),
        ("edges", "-1", "edges must be between 0 and 1000, got -1"),
        ("edges", "one", "edges must be an integer, got 'one'"),
        ("fraction", "1.5", "fraction must be between 0 and 1, got 1.5"),
        ("fraction", "-0.01", "fraction must be between 0 and 1, got -0.01"),
        ("fraction", "", "fraction must be a number, got ''"),
    ],
)
def test_a_bad_number_in_a_row_is_refused_in_one_line_naming_the_file_line_and_value(
    tmp_path, field, value, said
):
    """A copy of the shipped file with one number of its first data row spoilt, written to
    tmp_path and read back: refused in one line naming the file, the row's line and the value,
    in _validation's words (not Python's raw int()/float() errors, not passed through)."""
    from importlib.resources import files

    shipped = files("coinflight.datasets").joinpath(EDGE_FILE).read_text(encoding="utf-8")
    lines = shipped.splitlines()
    header_at = next(i for i, line in enumerate(lines) if line.startswith("source,"))
    first = header_at + 1  # 0-based index of the first data row
    fields = next(csv.reader([lines[first]]))
    fields[COLUMNS.index(field)] = value
    out = io.StringIO()
    csv.writer(out, lineterminator="").writerow(fields)
    lines[first] = out.getvalue()
    path = tmp_path / EDGE_FILE
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert parse_edge_experiments(shipped) == edge_experiments()  # the unspoilt file reads
    with pytest.raises(ValueError) as caught:
        parse_edge_experiments(path.read_text(encoding="utf-8"), where=str(path))
    assert str(caught.value) == f"{path} line {first + 1}: {said}"
    assert "\n" not in str(caught.value)


def test_a_row_of_the_wrong_width_or_a_wrong_header_is_refused_naming_its_line():
    header = ",".join(COLUMNS) + "\n"
    with pytest.raises(ValueError, match=r"^edges\.txt line 2: a row must have 8 fields, got 7$"):
        parse_edge_experiments(header + "murray_teare_1993,0.3,,,0.1,measured,x\n", "edges.txt")
    with pytest.raises(ValueError, match=r"^thick_coin_edges\.txt line 2: the header must be "):
        parse_edge_experiments("# note\nsource,ratio\nmurray_teare_1993,0.3\n")
