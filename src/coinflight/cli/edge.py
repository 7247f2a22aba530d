"""``coinflight edge``: P(edge) of thick coins as numbers (the figure: :mod:`.plot_edge`)."""

from __future__ import annotations

from typing import Annotated, Any, cast

import typer

from coinflight.cli.cluster import ClusterOptions
from coinflight.cli.command import Group, command
from coinflight.cli.groups import _dist
from coinflight.cli.landing_groups import CORNER_HELP, ENDING_HELP, PIVOTING_HELP, ROLLING_HELP
from coinflight.cli.options import (
    CONTACT_PANEL,
    OUTPUT_PANEL,
    SURFACE_PANEL,
    Gravity,
    SimulateSeed,
    number_option,
    print_json,
)
from coinflight.queries.edge import TABLE_RATIOS

SIM_PANEL = "Simulation"
RATIOS = "0.1,0.2,0.3,0.4,0.5,0.6,0.8,1"
_SETTING = "vigorous planar spins, landing dead on a table; coinflight.studies.edge.simulate_edge"


def _simulate(what: str) -> Any:
    """--simulate N: tosses per ratio (``what``: what the command does with them)."""
    return typer.Option(
        "--simulate",
        min=1,
        max=10**7,
        metavar="N",
        rich_help_panel=SIM_PANEL,
        help=f"Also land N simulated tosses per ratio ({_SETTING}) and {what}.",
    )


_ONLY = "with --simulate: "
EdgeRatios = Annotated[
    str,
    typer.Option(
        "--ratios",
        metavar="R,R,...",
        help="Thickness / diameter ratios h/d, each between 0.001 and 100.",
    ),
]
EdgeSimulate = Annotated[
    int | None, _simulate("report their edge fraction with its standard error")
]
Restitution = Annotated[
    float | None,
    number_option(
        "--restitution",
        "E",
        SURFACE_PANEL,
        _ONLY + "the table's coefficient of restitution in [0, 1] (default 0: lands dead, "
        "as in the dynamic model).",
    ),
]
Friction = Annotated[
    float | None,
    number_option(
        "--friction",
        "MU",
        SURFACE_PANEL,
        _ONLY + "the table's Coulomb friction coefficient, 0 to 3 (default 0.3).",
    ),
]
DropHeight = Annotated[
    float | None,
    number_option(
        "--drop-height",
        "D",
        SURFACE_PANEL,
        _ONLY + "how far the table lies below the launch height, m (default 0.5).",
    ),
]
Ending = Annotated[
    str | None,
    typer.Option(
        "--ending",
        metavar="rocking|contact|rigid",
        rich_help_panel=CONTACT_PANEL,
        help=_ONLY + ENDING_HELP + " Only landings that bounce (--restitution > 0) reach it.",
    ),
]
RollingResistance = Annotated[
    float | None,
    number_option(
        "--rolling-resistance",
        "L",
        CONTACT_PANEL,
        _ONLY + "--ending contact or rigid: " + ROLLING_HELP,
    ),
]
PivotingResistance = Annotated[
    float | None,
    number_option(
        "--pivoting-resistance",
        "L",
        CONTACT_PANEL,
        _ONLY + "--ending contact or rigid: " + PIVOTING_HELP,
    ),
]
CornerRadius = Annotated[
    float | None,
    number_option(
        "--corner-radius",
        "A",
        CONTACT_PANEL,
        _ONLY + CORNER_HELP + " Every ratio's coin takes it: at most half the thinnest one's "
        "thickness (h/d × 24 mm / 2).",
    ),
]
SpinX = Annotated[
    str | None, _dist("--omega-x", "With --simulate: spin about the x diameter", "rad/s")
]
LaunchSpeed = Annotated[
    str | None, _dist("--launch-speed", "With --simulate: upward launch speed v0", "m/s")
]
EdgeGravity = Annotated[float | None, *Gravity.__metadata__]
SETTING = Group(
    {
        name: (kind, None)
        for name, kind in (
            ("restitution", Restitution),
            ("friction", Friction),
            ("drop_height", DropHeight),
            ("ending", Ending),
            ("rolling_resistance", RollingResistance),
            ("pivoting_resistance", PivotingResistance),
            ("corner_radius", CornerRadius),
            ("omega_x", SpinX),
            ("launch_speed", LaunchSpeed),
            ("g", EdgeGravity),
        )
    },
    dict,
)
"""The simulated landings' options: the command receives them as keywords of
:func:`~coinflight.queries.edge.edge_query` (None: not given)."""
EdgeJson = Annotated[
    bool,
    typer.Option(
        "--json",
        rich_help_panel=OUTPUT_PANEL,
        help="Print a JSON list on stdout, one object per ratio, instead of text.",
    ),
]


@command
def edge(
    *,
    ratios: EdgeRatios = TABLE_RATIOS,
    simulate: EdgeSimulate = None,
    seed: SimulateSeed = None,
    setting: Annotated[dict[str, Any], SETTING],
    cluster: ClusterOptions,
    json: EdgeJson = False,
) -> None:
    """P(edge) of thick coins per ratio h/d, from Yong & Mahadevan's (2011) models.

    Their geometric and dynamic models and, with --simulate, simulated landings.

    Simulated by default in the dynamic model's setting:
    spins of 150–300 rad/s about a diameter, launched at 1.5–3 m/s,
    landing dead (restitution 0, friction 0.3) on a table 0.5 m below.

    Example: coinflight edge --ratios 0.1,0.577,1 --simulate 4000 --seed 1 --json
    """
    from coinflight.queries.edge import edge_query, edge_rows

    query = edge_query(ratios, simulate, seed, scheduler=cluster.scheduler, **setting)
    with cluster.executor() as executor:
        rows = edge_rows(query, executor)
    if json:
        print_json(cast(Any, rows))  # a list: one object per ratio
        return
    width = max(13, 2 * len(f"{simulate or 0:,}") + 3)  # "edge / tosses", right-aligned
    header = f"{'h/d':>8}  {'geometric':>9}  {'dynamic':>9}"
    contact = simulate is not None and setting["ending"] == "contact"
    if simulate is not None:
        header += f"  {'simulated':>9}  {'± s.e.':>7}  {'edge / tosses':>{width}}"
    if contact:
        header += f"  {'decided upright':>15}"
    typer.echo(header)
    for row in rows:
        line = f"{row['ratio']:>8g}  {row['p_edge_geometric']:>9.4f}  {row['p_edge_dynamic']:>9.4f}"
        if "simulated" in row:
            s = row["simulated"]
            count = f"{s['successes']:,} / {s['n']:,}"
            line += f"  {s['p_edge']:>9.4f}  {s['stderr']:>7.4f}  {count:>{width}}"
            if contact:
                line += f"  {s['decided_upright']:>15,}"
        typer.echo(line)
    if simulate is not None:
        if contact:  # the edges predicted, not carried to rest: said apart
            typer.echo(
                "decided upright: edges the contact ending's upright decision ended while the "
                "coin still rolled (a measured predictor of ending on edge, not a proof)"
            )
        if setting["corner_radius"]:  # rounded rims: said, as the JSON rows say it
            typer.echo(f"corner radius {setting['corner_radius']:g} m")
        typer.echo(f"seed {rows[0]['simulated']['seed']}")


__all__ = ["edge"]
