"""Options for where the toss ends (hand or table) and the air, shared by several commands."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight.cli.options import number

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.surface import Drag, Surface
    from coinflight.model.toss import Toss
    from coinflight.outcomes.base import OutcomeModel

SURFACE_PANEL = "Landing"

SurfaceKindOption = Annotated[
    str,
    typer.Option(
        "--surface",
        metavar="hand|table",
        rich_help_panel=SURFACE_PANEL,
        help="hand: caught at launch height (no bounce); table: falls onto a hard surface, "
        "bounces and settles heads, tails or on edge.",
    ),
]
DropHeight = Annotated[
    float | None,
    typer.Option(
        "--drop-height",
        parser=number,
        metavar="D",
        rich_help_panel=SURFACE_PANEL,
        help="table: how far the surface lies below the launch height, m (default 0).",
    ),
]
Restitution = Annotated[
    float | None,
    typer.Option(
        "--restitution",
        parser=number,
        metavar="E",
        rich_help_panel=SURFACE_PANEL,
        help="table: coefficient of restitution in [0, 1] (default 0.5; 0 lands dead).",
    ),
]
Friction = Annotated[
    float | None,
    typer.Option(
        "--friction",
        parser=number,
        metavar="MU",
        rich_help_panel=SURFACE_PANEL,
        help="table: Coulomb friction coefficient ≥ 0 (default 0.3).",
    ),
]
DragCoefficient = Annotated[
    float | None,
    typer.Option(
        "--drag",
        parser=number,
        metavar="CD",
        rich_help_panel=SURFACE_PANEL,
        help="Air drag coefficient C_d ≥ 0 on the face area (1.17: a flat disc); "
        "integrated numerically, slower. Default 0 (no air).",
    ),
]
SpinDamping = Annotated[
    float | None,
    typer.Option(
        "--spin-damping",
        parser=number,
        metavar="K",
        rich_help_panel=SURFACE_PANEL,
        help="Damping torque −K ω on the spin, N m s ≥ 0 (default 0).",
    ),
]
Bounces = Annotated[
    int | None,
    typer.Option(
        "--bounces",
        metavar="K",
        rich_help_panel=SURFACE_PANEL,
        help="table: stop at the contact after K bounces (0: the first contact) and report "
        "the well the coin is in; default: bounce until it settles.",
    ),
]


def build_surface(
    kind: str, drop_height: float | None, restitution: float | None, friction: float | None
) -> Surface:
    """The :class:`~coinflight.model.surface.Surface` for the options (table options: a table)."""
    from coinflight.model.surface import DEFAULT_FRICTION, DEFAULT_RESTITUTION, Surface

    given = {
        "--drop-height": drop_height,
        "--restitution": restitution,
        "--friction": friction,
    }
    if kind == "hand":
        extra = [flag for flag, value in given.items() if value is not None]
        if extra:
            raise ValueError(f"{', '.join(extra)} applies to --surface table only")
    return Surface(
        kind,  # type: ignore[arg-type]
        drop_height=0.0 if drop_height is None else drop_height,
        restitution=DEFAULT_RESTITUTION if restitution is None else restitution,
        friction=DEFAULT_FRICTION if friction is None else friction,
    )


def build_drag(coefficient: float | None, spin_damping: float | None) -> Drag | None:
    """The :class:`~coinflight.model.surface.Drag` for the options, None when there is no air."""
    from coinflight.model.surface import Drag

    if coefficient is None and spin_damping is None:
        return None
    drag = Drag(
        coefficient=0.0 if coefficient is None else coefficient,
        spin_damping=0.0 if spin_damping is None else spin_damping,
    )
    return None if drag.is_zero else drag


def check_bounces(surface: Surface, bounces: int | None) -> None:
    """--bounces needs a table and a count between 0 and landing.MAX_BOUNCES."""
    if bounces is None:
        return
    if surface.kind != "table":
        raise ValueError("--bounces applies to --surface table only")
    from coinflight.outcomes.table import check_max_bounces

    check_max_bounces(bounces, "--bounces")


def surface_payload(surface: Surface, drag: Drag | None) -> dict[str, object]:
    """JSON description of the landing surface and the air (the model's ``to_dict``)."""
    from coinflight.outcomes import outcome_model

    return outcome_model(surface, drag).to_dict()


def describe_landing(surface: Surface, drag: Drag | None) -> str:
    """One line for the text output: where the toss ends, the air drag and the spin damping."""
    from coinflight.outcomes import outcome_model

    return outcome_model(surface, drag).describe()


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
    restitution: float | None,
    friction: float | None,
    drag: float | None,
    spin_damping: float | None,
    bounces: int | None = None,
) -> LandingChoice | None:
    """None for the plain hand catch; else the surface, drag and outcome model to use."""
    from coinflight import outcomes

    the_surface = build_surface(kind, drop_height, restitution, friction)
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
    restitution: float | None,
    friction: float | None,
    bounces: int | None,
) -> dict[str, Any]:
    """``outcome=`` for :func:`coinflight.studies.basin.basin_map` (empty for the hand)."""
    from coinflight.outcomes import outcome_model

    the_surface = build_surface(kind, drop_height, restitution, friction)
    check_bounces(the_surface, bounces)
    if not the_surface.bounces:
        return {}
    return {"outcome": outcome_model(the_surface, None, bounces)}


def table_title(
    drop_height: float | None,
    restitution: float | None,
    friction: float | None,
    bounces: int | None,
) -> str:
    """How a toss onto a table ends, for a map's title ("tossed heads up and …")."""
    s = build_surface("table", drop_height, restitution, friction)
    when = "at rest" if bounces is None else f"after {bounces} bounce{'s' * (bounces != 1)}"
    return (
        f"dropped on a table {s.drop_height:g} m below launch\n(restitution e = "
        f"{s.restitution:g}, friction μ = {s.friction:g}), the face {when}"
    )
