"""Workspace sweeps: the two-link annulus, the Kawasaki paper's extents, bad input."""

import numpy as np
import pytest

import screwkit as sk

DEG = np.pi / 180


def test_two_link_sweep_fills_the_annulus():
    l1, l2 = 1.0, 0.4
    s = sk.workspace.sweep(
        sk.robots.planar([l1, l2]),
        {1: (-np.pi, np.pi), 2: (-np.pi, np.pi)},
        num=(73, 91),
    )
    assert s.shape == (73, 91) and s.points.shape == (73, 91, 3)
    inner, outer = s.reach([0, 0, 0])
    assert np.isclose(inner, l1 - l2) and np.isclose(outer, l1 + l2)
    # every point is q1, q2 of its grid entry
    q1, q2 = s.q[..., 0], s.q[..., 1]
    expected = np.stack(
        [
            l1 * np.cos(q1) + l2 * np.cos(q1 + q2),
            l1 * np.sin(q1) + l2 * np.sin(q1 + q2),
        ],
        -1,
    )
    assert np.allclose(s.points[..., :2], expected, atol=1e-12)


def test_kawasaki_conclusion_extents_come_from_a_ten_degree_grid():
    # the paper's conclusion: x from -2114.7 to 2945.4 mm and "y" (the height z) from
    # -905.4 to 3195.4 mm
    robot = sk.robots.kawasaki_cx210l()
    coarse = sk.workspace.sweep(
        robot, {2: (30 * DEG, 180 * DEG), 3: (-90 * DEG, 60 * DEG)}, num=(16, 16)
    )
    x, z = (np.array(coarse.extents()[axis]) * 1000 for axis in "xz")
    assert np.allclose(x, [-2114.7, 2945.4], atol=0.1) and np.allclose(
        z, [-905.4, 3195.4], atol=0.1
    )
    # the full reach from the shoulder is a1 + a2 + sqrt(a3^2 + (d4 + d6)^2) away in the
    # arm plane
    shoulder = [0.3, 0, 0.55]
    fine = sk.workspace.sweep(
        robot, {2: (30 * DEG, 180 * DEG), 3: (-90 * DEG, 60 * DEG)}, num=1501
    )
    assert np.isclose(fine.reach(shoulder)[1], 1.19 + np.hypot(0.3, 1.425), atol=1e-6)


def test_sweep_determinant_changes_sign_across_the_elbow_singularity():
    robot = sk.robots.kawasaki_cx210l()
    s = sk.workspace.sweep(
        robot, {3: (-80 * DEG, -70 * DEG)}, num=101, q=np.radians([0, 60, 0, 0, 90, 0])
    )
    det = s.determinant()
    crossing = np.flatnonzero(np.diff(np.sign(det)))
    assert crossing.size == 1
    assert (
        s.values[0][crossing[0]]
        <= np.arctan2(-1.19, 0.3)
        <= s.values[0][crossing[0] + 1]
    )
    # the singular mask marks the two grid points on either side of the crossing, and
    # nothing else
    assert np.flatnonzero(s.singular()).tolist() == [crossing[0], crossing[0] + 1]


def test_bad_sweeps_are_clear_errors():
    arm = sk.robots.planar([1.0, 1.0])
    with pytest.raises(TypeError, match="ranges must be a dict"):
        sk.workspace.sweep(arm, [(0, 1)])
    with pytest.raises(ValueError, match="joint numbers 1..2"):
        sk.workspace.sweep(arm, {0: (0, 1)})
    with pytest.raises(ValueError, match=r"ranges\[1\] must be \(low, high\)"):
        sk.workspace.sweep(arm, {1: (0, 1, 2)})
    with pytest.raises(ValueError, match="num must be an integer >= 2"):
        sk.workspace.sweep(arm, {1: (0, 1)}, num=1)
    with pytest.raises(ValueError, match="finite"):
        sk.workspace.sweep(arm, {1: (0, np.nan)})
    with pytest.raises(
        ValueError, match=r"rows must select 2 rows, one per joint, for det J"
    ):
        sk.workspace.sweep(arm, {1: (0, 1)}).determinant()


def test_section_of_a_solid_sweep_is_the_swept_plane():
    robot = sk.robots.kawasaki_cx210l()
    solid = sk.workspace.sweep(
        robot,
        {1: (-np.pi, np.pi), 2: (30 * DEG, 180 * DEG), 3: (-90 * DEG, 60 * DEG)},
        num=(73, 31, 31),
    )
    cut = solid.section("y", 0.0, tolerance=1e-9)
    plane = sk.workspace.sweep(
        robot, {2: (30 * DEG, 180 * DEG), 3: (-90 * DEG, 60 * DEG)}, num=31
    )
    assert np.all(np.abs(cut[:, 1]) <= 1e-9)
    # it holds the plane sweep at q1 = 0 and its mirror at q1 = +-pi (the section turned
    # half way)
    expected = np.concatenate(
        [plane.points.reshape(-1, 3), plane.points.reshape(-1, 3) * [-1, 1, 1]]
    )
    nearest = np.min(
        np.linalg.norm(expected[:, None, [0, 2]] - cut[None, :, [0, 2]], axis=-1),
        axis=1,
    )
    assert np.all(nearest < 1e-9)
    with pytest.raises(ValueError, match="axis must be"):
        solid.section("w")


