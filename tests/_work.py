"""Work checks shared by the tests: a refusal comes before any work, the work made to fail the
test if it runs (not a clock: the machine is shared), and before any large allocation
(a tracemalloc peak)."""

from __future__ import annotations

import tracemalloc
from collections.abc import Callable, Sequence

import pytest

from coinflight.probability import _runner

MB = 2**20

RUNS_TASKS = ((_runner, "completed"),)
"""Where the tasks of every estimator and study run (:func:`coinflight.probability._runner.
run_tasks` calls it): the tosses, grid bands and map stripes."""


def command_work() -> list[tuple[object, str]]:
    """What does the work of any command: every estimator's, study's and map's tasks, the bias
    study's draws, the flights through air, a map's grid and its catches in the hand, any
    figure (a movie's frames included)."""
    from matplotlib.figure import Figure

    from coinflight.core import drag
    from coinflight.outcomes.hand import HandCatch
    from coinflight.probability import streams
    from coinflight.studies import basin

    return [
        *RUNS_TASKS,
        (streams, "unit_cube"),
        (drag, "catch"),
        (drag, "land"),
        (basin, "midpoints"),
        (HandCatch, "faces"),
        (Figure, "__init__"),
    ]


def exact_work() -> list[tuple[object, str]]:
    """What does the work of the exact method's integrals: the band measures of each rule
    (closed form, Gauss, (Ω, ψ)), the (Ω, ψ) rule's search for crossings and its integral,
    and the plane density's interpolant."""
    from coinflight.core import bands
    from coinflight.probability.exact import omega_psi

    measures = ("diameter_spin_integral", "time_average_uniform", "same_side_normal_time",
                "same_side_over_times", "in_band", "band_edges")  # fmt: skip
    return [
        *((bands, name) for name in measures),
        (omega_psi, "_crossings"),
        (omega_psi._PolarPlan, "integral"),
        (omega_psi._PlaneInterpolant, "_build"),
    ]


def ran(where: str) -> Callable[..., object]:
    """A stand-in for the function ``where`` that fails the test if called."""

    def fail(*_args: object, **_kwargs: object) -> object:
        raise AssertionError(f"{where} ran before the refusal")

    return fail


def never_run(patch: pytest.MonkeyPatch, never: Sequence[tuple[object, str]]) -> None:
    """Replace each ``(owner, name)`` of ``never`` by :func:`ran`'s stand-in."""
    for owner, name in never:
        patch.setattr(owner, name, ran(f"{getattr(owner, '__name__', owner)}.{name}"))


def refused_cheaply(
    call: Callable[[], object],
    match: str,
    never: Sequence[tuple[object, str]],
    peak_mb: float = 16.0,
) -> str:
    """``call()`` raises ValueError matching ``match`` before any of ``never`` runs (each
    ``(owner, name)`` a function doing the work, replaced by one failing the test if called;
    none: the work is the allocation), with a tracemalloc peak below ``peak_mb`` MB (the
    refused requests would allocate GBs); the message."""

    with pytest.MonkeyPatch.context() as patch:
        never_run(patch, never)
        tracemalloc.start()
        try:
            with pytest.raises(ValueError, match=match) as info:
                call()
            _, peak = tracemalloc.get_traced_memory()
        finally:
            tracemalloc.stop()
    assert peak < peak_mb * MB, f"peak {peak / MB:.1f} MB before refusing"
    return str(info.value)


def counted_catch(omega: object, launch_speed: float, air: object, budget: float) -> tuple:
    """A hand catch by the drag kernel's own loop (``catch_one.py_func``, heads up) with its
    steps counted and its budget ``MAX_STEPS`` set to ``budget``: (steps taken, the catch). A
    bound on the steps, not a clock (the machine is shared): a regression ends at the budget
    (catch time −1), not in hours. The patches are undone before any kernel compiles."""
    from coinflight.core import drag

    steps = 0
    step_size = drag.step_size

    def counted(*args: object) -> object:
        nonlocal steps
        steps += 1
        return step_size(*args)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(drag, "step_size", counted)
        patch.setattr(drag, "MAX_STEPS", int(budget))
        got = drag.catch_one.py_func(omega, 1.0, launch_speed, air)
    return steps, got
