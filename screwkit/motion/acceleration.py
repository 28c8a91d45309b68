"""Second-order kinematics in screw form: Jacobians in time, Hessians, accelerations.

Joint i's twist in the base frame, the column J_i of the space Jacobian, is moved only
by the joints before it; each moves it by a Lie bracket (Lynch and Park, ch. 5):

    dJ_i/dq_j = [J_j, J_i] = ad(J_j) J_i    for j < i, and 0 for j >= i,
    dJ_i/dt   = [W_i, J_i],                  W_i = J_1 dq_1 + ... + J_{i-1} dq_{i-1}.

The body Jacobian is moved by the joints after a column, dJb_i/dq_j = [Jb_i, Jb_j] for
j > i; the geometric Jacobian (rows [v; omega] of the end point) follows from the
space one. The end-effector acceleration is J ddq + dJ dq in each form.

Every function takes the chain first, like :mod:`screwkit.jacobians`: float joint
values (n,) or a batch (N, n) give float64 arrays with that leading axis; SymPy input
(numbers or symbols, one configuration) gives exact SymPy matrices, with the model's
decimals read as the exact decimals they print as.

>>> import numpy as np, screwkit as sk
>>> arm = sk.robots.planar([1.0, 1.0])
>>> a = geometric_acceleration(arm, [0.0, 0.0], [1.0, 0.0], [0.0, 0.0])
>>> np.round(a[:2], 12)   # the tip turning at 1 rad/s on a 2 m circle: 2 m/s^2 inward
array([-2.,  0.])
"""

import numpy as np
import sympy as sp
from sympy.simplify.fu import TR10i

from .. import _compiled
from .._checks import (
    as_sympy_scalar,
    check_chain,
    describe,
    is_symbolic,
)
from .._docstrings import fill
from ..lie import adjoint
from ..links import decimal
from ..transforms import inv
from . import LAZY, _second_order

# the names are listed once, in the family's table of what loads on first use
__all__ = list(LAZY["acceleration"])


def _exact(*values):
    return any(is_symbolic(v) for v in values)


def _exact_vector(chain, value, name):
    """One joint vector as n exact SymPy entries (floats read as printed decimals)."""
    if isinstance(value, (str, bytes)) or not isinstance(
        value, (list, tuple, np.ndarray, sp.MatrixBase)
    ):
        raise TypeError(
            f"{name} must be a joint vector of {chain.n} numbers or SymPy "
            f"expressions, got {describe(value)}"
        )
    entries = list(value) if not isinstance(value, np.ndarray) else value.tolist()
    if len(entries) != chain.n or any(isinstance(e, (list, tuple)) for e in entries):
        raise ValueError(
            f"{name} must have {chain.n} entries for this chain (one configuration "
            f"for exact input), got {describe(value)}"
        )
    return [decimal(as_sympy_scalar(e, f"{name}[{i}]")) for i, e in enumerate(entries)]


def _exact_parts(chain, q):
    """The exact space Jacobian (6, n) and pose (4, 4) in the chain's joint symbols,
    and the substitution {symbol: value} of the exact q.

    The brackets are taken in the symbols and q put in last: SymPy multiplies
    expressions in symbols fast, but products of numbers like cos(1/3) slowly (it asks
    each whether it is zero)."""
    values = dict(zip(chain.q_symbols, _exact_vector(chain, q, "q")))
    Js = sp.Matrix.hstack(*chain.twists_symbolic(rational=True))
    T = decimal(chain.fk_symbolic()).as_mutable()
    return Js, T, values


def _geometric_exact(Js, T):
    """The geometric Jacobian from the space one: column (v + w x p; w), p T's
    origin."""
    p = T[:3, 3]
    return sp.Matrix.hstack(
        *[
            sp.Matrix.vstack(Js[3:, i] + Js[:3, i].cross(p), Js[:3, i])
            for i in range(Js.shape[1])
        ]
    )


def _at(result, values):
    """An exact result (a matrix or a list of them) with the joint values put in."""
    if isinstance(result, list):
        return [block.xreplace(values) for block in result]
    return result.xreplace(values)


