r"""Torque of a grease-packed ball bearing at low temperature, calibrated on a grease
datasheet's low-temperature torque test and carried to another bearing by Palmgren's law.

The datasheet tests (records with provenance in ``data/grease_torques.toml``, ``[tests]``):

- ASTM D1478 (and FED-STD-791 Method 3458, its military twin): a No. 6204 open ball bearing
  (d = 20, D = 47 mm) packed completely full and struck off flush, held 2 h at the test
  temperature, inner ring turned at 1 ± 0.05 r/min; the restraining torque on the outer ring
  is the starting torque and, after 60 min, the running torque (§4.1); housing mass
  454 ± 3 g (§6.1.3); torque [g·cm] = 6.50 × scale reading [g] (§9.1.1).
- JIS K 2220, low-temperature torque (5.14; §18 in the current edition), as described by the
  Japan Lubricating Oil Society (JALOS Q&A ID-207): a 6204 open ball bearing filled 100 %,
  held 2 h at the test temperature, inner ring turned at 1 r/min; the starting torque is the
  largest reading on starting, the running torque the reading after 10 min (not ASTM's 60 min,
  so the two tests' running torques are not the same quantity). The housing mass is not in
  the stored description; ASTM D1478's 454 g is assumed.

Running torque: Palmgren's load-independent torque (Palmgren 1959, *Ball and Roller Bearing
Engineering*; the form of Yu 2017 eq 8, :func:`friction.palmgren_viscous_torque`)

.. math::

   M_0 = 10^{-7} f_0\,(\nu n)^{2/3} d_m^3 \quad [\mathrm{N\,mm}]

for :math:`\nu n \ge 2000` mm²/s·r/min (:math:`160\times10^{-7} f_0\,d_m^3` below),
ν the base oil's kinematic viscosity at the bearing temperature, n in r/min, dm in mm. The
grease factor f0 is calibrated on one datasheet running torque (:func:`grease_factor`); the
law then carries it to another temperature (through ν(T)), speed (n^(2/3)) and bearing
(dm³). Starting torque: the datasheet's starting/running ratio ks, taken as constant
(:func:`starting_ratio`): M_start = ks·M0 at the test's speed.

**The cold start.** What a lubricant adds to a bearing's breakaway after a soak at rest is
taken from its published starting-torque test: the breakaway adds ks times the lubricant's
running torque at the test's speed, M_start = ks·M0(ν(T), n_test, dm), so that it follows the
base oil's viscosity with temperature. Yu 2017 §1 cites Wikström & Höglund (Tribology
Transactions 39(3), 1996, parts I and II: starting and steady-state torque of grease-lubricated
rolling bearings at low temperatures) for the base oil's viscosity as the main cause of the
rise of a bearing's torque in the cold; the starting test's ratio carries the grease's yield
at rest, which no viscosity gives. ks and f0 are calibrated on the named datasheet points
(:func:`fit_points`); at any other temperature, speed or bearing the term is a prediction.
A lubricant without a published starting torque has no ks (0): BearingFriction then sets
``breakaway_lower_bound``, since its breakaway holds only the zero-speed limit of the viscous
term (a grease's yield at rest is missing from it).

Limits (stated, not modelled):

- dm³ presumes geometrically similar bearings with the same relative grease fill. The test
  bearing is packed completely full; a bearing filled to 20–40 % churns less, so the term
  over-predicts it by an unknown factor. Channelling after running-in is not modelled.
- (ν·n)^(2/3) is Palmgren's law for a lubricant's viscous drag. At low temperature a grease's
  torque is carried largely by its thickener (f0 calibrated on datasheets comes out ten or more
  times the oil values), so the base-oil ν(T) may under-state the temperature sensitivity.
- ks constant in temperature and size is an assumption without a cited law.
- Only where ν·n of the user's bearing lies near the test's (1 r/min, cold): at high speed
  the grease channels and Palmgren's oil-bath correlation no longer describes it.
- The running torque is read after different times in the two tests (JIS 10 min, ASTM
  60 min), while the fill is still being worked; f0 holds for the test it was calibrated on.
"""

from __future__ import annotations

from dataclasses import dataclass

from .._checks import check_finite, check_positive, check_range
from ..kernels.units import RPM
from .terms import palmgren_viscous_torque


