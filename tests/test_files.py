"""Outputs are written whole or not at all."""

from __future__ import annotations

import stat

import pytest

from coinflight._files import replacing, write_text


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
