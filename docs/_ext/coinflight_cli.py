"""The command-line reference page, generated from the commands at build time.

Typer's own documentation generator (``typer coinflight.cli.app utils docs``) walks the
command tree and writes Markdown (read by MyST); nothing is written by hand, so the page lists
exactly what ``coinflight COMMAND --help`` shows.
"""

from __future__ import annotations

from pathlib import Path

import typer
import typer.main
from typer.cli import get_docs_for_click

from coinflight.cli import app

PREAMBLE = """\
(cli)=

# Command-line reference

Generated from the commands themselves when this site is built (Typer's documentation
generator), so it lists exactly the options `coinflight COMMAND --help` shows. Units are SI
(rad/s, s, m, kg) unless an option says degrees. Bad input gets one line
`coinflight: error: …` on stderr and exit code 2. The symbols the commands print are defined
in the [glossary](glossary.rst); `--json` output keys are named after them.

"""


def cli_markdown() -> str:
    """The reference as Markdown, one section per command, the program itself at the top."""
    command = typer.main.get_command(app)
    ctx = typer.Context(command, info_name="coinflight")
    body = get_docs_for_click(obj=command, ctx=ctx, name="coinflight", title="coinflight")
    # Typer writes "# `coinflight`" as the top heading: push every heading one level down
    # so the page has one title, and let the program's section follow the preamble.
    lines = [("#" + line) if line.startswith("#") else line for line in body.splitlines()]
    return PREAMBLE + "\n".join(lines).strip() + "\n"


def write_cli_page(path: Path) -> None:
    """Write the page only when it changed (Sphinx then re-reads it only when needed)."""
    text = cli_markdown()
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
