from servofmu.physics.drives.actuator import Actuator, per_degree, reduction_ratio, stiffness_breakdown

ema = Actuator.from_catalog("liu2014_ema")  # data/actuators.toml
b = stiffness_breakdown(ema, output_angle=0.17, load_torque=[100.0, 300.0], temperature=253.15)
print(per_degree(b.total), b.share("housing"), reduction_ratio(ema, 0.17).total)
