"""Documentation inside each FMU (issue 15): rendered HTML with the equations, every
parameter with its provenance, the host requirements and a PNG of the FMU's characteristic
curve, computed by the FMU's own code."""

from __future__ import annotations

import math
import re
import zipfile

import numpy as np
import pytest

from servofmu.build import documentation as doc
from servofmu.build.fmu import FMUS

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("name", FMUS)
def test_every_fmu_carries_a_rendered_page_and_its_curve(fmus, name):
    with zipfile.ZipFile(fmus[name]) as zf:
        page = zf.read("documentation/index.html").decode()
        image = zf.read(f"documentation/{doc.IMAGE}")
    assert image.startswith(PNG) and len(image) > 10_000
    assert f'<img src="{doc.IMAGE}"' in page
    assert "<pre>" not in page  # docstrings are rendered, not pasted
    assert ":func:" not in page and ":class:" not in page  # Sphinx roles rendered as code
    assert "<h2>Equations</h2>" in page and "<h2>Host requirements</h2>" in page
    assert "LD_PRELOAD" in page and "numpy" in page
    cls = doc.slave_class(name)
    for v in cls.VARIABLES:
        assert f"<td>{v.name}</td>" in page, v.name
        if v.causality == "parameter":
            assert v.source, f"{name}.{v.name} has no provenance"
    # the provenance column follows each parameter's row
    first = next(v for v in cls.VARIABLES if v.causality == "parameter")
    row = re.search(rf"<tr><td>{first.name}</td>.*?</tr>", page).group(0)
    assert first.source.split(":")[0] in row


def test_bearing_page_renders_the_equations():
    page = doc.render("BearingFriction")
    assert "Yu eq 8" in page and "sliding_friction" in page and "calibrated" in page
    assert "<blockquote>" in page  # the indented equations of the docstrings


def test_curves_carry_units_on_both_axes():
    for name, make in doc.CURVES.items():
        curve = make()
        for label in (curve.xlabel, curve.ylabel):
            assert re.search(r"\[.+\]", label), f"{name}: {label!r} has no unit"
        if curve.right is not None:
            assert re.search(r"\[.+\]", curve.right[0])
        for _, y in curve.series:
            assert y.shape == curve.x.shape and np.all(np.isfinite(y))


def test_motor_curve_settles_at_the_steady_state_speed():
    """A 1 V step from rest: ω∞ = k_t·V/(R·b + k_t·k_e) (no load); after 5 mechanical time
    constants within 1 %; the current starts at 0 and peaks near V/R."""
    p = {v.name: v.start for v in doc.slave_class("DCMotor").VARIABLES}
    curve = doc.CURVES["DCMotor"]()
    names = ("torque_constant", "back_emf_constant", "resistance", "viscous_damping")
    kt, ke, r, b = (p[k] for k in names)
    steady = kt * 1.0 / (r * b + kt * ke)
    speed = curve.series[0][1]
    assert speed[0] == 0.0 and speed[-1] == pytest.approx(steady, rel=0.01)
    current = curve.right[2]
    assert current[0] == 0.0 and max(current) == pytest.approx(1.0 / r, rel=0.05)


def test_controller_curve_is_proportional_step_integral_ramp_and_limit():
    p = {v.name: v.start for v in doc.slave_class("ServoController").VARIABLES}
    curve = doc.CURVES["ServoController"]()
    t, command = curve.x, curve.series[0][1]
    at_1s = command[np.searchsorted(t, 1.0)]
    # the integral of the samples before t (one sample behind the continuous ramp)
    ramp = p["kp"] + p["ki"] * 1.0
    assert at_1s == pytest.approx(ramp - p["ki"] * p["sample_period"], rel=1e-12)
    assert max(command) == p["output_max"] and command[-1] == p["output_max"]


def test_bearing_and_actuator_curves_have_the_physical_trends():
    bearing = doc.CURVES["BearingFriction"]()
    running = bearing.series[0][1]
    cold = running[bearing.x == -40.0][0]  # the lower end of Krytox 143AA's data
    assert cold > 10 * running[-1]  # cold grease and preload: far above the warm torque
    # below it the viscosity is held: the torque moves with the fits and preload only
    assert running[0] < 1.5 * cold
    actuator = doc.CURVES["ActuatorStiffness"]()
    for _, k in actuator.series:
        assert np.all(np.diff(k) > 0)  # the Hertzian support bearings stiffen with load
    assert math.isclose(actuator.x[0], 10.0)
