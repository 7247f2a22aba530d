"""`coinflight paper`: the founding paper's numbers, figures and report."""

from __future__ import annotations

import math
import re

import pytest
from typer.testing import CliRunner

from _images import assert_nontrivial, colour_fraction
from coinflight.cli import app
from coinflight.plotting.style import CATCH_COLOR, LAUNCH_COLOR, method_color
from coinflight.report.document import Document, Table
from coinflight.report.paper import PROBABILITY_CASES, ROTATION_CASES, paper_numbers
from coinflight.report.reproduce import FIGURES

# Stefan & Cheche §3 (REFERENCES §1): rotation counts printed in the text of Figs 2c-d, 3c-f.
PAPER_ROTATIONS = {"2c": 8.913, "2d": 17.189, "3c": 9.059, "3d": 9.8142, "3e": 10.569, "3f": 11.324}


@pytest.fixture(scope="module")
def numbers():
    return paper_numbers(events=20_000, seed=7)


def test_cases_carry_the_papers_numbers():
    assert {c.figure: c.paper_rotations for c in ROTATION_CASES} == PAPER_ROTATIONS
    assert [c.figure for c in PROBABILITY_CASES] == ["2a", "2b", "3a", "3b"]


def test_rotations_match_the_paper_to_its_printed_digits(numbers):
    for row in numbers.rotations:
        c = row.case
        # Half a unit of the last printed digit.
        assert row.rotations == pytest.approx(c.paper_rotations, abs=0.5 * 10**-c.decimals)
        assert row.rotations_agree
        # θ(T)/2π by eqs 11, 15 directly.
        assert row.rotations == pytest.approx(
            math.hypot(c.omega_x, c.omega_y) * c.flight_time / (2 * math.pi), rel=1e-12
        )
        # The paper's Euler-matrix construction (eqs 12-13) and the closed form agree (eq 14).
        assert row.cos_theta_construction == pytest.approx(row.cos_theta, abs=1e-12)
        assert row.cos_theta_closed_form == pytest.approx(row.cos_theta, abs=1e-12)
        # "Diaconis' theorem": S ⟂ n in case b.
        assert abs(row.s_dot_n) < 1e-12
        assert row.face == ("heads" if row.cos_theta > 0 else "tails")


def test_fig_2c_text_disagrees_with_eq_14_and_2d_agrees(numbers):
    rows = {r.case.figure: r for r in numbers.rotations}
    # Paper: "In Fig. 2c the coin ends with head down"; 8.913 turns → θ mod 2π = 0.913·2π,
    # in (3π/2, 2π), cos θ > 0 → heads up by the paper's own rule i).
    assert rows["2c"].case.paper_face == "tails"
    assert rows["2c"].face == "heads"
    assert rows["2c"].face_agrees is False
    assert 270.0 < rows["2c"].theta_mod_deg < 360.0
    assert rows["2d"].face_agrees is True
    assert rows["3c"].face_agrees is None


def test_probabilities_a_b_and_exact(numbers):
    for row in numbers.probabilities:
        # The paper: "the probability tends to the unbiased value of 50%".
        assert abs(row.exact.p_heads - 0.5) < 0.01
        assert row.method_a.samples == 5000**2
        # Method A's midpoint rule on 5000² cells: error ~ bands²/N² ≪ 1e-4 here.
        assert row.method_a.p_heads == pytest.approx(row.exact.p_heads, abs=1e-4)
        # Method B tends to its 100 × 100 grid's value; 20 000 events: stderr ≈ 0.0035.
        assert row.method_b.details["grid_cells"] == 100
        assert row.method_b.seed == 7
        assert row.method_b.p_heads == pytest.approx(
            row.method_b_limit.p_heads, abs=5 * row.method_b.stderr
        )


def test_convergence_series_reach_the_papers_sizes(numbers):
    for row in numbers.probabilities:
        conv = row.convergence
        grid = conv.series("grid")
        events = conv.series("monte-carlo")
        # Method A up to 5000 intervals (5000² configurations), method B up to the events asked.
        assert grid[-1].samples == 5000**2
        assert grid[-1].p_heads == row.method_a.p_heads
        assert events[-1].samples == 20_000
        assert events[-1].p_heads == row.method_b.p_heads
        assert conv.exact == row.exact.p_heads
        assert conv.coarse_limit == row.method_b_limit.p_heads
        n, err = row.error_at("grid", 10**4)
        assert n == 10**4
        (at_1e4,) = [p for p in grid if p.samples == 10**4]
        assert err == abs(at_1e4.p_heads - conv.exact)


def test_speed_and_other_checks_in_the_report():
    from coinflight.report.reproduce import _other_checks

    checks = " ".join(_other_checks())
    # 3 and 5 m/s → T = 2 v0/g = 0.612 and 1.019 s; apex at T = 0.9 s: g T²/8 = 0.993 m.
    assert "0.612 to 1.019 s" in checks
    assert "0.993 m" in checks


def test_document_renders_tables_in_both_formats():
    doc = Document("t")
    doc.add(Table(("a", "b|c"), (("1", "2"),)))
    md = doc.to_markdown()
    assert "| a | b\\|c |" in md and "| 1 | 2 |" in md
    html = doc.to_html()
    assert "<th>b|c</th>" in html and "<td>2</td>" in html


