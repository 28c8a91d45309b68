"""The closed forms of one pose in Python floats: the scalar path of ``analytic_ik``.

For one pose the vectorised engines (:mod:`.spherical_wrist`, :mod:`.ur`) pay NumPy's
cost per call hundreds of times on arrays of a few numbers; here the same steps, in
the same order, run on floats with :mod:`math`, the arm's constant vectors computed
once per arm and cached on it. Each function returns what the engine's ``_solve``
returns for a batch of one pose: Q (8, 6) in the order of CONFIGURATIONS (NaN rows
where a branch does not reach), the singularity flags (8, 3) and the reason code.
The tests hold the two paths to the same numbers (tests/test_single_call_ik.py).
"""

import math

import numpy as np

from ..tolerances import IK_CLIP_TOL, IK_SINGULAR_TOL
from ..tolerances import IK_LABEL_TOL as WRIST_TOL

__all__ = []

_NAN_ROW = [math.nan] * 6


def _dot(a, b):
    a0, a1, a2 = a
    b0, b1, b2 = b
    return a0 * b0 + a1 * b1 + a2 * b2


def _cross(a, b):
    return (
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    )


def _wrap(angle):
    """An angle in (-pi, pi], as :func:`screwkit.transforms._wrap_angle`."""
    return math.pi - (math.pi - angle) % (2 * math.pi)


def _polar(y, x):
    """atan2(y, x) with its cosine and sine (1, y where x = y = 0), as the engines'
    ``_polar``."""
    h = math.hypot(x, y)
    if h > 0:
        return math.atan2(y, x), x / h, y / h
    return math.atan2(y, x), 1.0, y


def _turn(w, x, c, s):
    """x turned about the unit axis w by the angle of cosine c and sine s
    (:meth:`._closed_form.Turn.first`: x c + (w x x) s + w ((w . x)(1 - c)))."""
    w0, w1, w2 = w
    x0, x1, x2 = x
    along = (w0 * x0 + w1 * x1 + w2 * x2) * (1 - c)  # _dot and _cross inline
    return (
        x0 * c + (w1 * x2 - w2 * x1) * s + w0 * along,
        x1 * c + (w2 * x0 - w0 * x2) * s + w1 * along,
        x2 * c + (w0 * x1 - w1 * x0) * s + w2 * along,
    )


def _rows(T):
    """The rotation (3 rows) and position of a pose (4, 4) as floats."""
    rows = T.tolist()
    return [row[:3] for row in rows[:3]], [row[3] for row in rows[:3]]


def _times_inverse_home(R, t, Hinv):
    """G = T M^-1 of a pose (R, t) and the inverse home pose's columns: its rotation
    (3 rows) and position."""
    (h00, h01, h02, h03), (h10, h11, h12, h13), (h20, h21, h22, h23) = Hinv[:3]
    RG, tG = [], []
    for (r0, r1, r2), ti in zip(R, t):
        RG.append(
            (
                r0 * h00 + r1 * h10 + r2 * h20,
                r0 * h01 + r1 * h11 + r2 * h21,
                r0 * h02 + r1 * h12 + r2 * h22,
            )
        )
        tG.append(r0 * h03 + r1 * h13 + r2 * h23 + ti)
    return RG, tG


def _apply(R, x):
    (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) = R
    x0, x1, x2 = x
    return (
        a0 * x0 + a1 * x1 + a2 * x2,
        b0 * x0 + b1 * x1 + b2 * x2,
        c0 * x0 + c1 * x1 + c2 * x2,
    )


def _vector(array):
    return tuple(float(x) for x in array)


# ---- a spherical wrist, joints 2 and 3 parallel (SphericalWristArm) ------------------


