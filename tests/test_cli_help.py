"""``--help`` shows what the source says: the install extras' brackets, each command's
one-line description whole, the rarely used options after the common ones."""

from __future__ import annotations

import inspect
import re
import typing

import pytest
from typer.models import OptionInfo
from typer.testing import CliRunner

from coinflight.cli import app
from coinflight.cli.options import LATER_PANELS
from coinflight.cli.plot import plot_app

runner = CliRunner()
WIDE = {"COLUMNS": "2000"}  # no wrapping: a help text is one line of the table
BRACKETED = re.compile(r"\S*\[[^\]\n]+\]")  # coinflight[dask], [default: 60:90], ...


def _help(*path: str, env: dict[str, str] = WIDE) -> str:
    result = runner.invoke(app, [*path, "--help"], env=env)
    assert result.exit_code == 0, result.output
    return result.stdout


def _commands() -> list[tuple[tuple[str, ...], typing.Callable[..., None]]]:
    """(path, function) of every command, from the typer apps (the source, before click)."""
    found = []
    for info in app.registered_commands:
        found.append(((info.name,), info.callback))
    for info in plot_app.registered_commands:
        found.append((("plot", info.name), info.callback))
    return found


def _source_help(func: typing.Callable[..., None]) -> list[str]:
    """The docstring and every option's help of ``func`` as written in the source."""
    texts = [inspect.getdoc(func) or ""]
    for param in inspect.signature(func).parameters.values():
        for meta in getattr(param.annotation, "__metadata__", ()):
            if isinstance(meta, OptionInfo) and meta.help:
                texts.append(meta.help)
    return texts


def test_every_bracketed_word_of_the_source_is_shown():
    shown: set[str] = set()
    for path, func in _commands():
        words = {w for text in _source_help(func) for w in BRACKETED.findall(text)}
        if words:
            page = _help(*path)
            missing = sorted(w for w in words if w not in page)
            assert not missing, f"coinflight {' '.join(path)} --help drops {missing}"
            shown |= words
        assert "\\[" not in _help(*path)  # nothing escaped twice (a backslash shown)
    # the extras the help tells users to install (not a vacuous pass over no brackets)
    assert {'"coinflight[dask]', '"coinflight[parquet]'} <= shown


@pytest.mark.parametrize(
    ("command", "extra"),
    [
        ("sweep", "coinflight[parquet]"),
        ("sweep", "coinflight[dask]"),
        ("convergence", "coinflight[dask]"),
        ("probability", "coinflight[dask]"),
    ],
)
def test_the_install_extras_at_a_terminal_width(command, extra):
    assert f'pip install "{extra}"' in _help(command, env={"COLUMNS": "200"})


def test_every_command_has_a_whole_one_line_description():
    page = _help()
    for path, func in _commands():
        first = (inspect.getdoc(func) or "").split("\n\n")[0]
        assert "\n" not in first, f"{path}: the first paragraph is one line: {first!r}"
        assert first.endswith("."), first
        listing = page if len(path) == 1 else _help(path[0])
        assert first in listing, f"{path}: {first!r} not whole in the list"


@pytest.mark.parametrize("command", ["toss", "probability", "sweep", "edge", "convergence"])
def test_rarely_used_panels_come_last(command):
    page = _help(command)
    titles = re.findall(r"╭─ (.+?) ─", page)
    later = [t for t in titles if t in LATER_PANELS]
    assert later, titles  # each of these commands has rarely used options
    first_later = titles.index(later[0])
    assert all(t in LATER_PANELS for t in titles[first_later:]), titles
    assert later == [p for p in LATER_PANELS if p in later]


def test_the_common_options_of_toss_fit_a_screen():
    """At 100 columns the options of ``toss`` before the rarely used panels fit in 60 lines."""
    page = _help("toss", env={"COLUMNS": "100"})
    lines = page.splitlines()
    first_later = next(
        i for i, line in enumerate(lines) if any(f"─ {p} ─" in line for p in LATER_PANELS)
    )
    assert first_later <= 60, first_later
