"""
The founding paper's figures
============================

Stefan & Cheche ("Coin toss modeling", arXiv:1612.06705) model the coin as a thin cylinder
caught at launch height and compute P(heads) two ways over ranges of spin and flight time.
This tutorial redraws their figures from coinflight's closed form and checks the numbers they
state. ``coinflight paper --out paper/`` writes all of them with a report.
"""

# %%
# Figs 2c-d: the coin at launch and at the catch
# ----------------------------------------------
# ωx0 = 80 rad/s, T = 0.7 s, and ωx0 = 120 rad/s, T = 0.9 s. The paper states 8.913 and
# 17.189 rotations.
from coinflight import Coin, Flight, Toss, plot_toss

quarter = Coin.preset("us-quarter")
for spin, t in [(80.0, 0.7), (120.0, 0.9)]:
    out = Flight(quarter, Toss(omega=(spin, 0.0, 0.0), flight_time=t)).outcome
    print(f"omega_x0 = {spin:g} rad/s, T = {t} s: {out.rotations:.4f} rotations, {out.face_name}")

fig = plot_toss(quarter, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7), title="Fig 2c")

# %%
# The paper's text says the Fig 2c coin "ends with head down", but its own eq. 14 gives
# cos θ = cos(ΩT) = cos(2π × 8.9127) > 0: heads up, as drawn above (the report of
# ``coinflight paper`` lists this and the other places where the text and the formulas differ).
#
# Figs 3c-f: one spin, four flight times
# --------------------------------------
# ωx0 = 90, ωy0 = 30 rad/s (still a spin about a diameter, Ω = √(90² + 30²)) and
# T = 0.6, 0.65, 0.7, 0.75 s; the paper states 9.059, 9.8142, 10.569 and 11.324 rotations.
import numpy as np

times = np.array([0.6, 0.65, 0.7, 0.75])
batch = Toss(omega=(90.0, 30.0, 0.0), flight_time=times)
print(Flight(quarter, batch).outcome.rotations.round(4))
fig = plot_toss(quarter, batch, title="Figs 3c-f")

# %%
# Figs 2a-b and 3a-b: methods A and B converge to ½
# -------------------------------------------------
# Method A counts a fine grid of configurations; method B draws random events from a coarse
# grid of 100 cells per parameter. :func:`~coinflight.probability.convergence.convergence`
# runs both for growing sizes next to the exact value (small sizes here, so that this page
# builds in seconds; the paper goes to 5000² configurations).
from coinflight import TossDistribution, Uniform, convergence, plot_convergence, plot_estimates

fig2a = TossDistribution(omega_x=Uniform(60.0, 90.0), flight_time=Uniform(0.6, 0.9))
result = convergence(
    fig2a,
    ["grid", "monte-carlo"],
    grid_sizes=[10, 30, 100, 300, 1000],
    event_sizes=[100, 1_000, 10_000, 100_000],
    seed=1,
)
print(f"exact P(heads) = {result.exact:.6f}")
fig = plot_estimates(
    result, title="Fig 2a, the paper's form: ωx0 ∈ [60, 90] rad/s, T ∈ [0.6, 0.9] s"
)

# %%
# The same numbers as errors on log–log axes, where each method's rate is a straight line.
fig = plot_convergence(result, title="Fig 2a: ωx0 ∈ [60, 90] rad/s, T ∈ [0.6, 0.9] s")

# %%
# The basin behind the numbers
# ----------------------------
# Each configuration of Fig 2a's box ends heads or tails; the map of faces over (T, ωx0) shows
# Keller's hyperbolas ωT = (2k ± ½)π as the boundaries. Its fraction of heads cells is
# method A's estimate on the same grid.
from coinflight import basin_map, plot_basin

basin = basin_map(quarter, flight_time=(0.6, 0.9), spin=(60.0, 90.0), resolution=(300, 300))
fig = plot_basin(basin)
