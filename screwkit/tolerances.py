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

# ---- parallel: model, legs, numerics, search ----------------------------------------
