"""``coinflight edge``: P(edge) per ratio h/d as numbers (issue 11)."""

from __future__ import annotations

import json
import math

import pytest
from typer.testing import CliRunner

from _cli import answer
from coinflight.cli import app
from coinflight.studies.edge import edge_probability

RATIOS = [0.1, 0.3, 0.577, 1.0]


def _run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(app, ["edge", *args])
    return result.exit_code, result.stdout, result.stderr


def test_json_rows_are_the_closed_form_models():
    # Yong & Mahadevan 2011 (REFERENCES §5): geometric (h/d)/sqrt(1 + (h/d)²), dynamic
    # 2 arctan(h/d)/π; also written out here so that the command is checked against the formula.
    code, out, _ = _run("--ratios", "0.1,0.3,0.577,1", "--json")
    assert code == 0
    rows = json.loads(out)
    keys = {"ratio", "p_edge_geometric", "p_edge_dynamic", "coinflight_version", "command"}
    assert [set(row) for row in rows] == [keys] * 4
    assert [row["ratio"] for row in rows] == RATIOS
    for row, x in zip(rows, RATIOS, strict=True):
        geometric = float(edge_probability(x, "geometric"))
        dynamic = float(edge_probability(x, "dynamic"))
        assert row["p_edge_geometric"] == pytest.approx(geometric, abs=1e-12)
        assert row["p_edge_dynamic"] == pytest.approx(dynamic, abs=1e-12)
        assert row["p_edge_geometric"] == pytest.approx(x / math.sqrt(1 + x * x), abs=1e-12)
        assert row["p_edge_dynamic"] == pytest.approx(2 * math.atan(x) / math.pi, abs=1e-12)
    # h/d = 1: geometric 1/√2, dynamic exactly 1/2.
    assert rows[-1]["p_edge_dynamic"] == pytest.approx(0.5, abs=1e-12)


def test_simulated_rows_are_reproducible_and_follow_the_dynamic_model():
    args = ("--ratios", "0.1,0.3,0.577,1", "--simulate", "2000", "--seed", "1", "--json")
    code, out, _ = _run(*args)
    assert code == 0
    assert _run(*args)[1] == out  # same seed, same numbers
    rows = json.loads(out)
    for row in rows:
        s = row["simulated"]
        assert set(s) == {"p_edge", "stderr", "n", "successes", "seed"}
        assert s["n"] == 2000 and s["seed"] == 1
        assert s["p_edge"] == s["successes"] / 2000
        assert math.isfinite(s["stderr"]) and s["stderr"] > 0
        # Dead landings of vigorous planar spins: the dynamic model, within 4 s.e.
        assert abs(s["p_edge"] - row["p_edge_dynamic"]) < 4 * s["stderr"]


def test_seed_is_drawn_and_reported_when_not_given():
    drawn = ["edge", "--ratios", "0.577", "--simulate", "200", "--json"]
    first = answer(CliRunner().invoke(app, drawn), drawn)
    seed = first[0]["simulated"]["seed"]
    assert isinstance(seed, int)
    given = [*drawn, "--seed", str(seed)]
    assert answer(CliRunner().invoke(app, given), given) == first


def test_setting_options_reach_the_simulation():
    from coinflight.model.distributions import Fixed, Uniform
    from coinflight.studies.edge import simulate_edge

    args = ["--ratios", "0.3", "--simulate", "300", "--seed", "2", "--json"]
    setting = ["--restitution", "0.4", "--friction", "0.5", "--drop-height", "0.3"]
    setting += ["--omega-x", "100:200", "--launch-speed", "2", "--g", "9.8"]
    code, out, _ = _run(*args, *setting)
    assert code == 0
    ((_, expected),) = simulate_edge(
        [0.3],
        300,
        2,
        restitution=0.4,
        friction=0.5,
        drop_height=0.3,
        spin=Uniform(100.0, 200.0),
        launch_speed=Fixed(2.0),
        g=9.8,
    )
    assert json.loads(out)[0]["simulated"]["successes"] == expected.successes


