"""Screw systems: spans of screws, their rank, canonical basis and reciprocal system.

>>> import sympy as sp
>>> prismatic_xy = ScrewSystem([([1, 0, 0], [0, 0, 0], sp.oo), ([0, 1, 0], [0, 0, 0], sp.oo)])
>>> prismatic_xy.rank
2
>>> prismatic_xy.reciprocal().rank
4
"""
import sympy as sp

from . import _exact
from .screws import Screw, Twist, Wrench

__all__ = ["ScrewSystem"]

_OTHER = {Twist: Wrench, Wrench: Twist, Screw: Screw}


def _swap(row):
    """Coordinates [a; b] -> [b; a]: x . swap(y) is the reciprocal product."""
    return list(row[3:]) + list(row[:3])


class ScrewSystem:
    """The span of a list of screws (exact). ``kind`` is Twist (default), Wrench or Screw.

    ``screws`` may hold Screw objects, 6-vectors, or (s, r, h) triples as in the
    mobility paper's zeroth step.
    """

    def __init__(self, screws, kind=None, _field=None, _rank=None, _basis=None):
        if isinstance(screws, ScrewSystem):
            screws = screws.screws
        if not isinstance(screws, (list, tuple)):
            raise TypeError(f"screws must be a list of screws, 6-vectors or (s, r, h) triples, got {type(screws).__name__}")
        kinds = {type(s) for s in screws if isinstance(s, Screw)}
        if len(kinds) > 1:
            raise TypeError(f"a screw system holds one kind of screw, got {sorted(k.kind for k in kinds)}")
        self.kind = kind or (kinds.pop() if kinds else Twist)
        self.screws = [self._as_screw(s, i) for i, s in enumerate(screws)]
        self._field = _field
        self._rank = _rank
        self._basis = _basis

    def _as_screw(self, item, index):
        if isinstance(item, Screw):
            return item if type(item) is self.kind else self.kind(item.vector)
        if isinstance(item, (list, tuple)) and len(item) == 3:
            try:
                return self.kind.from_axis(*item)
            except (TypeError, ValueError) as error:
                raise type(error)(f"screw {index}: {error}") from None
        return self.kind(item)

    @property
    def field(self):
        if self._field is None:
            self._field = _exact.Field([e for s in self.screws for e in s.vector])
        return self._field

    @property
    def matrix(self):
        """The screws as the columns of a 6 x m SymPy matrix."""
        if not self.screws:
            return sp.zeros(6, 0)
        return sp.Matrix.hstack(*(s.vector for s in self.screws))

    def _domain_matrix(self):
        return self.field.matrix([list(s.vector) for s in self.screws]) if self.screws else None

    @property
    def rank(self):
        """The order of the system: the number of independent screws, for generic symbol values."""
        if self._rank is None:
            self._rank = self.field.rank(self._domain_matrix()) if self.screws else 0
        return self._rank

    order = rank

    def basis(self):
        """A canonical basis (list of screws), reduced so that each ends in 1 at its own pivot."""
        if self._basis is None:
            if not self.screws:
                self._basis = []
            else:
                R = _exact.reduced_basis(self.field, self._domain_matrix())
                self._basis = [self.kind._checked(sp.Matrix(6, 1, [self.field.to_sympy(e) for e in row]))
                               for row in R.to_list()]
        return list(self._basis)

    def reciprocal(self):
        """The system of every screw reciprocal to all of these (twists -> wrenches and back)."""
        other = _OTHER[self.kind]
        if not self.screws:
            return ScrewSystem([other(v) for v in sp.eye(6).columnspace()], kind=other)
        M = self.field.matrix([_swap(s.vector) for s in self.screws])
        N = _exact.null_space(self.field, M)
        basis = [other._checked(sp.Matrix(6, 1, [self.field.to_sympy(e) for e in row])) for row in N.to_list()]
        return ScrewSystem(basis, kind=other, _rank=len(basis), _basis=basis)

    def union(self, other):
        """The span of both systems (same kind)."""
        self._check_kind(other, "union")
        return ScrewSystem(self.screws + other.screws, kind=self.kind)

    def intersection(self, other):
        """The screws common to both spans: the reciprocal of the union of the reciprocals."""
        self._check_kind(other, "intersection")
        return self.reciprocal().union(other.reciprocal()).reciprocal()

    def contains(self, screw):
        """True if ``screw`` lies in the span (generically)."""
        return ScrewSystem(self.screws + [screw], kind=self.kind).rank == self.rank

    def _check_kind(self, other, operation):
        if not isinstance(other, ScrewSystem):
            raise TypeError(f"{operation} needs another ScrewSystem, got {type(other).__name__}")
        if other.kind is not self.kind:
            raise TypeError(f"cannot take the {operation} of a {self.kind.kind} system and a {other.kind.kind} system")

    def __len__(self):
        return len(self.screws)

    def __repr__(self):
        return f"ScrewSystem({len(self.screws)} {self.kind.kind}s, rank {self.rank})"

    def _repr_latex_(self):
        columns = sp.Matrix.hstack(*(s.vector for s in self.basis())) if self.rank else sp.zeros(6, 0)
        return f"$\\text{{{self.kind.kind} {self.rank}-system: }}{sp.latex(columns)}$"
