"""``coinflight edge --target P``: the ratio h/d for a chosen P(edge), its band, as text or JSON
(the search: :func:`coinflight.studies.edge_target.target_ratio`)."""

from __future__ import annotations

import sys
from typing import Any

import typer

from coinflight.cli.options import print_json

_NAMES = {
    "restitution": ("e", ""),
    "friction": ("μ", ""),
    "resistance": ("resistances", " m"),
    "rolling_resistance": ("rolling resistance", " m"),
    "pivoting_resistance": ("pivoting resistance", " m"),
}


def _cell(c: dict[str, Any]) -> str:
    return ", ".join(f"{_NAMES[k][0]} {c[k]:.3g}{_NAMES[k][1]}" for k in _NAMES if k in c)


def _root(r: dict[str, Any]) -> str:
    se = "∞ (no rise measured)" if r["stderr"] is None else f"{r['stderr']:.3f}"
    return f"{r['ratio']:.3f} ± {se}"


def run_target(query: Any, cluster: Any, json: bool) -> None:
    """Search the ratio of ``query`` (a checked :class:`coinflight.queries.edge.EdgeQuery` with
    a target), then print it: the band, each cell, Yong & Mahadevan's roots, the measured rows,
    the seed and the method. The size and estimated time go to stderr on a terminal."""
    from coinflight.queries.edge import target_answer

    def say(line: str) -> None:
        if sys.stderr.isatty():
            typer.echo(line, err=True)

    with cluster.executor() as executor:
        answer = target_answer(query, executor, say)
    if json:
        print_json(answer)
        return
    p, band = answer["target"], answer["band"]
    varied = [
        f"{_NAMES[k][0]} {lo:g}–{hi:g}{_NAMES[k][1]}"
        for k, (lo, hi) in answer["box"].items()
        if lo != hi
    ]
    typer.echo(f"P(edge) = {p:.4g}: h/d at which the simulated tosses land on edge that often")
    over = (
        f"a band over {', '.join(varied)} (e and μ: the surface presets' ranges"
        + (
            "; resistances: coinflight.model.surface's band, both alike)"
            if "resistance" in answer["box"]
            else ")"
        )
        if varied
        else "every parameter given: one cell"
    )
    psi = answer["setting"]["psi"]
    tosses = (
        "planar tosses"
        if psi is None
        else f"tosses wobbling on a cone ψ {'≈ 82° (human)' if psi == 'human' else f'{psi:g}°'}"
    )
    typer.echo(
        f"  {tosses}, {answer['n']:,} per ratio tried, the same at every ratio and cell; {over}"
    )
    if len(answer["cells"]) > 1:
        typer.echo(f"  band  {_root(band['low'])} – {_root(band['high'])} (± statistical error)")
    typer.echo(f"  {'h/d ± s.e.':>18}  {'dP/d(h/d)':>13}  cell")
    for c in answer["cells"]:
        slope = f"{c['slope']:.2f} ± {c['slope_stderr']:.2f}"
        typer.echo(f"  {_root(c):>18}  {slope:>13}  {_cell(c) or '-'}")
    ym = answer["yong_mahadevan"]
    typer.echo(
        f"Yong & Mahadevan (2011): geometric {ym['geometric']:.3f}, dynamic (dead landing) "
        f"{ym['dynamic']:.3f}"
    )
    for m in answer["measured"]:
        typer.echo(
            f"measured ({m['source']}): P(edge) {m['fraction']:.3f} ± {m['stderr']:.3f} at "
            f"h/d {m['ratio']:.3f} ({m['n']:,} flips)"
        )
    typer.echo(f"seed {answer['seed']}; method: {answer['method']}")


__all__ = ["run_target"]
