"""Help as written and in a useful order (:func:`tidy_help`, applied once to the command tree).

- typer renders help with rich, whose markup reads ``[...]`` as a style tag: the source's
  ``pip install "coinflight[dask]"`` would print as ``pip install "coinflight"``. No help text
  of coinflight uses rich markup, so every one (each command's help, short help and epilog,
  each option's help) is escaped.
- Options in the panels of rarely used ones (:data:`~coinflight.cli.options.LATER_PANELS`)
  are listed after the others, so that the common options fit a screen.
"""

from __future__ import annotations

from typing import Any

from rich.markup import escape

from coinflight.cli.options import LATER_PANELS

_DONE = "_coinflight_help_tidied"


def tidy_help(command: Any) -> None:
    """Escape rich markup in the help of ``command``, its options and every subcommand, so
    that ``--help`` prints what the source says, and list the options of the later panels
    last; in place, each command once (a second escape would show the backslashes).
    ``command``: a command of the click that typer carries with it."""
    if getattr(command, _DONE, False):
        return
    setattr(command, _DONE, True)
    for attribute in ("help", "short_help", "epilog"):
        text = getattr(command, attribute, None)
        if text:
            setattr(command, attribute, escape(text))
    for param in command.params:
        text = getattr(param, "help", None)
        if text:
            param.help = escape(text)
    command.params.sort(key=_later)  # stable: the source's order within each part
    for sub in getattr(command, "commands", {}).values():  # typer's groups are no click.Group
        tidy_help(sub)


def _later(param: Any) -> int:
    panel = getattr(param, "rich_help_panel", None)
    return LATER_PANELS.index(panel) + 1 if panel in LATER_PANELS else 0
