"""One kernel per idea: one pitch test, one pose check, one cross product, one twist of
an axis; the public functions that use them agree."""

import math

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit import _checks, links, urdf, viewer
from screwkit.transforms import _cross, axis_coordinates

# ---- one pitch test ---------------------------------------------------------------


@pytest.mark.parametrize("infinity", [math.inf, np.inf, np.float64("inf"), sp.oo])
def test_screw_motion_and_its_viewer_agree_on_a_translation(infinity):
    # an infinite pitch: a translation by theta along the unit s, whatever r
    T = sk.screw_motion([0, 0, 2], [5, 6, 7], infinity, 0.3)
    np.testing.assert_allclose(np.asarray(T, dtype=float)[:3, 3], [0, 0, 0.3])
    figure = viewer.screw_motion_viewer([0, 0, 2], [5, 6, 7], infinity)
    assert figure.model["h"] is None and figure.model["slider"]["unit"] == "m"


@pytest.mark.parametrize("pitch", ["inf", "0.5", -math.inf, math.nan, None])
def test_every_pitch_taker_refuses_a_string_or_a_non_finite_pitch_alike(pitch):
    error = ValueError if isinstance(pitch, float) else TypeError
    calls = [
        lambda: sk.screw_motion([0, 0, 1], [0, 0, 0], pitch, 0.3),
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], pitch),
        lambda: viewer.screw_motion_viewer([0, 0, 1], [0, 0, 0], pitch),
        lambda: sk.Screw.from_axis([0, 0, 1], [0, 0, 0], pitch),
    ]
    messages = set()
    for call in calls:
        with pytest.raises(error, match="h must be a pitch") as caught:
            call()
        messages.add(str(caught.value))
    assert len(messages) == 1  # one check, one sentence


def test_a_finite_pitch_is_drawn_as_the_motion_computes_it():
    figure = viewer.screw_motion_viewer([0, 0, 1], [1, 0, 0], np.float64(0.25))
    assert figure.model["h"] == 0.25
    # the motion of pitch 0.25 by pi/2 about z through (1, 0, 0): the origin turns to
    # (1, -1, 0) and rises by 0.25 pi / 2
    T = sk.screw_motion([0, 0, 1], [1, 0, 0], 0.25, np.pi / 2)
    np.testing.assert_allclose(T[:3, 3], [1, -1, np.pi / 8], atol=1e-12)


# ---- one pose check -----------------------------------------------------------------


def test_the_fast_pass_and_the_full_check_agree():
    rng = np.random.default_rng(3)
    angles = rng.uniform(-np.pi, np.pi, 20)
    T = sk.homogeneous(sk.rotz(angles), rng.normal(size=(20, 3)))
    assert _checks.check_poses(T) is T  # a float batch passes untouched
    reflected = T.copy()
    reflected[7, :3, 2] *= -1  # det -1: R^T R is still I
    with pytest.raises(ValueError, match="determinant \\+1"):
        _checks.check_poses(reflected)
    bad_row = T.copy()
    bad_row[4, 3, 0] = 1e-3
    with pytest.raises(ValueError, match="last row"):
        _checks.check_poses(bad_row)
    with pytest.raises(ValueError, match="must be one pose of shape"):
        _checks.check_poses(T, single_only=True)


def test_a_chain_base_uses_the_one_pose_check():
    with pytest.raises(ValueError, match="base must be one pose of shape"):
        links.rigid(np.stack([np.eye(4)] * 2), "base")
    base = links.rigid(sk.transl(1, 2, 3), "base")
    assert not base.flags.writeable and base[0, 3] == 1.0


# ---- one cross product and one twist of an axis ------------------------------------


def test_the_kernel_cross_product_of_single_vectors_and_batches():
    a, b = np.array([1.0, 2.0, 3.0]), np.array([-4.0, 0.5, 2.0])
    # by the determinant formula written out
    expected = [2 * 2 - 3 * 0.5, 3 * -4 - 1 * 2, 1 * 0.5 - 2 * -4]
    np.testing.assert_allclose(_cross(a, b), expected)
    batch = _cross(np.stack([a, b], axis=1), np.stack([b, a], axis=1))
    np.testing.assert_allclose(batch[:, 0], expected)
    np.testing.assert_allclose(batch[:, 1], -np.asarray(expected))


def test_a_urdf_joint_twist_is_the_twist_of_its_axis():
    text = """<robot name="r">
      <link name="a"/><link name="b"/><link name="c"/>
      <joint name="j1" type="revolute"><parent link="a"/><child link="b"/>
        <origin xyz="1 0 0"/><axis xyz="0 0 1"/>
        <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
      <joint name="j2" type="prismatic"><parent link="b"/><child link="c"/>
        <origin xyz="0 2 0"/><axis xyz="1 0 0"/>
        <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
    </robot>"""
    axes = urdf.read_urdf(text).axes
    # z through (1, 0, 0): (0, 0, 1; (1, 0, 0) x (0, 0, 1) = (0, -1, 0)); x sliding
    assert list(axes[0]) == [0, 0, 1, 0, -1, 0]
    assert list(axes[1]) == [0, 0, 0, 1, 0, 0]
    s, r = sp.Matrix([0, 0, 1]), sp.Matrix([1, 0, 0])
    assert axes[0] == axis_coordinates(s, r, 0)
