"""The Python examples of the README and the documentation run as written, and what they
compute obeys the equations they stand for: Yu eq 8 and eq 9 by hand for the bearing, Liu eq 1
and eq 6 for the actuator, Newton's law for the rotor (the electrical method) in the
co-simulation, and the plain-fmpy example shows the FMU's error and its discarded step."""

import contextlib
import io
import math
import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
#: Where the user reads Python examples: the README and the documentation's snippets
#: (docs/snippets/*.py, included in its pages).
SOURCES = (README, *sorted((ROOT / "docs" / "snippets").glob("*.py")))
KEYS = {
    "simulate_fmu(": "plain",
    "BearingModel(pair)": "bearing",
    "stiffness_breakdown(": "actuator",
    "run(": "harness",
    "tn.network(": "thermal",
    'friction_model="skf2004"': "friction",
}


def _blocks(path: Path) -> list[str]:
    text = path.read_text()
    return [text] if path.suffix == ".py" else re.findall(r"```python\n(.*?)```", text, flags=re.S)


@pytest.fixture(scope="module")
def runs():
    """Each distinct Python example of :data:`SOURCES` run once in its own namespace: {code:
    namespace}, and {key: [code, ...]} (the same example in several places runs once). The
    FMUs are built first into build/out, where the plain-fmpy example reads them."""
    from servofmu.build.fmu import ensure_built

    ensure_built()
    namespaces, by_key = {}, {k: [] for k in KEYS.values()}
    for path in SOURCES:
        for code in _blocks(path):
            (key,) = [k for marker, k in KEYS.items() if marker in code]
            if code not in namespaces:
                namespace, printed = {}, io.StringIO()
                with contextlib.redirect_stdout(printed):
                    exec(compile(code, str(path), "exec"), namespace)
                namespace["__printed__"] = printed.getvalue()
                namespaces[code] = namespace
            by_key[key].append(code)
    assert all(by_key.values()), by_key
    return namespaces, by_key


@pytest.fixture(scope="module", params=range(3), ids=lambda i: f"variant{i}")
def examples(request, runs):
    """The examples of one variant: for each key, the i-th distinct text of it (the last one
    when there are fewer), so that every distinct example is checked."""
    namespaces, by_key = runs
    out = {}
    for key, codes in by_key.items():
        distinct = list(dict.fromkeys(codes))
        out[key] = namespaces[distinct[min(request.param, len(distinct) - 1)]]
    return out


def test_bearing_example_follows_yu_eq_8_and_9(examples):
    ns = examples["bearing"]
    out, pair = ns["out"], ns["pair"]
    assert f"{out.friction_torque} {out.preload}" in ns["__printed__"]
    # eq 9: the running torque is the sum of its parts; at 0.17 rad/s, far above the 1 mrad/s
    # regularisation, the signed friction torque is the running torque
    parts = out.hysteresis_torque + out.spin_torque + out.sliding_torque + out.viscous_torque
    assert out.running_torque == pytest.approx(parts, rel=1e-12)
    assert out.friction_torque == pytest.approx(out.running_torque, rel=1e-6)
    # eq 8 by hand for the pair at −20 °C: Walther with Yu eq 18's a = 9.597, b = 3.773,
    # c = 0.932 cSt gives ν; n = 0.17 rad/s = 1.623 rpm; dm = (17 + 26)/2 mm for the 71803;
    # s0 of the example's coefficients; M = 2·1e-7·s0·(ν·n)^(2/3)·dm³ N·mm (ν·n ≥ 2000)
    nu = 10 ** (10 ** (9.597 - 3.773 * math.log10(253.15))) - 0.932
    assert out.kinematic_viscosity == pytest.approx(nu * 1e-6, rel=1e-9)
    n = 0.17 * 60 / (2 * math.pi)
    assert nu * n >= 2000
    s0 = pair.coefficients.palmgren_s0
    viscous = 2 * 1e-7 * s0 * (nu * n) ** (2 / 3) * 21.5**3 * 1e-3
    # (the model takes dm of the cooled, mounted bearing: 0.1 % smaller, dm³ 0.2 %)
    assert out.viscous_torque == pytest.approx(viscous, rel=5e-3)
    assert out.preload > 0 and not out.overloaded
    # the curve over 233…333 K: eq 8 falls with the viscosity while ν·n ≥ 2000 and is the
    # speed-independent floor 2·1e-7·s0·2000^(2/3)·dm³ above that temperature
    temps = np.linspace(233.15, 333.15, 101)
    nu_n = (10 ** (10 ** (9.597 - 3.773 * np.log10(temps))) - 0.932) * n
    curve = np.asarray(ns["curves"].viscous_torque)
    thick = nu_n >= 2000
    assert thick[0] and not thick[-1]
    assert np.all(np.diff(curve[thick]) < 0)
    floor = 2 * 1e-7 * s0 * 2000 ** (2 / 3) * 21.5**3 * 1e-3
    np.testing.assert_allclose(curve[~thick], floor, rtol=5e-3)


