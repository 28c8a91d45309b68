"""The parametrised exercises of the chapter mobility."""
