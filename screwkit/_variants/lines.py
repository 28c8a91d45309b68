"""The parametrised exercises of the chapter lines."""
