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
import numpy as np

from coinflight.studies.bias import psi_for_probability, same_side_probability

for psi in (90, 85, 80, 70, 60, 45):
    print(f"psi = {psi:2d} deg: p = {float(same_side_probability(psi, degrees=True)):.4f}")

# %%
# At ψ = 90° (a spin about a diameter, the founding paper's case) there is no bias; at 45°
# and below the coin never turns over at all.
#
# The closed form against the full flight
# ---------------------------------------
# :func:`~coinflight.studies.bias.simulate_same_side` tosses coins at a given ψ with random flight
# times and precession rates and counts those that land on the side they started; the
# closed form should sit within a few standard errors.
from coinflight.studies.bias import simulate_same_side

for psi in (60.0, 80.0):
    sim = simulate_same_side(psi, n=100_000, seed=1, degrees=True)
    exact = float(same_side_probability(psi, degrees=True))
    print(
        f"psi = {psi:g}: simulated {sim.p:.4f} ± {sim.stderr:.4f}, "
        f"closed form {exact:.4f} ({sim.z(exact):+.2f} s.e.)"
    )

# %%
# A natural toss
# --------------
# The ``human`` preset (:mod:`coinflight.studies.presets`) is a person's natural toss: launch speed
# about 2.4 m/s, about 38 rev/s about a diameter and a little spin about the normal, so that
# ψ is near but below 90°. Averaged over its spread of ψ:
from coinflight.studies.bias import expected_same_side
from coinflight.studies.presets import preset

human = preset("human")
print(f"human preset: P(same side) = {expected_same_side(human):.4f}")

# %%
# 350,757 real flips
# -------------------
# Bartoš et al. had 48 people flip coins and catch them, 350,757 times, each flip starting
# from the face the previous one landed on. Their per-person counts ship with coinflight
# (:mod:`coinflight.datasets`, with their provenance and citation), so this needs nothing
# outside the package:
from coinflight.datasets import DATASETS
from coinflight.studies.data import load_dataset, summarize

table = load_dataset("bartos2023")
print(DATASETS["bartos2023"].citation)
summary = summarize(table)
same = summary.same_side
lo, hi = same.ci95
print(f"{len(table.people)} people, {summary.flips:,} flips")
print(f"same side: {same.successes:,} of {same.trials:,} = {same.estimate:.5f}")
print(f"           95 % Clopper-Pearson interval [{lo:.5f}, {hi:.5f}]")
heads = summary.heads
print(f"heads:     {heads.successes:,} of {heads.trials:,} = {heads.estimate:.5f}")

# %%
# The same-side rate is 0.5077, its 95 % Clopper-Pearson interval excludes ½ by far, and the
# heads rate is ½ within its interval: exactly what the precession model predicts, in both
# respects. (``coinflight data`` prints the same numbers; ``--json`` for a program.)
#
# The ψ a measured rate implies
# -----------------------------
# Inverting p(ψ): which fixed ψ gives the measured same-side rate?
measured = same.estimate
psi_measured = float(psi_for_probability(measured, degrees=True))
print(f"measured {measured:.5f} -> psi = {psi_measured:.2f} deg")
fit = summary.psi
print(
    f"summarize's fit: psi = {np.degrees(fit.psi):.2f} deg, 95 % interval "
    f"[{np.degrees(fit.ci95[0]):.2f}, {np.degrees(fit.ci95[1]):.2f}] deg"
)

# %%
# The curve p(ψ) with the measured rate, its 95 % interval and its ψ marked. The lower panel
# zooms on where the measured rate lies; p(ψ) = p(180° − ψ), so the mirror 180° − ψ explains
# it as well and is marked too.
from coinflight import plot_bias

fig = plot_bias(measured=measured, psi_measured=psi_measured, measured_interval=same.ci95)

# %%
# People differ
# -------------
# One ψ for everybody is a simplification: a χ² test rejects that all 48 people share one
# same-side rate, and the forest plot shows each person's rate with its 95 % interval, the
# pooled rate as a diamond and the natural-toss model's prediction as a line.
from coinflight import plot_forest

het = summary.heterogeneity
print(f"chi2 = {het.chi2:.1f} on {het.dof} degrees of freedom, p = {het.p_value:.1e}")
fig = plot_forest(summary, p_model=float(expected_same_side(human)))