def _wrist_constants(arm):
    """The arm's constant vectors and numbers, computed once (floats)."""
    w, p, c = arm.w, arm.p, arm.c
    Hinv = np.linalg.inv(arm.home)
    a1, a2, w4, w5, w6 = (_vector(w[i]) for i in (0, 1, 3, 4, 5))
    u3 = c - p[2] - w[1] * (w[1] @ (c - p[2]))
    v3 = p[1] - p[2] - w[1] * (w[1] @ (p[1] - p[2]))
    lu, lv = np.linalg.norm(u3), np.linalg.norm(v3)
    x6 = np.cross(w[4], w[5])
    x6 = x6 / np.linalg.norm(x6)
    n45, n56 = np.cross(w[3], w[4]), np.cross(w[4], w[5])
    e = p[2] - p[1] - w[1] * (w[1] @ (p[2] - p[1]))
    k0 = p[2] - p[1] + w[1] * (w[1] @ (c - p[2]))
    w6x6 = np.cross(w[5], x6)
    fs = [x6, np.cross(w[4], x6), w6x6, np.cross(w[4], w6x6), w[4]]  # joint 6's
    fs = [_vector(f) for f in fs]
    return dict(
        a1=a1,
        a2=a2,
        a1a2=float(w[0] @ w[1]),
        n21=_vector(np.cross(w[1], w[0])),
        h=float(w[1] @ (c - p[0])),
        centre=_vector(Hinv[:3, :3] @ c + Hinv[:3, 3]),  # c in the home's frame
        p0=_vector(p[0]),
        p01=_vector(p[0] - p[1]),
        s3=1.0 if w[1] @ w[2] > 0 else -1.0,
        offset2=float((w[1] @ (c - p[1])) ** 2),
        lu2v2=float(lu**2 + lv**2),
        lulv2=float(2 * lu * lv),
        theta0=float(np.arctan2(np.cross(u3, v3) @ w[1], u3 @ v3)),
        k=(_vector(k0), _vector(u3), _vector(np.cross(w[1], u3))),
        k0a2=float(k0 @ w[1]),
        e=_vector(e),
        a2e=_vector(np.cross(w[1], e)),
        g6=_vector(Hinv[:3, :3] @ w[5]),  # RG w6 = R_T (Rh^T w6)
        gx6=_vector(Hinv[:3, :3] @ x6),
        w4=w4,
        w5=w5,
        w6=w6,
        c45=float(w[3] @ w[4]),
        c46=float(w[3] @ w[5]),
        c56=float(w[4] @ w[5]),
        n45=_vector(n45),
        m45=_vector(np.cross(w[3], n45)),
        nn45=float(n45 @ n45),
        norm45=float(np.linalg.norm(n45)),
        n56=_vector(n56),
        w4n56=float(w[3] @ n56),
        n45n56=float(n45 @ n56),
        n45w6=float(n45 @ w[5]),
        fs=fs,
        w4fs=[_vector(np.cross(w[3], f)) for f in fs],
        w4f=[float(w[3] @ f) for f in fs],
        w5x6=float(w[4] @ x6),
        w5w6x6=float(w[4] @ fs[2]),
        scale=float(arm.scale),
    )


def _constants(arm, build):
    found = arm.__dict__.get("_one_pose")
    if found is None:
        found = build(arm)
        object.__setattr__(arm, "_one_pose", found)  # a frozen dataclass: cached once
    return found


