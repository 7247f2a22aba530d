"""Command-line values of MuJoCo's contact settings for the MuJoCo benchmarks, checked where they
are parsed: ``type=`` helpers for argparse that build them through
:class:`coinflight.studies.mujoco_compare.FrictionSolver` (its wording), so that a bad value is
one line and exit 2, not a traceback from the middle of a run."""

from __future__ import annotations

import argparse
import contextlib
from typing import Any


def solimp(text: str) -> tuple[float, float, float]:
    """``--solimp D0,DMAX,WIDTH``: three numbers, checked by ``FrictionSolver``."""
    values: Any = text  # not numbers: refused as they are, in FrictionSolver's words
    with contextlib.suppress(ValueError):
        values = tuple(float(x) for x in text.split(","))
    return _solver(solimp=values).solimp


def timeconst(text: str) -> float:
    """``--timeconst T``: MuJoCo's contact time constant, s, checked by ``FrictionSolver``."""
    tau: Any = text  # not a number: refused as it is
    with contextlib.suppress(ValueError):
        tau = float(text)
    return _solver(timeconst=tau).timeconst


def _solver(**setting: Any) -> Any:
    from coinflight.studies import mujoco_compare as mc

    try:
        return mc.FrictionSolver(**setting)
    except (TypeError, ValueError) as refused:
        raise argparse.ArgumentTypeError(str(refused)) from None
