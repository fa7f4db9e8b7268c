"""Trusted FMU states: a serialized state carries a checksum of its bytes, so that an altered
state is refused; every restored value is checked as a value set through the FMI calls would
be; an algebraic FMU recomputes its outputs after fmi2SetFMUstate.

The states here are crafted the way a tool that edits saved states would: the serialized
JSON is changed and, where the bytes carry a checksum, sealed again with the SHA-256 of the
new bytes (the format ``servofmu.fmus.runtime`` documents), so that what is tested is the
check of the values, not the checksum."""

from __future__ import annotations

import hashlib
import json
import math
import random
import re

import pytest
from fmpy.fmi1 import FMICallException
from fmu_helpers import Fmu

_SEAL = re.compile(rb', "sha256": "([0-9a-f]{64})"\}\Z')
_INPUTS = {
    "BearingFriction": dict(temperature=253.15, speed=0.2, axial_load=5.0),
    "DCMotor": dict(voltage=6.0, load_torque=2e-3),
    "ServoController": dict(reference=1.0, measurement=0.25),
    "ThermalNetwork": dict(ambient_temperature=253.15, power_loss=0.05),
}


def _stepped(fmus, name: str, steps: int = 5, h: float = 1e-3) -> Fmu:
    fmu = Fmu(fmus[name], name).init(**_INPUTS[name])
    for k in range(steps):
        fmu.slave.doStep(k * h, h)
    return fmu


def _blob(fmu: Fmu) -> bytes:
    state = fmu.slave.getFMUstate()
    blob = bytes(fmu.slave.serializeFMUstate(state))
    fmu.slave.freeFMUstate(state)
    return blob


def _record(blob: bytes) -> dict:
    """The state in ``blob`` (its checksum field left out)."""
    record = json.loads(blob)
    record.pop("sha256", None)
    return record


def _sealed(record: dict, like: bytes) -> bytes:
    """``record`` serialized as the FMU does (with the SHA-256 of the JSON bytes as a last
    field when ``like``, the FMU's own serialization, carries one)."""
    body = json.dumps(record, allow_nan=True).encode()
    if not _SEAL.search(like):
        return body
    return body[:-1] + b', "sha256": "' + hashlib.sha256(body).hexdigest().encode() + b'"}'


def _restore(fmu: Fmu, blob: bytes) -> tuple[int, str]:
    """(status, messages logged) of fmi2DeSerializeFMUstate + fmi2SetFMUstate of ``blob``."""
    n = len(fmu.log)
    try:
        state = fmu.slave.deSerializeFMUstate(blob)
        try:
            fmu.slave.setFMUstate(state)
        finally:
            fmu.slave.freeFMUstate(state)
        status = 0
    except FMICallException as exc:
        status = exc.status
    return status, " ".join(m for _, m in fmu.log[n:])


def test_one_digit_edits_of_a_state_are_all_refused(fmus):
    """100 one-digit edits of a BearingFriction state, anywhere in its bytes (values, hidden
    state, checksum): every one is refused with fmi2Error and a message."""
    fmu = _stepped(fmus, "BearingFriction")
    good = _blob(fmu)
    assert _restore(fmu, good)[0] == 0  # the unedited state restores
    digits = [i for i, c in enumerate(good) if chr(c).isdigit()]
    rng = random.Random(20240611)
    accepted = []
    for i in rng.sample(digits, 100):
        new = rng.choice([d for d in b"0123456789" if d != good[i]])
        edited = good[:i] + bytes([new]) + good[i + 1 :]
        status, said = _restore(fmu, edited)
        if status == 0:
            accepted.append(good[max(0, i - 30) : i + 10])
        else:
            assert status == 3 and said, (status, said)
    assert accepted == [], f"{len(accepted)} of 100 edited states accepted: {accepted[:5]}"
    fmu.close()


def test_the_checksum_is_of_the_bytes_themselves(fmus):
    """A state whose bytes change without changing its JSON values (a space) is refused too:
    the checksum is of the bytes; the same state sealed again is accepted."""
    fmu = _stepped(fmus, "DCMotor")
    good = _blob(fmu)
    if not _SEAL.search(good):
        pytest.fail("the serialized state carries no checksum")
    spaced = good.replace(b'"fmu": ', b'"fmu":  ', 1)
    status, said = _restore(fmu, spaced)
    assert status == 3 and "checksum" in said, said
    assert _restore(fmu, _sealed(_record(good), good))[0] == 0
    fmu.close()


