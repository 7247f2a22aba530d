"""``coinflight sweep`` and :mod:`coinflight.probability.sweep`: the table, its grammar, seeds,
resumability, whole-or-nothing output."""

from __future__ import annotations

import csv
import json
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from tests._cli import one_line_error
from typer.testing import CliRunner

from coinflight import __version__
from coinflight.cli import app
from coinflight.model.coin import Coin
from coinflight.model.distributions import Fixed, Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.model.surface import TABLE_ONLY
from coinflight.outcomes import outcome_model
from coinflight.probability import estimate
from coinflight.probability import sweep as sweep_module
from coinflight.probability.sweep import (
    CHECKPOINT_SUFFIX,
    Case,
    product_cases,
    read_checkpoint,
    read_table,
    run_sweep,
    sweep,
)
from coinflight.queries.sweep import SweepLandings, parse_dists, sweep_query
from coinflight.queries.values import parse_numbers_list

runner = CliRunner()


def _cli(*args):
    return runner.invoke(app, [str(a) for a in args])


def _floats(rows, key):
    return [None if r[key] in ("", None) else float(r[key]) for r in rows]


MC_ARGS = [
    "sweep", "--omega-x-mean", "60,80", "--omega-x-sd", "0,5", "--flight-time", "0.5:0.8",
    "--coin", "us-quarter,eur-1", "--method", "monte-carlo", "--n", "2000", "--seed", "7",
]  # fmt: skip


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_table_round_trip_and_rows_reproducible_on_their_own(tmp_path, suffix):
    out = tmp_path / f"sweep{suffix}"
    result = _cli(*MC_ARGS, "--out", out, "--json")
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    assert summary["rows"] == 8 and summary["computed"] == 8 and summary["seed"] == 7
    rows, meta = read_table(out)
    assert len(rows) == 8
    assert meta["coinflight_version"] == __version__
    assert (meta["method"], meta["n"], meta["seed"]) == ("monte-carlo", 2000, 7)
    assert meta["inputs"]["--omega-x-mean"] == "60,80"
    assert not (tmp_path / f"sweep{suffix}{CHECKPOINT_SUFFIX}").exists()
    # row order: coin, then ωx mean, then ωx sd (last fastest); sd 0 is a fixed spin
    assert [r["coin"] for r in rows] == ["US quarter"] * 4 + ["€1"] * 4
    assert [r["omega_x.kind"] for r in rows[:4]] == ["fixed", "normal", "fixed", "normal"]
    # each row is estimate() with the row's own stream: SeedSequence(seed, spawn_key=(stream,))
    for row in rows:
        sd = float(row["omega_x.sd"] or 0)
        mean = float(row["omega_x.mean"])
        dist = TossDistribution(
            omega_x=Normal(mean, sd) if sd else mean,
            flight_time=Uniform(0.5, 0.8),
            coin=Coin.preset("us-quarter" if row["coin"] == "US quarter" else "eur-1"),
        )
        seq = np.random.SeedSequence(7, spawn_key=(int(row["stream"]),))
        alone = estimate(dist, "monte-carlo", n=2000, seed=seq)
        assert float(row["p_heads"]) == alone.p_heads  # bit for bit (CSV: repr of the float)
        assert float(row["stderr"]) == alone.stderr
        assert row["p_edge"] in ("", None)  # the hand cannot leave a coin on its edge


