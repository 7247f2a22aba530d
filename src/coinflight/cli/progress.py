"""A progress bar on stderr for long runs: one place, reused by every command.

Shown only when stderr is a terminal, ``--quiet`` (cli.options.Quiet) is not given, and the run
is still going after :data:`DELAY` seconds, so quick runs and pipes stay clean. rich is imported
lazily.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

DELAY = 1.0
"""Seconds before the bar appears."""


class _Bar:
    def __init__(self, total: int, description: str) -> None:
        self.total = total
        self.description = description
        self.done = 0
        self.start = time.monotonic()
        self._progress: Any = None
        self._task: Any = None

    def __call__(self, amount: int) -> None:
        self.done += int(amount)
        if self._progress is None and time.monotonic() - self.start >= DELAY:
            from rich.console import Console
            from rich.progress import (
                BarColumn,
                MofNCompleteColumn,
                Progress,
                TextColumn,
                TimeRemainingColumn,
            )

            self._progress = Progress(
                TextColumn("{task.description}"),
                BarColumn(),
                MofNCompleteColumn(),
                TimeRemainingColumn(),
                console=Console(file=sys.stderr),
                transient=True,
            )
            self._progress.start()
            self._task = self._progress.add_task(self.description, total=self.total)
        if self._progress is not None:
            self._progress.update(self._task, completed=self.done)

    def close(self) -> None:
        if self._progress is not None:
            self._progress.stop()


@contextmanager
def progress_bar(total: int, description: str, quiet: bool = False) -> Iterator[Any]:
    """A callable ``advance(amount)`` for the library's ``progress=``, or None when hidden."""
    if quiet or not sys.stderr.isatty():
        yield None
        return
    bar = _Bar(total, description)
    try:
        yield bar
    finally:
        bar.close()
