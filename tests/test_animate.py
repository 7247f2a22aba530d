"""`coinflight animate` and :mod:`coinflight.plotting.animation`."""

from __future__ import annotations

import math

import numpy as np
import pytest
from PIL import Image
from typer.testing import CliRunner

from _images import colour_fraction
from coinflight import Coin, Flight, Toss
from coinflight.cli import app
from coinflight.core.outcome import HEADS, TAILS
from coinflight.plotting.animation import animate_toss, ffmpeg_available, save_animation
from coinflight.plotting.style import HEADS_COLOR, TAILS_COLOR

QUARTER = Coin.preset("us-quarter")


def test_faces_follow_the_normal_and_end_on_the_outcome():
    toss = Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7)
    movie = animate_toss(QUARTER, toss, frames=50)
    np.testing.assert_allclose(movie.times[[0, -1]], [0.0, 0.7])
    # Planar spin: n·Z = cos(ωx0 t) (Stefan & Cheche eq 14); heads up where it is > 0.
    expected = np.where(np.cos(80.0 * movie.times) > 0, HEADS, TAILS)
    np.testing.assert_array_equal(movie.faces, expected)
    assert movie.faces[-1] == Flight(QUARTER, toss).outcome.face


def test_default_frame_count_follows_the_turns():
    # 8.913 turns (Stefan & Cheche Fig 2c) at 16 frames per turn.
    movie = animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7))
    assert len(movie.times) == int(16 * 80.0 * 0.7 / (2 * math.pi))


def test_gif_frames_show_both_faces(tmp_path):
    movie = animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7), frames=12)
    path = save_animation(movie, tmp_path / "toss.gif")
    with Image.open(path) as im:
        assert im.n_frames == 12
        assert im.size == (960, 768)  # 8 × 6.4 inches at MOVIE_DPI 120: text readable
        seen = set()
        for i in range(im.n_frames):
            im.seek(i)
            rgb = np.asarray(im.convert("RGB"))
            face = movie.faces[i]
            up, down = (HEADS_COLOR, TAILS_COLOR) if face == HEADS else (TAILS_COLOR, HEADS_COLOR)
            # The legend has one swatch of each; the coin and the "… up" label add the face up.
            assert colour_fraction(rgb, up, 16) > colour_fraction(rgb, down, 16), f"frame {i}"
            seen.add(int(face))
    assert seen == {HEADS, TAILS}


def test_rejects_batches_and_bad_frames():
    with pytest.raises(ValueError, match="single toss"):
        animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=np.array([0.6, 0.7])))
    with pytest.raises(ValueError, match="frames must be between 2 and 2000, got 1"):
        animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7), frames=1)
    with pytest.raises(ValueError, match="frames must be between 2 and 2000, got 2001"):
        animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7), frames=2001)


@pytest.mark.skipif(ffmpeg_available(), reason="ffmpeg is installed here")
def test_mp4_without_ffmpeg_names_what_is_missing(tmp_path):
    out = tmp_path / "toss.mp4"
    args = ["animate", "--omega", "80", "0", "0", "-T", "0.7", "--frames", "3", "--out", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2
    assert "MP4 needs the ffmpeg program" in result.stderr
    assert not out.exists()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(not ffmpeg_available(), reason="ffmpeg is not installed here")
def test_mp4_with_ffmpeg(tmp_path):  # pragma: no cover - depends on the machine
    out = tmp_path / "toss.mp4"
    args = ["animate", "--omega", "80", "0", "0", "-T", "0.7", "--frames", "6", "--out", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert out.stat().st_size > 1000


def test_cli_writes_a_gif(tmp_path):
    out = tmp_path / "toss.gif"
    args = ["animate", "--omega", "90", "30", "0", "-T", "0.6", "--frames", "8", "--fps", "10"]
    result = CliRunner().invoke(app, [*args, "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "8 frames at 10 fps" in result.stdout
    with Image.open(out) as im:
        assert im.n_frames == 8
        assert im.info["duration"] == 100


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--out", "toss.avi"], "--out must end in .gif or .mp4"),
        (["--out", "toss.gif", "--frames", "1"], "--frames"),
        (
            ["--out", "toss.gif", "--enlarge", "-2"],
            "enlarge must be between 0.001 and 1e+06, got -2.0",
        ),
    ],
)
def test_cli_bad_input(tmp_path, extra, message):
    args = ["animate", "-T", "0.7", *extra]
    args = [str(tmp_path / a) if a.startswith("toss.") else a for a in args]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2
    assert message in result.stderr
