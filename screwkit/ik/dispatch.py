"""The closed-form dispatcher: which engine solves a chain, and the labelled answer.

Closed form (:func:`analytic_ik`, :func:`analytic_ik_all`), solved from the chain's own
screws by the Paden–Kahan subproblems (:mod:`screwkit.ik.subproblems`), for any
lengths, offsets, base and tool of these structures (:data:`STRUCTURES`, tried in order;
:func:`structure` and ``IKSolutions.structure`` say which one a chain has):

* 6R, a spherical wrist (the last three axes meet) and joints 2, 3 parallel: the PUMA
  560, the Kawasaki CX210L (:mod:`screwkit.ik.spherical_wrist`);
* UR-type 6R: joints 2, 3, 4 parallel and axes 5, 6 meeting: the Universal Robots arms
  (:mod:`screwkit.ik.ur`, after Hawkins 2013);
* RRP with a spherical wrist, joints 1, 2 meeting: the Stanford arm
  (:mod:`screwkit.ik.stanford`; eight solutions, four with the boom forward).

Up to eight solutions, labelled l/r arm, u/d elbow, n/f wrist by geometric definitions
(Corke's labels for the PUMA). Any other 6R arm is classified by its axes
(:func:`screwkit.ik.decomposed.classify`): a spherical wrist or shoulder, or three
parallel axes 2, 3, 4 or 3, 4, 5, is solved by subproblems 5 and 6
(:mod:`screwkit.ik.decomposed`, labels 's0' ...); any other 6R by
the eigenvalue method of :mod:`screwkit.ik.general` (Raghavan-Roth, Manocha-Canny; up
to 16 solutions). A chain of none of these (not 6R or 7R) is refused with a
``ValueError`` that says what each structure needs (use
:func:`screwkit.ik.numeric_ik`). A 7R arm is solved with one joint held
(``fixed={index: value}``). Every solution carries its pose residual and a within-limits
flag. :func:`puma560_ik` is the same solver under the PUMA's name.

One angle convention: every closed-form angle is in (-pi, pi]. ``within_limits=True`` is
the explicit option that moves angles by whole turns into the joint limits
(e.g. q2 = -170 deg becomes 190 deg for the PUMA) and drops the solutions that cannot be
moved there.

Numeric IK of any chain is :mod:`screwkit.ik.newton`.

>>> import numpy as np, screwkit as sk
>>> robot = sk.robots.puma560()
>>> q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
>>> solutions = puma560_ik(robot.fk(q))
>>> [s.config for s in solutions]
['lun', 'luf', 'ldn', 'ldf', 'run', 'ruf', 'rdn', 'rdf']
>>> np.round(solutions.by_config('ruf').q, 6)
array([ 0.3,  0.5, -2. ,  0.4,  0.7,  0.2])
"""

import weakref
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import _compiled
from .._checks import (
    as_float_array,
    check_chain,
    check_flag,
    check_integer,
    check_poses,
    describe,
    one_pose,
)
from ..links import Joint
from ..robots import puma560
from ..tolerances import IK_JOINT_LIMIT_SLACK
from ..tolerances import IK_SINGULAR_TOL as SINGULAR_TOL
from ..transforms import _wrap_angle
from . import _one_pose
from ._closed_form import pose_residual
from .decomposed import DecomposedArm, _motions, classify
from .general import (
    _check_batch_size,
    _mobility,
    _mobility_reason,
    general_6r_ik,
)
from .spherical_wrist import CONFIGURATIONS, SphericalWristArm
from .stanford import StanfordArm
from .ur import URArm

__all__ = [
    "CONFIGURATIONS",
    "IKSolution",
    "IKSolutions",
    "analytic_ik",
    "analytic_ik_all",
    "configuration",
    "puma560_ik",
    "puma560_ik_all",
    "puma560_config",
    "SINGULAR_TOL",
    "STRUCTURES",
    "structure",
]


