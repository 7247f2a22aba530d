"""How a toss ends: outcome models that turn initial conditions into faces.

``base`` holds the one protocol every estimator and map asks (:class:`OutcomeModel`, with its
declared capabilities) and the tally helpers; one module per model: ``hand`` (the catch of the
founding paper), ``table`` (landings: bounces, edge), ``air`` (the catch through air). Kernels
live in :mod:`coinflight.core`; estimators in :mod:`coinflight.probability`.

The surface kinds are a registry: :func:`register` adds one (its name and outcome model), and
then :class:`~coinflight.model.surface.Surface` takes the name as its ``kind`` (with the table's
parameters the model declares it takes, :attr:`OutcomeModel.surface_parameters`), the command
line as ``--surface`` and the web API as ``surface=`` (the page's menu lists the registered
kinds), with no other edit. The built-ins, ``hand`` and ``table``, are registered when this
package is imported (``import coinflight`` imports it). :func:`outcome_model` is the one
factory: the CLI, the maps and the estimators build their model through it.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import partial
from typing import TYPE_CHECKING

from coinflight.model.surface import (
    TABLE_PARAMETERS,
    SurfaceKind,
    add_surface_kind,
    remove_surface_kind,
    surface_kind,
    surface_kinds,
)
from coinflight.outcomes.base import OutcomeModel, describe_air

if TYPE_CHECKING:
    from coinflight.model.surface import Drag, Surface

Builder = Callable[["Surface", "Drag | None", "int | None"], OutcomeModel]
"""(surface, drag, max_bounces) -> the outcome model (drag is None when there is no air)."""

SURFACE_KINDS = surface_kinds()
"""The registered surface kinds by name (:class:`~coinflight.model.surface.SurfaceKind`: summary,
parameters taken, builder, model), in the order registered: a read-only, live view."""

_NAME = re.compile(r"[a-z0-9]+(-[a-z0-9]+)*")


def _words(names: tuple[str, ...]) -> str:
    words = [name.replace("_", " ") for name in names]
    if not words:
        return "none of a table's parameters"
    listed = words[0] if len(words) == 1 else f"{', '.join(words[:-1])} and {words[-1]}"
    return f"{listed} only"


def _build(
    model: type[OutcomeModel], surface: Surface, drag: Drag | None, max_bounces: int | None
) -> OutcomeModel:
    """The default builder of :func:`register`: ``model.from_surface(surface)``, refusing an
    air drag and a bounce limit (the model reads neither)."""
    if drag is not None:
        raise ValueError(
            f"{describe_air(drag)}: the {model.name} takes no air (leave out --drag and "
            "--spin-damping, drag= in Python)"
        )
    if max_bounces is not None:
        raise ValueError(f"max_bounces applies to a table surface only, not the {model.name}")
    return model.from_surface(surface)


def register(kind: str, model: type[OutcomeModel], build: Builder | None = None) -> None:
    """Add (or replace) the surface kind ``kind``, ending its tosses by ``model``.

    Parameters
    ----------
    kind : str
        Its name: lowercase letters and digits, words joined by hyphens (``"soft-mat"``), as
        ``Surface(kind=...)``, ``--surface`` and the API's ``surface=`` take it.
    model : type
        A subclass of :class:`OutcomeModel`. Its declarations are the kind's:
        :attr:`~OutcomeModel.summary` (--surface's help, the page's menu),
        :attr:`~OutcomeModel.surface_parameters` (the table's parameters it takes; the others
        given are refused) and :attr:`~OutcomeModel.surface_refusal`.
    build : callable, optional
        ``(surface, drag, max_bounces) -> OutcomeModel``; default: ``model.from_surface(
        surface)``, refusing an air drag and a bounce limit. The web server's worker processes
        receive the registry with each request: a model and builder defined at the top level
        of a module (not a lambda) reach them.

    Examples
    --------
    >>> from coinflight.outcomes.hand import HandCatch
    >>> class Pillow(HandCatch):  # the hand's faces, under another name
    ...     name, summary, surface_refusal = "pillow", "caught on a pillow at launch height", ""
    >>> register("pillow", Pillow)
    >>> from coinflight.model.surface import Surface
    >>> outcome_model(Surface("pillow")).name
    'pillow'
    >>> Surface("pillow", drop_height=0.3)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: drop height 0.3 m does not apply to --surface pillow (...), which takes none of ...
    >>> unregister("pillow")
    """
    if not isinstance(kind, str) or not kind:
        raise TypeError(f"kind must be a non-empty string, got {kind!r}")
    if not _NAME.fullmatch(kind):
        raise ValueError(
            f"surface kind {kind!r}: a name is lowercase letters and digits, words joined by "
            "hyphens (as soft-mat)"
        )
    if not (isinstance(model, type) and issubclass(model, OutcomeModel)):
        raise TypeError(f"model must be a subclass of OutcomeModel, got {model!r}")
    if build is not None and not callable(build):
        raise TypeError(f"build must be callable, got {type(build).__name__}")
    takes = tuple(model.surface_parameters)
    unknown = [name for name in takes if name not in TABLE_PARAMETERS]
    if unknown:
        raise ValueError(
            f"{model.__name__}.surface_parameters {', '.join(map(repr, unknown))}: a surface "
            f"kind takes some of {', '.join(TABLE_PARAMETERS)}"
        )
    refusal = model.surface_refusal or (
        f"does not apply to --surface {kind} (Surface(kind={kind!r}) in Python: the "
        f"{model.name}), which takes {_words(takes)}"
    )
    add_surface_kind(
        SurfaceKind(
            name=kind,
            summary=model.summary or model.name,
            takes=takes,
            refusal=refusal,
            build=partial(_build, model) if build is None else build,
            model=model,
        )
    )


def unregister(kind: str) -> None:
    """Remove the surface kind ``kind`` (a plug-in's, or a test's); nothing if there is none."""
    remove_surface_kind(kind)


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
        the model) or the name of a registered kind (``Surface(name)``); default the hand.
    drag : Drag, optional
        Air drag on the flight; a zero drag is no air.
    max_bounces : int, optional
        Table: stop at the contact after this many bounces.

    Examples
    --------
    >>> outcome_model().name
    'hand catch'
    >>> from coinflight.model.surface import Surface
    >>> outcome_model(Surface("table", drop_height=0.8)).describe()  # doctest: +ELLIPSIS
    'landing on a table 0.8 m below launch (restitution 0.5, friction 0.3, rolling ...), no air ...'
    """
    from coinflight import _validation as v
    from coinflight.model.surface import Drag, Surface

    if surface is None:
        surface = "hand"
    if isinstance(surface, str):
        surface = Surface(surface)
    elif not isinstance(surface, Surface):
        raise TypeError(f"surface must be a Surface or a kind name, got {type(surface).__name__}")
    kind = surface_kind(surface.kind)  # (unregistered since the surface was made: refused)
    if drag is not None:
        v.instance("drag", drag, Drag, "a Drag")
        if drag.is_zero:
            drag = None
    model = kind.build(surface, drag, max_bounces)
    if not isinstance(model, OutcomeModel):
        raise TypeError(
            f"the builder of surface kind {kind.name!r} gave {type(model).__name__}, not an "
            "OutcomeModel"
        )
    return model


def _hand(surface: Surface, drag: Drag | None, max_bounces: int | None) -> OutcomeModel:
    from coinflight.outcomes.air import DragCatch
    from coinflight.outcomes.hand import HAND_CATCH

    if max_bounces is not None:
        raise ValueError("max_bounces applies to a table surface only, not the hand catch")
    return HAND_CATCH if drag is None else DragCatch(drag)


def _table(surface: Surface, drag: Drag | None, max_bounces: int | None) -> OutcomeModel:
    from coinflight.outcomes.table import TableLanding

    return TableLanding(surface, drag, max_bounces)


def _register_builtins() -> None:
    from coinflight.outcomes.hand import HandCatch
    from coinflight.outcomes.table import TableLanding

    register("hand", HandCatch, _hand)
    register("table", TableLanding, _table)


_register_builtins()

__all__ = [
    "SURFACE_KINDS",
    "Builder",
    "OutcomeModel",
    "outcome_model",
    "register",
    "unregister",
]