def _body_exact(Js, T):
    """J_b = Ad(T^-1) J_s, in the joint symbols, expanded and with sums of angles
    combined (the products of rotations cancel there)."""
    return (adjoint(inv(T)) * Js).applyfunc(lambda e: TR10i(sp.expand(e)))


def _rates(chain, q, dq):
    """q and the joint rates dq as float64 of one shape, (n,) or (N, n)."""
    q, dq = chain.check_q(q), chain.check_q(dq, "dq")
    if dq.shape != q.shape:
        raise ValueError(
            f"dq must have the shape of q, {q.shape}, got shape {dq.shape}"
        )
    return q, dq


def _generated_jacobian_dot(chain, outputs, q, dq):
    """dJ/dt of a generated Jacobian, 'space' or 'geometric', at rates dq.

    A batch q (N, n) is worked on laid out (6, n, N) as the generated code computes
    it, each entry contiguous over the batch (no transpose, no copy)."""
    q, dq = _rates(chain, q, dq)
    dot = getattr(_second_order, f"{outputs}_dot")  # space_dot, geometric_dot
    dot_rows = getattr(_second_order, f"{outputs}_dot_rows")
    if q.ndim == 1:
        return dot(chain._generated_jacobian(q, outputs), dq)
    values = np.empty((6 * chain.n, q.shape[0]))
    chain._run(outputs, q, range(6 * chain.n), values)
    rows = values.reshape(6, chain.n, -1)
    return _second_order.batch_first(dot_rows(rows, np.ascontiguousarray(dq.T)))


def _float_dot(chain, form, q, dq):
    """dJ/dt of a form at float q and dq: the generated Jacobian's brackets for the
    space and geometric forms, the body Jacobian's for the body form."""
    if form != "body":
        return _generated_jacobian_dot(chain, form, q, dq)
    q, dq = _rates(chain, q, dq)
    return _second_order.body_dot(chain.body_jacobian(q), dq)


def _float_hessian(chain, form, q):
    """The Hessian of a form at float q, from the chain's Jacobian of that form."""
    J = getattr(chain, f"{form}_jacobian")(chain.check_q(q))
    return _HESSIAN[form](J)


def _check_batch(chain, q, kind):
    """Refuse a batch q (N, n) (a NumPy array; a list is checked by the kernel, once
    converted) whose ``kind`` of results would pass the memory limit, before its
    entries are checked or its Jacobians computed."""
    shape = q.shape if isinstance(q, np.ndarray) else ()
    count = int(np.prod(shape[:-1])) if len(shape) == 2 else 1
    _second_order.check_batch(count, chain.n, kind)


def _float_rates(chain, q, dq, ddq=None):
    q, dq = _rates(chain, q, dq)
    if ddq is None:
        return q, dq
    ddq = chain.check_q(ddq, "ddq")
    if ddq.shape != q.shape:
        raise ValueError(
            f"ddq must have the shape of q, {q.shape}, got shape {ddq.shape}"
        )
    return q, dq, ddq


# The parameters and returns each family of functions shares, written once.
_Q = "q : array-like, shape (n,) or (N, n), joint values (rad, m); or n SymPy entries"
_DQ = "dq : array-like, the shape of q, joint rates (rad/s, m/s); or n SymPy entries"
_Q_DQ_DDQ = (
    "q, dq, ddq : array-like, shape (n,) or (N, n) each: joint values, rates and\n"
    "    accelerations (rad, rad/s, rad/s^2; m for prismatic joints); or SymPy entries"
)


def _sections(parameters, returns):
    """A Parameters section (the chain first) and a Returns section."""
    return (
        f"Parameters\n----------\nchain : Chain\n{parameters}\n\n"
        f"Returns\n-------\n{returns}"
    )


def _dot_sections(layout):
    """The sections of a Jacobian's time derivative, its columns laid out so."""
    return _sections(
        f"{_Q}\n{_DQ}",
        f"ndarray, shape (6, n) or (N, 6, n), {layout} per second;\n"
        "sympy.Matrix (6, n) for exact input",
    )


_HESSIAN_SECTIONS = _sections(
    _Q,
    "ndarray, shape (n, 6, n) or (N, n, 6, n); for exact input a list of n SymPy\n"
    "(6, n) matrices H[j]",
)


