"""Source of notebooks/puma_ik.ipynb: python tools/chapters/puma_ik.py"""
from _nb import code, md, write

cells = [
md(r"""
# The PUMA 560: inverse kinematics, all eight solutions

Given a pose $T$ of the tool, which joint vectors $q$ give $T(q) = T$? For the PUMA 560 the answer
is a closed form with up to **eight** solutions. The paper {cite}`surriani2018puma` computes one
per named pose with Corke's toolbox (its Table 3), finds that it differs from the joint vector
that produced the pose, and concludes that the solution is not unique. Here we derive all eight,
check Table 3 number by number, and say exactly which solution the paper printed and why.
"""),
code("""
import numpy as np
import matplotlib.pyplot as plt
import screwkit as sk
from screwkit.ik import CONFIGURATIONS

np.set_printoptions(precision=4, suppress=True)
puma = sk.robots.puma560()
"""),
md(r"""
## The geometric derivation

The last three axes of the PUMA meet in one point, the **wrist centre** $w$. Here (no tool,
$d_6 = 0$) it is the origin of the tool frame, $w = p$, and it depends on $q_1, q_2, q_3$ only.
This splits the problem in three.

**Arm (joint 1).** Seen from above, $w$ sits at the shoulder offset $d_3$ to the side of the arm's
vertical plane. With $r^2 = w_x^2 + w_y^2$ and $\varphi = \operatorname{atan2}(w_y, w_x)$, the plane
of the arm makes the angle

$$
q_1 = \varphi + \arcsin\frac{d_3}{r} \quad (\text{right arm, } r) \qquad\text{or}\qquad
q_1 = \varphi + \pi - \arcsin\frac{d_3}{r} \quad (\text{left arm, } l),
$$

and the wrist centre is at $V = \pm\sqrt{r^2 - d_3^2}$ along $x_1$ (in front of the shoulder for
the right arm). No solution if $r < d_3$.

**Elbow (joints 2 and 3).** In the arm's plane the wrist centre is
$(V, w_z) = a_2 (c_2, s_2) + a_3 (c_{23}, s_{23}) + d_4 (-s_{23}, c_{23})$: a two-link arm with a
bent forearm of length $\rho = \sqrt{a_3^2 + d_4^2}$ at the angle $\beta = \operatorname{atan2}(d_4,
a_3)$. The law of cosines gives

$$
a_3 c_3 - d_4 s_3 = \rho\cos(q_3 + \beta) = \frac{V^2 + w_z^2 - a_2^2 - \rho^2}{2 a_2},
$$

two values of $q_3$ (elbow up, $u$, or down, $d$: the elbow above or below the line from the
shoulder to the wrist centre), none when the right side exceeds $\rho$ in size (out of reach). Then
$q_2 = \operatorname{atan2}(w_z, V) - \operatorname{atan2}(a_3 s_3 + d_4 c_3,\ a_2 + a_3 c_3 - d_4 s_3)$.

**Wrist (joints 4-6).** With $R_{03}$ known, ${}^3R_6 = R_{03}^T R = R_z(q_4)\,R_y(-q_5)\,R_z(q_6)$
(the previous chapter): Z-Y-Z Euler angles, two solutions, $q_5 \le 0$ (*no flip*, $n$) and its
twin $(q_4 + \pi, -q_5, q_6 + \pi)$ (*flip*, $f$). If $q_5 = 0$ the axes of joints 4 and 6 line up
and only $q_4 + q_6$ is fixed (the **wrist singularity**): screwkit then sets $q_4 = 0$ and says
so.

Two arms times two elbows times two wrists: eight solutions, labelled as in Corke's toolbox
({cite}`corke2017rvc`). `benchmarks/bench_puma.py` runs the Robotics Toolbox for Python's
`ikine_a` beside screwkit for every label on 200 random poses: the 1600 joint vectors agree.

## Eight solutions for one pose
"""),
code("""
q_true = np.radians([20, 40, -110, 30, 50, -20])
T = puma.fk(q_true)
solutions = sk.ik.puma560_ik(T)
print(f"the pose was made by {np.degrees(q_true).round(1).tolist()} deg, configuration {sk.ik.puma560_config(q_true)}")
print(f"{'config':>6}  {'q (deg)':^52}  limits  residual < 1e-10")
for s in solutions:
    residual = np.abs(puma.fk(s.q) - T).max()
    print(f"{s.config:>6}  {' '.join(f'{v:8.2f}' for v in np.degrees(s.q))}  {str(s.within_limits):>6}  {residual < 1e-10}")
"""),
code("""
# NBVAL_IGNORE_OUTPUT
figure = plt.figure(figsize=(14, 7))
for k, s in enumerate(solutions, start=1):
    ax = sk.plotting.axes3d(((-0.6, 0.6), (-0.6, 0.6), (-0.4, 0.8)), ax=figure.add_subplot(2, 4, k, projection="3d"))
    sk.plotting.draw_chain(ax, puma, s.q, color="tab:blue" if s.within_limits else "tab:red", frame_length=0.12)
    ax.set_title(f"{s.config}" + ("" if s.within_limits else " (outside limits)"))
    ax.view_init(elev=15, azim=-50)
plt.tight_layout()
plt.show()
"""),
md(r"""
All eight put the tool at the same place with the same orientation. Two differ only by the
wrist flip; the left-arm solutions reach over the shoulder. Red ones break a joint limit.
`within_limits=True` keeps only the others, and `near=q` sorts them by distance to the current
configuration, which is how a controller picks one:
"""),
code("""
current = q_true + np.radians([3, -2, 4, 0, 1, 2])
allowed = sk.ik.puma560_ik(T, within_limits=True, near=current)
print("within limits, nearest first:", [s.config for s in allowed])
print("nearest to the current configuration:", np.degrees(allowed[0].q).round(2).tolist())
"""),
md(r"""
## Out of reach, and singular

An unreachable pose is an answer, not an error: the list is empty and says why.
"""),
code("""
for target in (sk.transl(0.9, 0.3, 0.2), sk.transl(0.05, 0.0, 0.3)):
    result = sk.ik.puma560_ik(target)
    print(len(result), "solutions:", result.reason)
"""),
md(r"""
Three of the four named poses have $q_5 = 0$, on the wrist singularity:
"""),
code("""
for name, q in puma.configurations.items():
    solutions_named = sk.ik.puma560_ik(puma.fk(q))
    singular = [f"{s.config}: {', '.join(s.singular)}" for s in solutions_named if s.singular]
    print(f"{name:>8}: {len(solutions_named)} solutions; singular ones: {singular or 'none'}")
"""),
md(r"""
Only the solutions of the arm that made the pose sit on the singularity: for the other arm
the wrist must turn to a different orientation relative to the forearm, and $q_5 \ne 0$ there.

## The paper's Table 3

Table 3 gives one joint vector per named pose. Does each reach its pose, which configuration is
it, and does it respect the joint limits?
"""),
code("""
table3 = {  # the paper's Table 3, rad
    "zero":    [2.5007, 1.6167, 0.0000, 3.1416, 1.6167, 0.6409],
    "ready":   [0.2689, 1.5708, -1.4768, 3.1416, 0.0940, 2.8726],
    "stretch": [2.7975, -3.1416, -1.4768, 1.8269, 0.3562, 1.2984],
    "nominal": [2.6486, -3.9270, 0.0940, 2.5326, 0.9743, 0.3734],
}
names = ["q1", "q2", "q3", "q4", "q5", "q6"]
for name, q_paper in table3.items():
    q_paper = np.array(q_paper)
    target = puma.fk(puma.configurations[name])
    reached = puma.fk(q_paper)
    position_error = np.linalg.norm(reached[:3, 3] - target[:3, 3])
    angle_error = np.linalg.norm(sk.ik.pose_error(reached, target)[3:])
    ours = sk.ik.puma560_ik(target)
    match = [s.config for s in ours if np.abs(np.angle(np.exp(1j * (s.q - q_paper)))).max() < 1e-3]
    low, high = puma.qlim.T
    outside = [n for n, v, lo, hi in zip(names, q_paper, low, high) if not lo <= v <= hi]
    print(f"{name:>8}: reaches its pose to {position_error * 1e3:.2f} mm and {np.degrees(angle_error):.3f} deg; "
          f"configuration {sk.ik.puma560_config(q_paper)}; equals screwkit's {match}; "
          f"outside limits: {outside or 'none'}")
"""),
md(r"""
Every vector of Table 3 is right: it reaches its pose to the rounding of its four decimals. And
each is the same configuration, **luf** (left arm, elbow up, wrist flipped), equal to screwkit's
`luf` solution after wrapping ($q_2 = -3.9270 = 2.3562 - 2\pi$ for *nominal*; $-3.1416$ and
$+3.1416$ are one angle). The poses themselves were made by right-arm vectors (*zero* is `rdn` or
`rdf` on the singular wrist, *nominal* is `ruf`). So the paper's vectors differ from the poses'
own not because the solver is inexact but because one fixed configuration was asked for all
four poses, and the toolbox returns the solution of the configuration it is asked for, not the
one nearest to the joint vector that made the pose.

None of the four, as printed, respects Corke's joint limits: the flipped wrist has $q_4 = 180°$
for *zero* and *ready* (limit 170°); *stretch* has $q_1 = 160.3°$, just past 160°; and $q_2 = -180°$
(*stretch*) and $-225°$ (*nominal*) lie below $-45°$, although the same angles written as $+180°$
and $+135°$ are inside (screwkit's `within_limits` tries such $2\pi$ shifts). Among the eight
solutions of each pose there are valid ones, the poses' own vectors among them.

## Numerical IK, and where it converges

`sk.ik.numeric_ik` works for any chain: Levenberg–Marquardt steps on the pose error, with
Sugihara's damping. It returns one solution, the one whose **basin of attraction** holds the
starting point. Which of the eight is that? Start from a grid of $(q_1, q_3)$, the other joints
at zero, and colour each start by the solution it reaches:
"""),
code("""
g = np.linspace(-np.pi, np.pi, 81)
G1, G3 = np.meshgrid(g, g)
starts = np.zeros((G1.size, 6))
starts[:, 0], starts[:, 2] = G1.ravel(), G3.ravel()
numeric = sk.ik.numeric_ik(puma, T, starts, max_iterations=100)
closed = sk.ik.puma560_ik_all(T)
distance = np.abs(np.angle(np.exp(1j * (numeric.q[:, None, :] - closed[None])))).max(axis=-1)
label = np.where(numeric.success & (distance.min(axis=1) < 1e-6), distance.argmin(axis=1), -1)
print(f"converged: {numeric.success.mean():.1%} of {len(starts)} starts, "
      f"median {np.median(numeric.iterations):.0f} iterations")
for k, config in enumerate(CONFIGURATIONS):
    print(f"  {config}: {np.mean(label == k):6.1%}")
"""),
code("""
# NBVAL_IGNORE_OUTPUT
from matplotlib.colors import ListedColormap
colours = ["0.85"] + list(plt.cm.tab10.colors[:8])
fig, ax = plt.subplots(figsize=(7, 6))
image = ax.pcolormesh(np.degrees(G1), np.degrees(G3), label.reshape(G1.shape), cmap=ListedColormap(colours),
                      vmin=-1.5, vmax=7.5, shading="nearest")
bar = fig.colorbar(image, ticks=range(-1, 8))
bar.ax.set_yticklabels(["failed"] + list(CONFIGURATIONS))
for k, q in enumerate(closed):
    ax.plot(*np.degrees(q[[0, 2]]), "o", color=colours[k + 1], mec="k", ms=9)
ax.set_xlabel("start q1 (deg)")
ax.set_ylabel("start q3 (deg)")
ax.set_title("Basins of attraction of the eight solutions (dots: the solutions)")
plt.show()
"""),
md(r"""
Here the start's $q_3$ decides almost everything: horizontal bands lead to the right-arm
solutions with the elbow up (`ruf`) or down (`rdn`, `rdf`), whatever the start's $q_1$; the
left-arm solutions attract only small islands near $q_1 = \pm 180°$, and some solutions none
at all. Numerical IK gives *a* solution, not always the nearest and never all of them; the
closed form gives all eight.

## Speed

All eight solutions for a batch of poses is one vectorised call (`puma560_ik_all`, shape
(N, 8, 6), NaN where a pose is out of reach): about 30 ms for 10,000 poses on this project's
machines, against about 0.26 ms per solution for the toolbox's `ikine_a` measured beside it
(see `benchmarks/bench_puma.py`).
"""),
code("""
# NBVAL_IGNORE_OUTPUT
rng = np.random.default_rng(1)
poses = puma.fk(rng.uniform(-np.pi, np.pi, (10_000, 6)))
%timeit sk.ik.puma560_ik_all(poses)
"""),
md(r"""
## Exercises

1. Find a pose that has only four solutions. (Hint: put the wrist centre where the two elbow
   solutions coincide.)
2. The shoulder offset $d_3$ keeps the wrist centre away from the axis of joint 1. What happens to
   the number of solutions for a pose whose wrist centre is at distance exactly $d_3$ from that
   axis?
3. Use `near=` to follow a straight line of poses with the closed form, always taking the
   solution nearest to the previous one. Does the configuration label change along the way?

````{dropdown} Solutions
1. At full stretch, $\rho\cos(q_3+\beta) = \rho$, the two elbow solutions are one: the pose of
   `puma.fk([0, 0.3, -np.arctan2(0.4318, 0.0203), 0, 0.5, 0])` has its elbow straight; each
   solution then carries the flag `'elbow'` and the "u" and "d" vectors coincide, leaving four
   distinct ones.
2. Then $V = 0$: the wrist centre lies on the shoulder's singular surface; the left and right
   arm solutions coincide ($\arcsin(d_3/r) = \pi/2$), and the flag `'shoulder'` is set.
3. Along a path that stays away from the singular surfaces the label stays the same; crossing one
   (for example $q_5$ through 0) the nearest solution changes its label.
````
"""),
]

write(cells, "notebooks/puma_ik.ipynb")
