"""The parametrised exercises of the chapter puma_ik."""
