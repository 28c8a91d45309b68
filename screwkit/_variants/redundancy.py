"""The parametrised exercises of the chapter redundancy."""
