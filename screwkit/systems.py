"""Screw systems: spans of screws, their rank, canonical basis and reciprocal system.

Exact screws (integers, rationals, symbols, pi, algebraic numbers such as sqrt(3),
sin(pi/5) = sqrt(5/8 - sqrt(5)/8) or a CRootOf, and sin/cos/tan of angles) are computed
exactly by :mod:`._exact`: the rank is the generic rank in the symbols, over the field
the entries really generate (cos(2a) and 2 cos(a)^2 - 1 are one number at a = 1/3 or
pi/7 as for a symbol a); what cannot be decided exactly is refused with the reason.
Screws given with floats (and no symbols) are computed by SVD: the rank counts the
singular values above ``tol * max(1, the largest)``, ``tol = RANK_TOL`` (1e-9) by
default (:mod:`screwkit.tolerances`), so two axes that differ by round-off count as
one. Floats mixed with symbols are refused with a message saying how to write them
exactly.

>>> import sympy as sp
>>> x, y, origin = [1, 0, 0], [0, 1, 0], [0, 0, 0]
>>> prismatic_xy = ScrewSystem([(x, origin, sp.oo), (y, origin, sp.oo)])
>>> prismatic_xy.rank
2
>>> prismatic_xy.reciprocal().rank
4
"""

import sympy as sp

from . import _certificates, _exact, _numeric, _system_geometry
from ._checks import describe
from ._docstrings import fill
from ._system_geometry import Classification, PrincipalScrews
from .screws import Screw, Twist, Wrench

__all__ = ["Classification", "PrincipalScrews", "ScrewSystem"]

_OTHER = {Twist: Wrench, Wrench: Twist, Screw: Screw}

#: The Parameters section of union and intersection (filled in by _docstrings.fill).
_OTHER_PARAMETERS = """Parameters
----------
other : ScrewSystem
    A system of the same kind."""


def _swap(row):
    """Coordinates [a; b] -> [b; a]: x . swap(y) is the reciprocal product."""
    return list(row[3:]) + list(row[:3])


