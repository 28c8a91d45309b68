"""Serial chains: from a Denavit–Hartenberg (DH) table or from joint screws
(product of exponentials).

A :class:`Chain` is a fixed, immutable model. Underneath, every chain is its joint
twists and a home pose: T(q) = base exp([S_1] q_1) ... exp([S_n] q_n) M tool
(Lynch and Park's product of exponentials); a DH table is one way to write those screws
down, :meth:`Chain.from_screws` another. Both kinds have the same methods:

* exact (SymPy): ``fk_symbolic`` in the joint symbols q1..qn, ``joint_twists`` at exact
  values;
* fast (NumPy): ``fk``, ``frames``, the Jacobians, one configuration ``(n,)`` or a batch
  ``(N, n)``, computed by straight-line code generated from the chain's numbers when it
  is first used (see :mod:`screwkit._compiled`; no SymPy, about a millisecond).

The chain describes the arm (its constructors and description); the computations on
it are functions of the chain in their modules, and its methods are those functions:
the description and joint values checked in :mod:`screwkit.links`, the exact
kinematics in :mod:`screwkit._exact_kinematics`, the fast in
:mod:`screwkit._fast_kinematics`, the Jacobians in :mod:`screwkit.jacobians`, the
second order in :mod:`screwkit.motion.acceleration` (``chain.fk(q)`` is
``_fast_kinematics.fk(chain, q)``, ``chain.space_jacobian(q)`` is
``sk.jacobians.space_jacobian(chain, q)``).

Standard DH (the default):  A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i).
Modified DH (Craig):        A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i),
where the row of link i holds alpha_{i-1} and a_{i-1}.

>>> import numpy as np
>>> arm = Chain([Link.revolute(a=1.0), Link.revolute(a=0.5)])
>>> np.round(arm.fk([0.0, np.pi / 2])[:2, 3], 6)
array([1. , 0.5])
>>> arm.fk(np.zeros((10, 2))).shape
(10, 4, 4)
"""

import types
from functools import cached_property

import numpy as np
import sympy as sp

from . import _exact_kinematics, _fast_kinematics
from . import jacobians as _jacobians
from . import links as _links
from ._checks import ChainType, describe
from ._docstrings import fill
from ._notation import textbook
from .ik import newton as _newton
from .jacobians import ROWS
from .links import (
    Convention,
    Joint,
    Link,
    dh_description,
    links_from_table,
    rigid,
    screw_description,
)
from .motion import acceleration as _acceleration
from .urdf import read_urdf

__all__ = ["Joint", "Convention", "Link", "Chain", "textbook", "ROWS"]


def _with_sections(name, where):
    """The Parameters and Returns of ``Chain.with_<name>``."""
    return f"""Parameters
----------
{name} : array-like, shape (4, 4)
    The rigid transform {where} (m).

Returns
-------
Chain
    A new chain (chains are immutable)."""


