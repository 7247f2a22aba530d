"""benchmarks/bench_edge_experiments.py refuses a bad input in one line, exit 2, no traceback
(the study's own wording, or argparse's), before any toss is simulated."""

from __future__ import annotations

import sys

import pytest

from _bench import bench_script, load_bench
from _cli import script_error
from coinflight.model.distributions import Fixed
from coinflight.studies.edge_experiments import axial_spin

SCRIPT = bench_script("bench_edge_experiments")


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
    assert script_error(SCRIPT, ["10", "--contact", "2", *args], tmp_path).startswith(said())


# A fault during the run (a ValueError or TypeError raised once the inputs were accepted) is not
# a bad input: it keeps its traceback (it leaves main, and Python prints it, exit 1), never a
# one-line "error:" with exit 2. The studies call progress once every input is checked; the
# fault is injected after that, where the tosses run. In-process, so the fault can be injected.


def _main(monkeypatch, *args: str) -> None:
    """The benchmark's main() with ``args`` on its command line."""
    bench = load_bench("bench_edge_experiments")
    monkeypatch.setattr(sys, "argv", [str(SCRIPT), *args])
    bench.main()


def _fault(exc: Exception):
    def boom(*_args, **_kwargs):
        raise exc

    return boom


def _no_tosses(ratios, n, seed, **_kwargs):
    """simulate_edge's result shape with no toss simulated (0 edges of n): the band's part of
    a run whose MuJoCo check is what the test is about."""
    from coinflight.probability.result import BinomialEstimate

    return [(float(ratios[0]), BinomialEstimate(0, n, 1))]


@pytest.mark.parametrize("exc", [ValueError("a fault in the run"), TypeError("a fault in the run")])
@pytest.mark.parametrize("args", [[], ["--wobble"], ["--psi", "80"]], ids=["band", "wobble", "psi"])
def test_a_fault_during_the_run_keeps_its_traceback(monkeypatch, capsys, exc, args):
    import coinflight.studies.edge as edge

    monkeypatch.setattr(edge, "simulate_edge", _fault(exc))  # the first toss of the run
    with pytest.raises(type(exc), match="a fault in the run"):
        _main(monkeypatch, "10", "--contact", "2", "--points", "2", *args)
    out, err = capsys.readouterr()
    assert out.splitlines()[0].startswith(("edge experiments: 2 experiments", "wobble sweep:"))
    assert "error:" not in err


def test_a_fault_during_the_mujoco_check_keeps_its_traceback(monkeypatch, capsys):
    pytest.importorskip("mujoco")
    import coinflight.outcomes.table as table
    import coinflight.studies.edge as edge

    monkeypatch.setattr(edge, "simulate_edge", _no_tosses)
    monkeypatch.setattr(table, "land", _fault(ValueError("a fault in the run")))
    with pytest.raises(ValueError, match="a fault in the run"):
        _main(monkeypatch, "10", "--contact", "2", "--points", "2", "--mujoco", "3")
    out, err = capsys.readouterr()
    assert "the MuJoCo check: 3 tosses in both endings and in MuJoCo" in out
    assert "error:" not in err


def test_a_bad_mujoco_size_is_one_line_and_exit_2_before_the_check_runs(monkeypatch, capsys):
    """Refused by the check's own bound (not argparse's), before a toss of it."""
    pytest.importorskip("mujoco")
    import coinflight.outcomes.table as table
    import coinflight.studies.edge as edge

    monkeypatch.setattr(edge, "simulate_edge", _no_tosses)
    monkeypatch.setattr(table, "land", _fault(AssertionError("the check ran")))
    with pytest.raises(SystemExit) as ended:
        _main(monkeypatch, "10", "--contact", "2", "--points", "2", "--mujoco", "200000")
    assert ended.value.code == 2
    out, err = capsys.readouterr()
    assert "the MuJoCo check" not in out  # its progress: called only once it is accepted
    assert err == (
        f"{SCRIPT.name}: error: tosses of the MuJoCo check must be between 1 and 100000, "
        "got 200000\n"
    )
