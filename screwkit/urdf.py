"""URDF to joint screws: the product of exponentials of a robot description file.

A URDF (Unified Robot Description Format) file describes a robot as a tree of links
joined by joints; each joint has an ``origin`` (its frame in the parent link's frame,
xyz in m and rpy in rad, R = Rz(yaw) Ry(pitch) Rx(roll)), an ``axis`` in its own frame
and ``limit``\\ s. :func:`read_urdf` walks the path from a base link to a tip link at
q = 0 and returns what :meth:`screwkit.Chain.from_urdf` needs: the joint screws in the
base frame, the home pose M of the tip link, the limits and the joint names. Fixed
joints are folded into the transforms between their neighbours.

The numbers are exact where the file's are: a decimal is read as the decimal it prints
(``0.1625`` -> 13/80) and an rpy angle equal to a multiple of pi/2 to double precision
(``1.5707963267948966``) is that multiple, so cos and sin are 0 and +-1 exactly; any
other angle's cosine and sine are SymPy Floats of double precision.

Parsing uses the standard library's XML parser. Refused, with a ``ValueError`` that
names the joint or link: malformed XML, mimic, floating and planar joints on the path,
a zero axis, an unknown link, a tree that branches below the base when no tip link is
given (the message lists the leaves).

>>> text = '''<robot name="arm"><link name="base"/><link name="l1"/>
... <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
... <origin xyz="0 0 0.1625" rpy="0 0 0"/><axis xyz="0 0 1"/>
... <limit lower="-3.14" upper="3.14" effort="1" velocity="1"/></joint></robot>'''
>>> description = read_urdf(text)
>>> description.joint_names, description.axes[0].T, description.home[2, 3]
(('j1',), Matrix([[0, 0, 1, 0, 0, 0]]), 13/80)
"""

import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ._checks import describe
from .transforms import axis_coordinates

__all__ = ["URDFDescription", "read_urdf", "data_file"]

#: The joint types a serial chain can hold, and those refused on the path.
MOVING = ("revolute", "continuous", "prismatic")
REFUSED = ("floating", "planar")


@dataclass(frozen=True)
class URDFDescription:
    """The serial chain of a URDF from ``base_link`` to ``tip_link`` at q = 0.

    Parameters
    ----------
    axes : tuple of sympy.Matrix (6, 1)
        The n exact joint screws [omega; v] in the base link's frame.
    home : sympy.Matrix (4, 4)
        The exact pose M of the tip link at q = 0 (m).
    qlim : tuple of (float, float) or None
        n pairs (min, max) (rad, or m for a prismatic joint), or None.
    joint_names : tuple of str
        The n URDF joint names, base to tip.
    name : str
        The robot's name.
    base_link : str
        The link whose frame is the base frame.
    tip_link : str
        The end-effector link.

    Examples
    --------
    The UR5e shipped with screwkit: six joints from base_link to tool0.

    >>> description = read_urdf(data_file("ur5e.urdf"))
    >>> description.name, description.base_link, description.tip_link
    ('UR5e', 'base_link', 'tool0')
    >>> len(description.axes), description.joint_names[0]
    (6, 'shoulder_pan_joint')
    """

    axes: tuple
    home: sp.Matrix
    qlim: tuple
    joint_names: tuple
    name: str
    base_link: str
    tip_link: str


@dataclass(frozen=True)
class _Joint:
    name: str
    kind: str
    parent: str
    child: str
    origin: sp.Matrix
    axis: tuple
    limit: tuple
    mimic: bool


def _parse(source):
    """The root element of ``source``: URDF text or the path of a URDF file."""
    if isinstance(source, bytes):
        source = source.decode()
    if isinstance(source, str) and source.lstrip().startswith("<"):
        text, where = source, "the URDF text"
    elif isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        if not os.path.isfile(path):
            raise ValueError(
                f"source must be URDF text or the path of a URDF file, "
                f"got {path!r}, which is no file"
            )
        with open(path, encoding="utf-8") as handle:
            text, where = handle.read(), path
    else:
        raise TypeError(
            f"source must be URDF text or a file path, got {describe(source)}"
        )
    try:
        root = ET.fromstring(text)
    except ET.ParseError as error:
        raise ValueError(
            f"source must be well-formed XML (URDF), got text that is not well-formed "
            f"XML ({where}): {error}"
        ) from None
    if root.tag != "robot":
        raise ValueError(
            f"source must be a URDF with a <robot> root element, got <{root.tag}>"
        )
    return root


