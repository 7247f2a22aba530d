"""What a toss is: frozen, validated value objects (SI units), built on :mod:`coinflight.core`.

``coin`` (:class:`Coin` and the real coins), ``toss`` (:class:`Toss`, the exact
:class:`Flight`), ``surface`` (:class:`Surface`, :class:`Drag`), ``distributions``
(:class:`Fixed`, :class:`Uniform`, :class:`Normal`) and ``ensemble`` (:class:`TossDistribution`).
Nothing here knows how a toss ends (:mod:`coinflight.outcomes`) or estimates anything.
"""