def test_the_resistances_reach_the_simulation():
    """--rolling-resistance and --pivoting-resistance reach simulate_edge: the rigid ending,
    which carries every bouncing landing (--restitution > 0) to rest, takes them."""
    from coinflight.studies.edge import simulate_edge

    args = ["--ratios", "0.1,0.577", "--simulate", "200", "--seed", "4", "--json"]
    resist = ["--restitution", "0.5", "--rolling-resistance", "1e-3",
              "--pivoting-resistance", "1e-3"]  # fmt: skip
    code, out, _ = _run(*args, *resist)
    assert code == 0
    expected = simulate_edge([0.1, 0.577], 200, 4, restitution=0.5,
                             rolling_resistance=1e-3, pivoting_resistance=1e-3)  # fmt: skip
    got = [row["simulated"]["successes"] for row in json.loads(out)]
    assert got == [e.successes for _, e in expected]


def test_the_corner_radius_reaches_the_simulated_coins():
    """--corner-radius rounds every ratio's coin (simulate_edge's coins): the same tosses (same
    seed) change their landings as a grows, and at a = h/2 the coin has no edge band left, so
    none of its dead landings stands on edge (core.outcome's well of a rounded rim), against
    the dynamic model's 2 arctan(0.3)/π = 0.186 for the sharp coin."""
    from coinflight.studies.edge import simulate_edge

    args = ["--ratios", "0.3", "--simulate", "1000", "--seed", "5", "--json"]
    half = 0.5 * 0.3 * 0.024  # h/2 of the h/d = 0.3 coin, m
    runs = {}
    for a in (None, 3e-4, half):
        code, out, _ = _run(*args, *([] if a is None else ["--corner-radius", repr(a)]))
        assert code == 0
        runs[a] = json.loads(out)[0]["simulated"]
    assert "corner_radius" not in runs[None]  # sharp: the row as it was
    assert runs[3e-4]["corner_radius"] == 3e-4 and runs[half]["corner_radius"] == half
    sharp, rounded, flat = (runs[a]["successes"] for a in (None, 3e-4, half))
    assert abs(sharp / 1000 - 2 * math.atan(0.3) / math.pi) < 4 * math.sqrt(0.186 * 0.814 / 1000)
    assert flat == 0 < rounded < sharp
    library = simulate_edge([0.3], 1000, 5, corner_radius=3e-4)
    assert library[0][1].successes == rounded


def test_text_table():
    code, out, _ = _run("--ratios", "0.577,1", "--simulate", "100", "--seed", "5")
    assert code == 0
    lines = out.splitlines()
    assert lines[0].split()[:4] == ["h/d", "geometric", "dynamic", "simulated"]
    assert lines[1].split()[:3] == ["0.577", "0.4998", "0.3332"]
    assert lines[2].split()[:3] == ["1", "0.7071", "0.5000"]
    assert lines[-1] == "seed 5"
    assert not any(line.startswith("corner radius") for line in lines)  # sharp: not said


