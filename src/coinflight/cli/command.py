"""Option groups: several command-line options that a command receives as one value.

typer maps one parameter to one option. A command that takes the coin options (``--coin``,
``--radius``, ``--thickness``, ``--mass``) would repeat four parameters, and the code that
turns them into a :class:`~coinflight.model.coin.Coin`, in every command. Instead a command
declares one parameter annotated with a :class:`Group` (``coin: CoinOptions``) and is
decorated with :func:`command`: the command line shows the group's options in its place, and
the command receives what the group's ``build`` makes of them.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypeVar

F = TypeVar("F", bound=Callable[..., None])


@dataclass(frozen=True)
class Group:
    """Options shown on the command line (``params``, name → (annotation, default)) and the
    callable that makes one value of them (called with them as keywords)."""

    params: dict[str, tuple[Any, Any]]
    build: Callable[..., Any]

    def parameters(self) -> list[inspect.Parameter]:
        kind = inspect.Parameter.KEYWORD_ONLY
        return [
            inspect.Parameter(name, kind, default=default, annotation=annotation)
            for name, (annotation, default) in self.params.items()
        ]


def _group_of(annotation: Any) -> Group | None:
    return next((m for m in getattr(annotation, "__metadata__", ()) if isinstance(m, Group)), None)


def command(func: F) -> F:
    """``func`` as typer should see it: each parameter annotated with a :class:`Group`
    replaced, in place, by the group's options; every parameter keyword-only."""
    params: list[inspect.Parameter] = []
    groups: dict[str, Group] = {}
    for p in inspect.signature(func).parameters.values():
        annotation = p.annotation
        if isinstance(annotation, str):  # from __future__ import annotations
            annotation = eval(annotation, func.__globals__)
        group = _group_of(annotation)
        if group is None:
            params.append(p.replace(annotation=annotation, kind=inspect.Parameter.KEYWORD_ONLY))
        else:
            groups[p.name] = group
            params.extend(group.parameters())

    @functools.wraps(func)
    def run(**kwargs: Any) -> None:
        for name, group in groups.items():
            kwargs[name] = group.build(**{key: kwargs.pop(key) for key in group.params})
        func(**kwargs)

    run.__signature__ = inspect.Signature(params)  # type: ignore[attr-defined]
    run.__annotations__ = {p.name: p.annotation for p in params}
    return run  # type: ignore[return-value]