@dataclass(frozen=True)
class IKSolution:
    """One closed-form solution of a pose.

    Parameters
    ----------
    q : ndarray, shape (6,)
        The joint vector (rad; m for a prismatic joint).
    config : str
        Its label, one of :data:`CONFIGURATIONS` ('lun' ... 'rdf').
    singular : tuple of str
        The singularities it sits on: ``'shoulder'``, ``'elbow'``, ``'wrist'`` (the
        Stanford arm's boom counts as its elbow); ``'continuum'`` (a decomposable 6R:
        an angle free) or ``'singular'`` (a general 6R: the Jacobian loses rank);
        empty for a regular solution. The answer's ``reason`` says so whenever one
        solution has any.
    within_limits : bool
        Whether q, or q moved by whole turns, respects the joint limits.
    residual : float
        How far the chain's pose at q is from the asked one: the largest entry of the
        rotation's difference and of the position's divided by the arm's size (m / m).

    Examples
    --------
    >>> IKSolution(np.array([0.1, -0.4, 0.3, 0.5, -0.6, 0.7]), "rdn")
    IKSolution(rdn: q=[+0.1000, -0.4000, +0.3000, +0.5000, -0.6000, +0.7000],
               within_limits=True)
    """

    q: np.ndarray
    config: str
    singular: tuple = ()
    within_limits: bool = True
    residual: float = float("nan")

    def __repr__(self):
        q = ", ".join(f"{v:+.4f}" for v in self.q)
        extra = f", singular={self.singular}" if self.singular else ""
        return (
            f"IKSolution({self.config}: q=[{q}], "
            f"within_limits={self.within_limits}{extra})"
        )


class _Residual:
    """IKSolution.residual: the value stored on the solution, or, for a solution of
    the scalar path (``_residual_of`` = (pose function, q, target, scale) set in
    place of it), computed on first access and stored (a frozen dataclass: its
    ``__dict__`` written directly). The field's default stays float('nan')."""

    def __get__(self, solution, owner=None):
        if solution is None:
            return float("nan")
        found = solution.__dict__
        try:
            return found["residual"]
        except KeyError:
            pose, q, target, scale = found["_residual_of"]  # kept: thread-safe
            value = found["residual"] = _one_pose.residual(pose(q), target, scale)
            return value

    def __set__(self, solution, value):
        solution.__dict__["residual"] = value
        solution.__dict__.pop("_residual_of", None)


def _state(solution):
    """The fields of a solution to pickle or copy, its residual computed (not the
    generated pose function it would be computed with)."""
    solution.residual  # noqa: B018 (computed and stored if not yet)
    return {k: v for k, v in solution.__dict__.items() if k != "_residual_of"}


IKSolution.residual = _Residual()  # after the dataclass took the field and default
IKSolution.__getstate__ = _state


class IKSolutions(list):
    """The solutions for one pose: a list of :class:`IKSolution`.

    Parameters
    ----------
    solutions : iterable of IKSolution
    reason : str or None
        Why the list is empty (out of reach, or outside the joint limits), or what is
        special about its solutions (some at a singular configuration or on a
        continuum, or the list possibly incomplete); None for isolated, regular
        solutions.
    structure : str or None
        The structure the closed form recognised (a key of :data:`STRUCTURES`).

    Examples
    --------
    A PUMA 560 reaches a regular pose in eight ways, one per label:

    >>> import screwkit as sk
    >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
    >>> solutions = analytic_ik(puma, puma.fk(q))
    >>> len(solutions), solutions.structure
    (8, 'spherical wrist (joints 2, 3 parallel)')
    """

    def __init__(self, solutions=(), reason=None, structure=None):
        super().__init__(solutions)
        self.reason = reason
        self.structure = structure

    def by_config(self, config):
        """The solution with this label.

        Parameters
        ----------
        config : str
            One of the eight labels of :data:`CONFIGURATIONS`; any other value is a
            ``ValueError``.

        Returns
        -------
        IKSolution or None
            None if that branch has no solution.

        Examples
        --------
        The PUMA's joint vector comes back under its own label:

        >>> import screwkit as sk
        >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
        >>> label = configuration(puma, q)
        >>> label
        'rdn'
        >>> analytic_ik(puma, puma.fk(q)).by_config(label)
        IKSolution(rdn: q=[+0.1000, -0.4000, +0.3000, +0.5000, -0.6000, +0.7000],
                   within_limits=True)
        """
        labels = (
            CONFIGURATIONS
            if not self or self[0].config in CONFIGURATIONS
            else [s.config for s in self]
        )
        if config not in labels:
            raise ValueError(
                f"config must be one of {', '.join(labels)}, got {config!r}"
            )
        return next((s for s in self if s.config == config), None)

    def nearest(self, q):
        """The solution closest to a joint vector, by wrapped angle differences.

        Parameters
        ----------
        q : array-like, shape (6,)
            A joint vector (rad).

        Returns
        -------
        IKSolution or None
            None if there is no solution.

        Examples
        --------
        Of the PUMA's eight solutions, the one nearest the joint vector that made the
        pose is that vector:

        >>> import screwkit as sk
        >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
        >>> analytic_ik(puma, puma.fk(q)).nearest(q)
        IKSolution(rdn: q=[+0.1000, -0.4000, +0.3000, +0.5000, -0.6000, +0.7000],
                   within_limits=True)
        """
        q = as_float_array(q, "q")
        n = len(self[0].q) if self else 6
        if q.shape != (n,):
            raise ValueError(f"q must have {n} entries, got shape {q.shape}")
        if not self:
            return None
        return min(self, key=lambda s: np.linalg.norm(_wrap_angle(s.q - q)))


