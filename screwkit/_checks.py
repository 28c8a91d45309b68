"""Input checks shared by every public function of screwkit.

Each check either returns the input converted to the form the caller computes
with (an exact SymPy matrix or expression, a float64 NumPy array, a float or an
int) or raises a ``TypeError``/``ValueError`` whose sentence names the argument,
what was expected and what was given.

Real numbers are Python ints and floats, NumPy integer and floating scalars and
arrays, and real SymPy numbers. Refused where a real number is meant: strings
(even numeric ones such as '0.5'), booleans, complex numbers and None.

>>> as_float_array([1, 2.5], "x")
array([1. , 2.5])
>>> as_float_array(["0.5"], "theta")
Traceback (most recent call last):
...
TypeError: theta must be a number or an array of numbers (real ones), got a string '0.5' in a list of length 1
>>> as_real_scalar(np.int64(3), "steps")
3.0
"""  # noqa: E501 (the doctest's expected TypeError is one line, as Python prints it)

import numbers

import numpy as np
import sympy as sp

from .tolerances import ROTATION_TOL, ZERO_TOL

#: The old name of :data:`screwkit.tolerances.ROTATION_TOL` (R^T R against I).
ORTHONORMAL_TOL = ROTATION_TOL

_INFINITE = {sp.nan, sp.zoo, sp.oo, -sp.oo}


#: The most characters of an input that an error message quotes (:func:`quoted`):
#: a message names what was wrong, it does not print the input back.
QUOTE_CHARS = 80

#: The largest array (bytes) a batched function builds in one piece before it refuses,
#: naming the size: 10^9 bytes (as ``screwkit.workspace``'s ``MAX_RESULT_BYTES``).
MAX_RESULT_BYTES = 1_000_000_000


def quoted(value, limit=QUOTE_CHARS):
    """``value`` as an error message quotes it: at most ``limit`` characters.

    The one way a message shows an input's value: an array is summarised by NumPy
    (its first and last entries) and anything longer than ``limit`` is cut, with
    "..." and, for an array, its shape.

    Parameters
    ----------
    value : object
        The value to quote.
    limit : int
        The most characters of the quote.

    Returns
    -------
    str

    Examples
    --------
    >>> quoted([1.5, 2.0])
    '[1.5, 2.0]'
    >>> quoted(np.arange(10**6.0))
    '[0.0, 1.0, 2.0, ..., 999997.0, 999998.0, 999999.0] (shape (1000000,))'
    >>> len(quoted(list(range(10**6))))
    80
    """
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, np.ndarray) and value.size > 6:
        ends = value.ravel()
        ends = [*map(repr, ends[:3].tolist()), "...", *map(repr, ends[-3:].tolist())]
        shape = f" (shape {value.shape})"
        text = "[" + ", ".join(ends) + "]"
        cut = max(limit - len(shape), 10)
        text = (text if len(text) <= cut else text[: cut - 3] + "...") + shape
    else:
        text = repr(value.tolist() if isinstance(value, np.ndarray) else value)
    if len(text) > limit:
        text = text[: limit - 3] + "..."
    return text


def check_result_bytes(nbytes, what, advice):
    """Refuse, before anything is allocated, a result of more than
    :data:`MAX_RESULT_BYTES` bytes: a ``ValueError`` that says what would be built,
    its size and what to do (``advice``)."""
    if nbytes > MAX_RESULT_BYTES:
        raise ValueError(
            f"{what} would build an array of {nbytes / 1e9:.3g} GB, but must stay "
            f"within the limit of {MAX_RESULT_BYTES / 1e9:g} GB; {advice}"
        )


def describe(value):
    """A short description of ``value`` for error messages: its shape or type."""
    if isinstance(value, sp.MatrixBase):
        return f"a SymPy matrix of shape {value.shape}"
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape} and dtype {value.dtype}"
    if isinstance(value, (list, tuple)):
        return f"a {type(value).__name__} of length {len(value)}"
    return f"{quoted(value)} ({type(value).__name__})"


def is_symbolic(value):
    """True if ``value`` holds SymPy objects (then screwkit computes exactly)."""
    if isinstance(value, (sp.Basic, sp.MatrixBase)):
        return True
    if isinstance(value, np.ndarray):
        return value.dtype == object and any(
            isinstance(v, sp.Basic) for v in value.flat
        )
    if isinstance(value, (list, tuple)):
        return any(is_symbolic(v) for v in value)
    return False


