"""``coinflight bias``, ``coinflight plot bias`` and ``coinflight data`` through the CLI."""

from __future__ import annotations

import json
import math
from importlib.resources import files
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coinflight.cli import app
from coinflight.model.distributions import Normal
from coinflight.studies import bias as b

# The counts of Bartoš et al. shipped inside the package (coinflight.datasets), nothing outside.
BARTOS = Path(str(files("coinflight.datasets") / "bartos2023.txt"))


def run(*args):
    return CliRunner().invoke(app, [str(a) for a in args])


def test_bias_fixed_psi_json():
    result = run("bias", "--psi", 60, "--json")
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    # REFERENCES §2: ψ = 60° → 0.608 (3 decimals).
    assert payload["p_same_side"] == pytest.approx(0.608, abs=5e-4)
    assert payload["psi_deg"] == 60.0
    assert payload["psi_model"] == "fixed"
    assert "monte_carlo" not in payload


def test_bias_text():
    result = run("bias", "--psi", 90)
    assert result.exit_code == 0, result.output
    assert "P(same side) = 0.500000" in result.stdout
    assert "Diaconis, Holmes & Montgomery 2007" in result.stdout


def test_bias_monte_carlo_json():
    result = run("bias", "--psi", 70, "--monte-carlo", 100_000, "--seed", 7, "--json")
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    mc = payload["monte_carlo"]
    assert (mc["n"], mc["seed"]) == (100_000, 7)
    assert mc["same"] / mc["n"] == pytest.approx(mc["p_same_side"], abs=1e-15)
    # 4 standard errors plus the finite-phase bound of tests/test_bias.py.
    assert abs(mc["p_same_side"] - payload["p_same_side"]) < 4 * mc["stderr"] + 5e-4
    assert mc["z"] == pytest.approx((mc["p_same_side"] - payload["p_same_side"]) / mc["stderr"])


def test_bias_psi_distribution():
    result = run("bias", "--psi-dist", "normal:81,5", "--json")
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    assert payload["psi_model"] == "distribution"
    assert payload["psi_dist"] == "normal:81,5"
    expected = b.mean_same_side_probability(Normal(81.0, 5.0), degrees=True)
    assert payload["p_same_side"] == pytest.approx(expected, abs=1e-12)
    # The spread adds bias: more than a fixed 81°.
    assert payload["p_same_side"] > float(b.same_side_probability(81.0, degrees=True))


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--psi", "200"], "psi must be between 0 and 180 (in degrees), got 200.0"),
        (["--psi", "-5"], "psi must be between 0 and 180 (in degrees), got -5.0"),
        ([], "give exactly one of --psi DEG, --psi-dist SPEC and --preset NAME"),
        (["--psi", "80", "--psi-dist", "normal:80,2"], "give exactly one of --psi"),
        (["--psi-dist", "normal:170,5"], "must lie within [0, 180] degrees"),
        (["--psi-dist", "normal:80"], "--psi-dist 'normal:80'"),
        (["--psi", "abc"], "'abc' is not a number"),
        (["--psi", "80", "--monte-carlo", "0"], "--monte-carlo"),
        (["--psi", "80", "--radius", "0.01"], "a custom coin needs --radius, --thickness and"),
    ],
)
def test_bias_bad_input_is_one_line_exit_2(args, message):
    result = run("bias", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr.startswith("coinflight: error: ")
    assert result.stderr.count("\n") == 1
    assert message in result.stderr


def test_plot_bias(tmp_path):
    out = tmp_path / "bias.png"
    result = run(
        "plot",
        "bias",
        "--out",
        out,
        "--monte-carlo",
        2000,
        "--psi-points",
        "60,90",
        "--measured",
        0.5077,
    )
    assert result.exit_code == 0, result.output
    assert out.is_file() and out.stat().st_size > 10_000
    assert f"wrote {out}" in result.stdout
    assert "needs a fixed ψ = 81.16°" in result.stdout


def test_plot_bias_bad_point(tmp_path):
    result = run(
        "plot", "bias", "--out", tmp_path / "x.png", "--monte-carlo", 10, "--psi-points", "60,190"
    )
    assert result.exit_code == 2
    assert "between 0 and 180" in result.stderr
    assert not (tmp_path / "x.png").exists()


NEEDS_MC = "needs --monte-carlo N (it sets the simulation)"


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["plot", "bias", "--psi-points", "10,20"], f"--psi-points {NEEDS_MC}"),
        (["plot", "bias", "--seed", "5"], f"--seed {NEEDS_MC}"),
        (["bias", "--psi", "80", "--seed", "5"], f"--seed {NEEDS_MC}"),
        (["bias", "--preset", "human", "--seed", "5"], f"--seed {NEEDS_MC}"),
        (
            ["plot", "bias", "--monte-carlo", "10", "--psi-points", "60,x"],
            "--psi-points must be comma-separated numbers such as 60,80,100; got '60,x'",
        ),
    ],
)
def test_simulation_options_need_the_simulation(tmp_path, argv, message):
    out = tmp_path / "x.png"
    result = run(*argv, *(["--out", out] if argv[0] == "plot" else []))
    assert result.exit_code == 2, result.output
    assert result.stderr == f"coinflight: error: {message}\n"
    assert not out.exists()


