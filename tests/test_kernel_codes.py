"""Face and status codes as IntEnums, the formulas written once, the contact record (issue 9)."""

from __future__ import annotations

import math

import numba
import numpy as np
import pytest

from _kernels import coin_air, coin_contact
from coinflight.core import ballistics, bands, precession, sampling, torque_free
from coinflight.core.contact import Contact
from coinflight.core.outcome import (
    EDGE,
    FACE_NAMES,
    HEADS,
    STATUS_NAMES,
    TAILS,
    Face,
    Status,
    face_from_alignment,
)


def test_codes_keep_their_integers_and_names():
    # The integers stored in every face/status array since the first release (core/bounce.py,
    # core/impact.py, outcomes/table.py before issue 9); code 5, "settled in contact", is the
    # rigid ending's, the one ending of a table landing. Code 4 ("settled rocking", the planar
    # rocking hand-off since removed) is retired but keeps its member and name, so that saved
    # outputs read the same; code 6 ("decided upright", the upright decision of the compliant
    # contact ending since removed) is no longer used and no member has it.
    assert [int(f) for f in Face] == [0, 1, 2]
    assert (TAILS, HEADS, EDGE) == (0, 1, 2)
    assert FACE_NAMES == ("tails", "heads", "edge")
    assert [int(s) for s in Status] == [0, 1, 2, 3, 4, 5]
    assert [s.name for s in Status] == [
        "SETTLED_ENERGY",
        "SETTLED_DEAD",
        "BOUNCE_LIMIT",
        "UNSETTLED",
        "SETTLED_ROCKING",
        "SETTLED_CONTACT",
    ]
    released = ("settled", "landed dead", "bounce limit", "unsettled", "settled rocking")
    assert (*released, "settled in contact") == STATUS_NAMES
    assert FACE_NAMES[Face.EDGE] == Face.EDGE.label == "edge"
    assert STATUS_NAMES.index("unsettled") == Status.UNSETTLED
    faces = face_from_alignment([0.5, -0.5], [1.0, 1.0])
    assert faces.dtype == np.int8 and faces.tolist() == [Face.HEADS, Face.TAILS]


@numba.njit(cache=False)
def _well(nz: float, edge_sine: float) -> Face:
    if abs(nz) < edge_sine:
        return Face.EDGE
    return Face.HEADS if nz > 0.0 else Face.TAILS


@numba.njit(cache=False)
def _fill(nz: np.ndarray, out: np.ndarray, status: np.ndarray) -> None:
    for k in range(nz.shape[0]):
        out[k] = _well(nz[k], 0.1)
        status[k] = Status.UNSETTLED if out[k] == Face.EDGE else Status.SETTLED_ENERGY


def test_numba_compiles_members_as_their_integers():
    nz = np.array([0.9, -0.9, 0.05])
    out = np.empty(3, dtype=np.int8)
    status = np.empty(3, dtype=np.int8)
    _fill(nz, out, status)
    assert out.tolist() == [1, 0, 2]
    assert status.tolist() == [0, 0, 3]
    assert _well(0.05, 0.1) is Face.EDGE  # a member comes back to Python as the member


def test_never_turns_over_is_the_sign_of_the_alignment():
    # n(t)·n0 = cos²ψ + sin²ψ cos(ωp t) (DHM 2007): negative somewhere in a turn iff cot²ψ < 1.
    rng = np.random.default_rng(9)
    i1, i3 = 1.0, 2.0
    for _ in range(200):
        wx, wy, wz = rng.normal(0.0, 30.0, 3)
        perp2, axial = wx * wx + wy * wy, i3 / i1 * wz
        ratio = axial * axial / perp2
        if abs(ratio - 1.0) < 1e-3:
            continue
        wp = math.sqrt(perp2 + axial * axial)
        t = np.linspace(0.0, 2.0 * math.pi / wp, 2001)
        dips = np.min(torque_free.normal_alignment(wx, wy, wz, t, i1, i3)) < 0.0
        assert bool(bands.never_turns_over(axial * axial, perp2)) is not dips
        assert bool(sampling.never_turns_over(axial * axial, perp2)) is not dips
    assert bands.never_turns_over(0.0, 0.0)  # no spin at all: the normal stays put
    assert bands.never_turns_over(1.0, 1.0)  # ψ = 45°: touches the horizontal, never passes
    psi = np.linspace(0.0, np.pi, 181)
    wobble = bands.never_turns_over(np.cos(psi) ** 2, np.sin(psi) ** 2)
    away = np.abs(np.degrees(psi) - 90.0) != 45.0
    np.testing.assert_array_equal(wobble[away], (np.abs(np.degrees(psi) - 90.0) > 45.0)[away])


def test_compiled_formulas_equal_the_numpy_ones():
    cot2 = np.array([0.0, 1e-300, 0.25, 0.5, 0.999999, 1.0, 3.0, np.inf])
    for c in cot2:
        assert sampling.half_width(c) == bands.half_width(c)
    np.testing.assert_array_equal(bands.half_width(cot2), np.arccos(-np.minimum(cot2, 1.0)))
    assert bands.half_width(0.0) == pytest.approx(np.pi / 2, abs=0)
    assert bands.half_width(2.0) == np.pi


def test_same_side_probability_keeps_its_values():
    # DHM 2007 section 2: p(90°) = 1/2, p(ψ ≤ 45°) = 1, p(60°) = 1/2 + arcsin(1/3)/π.
    psi = np.radians([90.0, 30.0, 45.0, 60.0, 150.0])
    expected = [0.5, 1.0, 1.0, 0.5 + math.asin(1.0 / 3.0) / math.pi, 1.0]
    np.testing.assert_allclose(precession.same_side_probability(psi), expected, rtol=0, atol=1e-15)


def test_v0_and_t_are_inverse():
    t = np.array([0.3, 0.7, 2.0])
    np.testing.assert_allclose(ballistics.flight_time(ballistics.launch_speed(t, 9.81), 9.81), t)


def test_contact_record_derives_its_fields_once():
    c = Contact.build(
        radius=0.012,
        thickness=0.002,
        mass=0.005,
        i1=1.0e-7,
        i3=2.0e-7,
        restitution=0.5,
        friction=0.3,
        drop_height=0.8,
        g=9.81,
        rest_speed=0.01,
    )
    assert c.half_thickness == 0.001
    assert c.reach == math.hypot(0.012, 0.001)
    assert c.edge_sine == 0.001 / c.reach
    assert c.barrier == 0.005 * 9.81 * c.reach

    @numba.njit(cache=False)
    def reach_of(contact: Contact) -> float:
        return math.sqrt(contact.radius**2 + contact.half_thickness**2)

    assert reach_of(c) == pytest.approx(c.reach, rel=1e-15)  # numba takes the record whole


def test_drag_landing_takes_the_contact_record():
    from coinflight import Coin
    from coinflight.core import drag

    coin = Coin.preset("us-nickel")
    contact = coin_contact(coin, rest_speed=0.01)
    air = coin_air(coin, drag_coefficient=1.0)
    face, _, first, settle, status = drag.land(np.array([[40.0, 3.0, 2.0]]), 2.0, 1.0, air, contact)
    assert int(face[0]) in tuple(Face) and int(status[0]) in tuple(Status)
    assert 0.0 < first[0] <= settle[0]
