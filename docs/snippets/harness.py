from servofmu.build.fmu import ensure_built
from servofmu.harness import Ramp, load_system, run

ssp = ensure_built() / "seeker_gimbal.ssp"  # builds FMUs and systems once into build/out
system = load_system(ssp)
try:
    res = run(
        system,
        parameters=["cold", {"controller.kp": 2.5}],  # a variant, then single values
        signals={"bearing.temperature": Ramp(0.2, 0.5, 233.15, 253.15)},  # K over s
        stop=0.5,
        record=["motor.speed", "motor.current", "bearing.running_torque", "bearing.temperature"],
    )
finally:
    system.close()
print(res["bearing.running_torque"][-1], res.data.dtype.names)
