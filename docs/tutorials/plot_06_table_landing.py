"""
Landing on a table
==================

A coin caught in the hand keeps the face it had at the catch. A coin that falls on a table
bounces, and each impact depends on two numbers that nobody has measured for a coin on your
table: the coefficient of **restitution** e (how much of the normal speed survives an
impact) and the **friction** coefficient μ; once the bounces die out it rolls, slides and
spins on its rim, slowed by rolling and pivoting resistances nobody has measured either. So a
table result is not one number: it is a band over plausible values. This tutorial computes
that band.
"""

# %%
# One toss onto a table
# ---------------------
# A :class:`~coinflight.outcomes.table.Landing` flies the coin exactly (torque-free precession plus
# ballistics), finds each contact by root finding, resolves each impact with Stronge's law
# (friction and the normal impulse together over the impact, energetic restitution), then
# carries the coin through its rolling, sliding, pivoting and hops on the table (the rigid,
# event-driven ending) until it has settled: heads, tails or edge.
from coinflight import Coin, Landing, Surface, Toss

nickel = Coin.preset("us-nickel")
toss = Toss.from_launch_speed(omega=(240.0, 5.0, 3.0), launch_speed=2.4)
for e in (0.2, 0.4, 0.6):
    table = Surface("table", drop_height=0.8, restitution=e, friction=0.3)
    out = Landing(nickel, toss, table).outcome
    print(f"e = {e}: {out.face_name} after {int(out.bounces)} bounces")

# %%
# The same toss ends differently for different e: single tosses onto a table are not a
# property of the toss alone.
#
# P(heads) and P(edge) as a band over e and μ
# -------------------------------------------
# Pletser (2022) assumes e = 0.5 and μ = 0.05 for a 50-eurocent coin; tables give μ 0.2-0.6 for
# the static friction of metal on dry wood; nobody has measured either for a coin;
# we take e ∈ [0.2, 0.6] and μ ∈ [0.1, 1] and estimate the probabilities at the corners of that
# box, with the same random tosses (seed 1) for each pair so that the differences are the
# surface's, not the sampling's. A landing carried to rest costs a few milliseconds (the coin
# rolls for a second or two), so each corner gets 800 tosses: a statistical error of about
# 0.018 on each number, printed beside it.
import numpy as np

from coinflight import TossDistribution, Uniform, estimate
from coinflight.outcomes.table import TableLanding

tosses = TossDistribution(
    omega_x=Uniform(150.0, 300.0),
    launch_speed=Uniform(1.5, 3.0),
    coin=nickel,
)
restitutions = [0.2, 0.6]
frictions = [0.1, 1.0]
p_heads = np.empty((2, 2))
p_edge = np.empty((2, 2))
n = 800
for i, e in enumerate(restitutions):
    for j, mu in enumerate(frictions):
        model = TableLanding(Surface("table", drop_height=0.8, restitution=e, friction=mu))
        r = estimate(tosses, "monte-carlo", n=n, seed=1, model=model)
        p_heads[i, j], p_edge[i, j] = r.p_heads, r.p_edge
se = np.sqrt(0.25 / n)
print(f"P(heads) from {p_heads.min():.3f} to {p_heads.max():.3f} (each ± {se:.3f} s.e. at most)")
print(f"P(edge)  from {p_edge.min():.3f} to {p_edge.max():.3f}")

# %%
# The statement to make is the band, e.g. "P(edge) between the two numbers above for
# e ∈ [0.2, 0.6], μ ∈ [0.1, 1]", not one of its points. The maps show where in the band each
# surface lies. Read P(edge) with care: a rigid coin on a perfectly flat, rigid table rolls to
# rest on its edge far more often than the 1 in 6,000 Murray & Teare (1993) counted for a nickel
# on a real table (the physics page, "Edges in the rigid ending", says why: roughness and give
# that the model lacks); P(heads) is not touched by that.
import matplotlib.pyplot as plt

fig, axes = plt.subplots(1, 2, figsize=(8.4, 3.6), layout="constrained")
for ax, values, label in [(axes[0], p_heads, "P(heads)"), (axes[1], p_edge, "P(edge)")]:
    im = ax.imshow(values, origin="lower", cmap="viridis")
    ax.set_xticks(range(2), [f"{m:g}" for m in frictions])
    ax.set_yticks(range(2), [f"{e:g}" for e in restitutions])
    ax.set_xlabel("friction μ")
    ax.set_ylabel("restitution e")
    for (i, j), v in np.ndenumerate(values):
        ax.text(j, i, f"{v:.3f}", ha="center", va="center", color="w", fontsize=8)
    ax.set_title(label)
    fig.colorbar(im, ax=ax, shrink=0.8)
fig.suptitle("US nickel onto a table 0.8 m below, ωx 150-300 rad/s, v0 1.5-3 m/s")

# %%
# Basins after each bounce
# ------------------------
# Strzałko et al. map heads and tails over (launch speed, spin) after 0, 1, 2, … impacts; the
# boundaries are smooth but grow more intricate with every bounce. Here, after one bounce:
from coinflight import basin_map, plot_basin
from coinflight.outcomes import outcome_model

surface = Surface("table", drop_height=0.3, restitution=0.5, friction=0.3)
basin = basin_map(
    nickel,
    flight_time=(2 * 1.0 / 9.81, 2 * 2.5 / 9.81),  # launch speed 1-2.5 m/s
    spin=(20.0, 60.0),
    resolution=(160, 120),
    outcome=outcome_model(surface, max_bounces=1),
)
fig = plot_basin(basin, boundaries=False, ending="on a table 0.3 m below, after 1 bounce")