def test_actuator_example_follows_liu_eq_1_and_6(examples):
    ns = examples["actuator"]
    b, ema = ns["b"], ns["ema"]
    assert ns["__printed__"].strip()
    elements = [np.asarray(getattr(b, e)) for e in b.ELEMENTS]
    # eq 6: the elements in series, and the compliance shares add up to one
    np.testing.assert_allclose(1 / b.total, sum(1 / k for k in elements), rtol=1e-12)
    np.testing.assert_allclose(sum(b.share(e) for e in b.ELEMENTS), 1.0, rtol=1e-12)
    np.testing.assert_allclose(b.deflection, np.array([100.0, 300.0]) / b.total, rtol=1e-12)
    # eq 1: i = i_g·(2π·L1/p)·i_r
    ratio = ns["reduction_ratio"](ema, 0.17)
    i_s = 2 * math.pi * ema.crank_length / ema.screw_lead
    assert ratio.total == pytest.approx(ema.gear_ratio * i_s * ratio.linkage, rel=1e-12)
    assert ns["per_degree"](b.total) == pytest.approx(b.total * math.pi / 180, rel=1e-12)
    # the Hertzian support pair stiffens with load (Liu's own elements are linear)
    assert b.total[1] > b.total[0]


def test_harness_example_obeys_newtons_law(examples):
    ns = examples["harness"]
    res = ns["res"]
    assert ns["__printed__"].strip()
    t, w, i = res["time"], res["motor.speed"], res["motor.current"]
    temp, friction = res["bearing.temperature"], res["bearing.running_torque"]
    # the ramp of the example: 233.15 K until 0.2 s, then 20 K in 0.3 s (a row holds the
    # value set one 1 ms step before)
    assert np.all(temp[t <= 0.2] == 233.15)
    assert np.all(np.diff(temp) >= 0) and temp.max() <= 253.15
    assert temp[-1] == pytest.approx(253.15 - 20 / 0.3 * 1e-3, rel=1e-9)
    # J·dω/dt = k_t·i − T_friction − b·ω while the rotor turns forward (the motor's ssv:
    # J = 2e-4 kg·m², k_t = 0.05 N·m/A, b = 1e-5 N·m·s/rad)
    from servofmu.harness import load_system

    system = load_system(ns["ssp"])
    try:
        p = {k: v[1] for k, v in system.components["motor"].parameters.items()}
    finally:
        system.close()
    turning = (t > 0.3) & (w > 0)
    assert turning.sum() > 100
    inertia = p["inertia"] * np.gradient(w, t)
    balance = p["torque_constant"] * i - friction - p["viscous_damping"] * w - inertia
    assert np.max(np.abs(balance[turning])) < 0.01 * np.max(p["torque_constant"] * i[turning])
    # colder grease, larger friction: −40 °C at the start against −20 °C at the end
    assert friction[t < 0.2].mean() > 1.5 * friction[-10:].mean()


def test_friction_model_example_adds_up(examples):
    # SKF: running = rolling + sliding (no per-contact terms), starting = Msl at rest; EHL with
    # the grease term: running = hysteresis + spin + rolling + grease
    ns = examples["friction"]
    out, cold = ns["out"], ns["cold"]
    assert out.hysteresis_torque == out.spin_torque == 0.0
    assert out.running_torque == pytest.approx(out.viscous_torque + out.sliding_torque, rel=1e-12)
    assert 0.0 < out.breakaway_torque < out.running_torque
    parts = cold.hysteresis_torque + cold.spin_torque + cold.sliding_torque
    parts += cold.viscous_torque + cold.grease_torque
    assert cold.running_torque == pytest.approx(parts, rel=1e-12)
    assert f"{cold.viscous_torque} {cold.grease_torque}" in ns["__printed__"]


def test_plain_fmpy_example_shows_the_error_and_the_discarded_step(examples):
    from servofmu.build.exportlib import compiled_export

    ns = examples["plain"]
    discards = [m for s, m in ns["messages"] if s == 2]
    assert set(ns["result"]["time"]) == {0.0}  # the rows end where the discarded step began
    assert discards and "one step takes at most 100000" in discards[-1], ns["messages"]
    if compiled_export() is not None:  # servofmu's export: the error raised (and printed)
        assert "fmi2ExitInitializationMode failed with status 3" in ns["__printed__"]


def test_every_snippet_is_shown_in_a_page():
    # the snippets run above are the ones a reader sees: each is included by a docs page
    pages = [*ROOT.joinpath("docs").glob("*.md"), *ROOT.joinpath("docs", "guide").glob("*.md")]
    included = {
        name
        for page in pages
        for name in re.findall(r"```\{literalinclude\} [./]*snippets/(\S+\.py)", page.read_text())
    }
    snippets = {p.name for p in SOURCES if p.suffix == ".py"}
    assert snippets and snippets <= included, snippets - included
