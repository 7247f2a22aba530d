"""Heads/tails maps: `coinflight plot basin` and :mod:`coinflight.plotting.basin`."""

from __future__ import annotations

import math
from importlib.resources import files
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from _images import assert_nontrivial, colour_fraction
from coinflight import Coin
from coinflight.cli import app
from coinflight.core import torque_free
from coinflight.core.outcome import HEADS
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.plotting.basin import plot_basin
from coinflight.plotting.style import HEADS_COLOR, TAILS_COLOR
from coinflight.studies.basin import basin_map, midpoints

QUARTER = Coin.preset("us-quarter")


def test_heads_fraction_is_the_papers_rule_on_the_midpoint_grid():
    # Method A of Stefan & Cheche on a 300×200 midpoint grid: heads iff cos(Ω T) > 0 (eq 14),
    # Ω = sqrt(ωx0² + ωy0²) (eq 15); Fig 3a ranges ωx0 ∈ [60, 90], ωy0 = 10, T ∈ [0.6, 0.9].
    basin = basin_map(QUARTER, (0.6, 0.9), (60.0, 90.0), omega_y=10.0, resolution=(300, 200))
    t = 0.6 + (np.arange(300) + 0.5) * 0.3 / 300
    w = 60.0 + (np.arange(200) + 0.5) * 30.0 / 200
    heads = np.cos(np.hypot(w[:, None], 10.0) * t[None, :]) > 0
    np.testing.assert_array_equal(basin.face == HEADS, heads)
    assert basin.heads_fraction == heads.mean()
    np.testing.assert_allclose(basin.flight_time, t, rtol=0, atol=1e-14)


@pytest.mark.parametrize(
    ("wx", "wy", "wz"),
    [
        ((60.0, 90.0), 0.0, 0.0),
        ((90.0, 120.0), 0.0, 0.0),
        ((60.0, 90.0), 60.0, 0.0),
        ((60.0, 90.0), 5.0, 30.0),
    ],
)
def test_heads_pixels_are_the_grid_method_count(wx, wy, wz):
    # The requirement: fraction of heads pixels == grid probability on the same grid
    # (estimate(method="grid") counts bands along T; the map evaluates every pixel).
    from coinflight.model.distributions import Uniform
    from coinflight.model.ensemble import TossDistribution
    from coinflight.probability import estimate

    n = 333
    dist = TossDistribution(Uniform(*wx), wy, wz, Uniform(0.6, 0.9), coin=QUARTER)
    grid = estimate(dist, "grid", n=n, threads=1)
    basin = basin_map(QUARTER, (0.6, 0.9), wx, omega_y=wy, omega_z=wz, resolution=(n, n))
    assert int(np.sum(basin.face == HEADS)) == grid.counts[1]
    assert basin.heads_fraction == grid.p_heads


def test_midpoints_are_cell_centres():
    np.testing.assert_allclose(midpoints(0.0, 1.0, 4), [0.125, 0.375, 0.625, 0.875])


def test_keller_hyperbolas_are_where_the_face_changes():
    # Keller 1986: boundaries Ω T = (2n ± ½)π, where cos θ(T) = 0 (REFERENCES §3).
    basin = basin_map(QUARTER, (0.6, 0.9), (90.0, 120.0), omega_y=20.0, resolution=(50, 50))
    curves = basin.boundaries()
    # Ω T runs over [0.6·sqrt(90²+20²), 0.9·sqrt(120²+20²)] = [55.3, 109.5] rad: 17 boundaries
    # at (k + ½)π cross the box (k = 17 … 34 minus the ones cut off by the corners).
    assert len(curves) >= 10
    for t, w in curves:
        ok = ~np.isnan(t)
        assert np.all((t[ok] >= 0.6) & (t[ok] <= 0.9))
        angle = np.hypot(w[ok], 20.0) * t[ok]
        np.testing.assert_allclose(np.cos(angle), 0.0, atol=1e-9)


def test_precessing_boundaries_and_dhm_probability():
    # Diaconis, Holmes & Montgomery 2007 (REFERENCES §2): over many turns P(same side) at
    # ψ = 60° is 1/2 + arcsin(cot²ψ)/π = 0.6082. 200:400 rad/s over 0.6:0.9 s spans ~29 turns
    # of ωp T, so the band average is within 1/(number of bands) ~ 0.005 of that limit.
    psi = math.radians(60.0)
    basin = basin_map(QUARTER, (0.6, 0.9), (200.0, 400.0), psi=psi, resolution=(600, 600))
    limit = 0.5 + math.asin(1.0 / math.tan(psi) ** 2) / math.pi
    assert basin.heads_fraction == pytest.approx(limit, abs=0.005)
    i1, i3 = QUARTER.moments
    for t, w in basin.boundaries():
        ok = ~np.isnan(t)
        wx, wz = w[ok] * math.sin(psi), w[ok] * math.cos(psi) * i1 / i3
        align = torque_free.normal_alignment(wx, 0.0, wz, t[ok], i1, i3)
        np.testing.assert_allclose(align, 0.0, atol=1e-9)


