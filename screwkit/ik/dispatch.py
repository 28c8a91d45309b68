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
(Corke's labels for the PUMA). Any other arm (7 joints, no spherical wrist and no three
parallel axes, ...) is refused with a ``ValueError`` that says what each structure
needs: use :func:`screwkit.ik.numeric_ik`. :func:`puma560_ik` is the same solver under
the PUMA's name.

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

from .._checks import as_float_array, check_chain, check_flag, check_poses
from ..robots import puma560
from ..tolerances import IK_JOINT_LIMIT_SLACK
from ..tolerances import IK_SINGULAR_TOL as SINGULAR_TOL
from ..transforms import _wrap_angle
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
        Stanford arm's boom counts as its elbow); empty for a regular solution.
    within_limits : bool
        Whether q, or q moved by whole turns, respects the joint limits.
    """

    q: np.ndarray
    config: str
    singular: tuple = ()
    within_limits: bool = True

    def __repr__(self):
        q = ", ".join(f"{v:+.4f}" for v in self.q)
        extra = f", singular={self.singular}" if self.singular else ""
        return (
            f"IKSolution({self.config}: q=[{q}], "
            f"within_limits={self.within_limits}{extra})"
        )


class IKSolutions(list):
    """The solutions for one pose: a list of :class:`IKSolution`.

    Parameters
    ----------
    solutions : iterable of IKSolution
    reason : str or None
        Why the list is empty (out of reach, or outside the joint limits); None when it
        is not.
    structure : str or None
        The structure the closed form recognised (a key of :data:`STRUCTURES`).
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
        """
        if config not in CONFIGURATIONS:
            raise ValueError(
                f"config must be one of {', '.join(CONFIGURATIONS)}, got {config!r}"
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
        """
        q = as_float_array(q, "q")
        if q.shape != (6,):
            raise ValueError(f"q must have 6 entries, got shape {q.shape}")
        if not self:
            return None
        return min(self, key=lambda s: np.linalg.norm(_wrap_angle(s.q - q)))


@lru_cache(maxsize=1)
def _default_puma():
    return puma560()


_ARMS = (
    weakref.WeakKeyDictionary()
)  # chains are immutable: their geometry is found once

#: The structures solved in closed form, in the order they are tried: {name: solver}.
STRUCTURES = {
    "spherical wrist (joints 2, 3 parallel)": SphericalWristArm,
    URArm.structure: URArm,
    StanfordArm.structure: StanfordArm,
}


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
    raise ValueError(
        f"{name} has none of the structures solved in closed form; "
        + "; ".join(refusals)
    )


def _name(arm):
    return next(name for name, solver in STRUCTURES.items() if isinstance(arm, solver))


def structure(chain):
    """The structure of a chain that :func:`analytic_ik` recognises.

    Parameters
    ----------
    chain : Chain

    Returns
    -------
    str
        A key of :data:`STRUCTURES`; a chain of none of them is a ``ValueError`` that
        names what each one needs.
    """
    return _name(_arm(chain))


def analytic_ik_all(chain, T):
    """All eight closed-form solutions of one pose or a batch, in the order of
    CONFIGURATIONS.

    Parameters
    ----------
    chain : Chain
        An arm of one of the :data:`STRUCTURES` (spherical wrist, UR-type, Stanford).
    T : array-like, shape (4, 4) or (N, 4, 4)
        Poses of the tool in the world frame (m).

    Returns
    -------
    Q : ndarray, shape (8, 6) or (N, 8, 6)
        Joint vectors, rad in (-pi, pi] (m for a prismatic joint); NaN rows for the
        branches that do not reach a pose (all eight when it is out of reach; see
        :func:`analytic_ik` for the reason). Computed in chunks, so memory stays
        bounded for large batches.
    """
    arm = _arm(chain)
    T = check_poses(T, "T")
    Q, _, _ = arm._solve_batch(T[None] if T.ndim == 2 else T)
    return Q[0] if T.ndim == 2 else Q