def test_text_table_says_the_corner_radius_as_the_json_does():
    args = ("--ratios", "0.3", "--simulate", "50", "--seed", "5", "--corner-radius", "3e-4")
    code, out, _ = _run(*args)
    assert code == 0
    assert out.splitlines()[-2:] == ["corner radius 0.0003 m", "seed 5"]
    code, js, _ = _run(*args, "--json")
    assert json.loads(js)[0]["simulated"]["corner_radius"] == 3e-4


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--ratios", "0"], "thickness/diameter ratio must be between 0.001 and 100, got 0"),
        (["--ratios", "abc"], "--ratios must be comma-separated numbers"),
        (["--ratios", "0.1,,1"], "--ratios must be comma-separated numbers"),
        (["--simulate", "0"], "--simulate"),
        (["--seed", "3"], "--seed needs --target P or --simulate N"),
        (["--friction", "0.1"], "--friction needs --target P or --simulate N"),
        (["--simulate", "10", "--restitution", "2"], "restitution must be between 0 and 1"),
        (["--simulate", "10", "--omega-x", "x"], "--omega-x 'x'"),
        (["--simulate", "10", "--launch-speed", "-1:2"], "it must be positive"),
        (["--rolling-resistance", "1e-4"], "--rolling-resistance needs --target P or --simulate N"),
        (["--corner-radius", "1e-4"], "--corner-radius needs --target P or --simulate N"),
        (
            ["--ratios", "0.577,0.1,1", "--simulate", "10", "--corner-radius", "0.002"],
            "--corner-radius: corner radius must be between 0 and 0.0012 (in m), got 0.002: at "
            "most half the "
            "thickness h/2 of the thinnest coin (h/d = 0.1, h = 0.0024 m)",
        ),
        (
            ["--simulate", "10", "--corner-radius", "-1e-4"],
            "--corner-radius: corner radius must be between 0",
        ),
        (  # coins thicker than wide (h/d = 2): the bound is the radius, 12 mm, not h/2
            ["--ratios", "2", "--simulate", "10", "--corner-radius", "0.02"],
            "--corner-radius: corner radius must be between 0 and 0.012 (in m), got 0.02: at "
            "most the radius r "
            "(a coin thicker than wide) of the thinnest coin (h/d = 2, h = 0.048 m)",
        ),
        (
            ["--simulate", "10", "--restitution", "0.5", "--pivoting-resistance", "0.5"],
            "pivoting resistance must be between 0 and 0.01",
        ),
        *(  # dead landings (e = 0) never reach the rigid ending: a resistance would be ignored
            (
                [*run, *e, f"--{which}-resistance", "1e-4"],
                f"--{which}-resistance acts on landings that bounce (--restitution above 0)",
            )
            for run in (["--simulate", "10"], ["--target", "1/3"])
            for e in ([], ["--restitution", "0"])
            if run[0] == "--simulate" or e
            for which in ("rolling", "pivoting")
        ),
        *(
            (
                ["--target", text],
                f"--target must be a probability strictly between 0 and 1, "
                f"a fraction such as 1/3 or a decimal such as 0.333; got {text!r}",
            )
            for text in ("0", "1", "2", "abc", "1/0", "-1/3", "nan", "1/3/4")
        ),
        (["--target", "1/3", "--ratios", "0.5"], "--ratios applies without --target"),
        *(
            (
                ["--target", "1/3", "--psi", text],
                "--psi must be a cone angle in degrees above 0 "
                f"and at most 90, or human; got {text!r}",
            )
            for text in ("0", "95", "abc", "nan")
        ),
        (["--simulate", "10", "--psi", "human"], "--psi applies with --target"),
        (
            ["--target", "1/3", "--corner-radius", "0.02"],
            "--corner-radius: corner radius must be between 0 and 0.012",
        ),
        (
            ["--target", "1/3", "--simulate", "1000000"],
            "more than the limit of 3,600 s; use fewer tosses per ratio",
        ),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args, words):
    code, out, err = _run(*args)
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("coinflight: error: ")
    assert words in lines[0]


def test_help():
    from coinflight.studies import edge as study

    code, out, _ = _run("--help")
    assert code == 0
    # The defaults the help states are the simulation's.
    assert (study.SIM_RESTITUTION, study.SIM_FRICTION, study.SIM_DROP) == (0.0, 0.3, 0.5)
    assert (study.SIM_SPIN, study.SIM_LAUNCH_SPEED) == ((150.0, 300.0), (1.5, 3.0))
    assert "(restitution 0, friction 0.3) on a table 0.5 m below" in out
    for flag in ("--ratios", "--simulate", "--seed", "--restitution", "--friction", "--json"):
        assert flag in out
    # The resistances act on every landing that bounces (the rigid ending carries it to rest),
    # on none that lands dead: each option says so.
    text = " ".join(out.replace("│", " ").split())
    bouncing = (
        "It acts on every landing that bounces (--restitution above 0), which the rigid ending "
        "carries to rest; dead landings (restitution 0, the default of --simulate) never reach "
        "that ending, and refuse the option."
    )
    assert text.count(bouncing) == 2  # --rolling-resistance and --pivoting-resistance
    assert "--ending" not in out


