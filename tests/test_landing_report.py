"""The landing report (issue 11): its files appear whole, its numbers are the library's, its
figures are drawn, and MuJoCo's part runs or is skipped cleanly."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

import coinflight
from _images import assert_nontrivial
from coinflight.cli import app
from coinflight.core.outcome import Status
from coinflight.model.surface import Surface
from coinflight.outcomes.table import TableLanding, land
from coinflight.probability import monte_carlo, streams
from coinflight.report import landing as report
from coinflight.report.document import Paragraph
from coinflight.studies import landing as study
from coinflight.studies import mujoco_compare
from coinflight.studies.edge import edge_table

SEED = 11
TINY = report.Sizes(
    dead=300,
    bouncing=50,
    bouncing_points=2,
    map_tosses=20,
    map_restitution=2,
    map_friction=2,
    band_tosses=3,
    band_integrated=6,
    mujoco=3,
    experiments=6,
    experiments_human=2,
    experiments_points=2,
)


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("landing") / "report"
    return out, report.landing_report(out, seed=SEED, sizes=TINY)


def test_every_file_is_written_and_the_figures_are_drawn(written):
    out, r = written
    names = {p.name for p in out.iterdir()}
    figures = {"dead_landings.png", "contact_maps.png", "nickel_band.png"}
    if mujoco_compare.available():
        figures.add("mujoco.png")
    assert names == figures | set(report.REPORTS)
    assert {p.name for p in r.files} == names
    for name in figures:
        assert_nontrivial(out / name)
    numbers = json.loads((out / "numbers.json").read_text())
    assert numbers["coinflight_version"] == coinflight.__version__  # where it came from
    assert "command" not in numbers  # called from Python, not from a command line
    md = (out / "report.md").read_text()
    for name in figures:
        assert f"]({name})" in md  # every figure is shown in the report
    assert "<table>" in (out / "report.html").read_text()


def test_thick_cylinders_section_is_the_studys(written):
    out, _ = written
    numbers = json.loads((out / "numbers.json").read_text())["edge_experiments"]
    # the study with the report's child for this question (part 6) of the seed
    again, left = study.thick_experiments(TINY.experiments, SEED, TINY.experiments_points)
    expected = json.loads(json.dumps({**again.to_dict(), "left_out": left}))
    numbers.pop("elapsed"), expected.pop("elapsed")
    assert numbers == expected and numbers["seed"] == SEED
    assert len(numbers["experiments"]) >= 1
    md = (out / "report.md").read_text()
    assert "## Thick cylinders against experiments" in md
    for row in again.table():
        assert row[-2] in {"inside", "above", "below", "too few tosses to judge"} and row[0] in md


def test_measured_edges_beside_the_human_tosses_band(written):
    # Every measured row of thick_coin_edges.txt, with its binomial error, beside the band of
    # human tosses as the preset makes them (its wobble).
    from coinflight.datasets import edge_experiments as dataset

    out, _ = written
    numbers = json.loads((out / "numbers.json").read_text())["edge_experiments_human"]
    again, _ = study.thick_experiments(
        TINY.experiments_human, SEED, TINY.experiments_points, "human"
    )
    expected = json.loads(json.dumps(again.to_dict()))
    numbers.pop("elapsed"), expected.pop("elapsed")
    assert numbers == expected and numbers["psi"] == "human"
    measured = dataset(kind="measured")
    assert [x["ratio"] for x in numbers["experiments"]] == [m.ratio for m in measured]
    md = (out / "report.md").read_text()
    assert "## Thick cylinders against experiments: human tosses with the preset's wobble" in md
    for x, m in zip(numbers["experiments"], measured, strict=True):
        b = x["band"]
        assert "resistance" in x["box"] and len(b["cells"]) == 2**5 + 1  # corners and centre
        assert x["stderr"] == pytest.approx(m.stderr)
        assert f"{m.fraction:.3f} ± {m.stderr:.3f} (" in md  # beside its band, with its error
        assert f"{b['low']:.3f} ± {b['low_stderr']:.3f} – {b['high']:.3f}" in md


def test_the_thick_cylinders_seed_printed_reproduces_the_numbers():
    import re

    from coinflight.datasets import edge_experiments as dataset
    from coinflight.studies.edge_experiments import edge_experiments, from_dataset

    x, left = study.thick_experiments(4, SEED, 2)
    blocks = report._experiments_section(x, tuple(left))
    text = " ".join(b.text for b in blocks if isinstance(b, Paragraph))
    found = re.search(r"child (\d+) of seed (\d+)", text)
    assert found, text
    child, seed = int(found[1]), int(found[2])
    records, _ = from_dataset(dataset())
    root = streams.seed_sequence(seed)
    again = edge_experiments(records, 4, streams.child(root, child), points=2)
    assert again.table() == x.table()
    # The report's seed alone draws other tosses: the child is what reproduces them.
    assert (
        edge_experiments(records, 4, seed, points=2).to_dict()["experiments"]
        != (x.to_dict()["experiments"])
    )


def test_the_numbers_are_the_librarys(written):
    out, _ = written
    numbers = json.loads((out / "numbers.json").read_text())
    assert numbers["seed"] == SEED and numbers["sizes"] == TINY.to_dict()
    # Dead landings: edge_table with the report's child stream (part 0) of the seed.
    rows = edge_table(list(study.RATIOS), TINY.dead, streams.child(streams.seed_sequence(SEED), 0))
    for row, got in zip(rows, numbers["dead_landings"], strict=True):
        assert got["p_edge"] == row["simulated"]["p_edge"]
        assert got["p_edge_dynamic"] == row["p_edge_dynamic"]
        se = math.sqrt(got["p_edge_dynamic"] * (1 - got["p_edge_dynamic"]) / TINY.dead)
        assert got["z_dynamic"] == pytest.approx((got["p_edge"] - got["p_edge_dynamic"]) / se)
    # A map cell is the Monte Carlo estimate of the same tosses (part 1) on that surface.
    maps = numbers["contact_maps"]
    e, mu = maps["restitution"][1], maps["friction"][0]
    model = TableLanding(
        Surface("table", drop_height=study.DROP_HEIGHT, restitution=e, friction=mu)
    )
    child = streams.child(streams.seed_sequence(SEED), 1)
    mc = monte_carlo.estimate(study.map_tosses(), TINY.map_tosses, child, model=model)
    assert maps["p_same_side"][0][1] == mc.p_same_side
    assert maps["p_edge"][0][1] == mc.p_edge
    # Bouncing edges: simulate_edge on the same tosses (part 4) with each cell's e, μ and ℓ.
    from coinflight.studies.edge import simulate_edge

    bouncing = numbers["bouncing_edges"]
    cells = bouncing["cells"]
    assert len(cells) == 2**3 + 1  # the corners of the box of e, μ, ℓ and its centre
    for name, ends in (("restitution", (0.3, 0.6)), ("friction", (0.05, 0.6))):
        values = sorted({c[name] for c in cells})  # the presets' union, and its centre
        assert values == pytest.approx([ends[0], sum(ends) / 2, ends[1]])
    values = sorted({c["resistance"] for c in cells})
    assert values == pytest.approx([1e-5, 1e-4, 1e-3])  # geometric centre
    child = streams.child(streams.seed_sequence(SEED), 4)
    j = 1
    rows = simulate_edge(
        list(study.RATIOS),
        TINY.bouncing,
        child,
        restitution=cells[j]["restitution"],
        friction=cells[j]["friction"],
        rolling_resistance=cells[j]["resistance"],
        pivoting_resistance=cells[j]["resistance"],
    )
    edge = np.array(bouncing["p_edge_cells"])
    assert edge[:, j].tolist() == [s.p for _, s in rows]
    assert bouncing["low"] == edge.min(axis=1).tolist()
    assert bouncing["high"] == edge.max(axis=1).tolist()
    assert "only the abstract could be read" in bouncing["hernandez_navarro_pinero"]
    # The report's words on bouncing are its table's: ratios whose whole band (±2 s.e.) lies
    # below the dead-landing model are named as such.
    n_b = TINY.bouncing
    below = [
        f"{r:g}"
        for r, hi, d in zip(
            bouncing["ratios"], bouncing["high"], numbers["dead_landings"], strict=True
        )
        if hi + 2 * math.sqrt(hi * (1 - hi) / n_b) < d["p_edge_dynamic"]
    ]
    md_text = (out / "report.md").read_text()
    if below:
        assert f"lowers P(edge) below the dead-landing model at h/d = {', '.join(below)}" in md_text
    else:
        assert "lowers P(edge) below" not in md_text
    # The text quotes the computed numbers, not others.
    md = (out / "report.md").read_text()
    first = numbers["dead_landings"][0]
    assert f"{first['p_edge']:.4f} ± {first['stderr']:.4f}" in md


def test_the_nickel_band_section_is_the_studys(written):
    """The nickel's band (issue 27): its section in the report, its numbers those of
    :func:`coinflight.studies.landing.nickel_band` with the report's seed."""
    out, r = written
    numbers = json.loads((out / "numbers.json").read_text())["nickel_band"]
    again = study.nickel_band(TINY.band_tosses, SEED, TINY.band_integrated)
    expected = json.loads(json.dumps(report._band_numbers(again)))
    numbers.pop("seconds"), expected.pop("seconds")  # wall time, not a result
    assert numbers == expected
    md = (out / "report.md").read_text()
    assert "## The US nickel's P(edge): a band over what is not measured, and why" in md
    assert numbers["round_rim"]["edges"] == 0
    assert "nickel band" in r.timings


