"""Documentation inside each FMU: rendered HTML with the equations (MathML), every parameter
with its provenance, the host requirements and a PNG of the FMU's characteristic curve,
computed by the FMU's own code; none of the artefacts that reStructuredText gives a docstring
written as plain text."""

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
    assert re.search(rf'<img [^>]*src="{doc.IMAGE}"', page)
    assert "<pre>" not in page  # docstrings are rendered, not pasted
    assert ":func:" not in page and ":class:" not in page  # Sphinx roles rendered as code
    assert "<h2>Equations</h2>" in page and "<h2>Host requirements</h2>" in page
    assert "LD_PRELOAD" in page and "numpy" in page
    cls = doc.slave_class(name)
    for v in cls.VARIABLES:
        assert re.search(rf"<td>(<p>)?{v.name}(</p>)?</td>", page), v.name
        if v.causality == "parameter":
            assert v.source, f"{name}.{v.name} has no provenance"
    # the provenance column follows each parameter's row
    first = next(v for v in cls.VARIABLES if v.causality == "parameter")
    row = re.search(rf"<tr>\s*<td>(<p>)?{first.name}(</p>)?</td>.*?</tr>", page, re.S).group(0)
    assert first.source.split(":")[0] in row


def test_bearing_page_renders_the_equations():
    page = doc.render("BearingFriction")
    assert "Yu eq 8" in page and "sliding_friction" in page and "calibrated" in page
    assert page.count('<math xmlns="http://www.w3.org/1998/Math/MathML" display="block">') > 20


def _paragraphs(page: str) -> list[str]:
    return [re.sub(r"\s+", " ", p) for p in re.findall(r"<p>(.*?)</p>", page, flags=re.S)]


@pytest.mark.parametrize("name", FMUS)
def test_page_has_math_and_no_rst_artefacts(name):
    """Every page renders without a docutils warning (strict), holds MathML and none of what
    reStructuredText makes of a docstring written as plain text: definition lists (a wrapped
    line followed by an indented one), block quotes (an indented formula, its lines run into
    one paragraph), list items glued to a paragraph, roles left raw, substitutions; and no
    paragraph twice, no note for developers."""
    page = doc.render(name, strict=True)
    assert "<math" in page and "</math>" in page
    assert "<dl" not in page  # definition lists: wrapped lines read as term + definition
    assert "<blockquote" not in page  # indented plain-text formulas
    assert "problematic" not in page and "system-message" not in page
    assert not re.search(r":(func|class|mod|meth|data|attr):`", page)
    assert not re.search(r"<p>- |<br />- |\n- [A-Za-z`]", page)  # a list item inside a paragraph
    text = re.sub(r"<[^>]+>", " ", page)
    assert not re.search(r"re-export|keeps working|\(tests/|issue \d+|commit [0-9a-f]{7}", text)
    outside_tables = re.sub(r"<table.*?</table>", "", page, flags=re.S)
    paragraphs = [p for p in _paragraphs(outside_tables) if len(p) > 60]
    assert len(paragraphs) == len(set(paragraphs)), "a paragraph appears twice"
    assert f"{name} FMU:" not in text  # the module's summary line repeats the description


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
    # below it the law is extrapolated (no published flow limit), not held: at -60 °C far
    # above, as Yu's eq 18 extrapolated gives (viscous torque × 17)
    assert running[0] > 10 * cold
    actuator = doc.CURVES["ActuatorStiffness"]()
    for _, k in actuator.series:
        assert np.all(np.diff(k) > 0)  # the Hertzian support bearings stiffen with load
    assert math.isclose(actuator.x[0], 10.0)
