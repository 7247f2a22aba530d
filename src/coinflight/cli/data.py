"""``coinflight data``: real same-side counts against the precession model."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import typer

from coinflight.cli.options import OUTPUT_HELP, OUTPUT_PANEL, JsonFlag, number, print_json
from coinflight.cli.output import echo_written
from coinflight.cli.parsers import output_file
from coinflight.datasets import DATASETS, DEFAULT_DATASET

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
INTERVAL_NAMES = {"exact": "Clopper-Pearson", "wilson": "Wilson"}


def data(
    dataset: Dataset = None,
    counts: Counts = None,
    interval: Interval = "exact",
    psi_sd: PsiSd = 0.0,
    plot: PlotFile = None,
    json_output: JsonFlag = False,
) -> None:
    """Same-side and heads rates of real flips, and the precession angle that explains them.

    Example: coinflight data --plot forest.png  (Bartoš et al.'s 350,757 flips)
    """
    from coinflight.studies.data import load_dataset, read_counts, summarize

    if dataset is not None and counts is not None:
        raise ValueError(
            f"give either --dataset or --counts, not both (got --dataset {dataset} and "
            f"--counts {counts})"
        )

    if not (math.isfinite(psi_sd) and psi_sd >= 0.0):
        raise ValueError(f"--psi-sd must be a non-negative number of degrees, got {psi_sd:g}")
    if plot is not None:
        from coinflight.plotting.style import figure_paths

        figure_paths(plot, "--plot")
    if counts is None:
        name = DEFAULT_DATASET if dataset is None else dataset
        table = load_dataset(name)
        shipped = DATASETS[name]
        source = f"{name} ({shipped.short}, doi:{shipped.doi})"
        described: dict[str, Any] = {
            "dataset": name,
            "source": name,
            "title": shipped.title,
            "citation": shipped.citation,
            "doi": shipped.doi,
            "provenance": shipped.provenance,
        }
    else:
        table = read_counts(counts)
        source = str(counts)
        described = {"dataset": None, "source": str(counts)}
    if plot is not None and len(table.people) > PLOT_MAX_PEOPLE:
        raise ValueError(
            f"--plot draws one row per person: at most {PLOT_MAX_PEOPLE:,} people, got "
            f"{len(table.people):,}; leave out --plot (--json lists every person)"
        )
    summary = summarize(table, interval, math.radians(psi_sd))
    written = []
    if plot is not None:
        from coinflight.plotting.forest import plot_forest
        from coinflight.plotting.style import save_figure

        written = save_figure(plot_forest(summary), plot)
    same, heads, fit = summary.same_side, summary.heads, summary.psi
    psi_deg = None if fit.psi is None else math.degrees(fit.psi)
    psi_ci = None if fit.ci95 is None else [math.degrees(x) for x in fit.ci95]
    if json_output:
        payload: dict[str, Any] = {
            **described,
            "people": len(summary.people),
            "flips": summary.flips,
            "same": same.successes,
            "p_same_side": same.estimate,
            "ci95": list(same.ci95),
            "p_value": same.p_value,
            "z": same.z,
            "heads": heads.successes,
            "p_heads": heads.estimate,
            "ci95_heads": list(heads.ci95),
            "p_value_heads": heads.p_value,
            "interval": INTERVAL_NAMES[same.method],
            "psi_deg": psi_deg,
            "psi_ci95_deg": psi_ci,
            "psi_model": fit.model,
            "psi_sd_deg": psi_sd,
            "psi_ci95_limited": fit.limited,
            "heterogeneity": {
                "chi2": summary.heterogeneity.chi2,
                "dof": summary.heterogeneity.dof,
                "p_value": summary.heterogeneity.p_value,
            },
            "p_same_side_floor": fit.floor,
            "per_person": [
                {
                    "person": name,
                    "same": p.successes,
                    "flips": p.trials,
                    "p_same_side": p.estimate,
                    "ci95": list(p.ci95),
                    "p_value": p.p_value,
                }
                for name, p in summary.people
            ],
            "plot": [str(p) for p in written],
        }
        print_json(payload)
        return
    method = INTERVAL_NAMES[same.method]
    typer.echo(f"{source}: {len(summary.people)} people, {summary.flips:,} flips")
    typer.echo(
        f"same side: {same.successes:,} of {same.trials:,} = {same.estimate:.5f}, "
        f"95% {method} interval [{same.ci95[0]:.5f}, {same.ci95[1]:.5f}]; "
        f"test against 1/2: p = {same.p_value:.2g} (z = {same.z:.2f})"
    )
    typer.echo(
        f"heads:     {heads.successes:,} of {heads.trials:,} = {heads.estimate:.5f}, "
        f"95% {method} interval [{heads.ci95[0]:.5f}, {heads.ci95[1]:.5f}]; "
        f"test against 1/2: p = {heads.p_value:.2g} (z = {heads.z:.2f})"
    )
    what = (
        "a fixed ψ for every flip"
        if fit.model == "fixed"
        else f"the mean of a normal ψ distribution with sd {psi_sd:g}°"
    )
    limit = " (an end capped at 90°: that rate is not reached)" if fit.limited else ""
    if psi_deg is None or psi_ci is None:
        typer.echo(
            f"precession (Diaconis et al. 2007, {what}): no ψ gives this same-side rate; "
            f"the model gives at least {fit.floor:.5f}"
        )
    else:
        typer.echo(
            f"precession (Diaconis et al. 2007, {what}): ψ = {psi_deg:.2f}°, "
            f"95% interval [{psi_ci[0]:.2f}°, {psi_ci[1]:.2f}°]{limit}"
        )
    het = summary.heterogeneity
    typer.echo(
        f"between people: χ² = {het.chi2:.1f} on {het.dof} degrees of freedom, p = "
        f"{het.p_value:.2g} (test that everyone has the same same-side rate)"
    )
    typer.echo("per person (same side of flips, rate, 95% interval):")
    width = max(len(name) for name, _ in summary.people)
    for name, p in summary.people:
        typer.echo(
            f"  {name:<{width}} {p.successes:>7,} of {p.trials:>7,}  {p.estimate:.4f}  "
            f"[{p.ci95[0]:.4f}, {p.ci95[1]:.4f}]"
        )
    echo_written(written)
