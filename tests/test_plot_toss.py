"""`coinflight plot toss` and :func:`coinflight.plotting.toss.plot_toss`."""

from __future__ import annotations

import math

import numpy as np
import pytest
from typer.testing import CliRunner

from _images import assert_nontrivial, colour_fraction
from coinflight import Coin, Flight, Toss
from coinflight.cli import app
from coinflight.plotting.style import CATCH_COLOR, HEADS_COLOR, LAUNCH_COLOR, TAILS_COLOR
from coinflight.plotting.toss import coin_rim, normal_path, plot_toss

QUARTER = Coin.preset("us-quarter")


def test_rim_lies_in_the_coin_plane_at_radius_r():
    # Stefan & Cheche §3: C(s) = R cos s u + R sin s (n × u) is a circle of radius R ⟂ n.
    flight = Flight(QUARTER, Toss(omega=(90.0, 30.0, 5.0), flight_time=0.6))
    state = flight.catch
    rim = coin_rim(state.attitude, radius=2.5)
    assert rim.shape == (121, 3)
    np.testing.assert_allclose(np.linalg.norm(rim, axis=-1), 2.5, rtol=1e-12)
    np.testing.assert_allclose(rim @ state.normal, 0.0, atol=1e-12)
    # Heads up at launch: the rim is the horizontal circle z = 0.
    start = flight.at(0.0)
    np.testing.assert_allclose(coin_rim(start.attitude, 1.0)[:, 2], 0.0, atol=1e-15)


def test_normal_path_is_a_cone_about_s():
    # Diaconis, Holmes & Montgomery 2007: n·Ŝ = cos ψ stays constant along the path.
    toss = Toss(omega=(30.0, 0.0, 200.0), flight_time=0.5)
    path = normal_path(QUARTER, toss, np.linspace(0.0, 0.5, 50))
    flight = Flight(QUARTER, toss)
    s = np.asarray(flight.catch.angular_momentum)
    cos_psi = path @ (s / np.linalg.norm(s))
    np.testing.assert_allclose(cos_psi, math.cos(float(flight.outcome.psi)), atol=1e-12)


def test_panels_say_the_face_given_by_the_papers_eq14():
    # Fig 3c-f: ωx0 = 90, ωy0 = 30 rad/s; heads iff cos(Ω T) > 0 (Stefan & Cheche eq 14).
    times = np.array([0.6, 0.65, 0.7, 0.75])
    fig = plot_toss(QUARTER, Toss(omega=(90.0, 30.0, 0.0), flight_time=times))
    titles = [ax.get_title() for ax in fig.axes][:4]
    big_omega = math.hypot(90.0, 30.0)
    for title, t in zip(titles, times, strict=True):
        face = "HEADS" if math.cos(big_omega * t) > 0 else "TAILS"
        assert f"lands {face} up" in title
        assert f"{big_omega * t / (2 * math.pi):.4g} turns" in title
    assert "US quarter" in fig._suptitle.get_text()
    assert len(fig.axes) == 5  # four coin panels and the sphere


def test_different_spins_each_get_their_spin_in_the_title():
    omega = np.array([[90.0, 30.0, 0.0], [30.0, 0.0, 60.0]])
    fig = plot_toss(QUARTER, Toss(omega=omega, flight_time=np.array([0.6, 0.3])))
    titles = [ax.get_title() for ax in fig.axes]
    assert titles[0].startswith("ω0 = (90, 30, 0) rad/s, T = 0.6 s")
    assert titles[1].startswith("ω0 = (30, 0, 60) rad/s, T = 0.3 s")
    # Two cones: ψ = 90° for the spin about a diameter, less with a spin about the normal.
    psi = Flight(QUARTER, Toss(omega=omega[1], flight_time=0.3)).outcome.psi
    assert f"ψ = {math.degrees(float(psi)):.1f}° to 90.0°" in titles[2]
    assert "2 different spins" in fig._suptitle.get_text()


def test_rejects_a_two_dimensional_batch():
    toss = Toss(omega=np.zeros((2, 2, 3)) + 80.0, flight_time=0.7)
    with pytest.raises(ValueError, match="one-dimensional batch"):
        plot_toss(QUARTER, toss)


