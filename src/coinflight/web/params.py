"""The API's query parameters: the command line's options, named with underscores
(``flight_time`` for ``--flight-time``), read into the same values the command line makes.

Errors say what the command line says, naming the option as the command line names it
(``Invalid value for '--flight-time': 'abc' is not a number``).
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import Depends, Query

from coinflight.queries.values import (
    COIN_NAMES,
    AirArgs,
    CoinArgs,
    TableArgs,
    TossArgs,
    flag,
)


def invalid(name: str, text: object, what: str) -> str:
    """The command line's words for a value it cannot read (typer's usage error)."""
    return f"Invalid value for '{flag(name)}': {text!r} {what}"


def numbers(text: str, name: str, count: int, metavar: str) -> tuple[float, ...]:
    """``count`` comma-separated numbers (``omega=80,0,0`` for ``--omega 80 0 0``)."""
    if len(text.split(",")) != count:
        raise ValueError(
            f"{flag(name)} takes {count} comma-separated numbers {metavar}; got {text!r}"
        )
    return number_list(text, name)


def number_list(text: str, name: str) -> tuple[float, ...]:
    """Comma-separated numbers, as many as given (``psis=0,5,10``)."""
    values = []
    for part in text.split(","):
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
CoinName = Annotated[str | None, _q(f"A real coin: {COIN_NAMES} (default us-quarter); as --coin.")]
Radius = Annotated[float | None, _q("Custom coin radius, m (as --radius).")]
Thickness = Annotated[float | None, _q("Custom coin thickness, m (as --thickness).")]
Mass = Annotated[float | None, _q("Custom coin mass, kg (as --mass).")]


def coin_args(
    coin: CoinName = None, radius: Radius = None, thickness: Thickness = None, mass: Mass = None
) -> CoinArgs:
    """--coin or the custom dimensions, as typed (resolved in the worker)."""
    return CoinArgs(coin, radius, thickness, mass)


CoinQuery = Annotated[CoinArgs, Depends(coin_args)]
"""The coin's four parameters, one dependency shared by the endpoints that take a coin."""

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
Surface = Annotated[
    str,
    _q(
        "Where the toss ends, as --surface: hand (caught at launch height), table, or another "
        "registered surface kind (GET /api/surfaces lists them)."
    ),
]
DropHeight = Annotated[float | None, _q("table: surface below the launch height, m.")]
Restitution = Annotated[
    str | None,
    _q("table: coefficient of restitution in [0, 1] (probability: also a distribution, 0.3:0.6)."),
]
Friction = Annotated[
    str | None, _q("table: Coulomb friction coefficient 0-3 (probability: also a distribution).")
]
RollingResistance = Annotated[
    str | None,
    _q(
        "table: rolling resistance length of the rigid ending, m, 0 to 0.01 (default 1e-4); not "
        "measured for coins, quote a band over 1e-5 to 1e-3. As --rolling-resistance."
    ),
]
PivotingResistance = Annotated[
    str | None,
    _q(
        "table: pivoting (drilling) resistance length of the rigid ending, m, 0 to 0.01 (default "
        "1e-4); not measured for coins, quote a band over 1e-5 to 1e-3. As "
        "--pivoting-resistance."
    ),
]
CornerRadius = Annotated[
    float | None,
    _q(
        "table: radius of the coin's rounded rim corners, m, 0 to half the thickness (or the "
        "radius if smaller; default 0: sharp); not measured for coins, quote a band. As "
        "--corner-radius."
    ),
]
ContactDuration = Annotated[
    str | None,
    _q(
        "table: contact duration t_c of one impact of the coin's rim, s, 1e-6 to 0.01 (default "
        "1e-4; Hertz: 5e-5 to 3e-4 on wood, 2e-5 to 4e-5 on stone or glass): rim points "
        "meeting the table less than t_c apart strike as one; not measured for coins, quote a "
        "band. As --contact-duration."
    ),
]
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
    surface: Surface = "hand",
    drop_height: DropHeight = None,
    restitution: Restitution = None,
    friction: Friction = None,
    rolling_resistance: RollingResistance = None,
    pivoting_resistance: PivotingResistance = None,
    corner_radius: CornerRadius = None,
    contact_duration: ContactDuration = None,
) -> TableArgs:
    """--surface and the table's options (as typed, parsed as the command line parses them);
    no --surface-preset."""
    return TableArgs(**locals(), surface_preset=None)


def air_args(drag: Drag = None, spin_damping: SpinDamping = None) -> AirArgs:
    """--drag and --spin-damping."""
    return AirArgs(drag, spin_damping)


TableQuery = Annotated[TableArgs, Depends(table_args)]
"""Where the toss ends: one dependency shared by the endpoints that land a coin."""
AirQuery = Annotated[AirArgs, Depends(air_args)]
"""The air: one dependency shared by the endpoints that fly through it."""


Trajectory = Annotated[
    int | None,
    _q(
        "Also sample the flight at K equally spaced times, 2 ≤ K ≤ 2000 (the closed form; "
        "for drawing it).",
    ),
]

