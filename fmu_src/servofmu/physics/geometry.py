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

from dataclasses import dataclass

import numpy as np

from ._checks import check_finite, check_positive, check_range
from .materials import Material, reduced_compliance
from .units import MM, UM


def ball_diameter_from_grooves(
    inner_groove_diameter, outer_groove_diameter, inner_curvature, outer_curvature, contact_angle
):
    """Ball diameter Dw [m] that gives the free contact angle ``contact_angle`` [rad].

    From Pd = d_o − d_i − 2·Dw and cos α0 = 1 − Pd/(2·(f_i + f_o − 1)·Dw)
    (Harris & Kotzalas 2007, ch. 2):  Dw = (d_o − d_i) / (2 + 2·(f_i + f_o − 1)·(1 − cos α0)).
    For Yu's 71803 (19.1109 / 23.8891 mm, 0.56 / 0.54, 15°) this gives 2.381 mm (a 3/32" ball).
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
    """
    d_i = check_positive("inner_groove_diameter", inner_groove_diameter, "m")
    d_o = check_positive("outer_groove_diameter", outer_groove_diameter, "m")
    dw = check_positive("ball_diameter", ball_diameter, "m")
    return d_o - d_i - 2.0 * dw


def free_contact_angle(clearance, curvature_distance):
    """Free (unloaded) contact angle α0 [rad] from the diametral clearance ``clearance`` [m].

    cos α0 = 1 − Pd/(2A) with A = (f_i + f_o − 1)·Dw [m] (Harris & Kotzalas 2007, ch. 2).
    With Pd ≤ 0 there is no free contact angle: the balls touch (or are compressed) at α = 0,
    and 0 is returned. Pd > 2A (beyond 90°) is rejected.
    """
    a = check_positive("curvature_distance", curvature_distance, "m")
    pd = np.asarray(clearance, dtype=float)
    if np.any(~np.isfinite(pd)) or np.any(pd > 2.0 * np.asarray(a)):
        raise ValueError(
            f"clearance = {clearance!r} m must be finite and <= 2·curvature_distance = "
            f"{2.0 * np.asarray(a)!r} m"
        )
    c = 1.0 - np.maximum(pd, 0.0) / (2.0 * a)
    out = np.arccos(np.clip(c, -1.0, 1.0))
    return out if out.ndim else float(out)


def first_contact_offset(clearance, curvature_distance):
    """Axial offset h [m] of the groove curvature centres, from the centred position, at which
    the ball first touches both grooves: h = √(A² − (A − Pd/2)²) = A·sin α0 for Pd ≥ 0, and 0
    for Pd ≤ 0 (balls already in contact). Harris & Kotzalas 2007, ch. 2 (axial play Pe = 2h).
    """
    a = np.asarray(check_positive("curvature_distance", curvature_distance, "m"))
    pd = np.clip(np.asarray(check_finite("clearance", clearance, "m"), dtype=float), 0.0, 2.0 * a)
    out = np.sqrt(np.maximum(a**2 - (a - 0.5 * pd) ** 2, 0.0))
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


@dataclass(frozen=True)
class BallBearing:
    """Catalogue geometry of one angular-contact ball bearing (unmounted, at its reference
    temperature), SI units. Build from the catalogue with :func:`catalog.bearing`.

    Attributes
    ----------
    key, name : designation (e.g. "71803") and description
    bore, outer_diameter, width : boundary dimensions d, D, B [m]
    n_balls : number of balls Z
    ball_diameter : Dw [m]
    inner_groove_diameter, outer_groove_diameter : groove-bottom diameters d_i, d_o [m]
    inner_curvature, outer_curvature : groove curvature factors f = r/Dw [-], > 0.5
    ring_material, ball_material : :class:`Material` of rings and balls
    provenance : ((field, source), ...)
    """

    key: str
    name: str
    bore: float
    outer_diameter: float
    width: float
    n_balls: int
    ball_diameter: float
    inner_groove_diameter: float
    outer_groove_diameter: float
    inner_curvature: float
    outer_curvature: float
    ring_material: Material
    ball_material: Material
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_positive("bore", self.bore, "m")
        check_positive("outer_diameter", self.outer_diameter, "m")
        check_positive("width", self.width, "m")
        check_positive("ball_diameter", self.ball_diameter, "m")
        check_range("inner_curvature", self.inner_curvature, 0.5, 1.0, lo_open=True)
        check_range("outer_curvature", self.outer_curvature, 0.5, 1.0, lo_open=True)
        if not (isinstance(self.n_balls, int) and self.n_balls >= 3):
            raise ValueError(f"n_balls = {self.n_balls!r} must be an integer >= 3")
        if not (self.bore < self.inner_groove_diameter < self.outer_groove_diameter):
            raise ValueError(
                f"groove diameters must satisfy bore < inner < outer: bore = {self.bore!r}, "
                f"inner_groove_diameter = {self.inner_groove_diameter!r}, "
                f"outer_groove_diameter = {self.outer_groove_diameter!r} m"
            )
        if self.outer_groove_diameter >= self.outer_diameter:
            raise ValueError(
                f"outer_groove_diameter = {self.outer_groove_diameter!r} m must be below "
                f"outer_diameter = {self.outer_diameter!r} m"
            )
        dm = 0.5 * (self.inner_groove_diameter + self.outer_groove_diameter)
        if self.n_balls * self.ball_diameter >= np.pi * dm:
            raise ValueError(
                f"n_balls = {self.n_balls} balls of {self.ball_diameter!r} m do not fit on the "
                f"pitch circle of {dm!r} m"
            )
        check_range(
            "clearance",
            self.clearance,
            -0.5 * self.curvature_distance,
            2.0 * self.curvature_distance,
            unit="m",
        )

    @property
    def pitch_diameter(self) -> float:
        """dm = (d_i + d_o)/2 [m]."""
        return 0.5 * (self.inner_groove_diameter + self.outer_groove_diameter)

    @property
    def clearance(self) -> float:
        """Unmounted diametral clearance Pd [m]."""
        return diametral_clearance(
            self.inner_groove_diameter, self.outer_groove_diameter, self.ball_diameter
        )

    @property
    def curvature_distance(self) -> float:
        """A = (f_i + f_o − 1)·Dw [m]."""
        return (self.inner_curvature + self.outer_curvature - 1.0) * self.ball_diameter

    @property
    def contact_angle(self) -> float:
        """Unmounted free contact angle α0 [rad]."""
        return free_contact_angle(self.clearance, self.curvature_distance)

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