@lru_cache(maxsize=1)
def _default_puma():
    return puma560()


_ARMS = (
    weakref.WeakKeyDictionary()
)  # chains are immutable: their geometry is found once

#: The largest batches of poses: analytic_ik answers each pose with Python objects
#: (a list of IKSolutions), analytic_ik_all with an array of 8 x 6 angles a pose
#: (384 bytes: 10^6 poses are 384 MB); larger ones are refused before any work.
MAX_POSES = 100_000
MAX_POSES_ALL = 1_000_000

#: The structures solved in closed form, in the order they are tried: {name: solver}.
STRUCTURES = {
    "spherical wrist (joints 2, 3 parallel)": SphericalWristArm,
    URArm.structure: URArm,
    StanfordArm.structure: StanfordArm,
}


#: The engines with a scalar path for one pose (:mod:`._one_pose`): {engine: solver}.
_ONE_POSE = {SphericalWristArm: _one_pose.solve_wrist, URArm: _one_pose.solve_ur}


class _GeneralArm:
    """A 6R arm of no decomposable class, solved by :mod:`screwkit.ik.general`."""

    def __init__(self, chain, solver, structure):
        self.chain, self.solver, self.structure = chain, solver, structure


def _arm(chain, name="chain"):
    try:
        return _ARMS[chain]
    except (KeyError, TypeError):
        pass
    refusals = []
    for structure, solver in STRUCTURES.items():
        try:
            arm = solver.from_chain(chain, name)
        except ValueError as error:
            refusals.append(f"{structure}: {error}")
            continue
        _ARMS[chain] = arm
        return arm
    if chain.n == 6 and all(j is Joint.REVOLUTE for j in chain.joints):
        try:
            arm = DecomposedArm.from_chain(chain, name)
        except ValueError as error:
            refusals.append(f"decomposable 6R: {error}")
        else:
            _ARMS[chain] = arm
            return arm
        arm = _GeneralArm(chain, general_6r_ik, classify(chain, name).name)
        _ARMS[chain] = arm
        return arm
    raise ValueError(
        f"{name} has none of the structures solved in closed form; "
        + "; ".join(refusals)
        + "; use screwkit.ik.numeric_ik"
    )


def _name(arm):
    try:
        return _NAMES[type(arm)]
    except KeyError:
        pass
    if isinstance(arm, (DecomposedArm, _GeneralArm)):
        return arm.structure
    name = next(name for name, solver in STRUCTURES.items() if isinstance(arm, solver))
    _NAMES[type(arm)] = name
    return name


#: The structure of each named engine's class, found once.
_NAMES = {}


def structure(chain):
    """The structure of a chain that :func:`analytic_ik` recognises.

    Parameters
    ----------
    chain : Chain

    Returns
    -------
    str
        A key of :data:`STRUCTURES`, or the class of a 6R arm from its axes
        (:func:`screwkit.ik.decomposed.classify`: 'spherical wrist (4, 5, 6 meet)',
        'three parallel (2, 3, 4)', ..., 'general ...'); a chain of none of them
        (neither 6R nor one of the structures) is a
        ``ValueError`` that names what each one needs.

    Examples
    --------
    >>> import screwkit as sk
    >>> structure(sk.robots.puma560())
    'spherical wrist (joints 2, 3 parallel)'
    >>> structure(sk.robots.stanford())
    'RRP arm with a spherical wrist (Stanford)'
    """
    check_chain(chain)
    try:
        name = _name(_arm(chain))
    except ValueError:
        if chain.n == 6 and all(j is Joint.REVOLUTE for j in chain.joints):
            return classify(chain).name
        raise
    if chain.n == 6 and all(j is Joint.REVOLUTE for j in chain.joints):
        rank = _mobility(chain)
        if rank < 6:
            name += f"; {rank} degrees of freedom (a continuum at every pose)"
    return name


