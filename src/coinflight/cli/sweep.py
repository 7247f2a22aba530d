"""``coinflight sweep``: P(heads), P(same side), P(edge) over the product of option lists.

The options and the printing; the grammar, the checks and the rows are
:mod:`coinflight.queries.sweep`'s."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated, Any

import typer

from coinflight.cli.cluster import ParallelOptions
from coinflight.cli.command import command
from coinflight.cli.options import (
    METHOD_PANEL,
    OUTPUT_HELP,
    OUTPUT_PANEL,
    TOSS_PANEL,
    Gravity,
    JsonFlag,
    Quiet,
    Seed,
    coin_option,
    option,
    print_json,
)
from coinflight.cli.progress import progress_bar
from coinflight.cli.sweep_groups import LANDINGS, TOSSES
from coinflight.probability import registry
from coinflight.queries.sweep import SweepLandings
from coinflight.queries.values import COIN_NAMES

Method = Annotated[
    str,
    option(
        "--method",
        "-m",
        metavar="|".join(registry.names()),
        panel=METHOD_PANEL,
        help="The method of every row: "
        + "; ".join(f"{e.name}: {e.description}" for e in registry.estimators())
        + ". exact handles the hand only.",
    ),
]
Size = Annotated[
    int | None,
    option(
        "--n",
        "-n",
        metavar="N",
        panel=METHOD_PANEL,
        help="The method's size for every row (as coinflight probability --n).",
        min=1,
    ),
]
Out = Annotated[
    Path,
    option(
        "--out",
        "-o",
        metavar="FILE",
        panel=OUTPUT_PANEL,
        help='The table: FILE.parquet (pip install "coinflight[parquet]"; the inputs, method, '
        "n, seed and version in its metadata) or FILE.csv (with FILE.csv.json). Resumable: "
        "finished rows are kept in FILE.partial.jsonl until FILE is written; run the same "
        "command again after a stop (Ctrl-C, a failure, a killed job) and only the missing rows "
        f"are computed (same options, method, n and seed; --fresh to start over). {OUTPUT_HELP}",
    ),
]
Fresh = Annotated[
    bool,
    option(
        "--fresh",
        metavar=None,
        panel=OUTPUT_PANEL,
        help="Start over: replace FILE.partial.jsonl (the rows of an earlier run of this "
        "table) instead of resuming from it.",
    ),
]
Coins = Annotated[str, coin_option("NAMES", f"Comma-separated coins: {COIN_NAMES}.")]
Starts = Annotated[
    str, option("--start", metavar="FACES", panel=TOSS_PANEL, help="heads, tails or heads,tails.")
]


@command
def sweep(
    ctx: typer.Context,
    *,
    tosses: Annotated[dict[str, Any], TOSSES],
    coin: Coins = "us-quarter",
    start: Starts = "heads",
    g: Gravity = 9.81,
    landings: Annotated[SweepLandings, LANDINGS],
    method: Method = "exact",
    n: Size = None,
    seed: Seed = None,
    cluster: ParallelOptions,
    out: Out,
    fresh: Fresh = False,
    quiet: Quiet = False,
    json_output: JsonFlag = False,
) -> None:
    """P(heads), P(same side), P(edge) for every combination of the given values, as one table.

    Each toss parameter takes a list of distributions: numbers (fixed), LOW:HIGH (uniform),
    normal:MEAN,SD; or --P-mean and --P-sd lists for normals over their product (a list of
    numbers also takes FROM:TO:COUNT). --coin, --start, --surface take comma-separated names,
    the table's options lists of numbers. One row per combination; one seed for the sweep,
    each row drawing its own stream from it and its inputs (a row does not depend on the
    others, their order or the workers).

    Example: coinflight sweep --omega-x-mean 150,200,250 --omega-x-sd 10,20 --launch-speed
    1.5:3 --coin us-quarter,eur-1 --method monte-carlo --n 100000 --seed 1 --out sweep.parquet
    """
    from coinflight.probability.sweep import run_sweep
    from coinflight.queries.sweep import sweep_query, sweep_summary

    t0 = time.perf_counter()
    query = sweep_query(
        tosses, landings, coin=coin, start=start, g=g, method=method, n=n, seed=seed, out=out,
        inputs=ctx.params,
    )  # fmt: skip
    with (
        cluster.executor() as executor,
        progress_bar(len(query.cases), "sweep", quiet) as bar,
    ):
        results, files = run_sweep(
            query.cases, out, method, n, seed, inputs=query.inputs, fresh=fresh,
            executor=executor, threads=cluster.threads, progress=bar,
        )  # fmt: skip
    if json_output:
        print_json(sweep_summary(query, results, files, time.perf_counter() - t0))
        return
    heads = [r.p_heads for r in results]
    reused = f" ({results.reused} reused from a previous run)" if results.reused else ""
    seed_text = "" if results.seed is None else f", seed {results.seed}"
    typer.echo(f"{len(results)} rows by {method}{reused}{seed_text}")
    typer.echo(f"P(heads) from {min(heads):.6f} to {max(heads):.6f}")
    typer.echo(f"wrote {', '.join(map(str, files))}")
