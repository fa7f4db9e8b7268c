"""The thermal network of a bearing mechanism: hand-computed cases, exact
stepping of stiff networks, the radiation linearisation against a fine ODE solution, the
parameters derived from the catalogue, and the ThermalNetwork FMU."""

import doctest
import math

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmu_helpers import Fmu
from kernels import implementations
from scipy.integrate import quad, solve_ivp

from servofmu.parameters import catalog
from servofmu.physics import compiled
from servofmu.physics.materials import Material
from servofmu.physics.thermal import network as tn

SIGMA = 5.670374419e-8
OUTPUTS = (
    "housing_temperature",
    "shaft_temperature",
    "outer_ring_temperature",
    "inner_ring_temperature",
)


def test_docstring_examples_run():
    result = doctest.testmod(tn)
    assert result.attempted > 10 and result.failed == 0


# ---------------------------------------------------------------------------- hand computations
def two_nodes(radiation=0.0):
    """Node a (C1 = 100 J/K) to the ambient through G1 = 2 W/K, node b (C2 = 10 J/K) to a
    through G2 = 0.5 W/K, the heat input into b."""
    return tn.ThermalNetwork(
        capacities=(100.0, 10.0),
        links=((0, 1, 0.5),),
        ambient=(2.0, 0.0),
        sink_radiation=(radiation, 0.0),
        heat_split=(0.0, 1.0),
        nodes=("a", "b"),
    )


def test_two_node_steady_state_and_time_constants_by_hand():
    net = two_nodes()
    # steady: all of P = 3 W leaves through G1 and passes G2: T_a = 280 + 3/2, T_b = T_a + 3/0.5
    assert tn.steady_state(net, 280.0, 0.0, 3.0) == pytest.approx([281.5, 287.5], abs=1e-9)
    # λ² + (G1/C1 + G2/C1 + G2/C2)·λ + G1·G2/(C1·C2) = 0
    b = 2.0 / 100 + 0.5 / 100 + 0.5 / 10  # 0.075 1/s
    c = 2.0 * 0.5 / (100 * 10)  # 1e-3 1/s²
    root = math.sqrt(b * b - 4 * c)
    hand = sorted([2.0 / (b - root), 2.0 / (b + root)], reverse=True)  # τ = −1/λ
    assert hand == pytest.approx([57.656, 17.344], abs=1e-3)
    assert tn.time_constants(net) == pytest.approx(hand, rel=1e-12)


def test_two_node_step_response_is_the_modal_solution():
    # from rest at the ambient, 3 W switched on: T(t) = T_ss + c1·v1·e^(λ1 t) + c2·v2·e^(λ2 t)
    net = two_nodes()
    b, c = 0.075, 1e-3
    lam = [(-b + math.sqrt(b * b - 4 * c)) / 2, (-b - math.sqrt(b * b - 4 * c)) / 2]
    # eigenvectors of [[−G12/C1, G2/C1], [G2/C2, −G2/C2]]: v = (1, (λ + 0.025)/0.005)
    vecs = [np.array([1.0, (lm + 0.025) / 0.005]) for lm in lam]
    start_offset = np.array([280.0, 280.0]) - np.array([281.5, 287.5])
    coef = np.linalg.solve(np.column_stack(vecs), start_offset)
    for h in (0.01, 7.0, 400.0):  # far below, near and far above the time constants
        got = tn.step(net, [280.0, 280.0], 280.0, 0.0, 3.0, h)
        hand = np.array([281.5, 287.5]) + sum(
            k * v * math.exp(lm * h) for k, v, lm in zip(coef, vecs, lam, strict=True)
        )
        np.testing.assert_allclose(got, hand, rtol=0, atol=1e-10)


def test_one_node_radiation_steady_state_by_hand():
    # ε·A = 0.01 m² to a 100 K sink, 2 W/K to 300 K air, no power: G·(Ta − T) = σεA(T⁴ − Ts⁴)
    net = two_nodes(radiation=0.01)
    t = tn.steady_state(net, 300.0, 100.0, 0.0)
    ta = t[0]
    assert 2.0 * (300.0 - ta) == pytest.approx(SIGMA * 0.01 * (ta**4 - 100.0**4), rel=1e-9)
    assert t[1] == pytest.approx(ta, abs=1e-9)  # no heat through b


