"""Independent references for the parametrised exercises of configuration_space:
exercise number -> a function of the statement's numbers ({name: (value, unit)})
giving the key, written here from the statement, not with the generator's code."""

import math

import numpy as np
from answer_references.configuration_space import _distance_rank

INDEPENDENT = {}


def _rank_of_all_distances(count, dim):
    # points in general position (drawn at random, fixed seed): the rank of the
    # Jacobian of all their pairwise squared distances is the number of independent
    # constraints
    points = np.random.default_rng(7).normal(size=(count, dim))
    return float(_distance_rank(points))


def constraints_in_the_plane(n):
    return _rank_of_all_distances(int(n["n"][0]), 2)


def constraints_in_space(n):
    return _rank_of_all_distances(int(n["n"][0]), 3)


def platform_on_sps_legs(n):
    # a prismatic leg between two spherical joints constrains nothing: the platform
    # keeps its 6 freedoms, and each leg adds one, its spin about its own line
    return 6.0 + n["legs"][0]


def area_of_the_annulus(n):
    # pi ((l1 + l2)^2 - (l1 - l2)^2) = 4 pi l1 l2, whichever link is longer
    return 4 * math.pi * n["l1"][0] * n["l2"][0]


INDEPENDENT[1] = constraints_in_the_plane
INDEPENDENT[2] = constraints_in_space
INDEPENDENT[5] = platform_on_sps_legs
INDEPENDENT[14] = area_of_the_annulus
