"""The founding paper's rotation counts and faces, through the library and through the CLI."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from coinflight import Coin, Flight, Toss
from coinflight.cli import app

# Stefan & Cheche, section 3 (text of Figs 2c-d and 3c-f); REFERENCES §1. Each count is printed
# to 3 or 4 decimals, so the tolerance is half a unit of the last printed digit.
# Faces: what the paper's own rule (eq 14, heads iff cos θ(T) > 0) gives. The paper's text says
# the coin of Fig 2c ends "head down"; with 8.913 turns, θ(T) mod 2π = 0.913·2π, cos θ > 0, so by
# its own formula it ends heads up (see the reproduction report).
PAPER_CASES = [
    # (ωx0, ωy0, T, rotations as printed, decimals printed, face by eq 14)
    pytest.param(80.0, 0.0, 0.7, 8.913, 3, "heads", id="fig2c"),
    pytest.param(120.0, 0.0, 0.9, 17.189, 3, "heads", id="fig2d"),
    pytest.param(90.0, 30.0, 0.6, 9.059, 3, "heads", id="fig3c"),
    pytest.param(90.0, 30.0, 0.65, 9.8142, 4, "heads", id="fig3d"),
    pytest.param(90.0, 30.0, 0.7, 10.569, 3, "tails", id="fig3e"),
    pytest.param(90.0, 30.0, 0.75, 11.324, 3, "tails", id="fig3f"),
]


@pytest.mark.parametrize(("wx", "wy", "t", "printed", "decimals", "face"), PAPER_CASES)
def test_rotation_counts_library(wx, wy, t, printed, decimals, face):
    flight = Flight(Coin.preset("us-quarter"), Toss(omega=(wx, wy, 0.0), flight_time=t))
    assert float(flight.outcome.rotations) == pytest.approx(printed, abs=0.5 * 10**-decimals)
    assert flight.outcome.face_name == face


@pytest.mark.parametrize(("wx", "wy", "t", "printed", "decimals", "face"), PAPER_CASES)
def test_rotation_counts_cli(wx, wy, t, printed, decimals, face):
    args = ["toss", "--omega", str(wx), str(wy), "0", "--flight-time", str(t), "--json"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    assert round(payload["rotations"], decimals) == pytest.approx(printed, abs=1e-12)
    assert payload["outcome"] == face
    # Case b) spins about a diameter: ψ = 90° (S ⟂ n, "Diaconis' theorem" in the paper).
    assert payload["psi"] == pytest.approx(1.5707963267948966, abs=1e-12)