# ---------------------------------------------------------------------------- stiff and exact
def stiff_network():
    """The four nodes with ring capacities of 1 mJ/K on 100 W/K links: time constants of about
    5 µs next to the frame's minutes."""
    return tn.ThermalNetwork(
        capacities=(150.0, 90.0, 1e-3, 1e-3),
        links=((0, 2, 100.0), (2, 3, 100.0), (3, 1, 100.0), (0, 1, 0.01)),
        ambient=(0.3, 0.0, 0.0, 0.0),
        sink_radiation=(0.0, 0.0, 0.0, 0.0),
        heat_split=(0.0, 0.0, 0.5, 0.5),
    )


def test_stiff_network_steps_exactly_far_above_its_time_constants():
    net = stiff_network()
    taus = tn.time_constants(net)
    assert min(taus) < 1e-5 and max(taus) > 100.0
    a = -tn.conductance_matrix(net) / np.array(net.capacities)[:, None]
    inputs = (
        np.array([0.3, 0, 0, 0]) / net.capacities * 330.0
        + np.array([0, 0, 0.5, 0.5]) / net.capacities * 2.0
    )
    ref = solve_ivp(
        lambda t, x: a @ x + inputs,
        (0, 3000),
        [250.0] * 4,
        method="Radau",
        rtol=1e-12,
        atol=1e-10,
        jac=lambda t, x: a,
        dense_output=True,
    )
    x = [250.0] * 4
    for k in range(50):  # 60 s steps, 10^7 times the shortest time constant
        x = tn.step(net, x, 330.0, 0.0, 2.0, 60.0)
        np.testing.assert_allclose(x, ref.sol(60.0 * (k + 1)), rtol=0, atol=1e-7)
    # and the steady state is reached exactly: K·T = G_a·T_a + P (linear solve by hand)
    k_mat = tn.conductance_matrix(net)
    exact = np.linalg.solve(k_mat, np.array([0.3 * 330.0, 0, 1.0, 1.0]))
    for _ in range(1000):  # 60000 s: 75 of the longest time constant (800 s)
        x = tn.step(net, x, 330.0, 0.0, 2.0, 60.0)
    np.testing.assert_allclose(x, exact, rtol=1e-12)


def test_stiff_network_with_radiation_matches_a_stiff_ode_solution():
    # a strong radiator on the frame (ε·A = 0.02 m², 0.08 W/K at 260 K): the stiff rings are
    # still exact, what remains is the second-order linearisation error of the radiation
    net = tn.ThermalNetwork(**{**vars(stiff_network()), "sink_radiation": (0.02, 0.0, 0.0, 0.0)})
    ref = tn.ode_solution(net, [250.0] * 4, 330.0, 200.0, 2.0, 1200.0)
    worst = {}
    for h in (60.0, 6.0):
        x, worst[h] = [250.0] * 4, 0.0
        for k in range(round(1200 / h)):
            x = tn.step(net, x, 330.0, 200.0, 2.0, h)
            worst[h] = max(worst[h], float(np.abs(np.array(x) - ref(h * (k + 1))).max()))
    assert worst[60.0] < 5e-3 and worst[6.0] < 5e-5  # measured 3.7e-3 and 3.6e-5 K
    assert 70 < worst[60.0] / worst[6.0] < 130  # second order: 10² = 100


def radiation_error(key, h, tolerance, horizon=3600.0):
    """Largest deviation [K] of the stepped preset from a 1e-11 Radau solution after the
    ambient and the sink jump from −60 to +80 °C (0.05 W of bearing loss), and the number of
    linearisations used."""
    net = tn.network(tn.preset(key))
    start = tn.steady_state(net, 213.15, 213.15, 0.0)
    ref = tn.ode_solution(net, start, 353.15, 353.15, 0.05, horizon)
    x, reference, renewals, worst = list(start), None, 0, 0.0
    for k in range(round(horizon / h)):
        if (
            reference is None
            or max(abs(a - b) for a, b in zip(x, reference, strict=True)) > tolerance
        ):
            reference, renewals = tuple(x), renewals + 1
        x = tn.step_unchecked(net, x, 353.15, 353.15, 0.05, h, reference)
        worst = max(worst, float(np.abs(np.array(x) - ref(h * (k + 1))).max()))
    return worst, renewals


