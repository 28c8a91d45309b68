"""Jacobians of serial chains (numeric, vectorised over a batch of configurations).

Two Jacobians, with names that say which:

* ``geometric_jacobian``: rows [v; omega], v the velocity of the end-effector point, both in
  the base frame (Spong, Siciliano, Corke's ``jacob0``);
* ``space_jacobian``: columns are the joint twists [omega; v] in the base frame, v being the
  velocity of the body point at the base origin (Lynch & Park's J_s).
"""
import numpy as np

from .chains import Joint

__all__ = ["geometric_jacobian", "space_jacobian"]


def geometric_jacobian(chain, q):
    """The geometric Jacobian: q (n,) -> (6, n), Q (N, n) -> (N, 6, n); rows [v; omega].

    Column i is (z_i x (p - o_i); z_i) for a revolute joint and (z_i; 0) for a prismatic
    one, with p the end-effector point.
    """
    z, o = chain.joint_axes(q)
    p = chain.fk(q)[..., None, :3, 3]
    revolute = np.array([j is Joint.REVOLUTE for j in chain.joints])[:, None]
    v = np.where(revolute, np.cross(z, p - o), z)
    omega = np.where(revolute, z, 0.0)
    return np.swapaxes(np.concatenate([v, omega], axis=-1), -1, -2)


def space_jacobian(chain, q):
    """The space Jacobian: q (n,) -> (6, n), Q (N, n) -> (N, 6, n); columns [omega; v].

    Column i is the twist of joint i in the base frame: (z_i; o_i x z_i) for a revolute
    joint (the velocity of the body point at the base origin), (0; z_i) for a prismatic one.
    """
    z, o = chain.joint_axes(q)
    revolute = np.array([j is Joint.REVOLUTE for j in chain.joints])[:, None]
    omega = np.where(revolute, z, 0.0)
    v = np.where(revolute, np.cross(o, z), z)
    return np.swapaxes(np.concatenate([omega, v], axis=-1), -1, -2)