def analytic_ik_all(chain, T):
    """All closed-form solutions of one pose or a batch, as a fixed-size array.

    Parameters
    ----------
    chain : Chain
        An arm of one of the :data:`STRUCTURES` (spherical wrist, UR-type, Stanford) or
        a decomposable 6R (:mod:`screwkit.ik.decomposed`).
    T : array-like, shape (4, 4) or (N, 4, 4)
        Poses of the tool in the world frame (m).

    Returns
    -------
    Q : ndarray, shape (8, 6) or (N, 8, 6)
        Joint vectors, rad in (-pi, pi] (m for a prismatic joint), in the order of
        CONFIGURATIONS (a decomposable arm: 's0' ... 's7', in increasing q1, then q2,
        ..., the solutions first); NaN rows for the branches that do not reach a pose
        (all eight when it is out of reach; see :func:`analytic_ik` for the reason).
        Computed in chunks, so memory stays bounded for large batches.

    Examples
    --------
    The PUMA's eight solutions of a pose: two values of q1 (the left and the right
    arm), four solutions each (elbow up or down, wrist flipped or not); the pose's
    own q1 = 0.1 is one of the two.

    >>> import screwkit as sk
    >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
    >>> Q = analytic_ik_all(puma, puma.fk(q))
    >>> Q.shape, bool(np.isclose(Q[:, 0], 0.1).sum() == 4)
    ((8, 6), True)
    """
    arm = _arm(chain)
    _check_batch_size(T, "T", MAX_POSES_ALL, "analytic_ik_all")
    T = check_poses(T, "T")
    batch = T[None] if T.ndim == 2 else T
    if isinstance(arm, _GeneralArm):
        raise ValueError(
            "chain must be an arm whose solutions are a fixed array of eight, got a "
            f"general 6R ({arm.structure}, up to 16 solutions): use analytic_ik"
        )
    if isinstance(arm, DecomposedArm) and _mobility(chain) < 6:
        raise ValueError(
            "chain must have 6 degrees of freedom for a fixed array of eight "
            f"solutions, got {_mobility(chain)} (its Jacobian's rank at every "
            "configuration: the solutions of a pose it reaches form a continuum); "
            "use analytic_ik"
        )
    Q = (
        arm.solve(batch)[0]
        if isinstance(arm, DecomposedArm)
        else arm._solve_batch(batch)[0]
    )
    return Q[0] if T.ndim == 2 else Q


def analytic_ik(chain, T, within_limits=False, near=None, fixed=None):
    """Every closed-form solution of a pose, labelled, for a 6R arm (or a 7R arm with
    one joint fixed).

    Parameters
    ----------
    chain : Chain
        A 6R arm: one of the :data:`STRUCTURES` (labels 'lun' ... 'rdf'), a decomposable
        6R (a spherical wrist or shoulder, three parallel axes 2, 3, 4 or 3, 4, 5:
        :mod:`screwkit.ik.decomposed`, labels 's0' ...), or any other 6R (solved by
        :mod:`screwkit.ik.general`, up to 16 solutions); a 7R arm with ``fixed``.
    T : array-like, shape (4, 4) or (N, 4, 4)
        The tool pose (m); a batch gives a list of answers.
    within_limits : bool, default False
        False: angles in (-pi, pi]. True: each angle moved by whole turns into its
        joint limits, the solutions that cannot be dropped; if none is left, the
        answer is empty and its ``reason`` says so.
    near : array-like, shape (n,), optional
        A joint vector (rad): the solutions are sorted by their distance to it.
    fixed : dict {int: float}, optional
        For a 7R arm: {joint index (0-based): value (rad)}, the joint held at that
        value while the six others are solved; the solutions hold all seven joints.

    Returns
    -------
    IKSolutions
        Every solution as an :class:`IKSolution` (with its residual and within-limits
        flag), sorted by distance to ``near`` if given; empty with a ``reason`` when
        out of reach; ``reason`` also says when the solutions form a continuum (an
        angle free: each listed solution is then one of a family). ``structure`` names
        the class. For a batch, a list of IKSolutions.

    Examples
    --------
    Every one of the PUMA's eight solutions of a pose reaches it:

    >>> import screwkit as sk
    >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
    >>> T = puma.fk(q)
    >>> solutions = analytic_ik(puma, T)
    >>> len(solutions), all(np.allclose(puma.fk(s.q), T) for s in solutions)
    (8, True)
    """
    check_chain(chain)
    if fixed is None and chain.n == 6 and one_pose(T) is not None:
        arm = _arm(chain)
        if type(arm) in _ONE_POSE:  # one pose of a named structure: the scalar path
            within_limits = check_flag(within_limits, "within_limits")
            near = _check_near(near)
            found = _ONE_POSE[type(arm)](arm, T)
            return _one_answer(arm, chain, T, found, within_limits, near)
        if type(arm) is _GeneralArm:  # one pose of a general 6R: already checked
            within_limits = check_flag(within_limits, "within_limits")
            near = _check_near(near)
            found = arm.solver(chain, T)
            return _general_answer(arm, chain, found, within_limits, near)
    _check_batch_size(T, "T", MAX_POSES, "analytic_ik (a list of answers)")
    if fixed is not None or chain.n == 7:
        return _fixed_ik(chain, T, within_limits, near, fixed)
    return _analytic_ik(_arm(chain), chain, check_poses(T, "T"), within_limits, near)


