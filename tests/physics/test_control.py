"""The discrete PID (physics.drives.control and the ServoController FMU) against values stepped by
hand from the law in the module docstring (Åström & Hägglund 2006, ch. 3):

    e_k = r_k − y_k,  D_k = (T_f·D_{k−1} − K_d·(y_k − y_{k−1}))/(T_f + T_s),
    v_k = K_p·e_k + I_k + D_k,  u_k = clip(v_k),  I_{k+1} = I_k + K_i·T_s·e_k unless winding up.
"""

import re

import pytest
from fmu_helpers import Fmu

from servofmu.physics.drives.control import PIDParameters, PIDState, pid_sample

#: K_p = 2, K_i = 10 /s, K_d = 0.01 s, T_f = T_s = 1 ms
GAINS = dict(kp=2.0, ki=10.0, kd=0.01, derivative_filter=1e-3, sample_period=1e-3)
#: (r_k, y_k) and u_k stepped by hand:
#:  k=0: e=1,   D=0 (no previous y),            v=2·1 + 0 + 0          = 2,     I1=0.01
#:  k=1: e=0.9, D=(0 − 0.01·0.1)/0.002 = −0.5,   v=1.8 + 0.01 − 0.5     = 1.31,  I2=0.019
#:  k=2: e=0.7, D=(−0.0005 − 0.002)/0.002 = −1.25, v=1.4 + 0.019 − 1.25 = 0.169, I3=0.026
#:  k=3: e=0.7, D=(−0.00125 − 0)/0.002 = −0.625, v=1.4 + 0.026 − 0.625  = 0.801, I4=0.033
#:  k=4: r steps to 2 (no derivative kick): e=1.7, D=−0.3125, v=3.4+0.033−0.3125 = 3.1205
HAND = [
    ((1.0, 0.0), 2.0),
    ((1.0, 0.1), 1.31),
    ((1.0, 0.3), 0.169),
    ((1.0, 0.3), 0.801),
    ((2.0, 0.3), 3.1205),
]


def test_pid_samples_by_hand():
    p, s = PIDParameters(mode="position", **GAINS), PIDState()
    for (r, y), u in HAND:
        got, s = pid_sample(p, s, r, y)
        assert got == pytest.approx(u, rel=1e-12, abs=1e-15)
    assert s.integral == pytest.approx(0.033 + 10 * 1e-3 * 1.7)


def test_clamping_anti_windup_by_hand():
    # K_p = 0.5, K_i = 100 /s, T_s = 1 ms, limit 1 V; e = 1 for eight samples, then −1:
    # v = 0.5, 0.6, …, 1.0 (I grows by 0.1 a sample), then 1.1 → u = 1 and I stays at 0.6;
    # at e = −1: v = −0.5 + 0.6 = 0.1 (a wound-up I of 0.8 would give 0.3)
    p = PIDParameters(kp=0.5, ki=100.0, output_min=-1.0, output_max=1.0, sample_period=1e-3)
    s, commands = PIDState(), []
    for e in [1.0] * 8 + [-1.0]:
        u, s = pid_sample(p, s, e, 0.0)
        commands.append(u)
    assert commands == pytest.approx([0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.0, 1.0, 0.1], abs=1e-12)
    assert s.integral == pytest.approx(0.5)
    # the lower limit likewise
    s = PIDState()
    for _ in range(8):
        u, s = pid_sample(p, s, -1.0, 0.0)
    assert u == -1.0 and s.integral == pytest.approx(-0.6)


def test_bad_parameters_name_the_value():
    with pytest.raises(ValueError, match=re.escape("mode = 'torque'")):
        PIDParameters(mode="torque")
    with pytest.raises(ValueError, match=re.escape("kp = -1.0")):
        PIDParameters(kp=-1.0)
    with pytest.raises(ValueError, match=re.escape("output_min = 2.0 V must be below")):
        PIDParameters(output_min=2.0, output_max=1.0)


def test_fmu_samples_by_hand(fmus):
    # one sample per 1 ms communication step, the inputs set before the step
    fmu = Fmu(fmus["ServoController"], "hand").init(reference=1.0, measurement=0.0, **GAINS)
    assert fmu.get("command") == pytest.approx(2.0)  # the first sample's command, at once
    t = 0.0
    for (r, y), u in HAND:
        fmu.set(reference=r, measurement=y)
        fmu.slave.doStep(t, 1e-3)
        t += 1e-3
        assert fmu.get("command") == pytest.approx(u, rel=1e-12, abs=1e-15)
    fmu.close()


def test_fmu_holds_the_command_between_samples(fmus):
    # T_s = 2 ms with 1 ms steps: samples at 0, 2, 4 ms see the inputs of those steps only
    gains = dict(GAINS, sample_period=2e-3)
    fmu = Fmu(fmus["ServoController"], "hold").init(reference=1.0, measurement=0.0, **gains)
    ys = [0.0, 0.5, 0.1, 0.5, 0.3]  # 0.5 is set only between samples: never seen
    got, t = [], 0.0
    for y in ys:
        fmu.set(measurement=y)
        fmu.slave.doStep(t, 1e-3)
        t += 1e-3
        got.append(fmu.get("command"))
    # k=0: 2; k=1 (y=0.1, T_s = 2 ms): D = (0 − 0.001)/0.003 = −1/3, I1 = 0.02,
    #       v = 1.8 + 0.02 − 1/3; k=2 (y=0.3): D = (−0.001/3 − 0.002)/0.003, I2 = 0.038
    u1 = 1.8 + 0.02 - 1 / 3
    u2 = 1.4 + 0.038 + (-0.001 / 3 - 0.002) / 0.003
    assert got == pytest.approx([2.0, 2.0, u1, u1, u2], rel=1e-12)
    fmu.close()