def test_radiation_linearisation_error_is_second_order_and_small():
    # measured (README): 5.4e-5 K at 10 s, 2.0e-3 K at 60 s steps (Ning, per-step linearisation)
    e10, _ = radiation_error("ning_space_vacuum", 10.0, 0.0)
    e60, _ = radiation_error("ning_space_vacuum", 60.0, 0.0)
    assert e10 < 1e-4 and e60 < 5e-3
    assert 25.0 < e60 / e10 < 45.0  # second order: (60/10)² = 36


def test_linearisation_tolerance_adds_little_and_saves_most_exponentials():
    exact, n_exact = radiation_error("ning_space_vacuum", 1.0, 0.0, horizon=1200.0)
    held, n_held = radiation_error("ning_space_vacuum", 1.0, 0.1, horizon=1200.0)
    assert n_exact == 1200 and n_held < 0.5 * n_exact  # the first 20 min move fastest
    assert exact < 1e-6 and held < 5e-6


def _rates_by_hand(net, t, ambient, sink, power):
    """dT/dt [K/s] of the module docstring's balance, written out with numpy (the oracle)."""
    t = np.asarray(t)
    c = np.asarray(net.capacities)
    q = -tn.conductance_matrix(net) @ t + np.asarray(net.ambient) * ambient
    q += np.asarray(net.heat_split) * power
    q -= tn.STEFAN_BOLTZMANN * np.asarray(net.sink_radiation) * (t**4 - sink**4)
    for i, j, e in net.exchange:
        flux = tn.STEFAN_BOLTZMANN * e * (t[i] ** 4 - t[j] ** 4)
        q[i] -= flux
        q[j] += flux
    return q / c


@pytest.mark.parametrize("key", tn.PRESETS)
def test_stepping_kernels_agree_bit_for_bit_and_with_the_balance_by_hand(key):
    # the ThermalNetwork FMU's per-step call (both implementations) against the exact path's
    # step_unchecked (bit for bit: the same arithmetic in the same order), and the rates and
    # the step against the balance written out with numpy
    net = tn.network(tn.preset(key))
    steppers = {impl: tn.stepper(net, impl) for impl in implementations()}
    refs = dict.fromkeys(steppers)
    t = tuple(tn.steady_state(net, 253.15, 233.15, 0.5))
    exps = 0
    for k in range(400):
        ambient, sink = 253.15 + 40.0 * math.sin(k / 30.0), 200.0 + 0.1 * k
        power, h = 0.1 + 0.05 * (k % 7), (1e-3, 0.5, 10.0)[k % 3]
        results = {}
        for impl, s in steppers.items():
            new, refs[impl], bad, outside = s.advance(
                t, ambient, sink, power, h, refs[impl], 0.1, 173.15, 473.15
            )
            assert bad == -1 and not outside
            results[impl] = new
        ref = refs["python"]
        assert len({tuple(v) for v in results.values()}) == 1  # compiled = Python, bit for bit
        assert len({r for r in refs.values()}) == 1
        assert results["python"] == tn.step_unchecked(net, list(t), ambient, sink, power, h, ref)
        f = compiled.module("thermal.stepping", "python").rates(
            tn._terms(net), t, ambient, sink, power
        )
        scale = float(np.abs(tn._terms(net)[0]).max()) * max(t)  # K/s of the largest term
        by_hand = _rates_by_hand(net, t, ambient, sink, power)
        np.testing.assert_allclose(f, by_hand, rtol=0, atol=1e-14 * scale)
        m = np.array(tn.propagator(net, h, ref))
        np.testing.assert_allclose(results["python"], np.asarray(t) + m @ f, rtol=1e-15, atol=0)
        exps += ref is not None and ref is t
        t = tuple(results["python"])
    assert (exps > 0) == net.radiating  # the reference was renewed on the way


