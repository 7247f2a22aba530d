"""Writing output files whole or not at all: the one place that does it.

Every output goes the same way: its files are first written into a hidden *staging folder*
(``.coinflight-partial-<pid>-<random>``, holding a marker file that says so) in the folder they
belong to, then renamed into place, all of them at the end, so that a reader sees every file of
a run or none of them:

- the targets are checked before anything is renamed (not a folder, a folder that can be
  written), so a target that cannot be replaced leaves every other one as it was;
- on any error, Ctrl-C included, the staging folder is removed and nothing is replaced;
- missing folders on the way to a target are created;
- a staging folder left by a run that was killed outright (SIGKILL, a power cut) is removed by
  the next run writing into the same folder when the process that made it is no longer running
  on this machine, or when it is older than :data:`STALE_AFTER` seconds; only a folder that is
  ours by construction is ever removed: its exact name, not a symbolic link, owned by this
  user, with the marker coinflight wrote in it (:func:`remove_stale_stages`).
"""

from __future__ import annotations

import os
import re
import shutil
import stat
import tempfile
import time
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path

STAGE_PREFIX = ".coinflight-partial-"
"""Name prefix of staging folders: ``.coinflight-partial-<pid>-<random>``."""
STAGE_MARKER = ".coinflight-stage"
"""The marker file in each staging folder; the staged files are in its ``files`` folder."""
_MARKER_TEXT = "coinflight staging folder {name}: removed when its run ends\n"
_STAGE_NAME = re.compile(re.escape(STAGE_PREFIX) + r"(\d{1,10})-[a-z0-9_]{8}")
STALE_AFTER = 24 * 3600.0
"""Seconds after which any staging folder is stale, whatever its process (writing takes
seconds; this bounds what a reused process id can keep alive)."""


@contextmanager
def replacing_all(paths: Iterable[str | os.PathLike[str]]) -> Iterator[list[Path]]:
    """Temporary files that become ``paths``, all of them, when the block succeeds.

    The caller writes each yielded path (same order, same file names, inside a staging folder
    beside its target); at the end every target is checked, then all are renamed into place.
    On any error, or if a target cannot be replaced, none is and the staging is removed.
    """
    targets = [Path(p) for p in paths]
    for target in targets:
        check_name(target)
    if len({t.absolute() for t in targets}) != len(targets):
        raise ValueError(f"cannot write {', '.join(map(str, targets))}: a file named twice")
    stages: dict[Path, Path] = {}
    try:
        temps = []
        for target in targets:
            folder = target.parent
            if folder not in stages:
                stages[folder] = _new_stage(folder, target)
            temps.append(stages[folder] / "files" / target.name)
        yield temps
        _swap(list(zip(temps, targets, strict=True)))
    finally:
        for stage in stages.values():
            shutil.rmtree(stage, ignore_errors=True)


