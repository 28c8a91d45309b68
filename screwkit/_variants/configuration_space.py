"""The parametrised exercises of the chapter configuration_space."""
