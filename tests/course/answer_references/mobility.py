"""The answer keys of the mobility chapter's exercises 11 and 12 (the planar four-bar),
recomputed independently: screwkit's mobility analysis of the four-bar read as a
parallel mechanism (the coupler held by the crank and the rocker), checked against the
rank of the four-bar's planar velocity constraints written here. Exercises 3 to 7 are
in .later_chapters."""

import numpy as np

import screwkit as sk

from .registry import reference

#: the four-bar of the exercises: ground pins O and C, coupler pins A and B (m)
O, A, B, C = (0, 0), (0.3, 0.8), (1.6, 1.0), (1.4, 0)


def _four_bar():
    z, revolute = [0, 0, 1], sk.limbs.revolute
    crank = revolute(z, [*O, 0]) + revolute(z, [*A, 0])
    rocker = revolute(z, [*C, 0]) + revolute(z, [*B, 0])
    return sk.mobility([crank, rocker])


def _planar_freedoms():
    """3 (n - 1) minus the rank of the pins' velocity constraints, n = 4 bodies."""
    rows = []
    for i, k, (x, y) in [(0, 1, O), (1, 2, A), (2, 3, B), (3, 0, C)]:
        row = np.zeros((2, 12))
        row[:, 3 * i : 3 * i + 3] += [[1, 0, -y], [0, 1, x]]
        row[:, 3 * k : 3 * k + 3] -= [[1, 0, -y], [0, 1, x]]
        rows.append(row[:, 3:])
    return 9 - np.linalg.matrix_rank(np.vstack(rows))


@reference("mobility", 11)
def _():
    m = _four_bar()
    assert m.number == _planar_freedoms() == 1
    return m.grubler_kutzbach


@reference("mobility", 12)
def _():
    m = _four_bar()
    # nu is what the count misses: the true mobility minus the spatial count
    assert m.idle_mobility == 0
    assert m.redundant_constraints == _planar_freedoms() - m.grubler_kutzbach
    return m.redundant_constraints
