"""Real flips against the precession model (``coinflight data --json``, ``GET /api/data``): the
counts summarized, ψ fitted, the JSON object."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from coinflight.studies.data import CountsSummary


def check_psi_sd(psi_sd: float) -> float:
    """--psi-sd: a finite number of degrees ≥ 0."""
    if not (math.isfinite(psi_sd) and psi_sd >= 0.0):
        raise ValueError(f"--psi-sd must be a non-negative number of degrees, got {psi_sd:g}")
    return psi_sd


def data_payload(
    described: dict[str, Any],
    summary: CountsSummary,
    psi_sd: float,
    written: Sequence[object] = (),
) -> dict[str, Any]:
    """The JSON object of ``coinflight data --json``: where the counts come from
    (``described``), the summary with ψ in degrees, and the files written (``written``)."""
    return {**described, **summary.to_dict(psi_sd), "plot": [str(p) for p in written]}


def dataset_payload(dataset: str | None, interval: str, psi_sd: float) -> dict[str, Any]:
    """``coinflight data [--dataset NAME] --interval I --psi-sd S --json`` for a dataset
    shipped with coinflight (the package's own file: nothing else is read)."""
    from coinflight.studies.data import counts_source, summarize

    check_psi_sd(psi_sd)
    table, _, described = counts_source(dataset, None)
    return data_payload(described, summarize(table, interval, math.radians(psi_sd)), psi_sd)


__all__ = ["check_psi_sd", "data_payload", "dataset_payload"]
