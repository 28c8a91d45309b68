"""The roots of a batch of quartics, in closed form (Ferrari), checked.

Subproblems 5 and 6 end in a quartic in z = exp(i theta) for every pose of a batch.
An eigenvalue call on 10,000 companion matrices costs tens of milliseconds; Ferrari's
formulas cost a few dozen array operations. Each root is polished by a Newton step;
a batch member whose roots do not satisfy the quartic, or whose sum is not minus the
second coefficient (Vieta: two roots polished onto one), to within
:data:`~screwkit.tolerances.IK_QUARTIC_TOL` gets the companion matrix's eigenvalues
instead.
"""

import numpy as np

from ..tolerances import IK_QUARTIC_TOL

__all__ = ["quartic_roots"]


def _cbrt(x):
    """The principal cube root of complex x, by its modulus and angle (NumPy's
    complex power takes a logarithm: four times slower)."""
    angle = np.arctan2(x.imag, x.real) / 3
    return np.cbrt(np.abs(x)) * (np.cos(angle) + 1j * np.sin(angle))


def _cubic_root(p, q):
    """A root of t^3 + p t + q = 0 (complex arrays), by Cardano: t = u - p / (3 u)
    with u^3 = -q/2 + sqrt(q^2/4 + p^3/27), the sign of the square root that avoids
    cancellation; 0 where p = q = 0 (u = 0)."""
    s = np.sqrt(q * q / 4 + p * p * p / 27)
    u3 = np.where(np.abs(-q / 2 + s) >= np.abs(-q / 2 - s), -q / 2 + s, -q / 2 - s)
    u = _cbrt(u3)
    zero = u == 0
    return np.where(zero, 0.0, u - p / (3 * np.where(zero, 1.0, u)))


def _ferrari(a, b, c, d):
    """The roots of z^4 + a z^3 + b z^2 + c z + d, complex arrays (...): (..., 4)."""
    # z = y - a/4: y^4 + p y^2 + q y + r
    a2 = a * a
    p = b - 3 * a2 / 8
    q = c - a * b / 2 + a2 * a / 8
    r = d - a * c / 4 + a2 * b / 16 - 3 * a2 * a2 / 256
    # (y^2 + p/2 + m)^2 = 2m y^2 - q y + m^2 + m p + p^2/4 - r is a square for
    # 8 m^3 + 8 p m^2 + (2 p^2 - 8 r) m - q^2 = 0; with m = t - p/3, a depressed cubic
    cubic_q = -(p * p * p) / 108 + p * r / 3 - q * q / 8
    m = _cubic_root(-(p * p) / 12 - r, cubic_q) - p / 3
    root = np.sqrt(2 * m)
    ok = np.abs(root) > 0
    half_q = np.where(ok, q / (2 * np.where(ok, root, 1.0)), 0.0)
    # y^2 -+ root y + (p/2 + m +- q / (2 root)) = 0
    y = []
    for sign in (1.0, -1.0):
        B, C = -sign * root, p / 2 + m + sign * half_q
        disc = np.sqrt(B * B - 4 * C)
        y += [(-B + disc) / 2, (-B - disc) / 2]
    y = np.stack(y, -1)
    if not np.all(ok):
        # m = 0 (q = 0 and p^2 = 4 r): a biquadratic, y^2 = (-p +- sqrt(p^2 - 4 r)) / 2
        w = np.sqrt(p * p - 4 * r)
        y2 = [np.sqrt((-p + w) / 2), np.sqrt((-p - w) / 2)]
        quad = np.stack([y2[0], -y2[0], y2[1], -y2[1]], -1)
        y = np.where(ok[..., None], y, quad)
    return y - (a / 4)[..., None]


def _value(coeffs, z):
    """The quartic and its derivative at z (..., 4); coeffs (..., 5), highest first."""
    f, df = coeffs[..., :1] + 0 * z, 0 * z
    for k in range(1, 5):
        df = df * z + f
        f = f * z + coeffs[..., k : k + 1]
    return f, df


def quartic_roots(coeffs):
    """The four complex roots of each quartic of a batch.

    Parameters
    ----------
    coeffs : complex array (..., 5)
        c4 z^4 + c3 z^3 + c2 z^2 + c1 z + c0, highest first, with c4 != 0.

    Returns
    -------
    complex array (..., 4)
        The roots, with multiplicity, in no particular order.
    """
    coeffs = np.asarray(coeffs, complex)
    monic = coeffs / coeffs[..., :1]
    z = _ferrari(*(monic[..., k] for k in range(1, 5)))
    f, df = _value(monic, z)  # a Newton step, where the derivative is not 0
    steep = np.abs(df) > 0
    z = z - np.where(steep, f / np.where(steep, df, 1.0), 0.0)
    f, _ = _value(monic, z)
    size = np.abs(monic).sum(-1)[..., None] * np.maximum(1.0, np.abs(z)) ** 4
    bad = ~np.all(np.isfinite(z) & (np.abs(f) <= IK_QUARTIC_TOL * size), -1)
    # two roots polished onto one, a third lost: the sum of the roots tells (Vieta)
    total = np.abs(z.sum(-1) + monic[..., 1])
    bad |= ~(total <= IK_QUARTIC_TOL * (np.abs(z).sum(-1) + 1.0))
    if np.any(bad):
        companion = np.zeros(monic[bad].shape[:-1] + (4, 4), complex)
        companion[..., 0, :] = -monic[bad][..., 1:]
        companion[..., 1, 0] = companion[..., 2, 1] = companion[..., 3, 2] = 1.0
        z[bad] = np.linalg.eigvals(companion)
    return z
