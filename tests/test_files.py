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
        (["plot", "basin", "--resolution", "8"], "coinflight.studies.basin", "basin_map"),
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


# --- one output path: every target checked before any is replaced (issue 10 item 2) ---


def test_replacing_all_replaces_none_when_one_target_is_a_folder(tmp_path):
    from coinflight._files import replacing_all

    (tmp_path / "x.csv").write_text("old")
    (tmp_path / "x.svg").mkdir()
    targets = [tmp_path / "x.csv", tmp_path / "x.json", tmp_path / "x.svg"]
    with (
        pytest.raises(ValueError, match=r"cannot write .*x\.svg: it is a folder"),
        replacing_all(targets) as temps,
    ):
        for tmp in temps:
            tmp.write_text("new")
    assert (tmp_path / "x.csv").read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.csv", "x.svg"]  # no staging left


def test_replacing_all_moves_every_file_at_the_end(tmp_path):
    from coinflight._files import replacing_all

    targets = [tmp_path / "x.csv", tmp_path / "sub" / "x.png"]
    with replacing_all(targets) as temps:
        for tmp in temps:
            tmp.write_text(tmp.name)
        assert not any(t.exists() for t in targets)  # nothing visible before the end
    assert [t.read_text() for t in targets] == ["x.csv", "x.png"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sub", "x.csv"]


def test_staged_folder_moves_nothing_when_a_file_cannot_replace_a_folder(tmp_path):
    from coinflight._files import staged_folder

    out = tmp_path / "paper"
    (out / "report.md").mkdir(parents=True)
    (out / "fig2a.png").write_text("old")
    with (
        pytest.raises(ValueError, match=r"cannot write .*report\.md: it is a folder"),
        staged_folder(out) as stage,
    ):
        write_text(stage / "fig2a.png", "new")
        write_text(stage / "report.md", "new")
    assert (out / "fig2a.png").read_text() == "old"
    assert sorted(p.name for p in out.iterdir()) == ["fig2a.png", "report.md"]


@pytest.mark.parametrize("name", ["", " ", ".", "..", "out/.", "out/"])
def test_a_path_naming_no_file_is_refused(tmp_path, name):
    from coinflight._files import check_name, check_writable

    with pytest.raises(ValueError, match=r"^cannot write .*(empty|it is a folder; give a file)"):
        check_name(name)
    with pytest.raises(ValueError, match=r"^cannot write "):
        check_writable(name)
    with pytest.raises(ValueError, match=r"^cannot write "), replacing(name):
        pass


def _dead_pid() -> int:
    import subprocess
    import sys

    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def _stage(folder, pid, tail="abcdefgh", marker=True):
    """A staging folder as _new_stage makes it (or, ``marker=False``, one named like it)."""
    from coinflight._files import _MARKER_TEXT, STAGE_MARKER, STAGE_PREFIX

    stage = folder / f"{STAGE_PREFIX}{pid}-{tail}"
    (stage / "files").mkdir(parents=True)
    (stage / "files" / "half.png").write_text("x")
    if marker:
        (stage / STAGE_MARKER).write_text(_MARKER_TEXT.format(name=stage.name))
    return stage


def test_stale_staging_folders_are_removed_live_ones_kept(tmp_path):
    import os
    import time

    from coinflight._files import STALE_AFTER, remove_stale_stages

    dead = _stage(tmp_path, _dead_pid(), "abc_1234")
    live = _stage(tmp_path, os.getpid(), "def_1234")
    old = _stage(tmp_path, os.getppid(), "ghi_1234")  # a running process, but long untouched
    long_ago = time.time() - STALE_AFTER - 60
    os.utime(old, (long_ago, long_ago))
    assert sorted(remove_stale_stages(tmp_path)) == sorted([dead, old])
    assert sorted(p.name for p in tmp_path.iterdir()) == [live.name]


def test_only_staging_folders_we_wrote_are_ever_removed(tmp_path):
    """Issue: writing pd/x.png deleted the user's pd/.partial-4000001-mythesis/ and a 3-day-old
    pd/.partial-notes/. Nothing without our exact name and our marker goes, however old and
    whatever process id it names; a link is never followed."""
    import os
    import time

    from typer.testing import CliRunner

    from coinflight._files import _MARKER_TEXT, STAGE_MARKER, STAGE_PREFIX, remove_stale_stages
    from coinflight.cli import app

    dead = _dead_pid()
    long_ago = time.time() - 3 * 24 * 3600
    users = []
    for name in (f".partial-{dead}-mythesis", ".partial-notes", f"{STAGE_PREFIX}notes"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "chapter.tex").write_text("years of work")
        users.append(tmp_path / name)
    # named like ours, but no marker; a marker with other words; a marker that is a link
    users.append(_stage(tmp_path, dead, "nomarker", marker=False))
    wrong = _stage(tmp_path, dead, "wrongtxt", marker=False)
    (wrong / STAGE_MARKER).write_text("my own notes\n")
    linked = _stage(tmp_path, dead, "linkmark", marker=False)
    elsewhere = tmp_path / "elsewhere.txt"
    elsewhere.write_text(_MARKER_TEXT.format(name=linked.name))
    (linked / STAGE_MARKER).symlink_to(elsewhere)
    users += [wrong, linked]
    # a link named like a stage, to a folder that has the marker: the folder stays
    outside = tmp_path.parent / f"{tmp_path.name}-outside"
    target = _stage(outside, dead, "target12")
    link = tmp_path / f"{STAGE_PREFIX}{dead}-symlink1"
    link.symlink_to(target, target_is_directory=True)
    users.append(link)
    for folder in users:
        os.utime(folder, (long_ago, long_ago), follow_symlinks=False)
    assert remove_stale_stages(tmp_path) == []
    out = tmp_path / "x.png"
    result = CliRunner().invoke(app, ["plot", "toss", "--flight-time", "0.5", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert out.exists()
    for folder in users:
        assert folder.is_symlink() or folder.is_dir(), folder
    for name in (f".partial-{dead}-mythesis", ".partial-notes", f"{STAGE_PREFIX}notes"):
        assert (tmp_path / name / "chapter.tex").read_text() == "years of work"
    assert (target / "files" / "half.png").exists() and elsewhere.exists()
    names = {p.name for p in tmp_path.iterdir()}
    assert names == {p.name for p in users} | {"x.png", "elsewhere.txt"}  # none of ours left


def test_a_later_run_removes_what_a_killed_run_left(tmp_path):
    """SIGKILL skips every clean-up: the staging folder stays, until the next run writing there."""
    import os
    import subprocess
    import sys

    from typer.testing import CliRunner

    from coinflight.cli import app

    code = (
        "import os, signal, sys\n"
        "from coinflight._files import staged_folder\n"
        "with staged_folder(sys.argv[1]) as stage:\n"
        "    (stage / 'fig.png').write_text('half')\n"
        "    os.kill(os.getpid(), signal.SIGKILL)\n"
    )
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).parents[1] / "src")}
    killed = subprocess.run([sys.executable, "-c", code, str(tmp_path)], env=env, check=False)
    assert killed.returncode == -9
    left = list(tmp_path.glob(".coinflight-partial-*"))
    assert len(left) == 1 and (left[0] / "files" / "fig.png").exists()
    out = tmp_path / "toss.png"
    result = CliRunner().invoke(app, ["plot", "toss", "--flight-time", "0.5", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["toss.png"]


CONVERGENCE = ["convergence", "--flight-time", "0.6:0.9", "--grid-sizes", "5", "--event-sizes"]


def test_convergence_writes_its_four_files_together_or_none(tmp_path, monkeypatch):
    from typer.testing import CliRunner

    import coinflight.plotting.style as style
    from coinflight.cli import app

    (tmp_path / "x.csv").write_text("old")
    real_savefig = style.save_figure

    def svg_fails(fig, path, *args, **kwargs):
        if str(path).endswith(".svg"):
            raise KeyboardInterrupt  # Ctrl-C while the last file is written
        return real_savefig(fig, path, *args, **kwargs)

    monkeypatch.setattr(style, "save_figure", svg_fails)
    argv = [*CONVERGENCE, "100", "--seed", "1", "-q", "--out", str(tmp_path / "x")]
    result = CliRunner().invoke(app, argv)
    assert (result.exit_code, result.stderr) == (130, "coinflight: interrupted\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.csv"]
    assert (tmp_path / "x.csv").read_text() == "old"

    monkeypatch.setattr(style, "save_figure", real_savefig)
    result = CliRunner().invoke(app, argv)
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.csv", "x.json", "x.png", "x.svg"]


@pytest.mark.parametrize(
    ("argv", "module", "name"),
    [
        ([*CONVERGENCE, "100"], "coinflight.probability.convergence", "convergence"),
        (["paper", "-q"], "coinflight.report.reproduce", "paper_numbers"),
    ],
)
def test_a_folder_in_the_place_of_an_output_file_fails_before_computing(
    tmp_path, monkeypatch, argv, module, name
):
    import importlib

    from typer.testing import CliRunner

    from coinflight.cli import app

    monkeypatch.setattr(importlib.import_module(module), name, _refuse)
    if argv[0] == "paper":
        out, folder = tmp_path, tmp_path / "report.md"
    else:
        out, folder = tmp_path / "x", tmp_path / "x.svg"
    folder.mkdir()
    result = CliRunner().invoke(app, [*argv, "--out", str(out)])
    assert (result.exit_code, result.stderr) == (
        2,
        f"coinflight: error: cannot write {folder}: it is a folder\n",
    )
    assert [p.name for p in tmp_path.iterdir()] == [folder.name]


@pytest.mark.parametrize(
    "argv",
    [
        ["paper", "-q"],
        [*CONVERGENCE, "100"],
        ["plot", "toss", "--flight-time", "0.5"],
        ["plot", "basin", "--resolution", "8"],
        ["plot", "bias"],
        ["plot", "edge"],
        ["animate", "--flight-time", "0.5"],
        ["data", "--counts", "counts.txt", "--plot"],
    ],
)
def test_an_empty_output_path_is_refused(tmp_path, monkeypatch, argv):
    """`--out ''` is not the current folder (Path('') is '.'): one line naming the option."""
    from typer.testing import CliRunner

    from coinflight.cli import app

    monkeypatch.chdir(tmp_path)
    flag = [] if argv[-1] == "--plot" else ["--out"]
    result = CliRunner().invoke(app, [*argv, *flag, ""])
    assert result.exit_code == 2, result.output
    assert result.stderr.count("\n") == 1
    # refused by the command line's rule for empty values (cli.errors), naming the option;
    # _files' own check ("cannot write '': the path is empty") stands behind it for the library
    assert f"{flag[0] if flag else argv[-1]} was given an empty value ''" in result.stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("out", [".", "..", "sub/.", "sub/"])
def test_a_figure_path_naming_a_folder_is_one_line(tmp_path, monkeypatch, out):
    """Not "PosixPath('.') has an empty name", nor a file sub.png for sub/."""
    from typer.testing import CliRunner

    from coinflight.cli import app

    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, ["plot", "toss", "--flight-time", "0.5", "--out", out])
    assert result.exit_code == 2, result.output
    assert result.stderr.endswith(f": cannot write {out}: it is a folder; give a file name\n")
    assert result.stderr.startswith("coinflight: error: Invalid value for '--out'")
    assert list(tmp_path.iterdir()) == []


def test_missing_folders_are_created(tmp_path):
    from typer.testing import CliRunner

    from coinflight.cli import app

    out = tmp_path / "a" / "b" / "toss.svg"
    result = CliRunner().invoke(app, ["plot", "toss", "--flight-time", "0.5", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert out.is_file()
    assert [p.name for p in out.parent.iterdir()] == ["toss.svg"]


def test_convergence_out_naming_a_folder_writes_into_it(tmp_path):
    from typer.testing import CliRunner

    from coinflight.cli import app

    argv = [*CONVERGENCE, "100", "--seed", "1", "-q", "--out", f"{tmp_path / 'new'}/"]
    result = CliRunner().invoke(app, argv)
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in (tmp_path / "new").iterdir()) == [
        f"convergence.{ext}" for ext in ("csv", "json", "png", "svg")
    ]


def test_a_device_or_pipe_is_never_replaced(tmp_path):
    import os

    from coinflight._files import check_writable

    fifo = tmp_path / "pipe.png"
    os.mkfifo(fifo)
    for attempt in (check_writable, lambda p: write_text(p, "x")):
        with pytest.raises(ValueError, match="it is not a regular file"):
            attempt(fifo)
    assert fifo.is_fifo()
    assert [p.name for p in tmp_path.iterdir()] == ["pipe.png"]


@pytest.mark.parametrize("folder", [False, True])
def test_the_library_refuses_an_empty_path_itself(folder):
    """Behind the command line's empty-value rule, the library's own check of a path."""
    from coinflight._files import check_name

    what = "a folder" if folder else "a file"
    with pytest.raises(ValueError, match=f"cannot write '': the path is empty; give {what}"):
        check_name("", folder=folder)