def grease_factor(running_torque, kinematic_viscosity, speed, mean_diameter):
    """Palmgren factor f0 [-] calibrated on one measured running torque of a grease-packed
    bearing: f0 = M_run / M0(f0 = 1) (Palmgren 1959; Yu 2017 eq 8).

    Parameters
    ----------
    running_torque : measured running torque M_run [N·m], > 0
    kinematic_viscosity : base-oil viscosity ν [m²/s] at the test temperature
    speed : test speed ω [rad/s] (ASTM D1478: 1 r/min)
    mean_diameter : dm [m] of the test bearing (6204: 33.5 mm)

    Returns
    -------
    f0 [-]

    >>> w = 2 * 3.141592653589793 / 60                      # 1 r/min
    >>> round(grease_factor(0.050, 5000e-6, w, 0.0335), 2)  # 50 mN·m, ν = 5000 mm²/s
    45.48
    """
    m = check_positive("running_torque", running_torque, "N·m")
    unit = palmgren_viscous_torque(kinematic_viscosity, speed, mean_diameter, 1.0)
    check_positive("palmgren torque at f0 = 1", unit, "N·m")
    return m / unit


def starting_ratio(starting_torque, running_torque):
    """Starting-to-running torque ratio ks = M_start/M_run [-] of one datasheet test.

    Parameters
    ----------
    starting_torque, running_torque : [N·m], > 0

    Returns
    -------
    ks [-], ≥ 1 expected (a ratio below 1 is accepted: some greases shear-thin at start)

    >>> round(starting_ratio(0.099, 0.050), 3)
    1.98
    """
    s = check_positive("starting_torque", starting_torque, "N·m")
    r = check_positive("running_torque", running_torque, "N·m")
    return s / r


@dataclass(frozen=True)
class GreaseTorqueTerm:
    """A calibrated grease torque term (see the module docstring for the law and its limits):
    a running part (f0 > 0) and a cold start (ks > 0), either of them 0 when its data are
    missing.

    Attributes
    ----------
    f0 : Palmgren factor [-], calibrated (0: no running part; the cold start then multiplies
        the friction model's own viscous torque)
    starting_ratio : ks = M_start/M_run [-], calibrated (0: no starting data)
    reference_speed : the test's speed [rad/s], at which ks was measured
    provenance : ((field, source), ...)
    """

    f0: float
    starting_ratio: float
    reference_speed: float
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_range("f0", self.f0, 0.0, None)
        check_range("starting_ratio", self.starting_ratio, 0.0, 1000.0)
        check_positive("reference_speed", self.reference_speed, "rad/s")
        if not (self.f0 > 0.0 or self.starting_ratio > 0.0):
            raise ValueError("a grease term needs f0 > 0 or starting_ratio > 0 (else: none)")

    @property
    def has_start(self) -> bool:
        """Whether the term knows the lubricant's starting torque (ks > 0)."""
        return self.starting_ratio > 0.0

    def running(self, kinematic_viscosity, speed, mean_diameter):
        """Running torque of one grease-packed bearing [N·m] at base-oil viscosity ν [m²/s],
        speed ω [rad/s] (sign ignored) and mean diameter dm [m]: Palmgren's M0 with f0.

        >>> t = GreaseTorqueTerm(f0=45.48, starting_ratio=1.98, reference_speed=0.10472)
        >>> round(t.running(5000e-6, 0.10472, 0.0335) * 1e3, 1)  # mN·m
        50.0
        """
        return palmgren_viscous_torque(kinematic_viscosity, speed, mean_diameter, self.f0)

    def starting(self, kinematic_viscosity, mean_diameter):
        """Starting torque [N·m] of one grease-packed bearing: ks times the running torque at
        the test's speed, at base-oil viscosity ν [m²/s] and mean diameter dm [m].

        >>> t = GreaseTorqueTerm(f0=45.48, starting_ratio=1.98, reference_speed=0.10472)
        >>> round(t.starting(5000e-6, 0.0335) * 1e3, 1)  # mN·m
        99.0
        """
        return self.starting_ratio * self.running(
            kinematic_viscosity, self.reference_speed, mean_diameter
        )


def relative_fit(ratios) -> float:
    """x minimising Σ (x·r_i − 1)²: Σ r_i / Σ r_i² (a relative least-squares scale).

    Parameters
    ----------
    ratios : sequence of float
        r_i [-], > 0.

    Returns
    -------
    float
        x [-].

    >>> relative_fit([1.0, 1.0])
    1.0
    """
    return sum(ratios) / sum(r * r for r in ratios)