def solve_wrist(arm, T):
    """:meth:`SphericalWristArm._solve` of one checked pose T (4, 4): Q (8, 6) as
    lists, flags (8, 3) as tuples of bool, the reason code."""
    k = _constants(arm, _wrist_constants)
    R, t = _rows(T)
    centre = _apply(R, k["centre"])
    p0 = k["p0"]
    d = (centre[0] + t[0] - p0[0], centre[1] + t[1] - p0[1], centre[2] + t[2] - p0[2])
    # joint 1: subproblem 4 (plane_angles and sinusoid_angles)
    a1, a2, scale = k["a1"], k["a2"], k["scale"]
    A, B, C = _joint_one(d, a1, a2, k["n21"], k["a1a2"], k["h"])
    radius2 = A**2 + B**2
    thetas, _, excess = _roots(A, B, C)
    shoulder_ok = excess >= -IK_CLIP_TOL * scale**2
    forward = math.sqrt(max(excess, 0.0))
    if radius2 < (IK_CLIP_TOL * scale) ** 2:  # the wrist centre on axis 1: q1 free
        thetas = (0.0, 0.0)
    p01 = k["p01"]
    g6, gx6 = _apply(R, k["g6"]), _apply(R, k["gx6"])
    rows, flags = [], []
    elbow_any = False
    shoulder_flag = forward**2 < IK_SINGULAR_TOL * scale**2
    for sigma, theta in ((-1.0, thetas[0]), (1.0, thetas[1])):  # the arm l, r
        ct, st = math.cos(theta), math.sin(theta)
        b = _turn(a1, d, ct, st)
        b1 = (b[0] + p01[0], b[1] + p01[1], b[2] + p01[2])
        q1 = _wrap(-theta)
        # joint 3: subproblem 3
        delta2 = (b1[0] ** 2 + b1[1] ** 2 + b1[2] ** 2) - k["offset2"]
        cosine = (k["lu2v2"] - delta2) / k["lulv2"]
        elbow_ok = abs(cosine) <= 1 + IK_CLIP_TOL
        elbow_any = elbow_any or elbow_ok
        cosine = min(max(cosine, -1.0), 1.0)
        beta = math.acos(cosine)
        s3 = k["s3"]
        theta0 = s3 * k["theta0"]
        elbows = []
        m = _cross(a2, b1)
        (x0, x1, x2), (m0, m1, m2) = b1, m
        dots = [v0 * x0 + v1 * x1 + v2 * x2 for v0, v1, v2 in k["k"]]
        crosses = [-(v0 * m0 + v1 * m1 + v2 * m2) for v0, v1, v2 in k["k"]]
        along2 = _dot(a2, b1) * k["k0a2"]
        em, a2em = _dot(k["e"], m), _dot(k["a2e"], m)
        for q3 in (theta0 + s3 * -beta, theta0 + s3 * beta):
            c3, s3q = math.cos(s3 * q3), math.sin(s3 * q3)
            q2, c2, s2 = _polar(
                crosses[0] + c3 * crosses[1] + s3q * crosses[2],
                dots[0] + c3 * dots[1] + s3q * dots[2] - along2,
            )
            elbows.append((q2, c2, s2, q3, c3, s3q, c2 * em + s2 * a2em))
        if sigma * elbows[0][6] < sigma * elbows[1][6]:
            elbows.reverse()  # u first, then d
        elbow_flag = 1 - abs(cosine) < IK_SINGULAR_TOL
        turned = [_turn(a1, g, ct, st) for g in (g6, gx6)]
        for q2, c2, s2, q3, c3, s3q, _ in elbows:
            c23, s23 = c2 * c3 - s2 * s3q, s2 * c3 + c2 * s3q
            t6, b = (_turn(a2, g, c23, -s23) for g in turned)
            wrists, wrist_ok, wrist_flag = _wrist(k, t6, b)
            reached = shoulder_ok and elbow_ok and wrist_ok
            for q4, q5, q6 in wrists:
                rows.append([q1, q2, _wrap(q3), q4, q5, q6] if reached else _NAN_ROW)
                flags.append((shoulder_flag, elbow_flag, wrist_flag))
    if not shoulder_ok:
        code = 1
    elif not elbow_any:
        code = 2
    else:
        code = 0 if any(row is not _NAN_ROW for row in rows) else 3
    return rows, flags, code


