"""P(edge) of thick coins per ratio (``coinflight edge``): the options checked in one order,
the setting of the simulated landings, the rows."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from coinflight.queries.values import parse_numbers, simulation_seed

TABLE_RATIOS = "0.1,0.3,0.577,1"
"""The ratios h/d of ``coinflight edge`` by default."""


@dataclass(frozen=True)
class EdgeQuery:
    """A checked request for the edge table: the ratios h/d, the simulated tosses per ratio
    (None: the closed forms only), their seed and the setting of
    :func:`coinflight.studies.edge.edge_table`."""

    ratios: list[float]
    simulate: int | None
    seed: int | None
    setting: dict[str, Any] = field(default_factory=dict)


def edge_query(
    ratios: str = TABLE_RATIOS,
    simulate: int | None = None,
    seed: int | None = None,
    *,
    scheduler: str | None = None,
    restitution: float | None = None,
    friction: float | None = None,
    drop_height: float | None = None,
    ending: str | None = None,
    rolling_resistance: float | None = None,
    pivoting_resistance: float | None = None,
    corner_radius: float | None = None,
    omega_x: str | None = None,
    launch_speed: str | None = None,
    g: float | None = None,
) -> EdgeQuery:
    """The options of ``coinflight edge`` checked in its order: the simulation's options need
    --simulate, so does --scheduler; the ratios; --corner-radius against the thinnest coin."""
    from coinflight.model.distributions import parse_distribution

    numbers = {
        "restitution": restitution,
        "friction": friction,
        "drop_height": drop_height,
        "ending": ending,
        "rolling_resistance": rolling_resistance,
        "pivoting_resistance": pivoting_resistance,
        "corner_radius": corner_radius,
    }
    texts = {
        "spin": ("--omega-x", omega_x, "rad/s"),
        "launch_speed": ("--launch-speed", launch_speed, "m/s"),
    }
    given = [("--" + k.replace("_", "-"), x) for k, x in numbers.items()]
    given += [(option, text) for option, text, _ in texts.values()] + [("--g", g)]
    the_seed = simulation_seed(simulate, seed, *given, run_flag="--simulate")
    setting: dict[str, Any] = {k: x for k, x in {**numbers, "g": g}.items() if x is not None}
    for key, (option, text, unit) in texts.items():
        if text is not None:
            setting[key] = parse_distribution(text, option, unit)
    if simulate is None and scheduler is not None:
        raise ValueError("--scheduler applies with --simulate (the closed forms are one task)")
    x = parse_numbers(ratios, "--ratios", TABLE_RATIOS)
    if corner_radius is not None:  # named as toss names it ("--corner-radius: corner radius …")
        from coinflight.studies.edge import check_ratios, simulated_corner_radius

        check_ratios(x)
        try:
            simulated_corner_radius(corner_radius, x)
        except ValueError as exc:
            raise ValueError(f"--corner-radius: {exc}") from None
    return EdgeQuery(x, simulate, the_seed, setting)


def edge_rows(query: EdgeQuery, executor: Any = None) -> list[dict[str, Any]]:
    """The JSON rows of ``coinflight edge --json``, one object per ratio
    (:func:`coinflight.studies.edge.edge_table`)."""
    from coinflight.studies.edge import edge_table

    return edge_table(query.ratios, query.simulate, query.seed, executor=executor, **query.setting)


__all__ = ["TABLE_RATIOS", "EdgeQuery", "edge_query", "edge_rows"]
