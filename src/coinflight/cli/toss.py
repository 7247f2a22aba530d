"""``coinflight toss``: one toss, caught in the hand at launch height."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated

import typer

from coinflight.cli.options import (
    TOSS_PANEL,
    CoinName,
    Gravity,
    JsonFlag,
    Mass,
    Radius,
    StartFace,
    Thickness,
    number,
    print_json,
    resolve_coin,
)
from coinflight.cli.surface import (
    Bounces,
    DragCoefficient,
    DropHeight,
    Friction,
    Restitution,
    SpinDamping,
    SurfaceKindOption,
    build_drag,
    build_surface,
    check_bounces,
    report_landing,
)

if TYPE_CHECKING:
    from coinflight.model.toss import Toss

Omega = Annotated[
    tuple[float, float, float],
    typer.Option(
        "--omega",
        parser=number,
        metavar="WX WY WZ",
        rich_help_panel=TOSS_PANEL,
        help="Body-frame angular velocity at launch, rad/s: x and y about diameters, "
        "z about the normal.",
    ),
]
FlightTime = Annotated[
    float | None,
    typer.Option(
        "--flight-time",
        "-T",
        parser=number,
        metavar="T",
        rich_help_panel=TOSS_PANEL,
        help="Flight time to catch at launch height, s.",
    ),
]
LaunchSpeed = Annotated[
    float | None,
    typer.Option(
        "--launch-speed",
        parser=number,
        metavar="V0",
        rich_help_panel=TOSS_PANEL,
        help="Upward launch speed, m/s (T = 2 V0 / g).",
    ),
]


def build_toss(
    omega: tuple[float, float, float],
    flight_time: float | None,
    launch_speed: float | None,
    start: str,
    g: float,
) -> Toss:
    """The :class:`~coinflight.model.toss.Toss` for the toss options (one of T and V0 required)."""
    from coinflight.model.toss import Toss

    if (flight_time is None) == (launch_speed is None):
        raise ValueError("give exactly one of --flight-time and --launch-speed")
    if flight_time is not None:
        return Toss(omega=omega, flight_time=flight_time, start=start, g=g)  # type: ignore[arg-type]
    return Toss.from_launch_speed(omega, launch_speed, start=start, g=g)  # type: ignore[arg-type]


def toss(
    omega: Omega = (80.0, 0.0, 0.0),
    flight_time: FlightTime = None,
    launch_speed: LaunchSpeed = None,
    start: StartFace = "heads",
    g: Gravity = 9.81,
    coin: CoinName = None,
    radius: Radius = None,
    thickness: Thickness = None,
    mass: Mass = None,
    surface: SurfaceKindOption = "hand",
    drop_height: DropHeight = None,
    restitution: Restitution = None,
    friction: Friction = None,
    drag: DragCoefficient = None,
    spin_damping: SpinDamping = None,
    bounces: Bounces = None,
    json_output: JsonFlag = False,
) -> None:
    """Toss one coin and tell which face it shows: caught at launch height, or on a table.

    Example: coinflight toss --omega 80 0 0 --flight-time 0.7
    (on a table: add --surface table --drop-height 0.8)
    """
    from coinflight.model.toss import Flight

    the_coin = resolve_coin(coin, radius, thickness, mass)
    the_surface = build_surface(surface, drop_height, restitution, friction)
    the_drag = build_drag(drag, spin_damping)
    check_bounces(the_surface, bounces)
    the_toss = build_toss(omega, flight_time, launch_speed, start, g)
    if the_surface.bounces or the_drag is not None:
        report_landing(the_coin, the_toss, the_surface, the_drag, json_output, bounces)
        return
    flight = Flight(the_coin, the_toss)
    out = flight.outcome
    catch = flight.catch
    t = flight.toss
    if json_output:
        print_json(
            {
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
                "omega": list(omega),
                "start": start,
                "g": t.g,
                "coin": {
                    "name": the_coin.name,
                    "radius": the_coin.radius,
                    "thickness": the_coin.thickness,
                    "mass": the_coin.mass,
                },
            }
        )
        return
    wx, wy, wz = omega
    typer.echo(f"{the_coin.describe()}, started {start} up")
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
