"""Source of notebooks/jacobians.ipynb: python tools/chapters/jacobians.py"""
from _nb import code, md, write

cells = [
md(r"""
# Jacobians and singularities

The forward kinematics says *where* the tool is; the Jacobian says how fast it moves when the
joints move, which forces the joints feel when the tool pushes, and where the arm loses a
direction of motion (a **singularity**). This chapter builds the Jacobian twice, from the DH
frames and from the joint screws, shows they are the same object seen from two points, factorises
the determinant of the PUMA 560's Jacobian into its shoulder, elbow and wrist singularities,
and measures how far a configuration is from them with Yoshikawa's manipulability
{cite}`yoshikawa1985manipulability`. The next chapter applies all of it to the Kawasaki CX210L
of the workspace paper {cite}`kawasaki2021workspace`.
"""),
code("""
import numpy as np
import sympy as sp
import matplotlib.pyplot as plt
from IPython.display import Math, display
import screwkit as sk
from screwkit import jacobians

np.set_printoptions(precision=4, suppress=True)
puma = sk.robots.puma560()
"""),
md(r"""
## The geometric Jacobian from the DH frames

Joint $i$ turns about the axis $z_{i-1}$ through the origin $o_{i-1}$ of frame $i-1$ (standard DH).
Turning it at the rate $\dot q_i$ spins everything after it at $\omega = z_{i-1}\dot q_i$, and the
end-effector point $p$ then moves at $\omega \times (p - o_{i-1})$. Adding the joints up,

$$
\begin{bmatrix} v \\ \omega \end{bmatrix} = J_g(q)\,\dot q, \qquad
J_g = \begin{bmatrix} z_0 \times (p - o_0) & \cdots & z_{n-1} \times (p - o_{n-1}) \\
z_0 & \cdots & z_{n-1}\end{bmatrix}
$$

(a prismatic joint contributes $(z_{i-1};\ 0)$). This is the **geometric Jacobian**, rows
$[v; \omega]$ in the base frame, as in Siciliano et al. {cite}`siciliano2009robotics` and Corke's
`jacob0` {cite}`corke2017rvc`. Everything in it comes from the frames of the FK chapter. For the
PUMA in the *nominal* pose:
"""),
code("""
q_nominal = puma.configurations["nominal"]
J = puma.geometric_jacobian(q_nominal)
print(J)
"""),
md(r"""
Is it right? Move each joint by $\pm h$ and difference the FK: the columns of $v$ are
$\partial p / \partial q_i$, those of $\omega$ come from $\dot R R^T = [\omega]_\times$
(`jacobians.numerical_jacobian`, a dozen lines worth reading). The test suite does this on random
configurations of every arm in the course; here once:
"""),
code("""
rng = np.random.default_rng(5)
worst = max(np.abs(puma.geometric_jacobian(q) - jacobians.numerical_jacobian(puma, q)).max()
            for q in rng.uniform(-np.pi, np.pi, (200, 6)))
print(f"geometric Jacobian = central differences of FK to 1e-9 on 200 random configurations: {worst < 1e-9}")
"""),
md(r"""
## The Jacobian as a set of joint twists

The screws chapter described an instantaneous motion by a **twist** $(\omega; v_O)$: the angular
velocity and the velocity of the body point that is passing through the origin $O$. Joint $i$
alone gives the twist $\dot q_i\,\$_i$ with $\$_i = (z_{i-1};\ o_{i-1}\times z_{i-1})$: a screw of
pitch 0 on the joint axis (pitch $\infty$, $(0; z_{i-1})$, for a prismatic joint). Twists add, so
the twist of the tool is $\sum_i \dot q_i \$_i$, and the matrix whose columns are the joint twists
in their *current* position is the **space Jacobian** $J_s$ {cite}`lynch2017modern`:

$$
\begin{bmatrix} \omega \\ v_O \end{bmatrix} = J_s(q)\,\dot q,\qquad J_s = [\,\$_1(q)\ \cdots\ \$_n(q)\,].
$$

At $q = 0$ its columns are the screw axes of the product of exponentials (FK chapter). The two
Jacobians carry the same information and differ in two ways: the block order, and the
**reference point**. $J_s$ reports the velocity of the body point at the base origin, $J_g$ that
of the end-effector point $p$; rigid-body kinematics relates them, $v_p = v_O + \omega\times p$:

$$
J_g = \begin{bmatrix} -[p]_\times & I \\ I & 0 \end{bmatrix} J_s .
$$

DH frames and screws meet here: the columns of $J_g$ are the joint screws, written at the tool.
"""),
code("""
Js = puma.space_jacobian(q_nominal)
p = puma.fk(q_nominal)[:3, 3]
change = np.block([[-sk.skew(p).astype(float), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])
print("space Jacobian (columns are the joint twists [omega; v_O]):")
print(Js)
print(f"J_g = [[-[p]x, I], [I, 0]] J_s at nominal: {np.allclose(change @ Js, J, atol=1e-12)}")
Q = rng.uniform(-np.pi, np.pi, (10_000, 6))
Jg_batch, Js_batch = puma.geometric_jacobian(Q), puma.space_jacobian(Q)
p_batch = puma.fk(Q)[:, :3, 3]
v_p = Js_batch[:, 3:] + np.cross(Js_batch[:, :3].swapaxes(1, 2), p_batch[:, None]).swapaxes(1, 2)
print(f"... and on 10,000 random configurations (batched): {np.allclose(v_p, Jg_batch[:, :3], atol=1e-12)}")
"""),
md(r"""
## Velocities one way, forces the other

The Jacobian maps joint rates to the tool's motion, $\dot x = J\dot q$. Its transpose maps a
**wrench** at the tool (force $f$ and moment $m$, the same reference point as $v$) back to the
joint torques that hold it in balance, $\tau = J^T \begin{bmatrix} f \\ m\end{bmatrix}$. Both
follow from the virtual power of the screws chapter: the power the wrench delivers to the tool's
twist equals the power the joints deliver, $f\cdot v + m\cdot\omega = \tau\cdot\dot q$ for every
$\dot q$. The PUMA holding 50 N straight down at the nominal pose:
"""),
code("""
wrench = np.array([0, 0, -50.0, 0, 0, 0])            # f (N), m (N m), at the tool point
tau = J.T @ wrench
print("joint torques tau = J^T F (N m):", tau.round(3))
qdot = rng.normal(size=6)
print(f"power check, F . (J qdot) = tau . qdot: {np.isclose(wrench @ (J @ qdot), tau @ qdot)}")
"""),
md(r"""
The wrist joints feel nothing: the PUMA has no tool offset here, so the tool point is the wrist
centre, and a force through it has no moment about axes 4, 5 and 6, which all pass through it.
Joint 1 feels nothing either: its axis is vertical, parallel to the force.

## The determinant, factorised

A six-joint arm is **singular** where $\det J = 0$: some tool twist can no longer be produced, and
some wrench is held with no torque at all. The determinant does not depend on the reference point
(the matrix that moves it has determinant 1), so compute it where $J$ is simplest: at the **wrist
centre** (the origin of frame 4, where the axes 4, 5, 6 meet). There the last three joints cannot
move the point, the upper-right block of $J$ vanishes, and

$$
J_{w} = \begin{bmatrix} A & 0 \\ C & D\end{bmatrix}, \qquad \det J = \det A\,\det D .
$$
"""),
code("""
J_wrist = jacobians.geometric_jacobian_symbolic(puma, point=4, symbolic_lengths=True)
print("upper-right block at the wrist centre is zero:", J_wrist[:3, 3:].is_zero_matrix)
det = jacobians.determinant_symbolic(puma, point=4, symbolic_lengths=True)
display(Math(r"\\det J = " + sp.latex(sk.textbook(det, collect=False))))
"""),
md(r"""
Three factors, three singularities (besides the constant $a_2$):

- **wrist**, $s_5 = 0$: axes 4 and 6 line up; the wrist loses one rotation (the IK chapter met it
  as "only $q_4 + q_6$ is fixed");
- **elbow**, $a_3 s_3 + d_4 c_3 = 0$: the wrist centre lies on the line through the axes of
  joints 2 and 3, with the arm stretched or folded; $q_3 = \operatorname{atan2}(-d_4, a_3) =
  -87.31°$ or $92.69°$;
- **shoulder**, $a_2 c_2 + a_3 c_{23} - d_4 s_{23} = 0$: the wrist centre lies in the vertical
  plane through $z_0$ and the axis of joint 2 (at distance $d_3$ from $z_0$). Then joint 1 moves
  it along the direction that joints 2 and 3 already give.

It is the textbook result (Siciliano et al. {cite}`siciliano2009robotics`, sec. 3.3). The test
suite checks this product against `det(J)` at random configurations; here the numbers for one,
and the rank at a configuration on each factor:
"""),
code("""
det_numeric = sp.lambdify(puma.q_symbols, det.subs(puma.length_symbols()))
q = rng.uniform(-np.pi, np.pi, 6)
print(f"factorised det = det J at a random q: {np.isclose(det_numeric(*q), np.linalg.det(puma.geometric_jacobian(q)), atol=1e-12)}")

a2, a3, d4 = 0.4318, 0.0203, 0.4318
elbow = np.arctan2(-d4, a3)
# the shoulder factor c2 (a2 + a3 c3 - d4 s3) - s2 (a3 s3 + d4 c3) vanishes at this q2 for a chosen q3
q3 = -0.6
shoulder_q2 = np.arctan2(a2 + a3 * np.cos(q3) - d4 * np.sin(q3), a3 * np.sin(q3) + d4 * np.cos(q3))
cases = {
    "general": np.radians([20, 40, -60, 30, 50, 10]),
    "wrist (q5 = 0)": np.radians([20, 40, -60, 30, 0, 10]),
    "elbow (q3 = -87.31 deg)": np.r_[0.35, 0.7, elbow, 0.5, 0.9, 0.2],
    "shoulder": np.r_[0.35, shoulder_q2, q3, 0.5, 0.9, 0.2],
}
print(f"{'configuration':<25}{'det J':>10}{'rank':>6}{'w':>9}{'condition':>11}")
for name, q in cases.items():
    print(f"{name:<25}{det_numeric(*q):>10.4f}{jacobians.rank(puma, q):>6}"
          f"{puma.manipulability(q):>9.4f}{jacobians.condition_number(puma, q):>11.1f}")
"""),
md(r"""
At a singular configuration screwkit answers: the rank is 5, the manipulability is exactly 0
(the smallest singular value is below NumPy's rank tolerance) and the condition number is
infinite. Nothing raises.

What is lost? The left null space of $J$ (its last left singular vector $y$, with $y^T J = 0$)
is best read as a wrench $y = (f; m)$ at the tool: a load that the joints hold with **zero
torque**, $\tau = J^T y = 0$, because the structure carries it. Since $J$ is not full rank, no joint
motion has a component along $y$ either.
"""),
code("""
for name in ("elbow (q3 = -87.31 deg)", "wrist (q5 = 0)"):
    q = cases[name]
    U, sigma, _ = np.linalg.svd(puma.geometric_jacobian(q))
    y = U[:, -1] * np.sign(U[np.argmax(np.abs(U[:, -1])), -1])  # the sign of a null vector is free: fix it
    f, m = y[:3], y[3:]
    z, o = puma.joint_axes(q)
    arm_line = puma.fk(q)[:3, 3] - o[1]          # from the shoulder (on axis 2) to the wrist centre
    print(f"{name}: f = {np.round(f, 3) + 0.0}, m = {np.round(m, 3) + 0.0}, "
          f"|J^T y| < 1e-12: {np.abs(puma.geometric_jacobian(q).T @ y).max() < 1e-12}")
    if name.startswith("elbow"):
        print(f"    m = 0 and f along the shoulder-to-wrist line: "
              f"{np.allclose(m, 0, atol=1e-9) and np.isclose(abs(f @ arm_line) / np.linalg.norm(arm_line), 1)}")
    else:
        print(f"    m is perpendicular to the wrist axes 4, 5, 6: {np.allclose(z[3:] @ m, 0, atol=1e-9)}")
"""),
md(r"""
At the elbow singularity the lost wrench is a pure force along the stretched arm, from the
shoulder to the wrist centre: the links take it in tension or compression, and, dually, the wrist
centre cannot move along that line. At the wrist singularity the moment is perpendicular to all
three wrist axes (axes 4 and 6 coincide, so they span only a plane with axis 5), with a force that
the arm joints balance.

## Manipulability and its ellipsoid

Away from a singularity, how *good* is a configuration? Map the unit ball of joint rates,
$\|\dot q\| \le 1$, through $J$: it becomes an **ellipsoid** of tool velocities with semi-axes
the singular values $\sigma_i$ of $J$ along the left singular vectors. Yoshikawa's
manipulability is its volume factor,

$$
w(q) = \sqrt{\det\left(J J^T\right)} = \sigma_1\sigma_2\cdots\sigma_m \quad(= |\det J| \text{ for a square } J),
$$

and the condition number $\sigma_1/\sigma_m$ says how round it is (1 is isotropic). With all six
rows, $w$ multiplies m/s by rad/s; the **translational** ellipsoid uses the rows $v$ alone and is
what we draw (`rows="position"`).

The slider below moves the PUMA's elbow toward its singularity: the ellipsoid flattens into a
disc, because the wrist centre cannot move along the stretched arm. (Sliders need a running
kernel; the three pictures after it show the same in the book.)
"""),
code("""
def show_ellipsoid(ax, q, scale=0.4):
    sk.plotting.draw_chain(ax, puma, q)
    centre, radii, axes = jacobians.ellipsoid(puma, q, rows="position")
    sk.plotting.draw_ellipsoid(ax, centre, radii, axes, scale=scale)
    w = puma.manipulability(q, rows="position")
    ax.set_title(f"q3 = {np.degrees(q[2]):.1f} deg: radii {np.round(radii, 3).tolist()} m/s, w = {w:.4f}", fontsize=9)
    ax.view_init(elev=15, azim=-70)

limits = ((-0.5, 0.9), (-0.7, 0.7), (-0.5, 0.9))
q_base = np.radians([0, 30, 0, 0, 45, 0])
"""),
code("""
# NBVAL_IGNORE_OUTPUT
import ipywidgets as widgets

def fold(q3_deg):
    q = q_base.copy()
    q[2] = np.radians(q3_deg)
    show_ellipsoid(sk.plotting.axes3d(limits, figsize=(6, 6)), q)
    plt.show()

widgets.interactive(fold, q3_deg=widgets.FloatSlider(value=-20, min=-87.3, max=60, step=0.5, description="q3 (deg)"))
"""),
code("""
# NBVAL_IGNORE_OUTPUT
figure = plt.figure(figsize=(15, 5))
for k, q3 in enumerate([np.radians(0), np.radians(-40), elbow], start=1):
    q = q_base.copy()
    q[2] = q3
    show_ellipsoid(sk.plotting.axes3d(limits, ax=figure.add_subplot(1, 3, k, projection="3d")), q)
plt.tight_layout()
plt.show()
"""),
md(r"""
The translational manipulability along that fold, and where it peaks:
"""),
code("""
q3_values = np.radians(np.arange(-87, 61, 1.0))
Q_fold = np.tile(q_base, (q3_values.size, 1))
Q_fold[:, 2] = q3_values
w_fold = puma.manipulability(Q_fold, rows="position")
best = np.argmax(w_fold)
print(f"w over q3 in [-87, 60] deg: largest {w_fold[best]:.4f} at q3 = {np.degrees(q3_values[best]):.0f} deg, "
      f"smallest {w_fold.min():.4f} at q3 = {np.degrees(q3_values[np.argmin(w_fold)]):.0f} deg")
print(f"at the elbow singularity itself: w = {puma.manipulability(np.r_[q_base[:2], elbow, q_base[3:]], rows='position'):.4f}")
fig, ax = plt.subplots(figsize=(6, 3))
ax.plot(np.degrees(q3_values), w_fold)
ax.axvline(np.degrees(elbow), color="tab:red", ls="--", label="elbow singularity")
ax.set_xlabel("q3 (deg)")
ax.set_ylabel("w, position rows (m$^3$/s$^3$)")
ax.legend()
plt.show()
"""),
md(r"""
The fold passes *two* singularities: the elbow at $-87.31°$, and, near $q_3 = 33°$, the shoulder
(with $q_2 = 30°$ the wrist centre then passes through the vertical plane of $z_0$ and axis 2,
where $a_2 c_2 + a_3 c_{23} - d_4 s_{23} = 0$). The translational manipulability peaks in between.

## Speed

The fast Jacobian compiles the exact joint axes $z_i, o_i$ and the tool point once (as `fk` does)
and evaluates them for a whole batch; the columns are then cross products of arrays. On this
project's 2-core machines `benchmarks/bench_jacobians.py` measures about 50 ms for 100,000 PUMA
Jacobians, about 16 times faster than calling the Robotics Toolbox's compiled `jacob0` once per
configuration (8 µs each), and the two agree to $10^{-15}$. A single Jacobian costs about 26 µs in
screwkit (the toolbox's C++ path is faster there: the batch is where screwkit wins).
"""),
code("""
# NBVAL_IGNORE_OUTPUT
Q = rng.uniform(-np.pi, np.pi, (100_000, 6))
%timeit puma.geometric_jacobian(Q)
"""),
md(r"""
## Exercises

1. For the planar two-link arm `sk.robots.planar([l1, l2])`, show that the $2\times 2$ Jacobian
   has $\det J = l_1 l_2 \sin q_2$, so $w = l_1 l_2 |\sin q_2|$, and find the elbow angle of
   largest manipulability. Check with `manipulability(..., rows="planar")`.
2. Why is $\det J$ the same whether $J$ reports the velocity of the tool point or of the wrist
   centre? Write the matrix that moves the reference point and its determinant.
3. The PUMA's *ready* pose $(0, 90°, -90°, 0, 0, 0)$: which of the three factors vanish?

````{dropdown} Solutions
1. $J = \begin{bmatrix} -l_1 s_1 - l_2 s_{12} & -l_2 s_{12} \\ l_1 c_1 + l_2 c_{12} & l_2 c_{12}\end{bmatrix}$,
   $\det J = l_1 l_2 (c_1 s_{12} - s_1 c_{12}) = l_1 l_2 \sin q_2$. Largest at $q_2 = \pm 90°$
   (elbow square), whatever the lengths; zero stretched or folded.
2. $J_p = \begin{bmatrix} I & -[p - w]_\times \\ 0 & I\end{bmatrix} J_w$: a block triangular
   matrix with identity blocks, determinant 1.
3. The wrist factor ($q_5 = 0$) and, nearly, the elbow: $a_3 s_3 + d_4 c_3 = -a_3 = -0.0203$ at
   $q_3 = -90°$, only 2.7° from the elbow singularity at $-87.31°$. The shoulder factor is
   $a_2 c_2 + a_3 c_{23} - d_4 s_{23} = a_3 = 0.0203$: close to zero as well, since the wrist
   centre is almost above the shoulder. *Ready* is a poor pose to start resolved-rate motion from.
````
"""),
]

write(cells, "notebooks/jacobians.ipynb")
