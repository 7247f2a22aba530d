"""``coinflight landing-report``: the table landing validated (coinflight.report.landing)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coinflight.cli.options import Quiet, out_folder

OutDir = Annotated[Path, out_folder("report.md, report.html, numbers.json and the figures (PNG)")]
QuickFlag = Annotated[
    bool,
    typer.Option(
        "--quick",
        help="Small samples (seconds, not the full report's tens of minutes): the same "
        "sections and figures, wider error bars.",
    ),
]
MujocoTosses = Annotated[
    int | None,
    typer.Option(
        "--mujoco",
        metavar="N",
        min=0,
        help="Identical tosses compared with MuJoCo (default 10000, 4 with --quick; 0 skips; "
        "skipped anyway when MuJoCo, the optional extra 'mujoco', is not installed).",
    ),
]
ReportSeed = Annotated[
    int,
    typer.Option("--seed", min=0, metavar="S", help="Seed of every random draw (reported)."),
]


def landing_report(
    out: OutDir = Path("landing-report"),
    seed: ReportSeed = 20261123,
    quick: QuickFlag = False,
    mujoco: MujocoTosses = None,
    quiet: Quiet = False,
) -> None:
    """Validate the table landing: figures, numbers and a report.

    Dead and bouncing landings against Yong & Mahadevan, maps over (e, μ), the US nickel's
    P(edge) band and its band in the rigid ending, MuJoCo against the rocking ending.

    Example: coinflight landing-report --out landing/ --quick
    """
    import dataclasses

    from coinflight.cli.progress import progress_bar
    from coinflight.report.landing import QUICK, Sizes, landing_report, report_files

    sizes = QUICK if quick else Sizes()
    if mujoco is not None:
        sizes = dataclasses.replace(sizes, mujoco=mujoco)
    report_files(out)  # before minutes of computing, not after
    with progress_bar(5, "landing report", quiet) as advance:

        def step(_name: str) -> None:
            if advance is not None:
                advance(1)

        report = landing_report(out, seed=seed, sizes=sizes, step=step)
    typer.echo(
        f"wrote {len(report.files)} files to {out} (seed {seed}); open {out / 'report.html'}"
    )
    for d in report.dead:
        typer.echo(
            f"dead landings h/d = {d.ratio:g}: P(edge) {d.simulated.p:.4f} ± "
            f"{d.simulated.stderr:.4f}, Yong & Mahadevan {d.dynamic:.4f} ({d.z:+.1f} s.e.)"
        )
    for b in report.bands:
        typer.echo(
            f"US nickel on {b.preset}: P(edge) {b.low[0]:.2e} to {b.high[0]:.2e} over the "
            f"literature's (e, μ); integrated {b.integrated.p:.2e} ± {b.integrated.stderr:.1e}"
        )
    if report.experiments is not None:
        for point in report.experiments.comparisons:
            obs = point.experiment.observed
            for band in point.bands:
                typer.echo(
                    f"{point.experiment.label}: measured {obs.p:.3f}, {band.ending} ending "
                    f"{band.low.p:.3f} to {band.high.p:.3f} over the unmeasured parameters: "
                    f"{band.verdict(obs)}"
                )
    if report.mujoco is None:
        typer.echo(report.mujoco_note)
    else:
        c = report.mujoco
        typer.echo(
            f"MuJoCo, {c.n:,} identical tosses: same well at first contact {c.first_agreement:.1%}"
        )
        for run in c.endings:
            p, se = c.fractions(run.rest), c.stderrs(run.rest)
            typer.echo(
                f"  {run.ending} ending: same face at rest {c.agreement(run):.1%}; tails, heads, "
                f"edge {', '.join(f'{x:.3f} ± {e:.3f}' for x, e in zip(p, se, strict=True))}; "
                f"{c.ratio(run):,.0f}× MuJoCo's speed"
            )
        p, se = c.fractions(c.mujoco_rest), c.stderrs(c.mujoco_rest)
        typer.echo(
            f"  MuJoCo: tails, heads, edge "
            f"{', '.join(f'{x:.3f} ± {e:.3f}' for x, e in zip(p, se, strict=True))}"
        )


__all__ = ["landing_report"]
