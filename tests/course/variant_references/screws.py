"""Independent references for the parametrised exercises of screws: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

INDEPENDENT = {}


def power_of_the_force(n):
    # the force's moment about the origin is x F along z; the body turns at omega
    # about z through the origin, so every point of the z axis is at rest: P = x F omega
    return n["x"][0] * n["F"][0] * n["omega"][0]


INDEPENDENT[6] = power_of_the_force
