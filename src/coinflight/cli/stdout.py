"""Standard output guarded as command-line tools guard it (see :mod:`coinflight.cli.errors`):
a closed pipe ends quietly with exit code 141, any other failure is one line and exit code 2."""

from __future__ import annotations

import errno
import io
import os
import sys
from typing import Any

from coinflight.cli.exits import fail

PIPE_CLOSED = 141
"""Exit code when standard output's reader has gone: 128 + SIGPIPE."""


class StdoutError(OSError):
    """A write to standard output failed (raised by the stream :func:`guard_stdout` installs)."""


class _RawStdout(io.RawIOBase):
    """File descriptor 1 whose write errors are :class:`StdoutError`, so that a failure of
    standard output is never confused with one of another file."""

    def __init__(self, fd: int = 1) -> None:
        super().__init__()
        self._fd = fd

    def writable(self) -> bool:
        return True

    def fileno(self) -> int:
        return self._fd

    def isatty(self) -> bool:
        return os.isatty(self._fd)

    def write(self, data: Any) -> int:
        try:
            return os.write(self._fd, data)
        except OSError as exc:
            raise StdoutError(exc.errno, exc.strerror) from None


def guard_stdout() -> None:
    """Prepare the standard streams of the console command (``main``), before any command runs.

    Closed descriptors 0-2 are reopened on ``/dev/null``, so that no output file is ever opened
    as one of them (a library writing to descriptor 2 would write into it); a closed standard
    output is then refused (one line, exit 2). ``sys.stdout`` becomes the same text stream over
    a writer whose errors are :class:`StdoutError`.
    """
    closed = []
    for fd in (0, 1, 2):
        try:
            os.fstat(fd)
        except OSError:
            closed.append(fd)
            null = os.open(os.devnull, os.O_RDWR)
            if null != fd:
                os.dup2(null, fd)
                os.close(null)
    if 1 in closed or sys.stdout is None:
        fail(f"cannot write to standard output: {os.strerror(errno.EBADF)}")
    old = sys.stdout
    old.flush()
    sys.stdout = io.TextIOWrapper(
        io.BufferedWriter(_RawStdout(1)),
        encoding=old.encoding,
        errors=old.errors,
        line_buffering=bool(old.line_buffering),
    )


def is_stdout_failure(exc: BaseException) -> bool:
    return isinstance(exc, StdoutError | BrokenPipeError)


def stdout_failed(exc: OSError) -> None:
    """End the command after standard output failed: quietly for a closed pipe, else one line."""
    stream = sys.stdout
    raw = getattr(getattr(stream, "buffer", None), "raw", None)
    if isinstance(raw, _RawStdout):  # point descriptor 1 at /dev/null: the last flush succeeds
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, raw.fileno())
        os.close(null)
    if exc.errno == errno.EPIPE:
        sys.exit(PIPE_CLOSED)
    fail(f"cannot write to standard output: {exc.strerror or exc}")
