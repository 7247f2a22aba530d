"""Where an output came from: the coinflight version and the command that made it.

The front ends say what was asked while they answer it (:func:`invoked`): the command line
its arguments (``coinflight toss --omega 80 0 0 --json``, :func:`command_line`), the web
application the request (``GET /api/toss?omega=80,0,0``). Every JSON answer
(:func:`coinflight.queries.encoding.json_text`) and every saved figure's metadata
(:func:`coinflight.plotting.style.save_figure`) carries :func:`provenance`. Called from
Python, outside both, an output carries the version alone.
"""

from __future__ import annotations

import shlex
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from contextvars import ContextVar

from coinflight._version import __version__

_COMMAND: ContextVar[str | None] = ContextVar("coinflight_command", default=None)


def command_line(argv: Sequence[str]) -> str:
    """The command line of ``coinflight`` run with ``argv``, quoted as a shell reads it."""
    return shlex.join(["coinflight", *argv])


@contextmanager
def invoked(command: str) -> Iterator[None]:
    """Within the block, outputs say they were made by ``command`` (a command line, or a web
    request such as ``GET /api/toss?omega=80,0,0``)."""
    token = _COMMAND.set(command)
    try:
        yield
    finally:
        _COMMAND.reset(token)


def provenance() -> dict[str, str]:
    """``{"coinflight_version": …, "command": …}``; ``command`` only within :func:`invoked`."""
    made: dict[str, str] = {"coinflight_version": __version__}
    command = _COMMAND.get()
    if command is not None:
        made["command"] = command
    return made
