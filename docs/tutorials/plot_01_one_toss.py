"""
One toss, then a probability for your own coin
==============================================

A toss is deterministic: the launch speed and the spin decide the face. This tutorial tosses
one coin, looks at what happened during the flight, then asks the question a person actually
has: *for my coin and the way I toss, what is the chance of heads?*
"""

# %%
# One toss
# --------
# A :class:`~coinflight.model.toss.Toss` is the launch: the body-frame spin ω0 in rad/s
# (x and y about diameters, z about the normal) and the flight time T in s (or
# ``launch_speed=`` v0 in m/s, T = 2 v0 / g). A :class:`~coinflight.model.toss.Flight` solves
# the flight in closed form.
import numpy as np

from coinflight import Coin, Flight, Toss

quarter = Coin.preset("us-quarter")
toss = Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7)
flight = Flight(quarter, toss)
print(flight.outcome.face_name, f"after {flight.outcome.rotations:.4f} rotations")

# %%
# Stefan & Cheche state 8.913 rotations for this toss (their Fig 2c). The coin spun about a
# diameter, so its normal n stayed perpendicular to its angular momentum S (ψ = 90°). Give it
# a little spin about its normal as well and the normal **precesses** on a cone of half-angle
# ψ < 90° about S:
wobbly = Flight(quarter, Toss(omega=(80.0, 0.0, 12.0), flight_time=0.7))
print(wobbly.outcome.face_name, f"psi = {np.degrees(wobbly.outcome.psi):.1f} degrees")

# %%
# The state at any time is one call away; times can be an array:
state = flight.at([0.0, 0.1, 0.2])
print(state.normal.round(3))

# %%
# Your own coin
# -------------
# Any uniform cylinder: from millimetres and grams, or in SI units with
# ``Coin(radius=…, thickness=…, mass=…)``.
mine = Coin.from_mm_g(diameter_mm=25.0, thickness_mm=2.0, mass_g=7.0, name="my coin")
print(mine.describe())

# %%
# Your own toss distribution, and P(heads)
# ----------------------------------------
# A person's tosses spread over ranges. A :class:`~coinflight.model.ensemble.TossDistribution`
# takes each initial condition as a number (fixed), a
# :class:`~coinflight.model.distributions.Uniform` range or a
# :class:`~coinflight.model.distributions.Normal`, and :func:`~coinflight.probability.estimate`
# turns it into a probability. ``"exact"`` integrates over Keller's heads bands, with no
# sampling error.
from coinflight import Normal, TossDistribution, Uniform, estimate

my_tosses = TossDistribution(
    omega_x=Uniform(150.0, 250.0),  # rad/s, about 24-40 rev/s
    flight_time=Normal(0.5, 0.05),  # s
    coin=mine,
)
result = estimate(my_tosses, "exact")
print(f"P(heads) = {result.p_heads:.6f}")

# %%
# The same with random tosses, reproducibly: the seed is part of the answer.
mc = estimate(my_tosses, "monte-carlo", n=200_000, seed=1)
print(f"P(heads) = {mc.p_heads:.4f} ± {mc.stderr:.4f} (s.e.), 95 % CI {mc.ci95}, seed {mc.seed}")

# %%
# A picture of the toss
# ---------------------
# :func:`~coinflight.plotting.toss.plot_toss` draws the coin at launch and at the catch, with n
# and S, and the path of n on the unit sphere.
from coinflight import plot_toss

fig = plot_toss(quarter, Toss(omega=(80.0, 0.0, 12.0), flight_time=0.7))
