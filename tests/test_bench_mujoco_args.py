"""The MuJoCo benchmarks' ``--solimp`` and ``--timeconst`` (benchmarks/mujoco_args.py) and
bench_rim_impacts.py's ``--converge``-only options: a bad value is one line naming it, in
FrictionSolver's words, exit 2 and no traceback, before anything is simulated."""

from __future__ import annotations

import argparse

import pytest

from _bench import BENCH, load_bench
from _cli import script_error
from coinflight.studies import mujoco_compare as mc

pytest.importorskip("mujoco")


def _words(**setting):  # type: ignore[no-untyped-def]
    """FrictionSolver's own refusal of the setting."""
    with pytest.raises((TypeError, ValueError)) as refused:
        mc.FrictionSolver(**setting)
    return str(refused.value)


def test_the_helpers_build_through_friction_solver():
    mujoco_args = load_bench("mujoco_args")

    assert mujoco_args.solimp("0.1,0.95,3e-5") == (0.1, 0.95, 3e-5)
    assert mujoco_args.timeconst("4e-3") == 4e-3
    for text, setting in (
        ("abc", {"solimp": "abc"}),
        ("0.9,1,0.001", {"solimp": (0.9, 1.0, 0.001)}),
        ("0.9,0.95", {"solimp": (0.9, 0.95)}),
    ):
        with pytest.raises(argparse.ArgumentTypeError) as refused:
            mujoco_args.solimp(text)
        assert str(refused.value) == _words(**setting)
    for text, tau in (("0", 0.0), ("1", 1.0), ("nan", float("nan")), ("soon", "soon")):
        with pytest.raises(argparse.ArgumentTypeError) as refused:
            mujoco_args.timeconst(text)
        assert str(refused.value) == _words(timeconst=tau)


CONVERGE_ONLY = "--slip-factor, --drill-factor and --resistance"
"""The start of bench_rim_impacts.py's refusal of its ``--converge``-only options alone."""


@pytest.mark.parametrize(
    ("script", "args", "said"),
    [
        ("bench_mujoco_edges.py", ["--solimp", "abc"], "argument --solimp: "),
        ("bench_mujoco_edges.py", ["--solimp", "0.9,1,0.001"], "argument --solimp: "),
        ("bench_mujoco_edges.py", ["--timeconst", "0"], "argument --timeconst: "),
        ("bench_edge_trace.py", ["--solimp", "0.9,1,0.001"], "argument --solimp: "),
        ("bench_rim_impacts.py", ["--solimp", "abc"], "argument --solimp: "),
        (
            "bench_rim_impacts.py",
            ["--resistance", "1e-3"],
            "--slip-factor, --drill-factor and --resistance",
        ),
        (
            "bench_rim_impacts.py",
            ["--slip-factor", "3"],
            "--slip-factor, --drill-factor and --resistance",
        ),
        (
            "bench_rim_impacts.py",
            ["--drill-factor", "0"],
            "--slip-factor, --drill-factor and --resistance",
        ),
    ],
)
def test_bad_mujoco_settings_are_one_line_and_exit_2(script, args, said, tmp_path):
    message = script_error(BENCH / script, ["2", *args], tmp_path)
    assert message.startswith(said), message
    if said.startswith("argument"):
        value = args[1]
        if args[0] == "--timeconst":
            expected = _words(timeconst=float(value))
        else:
            pieces = value.split(",")
            expected = _words(solimp=tuple(map(float, pieces)) if value != "abc" else value)
        assert message == f"{said}{expected}"