def _wrist(k, t, b):
    """Joints 4, 5 (subproblem 2) and 6 (subproblem 1) of one arm and elbow: the two
    (q4, q5, q6), n and f, whether real, and the wrist's singularity flag."""
    w4, w5, w6, c45, c56 = k["w4"], k["w5"], k["w6"], k["c45"], k["c56"]
    t4, t5, tn, tm = _dot(w4, t), _dot(w5, t), _dot(k["n45"], t), _dot(k["m45"], t)
    a = (c45 * c56 - t4) / (c45**2 - 1)
    bb = (c45 * t4 - c56) / (c45**2 - 1)
    gamma2 = (tn**2 + tm**2) / k["nn45"] ** 2 - bb**2
    sine46 = math.sqrt(tn**2 + tm**2) / math.sqrt(k["nn45"])
    ok = gamma2 >= -IK_CLIP_TOL
    root = math.sqrt(max(gamma2, 0.0))
    flag = root * k["norm45"] < IK_SINGULAR_TOL
    singular = sine46 <= WRIST_TOL
    if singular:
        free5 = _polar(_dot(k["n56"], t), _dot(w6, t) - c56 * t5)
    # joint 6: b . R4 f for the fixed f of "fs" is fb c4 + kb s4 + (w4 . b)(w4 . f)
    # (1 - c4), with fb = f . b and kb = (w4 x f) . b computed once per arm and elbow
    b0, b1, b2 = b
    w4b = _dot(w4, b)
    fb = [f0 * b0 + f1 * b1 + f2 * b2 for f0, f1, f2 in k["fs"]]
    kb = [f0 * b0 + f1 * b1 + f2 * b2 for f0, f1, f2 in k["w4fs"]]
    w4f, w5x6, w5w6x6 = k["w4f"], k["w5x6"], k["w5w6x6"]
    out = []
    for gamma, q4_free, c4_free in (
        (root * 1.0, math.pi, -1.0),
        (root * -1.0, 0.0, 1.0),
    ):
        if singular:
            (q5, c5, s5), (q4, c4, s4) = free5, (q4_free, c4_free, 0.0)
        else:
            q5, c5, s5 = _polar(
                a * k["w4n56"] + gamma * k["n45n56"],
                a * (k["c46"] - c45 * c56) + gamma * k["n45w6"],
            )
            q4, c4, s4 = _polar(bb * tn + gamma * tm, bb * (t5 - c45 * t4) + gamma * tn)
        # b . R4 f for f = x6, w5 x x6, w6 x x6, w5 x (w6 x x6), w5
        c4_ = 1 - c4
        x = fb[0] * c4 + kb[0] * s4 + w4b * w4f[0] * c4_
        y = fb[1] * c4 + kb[1] * s4 + w4b * w4f[1] * c4_
        z = fb[2] * c4 + kb[2] * s4 + w4b * w4f[2] * c4_
        u = fb[3] * c4 + kb[3] * s4 + w4b * w4f[3] * c4_
        v = fb[4] * c4 + kb[4] * s4 + w4b * w4f[4] * c4_
        along_x6 = x * c5 + y * s5 + v * w5x6 * (1 - c5)
        along_w6x6 = z * c5 + u * s5 + v * w5w6x6 * (1 - c5)
        out.append((q4, q5, math.atan2(along_w6x6, along_x6)))
    return out, ok, flag


# ---- UR-type: joints 2, 3, 4 parallel, axes 5 and 6 meeting (URArm) ------------------


def _fixed_parts(w, v):
    """The parts of a fixed vector v for turning it about w (:meth:`._closed_form.Turn.
    fixed`): its part across w, w x v and its part along w."""
    along = _dot(v, w)
    v_along = (w[0] * along, w[1] * along, w[2] * along)
    return (_sub(v, v_along), _cross(w, v), v_along)


def _fixed(parts, c, s):
    """The fixed vector of ``parts`` turned by the angle of cosine c and sine s:
    (v - w (v . w)) c + (w x v) s + w (v . w)."""
    (a0, a1, a2), (k0, k1, k2), (b0, b1, b2) = parts
    return (a0 * c + k0 * s + b0, a1 * c + k1 * s + b1, a2 * c + k2 * s + b2)


