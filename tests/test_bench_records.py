"""The record every speed benchmark prints with ``--json`` (benchmarks/_record.py): its
provenance keys and values checked directly, then each script run end to end with its quickest
options (stdout the record alone, the text on stderr, figures as finite numbers). The runs of
bench_figures and bench_sweep take half a minute or more each: marked slow."""

from __future__ import annotations

import json
import math
import os
import platform
import subprocess
import sys
from datetime import UTC, datetime, timedelta
from typing import Any

import numba
import numpy as np
import pytest
import scipy

from _bench import bench_on_path, bench_script
from coinflight import __version__

bench_on_path()
import _record  # noqa: E402  (benchmarks/ is on the path only now)

KEYS = {"benchmark", "figures", "command", "date", "versions", "machine", "load"}


def _check_provenance(rec: dict[str, Any], name: str, args: list[str]) -> None:
    assert set(rec) == KEYS
    assert set(_record.PROVENANCE_KEYS) | {"figures"} == KEYS
    assert rec["benchmark"] == name
    assert rec["command"] == " ".join(["python", f"benchmarks/{name}.py", *args])
    when = datetime.fromisoformat(rec["date"])
    assert when.utcoffset() == timedelta(0)
    assert abs(datetime.now(UTC) - when) < timedelta(hours=1)
    versions = rec["versions"]
    assert versions["coinflight"] == __version__
    assert versions["python"] == platform.python_version()
    assert versions["numpy"] == np.__version__
    assert versions["numba"] == numba.__version__
    assert versions["scipy"] == scipy.__version__
    assert rec["machine"]["cpus"] == os.cpu_count()
    assert rec["machine"]["processor"]
    for when_ in ("before", "after"):
        load = rec["load"][when_]
        assert len(load) == 3 and all(math.isfinite(x) and x >= 0.0 for x in load)


def test_the_record_holds_the_figures_and_the_provenance(monkeypatch):
    monkeypatch.setattr(os, "getloadavg", lambda: (1.234, 2.0, 3.0))
    recorder = _record.Recorder("bench_air", ["--quick", "--old-src", "/a path/src"])
    monkeypatch.setattr(os, "getloadavg", lambda: (4.0, 5.0, 6.0))
    rec = recorder.record({"hand_tosses_per_s": 123.5})
    # The command quoted as a shell reads it: the space in the path stays one argument.
    _check_provenance(rec, "bench_air", ["--quick", "--old-src", "'/a path/src'"])
    assert rec["figures"] == {"hand_tosses_per_s": 123.5}
    assert rec["load"] == {"before": [1.23, 2.0, 3.0], "after": [4.0, 5.0, 6.0]}
    # The timing's own load and other packages' versions, when the script gives them.
    own = recorder.record({}, load={"before": (7.0, 7.0, 7.0), "after": (8.0, 8.0, 8.0)},
                          more_versions={"mujoco": None})  # fmt: skip
    assert own["load"] == {"before": [7.0, 7.0, 7.0], "after": [8.0, 8.0, 8.0]}
    assert own["versions"]["mujoco"] is None and own["versions"]["scipy"] == scipy.__version__
    assert json.loads(recorder.json({"μ": 0.3}))["figures"] == {"μ": 0.3}
    assert "μ" in recorder.json({"μ": 0.3})  # non-ASCII kept
    assert _record.key("rigid ending, each toss its own e, μ") == (
        "rigid_ending_each_toss_its_own_e_mu"
    )


def test_the_text_goes_to_stderr_with_json_only(capsys):
    recorder = _record.Recorder("bench_x", [])
    with recorder.text_to_stderr(True):
        print("text")
    with recorder.text_to_stderr(False):
        print("plain")
    out, err = capsys.readouterr()
    assert err == "text\n" and out == "plain\n"


def _run(name: str, args: list[str]) -> dict[str, Any]:
    env = dict(os.environ, NUMBA_NUM_THREADS="2")
    done = subprocess.run(
        [sys.executable, str(bench_script(name)), *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=900,
    )
    assert done.returncode == 0, done.stderr
    rec = json.loads(done.stdout)  # the record alone on stdout
    _check_provenance(rec, name, args)
    return rec


def _positive(x: object) -> bool:
    return isinstance(x, float) and math.isfinite(x) and x > 0.0


@pytest.mark.parametrize(
    ("name", "args", "figure"),
    [
        ("bench_flippers", ["--quick", "--json", "--repeats", "2"], "analyse_s"),
        (
            "bench_air",
            ["--json", "--n", "200", "--rest", "20", "--repeats", "1", "--reference", "1"],
            "air_table_to_rest_tosses_per_s",
        ),
        (
            "bench_bounce",
            ["--quick", "--n", "24", "--rounds", "1", "--json"],
            "human_to_rest_tosses_per_s",
        ),
        ("bench_targets", ["--json", "--n", "20", "--rounds", "1"], None),
        pytest.param("bench_figures", ["--quick", "--json"], "paper_s", marks=pytest.mark.slow),
        ("bench_probability", ["--accuracy", "--json"], "warm_up_s"),
        pytest.param("bench_sweep", ["--quick", "--json"], "speed_up", marks=pytest.mark.slow),
    ],
)
def test_each_script_prints_its_record(name, args, figure):
    rec = _run(name, args)
    figures = rec["figures"]
    if figure is not None:
        assert _positive(figures[figure]), figures
    if name == "bench_targets":
        assert [r["n"] for r in figures["targets"]] == [20] * 7
        assert all(_positive(r["measured"]) for r in figures["targets"])
        assert set(rec["versions"]) >= {"mujoco"}
    if name == "bench_bounce":
        from coinflight.studies import mujoco_compare

        assert figures["to_rest_target_tosses_per_s"] == 20_000.0
        assert figures["first_contact_target_tosses_per_s"] == 2e6
        assert figures["tosses"] == 24 and figures["first_contact_tosses"] == 200_000
        for kind in ("vigorous", "human"):
            assert _positive(figures[f"{kind}_first_contact_tosses_per_s"])
            if mujoco_compare.available():  # on 16 of the same tosses
                assert figures[f"{kind}_mujoco_tosses"] == 16
                assert _positive(figures[f"{kind}_speed_ratio"])
                assert figures[f"{kind}_speed_ratio"] == pytest.approx(
                    figures[f"{kind}_to_rest_tosses_per_s"]
                    / figures[f"{kind}_mujoco_tosses_per_s"],
                    rel=1e-12,
                )
    if name == "bench_air":
        assert figures["tosses"] == 200 and figures["rest_tosses"] == 20
    if name == "bench_probability":
        acc = figures["time_to_accuracy"]
        assert len(acc) == 5 and all(_positive(row["exact_ms"]) for row in acc.values())
    if name == "bench_sweep":
        assert figures["rows"] == 200 and figures["speed_up_target"] == 2.0


def test_json_is_refused_in_one_line_where_no_record_is_made():
    env = dict(os.environ, NUMBA_NUM_THREADS="2")
    for name, args in (("bench_air", ["--profile", "10", "--json"]),):  # fmt: skip
        done = subprocess.run(
            [sys.executable, str(bench_script(name)), *args],
            capture_output=True,
            text=True,
            env=env,
            timeout=300,
        )
        assert done.returncode == 2 and done.stdout == ""
        assert done.stderr.count("\n") == 1 and "--json records the default run" in done.stderr
