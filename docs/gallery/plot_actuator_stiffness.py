"""
Actuator stiffness versus hinge moment
======================================

Liu's electromechanical actuator (gear train, ball screw, crank-slider, housing) with the
screw's preloaded support bearings, at the output shaft: the stiffness and each element's
share of the compliance versus the hinge moment, at two temperatures.
"""

import os

import matplotlib.pyplot as plt
import numpy as np

from servofmu.physics.drives.actuator import Actuator, per_degree, stiffness_breakdown

COARSE = os.environ.get("SERVOFMU_GALLERY") == "coarse"  # the site's quick build
moments = np.linspace(20.0, 300.0, 8 if COARSE else 57)  # N·m
ema = Actuator.from_catalog("liu2014_ema")

fig, (left, right) = plt.subplots(1, 2, figsize=(9.0, 3.8))
for celsius in (-40.0, 20.0):
    b = stiffness_breakdown(ema, output_angle=np.radians(10.0), load_torque=moments,
                            temperature=celsius + 273.15)  # fmt: skip
    left.plot(moments, per_degree(b.total), label=f"{celsius:+.0f} °C")
b = stiffness_breakdown(ema, np.radians(10.0), moments, 293.15)
for element in b.ELEMENTS:
    right.plot(moments, 100 * np.asarray(b.share(element)), label=element)
left.set_xlabel("hinge moment [N·m]")
left.set_ylabel("stiffness at the output [N·m/°]")
left.legend()
right.set_xlabel("hinge moment [N·m]")
right.set_ylabel("share of the compliance at 20 °C [%]")
right.legend(fontsize=7)
for ax in (left, right):
    ax.grid(True, alpha=0.3)
fig.tight_layout()

# %%
# Liu's own elements are linear in the load; the Hertzian support bearings stiffen with it,
# which is what makes the actuator stiffer at larger hinge moments.
