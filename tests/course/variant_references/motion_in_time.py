"""Independent references for the parametrised exercises of motion_in_time: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

INDEPENDENT = {}


def peak_of_the_quintic(n):
    # ds/dt = 30 tau^2 (1 - tau)^2 / T is largest at tau = 1/2: 30/16/T
    return 15 / (8 * n["T"][0])


INDEPENDENT[3] = peak_of_the_quintic
