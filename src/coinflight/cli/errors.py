"""One clear line on stderr and exit code 2 for every bad input, never a traceback."""

from __future__ import annotations

import os
import sys
import warnings
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

import typer
from typer.core import TyperGroup

USAGE_ERROR = 2


def fail(message: str, code: int = USAGE_ERROR) -> None:
    """Print ``coinflight: error: message`` on stderr and exit with ``code``."""
    typer.echo(f"coinflight: error: {message}", err=True)
    sys.exit(code)


class OneLineErrors(TyperGroup):
    """A typer group whose errors are one line on stderr.

    Typer's usage errors (unknown option, malformed number) and the library's ``ValueError`` /
    ``TypeError`` (a value outside its allowed range) both end as ``coinflight: error: …`` with
    exit code 2. Set ``COINFLIGHT_DEBUG=1`` to see the traceback of a library error instead.
    """

    def main(  # type: ignore[override]
        self,
        args: Sequence[str] | None = None,
        prog_name: str | None = None,
        complete_var: str | None = None,
        standalone_mode: bool = True,
        **extra: Any,
    ) -> Any:
        try:
            with one_line_warnings():
                rv = super().main(
                    args=args,
                    prog_name=prog_name,
                    complete_var=complete_var,
                    standalone_mode=False,
                    **extra,
                )
        except typer.TyperException as exc:
            fail(_one_line(exc.format_message()), exc.exit_code)
        except typer.Abort:
            fail("aborted", 1)
        except KeyboardInterrupt:
            fail("interrupted", 130)
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
                typer.echo(f"coinflight: warning: {text}", err=True)

        warnings.showwarning = show
        yield


def _one_line(message: str) -> str:
    return " ".join(message.split())
