"""The library's plausibility warnings heard while a command answers, for both front ends.

A value inside its allowed range but unusual for a coin toss (a radius given in millimetres as
metres) raises a :class:`~coinflight._validation.PlausibilityWarning` and the work goes on. The
command line prints each one once, as ``coinflight: warning: …`` on standard error; its
``--json`` and the web's answers carry them as ``"warnings"`` (a worker's standard error
reaches no one). Both hear them here, once: :func:`heard` while the answer is computed,
:func:`with_warnings` when its JSON is written.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any

_HEARD: ContextVar[list[str] | None] = ContextVar("coinflight_plausibility", default=None)


def one_line(message: object) -> str:
    """A message with its white space folded to single spaces (one line)."""
    return " ".join(str(message).split())


@contextmanager
def heard(on_new: Callable[[str], None] | None = None) -> Iterator[list[str]]:
    """Collect the plausibility warnings issued inside the block (from any thread), each once,
    as one line, in the order heard; ``on_new(text)`` is called at each new one. Other
    warnings are shown as Python shows them."""
    from coinflight._validation import PlausibilityWarning

    texts: list[str] = []
    token = _HEARD.set(texts)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("always", PlausibilityWarning)
            default = warnings.showwarning

            def show(
                message: Warning | str, category: type[Warning], *args: Any, **kw: Any
            ) -> None:
                if not issubclass(category, PlausibilityWarning):
                    default(message, category, *args, **kw)
                elif (text := one_line(message)) not in texts:
                    texts.append(text)
                    if on_new is not None:
                        on_new(text)

            warnings.showwarning = show
            yield texts
    finally:
        _HEARD.reset(token)


def so_far() -> list[str]:
    """The warnings the innermost :func:`heard` block has collected (none outside one)."""
    return list(_HEARD.get() or [])


def with_warnings(payload: Any, texts: list[str]) -> Any:
    """``payload`` with ``texts`` added to its ``"warnings"`` (a JSON object: the list made when
    there are any, extended when it exists, each text once; a list of objects: each of them).
    The object is changed in place and returned."""
    if not texts:
        return payload
    if isinstance(payload, list):
        for item in payload:
            with_warnings(item, texts)
        return payload
    if isinstance(payload, dict):
        listed = payload.setdefault("warnings", [])
        listed.extend(text for text in texts if text not in listed)
    return payload


__all__ = ["heard", "one_line", "so_far", "with_warnings"]