@pytest.mark.parametrize(
    "name, where, field, value",
    [
        ("DCMotor", "values", "speed", 1e300),  # beyond initial_speed's range
        ("DCMotor", "values", "current", math.nan),
        ("DCMotor", "values", "motor_torque", 1e6),  # not k_t·current
        ("ServoController", "hidden", "derivative", math.inf),
        ("ServoController", "hidden", "integral", math.nan),
        ("ServoController", "values", "command", math.inf),
        ("ThermalNetwork", "values", "shaft_temperature", -5.0),
        ("ThermalNetwork", "values", "housing_temperature", math.inf),
        ("BearingFriction", "hidden", "prerolling", [math.nan, 0.0]),
        ("BearingFriction", "hidden", "prerolling", [0.0, 1e-3]),  # without pre-rolling
    ],
)
def test_a_restored_value_that_the_fmu_could_not_hold_is_refused(fmus, name, where, field, value):
    fmu = _stepped(fmus, name)
    good = _blob(fmu)
    before = fmu.real_outputs()
    record = _record(good)
    record[where][field] = value
    status, said = _restore(fmu, _sealed(record, good))
    assert status == 3, f"{name}: {field} = {value!r} restored with status {status}"
    assert field in said and "nothing restored" in said, said
    fmu.close()
    # the refusal left the instance's values as they were, and it goes on from a good state
    again = _stepped(fmus, name)
    assert _restore(again, good)[0] == 0 and again.real_outputs() == before
    again.slave.doStep(5e-3, 1e-3)
    again.close()


def test_an_input_restored_out_of_range_is_refused_at_the_next_step_as_if_set(fmus):
    """fmi2SetReal accepts any value and the step refuses one outside the range: a restored
    input is treated the same way."""
    fmu = _stepped(fmus, "DCMotor")
    good = _blob(fmu)
    record = _record(good)
    record["values"]["voltage"] = 5e3  # valid: [-1000, 1000] V
    assert _restore(fmu, _sealed(record, good))[0] == 0
    with pytest.raises(FMICallException, match="status 3"):
        fmu.slave.doStep(5e-3, 1e-3)
    assert "voltage = 5000.0 is outside the valid range" in fmu.log[-1][1], fmu.log[-1]
    fmu.close()


@pytest.mark.parametrize("read_first", [True, False])
def test_an_algebraic_fmu_recomputes_its_outputs_after_a_restored_state(fmus, read_first):
    """A friction_torque of 1e6 N·m in a state does not survive: the outputs are the
    model's for the restored inputs, read right away or after the next step."""
    fmu = _stepped(fmus, "BearingFriction")
    torque = fmu.get("friction_torque")
    good = _blob(fmu)
    record = _record(good)
    record["values"]["friction_torque"] = 1e6
    record["values"]["power_loss"] = 1e6
    assert _restore(fmu, _sealed(record, good))[0] == 0
    if read_first:
        assert fmu.get("friction_torque") == torque
    fmu.slave.doStep(5e-3, 1e-3)
    assert fmu.get("friction_torque") == torque
    assert fmu.get("power_loss") == pytest.approx(abs(torque * 0.2))
    fmu.close()


def test_a_motor_step_beyond_the_range_of_its_state_is_discarded_and_saved_states_restore(fmus):
    """The DCMotor's state stays within the ranges its initial_* parameters allow: a step
    that would leave them is discarded naming the variable, so that every state the FMU saved
    before can be restored."""
    fmu = Fmu(fmus["DCMotor"], "fast")
    fmu.init(voltage=1e3, back_emf_constant=1e-6, viscous_damping=0.0, inertia=1e-9)
    saved, t, h = None, 0.0, 1e-4
    with pytest.raises(FMICallException, match="status 2"):
        for _ in range(1000):
            saved = _blob(fmu)  # the state before the step
            fmu.slave.doStep(t, h)
            t += h
    assert "speed = " in fmu.log[-1][1] and "initial_speed: [-100000, 100000]" in fmu.log[-1][1]
    assert saved is not None and _restore(fmu, saved)[0] == 0
    assert abs(fmu.get("speed")) <= 1e5
    fmu.close()