def _acceleration_sections(entries):
    """The sections of an end-effector acceleration, its six entries named so."""
    return _sections(
        _Q_DQ_DDQ,
        f"ndarray, shape (6,) or (N, 6), {entries};\n"
        "sympy.Matrix (6, 1) for exact input",
    )


def _exact_jacobian(Js, T, form):
    """The exact Jacobian of a form, 'space', 'body' or 'geometric', from the space
    one Js and the pose T."""
    if form == "space":
        return Js
    if form == "body":
        return _body_exact(Js, T)
    return _geometric_exact(Js, T)


#: The second-order kernels of each form: the time derivative and the Hessian.
_DOT = {
    "space": _second_order.space_dot,
    "body": _second_order.body_dot,
    "geometric": _second_order.geometric_dot,
}
_HESSIAN = {
    "space": _second_order.space_hessian,
    "body": _second_order.body_hessian,
    "geometric": _second_order.geometric_hessian,
}


def _one_dot(chain, form, values, rates):
    """dJ/dt of a form at one configuration, q and dq lists of n floats: the
    Jacobian's entries from the generated code and the brackets in Python floats,
    (6, n)."""
    if form == "body":
        J = chain.body_jacobian(values).ravel().tolist()
    else:
        J = _compiled.scalar(chain, form)(values)
    return np.array(_SCALAR_DOT[form](J, chain.n, rates), float).reshape(6, chain.n)


# The kernels of one configuration: J the Jacobian's 6 n entries row by row (entry
# (r, i) at r n + i), rates a list of n floats; they return dJ/dt's entries in that
# order, with the sums and products of :mod:`._second_order` in the same order (the
# prefix sums of ``_before``, the suffix sums of ``_from``, the cross products of
# ``transforms._cross_into``), so that one configuration gives the batch's numbers.


def _space_dot_one(J, n, rates):
    """:func:`_second_order.space_dot` of one configuration (columns [w; v])."""
    out = [0.0] * (6 * n)
    a0 = a1 = a2 = b0 = b1 = b2 = 0.0  # W_i = (a; b), the sum of J_j dq_j, j < i
    for i in range(n):
        if i:
            k, rate = i - 1, rates[i - 1]
            a0, a1, a2 = (
                a0 + J[k] * rate,
                a1 + J[n + k] * rate,
                a2 + J[2 * n + k] * rate,
            )
            b0 = b0 + J[3 * n + k] * rate
            b1 = b1 + J[4 * n + k] * rate
            b2 = b2 + J[5 * n + k] * rate
        w0, w1, w2 = J[i], J[n + i], J[2 * n + i]
        v0, v1, v2 = J[3 * n + i], J[4 * n + i], J[5 * n + i]
        out[i] = a1 * w2 - a2 * w1
        out[n + i] = a2 * w0 - a0 * w2
        out[2 * n + i] = a0 * w1 - a1 * w0
        out[3 * n + i] = (a1 * v2 - a2 * v1) + b1 * w2 - b2 * w1
        out[4 * n + i] = (a2 * v0 - a0 * v2) + b2 * w0 - b0 * w2
        out[5 * n + i] = (a0 * v1 - a1 * v0) + b0 * w1 - b1 * w0
    return out


def _suffix_sums(J, n, rates):
    """The sums over j >= i of the six rows of column j times dq_j, for every i: a
    list of n lists."""
    rows = range(6)
    sums = [None] * n
    last, rate = n - 1, rates[n - 1]
    S = [J[r * n + last] * rate for r in rows]
    sums[last] = S
    for i in range(n - 2, -1, -1):
        rate = rates[i]
        S = [S[k] + J[r * n + i] * rate for k, r in enumerate(rows)]
        sums[i] = S
    return sums


