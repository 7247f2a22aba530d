"""The landing surface and the air, from the options as typed: built, checked, described
(the command line's and the web application's one reading of --surface, --drop-height,
--restitution, --friction, --drag, --spin-damping and --bounces)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from coinflight.model.surface import Drag, Surface
    from coinflight.outcomes.base import OutcomeModel


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