def test_exact_rows_are_the_published_values(tmp_path):
    out = tmp_path / "s.csv"
    result = _cli(
        "sweep", "--omega-x", "60:90", "--omega-y", "0,10", "--flight-time", "0.6:0.9",
        "--out", out,
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    rows, meta = read_table(out)
    # Stefan & Cheche Figs 2a and 3a (the module docstring of probability.sweep)
    assert [round(x, 5) for x in _floats(rows, "p_heads")] == [0.49747, 0.49721]
    assert meta["seed"] is None and rows[0]["stream"] == ""
    assert "2 rows by exact" in result.stdout


def test_table_rows_have_p_edge_and_the_surface(tmp_path):
    out = tmp_path / "t.parquet"
    result = _cli(
        "sweep", "--omega-x", "60:90", "--launch-speed", "1.5:2.5", "--surface", "hand,table",
        "--restitution", "0.3,0.6", "--method", "monte-carlo", "--n", "40", "--seed", "1",
        "--out", out,
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    rows, _ = read_table(out)
    assert [r["surface"] for r in rows] == ["hand", "table", "table"]
    assert [r["restitution"] for r in rows] == [None, 0.3, 0.6]
    assert rows[0]["p_edge"] is None
    for r in rows[1:]:
        assert r["p_edge"] == r["edge"] / 40
        assert r["p_heads"] + r["p_tails"] + r["p_edge"] == pytest.approx(1.0, abs=1e-12)


def test_table_rows_keep_the_outcome_models_tallies(tmp_path):
    """The tallies of each row's outcome model (unsettled, with its fraction) are columns of
    the table, empty where the model has none (the hand)."""
    out = tmp_path / "t.csv"
    result = _cli(
        "sweep", "--omega-x", "150:300", "--omega-z=-40:40", "--launch-speed", "1.5:3",
        "--surface", "hand,table", "--restitution", "0.5", "--friction", "0.6",
        "--method", "monte-carlo", "--n", "40", "--seed", "1", "--out", out,
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    rows, _ = read_table(out)
    hand, table = rows
    tallies = ("unsettled", "unsettled_fraction")
    assert all(hand[k] in ("", None) for k in tallies)
    unsettled = int(table["unsettled"])
    assert float(table["unsettled_fraction"]) == unsettled / 40


def test_sweep_rows_carry_the_results_tallies():
    """SweepResults.to_dicts: the tally columns are the estimate's details, other details
    left out."""
    from coinflight.model.surface import Surface

    surface = Surface("table", 0.5, 0.5, 0.6)
    dist = TossDistribution(omega_x=Uniform(150.0, 300.0), omega_z=Uniform(-40.0, 40.0),
                            launch_speed=Uniform(1.5, 3.0))  # fmt: skip
    cases = [Case(dist), Case(dist, outcome_model(surface))]
    result = sweep(cases, "monte-carlo", 40, 1)
    hand, table = result.to_dicts()
    assert "unsettled" not in hand
    details = result[1].details
    for k in ("unsettled", "unsettled_fraction"):
        assert table[k] == details[k]
    assert not any(k.startswith("details.") for k in table)


def _cases(k=6):
    return [
        Case(TossDistribution(omega_x=Uniform(60 + 5 * i, 90 + 5 * i), flight_time=0.7))
        for i in range(k)
    ]


REAL_ROW_TASK = sweep_module._row_task


class _Counting:
    """_row_task that counts its calls and fails on one row (a stop in the middle)."""

    def __init__(self, fail_at=None):
        self.calls = []
        self.fail_at = fail_at
        self.real = REAL_ROW_TASK

    def __call__(self, args):
        if args[0].omega_x.low == self.fail_at:
            raise ValueError("stopped here")
        self.calls.append(args[0].omega_x.low)
        return self.real(args)


def test_a_stopped_sweep_leaves_no_table_and_the_rerun_computes_only_the_rest(
    tmp_path, monkeypatch
):
    out = tmp_path / "s.parquet"
    stopped = _Counting(fail_at=75.0)  # the 4th row
    monkeypatch.setattr(sweep_module, "_row_task", stopped)
    with pytest.raises(ValueError, match="stopped here"):
        run_sweep(_cases(), out, "monte-carlo", n=5000, seed=3, threads=1)
    assert not out.exists()  # whole or not at all
    checkpoint = tmp_path / f"s.parquet{CHECKPOINT_SUFFIX}"
    assert len(read_checkpoint(checkpoint, "monte-carlo", 5000, 3)) == 3
    rerun = _Counting()
    monkeypatch.setattr(sweep_module, "_row_task", rerun)
    results, _ = run_sweep(_cases(), out, "monte-carlo", n=5000, seed=3, threads=1)
    assert sorted(rerun.calls) == [75.0, 80.0, 85.0]  # only the missing rows
    assert results.reused == 3
    assert not checkpoint.exists()
    fresh = sweep(_cases(), "monte-carlo", n=5000, seed=3)
    assert [r.counts for r in results] == [r.counts for r in fresh]
    rows, _ = read_table(out)
    assert [r["p_heads"] for r in rows] == [r.p_heads for r in fresh]


def test_a_checkpoint_is_reused_only_for_the_same_method_n_and_seed(tmp_path, monkeypatch):
    checkpoint = tmp_path / "c.jsonl"
    sweep(_cases(3), "monte-carlo", n=1000, seed=1, checkpoint=checkpoint)
    counting = _Counting()
    monkeypatch.setattr(sweep_module, "_row_task", counting)
    assert sweep(_cases(3), "monte-carlo", n=1000, seed=1, checkpoint=checkpoint).reused == 3
    assert sweep(_cases(4), "monte-carlo", n=1000, seed=1, checkpoint=checkpoint).reused == 3
    assert counting.calls == [75.0]
    for other in [
        dict(method="monte-carlo", n=1000, seed=2),
        dict(method="monte-carlo", n=999, seed=1),
        dict(method="qmc", n=64, seed=1),
    ]:  # another run's checkpoint: refused, naming it and the run it belongs to
        with pytest.raises(
            ValueError, match=r"belongs to another run \(method monte-carlo, n 1000"
        ):
            sweep(_cases(3), **other, checkpoint=checkpoint)
        assert sweep(_cases(3), **other, checkpoint=checkpoint, fresh=True).reused == 0
        sweep(_cases(3), "monte-carlo", n=1000, seed=1, checkpoint=checkpoint, fresh=True)
    assert len(counting.calls) == 1 + 6 * 3


def test_a_torn_last_line_of_a_killed_run_is_recomputed(tmp_path):
    checkpoint = tmp_path / "c.jsonl"
    first = sweep(_cases(3), "monte-carlo", n=1000, seed=1, checkpoint=checkpoint)
    text = checkpoint.read_text()
    checkpoint.write_text(text[: len(text) - 40])  # killed while writing the last row
    again = sweep(_cases(3), "monte-carlo", n=1000, seed=1, checkpoint=checkpoint)
    assert again.reused == 2
    assert [r.counts for r in again] == [r.counts for r in first]
    # the torn line was dropped, not glued to the row appended after it
    assert len(read_checkpoint(checkpoint, "monte-carlo", 1000, 1)) == 3
    assert checkpoint.read_text().count("\n") == 4


def _edit_row(text, old, new):
    lines = text.splitlines(keepends=True)
    assert old in lines[1]
    lines[1] = lines[1].replace(old, new, 1)
    return "".join(lines)


CHECKPOINT_ARGS = [
    "sweep", "--omega-x", "60:90,65:95,70:100", "--flight-time", "0.7",
    "--method", "monte-carlo", "--n", "1000", "--seed", "5",
]  # fmt: skip


@pytest.mark.parametrize(
    "damage, words",
    [
        (lambda t: _edit_row(t, '"p_heads": 0.', '"p_heads": 1.7'), "checksum does not match"),
        (lambda t: _edit_row(t, '"p_heads": 0.', '"p_heads": 0.1'), "checksum does not match"),
        (lambda t: t + "{}\n", "line 4: it is not a row"),
        (lambda t: t.splitlines(keepends=True)[0] + "not json\n", "line 2: it is not JSON"),
        (lambda t: t.split("\n", 1)[1], "was not written by coinflight"),
        (lambda t: "", "was not written by coinflight"),
        (lambda t: "\x00\xff" * 50, "was not written by coinflight"),
        (lambda t: t.replace('"seed": 5}', '"seed": 6}', 1), "belongs to another run"),
    ],
)
def test_a_checkpoint_coinflight_did_not_write_is_refused_naming_it(
    tmp_path, monkeypatch, damage, words
):
    """Issue: a checkpoint edited to p_heads 1.7 was reused and reported; random bytes stopped
    every rerun with a decode error naming no file. Each: one line naming the file, exit 2,
    nothing computed or written; --fresh starts over."""
    out = tmp_path / "s.csv"
    checkpoint = tmp_path / f"s.csv{CHECKPOINT_SUFFIX}"
    args = [*CHECKPOINT_ARGS, "--out", out]
    monkeypatch.setattr(sweep_module, "_row_task", _Counting(fail_at=70.0))
    assert one_line_error(*args) == "stopped here"  # a run stopped at its last row
    monkeypatch.undo()
    assert len(read_checkpoint(checkpoint, "monte-carlo", 1000, 5)) == 2
    damaged = damage(checkpoint.read_bytes().decode("latin-1"))
    checkpoint.write_bytes(damaged.encode("latin-1"))
    before = checkpoint.read_bytes()
    line = one_line_error(*args)
    assert line.startswith(f"the checkpoint {checkpoint} "), line
    assert words in line and "--fresh" in line, line
    assert checkpoint.read_bytes() == before and not out.exists()
    result = _cli(*args, "--fresh", "--json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["reused"] == 0 and not checkpoint.exists()
    with open(out, newline="") as f:
        assert all(0 <= float(r["p_heads"]) <= 1 for r in csv.DictReader(f))


def test_a_checkpoint_longer_than_any_sweep_is_refused(tmp_path, monkeypatch):
    from coinflight.probability import checkpoint as checkpoint_module
    from coinflight.probability.checkpoint import Checkpoint

    path = tmp_path / "c.jsonl"
    sweep(_cases(3), "monte-carlo", n=1000, seed=1, checkpoint=path)
    monkeypatch.setattr(checkpoint_module, "MAX_ROWS", 2)  # where the checkpoint reads it
    with pytest.raises(ValueError, match=r"holds more rows than a sweep has \(2\)"):
        Checkpoint(path, "monte-carlo", 1000, 1).read()


def test_a_checkpoint_row_out_of_range_is_refused_even_with_its_checksum(tmp_path):
    """Ranges are checked on read, beyond the checksum (a row rewritten with a fresh one)."""
    from coinflight.probability.checkpoint import Checkpoint, _checksum

    path = tmp_path / "c.jsonl"
    sweep(_cases(2), "monte-carlo", n=1000, seed=1, checkpoint=path)
    header, *rows = path.read_text().splitlines()
    for change, words in [
        ({"p_heads": 1.7}, "not a number in \\[0, 1\\]"),
        ({"p_heads": 0.1}, "do not sum to 1"),
        ({"n": 2000}, "not of this run's method and n"),
        ({"counts": {"tails": -1, "heads": 1001, "edge": 0}}, "non-negative integers"),
        ({"stderr": -0.5}, "stderr is not a non-negative number"),
    ]:
        entry = json.loads(rows[0])
        entry["result"].update(change)
        entry["check"] = _checksum(entry["key"], entry["result"])
        path.write_text("\n".join([header, json.dumps(entry), rows[1]]) + "\n")
        with pytest.raises(ValueError, match=f"{path} is damaged at line 2: .*{words}"):
            Checkpoint(path, "monte-carlo", 1000, 1).read()


def test_a_checkpoint_that_is_a_link_or_a_folder_is_never_followed(tmp_path, monkeypatch):
    """Issue: a checkpoint that was a symlink was followed (rows appended to another file,
    then the link deleted). A link is refused, the file it points to untouched; --fresh
    replaces the link itself."""
    out = tmp_path / "s.csv"
    checkpoint = tmp_path / f"s.csv{CHECKPOINT_SUFFIX}"
    args = [*CHECKPOINT_ARGS, "--out", out]
    other = tmp_path / "notes.txt"
    other.write_text("mine\n")
    checkpoint.symlink_to(other)
    assert "is a symbolic link" in one_line_error(*args)
    dangling = tmp_path / "nowhere.jsonl"
    checkpoint.unlink()
    checkpoint.symlink_to(dangling)  # a link to nothing: not created through it either
    assert "is a symbolic link" in one_line_error(*args)
    assert not dangling.exists()
    result = _cli(*args, "--fresh")
    assert result.exit_code == 0, result.output
    assert other.read_text() == "mine\n" and not dangling.exists()
    assert not checkpoint.exists() and not checkpoint.is_symlink()
    out.unlink()
    checkpoint.mkdir()
    assert "is not a regular file" in one_line_error(*args)
    assert "is not a regular file" in one_line_error(*args, "--fresh")
    # a link put in its place while the sweep runs is not removed at its end
    checkpoint.rmdir()
    real = sweep_module.write_table

    def swap_then_write(*a, **k):
        checkpoint.unlink()
        checkpoint.symlink_to(other)
        return real(*a, **k)

    monkeypatch.setattr(sweep_module, "write_table", swap_then_write)
    result = _cli(*args)
    assert result.exit_code == 0, result.output
    assert checkpoint.is_symlink() and other.read_text() == "mine\n"
    checkpoint.unlink()  # nor a file of someone else's put there

    def replace_then_write(*a, **k):
        checkpoint.unlink()
        checkpoint.write_text("someone else's\n")
        return real(*a, **k)

    monkeypatch.setattr(sweep_module, "write_table", replace_then_write)
    result = _cli(*args)
    assert result.exit_code == 0, result.output
    assert checkpoint.read_text() == "someone else's\n"


def test_the_cli_resumes_after_a_failure(tmp_path, monkeypatch):
    out = tmp_path / "s.csv"
    args = [
        "sweep", "--omega-x", "60:90,65:95,70:100,75:105", "--flight-time", "0.7",
        "--method", "monte-carlo", "--n", "1000", "--seed", "5", "--out", out, "--json",
    ]  # fmt: skip
    monkeypatch.setattr(sweep_module, "_row_task", _Counting(fail_at=70.0))
    assert one_line_error(*args) == "stopped here"
    assert not out.exists() and not (tmp_path / "s.csv.json").exists()
    monkeypatch.setattr(sweep_module, "_row_task", _Counting())
    result = _cli(*args)
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["reused"] == 2
    with open(out, newline="") as f:
        assert len(list(csv.DictReader(f))) == 4


def test_rows_do_not_depend_on_the_other_rows_or_their_order():
    cases = _cases(4)
    all_rows = sweep(cases, "monte-carlo", n=3000, seed=9)
    some = sweep([cases[2], cases[0]], "monte-carlo", n=3000, seed=9)
    assert [r.counts for r in some] == [all_rows[2].counts, all_rows[0].counts]
    # a run of n tosses is the first n of a longer one, row by row
    longer = sweep(cases, "monte-carlo", n=2 * 3000, seed=9)
    assert all(a.counts != b.counts for a, b in zip(all_rows, longer, strict=True))


def test_work_and_rows_are_bounded_before_anything_runs():
    # the distributions of one parameter are counted before they are built
    message = one_line_error(
        "sweep", "--omega-x-mean", "0:1000:10000", "--omega-x-sd", "1:2:1000",
        "--flight-time", "0.7", "--out", "never.csv",
    )  # fmt: skip
    assert "is 10,000 × 1,000 = 10,000,000 distributions, more than the 100,000 rows" in message
    # and the rows before any case is built
    message = one_line_error(
        "sweep", "--omega-x-mean", "60:90:100", "--omega-x-sd", "1", "--omega-y-mean",
        "0:10:100", "--omega-y-sd", "0", "--flight-time-mean", "0.5:0.6:11",
        "--flight-time-sd", "0", "--out", "never.csv",
    )  # fmt: skip
    assert message == (
        "a sweep of 100 omega_x × 100 omega_y × 11 flight_time is 110,000 rows, more than "
        "100,000; use fewer"
    )
    message = one_line_error(
        "sweep", "--omega-x", "60:90,70:90", "--flight-time", "0.7", "--method", "monte-carlo",
        "--n", "50000000000", "--out", "never.csv",
    )  # fmt: skip
    assert message.startswith("a sweep of 2 rows by monte-carlo with n = 50000000000 is ")
    assert "use fewer values per option or a smaller n" in message


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--omega-x", "normal:80,5,normal:90,5"], "a normal is normal:MEAN,SD; for several"),
        (["--omega-x-mean", "80"], "--omega-x-mean needs --omega-x-sd"),
        (["--omega-x-sd", "5"], "--omega-x-sd needs --omega-x-mean"),
        (["--omega-x", "60:90", "--omega-x-mean", "80", "--omega-x-sd", "1"], "not both"),
        (["--omega-x-mean", "80,a", "--omega-x-sd", "1"], "'a' is not a number nor FROM:TO"),
        (["--omega-x-mean", "1:2:0", "--omega-x-sd", "1"], "COUNT a whole number 1–10000"),
        (["--omega-x-mean", "80", "--omega-x-sd", "-1"], "standard deviation must be ≥ 0"),
        (["--omega-x", "90:60"], "--omega-x '90:60'"),
        (["--restitution", "0.5"], f"--restitution {TABLE_ONLY}"),
        # the shared wording of a name outside its choices (_validation.choice)
        (["--surface", "sand"], "--surface must be one of hand, table; got 'sand'"),
        (["--surface", "table"], "--method exact handles --surface hand only"),
        (["--coin", "us-quarter,,eur-1"], "--coin 'us-quarter,,eur-1': give comma-separated"),
        (["--coin", "peso"], "peso"),
        (["--start", "heads,edge"], "--start must be one of heads, tails; got 'edge'"),
        (["--seed", "3"], "--seed applies to monte-carlo and qmc, not exact"),
        (["--n", "30"], "--n does not apply to the exact method"),
        (["--launch-speed", "2", "--flight-time", "0.7"], "give one of --flight-time and"),
    ],
)
def test_bad_input_is_one_line(args, words, tmp_path):
    base = ["sweep", "--out", tmp_path / "x.csv"]
    if not {"--omega-x", "--omega-x-mean", "--omega-x-sd"} & set(args):
        base += ["--omega-x", "60:90"]
    if not {"--launch-speed", "--flight-time"} & set(args):
        base += ["--flight-time", "0.6:0.9"]
    assert words in one_line_error(*base, *args)
    assert not list(tmp_path.iterdir())


def test_an_unknown_table_format_is_refused_before_any_work(tmp_path):
    message = one_line_error("sweep", "--omega-x", "60:90", "--flight-time", "0.7",
                             "--out", tmp_path / "x.xlsx")  # fmt: skip
    assert "the table's format follows the suffix, .parquet or .csv" in message


def test_the_query_sweeps_the_table_lists_over_the_table_rows_as_the_numbers_given(tmp_path):
    # coinflight.queries.sweep, the command's one reading: the hand row once, the table rows
    # over restitution × friction, each surface holding the list's float itself (no text
    # round trip: 0.6 / 3 is 0.19999999999999998, as numpy.linspace gives it)
    query = sweep_query(
        {"omega_x": (["60:90"], None, None), "flight_time": (["0.7"], None, None)},
        SweepLandings(surface="hand,table", restitution="0.3,0.5", friction="0:0.6:4"),
        g=9.81, method="monte-carlo", n=100, out=tmp_path / "x.csv",
    )  # fmt: skip
    assert query.cases[0].model == outcome_model("hand")
    table = [(c.model.surface.restitution, c.model.surface.friction) for c in query.cases[1:]]
    frictions = [float(x) for x in np.linspace(0, 0.6, 4)]
    assert table == [(e, mu) for e in (0.3, 0.5) for mu in frictions]
    assert not list(tmp_path.iterdir())  # nothing written by reading the options


def test_the_grammar():
    assert parse_numbers_list("150,200, 250", "--x") == [150.0, 200.0, 250.0]
    assert parse_numbers_list("0:1:3,5", "--x") == [0.0, 0.5, 1.0, 5.0]
    assert parse_dists(["60:90,10", "normal:80,5"], "--omega-x", "rad/s") == [
        Uniform(60, 90),
        Fixed(10),
        Normal(80, 5),
    ]


@settings(max_examples=25, deadline=None)
@given(
    sizes=st.lists(st.integers(1, 3), min_size=7, max_size=7),
)
def test_product_cases_has_one_row_per_combination_in_order(sizes):
    lists = {
        "omega_x": [Uniform(60 + i, 90 + i) for i in range(sizes[0])],
        "omega_y": [float(i) for i in range(sizes[1])],
        "omega_z": [float(-i) for i in range(sizes[2])],
        "flight_time": [0.5 + 0.1 * i for i in range(sizes[3])],
        "coins": [Coin.preset(c) for c in ("us-quarter", "eur-1", "us-cent")[: sizes[4]]],
        "starts": ["heads", "tails"][: min(2, sizes[5])],
        "models": [outcome_model(), outcome_model("table")][: min(2, sizes[6])],
    }
    cases = product_cases(**lists)
    expected = np.prod([len(x) for x in lists.values()])
    assert len(cases) == expected
    assert len({(c.dist, c.model.to_dict()["surface"], c.dist.coin.name) for c in cases}) == len(
        cases
    )
    last = cases[-1]
    assert last.dist.flight_time.mean == pytest.approx(lists["flight_time"][-1])
    assert cases[1 % len(cases)].dist.flight_time.mean == pytest.approx(
        lists["flight_time"][1 % sizes[3]]
    )
    assert len({c.stream() for c in cases}) == len(cases)  # a stream each


def test_without_pyarrow_a_parquet_table_says_how_to_install_it(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    message = one_line_error("sweep", "--omega-x", "60:90", "--flight-time", "0.7",
                             "--out", tmp_path / "x.parquet")  # fmt: skip
    assert message == (
        'writing Parquet needs pyarrow: pip install "coinflight[parquet]" (or write a .csv)'
    )
    assert not list(tmp_path.iterdir())  # refused before any row ran
