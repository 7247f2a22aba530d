"""P(edge) of thick coins per ratio (``coinflight edge``): the options checked in one order,
the setting of the simulated landings, the rows; with ``--target``, the ratio h/d for a chosen
P(edge) (:func:`coinflight.studies.edge_target.target_ratio`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from coinflight.queries.values import flag, parse_numbers, simulation_seed

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
    target: float | None = None
    """With ``--target``: the P(edge) whose ratio is searched (``ratios`` then empty and
    ``simulate`` the tosses per evaluated ratio)."""


TARGET_EXAMPLE = "a fraction such as 1/3 or a decimal such as 0.333"


def parse_target(text: str) -> float:
    """--target: a probability strictly between 0 and 1, written ``1/3`` or ``0.333``, else a
    ValueError naming the option, what it takes and the text."""
    bad = ValueError(
        f"--target must be a probability strictly between 0 and 1, {TARGET_EXAMPLE}; got {text!r}"
    )
    parts = text.split("/")
    try:
        numbers = [float(part) for part in parts]
    except ValueError:
        raise bad from None
    if len(numbers) > 2 or not all(map(math.isfinite, numbers)):
        raise bad
    if len(numbers) == 2 and numbers[1] == 0.0:
        raise bad
    p = numbers[0] / numbers[1] if len(numbers) == 2 else numbers[0]
    if not 0.0 < p < 1.0:
        raise bad
    return p


def parse_psi(text: str) -> float | str:
    """--psi: ``human`` or a cone angle in degrees (0 < ψ ≤ 90), else a ValueError naming the
    option, what it takes and the text."""
    if text.strip().lower() == "human":
        return "human"
    try:
        degrees = float(text)
    except ValueError:
        degrees = math.nan
    if not 0.0 < degrees <= 90.0:  # NaN fails too
        raise ValueError(
            f"--psi must be a cone angle in degrees above 0 and at most 90, or human; got {text!r}"
        )
    return degrees


def edge_query(
    ratios: str | None = None,
    simulate: int | None = None,
    seed: int | None = None,
    *,
    target: str | None = None,
    scheduler: str | None = None,
    restitution: float | None = None,
    friction: float | None = None,
    drop_height: float | None = None,
    rolling_resistance: float | None = None,
    pivoting_resistance: float | None = None,
    corner_radius: float | None = None,
    omega_x: str | None = None,
    launch_speed: str | None = None,
    psi: str | None = None,
    g: float | None = None,
) -> EdgeQuery:
    """The options of ``coinflight edge`` checked in its order: --target and --ratios apart; the
    simulation's options need --simulate or --target, so does --scheduler; a resistance needs
    landings that bounce (restitution above 0: given, or --target's band); the ratios;
    --corner-radius against the thinnest coin (with --target, against the coin's radius: the
    search starts at the thinnest coin that takes it)."""
    from coinflight.model.distributions import parse_distribution

    p = None
    if target is not None:
        p = parse_target(target)
        if ratios is not None:
            raise ValueError("--ratios applies without --target (--target searches the ratio)")
        if simulate is None:
            from coinflight.studies.edge_target import DEFAULT_TOSSES

            simulate = DEFAULT_TOSSES

    numbers = {
        "restitution": restitution,
        "friction": friction,
        "drop_height": drop_height,
        "rolling_resistance": rolling_resistance,
        "pivoting_resistance": pivoting_resistance,
        "corner_radius": corner_radius,
    }
    texts = {
        "spin": ("--omega-x", omega_x, "rad/s"),
        "launch_speed": ("--launch-speed", launch_speed, "m/s"),
    }
    given: list[tuple[str, object]] = [(flag(k), x) for k, x in numbers.items()]
    given += [(option, text) for option, text, _ in texts.values()] + [("--g", g)]
    the_seed = simulation_seed(simulate, seed, *given, run_flag="--target P or --simulate")
    setting: dict[str, Any] = {k: x for k, x in {**numbers, "g": g}.items() if x is not None}
    for key, (option, text, unit) in texts.items():
        if text is not None:
            setting[key] = parse_distribution(text, option, unit)
    if simulate is None and scheduler is not None:
        raise ValueError("--scheduler applies with --simulate (the closed forms are one task)")
    dead = restitution == 0.0 or (restitution is None and p is None)  # --target spreads e > 0
    for which in ("rolling", "pivoting"):
        if dead and numbers[f"{which}_resistance"] is not None:
            raise ValueError(
                f"--{which}-resistance acts on landings that bounce (--restitution above 0): "
                f"dead ones (restitution 0{', the default' if restitution is None else ''}) "
                "never reach the rigid ending, where the resistances act"
            )
    if psi is not None:
        if p is None:
            raise ValueError(
                "--psi applies with --target (the rows of --simulate are planar tosses)"
            )
        setting["psi"] = parse_psi(psi)
    if p is not None:
        if corner_radius is not None:
            from coinflight.studies.edge import SIM_RATIOS, simulated_corner_radius

            try:  # a coin thicker than wide bounds it by its radius
                simulated_corner_radius(corner_radius, [SIM_RATIOS[1]])
            except ValueError as exc:
                raise ValueError(f"--corner-radius: {exc}") from None
        return EdgeQuery([], simulate, the_seed, setting, p)
    x = parse_numbers(TABLE_RATIOS if ratios is None else ratios, "--ratios", TABLE_RATIOS)
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


def target_answer(query: EdgeQuery, executor: Any = None, progress: Any = None) -> dict[str, Any]:
    """The JSON object of ``coinflight edge --target P --json``
    (:meth:`coinflight.studies.edge_target.EdgeTarget.to_dict`)."""
    from coinflight.studies.edge_target import target_ratio

    if query.target is None or query.simulate is None:
        raise ValueError("the query has no --target")
    setting = dict(query.setting)
    result = target_ratio(
        query.target, query.simulate, query.seed, executor=executor, progress=progress, **setting
    )
    return result.to_dict()


__all__ = [
    "TABLE_RATIOS",
    "EdgeQuery",
    "edge_query",
    "edge_rows",
    "parse_psi",
    "parse_target",
    "target_answer",
]
