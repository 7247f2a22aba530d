"""How the command ends: one line on stderr and an exit code (2 for bad input, 130 after
Ctrl-C), never a traceback."""

from __future__ import annotations

import os
import sys
from contextlib import suppress

import typer

USAGE_ERROR = 2
INTERRUPTED = 130
"""Exit code after Ctrl-C: 128 + SIGINT."""


def fail(message: str, code: int = USAGE_ERROR) -> None:
    """Print ``coinflight: error: message`` on stderr and exit with ``code``."""
    say(f"coinflight: error: {message}")
    sys.exit(code)


def interrupted() -> None:
    """After Ctrl-C: ``coinflight: interrupted`` on stderr and exit code 130."""
    say("coinflight: interrupted")
    sys.exit(INTERRUPTED)


def exit_now(code: int) -> None:
    """End the process at once with ``code`` (after Ctrl-C, in the console command only).

    The outputs' staging folders are already gone (removed as the interrupt unwound); what
    is skipped is waiting for worker threads to finish their chunk, and CPython's habit of
    ending with SIGINT itself, not exit code 130, when the interrupt landed in an import.
    """
    for stream in (sys.stdout, sys.stderr):
        with suppress(OSError, ValueError, AttributeError):
            stream.flush()
    os._exit(code)


def say(line: str) -> None:
    """One line on stderr; if stderr itself cannot be written, nothing (the exit code tells)."""
    with suppress(OSError, ValueError):
        typer.echo(line, err=True)
