"""The landing surface and the air, from the options as typed: built, checked, described."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from coinflight.model.surface import Drag, Surface


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
    """JSON description of the landing surface and the air."""
    out: dict[str, object] = {"surface": surface.kind}
    if surface.bounces:
        out.update(
            drop_height=surface.drop_height,
            restitution=surface.restitution,
            friction=surface.friction,
        )
    out["drag"] = (
        None
        if drag is None
        else {
            "coefficient": drag.coefficient,
            "spin_damping": drag.spin_damping,
            "air_density": drag.air_density,
        }
    )
    return out


def describe_landing(surface: Surface, drag: Drag | None) -> str:
    """One line for the text output: where the toss ends, the air drag and the spin damping."""
    if surface.bounces:
        where = (
            f"landing on a table {surface.drop_height:g} m below launch (restitution "
            f"{surface.restitution:g}, friction {surface.friction:g})"
        )
    else:
        where = "caught in the hand"
    if drag is None:
        return f"{where}, no air drag"
    air = f"air drag C_d = {drag.coefficient:g}" if drag.coefficient > 0 else "no air drag"
    if drag.spin_damping > 0:
        air += f", spin damping K = {drag.spin_damping:g} N m s"
    return f"{where}, {air}"