class ScrewSystem:
    """The span of a list of screws. ``kind`` is Twist (default), Wrench or Screw.

    Parameters
    ----------
    screws : list of Screw, of 6-vectors [angular; linear], or of (s, r, h) triples
        The screws spanning the system; triples as in the mobility paper's zeroth step
        (s, r in m, h in m/rad or sympy.oo).
    kind : {Twist, Wrench, Screw}, optional
        By default the kind of the screws given (Twist for vectors).
    tol : float, optional
        Relative tolerance of the rank when the screws hold floats (SVD; default
        ``RANK_TOL``, 1e-9, of :mod:`screwkit.tolerances`); exact screws ignore
        it.

    Examples
    --------
    Two parallel revolute axes (z through the origin and through (1, 0, 0)) span a
    2-system: their difference is a translation along y.

    >>> x, z, origin = [1, 0, 0], [0, 0, 1], [0, 0, 0]
    >>> ScrewSystem([(z, origin, 0), (z, x, 0)])
    ScrewSystem(2 twists, rank 2)
    """

    def __init__(self, screws, kind=None, tol=None):
        if isinstance(screws, ScrewSystem):
            screws = screws.screws
        if not isinstance(screws, (list, tuple)):
            raise TypeError(
                "screws must be a list of screws, 6-vectors or (s, r, h) triples, "
                f"got {type(screws).__name__}"
            )
        if kind is not None and kind not in _OTHER:
            raise TypeError(f"kind must be Twist, Wrench or Screw, got {kind!r}")
        kinds = {type(s) for s in screws if isinstance(s, Screw)}
        if len(kinds) > 1:
            raise TypeError(
                "a screw system holds one kind of screw, got "
                f"{sorted(k.noun for k in kinds)}"
            )
        self.kind = kind or (kinds.pop() if kinds else Twist)
        self.tol = _numeric.TOL if tol is None else _numeric.check_tol(tol)
        self.screws = [self._as_screw(s, i) for i, s in enumerate(screws)]
        self.numeric = _numeric.has_floats(
            [e for s in self.screws for e in _exact.entries(s.vector)]
        )
        if self.numeric:
            self._array = _numeric.to_array(
                [list(s.vector) for s in self.screws], "screws"
            )
        self._field = self._independent = self._basis = self._rank = None

    @classmethod
    def _of_basis(cls, basis, kind, tol, field=None):
        """The system spanned by ``basis``, screws already independent and reduced (the
        results of basis() and reciprocal(), whose rank and basis are known). Numeric
        when an entry is a float, as for any system (a basis of integers is exact)."""
        system = cls.__new__(cls)
        system.kind, system.tol, system.screws = kind, tol, list(basis)
        system.numeric = _numeric.has_floats(
            [e for s in basis for e in _exact.entries(s.vector)]
        )
        if system.numeric:
            system._array = _numeric.to_array([list(s.vector) for s in basis], "screws")
        system._field = field
        system._independent = list(range(len(basis)))
        system._rank = len(basis)
        system._basis = list(basis)
        return system

    @property
    def noun(self):
        """The kind of screw as a word ('twist', 'wrench' or 'screw')."""
        return self.kind.noun

    def _as_screw(self, item, index):
        if isinstance(item, Screw):
            return item if type(item) is self.kind else self.kind(item.vector)
        if isinstance(item, (list, tuple)) and len(item) == 3:
            try:
                return self.kind.from_axis(*item)
            except (TypeError, ValueError) as error:
                raise type(error)(f"screw {index}: {error}") from None
        try:
            return self.kind(item)
        except (TypeError, ValueError) as error:
            raise type(error)(f"screw {index}: {error}") from None

    @property
    def field(self):
        """The exact field of the screws' coordinates (exact systems only)."""
        if self._field is None:
            self._field = _exact.Field(
                [e for s in self.screws for e in _exact.entries(s.vector)]
            )
        return self._field

    @property
    def matrix(self):
        """The screws as the columns of a 6 x m SymPy matrix."""
        if not self.screws:
            return sp.zeros(6, 0)
        return sp.Matrix.hstack(*(s.vector for s in self.screws))

    def _domain_matrix(self, swap=False):
        order = _swap if swap else list
        return self.field.matrix([order(_exact.entries(s.vector)) for s in self.screws])

    def _independent_rows(self):
        """Indices of a largest generically independent set of the (exact) screws."""
        if self._independent is None:
            self._independent = (
                self.field.independent_rows(self._domain_matrix())
                if self.screws
                else []
            )
        return self._independent

    @property
    def rank(self):
        """The order of the system, the number of independent screws.

        For generic symbol values (exact), or by SVD with the tolerance ``tol``
        (floats).
        """
        if self._rank is None:
            if self.numeric:
                self._rank = _numeric.rank(self._array, self.tol) if self.screws else 0
            else:
                self._rank = len(self._independent_rows())
        return self._rank

    order = rank

    def basis(self):
        """A canonical basis, reduced so that each screw ends in 1 at its own pivot.

        Returns
        -------
        list of Screw
            ``rank`` screws of the system's kind.

        Examples
        --------
        The two parallel revolutes of the class example: a rotation about z through
        the origin and a translation along y.

        >>> x, z, origin = [1, 0, 0], [0, 0, 1], [0, 0, 0]
        >>> ScrewSystem([(z, origin, 0), (z, x, 0)]).basis()
        [Twist([0, 0, 1, 0, 0, 0]), Twist([0, 0, 0, 0, 1, 0])]
        """
        if self._basis is None:
            if not self.screws:
                self._basis = []
            elif self.numeric:
                rows = _numeric.as_sympy_rows(
                    _numeric.reduced_basis(self._array, self.tol)
                )
                self._basis = [self.kind._checked(sp.Matrix(6, 1, row)) for row in rows]
            else:
                R = _exact.reduced_basis(
                    self.field, self._domain_matrix(), self._independent_rows()
                )
                self._basis = [self._from_field(row) for row in R.to_list()]
        return list(self._basis)

    def reduced(self):
        """The same span with its canonical basis as its screws.

        Returns
        -------
        ScrewSystem
            The system with rank and basis known: what a system is printed as, and the
            cheaper one to take further.

        Examples
        --------
        Three screws of a 2-system reduce to two:

        >>> S = ScrewSystem([[0, 0, 1, 0, 0, 0], [0, 0, 1, 0, -1, 0], [0] * 4 + [1, 0]])
        >>> S.reduced().screws
        [Twist([0, 0, 1, 0, 0, 0]), Twist([0, 0, 0, 0, 1, 0])]
        """
        field = None if self.numeric else self.field
        return ScrewSystem._of_basis(self.basis(), self.kind, self.tol, field)

    def reciprocal(self):
        """The system of every screw reciprocal to all of these.

        Returns
        -------
        ScrewSystem
            Of order 6 - rank; wrenches for twists and twists for wrenches.

        Examples
        --------
        A ball joint (three rotations through the origin) transmits exactly the
        forces through its centre:

        >>> ball = ScrewSystem([(d, [0, 0, 0], 0) for d in sp.eye(3).columnspace()])
        >>> ball.reciprocal().basis()
        [Wrench([1, 0, 0, 0, 0, 0]), Wrench([0, 1, 0, 0, 0, 0]),
         Wrench([0, 0, 1, 0, 0, 0])]
        """
        other = _OTHER[self.kind]
        if not self.screws:
            return ScrewSystem([other(v) for v in sp.eye(6).columnspace()], kind=other)
        if self.numeric:
            kernel = _numeric.null_space(self._array[:, [3, 4, 5, 0, 1, 2]], self.tol)
            basis = [
                other._checked(sp.Matrix(6, 1, row))
                for row in _numeric.as_sympy_rows(kernel)
            ]
            return ScrewSystem._of_basis(basis, other, self.tol)
        # swapping the columns keeps the independent rows: x . swap(y) is reciprocity
        kernel = _exact.null_space(
            self.field, self._domain_matrix(swap=True), self._independent_rows()
        )
        basis = [
            other._checked(sp.Matrix(6, 1, [self.field.to_sympy(e) for e in row]))
            for row in kernel.to_list()
        ]
        return ScrewSystem._of_basis(basis, other, self.tol)

    def certificate(self, timeout=30.0):
        """A proof of the rank, checked exactly (exact screws only).

        With M the m x 6 matrix whose rows are the screws: M[rows, cols] is a nonzero
        r x r minor (rank >= r) and ``kernel`` holds 6 - r independent exact vectors
        with M k = 0 identically (rank <= r). Both are checked without sampling, in
        a field where every relation among the entries holds
        (:mod:`screwkit._certificates`).

        Parameters
        ----------
        timeout : float, optional
            Seconds the exact check may take (default 30); past it the certificate
            says it is not proven.

        Returns
        -------
        RankCertificate
            Unpacks as ``rows, cols, kernel``; ``proven`` and ``reason`` say what was
            checked.

        Raises
        ------
        TypeError
            If the screws hold floats (their rank is decided with a tolerance).
        ArithmeticError
            If the exact check contradicts the sampled rank (a bug to report).

        Examples
        --------
        The ball joint's rank 3, proven: a nonzero 3x3 minor and 3 kernel vectors.

        >>> ball = ScrewSystem([(d, [0, 0, 0], 0) for d in sp.eye(3).columnspace()])
        >>> certificate = ball.certificate()
        >>> certificate.proven, certificate.rows, len(certificate.kernel)
        (True, (0, 1, 2), 3)
        """
        if isinstance(timeout, bool) or not isinstance(timeout, (int, float)):
            raise TypeError(
                f"timeout must be a positive number of seconds, got {describe(timeout)}"
            )
        if not timeout > 0:
            raise ValueError(
                f"timeout must be a positive number of seconds, got {timeout!r}"
            )
        if self.numeric:
            raise TypeError(
                "certificate() proves the rank of exact screws; these hold floats, "
                f"whose rank is decided by SVD with tol={self.tol}: write them "
                "exactly (integers, sympy.Rational, sympy.sqrt, symbols) for a proof"
            )
        M = [_exact.entries(s.vector) for s in self.screws]
        if not self.screws:
            kernel = [sp.eye(6)[:, j] for j in range(6)]
            return _certificates.RankCertificate(
                [], [], kernel, True, "no screw: rank 0, every vector in the kernel"
            )
        rows = self._independent_rows()
        cols = _exact.pivot_columns(self.field, self._domain_matrix(), rows)
        basis = _exact.null_space(self.field, self._domain_matrix(), rows)
        kernel = [
            sp.Matrix(6, 1, [self.field.to_sympy(e) for e in row])
            for row in basis.to_list()
        ]
        verdict, reason = _certificates.certify(M, rows, cols, kernel, timeout)
        if verdict is False:
            raise ArithmeticError(
                f"the exact check contradicts the sampled rank {len(rows)}: {reason}"
            )
        return _certificates.RankCertificate(rows, cols, kernel, bool(verdict), reason)

    def principal_screws(self):
        """The principal screws and pitches of a 1-, 2- or 3-system.

        The pitch of a member x = B c is (c^T A c) / (c^T D c) with D = W^T W (W the
        direction rows of the basis B) and A the symmetric part of W^T V (V the moment
        rows); the principal screws are the generalised eigenvectors of A c = h D c
        (the kernel is the private ``screwkit._system_geometry``), exact for exact
        screws.

        Returns
        -------
        PrincipalScrews
            ``screws``, ``pitches`` (m/rad; ``sympy.oo`` or ``inf`` for a
            translation), ``unique`` and ``reason`` (why not unique).

        Raises
        ------
        ValueError
            For a system of order 0, 4, 5 or 6 (take the reciprocal of a 4- or
            5-system).

        Examples
        --------
        >>> import sympy as sp
        >>> planar = ScrewSystem([([0, 0, 1], [0, 0, 0], 0), ([1, 0, 0], [0, 0, 0],
        ...                       sp.oo), ([0, 1, 0], [0, 0, 0], sp.oo)])
        >>> planar.principal_screws().pitches
        [0, oo, oo]
        """
        return _system_geometry.principal_screws(self)

    def pitch_of(self, x):
        """The pitch of a member of the span.

        Parameters
        ----------
        x : Screw or 6-vector
            A member of the system (not zero).

        Returns
        -------
        number
            (s . s0) / (s . s) (m/rad); ``sympy.oo`` (exact) or ``inf`` (float) for
            a translation.

        Examples
        --------
        >>> ScrewSystem([[0, 0, 1, 0, 0, 0], [0, 0, 0, 0, 0, 1]]).pitch_of(
        ...     [0, 0, 2, 0, 0, 1])
        1/2
        """
        return _system_geometry.pitch_of(self, x)

    def classify(self):
        """The type of the system and its invariants (unchanged by any rigid motion and
        any change of basis).

        Returns
        -------
        Classification
            ``order``, ``type`` (the order and Gibson and Hunt's type, such as
            '3-IIC' for planar motion, see :class:`Classification`),
            ``translations``, ``pitches``, ``name`` ('planar motion', 'spherical
            motion', ...), ``description`` and ``gibson_hunt`` (the type alone,
            'IIC').

        Examples
        --------
        >>> origin = [0, 0, 0]
        >>> ScrewSystem([(d, origin, 0) for d in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
        ...             ).classify()[4:]
        ('spherical motion', 'every member a rotation about one point', 'IIA')
        """
        return _system_geometry.classify(self)

    def _from_field(self, row):
        return self.kind._checked(
            sp.Matrix(6, 1, [self.field.to_sympy(e) for e in row])
        )

    @fill(parameters=_OTHER_PARAMETERS)
    def union(self, other):
        """The span of both systems.

        {parameters}

        Returns
        -------
        ScrewSystem
            The span of the screws of both.

        Examples
        --------
        >>> slide_x = ScrewSystem([([1, 0, 0], [0, 0, 0], sp.oo)])
        >>> slide_y = ScrewSystem([([0, 1, 0], [0, 0, 0], sp.oo)])
        >>> slide_x.union(slide_y).rank, slide_x.union(slide_x).rank
        (2, 1)
        """
        self._check_kind(other, "union")
        return ScrewSystem(
            self.screws + other.screws, kind=self.kind, tol=min(self.tol, other.tol)
        )

    @fill(parameters=_OTHER_PARAMETERS)
    def intersection(self, other):
        """The screws common to both spans: the reciprocal of the union of the
        reciprocals.

        {parameters}

        Returns
        -------
        ScrewSystem
            The intersection of the two spans.

        Examples
        --------
        Planar motion in the xy plane and the rotations about the origin share one
        motion: the rotation about the z axis.

        >>> x, y, z, origin = sp.eye(3).columnspace() + [[0, 0, 0]]
        >>> planar = ScrewSystem([(z, origin, 0), (x, origin, sp.oo),
        ...                       (y, origin, sp.oo)])
        >>> ball = ScrewSystem([(d, origin, 0) for d in (x, y, z)])
        >>> planar.intersection(ball).basis()
        [Twist([0, 0, 1, 0, 0, 0])]
        """
        self._check_kind(other, "intersection")
        return self.reciprocal().union(other.reciprocal()).reciprocal()

    def contains(self, screw):
        """Whether ``screw`` lies in the span (generically).

        Parameters
        ----------
        screw : Screw or 6-vector
            The screw to test.

        Returns
        -------
        bool
            True if adding it does not raise the rank (generically, for symbols).

        Examples
        --------
        Planar motion contains the rotation about any vertical line, not a rotation
        about x:

        >>> planar = ScrewSystem([[0, 0, 1, 0, 0, 0], [0, 0, 0, 1, 0, 0],
        ...                       [0, 0, 0, 0, 1, 0]])
        >>> vertical_at_1_2 = [0, 0, 1, 2, -1, 0]  # (z; r x z), r = (1, 2, 0)
        >>> planar.contains(vertical_at_1_2), planar.contains([1, 0, 0, 0, 0, 0])
        (True, False)
        """
        return (
            ScrewSystem(self.screws + [screw], kind=self.kind, tol=self.tol).rank
            == self.rank
        )

    def _check_kind(self, other, operation):
        if not isinstance(other, ScrewSystem):
            raise TypeError(
                f"other must be a ScrewSystem (the {operation} is of two systems), "
                f"got {describe(other)}"
            )
        if other.kind is not self.kind:
            raise TypeError(
                f"cannot take the {operation} of a {self.noun} system and a "
                f"{other.noun} system"
            )

    def __len__(self):
        return len(self.screws)

    def __repr__(self):
        plural = "es" if self.noun.endswith("ch") else "s"
        return f"ScrewSystem({len(self.screws)} {self.noun}{plural}, rank {self.rank})"

    def summary(self):
        """The system as plain text.

        Returns
        -------
        str
            Its order and its canonical basis, one screw a line.

        Examples
        --------
        >>> print(ScrewSystem([[0, 0, 2, 0, 0, 0], [0, 0, 1, 0, 0, 0]]).summary())
        twist 1-system
          [0, 0, 1, 0, 0, 0]
        """
        rows = [str(list(s.vector)) for s in self.basis()] or ["(none)"]
        return "\n".join([f"{self.noun} {self.rank}-system"] + ["  " + r for r in rows])

    def _repr_latex_(self):
        name = f"{self.noun} {self.rank}-system: "
        return f"$\\text{{{name}}}{latex_table(self.basis())}$"

    def _repr_html_(self):
        return html_table(self.basis(), f"{self.noun} {self.rank}-system")


