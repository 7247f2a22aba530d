"""benchmarks/bench_edge_experiments.py refuses a bad input in one line, exit 2, no traceback
(the study's own wording, or argparse's), before any toss is simulated."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from coinflight.model.distributions import Fixed
from coinflight.studies.edge_experiments import axial_spin

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_edge_experiments.py"


def _study_words(psi: float | str) -> str:
    """The study's refusal of ``psi`` (axial_spin's, the one wording)."""
    with pytest.raises(ValueError) as refused:
        axial_spin(0.5, Fixed(30.0), psi)
    return str(refused.value)


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (["--psi", "95"], lambda: _study_words(95.0)),
        (["--psi", "0"], lambda: _study_words(0.0)),
        (["--psi", "wobbly"], lambda: _study_words("wobbly")),
        (["--psi", "nan"], lambda: _study_words(float("nan"))),
        (["--points", "1"], lambda: "points per parameter must be between 2 and 9, got 1"),
        (["--wobble", "--psi", "80"], lambda: "--psi is one cone angle for the band"),
        (["--mujoco", "-2"], lambda: "argument --mujoco: must be a whole number ≥ 0"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args, said, tmp_path):
    run = subprocess.run(
        [sys.executable, str(SCRIPT), "10", "--contact", "2", *args],
        capture_output=True,
        text=True,
        timeout=300,  # start-up and imports only: every input is checked before a toss
        cwd=tmp_path,
    )
    assert run.returncode == 2, run.stderr
    assert run.stdout == ""
    assert "Traceback" not in run.stderr
    last = run.stderr.strip().splitlines()[-1]  # argparse's own errors print the usage first
    assert last.startswith(f"{SCRIPT.name}: error: {said()}"), run.stderr