@pytest.mark.parametrize(
    ("points", "shown"),
    [("60,200", "200.0"), ("-1,60", "-1.0"), ("60,200,-1", "[200. -1.]")],
)
def test_bad_values_print_as_numbers(tmp_path, points, shown):
    # One offending value reads as a number ("got 200.0"), not a NumPy array ("got [200.]").
    result = run(
        "plot", "bias", "--out", tmp_path / "x.png", "--monte-carlo", 10, "--psi-points", points
    )
    assert result.exit_code == 2
    assert result.stderr == (
        "coinflight: error: precession angle psi must be between 0 and 180 (in degrees), "
        f"got {shown}\n"
    )


def test_data_json_on_the_shipped_dataset_by_default():
    # Issue 13: `coinflight data --json`, nothing else, reproduces 178,078 of 350,757.
    result = run("data", "--json", "--seed", 5)  # seed: the held-out splits
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    # REFERENCES §6 / the issue: 178,078 same-side of 350,757; 0.508 [0.506, 0.509] and
    # heads 0.500 [0.498, 0.502], printed to 3 decimals.
    assert (payload["same"], payload["flips"], payload["people"]) == (178_078, 350_757, 48)
    assert round(payload["p_same_side"], 3) == pytest.approx(0.508, abs=1e-12)
    assert [round(x, 3) for x in payload["ci95"]] == pytest.approx([0.506, 0.509], abs=1e-12)
    assert round(payload["p_heads"], 3) == pytest.approx(0.500, abs=1e-12)
    assert [round(x, 3) for x in payload["ci95_heads"]] == pytest.approx([0.498, 0.502], abs=1e-12)
    assert payload["interval"] == "Clopper-Pearson"
    assert payload["psi_model"] == "fixed"
    psi = payload["psi_deg"]
    assert float(b.same_side_probability(psi, degrees=True)) == pytest.approx(
        payload["p_same_side"], abs=1e-12
    )
    assert payload["psi_ci95_deg"][0] < psi < payload["psi_ci95_deg"][1]
    assert len(payload["per_person"]) == 48
    assert payload["p_value"] < 1e-15
    assert payload["dataset"] == "bartos2023"
    assert payload["doi"] == "10.1080/01621459.2025.2516210"
    assert "Fair coins tend to land on the same side" in payload["citation"]
    assert payload["heads"] == 175_420
    # --dataset bartos2023 and --counts on the shipped file give the same numbers.
    named = json.loads(run("data", "--dataset", "bartos2023", "--json", "--seed", 5).stdout)
    from_file = json.loads(run("data", "--counts", BARTOS, "--json", "--seed", 5).stdout)
    # the same answer; each says its own command line (coinflight._provenance)
    assert named == {**payload, "command": "coinflight data --dataset bartos2023 --json --seed 5"}
    assert from_file["command"] == f"coinflight data --counts {BARTOS} --json --seed 5"
    assert from_file["dataset"] is None and from_file["source"] == str(BARTOS)
    strip = ("dataset", "source", "title", "citation", "doi", "provenance", "command")
    assert {k: x for k, x in from_file.items() if k not in strip} == {
        k: x for k, x in payload.items() if k not in strip
    }


def test_data_text_and_forest_plot(tmp_path):
    out = tmp_path / "forest.svg"
    result = run("data", "--counts", BARTOS, "--plot", out, "--interval", "wilson")
    assert result.exit_code == 0, result.output
    assert "same side: 178,078 of 350,757 = 0.50770" in result.stdout
    assert "95% Wilson interval [0.50604, 0.50935]" in result.stdout
    assert "heads:     175,420 of 350,757 = 0.50012" in result.stdout
    assert "a fixed ψ for every flip): ψ = 81.16°" in result.stdout
    assert "TianqiP" in result.stdout
    assert out.is_file()
    assert "TianqiP" in out.read_text(encoding="utf-8")


def test_data_psi_sd():
    result = run("data", "--counts", BARTOS, "--psi-sd", 3, "--json")
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    assert payload["psi_model"] == "normal"
    assert payload["psi_sd_deg"] == 3.0
    p = b.mean_same_side_probability(Normal(payload["psi_deg"], 3.0), degrees=True)
    assert p == pytest.approx(payload["p_same_side"], abs=1e-9)


