"""``coinflight toss``: one toss, caught in the hand at launch height."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import typer

from coinflight.cli.command import command
from coinflight.cli.groups import CoinOptions, TossOptions
from coinflight.cli.landing_groups import AirOptions, TableOptions
from coinflight.cli.options import Bounces, JsonFlag, print_json
from coinflight.cli.surface import build_drag, build_surface, check_bounces, report_landing
from coinflight.cli.values import build_toss

if TYPE_CHECKING:
    from coinflight.cli.values import TossArgs
    from coinflight.model.coin import Coin
    from coinflight.model.toss import Flight


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

    the_surface = build_surface(*table)
    the_drag = build_drag(*air)
    check_bounces(the_surface, bounces)
    the_toss = build_toss(args)
    if the_surface.bounces or the_drag is not None:
        report_landing(coin, the_toss, the_surface, the_drag, json_output, bounces)
        return
    flight = Flight(coin, the_toss)
    if json_output:
        print_json(_payload(flight, args))
        return
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


def _payload(flight: Flight, args: TossArgs) -> dict[str, object]:
    """The JSON object of ``coinflight toss --json`` for a catch in the hand."""
    out, catch, t, coin = flight.outcome, flight.catch, flight.toss, flight.coin
    return {
        "outcome": out.face_name,
        "same_side": bool(out.same_side),
        "rotations": float(out.rotations),
        "psi": float(out.psi),
        "psi_deg": math.degrees(float(out.psi)),
        "normal": catch.normal,
        "angular_momentum": catch.angular_momentum,
        "omega_at_catch": catch.omega,
        "cos_theta": float(out.alignment),
        "flight_time": float(t.flight_time),
        "launch_speed": float(t.launch_speed),
        "apex": float(t.apex),
        "omega": list(args.omega),
        "start": args.start,
        "g": t.g,
        "coin": _coin_dict(coin),
    }


def _coin_dict(coin: Coin) -> dict[str, object]:
    # Belongs on Coin (model/coin.py) as to_dict; cli/surface.report_landing writes the same.
    return {
        "name": coin.name,
        "radius": coin.radius,
        "thickness": coin.thickness,
        "mass": coin.mass,
    }


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
