"""Chain.from_urdf on small URDFs written here: hand-derived poses, exact screws and
the refusals."""

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
import screwkit.urdf  # noqa: F401  (sk.urdf)


def joint(
    name,
    parent,
    child,
    kind="revolute",
    xyz="0 0 0",
    rpy="0 0 0",
    axis="0 0 1",
    limit=(-3, 3),
    extra="",
):
    limit_tag = (
        ""
        if limit is None
        else (f'<limit lower="{limit[0]}" upper="{limit[1]}" effort="1" velocity="1"/>')
    )
    axis_tag = "" if axis is None else f'<axis xyz="{axis}"/>'
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
        f'<child link="{child}"/><origin xyz="{xyz}" rpy="{rpy}"/>{axis_tag}'
        f"{limit_tag}{extra}</joint>"
    )


def robot(links, joints, name="test"):
    body = "".join(f'<link name="{link}"/>' for link in links)
    return f'<robot name="{name}">{body}{"".join(joints)}</robot>'


TWO_LINK = robot(
    ["base", "l1", "l2", "tool"],
    [
        joint("shoulder", "base", "l1"),
        joint("elbow", "l1", "l2", xyz="0.7 0 0"),
        joint(
            "flange", "l2", "tool", kind="fixed", xyz="0.45 0 0", limit=None, axis=None
        ),
    ],
)


def test_two_link_arm_matches_the_planar_formula():
    arm = sk.Chain.from_urdf(TWO_LINK)
    assert arm.n == 2 and arm.joint_names == ("shoulder", "elbow")
    rng = np.random.default_rng(1)
    for q1, q2 in rng.uniform(-3, 3, (20, 2)):
        T = arm.fk([q1, q2])
        x = 0.7 * np.cos(q1) + 0.45 * np.cos(q1 + q2)
        y = 0.7 * np.sin(q1) + 0.45 * np.sin(q1 + q2)
        np.testing.assert_allclose(T[:3, 3], [x, y, 0], atol=1e-14)
        np.testing.assert_allclose(T[:3, :3], sk.rotz(q1 + q2), atol=1e-14)
    np.testing.assert_array_equal(arm.qlim, [[-3, 3], [-3, 3]])


def test_decimals_are_read_exactly():
    arm = sk.Chain.from_urdf(TWO_LINK)
    screws = arm.twists_symbolic([0, 0])
    assert screws[1] == sp.Matrix([0, 0, 1, 0, -sp.Rational(7, 10), 0])
    M = sk.urdf.read_urdf(TWO_LINK).home  # exact; the chain keeps it as floats
    assert M[0, 3] == sp.Rational(23, 20)


def test_prismatic_joint_and_continuous_joint():
    text = robot(
        ["base", "carriage", "arm"],
        [
            joint(
                "slide",
                "base",
                "carriage",
                kind="prismatic",
                axis="1 0 0",
                limit=(0, 0.5),
            ),
            joint(
                "turn",
                "carriage",
                "arm",
                kind="continuous",
                xyz="0 0 0.2",
                axis="0 0 1",
            ),
        ],
    )
    arm = sk.Chain.from_urdf(text)
    assert [j.value for j in arm.joints] == ["P", "R"]
    np.testing.assert_array_equal(arm.qlim, [[0, 0.5], [-np.inf, np.inf]])
    T = arm.fk([0.3, 0.4])
    np.testing.assert_allclose(T[:3, 3], [0.3, 0, 0.2], atol=1e-15)
    np.testing.assert_allclose(T[:3, :3], sk.rotz(0.4), atol=1e-15)
    assert arm.twists_symbolic([0, 0])[0] == sp.Matrix([0, 0, 0, 1, 0, 0])