def test_the_report_is_whole_or_nothing(tmp_path, monkeypatch):
    from coinflight.plotting import style

    out = tmp_path / "report"
    saved = []

    def first_then_fail(fig, path, *args, **kwargs):
        if saved:
            raise RuntimeError("interrupted")
        saved.append(path)
        path.with_suffix(".png").write_bytes(b"half a report")
        return [path.with_suffix(".png")]

    monkeypatch.setattr(style, "save_figure", first_then_fail)
    sizes = dataclasses.replace(TINY, mujoco=0, experiments=0)
    with pytest.raises(RuntimeError, match="interrupted"):
        report.landing_report(out, seed=1, sizes=sizes)
    assert saved  # one figure was written (into the stage) before the failure
    assert not out.exists() or not any(out.iterdir())  # ... and none of it appeared


def test_cli_landing_report_quick_skips_mujoco_cleanly_when_absent(tmp_path, monkeypatch):
    # TINY with the fewest landings carried to rest (the command line is what is tested here)
    quick = dataclasses.replace(TINY, band_tosses=1, band_integrated=1, experiments_human=0)
    monkeypatch.setattr(report, "QUICK", quick)
    monkeypatch.setattr(mujoco_compare, "available", lambda: False)
    out = tmp_path / "cli"
    result = CliRunner().invoke(
        app, ["landing-report", "--out", str(out), "--quick", "--seed", str(SEED)]
    )
    assert result.exit_code == 0, result.output
    assert "dead landings h/d = 0.577" in result.stdout
    assert "US nickel on coin-on-wood: P(edge) " in result.stdout  # with its errors
    assert ", planar tosses " in result.stdout and "over the unmeasured parameters" in result.stdout
    assert "MuJoCo is not installed (pip install 'coinflight[mujoco]')" in result.stdout
    assert not (out / "mujoco.png").exists()
    assert "MuJoCo is not installed" in (out / "report.md").read_text()
    numbers = json.loads((out / "numbers.json").read_text())
    assert numbers["mujoco"] is None
    # The same seed and sizes as the library's report: the same numbers.
    assert numbers["dead_landings"][0]["p_edge"] == pytest.approx(
        study.dead_landings(quick.dead, SEED)[0].simulated.p, abs=0
    )


