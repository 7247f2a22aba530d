"""Outputs are written whole or not at all."""

from __future__ import annotations

import stat
from importlib.resources import files
from pathlib import Path

import pytest

from coinflight._files import replacing, write_text

# The counts of Bartoš et al. shipped inside the package (coinflight.datasets), nothing outside.
BARTOS = Path(str(files("coinflight.datasets") / "bartos2023.txt"))


def test_write_text_creates_folders_and_readable_file(tmp_path):
    path = write_text(tmp_path / "a" / "b" / "report.md", "héllo\n")
    assert path.read_text(encoding="utf-8") == "héllo\n"
    assert stat.S_IMODE(path.stat().st_mode) == 0o644
    assert [p.name for p in path.parent.iterdir()] == ["report.md"]


def test_failure_leaves_the_old_file_and_no_temporary(tmp_path):
    target = tmp_path / "figure.png"
    target.write_bytes(b"old")
    with pytest.raises(RuntimeError, match="interrupted"), replacing(target) as tmp:
        tmp.write_bytes(b"half")
        raise RuntimeError("interrupted")
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["figure.png"]


def test_staged_folder_moves_all_files_or_none(tmp_path):
    from coinflight._files import staged_folder

    out = tmp_path / "paper"
    with staged_folder(out) as stage:
        write_text(stage / "a.md", "a")
        write_text(stage / "sub" / "b.md", "b")
        assert list(out.glob("*.md")) == []  # nothing visible before the end
    assert (out / "a.md").read_text() == "a"
    assert (out / "sub" / "b.md").read_text() == "b"
    assert sorted(p.name for p in out.iterdir()) == ["a.md", "sub"]

    failed = tmp_path / "failed"
    with pytest.raises(KeyboardInterrupt), staged_folder(failed) as stage:
        write_text(stage / "a.md", "a")
        raise KeyboardInterrupt
    assert list(failed.iterdir()) == []


def test_unwritable_paths_are_value_errors_naming_the_path(tmp_path):
    from coinflight._files import check_writable, staged_folder

    blocker = tmp_path / "afile"
    blocker.write_text("x")
    for path in (blocker / "x.png", blocker / "sub" / "x.png"):
        with pytest.raises(ValueError, match=r"cannot write .*afile is a file, not a folder"):
            write_text(path, "a")
        with pytest.raises(ValueError, match="afile is a file, not a folder"):
            check_writable(path)
    folder_error = pytest.raises(ValueError, match=r"cannot write .*afile/paper: .*afile is a file")
    with folder_error, staged_folder(blocker / "paper"):
        pass
    with pytest.raises(ValueError, match="it is a file, not a folder"):
        check_writable(blocker, folder=True)
    with pytest.raises(ValueError, match="it is a folder"):
        check_writable(tmp_path)
    # A writable place passes and is left as it was.
    check_writable(tmp_path / "new" / "x.png")
    check_writable(tmp_path / "new", folder=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


def _refuse(*_args, **_kwargs):
    raise AssertionError("computed before checking the output location")


@pytest.mark.parametrize(
    ("argv", "module", "name"),
    [
        (["plot", "basin", "--resolution", "8"], "coinflight.plotting.basin", "basin_map"),
        (["animate", "--flight-time", "0.5"], "coinflight.plotting.animation", "animate_toss"),
        (["paper", "-q"], "coinflight.report.reproduce", "reproduce_paper"),
    ],
)
def test_long_commands_check_the_output_before_computing(tmp_path, monkeypatch, argv, module, name):
    import importlib

    from typer.testing import CliRunner

    from coinflight.cli import app

    monkeypatch.setattr(importlib.import_module(module), name, _refuse)
    blocker = tmp_path / "afile"
    blocker.write_text("x")
    suffix = "" if argv[0] == "paper" else (".gif" if argv[0] == "animate" else ".png")
    out = blocker / f"out{suffix}"
    result = CliRunner().invoke(app, [*argv, "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert (
        result.stderr
        == f"coinflight: error: cannot write {out}: {blocker} is a file, not a folder\n"
    )


@pytest.mark.parametrize(
    "argv",
    [
        ["plot", "bias", "--out"],
        ["plot", "toss", "--flight-time", "0.5", "--out"],
        ["data", "--counts", str(BARTOS), "--plot"],
    ],
)
def test_unwritable_figure_is_one_line_and_exit_2(tmp_path, argv):
    from typer.testing import CliRunner

    from coinflight.cli import app

    blocker = tmp_path / "afile"
    blocker.write_text("x")
    result = CliRunner().invoke(app, [*argv, str(blocker / "x.png")])
    assert result.exit_code == 2, result.output
    assert result.stderr.startswith("coinflight: error: cannot write ")
    assert "Traceback" not in result.output
