"""``coinflight toss``: one toss, caught in the hand at launch height."""

from __future__ import annotations

import math

import typer

from coinflight.cli.command import command
from coinflight.cli.groups import CoinOptions, TossOptions
from coinflight.cli.landing_groups import AirOptions, TableOptions
from coinflight.cli.options import Bounces, JsonFlag, print_json
from coinflight.cli.surface import report_landing
from coinflight.queries.toss import toss_payload, toss_query


@command
def toss(
    args: TossOptions,
    coin: CoinOptions,
    table: TableOptions,
    air: AirOptions,
    bounces: Bounces = None,
    json_output: JsonFlag = False,
) -> None:
    """Toss one coin and tell which face it shows: caught at launch height, or on a table.

    Example: coinflight toss --omega 80 0 0 --flight-time 0.7
    (on a table: add --surface table --drop-height 0.8)
    """
    from coinflight.model.toss import Flight

    query = toss_query(coin, args, table, air, bounces)
    if json_output:
        print_json(toss_payload(query))
        return
    if not query.caught:
        report_landing(query.coin, query.toss, query.surface, query.drag, False, bounces)
        return
    flight = Flight(coin, query.toss)
    out, t = flight.outcome, flight.toss
    wx, wy, wz = args.omega
    typer.echo(f"{coin.describe()}, started {args.start} up")
    typer.echo(
        f"spin ω0 = ({wx:g}, {wy:g}, {wz:g}) rad/s, flight time T = {float(t.flight_time):.4g} s "
        f"(launch speed {float(t.launch_speed):.3g} m/s, apex {float(t.apex):.3g} m)"
    )
    typer.echo(
        f"lands {out.face_name.upper()} up after {_turns(float(out.rotations), float(out.psi))}"
    )


def _turns(rotations: float, psi: float) -> str:
    """What the coin did, in words: tumbling about a diameter, precessing, or only wobbling."""
    psi_deg = math.degrees(psi)
    if abs(psi_deg - 90.0) < 1e-9:
        return f"{rotations:.4f} rotations about a diameter (ψ = 90°: S ⟂ n)"
    wobble = (
        "; it only wobbles and never turns over (ψ < 45° or > 135°)"
        if abs(psi_deg - 90.0) > 45.0
        else ""
    )
    return (
        f"{rotations:.4f} turns of its normal about the angular momentum, on a cone of "
        f"half-angle ψ = {psi_deg:.1f}°{wobble}"
    )
