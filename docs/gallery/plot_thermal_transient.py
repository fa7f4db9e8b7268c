"""
Thermal transient of a gimbal
=============================

Yu's gimbal in a climatic chamber that cools in one step from +20 to −40 °C: the four part
temperatures of :mod:`servofmu.physics.thermal.network` (frame, shaft, outer and inner
rings), and the preload of the bearing pair that reads them (``temperature_mode`` parts)
against the preload with every part at the chamber temperature.
"""

import os

import matplotlib.pyplot as plt
import numpy as np

from servofmu.physics.bearing import BearingModel, BearingPair
from servofmu.physics.thermal import network as tn

COARSE = os.environ.get("SERVOFMU_GALLERY") == "coarse"  # the site's quick build
h = 120.0 if COARSE else 20.0  # s, one step of the network
minutes = np.arange(0.0, 120.0 + 1e-9, h / 60.0)

net = tn.network(tn.preset("yu2017_gimbal_chamber"))
t = tn.steady_state(net, ambient=293.15, sink=293.15, power=0.0)  # soaked at 20 °C [K]
parts = [t]
for _ in minutes[1:]:
    t = tn.step(net, t, ambient=233.15, sink=233.15, power=0.0, h=h)
    parts.append(t)
parts = np.array(parts)  # K, columns in net.nodes order

model = BearingModel(BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa"))
order = [net.nodes.index(n) for n in ("housing", "shaft", "outer_ring", "inner_ring")]
preload = [model.evaluate(tuple(row[order]), 0.17).preload for row in parts]
steady = model.evaluate(233.15, 0.17).preload

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 6.0))
for i, name in enumerate(net.nodes):
    top.plot(minutes, parts[:, i] - 273.15, label=name.replace("_", " "))
top.set_ylabel("temperature [°C]")
top.legend()
bottom.plot(minutes, preload, label="parts at their own temperatures")
bottom.axhline(steady, color="k", ls="--", label="every part at −40 °C")
bottom.set_xlabel("time after the chamber step [min]")
bottom.set_ylabel("preload [N]")
bottom.legend()
for ax in (top, bottom):
    ax.grid(True, alpha=0.3)
fig.tight_layout()

# %%
# The housing and the outer rings follow the chamber first, the shaft and the inner rings lag
# behind the balls' small conductance. The aluminium frame shrinks onto the steel shaft's
# loop faster than the shaft does, so the preload rises ahead of the parts' mean temperature
# and overshoots its soaked value slightly before it settles.