# --- a range of tosses (probability) ------------------------------------------------------------
_DIST = "a number, LOW:HIGH (uniform) or normal:MEAN,SD"
OmegaX = Annotated[str, _q(f"Spin about the x diameter, rad/s: {_DIST} (as --omega-x).")]
OmegaY = Annotated[str, _q(f"Spin about the y diameter, rad/s: {_DIST} (as --omega-y).")]
OmegaZ = Annotated[str, _q(f"Spin about the normal, rad/s: {_DIST} (as --omega-z).")]
FlightTimes = Annotated[
    str | None, _q(f"Flight time T (catch at launch height), s: {_DIST} (as --flight-time).")
]
LaunchSpeeds = Annotated[
    str | None, _q(f"Upward launch speed v0 (T = 2 v0 / g), m/s: {_DIST} (as --launch-speed).")
]
TossPreset = Annotated[
    str | None,
    _q("A named distribution of tosses: human; toss parameters given replace its values."),
]
Method = Annotated[str, _q("exact, grid, monte-carlo or qmc (as --method).")]
Size = Annotated[int | None, _q("The method's size (as --n): cells per parameter, tosses, …")]
Seed = Annotated[int | None, _q("Seed of monte-carlo and qmc (reported; drawn if not given).")]
GridCells = Annotated[int | None, _q("monte-carlo only: draw from the midpoints of C cells.")]

# --- a map (basin) ---------------------------------------------------------------------------
FlightTimeRange = Annotated[str | None, _q("Range of flight times LO:HI, s (default 0.6:0.9).")]
LaunchSpeedRange = Annotated[str | None, _q("Range of launch speeds LO:HI, m/s, instead.")]
OmegaXRange = Annotated[str | None, _q("Range of the spin ωx0 LO:HI, rad/s (default 60:90).")]
OmegaYFixed = Annotated[float, _q("Fixed spin about the other diameter ωy0, rad/s.")]
OmegaZFixed = Annotated[float, _q("Fixed spin about the normal ωz0, rad/s.")]
PsiFixed = Annotated[
    float | None,
    _q("Fixed angle between the normal and S, degrees; the spin axis is then the precession rate."),
]
PrecessionRange = Annotated[
    str | None, _q("Range of the precession rate LO:HI, rad/s, with psi (default 60:90).")
]
Resolution = Annotated[str, _q("Grid cells: N (N×N) or NTxNW (as --resolution).")]
Boundaries = Annotated[bool, _q("Also the analytic heads/tails boundaries (hand only).")]


def basin_box(
    flight_time: FlightTimeRange = None,
    launch_speed: LaunchSpeedRange = None,
    omega_x: OmegaXRange = None,
    omega_y: OmegaYFixed = 0.0,
    omega_z: OmegaZFixed = 0.0,
    psi: PsiFixed = None,
    precession_rate: PrecessionRange = None,
    resolution: Resolution = "500",
    start: Start = "heads",
    g: Gravity = 9.81,
    bounces: Bounces = None,
    boundaries: Boundaries = False,
) -> dict[str, Any]:
    """The map's box, its toss, the bounces and the boundaries, as typed: the keywords of
    :func:`~coinflight.queries.basin.basin_query` (``g`` checked by the endpoint)."""
    return dict(locals())


BasinBox = Annotated[dict[str, Any], Depends(basin_box)]
"""The map's options but the coin and the table: one dependency of ``/api/basin``."""

# --- the same-side bias and real flips --------------------------------------------------------
Psi = Annotated[float | None, _q("Fixed angle ψ between the normal and S, degrees, 0-180.")]
Psis = Annotated[
    str | None,
    _q(
        "Several fixed ψ at once, degrees, comma-separated (psis=0,5,10, at most 2000): the "
        "answer is then a list, for each ψ in the order given the object that psi=ψ answers "
        "(one request for a curve p(ψ)); not with psi, psi_dist, preset or monte_carlo.",
        examples=["0,45,90,135,180"],
    ),
]
PsiDist = Annotated[
    str | None, _q("A distribution of ψ in degrees: normal:MEAN,SD, LOW:HIGH or a number.")
]
PsiPreset = Annotated[str | None, _q("A named distribution of tosses: human.")]
MonteCarlo = Annotated[
    int | None, _q("Also simulate N tosses of the full flight (as --monte-carlo).")
]
Dataset = Annotated[str | None, _q("A dataset shipped with coinflight (default bartos2023).")]
Interval = Annotated[str, _q("95 % interval: exact (Clopper-Pearson) or wilson.")]
PsiSd = Annotated[float, _q("Spread of ψ, degrees: 0 fits one fixed ψ; > 0 a normal's mean.")]
SplitSeed = Annotated[
    int | None, _q("Seed of the held-out splits of the people (reported; drawn if not given).")
]
Folds = Annotated[int | None, _q("Held-out check: groups of people (as --folds, default 2).")]
Repeats = Annotated[int | None, _q("Held-out check: random splits (as --repeats, default 20).")]
