"""Options for where the toss ends (hand or table) and the air, shared by several commands."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import typer

from coinflight.cli.landing import (
    build_drag,
    build_surface,
    check_bounces,
    describe_landing,
    surface_payload,
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
    from coinflight.core.outcome import FACE_NAMES

    wx, wy, wz = (float(w) for w in toss.omega)
    head = {
        "omega": [wx, wy, wz],
        "start": toss.start,
        "g": toss.g,
        "flight_time": float(toss.flight_time),
        "launch_speed": float(toss.launch_speed),
        "apex": float(toss.apex),
        "coin": {
            "name": coin.name,
            "radius": coin.radius,
            "thickness": coin.thickness,
            "mass": coin.mass,
        },
    }
    if surface.bounces:
        from coinflight.outcomes.table import STATUS_NAMES, Landing

        out = Landing(coin, toss, surface, drag, bounces).outcome
        payload: dict[str, object] = {
            "outcome": out.face_name,
            "bounces": int(out.bounces),
            "first_contact": float(out.first_contact),
            "settle_time": float(out.settle_time),
            "status": STATUS_NAMES[int(out.status)],
        }
        line = (
            f"lands on the table at t = {float(out.first_contact):.4f} s, bounces "
            f"{int(out.bounces)} times and ends {out.face_name.upper()} "
            f"(at t = {float(out.settle_time):.4f} s; {out.status_name})"
        )
        if out.status_name == "unsettled":
            line = (
                f"lands on the table at t = {float(out.first_contact):.4f} s and has NOT "
                f"settled after {int(out.bounces)} impacts (status unsettled, stopped at "
                f"t = {float(out.settle_time):.4f} s): the face up then was "
                f"{out.face_name.upper()}, not a resting face"
            )
    else:
        from coinflight.outcomes.table import catch_with_drag

        assert drag is not None
        face, when = catch_with_drag(
            coin, toss.omega.reshape(1, 3), toss.launch_speed, toss.start_sign, toss.g, drag
        )
        name = FACE_NAMES[int(face[0])]
        payload = {"outcome": name, "catch_time": float(when[0])}
        line = f"caught at launch height at t = {float(when[0]):.4f} s, {name.upper()} up"
    payload.update(surface_payload(surface, drag))
    payload.update(head)
    if json_output:
        print_json(payload)
        return
    typer.echo(f"{coin.describe()}, started {toss.start} up")
    typer.echo(
        f"spin ω0 = ({wx:g}, {wy:g}, {wz:g}) rad/s, launch speed "
        f"{float(toss.launch_speed):.3g} m/s (apex {float(toss.apex):.3g} m); "
        f"{describe_landing(surface, drag)}"
    )
    typer.echo(line)


@dataclass(frozen=True)
class LandingChoice:
    """The landing the options ask for, and the outcome model that evaluates it."""

    surface: Surface
    drag: Drag | None
    model: OutcomeModel

    def describe(self) -> str:
        """One line for the text output (:func:`describe_landing`)."""
        return describe_landing(self.surface, self.drag)


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
    from coinflight.outcomes.table import DragCatch, TableLanding

    the_surface = build_surface(kind, drop_height, restitution, friction)
    the_drag = build_drag(drag, spin_damping)
    check_bounces(the_surface, bounces)
    if the_surface.bounces:
        return LandingChoice(the_surface, the_drag, TableLanding(the_surface, the_drag, bounces))
    if the_drag is not None:
        return LandingChoice(the_surface, the_drag, DragCatch(the_drag))
    return None


def table_outcome(
    kind: str,
    drop_height: float | None,
    restitution: float | None,
    friction: float | None,
    bounces: int | None,
) -> dict[str, Any]:
    """``outcome=`` for :func:`coinflight.plotting.basin.basin_map` (empty for the hand)."""
    from coinflight.outcomes.table import table_faces

    the_surface = build_surface(kind, drop_height, restitution, friction)
    check_bounces(the_surface, bounces)
    if not the_surface.bounces:
        return {}
    return {"outcome": table_faces(the_surface, bounces)}


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