class Chain(ChainType):
    """A serial chain between a fixed ``base`` and a ``tool`` transform; immutable.

    ``Chain(links, ...)`` describes it by a DH table; :meth:`from_table` takes the table
    as an array, and :meth:`from_screws` builds a chain from joint screws and a home
    pose.

    Parameters
    ----------
    links : sequence of Link, one per joint (n >= 1)
    convention : Convention.STANDARD (default) or Convention.MODIFIED
    base, tool : 4x4 rigid transforms (default identity): T = base @ A_1 ... A_n @ tool
    name : str, used in messages and titles
    configurations : optional {name: joint vector (n,)}, named configurations
        ('zero', ...)

    Examples
    --------
    A planar 2R arm with unit links, bent at the elbow: its tip is at (1, 1).

    >>> arm = Chain([Link.revolute(a=1.0), Link.revolute(a=1.0)], name="2R")
    >>> arm
    Chain('2R', 2 joints RR, standard DH)
    >>> np.round(arm.fk([0.0, np.pi / 2])[:2, 3], 6)
    array([1., 1.])
    """

    #: The URDF joint names in order for a chain from :meth:`from_urdf`, None otherwise.
    joint_names = None

    def __init__(
        self,
        links,
        convention=Convention.STANDARD,
        base=None,
        tool=None,
        name="chain",
        configurations=None,
    ):
        self._setup(dh_description(links, convention), base, tool, name, configurations)

    def _setup(self, description, base, tool, name, configurations):
        """Keep a checked description (:func:`~screwkit.links.dh_description` or
        :func:`~screwkit.links.screw_description`) and the options, checked."""
        if not isinstance(name, str):
            raise TypeError(f"name must be a string, got {describe(name)}")
        state = self.__dict__
        state.update(links=None, convention=None, frame=None)
        state.update(_screws=None, _exact_screws=None, _home=None)
        state.update(description)
        state.update(base=rigid(base, "base"), tool=rigid(tool, "tool"), name=name)
        state["q_symbols"] = sp.symbols(f"q1:{self.n + 1}", real=True)
        named = {}
        for key, value in (configurations or {}).items():
            named[key] = self.check_one(value, f"configurations[{key!r}]").copy()
            named[key].setflags(write=False)
        state["configurations"] = types.MappingProxyType(named)

    def __setattr__(self, name, value):
        raise AttributeError(
            f"a Chain is immutable: cannot set {name!r}; make a new chain "
            "(e.g. chain.with_tool(T), chain.with_base(T))"
        )

    # ---- constructors ----------------------------------------------------------------

    @classmethod
    def from_table(
        cls, table, joints=None, convention=Convention.STANDARD, qlim=None, **options
    ):
        """A chain from a DH table.

        For a revolute joint, theta is the joint offset (theta = q + offset); for a
        prismatic one, d is (d = q + offset).

        Parameters
        ----------
        table : array-like, shape (n, 4)
            Columns (theta, d, a, alpha), in rad and m.
        joints : sequence of Joint, or str, optional
            A string such as 'RRP'; all revolute by default.
        convention : Convention, optional
            ``Convention.STANDARD`` (default) or ``Convention.MODIFIED``.
        qlim : array-like, shape (n, 2), or None, optional
            Joint limits (rad or m; +-inf: no limit).
        **options
            ``base``, ``tool``, ``name``, ``configurations``, as for :class:`Chain`.

        Returns
        -------
        Chain
            A DH chain (``chain.is_dh``), one link per row of the table.

        Examples
        --------
        The planar 2R arm with unit links, rows (theta, d, a, alpha):

        >>> arm = Chain.from_table([[0, 0, 1.0, 0], [0, 0, 1.0, 0]], name="2R")
        >>> np.round(arm.fk([0.0, np.pi / 2])[:2, 3], 6)
        array([1., 1.])
        """
        return cls(links_from_table(table, joints, qlim), convention, **options)

    @classmethod
    def from_screws(
        cls,
        axes,
        home,
        frame="space",
        qlim=None,
        base=None,
        tool=None,
        name="chain",
        configurations=None,
    ):
        """A chain from its joint screws and home pose: the product of exponentials.

        frame="space": T(q) = base exp([S_1] q_1) ... exp([S_n] q_n) M tool, the S_i
        written in the base frame at q = 0; frame="body": T(q) = base M
        exp([B_1] q_1) ... exp([B_n] q_n) tool, the B_i written in the end-effector
        frame at q = 0.

        Parameters
        ----------
        axes : list of n Twist objects or 6-vectors [omega; v], or an (n, 6) array
            Unit screw axes, ``|omega| = 1`` for a revolute (pitch 0) or helical
            (pitch omega . v) joint, omega = 0 and ``|v| = 1`` for a prismatic one.
        home : array-like, shape (4, 4)
            The rigid transform M, the end-effector pose at q = 0 (m).
        frame : {'space', 'body'}, optional
            Where the axes are written.
        qlim : array-like, shape (n, 2), or None, optional
            Joint limits (rad, or m for prismatic joints; +-inf: none).
        base, tool : array-like, shape (4, 4), optional
            Rigid transforms (default identity).
        name : str, optional
            Used in messages and titles.
        configurations : dict, optional
            {name: joint vector (n,)}, named configurations.

        Returns
        -------
        Chain
            A chain of joint screws (``chain.is_dh`` is False).

        Examples
        --------
        The planar 2R arm with unit links: z through the origin, z through
        (1, 0, 0) (v = (1, 0, 0) x z = (0, -1, 0)), its tip at (2, 0, 0) at home.

        >>> M = np.eye(4)
        >>> M[0, 3] = 2.0
        >>> arm = Chain.from_screws([[0, 0, 1, 0, 0, 0], [0, 0, 1, 0, -1, 0]], M)
        >>> arm
        Chain('chain', 2 joints RR, product of exponentials, space form)
        >>> np.round(arm.fk([0.0, np.pi / 2])[:2, 3], 6)
        array([1., 1.])
        """
        chain = cls.__new__(cls)
        description = screw_description(axes, home, frame, qlim)
        chain._setup(description, base, tool, name, configurations)
        return chain

    @classmethod
    def from_urdf(cls, source, base_link=None, tip_link=None):
        """A chain from a URDF file or text.

        The joints from ``base_link`` to ``tip_link`` become joint screws in the base
        link's frame, exact where the file's numbers are (:mod:`screwkit.urdf`).
        Revolute, continuous and prismatic joints; fixed joints folded into their
        neighbours; limits into ``qlim``; ``chain.joint_names`` lists the URDF joint
        names.

        Parameters
        ----------
        source : str or os.PathLike
            URDF text (starting with '<') or a URDF file's path.
        base_link : str or None, optional
            The link whose frame is the base frame (default: the root).
        tip_link : str or None, optional
            The end-effector link (required when the tree branches).

        Returns
        -------
        Chain
            A chain from screws, named after the robot.

        Examples
        --------
        One revolute joint about z, 0.5 m above the base link:

        >>> urdf = '''<robot name="one"><link name="base"/><link name="arm"/>
        ... <joint name="shoulder" type="revolute">
        ...   <parent link="base"/><child link="arm"/>
        ...   <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/>
        ...   <limit lower="-1" upper="1" effort="1" velocity="1"/>
        ... </joint></robot>'''
        >>> arm = Chain.from_urdf(urdf)
        >>> arm.joint_names, arm.qlim
        (('shoulder',), array([[-1.,  1.]]))
        >>> np.round(arm.home()[:3, 3], 6)
        array([0. , 0. , 0.5])
        """
        urdf = read_urdf(source, base_link, tip_link)
        chain = cls.from_screws(
            list(urdf.axes),
            urdf.home,
            name=urdf.name,
            qlim=[q or (-np.inf, np.inf) for q in urdf.qlim],
        )
        chain.__dict__["joint_names"] = urdf.joint_names
        return chain

    def _copy(self, **changes):
        """A new chain like this one with some constructor arguments changed."""
        options = dict(
            base=self.base,
            tool=self.tool,
            name=self.name,
            configurations=dict(self.configurations),
        )
        options.update(changes)
        if self.links is not None:
            return Chain(self.links, self.convention, **options)
        chain = Chain.from_screws(
            self._exact_screws,
            self._home,
            self.frame,
            qlim=[tuple(limit) for limit in self._qlim],
            **options,
        )
        chain.__dict__["joint_names"] = self.joint_names
        return chain

    @fill(sections=_with_sections("tool", "of the tool in the last frame"))
    def with_tool(self, tool):
        """The same chain with another tool transform.

        {sections}

        Examples
        --------
        A 0.5 m tool on the planar 2R arm with unit links: stretched, its tip is
        at x = 2.5.

        >>> import screwkit as sk
        >>> arm = sk.robots.planar([1.0, 1.0]).with_tool(sk.transl(0.5, 0, 0))
        >>> np.round(arm.fk([0.0, 0.0])[:3, 3], 6)
        array([2.5, 0. , 0. ])
        """
        return self._copy(tool=tool)

    @fill(sections=_with_sections("base", "of the chain's base in the world frame"))
    def with_base(self, base):
        """The same chain on another base transform.

        {sections}

        Examples
        --------
        The planar 2R arm with unit links on a base 1 m up:

        >>> import screwkit as sk
        >>> arm = sk.robots.planar([1.0, 1.0]).with_base(sk.transl(0, 0, 1.0))
        >>> np.round(arm.fk([0.0, 0.0])[:3, 3], 6)
        array([2., 0., 1.])
        """
        return self._copy(base=base)

    # ---- description -----------------------------------------------------------------

    @property
    def n(self):
        """Number of joints."""
        return len(self.joints)

    @property
    def qlim(self):
        """Joint limits, shape (n, 2); -inf/inf where a joint has none."""
        return self._qlim.copy()

    @property
    def is_dh(self):
        """True for a chain described by a DH table, False for one built from screws."""
        return self.links is not None

    def __repr__(self):
        kinds = "".join(j.value for j in self.joints)
        form = (
            f"{self.convention.value} DH"
            if self.is_dh
            else f"product of exponentials, {self.frame} form"
        )
        return f"Chain({self.name!r}, {self.n} joints {kinds}, {form})"

    table = _exact_kinematics.table
    _repr_html_ = _exact_kinematics._repr_html_

    # ---- input checks (see screwkit.links) -------------------------------------------

    check_q = _links.check_q
    check_one = _links.check_one
    within_limits = _links.within_limits

    # ---- exact -----------------------------------------------------------------------

    _require_dh = _exact_kinematics._require_dh
    _exact_q = _exact_kinematics._exact_q
    link_transforms = _exact_kinematics.link_transforms
    length_symbols = _exact_kinematics.length_symbols
    _with_symbolic_lengths = _exact_kinematics._with_symbolic_lengths
    fk_symbolic = _exact_kinematics.fk_symbolic
    frames_symbolic = _exact_kinematics.frames_symbolic
    joint_frames = _exact_kinematics.joint_frames
    twists_symbolic = _exact_kinematics.twists_symbolic
    joint_twists = _exact_kinematics.joint_twists

    # ---- fast ------------------------------------------------------------------------

    _program = cached_property(_fast_kinematics._program)
    _functions = cached_property(_fast_kinematics._functions)
    source = _fast_kinematics.source
    _run = _fast_kinematics._run
    fk = _fast_kinematics.fk
    frames = _fast_kinematics.frames
    _twists_and_pose = _fast_kinematics._twists_and_pose
    joint_axes = _jacobians.joint_axes

    # ---- Jacobians: outputs of the generated program ---------------------------------

    _generated_jacobian = _jacobians._generated_jacobian
    space_jacobian = _jacobians.space_jacobian
    geometric_jacobian = _jacobians.geometric_jacobian
    body_jacobian = _jacobians.body_jacobian
    jacobian_rows = _jacobians.jacobian_rows
    singular_values = _jacobians.singular_values
    lost_rank = _jacobians.lost_rank
    manipulability = _jacobians.manipulability

    numeric_ik = _newton.numeric_ik

    # ---- product of exponentials -----------------------------------------------------

    home = _fast_kinematics.home
    screw_axes = _fast_kinematics.screw_axes
    body_screw_axes = _fast_kinematics.body_screw_axes
    fk_poe = _fast_kinematics.fk_poe

    # ---- second order: Jacobians in time (see screwkit.motion.acceleration) -------

    _rates = _acceleration._rates
    _generated_jacobian_dot = _acceleration._generated_jacobian_dot
    space_jacobian_dot = _acceleration.space_jacobian_dot
    body_jacobian_dot = _acceleration.body_jacobian_dot
    geometric_jacobian_dot = _acceleration.geometric_jacobian_dot
    space_hessian = _acceleration.space_hessian
    body_hessian = _acceleration.body_hessian
    geometric_hessian = _acceleration.geometric_hessian
