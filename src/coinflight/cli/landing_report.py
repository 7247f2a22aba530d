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
        help="Small samples (a minute or two, not the full report's ten or so): the same "
        "sections and figures, wider error bars.",
    ),
]
MujocoTosses = Annotated[
    int | None,
    typer.Option(
        "--mujoco",
        metavar="N",
        min=0,
        help="Identical tosses compared with MuJoCo (default 1000, 4 with --quick; 0 skips; "
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
    P(edge) band, the same tosses in MuJoCo, thick cylinders against experiments.

    Example: coinflight landing-report --out landing/ --quick
    """
    import dataclasses

    from coinflight.cli.progress import progress_bar
    from coinflight.report.landing import QUICK, Sizes, landing_report, report_files

    sizes = QUICK if quick else Sizes()
    if mujoco is not None:
        sizes = dataclasses.replace(sizes, mujoco=mujoco)
    report_files(out)  # before minutes of computing, not after
    sections = 4 + (sizes.mujoco > 0) + 2 * (sizes.experiments > 0)
    with progress_bar(sections, "landing report", quiet) as advance:

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
    for b in report.band.bands:
        (lo, lo_se), (hi, hi_se) = b.low, b.high
        typer.echo(
            f"US nickel on {b.preset}: P(edge) {lo:.3f} ± {lo_se:.3f} to {hi:.3f} ± {hi_se:.3f} "
            f"over e, μ, the resistances and the corner radius; integrated "
            f"{b.integrated.p:.3f} ± {b.integrated.stderr:.3f}"
        )
    for x in (report.experiments, report.experiments_human):
        if x is None:
            continue
        tosses = "human tosses" if x.psi == "human" else "planar tosses"
        for point in x.comparisons:
            obs, band = point.experiment.observed, point.band
            typer.echo(
                f"{point.experiment.label}: measured {obs.p:.3f} ± {obs.stderr:.3f}, {tosses} "
                f"{band.low.p:.3f} ± {band.low.stderr:.3f} to {band.high.p:.3f} ± "
                f"{band.high.stderr:.3f} over the unmeasured parameters: {band.verdict(obs)}"
            )
    if report.mujoco is None:
        typer.echo(report.mujoco_note)
    else:
        c = report.mujoco
        typer.echo(
            f"MuJoCo, {c.n:,} identical tosses: same well at first contact {c.first_agreement:.1%}"
        )
        p, se = c.fractions(c.coinflight.rest), c.stderrs(c.coinflight.rest)
        typer.echo(
            f"  coinflight: same face at rest {c.rest_agreement:.1%}; tails, heads, edge "
            f"{', '.join(f'{x:.3f} ± {e:.3f}' for x, e in zip(p, se, strict=True))}; "
            f"{c.speed_ratio:,.1f}× MuJoCo's speed"
        )
        p, se = c.fractions(c.mujoco_rest), c.stderrs(c.mujoco_rest)
        typer.echo(
            f"  MuJoCo: tails, heads, edge "
            f"{', '.join(f'{x:.3f} ± {e:.3f}' for x, e in zip(p, se, strict=True))}"
        )


__all__ = ["landing_report"]