def _body_dot_one(J, n, rates):
    """:func:`_second_order.body_dot` of one configuration (columns [w; v]); W_i the
    sum over j > i, the sum over j >= i less column i's own term."""
    out = [0.0] * (6 * n)
    for i, S in enumerate(_suffix_sums(J, n, rates)):
        w0, w1, w2 = J[i], J[n + i], J[2 * n + i]
        v0, v1, v2 = J[3 * n + i], J[4 * n + i], J[5 * n + i]
        rate = rates[i]
        a0, a1, a2 = S[0] - w0 * rate, S[1] - w1 * rate, S[2] - w2 * rate
        b0, b1, b2 = S[3] - v0 * rate, S[4] - v1 * rate, S[5] - v2 * rate
        out[i] = w1 * a2 - w2 * a1
        out[n + i] = w2 * a0 - w0 * a2
        out[2 * n + i] = w0 * a1 - w1 * a0
        out[3 * n + i] = (w1 * b2 - w2 * b1) + v1 * a2 - v2 * a1
        out[4 * n + i] = (w2 * b0 - w0 * b2) + v2 * a0 - v0 * a2
        out[5 * n + i] = (w0 * b1 - w1 * b0) + v0 * a1 - v1 * a0
    return out


def _geometric_dot_one(J, n, rates):
    """:func:`_second_order.geometric_dot` of one configuration (rows [v; omega],
    columns (u; w)): (W x u + w x S; W x w)."""
    n2, n3, n4, n5 = 2 * n, 3 * n, 4 * n, 5 * n
    S0, S1, S2 = [0.0] * n, [0.0] * n, [0.0] * n  # S_i, the sum of u_j dq_j, j >= i
    k, rate = n - 1, rates[n - 1]
    s0, s1, s2 = J[k] * rate, J[n + k] * rate, J[n2 + k] * rate
    S0[k], S1[k], S2[k] = s0, s1, s2
    for k in range(n - 2, -1, -1):
        rate = rates[k]
        s0, s1, s2 = s0 + J[k] * rate, s1 + J[n + k] * rate, s2 + J[n2 + k] * rate
        S0[k], S1[k], S2[k] = s0, s1, s2
    out = [0.0] * (6 * n)
    a0 = a1 = a2 = 0.0  # W_i, the sum of w_j dq_j over j < i
    for i in range(n):
        if i:
            k, rate = i - 1, rates[i - 1]
            a0, a1, a2 = (
                a0 + J[n3 + k] * rate,
                a1 + J[n4 + k] * rate,
                a2 + J[n5 + k] * rate,
            )
        u0, u1, u2 = J[i], J[n + i], J[n2 + i]
        w0, w1, w2 = J[n3 + i], J[n4 + i], J[n5 + i]
        s0, s1, s2 = S0[i], S1[i], S2[i]
        out[i] = (a1 * u2 - a2 * u1) + w1 * s2 - w2 * s1
        out[n + i] = (a2 * u0 - a0 * u2) + w2 * s0 - w0 * s2
        out[n2 + i] = (a0 * u1 - a1 * u0) + w0 * s1 - w1 * s0
        out[n3 + i] = a1 * w2 - a2 * w1
        out[n4 + i] = a2 * w0 - a0 * w2
        out[n5 + i] = a0 * w1 - a1 * w0
    return out


_SCALAR_DOT = {
    "space": _space_dot_one,
    "body": _body_dot_one,
    "geometric": _geometric_dot_one,
}


def _jacobian_dot(chain, form, q, dq):
    """dJ/dt of a form, exact for SymPy input, else in floats (one plain
    configuration by the scalar path)."""
    check_chain(chain)
    values, rates = _compiled.one(q, chain.n), _compiled.one(dq, chain.n)
    if values is not None and rates is not None:
        return _one_dot(chain, form, values, rates)
    if _exact(q, dq):
        Js, T, values = _exact_parts(chain, q)
        dq = _exact_vector(chain, dq, "dq")
        return _at(_DOT[form](_exact_jacobian(Js, T, form), dq), values)
    _check_batch(chain, q, "Jacobian derivatives")
    return _float_dot(chain, form, q, dq)


def _hessian(chain, form, q):
    """The Hessian of a form, exact for SymPy input, else in floats."""
    check_chain(chain)
    if _exact(q):
        Js, T, values = _exact_parts(chain, q)
        return _at(_HESSIAN[form](_exact_jacobian(Js, T, form)), values)
    _check_batch(chain, q, "Hessians")
    return _float_hessian(chain, form, q)