def test_stepper_names_the_first_bad_node_and_flags_the_range():
    net = tn.ThermalNetwork(
        (10.0, 1.0), links=((0, 1, 1.0),), ambient=(2.0, 0.0), sink_radiation=(0.0, 0.0),
        heat_split=(0.0, 1.0), nodes=("a", "b"),
    )  # fmt: skip
    for impl in implementations():
        s = tn.stepper(net, impl)
        _, _, bad, outside = s.advance(
            (300.0, 300.0), 300.0, 0.0, 0.0, 1.0, None, 0.1, 250.0, 350.0
        )
        assert (bad, outside) == (-1, False)
        _, _, bad, outside = s.advance(
            (300.0, 300.0), 300.0, 0.0, 1e3, 1.0, None, 0.1, 250.0, 350.0
        )
        assert (bad, outside) == (-1, True)  # node b heats far above 350 K
        new, _, bad, _ = s.advance((300.0, 300.0), 300.0, 0.0, -1e6, 1e-3, None, 0.1, 250.0, 350.0)
        assert bad == 1 and new[0] > 0.0 >= new[1]  # the heat drawn takes b below 0 K


# ---------------------------------------------------------------------------- heat transfer
def test_constriction_resistance_is_yovanovichs_integral():
    # ∫₀^∞ dt/√((a²+t)(b²+t)t) with t = a²·s²: (2/a)·∫₀^∞ ds/√((1+s²)(β²+s²)), β = b/a
    for a, b in ((1e-3, 1e-3), (2e-4, 4e-5), (1e-4, 1e-6)):
        beta = b / a
        half, _ = quad(
            lambda s, beta=beta: 1.0 / math.sqrt((1 + s * s) * (beta * beta + s * s)),
            0,
            np.inf,
            epsabs=0,
            epsrel=1e-11,
            limit=500,
        )
        integral = 2.0 * half / a
        assert tn.constriction_resistance(a, b, 40.0) == pytest.approx(
            integral / (4 * math.pi * 40.0), rel=1e-7
        )


def test_ball_conductance_grows_with_the_cube_root_of_the_preload():
    b = catalog.bearing("71803")
    ratio = tn.ball_conductance(b, 200.0) / tn.ball_conductance(b, 25.0)
    assert ratio == pytest.approx(2.0, rel=1e-9)  # contact size ∝ Q^(1/3), 8^(1/3) = 2
    with pytest.raises(ValueError, match=r"preload = 0\.0"):
        tn.ball_conductance(b, 0.0)


def test_forced_convection_by_hand():
    # Churchill-Bernstein with air at 300 K (Incropera Table A.4): D = 36 mm, V = 1 m/s
    re = 1.0 * 0.036 / 15.89e-6
    nu = (
        0.3
        + 0.62
        * re**0.5
        * 0.707 ** (1 / 3)
        / (1 + (0.4 / 0.707) ** (2 / 3)) ** 0.25
        * (1 + (re / 282000) ** 0.625) ** 0.8
    )
    assert tn.forced_convection_coefficient(0.036, 1.0) == pytest.approx(
        nu * 0.0263 / 0.036, rel=1e-12
    )
    assert tn.forced_convection_coefficient(0.036, 0.0) == 0.0


def test_contact_conductance_follows_the_handbook_rows():
    steel, ti = catalog.material("9cr18"), catalog.material("tc4")
    # Incropera Table 3.1(a) stainless steel: 1/12.2e-4 at 0.1 MPa, 1/1.67e-4 at 10 MPa, a power
    # law between, scaled by k_s/14.9; the air-filled gap 1/2.75e-4 as the floor in air
    scale = 2 * 24.2 * 6.7 / (24.2 + 6.7) / 14.9
    lo, hi = scale / 12.2e-4, scale / 1.67e-4

    def h(pressure, vacuum=True):
        return tn.contact_conductance(ti, steel, pressure, vacuum)[0]

    assert h(0.0) == pytest.approx(lo) and h(1e5) == pytest.approx(lo)
    assert h(1e7) == pytest.approx(hi) and h(1e8) == pytest.approx(hi)  # no extrapolation
    assert h(1e6) == pytest.approx(math.sqrt(lo * hi))  # the geometric middle of 0.1…10 MPa
    assert h(0.0, vacuum=False) == pytest.approx(1 / 2.75e-4)
    assert h(1e7, vacuum=False) == pytest.approx(hi)  # above the air floor


