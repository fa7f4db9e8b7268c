"""Ball–race geometry of an angular-contact ball bearing.

Conventions (Harris & Kotzalas 2007, *Essential Concepts of Bearing Technology*, ch. 2):
groove ("race") diameters are measured at the groove bottoms; the groove curvature factor is
f = r/Dw (groove radius over ball diameter), f > 0.5; the diametral clearance
(ISO "radial internal clearance") is Pd = d_o − d_i − 2·Dw (Yu 2017 §2.1, P_r2); the distance
between the inner and outer groove curvature centres in contact is A = r_i + r_o − Dw
= (f_i + f_o − 1)·Dw.

Axial offsets are measured between the groove curvature centres, from the *centred* position
(both centres in one radial plane). With clearance Pd ≥ 0 the ball first touches both grooves
at the offset h = A·sin α0 (the free contact angle α0, cos α0 = 1 − Pd/(2A)); with negative
clearance the balls are already compressed at zero offset. This general geometry stays valid at
zero and negative clearance, where Yu 2017 eq 16–17 (which divide by the free contact angle's
cosine) are singular.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._checks import check_finite, check_positive, check_range
from ..kernels import contact as kernels
from ..kernels.units import MM, UM
from ..materials import Material, reduced_compliance


def ball_diameter_from_grooves(
    inner_groove_diameter, outer_groove_diameter, inner_curvature, outer_curvature, contact_angle
):
    """Ball diameter Dw [m] that gives the free contact angle ``contact_angle`` [rad].

    From Pd = d_o − d_i − 2·Dw and cos α0 = 1 − Pd/(2·(f_i + f_o − 1)·Dw)
    (Harris & Kotzalas 2007, ch. 2):  Dw = (d_o − d_i) / (2 + 2·(f_i + f_o − 1)·(1 − cos α0)).
    For Yu's 71803 (19.1109 / 23.8891 mm, 0.56 / 0.54, 15°) this gives 2.381 mm (a 3/32" ball).

    Parameters
    ----------
    inner_groove_diameter, outer_groove_diameter : d_i, d_o [m] (groove bottoms), d_i < d_o
    inner_curvature, outer_curvature : f_i, f_o = r/Dw [-], in (0.5, 1]
    contact_angle : free contact angle α0 [rad], in [0, π/2)

    Returns
    -------
    float or numpy.ndarray
        Dw [m].

    Examples
    --------
    >>> dw = ball_diameter_from_grooves(19.1109e-3, 23.8891e-3, 0.56, 0.54, math.radians(15))
    >>> round(float(dw) * 1e3, 4)  # mm: Yu's 71803, a 3/32" ball (2.381 mm)
    2.381

    At α0 = 0 there is no clearance, Dw = (d_o − d_i)/2 (by hand: (24 − 19)/2 = 2.5 mm):

    >>> round(float(ball_diameter_from_grooves(0.019, 0.024, 0.56, 0.54, 0.0)) * 1e3, 6)  # mm
    2.5
    """
    d_i = check_positive("inner_groove_diameter", inner_groove_diameter, "m")
    d_o = check_positive("outer_groove_diameter", outer_groove_diameter, "m")
    f_i = check_range("inner_curvature", inner_curvature, 0.5, 1.0, lo_open=True)
    f_o = check_range("outer_curvature", outer_curvature, 0.5, 1.0, lo_open=True)
    alpha = check_range("contact_angle", contact_angle, 0.0, np.pi / 2, hi_open=True, unit="rad")
    if np.any(np.asarray(d_o) <= np.asarray(d_i)):
        raise ValueError(
            f"outer_groove_diameter = {d_o!r} m must exceed inner_groove_diameter = {d_i!r} m"
        )
    return (d_o - d_i) / (2.0 + 2.0 * (f_i + f_o - 1.0) * (1.0 - np.cos(alpha)))


def diametral_clearance(inner_groove_diameter, outer_groove_diameter, ball_diameter):
    """Diametral (radial internal) clearance Pd = d_o − d_i − 2·Dw [m] (Yu 2017 §2.1, P_r2).

    Negative values mean a radial interference of the balls between the grooves.

    Parameters
    ----------
    inner_groove_diameter, outer_groove_diameter : d_i, d_o [m] (groove bottoms)
    ball_diameter : Dw [m]

    Returns
    -------
    float or numpy.ndarray
        Pd [m] (negative: interference).

    Examples
    --------
    Yu's 71803 with a 3/32" ball, by hand 23.8891 − 19.1109 − 2·2.381 = 0.0162 mm:

    >>> round(float(diametral_clearance(19.1109e-3, 23.8891e-3, 2.381e-3)) * 1e6, 4)  # µm
    16.2
    """
    d_i = check_positive("inner_groove_diameter", inner_groove_diameter, "m")
    d_o = check_positive("outer_groove_diameter", outer_groove_diameter, "m")
    dw = check_positive("ball_diameter", ball_diameter, "m")
    return kernels.diametral_clearance(d_i, d_o, dw)


def free_contact_angle(clearance, curvature_distance):
    """Free (unloaded) contact angle α0 [rad] from the diametral clearance ``clearance`` [m].

    cos α0 = 1 − Pd/(2A) with A = (f_i + f_o − 1)·Dw [m] (Harris & Kotzalas 2007, ch. 2).
    With Pd ≤ 0 there is no free contact angle: the balls touch (or are compressed) at α = 0,
    and 0 is returned. Pd > 2A (beyond 90°) is rejected.

    Parameters
    ----------
    clearance : diametral clearance Pd [m], ≤ 2A
    curvature_distance : A = (f_i + f_o − 1)·Dw [m]

    Returns
    -------
    float or numpy.ndarray
        α0 [rad] (0 for Pd ≤ 0).

    Examples
    --------
    Pd = A gives cos α0 = 1/2, α0 = 60° (by hand):

    >>> round(math.degrees(free_contact_angle(0.1e-3, 0.1e-3)), 6)  # degrees
    60.0

    The catalogue's 71803 gets back its nominal 15°; a negative clearance gives 0:

    >>> from servofmu.parameters import catalog
    >>> b = catalog.bearing("71803")
    >>> round(math.degrees(free_contact_angle(b.clearance, b.curvature_distance)), 6)  # degrees
    15.0
    >>> free_contact_angle(-2e-6, b.curvature_distance)
    0.0
    """
    a = check_positive("curvature_distance", curvature_distance, "m")
    pd = np.asarray(clearance, dtype=float)
    if np.any(~np.isfinite(pd)) or np.any(pd > 2.0 * np.asarray(a)):
        raise ValueError(
            f"clearance = {clearance!r} m must be finite and <= 2·curvature_distance = "
            f"{2.0 * np.asarray(a)!r} m"
        )
    out = np.asarray(kernels.free_contact_angle(pd, a))
    return out if out.ndim else float(out)


def first_contact_offset(clearance, curvature_distance):
    """Axial offset h [m] of the groove curvature centres, from the centred position, at which
    the ball first touches both grooves: h = √(A² − (A − Pd/2)²) = A·sin α0 for Pd ≥ 0, and 0
    for Pd ≤ 0 (balls already in contact). Harris & Kotzalas 2007, ch. 2 (axial play Pe = 2h).

    Parameters
    ----------
    clearance : diametral clearance Pd [m] (clipped to [0, 2A])
    curvature_distance : A = (f_i + f_o − 1)·Dw [m]

    Returns
    -------
    float or numpy.ndarray
        h [m] (0 for Pd ≤ 0).

    Examples
    --------
    A = 100 µm, Pd = 40 µm: A − Pd/2 = 80 µm, so h = √(100² − 80²) = 60 µm (by hand):

    >>> round(first_contact_offset(40e-6, 100e-6) * 1e6, 6)  # µm
    60.0
    >>> first_contact_offset(-1e-6, 100e-6)  # negative clearance: in contact at once
    0.0
    """
    a = np.asarray(check_positive("curvature_distance", curvature_distance, "m"))
    pd = np.asarray(check_finite("clearance", clearance, "m"), dtype=float)
    out = np.asarray(kernels.first_contact_offset(pd, a))
    return out if out.ndim else float(out)


def ball_set_from_design_rule(bore, outer_diameter, section_ratio, fill):
    """Pitch diameter, ball diameter and ball count of a ball set sized from the boundary
    dimensions, for a bearing whose internal geometry is not published.

    dm = (d + D)/2,  Dw = k·(D − d),  Z = round(φ·π·dm/Dw). The coefficients k and φ of the
    catalogue are calibrated on its bearings with a published ball set, and the rule's
    leave-one-out error on them is stated with them (``data/bearing_rules.toml``,
    :func:`catalog.ball_set_rule`).

    Parameters
    ----------
    bore : bore diameter d [m]
    outer_diameter : outside diameter D [m], > d
    section_ratio : k = Dw/(D − d) [-], in (0, 0.5)
    fill : φ = Z·Dw/(π·dm) [-], the fraction of the pitch circle taken by balls, in (0, 1)

    Returns
    -------
    (pitch_diameter [m], ball_diameter [m], n_balls [-])

    Examples
    --------
    >>> dm, dw, z = ball_set_from_design_rule(0.015, 0.032, 0.2859, 0.570)  # a 7002
    >>> round(dm * 1e3, 2), round(dw * 1e3, 3), z
    (23.5, 4.86, 9)
    """
    d = check_positive("bore", bore, "m")
    big_d = check_positive("outer_diameter", outer_diameter, "m")
    if not big_d > d:
        raise ValueError(f"outer_diameter = {big_d!r} m must exceed bore = {d!r} m")
    k = check_range("section_ratio", section_ratio, 0.0, 0.5, lo_open=True, hi_open=True)
    phi = check_range("fill", fill, 0.0, 1.0, lo_open=True, hi_open=True)
    dm = 0.5 * (d + big_d)
    dw = k * (big_d - d)
    n_balls = round(phi * np.pi * dm / dw)
    return dm, dw, n_balls


@dataclass(frozen=True)
class BallSetRule:
    """The catalogue's design rule for a ball set (:func:`ball_set_from_design_rule`), with the
    bearings it was calibrated on and its leave-one-out error on them.

    Attributes
    ----------
    section_ratio : k = Dw/(D − d) [-]
    fill : φ = Z·Dw/(π·dm) [-]
    calibration_bearings : catalogue keys of the bearings with a published ball set
    ball_diameter_error : stated bound of |ΔDw|/Dw [-]
    ball_count_error : stated bound of |ΔZ| [balls]
    pitch_diameter_error : stated bound of |Δdm|/dm [-]
    provenance : ((field, source), ...)
    """

    section_ratio: float
    fill: float
    calibration_bearings: tuple[str, ...]
    ball_diameter_error: float
    ball_count_error: int
    pitch_diameter_error: float
    provenance: tuple[tuple[str, str], ...] = ()

    def ball_set(self, bore, outer_diameter):
        """(dm [m], Dw [m], Z) of a bearing with ``bore`` and ``outer_diameter`` [m]."""
        return ball_set_from_design_rule(bore, outer_diameter, self.section_ratio, self.fill)


def clearance_from_group(bore, group: str, table) -> tuple[float, float]:
    """Range (min, max) [m] of the radial internal clearance of a deep-groove ball bearing of
    ``bore`` [m] in clearance ``group`` ("C2", "N", "C3", "C4"), from ``table``: rows
    ``{"over", "incl", <group>: [min, max]}`` with the bore in mm and the clearance in µm
    (ISO 5753-1:2009 Table 1, kept in ``data/bearing_rules.toml``).

    Parameters
    ----------
    bore : bore diameter d [m]
    group : clearance group name
    table : the rows described above

    Returns
    -------
    (minimum, maximum) radial internal clearance [m]

    Examples
    --------
    >>> rows = [{"over": 24, "incl": 30, "N": [5, 20]}]
    >>> [round(x * 1e6, 1) for x in clearance_from_group(0.025, "N", rows)]
    [5.0, 20.0]
    """
    d_mm = check_positive("bore", bore, "m") / MM
    for row in table:
        if row["over"] < d_mm <= row["incl"]:
            if group not in row:
                raise ValueError(
                    f"radial_clearance_group = {group!r} is not one of "
                    f"{sorted(k for k in row if k not in ('over', 'incl'))}"
                )
            low, high = row[group]
            return low * UM, high * UM
    spans = [(r["over"], r["incl"]) for r in table]
    raise ValueError(f"bore = {bore!r} m is outside the clearance table's bores {spans} mm")


#: Largest nominal contact angle of the model [rad]: 45°, beyond which a ball bearing is a
#: thrust bearing in all but name (ISO 281:2007 splits radial and thrust ball bearings there).
MAX_CONTACT_ANGLE = np.pi / 4.0


def clearance_from_contact_angle(ball_diameter, inner_curvature, outer_curvature, contact_angle):
    """Unmounted diametral clearance Pd = 2·A·(1 − cos α0) [m] that gives the free contact
    angle α0, A = (f_i + f_o − 1)·Dw (the inverse of :func:`free_contact_angle`; Harris &
    Kotzalas 2007, ch. 2).

    Parameters
    ----------
    ball_diameter : Dw [m]
    inner_curvature, outer_curvature : f_i, f_o [-]
    contact_angle : free contact angle α0 [rad] (0: no clearance)

    Returns
    -------
    float
        Pd [m].

    Examples
    --------
    >>> pd = clearance_from_contact_angle(2.381e-3, 0.56, 0.54, math.radians(15))
    >>> round(float(pd) * 1e6, 2)  # µm: the 71803 of Yu 2017
    16.23
    """
    dw = check_positive("ball_diameter", ball_diameter, "m")
    f_i = check_range("inner_curvature", inner_curvature, 0.5, lo_open=True)
    f_o = check_range("outer_curvature", outer_curvature, 0.5, lo_open=True)
    alpha = check_range("contact_angle", contact_angle, 0.0, 0.5 * math.pi, unit="rad")
    a = (f_i + f_o - 1.0) * dw
    return 2.0 * a * (1.0 - np.cos(alpha))


def bearing_geometry_problems(
    bore,
    outer_diameter,
    width,
    ball_diameter,
    n_balls,
    pitch_diameter,
    nominal_contact_angle,
    inner_curvature,
    outer_curvature,
) -> list[str]:
    """Every reason why the numbers cannot be an angular-contact or deep-groove ball bearing
    (empty: they can), each naming the values (parameter names as the FMU's; SI units).

    The conditions: positive finite sizes, d < D; the ball fits in the ring section,
    Dw < (D − d)/2; the balls fit on the pitch circle, Z·Dw < π·dm; grooves wider than the
    ball, f > 0.5 (and ≤ 1); 0 ≤ α0 ≤ 45°; d < dm < D; and both rings keep some material
    between groove and bore or outside diameter (d < d_i, d_o < D). Harris & Kotzalas 2007,
    ch. 2 (geometry of ball bearings).

    Parameters
    ----------
    bore, outer_diameter, width : d, D, B [m]
    ball_diameter : Dw [m]
    n_balls : Z [-] (an integer ≥ 3)
    pitch_diameter : dm [m]
    nominal_contact_angle : free contact angle α0 [rad]
    inner_curvature, outer_curvature : f_i, f_o [-]

    Returns
    -------
    list[str]
        One sentence per problem.

    Examples
    --------
    >>> bearing_geometry_problems(0.017, 0.026, 0.005, 0.005, 15, 0.0215, 0.26, 0.56, 0.54)[0]
    'ball_diameter = 0.005 m must be below (outer_diameter − bore)/2 = 0.0045 m'
    """
    values = {
        "bore": bore,
        "outer_diameter": outer_diameter,
        "width": width,
        "ball_diameter": ball_diameter,
        "pitch_diameter": pitch_diameter,
    }
    problems = [
        f"{k} = {v!r} m must be positive and finite"
        for k, v in values.items()
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0)
    ]
    if not (isinstance(n_balls, (int, np.integer)) and not isinstance(n_balls, bool)):
        problems.append(f"n_balls = {n_balls!r} must be an integer")
    elif n_balls < 3:
        problems.append(f"n_balls = {n_balls!r} must be at least 3")
    for name, f in (("inner_curvature", inner_curvature), ("outer_curvature", outer_curvature)):
        if not (isinstance(f, (int, float)) and 0.5 < f <= 1.0):
            problems.append(
                f"{name} = {f!r} must exceed 0.5 (a groove wider than the ball) and be ≤ 1"
            )
    alpha = nominal_contact_angle
    if not (isinstance(alpha, (int, float)) and 0.0 <= alpha <= MAX_CONTACT_ANGLE):
        problems.append(
            f"nominal_contact_angle = {float(alpha)!r} rad ({math.degrees(alpha):g}°) is outside "
            "0…45° (0…0.7854 rad)"
            if isinstance(alpha, (int, float)) and math.isfinite(alpha)
            else f"nominal_contact_angle = {alpha!r} rad is outside 0…45° (0…0.7854 rad)"
        )
    if problems:  # the relations below need valid numbers
        return problems
    d, big_d, dw, dm = (float(x) for x in (bore, outer_diameter, ball_diameter, pitch_diameter))
    if not d < big_d:
        return [f"outer_diameter = {big_d:.6g} m must exceed bore = {d:.6g} m"]
    if not dw < 0.5 * (big_d - d):
        problems.append(
            f"ball_diameter = {dw:.6g} m must be below (outer_diameter − bore)/2 = "
            f"{0.5 * (big_d - d):.6g} m"
        )
    if not n_balls * dw < np.pi * dm:
        problems.append(
            f"n_balls × ball_diameter = {n_balls} × {dw:.6g} m = {n_balls * dw:.6g} m must be "
            f"below π × pitch_diameter = {np.pi * dm:.6g} m (the balls must fit on the pitch "
            "circle)"
        )
    if not d < dm < big_d:
        problems.append(
            f"pitch_diameter = {dm:.6g} m must lie between bore = {d:.6g} m and outer_diameter = "
            f"{big_d:.6g} m"
        )
    if problems:
        return problems
    half = dw + 0.5 * clearance_from_contact_angle(dw, inner_curvature, outer_curvature, alpha)
    if not dm - half > d:
        problems.append(
            f"the inner groove (diameter pitch_diameter − ball_diameter − clearance/2 = "
            f"{dm - half:.6g} m) must stay above bore = {d:.6g} m"
        )
    if not dm + half < big_d:
        problems.append(
            f"the outer groove (diameter pitch_diameter + ball_diameter + clearance/2 = "
            f"{dm + half:.6g} m) must stay below outer_diameter = {big_d:.6g} m"
        )
    return problems


@dataclass(frozen=True)
class BallBearing:
    """Geometry of one angular-contact or deep-groove ball bearing (unmounted, at its
    reference temperature), SI units: the nine numbers of a datasheet and a design, from
    which the groove diameters follow. Build it from the catalogue with
    :func:`catalog.bearing`; the FMU parameters of the same names give the same record.

    Attributes
    ----------
    key, name : designation (e.g. "71803") and description
    bore, outer_diameter, width : boundary dimensions d, D, B [m]
    n_balls : number of balls Z
    ball_diameter : Dw [m]
    pitch_diameter : dm [m], the mean of the groove-bottom diameters
    nominal_contact_angle : free (unloaded, unmounted) contact angle α0 [rad], 0…45°; it sets
        the diametral clearance Pd = 2·A·(1 − cos α0)
    inner_curvature, outer_curvature : groove curvature factors f = r/Dw [-], > 0.5
    ring_material, ball_material : :class:`Material` of rings and balls
    provenance : ((field, source), ...)

    A geometry that cannot be a bearing raises ValueError naming every problem
    (:func:`bearing_geometry_problems`).
    """

    key: str
    name: str
    bore: float
    outer_diameter: float
    width: float
    n_balls: int
    ball_diameter: float
    pitch_diameter: float
    nominal_contact_angle: float
    inner_curvature: float
    outer_curvature: float
    ring_material: Material
    ball_material: Material
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        problems = bearing_geometry_problems(
            self.bore,
            self.outer_diameter,
            self.width,
            self.ball_diameter,
            self.n_balls,
            self.pitch_diameter,
            self.nominal_contact_angle,
            self.inner_curvature,
            self.outer_curvature,
        )
        if problems:
            raise ValueError(f"bearing {self.key!r} cannot be built: " + "; ".join(problems))

    @property
    def clearance(self) -> float:
        """Unmounted diametral clearance Pd = 2·A·(1 − cos α0) [m]."""
        return float(
            clearance_from_contact_angle(
                self.ball_diameter,
                self.inner_curvature,
                self.outer_curvature,
                self.nominal_contact_angle,
            )
        )

    @property
    def inner_groove_diameter(self) -> float:
        """d_i = dm − Dw − Pd/2 [m] (groove bottom)."""
        return self.pitch_diameter - self.ball_diameter - 0.5 * self.clearance

    @property
    def outer_groove_diameter(self) -> float:
        """d_o = dm + Dw + Pd/2 [m] (groove bottom)."""
        return self.pitch_diameter + self.ball_diameter + 0.5 * self.clearance

    @property
    def curvature_distance(self) -> float:
        """A = (f_i + f_o − 1)·Dw [m]."""
        return (self.inner_curvature + self.outer_curvature - 1.0) * self.ball_diameter

    @property
    def contact_angle(self) -> float:
        """Unmounted free contact angle α0 [rad] (= :attr:`nominal_contact_angle`)."""
        return self.nominal_contact_angle

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")

    def race_geometry(self) -> RaceGeometry:
        """The unmounted geometry at the reference temperature."""
        return RaceGeometry(
            ball_diameter=self.ball_diameter,
            inner_race_diameter=self.inner_groove_diameter,
            outer_race_diameter=self.outer_groove_diameter,
            inner_groove_radius=self.inner_curvature * self.ball_diameter,
            outer_groove_radius=self.outer_curvature * self.ball_diameter,
            n_balls=self.n_balls,
            compliance=reduced_compliance(self.ring_material, self.ball_material),
        )


@dataclass(frozen=True)
class RaceGeometry:
    """Operating ball–race geometry of one bearing (after thermal growth and fits), SI.

    Fields may be numpy arrays of one common shape (one geometry per temperature).

    Attributes
    ----------
    ball_diameter : Dw [m]
    inner_race_diameter, outer_race_diameter : groove-bottom diameters d_i, d_o [m]
    inner_groove_radius, outer_groove_radius : groove radii r_i = f_i·Dw, r_o = f_o·Dw [m]
    n_balls : Z
    compliance : Hertz compliance η = Σ(1 − ν²)/E of ball and ring [1/Pa]
    """

    ball_diameter: float | np.ndarray
    inner_race_diameter: float | np.ndarray
    outer_race_diameter: float | np.ndarray
    inner_groove_radius: float | np.ndarray
    outer_groove_radius: float | np.ndarray
    n_balls: int
    compliance: float

    def __post_init__(self):
        dw = check_positive("ball_diameter", self.ball_diameter, "m")
        check_positive("inner_race_diameter", self.inner_race_diameter, "m")
        check_positive("outer_race_diameter", self.outer_race_diameter, "m")
        for name in ("inner_groove_radius", "outer_groove_radius"):
            r = check_positive(name, getattr(self, name), "m")
            bad = np.asarray(r) <= 0.5 * np.asarray(dw)
            if np.any(bad):
                raise ValueError(
                    f"{name} = {float(np.asarray(r)[bad].flat[0])!r} m must exceed half the ball "
                    f"diameter (curvature factor > 0.5)"
                )
        if not (isinstance(self.n_balls, (int, np.integer)) and self.n_balls >= 3):
            raise ValueError(f"n_balls = {self.n_balls!r} must be an integer >= 3")
        check_positive("compliance", self.compliance, "1/Pa")

    @property
    def pitch_diameter(self):
        """dm = (d_i + d_o)/2 [m]."""
        return 0.5 * (self.inner_race_diameter + self.outer_race_diameter)

    @property
    def clearance(self):
        """Diametral clearance Pd [m] (negative: radial interference)."""
        return self.outer_race_diameter - self.inner_race_diameter - 2.0 * self.ball_diameter

    @property
    def curvature_distance(self):
        """A = r_i + r_o − Dw [m]."""
        return self.inner_groove_radius + self.outer_groove_radius - self.ball_diameter

    @property
    def inner_curvature(self):
        """f_i = r_i/Dw [-]."""
        return self.inner_groove_radius / self.ball_diameter

    @property
    def outer_curvature(self):
        """f_o = r_o/Dw [-]."""
        return self.outer_groove_radius / self.ball_diameter

    @property
    def radial_centre_distance(self):
        """Radial distance between the groove curvature centres at zero radial displacement,
        A − Pd/2 [m] (may exceed A: negative clearance)."""
        return self.curvature_distance - 0.5 * self.clearance

    @property
    def inner_centre_radius(self):
        """Radius of the locus of inner-groove curvature centres, d_i/2 + r_i [m] (moment arm
        of a tilt)."""
        return 0.5 * self.inner_race_diameter + self.inner_groove_radius

    @property
    def free_contact_angle(self):
        """α0 [rad] (0 at negative clearance)."""
        return free_contact_angle(self.clearance, self.curvature_distance)

    @property
    def first_contact_offset(self):
        """h [m]: axial offset of first contact from the centred position."""
        return first_contact_offset(self.clearance, self.curvature_distance)
