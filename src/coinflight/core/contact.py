"""The parameters of a coin meeting a surface, gathered once for the landing kernels (SI units).

:class:`Contact` is a ``NamedTuple`` of floats, so that numba passes it to compiled kernels as
one argument (its fields read as ``contact.radius`` inside them) and Python code builds it once
with :meth:`Contact.build` instead of handing a dozen floats down every call. The quantities
derived from the coin's shape (its reach, the sine of its edge angle and the face/edge energy
barrier) are computed there, once, for every kernel.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from coinflight.core.impact import CONTACT_DURATION


class Contact(NamedTuple):
    """A coin, a horizontal surface and gravity, as the landing kernels read them.

    Attributes
    ----------
    radius, half_thickness : float
        Radius r and half-thickness h/2 of the coin, m.
    mass : float
        Mass m, kg.
    i1, i3 : float
        Principal moments about a diameter and about the normal, kg m².
    restitution, friction : float
        Coefficient of restitution e in [0, 1] and of friction μ ≥ 0 of the surface (a Surface
        takes μ up to :data:`coinflight.model.surface.MAX_FRICTION`, the range the landing
        kernels are validated over).
    drop_height : float
        Launch height of the centre of mass above the surface, m.
    g : float
        Gravitational acceleration, m/s².
    rest_speed : float
        Rebound speed of the contact point below which the bounces have died out, m/s.
    reach : float
        ρ = sqrt(r² + (h/2)²), the distance from the centre of mass to the rim's corner, m.
    edge_sine : float
        (h/2) / ρ = sin(arctan(h / 2r)): the coin rests on its edge while |n_z| is below it.
    barrier : float
        m g ρ, the potential energy of the coin balanced on its corner above the centre of
        mass at the surface, J: below it the coin can no longer change well (Vulović & Prange
        1986, the face/edge barrier; see :mod:`coinflight.core.bounce`).
    rolling_resistance, pivoting_resistance : float
        Lengths ℓ_r, ℓ_p ≥ 0 of the rolling and pivoting (drilling) resistance of the coin's rim
        on the surface, m: torques ℓ F_n against the horizontal and the vertical part of the
        angular velocity in contact, regularised below a slow spin
        (:mod:`coinflight.core.rigid_contact`).
    corner_radius : float
        a ≥ 0, the radius of the rounded corners of the coin's rim, m
        (:attr:`coinflight.model.coin.Coin.corner_radius`): the coin is a cylinder of radius
        r − a and half-thickness h/2 − a swept by a ball of radius a. ``barrier`` and
        ``edge_sine`` are the rounded coin's wells' (m g (a + ρ′) and (h/2 − a)/ρ′,
        ρ′ = sqrt((r − a)² + (h/2 − a)²)). So the corner radius reaches: the rigid ending
        (:mod:`coinflight.core.rigid_ending`, which touches the table with the rounded rim);
        the end of every landing through these two fields
        (:func:`coinflight.core.bounce.after_impact`'s energy test and every
        :func:`coinflight.core.impact.resting_face`, with or without air); the impact law
        (:func:`coinflight.core.impact.impact`, whose contact point is the rounded rim's lowest
        point) and the search for the next contact in flight
        (:func:`coinflight.core.bounce.next_contact` and the air kernel of
        :mod:`coinflight.core.drag`), with or without air. 0: sharp corners, to the last bit
        what the kernels gave before they took a.
    contact_duration : float
        t_c ≥ 0, how long one impact of the coin's rim on the table lasts, s (a physical
        parameter of the surface, not measured for coins:
        :data:`coinflight.core.impact.CONTACT_DURATION`, the default, gives its source): a
        second rim point meeting the table within it makes one simultaneous impact
        (:func:`coinflight.core.impact.simultaneous_point`), with or without air.
    """

    radius: float
    half_thickness: float
    mass: float
    i1: float
    i3: float
    restitution: float
    friction: float
    drop_height: float
    g: float
    rest_speed: float
    reach: float
    edge_sine: float
    barrier: float
    rolling_resistance: float = 0.0
    pivoting_resistance: float = 0.0
    corner_radius: float = 0.0
    contact_duration: float = CONTACT_DURATION

    @classmethod
    def build(
        cls,
        *,
        radius: float,
        thickness: float,
        mass: float,
        i1: float,
        i3: float,
        restitution: float,
        friction: float,
        drop_height: float,
        g: float,
        rest_speed: float,
        rolling_resistance: float = 0.0,
        pivoting_resistance: float = 0.0,
        corner_radius: float = 0.0,
        contact_duration: float | None = None,
    ) -> Contact:
        """The record for a coin of ``thickness`` h (m); the derived fields computed here.

        No validation: the value layer (:class:`~coinflight.model.coin.Coin`,
        :class:`~coinflight.model.surface.Surface`) has checked every value.
        ``contact_duration`` (the impact's t_c) defaults to
        :data:`coinflight.core.impact.CONTACT_DURATION`.
        """
        if contact_duration is None:
            contact_duration = CONTACT_DURATION
        hh = 0.5 * float(thickness)
        # sqrt(r² + hh²) as the bounce kernel always computed it (hypot can differ by an ulp).
        reach = math.sqrt(float(radius) * float(radius) + hh * hh)
        a = float(corner_radius)
        # The rounded rim's corner, as seen from the centre of mass (ρ′, and a + ρ′ its height).
        inner = math.sqrt((float(radius) - a) ** 2 + (hh - a) ** 2) if a > 0.0 else reach
        return cls(
            radius=float(radius),
            half_thickness=hh,
            mass=float(mass),
            i1=float(i1),
            i3=float(i3),
            restitution=float(restitution),
            friction=float(friction),
            drop_height=float(drop_height),
            g=float(g),
            rest_speed=float(rest_speed),
            reach=reach,
            edge_sine=(hh - a) / inner,
            barrier=float(mass) * float(g) * (a + inner),
            rolling_resistance=float(rolling_resistance),
            pivoting_resistance=float(pivoting_resistance),
            corner_radius=a,
            contact_duration=float(contact_duration),
        )


__all__ = ["Contact"]