# ---------------------------------------------------------------------------- presets
def test_materials_without_thermal_properties_still_load():
    bare = Material(key="x", name="x", youngs_modulus=2e11, poisson_ratio=0.3, expansion=1e-5)
    assert bare.density is None and bare.emissivity is None
    with pytest.raises(ValueError, match="material 'x' has no density"):
        bare.thermal("density")
    for key in ("cast_aluminium", "steel_45", "bearing_steel_yu", "9cr18", "tc4"):
        m = catalog.material(key)
        assert all(getattr(m, f) for f in catalog.OPTIONAL_MATERIAL_FIELDS), key
        assert m.source("density").startswith("handbook")


def test_presets_carry_provenance_and_the_environment():
    yu, ning = tn.preset("yu2017_gimbal_chamber"), tn.preset("ning_space_vacuum")
    for p in (yu, ning):
        for field in tn.PARAMETER_FIELDS[:-1]:
            assert p.source(field), field
    assert not yu.vacuum and yu.convection_coefficient > 0 and yu.gas_gap_conductance > 0
    assert ning.vacuum and ning.convection_coefficient == 0 and ning.gas_gap_conductance == 0
    assert ning.mount_conductance > 0 and yu.mount_conductance == 0
    # the housing of Yu's gimbal: ρ·c·V of a Ø26/Ø36 × 118 mm cast-aluminium tube
    volume = math.pi / 4 * (0.036**2 - 0.026**2) * 0.118
    assert yu.housing_capacity == pytest.approx(2670 * 963 * volume, rel=1e-12)
    net = tn.network(ning)
    assert net.ambient[0] == ning.mount_conductance  # no convection in vacuum
    assert tn.network(yu).ambient[0] == pytest.approx(
        yu.convection_coefficient * yu.housing_convection_area
    )
    # Ning's own test rig in chamber air: the same parts, convection and a gas gap added
    air = tn.preset("ning_chamber_air")
    assert not air.vacuum and air.convection_coefficient > 0 and air.gas_gap_conductance > 0
    assert air.housing_capacity == ning.housing_capacity and air.mount_conductance > 0
    assert air.source("air_speed") == "" and "assumed" in air.source("convection_coefficient")
    assert tn.time_constants(tn.network(air))[0] < tn.time_constants(net)[0]


def test_uniform_soak_is_a_steady_state_and_the_shaft_lags_the_frame():
    net = tn.network(tn.preset("yu2017_gimbal_chamber"))
    cold = tn.steady_state(net, 233.15, 233.15, 0.0)
    assert cold == pytest.approx([233.15] * 4, abs=1e-9)
    x = cold
    for _ in range(60):  # ten minutes after the chamber steps to +60 °C
        x = tn.step(net, x, 333.15, 333.15, 0.0, 10.0)
    housing, shaft = x[tn.HOUSING], x[tn.SHAFT]
    assert 233.15 < shaft < housing < 333.15
    assert housing - shaft > 10.0  # the steel shaft inside lags the aluminium frame


def test_steady_state_balances_the_heat_by_hand():
    p = tn.preset("ning_space_vacuum")
    t = tn.steady_state(tn.network(p), 293.15, 100.0, 0.7)
    out = p.mount_conductance * (t[0] - 293.15)
    out += SIGMA * p.housing_emissivity * p.housing_radiating_area * (t[0] ** 4 - 100.0**4)
    out += SIGMA * p.shaft_emissivity * p.shaft_radiating_area * (t[1] ** 4 - 100.0**4)
    assert out == pytest.approx(0.7, rel=1e-9)


@pytest.mark.parametrize(
    "change, text",
    [
        ({"housing_capacity": 0.0}, "housing_capacity = 0.0"),
        ({"ball_conductance": -1.0}, "ball_conductance = -1.0"),
        ({"housing_emissivity": float("nan")}, "housing_emissivity = nan"),
    ],
)
def test_bad_parameters_name_the_variable(change, text):
    values = {**tn.preset("yu2017_gimbal_chamber").as_dict(), **change}
    with pytest.raises(ValueError, match=text):
        tn.ThermalParameters(**values)


def test_bad_inputs_name_the_variable():
    net = tn.network(tn.preset("yu2017_gimbal_chamber"))
    with pytest.raises(ValueError, match="ambient = nan"):
        tn.step(net, [293.15] * 4, float("nan"), 293.15, 0.0, 1.0)
    with pytest.raises(ValueError, match=r"shaft temperature = -1\.0"):
        tn.step(net, [293.15, -1.0, 293.15, 293.15], 293.15, 293.15, 0.0, 1.0)
    with pytest.raises(ValueError, match="no steady state"):
        isolated = tn.ThermalNetwork(
            (1.0,), ambient=(0.0,), sink_radiation=(0.0,), heat_split=(1.0,), nodes=("x",)
        )
        tn.steady_state(isolated, 293.15, 293.15, 1.0)


