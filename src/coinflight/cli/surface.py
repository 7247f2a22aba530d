"""Options for where the toss ends (a registered surface kind: hand, table, …) and the air, shared
by several commands."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from coinflight.cli.options import SURFACE_PANEL
from coinflight.model.surface import surface_kinds
from coinflight.queries.landing import (
    LandingChoice,
    build_drag,
    build_surface,
    check_bounces,
    outcome_model,
    table_outcome,
)

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.surface import Drag, Surface
    from coinflight.model.toss import Toss

__all__ = [
    "LandingChoice",
    "SurfaceOption",
    "build_drag",
    "build_surface",
    "check_bounces",
    "outcome_model",
    "report_landing",
    "table_outcome",
    "table_title",
]


def _complete(incomplete: str) -> list[tuple[str, str]]:
    return [(k.name, k.summary) for k in surface_kinds().values() if k.name.startswith(incomplete)]


_KINDS = surface_kinds().values()
SurfaceOption = Annotated[
    str,
    typer.Option(
        "--surface",
        metavar="|".join(k.name for k in _KINDS),
        rich_help_panel=SURFACE_PANEL,
        help="; ".join(f"{k.name}: {k.summary}" for k in _KINDS) + ".",
        autocompletion=_complete,
    ),
]
"""--surface NAME: a registered surface kind (:func:`coinflight.outcomes.register`; the help
and the shell completion list them, the surface checks the name in its words)."""


def report_landing(
    coin: Coin,
    toss: Toss,
    surface: Surface,
    drag: Drag | None,
    json_output: bool,
    bounces: int | None = None,
) -> None:
    """``coinflight toss`` for a table landing or a flight through air: text or JSON."""
    from coinflight.cli.options import print_json
    from coinflight.queries.toss import landing_report

    payload, line, model = landing_report(coin, toss, surface, drag, bounces)
    if json_output:
        print_json(payload)
        return
    wx, wy, wz = (float(w) for w in toss.omega)
    typer.echo(f"{coin.describe()}, started {toss.start} up")
    typer.echo(
        f"spin ω0 = ({wx:g}, {wy:g}, {wz:g}) rad/s, launch speed "
        f"{float(toss.launch_speed):.3g} m/s (apex {float(toss.apex):.3g} m); "
        f"{model.describe()}"
    )
    typer.echo(line)


def table_title(
    drop_height: float | None,
    restitution: str | None,
    friction: str | None,
    bounces: int | None,
) -> str:
    """How a toss onto a table ends, for a map's title ("tossed heads up and …")."""
    s = build_surface("table", drop_height, restitution, friction)
    when = "at rest" if bounces is None else f"after {bounces} bounce{'s' * (bounces != 1)}"
    return (
        f"dropped on a table {s.drop_height:g} m below launch\n(restitution e = "
        f"{s.restitution:g}, friction μ = {s.friction:g}), the face {when}"
    )
