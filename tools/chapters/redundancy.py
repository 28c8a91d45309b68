"""Source of notebooks/redundancy.ipynb: python tools/chapters/redundancy.py"""
from _nb import code, md, write

cells = [
md(r"""
# Redundancy and manipulability

A planar arm with five joints that only has to place its tip at a point $(x, y)$ has three
joints to spare: infinitely many configurations reach the same point. This chapter follows a
thesis chapter on planar redundant arms {cite}`thesis_redundancy`: resolved-rate inverse
kinematics with the **pseudo-inverse**, and **null-space motion** that spends the spare joints on
raising Yoshikawa's manipulability {cite}`yoshikawa1985manipulability` while the tip stays on its
path. We derive the kinematics with SymPy, correct two typos of the thesis, simulate a 5-link
arm on the thesis's three paths (a circle, a vertical and a horizontal line) with and without
redundancy resolution and joint limits, and end with the thesis's two-arm robot.
"""),
code("""
import numpy as np
import sympy as sp
import matplotlib.pyplot as plt
from IPython.display import HTML, Math, display
import screwkit as sk
from screwkit import redundancy as rd

np.set_printoptions(precision=4, suppress=True)
"""),
md(r"""
## Forward kinematics and the Jacobian (thesis eqs. 2.1-2.17)

The thesis numbers links and joints from 0: link $l_i$ follows joint $\theta_i$, and the angle of
link $i$ from the $x$ axis is the sum $\theta_{01\cdots i} = \theta_0 + \cdots + \theta_i$ (its
eq. 2.3). The tip is the sum of the link vectors (eqs. 2.4-2.6) and the Jacobian
$J_{ij} = \partial x_i / \partial \theta_j$ is $2\times 5$ (eqs. 2.14-2.17):
"""),
code("""
theta = sp.symbols("theta0:5", real=True)
l = sp.symbols("l0:5", positive=True)
sums = [sum(theta[: i + 1]) for i in range(5)]
x4 = sum(l[i] * sp.cos(sums[i]) for i in range(5))
y4 = sum(l[i] * sp.sin(sums[i]) for i in range(5))
J = sp.Matrix([x4, y4]).jacobian(theta)
display(Math(r"J_{11} = " + sp.latex(J[0, 0]) + r",\\qquad J_{25} = " + sp.latex(J[1, 4])))
# the thesis's entries, eq. 2.17: J_1j = -sum_{i >= j} l_i sin(theta_0..i), J_2j = sum_{i >= j} l_i cos(theta_0..i)
thesis = sp.Matrix(2, 5, lambda r, j: sum((-l[i] * sp.sin(sums[i]) if r == 0 else l[i] * sp.cos(sums[i]))
                                          for i in range(j, 5)))
print("eq. 2.17 agrees with the derivative of eqs. 2.4-2.5:", sp.simplify(J - thesis) == sp.zeros(2, 5))
"""),
md(r"""
The thesis's Jacobian is right. Its eq. 2.2 is not: the last line writes $y_4$ with
$l_3\cos(\theta_0 + \theta_1 + \theta_2 + \theta_3)$ where the sine belongs (eq. 2.5, two pages on,
has it right). The difference is not small:
"""),
code("""
y4_printed = y4 - l[3] * sp.sin(sums[3]) + l[3] * sp.cos(sums[3])
print("eq. 2.2 as printed minus the correct y4:", sp.simplify(y4_printed - y4))
LENGTHS = np.array([0.3, 0.25, 0.2, 0.15, 0.1])                 # m, the arm of this chapter
arm = sk.robots.planar(LENGTHS)
lengths = dict(zip(l, LENGTHS))
q_test = np.radians([40, -30, -20, -50, 30])
values = {**lengths, **dict(zip(theta, q_test))}
print(f"at q = {np.degrees(q_test).round(0).tolist()} deg: y4 = {float(y4.subs(values)):.4f} m, "
      f"as printed {float(y4_printed.subs(values)):.4f} m, screwkit {arm.fk(q_test)[1, 3]:.4f} m")
"""),
md(r"""
`sk.robots.planar(lengths)` is this arm as a DH chain (every $\alpha$ and $d$ zero), so the whole
library applies to it; `rd.planar_kinematics` is the same computation specialised to the plane for
speed, and the test suite checks the two against each other.

## The pseudo-inverse, and a typo that breaks it

With $\dot x = J\dot q$ and $J$ of size $2\times n$, $n > 2$, many $\dot q$ give the same $\dot x$.
The one of least norm, $\min \tfrac12 \dot q^T\dot q$ subject to $J\dot q = \dot x$ (thesis eqs.
2.26-2.32 with $W = I$), is

$$
\dot q = J^+\dot x, \qquad J^+ = J^T\left(J J^T\right)^{-1},
$$

the Moore-Penrose inverse of a full-rank "wide" $J$. The thesis's eqs. 2.42-2.43 write
$J^+ = J^T(J^T J)^{-1}$ instead. That cannot be computed: $J^T J$ is $n \times n$ but has rank
2, so it has no inverse. (Eqs. 2.40-2.41 also write $x = J\theta$, which holds for velocities,
$\dot x = J\dot\theta$, not positions.)
"""),
code("""
J_num = arm.geometric_jacobian(q_test)[:2]                   # the 2 x 5 planar Jacobian
print(f"rank of J^T J (5 x 5): {np.linalg.matrix_rank(J_num.T @ J_num)}; |det(J^T J)| < 1e-30: {abs(np.linalg.det(J_num.T @ J_num)) < 1e-30}")
J_plus = J_num.T @ np.linalg.inv(J_num @ J_num.T)
print("J^T (J J^T)^-1 equals NumPy's pinv:", np.allclose(J_plus, np.linalg.pinv(J_num)))
print("J J+ = I (2 x 2):", np.allclose(J_num @ J_plus, np.eye(2)))
"""),
md(r"""
## Null-space motion

Adding any $\dot q_0$ of the **null space** of $J$ leaves the tip where it is. The thesis
(eqs. 2.34-2.37) minimises $\tfrac12\|\dot q - \dot\varphi\|^2$ instead, and gets

$$
\dot q = J^+\dot x + \left(I - J^+J\right)\dot\varphi, \qquad \dot\varphi = k\,\nabla w(q)
\quad\text{(eq. 2.38)},
$$

where $I - J^+J$ projects onto the null space. With $w = \sqrt{\det(JJ^T)}$ (eq. 2.39) the spare
joints climb the manipulability while the tip follows the path.

**The gradient, exactly.** By the Cauchy-Binet formula $\det(JJ^T)$ is the sum of the squares of
the $2\times 2$ minors of $J$. Column $i$ of $J$ is $z\times r_i$, with $r_i$ the vector from joint
$i$ to the tip, so the minor of columns $i, j$ is $m_{ij} = r_i\times r_j$ (a scalar in the plane).
Turning joint $k$ turns $r_i$ by $z \times r_{\max(i,k)}$, which gives

$$
w^2 = \sum_{i<j} m_{ij}^2, \qquad
\frac{\partial m_{ij}}{\partial q_k} = r_i\cdot r_{\max(j,k)} - r_{\max(i,k)}\cdot r_j, \qquad
\frac{\partial w}{\partial q_k} = \frac{1}{2w}\sum_{i,j} m_{ij}\,\frac{\partial m_{ij}}{\partial q_k}.
$$

`rd.manipulability_gradient` evaluates this closed form, vectorised. Against SymPy's derivative of
$w$ and against finite differences:
"""),
code("""
w_symbolic = sp.sqrt((J * J.T).det())
gradient_symbolic = [sp.lambdify(list(theta) + list(l), sp.diff(w_symbolic, t)) for t in theta]
w, gradient = rd.manipulability_gradient(LENGTHS, q_test)
print("w =", round(float(w), 6), " = sqrt(det(J J^T)):", np.isclose(w, np.sqrt(np.linalg.det(J_num @ J_num.T))))
print("grad w (closed form):", gradient.round(6))
print("equals SymPy's diff:", np.allclose(gradient, [g(*q_test, *LENGTHS) for g in gradient_symbolic]))
h = 1e-6
central = [(rd.manipulability_gradient(LENGTHS, q_test + h * e)[0]
            - rd.manipulability_gradient(LENGTHS, q_test - h * e)[0]) / (2 * h)
           for e in np.eye(5)]
print("equals central differences:", np.allclose(gradient, central, atol=1e-8))
projector = np.eye(5) - J_plus @ J_num
print("J (I - J+ J) grad w = 0, the tip does not move:", np.allclose(J_num @ projector @ gradient, 0, atol=1e-14))
"""),
md(r"""
## Resolved rates, integrated

The thesis integrates $\dot q$ by Euler steps, $q_{k+1} = q_k + \dot q_k\,\Delta t$ (eq. 2.21).
Each step follows the tangent of the path, so the tip slowly drifts off it. A **closed-loop** term
pulls it back: $\dot q = J^+(\dot x_d + K e) + (I - J^+J)\dot\varphi$, with $e = x_d - x(q)$ the
tip's error and $K$ a gain (1/s; $K\Delta t < 2$ keeps the loop stable). `rd.resolve` runs the
loop; row $i$ of its result belongs to sample $i$ of the path.

The arm: five links of 0.3, 0.25, 0.2, 0.15 and 0.1 m. The paths, 10 s each at
$\Delta t$ = 10 ms with a smooth (quintic) timing that starts and ends at rest:
"""),
code("""
paths = {
    "circle": rd.circle((0.45, 0.25), 0.15, duration=10.0, dt=0.01),
    "vertical line": rd.line((0.55, -0.2), (0.55, 0.45), duration=10.0, dt=0.01),
    "horizontal line": rd.line((-0.2, 0.5), (0.55, 0.5), duration=10.0, dt=0.01),
}
guesses = {"circle": [30, -30, -30, -30, -30], "vertical line": [30, -30, -30, -30, -30],
           "horizontal line": [150, -30, -30, -30, -30]}
starts = {name: rd.start_configuration(arm, path.position[0], np.radians(guesses[name]))
          for name, path in paths.items()}
for name, q0 in starts.items():
    print(f"{name:<16} starts at {paths[name].position[0].round(3).tolist()} m with q0 = {np.degrees(q0).round(1).tolist()} deg")
"""),
code("""
circle = paths["circle"]
closed = rd.resolve(arm, circle, starts["circle"])
open_loop = rd.resolve(arm, circle, starts["circle"], feedback_gain=0.0)
print(f"largest distance from the circle, open loop (thesis eq. 2.21): {open_loop.error.max() * 1000:.2f} mm")
print(f"largest distance from the circle, closed loop K = 50/s:        {closed.error.max() * 1000:.3f} mm")
"""),
md(r"""
The open loop drifts by millimetres over one circle; the closed loop stays within a few hundredths
of a millimetre, well inside the 0.1 mm this course asks for.

## Four simulations on three paths

The thesis's related work (Marindani, 2011) compares four simulations: with or without using the
redundancy, with or without joint limits. Here: limits of ±60° on joints 2-5 (joint 1 free);
"using the redundancy" is the null-space gain $k = 5$; with limits, the arm either just **clamps**
(the joint stops at its limit and the tip leaves the path) or also **avoids** them, adding to
$\dot\varphi$ the descent of a barrier $H = \sum_i (q_{i,\max} - q_{i,\min})^2 / (4 (q_{i,\max} -
q_i)(q_i - q_{i,\min}))$, which is 1 at mid-range and grows without bound at a limit.
"""),
code("""
limits = np.radians([[-180, 180]] + [[-60, 60]] * 4)
limited_arm = sk.robots.planar(LENGTHS, qlim=limits)
simulations = {
    "1 no redundancy, no limits": dict(robot=arm, null_space_gain=0.0, joint_limits=None),
    "2 no redundancy, limits": dict(robot=limited_arm, null_space_gain=0.0, joint_limits="clamp"),
    "3 redundancy, no limits": dict(robot=arm, null_space_gain=5.0, joint_limits=None),
    "4 redundancy, limits": dict(robot=limited_arm, null_space_gain=5.0, joint_limits="avoid"),
}
runs = {}
print(f"{'path':<16}{'simulation':<29}{'mean w':>8}{'min w':>8}{'max error':>11}{'clamped':>9}{'in limits':>11}")
for name, path in paths.items():
    for label, options in simulations.items():
        options = dict(options)
        robot = options.pop("robot")
        run = rd.resolve(robot, path, starts[name], **options)
        runs[name, label] = run
        inside = limited_arm.within_limits(run.q).mean() * 100
        print(f"{name:<16}{label:<29}{run.manipulability.mean():8.4f}{run.manipulability.min():8.4f}"
              f"{run.error.max() * 1000:8.3f} mm{run.limited.mean() * 100:8.1f}%{inside:10.0f}%")
"""),
md(r"""
What the table says (w in m², the area factor of the velocity ellipse per unit joint rate):
"""),
code("""
for name in paths:
    base, climb, limited = (runs[name, label] for label in
                            ("1 no redundancy, no limits", "3 redundancy, no limits", "4 redundancy, limits"))
    print(f"{name:<16} null space raises mean w by {100 * (climb.manipulability.mean() / base.manipulability.mean() - 1):4.1f}% "
          f"and min w by {100 * (climb.manipulability.min() / base.manipulability.min() - 1):4.1f}%; "
          f"within limits: {100 * (limited.manipulability.mean() / base.manipulability.mean() - 1):4.1f}% and "
          f"{100 * (limited.manipulability.min() / base.manipulability.min() - 1):5.1f}%")
"""),
md(r"""
- **Redundancy raises manipulability on every path**, most on the circle, whose near side forces
  the plain pseudo-inverse into a curled, poorly conditioned arm: the minimum rises by about 30%.
  The tip error does not change: null-space motion is invisible at the tip.
- **Without limits, the arm bends joints past ±60°** (simulation 1 on the circle, and simulation 3
  on every path: climbing $w$ stretches some joints and folds others).
- **Clamping costs accuracy**: on the circle simulation 2 leaves the path by almost a centimetre
  while a joint is stopped.
- **Avoiding the limits in the null space costs some manipulability and no accuracy**:
  simulation 4 stays within the limits and on the path to 0.03 mm, and its mean $w$ still beats
  simulation 1 on every path. On the horizontal line, whose ends need joints near their limits,
  the barrier and the manipulability gradient pull against each other: the mean gains only 0.5%
  and the minimum is 0.7% lower than without redundancy resolution.

### Manipulability over time
"""),
code("""
# NBVAL_IGNORE_OUTPUT
fig, axes = plt.subplots(1, 3, figsize=(15, 3.8), sharey=True)
for ax, name in zip(axes, paths):
    for label in simulations:
        run = runs[name, label]
        ax.plot(run.t, run.manipulability, label=label)
    ax.set_title(name)
    ax.set_xlabel("t (s)")
axes[0].set_ylabel("w = sqrt(det(J J^T)) (m$^2$)")
axes[0].legend(fontsize=8)
plt.tight_layout()
plt.show()
"""),
md(r"""
### Stick pictures

The arm every 0.5 s along each path, without (grey) and with (blue) redundancy resolution within the
joint limits:
"""),
code("""
# NBVAL_IGNORE_OUTPUT
fig, axes = plt.subplots(1, 3, figsize=(15, 5))
for ax, name in zip(axes, paths):
    for label, colour in (("2 no redundancy, limits", "0.6"), ("4 redundancy, limits", "tab:blue")):
        run = runs[name, label]
        for q in run.q[::50]:
            sk.plotting.draw_planar(ax, arm, q, color=colour, alpha=0.35)
    ax.plot(*paths[name].position.T, "r-", lw=1.5)
    ax.plot(0, 0, "ks", ms=8)
    ax.set_aspect("equal")
    ax.set_xlim(-0.6, 1.0)
    ax.set_ylim(-0.35, 0.8)
    ax.set_title(f"{name}: grey simulation 2, blue simulation 4")
plt.tight_layout()
plt.show()
"""),
md(r"""
### The circle, animated

The animation below plays in the book without a kernel (matplotlib's JavaScript export): the arm
without (grey) and with (blue) null-space motion, both within the limits, and the manipulability
of each.
"""),
code("""
# NBVAL_IGNORE_OUTPUT
from matplotlib import animation

plain, climbing = runs["circle", "2 no redundancy, limits"], runs["circle", "4 redundancy, limits"]
frames = range(0, len(circle.t), 40)
fig, (ax, ax_w) = plt.subplots(1, 2, figsize=(10, 4.2), dpi=60)
ax.plot(*circle.position.T, "r-", lw=1)
ax.set_aspect("equal"); ax.set_xlim(-0.1, 0.9); ax.set_ylim(-0.2, 0.6)
grey = sk.plotting.draw_planar(ax, arm, plain.q[0], color="0.5")
blue = sk.plotting.draw_planar(ax, arm, climbing.q[0], color="tab:blue")
ax_w.plot(plain.t, plain.manipulability, color="0.5", label="without")
ax_w.plot(climbing.t, climbing.manipulability, color="tab:blue", label="with null-space motion")
marker = ax_w.axvline(0, color="k", lw=1)
ax_w.set_xlabel("t (s)"); ax_w.set_ylabel("w (m$^2$)"); ax_w.legend(loc="lower right")

def update(k):
    for line, run in ((grey, plain), (blue, climbing)):
        points = rd.planar_kinematics(LENGTHS, run.q[k])[0]
        line.set_data(points[:, 0], points[:, 1])
    marker.set_xdata([circle.t[k]])
    return grey, blue, marker

movie = animation.FuncAnimation(fig, update, frames=frames, interval=160, blit=True)
plt.close(fig)
HTML(sk.plotting.animation_html(movie))
"""),
md(r"""
### Try the gain

With a running kernel, the slider sets the null-space gain $k$ for the circle within limits; the
tip error stays the same while $w$ changes. (A thousand steps take well under 0.2 s, see below.)
"""),
code("""
# NBVAL_IGNORE_OUTPUT
import ipywidgets as widgets

def try_gain(k):
    run = rd.resolve(limited_arm, circle, starts["circle"], null_space_gain=k, joint_limits="avoid")
    fig, ax = plt.subplots(figsize=(6, 3))
    ax.plot(run.t, run.manipulability)
    ax.set_ylim(0.15, 0.4)
    ax.set_title(f"k = {k}: mean w {run.manipulability.mean():.4f}, min {run.manipulability.min():.4f}, "
                 f"max error {run.error.max() * 1000:.3f} mm", fontsize=9)
    plt.show()

widgets.interactive(try_gain, k=widgets.FloatSlider(value=5.0, min=0.0, max=20.0, step=0.5))
"""),
md(r"""
## The two-arm robot

The thesis's robot has two such arms, links $l_0, \ldots, l_4$ each, mounted side by side
(`sk.robots.two_arm_planar`, bases 0.4 m apart). Each arm has its own joints, so the two
resolve independently, on the same clock: here the left arm draws a circle while the right one
draws a vertical line.
"""),
code("""
left, right = sk.robots.two_arm_planar(LENGTHS, separation=0.4)
two_paths = {left: rd.circle((-0.45, 0.45), 0.12, duration=8.0, dt=0.01),
             right: rd.line((0.45, 0.2), (0.45, 0.6), duration=8.0, dt=0.01)}
two_runs = {}
for robot, path, guess in zip((left, right), two_paths.values(), ([150, 30, 30, 30, 30], [30, -30, -30, -30, -30])):
    q0 = rd.start_configuration(robot, path.position[0], np.radians(guess))
    two_runs[robot] = rd.resolve(robot, path, q0, null_space_gain=5.0)
    run = two_runs[robot]
    print(f"{robot.name}: base at x = {robot.base[0, 3]:+.1f} m, {path.name}, max error {run.error.max() * 1000:.3f} mm, "
          f"mean w {run.manipulability.mean():.4f}")
"""),
code("""
# NBVAL_IGNORE_OUTPUT
fig, ax = plt.subplots(figsize=(8, 5))
for robot, colour in ((left, "tab:green"), (right, "tab:purple")):
    for q in two_runs[robot].q[::80]:
        origins = robot.frames(q)[:, :2, 3]
        ax.plot(*origins.T, "-o", color=colour, lw=2, ms=3, alpha=0.4)
    ax.plot(*two_paths[robot].position.T, "r-", lw=1.5)
ax.plot([-0.2, 0.2], [0, 0], "k-", lw=8, solid_capstyle="butt")
ax.set_aspect("equal")
ax.set_title("two arms, two paths, one clock")
plt.show()
"""),
md(r"""
## Speed

`rd.resolve` is a loop over steps of small NumPy operations on the $2\times n$ Jacobian; the
closed-form gradient costs about as much as the step itself. On this project's 2-core machines a
1000-step circle takes about 25 ms without null-space motion and under 100 ms with it and the
limit avoidance (the goal is under 0.2 s):
"""),
code("""
# NBVAL_IGNORE_OUTPUT
%timeit rd.resolve(arm, circle, starts["circle"])
%timeit rd.resolve(limited_arm, circle, starts["circle"], null_space_gain=5.0, joint_limits="avoid")
"""),
md(r"""
## Exercises

1. Why does null-space motion not change the tip's error at all (compare simulations 1 and 3)?
2. Run the circle with `feedback_gain=0` and $\Delta t$ = 1 ms instead of 10 ms. How does the drift
   scale with the step?
3. Ask `rd.resolve` for a circle of radius 0.3 m around (0.8, 0): what does it answer, and why?

````{dropdown} Solutions
1. $J(I - J^+J) = J - JJ^+J = J - J = 0$ (because $JJ^+ = I$): whatever $\dot\varphi$ is, its
   projection produces no tip velocity. Only the integration error of each step could differ, and
   the closed loop corrects it.
2. Euler's local error is $O(\Delta t^2)$ per step and there are $1/\Delta t$ steps: the drift is
   $O(\Delta t)$, about ten times smaller at 1 ms.
3. A `ValueError` before simulating: the circle reaches $|p| = 1.1$ m while the arm reaches at
   most $\sum l_i = 1$ m; the message says at which sample and time the path leaves the annulus.
````
"""),
]

write(cells, "notebooks/redundancy.ipynb")