@contextmanager
def replacing(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary file that becomes ``path`` when the block succeeds (see :func:`replacing_all`).

    An interrupted run therefore never leaves a half-written file, nor replaces a good one
    with it.
    """
    with replacing_all([path]) as (tmp,):
        yield tmp


def write_text(path: str | os.PathLike[str], text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all."""
    with replacing(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


@contextmanager
def staged_folder(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A staging folder inside ``path`` whose files all move into ``path`` when the block succeeds.

    For outputs made of several files (a report and its figures): they appear together at the
    end, or, if the run fails or is interrupted, or one of them cannot replace what is in its
    place (a folder of that name), none of them does.
    """
    target = Path(path)
    check_name(target, folder=True)
    stage = _new_stage(target, target, folder_target=True)
    files = stage / "files"
    try:
        yield files
        moves = [
            (item, target / item.relative_to(files))
            for item in sorted(files.rglob("*"))
            if item.is_file()
        ]
        _swap(moves)
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def _new_stage(folder: Path, target: Path, folder_target: bool = False) -> Path:
    """A new staging folder in ``folder`` (created if missing), after removing stale ones."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        remove_stale_stages(folder)
        stage = Path(tempfile.mkdtemp(prefix=f"{STAGE_PREFIX}{os.getpid()}-", dir=folder))
        (stage / STAGE_MARKER).write_text(_MARKER_TEXT.format(name=stage.name), encoding="utf-8")
        (stage / "files").mkdir()
        return stage
    except OSError as exc:
        check_writable(target, folder=folder_target)  # names a file in the way, if that is it
        raise cannot_write(target, exc) from None


def _swap(moves: list[tuple[Path, Path]]) -> None:
    """Rename each staged file onto its target: every target checked first, then all moved."""
    for _, dest in moves:
        try:
            _check_target(dest)
        except OSError as exc:
            raise cannot_write(dest, exc) from None
    for tmp, dest in moves:
        try:
            dest.parent.mkdir(parents=True, exist_ok=True)
            os.replace(tmp, dest)
        except OSError as exc:
            raise cannot_write(dest, exc) from None


def _check_target(dest: Path) -> None:
    if dest.is_dir():
        raise ValueError(f"cannot write {dest}: it is a folder")
    _check_replaceable(dest)
    for parent in reversed(dest.parents):
        if parent.exists() and not parent.is_dir():
            raise ValueError(f"cannot write {dest}: {parent} is a file, not a folder")


def _check_replaceable(dest: Path) -> None:
    """A device, pipe or socket is never replaced by a file (``--out /dev/null`` as root would
    otherwise remove the device)."""
    if dest.exists() and not dest.is_file() and not dest.is_dir():
        raise ValueError(
            f"cannot write {dest}: it is not a regular file (a device, pipe or socket); "
            "give a file name"
        )


def remove_stale_stages(folder: str | os.PathLike[str]) -> list[Path]:
    """Remove the staging folders in ``folder`` that no running process will finish.

    A folder is removed only when it is ours by construction: named exactly
    ``.coinflight-partial-<pid>-<8 characters>``, a folder and not a symbolic link, owned by
    this user, and holding the marker file coinflight wrote in it (:data:`STAGE_MARKER`, a
    regular file with its words); and stale: no process ``pid`` runs on this machine, or it
    was last modified more than :data:`STALE_AFTER` seconds ago. Anything else (a user's
    ``.partial-notes``, a folder named like ours without the marker) is left alone. Returns
    the folders removed. Errors (a folder that cannot be listed or removed) are ignored:
    cleaning up never stops a run.
    """
    removed: list[Path] = []
    try:
        candidates = list(Path(folder).glob(STAGE_PREFIX + "*"))
    except OSError:
        return removed
    now = time.time()
    for stage in candidates:
        match = _STAGE_NAME.fullmatch(stage.name)
        if match is None:
            continue
        try:
            info = stage.lstat()
            if not stat.S_ISDIR(info.st_mode) or info.st_uid != os.getuid():
                continue
            if not _is_marked(stage):
                continue
        except OSError:
            continue
        if not _running(int(match.group(1))) or now - info.st_mtime > STALE_AFTER:
            shutil.rmtree(stage, ignore_errors=True)  # never follows links (os.open/unlinkat)
            removed.append(stage)
    return removed


def _is_marked(stage: Path) -> bool:
    """True when ``stage`` holds the marker :func:`_new_stage` wrote (read without following a
    link)."""
    marker = stage / STAGE_MARKER
    if not stat.S_ISREG(marker.lstat().st_mode):
        return False
    expected = _MARKER_TEXT.format(name=stage.name).encode("utf-8")
    fd = os.open(marker, os.O_RDONLY | os.O_NOFOLLOW)
    with os.fdopen(fd, "rb") as f:
        return f.read(len(expected) + 1) == expected


def _running(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError):
        return True  # someone else's process, or a number we cannot ask about: keep it
    return True


def cannot_write(path: str | os.PathLike[str], exc: OSError) -> ValueError:
    """The one wording of an output that cannot be written: ``cannot write PATH: reason``."""
    reason = exc.strerror or str(exc)
    name = None if exc.filename is None else os.fspath(exc.filename)
    ours = STAGE_PREFIX in (name or "") or Path(name or "").name.startswith(".")
    if name is not None and name != os.fspath(path) and not ours:
        reason = f"{reason} ({name})"  # a folder on the way, not our temporary file
    return ValueError(f"cannot write {os.fspath(path)}: {reason}")


def names_folder(path: str | os.PathLike[str]) -> bool:
    """True when the text of ``path`` can only name a folder: it ends in a separator, ``.`` or
    ``..`` (``Path("out/")`` and ``Path("out/.")`` lose this: pass the user's text)."""
    text = os.fspath(path)
    last = text.replace(os.sep, "/").rsplit("/", 1)[-1]
    return last in ("", ".", "..")


def check_name(path: str | os.PathLike[str], folder: bool = False) -> None:
    """ValueError for a path that names no file: empty, or ending in ``/``, ``.`` or ``..``.

    ``folder=True`` accepts a folder's name (``.``, ``out/``) but not an empty path.
    """
    text = os.fspath(path)
    if not text.strip():
        what = "a folder" if folder else "a file"
        raise ValueError(f"cannot write {text!r}: the path is empty; give {what}")
    if not folder and names_folder(text):
        raise ValueError(f"cannot write {text}: it is a folder; give a file name")


def check_writable(path: str | os.PathLike[str], folder: bool = False) -> None:
    """ValueError unless ``path`` (a file, or a folder if ``folder``) can be written.

    For commands that compute for a long time before they write: they call this first, so a
    bad output location fails at once. The check creates nothing that stays: it makes and
    removes one temporary file in the nearest folder that already exists.
    """
    check_name(path, folder)
    try:
        _check_writable(Path(path), folder)
    except OSError as exc:  # a name over the system's limit, a folder that cannot be read
        raise cannot_write(path, exc) from None


def _check_writable(target: Path, folder: bool) -> None:
    if target.exists():
        if folder and not target.is_dir():
            raise ValueError(f"cannot write {target}: it is a file, not a folder")
        if not folder and target.is_dir():
            raise ValueError(f"cannot write {target}: it is a folder")
        if not folder:
            _check_replaceable(target)
    base = target if folder else target.parent
    while not base.exists() and base != base.parent:
        base = base.parent
    if not base.is_dir():
        raise ValueError(f"cannot write {target}: {base} is a file, not a folder")
    try:
        fd, tmp = tempfile.mkstemp(prefix=".coinflight-check-", dir=base)
    except OSError as exc:
        raise cannot_write(target, exc) from None
    os.close(fd)
    os.unlink(tmp)


def check_all_writable(paths: Iterable[str | os.PathLike[str]]) -> list[Path]:
    """:func:`check_writable` for each of ``paths`` (the files of one output); returns them."""
    checked = [Path(p) for p in paths]
    for p in checked:
        check_writable(p)
    return checked