def test_cli_writes_a_readable_png(tmp_path):
    out = tmp_path / "fig3.png"
    args = ["plot", "toss", "--omega", "90", "30", "0", "--times", "0.6,0.65", "--out", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert str(out) in result.stdout
    rgb = assert_nontrivial(out)
    assert colour_fraction(rgb, LAUNCH_COLOR) > 1e-3
    assert colour_fraction(rgb, CATCH_COLOR) > 1e-3


def test_cli_svg_by_suffix(tmp_path):
    out = tmp_path / "toss.svg"
    args = ["plot", "toss", "--omega", "80", "0", "0", "-T", "0.7", "--out", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert out.read_text().lstrip().startswith("<?xml")


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--times", "0.6,x"], "--times must be comma-separated numbers"),
        (["--times", "0.6", "-T", "0.7"], "give --times or one of"),
        (["--times", "0.6,-1"], "flight time must be between 1e-06 and 10000 (in s)"),
        ([], "give exactly one of --flight-time and --launch-speed"),
    ],
)
def test_cli_bad_input_is_one_line(tmp_path, extra, message):
    out = tmp_path / "x.png"
    result = CliRunner().invoke(app, ["plot", "toss", "--out", str(out), *extra])
    assert result.exit_code == 2
    assert message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not out.exists()


def test_four_panels_keep_their_labels_clear_and_the_sphere_names_each_catch():
    # Fig 3c-f layout: the bottom row's titles overlapped the top row's "Y (mm)" labels and
    # the legend covered the last "Y (mm)".
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    times = np.array([0.6, 0.65, 0.7, 0.75])
    fig = plot_toss(QUARTER, Toss(omega=(90.0, 30.0, 0.0), flight_time=times))
    FigureCanvasAgg(fig).draw()
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    coins, sphere = fig.axes[:4], fig.axes[4]

    def box(artist):
        return artist.get_window_extent(renderer)

    legend = box(fig.legends[0])
    for top, bottom in ((coins[0], coins[2]), (coins[1], coins[3])):
        for label in (top.xaxis.label, top.yaxis.label):
            assert not box(label).overlaps(box(bottom.title))
    for ax in coins:
        for label in (ax.xaxis.label, ax.yaxis.label, ax.zaxis.label):
            assert not box(label).overlaps(legend)
            assert fig.bbox.contains(*box(label).min) and fig.bbox.contains(*box(label).max)
    names = [t.get_text() for t in sphere.texts]
    assert [f"T = {t:g} s" for t in times] == [n for n in names if n.startswith("T = ")]
    # the figure's title clear of the top panels' titles; one viewpoint for every panel
    for ax in coins[:2]:
        assert not box(fig._suptitle).overlaps(box(ax.title))
    assert len({(ax.elev, ax.azim) for ax in coins}) == 1
    # from it every face up is seen from its own side (no coin edge-on or from below)
    normals = np.asarray(
        Flight(QUARTER, Toss(omega=(90.0, 30.0, 0.0), flight_time=times)).catch.normal
    )
    up = np.where(normals[:, 2:3] >= 0, normals, -normals)
    assert (up @ _view_direction(coins[0])).min() > 0.3


def _view_direction(ax) -> np.ndarray:
    el, az = math.radians(ax.elev), math.radians(ax.azim)
    return np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])


@pytest.mark.parametrize(
    ("omega", "flight_time", "letter"),
    [((80.0, 0.0, 0.0), 0.7, "H"), ((90.0, 30.0, 0.0), 0.7, "T"), ((0.0, 0.0, 5.0), 0.5, "H")],
)
def test_camera_sees_the_face_up_and_marks_it(omega, flight_time, letter):
    # Stefan & Cheche Fig 2c (ω0 = (80, 0, 0) rad/s, T = 0.7 s: 8.913 turns, heads up by eq 14);
    # Fig 3e (90, 30, 0), T = 0.7 s: 10.569 turns, tails up; a flat spin: heads up, lying flat.
    toss = Toss(omega=omega, flight_time=flight_time)
    n = np.asarray(Flight(QUARTER, toss).catch.normal)
    up = n if n[2] >= 0 else -n
    ax = plot_toss(QUARTER, toss).axes[0]
    # The old camera (elev 20°, azim −30°) saw Fig 2c's caught coin edge-on: cos = 0.17.
    assert _view_direction(ax) @ up > 0.5
    assert [t.get_text() for t in ax.texts if t.get_text() in ("H", "T")] == [letter]
    # The face up is drawn last and strong, in the heads or tails colour.
    faces = [c for c in ax.collections if len(c.get_facecolor()) == 1]
    top = faces[-1].get_facecolor()[0]
    colour = HEADS_COLOR if letter == "H" else TAILS_COLOR
    rgb = [int(colour[i : i + 2], 16) / 255 for i in (1, 3, 5)]
    np.testing.assert_allclose(top[:3], rgb, atol=1e-6)
    assert top[3] == pytest.approx(0.75)
