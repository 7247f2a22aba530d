"""
One toss: the coin at launch and at catch
=========================================

:func:`coinflight.plotting.toss.plot_toss` draws the coin at launch and at catch with its
normal n and angular momentum S, and the path of n on the unit sphere.
"""

from coinflight import Coin, Toss, plot_toss

fig = plot_toss(Coin.preset("us-quarter"), Toss(omega=(90.0, 30.0, 0.0), flight_time=0.7))
