"""The parametrised exercises of the chapter statics."""
