"""Crank mechanism: piston kinematics (and, later, dynamics and multi-cylinder torque)."""
