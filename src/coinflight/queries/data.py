"""Real flips against the precession model (``coinflight data --json``, ``GET /api/data``): the
counts summarized, ψ fitted, the people's ψ population fitted and checked, the JSON object."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from coinflight.studies.data import CountsSummary, CountsTable
    from coinflight.studies.flippers import FlipperAnalysis


def check_psi_sd(psi_sd: float) -> float:
    """--psi-sd: a finite number of degrees ≥ 0."""
    if not (math.isfinite(psi_sd) and psi_sd >= 0.0):
        raise ValueError(f"--psi-sd must be a non-negative number of degrees, got {psi_sd:g}")
    return psi_sd


def check_splits(seed: int | None, folds: int, repeats: int) -> None:
    """--seed, --folds and --repeats of the held-out check, in the library's words."""
    from coinflight import _validation as v
    from coinflight.probability import streams
    from coinflight.studies.flippers import MAX_REPEATS

    streams.check_seed(seed)
    v.count("--folds", folds, 2)
    v.count("--repeats", repeats, 1, MAX_REPEATS)


def flippers(
    table: CountsTable, seed: int | None, folds: int, repeats: int
) -> FlipperAnalysis | str:
    """The ψ population of the table's people (:func:`coinflight.studies.flippers.analyse`), or
    the one line saying why it is not fitted (more people than it is fitted to; folds more than
    people)."""
    from coinflight import _validation as v
    from coinflight.studies.flippers import MAX_FIT_PEOPLE, analyse

    people = len(table.people)
    if people > MAX_FIT_PEOPLE:
        shown, most = v.over_limit(people, MAX_FIT_PEOPLE)
        return f"not fitted: the ψ population is fitted to at most {most} people, got {shown}"
    if people >= 2 and folds > people:
        raise ValueError(f"--folds must be at most the number of people ({people}), got {folds}")
    return analyse(table, seed, folds=folds, repeats=repeats)


def data_payload(
    described: dict[str, Any],
    summary: CountsSummary,
    psi_sd: float,
    written: Sequence[object] = (),
    analysis: FlipperAnalysis | str | None = None,
) -> dict[str, Any]:
    """The JSON object of ``coinflight data --json``: where the counts come from
    (``described``), the summary with ψ in degrees, the people's ψ population in
    ``heterogeneity`` (``analysis``: :func:`flippers`), and the files written (``written``)."""
    payload = {**described, **summary.to_dict(psi_sd), "plot": [str(p) for p in written]}
    if isinstance(analysis, str):
        payload["heterogeneity"]["not_fitted"] = analysis
    elif analysis is not None:
        payload["heterogeneity"] = analysis.to_dict()
    return payload


def dataset_payload(
    dataset: str | None,
    interval: str,
    psi_sd: float,
    seed: int | None = None,
    folds: int | None = None,
    repeats: int | None = None,
    bound: Callable[[str, float], None] | None = None,
) -> dict[str, Any]:
    """``coinflight data [--dataset NAME] --interval I --psi-sd S [--seed N] --json`` for a
    dataset shipped with coinflight (the package's own file: nothing else is read).

    ``bound(what, seconds)``, if given, is called with the held-out check's estimated work
    before it starts (the server refuses work beyond its budget).
    """
    from coinflight.studies.data import counts_source, summarize
    from coinflight.studies.flippers import DEFAULT_FOLDS, DEFAULT_REPEATS

    folds = DEFAULT_FOLDS if folds is None else folds
    repeats = DEFAULT_REPEATS if repeats is None else repeats
    check_psi_sd(psi_sd)
    check_splits(seed, folds, repeats)
    table, _, described = counts_source(dataset, None)
    if bound is not None:
        from coinflight.studies.flippers import held_out_seconds

        people = len(table.people)
        bound(f"a held-out check of {people} people in {folds} folds × {repeats} splits",
              held_out_seconds(people, folds, repeats))  # fmt: skip
    summary = summarize(table, interval, math.radians(psi_sd))
    analysis = flippers(table, seed, folds, repeats)
    return data_payload(described, summary, psi_sd, (), analysis)


__all__ = ["check_psi_sd", "check_splits", "data_payload", "dataset_payload", "flippers"]
