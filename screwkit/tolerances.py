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

# ---- core: checks, rigid motions, screws, chains ------------------------------------

# ---- ik: subproblems, closed-form engines, Newton -----------------------------------

# ---- parallel: model, legs, numerics, search ----------------------------------------

# ---- motion: second-order kinematics, trajectories, differential IK ------------------

#: Below this angle (rad) slerp and the SE(2) logarithm take the straight line /
#: the translation: sin(W) / W is 1 there to within W^2 / 6 < 1e-17, below round-off;
#: also how far a quaternion's norm may be from 1 (relative) before it is refused.
SLERP_LINEAR_BELOW = 1e-9

#: Below this angle (rad) a - sin(a) is taken from its series to the a^7 term (the next
#: term, a^9 / 362880, is below 3e-24 there; the subtraction would lose every digit).
SERIES_BELOW = 1e-2

#: A sample of a path is near a singularity when its Jacobian's condition number
#: exceeds 1 / NEAR_SINGULAR: the joint rates are then more than 1000 times the tool's
#: speed in the worst direction (rows [v; omega] mix m and rad: an arm about 1 m
#: across).
NEAR_SINGULAR = 1e-3

#: A differential-IK step tracks the asked twist when the residual |J dq - V| is below
#: this fraction of |V| (plus this much absolutely): above round-off of a 6 x n
#: solve (about 1e-15 relative, times a condition number up to 1e3 and margin).
TRACKING_RTOL = 1e-9

#: DAQP's proximal-point weight for an undamped (only convex) differential-IK QP:
#: each iteration adds PROXIMAL_WEIGHT |dq - dq_previous|^2; 1e-2 against J^T J of
#: entries about 1 (m^2) converges in a few iterations.
PROXIMAL_WEIGHT = 1e-2

#: DAQP stops its proximal iterations when the iterate moves less than this (rad/s):
#: J dq then meets V to round-off (about 1e-15 on the chapter's arms).
PROXIMAL_STOP = 1e-12