def _fixed_ik(chain, T, within_limits, near, fixed):
    """analytic_ik of a 7R chain with one joint fixed: the 6R that remains."""
    if fixed is None:
        try:
            _arm(chain)
        except ValueError as refusal:
            why = str(refusal)
        raise ValueError(
            "fixed must name one joint of a 7-joint chain to hold, e.g. "
            f"fixed={{2: 0.0}}, got None for {chain.name!r}; {why}"
        )
    if chain.n != 7:
        raise ValueError(f"fixed is for a chain of 7 joints, got {chain.n} joints")
    if not isinstance(fixed, dict) or len(fixed) != 1:
        raise TypeError(
            f"fixed must be a dict of one entry {{joint index: value}}, got "
            f"{describe(fixed)}"
        )
    ((j, value),) = fixed.items()
    j = check_integer(j, "fixed", minimum=0)
    if j > 6:
        raise ValueError(f"fixed must name a joint index 0 ... 6, got {j}")
    value = as_float_array(value, "fixed")
    if value.ndim != 0:
        raise ValueError(
            f"fixed must map the joint index to one angle (rad), got an array of "
            f"shape {value.shape} for joint {j}"
        )
    value = float(value)
    if chain.joints[j] is not Joint.REVOLUTE:
        raise ValueError(f"fixed must name a revolute joint, joint {j} is not")
    S, M = chain.screw_axes(), chain.home()
    w = S[:, :3]
    r = np.cross(w, S[:, 3:])
    E = _motions(w[j], r[j], np.array(value))
    w_after = w[j + 1 :] @ E[:3, :3].T
    r_after = r[j + 1 :] @ E[:3, :3].T + E[:3, 3]
    axes = np.vstack([w[:j], w_after])
    points = np.vstack([r[:j], r_after])
    screws = np.hstack([axes, np.cross(points, axes)])
    keep = [i for i in range(7) if i != j]
    reduced = chain.from_screws(
        screws, E @ M, qlim=chain.qlim[keep], name=f"{chain.name} (joint {j} fixed)"
    )
    near6 = None
    if near is not None:
        near = as_float_array(near, "near")
        if near.shape != (7,):
            raise ValueError(
                f"near must be a joint vector of 7 entries, got shape {near.shape}"
            )
        near6 = near[keep]
    answers = analytic_ik(reduced, T, within_limits, near6)
    single = isinstance(answers, IKSolutions)
    out = []
    for answer in [answers] if single else answers:
        widened = IKSolutions(
            [
                IKSolution(
                    np.insert(s.q, j, value),
                    s.config,
                    s.singular,
                    s.within_limits,
                    s.residual,
                )
                for s in answer
            ],
            reason=answer.reason,
            structure=f"{answer.structure}, joint {j + 1} of 7 fixed",
        )
        out.append(widened)
    return out[0] if single else out


def _analytic_ik(arm, chain, T, within_limits, near):
    """analytic_ik for poses T already checked."""
    within_limits, near = check_flag(within_limits, "within_limits"), _check_near(near)
    batch = T if T.ndim == 3 else T[None]
    if isinstance(arm, DecomposedArm):
        answers = _decomposed_answers(arm, chain, batch, within_limits, near)
    elif isinstance(arm, _GeneralArm):
        answers = [
            _general_answer(arm, chain, found, within_limits, near)
            for found in arm.solver(chain, batch)
        ]
    else:
        Q, flags, code = arm._solve_batch(batch)
        limits = chain.qlim
        answers = [
            _answer(
                arm,
                batch[k],
                Q[k],
                flags[k],
                code[k],
                limits,
                within_limits,
                near,
                chain,
            )
            for k in range(batch.shape[0])
        ]
    return answers if T.ndim == 3 else answers[0]


def _check_near(near):
    """``near`` as a float array (6,), or None."""
    if near is not None:
        near = as_float_array(near, "near")
        if near.shape != (6,):
            raise ValueError(
                f"near must be a joint vector of 6 entries, got shape {near.shape}"
            )
    return near


def _listed(solutions, limits, within_limits, near, structure, reason=None):
    """IKSolutions of (q, label, residual, singular) rows: limits, order and reason."""
    if not solutions:
        return IKSolutions([], reason=reason, structure=structure)
    Q = np.array([s[0] for s in solutions])
    moved, inside = _into_limits(Q, limits)
    listed = [
        IKSolution(
            q=m if within_limits and ok else q,
            config=label,
            singular=singular,
            within_limits=bool(ok),
            residual=float(res),
        )
        for (q, label, res, singular), m, ok in zip(solutions, moved, inside)
    ]
    kept = [s for s in listed if s.within_limits] if within_limits else listed
    result = _nearest_first(IKSolutions(kept, reason=reason, structure=structure), near)
    if not kept:
        result.reason = _outside_limits(listed)
    return result


