import numpy as np

from servofmu.physics.bearing import BearingModel, BearingPair, with_mounting

pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")  # data/mountings.toml
pair = with_mounting(pair, shim=0.02e-3, loop_stiffness=5e6)  # a compliant yoke
model = BearingModel(pair)
out = model.evaluate(temperature=253.15, speed=0.17, axial_load=5.0)  # SI: K, rad/s, N
print(out.friction_torque, out.preload, out.contact_angle, out.overloaded)
curves = model.curves(np.linspace(233.15, 333.15, 101), speed=0.17)  # vectorised over T
