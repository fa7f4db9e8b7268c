"""Friction torque of the seeker-gimbal bearing pair through a temperature ramp, with plain
fmpy: no servofmu import. Build the FMU first (``servofmu build``), then

    python examples/bearing_friction_temperature.py [build/out/BearingFriction.fmu] [out.png]

The temperature input ramps from −40 °C to +60 °C over 100 s at a constant low speed; the
plot shows the running torque and its viscous and geometric (hysteresis + spin) parts.
"""

import sys

import numpy as np
from fmpy import read_model_description, simulate_fmu

fmu = sys.argv[1] if len(sys.argv) > 1 else "build/out/BearingFriction.fmu"
png = sys.argv[2] if len(sys.argv) > 2 else "bearing_friction_temperature.png"

# input signal: a structured array with a time column and one column per input of the FMU
# (fmpy warns of an input without one); the inputs not ramped here keep their start values
t = np.array([0.0, 100.0])
ramped = {"temperature": [233.15, 333.15], "speed": [0.1745, 0.1745]}  # K; rad/s (10 °/s)
inputs = [v for v in read_model_description(fmu).modelVariables if v.causality == "input"]
signals = np.zeros(2, dtype=[("time", float)] + [(v.name, float) for v in inputs])
signals["time"] = t
for v in inputs:
    signals[v.name] = ramped.get(v.name, float(v.start))

# fmpy prints the FMU's errors (e.g. a temperature outside 173.15…473.15 K) and raises; a
# discarded step only ends the rows early: debug_logging=True prints every message, discards
# included (README, "Messages in plain fmpy")
result = simulate_fmu(
    fmu,
    stop_time=100.0,
    output_interval=0.5,
    input=signals,
    output=["running_torque", "viscous_torque", "hysteresis_torque", "spin_torque", "preload"],
    debug_logging=False,
)
temp_c = np.interp(result["time"], t, signals["temperature"]) - 273.15
print(f"{'T [°C]':>8} {'running [N·mm]':>15} {'viscous':>9} {'geometric':>10} {'preload [N]':>12}")
for i in range(0, len(result), 40):
    geo = result["hysteresis_torque"][i] + result["spin_torque"][i]
    print(
        f"{temp_c[i]:8.1f} {1e3 * result['running_torque'][i]:15.3f} "
        f"{1e3 * result['viscous_torque'][i]:9.3f} {1e3 * geo:10.3f} {result['preload'][i]:12.1f}"
    )

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(6.4, 4.2))
ax.semilogy(temp_c, 1e3 * result["running_torque"], label="running")
ax.semilogy(temp_c, 1e3 * result["viscous_torque"], label="viscous")
ax.semilogy(
    temp_c, 1e3 * (result["hysteresis_torque"] + result["spin_torque"]) + 1e-6, label="geometric"
)
ax.set_xlabel("temperature [°C]")
ax.set_ylabel("friction torque [N·mm]")
ax.legend()
fig.tight_layout()
fig.savefig(png)
print(f"plot: {png}")