def test_psi_grid_has_the_asked_cone_angle_and_rate_through_a_swapped_outcome():
    seen = {}

    def recording(coin, omega, flight_time, start_sign, g):
        seen["omega"] = omega
        return HAND_CATCH.faces(coin, omega, flight_time, start_sign, g)

    psi = math.radians(75.0)
    basin = basin_map(QUARTER, spin=(50.0, 70.0), psi=psi, resolution=(4, 5), outcome=recording)
    i1, i3 = QUARTER.moments
    omega = seen["omega"]
    assert omega.shape == (5, 4, 3)
    np.testing.assert_allclose(torque_free.cone_angle(omega, i1, i3), psi, rtol=1e-12)
    rate = torque_free.precession_rate(omega, i1, i3)
    np.testing.assert_allclose(rate, np.broadcast_to(basin.spin[:, None], (5, 4)), rtol=1e-12)


def test_boundaries_of_a_fixed_normal_spin_separate_the_faces():
    # ωz = 20 rad/s: cot ψ = I3 ωz / (I1 ωx) ≈ 0.66 … 0.44, ψ ≈ 57° … 66° over ωx ∈ [60, 90];
    # boundaries where cos²ψ + sin²ψ cos(ωp T) = 0 (DHM 2007). Each must be where n(T)·n0
    # vanishes, and the boundaries crossed along a row must match the face changes in the map.
    basin = basin_map(QUARTER, omega_z=20.0, resolution=(400, 3))
    i1, i3 = QUARTER.moments
    curves = basin.boundaries()
    assert curves
    for t, w in curves:
        ok = ~np.isnan(t)
        align = torque_free.normal_alignment(w[ok], 0.0, 20.0, t[ok], i1, i3)
        np.testing.assert_allclose(align, 0.0, atol=1e-9)
    row = basin.face[1]
    changes = int(np.sum(row[1:] != row[:-1]))
    w_mid = basin.spin[1]
    crossings = 0
    for t, w in curves:
        t_at = np.interp(w_mid, w, t)
        crossings += bool(np.isfinite(t_at) and basin.flight_time[0] < t_at < basin.flight_time[-1])
    assert changes == crossings > 5


def test_small_cone_never_turns_over():
    # ψ < 45°: cos²ψ + sin²ψ cos(ωp T) > 0 always (DHM 2007), so a heads-up toss stays heads.
    basin = basin_map(QUARTER, omega_z=200.0, resolution=(40, 40))
    assert basin.heads_fraction == 1.0
    assert basin.boundaries() == []


def test_tails_start_mirrors_heads_start():
    heads = basin_map(QUARTER, resolution=(60, 60))
    tails = basin_map(QUARTER, resolution=(60, 60), start="tails")
    np.testing.assert_array_equal(heads.face + tails.face, 1)


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        ({"flight_time": (0.9, 0.6)}, ValueError, "low < high"),
        ({"flight_time": (0.0, 0.6)}, ValueError, "must be positive"),
        ({"resolution": (0, 10)}, ValueError, "at least 1×1"),
        ({"psi": 0.5, "omega_z": 3.0}, ValueError, "not both"),
        ({"start": "edge"}, ValueError, "start must be one of"),
    ],
)
def test_bad_arguments(kwargs, error, message):
    with pytest.raises(error, match=message):
        basin_map(QUARTER, **kwargs)


def test_picture_shows_the_heads_fraction(tmp_path):
    from coinflight.plotting.style import save_figure

    basin = basin_map(QUARTER, omega_y=10.0, resolution=(200, 200))
    (path,) = save_figure(plot_basin(basin), tmp_path / "basin.png")
    rgb = assert_nontrivial(path)
    heads, tails = colour_fraction(rgb, HEADS_COLOR, 2), colour_fraction(rgb, TAILS_COLOR, 2)
    assert heads > 0.05 and tails > 0.05
    # The map fills most of the picture; legend swatches are small against it.
    assert heads / (heads + tails) == pytest.approx(basin.heads_fraction, abs=0.02)


def test_cli_writes_the_map_and_prints_the_grid_probability(tmp_path):
    out = tmp_path / "basin.png"
    args = ["plot", "basin", "--omega-x", "60:90", "--omega-y", "10", "--resolution", "120x80"]
    result = CliRunner().invoke(app, [*args, "--out", str(out)])
    assert result.exit_code == 0, result.output
    expected = basin_map(QUARTER, (0.6, 0.9), (60.0, 90.0), omega_y=10.0, resolution=(120, 80))
    assert f"P(heads) on the 120×80 grid = {expected.heads_fraction:.6f}" in result.stdout
    rgb = assert_nontrivial(out)
    assert colour_fraction(rgb, HEADS_COLOR, 2) > 0.05
    assert colour_fraction(rgb, TAILS_COLOR, 2) > 0.05