def _end_acceleration(chain, form, q, dq, ddq):
    """J ddq + dJ dq of a form: exactly, in the joint symbols with q put in last, for
    SymPy input; else with the chain's float Jacobian and its derivative."""
    check_chain(chain)
    if _exact(q, dq, ddq):
        Js, T, values = _exact_parts(chain, q)
        dq = _exact_vector(chain, dq, "dq")
        ddq = sp.Matrix(_exact_vector(chain, ddq, "ddq"))
        J = _exact_jacobian(Js, T, form)
        return _at(J * ddq + _DOT[form](J, dq) * sp.Matrix(dq), values)
    _check_batch(chain, q, "accelerations")
    q, dq, ddq = _float_rates(chain, q, dq, ddq)
    J = getattr(chain, f"{form}_jacobian")(q)
    dJ = _float_dot(chain, form, q, dq)
    product = "...ij,...j->...i"
    return np.einsum(product, J, ddq) + np.einsum(product, dJ, dq)


@fill(sections=_dot_sections("columns [omega; v]"))
def space_jacobian_dot(chain, q, dq):
    """The time derivative of the space Jacobian, column i = [W_i, J_i].

    {sections}

    Examples
    --------
    A planar 2R arm with unit links: joint 2's twist is (z; (c1, s1, 0) x z), whose
    v = (s1, -c1, 0) changes at (c1, s1, 0) dq1: (1, 0, 0) at q1 = 0, dq1 = 1.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> dJ = space_jacobian_dot(arm, [0.0, 0.0], [1.0, 0.0])
    >>> np.round(dJ.T, 6) + 0.0
    array([[0., 0., 0., 0., 0., 0.],
           [0., 0., 0., 1., 0., 0.]])
    """
    return _jacobian_dot(chain, "space", q, dq)


@fill(sections=_dot_sections("columns [omega; v]"))
def body_jacobian_dot(chain, q, dq):
    """The time derivative of the body Jacobian, column i = [Jb_i, Wb_i], Wb_i the
    sum of Jb_j dq_j over j > i.

    {sections}

    Examples
    --------
    A planar 2R arm with unit links: joint 1's body column is
    (0, 0, 1, sin q2, 1 + cos q2, 0), which changes at (0, 0, 0, 1, 0, 0) dq2 at
    q2 = 0; joint 2's column is constant.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> dJ = body_jacobian_dot(arm, [0.0, 0.0], [0.0, 1.0])
    >>> np.round(dJ.T, 6) + 0.0
    array([[0., 0., 0., 1., 0., 0.],
           [0., 0., 0., 0., 0., 0.]])
    """
    return _jacobian_dot(chain, "body", q, dq)


@fill(sections=_dot_sections("rows [v; omega]"))
def geometric_jacobian_dot(chain, q, dq):
    """The time derivative of the geometric Jacobian (rows [v; omega] of the end
    point), as the Robotics Toolbox's ``jacob0_dot``.

    {sections}

    Examples
    --------
    A planar 2R arm with unit links: the rows v_x, v_y of J are
    (-s1 - s12, -s12) and (c1 + c12, c12); at q = 0 with dq = (1, 0) they change at
    (-2, -1) and (0, 0).

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> dJ = geometric_jacobian_dot(arm, [0.0, 0.0], [1.0, 0.0])
    >>> np.round(dJ[:2], 6) + 0.0
    array([[-2., -1.],
           [ 0.,  0.]])
    """
    return _jacobian_dot(chain, "geometric", q, dq)


@fill(sections=_HESSIAN_SECTIONS)
def space_hessian(chain, q):
    """The Hessian of the space Jacobian, H[j, :, i] = dJ_i/dq_j = [J_j, J_i] (j < i).

    {sections}

    Examples
    --------
    A planar 2R arm with unit links: only joint 2's twist moves, with q1:
    dJ_2/dq1 = (0, 0, 0, c1, s1, 0), (0, 0, 0, 1, 0, 0) at q1 = 0.

    >>> import screwkit as sk
    >>> H = space_hessian(sk.robots.planar([1.0, 1.0]), [0.0, 0.0])
    >>> H.shape
    (2, 6, 2)
    >>> np.round(H[0, :, 1], 6) + 0.0
    array([0., 0., 0., 1., 0., 0.])
    >>> H[0, :, 1] = 0.0  # nothing else
    >>> bool(np.allclose(H, 0.0))
    True
    """
    return _hessian(chain, "space", q)


