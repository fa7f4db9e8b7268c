# Declarations of motor_stepping.py for its compilation.
cpdef tuple friction_substeps(
    tuple phi, tuple gamma, double current, double speed, double angle, double voltage,
    double load_torque, int substeps, double running_friction, double breakaway_friction)