def test_quarter_turn_rpy_is_exact_and_axis_is_turned():
    # the elbow's frame is turned +90 deg about x: its z axis is the parent's -y
    text = robot(
        ["base", "l1", "l2"],
        [
            joint("j1", "base", "l1", xyz="0 0 0.1625"),
            joint("j2", "l1", "l2", xyz="0 0.138 0", rpy="1.5707963267948966 0 0"),
        ],
    )
    arm = sk.Chain.from_urdf(text)
    S = arm.twists_symbolic([0, 0])[1]
    # w = (0, -1, 0) through p = (0, 0.138, 0.1625): v = p x w = (0.1625, 0, 0)
    assert S == sp.Matrix([0, -1, 0, sp.Rational(13, 80), 0, 0])
    M = sk.urdf.read_urdf(text).home
    assert M == sp.Matrix(
        [
            [1, 0, 0, 0],
            [0, 0, -1, sp.Rational(138, 1000)],
            [0, 1, 0, sp.Rational(1625, 10000)],
            [0, 0, 0, 1],
        ]
    )
    q = 0.37
    R = sk.rotx(np.pi / 2) @ sk.rotz(q)
    np.testing.assert_allclose(arm.fk([0, q])[:3, :3], R, atol=1e-15)


def test_other_angles_follow_the_urdf_rule():
    # rpy = (r, p, y): R = Rz(y) Ry(p) Rx(r), an independent product
    r, p, y = 0.3, -0.2, 1.1
    text = robot(
        ["base", "l1"],
        [
            joint(
                "j1", "base", "l1", xyz="0.1 0.2 0.3", rpy=f"{r} {p} {y}", axis="0 1 0"
            )
        ],
    )
    arm = sk.Chain.from_urdf(text)
    R0 = sk.rotz(y) @ sk.roty(p) @ sk.rotx(r)
    q = 0.8
    np.testing.assert_allclose(arm.fk([q])[:3, :3], R0 @ sk.roty(q), atol=1e-14)
    np.testing.assert_allclose(arm.fk([q])[:3, 3], [0.1, 0.2, 0.3], atol=1e-15)


def test_fixed_joints_are_folded_between_moving_ones():
    split = robot(
        ["base", "a", "b", "c"],
        [
            joint("j1", "base", "a"),
            joint(
                "mount",
                "a",
                "b",
                kind="fixed",
                xyz="0.3 0 0",
                rpy="0 0 1.5707963267948966",
                limit=None,
            ),
            joint("j2", "b", "c", xyz="0.2 0 0", axis="1 0 0"),
        ],
    )
    arm = sk.Chain.from_urdf(split)
    assert arm.joint_names == ("j1", "j2")
    q1, q2 = 0.4, -0.9
    # after the mount, x of frame b is y of frame a: the elbow sits at (0.3, 0.2) in a
    expected = (
        sk.homogeneous(sk.rotz(q1))
        @ sk.transl(0.3, 0.2, 0)
        @ sk.homogeneous(sk.rotz(np.pi / 2) @ sk.rotx(q2))
    )
    np.testing.assert_allclose(arm.fk([q1, q2]), expected, atol=1e-14)


def test_base_and_tip_links_choose_the_sub_chain():
    tree = robot(
        ["base", "l1", "l2", "left", "right"],
        [
            joint("j1", "base", "l1"),
            joint("j2", "l1", "l2", xyz="1 0 0"),
            joint("fl", "l2", "left", kind="prismatic", axis="0 1 0", limit=(0, 0.04)),
            joint(
                "fr", "l2", "right", kind="prismatic", axis="0 -1 0", limit=(0, 0.04)
            ),
        ],
    )
    with pytest.raises(ValueError, match="branches below 'base'.*left, right"):
        sk.Chain.from_urdf(tree)
    arm = sk.Chain.from_urdf(tree, tip_link="left")
    assert arm.joint_names == ("j1", "j2", "fl")
    wrist = sk.Chain.from_urdf(tree, base_link="l1", tip_link="right")
    assert wrist.joint_names == ("j2", "fr")
    np.testing.assert_allclose(
        wrist.fk([0.5, 0.01])[:3, 3],
        [1 + 0.01 * np.sin(0.5), -0.01 * np.cos(0.5), 0],
        atol=1e-15,
    )
    assert arm.with_tool(sk.transl(0, 0, 0.1)).joint_names == arm.joint_names