def test_data_malformed_file_names_the_line(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text(
        "person hsame hdiff tsame tdiff same flips\nA 1 2 3 4 4 10\nB 1 2 3 4\n", encoding="utf-8"
    )
    result = run("data", "--counts", bad)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr.count("\n") == 1
    assert f"coinflight: error: {bad}, line 3: expected 7 columns" in result.stderr


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--interval", "bayes"], "interval method must be one of exact, wilson"),
        (["--psi-sd", "-1"], "--psi-sd must be a non-negative number"),
        (["--psi-sd", "20"], "a spread of psi of 20° is too wide"),
        (["--psi-sd", "30"], "a spread of psi of 30° is too wide"),
    ],
)
def test_data_bad_options(args, message):
    result = run("data", "--counts", BARTOS, *args)
    assert result.exit_code == 2
    assert message in result.stderr


def test_data_spread_too_large_for_the_rate():
    # sd 12°: even a mean of 90° gives more than the measured 0.5077, so no ψ; said, exit 0.
    result = run("data", "--counts", BARTOS, "--psi-sd", 12, "--json")
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    assert payload["psi_deg"] is None
    assert payload["psi_ci95_deg"] is None  # was [90.0, 90.0]: an interval about no angle
    assert payload["p_same_side_floor"] > payload["p_same_side"]
    text = run("data", "--counts", BARTOS, "--psi-sd", 12).stdout
    (line,) = [s for s in text.splitlines() if s.startswith("precession")]
    assert "no ψ gives this same-side rate" in line and "interval" not in line


def test_data_missing_file(tmp_path):
    result = run("data", "--counts", tmp_path / "none.txt")
    assert result.exit_code == 2
    assert "cannot read counts file" in result.stderr


def test_psi_sd_default_is_fixed_angle():
    # The reported ψ is documented as a fixed angle unless --psi-sd is given.
    result = run("data", "--counts", BARTOS, "--json")
    payload = json.loads(result.stdout)
    assert payload["psi_sd_deg"] == 0.0
    assert payload["psi_deg"] == pytest.approx(
        float(b.psi_for_probability(178_078 / 350_757, degrees=True)), abs=1e-9
    )
    assert math.isfinite(payload["psi_deg"])


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            ["--dataset", "bartos2023", "--counts", "x.txt"],
            "give either --dataset or --counts, not both (got --dataset bartos2023 and "
            "--counts x.txt)",
        ),
        (["--dataset", "nope"], "dataset must be one of bartos2023; got 'nope'"),
        (["--counts", "/dev/zero"], "counts files may be at most 16 MiB (16,777,216 bytes)"),
    ],
)
def test_data_source_errors_are_one_line(args, message):
    if "/dev/zero" in args and not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero")
    result = run("data", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    (line,) = result.stderr.splitlines()
    assert line.startswith("coinflight: error: ") and message in line


def test_data_counts_of_1e18_are_a_range_error_not_scipys(tmp_path):
    # Issue 10 item 6: "brentq raised a ValueError; report this to the SciPy developers".
    big = tmp_path / "big.txt"
    big.write_text(
        "person hsame hdiff tsame tdiff same flips\n"
        "A 1000000000000000000 1 1000000000000000000 1 2000000000000000000 2000000000000000002\n",
        encoding="utf-8",
    )
    result = run("data", "--counts", big)
    assert result.exit_code == 2
    assert result.stderr == (
        f"coinflight: error: {big}, line 2: hsame must be between 0 and 1,000,000,000,000, "
        "got 1000000000000000000\n"
    )


def test_data_text_names_the_dataset_and_its_doi():
    first = run("data").stdout.splitlines()[0]
    assert first == (
        "bartos2023 (Bartoš et al. 2023, doi:10.1080/01621459.2025.2516210): 48 people, "
        "350,757 flips"
    )


def test_data_forest_plot_of_too_many_people_is_refused_before_computing(tmp_path, monkeypatch):
    # One row per person: a forest plot of 200,000 people would be a figure miles tall.
    import coinflight.cli.data
    import coinflight.studies.data

    monkeypatch.setattr(coinflight.cli.data, "PLOT_MAX_PEOPLE", 47)

    def refuse(*_args, **_kwargs):
        raise AssertionError("summarized before refusing the plot")

    monkeypatch.setattr(coinflight.studies.data, "summarize", refuse)
    result = run("data", "--plot", tmp_path / "forest.png")
    assert result.exit_code == 2
    assert result.stderr == (
        "coinflight: error: --plot draws one row per person: at most 47 people, got 48; "
        "leave out --plot (--json lists every person)\n"
    )
    assert list(tmp_path.iterdir()) == []
