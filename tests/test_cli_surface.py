"""The --surface / --drop-height / --restitution / --friction / --drag options of the CLI."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from typer.testing import CliRunner

from _cli import answer
from coinflight import Coin, Toss
from coinflight.cli import app
from coinflight.core.bounce import MAX_IMPACTS
from coinflight.model.surface import TABLE_ONLY, Surface
from coinflight.outcomes.table import Landing

TOSS = ["toss", "--omega", "240", "5", "3", "--flight-time", "0.49"]


def _run(*args):
    return CliRunner().invoke(app, list(args))


def test_toss_on_a_table_matches_the_library():
    result = _run(
        *TOSS,
        "--surface",
        "table",
        "--drop-height",
        "0.8",
        "--coin",
        "us-nickel",
        "--restitution",
        "0.6",
        "--friction",
        "0.2",
        "--json",
    )
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    landing = Landing(
        Coin.preset("us-nickel"),
        Toss((240.0, 5.0, 3.0), 0.49),
        Surface("table", drop_height=0.8, restitution=0.6, friction=0.2),
    ).outcome
    assert out["outcome"] == landing.face_name
    assert out["bounces"] == int(landing.bounces)
    assert out["settle_time"] == pytest.approx(float(landing.settle_time), rel=1e-12)
    assert out["surface"] == "table"
    assert (out["restitution"], out["friction"], out["drop_height"]) == (0.6, 0.2, 0.8)


def test_toss_text_and_first_contact():
    result = _run(*TOSS, "--surface", "table", "--bounces", "0")
    assert result.exit_code == 0, result.output
    assert "bounces 0 times" in result.stdout
    assert "bounce limit" in result.stdout


def test_toss_with_drag_in_the_hand():
    result = _run(*TOSS, "--drag", "1.17", "--json")
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    # Drag shortens the flight below T = 0.49 s.
    assert 0.4 < out["catch_time"] < 0.49
    assert out["outcome"] in ("heads", "tails")
    assert out["drag"]["coefficient"] == 1.17


@pytest.mark.parametrize(
    ("args", "described"),
    [
        (["--spin-damping", "1e-6"], "caught in the hand, no air drag, spin damping K = 1e-06"),
        (
            ["--surface", "table", "--drag", "1.17", "--spin-damping", "2e-7"],
            "landing on a table 0 m below launch (restitution 0.5, friction 0.3, rolling "
            "resistance 0.0001 m, pivoting resistance 0.0001 m), air drag C_d = 1.17, spin "
            "damping K = 2e-07 N m s",
        ),
    ],
)
def test_toss_text_names_drag_and_spin_damping(args, described):
    result = _run(*TOSS, *args)
    assert result.exit_code == 0, result.output
    assert described in result.stdout


def test_hand_without_drag_is_unchanged():
    plain, zero = [*TOSS, "--json"], [*TOSS, "--drag", "0", "--json"]
    assert answer(_run(*plain), plain) == answer(_run(*zero), zero)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--surface", "table", "--restitution", "1.5"], "restitution must be between 0 and 1"),
        (["--surface", "table", "--restitution", "-0.5"], "restitution must be between 0 and 1"),
        (["--surface", "table", "--friction", "-0.1"], "friction must be between 0 and 3"),
        (
            ["--surface", "table", "--friction", "3.5"],
            "friction must be between 0 and 3, got 3.5",
        ),
        (["--drag", "-1"], "drag coefficient must be between 0 and 10, got -1.0"),
        (["--spin-damping", "-1"], "spin damping must be between 0 and 0.001 (in N m s)"),
        (["--surface", "table", "--drop-height", "-0.3"], "surface above the launch point"),
        (["--surface", "sand"], "surface must be one of hand, table"),
        (["--restitution", "0.5"], f"--restitution {TABLE_ONLY}"),
        (["--bounces", "2"], f"--bounces {TABLE_ONLY}"),
        (["--surface", "table", "--restitution", "abc"], "is not a number"),
    ],
)
def test_bad_input_one_line_exit_2(args, message):
    result = _run(*TOSS, *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("coinflight: error: ")
    assert message in lines[0]


def test_surface_above_launch_point_cannot_be_built():
    with pytest.raises(ValueError, match="above the launch point"):
        Surface("table", drop_height=-np.float64(0.1))


PROB = ["probability", "--omega-x", "150:300", "--launch-speed", "1.5:3", "--quiet"]


def test_probability_on_a_table_reports_p_edge():
    # A thick coin (h/d = 0.575) lands on edge often; the three probabilities add up to 1.
    coin = ["--radius", "0.012", "--thickness", "0.0138", "--mass", "0.005"]
    table = ["--surface", "table", "--drop-height", "0.5", "--restitution", "0"]
    args = [*PROB, *coin, *table, "--method", "qmc", "--n", "4096", "--seed", "3", "--json"]
    result = _run(*args)
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    assert out["p_heads"] + out["p_tails"] + out["p_edge"] == pytest.approx(1.0, abs=1e-12)
    assert out["counts"]["edge"] > 0
    # Landing dead (e = 0) in vigorous planar tosses: Yong & Mahadevan's 2 arctan(h/d)/π.
    assert out["p_edge"] == pytest.approx(2 * np.arctan(0.0138 / 0.024) / np.pi, abs=0.03)
    assert (out["surface"], out["restitution"]) == ("table", 0.0)


def test_probability_table_text_and_exact_refused():
    args = [*PROB, "--surface", "table", "--method", "monte-carlo", "--n", "60", "--seed", "1"]
    result = _run(*args)
    assert result.exit_code == 0, result.output
    assert "P(edge) = " in result.stdout
    assert "landing on a table" in result.stdout
    refused = _run(*PROB, "--surface", "table")
    assert refused.exit_code == 2
    assert "exact method handles the hand catch only" in refused.stderr


def test_probability_bad_surface_input():
    result = _run(*PROB, "--surface", "table", "--restitution", "7", "--method", "qmc")
    assert result.exit_code == 2
    assert "restitution must be between 0 and 1" in result.stderr


def test_basin_after_k_bounces(tmp_path):
    from coinflight.outcomes import outcome_model
    from coinflight.outcomes.table import land
    from coinflight.studies.basin import basin_map

    coin = Coin.preset("us-nickel")
    surface = Surface("table", drop_height=0.3)
    maps = [
        basin_map(
            coin,
            (0.3, 0.4),
            (20.0, 40.0),
            resolution=(40, 30),
            outcome=outcome_model(surface, max_bounces=k),
        )
        for k in (0, 1)
    ]
    # Pixel by pixel, the map after 0 bounces is the well at the first contact.
    t, w = np.meshgrid(maps[0].flight_time, maps[0].spin)
    omega = np.stack([w, 0 * w, 0 * w], axis=-1).reshape(-1, 3)
    first = land(coin, omega, 0.5 * 9.81 * t.reshape(-1), 1.0, 9.81, surface, max_bounces=0)
    np.testing.assert_array_equal(maps[0].face, first.face.reshape(w.shape))
    # A bounce moves some pixels to another face.
    assert np.any(maps[0].face != maps[1].face)
    out = tmp_path / "basin.png"
    args = ["plot", "basin", "--surface", "table", "--drop-height", "0.3", "--bounces", "1"]
    result = _run(*args, "--resolution", "40", "--coin", "us-nickel", "--out", str(out))
    assert result.exit_code == 0, result.output
    assert out.stat().st_size > 0
    assert "P(edge) on the grid" in result.stdout


def test_table_basin_title_names_coin_start_grid_and_table():
    from coinflight.cli.surface import table_title
    from coinflight.outcomes import outcome_model
    from coinflight.plotting.basin import plot_basin
    from coinflight.studies.basin import basin_map

    surface = Surface("table", drop_height=0.3, restitution=0.4, friction=0.2)
    basin = basin_map(
        Coin.preset("us-nickel"),
        (0.3, 0.4),
        (20.0, 40.0),
        resolution=(12, 10),
        start="tails",
        outcome=outcome_model(surface, max_bounces=1),
    )
    fig = plot_basin(basin, ending=table_title(0.3, 0.4, 0.2, 1), boundaries=False)
    title = fig._suptitle.get_text()
    assert title.startswith("Which face a US nickel shows, tossed tails up and dropped on a table")
    assert "0.3 m below launch" in title and "e = 0.4" in title and "μ = 0.2" in title
    assert "after 1 bounce" in title and "ωy0 = 0 rad/s" in title
    assert f"12×10 grid: P(heads) = {basin.heads_fraction:.4f}" in title


def test_basin_bounces_need_a_table(tmp_path):
    result = _run("plot", "basin", "--bounces", "1", "--out", str(tmp_path / "b.png"))
    assert result.exit_code == 2
    assert "--bounces applies to --surface table only" in result.stderr
    assert not (tmp_path / "b.png").exists()


def test_toss_that_never_settles_says_so():
    # e = 1, μ = 0: no energy is lost, the coin bounces for ever; the kernel stops at its impact
    # limit and the face it shows is no result.
    table = ["--surface", "table", "--restitution", "1", "--friction", "0"]
    plain = _run(*TOSS, *table)
    assert plain.exit_code == 0, plain.output
    assert f"has NOT settled after {MAX_IMPACTS} impacts" in plain.stdout
    assert "not a resting face" in plain.stdout
    assert " ends " not in plain.stdout
    out = json.loads(_run(*TOSS, *table, "--json").stdout)
    assert (out["status"], out["bounces"]) == ("unsettled", MAX_IMPACTS)


def test_probability_warns_about_tosses_that_never_settle():
    # e = 1, μ = 0 conserves energy: the coin bounces until the impact limit and never settles.
    import json

    from typer.testing import CliRunner

    from coinflight.cli import app

    args = [
        "probability",
        "--surface",
        "table",
        "--drop-height",
        "0.5",
        "--omega-x",
        "60:90",
        "-T",
        "0.6:0.9",
        "--restitution",
        "1",
        "--friction",
        "0",
        "-m",
        "monte-carlo",
        "--n",
        "100",
        "--seed",
        "1",
    ]
    result = CliRunner().invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["details"]["unsettled"] == 100
    assert any("never settled" in w for w in payload["warnings"])
    plain = CliRunner().invoke(app, args)
    assert "warning: 100 of 100 tosses (100 %) never settled" in plain.stdout


def test_surface_help_and_completion_list_the_kinds_registered_before_the_cli_is_built():
    # A plug-in registering a surface kind before the command line is imported: --surface's
    # help and metavar (built from the registry) and its shell completion name it.
    code = textwrap.dedent(
        """
        from coinflight import outcomes
        from coinflight.outcomes.hand import HandCatch

        class Pillow(HandCatch):
            name, summary, surface_refusal = "pillow", "caught on a pillow", ""

        outcomes.register("pillow", Pillow)
        from typer.testing import CliRunner

        from coinflight.cli import app
        from coinflight.cli.surface import _complete

        print(CliRunner().invoke(app, ["probability", "--help"], env={"COLUMNS": "2000"}).stdout)
        print(_complete("p"), _complete("t"))
        """
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    help_line = next(line for line in run.stdout.splitlines() if "--surface " in line)
    assert "hand|table|pillow" in help_line
    assert (
        "hand: caught at launch height (no bounce); table: falls onto a hard surface, bounces "
        "and settles heads, tails or on edge; pillow: caught on a pillow." in help_line
    )
    completions = run.stdout.strip().splitlines()[-1]
    assert completions == (
        "[('pillow', 'caught on a pillow')] [('table', 'falls onto a hard surface, bounces and "
        "settles heads, tails or on edge')]"
    )


def test_a_surface_made_first_knows_the_built_in_kinds():
    # The built-ins register when coinflight.outcomes is imported, which importing any part of
    # coinflight does: a Surface made before anything else takes them, and names them.
    code = (
        "from coinflight.model.surface import Surface\n"
        "print(Surface('table', drop_height=0.3).drop_height)\n"
        "try:\n    Surface('sand')\nexcept ValueError as e:\n    print(e)\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert run.stdout.splitlines() == ["0.3", "surface must be one of hand, table; got 'sand'"]
