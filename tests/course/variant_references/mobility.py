"""Independent references for the parametrised exercises of mobility: exercise number
-> a function of the statement's numbers ({name: (value, unit)}) giving the key,
written here from the statement, not with the generator's code."""

INDEPENDENT = {}


def count_a_spatial_parallel_mechanism(n):
    # n limbs of three joints: 2 + 2 n links, 3 n joints; a revolute or a prismatic
    # joint has one freedom, a universal two, a spherical three, so that
    # M = 6 (2 + 2 n - 3 n - 1) + n f = 6 + n (f - 6)
    limbs = n["limbs"][0]
    f = (
        n["revolute joints per limb"][0]
        + n["prismatic joints per limb"][0]
        + 2 * n["universal joints per limb"][0]
        + 3 * n["spherical joints per limb"][0]
    )
    return 6 + limbs * (f - 6)


def count_a_planar_parallel_mechanism(n):
    # n limbs of m revolutes: 2 + n (m - 1) links, n m joints of one freedom each,
    # M = 6 (1 + n (m - 1) - n m) + n m = 6 - n (6 - m)
    limbs, chain = n["limbs"][0], n["revolutes per limb"][0]
    return 6 - limbs * (6 - chain)


def redundant_constraints_of_a_planar_mechanism(n):
    # each limb's vertical revolutes span the planar twists (Rz, Tx, Ty): it imposes
    # the 3-system (Fz, Mx, My); all limbs impose the same one, PWS order 3
    return 3 * n["limbs"][0] - 3


INDEPENDENT[4] = count_a_spatial_parallel_mechanism
INDEPENDENT[5] = count_a_planar_parallel_mechanism
INDEPENDENT[6] = redundant_constraints_of_a_planar_mechanism