# ---- real numbers (NumPy) ------------------------------------------------------------


def _not_real(entry):
    """A phrase naming why ``entry`` (one element) is not a real number, or None if it
    is one."""
    if entry is None:
        return "None"
    if isinstance(entry, (bool, np.bool_)):
        return f"a boolean {entry!r}"
    if isinstance(entry, (str, bytes, np.str_, np.bytes_)):
        return f"a string {quoted(str(entry))}"
    if isinstance(entry, sp.Basic):
        if not isinstance(entry, sp.Expr) or entry.is_Boolean:
            return f"{quoted(entry)} ({type(entry).__name__})"
        if entry.free_symbols:
            return f"the symbolic expression {quoted(entry)}"
        if entry.is_extended_real is False:
            return f"the complex number {quoted(entry)}"
        return None
    if isinstance(entry, numbers.Real):
        return None
    if isinstance(entry, numbers.Complex):
        return f"the complex number {quoted(entry)}"
    return f"{describe(entry)}"


def _first_not_real(value):
    """The phrase of the first element of a nested list/tuple/object array that is not
    real."""
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, (list, tuple)):
            stack.extend(reversed(item))
        elif isinstance(item, np.ndarray):
            if item.dtype == object:
                stack.extend(reversed(item.ravel().tolist()))
            elif item.dtype.kind not in "iuf":
                return _dtype_phrase(item)
        else:
            reason = _not_real(item)
            if reason is not None:
                return reason
    return None


_PLAIN = (float, int, np.floating, np.integer)


def _plain_numbers(value):
    """True if every element of a nested sequence is a float or a (non-bool) integer: a
    fast test (types are collected in C), so that only unusual input is walked element
    by element."""
    try:
        elements = np.asarray(value, dtype=object).ravel().tolist()
    except ValueError:
        return False
    return all(
        issubclass(kind, _PLAIN) and kind is not bool
        for kind in set(map(type, elements))
    )


def _dtype_phrase(array):
    kind = {
        "b": "booleans",
        "c": "complex numbers",
        "U": "strings",
        "S": "bytes",
        "M": "dates",
        "m": "time deltas",
        "V": "raw records",
    }.get(array.dtype.kind, "")
    return f"an array of {kind or array.dtype} (dtype {array.dtype})"


def as_float_array(value, name):
    """``value`` as a float64 array of real numbers (any shape, empty allowed).

    ``TypeError`` for strings, booleans, complex numbers, None or other objects,
    ``ValueError`` for a ragged nested list or an entry that is NaN or infinite.
    """
    if isinstance(value, np.ndarray) and value.dtype.kind in "iuf":
        array = value.astype(float, copy=False)
    else:
        if isinstance(value, (list, tuple, np.ndarray)):
            reason = None if _plain_numbers(value) else _first_not_real(value)
        else:
            reason = _not_real(value)
        if reason is not None:
            where = (
                "" if not isinstance(value, (list, tuple)) else f" in {describe(value)}"
            )
            raise TypeError(
                f"{name} must be a number or an array of numbers (real ones), got "
                f"{reason}{where}"
            )
        try:
            array = np.asarray(value, dtype=float)
        except ValueError:
            raise ValueError(
                f"{name} must be a rectangular array of real numbers "
                f"(rows of equal length), got {describe(value)} with rows of different "
                "lengths"
            ) from None
        except TypeError:
            raise TypeError(
                f"{name} must be a number or an array of numbers (real ones), got "
                f"{describe(value)}"
            ) from None
        except OverflowError:
            raise ValueError(
                f"{name} must be finite, got an integer too large for a float "
                f"(above 1.8e308) in {describe(value)}"
            ) from None
    check_finite(array, name)
    return array


def check_finite(array, name):
    """Raise ``ValueError`` naming the first NaN or infinite entry of the float
    ``array``."""
    finite = np.isfinite(array)
    if not finite.all():
        index = tuple(int(i) for i in np.argwhere(~finite)[0])
        where = f" at index {index}" if index else ""
        raise ValueError(f"{name} must be finite, got {array[index]}{where}")
    return array