def test_planar_singular_points_are_found_with_the_planar_rows():
    # A two-link arm is singular exactly where det [[-l1 s1 - l2 s12, -l2 s12], [l1 c1 +
    # l2 c12, l2 c12]] = l1 l2 sin q2 vanishes: on this grid, the 33 points with q2 = 0
    # (q2 in [-1, 1] holds no +-pi).
    l1, l2 = 1.0, 0.5
    s = sk.workspace.sweep(
        sk.robots.planar([l1, l2]), {1: (-np.pi, np.pi), 2: (-1.0, 1.0)}, num=33
    )
    mask = s.singular(rows="planar")
    assert mask.sum() == 33 and np.all(s.q[mask][:, 1] == 0.0)
    assert np.allclose(
        s.determinant(rows="planar"), l1 * l2 * np.sin(s.q[..., 1]), atol=1e-12
    )
    # all six rows keep rank 2 (the angular rows z, z and the planar rows differ): none
    # found
    assert s.singular().sum() == 0


def test_planar_singular_lines_between_grid_points_mark_both_neighbours():
    # q2 from -0.95 to 1.05 in steps of 1/16 passes q2 = 0 between two grid columns
    s = sk.workspace.sweep(
        sk.robots.planar([1.0, 0.5]), {1: (0.0, 1.0), 2: (-0.95, 1.05)}, num=(5, 33)
    )
    mask = s.singular(rows="planar")
    columns = np.flatnonzero(mask.any(axis=0))
    assert mask.sum() == 10 and len(columns) == 2
    assert s.values[1][columns[0]] < 0 < s.values[1][columns[1]]


def test_a_sweep_too_large_is_refused_up_front_with_its_size_and_a_suggestion():
    puma = sk.robots.puma560()
    with pytest.raises(
        ValueError,
        match=r"at most max_configurations = 10,000,000 configurations, "
        r"got 301 x 301 x 301 = 27,270,901 .* num=215",
    ):
        sk.workspace.sweep(puma, {1: (0, 1), 2: (0, 1), 3: (0, 1)})
    with pytest.raises(
        ValueError,
        match=r"got 301 x 301 x 301 x 301 = 8,208,541,201 \(its points alone "
        r"would take 197.00 GB\)",
    ):
        sk.workspace.sweep(puma, {1: (0, 1), 2: (0, 1), 3: (0, 1), 4: (0, 1)})
    # the limit is a keyword: 3 x 3 x 3 = 27 configurations need max_configurations >=
    # 27
    with pytest.raises(ValueError, match="got 3 x 3 x 3 = 27"):
        sk.workspace.sweep(
            puma, {1: (0, 1), 2: (0, 1), 3: (0, 1)}, num=3, max_configurations=26
        )
    assert (
        sk.workspace.sweep(
            puma, {1: (0, 1), 2: (0, 1), 3: (0, 1)}, num=3, max_configurations=27
        ).size
        == 27
    )


def test_chunked_results_equal_one_batched_call(monkeypatch):
    robot = sk.robots.kawasaki_cx210l()
    monkeypatch.setattr(sk.workspace, "CHUNK", 7)  # many chunks, the last one partial
    s = sk.workspace.sweep(
        robot,
        {2: (0.5, 3.0), 3: (-1.5, 1.0)},
        num=(9, 11),
        q=[0.1, 0, 0, 0.2, 0.3, 0.4],
    )
    flat_q = s.q.reshape(-1, 6)
    assert np.array_equal(
        flat_q[:, [0, 3, 4, 5]], np.tile([0.1, 0.2, 0.3, 0.4], (99, 1))
    )
    assert np.allclose(s.points.reshape(-1, 3), robot.fk(flat_q)[:, :3, 3], atol=1e-15)
    J = robot.geometric_jacobian(flat_q)
    assert np.allclose(s.jacobians().reshape(-1, 6, 6), J, atol=1e-15)
    assert np.allclose(s.determinant().ravel(), np.linalg.det(J), atol=1e-15)
    assert np.allclose(
        s.manipulability("position").ravel(),
        robot.manipulability(flat_q, rows="position"),
    )


def test_results_larger_than_the_stated_limit_are_refused(monkeypatch):
    s = sk.workspace.sweep(sk.robots.planar([1.0, 0.5]), {1: (0, 1), 2: (0, 1)}, num=10)
    monkeypatch.setattr(sk.workspace, "MAX_RESULT_BYTES", 1000)
    with pytest.raises(
        ValueError, match=r"Sweep.jacobians would build one array of 0.00 GB.*stream"
    ):
        s.jacobians()
    with pytest.raises(ValueError, match=r"Sweep.q would build one array"):
        _ = s.q
    assert s.manipulability("planar").shape == (10, 10)  # streams: no limit
