"""Independent references for the parametrised exercises of configuration_space: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

INDEPENDENT = {}
