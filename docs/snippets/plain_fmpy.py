import numpy as np
from fmpy import simulate_fmu

# a temperature given in °C where kelvin are asked: fmpy prints the FMU's error
#   [ERROR] BearingFriction: fmi2ExitInitializationMode: temperature = 20.0 is outside ...
celsius = np.array([(0.0, 20.0), (1.0, 20.0)], dtype=[("time", float), ("temperature", float)])
try:
    simulate_fmu("build/out/BearingFriction.fmu", stop_time=1.0, input=celsius)
except Exception as exc:
    print(exc)  # fmi2ExitInitializationMode failed with status 3 (error).

messages = []


def keep(component, instance, status, category, message):
    messages.append((status, message.decode()))


# a 20 s step is more than DCMotor takes at once (10 s): discarded, the run ends at t = 0
result = simulate_fmu(
    "build/out/DCMotor.fmu", stop_time=40.0, output_interval=20.0, debug_logging=True, logger=keep
)
print(result["time"])  # [0. 0.]: the rows end where the discarded step began
print([m for s, m in messages if s == 2])  # status 2, fmi2Discard: "DCMotor: ... at most 100000"