def _between(w, a, b):
    """Subproblem 1 (:func:`.subproblems.rotation_angles`): the angle about w from a
    to b, their parts across w."""
    w0, w1, w2 = w
    a0, a1, a2 = a
    b0, b1, b2 = b
    aw, bw = a0 * w0 + a1 * w1 + a2 * w2, b0 * w0 + b1 * w1 + b2 * w2
    a0, a1, a2 = a0 - w0 * aw, a1 - w1 * aw, a2 - w2 * aw
    b0, b1, b2 = b0 - w0 * bw, b1 - w1 * bw, b2 - w2 * bw
    return math.atan2(
        (a1 * b2 - a2 * b1) * w0 + (a2 * b0 - a0 * b2) * w1 + (a0 * b1 - a1 * b0) * w2,
        a0 * b0 + a1 * b1 + a2 * b2,
    )


def _joint_one(d, axis, across, normal, cosine, offset):
    """Joint 1's equation A cos + B sin = C (subproblem 4; the three floats), for
    the point d (3 floats) that axis 1 (unit ``axis``) turns: the components of d
    along ``across`` and ``normal`` (its cross product with the axis) with their
    part along the axis taken off (``cosine`` the two axes' cosine), ``offset`` the
    component the point must have."""
    along = _dot(axis, d)
    return _dot(across, d) - along * cosine, _dot(normal, d), offset - along * cosine


def _roots(A, B, C):
    """The two angles of A cos + B sin = C, whether real, and the excess
    (``ur._roots``)."""
    radius2 = A**2 + B**2
    excess = radius2 - C**2
    phi = math.atan2(B, A)
    half = math.atan2(math.sqrt(max(excess, 0.0)), C)
    return [phi - half, phi + half], excess >= -IK_CLIP_TOL * radius2, excess


def _add(a, b):
    a0, a1, a2 = a
    b0, b1, b2 = b
    return (a0 + b0, a1 + b1, a2 + b2)


def _sub(a, b):
    a0, a1, a2 = a
    b0, b1, b2 = b
    return (a0 - b0, a1 - b1, a2 - b2)


def _ur_constants(arm):
    w, p, c = arm.w, arm.p, arm.c
    u = w[1]
    x = np.cross(u, w[0])
    x = x / np.linalg.norm(x)

    def across(v):
        return v - u * (v @ u)

    r2, r3 = across(p[2] - p[1]), across(p[3] - p[2])
    s3 = float(np.sign(w[2] @ u))
    return dict(
        w=[_vector(v) for v in w],
        p=[_vector(v) for v in p],
        c=_vector(c),
        Hinv=np.linalg.inv(arm.home).tolist(),
        h=float(u @ (c - p[0])),
        w1u=float(w[0] @ u),
        uw1=_vector(np.cross(u, w[0])),
        w1u_cross=_vector(np.cross(w[0], u)),
        A5=float(u @ w[5] - (w[4] @ w[5]) * (u @ w[4])),
        B5=float(u @ np.cross(w[4], w[5])),
        c56u5=float((w[4] @ w[5]) * (u @ w[4])),
        w6n54=float(w[5] @ np.cross(w[4], w[3])),
        w56n54=float(np.cross(w[4], w[5]) @ np.cross(w[4], w[3])),
        x=_vector(x),
        r2=_vector(r2),
        r3=_vector(r3),
        A3=float(r2 @ r3),
        B3=float(r2 @ np.cross(s3 * u, r3)),
        r2r3=(float(r2 @ r2), float(r3 @ r3)),
        s3=s3,
        s4=float(np.sign(w[3] @ u)),
        p43=_vector(p[3] - p[4]),
        **{
            "u about w1": _fixed_parts(_vector(w[0]), _vector(u)),
            "u about w5": _fixed_parts(_vector(w[4]), _vector(u)),
            "p43 about w5": _fixed_parts(_vector(w[4]), _vector(p[3] - p[4])),
            "x about w5": _fixed_parts(_vector(w[4]), _vector(x)),
            "r3 about w3": _fixed_parts(_vector(w[2]), _vector(r3)),
        },
        scale=float(arm.scale),
    )


