"""``coinflight paper``: regenerate the founding paper's figures and a reproduction report."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coinflight.cli.options import CoinName, PaperSeed, Quiet, out_folder

OutDir = Annotated[Path, out_folder("the figures (PNG and SVG), report.md and report.html")]
Events = Annotated[
    int,
    typer.Option(
        "--events",
        min=100,
        max=10**9,
        help="Method B: random events per probability figure (the paper does not say).",
    ),
]


def paper(
    out: OutDir = Path("paper"),
    seed: PaperSeed = 20240601,
    events: Events = 10**6,
    coin: CoinName = None,
    quiet: Quiet = False,
) -> None:
    """Reproduce Stefan & Cheche's figures 2a-d, 3a-f and write a report beside them.

    Example: coinflight paper --out paper/
    """
    from coinflight.cli.progress import progress_bar
    from coinflight.queries.values import resolve_coin
    from coinflight.report.paper import paper_work
    from coinflight.report.reproduce import paper_files, reproduce_paper

    the_coin = resolve_coin(coin, None, None, None)
    paper_files(out)  # all 16 files, before minutes of computing, not after
    # The bar counts the probabilities' estimates (grid cells, Monte Carlo events): nearly all
    # of the run, and at --events 10⁹ minutes of it, which whole steps would not show moving.
    with progress_bar(paper_work(events, the_coin), "reproducing the paper", quiet) as advance:
        report = reproduce_paper(out, coin=the_coin, seed=seed, events=events, progress=advance)
    rows = report.numbers.rotations
    typer.echo(
        f"wrote {len(report.files)} files to {out} in {report.elapsed:.1f} s "
        f"(method B seed {seed}); open {out / 'report.html'}"
    )
    agree = sum(r.rotations_agree for r in rows)
    typer.echo(f"rotations: {agree}/{len(rows)} agree with the paper to its printed digits")
    for r in rows:
        if r.face_agrees is False:
            typer.echo(
                f"Fig {r.case.figure}: the paper's text says {r.case.paper_face} up; "
                f"its own eq 14 gives {r.face} up (cos θ = {r.cos_theta:+.4f})"
            )
    for p in report.numbers.probabilities:
        typer.echo(
            f"Fig {p.case.figure}: P(heads) method A {p.method_a.p_heads:.6f}, "
            f"method B {p.method_b.p_heads:.4f}, exact {p.exact.p_heads:.6f}"
        )


__all__ = ["paper"]
