"""Every tolerance of screwkit, named once.

A float computation is compared with a tolerance, never with zero. Each constant
below says what it is compared with and why it has the value it has. Two kinds:

- **relative** tolerances (no unit) compare a quantity with another of the same
  kind: a singular value with the largest, an angle's sine with 1, a residual
  with the size of the pose it belongs to;
- **length** tolerances are written for a mechanism or chain about a metre across
  and are used as ``LENGTH_TOL * scale``, where ``scale`` is the instance's own
  size (its longest link, leg or offset; :func:`length_scale`), so that an
  instance given in millimetres (all lengths times 1000) gets the same answers,
  scaled, as the same instance in metres.

Nothing else in screwkit writes a bare tolerance literal: a new one is added here,
in the section of the family that uses it, with its reason.
"""

import numpy as np

# ---- core: checks, rigid motions, screws, chains ------------------------------------

#: Relative. A float matrix's rank counts its singular values above
#: ``RANK_TOL * max(1, largest singular value)`` (screw systems, mobility): float
#: screws built from measured or computed frames differ from exact ones in their last
#: bits (about 1e-16 relative), and a genuine independent direction is many orders
#: larger; 1e-9 sits between with room on both sides.
RANK_TOL = 1e-9

#: Relative. How far a float rotation given as INPUT may be from an exact one: the
#: largest entry of R^T R - I for a rotation matrix, | |q| - 1 | for a quaternion.
#: Tables and printouts give rotations to 6 or 7 significant digits, so the check is
#: loose enough for those and still refuses a matrix that is not a rotation.
ROTATION_TOL = 1e-6

#: Relative. How far from 1 the norm of a joint screw's omega (or of v, for a
#: prismatic joint) may be. Joint screws come from frames, URDF files or exact
#: numbers, so they are unit to round-off; a looser check would accept an axis whose
#: length silently rescales the joint variable (it is then normalised to the last bit).
UNIT_SCREW_TOL = 1e-9

#: Unitless. A float quantity of order one (a direction's norm, a quaternion's entry,
#: an entry of a pose's last row, the cosine between two unit vectors) this close to 0
#: is 0: thousands of units in the last place of 1, above the round-off of the few
#: operations that produce it and far below any value a user means. For a length it is
#: used as ``ZERO_TOL * scale`` (:func:`length_scale`).
ZERO_TOL = 1e-12

#: Unitless. |sin| (ZYZ) or |cos| (ZYX) of the middle Euler angle below which a float
#: rotation is gimbal-locked: the two outer angles are then computed from a sum of
#: products of about that size and lose all meaning; looser than ZERO_TOL because the
#: angles themselves, not only a test, are computed from that small number.
LOCK_TOL = 1e-9

#: Unitless. Two unit directions are parallel when | |s1 . s2| - 1 | is below this
#: (a parallelogram's four axes), a quarter of the round-off of computing s1 . s2 from
#: axes typed to 9 digits.
PARALLEL_TOL = 1e-9

#: Length (m for an instance 1 m across; times :func:`length_scale`). Two points closer
#: than ``LENGTH_TOL * scale`` are one point (a mechanism of no extent, a tool on its
#: last joint's axis, a parallelogram's equal sides): a nanometre on a metre.
LENGTH_TOL = 1e-9

#: Length (m, times :func:`length_scale`). Frame origins closer than this are labelled
#: together on a drawing: a micrometre on a metre, invisible at any figure size.
DRAWING_TOL = 1e-6

#: Length (m, times :func:`length_scale`). The distance to the target at which the
#: start configuration's Newton iteration stops (quadratic convergence gets there in a
#: step or two beyond 1e-6).
POSITION_TOL = 1e-10

#: Relative. A float is on a grid of steps (a slider's values, a path's time samples)
#: when value / step is this close to a whole number, relative to the number of steps.
STEP_TOL = 1e-9

#: Unitless. Float coefficients of a compiled program (cos and sin of a DH alpha) this
#: close to 0 or +-1 are taken as exact: cos(pi/2) computes as 6e-17, and a DH table's
#: genuine angles are far from a right angle at this level.
SNAP_TOL = 1e-14

#: Relative. A float angle whose number of quarter turns alpha / (pi/2) is this close to
#: a whole number is that multiple of pi/2 exactly: np.pi / 2 is within one unit in the
#: last place (1.1e-16 relative) of pi/2.
QUARTER_TURN_TOL = 1e-15

#: Unitless. An expression of order one evaluated at a random point (floats with 15
#: digits) is 0 below this: the test of an identity (cos^2 + sin^2 - 1) at sample
#: points.
SAMPLE_ZERO_TOL = 1e-9

#: Angle (rad). Below it the series of theta / sin(theta) and of the logarithm's
#: translation factor replace the closed forms, which cancel there; the series' next
#: term is then below 1e-17.
SMALL_ANGLE = 1e-4

#: The smallest positive divisor used where a norm or determinant may be exactly 0
#: (np.maximum(norm, DIVISION_FLOOR)): a guard against division by zero, not a test.
DIVISION_FLOOR = 1e-300

#: Angle (rad). Joint angles are clipped this far inside their limits before the
#: limit gradient divides by the distance to a limit.
LIMIT_MARGIN = 1e-9

#: Angle (rad) or length (m). The step of central finite differences: near the cube
#: root of the float64 epsilon (6e-6), where truncation and round-off errors balance.
FD_STEP = 1e-6


def length_scale(*lengths):
    """The size of an instance, for length tolerances used as ``LENGTH_TOL * scale``.

    Parameters
    ----------
    *lengths : array-like of float (m)
        The instance's lengths or points: link lengths, joint points, screw moments.

    Returns
    -------
    float
        The largest absolute entry (m), or 1.0 for an instance of no size (every
        entry 0, where there is nothing to scale).

    >>> length_scale([0.0, 2.0], [[-3.0, 1.0]])
    3.0
    >>> length_scale([0, 0])
    1.0
    """
    largest = max((float(np.max(np.abs(v), initial=0.0)) for v in lengths), default=0.0)
    return largest if largest > 0 else 1.0


# ---- ik: subproblems, closed-form engines, Newton -----------------------------------

# ---- parallel: model, legs, numerics, search ----------------------------------------