def as_real_scalar(value, name):
    """One finite real number as a Python float (NumPy integers and 0-d arrays
    accepted)."""
    array = as_float_array(value, name)
    if array.shape != ():
        raise TypeError(f"{name} must be a single real number, got {describe(value)}")
    return float(array)


def real_number(value, name, what="a real number"):
    """One finite real number (not a bool, text, None or complex): an int stays an int,
    anything else float() takes becomes a float."""
    if (
        isinstance(value, (bool, np.bool_, str, bytes))
        or value is None
        or isinstance(value, (complex, np.complexfloating))
    ):
        raise TypeError(f"{name} must be {what}, got {describe(value)}")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be {what}, got {describe(value)}") from None
    if not np.isfinite(number):
        raise ValueError(f"{name} must be finite, got {number}")
    return int(value) if isinstance(value, (int, np.integer)) else number


def check_positive(value, name, allow_zero=False):
    """One finite real number > 0 (or >= 0 with ``allow_zero``), as a float."""
    number = as_real_scalar(value, name)
    if number < 0 or (number == 0 and not allow_zero):
        expected = "a number >= 0" if allow_zero else "a positive number"
        raise ValueError(f"{name} must be {expected}, got {number!r}")
    return number


def check_integer(value, name, minimum=None):
    """One integer (Python or NumPy; not a bool or a float) >= ``minimum``, as an
    int."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(
        value, (numbers.Integral, np.integer)
    ):
        raise TypeError(f"{name} must be an integer, got {describe(value)}")
    if minimum is not None and value < minimum:
        raise ValueError(
            f"{name} must be an integer >= {minimum}, got {quoted(int(value))}"
        )
    return int(value)


def check_flag(value, name):
    """``value`` as a bool if it is True or False (NumPy's too), else a
    ``TypeError``."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be True or False, got {describe(value)}")
    return bool(value)


def check_option(value, name, options):
    """``value`` if it is one of ``options`` (strings or None), else a ``ValueError``
    naming them."""
    if isinstance(value, (str, type(None))) and value in options:
        return value
    listed = ", ".join(repr(o) for o in options)
    error = ValueError if isinstance(value, (str, type(None))) else TypeError
    raise error(f"{name} must be one of {listed}, got {describe(value)}")


class ChainType:
    """The type the checks recognise as a chain: :class:`screwkit.Chain` derives from
    it.

    The checks are the lowest layer and the chains a higher one: this marker lets
    :func:`check_chain` recognise a chain without importing the layer above it.
    """

    __slots__ = ()


def check_chain(value, name="chain"):
    """``value`` if it is a screwkit Chain, else a ``TypeError`` naming ``name``.

    The one check (and the one message) of every function that takes a chain.
    """
    if not isinstance(value, ChainType):
        raise TypeError(
            f"{name} must be a screwkit Chain (e.g. sk.robots.puma560()), got "
            f"{describe(value)}"
        )
    return value


def array_of_shape(value, name, shape, what):
    """``value`` as a float64 array of exactly ``shape``, else a ValueError: ``name``
    must be ``what`` (which says the shape expected), and the shape given."""
    array = as_float_array(value, name)
    if array.shape != tuple(shape):
        raise ValueError(f"{name} must be {what}, got shape {array.shape}")
    return array


def check_shape(array, name, shape):
    """Require ``array.shape`` to end with ``shape`` (leading axes are a batch)."""
    tail = array.shape[array.ndim - len(shape) :] if array.ndim >= len(shape) else None
    if tail != tuple(shape):
        expected = ", ".join(str(s) for s in shape)
        single = f"({expected},)" if len(shape) == 1 else f"({expected})"
        raise ValueError(
            f"{name} must have shape {single} or (N, {expected}) for a batch, "
            f"got shape {array.shape}"
        )
    return array


# ---- exact numbers (SymPy) -----------------------------------------------------------


