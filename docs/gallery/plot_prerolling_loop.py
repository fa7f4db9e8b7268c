"""
Pre-rolling: Dahl's torque–angle loop
=====================================

BearingFriction with ``prerolling_model`` = 1 turned through a small angle and back, driven
through fmpy: the friction torque builds up from rest along T = T_c·(1 − e^(−σ₀θ/T_c)) and
traces a hysteresis loop at each reversal. ``prerolling_stiffness`` is set to a measured-like
1 N·m/rad so that the loop spans tens of microradians (the rest stiffness of the contacts,
about 9.7e3 N·m/rad for this pair at 20 °C, would squeeze it into 0.1 µrad). T_c is the FMU's
own torque without pre-rolling at that speed.
"""

import os

import matplotlib.pyplot as plt
import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

from servofmu.build.fmu import ensure_built

COARSE = os.environ.get("SERVOFMU_GALLERY") == "coarse"  # the site's quick build
SIGMA0 = 1.0  # N·m/rad
SPEED = 0.05  # rad/s
STEP = 2e-4 if COARSE else 5e-5  # s

fmu = str(ensure_built() / "BearingFriction.fmu")  # built into ./build/out on first use
md = read_model_description(fmu)
vr = {v.name: v.valueReference for v in md.modelVariables}
unzipped = extract(fmu)


def bearing(model: int) -> FMU2Slave:
    """An initialised instance at SPEED with prerolling_model = ``model``."""
    slave = FMU2Slave(
        guid=md.guid,
        unzipDirectory=unzipped,
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName=f"bearing{model}",
    )
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.setInteger([vr["prerolling_model"]], [model])
    slave.setReal([vr["prerolling_stiffness"], vr["speed"]], [SIGMA0, SPEED])
    slave.exitInitializationMode()
    return slave


off = bearing(0)
coulomb = off.getReal([vr["friction_torque"]])[0]  # T_c: the torque without pre-rolling
off.terminate()
off.freeInstance()
slave = bearing(1)

# out 600 µrad, back to −600 µrad, out again: each leg 1200 µrad against T_c/σ₀ ≈ 300 µrad
legs = [(SPEED, 600e-6), (-SPEED, 1200e-6), (SPEED, 1200e-6)]
t, angle, torque = 0.0, [0.0], [0.0]
for speed, span in legs:
    slave.setReal([vr["speed"]], [speed])
    for _ in range(round(span / (abs(speed) * STEP))):
        slave.doStep(t, STEP)
        t += STEP
        a, m = slave.getReal([vr["prerolling_angle"], vr["friction_torque"]])
        angle.append(a)
        torque.append(m)
slave.terminate()
slave.freeInstance()

angle, torque = 1e6 * np.array(angle), 1e3 * np.array(torque)  # µrad, N·mm
fig, ax = plt.subplots(figsize=(6.4, 4.2))
ax.plot(angle, torque, lw=1.2, label=f"BearingFriction, σ₀ = {SIGMA0:g} N·m/rad")
theta = np.linspace(0.0, 600.0, 200)
ax.plot(
    theta,
    1e3 * coulomb * (1.0 - np.exp(-SIGMA0 * 1e-6 * theta / coulomb)),
    "k--",
    lw=1.0,
    label="from rest: T_c·(1 − exp(−σ₀θ/T_c))",
)
ax.axhline(1e3 * coulomb, color="0.5", lw=0.8, ls=":")
ax.axhline(-1e3 * coulomb, color="0.5", lw=0.8, ls=":")
ax.set_xlabel("relative angle of the rings θ [µrad]")
ax.set_ylabel("friction torque [N·mm]")
ax.set_title("Dahl's pre-rolling loop of Yu's gimbal pair at 20 °C")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8, loc="lower right")
fig.tight_layout()

# %%
# The loop closes onto ±T_c (dotted) within a few T_c/σ₀; at each reversal the torque leaves
# ±T_c with the slope 2σ₀ — the stored elastic torque first unloads, then reloads the other
# way. A small oscillation about rest sees the slope σ₀: the rotor's Dahl resonance.
