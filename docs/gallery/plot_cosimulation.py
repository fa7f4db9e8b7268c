"""
A co-simulation of the seeker gimbal
====================================

The ``seeker_gimbal`` SSP system (controller → DC motor ↔ bearing friction, 1 ms steps) run by
servofmu's fmpy harness while the chamber warms from −40 to −20 °C: the speed loop holds
10 °/s, and the motor current follows the bearing's running torque (Yu's electrical method:
torque = k_t·i). The FMUs are built into ``./build/out`` on first use.
"""

import os

import matplotlib.pyplot as plt

from servofmu.build.fmu import ensure_built
from servofmu.harness import Ramp, load_system, run

COARSE = os.environ.get("SERVOFMU_GALLERY") == "coarse"  # the site's quick build
stop = 1.0 if COARSE else 4.0  # s

system = load_system(ensure_built() / "seeker_gimbal.ssp")
try:
    res = run(
        system,
        signals={"bearing.temperature": Ramp(0.2, stop - 0.2, 233.15, 253.15)},  # K over s
        stop=stop,
        record=["motor.speed", "motor.current", "bearing.running_torque", "bearing.temperature"],
    )
finally:
    system.close()

fig, axes = plt.subplots(3, 1, sharex=True, figsize=(6.4, 6.4))
axes[0].plot(res["time"], res["bearing.temperature"] - 273.15)
axes[0].set_ylabel("chamber [°C]")
axes[1].plot(res["time"], res["motor.speed"] * 180 / 3.141592653589793)
axes[1].set_ylabel("speed [°/s]")
axes[2].plot(res["time"], 1e3 * res["bearing.running_torque"], label="bearing running torque")
axes[2].plot(res["time"], 1e3 * 0.05 * res["motor.current"], "--", label="k_t·i")
axes[2].set_ylabel("torque [N·mm]")
axes[2].set_xlabel("time [s]")
axes[2].legend()
for ax in axes:
    ax.grid(True, alpha=0.3)
fig.tight_layout()

# %%
# ``k_t = 0.05 N·m/A`` is the motor's torque constant in the system's parameter set; once the
# speed has settled, k_t·i differs from the bearing torque only by the rotor's viscous
# damping and its acceleration.
