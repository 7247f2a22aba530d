"""``coinflight edge``: P(edge) of thick coins as numbers (the figure: :mod:`.plot_edge`; the
options: :mod:`.edge_groups`; ``--target``'s text: :mod:`.edge_target`)."""

from __future__ import annotations

from typing import Annotated, Any, cast

import typer

from coinflight.cli.cluster import ClusterOptions
from coinflight.cli.command import command
from coinflight.cli.edge_groups import SETTING, EdgeJson, EdgeRatios, EdgeSimulate, TargetOption
from coinflight.cli.options import SimulateSeed, print_json


@command
def edge(
    *,
    ratios: EdgeRatios = None,
    simulate: EdgeSimulate = None,
    target: TargetOption = None,
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

    With --target P: the ratio h/d at which those tosses land on edge with probability P,
    as a band over the table's unmeasured parameters not given: restitution 0.3–0.6 (landings
    that bounce, each carried to rest by the rigid ending), friction 0.05–0.6 and the rolling
    and pivoting resistances 1e-5–1e-3 m.

    Example: coinflight edge --ratios 0.1,0.577,1 --simulate 4000 --seed 1 --json

    Example: coinflight edge --target 1/3 --seed 1
    """
    from coinflight.queries.edge import edge_query, edge_rows

    query = edge_query(
        ratios, simulate, seed, target=target, scheduler=cluster.scheduler, **setting
    )
    if query.target is not None:
        from coinflight.cli.edge_target import run_target

        run_target(query, cluster, json)
        return
    with cluster.executor() as executor:
        rows = edge_rows(query, executor)
    if json:
        print_json(cast(Any, rows))  # a list: one object per ratio
        return
    width = max(13, 2 * len(f"{simulate or 0:,}") + 3)  # "edge / tosses", right-aligned
    header = f"{'h/d':>8}  {'geometric':>9}  {'dynamic':>9}"
    if simulate is not None:
        header += f"  {'simulated':>9}  {'± s.e.':>7}  {'edge / tosses':>{width}}"
    typer.echo(header)
    for row in rows:
        line = f"{row['ratio']:>8g}  {row['p_edge_geometric']:>9.4f}  {row['p_edge_dynamic']:>9.4f}"
        if "simulated" in row:
            s = row["simulated"]
            count = f"{s['successes']:,} / {s['n']:,}"
            line += f"  {s['p_edge']:>9.4f}  {s['stderr']:>7.4f}  {count:>{width}}"
        typer.echo(line)
    if simulate is not None:
        if setting["corner_radius"]:  # rounded rims: said, as the JSON rows say it
            typer.echo(f"corner radius {setting['corner_radius']:g} m")
        typer.echo(f"seed {rows[0]['simulated']['seed']}")


__all__ = ["edge"]