def test_cli_launch_speed_range_is_the_flight_time_range(tmp_path):
    # T = 2 v0 / g (Stefan & Cheche eq 11): 2.943:4.4145 m/s at g = 9.81 is T ∈ [0.6, 0.9] s.
    args = ["plot", "basin", "--resolution", "90x60", "--out", str(tmp_path / "v.png")]
    by_speed = CliRunner().invoke(app, [*args, "--launch-speed", "2.943:4.4145"])
    by_time = CliRunner().invoke(app, [*args, "--flight-time", "0.6:0.9"])
    assert by_speed.exit_code == 0 and by_time.exit_code == 0
    assert by_speed.stdout.splitlines()[0] == by_time.stdout.splitlines()[0]


def test_cli_psi(tmp_path):
    out = tmp_path / "psi.svg"
    args = ["plot", "basin", "--psi", "60", "--precession-rate", "100:200", "--resolution", "50"]
    result = CliRunner().invoke(app, [*args, "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert out.is_file()


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--omega-x", "90"], "--omega-x must be a range LO:HI"),
        (["--omega-x", "90:x"], "--omega-x '90:x'"),
        (["--resolution", "10by10"], "--resolution must be N or NTxNW"),
        (["--psi", "60", "--omega-z", "4"], "with --psi the spin is set by --precession-rate"),
        (["--precession-rate", "1:2"], "--precession-rate goes with --psi"),
        (["--psi", "190"], "--psi must be between 0 and 180"),
        (["--flight-time", "0.9:0.6"], "range 0.9:0.6 is reversed"),
        (["--flight-time", "0.6:0.9", "--launch-speed", "3:4"], "not both"),
        (["--launch-speed", "0:4"], "--launch-speed range must be positive"),
    ],
)
def test_cli_bad_input(tmp_path, extra, message):
    out = tmp_path / "x.png"
    result = CliRunner().invoke(app, ["plot", "basin", "--out", str(out), *extra])
    assert result.exit_code == 2
    assert message in result.stderr
    assert not out.exists()


# The counts of Bartoš et al. shipped inside the package (coinflight.datasets), nothing outside.
BARTOS = Path(str(files("coinflight.datasets") / "bartos2023.txt"))


@pytest.mark.parametrize(
    ("argv", "option"),
    [
        (["plot", "basin", "--out"], "--out"),
        (["plot", "toss", "--flight-time", "0.5", "--out"], "--out"),
        (["plot", "bias", "--monte-carlo", "10", "--out"], "--out"),
        (["data", "--counts", str(BARTOS), "--plot"], "--plot"),
    ],
)
def test_every_figure_command_checks_the_format_first(tmp_path, monkeypatch, argv, option):
    import coinflight.studies.basin

    def refuse(*_args, **_kwargs):
        raise AssertionError("computed before checking the format")

    monkeypatch.setattr(coinflight.studies.basin, "basin_map", refuse)
    out = tmp_path / "figure.txt"
    result = CliRunner().invoke(app, [*argv, str(out)])
    assert result.exit_code == 2, result.output
    assert result.stdout == ""  # nothing computed and printed before the error
    (line,) = result.stderr.splitlines()
    assert line.startswith(
        f"coinflight: error: {option} {str(out)!r}: cannot write a figure as .txt"
    )
    assert ".png, .svg, .pdf" in line and "without a suffix, FILE.png and FILE.svg" in line
    assert list(tmp_path.iterdir()) == []


def test_figure_without_suffix_is_png_and_svg(tmp_path):
    from coinflight.plotting.style import figure_paths, image_formats

    assert figure_paths(tmp_path / "f", "--out") == [tmp_path / "f.png", tmp_path / "f.svg"]
    assert image_formats()[:3] == ["png", "svg", "pdf"]
    result = CliRunner().invoke(
        app, ["data", "--counts", str(BARTOS), "--plot", str(tmp_path / "f")]
    )
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.png", "f.svg"]
    assert f"wrote {tmp_path / 'f.png'}" in result.stdout
    assert f"wrote {tmp_path / 'f.svg'}" in result.stdout


def test_the_analytic_boundaries_are_drawn_on_the_catch_in_the_hand_only():
    # One rule for the command line and the web: drawn when asked for on the catch in the hand;
    # a table's map is drawn without them (the command line) and a request for them on a
    # table refused (the library, the web), in one line.
    from coinflight.queries.basin import HAND, basin_query, draws_boundaries
    from coinflight.queries.values import TableArgs

    table = TableArgs("table", None, None, None, None)
    assert draws_boundaries(HAND, True)
    assert not draws_boundaries(HAND, False)
    assert not draws_boundaries(table, True)
    assert not draws_boundaries(table, False)
    with pytest.raises(ValueError, match="belong to the catch in the hand"):
        basin_query(QUARTER, resolution="2", table=table, boundaries=True)


def test_a_precession_angle_next_to_0_draws_its_map(tmp_path):
    """ψ = 2.3e-161° (cot²ψ beyond the largest float; found by tests/test_cli_generated.py):
    the map of a coin spinning about its normal, all heads, instead of an OverflowError."""
    out = tmp_path / "basin.png"
    argv = ["plot", "basin", "--psi", "2.33302e-161", "--out", str(out)]
    result = CliRunner().invoke(app, argv)
    assert result.exit_code == 0, result.output
    assert "P(heads) on the 500×500 grid = 1.000000" in result.stdout
    assert_nontrivial(out)
