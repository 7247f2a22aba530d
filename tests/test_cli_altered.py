"""Nothing a user typed is silently dropped or altered (issue: a hostile run's class 6).

An empty value read as the option left out (``plot basin --flight-time ''`` drew the default
map), an absurd count taken as given (``--threads 99999999999999999999``), an existing folder
given as an output file (``--out FOLDER`` wrote ``FOLDER.png`` beside it), an error about
another option than the one given (``--surface hand --bounces 2``: "Surface kind 'table'"),
pydantic's sentences instead of ours (``--seed nan``), a RuntimeWarning before the error line
(``bias --psi-dist normal:0,1e308``). Each is refused in one line before any work runs.
"""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from _cli import one_line_error
from _work import command_work, never_run
from coinflight.web.app import create_app

EMPTY_LINES = [
    ["plot", "basin", "--flight-time", ""],
    ["plot", "basin", "--flight-time="],
    ["plot", "basin", "-T", " "],
    ["plot", "basin", "--omega-x", ""],
    ["plot", "edge", "--ratios", ""],
    ["plot", "bias", "--psi-points", ""],
    ["probability", "--omega-x", "60:90", "--flight-time", "0.7", "--preset", ""],
    ["probability", "--omega-x", "60:90", "--flight-time", "0.7", "--coin", ""],
    ["probability", "--omega-x", "60:90", "--flight-time", "0.7", ""],
    ["bias", "--psi-dist", ""],
    ["toss", "--omega", "80", "0", "0", "--flight-time", "0.7", "--surface", ""],
    ["sweep", "--omega-x", "60:90", "--flight-time", "0.6:0.9", "--coin", "", "--out", "s.csv"],
    ["data", "--dataset", ""],
]


@pytest.mark.parametrize("args", EMPTY_LINES, ids=lambda a: " ".join(map(repr, a)))
def test_an_empty_value_is_refused_not_taken_as_the_default(args, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    never_run(monkeypatch, command_work())
    line = one_line_error(*args)
    assert "empty" in line and ("give a value" in line)
    assert not list(tmp_path.iterdir())  # nothing drawn, nothing written


def test_the_empty_value_names_its_option():
    assert one_line_error("plot", "basin", "--flight-time", "") == (
        "--flight-time was given an empty value ''; give a value, or leave --flight-time out "
        "for its default"
    )
    assert one_line_error("plot", "basin", "--flight-time=").startswith("--flight-time was given")


@pytest.mark.parametrize("count", ["99999999999999999999", "1025", "0"])
def test_an_absurd_thread_count_is_refused(count, monkeypatch):
    never_run(monkeypatch, command_work())
    line = one_line_error(
        "probability", "--omega-x", "60:90", "-T", "0.7", "--method", "monte-carlo",
        "--n", "1000", "--threads", count,
    )  # fmt: skip
    assert line == f"threads must be between 1 and 1024, got {count}"


def test_an_absurd_local_worker_count_is_refused():
    from coinflight.probability.distributed import check_scheduler

    with pytest.raises(ValueError, match=r"^workers must be between 1 and 256, got 10{20}$"):
        check_scheduler("local", 10**20)


@pytest.mark.parametrize(
    "args",
    [["plot", "basin"], ["plot", "toss", "--flight-time", "0.7"], ["plot", "edge"]],
    ids=" ".join,
)
def test_an_existing_folder_is_not_an_output_file(args, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "results").mkdir()
    never_run(monkeypatch, command_work())
    line = one_line_error(*args, "--out", "results")
    assert "'results' is an existing folder; give a file's name, such as 'results/figure.png'" in (
        line
    )
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results"]  # no results.png beside it


def test_a_table_option_with_the_hand_names_both():
    line = one_line_error("toss", "--omega", "80", "0", "0", "-T", "0.7", "--surface", "hand",
                          "--bounces", "2")  # fmt: skip
    assert line.startswith("--bounces applies to --surface table only")
    assert "not to a catch in the hand (--surface hand" in line
    assert "Surface kind" not in line


@pytest.mark.parametrize(
    "option, text, words",
    [
        ("--seed", "nan", "'nan' is not a valid integer"),
        ("--seed", "1e400", "'1e400' is not a valid integer"),
        ("--n", "1.5", "'1.5' is not a valid integer"),
    ],
)
def test_unreadable_counts_in_our_words_on_the_command_line_and_the_web(option, text, words):
    line = one_line_error(
        "probability", "--omega-x", "60:90", "-T", "0.7", "--method", "qmc", option, text
    )
    assert line.endswith(words) and "Input should be" not in line
    with TestClient(create_app(workers=1)) as client:
        got = client.get(
            "/api/probability",
            params={"omega_x": "60:90", "flight_time": "0.7", "method": "qmc", option[2:]: text},
        )
    assert got.status_code == 422
    assert got.json()["detail"] == f"Invalid value for '{option}': {words}"


def test_a_bound_of_typer_in_our_words():
    line = one_line_error("bias", "--psi", "80", "--monte-carlo", "-1")
    assert line == "Invalid value for '--monte-carlo': '-1' must be at least 1"
    line = one_line_error("plot", "basin", "--dpi", "5")
    assert line == "Invalid value for '--dpi': '5' must be at least 20"


def test_bias_overflowing_normal_is_one_line_without_a_warning():
    # issue: a RuntimeWarning (overflow) was printed before the error line.
    line = one_line_error("bias", "--psi-dist", "normal:0,1e308")
    assert "normal(0, sd 1e+308) is too wide" in line
