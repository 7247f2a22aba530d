"""The walkthrough "adding an outcome model" (ARCHITECTURE.md), followed with a toy soft mat.

A new model touches at most three places: its kernel (here an existing one,
:func:`coinflight.core.torque_free.normal_alignment`), its model (the class below, which would be
``src/coinflight/outcomes/mat.py``) and one registration line (:func:`coinflight.outcomes.register`
at the end of ``src/coinflight/outcomes/__init__.py``, here at run time). Nothing else changes:
the factory, the estimators, the maps, ``Surface("soft-mat")``, ``coinflight probability
--surface soft-mat`` and the web API's ``surface=soft-mat`` take it as it is, and unregistering
it brings back their refusal.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from _cli import answer, api_answer, one_line_error, runner
from coinflight import outcomes
from coinflight.cli import app
from coinflight.core import torque_free
from coinflight.core.outcome import EDGE, face_from_alignment
from coinflight.model.coin import Coin
from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.model.surface import Drag, Surface
from coinflight.outcomes.air import DragCatch
from coinflight.outcomes.base import OutcomeModel
from coinflight.outcomes.hand import HAND_CATCH, HandCatch
from coinflight.outcomes.table import TableLanding
from coinflight.probability import estimate
from coinflight.studies.basin import basin_map

QUARTER = Coin.preset("us-quarter")
G = 9.81


# --- touch point 2 of 3: the model (would be src/coinflight/outcomes/mat.py) ----------------
class SoftMat(OutcomeModel):
    """A thick soft mat ``depth`` m below launch stops the coin dead when its centre reaches it.

    The face is the one nearest up then: the sign of n(t)·Z at the time t the centre has fallen
    ``depth`` below launch height, t = (v0 + sqrt(v0² + 2 g depth)) / g with v0 = g T / 2
    (uniform gravity, no drag); the attitude is the torque-free closed form (touch point 1, the
    kernel, reused).
    """

    name = "soft mat"
    summary = "a thick soft mat --drop-height below launch stops the coin dead"
    surface_parameters = ("drop_height",)  # of the table's parameters, the mat takes its depth

    def __init__(self, depth: float = 0.0) -> None:
        self.depth = depth

    @classmethod
    def from_surface(cls, surface):
        return cls(float(surface.drop_height))

    def faces(self, coin, omega, flight_time, start_sign, g):
        v0 = 0.5 * g * np.asarray(flight_time, dtype=float)
        t = (v0 + np.sqrt(v0 * v0 + 2.0 * g * self.depth)) / g
        i1, i3 = coin.moments
        align = torque_free.normal_alignment(omega[..., 0], omega[..., 1], omega[..., 2], t, i1, i3)
        return face_from_alignment(align, start_sign)


@pytest.fixture
def registry():
    """The soft mat registered for the test, and unregistered after it."""
    # --- touch point 3 of 3: one registration line --------------------------------------------
    outcomes.register("soft-mat", SoftMat)
    yield outcomes.SURFACE_KINDS
    outcomes.unregister("soft-mat")


def _mat(depth: float) -> OutcomeModel:
    return outcomes.outcome_model(Surface("soft-mat", drop_height=depth))


DIST = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))


NOT_REGISTERED = "surface must be one of hand, table; got 'soft-mat'"
MAT_REFUSAL = (
    "does not apply to --surface soft-mat (Surface(kind='soft-mat') in Python: the soft mat), "
    "which takes drop height only"
)


def test_the_soft_mat_is_built_by_the_factory_with_one_line():
    with pytest.raises(ValueError, match=f"^{re.escape(NOT_REGISTERED)}$"):
        outcomes.outcome_model("soft-mat")
    outcomes.register("soft-mat", SoftMat)
    try:
        assert list(outcomes.SURFACE_KINDS) == ["hand", "table", "soft-mat"]
        model = _mat(0.5)
        assert isinstance(model, SoftMat) and model.depth == 0.5
        assert outcomes.outcome_model("soft-mat").depth == 0.0  # the surface's default
        # The surface takes what the model declares, and refuses the rest in one line.
        given = "restitution 0.3, friction 0.2"
        with pytest.raises(ValueError, match=re.escape(f"{given} {MAT_REFUSAL}")):
            Surface("soft-mat", restitution=0.3, friction=0.2)
        with pytest.raises(
            ValueError, match=re.escape(f"rolling resistance 0.0002 m {MAT_REFUSAL}")
        ):
            Surface("soft-mat", rolling_resistance=2e-4)
        with pytest.raises(ValueError, match=r"^air drag C_d = 1.17: the soft mat takes no air"):
            outcomes.outcome_model("soft-mat", Drag(coefficient=1.17))
        with pytest.raises(ValueError, match=r"^max_bounces applies to a table surface only, no"):
            outcomes.outcome_model("soft-mat", max_bounces=1)
    finally:
        outcomes.unregister("soft-mat")
    with pytest.raises(ValueError, match=f"^{re.escape(NOT_REGISTERED)}$"):
        Surface("soft-mat")
    # The defaults of the protocol stand for everything the model does not declare.
    assert not model.closed_form_bands and not model.can_end_on_edge and model.deterministic
    assert model.describe() == "soft mat"


def test_a_mat_at_launch_height_is_the_hand_catch_in_monte_carlo_and_on_a_map(registry):
    # depth 0: the centre reaches the mat at t = 2 v0 / g = T, where the hand catches it. The
    # two models share no code path (the hand counts by the compiled affine kernel), so equal
    # counts on 20,000 random tosses and equal maps test the plumbing end to end.
    mat = _mat(0.0)
    by_mat = estimate(DIST, "monte-carlo", n=20_000, seed=11, model=mat)
    by_hand = estimate(DIST, "monte-carlo", n=20_000, seed=11)
    assert by_mat.counts == by_hand.counts
    assert by_mat.seed == 11
    mat_map = basin_map(QUARTER, resolution=(60, 40), outcome=mat)
    hand_map = basin_map(QUARTER, resolution=(60, 40))
    np.testing.assert_array_equal(mat_map.face, hand_map.face)


def test_a_deeper_mat_is_the_catch_at_the_later_contact(registry):
    depth = 0.5
    mat = _mat(depth)
    mat_map = basin_map(QUARTER, resolution=(60, 40), outcome=mat)
    # Pixel by pixel: the hand catch's face at the time the centre falls 0.5 m below launch
    # (z(t) = v0 t − g t²/2 = −0.5 m, v0 = g T / 2), found here by NumPy's polynomial roots.
    t, w = np.meshgrid(mat_map.flight_time, mat_map.spin)
    later = np.array(
        [max(np.roots([-0.5 * G, 0.5 * G * tt, depth]).real) for tt in t.ravel()]
    ).reshape(t.shape)
    omega = np.stack([w, 0 * w, 0 * w], axis=-1)
    np.testing.assert_array_equal(mat_map.face, HAND_CATCH.faces(QUARTER, omega, later, 1.0, G))
    assert np.any(mat_map.face != basin_map(QUARTER, resolution=(60, 40)).face)
    # The estimators ask its capabilities: no closed-form bands, so the grid evaluates every
    # configuration and the exact method refuses, naming it.
    grid = estimate(DIST, "grid", n=50, model=mat)
    assert grid.details["how"] == "every configuration evaluated"
    assert grid.p_heads == pytest.approx(
        float(np.mean(basin_map(QUARTER, resolution=(50, 50), outcome=mat).face == 1)), abs=0
    )
    with pytest.raises(ValueError, match="exact method handles the hand catch only, not soft mat"):
        estimate(DIST, "exact", model=mat)


def test_the_factory_builds_each_registered_model():
    assert outcomes.outcome_model() is HAND_CATCH
    assert outcomes.outcome_model(Surface("hand")) is HAND_CATCH
    assert outcomes.outcome_model("hand", Drag(coefficient=0.0)) is HAND_CATCH  # no air
    air = outcomes.outcome_model(Surface("hand"), Drag(coefficient=1.17))
    assert isinstance(air, DragCatch) and air.drag.coefficient == 1.17
    table = Surface("table", drop_height=0.3)
    landing = outcomes.outcome_model(table, max_bounces=2)
    assert isinstance(landing, TableLanding)
    assert (landing.surface, landing.drag, landing.max_bounces) == (table, None, 2)
    assert landing.can_end_on_edge and not landing.closed_form_bands
    assert HandCatch.closed_form_bands and not HandCatch.can_end_on_edge
    assert landing.to_dict()["max_bounces"] == 2
    with pytest.raises(ValueError, match=r"^max_bounces applies to a table surface only"):
        outcomes.outcome_model("hand", max_bounces=1)
    with pytest.raises(TypeError, match=r"^surface must be a Surface or a kind name, got int"):
        outcomes.outcome_model(3)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"^drag must be a Drag"):
        outcomes.outcome_model("hand", "air")  # type: ignore[arg-type]


def test_table_faces_on_a_map_count_edges_like_the_estimator():
    # One implementation of a table's faces: the map's pixels and the grid's configurations are
    # the same tosses (cell midpoints), so their face fractions agree exactly.
    model = outcomes.outcome_model(Surface("table", drop_height=0.3, restitution=0.2))
    dist = TossDistribution(Uniform(20, 40), 0, 0, Uniform(0.3, 0.4), coin=Coin.preset("us-nickel"))
    grid = estimate(dist, "grid", n=30, model=model)
    basin = basin_map(dist.coin, (0.3, 0.4), (20.0, 40.0), resolution=(30, 30), outcome=model)
    assert grid.p_heads == basin.heads_fraction
    assert grid.p_edge == basin.fraction(EDGE)


MAT_ARGS = ["--omega-x", "60:90", "--flight-time", "0.6:0.9", "--surface", "soft-mat"]
MC = ["--method", "monte-carlo", "--n", "20000", "--seed", "11"]


def test_the_command_line_reaches_the_mat_with_no_other_edit(registry):
    # coinflight probability --surface soft-mat: the estimate of the model itself, the mat's
    # depth from --drop-height (the one table parameter it declares), the rest refused.
    argv = ["probability", *MAT_ARGS, "--drop-height", "0.5", *MC, "--json"]
    out = answer(runner.invoke(app, argv), argv)
    by_model = estimate(DIST, "monte-carlo", n=20_000, seed=11, model=SoftMat(0.5))
    assert (out["counts"]["heads"], out["counts"]["tails"]) == tuple(by_model.counts[1::-1])
    assert out["p_heads"] == by_model.p_heads
    assert out["surface"] == "soft mat"
    refused = one_line_error("probability", *MAT_ARGS, "--restitution", "0.3", *MC)
    assert refused == f"--restitution {MAT_REFUSAL}"
    # coinflight toss --surface soft-mat: the face the model gives.
    toss = ["toss", "--omega", "80", "0", "0", "--flight-time", "0.7", "--surface", "soft-mat"]
    toss += ["--drop-height", "0.5", "--json"]
    face = SoftMat(0.5).faces(QUARTER, np.array([[80.0, 0, 0]]), np.array([0.7]), 1.0, G)
    assert answer(runner.invoke(app, toss), toss)["outcome"] == ["tails", "heads"][int(face[0])]
    # Unregistered, it is refused again, in the surface's words.
    outcomes.unregister("soft-mat")
    assert one_line_error("probability", *MAT_ARGS, *MC) == NOT_REGISTERED


def test_the_web_api_reaches_the_mat_with_no_other_edit(registry):
    # The server's worker processes are forked before the mat is registered: they receive the
    # registry with each request, so the API answers as the command line does, lists the mat
    # in /api/surfaces (the page's menu), and refuses it once unregistered.
    from fastapi.testclient import TestClient

    from coinflight.queries.landing import SUGGESTED_MOST
    from coinflight.web import create_app

    query = "omega_x=60:90&flight_time=0.6:0.9&surface=soft-mat&method=monte-carlo&n=20000&seed=11"
    argv = ["probability", *MAT_ARGS, "--drop-height", "0.5", *MC, "--json"]
    by_cli = answer(runner.invoke(app, argv), argv)
    with TestClient(create_app(workers=1)) as client:
        listed = api_answer(client.get("/api/surfaces"))["surfaces"]
        assert [kind["name"] for kind in listed] == ["hand", "table", "soft-mat"]
        assert listed[2] == {
            "name": "soft-mat",
            "summary": SoftMat.summary,
            "takes": ["drop_height"],
            "can_end_on_edge": False,
            "closed_form_bands": False,
            # The tosses the page proposes, from the mat's rate (the base's 1e5 a second).
            "suggested_n": SUGGESTED_MOST,
        }
        by_api = api_answer(client.get(f"/api/probability?{query}&drop_height=0.5"))
        assert {**by_api, "elapsed": 0} == {**by_cli, "elapsed": 0}
        refused = client.get(f"/api/probability?{query}&friction=0.2")
        assert (refused.status_code, refused.json()["detail"]) == (422, f"--friction {MAT_REFUSAL}")
        # A builder the workers cannot receive (a lambda: not importable by name) is neither
        # listed nor answered, in the surface's words.
        outcomes.register("lambda-mat", SoftMat, lambda surface, drag, bounces: SoftMat(0.5))
        try:
            assert outcomes.outcome_model("lambda-mat").depth == 0.5  # in this process
            names = [kind["name"] for kind in api_answer(client.get("/api/surfaces"))["surfaces"]]
            assert names == ["hand", "table", "soft-mat"]
            refused = client.get(f"/api/probability?{query.replace('soft-mat', 'lambda-mat')}")
            assert refused.json()["detail"] == (
                "surface must be one of hand, table, soft-mat; got 'lambda-mat'"
            )
        finally:
            outcomes.unregister("lambda-mat")
        outcomes.unregister("soft-mat")
        refused = client.get(f"/api/probability?{query}")
        assert (refused.status_code, refused.json()["detail"]) == (422, NOT_REGISTERED)
        assert [kind["name"] for kind in api_answer(client.get("/api/surfaces"))["surfaces"]] == [
            "hand",
            "table",
        ]


def test_a_registration_is_checked_in_one_line():
    with pytest.raises(ValueError, match=r"^surface kind 'Soft Mat': a name is lowercase letters"):
        outcomes.register("Soft Mat", SoftMat)
    with pytest.raises(TypeError, match=r"^model must be a subclass of OutcomeModel, got 3"):
        outcomes.register("mat", 3)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"^build must be callable, got str"):
        outcomes.register("mat", SoftMat, "build")  # type: ignore[arg-type]

    class Sand(SoftMat):
        surface_parameters = ("depth",)

    with pytest.raises(ValueError, match=r"^Sand.surface_parameters 'depth': a surface kind take"):
        outcomes.register("sand", Sand)

    class Broken(SoftMat):
        @classmethod
        def from_surface(cls, surface):
            return 3

    outcomes.register("broken", Broken)
    try:
        with pytest.raises(TypeError, match=r"^the builder of surface kind 'broken' gave int, "):
            outcomes.outcome_model("broken")
    finally:
        outcomes.unregister("broken")
    assert list(outcomes.SURFACE_KINDS) == ["hand", "table"]
