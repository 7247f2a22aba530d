"""MuJoCo's friction made harder (coinflight.studies.mujoco_compare.FrictionSolver): the cone,
impratio and the no-slip pass reach MuJoCo's model, bad values are refused in one line, the
run reports them, and they do what MuJoCo documents (less creep of a contact that should
stick)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from coinflight import _validation
from coinflight.model.coin import Coin
from coinflight.studies import mujoco_compare as mc

mujoco = pytest.importorskip("mujoco")

NICKEL = Coin.preset("us-nickel")


def test_the_solver_reaches_the_model():
    hard = mc.FrictionSolver("elliptic", 10.0, 0)
    m = mc.model(NICKEL, 0.3, 0.5, engine=mc.Engine(condim=3, solver=hard))
    assert m.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC and m.opt.impratio == 10.0
    assert m.opt.noslip_iterations == 0
    m = mc.model(NICKEL, 0.3, 0.5, engine=mc.Engine(solver=mc.FrictionSolver(noslip_iterations=20)))
    assert m.opt.cone == mujoco.mjtCone.mjCONE_PYRAMIDAL and m.opt.impratio == 1.0
    assert m.opt.noslip_iterations == 20
    # The default is MuJoCo's: the comparison's model is unchanged.
    m = mc.model(NICKEL, 0.3, 0.5)
    assert m.opt.cone == mujoco.mjtCone.mjCONE_PYRAMIDAL and m.opt.impratio == 1.0
    assert m.opt.noslip_iterations == 0 and mc.FrictionSolver() == mc.DEFAULT_SOLVER


def test_numpy_numbers_reach_the_model_as_numbers():
    solver = mc.FrictionSolver("elliptic", np.float64(10.0), np.int64(5))
    assert type(solver.impratio) is float and type(solver.noslip_iterations) is int
    assert 'impratio="10.0"' in solver.option() and "np." not in solver.option()
    m = mc.model(NICKEL, 0.3, 0.5, engine=mc.Engine(condim=3, solver=solver))
    assert m.opt.impratio == 10.0 and m.opt.noslip_iterations == 5
    assert solver == mc.FrictionSolver("elliptic", 10.0, 5)


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        (
            {"cone": "conic"},
            ValueError,
            "MuJoCo cone must be one of pyramidal, elliptic; got 'conic'",
        ),
        ({"impratio": 0.0}, ValueError, "MuJoCo impratio must be a positive number, got 0.0"),
        ({"impratio": math.inf}, ValueError, "MuJoCo impratio must be a positive number, got inf"),
        ({"impratio": True}, ValueError, "MuJoCo impratio must be a positive number, got True"),
        ({"noslip_iterations": -1}, ValueError, "between 0 and 100, got -1"),
        (
            {"noslip_iterations": 101},
            ValueError,
            "MuJoCo noslip_iterations must be between 0 and 100, got 101",
        ),
        ({"noslip_iterations": 2.0}, TypeError, "MuJoCo noslip_iterations must be an integer"),
    ],
)
def test_bad_solver_values_are_refused_in_one_line(kwargs, error, words):
    with pytest.raises(error, match=words.replace("(", r"\(").replace(")", r"\)")) as caught:
        mc.FrictionSolver(**kwargs)
    assert "\n" not in str(caught.value)


def test_a_harder_solver_raises_the_work_estimate():
    # Measured factors (benchmarks/bench_mujoco_edges.py's notes, 446 hand-off states): elliptic
    # impratio 10 1,154 s, impratio 100 2,493 s (2.2 times), 20 no-slip iterations 2,195 s (1.9).
    base = mc.seconds_estimate(1000, 20.0)
    assert mc.seconds_estimate(1000, 20.0, solver=mc.FrictionSolver("elliptic", 10.0)) == base
    hard = mc.seconds_estimate(1000, 20.0, solver=mc.FrictionSolver("elliptic", 100.0))
    assert hard == pytest.approx(2.2 * base, rel=1e-12)
    noslip = mc.seconds_estimate(1000, 20.0, solver=mc.FrictionSolver(noslip_iterations=20))
    assert noslip == pytest.approx(1.9 * base, rel=1e-12)
    # The bound sees the solver: a run the default solver may do, the hardest may not.
    n = int(_validation.MAX_RUN_SECONDS / (base / 1000) * 0.9)
    mc.bound([n], 20.0)
    hardest = mc.FrictionSolver("elliptic", 100.0, mc.MAX_NOSLIP_ITERATIONS)
    with pytest.raises(ValueError, match="MuJoCo tosses") as caught:
        mc.bound([n], 20.0, solver=hardest)
    assert "\n" not in str(caught.value)


def test_a_solver_must_be_a_friction_solver():
    with pytest.raises(TypeError, match=r"solver must be a mujoco_compare\.FrictionSolver"):
        mc.Engine(solver="elliptic")  # type: ignore[arg-type]


def _creep(solver: mc.FrictionSolver) -> float:
    """Distance (m) a nickel lying flat creeps in 0.5 s under a horizontal push of half its
    friction limit (μ 0.3, condim 3): Coulomb friction would hold it still."""
    m = mc.model(NICKEL, 0.3, 1.0, engine=mc.Engine(condim=3, solver=solver))
    d = mujoco.MjData(m)
    d.qpos[:3] = (0.0, 0.0, NICKEL.thickness / 2)
    for _ in range(2000):  # settle, 0.2 s
        mujoco.mj_step(m, d)
    x0 = float(d.qpos[0])
    d.xfrc_applied[1, 0] = 0.5 * 0.3 * NICKEL.mass * 9.81
    for _ in range(5000):
        mujoco.mj_step(m, d)
    return float(d.qpos[0]) - x0


def test_harder_friction_creeps_less():
    # MuJoCo's soft friction lets a contact below its friction limit creep (measured 0.013 mm
    # in 0.5 s with the 1 ms time constant); impratio 100 with the elliptic cone makes the
    # friction impedance 100 times the normal's and the no-slip pass removes the creep: both
    # cut it by more than 10 (measured ~100 and ~36 times).
    soft = _creep(mc.FrictionSolver("elliptic", 1.0))
    assert soft > 5e-6
    assert _creep(mc.FrictionSolver("elliptic", 100.0)) < soft / 10
    assert _creep(mc.FrictionSolver(noslip_iterations=20)) < soft / 10


def test_a_run_reports_its_solver():
    solver = mc.FrictionSolver("elliptic", 10.0, 5)
    hh = NICKEL.thickness / 2
    run = mc.run_from(
        NICKEL,
        np.array([hh + 1e-4]),
        np.zeros((1, 3)),
        np.array([[0.0, 0.0, 1.0]]),
        np.zeros((1, 3)),
        0.5,
        0.3,
        1.0,
        threads=1,
        engine=mc.Engine(condim=3, limit=0.5, solver=solver),
    )
    assert run.engine.solver == solver
    settings = run.settings(0.3)
    assert settings["cone"] == "elliptic" and settings["impratio"] == 10.0
    assert settings["noslip_iterations"] == 5
    assert run.rest.tolist() == [1] and run.unsettled == 0


def test_solimp_reaches_the_model_and_the_default_is_mujocos():
    # MuJoCo's own default solimp is (0.9, 0.95, 0.001, 0.5, 2) (XML reference, geom/solimp):
    # a model without the attribute and the comparison's default model agree on all five.
    plain = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><geom type="plane" size="1 1 0.1"/></worldbody></mujoco>'
    )
    m = mc.model(NICKEL, 0.3, 0.5)
    assert np.array_equal(m.geom_solimp, np.vstack([plain.geom_solimp[0]] * 2))
    assert mc.DEFAULT_SOLVER.solimp == mc.SOLIMP == tuple(plain.geom_solimp[0, :3])
    soft = mc.FrictionSolver(solimp=(np.float64(0.1), 0.95, 3e-5))
    assert type(soft.solimp[0]) is float and "np." not in soft.contact()
    m = mc.model(NICKEL, 0.3, 0.5, engine=mc.Engine(condim=3, solver=soft))
    assert np.allclose(m.geom_solimp[:, :3], [[0.1, 0.95, 3e-5]] * 2, rtol=0, atol=0)
    assert np.allclose(m.geom_solimp[:, 3:], plain.geom_solimp[0, 3:], rtol=0, atol=0)
    assert soft.settings()["solimp"] == [0.1, 0.95, 3e-5]


@pytest.mark.parametrize(
    "solimp",
    [(0.9, 0.95), (0.0, 0.95, 0.001), (0.9, 1.0, 0.001), (0.9, 0.95, 0.0), (0.9, 0.95, math.nan),
     (True, 0.95, 0.001), "0.9 0.95 0.001", 0.9],
)  # fmt: skip
def test_bad_solimp_is_refused_in_one_line(solimp):
    with pytest.raises(ValueError, match="MuJoCo solimp must be three numbers") as caught:
        mc.FrictionSolver(solimp=solimp)
    assert "\n" not in str(caught.value)


def test_a_soft_first_touch_lengthens_a_slow_rim_contact():
    # The impedance d0 at zero penetration sets how soft MuJoCo's contact is at first touch: a
    # nickel dropped upright on its rim at 0.1 m/s stays in contact longer with d0 = 0.1 than
    # with MuJoCo's default 0.9 (each with the damping calibrated to e 0.5 by a flat drop).
    def contact_steps(solver):
        zeta = mc.calibrated_damping(NICKEL, 0.5, 2.0, engine=mc.Engine(condim=3, solver=solver))
        m = mc.model(NICKEL, 0.0, zeta, engine=mc.Engine(condim=3, solver=solver))
        d = mujoco.MjData(m)
        d.qpos[:3] = (0.0, 0.0, NICKEL.radius + 1e-6)
        d.qpos[3:7] = (math.sqrt(0.5), math.sqrt(0.5), 0.0, 0.0)  # heads normal horizontal
        d.qvel[2] = -0.1
        touched = steps = 0
        for _ in range(400):
            mujoco.mj_step(m, d)
            if d.ncon:
                touched, steps = 1, steps + 1
            elif touched:
                break
        return steps

    default = contact_steps(mc.DEFAULT_SOLVER)
    soft = contact_steps(mc.FrictionSolver(solimp=(0.1, 0.95, 3e-5)))
    assert 0 < default < soft


def test_timeconst_reaches_the_model_and_the_settings():
    m = mc.model(NICKEL, 0.3, 0.25)
    assert np.all(m.geom_solref == [[mc.TIMECONST, 0.25]] * 2)
    slow = mc.FrictionSolver(timeconst=np.float64(4e-3))
    assert type(slow.timeconst) is float
    m = mc.model(NICKEL, 0.3, 0.25, engine=mc.Engine(solver=slow))
    assert np.all(m.geom_solref == [[4e-3, 0.25]] * 2)
    assert slow.settings()["timeconst"] == 4e-3


@pytest.mark.parametrize("tau", [1e-4, 0.2, math.nan, math.inf])
def test_bad_timeconst_is_refused_in_one_line(tau):
    # _validation's wording for a range (v.in_range).
    with pytest.raises(
        ValueError, match=r"MuJoCo timeconst must be between 0\.0002 and 0\.1 \(in s\), got"
    ):
        mc.FrictionSolver(timeconst=tau)


@pytest.mark.parametrize("tau", [True, "1e-3", (1e-3, 2e-3)])
def test_a_timeconst_that_is_not_one_number_is_refused(tau):
    # _validation's wordings for a value that is no number (a bool, a string) or several.
    words = r"MuJoCo timeconst must be (a number or an array of numbers|a single number), got"
    with pytest.raises(TypeError, match=words) as caught:
        mc.FrictionSolver(timeconst=tau)
    assert "\n" not in str(caught.value)


def _flat_slide_in_mujoco(friction):
    """A nickel lying flat on the plane, set sliding at 0.5 m/s: (share of 300 steps in
    contact, largest upward speed m/s) in MuJoCo (condim 3, the comparison's settings)."""
    zeta = mc.calibrated_damping(NICKEL, 0.5, 4.55, engine=mc.Engine(condim=3, integrator="Euler"))
    m = mc.model(NICKEL, friction, zeta, engine=mc.Engine(condim=3, integrator="Euler"))
    d = mujoco.MjData(m)
    d.qpos[:3] = (0.0, 0.0, NICKEL.thickness / 2)
    for _ in range(300):  # settle at rest on the face
        mujoco.mj_step(m, d)
    d.qvel[:] = 0.0
    d.qvel[0] = 0.5
    on, up = 0, -math.inf
    for _ in range(300):
        mujoco.mj_step(m, d)
        on += d.ncon > 0
        up = max(up, float(d.qvel[2]))
    return on / 300, up


def test_a_sliding_contact_lifts_in_mujoco():
    # MuJoCo's convex soft contact moves a sliding contact apart ("the only way to initiate
    # slip is to generate some motion in the normal direction", its documentation); without
    # friction it stays pressed. Measured: in contact 7 % of the steps, rising at up to
    # 32 mm/s with μ 0.3, 89 % frictionless.
    share, up = _flat_slide_in_mujoco(0.3)
    assert share < 0.3 and up > 0.01
    share0, up0 = _flat_slide_in_mujoco(0.0)
    assert share0 > 0.8 and up0 < 0.002
