"""The API's query parameters: the command line's options, named with underscores
(``flight_time`` for ``--flight-time``), read into the same values the command line makes.

Errors say what the command line says, naming the option as the command line names it
(``Invalid value for '--flight-time': 'abc' is not a number``).
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import Query

from coinflight.queries.values import AirArgs, TableArgs, TossArgs


def flag(name: str) -> str:
    """The command-line option of the API parameter ``name`` (``omega_x`` → ``--omega-x``)."""
    return "--" + name.replace("_", "-")


def invalid(name: str, text: object, what: str) -> str:
    """The command line's words for a value it cannot read (typer's usage error)."""
    return f"Invalid value for '{flag(name)}': {text!r} {what}"


def numbers(text: str, name: str, count: int, metavar: str) -> tuple[float, ...]:
    """``count`` comma-separated numbers (``omega=80,0,0`` for ``--omega 80 0 0``)."""
    parts = text.split(",")
    if len(parts) != count:
        raise ValueError(
            f"{flag(name)} takes {count} comma-separated numbers {metavar}; got {text!r}"
        )
    values = []
    for part in parts:
        try:
            values.append(float(part))
        except ValueError:
            raise ValueError(invalid(name, part, "is not a number")) from None
    return tuple(values)


def gravity(g: float) -> float:
    """--g checked as the command line checks it, before anything divides by it."""
    from coinflight.model.toss import GRAVITY

    try:
        return GRAVITY.check(g)
    except ValueError as exc:
        raise ValueError(f"Invalid value for '--g': {exc}") from None


def _q(description: str, **extra: Any) -> Any:
    return Query(description=description, **extra)


# --- the coin --------------------------------------------------------------------------------
CoinName = Annotated[
    str | None,
    _q(
        "A real coin: us-cent, us-nickel, us-dime, us-quarter, us-half-dollar, eur-1, eur-2, "
        "eur-50c, gbp-1 (default us-quarter); as --coin."
    ),
]
Radius = Annotated[float | None, _q("Custom coin radius, m (as --radius).")]
Thickness = Annotated[float | None, _q("Custom coin thickness, m (as --thickness).")]
Mass = Annotated[float | None, _q("Custom coin mass, kg (as --mass).")]

# --- one toss --------------------------------------------------------------------------------
Omega = Annotated[
    str,
    _q(
        "Body-frame angular velocity at launch WX,WY,WZ, rad/s: x and y about diameters, z "
        "about the normal (as --omega WX WY WZ).",
        examples=["80,0,0"],
    ),
]
FlightTime = Annotated[float | None, _q("Flight time to catch at launch height, s.")]
LaunchSpeed = Annotated[float | None, _q("Upward launch speed, m/s (T = 2 V0 / g).")]
Start = Annotated[str, _q("Face up at launch: heads or tails.")]
Gravity = Annotated[float, _q("Gravitational acceleration, m/s².")]

# --- where it ends ---------------------------------------------------------------------------
Surface = Annotated[str, _q("hand (caught at launch height) or table (as --surface).")]
DropHeight = Annotated[float | None, _q("table: surface below the launch height, m.")]
Restitution = Annotated[float | None, _q("table: coefficient of restitution in [0, 1].")]
Friction = Annotated[float | None, _q("table: Coulomb friction coefficient ≥ 0.")]
Drag = Annotated[float | None, _q("Air drag coefficient C_d ≥ 0 (integrated numerically).")]
SpinDamping = Annotated[float | None, _q("Damping torque −K ω on the spin, N m s ≥ 0.")]
Bounces = Annotated[int | None, _q("table: stop at the contact after K bounces.")]


def toss_args(
    omega: str, flight_time: float | None, launch_speed: float | None, start: str, g: float
) -> TossArgs:
    """The toss options as the command line's :class:`~coinflight.queries.values.TossArgs`."""
    wx, wy, wz = numbers(omega, "omega", 3, "WX,WY,WZ")
    return TossArgs((wx, wy, wz), flight_time, launch_speed, start, gravity(g))


def table_args(
    surface: str, drop_height: float | None, restitution: float | None, friction: float | None
) -> TableArgs:
    """--surface and the table's options."""
    return TableArgs(surface, drop_height, restitution, friction)


def air_args(drag: float | None, spin_damping: float | None) -> AirArgs:
    """--drag and --spin-damping."""
    return AirArgs(drag, spin_damping)


Trajectory = Annotated[
    int | None,
    _q(
        "Also sample the flight at K equally spaced times, 2 ≤ K ≤ 2000 (the closed form; "
        "for drawing it).",
    ),
]