def solve_ur(arm, T):
    """:meth:`URArm._solve` of one checked pose T (4, 4): Q (8, 6) as lists, flags
    (8, 3) as tuples of bool, the reason code."""
    k = _constants(arm, _ur_constants)
    w, p, scale = k["w"], k["p"], k["scale"]
    u, w1, w6 = w[1], w[0], w[5]
    R, t = _rows(T)
    RG, tG = _times_inverse_home(R, t, k["Hinv"])
    RGt = list(zip(*RG))
    # joint 1
    d = _sub(_add(_apply(RG, k["c"]), tG), p[0])
    A, B, C = _joint_one(d, w1, u, k["uw1"], k["w1u"], k["h"])
    radius1 = A**2 + B**2
    thetas, shoulder_ok, excess1 = _roots(A, B, C)
    if radius1 < (IK_CLIP_TOL * scale) ** 2:
        thetas = [0.0, 0.0]
    arms = []
    for theta in thetas:
        ct, st = math.cos(theta), math.sin(theta)
        x1 = _add(p[0], _turn(w1, d, ct, st))
        arms.append((_dot(_sub(x1, p[0]), k["w1u_cross"]), theta, ct, st))
    if arms[1][0] < arms[0][0]:
        arms.reverse()  # l first, then r
    g6 = _apply(RG, w6)
    p0, p4, p5, r2 = p[0], p[4], p[5], k["r2"]
    p43_w5, x_w5, r3_w3 = k["p43 about w5"], k["x about w5"], k["r3 about w3"]
    (r22, r33), A3, B3, s3, s4 = k["r2r3"], k["A3"], k["B3"], k["s3"], k["s4"]
    elbow_scale = IK_SINGULAR_TOL * (A3**2 + B3**2)
    out, flags, wrist_any = [None] * 8, [None] * 8, False
    shoulder_flag = abs(excess1) < IK_SINGULAR_TOL * radius1
    for arm_index, (_, theta, ct, st) in enumerate(arms):
        sigma = -1.0 if arm_index == 0 else 1.0
        q1 = _wrap(-theta)
        # joint 5
        C5 = _dot(_turn(w1, g6, ct, st), u) - k["c56u5"]
        q5s, wrist_ok, _ = _roots(k["A5"], k["B5"], C5)
        wrist_any = wrist_any or wrist_ok
        flip = [math.cos(q) * k["w6n54"] + math.sin(q) * k["w56n54"] for q in q5s]
        if flip[1] < flip[0]:
            q5s.reverse()  # n first, then f
        R1u = _fixed(k["u about w1"], ct, -st)
        a = _apply(RGt, R1u)
        aw6 = _dot(a, w6)
        a_perp = (a[0] - w6[0] * aw6, a[1] - w6[1] * aw6, a[2] - w6[2] * aw6)
        perp2 = a_perp[0] ** 2 + a_perp[1] ** 2 + a_perp[2] ** 2
        on_axis = perp2 < IK_CLIP_TOL**2
        wrist_flag = on_axis or perp2 < IK_SINGULAR_TOL
        for wrist_index, q5 in enumerate(q5s):
            c5, s5 = math.cos(q5), math.sin(q5)
            b = _fixed(k["u about w5"], c5, -s5)
            q6 = 0.0 if on_axis else _between(w6, a, b)
            c6, s6 = math.cos(q6), math.sin(q6)
            # joints 2-4
            y = _add(p4, _fixed(p43_w5, c5, -s5))
            z = _add(p5, _turn(w6, _sub(y, p5), c6, -s6))
            g = _add(_apply(RG, z), tG)
            P = _add(p0, _turn(w1, _sub(g, p0), ct, st))
            rx = _turn(w6, _fixed(x_w5, c5, -s5), c6, -s6)
            rx = _turn(w1, _apply(RG, rx), ct, st)
            phi4 = _between(u, k["x"], rx)
            v = _sub(P, p[1])
            vu = _dot(v, u)
            ys = (v[0] - u[0] * vu, v[1] - u[1] * vu, v[2] - u[2] * vu)
            delta2 = ys[0] ** 2 + ys[1] ** 2 + ys[2] ** 2
            C3 = (delta2 - r22 - r33) / 2
            q3s, elbow_ok, excess3 = _roots(A3, B3, C3)
            elbows = []
            ys_r2_u, ys_r2 = _dot(_cross(ys, r2), u), _dot(ys, r2)
            for q3 in q3s:
                xs = _add(r2, _fixed(r3_w3, math.cos(q3), math.sin(q3)))
                q2 = _between(u, xs, ys)
                above = math.cos(q2) * ys_r2_u + math.sin(q2) * ys_r2
                elbows.append((-sigma * above, q2, q3))
            if elbows[1][0] < elbows[0][0]:
                elbows.reverse()  # u first, then d
            reached = shoulder_ok and wrist_ok and elbow_ok
            elbow_flag = abs(excess3) < elbow_scale
            for elbow_index, (_, q2, q3) in enumerate(elbows):
                q4 = s4 * (phi4 - q2 - s3 * q3)
                row = [q1, _wrap(q2), _wrap(q3), _wrap(q4), _wrap(q5), _wrap(q6)]
                index = 4 * arm_index + 2 * elbow_index + wrist_index
                out[index] = row if reached else _NAN_ROW
                flags[index] = (shoulder_flag, elbow_flag, wrist_flag)
    if not shoulder_ok:
        code = 1
    elif all(row is _NAN_ROW for row in out):
        code = 2 if wrist_any else 3
    else:
        code = 0
    return out, flags, code