def fit_points(points, rig, visc):
    """f0 and ks fitted on published torques of one test (relative least squares: f0 on the
    running torques, then ks on the starting torques with the model's own running torques;
    one point: both exactly), and the per-point numbers.

    Parameters
    ----------
    points : sequence of :class:`GreaseTorquePoint` of one test
    rig : the test's :class:`TorqueTest`
    visc : the base oil's viscosity model (its law, extrapolated where it must be)

    Returns
    -------
    tuple
        (f0, ks, rows): rows = [(temperature [K], ν [m²/s], M_start, M_run [N·m], f0_i [-])].

    >>> rig, visc = torque_test("jis_k2220"), base_oil_viscosity("molykote_g1074")
    >>> f0, ks, rows = fit_points(grease_torque_points("molykote_g1074"), rig, visc)
    >>> round(f0, 2), round(ks, 2), len(rows)
    (10.89, 1.98, 1)
    """
    rows = []
    for p in points:
        nu = float(visc.kinematic_viscosity(p.temperature))
        f0_i = grease_factor(p.running_torque, nu, rig.speed, rig.mean_diameter)
        rows.append((p.temperature, nu, p.starting_torque, p.running_torque, f0_i))
    f0 = relative_fit([1.0 / r[4] for r in rows])
    # the model's running torque at the test speed: f0·u_i = r_run·f0/f0_i
    model_run = [r[3] * f0 / r[4] for r in rows]
    ks = relative_fit([m / r[2] for m, r in zip(model_run, rows, strict=True)])
    return f0, ks, rows


def lubricant_term(lubricant: str) -> GreaseTorqueTerm | None:
    """The grease term of catalogue lubricant ``lubricant`` calibrated on its published
    low-temperature torques (``data/grease_torques.toml``; :func:`fit_points` on the points of
    the test its first point names), or None when it has none.

    Returns
    -------
    GreaseTorqueTerm or None

    >>> t = lubricant_term("molykote_g1074")
    >>> round(t.f0, 2), round(t.starting_ratio, 2), dict(t.provenance)["f0"][:10]
    (10.89, 1.98, 'calibrated')
    >>> lubricant_term("krytox_143aa") is None
    True
    """
    points = grease_torque_points(lubricant)
    if not points:
        return None
    test = points[0].test
    chosen = [p for p in points if p.test == test]
    rig = torque_test(test)
    f0, ks, rows = fit_points(chosen, rig, base_oil_viscosity(lubricant))
    where = ", ".join(f"{t - 273.15:g} °C" for t, *_ in rows)
    src = f"calibrated: {rig.name} datasheet point(s) of {lubricant} at {where}"
    return GreaseTorqueTerm(
        f0=f0,
        starting_ratio=ks,
        reference_speed=rig.speed,
        provenance=(
            ("f0", src + " (running torque)"),
            ("starting_ratio", src + " (starting/running)"),
            ("reference_speed", f"{rig.source('speed')} ({test})"),
        ),
    )


def calibrate_grease_term(
    starting_torque, running_torque, kinematic_viscosity, speed, mean_diameter, provenance=()
) -> GreaseTorqueTerm:
    """The :class:`GreaseTorqueTerm` calibrated on one datasheet point: f0 on the running
    torque (:func:`grease_factor`), ks on the starting/running ratio (:func:`starting_ratio`).

    Parameters
    ----------
    starting_torque, running_torque : datasheet torques [N·m]
    kinematic_viscosity : base-oil ν [m²/s] at the test temperature
    speed : test speed [rad/s]
    mean_diameter : test bearing dm [m]
    provenance : ((field, source), ...) to carry along

    Returns
    -------
    :class:`GreaseTorqueTerm`

    >>> w = 2 * 3.141592653589793 / 60
    >>> t = calibrate_grease_term(0.099, 0.050, 5000e-6, w, 0.0335)
    >>> round(t.f0, 2), round(t.starting_ratio, 2)
    (45.48, 1.98)
    """
    check_finite("speed", speed, "rad/s")
    return GreaseTorqueTerm(
        f0=grease_factor(running_torque, kinematic_viscosity, speed, mean_diameter),
        starting_ratio=starting_ratio(starting_torque, running_torque),
        reference_speed=abs(speed),
        provenance=tuple(provenance),
    )