_HEADERS = {Twist: ("ω", "v"), Wrench: ("f", "m"), Screw: ("s", "s₀")}


def latex_table(screws):
    """The screws as the columns of a LaTeX matrix, angular part above the linear
    part."""
    if not screws:
        return r"\{0\}"
    return sp.latex(sp.Matrix.hstack(*(s.vector for s in screws)))


def _cell(entry):
    if entry.is_Integer or entry.is_Float:
        return str(entry)
    return f"<math>{sp.mathml(entry, printer='presentation')}</math>"


def _bracket_style(column, last, row):
    """A cell's style: centred, spaced, with a matrix bracket on the outer columns."""
    style = ["text-align:center", "padding:0.1em 0.7em"]
    for side, outer in (("left", column == 0), ("right", column == last)):
        if outer:
            style.append(f"border-{side}:1.5px solid")
            if row in (0, 5):
                style.append(f"border-{'top' if row == 0 else 'bottom'}:1.5px solid")
    return ";".join(style)


def html_table(screws, caption):
    """The screws as an HTML table (one column per screw, MathML entries) under
    ``caption``, framed by the brackets of a matrix."""
    head = (
        '<table class="screwkit-system" style="border-collapse:separate;'
        'border-spacing:0;margin:0.4em 0">'
        f'<caption style="white-space:nowrap;text-align:left">{caption}</caption>'
    )
    if not screws:
        return head + "<tr><td>(no screw: the zero system)</td></tr></table>"
    angular, linear = _HEADERS[type(screws[0])]
    rows = []
    last = len(screws) - 1
    for k in range(6):
        label = f"{angular if k < 3 else linear}<sub>{'xyz'[k % 3]}</sub>"
        cells = "".join(
            f'<td style="{_bracket_style(j, last, k)}">{_cell(s.vector[k])}</td>'
            for j, s in enumerate(screws)
        )
        rows.append(
            f'<tr><th style="padding:0.1em 0.6em 0.1em 0">{label}</th>{cells}</tr>'
        )
    return head + "".join(rows) + "</table>"