def _nearest_first(result, near):
    """The solutions sorted by wrapped distance to ``near`` (None: as they are)."""
    if near is not None:
        result.sort(key=lambda s: np.linalg.norm(_wrap_angle(s.q - near)))
    return result


def _outside_limits(listed):
    """Why no solution is left: each one, with the joint limit it violates."""
    return "every solution violates a joint limit, even moved by whole turns: " + (
        ", ".join(
            f"{s.config} q = {np.round(np.degrees(s.q), 1).tolist()} deg"
            for s in listed
        )
    )


_CONTINUUM = (
    "a continuum: an angle is free at this pose (two axes aligned, or a point on "
    "the axis it turns about); each listed solution is one of a family"
)


def _decomposed_answers(arm, chain, batch, within_limits, near):
    Q, residual, free = arm.solve(batch)
    answers = []
    for k in range(batch.shape[0]):
        rows = ~np.isnan(Q[k, :, 0])
        solutions = [
            (q, f"s{i}", res, ("continuum",) if f else ())
            for i, (q, res, f) in enumerate(
                zip(Q[k, rows], residual[k, rows], free[k, rows])
            )
        ]
        reason = _CONTINUUM if free[k].any() else None
        if not solutions:
            reason = "out of reach: no real solution of the subproblems"
        answers.append(
            _listed(solutions, chain.qlim, within_limits, near, arm.structure, reason)
        )
    rank = _mobility(chain)
    if rank < 6:  # a continuum wherever it reaches: the subproblems may miss it
        for k, answer in enumerate(answers):
            if not answer and answer.reason.startswith("out of reach"):
                found = general_6r_ik(chain, batch[k])
                general = _GeneralArm(chain, general_6r_ik, arm.structure)
                answers[k] = _general_answer(general, chain, found, within_limits, near)
            elif answer and not any(s.singular for s in answer):
                answer.reason = _mobility_reason(rank, answer.reason, True)
    return answers


def _general_answer(arm, chain, found, within_limits, near):
    """The IKSolutions of a general 6R arm from its solver's answer for one pose:
    :func:`_listed`'s limits, order and reason, the limits computed on floats
    (:func:`._one_pose.into_limits`)."""
    limits, slack, new = chain.qlim.tolist(), IK_JOINT_LIMIT_SLACK, object.__new__
    listed = []
    rows = zip(found.Q.tolist(), found.residuals.tolist(), found.singular.tolist())
    for i, (q, res, flag) in enumerate(rows):
        moved, ok = _one_pose.into_limits(q, limits, slack)
        solution = new(IKSolution)  # frozen: its fields set at once
        solution.__dict__.update(
            q=np.array(moved if within_limits else q, float),
            config=f"s{i}",
            singular=("singular",) if flag else (),
            within_limits=ok,
            residual=res,
        )
        listed.append(solution)
    kept = [s for s in listed if s.within_limits] if within_limits else listed
    reason = found.reason or (None if listed else "out of reach: no real solution")
    result = IKSolutions(kept, reason=reason, structure=arm.structure)
    _nearest_first(result, near)
    if listed and not kept:
        result.reason = _outside_limits(listed)
    return result


def _answer(arm, T, Q, flags, code, limits, within_limits, near, chain=None):
    if code != 0:
        return IKSolutions([], reason=arm._reason(T, code), structure=_name(arm))
    names = ("shoulder", "elbow", "wrist")
    moved, inside = _into_limits(Q, limits, getattr(arm, "revolute", None))
    reached = ~np.isnan(Q[:, 0])
    residual = np.full(len(Q), np.nan)
    if chain is not None and reached.any():
        residual[reached] = pose_residual(chain, Q[reached], T, arm.scale)
    solutions = []
    for q, q_moved, ok, config, flag, res in zip(
        Q, moved, inside, CONFIGURATIONS, flags, residual
    ):
        if np.isnan(q[0]):
            continue
        solutions.append(
            IKSolution(
                q=q_moved if within_limits and ok else q,
                config=config,
                within_limits=bool(ok),
                singular=tuple(n for n, f in zip(names, flag) if f),
                residual=float(res),
            )
        )
    if within_limits:
        solutions = [s for s in solutions if s.within_limits]
    result = _nearest_first(IKSolutions(solutions, structure=_name(arm)), near)
    result.reason = _singular_reason(result)
    if not result:
        result.reason = _outside_limits(
            _answer(arm, T, Q, flags, code, limits, False, None)
        )
    return result


