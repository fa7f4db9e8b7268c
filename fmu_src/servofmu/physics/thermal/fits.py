r"""Radial thermal coupling of the rings with housing and shaft (Yu 2017 eq 10–13; Ning §2.1).

Free thermal growth (Yu eq 10):

.. math::

   D_1 = D\,(1 + \alpha\,\Delta T).

An interference fit between a ring and its seat creates a contact pressure p given by Lamé's
thick-cylinder solution (Yu eq 12–13): the seat and the ring deform until their radial
displacements close the interference.

Corrections to the printed equations:

- Yu eq 11–13 swap the names of the ring outer diameter and the outer-groove diameter; here the
  ring is an annulus from its groove diameter to its outside diameter, as eq 12's structure
  requires.
- Yu eq 11 subtracts 2Δ from the bore diameter, so Yu's Δ is a radial interference; the
  functions here take the *diametral* interference (2Δ for Yu, Ning's values as printed).
- The fit pressure is clamped at p ≥ 0: a seat that has grown away from the ring loses contact
  instead of pulling on it (the printed eq 13 would go negative).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._checks import check_finite, check_nonnegative, check_positive, check_temperature
from ..contact.geometry import BallBearing, RaceGeometry
from ..kernels import lame
from ..materials import Material, reduced_compliance


@dataclass(frozen=True)
class RadialFit:
    """Seats of the rings (SI).

    Attributes
    ----------
    housing_material : material of the housing (frame) around the outer ring
    housing_outer_diameter : outside diameter of the housing boss D_L [m] (Yu eq 11)
    outer_interference : diametral interference of outer ring and bore at assembly [m]
        (negative: clearance fit)
    shaft_material : material of the shaft inside the inner ring
    shaft_bore : bore of a hollow shaft [m] (0: solid)
    inner_interference : diametral interference of shaft and inner ring at assembly [m]
    provenance : ((field, source), ...)
    """

    housing_material: Material
    housing_outer_diameter: float
    outer_interference: float
    shaft_material: Material
    shaft_bore: float
    inner_interference: float
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_positive("housing_outer_diameter", self.housing_outer_diameter, "m")
        check_finite("outer_interference", self.outer_interference, "m")
        check_nonnegative("shaft_bore", self.shaft_bore, "m")
        check_finite("inner_interference", self.inner_interference, "m")


def fit_pressure(
    interference,
    interface_diameter,
    inner_bore,
    outer_diameter,
    inner_material: Material,
    outer_material: Material,
):
    """Contact pressure p [Pa] of a shrink fit between two annuli (Lamé; Yu 2017 eq 12–13).

    Parameters
    ----------
    interference : diametral interference δ [m] (≤ 0 gives p = 0)
    interface_diameter : d [m], the common diameter
    inner_bore : bore d_b [m] of the inner body (0 for a solid shaft), < d
    outer_diameter : outside diameter D [m] of the outer body, > d
    inner_material, outer_material : materials of the inner and outer body

    p = δ / (k_in + k_out),  k_in = d/E_in·((d² + d_b²)/(d² − d_b²) − ν_in),
    k_out = d/E_out·((D² + d²)/(D² − d²) + ν_out); clamped at p ≥ 0 (Yu's k1, k2 with the
    ring diameters named as the equation's structure requires).

    Returns
    -------
    float or numpy.ndarray
        p [Pa] (0 where δ ≤ 0).

    Examples
    --------
    A solid steel shaft in a steel ring with D = 2d: k_in + k_out = (d/E)·(1 − ν + 5/3 + ν),
    so p = 3·δ·E/(8·d), by hand 3 · 10 µm · 206 GPa / (8 · 10 mm) = 77.25 MPa:

    >>> from servofmu.parameters import catalog
    >>> steel = catalog.material("bearing_steel_yu")  # E = 206 GPa
    >>> round(float(fit_pressure(10e-6, 0.010, 0.0, 0.020, steel, steel)) / 1e6, 6)  # MPa
    77.25
    >>> float(fit_pressure(-1e-6, 0.010, 0.0, 0.020, steel, steel))  # a clearance fit
    0.0
    """
    delta = check_finite("interference", interference, "m")
    d = check_positive("interface_diameter", interface_diameter, "m")
    d_b = check_nonnegative("inner_bore", inner_bore, "m")
    d_o = check_positive("outer_diameter", outer_diameter, "m")
    if np.any(np.asarray(d_b) >= np.asarray(d)) or np.any(np.asarray(d_o) <= np.asarray(d)):
        raise ValueError(
            f"need inner_bore < interface_diameter < outer_diameter, got {d_b!r}, {d!r}, {d_o!r} m"
        )
    return _fit_pressure(delta, d, d_b, d_o, inner_material, outer_material)


def _fit_pressure(delta, d, d_b, d_o, m_in: Material, m_out: Material):
    inner = lame.shaft_compliance(d_b, d, m_in.youngs_modulus, m_in.poisson_ratio)
    outer = lame.hub_compliance(d, d_o, m_out.youngs_modulus, m_out.poisson_ratio)
    return lame.fit_pressure(delta, d, inner, outer)


def _check_annulus(bore, outer_diameter):
    d_b = check_positive("bore", bore, "m")
    d_o = check_positive("outer_diameter", outer_diameter, "m")
    if np.any(np.asarray(d_b) >= np.asarray(d_o)):
        raise ValueError(f"bore = {bore!r} m must be below outer_diameter = {outer_diameter!r} m")


def bore_change_under_external_pressure(pressure, outer_diameter, bore, material: Material):
    """Change of the bore diameter [m] of an annulus (bore d_b, outside D) under external
    pressure p [Pa]: Δd_b = −2·p·D²·d_b / (E·(D² − d_b²)) (Lamé; Yu 2017 eq 13, third line,
    the outer raceway of a ring pressed into a housing).

    Parameters
    ----------
    pressure : external pressure p [Pa], ≥ 0
    outer_diameter : outside diameter D [m]
    bore : bore diameter d_b [m], < D
    material : :class:`~.materials.Material` of the annulus (E [Pa])

    Returns
    -------
    float or numpy.ndarray
        Δd_b [m] (negative: the bore shrinks).

    Examples
    --------
    With D = 2·d_b, Δd_b = −8·p·d_b/(3·E), by hand −8 · 77.25 MPa · 10 mm / (3 · 206 GPa)
    = −10 µm:

    >>> from servofmu.parameters import catalog
    >>> steel = catalog.material("bearing_steel_yu")  # E = 206 GPa
    >>> dd = bore_change_under_external_pressure(77.25e6, 0.020, 0.010, steel)
    >>> round(float(dd) * 1e6, 6)  # µm
    -10.0
    """
    p = check_nonnegative("pressure", pressure, "Pa")
    _check_annulus(bore, outer_diameter)
    return lame.bore_change(p, outer_diameter, bore, material.youngs_modulus)


def outside_change_under_internal_pressure(pressure, bore, outer_diameter, material: Material):
    """Change of the outside diameter [m] of an annulus (bore d, outside D) under internal
    pressure p [Pa]: ΔD = 2·p·d²·D / (E·(D² − d²)) (Lamé; the inner raceway of a ring pressed
    onto a shaft, Ning §2.1).

    Parameters
    ----------
    pressure : internal pressure p [Pa], ≥ 0
    bore : bore diameter d [m], < D
    outer_diameter : outside diameter D [m]
    material : :class:`~.materials.Material` of the annulus (E [Pa])

    Returns
    -------
    float or numpy.ndarray
        ΔD [m] (positive: the outside grows).

    Examples
    --------
    With D = 2·d, ΔD = 4·p·d/(3·E), by hand 4 · 77.25 MPa · 10 mm / (3 · 206 GPa) = 5 µm:

    >>> from servofmu.parameters import catalog
    >>> steel = catalog.material("bearing_steel_yu")  # E = 206 GPa
    >>> dd = outside_change_under_internal_pressure(77.25e6, 0.010, 0.020, steel)
    >>> round(float(dd) * 1e6, 6)  # µm
    5.0
    """
    p = check_nonnegative("pressure", pressure, "Pa")
    _check_annulus(bore, outer_diameter)
    return lame.outside_change(p, bore, outer_diameter, material.youngs_modulus)


@dataclass(frozen=True)
class MountedGeometry:
    """Result of :func:`mounted_geometry`.

    Attributes
    ----------
    race : operating :class:`RaceGeometry`
    outer_fit_pressure, inner_fit_pressure : Lamé pressures [Pa] (0 where the fit is lost)
    outer_interference, inner_interference : diametral interferences at temperature [m]
    """

    race: RaceGeometry
    outer_fit_pressure: np.ndarray
    inner_fit_pressure: np.ndarray
    outer_interference: np.ndarray
    inner_interference: np.ndarray


def mounted_geometry(
    bearing: BallBearing,
    fit: RadialFit,
    temperature,
    assembly_temperature: float,
    coupled: bool = True,
) -> MountedGeometry:
    """Operating geometry of a bearing mounted with ``fit`` (Yu 2017 eq 10–13; Ning §2.1).

    Parameters
    ----------
    bearing : catalogue geometry (at ``assembly_temperature``)
    fit : seats and interferences at ``assembly_temperature``
    temperature : T [K], uniform (scalar or array), or a
        :class:`~.thermal.temperatures.PartTemperatures` (housing, shaft, outer ring, inner ring;
        the balls take the rings' mean)
    assembly_temperature : T0 [K] at which ``fit`` holds
    coupled : False gives free thermal growth only (Yu Fig 3 "without coupling")

    Returns
    -------
    MountedGeometry
        Operating race geometry [m], fit pressures [Pa] and interferences [m].

    Each part grows freely by α·(T_part − T0) (eq 10); the interferences become
    δ_o = D·(1 + α_ring·ΔT_o) − (D − δ_o0)·(1 + α_housing·ΔT_h) and likewise for the inner
    ring on the shaft; the Lamé pressures (eq 12) then shrink the outer raceway (eq 13) and
    expand the inner raceway. The clearance follows as Pd = d_o − d_i − 2·Dw (Yu §2.1).

    Examples
    --------
    Yu's 71803 in its aluminium frame: at the assembly temperature without coupling nothing
    grows and the clearance is the catalogue's; the 12 µm outer fit closes part of it:

    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> b, fit, t0 = pair.bearing, pair.mounting.fit, pair.mounting.assembly_temperature
    >>> free = mounted_geometry(b, fit, t0, t0, coupled=False)
    >>> round(float(free.race.clearance) * 1e6, 4), round(b.clearance * 1e6, 4)  # µm
    (16.226, 16.226)
    >>> m = mounted_geometry(b, fit, t0, t0)
    >>> round(float(m.race.clearance) * 1e6, 4), round(float(m.outer_fit_pressure) / 1e6, 4)
    (9.6583, 4.4114)

    60 K colder the aluminium housing shrinks onto the steel ring: the interference grows by
    about 60 K · 26 mm · (21.7 − 11.7)·1e-6/K = 15.6 µm (by hand; 15.58 µm with the housing
    bore 12 µm below 26 mm):

    >>> cold = mounted_geometry(b, fit, t0 - 60.0, t0)
    >>> round(float(cold.outer_interference) * 1e6, 4)  # µm, was 12
    27.5844
    """
    from .temperatures import part_temperatures

    temps = part_temperatures(temperature)
    t0 = check_temperature("assembly_temperature", assembly_temperature)
    return mounted_geometry_at(
        bearing,
        fit,
        *(np.asarray(t) for t in (temps.housing, temps.shaft, temps.outer_ring, temps.inner_ring)),
        t0,
        coupled,
    )


def mounted_geometry_at(
    bearing: BallBearing, fit: RadialFit, t_h, t_s, t_o, t_i, t0: float, coupled: bool
) -> MountedGeometry:
    """:func:`mounted_geometry` at temperatures already checked: housing ``t_h``, shaft
    ``t_s``, outer ring ``t_o``, inner ring ``t_i`` and assembly ``t0`` [K] (floats or arrays
    that broadcast together); the path of :func:`~.pair.state.thermal_state`, which checks
    them once.

    Returns
    -------
    MountedGeometry
        As :func:`mounted_geometry`.

    Examples
    --------
    >>> from servofmu.physics.pair.configuration import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa")
    >>> b, fit, t0 = pair.bearing, pair.mounting.fit, pair.mounting.assembly_temperature
    >>> g = mounted_geometry_at(b, fit, t0, t0, t0, t0, t0, True)
    >>> float(g.race.clearance) == float(mounted_geometry(b, fit, t0, t0).race.clearance)
    True
    """
    ring, ball = bearing.ring_material, bearing.ball_material
    d_i, d_o, dw, r_i, r_o, p_o, p_i, delta_o, delta_i = lame.mounted_races(
        t_h,
        t_s,
        t_o,
        t_i,
        t0,
        _elastic(ring),
        ball.expansion,
        _elastic(fit.housing_material),
        _elastic(fit.shaft_material),
        (
            bearing.outer_diameter,
            bearing.bore,
            bearing.outer_groove_diameter,
            bearing.inner_groove_diameter,
            bearing.ball_diameter,
            bearing.inner_curvature,
            bearing.outer_curvature,
        ),
        (
            bearing.outer_diameter - fit.outer_interference,
            bearing.bore + fit.inner_interference,
            fit.housing_outer_diameter,
            fit.shaft_bore,
        ),
        coupled,
    )
    race = RaceGeometry(
        ball_diameter=dw,
        inner_race_diameter=d_i,
        outer_race_diameter=d_o,
        inner_groove_radius=r_i,
        outer_groove_radius=r_o,
        n_balls=bearing.n_balls,
        compliance=reduced_compliance(ring, ball),
    )
    return MountedGeometry(race, p_o, p_i, delta_o, delta_i)


def _elastic(material: Material) -> tuple[float, float, float]:
    """(α [1/K], E [Pa], ν [-]) of a material, as :func:`~.kernels.lame.mounted_races` takes
    it."""
    return material.expansion, material.youngs_modulus, material.poisson_ratio
