"""The other side of the bad-input contract: valid edge cases are answers, not errors
(NumPy integers, empty batches, SymPy reals, a symbolic universal joint, a student's
unreadable answer), one message for a non-chain everywhere, and no function changes its
input. The builders are table_core's."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import settings
from table_core import T_STEPS, arm, arm2, ax2, ax3, path, puma, q0
from table_screws import O, theta

import screwkit as sk
from screwkit import exercises, limbs
from screwkit import plotting as pl
from screwkit import redundancy as rd
from screwkit import workspace as ws


def test_a_universal_joint_with_symbolic_perpendicular_axes_is_valid():
    """A valid U, perpendicular for every theta (the control row of the joint table)."""
    limb = limbs.universal(
        [sp.cos(theta), sp.sin(theta), 0], [-sp.sin(theta), sp.cos(theta), 0], O
    )
    assert len(limb) == 2


def test_a_wrong_typed_answer_is_a_verdict_not_an_error():
    """check() reads what a student types: unreadable input is a wrong verdict."""
    verdict = exercises.check("parallel_kinematics", 10, None)
    assert not verdict.correct and "Could not read" in verdict.message


def test_a_non_chain_gets_one_message_everywhere():
    for call in (
        lambda: ws.sweep("puma", {1: (0, 1)}),
        lambda: pl.draw_chain(ax3(), "puma", [0] * 6),
    ):
        with pytest.raises(
            TypeError, match=r"^chain must be a screwkit Chain .*got 'puma' \(str\)"
        ):
            call()


# ---- valid edge cases are answers ----------------------------------------------------


def test_numpy_integer_scalars_are_real_numbers():
    assert np.array_equal(sk.rotz(np.int64(0)), np.eye(3))
    assert np.array_equal(
        sk.transl(np.int32(1), np.int64(2), np.uint8(3))[:3, 3], [1, 2, 3]
    )
    assert (
        sk.twist_from_axis([0, 0, 1], [1, 0, 0], np.int64(2))[5] == 2.0
    )  # r x s + h s
    assert ws.sweep(arm2(), {np.int64(1): (0, 1)}, num=np.int64(3)).shape == (3,)


def test_empty_batches_give_empty_results():
    assert sk.rotz([]).shape == (0, 3, 3)
    assert sk.rot_axis([0, 0, 1], np.zeros(0)).shape == (0, 3, 3)
    assert sk.transl(np.zeros((0, 3))).shape == (0, 4, 4)
    assert sk.inv(np.zeros((0, 4, 4))).shape == (0, 4, 4)
    assert sk.exp_twist([0, 0, 1, 0, 0, 0], []).shape == (0, 4, 4)
    assert sk.homogeneous(np.zeros((0, 3, 3))).shape == (0, 4, 4)
    assert rd.timing(np.zeros(0), 1.0)[0].shape == (0,)


def test_sympy_reals_are_accepted_where_numbers_are_meant():
    assert np.allclose(
        np.array(sk.rotz(sp.Float(0.5)), dtype=float), sk.rotz(0.5)
    )  # exact in, out
    assert isinstance(sk.rotz(sp.Float(0.5)), sp.MatrixBase)
    assert sk.transl([sp.Rational(1, 2), 0, 0])[0, 3] == sp.Rational(1, 2)


def test_the_hypothesis_profile_is_derandomized():
    assert settings.default.derandomize and settings.default.database is None


# ---- nothing changes its input -------------------------------------------------------


def _mutation_calls():
    T = sk.transl(1, 2, 3) @ sk.homogeneous(sk.rotz(0.3))
    yield "rotz", sk.rotz, (np.array([0.1, 0.2]),)
    yield "skew", sk.skew, (np.array([1.0, 2.0, 3.0]),)
    yield "rot_axis", sk.rot_axis, (np.array([1e200, 0.0, 0.0]), np.array([0.1, 0.2]))
    yield "transl", sk.transl, (np.array([[1.0, 2.0, 3.0]]),)
    yield "homogeneous", sk.homogeneous, (sk.rotz(0.2), np.array([1.0, 2.0, 3.0]))
    yield "inv", sk.inv, (T,)
    yield (
        "twist_from_axis",
        sk.twist_from_axis,
        (np.array([0.0, 0.0, 2.0]), np.array([1.0, 0, 0]), 0.5),
    )
    yield (
        "exp_twist",
        sk.exp_twist,
        (np.array([0, 0, 2.0, 1, 0, 0]), np.array([0.1, 0.2])),
    )
    yield "screw_motion", sk.screw_motion, ([0, 0, 1], [1, 0, 0], 0.1, [0.5, 1.0])
    yield (
        "sweep",
        ws.sweep,
        (arm2(), {1: np.array([0.0, 1.0])}, np.array([3]), np.array([0.0, 0.5])),
    )
    yield (
        "start_configuration",
        rd.start_configuration,
        (arm(), np.array([0.5, 0.1]), np.array([0.3, 0.6, 0.6])),
    )
    yield "resolve", rd.resolve, (arm(), path(), q0().copy())
    yield (
        "planar_kinematics",
        rd.planar_kinematics,
        (np.array([0.4, 0.3, 0.2]), np.array([0.1, 0.2, 0.3])),
    )
    yield (
        "pseudo_inverse",
        rd.pseudo_inverse,
        (np.array([[1.0, 0.5, 0.2], [0.0, 0.3, 0.1]]), 0.1, 10.0),
    )
    yield "timing", rd.timing, (np.array([0.0, 0.5, 1.0]), 1.0)
    yield "draw_frame", pl.draw_frame, (ax3(), T)
    yield "draw_chain", pl.draw_chain, (ax3(), puma(), np.zeros(6))
    yield "draw_planar", pl.draw_planar, (ax2(), arm2(), np.array([0.1, 0.2]))
    yield (
        "draw_ellipsoid",
        pl.draw_ellipsoid,
        (ax3(), np.zeros(3), np.ones(3), np.eye(3)),
    )


def _copy(value):
    if isinstance(value, dict):
        return {k: _copy(v) for k, v in value.items()}
    return (
        np.array(value, copy=True) if isinstance(value, (np.ndarray, list)) else value
    )


def _same(a, b):
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, (np.ndarray, list)):
        return np.array_equal(np.asarray(a), np.asarray(b))
    return True


MUTATION_NAMES = [
    "rotz",
    "skew",
    "rot_axis",
    "transl",
    "homogeneous",
    "inv",
    "twist_from_axis",
    "exp_twist",
    "screw_motion",
    "sweep",
    "start_configuration",
    "resolve",
    "planar_kinematics",
    "pseudo_inverse",
    "timing",
    "draw_frame",
    "draw_chain",
    "draw_planar",
    "draw_ellipsoid",
]


def test_the_mutation_table_names_every_call():
    assert [c[0] for c in _mutation_calls()] == MUTATION_NAMES


@pytest.mark.parametrize("name", MUTATION_NAMES)
def test_no_function_changes_its_input(name):
    # the calls are built lazily, up to the one asked for (robots and axes on first use)
    _, function, arguments = next(c for c in _mutation_calls() if c[0] == name)
    before = [_copy(a) for a in arguments]
    function(*arguments)
    assert all(_same(a, b) for a, b in zip(before, arguments))


def test_a_path_keeps_its_own_copy_of_the_arrays():
    t, position = T_STEPS.copy(), np.ones((5, 2))
    path = rd.Path(t, position, np.zeros((5, 2)))
    t[:], position[:] = 7.0, 7.0
    assert np.array_equal(path.t, T_STEPS) and np.all(path.position == 1.0)
