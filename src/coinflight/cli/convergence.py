"""``coinflight convergence``: estimates against configurations / events (the paper's Figs 2-3)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coinflight.cli.options import (
    OUTPUT_HELP,
    CoinName,
    Gravity,
    JsonFlag,
    Mass,
    Radius,
    StartFace,
    Thickness,
    print_json,
    resolve_coin,
)
from coinflight.cli.probability import (
    METHOD_PANEL,
    FlightTimeDist,
    LaunchSpeedDist,
    OmegaX,
    OmegaY,
    OmegaZ,
    Seed,
    Threads,
    build_distribution,
)
from coinflight.cli.progress import Quiet, progress_bar
from coinflight.probability import registry


def output_prefix(text: str) -> Path:
    """Parse --out PREFIX: a folder's name (existing, or ending in /) means DIR/convergence."""
    from coinflight._files import check_name, names_folder

    try:
        check_name(text, folder=True)
    except ValueError as exc:
        raise typer.BadParameter(str(exc)) from None
    path = Path(text)
    return path / "convergence" if names_folder(text) or path.is_dir() else path


def _int_list(text: str, option: str) -> list[int]:
    try:
        values = [int(part) for part in text.split(",") if part.strip()]
    except ValueError:
        raise ValueError(f"{option} {text!r}: give comma-separated whole numbers") from None
    if not values:
        raise ValueError(f"{option} {text!r}: give at least one size")
    return values


Methods = Annotated[
    str,
    typer.Option(
        "--methods",
        metavar="LIST",
        rich_help_panel=METHOD_PANEL,
        help="Comma-separated, of "
        + ", ".join(registry.names(series=True))
        + " (grid: method A; monte-carlo: method B with --grid-cells 100, the default).",
    ),
]
Cells = Annotated[
    int | None,
    typer.Option(
        "--grid-cells",
        metavar="C",
        rich_help_panel=METHOD_PANEL,
        help="Cells per parameter for method B (default 100, as the paper); 0 for plain Monte "
        "Carlo.",
    ),
]
Out = Annotated[
    Path,
    typer.Option(
        "--out",
        "-o",
        metavar="PREFIX",
        parser=output_prefix,
        rich_help_panel="Output",
        help="Write PREFIX.csv, PREFIX.json, PREFIX.png and PREFIX.svg, all together at the end "
        f"(a folder, existing or written as DIR/: DIR/convergence.*). {OUTPUT_HELP}",
    ),
]


def convergence(
    omega_x: OmegaX = "60:90",
    omega_y: OmegaY = "0",
    omega_z: OmegaZ = "0",
    flight_time: FlightTimeDist = None,
    launch_speed: LaunchSpeedDist = None,
    start: StartFace = "heads",
    g: Gravity = 9.81,
    coin: CoinName = None,
    radius: Radius = None,
    thickness: Thickness = None,
    mass: Mass = None,
    methods: Methods = "grid,monte-carlo",
    grid_sizes: Annotated[
        str | None,
        typer.Option(
            "--grid-sizes",
            metavar="N1,N2,…",
            rich_help_panel=METHOD_PANEL,
            help="Cells per parameter for method A (default 5,10,…,5000).",
        ),
    ] = None,
    event_sizes: Annotated[
        str | None,
        typer.Option(
            "--event-sizes",
            metavar="N1,N2,…",
            rich_help_panel=METHOD_PANEL,
            help="Events for method B / Monte Carlo (default 100,…,10000000).",
        ),
    ] = None,
    qmc_sizes: Annotated[
        str | None,
        typer.Option(
            "--qmc-sizes",
            metavar="N1,N2,…",
            rich_help_panel=METHOD_PANEL,
            help="QMC points, each 16 × a power of two (default 64,…,1048576).",
        ),
    ] = None,
    grid_cells: Cells = None,
    seed: Seed = None,
    threads: Threads = None,
    out: Out = Path("convergence"),
    quiet: Quiet = False,
    json_output: JsonFlag = False,
) -> None:
    """Estimates of P(heads) as configurations / events grow, with the exact value.

    Example (the paper's Fig 2a): coinflight convergence --omega-x 60:90 --flight-time 0.6:0.9
    --seed 1 --out fig2a
    """
    from coinflight._files import check_all_writable, replacing_all
    from coinflight.plotting.convergence import plot_convergence
    from coinflight.plotting.style import save_figure
    from coinflight.probability.convergence import convergence as run
    from coinflight.probability.convergence import work_total

    the_coin = resolve_coin(coin, radius, thickness, mass)
    dist = build_distribution(
        omega_x, omega_y, omega_z, flight_time, launch_speed, the_coin, start, g
    )
    method_list = [m.strip() for m in methods.split(",") if m.strip()]
    grid_cells_given = grid_cells is not None
    if grid_cells is None:
        grid_cells = 100
    sizes: dict[str, list[int]] = {}
    if grid_sizes is not None:
        sizes["grid_sizes"] = _int_list(grid_sizes, "--grid-sizes")
    if event_sizes is not None:
        sizes["event_sizes"] = _int_list(event_sizes, "--event-sizes")
    if qmc_sizes is not None:
        sizes["qmc_sizes"] = _int_list(qmc_sizes, "--qmc-sizes")
    for option, text, needed in (
        ("--grid-sizes", grid_sizes, "grid"),
        ("--event-sizes", event_sizes, "monte-carlo"),
        ("--qmc-sizes", qmc_sizes, "qmc"),
    ):
        if text is not None and needed not in method_list:
            raise ValueError(f"{option} applies to --methods {needed}, not given in {methods!r}")
    if not set(registry.names(seeded=True)) & set(method_list):
        if seed is not None:
            seeded = " and ".join(registry.names(seeded=True))
            raise ValueError(f"--seed applies to {seeded}, not to {methods!r}")
        if grid_cells_given:
            raise ValueError(f"--grid-cells applies to --methods monte-carlo, not {methods!r}")
    if grid_cells < 0:
        raise ValueError(
            f"--grid-cells must be 0 (plain Monte Carlo) or positive, got {grid_cells}"
        )
    prefix = out  # already DIR/convergence for a folder (output_prefix)
    targets = [prefix.with_name(f"{prefix.name}.{ext}") for ext in ("csv", "json", "png", "svg")]
    check_all_writable(targets)  # before computing, not after
    total = work_total(dist, method_list, **sizes)
    with progress_bar(total, "convergence", quiet) as bar:
        result = run(
            dist,
            method_list,
            seed=seed,
            grid_cells=grid_cells or None,
            threads=threads,
            progress=bar,
            **sizes,  # type: ignore[arg-type]
        )
    fig = plot_convergence(result)
    with replacing_all(targets) as (csv, _, png, svg):  # the four files together, or none
        result.write(csv.with_name(prefix.name))  # PREFIX.csv and PREFIX.json
        save_figure(fig, png)
        save_figure(fig, svg)
    written = targets
    if json_output:
        payload = result.to_dict()
        payload["files"] = [str(p) for p in written]
        print_json(payload)
        return
    exact = "not available" if result.exact is None else f"{result.exact:.6f} ({result.exact_how})"
    typer.echo(f"exact P(heads) = {exact}")
    for m in result.methods:
        last = result.series(m)[-1]
        typer.echo(f"{m}: P(heads) = {last.p_heads:.6f} at {last.samples:,} (largest size)")
    files = ", ".join(str(p) for p in written)
    typer.echo(f"wrote {files}" if result.seed is None else f"seed {result.seed}; wrote {files}")