@pytest.fixture(scope="module")
def paper_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("paper")
    result = CliRunner().invoke(app, ["paper", "--out", str(out), "--events", "20000", "-q"])
    assert result.exit_code == 0, result.output
    return out, result


def test_cli_writes_every_figure_and_the_report(paper_dir):
    out, result = paper_dir
    for stem in FIGURES:
        assert_nontrivial(out / f"{stem}.png")
        assert (out / f"{stem}.svg").read_text().lstrip().startswith("<?xml")
    assert (out / "report.md").is_file() and (out / "report.html").is_file()
    assert "rotations: 6/6 agree" in result.stdout
    assert "Fig 2c: the paper's text says tails up; its own eq 14 gives heads up" in result.stdout


def test_figures_show_their_colours(paper_dir):
    out, _ = paper_dir
    for stem in ("fig2c", "fig2d", "fig3c-f"):
        rgb = assert_nontrivial(out / f"{stem}.png")
        assert colour_fraction(rgb, LAUNCH_COLOR) > 1e-3, stem
        assert colour_fraction(rgb, CATCH_COLOR) > 1e-3, stem
    for stem in ("fig2a", "fig2b", "fig3a", "fig3b"):
        rgb = assert_nontrivial(out / f"{stem}.png")
        assert colour_fraction(rgb, method_color("grid")) > 1e-3, stem
        assert colour_fraction(rgb, method_color("monte-carlo")) > 1e-3, stem


def test_report_table_is_right_against_the_paper_and_coinflight(paper_dir, numbers):
    out, _ = paper_dir
    md = (out / "report.md").read_text()
    rows = {}
    for line in md.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) == 12 and cells[0] in PAPER_ROTATIONS:
            rows[cells[0]] = cells
    assert set(rows) == set(PAPER_ROTATIONS)
    for fig, cells in rows.items():
        assert float(cells[4]) == PAPER_ROTATIONS[fig]
        assert float(cells[5]) == pytest.approx(PAPER_ROTATIONS[fig], abs=6e-4)
        assert cells[6] == "yes"
    assert rows["2c"][9:] == ["heads", "tails", "NO"]
    assert rows["2d"][9:] == ["heads", "heads", "yes"]
    # Probability rows: exact values as coinflight computes them (independent of the seed).
    exact = {r.case.figure: r.exact.p_heads for r in numbers.probabilities}
    for fig, p in exact.items():
        assert re.search(rf"^\| {fig} \|.*\| {p:.6f} \|", md, re.M), fig
    html = (out / "report.html").read_text()
    assert html.startswith("<!DOCTYPE html>")
    for stem in FIGURES:
        assert f'src="{stem}.png"' in html
    assert "head down" in html and "T = 2 v0/g" in html
    assert "faster convergent" in md


def test_cli_refuses_a_file_as_folder(tmp_path):
    f = tmp_path / "file"
    f.write_text("x")
    result = CliRunner().invoke(app, ["paper", "--out", str(f), "-q"])
    assert result.exit_code == 2
    assert result.stderr == f"coinflight: error: cannot write {f}: it is a file, not a folder\n"


def _body(markdown: str) -> str:
    from coinflight.report.reproduce import TIMINGS_HEADING

    body, footer = markdown.split(TIMINGS_HEADING)
    assert "Generated by coinflight" in footer and " s." in footer  # the timings are there
    return body


def test_report_body_is_the_same_between_runs(paper_dir):
    # A second run (the library, not the command) with the same seed and events: the body is
    # the same to the byte; only the timings after it may differ.
    from coinflight.report.paper import DEFAULT_SEED
    from coinflight.report.reproduce import build_document, timings_footer

    out, _ = paper_dir
    again = paper_numbers(events=20_000, seed=DEFAULT_SEED)
    doc = build_document(again)
    doc.add(*timings_footer(again, 1234.5))
    written = (out / "report.md").read_text()
    assert _body(written) == _body(doc.to_markdown())
    assert "1234.5" not in written and "1234.5" in doc.to_markdown()
    # Nothing that changes between runs in the body: no "in N s", no timing table.
    assert not re.search(r"in \d+\.\d s", _body(written))
    assert "seconds" not in _body(written)


def test_captions_name_the_colours_drawn(paper_dir):
    from coinflight.plotting.style import HEADS_COLOR, TAILS_COLOR, color_name

    out, _ = paper_dir
    body = _body((out / "report.md").read_text())
    # Okabe & Ito: #0072B2 is "blue", #D55E00 "vermillion" (drawn orange-red, never called red).
    assert color_name(method_color("grid")) == color_name(CATCH_COLOR) == "blue"
    assert color_name(method_color("monte-carlo")) == color_name(LAUNCH_COLOR) == "vermillion"
    assert not re.search(r"\bred\b", body)
    assert "method A (blue) and method B (vermillion)" in body
    assert "at launch (vermillion) and at catch (blue)" in body
    heads, tails = color_name(HEADS_COLOR), color_name(TAILS_COLOR)
    assert f"heads face {heads} and tails face {tails}" in body
    with pytest.raises(ValueError, match="not in the Okabe & Ito palette"):
        color_name("#FF0000")
