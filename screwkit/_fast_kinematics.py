"""A chain's fast kinematics (NumPy): the straight-line program generated from its
numbers, FK and frames of one configuration or a batch, and the product of
exponentials.

The functions take the chain first; each is the :class:`~screwkit.chains.Chain` method
of the same name (``chain.fk(q)`` is ``fk(chain, q)``). The program is built once per
chain (``chain._program``, cached) and each output compiled on first use (see
:mod:`screwkit._compiled`).
"""

import numpy as np

from . import _compiled
from ._checks import check_option
from ._docstrings import CHAIN, CHAIN_Q, fill
from .links import axis_points, dh_factors, translation
from .transforms import exp_twist


def _program(chain):
    """The chain as constants and unit joint twists for :mod:`screwkit._compiled`
    (floats only)."""
    if chain.is_dh:
        parts = [
            dh_factors(link, i, chain.convention)
            for i, link in enumerate(chain.links, start=1)
        ]
        pres = [pre for pre, _, _ in parts] + [np.eye(4)]
        start = np.asarray(chain.base) @ pres[0]
        factors, marks = [], {0: np.linalg.inv(pres[0])}
        for k, (_, twist, post) in enumerate(parts, start=1):
            after = post @ pres[k]
            if k == chain.n:
                after = after @ chain.tool
            factors.append((twist, after, np.zeros(3)))
            marks[k] = np.linalg.inv(pres[k])
        offsets = np.array(
            [float(link._numbers(i)[0][3]) for i, link in enumerate(chain.links, 1)]
        )
        return _compiled.Program(start, factors, marks), offsets
    home = np.asarray(chain._home)
    if chain.frame == "space":
        start, last = np.asarray(chain.base), home @ chain.tool
        points = axis_points(chain._screws, np.zeros(3))
    else:
        start, last = np.asarray(chain.base) @ home, np.asarray(chain.tool)
        # the screws are in end-effector coordinates: start from the base origin
        # seen there
        points = axis_points(chain._screws, -home[:3, :3].T @ home[:3, 3])
    factors = [(S, np.eye(4), r) for S, r in zip(chain._screws, points)]
    factors[-1] = (factors[-1][0], last, factors[-1][2])
    marks = {k: translation(points[k]) for k in range(chain.n)}
    marks[chain.n] = np.eye(4)
    return _compiled.Program(start, factors, marks), np.zeros(chain.n)


def _functions(chain):
    """The generated functions, compiled on first use: {'pose' | 'axes' | 'frames':
    function}."""
    return {}


@fill(chain=CHAIN)
def source(chain, outputs="pose"):
    """The straight-line Python that computes this chain's ``outputs`` (a string).

    The function ``kinematics(t, c, s)`` generated from the chain's numbers (see
    :mod:`screwkit._compiled`): ``t`` the joint angles plus their offsets
    (t = q + offset; the DH theta or d offsets), ``c``, ``s`` their cosines and
    sines; it returns the entries row by row. ``outputs``: 'pose'
    (the 12 entries of T's top three rows), 'frames', 'space' or 'geometric'
    (the Jacobians, 6 x n) or 'axes' (each joint's twist and a point, then the
    pose). What :meth:`fk` and the Jacobians run, as text to read.

    {chain}
    outputs : {'pose', 'frames', 'space', 'geometric', 'axes'}, optional
        What the generated function returns.

    Returns
    -------
    str
        The function's source.

    Examples
    --------
    >>> import screwkit as sk
    >>> arm = sk.Chain([sk.Link.revolute(a=1.0)])
    >>> print(arm.source())  # doctest: +NORMALIZE_WHITESPACE
    def kinematics(t, c, s):
        c1 = c[0]
        s1 = s[0]
        return (c1, -1.0*s1, 0.0, c1, s1, c1, 0.0, s1, 0.0, 0.0, 1.0, 0.0,)
    """
    check_option(outputs, "outputs", ("pose", "frames", "space", "geometric", "axes"))
    return chain._program[0].source(outputs)


#: The last row of a pose, appended to the 12 entries the generated code computes.
_LAST_ROW = (0.0, 0.0, 0.0, 1.0)


def _run(chain, outputs, q, rows=None, out=None):
    """Generated code ``outputs`` at q: a list of entries for (n,), else
    ``out[rows[k]]`` filled."""
    program, offsets = chain._program
    if outputs not in chain._functions:
        chain._functions[outputs] = program.compile(outputs)
    function = chain._functions[outputs]
    if q.ndim == 1:
        return _compiled.evaluate(function, q + offsets)
    return _compiled.evaluate_batch(function, q + offsets, out, rows)


@fill(parameters=CHAIN_Q)
def fk(chain, q):
    """The end-effector pose.

    {parameters}

    Returns
    -------
    ndarray, shape (4, 4) or (N, 4, 4)
        The pose(s) in the base's world frame (m).

    Examples
    --------
    A planar 2R arm with unit links at q = (0, pi/2): the tip is at (1, 1), the
    tool's x axis along the base's y.

    >>> import screwkit as sk
    >>> T = fk(sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> np.round(T, 6) + 0.0
    array([[ 0., -1.,  0.,  1.],
           [ 1.,  0.,  0.,  1.],
           [ 0.,  0.,  1.,  0.],
           [ 0.,  0.,  0.,  1.]])
    """
    values = _compiled.one(q, chain.n)
    if values is not None:  # one configuration: the scalar path
        entries = _compiled.scalar(chain, "pose")(values) + _LAST_ROW
        return np.array(entries, float).reshape(4, 4)
    q = chain.check_q(q)
    if q.ndim == 1:
        T = np.eye(4)
        T[:3] = np.reshape(chain._run("pose", q), (3, 4))
        return T
    T = np.empty((4, 4, q.shape[0]))
    T[3] = np.array([0.0, 0.0, 0.0, 1.0])[:, None]
    chain._run("pose", q, range(12), T.reshape(16, -1))
    return T.transpose(2, 0, 1)  # a view: each entry was computed as one contiguous row


