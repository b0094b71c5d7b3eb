"""Crank mechanism: piston kinematics, gas pressure (indicator files, p-V diagrams, the Wiebe cycle), forces and
cylinder torque, and the multi-cylinder torque."""