def test_target_json_carries_the_band_the_closed_forms_the_measured_rows_and_the_run():
    args = ["edge", "--target", "1/3", "--simulate", "400", "--seed", "2", "--json"]
    first = answer(CliRunner().invoke(app, args), args)
    again = ["edge", "--target", "0.3333333333333333", "--simulate", "400", "--seed", "2", "--json"]
    second = answer(CliRunner().invoke(app, again), again)
    for obj in (first, second):
        obj.pop("elapsed")
    assert first == second  # 1/3 written either way, same seed: the same search
    assert first["target"] == pytest.approx(1 / 3, rel=1e-15)
    assert first["seed"] == 2 and first["n"] == 400 and "bisect" in first["method"]
    # Yong & Mahadevan (2011): 1/(2√2) geometric, 1/√3 dynamic
    ym = first["yong_mahadevan"]
    assert ym["geometric"] == pytest.approx(1 / (2 * math.sqrt(2)), rel=1e-12)
    assert ym["dynamic"] == pytest.approx(1 / math.sqrt(3), rel=1e-12)
    assert [round(m["ratio"], 3) for m in first["measured"]] == [0.354, 0.577]
    assert first["box"] == {
        "restitution": [0.3, 0.6],
        "friction": [0.05, 0.6],
        "resistance": [1e-5, 1e-3],
    }
    assert "ending" not in first  # one ending: the rigid one carries every bounce to rest
    roots = [c["ratio"] for c in first["cells"]]
    assert len(roots) == 9 and first["band"]["low"]["ratio"] == min(roots)
    assert first["band"]["high"]["ratio"] == max(roots)
    for c in first["cells"]:
        b = c["bracket"]
        assert b["low"] <= c["ratio"] <= b["high"] and b["p_low"] <= 1 / 3 <= b["p_high"]
        assert c["stderr"] is None or c["stderr"] > 0
    assert first["estimated_seconds"] > 0


def test_target_text_dead_landing_is_the_dynamic_root():
    # Restitution 0: the dynamic model's setting, root tan(π/6) = 1/√3 (Yong & Mahadevan 2011).
    code, out, _ = _run(
        "--target", "1/3", "--simulate", "20000", "--seed", "1", "--restitution", "0",
        "--friction", "0.3",
    )  # fmt: skip
    assert code == 0
    assert "every parameter given: one cell" in out
    assert "Yong & Mahadevan (2011): geometric 0.354, dynamic (dead landing) 0.577" in out
    assert "measured (standup_maths_2018): P(edge) 0.132 ± 0.011 at h/d 0.354" in out
    assert "seed 1; method: common random numbers" in out
    line = next(x for x in out.splitlines() if x.strip().endswith("e 0, μ 0.3"))
    ratio, _, se = line.split()[:3]
    assert abs(float(ratio) - 1 / math.sqrt(3)) < 4 * float(se)


def test_target_with_bouncing_landings_and_few_tosses():
    # e and μ given, neither resistance: the resistances alone spread (bouncing landings reach
    # the rigid ending, where they act).
    code, out, _ = _run(
        "--target", "1/3", "--simulate", "30", "--seed", "1",
        "--restitution", "0.45", "--friction", "0.3", "--json",
    )  # fmt: skip
    assert code == 0
    obj = json.loads(out)
    assert "ending" not in obj and obj["box"]["resistance"] == [1e-5, 1e-3]
    assert len(obj["cells"]) == 3  # the resistance's two ends and its geometric centre
    assert obj["cells"][-1]["resistance"] == pytest.approx(1e-4)


def test_target_with_a_wobble_says_it():
    # every parameter given (one cell); the resistances high: a wobbling cylinder rolls long
    one_cell = ["--restitution", "0.45", "--friction", "0.3", "--rolling-resistance", "1e-3",
                "--pivoting-resistance", "1e-3"]  # fmt: skip
    code, out, _ = _run("--target", "1/3", "--simulate", "300", "--seed", "1", "--psi", "human",
                        *one_cell, "--json")  # fmt: skip
    assert code == 0
    obj = json.loads(out)
    assert obj["setting"]["psi"] == "human" and len(obj["cells"]) == 1
    code, out, _ = _run("--target", "1/3", "--simulate", "300", "--seed", "1", "--psi", "80",
                        *one_cell)  # fmt: skip
    assert code == 0 and "tosses wobbling on a cone ψ 80°" in out
