"""A heads/tails map over flight times and spins (``coinflight plot basin``'s map,
``GET /api/basin``): the options read as the command line reads them, the map, its JSON.

The command line draws the map (there is no ``--json``); the JSON object is the map's
:meth:`~coinflight.studies.basin.BasinMap.to_dict` (the grid's centres, the face codes row by
row along the spin axis, the fractions, the box and the toss), with ``resolution`` [NT, NW],
``surface`` (the model's description: hand, or the table's drop height, restitution, friction
and ``bounces``) and, when asked for, ``boundaries``: the analytic heads/tails boundaries as
curves ``{"flight_time": [...], "spin": [...]}`` (null where a curve leaves the box).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from coinflight.queries.landing import table_outcome
from coinflight.queries.values import TableArgs, parse_range, parse_resolution

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.studies.basin import BasinMap

HAND = TableArgs("hand", None, None, None, None)
"""The catch in the hand (no table options): the default landing of a map."""


def spin_box(
    omega_x: str | None,
    omega_y: float,
    omega_z: float,
    psi: float | None,
    precession_rate: str | None,
) -> tuple[tuple[float, float], float | None]:
    """The map's spin axis (--omega-x, or --precession-rate at a fixed --psi), and ψ in
    radians (None without --psi)."""
    if psi is None:
        if precession_rate is not None:
            raise ValueError("--precession-rate goes with --psi; use --omega-x without --psi")
        return parse_range("60:90" if omega_x is None else omega_x, "--omega-x", "rad/s"), None
    if omega_x is not None or omega_y != 0.0 or omega_z != 0.0:
        raise ValueError(
            "with --psi the spin is set by --precession-rate; drop --omega-x/--omega-y/--omega-z"
        )
    if not 0.0 < psi < 180.0:
        raise ValueError(f"--psi must be between 0 and 180 degrees (exclusive), got {psi:g}")
    spin = parse_range(
        "60:90" if precession_rate is None else precession_rate, "--precession-rate", "rad/s"
    )
    return spin, math.radians(psi)


def time_range(flight_time: str | None, launch_speed: str | None, g: float) -> tuple[float, float]:
    """The map's flight-time axis, s: --flight-time, or --launch-speed turned into T."""
    from coinflight.core.ballistics import flight_time as time_of_flight

    if flight_time is not None and launch_speed is not None:
        raise ValueError("give --flight-time or --launch-speed, not both")
    if launch_speed is None:
        return parse_range("0.6:0.9" if flight_time is None else flight_time, "--flight-time", "s")
    v_lo, v_hi = parse_range(launch_speed, "--launch-speed", "m/s")
    if v_lo <= 0:
        raise ValueError(f"--launch-speed range must be positive, got {launch_speed!r} m/s")
    return float(time_of_flight(v_lo, g)), float(time_of_flight(v_hi, g))


MAP_SECONDS = 60.0
"""Longest map of table landings a command asks for, s of estimated work at the outcome
model's rate (a minute, as the grid method's: landings carried to rest through the rigid
ending, about 70 a second for the work bounds at the default resistances, make about 4,000
cells; stopped after K bounces with --bounces, 20,000 a second, a 500×500 map takes 12.5 s).
The library's own bound is an hour (:func:`coinflight.studies.basin.basin_map`); a command that
waits for its figure or its page gets a minute."""


def basin_query(
    coin: Coin,
    *,
    flight_time: str | None = None,
    launch_speed: str | None = None,
    omega_x: str | None = None,
    omega_y: float = 0.0,
    omega_z: float = 0.0,
    psi: float | None = None,
    precession_rate: str | None = None,
    resolution: str = "500",
    start: str = "heads",
    g: float = 9.81,
    table: TableArgs = HAND,
    bounces: int | None = None,
    executor: Any = None,
    boundaries: bool = False,
) -> BasinMap:
    """The map ``coinflight plot basin`` draws, for its options as typed (``executor``: where
    its rows run, as :func:`coinflight.studies.basin.basin_map` takes it; ``boundaries``: its
    analytic boundaries will be drawn, which only the catch in the hand has, their number
    bounded before the map is computed)."""
    from coinflight import _validation as v
    from coinflight.queries.landing import landing_coin
    from coinflight.studies.basin import basin_map

    spin, psi_rad = spin_box(omega_x, omega_y, omega_z, psi, precession_rate)
    _catch_only(table, boundaries)
    outcome = table_outcome(table, bounces)
    n_t, n_w = parse_resolution(resolution)
    if outcome:  # a map of table landings: each cell a landing, at the model's rate
        v.work_bound(
            f"a map of {v.quantity(n_t)}×{v.quantity(n_w)} table landings",
            n_t * n_w / outcome["outcome"].rate,
            MAP_SECONDS,
            "s of work",
            "use a coarser resolution (e.g. 60x60), or --bounces K for the face after K bounces",
        )
    return basin_map(
        landing_coin(coin, table),
        time_range(flight_time, launch_speed, g),
        spin,
        omega_y=omega_y,
        omega_z=omega_z,
        psi=psi_rad,
        resolution=(n_t, n_w),
        start=start,
        g=g,
        executor=executor,
        boundaries=boundaries,
        **outcome,
    )


def draws_boundaries(table: TableArgs, boundaries: bool) -> bool:
    """Whether a map's analytic boundaries are drawn: asked for (``boundaries``) and the map is
    of the catch in the hand, the only one that has them. The command line draws a table's
    map without them; a request that asks for them on a table is refused (the web)."""
    return boundaries and table.surface == "hand"


def _catch_only(table: TableArgs, boundaries: bool) -> None:
    """ValueError if the analytic boundaries are asked for and the map is not of the catch in
    the hand (their own: :func:`draws_boundaries`)."""
    if boundaries and not draws_boundaries(table, boundaries):
        raise ValueError("the analytic boundaries belong to the catch in the hand; leave out "
                         "--boundaries with --surface table")  # fmt: skip


def basin_payload(
    basin: BasinMap,
    table: TableArgs = HAND,
    bounces: int | None = None,
    boundaries: bool = False,
) -> dict[str, Any]:
    """The JSON object of a map (see the module's notes)."""
    from coinflight.queries.landing import surface_from, surface_payload

    payload = basin.to_dict()
    n_w, n_t = basin.face.shape
    payload["resolution"] = [n_t, n_w]
    payload.update(surface_payload(surface_from(table), None))
    payload["bounces"] = bounces
    _catch_only(table, boundaries)
    if boundaries:
        payload["boundaries"] = [
            {"flight_time": [None if math.isnan(x) else float(x) for x in t], "spin": w.tolist()}
            for t, w in basin.boundaries(n_points=200)
        ]
    return payload


__all__ = ["basin_payload", "basin_query", "draws_boundaries", "spin_box", "time_range"]
