r"""Lumped-capacitance thermal network of a bearing mechanism (the ThermalNetwork FMU's equations).

Nodes (each part isothermal; SI throughout): housing (frame), shaft, outer rings, inner rings of
the bearing pair. The balls are not a node: each ball's capacity goes half to each ring, and its
two contacts are conductances in series between the rings. The lubricant's capacity is
neglected: a 30 % fill of a 71803's free space with PFPE grease (≈ 1.9 g/cm³, ≈ 1 J/(g·K))
holds about 0.4 J/K per bearing (an estimate), a tenth of its rings and balls and 0.2 % of
frame and shaft; a MoS2 film holds nothing. Energy balance of node k (capacity
:math:`C_k` [J/K], temperature :math:`T_k` [K]):

.. math::

   C_k\,\frac{dT_k}{dt} = \sum_j G_{kj}\,(T_j - T_k) + G_{k,a}\,(T_a - T_k)
   - \sigma\,\varepsilon_k A_k\,(T_k^4 - T_s^4)
   - \sum_j \sigma\,\mathcal{F}_{kj}\,(T_k^4 - T_j^4) + s_k\,P

with the conductances between parts :math:`G_{kj}` and to the ambient (convection, mounting)
:math:`G_{k,a}` [W/K], the radiating areas :math:`\varepsilon_k A_k` and exchange areas
:math:`\mathcal{F}_{kj}` [m²], the share :math:`s_k` of the bearing's power loss P [W], the
ambient (chamber air, mounting plate) temperature T_a, the radiative sink (chamber
walls, shroud, space) T_s and σ = 5.670374419e-8 W/(m²·K⁴). The conductances:

- ring fits: :math:`G = h_c\,\pi D B` per bearing seat; h_c from the thermal contact resistances of
  Incropera et al. (2007), *Fundamentals of Heat and Mass Transfer*, 6th ed., Table 3.1(a):
  stainless steel in vacuum, 6–25e-4 m²·K/W at 100 kPa and 0.7–4.0e-4 at 10 MPa (geometric
  means), interpolated as a power of the Lamé fit pressure of the assembly (:mod:`.thermal.fits`;
  Yu's 12 µm outer fit: 4.4 MPa, Ning's 5 µm inner fit: 1.6 MPa), the 100 kPa row for a
  clearance fit; in air the air-filled interface of Table 3.1(b) (2.75e-4) is the lower
  bound. The stainless rows are scaled with the harmonic-mean conductivity of the two metals,
  as the contact conductance of Mikic/Yovanovich, h_c = 1.25·k_s·(m/σ)·(P/H_c)^0.95, is
  proportional to it (Yovanovich & Marotta 2003, in Bejan & Kraus, *Heat Transfer
  Handbook*, ch. 4). The fit pressure changes with temperature; the conductances stay at
  their assembly values.
- ball contacts: the constriction resistance of an isothermal elliptical contact (semi-axes
  a ≥ b) on a half-space, :math:`R = K(m)/(2\pi\lambda a)`, :math:`m = 1 - b^2/a^2`, K the
  complete elliptic integral
  of the first kind (Yovanovich 1976, "Thermal constriction resistance of contacts on a
  half-space: integral formulation", AIAA Prog. Astronaut. Aeronaut. 49; for a circle it is
  Holm's 1/(4·λ·a)), on the ball side and the race side of each contact, with the Hertz
  semi-axes of :mod:`.contact.hertz` at the ball load of a reference preload (Q = F/(Z·sin α0)). Z
  balls in parallel, the inner and outer contact of each in series. Dry contacts: the
  lubricant meniscus around a greased contact adds a parallel path, so the value is a lower
  bound for grease and the estimate for a dry MoS2 film. The conductance grows as F^(1/3);
  it is evaluated once, at the reference preload, and vanishes when the preload is lost,
  which the constant value does not follow.
- shaft to frame: conduction through the gas in the annulus between shaft and housing bore
  between the bearings, :math:`G = 2\pi k_\mathrm{gas} L/\ln(r_o/r_i)` (conduction regime:
  the gap Rayleigh number of a few-millimetre annulus is far below the onset of convection;
  Incropera §9.8), absent in vacuum; and gray-body radiation across it,
  :math:`\mathcal{F} = A_i/(1/\varepsilon_i + (1 - \varepsilon_o)/\varepsilon_o\cdot r_i/r_o)`
  (long concentric cylinders, Incropera Table 13.3).
- convection to the chamber air: forced convection over the housing as a cylinder in cross
  flow, Churchill & Bernstein (Incropera eq 7.54), air properties at 300 K (Table A.4); none
  in vacuum. Mounting: a housing face bolted to a temperature-controlled plate at T_a, a
  light contact (Table 3.1, 100 kPa row) in series with conduction through half the housing.

Integration over a communication step h with the inputs held (zero-order hold): with
:math:`f(T) = dT/dt` and J its Jacobian at the reference temperatures :math:`T_\mathrm{ref}`,

.. math::

   T(t + h) = T(t) + h\,\varphi_1(hJ)\,f(T(t)), \qquad \varphi_1(z) = \frac{e^z - 1}{z},

where :math:`h\,\varphi_1(hJ)` is the top-right block of
:math:`\exp\left(h\begin{bmatrix} J & I \\ 0 & 0 \end{bmatrix}\right)` (Van Loan 1978; the
exponential Rosenbrock–Euler method, Hochbruck & Ostermann 2010, Acta Numerica 19). Without
radiation the network is linear, J is its system matrix and this is the exact solution for
any step, stiff or not (the rings' time constants are seconds, the frame's minutes), as in
DCMotor; the matrix is cached per step size. Radiation is not linear: the step is then the
exact solution of the network linearised about T_ref (radiation replaced by its tangent, the
fluxes themselves taken at T(t)); the steady state is exact and the error is second order in
h when T_ref = T(t). T_ref is renewed once a node has moved more than a tolerance from it
(0: every step); each renewal costs one matrix exponential. Measured against Radau at
rtol = atol = 1e-11 over 3 h after the ambient and the sink jump by 140 K, largest error of
any part with per-step linearisation: Yu's gimbal 4.4e-7, 4.5e-5, 1.7e-3 and 0.24 K at 1, 10,
60 and 600 s steps; Ning's bearing 5.4e-7, 5.4e-5, 2.0e-3 and 0.26 K (second order); renewed
every 0.1 K at 1 s steps, 1.4e-6 K with a seventh of the exponentials.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import expm
from scipy.optimize import root
from scipy.special import ellipk

from .. import compiled
from .._checks import check_choice, check_finite, check_nonnegative, check_positive, check_range
from ..contact import hertz
from ..materials import Material, reduced_compliance
from .fits import fit_pressure

NODES = ("housing", "shaft", "outer_ring", "inner_ring")
HOUSING, SHAFT, OUTER, INNER = range(4)
STEFAN_BOLTZMANN = 5.670374419e-8  # σ [W/(m²·K⁴)], CODATA 2018 (exact in the 2019 SI)
#: The per-step arithmetic (rates, exponential step): compiled when the build could compile it.
stepping = compiled.module("thermal.stepping")


# ---------------------------------------------------------------------------- the network
@dataclass(frozen=True)
class ThermalNetwork:
    """A lumped network (see the module docstring), SI. Hashable: it keys the caches.

    Attributes
    ----------
    capacities : C_k [J/K], > 0
    links : ((i, j, G_ij [W/K]), ...) conduction between nodes i and j
    ambient : G_k,a [W/K] of each node to the ambient temperature
    sink_radiation : ε_k·A_k [m²] of each node towards the sink
    exchange : ((i, j, 𝓔_ij [m²]), ...) gray-body radiation between nodes i and j
    heat_split : share s_k [-] of the heat input that enters each node (sum 1)
    nodes : node names
    """

    capacities: tuple[float, ...]
    links: tuple[tuple[int, int, float], ...] = ()
    ambient: tuple[float, ...] = ()
    sink_radiation: tuple[float, ...] = ()
    exchange: tuple[tuple[int, int, float], ...] = ()
    heat_split: tuple[float, ...] = ()
    nodes: tuple[str, ...] = NODES

    def __post_init__(self):
        n = len(self.capacities)
        if len(self.nodes) != n:
            raise ValueError(f"nodes = {self.nodes!r} must name the {n} capacities")
        for name, c in zip(self.nodes, self.capacities, strict=True):
            check_positive(f"{name} capacity", c, "J/K")
        for field in ("ambient", "sink_radiation", "heat_split"):
            values = getattr(self, field)
            if len(values) != n:
                raise ValueError(f"{field} = {values!r} must have one value per node ({n})")
            for name, v in zip(self.nodes, values, strict=True):
                check_nonnegative(f"{name} {field}", v)
        for field in ("links", "exchange"):
            for i, j, g in getattr(self, field):
                if not (0 <= i < n and 0 <= j < n and i != j):
                    raise ValueError(f"{field}: nodes ({i}, {j}) must be two of 0…{n - 1}")
                check_nonnegative(f"{field} {self.nodes[i]}–{self.nodes[j]}", g)
        if abs(sum(self.heat_split) - 1.0) > 1e-12:
            raise ValueError(f"heat_split = {self.heat_split!r} must sum to 1")

    @property
    def radiating(self) -> bool:
        """True when any radiation term is present (the network is then not linear)."""
        return any(self.sink_radiation) or any(e for _, _, e in self.exchange)


def conductance_matrix(network: ThermalNetwork) -> np.ndarray:
    """K [W/K]: the weighted Laplacian of the conduction links plus diag(G_k,a), so that the
    linear part of the balance is C·dT/dt = −K·T + G_a·T_a (module docstring).

    Parameters
    ----------
    network : ThermalNetwork
        The network (links [W/K], ambient conductances [W/K]).

    Returns
    -------
    ndarray
        K [W/K], n × n, symmetric.

    Examples
    --------
    >>> k = conductance_matrix(network(preset("yu2017_gimbal_chamber")))
    >>> k.shape, bool(np.allclose(k, k.T))
    ((4, 4), True)
    """
    k = np.diag(np.asarray(network.ambient, dtype=float))
    for i, j, g in network.links:
        k[i, i] += g
        k[j, j] += g
        k[i, j] -= g
        k[j, i] -= g
    return k


@functools.lru_cache(maxsize=64)
def _terms(network: ThermalNetwork):
    """Per-node coefficients, divided by the capacities, as floats for the stepping loop:
    (A = −C⁻¹K rows, ambient G/C, heat split s/C, sink σεA/C, exchange (i, j, σ𝓔/C_i, σ𝓔/C_j))."""
    c = network.capacities
    a = -conductance_matrix(network) / np.asarray(c)[:, None]
    rows = tuple(tuple(float(v) for v in row) for row in a)
    amb = tuple(g / ci for g, ci in zip(network.ambient, c, strict=True))
    split = tuple(s / ci for s, ci in zip(network.heat_split, c, strict=True))
    sink = tuple(STEFAN_BOLTZMANN * e / ci for e, ci in zip(network.sink_radiation, c, strict=True))
    exch = tuple(
        (i, j, STEFAN_BOLTZMANN * e / c[i], STEFAN_BOLTZMANN * e / c[j])
        for i, j, e in network.exchange
        if e
    )
    return rows, amb, split, sink, exch


def _rates(terms, t, ambient, sink, power):
    return stepping.rates(terms, t, ambient, sink, power)


def temperature_rates(network: ThermalNetwork, temperatures, ambient, sink, power):
    """dT/dt [K/s] of every node (module docstring) at node temperatures ``temperatures``
    [K], ambient temperature ``ambient`` [K], sink temperature ``sink`` [K] and heat input
    ``power`` [W].

    Returns
    -------
    ndarray
        dT/dt [K/s] per node.

    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> temperature_rates(net, [300.0], 290.0, 290.0, 5.0)  # (2·(290 − 300) + 5)/10
    [-1.5]
    """
    t = _check_state(network, temperatures)
    _check_inputs(ambient, sink, power)
    return _rates(_terms(network), t, ambient, sink, power)


def jacobian(network: ThermalNetwork, temperatures) -> np.ndarray:
    """∂(dT/dt)/∂T [1/s] at node temperatures ``temperatures`` [K]: the linear part plus the
    tangent of the radiation terms (independent of the sink temperature).

    Returns
    -------
    ndarray
        ∂(dT/dt)/∂T [1/s], n × n.

    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> jacobian(net, [300.0])
    array([[-0.2]])
    """
    t = _check_state(network, temperatures)
    return _jacobian(_terms(network), t)


def _jacobian(terms, t) -> np.ndarray:
    rows, _, _, sink_k, exch = terms
    j = np.array(rows, dtype=float)
    for k, coef in enumerate(sink_k):
        j[k, k] -= 4.0 * coef * t[k] ** 3
    for i, jj, ci, cj in exch:
        j[i, i] -= 4.0 * ci * t[i] ** 3
        j[i, jj] += 4.0 * ci * t[jj] ** 3
        j[jj, i] += 4.0 * cj * t[i] ** 3
        j[jj, jj] -= 4.0 * cj * t[jj] ** 3
    return j


@functools.lru_cache(maxsize=16)
def propagator(network: ThermalNetwork, step: float, reference: tuple[float, ...] | None = None):
    """h·φ1(h·J) [s] for the step ``step`` [s] with J linearised about the node temperatures
    ``reference`` [K] (ignored, and best None, for a network without radiation): the top-right
    block of expm([[J, I], [0, 0]]·h). Nested tuples of floats; cached.

    Returns
    -------
    tuple
        h·φ1(h·J) [s] as nested tuples of floats (n × n).

    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> round(propagator(net, 5.0)[0][0], 10)  # (1 − e^(−0.2·5))/0.2
    3.1606027941
    """
    h = check_positive("step", step, "s")
    n = len(network.capacities)
    if network.radiating:
        if reference is None:
            raise ValueError("reference temperatures are needed for a radiating network")
        j = _jacobian(_terms(network), _check_state(network, reference))
    else:
        j = np.array(_terms(network)[0], dtype=float)
    m = np.zeros((2 * n, 2 * n))
    m[:n, :n] = j * h
    m[:n, n:] = np.eye(n) * h
    block = expm(m)[:n, n:]
    return tuple(tuple(float(v) for v in row) for row in block)


def step(
    network: ThermalNetwork,
    temperatures,
    ambient: float,
    sink: float,
    power: float,
    h: float,
    reference=None,
):
    """Node temperatures [K] after ``h`` [s] from ``temperatures`` [K] with the ambient and
    sink temperatures [K] and the heat input ``power`` [W] held (module docstring).

    ``reference`` [K]: the temperatures about which radiation is linearised (default: the
    start temperatures, i.e. re-linearised every step). Exact for a network without
    radiation; with radiation the error is second order in h (module docstring: 5.4e-5 K at
    10 s steps for Ning's bearing after a 140 K jump).

    Returns
    -------
    ndarray
        Node temperatures [K] after ``h``.

    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> [round(t, 9) for t in step(net, [300.0], 290.0, 0.0, 0.0, 5.0)]  # 290 + 10·e^(−1)
    [293.678794412]
    """
    t = _check_state(network, temperatures)
    _check_inputs(ambient, sink, power)
    h = check_positive("h", h, "s")
    ref = None
    if network.radiating:
        ref = tuple(_check_state(network, t if reference is None else reference))
    return step_unchecked(network, t, ambient, sink, power, h, ref)


def step_unchecked(network, t, ambient, sink, power, h, reference):
    """:func:`step` without its argument checks, for a caller that checked them (the
    ThermalNetwork FMU checks its inputs once per step).

    Parameters
    ----------
    network : ThermalNetwork
    t : sequence of float
        Node temperatures [K], one per node.
    ambient, sink, power, h : as :func:`step` ([K], [K], [W], [s]; finite, h > 0)
    reference : tuple of float or None
        Temperatures [K] about which radiation is linearised (None without radiation).

    Returns
    -------
    list of float
        Node temperatures [K] after ``h``.

    Examples
    --------
    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> [round(t, 9) for t in step_unchecked(net, [300.0], 290.0, 0.0, 0.0, 5.0, None)]
    [293.678794412]
    """
    m = propagator(network, h, reference)
    return stepping.exponential_step(m, t, _rates(_terms(network), t, ambient, sink, power))


def stepper(network: ThermalNetwork, implementation: str | None = None):
    """The per-step update of ``network`` in one call (:class:`.stepping.NetworkStepper`:
    the arithmetic of :func:`step_unchecked`, with the propagator kept while the step size and
    the reference stay), of ``implementation`` ("compiled", "python"; None: the one
    :mod:`servofmu.physics.compiled` chose).

    Returns
    -------
    NetworkStepper

    Examples
    --------
    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> new, ref, bad, outside = stepper(net).advance((300.0,), 290.0, 0.0, 0.0, 5.0, None, 0.1,
    ...                                               200.0, 400.0)
    >>> [round(t, 9) for t in new], ref, bad, outside  # 290 + 10·e^(−1)
    ([293.678794412], None, -1, False)
    """
    kernel = compiled.module("thermal.stepping", implementation)
    return kernel.NetworkStepper(
        _terms(network), network.radiating, functools.partial(propagator, network)
    )


def shared_step(*args, implementation: str | None = None):
    """The ThermalNetwork FMU's step on the values it shares with servofmu's export
    (:class:`.stepping.NetworkSharedStep`; ``args``: those of
    :class:`~servofmu.physics.shared_step.SharedStep`), of ``implementation`` (as
    :func:`stepper`, whose steppers it runs).

    Returns
    -------
    NetworkSharedStep

    Examples
    --------
    >>> step = shared_step(bytearray(32), 0, 0, 2, False, None, None)  # a block of no values
    >>> type(step).__name__, step.armed
    ('NetworkSharedStep', False)
    """
    return compiled.module("thermal.stepping", implementation).NetworkSharedStep(*args)


def steady_state(network: ThermalNetwork, ambient: float, sink: float, power: float):
    """Node temperatures [K] where every rate vanishes, for the ambient and sink temperatures
    [K] and the heat input [W] (scipy.optimize.root with the analytic Jacobian, started from
    the linear solution with radiation linearised at the ambient temperature). ValueError when
    there is none (no path to the ambient or the sink).

    Returns
    -------
    ndarray
        Node temperatures [K].

    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> [round(t, 9) for t in steady_state(net, 290.0, 0.0, 5.0)]  # 290 + 5/2
    [292.5]
    """
    _check_inputs(ambient, sink, power)
    terms = _terms(network)
    c = np.asarray(network.capacities)

    def balance(x):  # heat balance [W] and its Jacobian [W/K]
        x = [float(v) for v in x]
        return c * np.asarray(_rates(terms, x, ambient, sink, power)), c[:, None] * _jacobian(
            terms, x
        )

    x = _newton_step(balance, [float(ambient)] * len(c))  # exact without radiation
    if network.radiating:
        sol = root(balance, x, jac=True, method="hybr", options={"xtol": 1e-13})
        x = _newton_step(balance, sol.x)  # MINPACK may stop short when it starts at the answer
        imbalance = float(np.abs(balance(x)[0]).max())
        scale = 1.0 + abs(power) + float(np.abs(conductance_matrix(network)).max()) * ambient
        if not imbalance <= 1e-10 * scale:
            raise ValueError(f"steady state not found: {sol.message} (imbalance {imbalance:.3g} W)")
    return [float(v) for v in x]


def _newton_step(balance, x):
    q, k = balance(x)
    try:
        new = np.asarray(x) - np.linalg.solve(k, q)
    except np.linalg.LinAlgError:
        new = np.full(len(q), np.nan)
    if not np.all(np.isfinite(new) & (new > 0.0)):
        raise ValueError(
            "the network has no steady state: no node connects to the ambient or the sink "
            "(set some convection, mounting or radiation)"
        )
    return new


def ode_solution(
    network: ThermalNetwork, temperatures, ambient, sink, power, duration, tolerance=1e-11
):
    """The network's ODE solved by scipy's Radau (stiff, analytic Jacobian) from
    ``temperatures`` [K] over ``duration`` [s] with the inputs held (ambient and sink [K],
    power [W]) at rtol = atol = ``tolerance``: a dense ``OdeSolution`` (call it with a time
    [s]), the reference against which :func:`step` is measured.

    Returns
    -------
    scipy.integrate.OdeSolution
        T(t) [K] for t [s] in [0, duration].

    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> round(float(ode_solution(net, [300.0], 290.0, 0.0, 0.0, 5.0)(5.0)[0]), 6)
    293.678794
    """
    from scipy.integrate import solve_ivp

    t0 = _check_state(network, temperatures)
    _check_inputs(ambient, sink, power)
    tol = check_positive("tolerance", tolerance)
    terms = _terms(network)
    sol = solve_ivp(
        lambda t, x: _rates(terms, [float(v) for v in x], ambient, sink, power),
        (0.0, check_positive("duration", duration, "s")),
        t0,
        method="Radau",
        rtol=tol,
        atol=tol,
        jac=lambda t, x: _jacobian(terms, [float(v) for v in x]),
        dense_output=True,
    )
    if not sol.success:
        raise ValueError(f"ODE solution failed: {sol.message}")
    return sol.sol


def time_constants(network: ThermalNetwork, temperature: float = 293.15):
    """Time constants τ = −1/λ [s] of the network linearised at the uniform temperature
    ``temperature`` [K] (λ the eigenvalues of the Jacobian), longest first; inf for a mode
    without decay (no path to the ambient or sink).

    Returns
    -------
    ndarray
        τ [s], longest first.

    >>> net = ThermalNetwork((10.0,), ambient=(2.0,), sink_radiation=(0.0,), heat_split=(1.0,),
    ...                      nodes=("part",))
    >>> time_constants(net)
    [5.0]
    """
    t = check_positive("temperature", temperature, "K")
    lam = np.linalg.eigvals(jacobian(network, [t] * len(network.capacities))).real
    return sorted((math.inf if v >= 0 else float(-1.0 / v) for v in lam), reverse=True)


def _check_state(network, temperatures):
    t = [float(v) for v in temperatures]
    if len(t) != len(network.capacities):
        raise ValueError(f"temperatures = {temperatures!r} must give one value per node")
    for name, v in zip(network.nodes, t, strict=True):
        check_positive(f"{name} temperature", v, "K")
    return t


def _check_inputs(ambient, sink, power):
    check_positive("ambient", ambient, "K")
    check_nonnegative("sink", sink, "K")
    check_finite("power", power, "W")


# ---------------------------------------------------------------------------- heat transfer
def constriction_resistance(semi_major, semi_minor, conductivity):
    """Constriction resistance [K/W] of an isothermal elliptical contact of semi-axes
    ``semi_major`` ≥ ``semi_minor`` [m] on a half-space of conductivity ``conductivity``
    [W/(m·K)]: R = K(m)/(2·π·λ·a), m = 1 − b²/a² (Yovanovich 1976; module docstring). It is
    (1/4πλ)·∫₀^∞ dt/√((a²+t)(b²+t)t), the electrostatic capacitance of the elliptic disc.

    Returns
    -------
    float or ndarray
        R [K/W].

    >>> round(constriction_resistance(1e-3, 1e-3, 50.0), 9)  # circle: 1/(4·λ·a)
    5.0
    """
    a = check_positive("semi_major", semi_major, "m")
    b = check_positive("semi_minor", semi_minor, "m")
    lam = check_positive("conductivity", conductivity, "W/(m·K)")
    if np.any(np.asarray(b) > np.asarray(a)):
        raise ValueError(f"semi_minor = {semi_minor!r} m must not exceed semi_major = {a!r} m")
    out = ellipk(1.0 - (b / a) ** 2) / (2.0 * np.pi * lam * a)
    return out if np.ndim(out) else float(out)


def ball_conductance(bearing, preload: float) -> float:
    """Conductance [W/K] between the outer and the inner ring of one angular-contact bearing
    through its Z balls under the axial preload ``preload`` [N] (module docstring): each
    ball's inner and outer contact in series, each contact the constriction of the ball side
    and of the race side (:func:`constriction_resistance`), Hertz semi-axes of
    :func:`hertz.groove_contact` at the free contact angle α0 and Q = F/(Z·sin α0).

    Returns
    -------
    float
        [W/K] through the bearing's balls.

    >>> from servofmu.parameters import catalog
    >>> round(ball_conductance(catalog.bearing("71803"), 92.8), 4)
    0.0641
    """
    f = check_positive("preload", preload, "N")
    b = bearing
    alpha = b.contact_angle
    if alpha <= 0.0:
        raise ValueError(f"bearing {b.key!r} has no free contact angle to carry the preload")
    q = f / (b.n_balls * math.sin(alpha))
    eta = reduced_compliance(b.ring_material, b.ball_material)
    lam_ring = b.ring_material.thermal("thermal_conductivity")
    lam_ball = b.ball_material.thermal("thermal_conductivity")
    per_ball = 0.0
    for race, curvature in (("inner", b.inner_curvature), ("outer", b.outer_curvature)):
        contact = hertz.groove_contact(
            b.ball_diameter, b.pitch_diameter, curvature, alpha, eta, race
        )
        a, bb = (float(x) for x in contact.semi_axes(q))
        per_ball += constriction_resistance(a, bb, lam_ball) + constriction_resistance(
            a, bb, lam_ring
        )
    return b.n_balls / per_ball


def contact_conductance(material_a: Material, material_b: Material, pressure, vacuum: bool):
    """Thermal contact conductance h_c [W/(m²·K)] of a metallic seat under the contact
    pressure ``pressure`` [Pa], and its provenance (module docstring). Incropera Table 3.1(a)
    gives the stainless-steel interface in vacuum at 100 kPa and at 10 MPa; between them h_c
    is interpolated as a power of the pressure, outside them the nearer row is kept (no
    extrapolation; a seat without pressure, a clearance fit, takes the 100 kPa row). The
    result is scaled by the harmonic-mean conductivity k_s = 2·λa·λb/(λa + λb) of the two
    metals over the stainless steel's. In air, the air-filled interface of Table 3.1(b) is the
    lower bound.

    Returns
    -------
    tuple
        (h_c [W/(m²·K)], provenance).

    >>> from servofmu.parameters import catalog
    >>> tc4, ring = catalog.material("tc4"), catalog.material("9cr18")
    >>> round(contact_conductance(tc4, ring, 1.0e7, True)[0])  # the 10 MPa row, scaled
    4218
    """
    p = check_nonnegative("pressure", pressure, "Pa")
    hb = _handbook()
    p_lo, p_hi = hb["light_contact_pressure"][0], hb["pressed_contact_pressure"][0]
    h_lo = 1.0 / hb["light_contact_resistance"][0]
    h_hi = 1.0 / hb["pressed_contact_resistance"][0]
    k_ref = hb["contact_reference_conductivity"][0]
    la = material_a.thermal("thermal_conductivity")
    lb = material_b.thermal("thermal_conductivity")
    k_s = 2.0 * la * lb / (la + lb)
    exponent = math.log(h_hi / h_lo) / math.log(p_hi / p_lo)
    h = h_lo * (min(max(p, p_lo), p_hi) / p_lo) ** exponent * k_s / k_ref
    src = (
        f"derived: Incropera Table 3.1(a) stainless steel in vacuum, 1/R'' = {h_lo:.4g} W/(m²·K) "
        f"at {p_lo / 1e6:g} MPa and {h_hi:.4g} at {p_hi / 1e6:g} MPa (geometric means of the "
        f"ranges), ∝ P^{exponent:.3f} between, at P = {p / 1e6:.3g} MPa; × k_s/k_ref = "
        f"{k_s:.3g}/{k_ref:g} ({material_a.key}, {material_b.key} against AISI 304)"
    )
    h_air = 1.0 / hb["air_filled_contact_resistance"][0]
    if not vacuum and h_air > h:
        return (
            h_air,
            "derived: the air-filled interface of Incropera Table 3.1(b), 1/2.75e-4 m²·K/W",
        )
    return h, src


def forced_convection_coefficient(diameter: float, air_speed: float) -> float:
    """Mean heat-transfer coefficient [W/(m²·K)] of air flowing at ``air_speed`` [m/s] across
    a cylinder of diameter ``diameter`` [m]: Churchill & Bernstein,
    Nu = 0.3 + 0.62·Re^½·Pr^⅓/[1 + (0.4/Pr)^⅔]^¼·[1 + (Re/282000)^⅝]^⅘ (Incropera et al. 2007,
    eq 7.54), air properties at 300 K (Table A.4, data/thermal.toml). 0 at zero speed.

    Returns
    -------
    float
        h [W/(m²·K)].

    >>> round(forced_convection_coefficient(0.036, 1.0), 2)
    17.74
    """
    d = check_positive("diameter", diameter, "m")
    v = check_nonnegative("air_speed", air_speed, "m/s")
    if v == 0.0:
        return 0.0
    hb = _handbook()
    k, nu, pr = (hb[f][0] for f in ("air_conductivity", "air_kinematic_viscosity", "air_prandtl"))
    re = v * d / nu
    nusselt = (
        0.3
        + (0.62 * re**0.5 * pr ** (1 / 3) / (1.0 + (0.4 / pr) ** (2 / 3)) ** 0.25)
        * (1.0 + (re / 282000.0) ** 0.625) ** 0.8
    )
    return nusselt * k / d


def annulus_conductance(inner_diameter, outer_diameter, length, conductivity):
    """Conduction [W/K] through a cylindrical annulus (gas between shaft and housing bore):
    2·π·λ·L/ln(r_o/r_i) (Incropera et al. 2007, eq 3.27).

    Returns
    -------
    float or ndarray
        [W/K].

    >>> round(annulus_conductance(0.017, 0.026, 0.098, 0.0263), 5)
    0.03811
    """
    di = check_positive("inner_diameter", inner_diameter, "m")
    do = check_positive("outer_diameter", outer_diameter, "m")
    length = check_nonnegative("length", length, "m")
    lam = check_positive("conductivity", conductivity, "W/(m·K)")
    if do <= di:
        raise ValueError(f"outer_diameter = {do!r} m must exceed inner_diameter = {di!r} m")
    return 2.0 * math.pi * lam * length / math.log(do / di)


def cylinder_exchange_area(
    inner_diameter, outer_diameter, length, inner_emissivity, outer_emissivity
):
    """Gray-body exchange area 𝓔 [m²] of two long concentric cylinders (the shaft inside the
    housing bore): q = σ·𝓔·(T_i⁴ − T_o⁴), 𝓔 = A_i/(1/ε_i + (1 − ε_o)/ε_o·r_i/r_o)
    (Incropera et al. 2007, Table 13.3); diameters and length [m], emissivities [-].

    Returns
    -------
    float or ndarray
        𝓔 [m²].

    >>> round(cylinder_exchange_area(0.02, 0.04, 1.0, 1.0, 1.0), 6)  # black: A_i = π·d·L
    0.062832
    """
    di = check_positive("inner_diameter", inner_diameter, "m")
    do = check_positive("outer_diameter", outer_diameter, "m")
    length = check_nonnegative("length", length, "m")
    ei = check_range("inner_emissivity", inner_emissivity, 0.0, 1.0, lo_open=True)
    eo = check_range("outer_emissivity", outer_emissivity, 0.0, 1.0, lo_open=True)
    if do <= di:
        raise ValueError(f"outer_diameter = {do!r} m must exceed inner_diameter = {di!r} m")
    return math.pi * di * length / (1.0 / ei + (1.0 - eo) / eo * di / do)


def _handbook() -> dict:
    from ...parameters import catalog

    return catalog.thermal("handbook")


# ---------------------------------------------------------------------------- the mechanism
@dataclass(frozen=True)
class ThermalParameters:
    """The four-node network of a bearing mechanism as named quantities (SI): the
    ThermalNetwork FMU's parameters, with the provenance of each. :func:`network` assembles
    the :class:`ThermalNetwork`; :func:`mechanism_parameters` derives the values from a
    mounting's geometry and materials.

    Attributes
    ----------
    housing_capacity, shaft_capacity, outer_ring_capacity, inner_ring_capacity : [J/K], > 0
        (each ring node: the rings of both bearings and half of their balls)
    outer_fit_conductance : housing ↔ outer rings through their seats [W/K], > 0
    ball_conductance : outer ↔ inner rings through the balls [W/K], > 0
    inner_fit_conductance : inner rings ↔ shaft through their seats [W/K], > 0
    gas_gap_conductance : shaft ↔ housing through the gas between them [W/K] (not in vacuum)
    mount_conductance : housing ↔ ambient through its mounting [W/K]
    convection_coefficient : h to the ambient air [W/(m²·K)] (not in vacuum)
    housing_convection_area, shaft_convection_area : surfaces in the air [m²]
    housing_emissivity, shaft_emissivity : [-] in [0, 1]
    housing_radiating_area, shaft_radiating_area : surfaces seeing the sink [m²]
    exchange_area : gray-body exchange area 𝓔 shaft ↔ housing [m²]
    inner_ring_heat_fraction : share of the power loss entering the inner rings [-]
    environment : "air" or "vacuum" (:data:`ENVIRONMENTS`; vacuum removes convection and the
        gas gap)
    provenance : ((field, source), ...)
    """

    housing_capacity: float
    shaft_capacity: float
    outer_ring_capacity: float
    inner_ring_capacity: float
    outer_fit_conductance: float
    ball_conductance: float
    inner_fit_conductance: float
    gas_gap_conductance: float = 0.0
    mount_conductance: float = 0.0
    convection_coefficient: float = 0.0
    housing_convection_area: float = 0.0
    shaft_convection_area: float = 0.0
    housing_emissivity: float = 0.0
    housing_radiating_area: float = 0.0
    shaft_emissivity: float = 0.0
    shaft_radiating_area: float = 0.0
    exchange_area: float = 0.0
    inner_ring_heat_fraction: float = 0.5
    environment: str = "air"
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_choice("environment", self.environment, ENVIRONMENTS)
        for field in POSITIVE_FIELDS:
            check_positive(field, getattr(self, field), UNITS[field])
        for field in NONNEGATIVE_FIELDS:
            check_nonnegative(field, getattr(self, field), UNITS[field])
        for field in ("housing_emissivity", "shaft_emissivity", "inner_ring_heat_fraction"):
            check_range(field, getattr(self, field), 0.0, 1.0)

    def source(self, field: str) -> str:
        """Provenance of one field ("" when not recorded)."""
        return dict(self.provenance).get(field, "")

    @property
    def vacuum(self) -> bool:
        """Whether the mechanism is in vacuum (no convection, no gas gap)."""
        return self.environment == "vacuum"

    def as_dict(self) -> dict:
        """{FMU parameter name: value} (the provenance left out)."""
        return {f: getattr(self, f) for f in PARAMETER_FIELDS}


PARAMETER_FIELDS = tuple(f.name for f in dataclasses.fields(ThermalParameters))[:-1]
#: The environments of a mechanism: in air (convection, gas gap) or in vacuum.
ENVIRONMENTS = ("air", "vacuum")
UNITS = {
    **dict.fromkeys(PARAMETER_FIELDS[:4], "J/K"),
    **dict.fromkeys(PARAMETER_FIELDS[4:9], "W/K"),
    "convection_coefficient": "W/(m²·K)",
    **dict.fromkeys(
        ("housing_convection_area", "shaft_convection_area", "housing_radiating_area"), "m²"
    ),
    **dict.fromkeys(("shaft_radiating_area", "exchange_area"), "m²"),
    **dict.fromkeys(("housing_emissivity", "shaft_emissivity", "inner_ring_heat_fraction"), "-"),
}
POSITIVE_FIELDS = PARAMETER_FIELDS[:7]
NONNEGATIVE_FIELDS = tuple(f for f in PARAMETER_FIELDS[7:] if UNITS.get(f, "-") != "-")


def network(p: ThermalParameters) -> ThermalNetwork:
    """The :class:`ThermalNetwork` of the parameters: nodes housing, shaft, outer ring, inner
    ring; in vacuum without convection and without the gas gap.

    Returns
    -------
    ThermalNetwork
        Nodes, capacities [J/K], links [W/K], ambient and sink couplings.

    >>> net = network(preset("yu2017_gimbal_chamber"))
    >>> net.nodes, net.radiating
    (('housing', 'shaft', 'outer_ring', 'inner_ring'), True)
    """
    air = 0.0 if p.vacuum else 1.0
    links = (
        (HOUSING, OUTER, p.outer_fit_conductance),
        (OUTER, INNER, p.ball_conductance),
        (INNER, SHAFT, p.inner_fit_conductance),
        (HOUSING, SHAFT, air * p.gas_gap_conductance),
    )
    h = air * p.convection_coefficient
    return ThermalNetwork(
        capacities=(
            p.housing_capacity,
            p.shaft_capacity,
            p.outer_ring_capacity,
            p.inner_ring_capacity,
        ),
        links=links,
        ambient=(
            p.mount_conductance + h * p.housing_convection_area,
            h * p.shaft_convection_area,
            0.0,
            0.0,
        ),
        sink_radiation=(
            p.housing_emissivity * p.housing_radiating_area,
            p.shaft_emissivity * p.shaft_radiating_area,
            0.0,
            0.0,
        ),
        exchange=((SHAFT, HOUSING, p.exchange_area),),
        heat_split=(0.0, 0.0, 1.0 - p.inner_ring_heat_fraction, p.inner_ring_heat_fraction),
    )


PRESETS = ("yu2017_gimbal_chamber", "ning_space_vacuum", "ning_chamber_air")


def mechanism_parameters(
    bearing,
    mounting,
    *,
    vacuum: bool,
    air_speed: float = 0.0,
    reference_preload: float | None = None,
    mounted: bool = False,
    inner_ring_heat_fraction: float = 0.5,
    n_bearings: int = 2,
    notes: dict | None = None,
) -> ThermalParameters:
    """The network of a bearing pair in its mounting, derived from geometry and materials
    (module docstring), with the provenance of every value.

    Parameters
    ----------
    bearing : :class:`geometry.BallBearing` (dimensions, ring and ball materials)
    mounting : :class:`bearing.Mounting` (housing outside diameter, shaft bore, fits and their
        materials, loop members "frame"/"housing" and "shaft" for the part lengths)
    vacuum : no air: no convection, no gas in the gap, vacuum rows of the contact table
    air_speed : air speed across the housing [m/s] (forced convection; 0: none)
    reference_preload : axial preload [N] at which the ball contacts are evaluated (default:
        the mounting's assembly preload)
    mounted : the housing's end face is bolted to a plate at the ambient temperature
    inner_ring_heat_fraction : share of the power loss entering the inner rings [-]
    n_bearings : bearings in the mechanism (a pair: 2)
    notes : provenance of the values passed in ({argument: source}), e.g. from a preset

    Parts: the housing is a tube from the bearing's outside diameter to the housing's, as long
    as the loop member "frame" (or "housing"); the shaft a (hollow) cylinder of the bearing
    bore, as long as the member "shaft" (either: the longest member when missing). Rings are
    annuli to the groove bottoms (shoulders left out: about a fifth of their mass). The end
    faces of the shaft and of the housing (one of them when mounted) see the air and the sink.

    Returns
    -------
    ThermalParameters
        Capacities [J/K], conductances [W/K], areas [m²], emissivities [-], each with its
        provenance.

    >>> from servofmu.parameters import catalog
    >>> p = mechanism_parameters(catalog.bearing("71803"), catalog.mounting("yu2017_gimbal"),
    ...                          vacuum=False, air_speed=1.0, reference_preload=92.8)
    >>> round(p.housing_capacity, 1), round(p.ball_conductance, 4)
    (147.7, 0.1282)
    """
    notes = dict(notes or {})
    n = int(n_bearings)
    if n < 1:
        raise ValueError(f"n_bearings = {n_bearings!r} must be at least 1")
    preload = _reference_preload(mounting, reference_preload, notes)
    geo = _geometry(bearing, mounting)
    values, prov = {}, {}
    for part in (_capacities, _fits, _gap, _surfaces):
        v, s = part(bearing, mounting, geo, n, vacuum, mounted)
        values.update({k: float(x) for k, x in v.items()})
        prov.update(s)
    values["ball_conductance"] = n * ball_conductance(bearing, preload)
    prov["ball_conductance"] = (
        f"derived: {n} × ball_conductance(Z = {bearing.n_balls}) at the preload "
        f"{preload:.4g} N ({notes.get('reference_preload', '')}), Yovanovich 1976 "
        "constriction of the Hertz ellipses, dry contacts (a lower bound with grease)"
    )
    values["convection_coefficient"] = (
        0.0
        if vacuum
        else forced_convection_coefficient(mounting.fit.housing_outer_diameter, air_speed)
    )
    prov["convection_coefficient"] = (
        "vacuum: no convection"
        if vacuum
        else f"derived: Churchill-Bernstein (Incropera eq 7.54), air at 300 K crossing the "
        f"Ø{mounting.fit.housing_outer_diameter * 1e3:.4g} mm housing at {air_speed:g} m/s "
        f"({notes.get('air_speed', 'given')})"
    )
    values["inner_ring_heat_fraction"] = inner_ring_heat_fraction
    prov["inner_ring_heat_fraction"] = notes.get("inner_ring_heat_fraction", "given")
    return ThermalParameters(
        **values,
        environment="vacuum" if vacuum else "air",
        provenance=tuple(sorted(prov.items())),
    )


def parameters_for_pair(pair, *, vacuum: bool, **options) -> ThermalParameters:
    """:func:`mechanism_parameters` of a :class:`bearing.BearingPair` (or any object with
    ``bearing`` and ``mounting``); ``options`` as there.

    Returns
    -------
    ThermalParameters

    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("ning_space_shaft", "mos2_film")
    >>> round(parameters_for_pair(pair, vacuum=True, mounted=True).mount_conductance, 4)
    0.097
    """
    return mechanism_parameters(pair.bearing, pair.mounting, vacuum=vacuum, **options)


@functools.cache
def preset(key: str) -> ThermalParameters:
    """The parameters of preset ``key`` (:data:`PRESETS`, ``data/thermal.toml``): Yu's
    seeker gimbal in the air of a climatic chamber, Ning's space bearing in thermal vacuum,
    and Ning's bearing on his rig in the air of his high-low temperature chamber.

    Returns
    -------
    ThermalParameters

    >>> round(preset("ning_space_vacuum").housing_capacity, 1)
    145.6
    """
    from ...parameters import catalog

    if key not in PRESETS:
        raise ValueError(f"thermal preset = {key!r} is not one of {list(PRESETS)}")
    entry = catalog.thermal(key)
    mounting = catalog.mounting(entry["mounting"])
    values = {
        f: entry[f][0]
        for f in ("air_speed", "inner_ring_heat_fraction", "reference_preload")
        if f in entry
    }
    notes = {f: entry[f][1] for f in values}
    return mechanism_parameters(
        catalog.bearing(mounting.bearing_key),
        mounting,
        vacuum=entry["vacuum"],
        mounted=entry["mounted"],
        notes=notes,
        **values,
    )


def _reference_preload(mounting, given, notes) -> float:
    if given is not None:
        return check_positive("reference_preload", given, "N")
    if mounting.assembly_preload is None:
        raise ValueError(
            f"mounting {mounting.key!r} gives no assembly preload: pass reference_preload [N], "
            "the preload at which to evaluate the ball contacts"
        )
    notes.setdefault("reference_preload", mounting.source("assembly_preload") or "assembly preload")
    return mounting.assembly_preload


@dataclass(frozen=True)
class _Geometry:
    d: float  # bearing bore = shaft diameter [m]
    outer: float  # bearing outside diameter = housing bore [m]
    housing: float  # housing outside diameter [m]
    bore: float  # shaft bore [m]
    housing_length: float
    shaft_length: float
    lengths: tuple[str, str]  # provenance of the two lengths


def _geometry(bearing, mounting) -> _Geometry:
    members = {m.name: m for m in mounting.loop.members}
    span = max(m.length for m in mounting.loop.members)

    def length(names, part):
        for name in names:
            if name in members:
                src = mounting.source(f"loop.{name}.length") or "the mounting"
                return members[name].length, f"loop member {name!r} ({src})"
        return span, f"assumed: the preload loop's longest member ({span * 1e3:.4g} mm)"

    (lh, sh), (ls, ss) = length(("frame", "housing"), "housing"), length(("shaft",), "shaft")
    fit = mounting.fit
    if fit.housing_outer_diameter <= bearing.outer_diameter:
        raise ValueError(
            f"housing_outer_diameter = {fit.housing_outer_diameter!r} m must exceed the "
            f"bearing's outer_diameter = {bearing.outer_diameter!r} m"
        )
    if fit.shaft_bore >= bearing.bore:
        raise ValueError(f"shaft_bore = {fit.shaft_bore!r} m must be below the bearing bore")
    return _Geometry(
        bearing.bore,
        bearing.outer_diameter,
        fit.housing_outer_diameter,
        fit.shaft_bore,
        lh,
        ls,
        (sh, ss),
    )


def _annulus(d_in, d_out):
    return math.pi / 4.0 * (d_out**2 - d_in**2)


def _heat_capacity(material: Material, volume: float) -> float:
    return material.thermal("density") * material.thermal("specific_heat") * volume


def _capacities(b, mounting, g: _Geometry, n, vacuum, mounted):
    fit = mounting.fit
    ball = 0.5 * b.n_balls * _heat_capacity(b.ball_material, math.pi / 6.0 * b.ball_diameter**3)
    values = {
        "housing_capacity": _heat_capacity(
            fit.housing_material, _annulus(g.outer, g.housing) * g.housing_length
        ),
        "shaft_capacity": _heat_capacity(
            fit.shaft_material, _annulus(g.bore, g.d) * g.shaft_length
        ),
        "outer_ring_capacity": n
        * (
            _heat_capacity(b.ring_material, _annulus(b.outer_groove_diameter, g.outer) * b.width)
            + ball
        ),
        "inner_ring_capacity": n
        * (
            _heat_capacity(b.ring_material, _annulus(g.d, b.inner_groove_diameter) * b.width) + ball
        ),
    }
    ring = f"{b.ring_material.key} ρ·c; half of the {b.n_balls} {b.ball_material.key} balls"
    prov = {
        "housing_capacity": f"derived: ρ·c of {fit.housing_material.key} × tube "
        f"Ø{g.outer * 1e3:.4g}/Ø{g.housing * 1e3:.4g} mm × {g.housing_length * 1e3:.4g} mm, "
        f"length: {g.lengths[0]}",
        "shaft_capacity": f"derived: ρ·c of {fit.shaft_material.key} × cylinder Ø{g.d * 1e3:.4g}"
        f"/Ø{g.bore * 1e3:.4g} mm × {g.shaft_length * 1e3:.4g} mm, length: {g.lengths[1]}",
        "outer_ring_capacity": f"derived: {n} outer rings (annulus D to the groove bottom, {ring})",
        "inner_ring_capacity": f"derived: {n} inner rings (annulus d to the groove bottom, {ring})",
    }
    return values, prov


def _fits(b, mounting, g: _Geometry, n, vacuum, mounted):
    fit = mounting.fit
    values, prov = {}, {}
    seats = (
        ("outer_fit_conductance", fit.housing_material, fit.outer_interference, g.outer),
        ("inner_fit_conductance", fit.shaft_material, fit.inner_interference, g.d),
    )
    pressures = (
        fit_pressure(
            fit.outer_interference,
            g.outer,
            b.outer_groove_diameter,
            g.housing,
            b.ring_material,
            fit.housing_material,
        ),
        fit_pressure(
            fit.inner_interference,
            g.d,
            g.bore,
            b.inner_groove_diameter,
            fit.shaft_material,
            b.ring_material,
        ),
    )
    for (field, seat_material, _, diameter), pressure in zip(seats, pressures, strict=True):
        h, src = contact_conductance(seat_material, b.ring_material, float(pressure), vacuum)
        values[field] = n * h * math.pi * diameter * b.width
        prov[field] = (
            f"derived: {n} seats π·{diameter * 1e3:.4g} mm·{b.width * 1e3:.4g} mm × h_c = "
            f"{h:.4g} W/(m²·K) at the Lamé fit pressure {float(pressure) / 1e6:.3g} MPa of the "
            f"assembly ({'vacuum' if vacuum else 'air'}; {src})"
        )
    return values, prov


def _gap(b, mounting, g: _Geometry, n, vacuum, mounted):
    fit = mounting.fit
    gap = max(g.shaft_length - n * b.width, 0.0)
    k_air, k_src = _handbook()["air_conductivity"]
    eps_s = fit.shaft_material.thermal("emissivity")
    eps_h = fit.housing_material.thermal("emissivity")
    where = (
        f"annulus Ø{g.d * 1e3:.4g}/Ø{g.outer * 1e3:.4g} mm over {gap * 1e3:.4g} mm between "
        "the bearings"
    )
    values = {
        "gas_gap_conductance": 0.0 if vacuum else annulus_conductance(g.d, g.outer, gap, k_air),
        "exchange_area": cylinder_exchange_area(g.d, g.outer, gap, eps_s, eps_h),
    }
    prov = {
        "gas_gap_conductance": "vacuum: no gas"
        if vacuum
        else f"derived: conduction through air ({k_src}) in the {where}",
        "exchange_area": f"derived: concentric cylinders (Incropera Table 13.3), {where}, "
        f"ε {eps_s:g} (shaft) and {eps_h:g} (housing)",
    }
    return values, prov


def _surfaces(b, mounting, g: _Geometry, n, vacuum, mounted):
    fit = mounting.fit
    face = _annulus(g.outer, g.housing)
    housing = math.pi * g.housing * g.housing_length + (1 if mounted else 2) * face
    shaft = 2.0 * _annulus(g.bore, g.d)
    ends = "one end face bolted" if mounted else "both end faces free"
    values = {
        "housing_convection_area": housing,
        "housing_radiating_area": housing,
        "shaft_convection_area": shaft,
        "shaft_radiating_area": shaft,
        "housing_emissivity": fit.housing_material.thermal("emissivity"),
        "shaft_emissivity": fit.shaft_material.thermal("emissivity"),
        "mount_conductance": _mount(fit.housing_material, face, g.housing_length, vacuum)
        if mounted
        else 0.0,
    }
    prov = {
        "housing_convection_area": f"derived: outside of the housing tube, {ends}",
        "housing_radiating_area": f"derived: outside of the housing tube, {ends}",
        "shaft_convection_area": "assumed: the two end faces of the shaft are exposed",
        "shaft_radiating_area": "assumed: the two end faces of the shaft see the sink",
        "housing_emissivity": fit.housing_material.source("emissivity"),
        "shaft_emissivity": fit.shaft_material.source("emissivity"),
        "mount_conductance": (
            "derived: the housing end face on a plate of the same metal (Incropera Table "
            "3.1, 100 kPa row) in series with conduction through half the housing"
            if mounted
            else "assumed: not mounted to a temperature-controlled plate"
        ),
    }
    return values, prov


def _mount(material: Material, face: float, length: float, vacuum: bool) -> float:
    """Housing end face (area ``face`` [m²]) on a plate at the ambient temperature: a light
    contact of the metal on itself in series with conduction over half the housing length."""
    h, _ = contact_conductance(material, material, 0.0, vacuum)
    wall = material.thermal("thermal_conductivity") * face / (0.5 * length)
    return 1.0 / (1.0 / (h * face) + 1.0 / wall)