def _one_answer(arm, chain, T, found, within_limits, near):
    """:func:`_answer` of one pose the scalar path solved, ``found`` = (rows, flags,
    code) as lists (:mod:`._one_pose`): the same solutions, labels, flags and reason,
    the limits and residuals computed on floats."""
    rows, flags, code = found
    name = _name(arm)
    if code != 0:
        return IKSolutions([], reason=arm._reason(T, code), structure=name)
    limits, target = chain.qlim.tolist(), T[:3].ravel().tolist()
    pose, scale = _compiled.scalar(chain, "pose"), arm.scale
    solutions, singular = [], False
    new, slack = object.__new__, IK_JOINT_LIMIT_SLACK
    for q, config, flag in zip(rows, CONFIGURATIONS, flags):
        if q[0] != q[0]:  # NaN: the branch does not reach
            continue
        moved, ok = _one_pose.into_limits(q, limits, slack)
        if within_limits and not ok:
            continue
        solution = new(IKSolution)  # frozen: its fields set at once, the residual
        solution.__dict__.update(  # computed when asked (_Residual)
            q=moved if within_limits else q,
            config=config,
            within_limits=ok,
            singular=_SINGULAR[flag],
            _residual_of=(pose, q, target, scale),
        )
        singular = singular or flag != _REGULAR
        solutions.append(solution)
    if solutions:
        Q = np.array([s.q for s in solutions], float)
        for solution, q in zip(solutions, Q):
            solution.__dict__["q"] = q
    result = IKSolutions(solutions, structure=name)
    if near is not None:
        _nearest_first(result, near)
    if singular:
        result.reason = _singular_reason(result)
    if not result:
        Q, flags = np.array(rows, float), np.array(flags)
        listed = _answer(arm, T, Q, flags, code, chain.qlim, False, None)
        result.reason = _outside_limits(listed)
    return result


_REGULAR = (False, False, False)

#: The singular field of each (shoulder, elbow, wrist) flags, as _answer builds it.
_SINGULAR = {
    (a, b, c): tuple(
        name for name, f in zip(("shoulder", "elbow", "wrist"), (a, b, c)) if f
    )
    for a in (False, True)
    for b in (False, True)
    for c in (False, True)
}


def _singular_reason(solutions):
    """The reason of a named structure's solutions at a singularity (None if none is):
    a wrist or shoulder singularity is a continuum, an elbow one a double solution."""
    kinds = {name for s in solutions for name in s.singular}
    if not kinds:
        return None
    count = sum(1 for s in solutions if s.singular)
    said = []
    if kinds & {"wrist", "shoulder"}:
        said.append(
            "at a wrist or shoulder singularity a joint angle is free (a continuum): "
            "each listed solution is one of a family"
        )
    if "elbow" in kinds:
        said.append("at an elbow singularity solutions coincide in pairs")
    return (
        f"{count} of the {len(solutions)} solutions are at a singular configuration "
        f"({', '.join(sorted(kinds))}; see each solution's singular): "
        + "; ".join(said)
    )


def _into_limits(Q, qlim, revolute=None):
    """Q (k, 6) with each angle moved by a multiple of 2 pi into its limits (the value
    nearest to its (-pi, pi] value), and whether each row could be moved there, (k,).
    ``revolute`` (6,) marks the angles (default all); other joints are not moved."""
    low, high = qlim[:, 0], qlim[:, 1]
    already = (Q >= low) & (Q <= high)
    angles = np.ones(Q.shape[-1], bool) if revolute is None else revolute
    turns = np.arange(-3, 4) * angles[:, None]
    candidates = Q[..., None] + 2 * np.pi * turns  # (k, 6, 7)
    slack = IK_JOINT_LIMIT_SLACK
    fits = (candidates >= low[:, None] - slack) & (candidates <= high[:, None] + slack)
    distance = np.where(fits, np.abs(candidates - Q[..., None]), np.inf)
    nearest = np.take_along_axis(candidates, distance.argmin(axis=-1)[..., None], -1)[
        ..., 0
    ]
    return np.where(already, Q, nearest), np.all(already | fits.any(axis=-1), axis=-1)


def configuration(chain, q):
    """The configuration label of a joint vector, from the geometric definitions of the
    chain's structure (:mod:`screwkit.ik.spherical_wrist`, :mod:`screwkit.ik.ur`,
    :mod:`screwkit.ik.stanford`), singular cases included.

    Parameters
    ----------
    chain : Chain
        An arm of one of the :data:`STRUCTURES`.
    q : array-like, shape (6,) or (N, 6)
        Joint vectors (rad; m for a prismatic joint).

    Returns
    -------
    str or list of str
        The label ('ruf', ...) of q, or the N labels of a batch.

    Examples
    --------
    A PUMA with its wrist centre in front of the shoulder (r), the elbow below
    (d) and q5 < 0 (n):

    >>> import screwkit as sk
    >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
    >>> configuration(puma, q)
    'rdn'
    """
    arm = _arm(chain)
    if isinstance(arm, (DecomposedArm, _GeneralArm)):
        raise ValueError(
            f"chain must be an arm of the STRUCTURES for a configuration label; "
            f"{arm.structure} has none (its solutions are numbered 's0' ...)"
        )
    q = chain.check_q(q)
    labels = arm._labels(q)
    return str(labels) if q.ndim == 1 else labels.tolist()


