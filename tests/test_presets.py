"""The ``human`` toss preset and the closed-form same-side average over a toss distribution."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from coinflight import Coin
from coinflight.cli import app
from coinflight.core import precession
from coinflight.model.distributions import Fixed, Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability import estimate
from coinflight.studies import bias as b
from coinflight.studies.presets import PRESETS, human, preset

# Finite-phase allowance, as in tests/test_bias.py (the closed form assumes a uniform phase).
PHASE_BIAS = 5e-4


def test_human_uses_the_published_numbers():
    d = human()
    # REFERENCES §2 (Diaconis via Keller): upward speed ≈ 2.4 m/s, spin ≈ 38 rev/s.
    assert d.flight_time.mean == pytest.approx(2 * 2.4 / 9.81, rel=1e-12)
    assert d.omega_x.mean == pytest.approx(38 * 2 * math.pi, rel=1e-12)
    assert d.omega_y.is_fixed and d.omega_y.mean == 0.0
    # ψ near but below 90°: ωz > 0 for all but a few per cent of tosses (ωz < 0 is ψ > 90°).
    assert 0.0 < float(d.omega_z.cdf(0.0)) < 0.05
    assert d.start == "heads"


def test_human_closed_form_is_near_the_measured_rate():
    # REFERENCES §2: mean per-flip p ≈ 0.508 (DHM); §6: 0.508 [0.506, 0.509] (Bartoš et al.).
    p = b.expected_same_side(human())
    assert p == pytest.approx(0.508, abs=5e-4)
    assert 0.506 <= p <= 0.509


def test_human_monte_carlo_of_the_full_flight_agrees():
    d = human()
    r = estimate(d, "monte-carlo", 400_000, seed=2023)
    p = b.expected_same_side(d)
    assert r.seed == 2023
    assert abs(r.p_same_side - p) < 4 * r.stderr + PHASE_BIAS
    # ... and the bias is detected: far from 1/2.
    assert r.p_same_side - 0.5 > 8 * r.stderr


def test_human_tails_start_is_the_mirror_image():
    d = human(start="tails")
    r = estimate(d, "monte-carlo", 200_000, seed=7)
    assert r.p_same_side == pytest.approx(r.p_tails, abs=1e-15)
    assert abs(r.p_same_side - b.expected_same_side(d)) < 4 * r.stderr + PHASE_BIAS


@pytest.mark.parametrize("coin", ["us-cent", "gbp-1", "us-half-dollar"])
def test_human_bias_is_the_same_for_every_coin(coin):
    # ωz scales with I1/I3 so that the ψ distribution, hence p, does not depend on the coin.
    assert b.expected_same_side(human(coin=Coin.preset(coin))) == pytest.approx(
        b.expected_same_side(human()), abs=1e-9
    )


def test_preset_lookup():
    assert set(PRESETS) == {"human"}
    assert preset("human").omega_x == human().omega_x
    with pytest.raises(ValueError, match=r"unknown preset 'humn' \(did you mean human\?\)"):
        preset("humn")


def test_expected_same_side_for_a_spin_about_a_diameter_is_one_half():
    d = TossDistribution(Uniform(60, 90), Uniform(0, 30), 0, Uniform(0.6, 0.9))
    assert b.expected_same_side(d) == pytest.approx(0.5, abs=1e-15)


def test_expected_same_side_fixed_spin_is_the_closed_form():
    coin = Coin.preset("us-quarter")
    i1, i3 = coin.moments
    psi = math.radians(70.0)
    w_perp, wz = (float(x) for x in precession.spin_on_cone(200.0, psi, i1, i3))
    d = TossDistribution(w_perp, 0.0, wz, 0.5, coin=coin)
    assert b.expected_same_side(d) == pytest.approx(float(b.same_side_probability(psi)), abs=1e-12)


class _PsiOfNormalSpin:
    """ψ = arctan2(I1 ωx, I3 ωz) with ωz normal, ωx fixed: ψ decreases in ωz, so its quantile
    function is ψ(u) = arctan2(I1 ωx, I3 ωz_ppf(1 − u))."""

    def __init__(self, wx, wz, i1, i3):
        self.wx, self.wz, self.i1, self.i3 = wx, wz, i1, i3

    def ppf(self, u):
        return np.arctan2(self.i1 * self.wx, self.i3 * self.wz.ppf(1.0 - np.asarray(u)))


def test_expected_same_side_matches_psi_quadrature():
    coin = Coin.preset("us-quarter")
    i1, i3 = coin.moments
    wz = Normal(25.0, 10.0)
    d = TossDistribution(Fixed(240.0), 0.0, wz, 0.5, coin=coin)
    expected = b.mean_same_side_probability(_PsiOfNormalSpin(240.0, wz, i1, i3))
    # Midpoint rule with 10⁶ cells on a smooth integrand (documented accuracy 1e-6).
    assert b.expected_same_side(d) == pytest.approx(expected, abs=1e-6)


def test_cli_bias_preset_json():
    result = CliRunner().invoke(app, ["bias", "--preset", "human", "--json"])
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    assert payload["preset"] == "human"
    assert payload["distribution"]["omega_x"] == human().omega_x.to_dict()
    assert payload["p_same_side"] == pytest.approx(b.expected_same_side(human()), abs=1e-15)
    lo, hi = payload["psi_range95_deg"]
    assert lo < payload["psi_deg"] < hi <= 90.0


def test_cli_bias_preset_monte_carlo_text():
    args = ["bias", "--preset", "human", "--monte-carlo", "100000", "--seed", "5"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "P(same side) = 0.508" in result.stdout
    assert "Monte Carlo (coinflight.probability, full flight)" in result.stdout
    assert "seed 5" in result.stdout


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--preset", "human", "--psi", "80"], "give exactly one of --psi DEG, --psi-dist"),
        (["--preset", "robot"], "unknown preset 'robot'"),
    ],
)
def test_cli_bias_preset_errors(args, message):
    result = CliRunner().invoke(app, ["bias", *args])
    assert result.exit_code == 2
    assert message in result.stderr


def test_preset_overrides():
    assert preset("human", omega_z=0.0).spin_about_diameter
    d = preset("human", launch_speed=Uniform(2.0, 3.0))
    assert d.flight_time == Uniform(2 * 2.0 / 9.81, 2 * 3.0 / 9.81)
    assert d.omega_z == human().omega_z  # untouched conditions stay the preset's
    assert preset("human", flight_time=0.5).flight_time == Fixed(0.5)
    with pytest.raises(ValueError, match="at most one of flight_time and launch_speed"):
        preset("human", flight_time=0.5, launch_speed=2.0)
    with pytest.raises(ValueError, match="cannot override coin_size of a preset"):
        preset("human", coin_size=3.0)


def _probability(*args):
    result = CliRunner().invoke(app, ["probability", *map(str, args), "--quiet", "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_cli_probability_preset_human():
    payload = _probability(
        "--preset", "human", "--method", "monte-carlo", "--n", 200_000, "--seed", 12
    )
    assert payload["seed"] == 12
    assert payload["distribution"]["omega_z"] == human().omega_z.to_dict()
    p = b.expected_same_side(human())
    assert abs(payload["p_same_side"] - p) < 4 * payload["stderr"] + PHASE_BIAS


def test_cli_probability_preset_with_an_explicit_override():
    # --omega-z 0 typed by the user replaces the preset's precession: no bias left (ψ = 90°).
    payload = _probability(
        "--preset", "human", "--omega-z", 0, "--method", "monte-carlo", "--n", 200_000, "--seed", 12
    )
    assert payload["distribution"]["omega_z"] == Fixed(0.0).to_dict()
    assert payload["distribution"]["omega_x"] == human().omega_x.to_dict()
    assert abs(payload["p_same_side"] - 0.5) < 4 * payload["stderr"] + PHASE_BIAS


def test_cli_probability_preset_conflicting_times():
    result = CliRunner().invoke(
        app, ["probability", "--preset", "human", "--flight-time", "0.5", "--launch-speed", "3"]
    )
    assert result.exit_code == 2
    assert "give at most one of --flight-time and --launch-speed" in result.stderr
