from servofmu.physics.thermal import network as tn
from servofmu.physics.bearing import BearingPair

pair = BearingPair.from_catalog("ning_space_shaft", "mos2_film")
params = tn.parameters_for_pair(
    pair, vacuum=True, mounted=True
)  # or tn.preset("ning_space_vacuum")
net = tn.network(params)
t = tn.steady_state(net, ambient=213.15, sink=213.15, power=0.0)  # soaked at −60 °C, [K]
for _ in range(60):  # one hour at +80 °C in 60 s steps
    t = tn.step(net, t, ambient=353.15, sink=353.15, power=0.05, h=60.0)
print(dict(zip(net.nodes, (round(x - 273.15, 2) for x in t))), tn.time_constants(net)[:2])
print(params.source("ball_conductance"))
fmu_start_values = params.as_dict()  # the ThermalNetwork FMU's parameter names
