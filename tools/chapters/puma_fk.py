"""Source of notebooks/puma_fk.ipynb: python tools/chapters/puma_fk.py"""
from _nb import code, md, write

cells = [
md(r"""
# The PUMA 560: Denavit–Hartenberg and forward kinematics

The PUMA 560 (Unimation, 1978) is the arm on which a generation learned kinematics: six revolute
joints, a shoulder offset and a spherical wrist. This chapter follows Surriani, Arrofiq and
Fahmizal (2018) {cite}`surriani2018puma`, who model it with Corke's DH parameters and compute its
pose in four named configurations. We derive every matrix of the paper with SymPy, compare them
term by term, and find where the printed equations and matrices are wrong, and why.

**What you will learn:** the standard DH convention and its modified (Craig) variant; link
transforms; the symbolic pose in the textbook's $c_1, s_{23}$ notation; what the four named poses
look like; the same pose by a product of exponentials of joint screws.
"""),
code("""
import numpy as np
import sympy as sp
import matplotlib.pyplot as plt
import screwkit as sk

np.set_printoptions(precision=4, suppress=True)
puma = sk.robots.puma560()
puma
"""),
md(r"""
## The DH convention

Each link $i$ carries a frame $\{i\}$. In **standard DH** the frame of link $i$ is reached from
$\{i-1\}$ by four elementary motions,

$$
{}^{i-1}A_i = R_z(\theta_i)\,T_z(d_i)\,T_x(a_i)\,R_x(\alpha_i)
= \begin{bmatrix}
c_{\theta_i} & -s_{\theta_i} c_{\alpha_i} & s_{\theta_i} s_{\alpha_i} & a_i c_{\theta_i}\\
s_{\theta_i} & c_{\theta_i} c_{\alpha_i} & -c_{\theta_i} s_{\alpha_i} & a_i s_{\theta_i}\\
0 & s_{\alpha_i} & c_{\alpha_i} & d_i\\
0 & 0 & 0 & 1\end{bmatrix},
$$

so joint $i$ turns about $z_{i-1}$ (the paper's eq. 7). **Modified DH** (Craig) puts the
joint on $z_i$ instead: ${}^{i-1}A_i = R_x(\alpha_{i-1})\,T_x(a_{i-1})\,R_z(\theta_i)\,T_z(d_i)$.
screwkit does both (`sk.Convention.STANDARD`, the default, and `sk.Convention.MODIFIED`); the tests
check that a chain and its modified-DH rewrite give the same pose.

The paper's Table 2 is Corke's model. screwkit's `puma560()` is the same table, with the paper's
$d_1 = 0$ (frame 0 on the shoulder axis, no pedestal) and Corke's $d_3 = 0.15005$ m, which the
table rounds to 0.15:
"""),
code("""
print(f"{'joint':>5} {'theta':>6} {'d (m)':>8} {'a (m)':>8} {'alpha':>7} {'limits (deg)':>14}")
for i, link in enumerate(puma.links, start=1):
    low, high = np.degrees(link.qlim)
    print(f"{i:>5} {'q' + str(i):>6} {float(link.d):>8.5f} {float(link.a):>8.4f} "
          f"{float(link.alpha):>7.4f} {low:>6.0f}..{high:<6.0f}")
"""),
md(r"""
The frames of the table, drawn at $q = 0$ (x red, y green, z blue; joint $i$ turns about the blue
$z$ axis of frame $i-1$, marked by a black segment). Frames 4, 5 and 6 share the wrist centre,
and frames 0 and 1 the shoulder:
"""),
code("""
# NBVAL_IGNORE_OUTPUT
ax = sk.plotting.axes3d(((-0.2, 0.6), (-0.4, 0.4), (-0.2, 0.6)), figsize=(6, 6))
sk.plotting.draw_chain(ax, puma, np.zeros(6), frames=True, frame_length=0.1)
ax.view_init(elev=25, azim=-55)
ax.set_title("PUMA 560 at q = 0: the DH frames {0} ... {6}")
plt.show()
"""),
md(r"""
The joint limits are those of Corke's model (from Wang and Chen, 1991). The paper's Table 1 lists
other ranges, $q_2 \in [-245°, 45°]$ and $q_3 \in [-45°, 225°]$, taken from a source that uses
**Lee's** joint conventions rather than Paul's (see below: the two differ in the sign of every
twist, and the joints turn the other way). Negating Corke's ranges gives $q_2 \in [-225°, 45°]$
and $q_3 \in [-45°, 225°]$: the second matches Table 1, the first matches it if $-245$ is a
misprint of $-225$ (a range of 270°, as in Corke's model, rather than 290°). Joints 1, 4, 5 and 6
have the same ranges in both.

## The six link transforms (eqs. 8-13)
"""),
code("""
A = puma.link_transforms()
for i, Ai in enumerate(A, start=1):
    print(f"A{i} =", sk.textbook(Ai).tolist())
"""),
md(r"""
Now the paper's printed matrices, transcribed as they stand (with $d_2$ where eq. 9 has it and
$d_6$ in eq. 13):
"""),
code("""
q1, q2, q3, q4, q5, q6 = puma.q_symbols
a2, a3, d2, d3, d4, d6 = sp.symbols("a2 a3 d2 d3 d4 d6", positive=True)
c = {i: sp.cos(q) for i, q in enumerate(puma.q_symbols, start=1)}
s = {i: sp.sin(q) for i, q in enumerate(puma.q_symbols, start=1)}
paper_A = [
    sp.Matrix([[c[1], 0, -s[1], 0], [s[1], 0, c[1], 0], [0, -1, 0, 0], [0, 0, 0, 1]]),
    sp.Matrix([[c[2], -s[2], 0, a2 * c[2]], [s[2], c[2], 0, a2 * s[2]], [0, 0, 1, d2], [0, 0, 0, 1]]),
    sp.Matrix([[c[3], 0, s[3], a3 * c[3]], [s[3], 0, -c[3], a3 * s[3]], [0, 1, 0, 0], [0, 0, 0, 1]]),
    sp.Matrix([[c[4], 0, -s[4], 0], [s[4], 0, c[4], 0], [0, -1, 0, d4], [0, 0, 0, 1]]),
    sp.Matrix([[c[5], 0, s[5], 0], [s[5], 0, -c[5], 0], [0, 1, 0, 0], [0, 0, 0, 1]]),
    sp.Matrix([[c[6], -s[6], 0, 0], [s[6], c[6], 0, 0], [0, 0, 1, d6], [0, 0, 0, 1]]),
]
"""),
md(r"""
Compare them with the link transforms of two tables: Table 2 as printed ($\alpha = 90°, 0, -90°,
90°, -90°, 0$) and the same table with **every twist negated**, the offset on link 2 and $d_6$
on link 6 as the equations have them:
"""),
code("""
pi = sp.pi
def symbolic_puma(alphas, offset_link, d6_symbol=d6):
    d = [0, 0, 0, d4, 0, d6_symbol]
    d[offset_link] = d2 if offset_link == 1 else d3
    a = [0, a2, a3, 0, 0, 0]
    return sk.Chain([sk.Link.revolute(d=d[i], a=a[i], alpha=alphas[i]) for i in range(6)])

table2 = symbolic_puma([pi / 2, 0, -pi / 2, pi / 2, -pi / 2, 0], offset_link=2)
negated = symbolic_puma([-pi / 2, 0, pi / 2, -pi / 2, pi / 2, 0], offset_link=1)

print(f"{'eq.':>4} {'matrix':>6}  equals Table 2's   equals negated twists")
for i, (mine, theirs, paper) in enumerate(zip(table2.link_transforms(), negated.link_transforms(), paper_A)):
    same = lambda M: (M - paper).subs(d3, d2).expand() == sp.zeros(4)
    print(f"{i + 8:>4} {'A' + str(i + 1):>6}  {str(same(mine)):<18}{same(theirs)}")
"""),
md(r"""
Every printed link matrix follows the **negated** twists: eqs. 8-13 were written for Lee's
convention (Fu, Gonzalez and Lee's textbook), while Table 2, the joint values and the poses of
eqs. 32-35 are Corke's, who (his model's comments say) uses Paul's twists, "the negative of
Lee's values, which means the zero angle position is a righty for Paul, and lefty for Lee".
The shoulder offset is $d_3$ in the table and $d_2$ in eq. 9; since $\alpha_2 = 0$, $z_1$ and
$z_2$ are parallel and the two placements give the same pose.

What is the relation between the two arms? Negating every twist mirrors the arm in its
$x$-$z$ plane and turns every joint the other way: with $S = \mathrm{diag}(1, -1, 1)$,
$T_\text{negated}(q) = S\,T_\text{Table 2}(-q)\,S$. SymPy confirms it exactly:
"""),
code("""
S = sp.diag(1, -1, 1, 1)
mirror = S * table2.fk_symbolic().subs({q: -q for q in puma.q_symbols}).subs(d3, d2) * S
print((mirror - negated.fk_symbolic()).applyfunc(sp.simplify) == sp.zeros(4))
"""),
md(r"""
## The pose, symbolically (eqs. 14-31)

`fk_symbolic()` multiplies the link transforms exactly and combines sums of angles after each
link ($c_2 c_3 - s_2 s_3 \to c_{23}$), which takes a fraction of a second. `sk.textbook` writes the
result in the book's notation. The arm, ${}^0T_3$ (eq. 15), for Table 2:
"""),
code("""
T03 = puma.fk_symbolic(symbolic_lengths=True, upto=3)
sk.textbook(T03)
"""),
md(r"""
and the wrist, ${}^3T_6 = A_4 A_5 A_6$ (eq. 17, here without $d_6$, which is zero for the
PUMA):
"""),
code("""
T36 = sp.simplify(A[3] * A[4] * A[5]).subs(0.4318, d4)
sk.textbook(T36)
"""),
md(r"""
The wrist of Table 2 is $R_z(q_4)\,R_y(-q_5)\,R_z(q_6)$: Z-Y-Z Euler angles with $q_5$ negated.
The paper's eq. 17, $R_z(q_4)R_y(q_5)R_z(q_6)$ with entry (2,2) printed as $-s_4c_5s_6 - c_4c_6$,
again follows the negated twists, with one sign wrong: it must be $-s_4c_5s_6 + c_4c_6$ (at
$q = 0$ the printed entry gives $-1$ on the diagonal of a rotation that should be the identity).

In eq. 15, two entries are wrong for either convention: ${}^0o_y$ ends with $-d_2 c_1$ where
$+d_2 c_1$ is right for the equations' own convention (and $-d_3 c_1$ for Table 2, as above), and
${}^0o_z = -a_2 s_2 - a_2 s_{23}$ has $a_2$ where $a_3$ belongs.

Now the full pose, entry by entry: the paper's eqs. 20-31 as printed, against both models.
"""),
code("""
c23, s23 = sp.cos(q2 + q3), sp.sin(q2 + q3)
C, Sn = c, s
paper_T = {
    "r11": C[1]*(c23*(C[4]*C[5]*C[6] - Sn[4]*Sn[6]) - s23*Sn[5]*C[6]) - Sn[1]*(Sn[4]*C[5]*C[6] + C[4]*Sn[6]),
    "r21": Sn[1]*(c23*(C[4]*C[5]*C[6] - Sn[4]*Sn[6]) - s23*Sn[5]*C[6]) + C[1]*(Sn[4]*C[5]*C[6] + C[4]*Sn[6]),
    "r31": -s23 - (C[4]*C[5]*C[6] - Sn[4]*Sn[6]) - c23*Sn[5]*C[6],
    "r12": C[1]*(-c23*(C[4]*C[5]*Sn[6] + Sn[4]*Sn[6]) + s23*Sn[5]*Sn[6]) - Sn[1]*(-Sn[4]*C[5]*Sn[6] + C[4]*Sn[6]),
    "r22": Sn[1]*(-c23*(C[4]*C[5]*Sn[6] + Sn[4]*Sn[6]) + s23*Sn[5]*Sn[6]) + C[1]*(-Sn[4]*C[5]*Sn[6] + C[4]*Sn[6]),
    "r32": s23*(C[4]*C[5]*Sn[6] + Sn[4]*C[6]) + c23*Sn[5]*Sn[6],
    "r13": C[1]*(c23*C[4]*Sn[5] + s23*C[5]) - Sn[1]*Sn[4]*Sn[5],
    "r23": Sn[1]*(c23*C[4]*Sn[5] + s23*C[5]) + C[1]*Sn[4]*Sn[5],
    "r33": -s23*C[4]*Sn[5] + c23*C[5],
    "ox": C[1]*(d6*(c23*C[4]*Sn[5] + s23*C[5]) + s23*d4 + a3*c23 + a3*C[2]) - Sn[1]*(d6*Sn[4]*Sn[5] + d2),
    "oy": Sn[1]*(d6*(c23*C[4]*Sn[5] + s23*C[5]) + s23*d4 + a3*c23 + a3*C[2]) - C[1]*(d6*Sn[4]*Sn[5] + d2),
    "oz": d6*(c23*C[5] - s23*C[4]*Sn[5]) + c23*d4 - a3*s23 - a2*Sn[2],
}
where = {"r11": (0, 0), "r21": (1, 0), "r31": (2, 0), "r12": (0, 1), "r22": (1, 1), "r32": (2, 1),
         "r13": (0, 2), "r23": (1, 2), "r33": (2, 2), "ox": (0, 3), "oy": (1, 3), "oz": (2, 3)}
T_table2 = table2.fk_symbolic().subs(d3, d2)
T_negated = negated.fk_symbolic()
agree = lambda e: sp.simplify(sp.expand_trig(e)) == 0
print(f"{'eq.':>4} {'entry':>6}  equals Table 2's   equals negated twists")
for k, (name, expr) in enumerate(paper_T.items()):
    i, j = where[name]
    print(f"{k + 20:>4} {name:>6}  {str(agree(expr - T_table2[i, j])):<18}{agree(expr - T_negated[i, j])}")
"""),
md(r"""
Seven of the twelve printed entries are right for the negated twists; five are not right for
either model. Reading each against the correct expression shows a typesetting slip in every case:

| eq. | printed | correct (negated twists) |
|---|---|---|
| 22 | $-s_{23} - (c_4c_5c_6 - s_4s_6) - c_{23}s_5c_6$ | $-s_{23}\,(c_4c_5c_6 - s_4s_6) - c_{23}s_5c_6$ |
| 23, 24 | $\ldots(c_4c_5s_6 + s_4 s_6)\ldots(-s_4c_5s_6 + c_4 s_6)$ | $\ldots(c_4c_5s_6 + s_4 c_6)\ldots(-s_4c_5s_6 + c_4 c_6)$ |
| 29 | $\ldots + a_3 c_{23} + a_3 c_2$ | $\ldots + a_3 c_{23} + a_2 c_2$ |
| 30 | $\ldots + a_3 c_2] - c_1(d_6 s_4 s_5 + d_2)$ | $\ldots + a_2 c_2] + c_1(d_6 s_4 s_5 + d_2)$ |

With these corrections all twelve entries agree exactly:
"""),
code("""
corrected = dict(paper_T)
corrected["r31"] = -s23*(C[4]*C[5]*C[6] - Sn[4]*Sn[6]) - c23*Sn[5]*C[6]
corrected["r12"] = C[1]*(-c23*(C[4]*C[5]*Sn[6] + Sn[4]*C[6]) + s23*Sn[5]*Sn[6]) - Sn[1]*(-Sn[4]*C[5]*Sn[6] + C[4]*C[6])
corrected["r22"] = Sn[1]*(-c23*(C[4]*C[5]*Sn[6] + Sn[4]*C[6]) + s23*Sn[5]*Sn[6]) + C[1]*(-Sn[4]*C[5]*Sn[6] + C[4]*C[6])
corrected["ox"] = C[1]*(d6*(c23*C[4]*Sn[5] + s23*C[5]) + s23*d4 + a3*c23 + a2*C[2]) - Sn[1]*(d6*Sn[4]*Sn[5] + d2)
corrected["oy"] = Sn[1]*(d6*(c23*C[4]*Sn[5] + s23*C[5]) + s23*d4 + a3*c23 + a2*C[2]) + C[1]*(d6*Sn[4]*Sn[5] + d2)
print(all(agree(expr - T_negated[where[name]]) for name, expr in corrected.items()))
"""),
md(r"""
And the pose of screwkit's model (Table 2, Corke's convention) in textbook notation; these are
the expressions behind every number below:
"""),
code("""
T06 = puma.fk_symbolic(symbolic_lengths=True)
sk.textbook(T06[:3, :])
"""),
md(r"""
## The four named poses (eqs. 32-35)

Corke's named configurations: *zero* (all joints 0, the arm an "L"), *ready* (arm straight up),
*stretch* (arm straight out along $x$) and *nominal* (a table-top picking pose). The paper's
*nominal* has $q_3 = -\pi$, as has the current Robotics Toolbox {cite}`corke2017rvc`; older versions used $+\pi$,
the same joint angle.
"""),
code("""
paper_poses = {  # eqs. 32-35 as printed
    "zero":    [[1, 0, 0, 0.4521], [0, 1, 0, -0.1500], [0, 0, 1, 0.4381]],
    "ready":   [[1, 0, 0, 0.0203], [0, 1, 0, -0.1500], [0, 0, 1, 0.8636]],
    "stretch": [[1, 0, 1, 0.8636], [0, 1, 0, -0.1501], [-1, 0, 0, -0.0203]],
    "nominal": [[1, 0, 1, 0.5963], [0, 1, 0, -0.1501], [-1, 0, 0, -0.01435]],
}
for name, q in puma.configurations.items():
    T = puma.fk(q)
    printed = np.array(paper_poses[name])
    print(f"{name}: q = {np.round(np.degrees(q), 1).tolist()} deg")
    for row, paper_row in zip(T[:3], printed):
        print("   ", " ".join(f"{v:8.5f}" for v in row), "   paper:", " ".join(f"{v:8.5f}" for v in paper_row))
    rotation_ok = np.allclose(printed[:, :3], T[:3, :3], atol=1e-9)
    print(f"    largest difference in position {np.max(np.abs(printed[:, 3] - T[:3, 3])):.5f} m, "
          f"rotation as printed {'agrees' if rotation_ok else 'DISAGREES'}")
"""),
md(r"""
The positions agree to the printed four digits, with one exception: in *zero*, the paper's
$z = 0.4381$ m swaps two digits of $d_4 = 0.4318$ m (the pose is the "L": the forearm points up
by $d_4$, and the wrist is at $x = a_2 + a_3 = 0.4521$, $y = -d_3$, $z = d_4$). The $y$ values
$-0.1500$ and $-0.1501$ are the same $-d_3 = -0.15005$ m rounded two ways.

The rotations of *stretch* and *nominal* are printed with a stray 1 in the corner: a matrix with
rows $(1, 0, 1)$ and $(-1, 0, 0)$ is not a rotation (its first row has length $\sqrt 2$). The tool
points along $x_0$ (third column) with its $x$ axis down, so $r_{11} = 0$.

The four poses in 3D (the black segments are the joint axes):
"""),
code("""
# NBVAL_IGNORE_OUTPUT
figure = plt.figure(figsize=(10, 9))
for k, (name, q) in enumerate(puma.configurations.items(), start=1):
    ax = sk.plotting.axes3d(((-0.3, 0.9), (-0.6, 0.6), (-0.3, 0.9)), ax=figure.add_subplot(2, 2, k, projection="3d"))
    sk.plotting.draw_chain(ax, puma, q, frames=False)
    sk.plotting.draw_frame(ax, np.eye(4), label="0", length=0.15, alpha=0.5)
    ax.set_title(f"{name}: {np.round(np.degrees(q)).astype(int).tolist()} deg")
    ax.view_init(elev=20, azim=-60)
plt.tight_layout()
plt.show()
"""),
md(r"""
Move the arm yourself (the sliders need a running kernel: open this chapter as a notebook). The
title gives the position of the tool.
"""),
code("""
# NBVAL_IGNORE_OUTPUT
sk.widgets.joint_sliders(puma, puma.configurations["nominal"],
                         limits=((-0.9, 0.9), (-0.9, 0.9), (-0.5, 1.0)))
"""),
md(r"""
## The same pose from screws: the product of exponentials

At $q = 0$ each joint is a screw of pitch 0 in the base frame, $\$_i = (z_i;\ p_i \times z_i)$
([angular; linear], as everywhere in this course), and the pose is

$$
T(q) = e^{[\$_1] q_1}\, e^{[\$_2] q_2} \cdots e^{[\$_6] q_6}\, M, \qquad M = T(0).
$$

No frames per link, no DH table: just six joint screws and a home pose.
"""),
code("""
print("joint screws at q = 0, rows (omega; v):")
print(puma.screw_axes())
print("home pose M:")
print(puma.home())
rng = np.random.default_rng(560)
Q = rng.uniform(-np.pi, np.pi, (1000, 6))
difference = max(np.abs(puma.fk_poe(q) - puma.fk(q)).max() for q in Q)
print(f"PoE equals DH to 1e-12 over 1000 random configurations: {difference < 1e-12}")
"""),
md(r"""
## Speed

`puma.fk` evaluates the exact product, compiled once by `sympy.lambdify` with common
subexpressions. One pose takes a few microseconds; a batch of 100,000 poses is one call. The
benchmark `benchmarks/bench_puma.py` times the same tasks with the Robotics Toolbox for Python
side by side (about 7 µs against 64 µs for one pose, 21 ms against 270 ms for 100,000 on this
project's machines).
"""),
code("""
# NBVAL_IGNORE_OUTPUT
%timeit puma.fk(Q[0])
Qbig = rng.uniform(-np.pi, np.pi, (100_000, 6))
%timeit puma.fk(Qbig)
"""),
md(r"""
## Exercises

1. Write the DH table of a planar two-link arm with lengths 1 m and 0.5 m and check with
   `sk.Chain.from_table` that the tool is at $(1 + 0.5\cos q_2,\ 0.5 \sin q_2)$ when $q_1 = 0$.
2. The *ready* pose puts the wrist centre straight above the shoulder. Which joint then cannot
   change the position of the wrist centre? (Look at the screw of joint 1.)
3. Show with SymPy that moving the shoulder offset from $d_3$ to $d_2$ does not change the pose.

````{dropdown} Solutions
1. `sk.Chain.from_table([[0, 0, 1, 0], [0, 0, 0.5, 0]]).fk([0, q2])` has translation
   $(1 + 0.5\cos q_2, 0.5\sin q_2, 0)$.
2. Joint 1: its axis is $z_0$, and in *ready* the wrist centre is at $(a_3, -d_3, a_2 + d_4)$, at
   distance $\sqrt{a_3^2 + d_3^2}$ from the axis, so joint 1 does move it, on a small circle. The
   **shoulder singularity** needs the wrist centre at distance exactly $d_3$ from $z_0$ (in the
   vertical plane through $z_0$ and the axis of joint 2), where joint 1 moves it along a line that joints 2 and 3
   can also produce; see the Jacobian chapter.
3. `symbolic_puma(alphas, offset_link=1).fk_symbolic()` and `offset_link=2` differ by nothing once
   $d_2 = d_3$: $A_2$ translates along $z_1$ and $A_3$ along $z_2$, and $z_1 = z_2$ because
   $\alpha_2 = 0$.
````
"""),
]

write(cells, "notebooks/puma_fk.ipynb")
