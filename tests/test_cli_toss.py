"""``coinflight toss`` as a new user meets it: output, JSON, help, and bad input."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from _cli import answer
from coinflight import __version__
from coinflight.cli import app

runner = CliRunner()


def run(*args: str):
    return runner.invoke(app, list(args))


def test_plain_output_is_a_short_summary():
    result = run("toss", "--omega", "80", "0", "0", "--flight-time", "0.7")
    assert result.exit_code == 0
    lines = result.stdout.strip().splitlines()
    assert len(lines) == 3
    assert "HEADS" in lines[-1]
    assert "8.9127 rotations" in lines[-1]


def test_plain_output_says_when_the_coin_only_wobbles():
    # Spin mostly about the normal: ψ < 45°, the coin never turns over (DHM 2007).
    result = run("toss", "--omega", "10", "0", "300", "--flight-time", "0.7")
    assert result.exit_code == 0
    assert "HEADS" in result.stdout
    assert "only wobbles and never turns over" in result.stdout
    result = run("toss", "--omega", "80", "0", "0", "--flight-time", "0.7")
    assert "wobbles" not in result.stdout and "rotations about a diameter" in result.stdout


def test_json_has_the_documented_fields():
    result = run(
        "toss",
        "--omega",
        "90",
        "30",
        "5",
        "--launch-speed",
        "3.5",
        "--coin",
        "eur-1",
        "--start",
        "tails",
        "--json",
    )
    assert result.exit_code == 0
    payload = json.loads(result.stdout)
    assert payload["outcome"] in {"heads", "tails"}
    for key in ("rotations", "psi"):
        assert isinstance(payload[key], float)
    assert len(payload["normal"]) == 3
    assert len(payload["angular_momentum"]) == 3
    assert payload["flight_time"] == pytest.approx(2 * 3.5 / 9.81, rel=1e-12)
    assert payload["coin"]["name"] == "€1"


def test_custom_coin_and_gravity():
    result = run(
        "toss",
        "--omega",
        "80",
        "0",
        "0",
        "-T",
        "0.7",
        "--radius",
        "0.01",
        "--thickness",
        "0.002",
        "--mass",
        "0.004",
        "--g",
        "1.62",
        "--json",
    )
    assert result.exit_code == 0
    payload = json.loads(result.stdout)
    assert payload["coin"]["radius"] == 0.01
    assert payload["launch_speed"] == pytest.approx(1.62 * 0.7 / 2, rel=1e-12)


def test_negative_spin_components_parse():
    result = run("toss", "--omega", "-80", "-3", "-1", "-T", "0.7", "--json")
    assert result.exit_code == 0
    assert json.loads(result.stdout)["omega"] == [-80.0, -3.0, -1.0]


BAD_INPUTS = [
    (["toss", "--flight-time", "0"], "flight time must be between 1e-06 and 10000 (in s)"),
    (["toss", "--flight-time", "-0.5"], "flight time must be between 1e-06 and 10000 (in s)"),
    (["toss", "--flight-time", "nan"], "flight time must be between 1e-06 and 10000 (in s)"),
    (["toss", "--flight-time", "inf"], "flight time must be between 1e-06 and 10000 (in s)"),
    (["toss", "--launch-speed", "-3"], "launch speed must be positive and finite"),
    (["toss", "--launch-speed", "0"], "launch speed must be positive and finite"),
    (["toss", "-T", "1", "--omega", "nan", "0", "0"], "omega must be finite"),
    (
        ["toss", "-T", "1", "--omega", "abc", "0", "0"],
        "Invalid value for '--omega': 'abc' is not a number",
    ),
    (["toss", "-T", "1x"], "'1x' is not a number"),
    (["toss", "-T", "1", "--omega", "1", "2"], "'--omega' requires 3 arguments"),
    (["toss", "-T", "1", "--coin", "penny"], "unknown coin 'penny'"),
    (
        ["toss", "-T", "1", "--radius", "0", "--thickness", "0.001", "--mass", "0.005"],
        "radius must be between 1e-06 and 1000 (in m)",
    ),
    (
        ["toss", "-T", "1", "--radius", "0.01", "--thickness", "-1", "--mass", "0.005"],
        "thickness must be between 1e-06 and 1000 (in m)",
    ),
    (
        ["toss", "-T", "1", "--radius", "0.01", "--thickness", "0.001", "--mass", "0"],
        "mass must be between 1e-09 and 1e+06 (in kg)",
    ),
    (
        ["toss", "-T", "1", "--radius", "0.01"],
        "a custom coin needs --radius, --thickness and --mass",
    ),
    (["toss", "-T", "1", "--coin", "eur-1", "--mass", "0.01"], "give either --coin or custom"),
    (
        ["toss", "-T", "1", "--launch-speed", "3"],
        "give exactly one of --flight-time and --launch-speed",
    ),
    (["toss"], "give exactly one of --flight-time and --launch-speed"),
    (["toss", "-T", "1", "--start", "edge"], "start must be one of heads, tails"),
    (["toss", "-T", "1", "--g", "-9.81"], "g must be between 0.001 and 1000 (in m/s²), got -9.81"),
    (["toss", "-T", "1", "--frobnicate"], "No such option: --frobnicate"),
    (["tosss"], "No such command 'tosss'"),
]


@pytest.mark.parametrize(("args", "message"), BAD_INPUTS, ids=[" ".join(a) for a, _ in BAD_INPUTS])
def test_bad_input_gives_one_clear_line_and_exit_2(args, message):
    result = run(*args)
    assert result.exit_code == 2
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("coinflight: error: ")
    assert message in lines[0]
    assert "Traceback" not in result.stderr


def test_version_and_help():
    assert run("--version").stdout.strip() == f"coinflight {__version__}"
    result = run("--help")
    assert result.exit_code == 0
    assert "toss" in result.stdout
    result = run("toss", "--help")
    assert result.exit_code == 0
    assert "--omega" in result.stdout and "--flight-time" in result.stdout


def test_help_needs_no_heavy_imports():
    """``coinflight --help`` stays fast: SciPy, numba, matplotlib and the web stack
    (fastapi, uvicorn) are imported only when used."""
    code = (
        "import sys\n"
        "from coinflight.cli import app\n"
        "from typer.main import get_command\n"
        "get_command(app)\n"
        "heavy = ('scipy', 'numba', 'matplotlib', 'fastapi', 'starlette', 'uvicorn', 'pydantic')\n"
        "print(sorted(m for m in heavy if m in sys.modules))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_console_script_runs_end_to_end():
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "coinflight",
            "toss",
            "--omega",
            "80",
            "0",
            "0",
            "-T",
            "0.7",
            "--json",
        ],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout)["outcome"] == "heads"
    bad = subprocess.run(
        [sys.executable, "-m", "coinflight", "toss", "-T", "-1"], capture_output=True, text=True
    )
    assert bad.returncode == 2
    assert (
        bad.stderr.strip()
        == "coinflight: error: flight time must be between 1e-06 and 10000 (in s), got -1.0"
    )


def test_coin_name_in_any_case_on_the_command_line():
    """``--coin US-Cent`` is the cent (presets by casefold), in ``toss`` as in every command
    that takes a coin (they share its one lookup, ``Coin.preset``)."""
    upper = ["toss", "-T", "0.7", "--coin", "US-Cent", "--json"]
    lower = ["toss", "-T", "0.7", "--coin", "us-cent", "--json"]
    assert answer(run(*upper), upper) == answer(run(*lower), lower)
    bad = run("toss", "-T", "0.7", "--coin", "US-Penny")
    assert bad.exit_code == 2
    assert bad.stderr.strip() == (
        "coinflight: error: unknown coin 'US-Penny'; known coins: us-cent, us-nickel, us-dime, "
        "us-quarter, us-half-dollar, eur-1, eur-2, eur-50c, gbp-1"
    )
