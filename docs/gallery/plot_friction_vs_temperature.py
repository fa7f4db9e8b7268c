"""
Friction torque versus temperature
==================================

The running and breakaway torque of Yu's seeker-gimbal bearing pair (two 71803 in a
cast-aluminium yoke on a steel shaft, Krytox 143AA grease) from −60 to +80 °C at 10 °/s, and
the preload that the thermal coupling of frame, shaft and bearings leaves. The curve is the
exact, vectorised path of :class:`servofmu.physics.bearing.BearingModel`.
"""

import os

import matplotlib.pyplot as plt
import numpy as np

from servofmu.physics.bearing import BearingModel, BearingPair

COARSE = os.environ.get("SERVOFMU_GALLERY") == "coarse"  # the site's quick build
celsius = np.linspace(-60.0, 80.0, 15 if COARSE else 141)

pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
out = BearingModel(pair).curves(celsius + 273.15, speed=np.radians(10.0))  # K, rad/s

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 6.0))
top.semilogy(celsius, 1e3 * np.asarray(out.running_torque), label="running torque")
top.semilogy(celsius, 1e3 * np.asarray(out.breakaway_torque), label="breakaway torque")
top.semilogy(celsius, 1e3 * np.asarray(out.viscous_torque), "--", label="viscous part")
top.set_ylabel("torque [N·mm]")
top.legend()
top.grid(True, which="both", alpha=0.3)
bottom.plot(celsius, np.asarray(out.preload), color="C3")
bottom.set_xlabel("temperature [°C]")
bottom.set_ylabel("preload [N]")
bottom.grid(True, alpha=0.3)
fig.suptitle("71803 pair in Yu's gimbal, 10 °/s")
fig.tight_layout()

# %%
# The cold grease and the preload raised by the aluminium frame's shrinkage make the torque
# at −40 °C ten times the torque at 20 °C; above about 37 °C the shim's preload is lost
# (flag ``unloaded``) and only the viscous and the unloaded contacts' torque remain.
unloaded = celsius[np.asarray(out.unloaded, dtype=bool)]
print(f"preload lost from {unloaded.min():.0f} °C" if unloaded.size else "never unloaded")
