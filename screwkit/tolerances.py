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
