"""The parametrised exercises of the chapter jacobians."""