def test_cli_landing_report_refuses_a_bad_folder_before_computing():
    from _cli import one_line_error

    # an empty value is refused by the command line itself, naming the option (cli.errors)
    assert "--out was given an empty value" in one_line_error("landing-report", "--out", "")
    # /proc refuses new files even to root: refused by the check before any computing.
    assert "cannot write /proc/" in one_line_error("landing-report", "--out", "/proc/x/y")


# --- MuJoCo ---------------------------------------------------------------------------------------
mujoco = pytest.importorskip("mujoco")


def test_mujoco_contact_is_calibrated_to_the_restitution():
    coin = study.mujoco_tosses().coin
    zeta = mujoco_compare.calibrated_damping(coin, 0.5, 4.5)
    assert mujoco_compare.flat_drop_restitution(coin, 4.5, zeta) == pytest.approx(0.5, abs=2e-3)
    # A dead landing is beyond MuJoCo's soft contact: refused, not silently approximated.
    with pytest.raises(ValueError, match="cannot rebound at restitution 0"):
        mujoco_compare.calibrated_damping(coin, 0.0, 4.5)


def test_mujoco_agrees_with_coinflight_at_the_first_contact():
    # Geometry and free flight only: the same well at the first contact (planar tosses, no
    # precession for MuJoCo's Euler integrator to drift in).
    c = study.mujoco_comparison(6, seed=3)
    assert c.first_agreement == 1.0
    assert c.n == 6 and c.settings["flat_drop_restitution"] == pytest.approx(0.5, abs=2e-3)
    # coinflight lands the same tosses with MuJoCo's torsional and rolling friction as its
    # pivoting and rolling resistance.
    assert c.rolling_resistance == mujoco_compare.ROLLING == 1e-4
    assert c.pivoting_resistance == mujoco_compare.TORSIONAL == 5e-3
    surface = Surface(
        "table",
        study.DROP_HEIGHT,
        c.restitution,
        c.friction,
        rolling_resistance=1e-4,
        pivoting_resistance=5e-3,
    )
    root = streams.child(streams.seed_sequence(3), 3)
    omega, v0 = study._draw(study.mujoco_tosses(), 6, root)
    out = land(study.mujoco_tosses().coin, omega, v0, 1.0, 9.81, surface)
    np.testing.assert_array_equal(out.face, c.coinflight.rest)
    assert c.coinflight.at_impact == np.count_nonzero(out.status == Status.SETTLED_ENERGY)
    assert c.coinflight.unsettled == np.count_nonzero(out.status == Status.UNSETTLED)
    # MuJoCo's restitution is reported at the probe speeds and at the landing speed.
    by_speed = dict(c.settings["flat_drop_restitution_by_speed"])
    assert set(mujoco_compare.PROBE_SPEEDS) < set(by_speed) and len(by_speed) == 4
    landing = max(by_speed)
    assert by_speed[landing] == c.settings["flat_drop_restitution"]
    assert c.rest_agreement == np.mean(c.coinflight.rest == c.mujoco_rest)
    assert c.speed_ratio == c.mujoco_seconds / c.coinflight.seconds
    assert c.mujoco_unsettled == int(c.mujoco.moving.sum()) and c.mujoco.limit == 20.0
    assert c.settings["condim"] == 6 and c.settings["friction"][1:] == [5e-3, 1e-4]


