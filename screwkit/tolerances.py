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


# ---- lines and screw systems ---------------------------------------------------------

#: Relative. A float line's coordinates (w; m) must satisfy |w . m| <= KLEIN_TOL |w| |m|
#: (the cosine of the angle between w and m): lines typed to 6 or 7 digits pass, a
#: screw of pitch h != 0 (w . m = h |w|^2) is refused; the excess is then removed.
KLEIN_TOL = 1e-6

#: Unitless. Two float lines are parallel when the sine of the angle between their
#: unit directions, |u_a x u_b|, is below this: round-off of a few 1e-16 per operation
#: is far below, a genuine angle of a micro-radian far above.
LINE_ANGLE_TOL = 1e-9

#: Relative. The rank of a set of float lines, and the zero tests of the quadratic form
#: w . m on their span, after every direction is made unit and every moment divided by
#: the lines' size (so the test is the same in m and mm): as RANK_TOL for screws.
LINE_RANK_TOL = 1e-9

#: Relative. Two principal pitches of a float screw system are equal, and a direction
#: part is singular, below this fraction of the system's size (the largest of its
#: lengths: moments over unit directions and pitches); the same in m and mm.
PITCH_TOL = 1e-9


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

    Examples
    --------
    >>> length_scale([0.0, 2.0], [[-3.0, 1.0]])
    3.0
    >>> length_scale([0, 0])
    1.0
    """
    largest = max((float(np.max(np.abs(v), initial=0.0)) for v in lengths), default=0.0)
    return largest if largest > 0 else 1.0


# ---- ik: subproblems, closed-form engines, Newton -----------------------------------

#: The subproblems' consistency conditions on float input (a unit axis, pitch 0,
#: p and q in one plane across the axis, a residual that decides 0, 1 or 2 solutions):
#: relative to the size of the points involved (1 + their distances from the axis),
#: so round-off of a few 1e-16 per metre is never taken for a real miss.
SUBPROBLEM_TOL = 1e-9

#: A closed-form engine's structure checks (:mod:`screwkit.ik`): the sine between two
#: axes that must be parallel (or must not be), a joint's pitch, and, times the arm's
#: size (:func:`screwkit.ik._closed_form.arm_scale`, m), the distance by which axes
#: that must meet miss. An arm read from a URDF or a DH table of decimals is exact to
#: about 1e-15 relative, far inside it; a real offset of a millimetre far outside.
IK_STRUCTURE_TOL = 1e-9

#: Round-off that pushes a square-root or arccos argument of the closed forms just
#: outside its range (a negative discriminant, a cosine beyond +-1) by less than this
#: (relative; times the arm's size squared for an area) is clipped: a pose on a
#: singularity is solved, not dropped. The same number decides when a point counts as
#: on an axis (its angle free) and a direction as along one.
IK_CLIP_TOL = 1e-10

#: The tie-break of the configuration labels (l/r, u/d, n/f), the same for the three
#: closed-form engines: a signed measure within it of 0 counts as the singular side
#: ('r', 'd', 'f'). Used as is for a unit-free measure (a sine), times the arm's size
#: for a length and times its square for an area, so that the labels and the closed
#: form agree on poses solved at a singularity and every label round-trips.
IK_LABEL_TOL = 1e-10

#: The decomposed engine lists a pose's solutions in increasing q1, then q2, ...; angles
#: (rad) are compared on a grid of this step, so that siblings whose q1 is the same
#: angle (it differs only in its last bits, which the CPU's SIMD path decides) are
#: ordered by q2 on every machine rather than by round-off.
IK_ORDER_TOL = 1e-6

#: A closed-form solution is flagged singular (shoulder, elbow, wrist) when its measure
#: is below this: the squared distance of the wrist centre from the plane of axis 1
#: (times the arm's size squared), 1 - |cos| of the elbow, the sine between axes 4 and
#: 6. Looser than the clipping above: it reports the poses near a singularity, where
#: the solutions come close together, not only those on it.
IK_SINGULAR_TOL = 1e-9

#: How far (rad) an angle moved by whole turns may lie outside a joint limit and still
#: count as inside: the round-off of adding 2 pi k to an angle of (-pi, pi].
IK_JOINT_LIMIT_SLACK = 1e-12

#: Newton's default success test (:func:`screwkit.ik.numeric_ik`): the norm of the
#: error twist [omega; v] theta, rad and m. Near the round-off of a chain's forward
#: kinematics (about 1e-15 per metre) times the few hundred flops of a step, and far
#: below anything a drawing or a machine could see.
NEWTON_TOL = 1e-10

#: The floor of Newton's adaptive damping lambda = |V|^2 / 2 + NEWTON_DAMPING: keeps
#: J^T J + lambda I invertible at a singular configuration once the error is tiny.
NEWTON_DAMPING = 1e-9

#: Subproblems 5 and 6 (:mod:`screwkit.ik.subproblems`) and the decomposed engine
#: (:mod:`screwkit.ik.decomposed`). A 2x2 block of their two sinusoid equations counts
#: as of rank 1 (the equations are solved one after the other instead of through the
#: quartic) when |det| is below this times its squared Frobenius norm, and a coefficient
#: vector counts as 0 below this times the equations' size. A structural rank drop (two
#: axes that meet, two parallel) is exact to round-off, a few 1e-16.
IK_RANK_TOL = 1e-10

#: A root z of the quartic in z = exp(i theta) is a real angle candidate when
#: ||z| - 1| is below this: a double root (a tangency) splits off the unit circle by
#: about the square root of round-off, 1e-8; each candidate is then polished by Newton
#: and kept only if its residual passes IK_ACCEPT_TOL, so a loose gate drops nothing
#: real and lets nothing false through.
IK_ROOT_TOL = 1e-5

#: The closed-form quartic (:mod:`screwkit.ik._quartic`, Ferrari) is trusted for a batch
#: member when each root's value and the roots' sum (Vieta) are within this of 0
#: relative to the coefficients' size; else the companion matrix's eigenvalues are used.
IK_QUARTIC_TOL = 1e-9

#: A candidate of subproblems 5 and 6, or a joint vector of the decomposed engine, is a
#: solution when its residual (the equations', relative to their size; the pose's:
#: rotation entries and positions divided by the arm's size) is below this after
#: polishing. Round-off leaves about 1e-14; a near-miss of a false candidate is 1e-6 or
#: more.
IK_ACCEPT_TOL = 1e-9

#: Two solutions of the decomposed engine are one (a double root found twice) when
#: their joint angles differ by less than this (rad), wrapped.
IK_DUPLICATE_TOL = 1e-7

# The general 6R (:mod:`screwkit.ik.general`): lengths are divided by the chain's size
# (length_scale of its screws' moments and home position) before the elimination, so
# the constants below are relative.

#: The right side's 14 x 8 coefficient matrix Q (joints 1 and 2) has full rank when
#: its smallest singular value is above this fraction of its largest: a generic arm's
#: is above 1e-3, one with aligned or meeting axes' exactly 0 to round-off (1e-16).
IK_GENERAL_RANK_TOL = 1e-9

#: A form of the elimination is well conditioned when both ratios above (Q's smallest
#: to largest singular value, M2's smallest to the problem's largest entry) exceed
#: this: on random arms they are above 3e-3 and 1e-5, on degenerate forms 1e-16. A
#: form between the hard limits and this is used only when no other form is well
#: conditioned (the best of them), so a nearly special arm is solved from its best
#: form rather than its first.
IK_GENERAL_COMFORT_TOL = 1e-6

#: The leading 12 x 12 matrix M2 of the eigenvalue problem is invertible when its
#: smallest singular value is above this fraction of the problem's largest entry;
#: below it the problem is singular (det M(x) = 0 for every x, special geometry) or
#: has a root at infinity, and another angle shift or formulation is tried.
IK_GENERAL_LEADING_TOL = 1e-10

#: An eigenvalue x = tan(q3 / 2) is a candidate when |Im x| is below this fraction of
#: 1 + |x|: loose, because a double real root splits into a complex pair about
#: sqrt(eps) apart; Newton and the residual decide which candidates are solutions.
IK_GENERAL_REAL_TOL = 1e-4

#: Real eigenvalues x3 closer than this (relative to 1 + |x3|) are one repeated root:
#: solutions sharing q3, whose eigenvectors mix. A repeated root with independent
#: eigenvectors is computed to round-off (1e-14), distinct roots of a generic pose
#: differ by far more; a false grouping costs only a few more candidates.
IK_GENERAL_CLUSTER_TOL = 1e-6

#: The null space of M(x3) at a repeated root: its singular values below this
#: fraction of the largest (round-off, 1e-15, against 1e-4 or more for the others).
IK_GENERAL_NULL_TOL = 1e-8

#: A polished candidate is a solution when its error twist [omega; v / scale] has a
#: norm below this: Newton from an eigenvalue reaches 1e-14, a candidate from a
#: complex root or a spurious one stays far above.
IK_GENERAL_ACCEPT_TOL = 1e-10

#: A real root of the eigenvalue problem is accounted for when a solution's angle of
#: the eigenvalue joint is within this of it (rad): a simple root is computed to
#: 1e-12, a double one to about sqrt(eps); a root that fewer solutions account for
#: than it should (a repeated root: one for each solution sharing it) makes the
#: answer say that it may be incomplete.
IK_GENERAL_EXPLAINED_TOL = 1e-4

#: A root's candidate is consistent (a solution must then account for the root) when
#: the 8 products (1, c1, s1) x (1, c2, s2) it gives for joints 1 and 2 are those of
#: two angles to this (c^2 + s^2 = 1, products of the factors): a genuine root's are
#: to 1e-10, a spurious root's (special geometry: extra factors of the determinant,
#: e.g. the PUMA's q = 0 and pi) are off by 0.5 or more.
IK_GENERAL_CONSISTENT_TOL = 1e-4

#: Two solutions are one when no joint angle differs by more than this (rad, modulo a
#: turn): polished solutions agree to 1e-12, distinct ones of a generic pose differ by
#: far more.
IK_GENERAL_SAME_TOL = 1e-7

#: A solution is at a singular configuration (the answer says so: solutions may
#: coincide or form a continuum there) when the smallest singular value of its space
#: Jacobian (lengths divided by the chain's size) is below this fraction of the
#: largest: a generic solution's ratio is above 1e-3, one on aligned axes 1e-16.
IK_GENERAL_SINGULAR_TOL = 1e-8

#: The damping (Levenberg-Marquardt, lengths divided by the chain's size) of the
#: Newton search that screwkit.ik.general runs where its elimination finds nothing:
#: small enough not to slow convergence, large enough to step across singular
#: configurations.
IK_GENERAL_SEARCH_DAMPING = 1e-4

#: Newton's polish of screwkit.ik.general stops moving a solution once its error is a
#: thousandth of the acceptance, IK_GENERAL_ACCEPT_TOL: the last step then changes
#: nothing the acceptance could see.
IK_GENERAL_POLISH_TOL = IK_GENERAL_ACCEPT_TOL * 1e-3

#: Newton's polish of screwkit.ik.general keeps a Jacobian from before a step of at
#: most IK_GENERAL_KEEP_STEP (rad, each joint) where its Hadamard bound
#: ``|det J| / |J|_F^6`` (a lower bound of sigma_min / sigma_max) is above
#: IK_GENERAL_KEEP_BOUND: the step changes sigma_min / sigma_max by about the step,
#: a hundredth of that bound, which stays far above IK_GENERAL_SINGULAR_TOL: the
#: singular flag read from it is the one at the polished solution.
IK_GENERAL_KEEP_STEP = 1e-8
IK_GENERAL_KEEP_BOUND = 1e-6

#: Newton's polish of screwkit.ik.general takes the pseudo-inverse's step where the
#: Jacobian's Hadamard ratio (``|det J|`` over the product of its columns' lengths, 1
#: for orthogonal columns) is below this, and an LU solve (the same step up to
#: round-off, five times cheaper) above it: the two differ only where J is singular to
#: working precision, whose ratio is far below.
IK_GENERAL_HADAMARD_TOL = 1e-10

# ---- parallel: model, legs, numerics, search ----------------------------------------
# A length below is written for a mechanism about 1 m across and used times the
# mechanism's own size (ParallelManipulator.scale, the farthest attachment point from
# its frame's origin; a leg's l1 + l2 in the legs' kernels), so that the same mechanism
# in millimetres gets the same answers, scaled.

#: A platform pose of a planar or translational mechanism must keep its motion: the
#: rotation block may differ from the allowed one (and a planar pose's z-translation,
#: divided by the scale, from 0) by this much. Relative: rotation entries are numbers.
PARALLEL_MOTION_TOL = 1e-9

#: Forward kinematics stops when every loop-closure residual is below this length
#: (times the scale): the residuals are lengths, reached by Newton to round-off.
PARALLEL_FK_TOL = 1e-12

#: A converged pose is accepted (success) when its residuals are below
#: max(tol, this length times the scale): a looser floor than PARALLEL_FK_TOL, so that
#: a pose Newton polished to round-off is not refused for its last bits.
PARALLEL_FK_ACCEPT_TOL = 1e-10

#: Newton's largest step in any component of the platform twist: 0.5 rad in angle,
#: 0.5 times the scale in length. Damping keeps a far start from jumping across
#: assembly modes; near the solution the step is far smaller and Newton is undamped.
PARALLEL_NEWTON_MAX_STEP = 0.5

#: A crank leg (3-RRR, delta) cannot be solved when the platform point lies on the
#: crank's axis: the distance to the axis is compared with this length times l1 + l2.
PARALLEL_AXIS_TOL = 1e-12

#: A leg reaches its platform point when the law of cosines' ratio is within 1 + this
#: (relative), or the point's distance within l1 + l2 and |l1 - l2| -/+ this length
#: times l1 + l2: round-off at a leg stretched straight is not "out of reach".
PARALLEL_REACH_TOL = 1e-12

#: The 3-RPR's polynomial: a leading coefficient (or a remainder of the division by
#: 1 + t^2) below this fraction of the largest coefficient counts as zero (relative).
PARALLEL_POLY_ZERO_TOL = 1e-9

#: A root t of the 3-RPR's sextic is real when |Im t| is below this fraction of
#: 1 + |t| (relative): a double real root splits into a complex pair about sqrt(eps).
PARALLEL_REAL_ROOT_TOL = 1e-6

#: Cramer's rule for the 3-RPR's platform point fails where its determinant is below
#: this fraction of its largest coefficient (relative: the coefficients are areas, so
#: the test is the same in any unit).
PARALLEL_CRAMER_TOL = 1e-12

#: Newton polishing a candidate assembly mode stops at this residual (times the
#: scale), tighter than PARALLEL_FK_TOL: the modes are reported to round-off.
PARALLEL_POLISH_TOL = 1e-13

#: Two assembly modes are the same pose when no rotation entry differs by more than
#: this (and no translation by more than this times the scale).
PARALLEL_SAME_POSE_TOL = 1e-6

#: Base and platform points lie in the base plane (the mirror image of a Stewart
#: platform's pose is then an assembly mode too) when their z is below this length
#: times the scale (NumPy's allclose default, which it replaces).
PARALLEL_FLAT_TOL = 1e-8

#: fk_all lists a spatial mechanism's modes by height, platform above the base first;
#: heights that agree to this many decimals (of the scale) count as equal.
PARALLEL_HEIGHT_DECIMALS = 9

#: The loop closure's Jacobian at an assembly mode (its linear columns times the scale,
#: so that every column is a length) loses rank when its smallest singular value is
#: below this fraction of its largest (relative): a direct singularity, or a point of a
#: continuum of solutions. As RANK_TOL.
PARALLEL_RANK_TOL = 1e-9

#: A continuum of assembly modes is probed by stepping this far from a singular mode
#: along the Jacobian's kernel (rad, or times the scale in length) and projecting back
#: onto the solutions by least-squares Newton: a continuum is reached again at about
#: this distance, an isolated (double) mode is not. Far above round-off, far below the
#: distance between distinct modes of a mechanism about 1 m across.
PARALLEL_CONTINUUM_STEP = 1e-2

#: The delta's closed form: three spheres of radius l2 meet in two points, one (they
#: touch) or none, as h^2 = l2^2 - (circumradius of the centres)^2 is above, within or
#: below this fraction of l2^2 (relative): round-off of h^2 is a few 1e-16 of l2^2.
PARALLEL_SPHERES_TOL = 1e-12

#: Width (in t = tan(phi / 2), dimensionless) of the exact isolating intervals of a
#: 3-RPR's real roots (parallel.proven.rpr_fk_proven): far below a double's
#: resolution, so each interval's midpoint is the root to round-off.
PARALLEL_PROVEN_ROOT_WIDTH = 2.0**-70

# ---- workspace and redundancy: defaults of the chapters' sweeps and planar arms ---

#: How far (m) a swept point may lie from the plane of a workspace section and still be
#: drawn in it: 1 cm, a dot's width in a figure of an arm about a metre across.
SECTION_TOL = 0.01

#: How far (m) q0's end effector may be from a redundancy path's start: 1 mm, so that
#: the feedback's first step (gain 50/s, dt about 0.01 s) stays small.
PATH_START_TOL = 1e-3

#: Below this smallest singular value (m) of a planar Jacobian, damped least squares
#: fades in (Nakamura's singular region): 5 cm on arms of links 0.2 to 1 m.
SINGULAR_REGION = 0.05

#: The damping (m) of the Newton steps that find a planar arm's start configuration:
#: enough to cross a stretched (singular) guess, and gone inside SINGULAR_REGION's
#: fade long before the target is met.
START_DAMPING = 0.01

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

# ---- statics and contact: joint torques, stiffness, closure -------------------------
# Wrenches mix forces (N) and moments (N m): before a rank, an LP or a singularity test
# the moment rows are divided by the instance's size (length_scale of its points or
# frames), so that the same instance in millimetres gets the same answers.

#: Relative. A contact set's wrench matrix (moments divided by the size) has full rank
#: when its smallest singular value exceeds this times its largest: as RANK_TOL, between
#: round-off (1e-16) and any contact placement a user means.
CONTACT_RANK_TOL = 1e-9

#: Relative. A closure certificate balances when |W k| <= CLOSURE_TOL |W| |k| (the
#: contact forces k) and separates when w_i . y >= -CLOSURE_TOL |w_i| |y|: HiGHS meets
#: its constraints to about 1e-9 relative (its default feasibility tolerance), and a
#: genuine imbalance of a random contact set is orders of magnitude larger.
CLOSURE_TOL = 1e-7

#: Relative. A Jacobian (moment rows divided by the size) is singular for the statics
#: (no stiffness at the tool, no output twist of a leg) when its smallest singular
#: value is below this times its largest: a condition number above 1e9.
STATICS_SINGULAR_TOL = 1e-9

#: Relative. Eigenvalues of a stiffness or compliance matrix are real (Patterson and
#: Lipkin: a symmetric positive semi-definite matrix times the swap Pi) up to round-off:
#: an imaginary part above this times the largest |eigenvalue| means the matrix is not
#: one.
EIGEN_IMAGINARY_TOL = 1e-8
