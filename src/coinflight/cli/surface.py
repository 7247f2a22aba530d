"""Options for where the toss ends (hand or table) and the air, shared by several commands."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import typer

from coinflight.cli.landing import (
    build_drag,
    build_surface,
    check_bounces,
)

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.surface import Drag, Surface
    from coinflight.model.toss import Toss
    from coinflight.outcomes.base import OutcomeModel


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
    from coinflight.outcomes import outcome_model

    model = outcome_model(surface, drag, bounces)
    payload, line = model.report(coin, toss)
    wx, wy, wz = (float(w) for w in toss.omega)
    payload.update(model.to_dict())
    payload.update(
        omega=[wx, wy, wz],
        start=toss.start,
        g=toss.g,
        flight_time=float(toss.flight_time),
        launch_speed=float(toss.launch_speed),
        apex=float(toss.apex),
        coin={
            "name": coin.name,
            "radius": coin.radius,
            "thickness": coin.thickness,
            "mass": coin.mass,
        },
    )
    if json_output:
        print_json(payload)
        return
    typer.echo(f"{coin.describe()}, started {toss.start} up")
    typer.echo(
        f"spin ω0 = ({wx:g}, {wy:g}, {wz:g}) rad/s, launch speed "
        f"{float(toss.launch_speed):.3g} m/s (apex {float(toss.apex):.3g} m); "
        f"{model.describe()}"
    )
    typer.echo(line)


@dataclass(frozen=True)
class LandingChoice:
    """The landing the options ask for, and the outcome model that evaluates it."""

    surface: Surface
    drag: Drag | None
    model: OutcomeModel

    def describe(self) -> str:
        """One line for the text output (the model's ``describe``)."""
        return self.model.describe()


def outcome_model(
    kind: str,
    drop_height: float | None,
    restitution: str | None,
    friction: str | None,
    surface_preset: str | None,
    drag: float | None,
    spin_damping: float | None,
    bounces: int | None = None,
    ranged: bool = False,
) -> LandingChoice | None:
    """None for the plain hand catch; else the surface, drag and outcome model to use
    (``ranged``: --restitution and --friction may be distributions, read apart with
    :func:`~coinflight.cli.landing.contact_spread`)."""
    from coinflight import outcomes

    the_surface = build_surface(kind, drop_height, restitution, friction, surface_preset, ranged)
    the_drag = build_drag(drag, spin_damping)
    check_bounces(the_surface, bounces)
    if not the_surface.bounces and the_drag is None:
        return None
    return LandingChoice(
        the_surface, the_drag, outcomes.outcome_model(the_surface, the_drag, bounces)
    )


def table_outcome(
    kind: str,
    drop_height: float | None,
    restitution: str | None,
    friction: str | None,
    surface_preset: str | None,
    bounces: int | None,
) -> dict[str, Any]:
    """``outcome=`` for :func:`coinflight.studies.basin.basin_map` (empty for the hand)."""
    from coinflight.outcomes import outcome_model

    the_surface = build_surface(kind, drop_height, restitution, friction, surface_preset)
    check_bounces(the_surface, bounces)
    if not the_surface.bounces:
        return {}
    return {"outcome": outcome_model(the_surface, None, bounces)}


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
