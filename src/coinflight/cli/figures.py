"""``coinflight plot toss`` and ``coinflight plot basin``: the coin drawn, and heads/tails maps."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coinflight.cli.options import (
    OUTPUT_HELP,
    OUTPUT_PANEL,
    TOSS_PANEL,
    CoinName,
    Gravity,
    Mass,
    Radius,
    StartFace,
    Thickness,
    number,
    output_file,
    resolve_coin,
)
from coinflight.cli.surface import (
    Bounces,
    DropHeight,
    Friction,
    Restitution,
    SurfaceKindOption,
    table_outcome,
    table_title,
)
from coinflight.cli.toss import FlightTime, LaunchSpeed, Omega, build_toss

OutFile = Annotated[
    Path,
    typer.Option(
        "--out",
        "-o",
        metavar="FILE",
        parser=output_file,
        rich_help_panel=OUTPUT_PANEL,
        help="Image file to write; the format follows the suffix (.png, .svg, .pdf, …); "
        f"without a suffix, FILE.png and FILE.svg (written together). {OUTPUT_HELP}",
    ),
]
Dpi = Annotated[
    int,
    typer.Option("--dpi", min=20, max=1200, rich_help_panel=OUTPUT_PANEL, help="PNG resolution."),
]
Times = Annotated[
    str | None,
    typer.Option(
        "--times",
        metavar="T1,T2,...",
        rich_help_panel=TOSS_PANEL,
        help="Several flight times, s, one panel each (as Stefan & Cheche Figs 3c-f); "
        "replaces --flight-time.",
    ),
]


def parse_numbers(text: str, name: str, example: str = "0.6,0.65,0.7") -> list[float]:
    """Comma-separated numbers, or a ValueError naming the option, an ``example`` of what it
    takes and the bad text."""
    parts = [p.strip() for p in text.split(",")]
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise ValueError(
            f"{name} must be comma-separated numbers such as {example}; got {text!r}"
        ) from None
    return values


def parse_range(text: str, name: str, unit: str = "") -> tuple[float, float]:
    """ "LO:HI" as two numbers (the range syntax of :func:`parse_distribution`).

    A map needs a box, so a fixed value or a normal distribution is refused with a ValueError
    naming the option and the text.
    """
    from coinflight.model.distributions import Uniform, parse_distribution

    dist = parse_distribution(text, name, unit)
    if not isinstance(dist, Uniform):
        raise ValueError(
            f"{name} must be a range LO:HI such as 60:90 for a map; got {text!r} "
            f"({dist.describe(unit)})"
        )
    return dist.low, dist.high


def parse_resolution(text: str) -> tuple[int, int]:
    """ "N" (N×N cells) or "NTxNW" (cells along T, along the spin)."""
    parts = text.lower().split("x")
    try:
        if len(parts) not in (1, 2):
            raise ValueError
        sizes = [int(p) for p in parts]
    except ValueError:
        raise ValueError(
            f"--resolution must be N or NTxNW with whole numbers, such as 500 or 600x400; "
            f"got {text!r}"
        ) from None
    return (sizes[0], sizes[-1])


def _written(paths: list[Path]) -> None:
    for p in paths:
        typer.echo(f"wrote {p}")


def plot_toss(
    out: OutFile,
    omega: Omega = (80.0, 0.0, 0.0),
    flight_time: FlightTime = None,
    launch_speed: LaunchSpeed = None,
    times: Times = None,
    start: StartFace = "heads",
    g: Gravity = 9.81,
    coin: CoinName = None,
    radius: Radius = None,
    thickness: Thickness = None,
    mass: Mass = None,
    dpi: Dpi = 150,
) -> None:
    """Draw the coin at launch (red) and at catch (blue), n and S, and the precession cone.

    Example: coinflight plot toss --omega 90 30 0 --times 0.6,0.65,0.7,0.75 --out fig3.png
    """
    import numpy as np

    from coinflight.model.toss import Toss
    from coinflight.plotting.style import figure_paths, save_figure
    from coinflight.plotting.toss import plot_toss as draw

    figure_paths(out, "--out")
    the_coin = resolve_coin(coin, radius, thickness, mass)
    if times is not None:
        if flight_time is not None or launch_speed is not None:
            raise ValueError("give --times or one of --flight-time and --launch-speed, not both")
        values = np.asarray(parse_numbers(times, "--times"))
        the_toss = Toss(omega=omega, flight_time=values, start=start, g=g)  # type: ignore[arg-type]
    else:
        the_toss = build_toss(omega, flight_time, launch_speed, start, g)
    _written(save_figure(draw(the_coin, the_toss), out, dpi=dpi))


FlightTimeRange = Annotated[
    str | None,
    typer.Option(
        "--flight-time",
        "-T",
        metavar="LO:HI",
        rich_help_panel=TOSS_PANEL,
        help="Range of flight times T, s \\[default: 0.6:0.9, Stefan & Cheche].",
    ),
]
LaunchSpeedRange = Annotated[
    str | None,
    typer.Option(
        "--launch-speed",
        metavar="LO:HI",
        rich_help_panel=TOSS_PANEL,
        help="Range of upward launch speeds v0, m/s, instead of --flight-time (T = 2 v0 / g).",
    ),
]
OmegaXRange = Annotated[
    str | None,
    typer.Option(
        "--omega-x",
        metavar="LO:HI",
        rich_help_panel=TOSS_PANEL,
        help="Range of the spin about a diameter ωx0, rad/s \\[default: 60:90].",
    ),
]
OmegaY = Annotated[
    float,
    typer.Option(
        "--omega-y",
        parser=number,
        metavar="WY",
        rich_help_panel=TOSS_PANEL,
        help="Fixed spin about the other diameter ωy0, rad/s.",
    ),
]
OmegaZ = Annotated[
    float,
    typer.Option(
        "--omega-z",
        parser=number,
        metavar="WZ",
        rich_help_panel=TOSS_PANEL,
        help="Fixed spin about the normal ωz0, rad/s (a precessing toss).",
    ),
]
PsiDeg = Annotated[
    float | None,
    typer.Option(
        "--psi",
        parser=number,
        metavar="DEG",
        rich_help_panel=TOSS_PANEL,
        help="Fixed angle between the normal and S, degrees; the vertical axis is then the "
        "precession rate (see --precession-rate).",
    ),
]
PrecessionRange = Annotated[
    str | None,
    typer.Option(
        "--precession-rate",
        metavar="LO:HI",
        rich_help_panel=TOSS_PANEL,
        help="Range of the precession rate ωp = |S|/I1, rad/s, with --psi \\[default: 60:90].",
    ),
]
Resolution = Annotated[
    str,
    typer.Option(
        "--resolution",
        metavar="N|NTxNW",
        rich_help_panel=OUTPUT_PANEL,
        help="Grid cells (pixels): N×N, or NT along T by NW along the spin.",
    ),
]
Boundaries = Annotated[
    bool,
    typer.Option(
        "--boundaries/--no-boundaries",
        rich_help_panel=OUTPUT_PANEL,
        help="Overlay the analytic heads/tails boundaries (Keller's hyperbolas when planar).",
    ),
]


def plot_basin(
    out: OutFile,
    flight_time: FlightTimeRange = None,
    launch_speed: LaunchSpeedRange = None,
    omega_x: OmegaXRange = None,
    omega_y: OmegaY = 0.0,
    omega_z: OmegaZ = 0.0,
    psi: PsiDeg = None,
    precession_rate: PrecessionRange = None,
    resolution: Resolution = "500",
    start: StartFace = "heads",
    g: Gravity = 9.81,
    coin: CoinName = None,
    radius: Radius = None,
    thickness: Thickness = None,
    mass: Mass = None,
    boundaries: Boundaries = True,
    dpi: Dpi = 150,
    surface: SurfaceKindOption = "hand",
    drop_height: DropHeight = None,
    restitution: Restitution = None,
    friction: Friction = None,
    bounces: Bounces = None,
) -> None:
    """Map heads and tails over a box of flight times and spins, with Keller's hyperbolas.

    Example: coinflight plot basin --omega-x 60:90 --flight-time 0.6:0.9 --out basin.png
    (on a table, after K bounces: --surface table --drop-height 0.3 --bounces K; the
    hyperbolas, which belong to the catch, are then not drawn)
    """
    import math

    from coinflight.plotting.basin import plot_basin as draw
    from coinflight.plotting.style import figure_paths, save_figure
    from coinflight.studies.basin import basin_map

    figure_paths(out, "--out")  # before the map is computed, not after
    the_coin = resolve_coin(coin, radius, thickness, mass)
    if psi is None:
        if precession_rate is not None:
            raise ValueError("--precession-rate goes with --psi; use --omega-x without --psi")
        spin = parse_range(omega_x or "60:90", "--omega-x", "rad/s")
        psi_rad = None
    else:
        if omega_x is not None or omega_y != 0.0 or omega_z != 0.0:
            raise ValueError(
                "with --psi the spin is set by --precession-rate; "
                "drop --omega-x/--omega-y/--omega-z"
            )
        if not 0.0 < psi < 180.0:
            raise ValueError(f"--psi must be between 0 and 180 degrees (exclusive), got {psi:g}")
        spin = parse_range(precession_rate or "60:90", "--precession-rate", "rad/s")
        psi_rad = math.radians(psi)
    if flight_time is not None and launch_speed is not None:
        raise ValueError("give --flight-time or --launch-speed, not both")
    if launch_speed is not None:
        v_lo, v_hi = parse_range(launch_speed, "--launch-speed", "m/s")
        if v_lo <= 0:
            raise ValueError(f"--launch-speed range must be positive, got {launch_speed!r} m/s")
        t_range = (2.0 * v_lo / g, 2.0 * v_hi / g)
    else:
        t_range = parse_range(flight_time or "0.6:0.9", "--flight-time", "s")
    basin = basin_map(
        the_coin,
        t_range,
        spin,
        omega_y=omega_y,
        omega_z=omega_z,
        psi=psi_rad,
        resolution=parse_resolution(resolution),
        start=start,
        g=g,
        **table_outcome(surface, drop_height, restitution, friction, bounces),
    )
    n_w, n_t = basin.face.shape
    typer.echo(f"P(heads) on the {n_t}×{n_w} grid = {basin.heads_fraction:.6f}")
    if surface == "table":
        typer.echo(f"P(edge) on the grid = {basin.fraction(2):.6f}")
        ending = table_title(drop_height, restitution, friction, bounces)
        figure = draw(basin, ending=ending, boundaries=False)
    else:
        figure = draw(basin, boundaries=boundaries)
    _written(save_figure(figure, out, dpi=dpi))


__all__ = ["parse_numbers", "parse_range", "parse_resolution", "plot_basin", "plot_toss"]