@fill(parameters=CHAIN_Q)
def frames(chain, q):
    """The base frame and every link frame.

    DH chain: frame k is base @ A_1 ... A_k; the last frame also carries the tool.
    Chain from screws: frame k < n sits on the axis of joint k + 1
    (a point of it, moved by joints 1..k), frame 0 has the base's orientation, and
    the last frame is the end effector.

    {parameters}

    Returns
    -------
    ndarray, shape (n + 1, 4, 4) or (N, n + 1, 4, 4)
        The frames (m).

    Examples
    --------
    The origins of a planar 2R arm's frames at q = (0, pi/2): base, elbow, tip.

    >>> import screwkit as sk
    >>> F = frames(sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> np.round(F[:, :2, 3], 6) + 0.0
    array([[0., 0.],
           [1., 0.],
           [1., 1.]])
    """
    q = chain.check_q(q)
    count = chain.n + 1
    if q.ndim == 1:
        T = np.zeros((count, 4, 4))
        T[:, :3] = np.reshape(chain._run("frames", q), (count, 3, 4))
        T[:, 3, 3] = 1.0
        return T
    T = np.zeros((count, 4, 4, q.shape[0]))
    T[:, 3, 3] = 1.0
    rows = [16 * (k // 12) + k % 12 for k in range(12 * count)]
    chain._run("frames", q, rows, T.reshape(16 * count, -1))
    return np.ascontiguousarray(T.transpose(3, 0, 1, 2))


def _twists_and_pose(chain, q):
    """Joint twists, axis points and pose, batch last: omega, v, point (3, n[, N]),
    T (3, 4[, N])."""
    rows = 9 * chain.n + 12
    if q.ndim == 1:
        values = np.array(chain._run("axes", q))
    else:
        values = np.empty((rows, q.shape[0]))
        chain._run("axes", q, range(rows), values)
    axes = values[:-12].reshape((chain.n, 3, 3) + values.shape[1:])
    axes = np.moveaxis(axes, 0, 2)  # (3 kinds, 3 coordinates, n[, N])
    return (
        axes[0],
        axes[1],
        axes[2],
        values[-12:].reshape((3, 4) + values.shape[1:]),
    )


@fill(chain=CHAIN)
def home(chain):
    """The end-effector pose at q = 0: the home pose of the product of
    exponentials.

    {chain}

    Returns
    -------
    ndarray, shape (4, 4)
        M (m).

    Examples
    --------
    A planar 2R arm with links 1 and 0.5 m, stretched along x:

    >>> import screwkit as sk
    >>> M = home(sk.robots.planar([1.0, 0.5]))
    >>> np.round(M[:3, 3], 6) + 0.0
    array([1.5, 0. , 0. ])
    """
    return chain.fk(np.zeros(chain.n))


@fill(chain=CHAIN)
def screw_axes(chain):
    """The joint screws at q = 0 in the base frame.

    Revolute: (z, p x z) for the axis z through p; prismatic: (0, z).

    {chain}

    Returns
    -------
    ndarray, shape (n, 6)
        Rows [omega; v]: the columns of the space Jacobian at q = 0.

    Examples
    --------
    A planar 2R arm with unit links: z through the origin, and z through
    (1, 0, 0), whose v = (1, 0, 0) x z = (0, -1, 0).

    >>> import screwkit as sk
    >>> np.round(screw_axes(sk.robots.planar([1.0, 1.0])), 6) + 0.0
    array([[ 0.,  0.,  1.,  0.,  0.,  0.],
           [ 0.,  0.,  1.,  0., -1.,  0.]])
    """
    return chain.space_jacobian(np.zeros(chain.n)).T


@fill(chain=CHAIN)
def body_screw_axes(chain):
    """The joint screws at q = 0 in the end-effector frame.

    {chain}

    Returns
    -------
    ndarray, shape (n, 6)
        Rows [omega; v].

    Examples
    --------
    A planar 2R arm with unit links: in the tool frame its axes are z through
    r = (-2, 0, 0) and (-1, 0, 0), so v = r x z = (0, 2, 0) and (0, 1, 0).

    >>> import screwkit as sk
    >>> np.round(body_screw_axes(sk.robots.planar([1.0, 1.0])), 6) + 0.0
    array([[0., 0., 1., 0., 2., 0.],
           [0., 0., 1., 0., 1., 0.]])
    """
    return chain.body_jacobian(np.zeros(chain.n)).T


@fill(chain=CHAIN)
def fk_poe(chain, q):
    """The pose by the product of exponentials exp([S1] q1) ... exp([Sn] qn) M.

    An independent route to :meth:`fk` (a loop of 4x4 exponentials), for checking.

    {chain}
    q : array-like, shape (n,)
        Joint values (rad or m).

    Returns
    -------
    ndarray, shape (4, 4)
        The pose (m).

    Examples
    --------
    The product of exponentials agrees with the DH route of :meth:`fk`:

    >>> import screwkit as sk
    >>> arm, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
    >>> bool(np.allclose(fk_poe(arm, q), fk(arm, q), atol=1e-12))
    True
    """
    q = chain.check_one(q)
    T = np.eye(4)
    for S, qi in zip(chain.screw_axes(), q):
        T = T @ exp_twist(S, qi)
    return T @ chain.home()
