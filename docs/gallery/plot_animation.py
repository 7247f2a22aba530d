"""
Animation of a toss
===================

:func:`~coinflight.plotting.animation.animate_toss` builds a slow-motion animation of one
toss: the coin rising, turning and falling, the face up and a clock. Shown here are four of
its frames; ``coinflight animate --omega 80 0 0 --flight-time 0.7 --out toss.gif`` (or
``.save("toss.gif")``) writes the whole movie.
"""

import matplotlib.pyplot as plt
import numpy as np

from coinflight import Coin, Toss
from coinflight.plotting.animation import animate_toss

movie = animate_toss(Coin.preset("us-quarter"), Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7))
frames = list(movie.rgb_frames(dpi=60))
picks = np.linspace(0, len(frames) - 1, 4).astype(int)
fig, axes = plt.subplots(2, 2, figsize=(10, 7.5), layout="constrained")
for ax, i in zip(axes.flat, picks, strict=True):
    ax.imshow(frames[i])
    ax.set_title(f"t = {movie.times[i]:.2f} s")
    ax.axis("off")
plt.close(movie.figure)