def as_sympy_matrix(value, name, shape):
    """``value`` as an exact SymPy matrix of the given ``shape``
    (a row is taken as a column).

    Entries must be real numbers or SymPy expressions; strings, booleans, complex
    numbers (such as ``sympy.I``) and non-finite values are refused.
    """
    if isinstance(value, sp.MatrixBase):
        matrix = value
    else:
        if value is None or isinstance(
            value, (str, bytes, bool, numbers.Number, sp.Basic)
        ):
            raise TypeError(
                f"{name} must be a matrix of shape {shape}, got {describe(value)}"
            )
        if _contains_string(value):
            raise TypeError(
                f"{name} must hold numbers or SymPy expressions, not strings, got "
                f"{quoted(value)}"
            )
        if _contains_none(value):
            raise TypeError(
                f"{name} must hold numbers or SymPy expressions, got None in "
                f"{quoted(value)}"
            )
        try:
            matrix = sp.Matrix(value)
        except (TypeError, ValueError, sp.SympifyError, AttributeError):
            raise TypeError(
                f"{name} must be a matrix of shape {shape}, got {describe(value)}"
            ) from None
    if matrix.shape != shape and not (shape[1] == 1 and matrix.shape == (1, shape[0])):
        raise ValueError(f"{name} must have shape {shape}, got {describe(matrix)}")
    entries = matrix.flat()
    for entry in entries:
        _check_exact_entry(entry, name)
    return sp.Matrix(shape[0], shape[1], [_exact_if_integral(e) for e in entries])


def _check_exact_entry(entry, name, what="an entry equal to"):
    """A finite, real SymPy expression; ``what`` introduces it in the messages."""
    what = f"{what} " if what else ""
    if not isinstance(entry, sp.Expr) or entry.is_Boolean:
        raise TypeError(
            f"{name} must hold numbers or SymPy expressions, got {quoted(entry)}"
        )
    if (
        entry in _INFINITE
        or not entry.is_Atom
        and entry.has(sp.nan, sp.zoo, sp.oo, -sp.oo)
    ):
        raise ValueError(f"{name} must be finite, got {what}{quoted(entry)}")
    if entry.is_number and entry.is_extended_real is False:
        raise TypeError(
            f"{name} must be real, got {what}the complex number {quoted(entry)}"
        )


def as_sympy_scalar(value, name):
    """``value`` as one exact, finite, real SymPy number or expression."""
    if isinstance(value, (str, bytes, bool, np.bool_)) or value is None:
        raise TypeError(
            f"{name} must be a number or a SymPy expression, got {describe(value)}"
        )
    try:
        entry = sp.sympify(value, strict=True)
    except sp.SympifyError:
        raise TypeError(
            f"{name} must be a number or a SymPy expression, got {describe(value)}"
        ) from None
    if not isinstance(entry, sp.Expr) or entry.is_Boolean:
        raise TypeError(
            f"{name} must be a number or a SymPy expression, got {describe(value)}"
        )
    _check_exact_entry(entry, name, what="")
    return _exact_if_integral(entry)


def _contains_string(value):
    if isinstance(value, (str, bytes)):
        return True
    if isinstance(value, (list, tuple)):
        return any(_contains_string(v) for v in value)
    return (
        isinstance(value, np.ndarray)
        and value.dtype.kind in "USO"
        and any(isinstance(v, (str, bytes)) for v in value.flat)
    )


def _contains_none(value):
    if value is None:
        return True
    if isinstance(value, (list, tuple)):
        return any(_contains_none(v) for v in value)
    return (
        isinstance(value, np.ndarray)
        and value.dtype.kind == "O"
        and any(v is None for v in value.flat)
    )


def _exact_if_integral(entry):
    """A float with an integer value (1.0, -0.0) is that integer, exactly; other entries
    stay."""
    if isinstance(entry, sp.Float) and float(entry).is_integer():
        return sp.Integer(int(entry))
    return entry


def as_scalar_or_batch(value, name):
    """An angle or distance: a real SymPy expression, or a float64 array of any
    shape."""
    if is_symbolic(value):
        if isinstance(value, (list, tuple, np.ndarray, sp.MatrixBase)):
            raise TypeError(
                f"{name} must be a single SymPy expression, got {describe(value)}"
            )
        return as_sympy_scalar(value, name)
    if isinstance(value, (bool, np.bool_)) or not isinstance(
        value, (numbers.Real, list, tuple, np.ndarray)
    ):
        raise TypeError(
            f"{name} must be a real number or an array of them, got {describe(value)}"
        )
    return as_float_array(value, name)