def puma560_ik(T, robot=None, within_limits=False, near=None):
    """Every closed-form solution for one pose of a PUMA 560: :func:`analytic_ik`.

    Parameters
    ----------
    T : array-like, shape (4, 4)
        The tool pose (m).
    robot : Chain, optional
        The PUMA the pose belongs to (any lengths d1, d3, a2, a3, d4, d6, offsets, base
        and tool); without one, ``robots.puma560()``: Corke's model with d1 = 0, the
        base frame on the shoulder. Poses of a PUMA with a pedestal (the Robotics
        Toolbox's d1 = 0.672 m) need that robot passed in.
    within_limits, near
        As for :func:`analytic_ik`.

    Returns
    -------
    IKSolutions
        Up to eight solutions, as :func:`analytic_ik` returns them.

    Examples
    --------
    At q = 0 the PUMA 560's tool is where its DH numbers put it:
    (a2 + a3, -d3, d4) = (0.4318 + 0.0203, -0.15005, 0.4318); one of the eight
    solutions of a regular pose is the vector that made it.

    >>> import screwkit as sk
    >>> puma = sk.robots.puma560()
    >>> np.round(puma.fk(np.zeros(6))[:3, 3], 5) + 0.0
    array([ 0.4521 , -0.15005,  0.4318 ])
    >>> q = [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
    >>> puma560_ik(puma.fk(q)).nearest(q)
    IKSolution(rdn: q=[+0.1000, -0.4000, +0.3000, +0.5000, -0.6000, +0.7000],
               within_limits=True)
    """
    robot = _default_puma() if robot is None else robot
    arm = _arm(robot, "robot")
    if type(arm) in _ONE_POSE and one_pose(T) is not None:  # the scalar path
        return analytic_ik(robot, T, within_limits, near)
    return _analytic_ik(
        arm, robot, check_poses(T, "T", single_only=True), within_limits, near
    )


def puma560_ik_all(Ts, robot=None):
    """All eight solutions of a batch of PUMA poses: :func:`analytic_ik_all` with
    ``robots.puma560()`` by default.

    Parameters
    ----------
    Ts : array-like, shape (N, 4, 4) (or (4, 4))
        Tool poses (m).
    robot : Chain, optional
        The PUMA the poses belong to (default ``robots.puma560()``).

    Returns
    -------
    ndarray, shape (N, 8, 6) (or (8, 6))
        Joint vectors, rad in (-pi, pi], in the order of :data:`CONFIGURATIONS`; NaN
        where a branch does not reach.

    Examples
    --------
    Two poses, eight solutions each:

    >>> import screwkit as sk
    >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
    >>> puma560_ik_all([puma.fk(q), puma.fk(np.zeros(6) + 0.2)]).shape
    (2, 8, 6)
    """
    return analytic_ik_all(_default_puma() if robot is None else robot, Ts)


def puma560_config(q, robot=None):
    """The configuration label of a PUMA joint vector: Corke's l/r, u/d, n/f.

    Arm 'r' when the wrist centre is in front of the shoulder along x1
    (a2 c2 + a3 c23 - d4 s23 > 0); elbow 'u' when the elbow is above the line from the
    shoulder to the wrist centre, seen with the arm pointing forward; wrist 'f' when
    q5 > 0. Singular cases follow the rule of :mod:`screwkit.ik.spherical_wrist`
    (shoulder: 'r', elbow: 'd', wrist: 'f' when cos q4 >= 0), so that every label
    round-trips.

    Parameters
    ----------
    q : array-like, shape (6,)
        A joint vector (rad).
    robot : Chain, optional
        The PUMA (default ``robots.puma560()``).

    Returns
    -------
    str
        The label, 'lun' ... 'rdf'.

    Examples
    --------
    At q1 = 0.1, q2 = -0.4, q3 = 0.3 the PUMA's wrist centre is in front of the
    shoulder (r), its elbow below the line to it (d), and q5 = -0.6 < 0 (n):

    >>> puma560_config([0.1, -0.4, 0.3, 0.5, -0.6, 0.7])
    'rdn'
    """
    robot = _default_puma() if robot is None else check_chain(robot, "robot")
    return configuration(robot, robot.check_one(q))
