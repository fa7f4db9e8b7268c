"""
Three friction models
=====================

The same bearing pair under each of BearingFriction's friction models (``yu2017``,
``skf2004``, ``ehl_per_contact``), with and without a grease term calibrated on a grease
datasheet (Molykote G-1074's −40 °C torque). The model is one parameter set
(:mod:`servofmu.parameters.bearing`): changing ``friction_model`` changes the torque
equations only, every thermal effect stays the same.
"""

import os

import matplotlib.pyplot as plt
import numpy as np

from servofmu.parameters.bearing import default_parameters, pair_from_parameters
from servofmu.physics.bearing import BearingModel

COARSE = os.environ.get("SERVOFMU_GALLERY") == "coarse"  # the site's quick build
celsius = np.linspace(-50.0, 40.0, 10 if COARSE else 91)
speed = np.radians(10.0)  # rad/s

fig, ax = plt.subplots(figsize=(6.4, 4.2))
for model in ("yu2017", "skf2004", "ehl_per_contact"):
    params = default_parameters() | {"friction_model": model}
    torque = BearingModel(pair_from_parameters(params)).curves(celsius + 273.15, speed)
    ax.semilogy(celsius, 1e3 * np.asarray(torque.running_torque), label=model)
greased = default_parameters() | {"grease_f0": 10.9, "grease_starting_ratio": 1.98}
torque = BearingModel(pair_from_parameters(greased)).curves(celsius + 273.15, speed)
ax.semilogy(celsius, 1e3 * np.asarray(torque.running_torque), "k--", label="yu2017 + grease term")
ax.set_xlabel("temperature [°C]")
ax.set_ylabel("running torque [N·mm]")
ax.set_title("Yu's gimbal pair at 10 °/s")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()

# %%
# The grease term carries a full test bearing's datasheet torque to this pair by Palmgren's
# law: a pair packed full of a cold grease turns far harder than the base oil alone says,
# which is why instrument bearings are filled to 20–40 % (the term over-predicts them).
