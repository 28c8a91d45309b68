"""The parametrised exercises of the chapter parallel_kinematics."""
