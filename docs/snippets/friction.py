from servofmu.physics.bearing import BearingModel, BearingPair
from servofmu.parameters.bearing import default_parameters, pair_from_parameters

skf = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="skf2004")
out = BearingModel(skf).evaluate(233.15, 0.1745)  # −40 °C, 10 °/s
print(out.running_torque, out.viscous_torque, out.sliding_torque, out.breakaway_torque)
params = default_parameters() | {"friction_model": "ehl_per_contact", "grease_f0": 10.9}
cold = BearingModel(pair_from_parameters(params)).evaluate(233.15, 0.1745)
print(cold.viscous_torque, cold.grease_torque)
