"""The parametrised exercises of the chapter poe."""