# ---- rotations and transforms --------------------------------------------------------


def check_rotation(rotation, name="R"):
    """A rotation matrix: shape (3, 3) or (N, 3, 3), orthonormal, determinant +1.

    SymPy input stays exact; its orthonormality is checked at a few sample
    values of its free symbols (a matrix that fails there is not a rotation).
    """
    if is_symbolic(rotation):
        R = as_sympy_matrix(rotation, name, (3, 3))
        _check_rotation_numeric(_sampled(R, name), name)
        return R
    R = check_shape(as_float_array(rotation, name), name, (3, 3))
    _check_rotation_numeric(R, name)
    return R


def _sample_numeric(matrix):
    symbols = sorted(matrix.free_symbols, key=str)
    if not symbols:
        return np.array(matrix.evalf(), dtype=float)
    samples = [0.3 + 0.7 * k for k in range(len(symbols))]
    return np.array(matrix.subs(dict(zip(symbols, samples))).evalf(), dtype=float)


def _sampled(matrix, name):
    """:func:`_sample_numeric`, with a ``TypeError`` naming ``name`` for an entry
    SymPy cannot evaluate to a number (an undefined function such as f(t))."""
    try:
        return _sample_numeric(matrix)
    except TypeError:
        bad = [e for e in matrix if e.atoms(sp.core.function.AppliedUndef)]
        raise TypeError(
            f"{name} must hold numbers, symbols or functions SymPy can evaluate, got "
            f"the entry {bad[0] if bad else matrix} (an undefined function has no "
            f"value to check)"
        ) from None


def _check_rotation_numeric(R, name):
    if R.size == 0:
        return
    gram = np.swapaxes(R, -1, -2) @ R
    deviation = np.max(np.abs(gram - np.eye(3)))
    if not deviation <= ROTATION_TOL:
        raise ValueError(
            f"{name} must be a rotation matrix (orthonormal columns), "
            f"but R^T R differs from the identity by {deviation:.3g}"
        )
    determinant = np.linalg.det(R)
    if np.any(determinant < 0):
        raise ValueError(
            f"{name} must be a rotation matrix with determinant +1, "
            f"got determinant {np.min(determinant):.3g} (a reflection)"
        )


def check_transform(transform, name="T"):
    """A homogeneous transform: shape (4, 4) or (N, 4, 4), rotation block, last row
    [0 0 0 1]."""
    if is_symbolic(transform):
        T = as_sympy_matrix(transform, name, (4, 4))
        if any((entry - target) != 0 for entry, target in zip(T[3, :], [0, 0, 0, 1])):
            raise ValueError(
                f"{name} must have last row [0, 0, 0, 1], got {list(T[3, :])}"
            )
        check_rotation(T[:3, :3], f"the rotation block of {name}")
        return T
    T = check_shape(as_float_array(transform, name), name, (4, 4))
    if not np.allclose(T[..., 3, :], [0.0, 0.0, 0.0, 1.0], atol=ZERO_TOL):
        bad = T[..., 3, :].reshape(-1, 4)
        first = bad[
            ~np.all(np.isclose(bad, [0.0, 0.0, 0.0, 1.0], atol=ZERO_TOL), axis=-1)
        ][0]
        raise ValueError(
            f"{name} must have last row [0, 0, 0, 1], got {first.tolist()}"
        )
    check_rotation(T[..., :3, :3], f"the rotation block of {name}")
    return T


def check_poses(T, name="T", single_only=False):
    """The one pose check: ``T`` as float64 rigid transforms.

    A float batch (N, 4, 4) is first checked in one fast pass over cache-sized blocks
    (the largest |R^T R - I|, the smallest det R, the last rows); the full check, and
    its message, runs only when that pass finds something wrong.

    Parameters
    ----------
    T : array-like, shape (4, 4) or (N, 4, 4), rigid transforms (m)
    name : str, the argument's name in messages
    single_only : bool, refuse a batch (one pose of shape (4, 4) expected)

    Returns
    -------
    ndarray, shape (4, 4) or (N, 4, 4), float64 (the caller's array if it already is)
    """
    if isinstance(T, (str, bytes)) or T is None:
        raise TypeError(
            f"{name} must be a 4x4 pose or an (N, 4, 4) batch, got {describe(T)}"
        )
    if not single_only and _is_pose_batch(T):
        return T
    T = as_float_array(T, name)
    if single_only and T.shape != (4, 4):
        raise ValueError(
            f"{name} must be one pose of shape (4, 4), got shape {T.shape}"
        )
    if T.ndim not in (2, 3):
        raise ValueError(
            f"{name} must have shape (4, 4) or (N, 4, 4), got shape {T.shape}"
        )
    return check_transform(T, name)


