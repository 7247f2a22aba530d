"""``coinflight data``: real same-side counts against the precession model."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated

import typer

from coinflight import _validation as v
from coinflight.cli.options import (
    OUTPUT_HELP,
    OUTPUT_PANEL,
    SPLITS_PANEL,
    JsonFlag,
    SplitSeed,
    number,
    print_json,
)
from coinflight.cli.output import echo_written
from coinflight.cli.parsers import output_file
from coinflight.datasets import DATASETS, DEFAULT_DATASET
from coinflight.studies.flippers import DEFAULT_FOLDS, DEFAULT_REPEATS, MAX_REPEATS

PLOT_MAX_PEOPLE = 1000
"""Most people a forest plot draws (one row each: 1,000 rows make a figure 180 inches tall)."""

Counts = Annotated[
    Path | None,
    typer.Option(
        "--counts",
        metavar="FILE",
        help="Your own per-person counts instead of a dataset: UTF-8 text, columns person hsame "
        "hdiff tsame tdiff same flips, one header line (the layout of the bartos2023 dataset); "
        "'# ' starts a comment line.",
    ),
]
Dataset = Annotated[
    str | None,
    typer.Option(
        "--dataset",
        metavar="NAME",
        help="A dataset shipped with coinflight: "
        + "; ".join(f"{d.name} ({d.short}: {d.title})" for d in DATASETS.values())
        + f". Default {DEFAULT_DATASET} when --counts is not given.",
    ),
]
Interval = Annotated[
    str,
    typer.Option(
        "--interval",
        metavar="exact|wilson",
        help="95 % interval: exact (Clopper-Pearson) or wilson (Wilson score).",
    ),
]
PsiSd = Annotated[
    float,
    typer.Option(
        "--psi-sd",
        parser=number,
        metavar="DEG",
        help="Spread of ψ, degrees: 0 fits one fixed ψ for every flip; > 0 fits the mean of a "
        "normal ψ distribution with this standard deviation.",
    ),
]
Folds = Annotated[
    int,
    typer.Option(
        "--folds",
        metavar="K",
        rich_help_panel=SPLITS_PANEL,
        help="Split the people into K groups; each is predicted by the ψ population fitted to "
        "the others (at least 2, at most the number of people).",
    ),
]
Repeats = Annotated[
    int,
    typer.Option(
        "--repeats",
        metavar="R",
        rich_help_panel=SPLITS_PANEL,
        help=f"Random splits of the people (1-{MAX_REPEATS}; each fits the model K times, "
        "about 20 ms each for 48 people).",
    ),
]
PlotFile = Annotated[
    Path | None,
    typer.Option(
        "--plot",
        metavar="FILE",
        parser=output_file,
        rich_help_panel=OUTPUT_PANEL,
        help="Also write a forest plot of the per-person rates; the format follows the suffix "
        f"(.png, .svg, .pdf, …); without a suffix, FILE.png and FILE.svg. {OUTPUT_HELP}",
    ),
]

PeoplePlotFile = Annotated[
    Path | None,
    typer.Option(
        "--plot-people",
        metavar="FILE",
        parser=output_file,
        rich_help_panel=OUTPUT_PANEL,
        help="Also write each person's rate against the 95 % predictive intervals of one ψ and "
        "of the ψ population, and the population under p(ψ); the format follows the suffix, as "
        f"--plot. {OUTPUT_HELP}",
    ),
]


def data(
    dataset: Dataset = None,
    counts: Counts = None,
    interval: Interval = "exact",
    psi_sd: PsiSd = 0.0,
    seed: SplitSeed = None,
    folds: Folds = DEFAULT_FOLDS,
    repeats: Repeats = DEFAULT_REPEATS,
    plot: PlotFile = None,
    plot_people: PeoplePlotFile = None,
    json_output: JsonFlag = False,
) -> None:
    """Same-side and heads rates of real flips, the precession angle that explains them.

    And how people differ: a ψ for each person from one population, checked on held-out people.

    Example: coinflight data --seed 1 --plot forest.png  (Bartoš et al.'s 350,757 flips)
    """
    from coinflight.queries.data import check_psi_sd, check_splits, data_payload, flippers
    from coinflight.studies.data import counts_source, summarize

    if dataset is not None and counts is not None:
        counts_source(dataset, counts)  # the error naming both, before any other
    check_psi_sd(psi_sd)
    check_splits(seed, folds, repeats)
    plots = [(flag, path) for flag, path in (("--plot", plot), ("--plot-people", plot_people))
             if path is not None]  # fmt: skip
    if plots:
        from coinflight.plotting.style import figure_paths

        for flag, path in plots:
            figure_paths(path, flag)
    table, source, described = counts_source(dataset, counts)
    for flag, _ in plots:
        if len(table.people) > PLOT_MAX_PEOPLE:
            shown, most = v.over_limit(len(table.people), PLOT_MAX_PEOPLE)
            raise ValueError(
                f"{flag} draws one row per person: at most {most} people, got "
                f"{shown}; leave out {flag} (--json lists every person)"
            )
    summary = summarize(table, interval, math.radians(psi_sd))
    analysis = flippers(table, seed, folds, repeats)
    if plot_people is not None and isinstance(analysis, str):
        raise ValueError(f"--plot-people draws the ψ population, which is {analysis}")
    written = []
    if plots:
        from coinflight.plotting.forest import plot_flippers, plot_forest
        from coinflight.plotting.style import save_figure

        if plot is not None:
            written += save_figure(plot_forest(summary), plot)
        if plot_people is not None and not isinstance(analysis, str):
            written += save_figure(plot_flippers(table, analysis), plot_people)
    if json_output:
        print_json(data_payload(described, summary, psi_sd, written, analysis))
        return
    for line in summary.report(source, psi_sd):
        typer.echo(line)
    if isinstance(analysis, str):
        typer.echo(f"people differ: ψ population {analysis}")
    else:
        for line in analysis.report():
            typer.echo(line)
    echo_written(written)