@fill(sections=_HESSIAN_SECTIONS)
def body_hessian(chain, q):
    """The Hessian of the body Jacobian, H[j, :, i] = dJb_i/dq_j = [Jb_i, Jb_j]
    (j > i).

    {sections}

    Examples
    --------
    A planar 2R arm with unit links: joint 1's body column
    (0, 0, 1, sin q2, 1 + cos q2, 0) has dJb_1/dq2 = (0, 0, 0, 1, 0, 0) at q2 = 0.

    >>> import screwkit as sk
    >>> H = body_hessian(sk.robots.planar([1.0, 1.0]), [0.0, 0.0])
    >>> np.round(H[1, :, 0], 6) + 0.0
    array([0., 0., 0., 1., 0., 0.])
    """
    return _hessian(chain, "body", q)


@fill(sections=_HESSIAN_SECTIONS)
def geometric_hessian(chain, q):
    """The Hessian of the geometric Jacobian, H[j, :, i] = dJ_i/dq_j, rows [v; omega]
    (the Robotics Toolbox's ``hessian0``).

    {sections}

    Examples
    --------
    For a planar 2R arm with unit links, H[:, 0, :] is the Hessian of the tip's
    x = cos q1 + cos(q1 + q2): [[-2, -1], [-1, -1]] at q = 0.

    >>> import screwkit as sk
    >>> H = geometric_hessian(sk.robots.planar([1.0, 1.0]), [0.0, 0.0])
    >>> np.round(H[:, 0, :], 6) + 0.0
    array([[-2., -1.],
           [-1., -1.]])
    """
    return _hessian(chain, "geometric", q)


@fill(sections=_acceleration_sections("[d omega/dt; dv/dt]"))
def space_acceleration(chain, q, dq, ddq):
    """The derivative of the end effector's space twist, dV_s/dt = J_s ddq + dJ_s dq.

    {sections}

    Examples
    --------
    A planar 2R arm with unit links, stretched, turning about joint 1 at 1 rad/s:
    a rotation about a fixed axis at a constant rate has a constant space twist,
    though the tip has a centripetal acceleration (see
    :func:`geometric_acceleration`).

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> dV = space_acceleration(arm, [0.0, 0.0], [1.0, 0.0], [0.0, 0.0])
    >>> np.round(dV, 6) + 0.0
    array([0., 0., 0., 0., 0., 0.])
    """
    return _end_acceleration(chain, "space", q, dq, ddq)


@fill(sections=_acceleration_sections("[d omega_b/dt; dv_b/dt]"))
def body_acceleration(chain, q, dq, ddq):
    """The derivative of the end effector's body twist, dV_b/dt = J_b ddq + dJ_b dq.

    {sections}

    Examples
    --------
    A planar 2R arm with unit links, stretched: joint 1 speeding up at 1 rad/s^2
    from rest gives J_b ddq, joint 1's body column: the tool 2 m from the axis
    starts along its y axis at 2 m/s^2.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> dV = body_acceleration(arm, [0.0, 0.0], [0.0, 0.0], [1.0, 0.0])
    >>> np.round(dV, 6) + 0.0
    array([0., 0., 1., 0., 2., 0.])
    """
    return _end_acceleration(chain, "body", q, dq, ddq)


@fill(sections=_acceleration_sections("[a (m/s^2); alpha (rad/s^2)]"))
def geometric_acceleration(chain, q, dq, ddq):
    """The end point's linear acceleration and the angular acceleration, in the base
    frame: [a; alpha] = J ddq + dJ dq with the geometric Jacobian (rows [v; omega]).

    ``a`` is the second derivative of the end point's position (centripetal and
    Coriolis terms included), which the space twist's derivative is not.

    {sections}

    Examples
    --------
    A planar 2R arm with unit links, stretched, turning about joint 1 at 1 rad/s:
    the tip, 2 m from the axis, has the centripetal acceleration
    omega^2 r = 2 m/s^2 towards the axis, and no angular acceleration.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> a = geometric_acceleration(arm, [0.0, 0.0], [1.0, 0.0], [0.0, 0.0])
    >>> np.round(a, 6) + 0.0
    array([-2.,  0.,  0.,  0.,  0.,  0.])
    """
    return _end_acceleration(chain, "geometric", q, dq, ddq)