def analytic_ik(chain, T, within_limits=False, near=None):
    """Every closed-form solution of a pose, labelled, for an arm of :data:`STRUCTURES`.

    Parameters
    ----------
    chain : Chain
        A 6R arm with a spherical wrist and joints 2, 3 parallel, a UR-type arm (joints
        2, 3, 4 parallel) or an RRP arm with a spherical wrist (Stanford); any other
        arm is a ``ValueError`` saying what each structure needs.
    T : array-like, shape (4, 4) or (N, 4, 4)
        The tool pose (m); a batch gives a list of answers.
    within_limits : bool, default False
        False: angles in (-pi, pi]. True: each angle moved by whole turns into its
        joint limits, the solutions that cannot be dropped; if none is left, the
        answer is empty and its ``reason`` says so.
    near : array-like, shape (6,), optional
        A joint vector (rad): the solutions are sorted by their distance to it.

    Returns
    -------
    IKSolutions
        Up to eight :class:`IKSolution` in the order of :data:`CONFIGURATIONS` (sorted
        by distance to ``near`` if given); empty with a ``reason`` when out of reach;
        ``structure`` names the structure recognised. For a batch, a list of
        IKSolutions.
    """
    return _analytic_ik(_arm(chain), chain, check_poses(T, "T"), within_limits, near)


def _analytic_ik(arm, chain, T, within_limits, near):
    """analytic_ik for poses T already checked."""
    within_limits = check_flag(within_limits, "within_limits")
    if near is not None:
        near = as_float_array(near, "near")
        if near.shape != (6,):
            raise ValueError(
                f"near must be a joint vector of 6 entries, got shape {near.shape}"
            )
    batch = T if T.ndim == 3 else T[None]
    Q, flags, code = arm._solve_batch(batch)
    limits = chain.qlim
    answers = [
        _answer(arm, batch[k], Q[k], flags[k], code[k], limits, within_limits, near)
        for k in range(batch.shape[0])
    ]
    return answers if T.ndim == 3 else answers[0]


def _answer(arm, T, Q, flags, code, limits, within_limits, near):
    if code != 0:
        return IKSolutions([], reason=arm._reason(T, code), structure=_name(arm))
    names = ("shoulder", "elbow", "wrist")
    moved, inside = _into_limits(Q, limits, getattr(arm, "revolute", None))
    solutions = []
    for q, q_moved, ok, config, flag in zip(Q, moved, inside, CONFIGURATIONS, flags):
        if np.isnan(q[0]):
            continue
        solutions.append(
            IKSolution(
                q=q_moved if within_limits and ok else q,
                config=config,
                within_limits=bool(ok),
                singular=tuple(n for n, f in zip(names, flag) if f),
            )
        )
    if within_limits:
        solutions = [s for s in solutions if s.within_limits]
    result = IKSolutions(solutions, structure=_name(arm))
    if near is not None:
        result.sort(key=lambda s: np.linalg.norm(_wrap_angle(s.q - near)))
    if not result:
        result.reason = (
            "every solution violates a joint limit, even moved by whole turns: "
            + ", ".join(
                f"{s.config} q = {np.round(np.degrees(s.q), 1).tolist()} deg"
                for s in _answer(arm, T, Q, flags, code, limits, False, None)
            )
        )
    return result


def _into_limits(Q, qlim, revolute=None):
    """Q (k, 6) with each angle moved by a multiple of 2 pi into its limits (the value
    nearest to its (-pi, pi] value), and whether each row could be moved there, (k,).
    ``revolute`` (6,) marks the angles (default all); other joints are not moved."""
    low, high = qlim[:, 0], qlim[:, 1]
    already = (Q >= low) & (Q <= high)
    angles = np.ones(6, bool) if revolute is None else revolute
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
    """
    arm = _arm(chain)
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
    """
    robot = _default_puma() if robot is None else robot
    arm = _arm(robot, "robot")
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
    """
    robot = _default_puma() if robot is None else check_chain(robot, "robot")
    return configuration(robot, robot.check_one(q))
