"""Joint screws for the mobility zeroth step: each helper returns a list of (s, r, h) triples.

A limb reads like its name: ``prismatic(x) + revolute(x, A) + universal(y, z, B)`` is a PRU limb.
Multi-freedom joints are sets of 1-freedom screws through one point: C = R + P on one
axis, U = two crossing R, S = three crossing R.

>>> import sympy as sp
>>> len(spherical([0, 0, 1]))
3
"""
import sympy as sp

from ._checks import as_sympy_matrix

__all__ = ["revolute", "prismatic", "helical", "cylindrical", "universal", "spherical",
           "parallelogram", "rotate_limb", "translate_limb"]


def _vec(v, name):
    return as_sympy_matrix(v, name, (3, 1))


def revolute(s, r):
    """R: rotation about the axis ``s`` through the point ``r``."""
    return [(_vec(s, "s"), _vec(r, "r"), 0)]


def prismatic(s, r=(0, 0, 0)):
    """P: translation along ``s`` (r only for drawing: a prismatic twist has no position)."""
    return [(_vec(s, "s"), _vec(r, "r"), sp.oo)]


def helical(s, r, h):
    """H: rotation about (s, r) with translation h per radian along it."""
    return [(_vec(s, "s"), _vec(r, "r"), h)]


def cylindrical(s, r):
    """C: rotation about and translation along the same axis."""
    return revolute(s, r) + prismatic(s, r)


def universal(s1, s2, r):
    """U: two revolute axes s1, s2 crossing at r."""
    return revolute(s1, r) + revolute(s2, r)


def spherical(r, axes=((1, 0, 0), (0, 1, 0), (0, 0, 1))):
    """S: three independent revolute axes through the centre r."""
    return [joint for axis in axes for joint in revolute(axis, r)]


def parallelogram(s, a1, a2, b1, b2):
    """Pa: four parallel revolute axes s at the corners A1, A2 (base side) and B1, B2."""
    return [joint for corner in (a1, a2, b1, b2) for joint in revolute(s, corner)]


def rotate_limb(limb, R):
    """The limb turned by the rotation matrix R (3x3) about the origin of the fixed frame."""
    R = as_sympy_matrix(R, "R", (3, 3))
    return [((R * _vec(s, "s")).applyfunc(sp.expand), (R * _vec(r, "r")).applyfunc(sp.expand), h)
            for s, r, h in limb]


def translate_limb(limb, p):
    """The limb moved by the vector p."""
    p = _vec(p, "p")
    return [(_vec(s, "s"), _vec(r, "r") + p, h) for s, r, h in limb]