@dataclass(frozen=True)
class TorqueTest:
    """A grease low-temperature torque test standard (``data/grease_torques.toml``).

    Attributes
    ----------
    key, name : e.g. "astm_d1478"
    bore, outer_diameter : test bearing d, D [m]
    speed : test speed [rad/s]
    radial_load : load on the test bearing [N] (from the housing mass)
    provenance : ((field, source), ...)
    """

    key: str
    name: str
    bore: float
    outer_diameter: float
    speed: float
    radial_load: float
    provenance: tuple[tuple[str, str], ...] = ()

    @property
    def mean_diameter(self) -> float:
        """dm = (d + D)/2 [m]."""
        return 0.5 * (self.bore + self.outer_diameter)

    @property
    def speed_rpm(self) -> float:
        return self.speed / RPM

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


@dataclass(frozen=True)
class GreaseTorquePoint:
    """One published low-temperature torque of a grease (``data/grease_torques.toml``).

    Attributes
    ----------
    lubricant : lubricant key (e.g. "molykote_g1074")
    test : test key (e.g. "jis_k2220")
    temperature : [K]
    starting_torque, running_torque : [N·m]
    provenance : ((field, source), ...)
    """

    lubricant: str
    test: str
    temperature: float
    starting_torque: float
    running_torque: float
    provenance: tuple[tuple[str, str], ...] = ()

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


def _entry_quantities(entry: dict, fields) -> tuple[dict, list]:
    from ...parameters.catalog import quantity

    values, prov = {}, []
    for field in fields:
        values[field], src = quantity(entry[field], field)
        prov.append((field, src))
    return values, prov


def torque_test(key: str) -> TorqueTest:
    """The :class:`TorqueTest` ``key`` from ``data/grease_torques.toml`` (``[tests.KEY]``).

    Parameters
    ----------
    key : "astm_d1478" or "jis_k2220"

    Returns
    -------
    :class:`TorqueTest` (SI)

    >>> round(torque_test("astm_d1478").mean_diameter * 1e3, 1)
    33.5
    """
    from ...parameters.catalog import _table

    tests = _table("grease_torques")["tests"]
    if key not in tests:
        raise ValueError(f"torque test key = {key!r} is not one of {sorted(tests)}")
    entry = tests[key]
    fields = ("bore", "outer_diameter", "speed", "housing_mass")
    v, prov = _entry_quantities(entry, fields)
    load = v.pop("housing_mass") * 9.80665
    prov.append(("radial_load", "derived: housing mass × g; " + dict(prov)["housing_mass"]))
    return TorqueTest(
        key=key,
        name=entry["name"],
        bore=v["bore"],
        outer_diameter=v["outer_diameter"],
        speed=v["speed"],
        radial_load=load,
        provenance=tuple(prov),
    )


def grease_torque_points(lubricant: str) -> list[GreaseTorquePoint]:
    """Published low-temperature torques of ``lubricant`` (``data/grease_torques.toml``).

    Parameters
    ----------
    lubricant : lubricant key

    Returns
    -------
    list of :class:`GreaseTorquePoint` (SI), possibly empty

    >>> [round(p.running_torque * 1e3, 1) for p in grease_torque_points("molykote_g1074")]
    [50.0]
    """
    from ...parameters.catalog import _table

    entry = _table("grease_torques").get("greases", {}).get(lubricant, {})
    out = []
    for pt in entry.get("points", []):
        fields = ("temperature", "starting_torque", "running_torque")
        v, prov = _entry_quantities(pt, fields)
        out.append(
            GreaseTorquePoint(lubricant=lubricant, test=pt["test"], provenance=tuple(prov), **v)
        )
    return out


def base_oil_viscosity(lubricant: str):
    """The base oil's viscosity model of catalogue lubricant ``lubricant``
    (``data/lubricants.toml``: the values of a grease are its base oil's).

    Parameters
    ----------
    lubricant : lubricant key

    Returns
    -------
    :class:`viscosity.ViscosityRange` (its law: the ASTM D341 line through ν40 and ν100, or
    Vogel's law through further points)

    >>> nu = base_oil_viscosity("molykote_g1074")
    >>> round(float(nu.kinematic_viscosity(313.15)) * 1e6, 3)   # 53 mm²/s at 40 °C
    53.0
    """
    from ...parameters.catalog import keys
    from ...parameters.catalog import lubricant as viscosity

    if lubricant not in keys("lubricants"):
        raise ValueError(f"lubricant = {lubricant!r} has no base-oil viscosities in lubricants")
    model = viscosity(lubricant)
    if model is None:
        raise ValueError(f"lubricant = {lubricant!r} is a dry film: no base-oil viscosity")
    return model
