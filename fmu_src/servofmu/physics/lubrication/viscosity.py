r"""Lubricant viscosity versus temperature, and the range of temperatures a lubricant's data
cover.

Two laws, each written once (kinematic viscosity ν, absolute temperature T):

- **Walther** (ASTM D341-20 §5; Yu 2017 eq 18), ν in cSt, T in K, lg = log10:

  .. math::

     \lg\,\lg(\nu + c) = a - b\,\lg T

  c = 0.7 cSt in ASTM D341, 0.932 in Yu's least-squares fit to DuPont's Krytox
  143AA data (catalogue key ``krytox_143aa``: Yu's a, b, c stay his). Two viscosities fix a and
  b (:func:`walther_from_two_points`): the ASTM D341 line through a datasheet's ν40 and ν100.
- **Vogel** (Vogel H., "Das Temperaturabhängigkeitsgesetz der Viskosität von Flüssigkeiten",
  Physikalische Zeitschrift 22 (1921) 645–646; reviewed with the Walther form by Seeton C. J.,
  "Viscosity–temperature correlation for liquids", Tribology Letters 22 (2006) 67–78,
  doi:10.1007/s11249-006-9071-2, §2):

  .. math::

     \ln \nu = a + \frac{b}{T - T_\infty}

  applied to the kinematic viscosity
  (the datasheets' quantity; a density change of a few per cent over the range goes into the
  constants). Three viscosities fix a, b and T∞ (:func:`vogel_from_points`).

Which law a lubricant uses: the ASTM D341 line when two viscosities are known (the datasheet
pair), Vogel's law when three or more are: through three exactly, through more by least
squares in ln ν. ASTM D341 draws a petroleum oil's viscosity as a straight line (§1.2), and a
straight line through ν40 and ν100 misses the cold points the catalogue holds: +57 % for
Pennzane SHF X-2000 at −40 °C, −59 % and −81 % for the VI-improved MIL-PRF-5606 oil X/C 5606J
at −40 and −54 °C. D341 applied piecewise between neighbouring points would pass each point
but bend at each and carry the last segment's slope below the coldest one; Vogel's third
constant bends the curve smoothly (T∞ is where the fit diverges, below every temperature it
is used at), and through the four points of X/C 5606J it misses none by more than 1 %
(``servofmu paper validation``, section viscosity).

**Range.** A viscosity model knows a lubricant between ``lower_limit`` and ``upper_limit``
[K] (:class:`ViscosityRange`): from the coldest temperature its data reach (its coldest
published viscosity, or the coldest temperature a paper's fit was used at) to an upper limit
the catalogue states (the maker's upper operating temperature, else the highest published
viscosity). Outside the range :meth:`ViscosityRange.outside` flags the point. A lubricant's
*flow limit* ``flow_limit`` is a different number: its published pour point (ASTM D97: the
lowest temperature at which it still flows), or, where none is published, the maker's lower
operating temperature. ASTM D341-20 §3.1 limits its charts to temperatures where the oil is a
homogeneous liquid, above its cloud point, a few kelvin above the pour point. A data end is
not a flow limit: an oil known to −40 °C may flow at −60 °C. What a bearing model uses
(:meth:`ViscosityRange.operating_viscosity`):

- between the data end and the flow limit, the law extrapolated (flagged): the liquid still
  flows, and its law is the usual estimate there (D341 §1.2 draws a petroleum oil's line
  straight; Vogel's third constant bends it towards its divergence T∞);
- below the flow limit no law holds (a gel, then a glass): the user's choice
  ``below_flow_limit`` (:data:`BELOW_FLOW_LIMIT`), ``"hold"`` the viscosity at its value at
  the limit (the default: finite torques, the flag says they are not backed by data) or
  ``"extrapolate"`` the law further (a bound the other way: the law's steep rise);
- a lubricant without a published flow limit (``flow_limit`` 0) is extrapolated at every
  temperature below its data: nothing says where its liquid law ends;
- above the upper limit the law is extrapolated (D341 §1.2: the lines stay straight to about
  340 °C; the viscosity keeps falling and the viscous torque with it).

Vogel's law diverges at T∞: it must lie below the coldest temperature the model is used at
(the hold temperature, else the lowest temperature the FMUs accept,
:data:`._checks.TEMPERATURE_RANGE`).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from .._checks import (
    TEMPERATURE_RANGE,
    check_choice,
    check_positive,
    check_range,
    check_temperature,
)
from ..kernels.units import CST
from ..kernels.viscosity import (  # the laws, shared with the per-step path
    operating_temperature,
    vogel_log_viscosity,
    walther_viscosity,
)

#: The reference temperatures of ν40 and ν100 (ISO 3448, ASTM D341) [K].
T40, T100 = 313.15, 373.15
#: What a bearing model does below a lubricant's flow limit (module docstring).
BELOW_FLOW_LIMIT = ("hold", "extrapolate")


@dataclass(frozen=True)
class ViscosityRange:
    """The temperatures a lubricant's viscosity data cover, its flow limit, and what a bearing
    model uses outside the data (module docstring). Base of the viscosity models.

    Attributes
    ----------
    lower_limit : the coldest temperature its data reach [K] (0: none)
    upper_limit : the upper limit its catalogue entry states [K] (inf: none)
    flow_limit : its pour point, or the maker's lower operating temperature where no pour
        point is published [K] (0: none published: the law is extrapolated at every
        temperature below the data)
    below_flow_limit : "hold" (the viscosity at its value at the flow limit) or
        "extrapolate" (the law) below the flow limit (:data:`BELOW_FLOW_LIMIT`)
    """

    lower_limit: float = 0.0
    upper_limit: float = math.inf
    flow_limit: float = 0.0
    below_flow_limit: str = "hold"

    def _check_range(self):
        lo = check_range("lower_limit", self.lower_limit, 0.0, None, unit="K")
        if not (lo < self.upper_limit and self.upper_limit > 0.0):
            raise ValueError(
                f"upper_limit = {self.upper_limit!r} K must lie above lower_limit = {lo!r} K"
            )
        check_range("flow_limit", self.flow_limit, 0.0, self.upper_limit, unit="K")
        check_choice("below_flow_limit", self.below_flow_limit, BELOW_FLOW_LIMIT)

    @property
    def hold_temperature(self) -> float:
        """The temperature [K] below which the viscosity is held at its value there: the flow
        limit (the data end if that is colder) when ``below_flow_limit`` is "hold"; 0 when the
        law is extrapolated everywhere.

        >>> ViscosityRange(233.15, 333.15, flow_limit=213.15).hold_temperature
        213.15
        >>> ViscosityRange(233.15, 333.15, 213.15, "extrapolate").hold_temperature
        0.0
        """
        if self.flow_limit > 0.0 and self.below_flow_limit == "hold":
            return min(self.flow_limit, self.lower_limit or self.flow_limit)
        return 0.0

    @property
    def coldest_use(self) -> float:
        """The coldest temperature [K] at which the law is evaluated: the hold temperature,
        else the lowest temperature the models accept (:data:`._checks.TEMPERATURE_RANGE`)."""
        return self.hold_temperature or TEMPERATURE_RANGE[0]

    def _check_held(self):
        """The law must be a finite number down to :attr:`coldest_use`."""
        t = self.coldest_use
        try:
            nu = self.viscosity_at(t)
        except (OverflowError, ZeroDivisionError, ValueError):
            nu = math.inf
        if not 0.0 < nu < math.inf:
            where = "flow_limit" if self.hold_temperature else "the coldest temperature accepted"
            raise ValueError(
                f"the viscosity at {where} = {t!r} K is {nu!r} m²/s: the law has no finite "
                "value there (raise the flow limit, or hold below it)"
            )

    def kinematic_viscosity(self, temperature):  # the law (subclasses)
        raise NotImplementedError

    def viscosity_at(self, t: float) -> float:  # the law on one float (subclasses)
        raise NotImplementedError

    def outside(self, temperature):
        """True where ``temperature`` [K] (float or array) lies outside
        [``lower_limit``, ``upper_limit``], the range of the data.

        Returns
        -------
        bool or ndarray of bool

        Examples
        --------
        >>> ViscosityRange(233.15, 333.15).outside(np.array([173.15, 253.15]))
        array([ True, False])
        """
        t = np.asarray(temperature)
        out = (t < self.lower_limit) | (t > self.upper_limit)
        return bool(out) if out.ndim == 0 else out

    def below_flow(self, temperature):
        """True where ``temperature`` [K] (float or array) lies below the flow limit (never
        without one).

        >>> ViscosityRange(233.15, 333.15, flow_limit=213.15).below_flow(203.15)
        True
        """
        t = np.asarray(temperature)
        out = (t < self.flow_limit) & (self.flow_limit > 0.0)
        return bool(out) if out.ndim == 0 else out

    def operating_viscosity(self, temperature):
        """The viscosity a bearing model uses at ``temperature`` [K] (float or array): the
        law's, held below :attr:`hold_temperature` (module docstring) [m²/s].

        Returns
        -------
        float or ndarray
            Kinematic viscosity [m²/s].

        Examples
        --------
        >>> held = walther_from_reference(32e-6, 5.4e-6, lower_limit=273.15, flow_limit=253.15)
        >>> bool(held.operating_viscosity(173.15) == held.kinematic_viscosity(253.15))
        True
        >>> bool(held.operating_viscosity(263.15) == held.kinematic_viscosity(263.15))
        True
        """
        t = check_temperature("temperature", temperature)
        hold = self.hold_temperature
        return self.kinematic_viscosity(np.maximum(t, hold) if hold else t)

    def operating_viscosity_at(self, t: float) -> float:
        """:meth:`operating_viscosity` on one float [K] → [m²/s] (the per-step path)."""
        return self.viscosity_at(operating_temperature(t, self.hold_temperature))


@dataclass(frozen=True, kw_only=True)
class WaltherViscosity(ViscosityRange):
    """Kinematic viscosity model lg lg(ν[cSt] + c) = a − b·lg(T[K]) (Yu 2017 eq 18; ASTM D341).

    Attributes
    ----------
    key, name : catalogue key and name
    a, b : Walther coefficients [-]
    c : additive constant [cSt] (0.7 in ASTM D341; 0.932 in Yu's Krytox fit)
    provenance : ((field, source), ...)
    lower_limit, upper_limit : the lubricant's range [K] (:class:`ViscosityRange`)
    """

    key: str
    name: str
    a: float
    b: float
    c: float = 0.7
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_range("a", self.a)
        check_positive("b", self.b)
        check_range("c", self.c, 0.0, 10.0, lo_open=True, unit="cSt")
        self._check_range()
        self._check_held()

    def kinematic_viscosity(self, temperature):
        """ν(T) [m²/s] of the law for ``temperature`` [K] (scalar or array). Yu 2017 eq 18."""
        return walther_kinematic_viscosity(temperature, self.a, self.b, self.c)

    def viscosity_at(self, t: float) -> float:
        """The law at one float temperature [K] → ν [m²/s] (math instead of numpy)."""
        return walther_viscosity(math.log10(t), self.a, self.b, self.c) * CST

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


def walther_kinematic_viscosity(temperature, a: float, b: float, c: float = 0.7):
    """Kinematic viscosity [m²/s] from the Walther equation (Yu 2017 eq 18; ASTM D341).

    Parameters
    ----------
    temperature : absolute temperature T [K], > 0
    a, b : Walther coefficients [-] of lg lg(ν + c) = a − b·lg T (lg = log10, ν in cSt)
    c : additive constant [cSt]

    The equation is written in cSt and kelvin; the result is converted to m²/s.

    Returns
    -------
    float or ndarray
        ν [m²/s].

    Examples
    --------
    >>> nu = walther_kinematic_viscosity(313.15, 8.0, 3.1)
    >>> round(float(nu) * 1e6, 2)  # cSt at 40 °C for lg lg(ν + 0.7) = 8 − 3.1·lg T
    67.38
    """
    t = check_temperature("temperature", temperature)
    return walther_viscosity(np.log10(t), a, b, c) * CST


def walther_from_two_points(
    t1: float,
    nu1: float,
    t2: float,
    nu2: float,
    c: float = 0.7,
    key: str = "",
    name: str = "",
    lower_limit: float = 0.0,
    upper_limit: float = math.inf,
    **flow,
) -> WaltherViscosity:
    """Walther/ASTM D341 fit through two measured viscosities.

    Parameters
    ----------
    t1, t2 : temperatures [K], different
    nu1, nu2 : kinematic viscosities [m²/s] at t1, t2; ν + c must exceed 1 cSt so that
        lg lg(ν + c) is defined
    c : additive constant [cSt] (ASTM D341: 0.7)
    lower_limit, upper_limit : the lubricant's range [K] (:class:`ViscosityRange`)
    flow : ``flow_limit`` [K] and ``below_flow_limit`` (:class:`ViscosityRange`)

    Returns the :class:`WaltherViscosity` with b = (Y1 − Y2)/(lg T2 − lg T1), a = Y1 + b·lg T1,
    Y = lg lg(ν[cSt] + c).

    Examples
    --------
    >>> v = walther_from_two_points(313.15, 32e-6, 373.15, 5.4e-6)  # an ISO VG 32 oil
    >>> round(float(v.kinematic_viscosity(313.15)) * 1e6, 9)  # cSt: back through the point
    32.0
    """
    t1 = check_temperature("t1", t1)
    t2 = check_temperature("t2", t2)
    if t1 == t2:
        raise ValueError(f"t2 = {t2!r} K must differ from t1 = {t1!r} K")
    y = []
    for label, nu in (("nu1", nu1), ("nu2", nu2)):
        nu_cst = check_positive(label, nu, "m²/s") / CST
        if nu_cst + c <= 1.0:
            raise ValueError(
                f"{label} = {nu!r} m²/s gives ν + c = {nu_cst + c:g} cSt; Walther needs > 1 cSt"
            )
        y.append(np.log10(np.log10(nu_cst + c)))
    b = (y[0] - y[1]) / (np.log10(t2) - np.log10(t1))
    a = y[0] + b * np.log10(t1)
    if b <= 0:
        raise ValueError(
            f"viscosity must fall with temperature: nu1 = {nu1!r} at t1 = {t1!r} K and "
            f"nu2 = {nu2!r} at t2 = {t2!r} K give b = {b:g} <= 0"
        )
    prov = (("a", "derived: ASTM D341 two-point fit"), ("b", "derived: ASTM D341 two-point fit"))
    return WaltherViscosity(
        key=key,
        name=name,
        a=float(a),
        b=float(b),
        c=c,
        provenance=prov,
        lower_limit=lower_limit,
        upper_limit=upper_limit,
        **flow,
    )


def walther_from_reference(
    viscosity_40: float,
    viscosity_100: float,
    c: float = 0.7,
    key: str = "",
    name: str = "",
    lower_limit: float = 0.0,
    upper_limit: float = math.inf,
    **flow,
) -> WaltherViscosity:
    """Walther/ASTM D341 model through the kinematic viscosities at 40 and 100 °C, the two
    numbers of every lubricant datasheet (:func:`walther_from_two_points` at 313.15 and
    373.15 K): the model of a lubricant with two known viscosities. Catalogue entries that give
    a, b (and c) are turned into ν40 and ν100 first, so that the FMU parameters
    ``lubricant_viscosity_40``/``_100`` reproduce them exactly.

    Parameters
    ----------
    viscosity_40, viscosity_100 : ν at 40 and 100 °C [m²/s], ν100 < ν40
    c : Walther's additive constant [cSt] (ASTM D341: 0.7)
    lower_limit, upper_limit : the lubricant's range [K] (:class:`ViscosityRange`)
    flow : ``flow_limit`` [K] and ``below_flow_limit`` (:class:`ViscosityRange`)

    Returns
    -------
    WaltherViscosity

    Examples
    --------
    >>> vg32 = walther_from_reference(32e-6, 5.4e-6)
    >>> round(float(vg32.kinematic_viscosity(T40)) * 1e6, 9)  # cSt at 40 °C
    32.0
    """
    nu40 = check_positive("viscosity_40", viscosity_40, "m²/s")
    nu100 = check_positive("viscosity_100", viscosity_100, "m²/s")
    if not nu100 < nu40:
        raise ValueError(
            f"viscosity_100 = {nu100!r} m²/s must be below viscosity_40 = {nu40!r} m²/s "
            "(a lubricant thins on heating)"
        )
    return walther_from_two_points(
        T40, nu40, T100, nu100, c=c, key=key, name=name,
        lower_limit=lower_limit, upper_limit=upper_limit, **flow,
    )  # fmt: skip


@dataclass(frozen=True, kw_only=True)
class VogelViscosity(ViscosityRange):
    """Kinematic viscosity model ln ν = a + b/(T − T∞) (Vogel 1921), ν in m²/s, T in K.

    Attributes
    ----------
    key, name : catalogue key and name
    a : ln ν at infinite temperature [ln(m²/s)]
    b : [K], > 0
    t_inf : Vogel temperature T∞ [K], where the law diverges; below ``lower_limit`` (and below
        every point it was fitted through)
    points : the (T [K], ν [m²/s]) points the law was fitted through
    provenance : ((field, source), ...)
    lower_limit, upper_limit : the lubricant's range [K] (:class:`ViscosityRange`)
    """

    key: str
    name: str
    a: float
    b: float
    t_inf: float
    points: tuple[tuple[float, float], ...] = ()
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_range("a", self.a)
        check_positive("b", self.b, "K")
        check_range("t_inf", self.t_inf, unit="K")
        self._check_range()
        coldest = min([t for t, _ in self.points] + [self.coldest_use])
        if not self.t_inf < coldest:
            raise ValueError(
                f"Vogel's T∞ = {self.t_inf:.6g} K must lie below the lowest temperature the "
                f"law is used at ({coldest:.6g} K: the flow limit it is held at, the coldest "
                "temperature accepted, or the coldest point), where it diverges"
            )
        self._check_held()

    def kinematic_viscosity(self, temperature):
        """ν(T) [m²/s] of the law for ``temperature`` [K] (scalar or array), Vogel 1921."""
        t = check_temperature("temperature", temperature)
        if np.any(np.asarray(t) <= self.t_inf):
            raise ValueError(
                f"temperature = {float(np.min(t))!r} K is at or below Vogel's T∞ = "
                f"{self.t_inf:.6g} K, where the fit diverges"
            )
        return np.exp(vogel_log_viscosity(t, self.a, self.b, self.t_inf))

    def viscosity_at(self, t: float) -> float:
        """The law at one float temperature [K] (above T∞) → ν [m²/s]."""
        return math.exp(vogel_log_viscosity(t, self.a, self.b, self.t_inf))

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


def _vogel_three(points) -> tuple[float, float, float]:
    """(a, b, T∞) of Vogel's law through three (T [K], ln ν) points, in closed form: the ratio
    of the two differences of ln ν fixes T∞ (linear in it), then b and a follow."""
    (u1, y1), (u2, y2), (u3, y3) = sorted(points)
    r = (y1 - y2) / (y2 - y3)
    den = r * (u3 - u2) - (u2 - u1)
    if den == 0.0:
        raise ValueError("the three points lie on an Arrhenius line (T∞ → −inf)")
    t_inf = (r * (u3 - u2) * u1 - (u2 - u1) * u3) / den
    b = (y1 - y2) * (u1 - t_inf) * (u2 - t_inf) / (u2 - u1)
    return y1 - b / (u1 - t_inf), b, t_inf


def vogel_from_points(
    points,
    key: str = "",
    name: str = "",
    lower_limit: float = 0.0,
    upper_limit: float = math.inf,
    **flow,
) -> VogelViscosity:
    """Vogel's law ln ν = a + b/(T − T∞) through ≥ 3 (T [K], ν [m²/s]) points: through three
    exactly (closed form), through more by least squares in ln ν (scipy.optimize
    .least_squares, from the closed form through the coldest, a middle and the warmest point).

    Parameters
    ----------
    points : sequence of (temperature [K], kinematic viscosity [m²/s]), at three or more
        different temperatures, the viscosity falling as the temperature rises
    lower_limit, upper_limit : the lubricant's range [K] (:class:`ViscosityRange`)
    flow : ``flow_limit`` [K] and ``below_flow_limit`` (:class:`ViscosityRange`); T∞ must lie
        below the coldest temperature the law is used at

    Returns
    -------
    VogelViscosity

    Examples
    --------
    Pennzane SHF X-2000 (Bessette 1997: 80 500, 107 and 14.3 cSt at −40, 40 and 100 °C):

    >>> pts = [(233.15, 80500e-6), (313.15, 107e-6), (373.15, 14.3e-6)]
    >>> v = vogel_from_points(pts)
    >>> [round(float(v.kinematic_viscosity(t)) / nu, 12) for t, nu in pts]  # through each
    [1.0, 1.0, 1.0]
    >>> round(v.t_inf, 1)  # K, where the law diverges
    137.8
    """
    pts = sorted((check_temperature("points temperature", t),
                  check_positive("points viscosity", nu, "m²/s")) for t, nu in points)  # fmt: skip
    temps = [t for t, _ in pts]
    if len(pts) < 3 or len(set(temps)) != len(temps):
        raise ValueError(f"Vogel's law needs three or more points at different temperatures: {pts}")
    if any(n2 >= n1 for (_, n1), (_, n2) in itertools.pairwise(pts)):
        raise ValueError(f"viscosity must fall as the temperature rises: points {pts}")
    logs = [(t, math.log(nu)) for t, nu in pts]
    a, b, t_inf = _vogel_three([logs[0], logs[len(logs) // 2], logs[-1]])
    if len(pts) > 3:
        from scipy.optimize import least_squares

        u = np.array(temps)
        y = np.array([ln for _, ln in logs])
        fit = least_squares(
            lambda x: vogel_log_viscosity(u, x[0], x[1], x[2]) - y,
            (a, b, t_inf),
            bounds=((-np.inf, 0.0, -np.inf), (np.inf, np.inf, temps[0])),
            xtol=1e-15,
            ftol=1e-15,
        )
        a, b, t_inf = (float(v) for v in fit.x)
    if not (b > 0.0 and t_inf < temps[0]):
        raise ValueError(
            f"no Vogel law falls through the points {pts}: b = {b:g} K, T∞ = {t_inf:g} K "
            "(needs b > 0 and T∞ below the coldest point)"
        )
    src = f"derived: Vogel's law through {len(pts)} points" + (
        " (least squares in ln ν)" if len(pts) > 3 else ""
    )
    return VogelViscosity(
        key=key, name=name, a=float(a), b=float(b), t_inf=float(t_inf), points=tuple(pts),
        provenance=(("a", src), ("b", src), ("t_inf", src)),
        lower_limit=lower_limit, upper_limit=upper_limit, **flow,
    )  # fmt: skip


def viscosity_model(
    viscosity_40: float,
    viscosity_100: float,
    walther_c: float = 0.7,
    cold_point: tuple[float, float] | None = None,
    key: str = "",
    name: str = "",
    lower_limit: float = 0.0,
    upper_limit: float = math.inf,
    flow_limit: float = 0.0,
    below_flow_limit: str = "hold",
) -> ViscosityRange:
    """The model of a lubricant known by its ν40, ν100 and optionally one more point (the
    FMU's parameters): the ASTM D341 line through ν40 and ν100 (Walther's ``walther_c``
    [cSt]) without ``cold_point``, else Vogel's law through the three points.

    Parameters
    ----------
    viscosity_40, viscosity_100 : ν at 40 and 100 °C [m²/s], ν100 < ν40
    walther_c : Walther's c [cSt] (used without a cold point)
    cold_point : (T [K], ν [m²/s]) or None
    lower_limit, upper_limit : the lubricant's range of data [K]
    flow_limit : its pour point or lower operating temperature [K] (0: none published)
    below_flow_limit : "hold" or "extrapolate" below the flow limit (module docstring)

    Returns
    -------
    WaltherViscosity or VogelViscosity

    Examples
    --------
    >>> v = viscosity_model(107e-6, 14.3e-6, cold_point=(233.15, 80500e-6))
    >>> type(v).__name__, round(float(v.kinematic_viscosity(233.15)) * 1e6)  # cSt at −40 °C
    ('VogelViscosity', 80500)
    """
    flow = {"flow_limit": flow_limit, "below_flow_limit": below_flow_limit}
    if cold_point is None:
        return walther_from_reference(
            viscosity_40, viscosity_100, c=walther_c, key=key, name=name,
            lower_limit=lower_limit, upper_limit=upper_limit, **flow,
        )  # fmt: skip
    pts = [cold_point, (T40, viscosity_40), (T100, viscosity_100)]
    return vogel_from_points(pts, key, name, lower_limit, upper_limit, **flow)
