"""The parametrised exercises of the chapter kawasaki_workspace."""
