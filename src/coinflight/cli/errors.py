"""One clear line on stderr and exit code 2 for every bad input, never a traceback."""

from __future__ import annotations

import os
import sys
from collections.abc import Sequence
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


def _one_line(message: str) -> str:
    return " ".join(message.split())
