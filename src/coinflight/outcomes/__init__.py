"""How a toss ends: outcome models that turn initial conditions into faces.

``base`` holds the one protocol every estimator and map asks (:class:`OutcomeModel`, with its
declared capabilities) and the tally helpers; one module per model: ``hand`` (the catch of the
founding paper), ``table`` (landings: bounces, edge), ``air`` (the catch through air). Kernels
live in :mod:`coinflight.core`; estimators in :mod:`coinflight.probability`.

:func:`outcome_model` is the one factory: the CLI, the maps and the estimators build their model
through it. A new model is its kernel, its module here, and ONE line of :data:`SURFACE_KINDS`
(or :func:`register` at run time).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from coinflight.outcomes.base import OutcomeModel

if TYPE_CHECKING:
    from coinflight.model.surface import Drag, Surface

Builder = Callable[["Surface | None", "Drag | None", "int | None"], OutcomeModel]
"""(surface, drag, max_bounces) -> the outcome model (drag is None when there is no air)."""


def _hand(surface: Surface | None, drag: Drag | None, max_bounces: int | None) -> OutcomeModel:
    from coinflight.outcomes.air import DragCatch
    from coinflight.outcomes.hand import HAND_CATCH

    if max_bounces is not None:
        raise ValueError("max_bounces applies to a table surface only, not the hand catch")
    return HAND_CATCH if drag is None else DragCatch(drag)


def _table(surface: Surface | None, drag: Drag | None, max_bounces: int | None) -> OutcomeModel:
    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import TableLanding

    return TableLanding(Surface("table") if surface is None else surface, drag, max_bounces)


SURFACE_KINDS: dict[str, Builder] = {
    "hand": _hand,
    "table": _table,
}
"""Where a toss may end -> the builder of its outcome model. One line per model."""


def register(kind: str, builder: Builder) -> None:
    """Add (or replace) the builder of surface kind ``kind`` in :data:`SURFACE_KINDS`."""
    if not isinstance(kind, str) or not kind:
        raise TypeError(f"kind must be a non-empty string, got {kind!r}")
    if not callable(builder):
        raise TypeError(f"builder must be callable, got {type(builder).__name__}")
    SURFACE_KINDS[kind] = builder


def outcome_model(
    surface: Surface | str | None = None,
    drag: Drag | None = None,
    max_bounces: int | None = None,
) -> OutcomeModel:
    """The outcome model of a toss that ends on ``surface`` through ``drag``.

    Parameters
    ----------
    surface : Surface or str, optional
        Where the toss ends: a :class:`~coinflight.model.surface.Surface` (its ``kind`` picks
        the model) or the name of a registered kind; default the hand.
    drag : Drag, optional
        Air drag on the flight; a zero drag is no air.
    max_bounces : int, optional
        Table: stop at the contact after this many bounces.

    Examples
    --------
    >>> outcome_model().name
    'hand catch'
    >>> from coinflight.model.surface import Surface
    >>> outcome_model(Surface("table", drop_height=0.8)).describe()
    'landing on a table 0.8 m below launch (restitution 0.5, friction 0.3), no air drag'
    """
    from coinflight import _validation as v
    from coinflight.model.surface import Drag, Surface

    if surface is None:
        kind, the_surface = "hand", None
    elif isinstance(surface, Surface):
        kind, the_surface = surface.kind, surface
    elif isinstance(surface, str):
        kind, the_surface = surface, None
    else:
        raise TypeError(f"surface must be a Surface or a kind name, got {type(surface).__name__}")
    v.choice("surface", kind, tuple(SURFACE_KINDS))
    if drag is not None:
        v.instance("drag", drag, Drag, "a Drag")
        if drag.is_zero:
            drag = None
    return SURFACE_KINDS[kind](the_surface, drag, max_bounces)


__all__ = ["SURFACE_KINDS", "Builder", "OutcomeModel", "outcome_model", "register"]
