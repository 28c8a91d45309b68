"""The parametrised exercises of the chapter redundancy: the keys' computations.

The statements and their draws are in screwkit/answers/redundancy.toml.
"""

import numpy as np

from ..redundancy import pseudo_inverse
from ..robots import planar
from . import register

WORDS = {3: "three", 4: "four", 5: "five"}


@register("redundancy", 4)
def least_norm_rates_of_the_last_link(n, phidot):
    """q1' (rad/s) of the least-norm rates that turn the last link of a planar arm of
    n unit links at ``phidot`` (rad/s), and the statement's phi and J."""
    arm = planar([1.0] * n)
    # the row omega_z of the geometric Jacobian: phi = q1 + ... + qn
    row = arm.geometric_jacobian(np.zeros(n))[5:6]
    qdot = np.linalg.pinv(row) @ [phidot]
    phi = " + ".join(f"q{i}" for i in range(1, n + 1))
    return qdot[0], {"n_word": WORDS[n], "phi": phi, "ones": " ".join(["1"] * n)}


@register("redundancy", 13)
def tip_of_a_three_link_arm(l1, l2, l3, q1, q2, q3):
    """The tip (x, y) (m) of a planar three-link arm at (q1, q2, q3) (deg)."""
    return planar([l1, l2, l3]).fk(np.radians((q1, q2, q3)))[:2, 3]


@register("redundancy", 14)
def least_norm_rates_along_a_path(l1, l2, l3, v):
    """The least-norm joint rates (rad/s) of a planar three-link arm at (0, 90, -90)
    deg that move its tip at (v, 0) m/s."""
    jacobian = planar([l1, l2, l3]).geometric_jacobian(np.radians([0, 90, -90]))[:2]
    return pseudo_inverse(jacobian) @ [v, 0.0]
