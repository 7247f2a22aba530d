"""The options of ``coinflight convergence`` read and checked: the methods, their sizes, the
cells of method B and the seed."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from coinflight.queries.values import parse_sizes

SIZE_OPTIONS = {
    "grid_sizes": ("--grid-sizes", "grid"),
    "event_sizes": ("--event-sizes", "monte-carlo"),
    "qmc_sizes": ("--qmc-sizes", "qmc"),
}
"""The sizes of each method's series: parameter → (option, the method it applies to)."""


@dataclass(frozen=True)
class ConvergencePlan:
    """The methods to run, their sizes (only those given: the library's defaults for the
    rest), the cells of method B (0: plain Monte Carlo) and the seed."""

    methods: list[str]
    sizes: dict[str, list[int]]
    grid_cells: int
    seed: int | None


def convergence_plan(
    methods: str,
    sizes: Mapping[str, str | None],
    grid_cells: int | None = None,
    seed: int | None = None,
) -> ConvergencePlan:
    """``--methods``, the sizes of each (``sizes``: parameter of :data:`SIZE_OPTIONS` → text,
    None when not given), ``--grid-cells`` (default 100, as the paper) and ``--seed``; a
    ValueError naming the option given for a method not asked for."""
    from coinflight.probability import registry

    method_list = [m.strip() for m in methods.split(",") if m.strip()]
    parsed = {
        name: parse_sizes(text, SIZE_OPTIONS[name][0])
        for name, text in sizes.items()
        if text is not None
    }
    for name, (option, needed) in SIZE_OPTIONS.items():
        if sizes.get(name) is not None and needed not in method_list:
            raise ValueError(f"{option} applies to --methods {needed}, not given in {methods!r}")
    if not set(registry.names(seeded=True)) & set(method_list):
        if seed is not None:
            seeded = " and ".join(registry.names(seeded=True))
            raise ValueError(f"--seed applies to {seeded}, not to {methods!r}")
        if grid_cells is not None:
            raise ValueError(f"--grid-cells applies to --methods monte-carlo, not {methods!r}")
    cells = 100 if grid_cells is None else grid_cells
    if cells < 0:
        raise ValueError(f"--grid-cells must be 0 (plain Monte Carlo) or positive, got {cells}")
    return ConvergencePlan(method_list, parsed, cells, seed)


__all__ = ["SIZE_OPTIONS", "ConvergencePlan", "convergence_plan"]
