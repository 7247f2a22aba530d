"""
The same-side bias and 350,757 real flips
=========================================

Diaconis, Holmes & Montgomery (2007) predicted that a coin caught in the hand lands on the
side it started on slightly more than half the time, about 51 %, because a real toss
precesses. Bartoš et al. (2025) flipped 350,757 coins to test it. This tutorial goes from the
physics to the data.
"""

# %%
# Why a precessing coin is biased
# -------------------------------
# The normal n turns about the fixed angular momentum S on a cone of half-angle ψ. Started
# heads up, it shows heads at the catch iff cos²ψ + sin²ψ cos(ωp T) > 0. Over the many turns
# ωp T of a real toss the phase is effectively uniform, and the fraction of it that satisfies
# the condition is p(ψ) = ½ + (1/π) arcsin(cot²ψ).
from coinflight.bias import psi_for_probability, same_side_probability

for psi in (90, 85, 80, 70, 60, 45):
    print(f"psi = {psi:2d} deg: p = {float(same_side_probability(psi, degrees=True)):.4f}")

# %%
# At ψ = 90° (a spin about a diameter, the founding paper's case) there is no bias; at 45°
# and below the coin never turns over at all.
#
# The closed form against the full flight
# ---------------------------------------
# :func:`~coinflight.bias.simulate_same_side` tosses coins at a given ψ with random flight
# times and precession rates and counts those that land on the side they started; the
# closed form should sit within a few standard errors.
from coinflight.bias import simulate_same_side

for psi in (60.0, 80.0):
    sim = simulate_same_side(psi, n=100_000, seed=1, degrees=True)
    exact = float(same_side_probability(psi, degrees=True))
    print(
        f"psi = {psi:g}: simulated {sim.p_same_side:.4f} ± {sim.stderr:.4f}, "
        f"closed form {exact:.4f} ({(sim.p_same_side - exact) / sim.stderr:+.2f} s.e.)"
    )

# %%
# A natural toss
# --------------
# The ``human`` preset (:mod:`coinflight.presets`) is a person's natural toss: launch speed
# about 2.4 m/s, about 38 rev/s about a diameter and a little spin about the normal, so that
# ψ is near but below 90°. Averaged over its spread of ψ:
from coinflight.bias import expected_same_side
from coinflight.presets import preset

human = preset("human")
print(f"human preset: P(same side) = {expected_same_side(human):.4f}")

# %%
# The ψ a measured rate implies
# -----------------------------
# Inverting p(ψ): which fixed ψ gives the same-side rate Bartoš et al. measured?
measured = 178_078 / 350_757
psi_measured = float(psi_for_probability(measured, degrees=True))
print(f"measured {measured:.5f} -> psi = {psi_measured:.2f} deg")

# %%
# The curve p(ψ) with the measured rate and its ψ marked:
from coinflight import plot_bias

fig = plot_bias(measured=measured, psi_measured=psi_measured)
