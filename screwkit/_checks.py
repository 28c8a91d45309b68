"""Input checks shared by every public function of screwkit.

Each check either returns the input converted to the form the caller computes
with (an exact SymPy matrix, or a float64 NumPy array) or raises a
``TypeError``/``ValueError`` whose sentence names the argument, what was
expected and what was given.
"""
import numbers

import numpy as np
import sympy as sp

#: Tolerance for numeric orthonormality checks of rotation matrices.
ORTHONORMAL_TOL = 1e-6


def describe(value):
    """A short description of ``value`` for error messages: its shape or type."""
    if isinstance(value, sp.MatrixBase):
        return f"a SymPy matrix of shape {value.shape}"
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape}"
    if isinstance(value, (list, tuple)):
        return f"a {type(value).__name__} of length {len(value)}"
    return f"{value!r} ({type(value).__name__})"


def is_symbolic(value):
    """True if ``value`` holds SymPy objects (then screwkit computes exactly)."""
    if isinstance(value, (sp.Basic, sp.MatrixBase)):
        return True
    if isinstance(value, np.ndarray):
        return value.dtype == object and any(isinstance(v, sp.Basic) for v in value.flat)
    if isinstance(value, (list, tuple)):
        return any(is_symbolic(v) for v in value)
    return False


def as_float_array(value, name):
    """``value`` as a float64 array; ``TypeError`` if it is not numeric, ``ValueError`` on NaN/inf."""
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be a number or an array of numbers, got {describe(value)}")
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(
            f"{name} must be a number or an array of numbers, got {describe(value)}"
        ) from None
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be finite, got a value that is NaN or infinite: {value!r}")
    return array


def as_sympy_matrix(value, name, shape):
    """``value`` as an exact SymPy matrix of the given ``shape``."""
    if isinstance(value, sp.MatrixBase):
        matrix = value
    else:
        if _contains_string(value):
            raise TypeError(f"{name} must hold numbers or SymPy expressions, not strings, got {value!r}")
        try:
            matrix = sp.Matrix(value)
        except (TypeError, ValueError, sp.SympifyError):
            raise TypeError(f"{name} must be a matrix of shape {shape}, got {describe(value)}") from None
    if matrix.shape != shape and not (shape[1] == 1 and matrix.shape == (1, shape[0])):
        raise ValueError(f"{name} must have shape {shape}, got {describe(matrix)}")
    entries = matrix.flat()
    for entry in entries:
        if not entry.is_Atom and entry.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or entry in _INFINITE:
            raise ValueError(f"{name} must be finite, got an entry equal to {entry}")
    return sp.Matrix(shape[0], shape[1], [_exact_if_integral(e) for e in entries])


_INFINITE = {sp.nan, sp.zoo, sp.oo, -sp.oo}


def as_sympy_scalar(value, name):
    """``value`` as one exact, finite SymPy number or expression."""
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be a number or a SymPy expression, got {describe(value)}")
    try:
        entry = sp.sympify(value, strict=True)
    except sp.SympifyError:
        raise TypeError(f"{name} must be a number or a SymPy expression, got {describe(value)}") from None
    if not isinstance(entry, sp.Expr):
        raise TypeError(f"{name} must be a number or a SymPy expression, got {describe(value)}")
    if entry in _INFINITE or not entry.is_Atom and entry.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise ValueError(f"{name} must be finite, got {entry}")
    return _exact_if_integral(entry)


def _contains_string(value):
    if isinstance(value, (str, bytes)):
        return True
    if isinstance(value, (list, tuple)):
        return any(_contains_string(v) for v in value)
    return isinstance(value, np.ndarray) and value.dtype.kind in "USO" and any(
        isinstance(v, (str, bytes)) for v in value.flat
    )


def _exact_if_integral(entry):
    """A float with an integer value (1.0, -0.0) is that integer, exactly; other entries stay."""
    if isinstance(entry, sp.Float) and float(entry).is_integer():
        return sp.Integer(int(entry))
    return entry


def check_shape(array, name, shape):
    """Require ``array.shape`` to end with ``shape`` (leading axes are a batch)."""
    tail = array.shape[array.ndim - len(shape):] if array.ndim >= len(shape) else None
    if tail != tuple(shape):
        expected = " x ".join(str(s) for s in shape)
        raise ValueError(
            f"{name} must have shape ({expected}) or (N, {expected}) for a batch, "
            f"got shape {array.shape}"
        )
    return array


def as_scalar_or_batch(value, name):
    """An angle or distance: a SymPy expression, or a float64 array of any shape."""
    if is_symbolic(value):
        if isinstance(value, (list, tuple, np.ndarray, sp.MatrixBase)):
            raise TypeError(f"{name} must be a single SymPy expression, got {describe(value)}")
        expr = sp.sympify(value)
        if expr.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise ValueError(f"{name} must be finite, got {expr}")
        return expr
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, list, tuple, np.ndarray)):
        raise TypeError(f"{name} must be a real number or an array of them, got {describe(value)}")
    return as_float_array(value, name)


def check_rotation(rotation, name="R"):
    """A rotation matrix: shape (3, 3) or (N, 3, 3), orthonormal, determinant +1.

    SymPy input stays exact; its orthonormality is checked at a few sample
    values of its free symbols (a matrix that fails there is not a rotation).
    """
    if is_symbolic(rotation):
        R = as_sympy_matrix(rotation, name, (3, 3))
        _check_rotation_numeric(_sample_numeric(R), name)
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


def _check_rotation_numeric(R, name):
    gram = np.swapaxes(R, -1, -2) @ R
    deviation = np.max(np.abs(gram - np.eye(3)))
    if deviation > ORTHONORMAL_TOL:
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
    """A homogeneous transform: shape (4, 4) or (N, 4, 4), rotation block, last row [0 0 0 1]."""
    if is_symbolic(transform):
        T = as_sympy_matrix(transform, name, (4, 4))
        if any((entry - target) != 0 for entry, target in zip(T[3, :], [0, 0, 0, 1])):
            raise ValueError(f"{name} must have last row [0, 0, 0, 1], got {list(T[3, :])}")
        check_rotation(T[:3, :3], f"the rotation block of {name}")
        return T
    T = check_shape(as_float_array(transform, name), name, (4, 4))
    if not np.allclose(T[..., 3, :], [0.0, 0.0, 0.0, 1.0], atol=1e-12):
        raise ValueError(f"{name} must have last row [0, 0, 0, 1], got {T[..., 3, :].tolist()}")
    check_rotation(T[..., :3, :3], f"the rotation block of {name}")
    return T