def one_pose(T):
    """``T`` if it is plainly one rigid transform, else None: the scalar path's check.

    A float64 array (4, 4), finite, with last row [0, 0, 0, 1] (within
    :data:`~screwkit.tolerances.ZERO_TOL`), R^T R within
    :data:`~screwkit.tolerances.ROTATION_TOL` of the identity and det R > 0: the tests
    of :func:`check_poses`, on Python floats. None for anything else; the caller's
    full check then runs and says what is wrong.
    """
    if type(T) is not np.ndarray or T.shape != (4, 4) or T.dtype.char != "d":
        return None
    (a, b, c, x), (d, e, f, y), (g, h, i, z), last = T.tolist()
    total = a + b + c + x + d + e + f + y + g + h + i + z + sum(last)
    if total - total != 0.0:  # a NaN or an infinity
        return None
    if max(abs(last[0]), abs(last[1]), abs(last[2]), abs(last[3] - 1.0)) > ZERO_TOL:
        return None
    gram = (
        a * a + d * d + g * g - 1.0,
        b * b + e * e + h * h - 1.0,
        c * c + f * f + i * i - 1.0,
        a * b + d * e + g * h,
        a * c + d * f + g * i,
        b * c + e * f + h * i,
    )
    if max(abs(v) for v in gram) > ROTATION_TOL:
        return None
    if a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) <= 0:
        return None
    return T


#: Where R_ij sits in a flattened 4 x 4 pose, for i, j = 0, 1, 2.
_ROTATION = [0, 1, 2, 4, 5, 6, 8, 9, 10]


def _is_pose_batch(T):
    """True if T is a float64 (N, 4, 4) array of rigid transforms (the fast pass)."""
    if not (
        isinstance(T, np.ndarray)
        and T.dtype == np.float64
        and T.ndim == 3
        and T.shape[1:] == (4, 4)
    ):
        return False
    flat = T.reshape(-1, 16)
    worst, det = 0.0, 1.0
    for start in range(0, len(flat), 8192):  # blocks that stay in the cache
        block_worst, block_det = _gram_and_det(flat[start : start + 8192].T[_ROTATION])
        worst, det = max(worst, block_worst), min(det, block_det)
    last = np.max(np.abs(T[:, 3, :] - [0.0, 0.0, 0.0, 1.0]), initial=0.0)
    return bool(
        worst <= ROTATION_TOL and last <= ZERO_TOL and det > 0 and np.isfinite(T).all()
    )


def _gram_and_det(r):
    """max |R^T R - I| and min det R over rotations given as rows r[3 i + j] = R_ij."""
    col = [(r[j], r[3 + j], r[6 + j]) for j in range(3)]
    dot, term = np.empty(r.shape[1]), np.empty(r.shape[1])  # in place: no temporaries
    worst = 0.0
    for i in range(3):
        for j in range(i, 3):
            np.multiply(col[i][0], col[j][0], out=dot)
            for k in (1, 2):
                dot += np.multiply(col[i][k], col[j][k], out=term)
            target = float(i == j)
            worst = max(worst, dot.max() - target, target - dot.min())
    # det R = c0 . (c1 x c2) > 0 (a reflection passes the Gram test)
    np.multiply(col[1][1], col[2][2], out=dot)
    dot -= np.multiply(col[1][2], col[2][1], out=term)
    det = dot * col[0][0]
    np.multiply(col[1][2], col[2][0], out=dot)
    dot -= np.multiply(col[1][0], col[2][2], out=term)
    det += np.multiply(dot, col[0][1], out=term)
    np.multiply(col[1][0], col[2][1], out=dot)
    dot -= np.multiply(col[1][1], col[2][0], out=term)
    det += np.multiply(dot, col[0][2], out=term)
    return worst, det.min(initial=1.0)