# ---------------------------------------------------------------------------- the FMU
def test_fmu_defaults_are_the_yu_preset_and_outputs_are_ready_after_initialization(fmus):
    fmu = Fmu(fmus["ThermalNetwork"], "init").init(
        ambient_temperature=253.15, sink_temperature=253.15, power_loss=0.5
    )
    lib = tn.steady_state(tn.network(tn.preset("yu2017_gimbal_chamber")), 253.15, 253.15, 0.5)
    assert fmu.get(*OUTPUTS) == pytest.approx(lib, abs=1e-9)
    fmu.close()


def test_fmu_steps_like_the_library(fmus):
    ning = tn.preset("ning_space_vacuum").as_dict()
    fmu = Fmu(fmus["ThermalNetwork"], "lib").init(
        ambient_temperature=213.15, sink_temperature=213.15, linearisation_tolerance=0.0, **ning
    )
    net = tn.network(tn.preset("ning_space_vacuum"))
    x = tn.steady_state(net, 213.15, 213.15, 0.0)
    t = 0.0
    for _ in range(30):
        fmu.set(ambient_temperature=353.15, sink_temperature=100.0, power_loss=0.2)
        fmu.slave.doStep(t, 20.0)
        t += 20.0
        x = tn.step(net, x, 353.15, 100.0, 0.2, 20.0)
    np.testing.assert_allclose(fmu.get(*OUTPUTS), x, rtol=0, atol=1e-9)
    fmu.close()


@pytest.mark.parametrize(
    "values, text",
    [
        ({"ambient_temperature": float("nan")}, "ambient_temperature = nan"),
        ({"sink_temperature": -3.0}, "sink_temperature = -3.0"),
        ({"power_loss": float("inf")}, "power_loss = inf"),
    ],
)
def test_fmu_refuses_bad_inputs_with_a_message(fmus, values, text):
    fmu = Fmu(fmus["ThermalNetwork"], "bad").init()
    before = fmu.get(*OUTPUTS)
    fmu.set(**values)
    with pytest.raises(FMICallException, match="status 3"):
        fmu.slave.doStep(0.0, 1.0)
    assert any(text in m and s == 3 for s, m in fmu.log), fmu.log
    assert fmu.get(*OUTPUTS) == before  # nothing computed is lost
    fmu.close()


@pytest.mark.parametrize(
    "values, text",
    [
        ({"housing_capacity": 0.0}, "housing_capacity = 0.0"),
        ({"ball_conductance": -0.1}, "ball_conductance = -0.1"),
        ({"inner_fit_conductance": float("nan")}, "inner_fit_conductance = nan"),
    ],
)
def test_fmu_refuses_bad_parameters_with_a_message(fmus, values, text):
    fmu = Fmu(fmus["ThermalNetwork"], "bad")
    with pytest.raises(FMICallException, match="fmi2ExitInitializationMode failed with status 3"):
        fmu.init(**values)
    assert any(text in m and s == 3 for s, m in fmu.log), fmu.log
    fmu.close()


def test_fmu_vacuum_switch_removes_convection(fmus):
    air = Fmu(fmus["ThermalNetwork"], "air").init(
        ambient_temperature=253.15, sink_temperature=253.15
    )
    vac = Fmu(fmus["ThermalNetwork"], "vac").init(
        ambient_temperature=253.15, sink_temperature=253.15, environment="vacuum"
    )
    t = 0.0
    for _ in range(30):
        for f in (air, vac):
            f.set(ambient_temperature=333.15, sink_temperature=253.15)
            f.slave.doStep(t, 20.0)
        t += 20.0
    # in air the frame follows the chamber air; in vacuum only radiation to the 253 K sink acts
    assert air.get("housing_temperature") > 280.0  # 296 K after 10 min
    assert vac.get("housing_temperature") == pytest.approx(253.15, abs=1e-6)
    air.close()
    vac.close()