def test_mujoco_contacts_carry_torsional_and_rolling_friction():
    # MuJoCo ignores its torsional and rolling coefficients below condim 4 and 6 (its default
    # is 3): the comparison's model must use 6, and its contacts must have 6 dimensions.
    coin = study.mujoco_tosses().coin
    m = mujoco_compare.model(coin, 0.3, 0.5)
    assert list(m.geom_condim) == [6, 6]
    np.testing.assert_array_equal(m.geom_friction[1], [0.3, 5e-3, 1e-4])
    d = mujoco.MjData(m)
    d.qpos[:3] = (0.0, 0.0, coin.thickness / 2 - 1e-5)  # resting flat, just touching
    mujoco.mj_forward(m, d)
    assert d.ncon > 0 and all(d.contact[i].dim == 6 for i in range(d.ncon))
    with pytest.raises(ValueError, match="MuJoCo condim must be 1, 3, 4 or 6, got 5"):
        mujoco_compare.Engine(condim=5)


def test_the_report_compares_the_landing_with_mujoco(written):
    out, r = written
    if r.mujoco is None:
        pytest.skip("MuJoCo not run")
    numbers = json.loads((out / "numbers.json").read_text())["mujoco"]
    c = r.mujoco
    assert numbers["rolling_resistance"] == 1e-4 and numbers["pivoting_resistance"] == 5e-3
    assert numbers["coinflight_rest"] == c.fractions(c.coinflight.rest).tolist()
    p = np.array(numbers["coinflight_rest"])
    np.testing.assert_allclose(numbers["coinflight_rest_stderr"], np.sqrt(p * (1 - p) / c.n))
    assert numbers["speed_ratio"] == c.mujoco_seconds / c.coinflight.seconds
    assert numbers["coinflight_ended_at_impact"] == c.coinflight.at_impact
    assert numbers["rest_agreement"] == c.rest_agreement
    md = (out / "report.md").read_text()
    assert "coinflight, at rest" in md
    assert f"{c.rest_agreement:.1%}" in md