def _numbers(element, attribute, default, where):
    """The numbers of a space-separated attribute, as exact Rationals (3 of them)."""
    text = default if element is None else element.get(attribute, default)
    try:
        values = [sp.Rational(word) for word in text.split()]
    except (TypeError, ValueError):
        raise ValueError(f"{where}: {attribute}={text!r} must be 3 numbers") from None
    if len(values) != 3:
        raise ValueError(
            f"{where}: {attribute}={text!r} must be 3 numbers, got {len(values)}"
        )
    return values


def _cos_sin(angle):
    """Exact cos and sin of a multiple of pi/2 (to double precision), else Floats."""
    value = float(angle)
    turns = round(value / (np.pi / 2))
    if value == float(turns * sp.pi / 2) or value == 0.0:
        return [(1, 0), (0, 1), (-1, 0), (0, -1)][turns % 4]
    return sp.Float(np.cos(value)), sp.Float(np.sin(value))


def _origin(element, where):
    """The 4x4 exact transform of an <origin> element (identity if absent)."""
    x, y, z = _numbers(element, "xyz", "0 0 0", where)
    (cr, sr), (cp, sp_), (cy, sy) = (
        _cos_sin(a) for a in _numbers(element, "rpy", "0 0 0", where)
    )
    R = (
        sp.Matrix([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
        * sp.Matrix([[cp, 0, sp_], [0, 1, 0], [-sp_, 0, cp]])
        * sp.Matrix([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    )
    return sp.Matrix.vstack(
        sp.Matrix.hstack(R, sp.Matrix([x, y, z])), sp.Matrix([[0, 0, 0, 1]])
    )


def _limit(element, kind, where):
    """(lower, upper) of a <limit>; None where there is none (continuous, or absent)."""
    if kind == "continuous" or element is None:
        return None
    try:
        lower, upper = (
            float(element.get("lower", "0")),
            float(element.get("upper", "0")),
        )
    except ValueError:
        raise ValueError(
            f"{where}: limit lower/upper must be numbers, "
            f"got {element.get('lower')!r}, {element.get('upper')!r}"
        ) from None
    if lower == upper == 0:
        return None  # URDF's defaults: no range given
    if not lower < upper:
        raise ValueError(
            f"{where}: limit lower must be below upper, got {lower}, {upper}"
        )
    return (lower, upper)


def _joints(root):
    """The links (a set of names) and joints ({child link: _Joint}), checked."""
    links = set()
    for element in root.findall("link"):
        name = element.get("name")
        if not name:
            raise ValueError("every <link> must have a name, got one without")
        links.add(name)
    joints = {}
    for element in root.findall("joint"):
        name = element.get("name") or "(unnamed)"
        where = f"joint {name!r}"
        kind = element.get("type")
        parent, child = element.find("parent"), element.find("child")
        if parent is None or child is None:
            raise ValueError(f"{where} must have a <parent> and a <child> link")
        parent, child = parent.get("link"), child.get("link")
        for role, link in (("parent", parent), ("child", child)):
            if link not in links:
                raise ValueError(
                    f"{where}: its {role} link {link!r} is not a link of the file"
                )
        if child in joints:
            raise ValueError(
                f"{where}: link {child!r} is already the child of joint "
                f"{joints[child].name!r}; a URDF is a tree"
            )
        if kind not in MOVING + REFUSED + ("fixed",):
            raise ValueError(
                f"{where} has the unknown type {kind!r}; expected one of "
                f"{', '.join(MOVING + REFUSED + ('fixed',))}"
            )
        axis = _numbers(element.find("axis"), "xyz", "1 0 0", where)
        joints[child] = _Joint(
            name,
            kind,
            parent,
            child,
            _origin(element.find("origin"), where),
            tuple(axis),
            _limit(element.find("limit"), kind, where),
            element.find("mimic") is not None,
        )
    return links, joints


def _path(links, joints, base_link, tip_link):
    """The joints from base_link down to tip_link, in order; both links checked."""
    roots = sorted(link for link in links if link not in joints)
    if len(roots) != 1:
        raise ValueError(
            f"the URDF must be one tree with one root link, got roots {roots}"
        )
    for name, link in (("base_link", base_link), ("tip_link", tip_link)):
        if link is not None and link not in links:
            raise ValueError(
                f"{name} must be a link of the URDF (its links are "
                f"{', '.join(sorted(links))}), got {link!r}"
            )
    base = roots[0] if base_link is None else base_link
    if tip_link is None:
        children = {}
        for joint in joints.values():
            children.setdefault(joint.parent, []).append(joint.child)
        leaves, stack = [], [base]
        while stack:
            link = stack.pop()
            stack.extend(children.get(link, []))
            if link not in children:
                leaves.append(link)
        if len(leaves) != 1:
            raise ValueError(
                f"the URDF branches below {base!r}: tip_link must name the end "
                f"of the chain, e.g. one of the leaves {', '.join(sorted(leaves))}"
            )
        tip_link = leaves[0]
    path, link = [], tip_link
    while link != base:
        if link not in joints:
            raise ValueError(f"tip_link {tip_link!r} is not below base_link {base!r}")
        path.append(joints[link])
        link = joints[link].parent
    return path[::-1], base, tip_link


def _unit(axis, where):
    vector = sp.Matrix(axis)
    norm2 = sum(e**2 for e in vector)
    if norm2 == 0:
        raise ValueError(f"{where} must have a non-zero axis, got xyz='0 0 0'")
    return vector if norm2 == 1 else vector / sp.sqrt(norm2)


def read_urdf(source, base_link=None, tip_link=None):
    """The serial chain of a URDF from ``base_link`` to ``tip_link``.

    Parameters
    ----------
    source : str or os.PathLike
        URDF text (starting with '<') or a URDF file's path.
    base_link : str or None
        The link whose frame is the base frame (default: the root).
    tip_link : str or None
        The end-effector link; required when the tree branches below ``base_link``
        (the error lists the leaves).

    Returns
    -------
    URDFDescription
        The chain's joint screws, home pose, limits and names.

    Examples
    --------
    The UR5e's tool at q = 0, exactly: (-0.8172, -0.2329, 0.0628) m, as its DH
    parameters give (a2 + a3, -(d4 + d6), d1 - d5; see ``sk.robots.ur5e``).

    >>> description = read_urdf(data_file("ur5e.urdf"))
    >>> description.home[:3, 3].T
    Matrix([[-2043/2500, -2329/10000, 157/2500]])
    """
    for name, value in (("base_link", base_link), ("tip_link", tip_link)):
        if value is not None and not isinstance(value, str):
            raise TypeError(
                f"{name} must be a link name (str) or None, got {describe(value)}"
            )
    root = _parse(source)
    links, joints = _joints(root)
    path, base, tip = _path(links, joints, base_link, tip_link)
    G = sp.eye(4)
    axes, limits, names = [], [], []
    for joint in path:
        where = f"joint {joint.name!r}"
        if joint.mimic and joint.kind != "fixed":
            raise ValueError(
                f"{where} is a mimic joint (it follows another joint), which a "
                "serial chain of independent joints cannot hold"
            )
        if joint.kind in REFUSED:
            raise ValueError(
                f"{where} is a {joint.kind} joint; a serial chain holds revolute, "
                "continuous, prismatic and fixed joints only"
            )
        G = G * joint.origin
        if joint.kind == "fixed":
            continue
        w = G[:3, :3] * _unit(joint.axis, where)
        pitch = sp.oo if joint.kind == "prismatic" else 0
        screw = axis_coordinates(w, G[:3, 3], pitch)  # (w; p x w), or (0; w)
        axes.append(screw.applyfunc(sp.expand))
        limits.append(joint.limit)
        names.append(joint.name)
    if not axes:
        raise ValueError(f"the URDF has no moving joint between {base!r} and {tip!r}")
    return URDFDescription(
        axes=tuple(axes),
        home=G.applyfunc(sp.expand),
        qlim=tuple(limits),
        joint_names=tuple(names),
        name=root.get("name") or "robot",
        base_link=base,
        tip_link=tip,
    )


def data_file(name):
    """The path of a URDF shipped with screwkit.

    Parameters
    ----------
    name : str
        The file's name: ``'ur5e.urdf'`` (the UR5e written from Universal Robots'
        published DH parameters).

    Returns
    -------
    str
        The file's path.

    Examples
    --------
    >>> os.path.basename(data_file("ur5e.urdf"))
    'ur5e.urdf'
    """
    if not isinstance(name, str):
        raise TypeError(f"name must be a file name (str), got {describe(name)}")
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
    path = os.path.join(folder, name)
    if not os.path.isfile(path):
        shipped = sorted(os.listdir(folder))
        raise ValueError(
            f"name must be one of the shipped files {shipped}, got {name!r}"
        )
    return path