def test_a_file_path_is_read(tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(TWO_LINK)
    for source in (path, str(path)):
        assert sk.Chain.from_urdf(source).name == "test"


def test_chains_from_tables_have_no_joint_names():
    assert sk.robots.puma560().joint_names is None


@pytest.mark.parametrize(
    "text, pattern",
    [
        ("<robot name='x'><link name='a'/>", "not well-formed XML"),
        ("<model/>", "<robot> root element"),
        (
            robot(
                ["a", "b", "c"],
                [
                    joint("j1", "a", "b"),
                    joint("j2", "b", "c", extra='<mimic joint="j1"/>'),
                ],
            ),
            "joint 'j2' is a mimic joint",
        ),
        (
            robot(["a", "b"], [joint("free", "a", "b", kind="floating")]),
            "joint 'free' is a floating joint",
        ),
        (
            robot(["a", "b"], [joint("flat", "a", "b", kind="planar")]),
            "joint 'flat' is a planar joint",
        ),
        (
            robot(["a", "b"], [joint("j1", "a", "b", axis="0 0 0")]),
            "joint 'j1' must have a non-zero axis",
        ),
        (
            robot(["a", "b"], [joint("j1", "a", "ghost")]),
            "joint 'j1': its child link 'ghost' is not a link",
        ),
        (
            robot(["a", "b"], [joint("j1", "a", "b", kind="screw")]),
            "joint 'j1' has the unknown type 'screw'",
        ),
        (
            robot(["a", "b"], [joint("j1", "a", "b", xyz="0 0")]),
            "joint 'j1': xyz='0 0' must be 3 numbers",
        ),
        (
            robot(["a", "b"], [joint("j1", "a", "b", limit=(1, -1))]),
            "joint 'j1': limit lower must be below upper",
        ),
        (robot(["a", "b"], [joint("j1", "a", "b", kind="fixed")]), "no moving joint"),
    ],
)
def test_refusals_name_the_joint_or_link(text, pattern):
    with pytest.raises(ValueError, match=pattern):
        sk.Chain.from_urdf(text)


def test_unknown_links_and_bad_arguments():
    with pytest.raises(
        ValueError, match="tip_link must be a link of the URDF .*, got 'hand'"
    ):
        sk.Chain.from_urdf(TWO_LINK, tip_link="hand")
    with pytest.raises(
        ValueError, match="base_link must be a link of the URDF .*, got 'hand'"
    ):
        sk.Chain.from_urdf(TWO_LINK, base_link="hand")
    with pytest.raises(ValueError, match="tip_link 'l1' is not below base_link 'l2'"):
        sk.Chain.from_urdf(TWO_LINK, base_link="l2", tip_link="l1")
    with pytest.raises(TypeError, match="tip_link must be a link name"):
        sk.Chain.from_urdf(TWO_LINK, tip_link=3)
    with pytest.raises(TypeError, match="source must be URDF text or a file path"):
        sk.Chain.from_urdf(42)
    with pytest.raises(ValueError, match="which is no file"):
        sk.Chain.from_urdf("no/such/file.urdf")


def test_mimic_joints_off_the_path_are_allowed():
    tree = robot(
        ["base", "l1", "f1", "f2"],
        [
            joint("j1", "base", "l1"),
            joint("finger1", "l1", "f1", kind="prismatic", limit=(0, 0.04)),
            joint(
                "finger2",
                "l1",
                "f2",
                kind="prismatic",
                limit=(0, 0.04),
                extra='<mimic joint="finger1"/>',
            ),
        ],
    )
    assert sk.Chain.from_urdf(tree, tip_link="f1").joint_names == ("j1", "finger1")
    with pytest.raises(ValueError, match="joint 'finger2' is a mimic joint"):
        sk.Chain.from_urdf(tree, tip_link="f2")
