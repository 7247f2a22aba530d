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
- standard error that cannot be written: the exit code alone tells;
- any other error of the operating system (a file name over the system's limit, a folder
  where a file was expected, no permission, a full disk): one line naming the file and the
  system's reason, exit code 2 (:func:`os_error_line`).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

import typer
from typer.core import TyperGroup

from coinflight._provenance import command_line, invoked
from coinflight.cli.exits import fail, interrupted, say
from coinflight.cli.helptext import tidy_help
from coinflight.cli.stdout import is_stdout_failure, stdout_failed


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
        if is_stdout_failure(exc):
            raise _Escape(exc) from exc
        raise


class OneLineErrors(TyperGroup):
    """A typer group whose errors are one line on stderr.

    Typer's usage errors (unknown option, malformed number) and the library's ``ValueError`` /
    ``TypeError`` (a value outside its allowed range) both end as ``coinflight: error: …`` with
    exit code 2. Set ``COINFLIGHT_DEBUG=1`` to see the traceback of a library error instead.
    Its help, and every subcommand's, is shown as written (:mod:`coinflight.cli.helptext`).
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        tidy_help(self)

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
                args = list(sys.argv[1:] if args is None else args)
                no_empty_values(args)
                with invoked(command_line(args)), one_line_warnings():
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
            if is_stdout_failure(exc):
                stdout_failed(exc)
            if os.environ.get("COINFLIGHT_DEBUG"):
                raise
            fail(os_error_line(exc))
        except typer.TyperException as exc:
            _in_our_words(exc)
            fail(_one_line(exc.format_message()), exc.exit_code)
        except typer.Abort:
            fail("aborted", 1)
        except (ValueError, TypeError) as exc:
            if os.environ.get("COINFLIGHT_DEBUG"):
                raise
            fail(_one_line(str(exc)))
        sys.exit(rv if isinstance(rv, int) else 0)


def no_empty_values(args: Sequence[str]) -> None:
    """ValueError for an empty (or blank) value on the command line, naming its option: no
    option of coinflight takes one, and read as "not given" it would silently become the
    default (``plot basin --flight-time ''`` drew the default map)."""
    for i, arg in enumerate(args):
        if arg == "--":
            return
        name, eq, value = arg.partition("=")
        if arg.startswith("--") and eq and not value.strip():
            option = name
        elif not arg.strip():
            previous = args[i - 1] if i else ""
            if not previous.startswith("-"):
                raise ValueError(f"an empty argument {arg!r} is not allowed; give a value")
            option = previous.partition("=")[0]
        else:
            continue
        raise ValueError(
            f"{option} was given an empty value {value if eq else arg!r}; give a value, or "
            f"leave {option} out for its default"
        )


@contextmanager
def one_line_warnings() -> Iterator[None]:
    """The library's :class:`~coinflight._validation.PlausibilityWarning` (an odd but allowed
    value, e.g. a radius in millimetres) as ``coinflight: warning: …`` on stderr, each once
    (:func:`coinflight.queries.plausibility.heard`; ``--json`` also carries them); other
    warnings as Python shows them."""
    from coinflight.queries.plausibility import heard

    with heard(lambda text: say(f"coinflight: warning: {text}")):
        yield


def os_error_line(exc: OSError) -> str:
    """The one line of an error of the operating system: ``PATH: reason`` (and the second
    path, for a rename), long paths shortened in their middle."""
    from coinflight._validation import shortened as shorten

    reason = exc.strerror or str(exc) or type(exc).__name__
    if exc.filename is None:
        return _one_line(reason)
    line = f"{shorten(os.fsdecode(exc.filename), 300)}: {reason}"
    if exc.filename2 is not None:
        line += f" ({shorten(os.fsdecode(exc.filename2), 300)})"
    return _one_line(line)


def _in_our_words(exc: Exception) -> None:
    """A text typer could not read as its option's type (typer reads through pydantic) in
    the words of :func:`coinflight._validation.unreadable`, those of the web too:
    ``'nan' is not a valid integer``, ``'-1' must be at least 1``, not pydantic's "Input should
    be a valid integer, unable to parse string as an integer"."""
    from coinflight._validation import unreadable

    errors = getattr(exc.__cause__, "errors", None)
    if not isinstance(exc, typer.BadParameter) or not callable(errors) or not errors():
        return
    reading = unreadable(errors()[0])
    if reading is not None:
        exc.message = reading


def _one_line(message: str) -> str:
    return " ".join(message.split())