# ---- the answer's numbers: limits and residuals of one solution ----------------------


def into_limits(q, limits, slack):
    """One solution q (6 floats) with each angle moved by a multiple of 2 pi into its
    limits (the candidate nearest to q of q + 2 pi k, k = -3 ... 3; the first of a
    tie), and whether every angle could be moved there (if not, q itself: the moves
    are not used): the arithmetic of ``dispatch._into_limits`` on floats (revolute
    joints)."""
    for x, (low, high) in zip(q, limits):
        if not low <= x <= high:
            break
    else:
        return q, True  # all within their limits already
    moved = list(q)
    for j, (x, (low, high)) in enumerate(zip(q, limits)):
        if low <= x <= high:
            continue
        low, high = low - slack, high + slack
        if low <= x <= high:  # k = 0 fits within the slack
            continue
        # the smallest whole turn k that fits wins (their distances 2 pi k apart);
        # of -k and k both fitting, the nearer one in floats, -k on a tie
        for step in _STEPS:
            below, above = x - step, x + step
            fits_below, fits_above = low <= below <= high, low <= above <= high
            if fits_below and fits_above:
                nearer = abs(above - x) < abs(below - x)
                moved[j] = above if nearer else below
                break
            if fits_below or fits_above:
                moved[j] = below if fits_below else above
                break
        else:
            return q, False  # this angle cannot be moved there: the moves unused
    return moved, True


#: The whole turns tried besides none, 2 pi k for k = 1, 2, 3 (each also as -k).
_STEPS = tuple(2 * math.pi * turn for turn in range(1, 4))


def residual(entries, target, scale):
    """The pose residual (:func:`._closed_form.pose_residual`) of one solution: the
    largest entry of the rotation's difference and of the position's divided by
    ``scale``, from the 12 entries of the chain's pose at q and of the target's top
    rows."""
    a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11 = entries
    b0, b1, b2, b3, b4, b5, b6, b7, b8, b9, b10, b11 = target
    rotation = max(
        abs(a0 - b0), abs(a1 - b1), abs(a2 - b2), abs(a4 - b4), abs(a5 - b5),
        abs(a6 - b6), abs(a8 - b8), abs(a9 - b9), abs(a10 - b10),
    )  # fmt: skip
    return max(rotation, max(abs(a3 - b3), abs(a7 - b7), abs(a11 - b11)) / scale)
