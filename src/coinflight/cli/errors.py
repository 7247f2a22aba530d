"""One clear line on stderr and exit code 2 for every bad input, never a traceback.

The standard streams are handled as command-line tools handle them:

- standard output closed by its reader (``coinflight data … | head -c 10``): the command ends
  quietly with exit code 141 (128 + SIGPIPE, what the shell reports for ``seq 1 1000000 |
  head -1``), standard output then pointing at ``/dev/null`` so nothing more is said;
- standard output that cannot be written (a full disk, ``> /dev/full``; a closed descriptor,
  ``>&-``): one line ``coinflight: error: cannot write to standard output: REASON`` and exit
  code 2, as for an output file that cannot be written; a closed standard output is refused
  before anything is computed;
- Ctrl-C (SIGINT): ``coinflight: interrupted`` and exit code 130 (128 + SIGINT); outputs being
  written are abandoned, their staging folders removed (:mod:`coinflight._files`);
- standard error that cannot be written: the exit code alone tells.
"""

from __future__ import annotations

import errno
import io
import os
import sys
import warnings
from collections.abc import Iterator, Sequence
from contextlib import contextmanager, suppress
from typing import Any

import typer
from typer.core import TyperGroup

USAGE_ERROR = 2
INTERRUPTED = 130
"""Exit code after Ctrl-C: 128 + SIGINT."""
PIPE_CLOSED = 141
"""Exit code when standard output's reader has gone: 128 + SIGPIPE."""


def fail(message: str, code: int = USAGE_ERROR) -> None:
    """Print ``coinflight: error: message`` on stderr and exit with ``code``."""
    _say(f"coinflight: error: {message}")
    sys.exit(code)


def interrupted() -> None:
    """After Ctrl-C: ``coinflight: interrupted`` on stderr and exit code 130."""
    _say("coinflight: interrupted")
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


def _say(line: str) -> None:
    """One line on stderr; if stderr itself cannot be written, nothing (the exit code tells)."""
    with suppress(OSError, ValueError):
        typer.echo(line, err=True)


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


def _is_stdout_failure(exc: BaseException) -> bool:
    return isinstance(exc, StdoutError | BrokenPipeError)


def _stdout_failed(exc: OSError) -> None:
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


class _Escape(Exception):
    """Carries Ctrl-C or a failure of standard output past typer, which would otherwise end
    the command silently (exit 130, or exit 1 for a closed pipe)."""

    def __init__(self, original: BaseException) -> None:
        super().__init__(str(original))
        self.original = original


@contextmanager
def _escaping() -> Iterator[None]:
    try:
        yield
    except KeyboardInterrupt as exc:
        raise _Escape(exc) from exc
    except OSError as exc:
        if _is_stdout_failure(exc):
            raise _Escape(exc) from exc
        raise


class OneLineErrors(TyperGroup):
    """A typer group whose errors are one line on stderr.

    Typer's usage errors (unknown option, malformed number) and the library's ``ValueError`` /
    ``TypeError`` (a value outside its allowed range) both end as ``coinflight: error: …`` with
    exit code 2. Set ``COINFLIGHT_DEBUG=1`` to see the traceback of a library error instead.
    """

    def make_context(self, *args: Any, **kwargs: Any) -> Any:
        with _escaping():  # --help and --version print while the context is made
            return super().make_context(*args, **kwargs)

    def invoke(self, ctx: Any) -> Any:
        with _escaping():
            return super().invoke(ctx)

    def main(  # type: ignore[override]
        self,
        args: Sequence[str] | None = None,
        prog_name: str | None = None,
        complete_var: str | None = None,
        standalone_mode: bool = True,
        **extra: Any,
    ) -> Any:
        try:
            try:
                with one_line_warnings():
                    rv = super().main(
                        args=args,
                        prog_name=prog_name,
                        complete_var=complete_var,
                        standalone_mode=False,
                        **extra,
                    )
                sys.stdout.flush()  # a full disk shows here when stdout is a file
            except _Escape as escape:
                raise escape.original from None
        except KeyboardInterrupt:
            interrupted()
        except OSError as exc:
            if not _is_stdout_failure(exc):
                raise
            _stdout_failed(exc)
        except typer.TyperException as exc:
            fail(_one_line(exc.format_message()), exc.exit_code)
        except typer.Abort:
            fail("aborted", 1)
        except (ValueError, TypeError) as exc:
            if os.environ.get("COINFLIGHT_DEBUG"):
                raise
            fail(_one_line(str(exc)))
        sys.exit(rv if isinstance(rv, int) else 0)


@contextmanager
def one_line_warnings() -> Iterator[None]:
    """The library's :class:`~coinflight._validation.PlausibilityWarning` (an odd but allowed
    value, e.g. a radius in millimetres) as ``coinflight: warning: …`` on stderr, each once;
    other warnings as Python shows them."""
    from coinflight._validation import PlausibilityWarning

    shown: set[str] = set()
    with warnings.catch_warnings():
        warnings.simplefilter("always", PlausibilityWarning)
        default = warnings.showwarning

        def show(message: Warning | str, category: type[Warning], *args: Any, **kw: Any) -> None:
            if not issubclass(category, PlausibilityWarning):
                default(message, category, *args, **kw)
            elif (text := _one_line(str(message))) not in shown:
                shown.add(text)
                _say(f"coinflight: warning: {text}")

        warnings.showwarning = show
        yield


def _one_line(message: str) -> str:
    return " ".join(message.split())
