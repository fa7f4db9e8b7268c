r"""The SKF (2004) model of the frictional moment of a rolling bearing, for deep-groove and
angular-contact ball bearings (SKF, "Friction"):

.. math::

   M = \phi_\mathrm{ish}\,\phi_\mathrm{rs}\,M_\mathrm{rr} + M_\mathrm{sl}
       + M_\mathrm{seal} + M_\mathrm{drag}

with the rolling moment (:math:`G_\mathrm{rr}` from Table 2a/2b)

.. math::

   M_\mathrm{rr} = G_\mathrm{rr}\,(\nu n)^{0.6},

the sliding moment

.. math::

   M_\mathrm{sl} = G_\mathrm{sl}\,\mu_\mathrm{sl}, \qquad
   \mu_\mathrm{sl} = \phi_\mathrm{bl}\,\mu_\mathrm{bl} + (1 - \phi_\mathrm{bl})\,\mu_\mathrm{EHL},
   \qquad
   \phi_\mathrm{bl} = \frac{1}{e^{2.6\times10^{-8}\,(n\nu)^{1.4}\,d_m}},

the inlet shear heating and the replenishment/starvation reduction factors

.. math::

   \phi_\mathrm{ish} = \frac{1}{1 + 1.84\times10^{-9}\,(n\,d_m)^{1.28}\,\nu^{0.64}},
   \qquad
   \phi_\mathrm{rs} = \frac{1}{e^{K_\mathrm{rs}\,\nu\,n\,(d + D)\sqrt{K_z/(2(D - d))}}},

and the starting torque (:math:`n \to 0`: :math:`\phi_\mathrm{bl} = 1`,
:math:`\mu_\mathrm{sl} = \mu_\mathrm{bl}`)

.. math::

   M_\mathrm{start} = M_\mathrm{sl} + M_\mathrm{seal}.

The catalogue writes every equation in its own units: dm, d, D [mm], F [N], n [r/min],
ν [mm²/s], M [N·mm]. The functions here take and return SI (m, N, rad/s, m²/s, N·m) and
convert at the edge (:mod:`servofmu.physics.kernels.units`).

Sources (see also ``data/skf_friction.toml``):

- SKF, *Rolling bearings*, PUB BU/P1 10000 EN (2012), chapter "Friction", section "The SKF
  model for calculating the frictional moment", pp. 104–106: the sliding moment,
  :math:`\mu_\mathrm{sl}`, :math:`\phi_\mathrm{bl}`, :math:`\mu_\mathrm{bl} \approx 0.15`,
  the :math:`\mu_\mathrm{EHL}` values and Table 2a "Geometric and load dependent variables
  for rolling and sliding frictional moments – radial bearings" (value as transcribed,
  original not checked). The model first appeared in the SKF General Catalogue 6000 EN
  (2005, "The new SKF model", pp. 89–103) and is unchanged in PUB BU/P1 17000 EN (2018).
- The starting torque, "at an ambient temperature of 20 to 30 °C": SKF, "Friction – Starting
  torque", https://www.skf.com (value as transcribed, original not checked).
- :math:`\phi_\mathrm{ish}` and :math:`\phi_\mathrm{rs}`: the variables and their units as
  SKF's web pages on the inlet shear heating and replenishment factors define them; the
  formulas above as printed in the catalogue (value as transcribed, original not checked).
- The geometry constants R1…S3 and Kz are data with per-value provenance in
  ``data/skf_friction.toml``, which states which of them were verified.

The catalogue's model is for a single bearing under its own radial and axial load. For a
preloaded pair, evaluate each bearing with its own (Fr, Fa) and add the moments.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._checks import check_choice, check_finite, check_nonnegative, check_positive, check_range
from ..kernels.units import CST, MM, NMM, RPM

BEARING_TYPES = ("deep_groove", "angular_contact")

#: Krs of φrs by lubrication method (SKF 10000 EN, "Kinematic replenishment/starvation
#: reduction factor"): 3e-8 for low-level oil bath and oil jet, 6e-8 for grease and oil-air.
REPLENISHMENT_KRS = {"oil_bath": 3.0e-8, "oil_jet": 3.0e-8, "grease": 6.0e-8, "oil_air": 6.0e-8}

#: μbl, the boundary (additive-dependent) sliding coefficient, "generally ≈ 0,15" (SKF 10000 EN
#: p. 103).
MU_BOUNDARY = 0.15
#: μEHL, the full-film sliding coefficient of ball bearings (SKF 10000 EN p. 103): mineral
#: oils 0.05, synthetic oils 0.04, transmission fluids 0.1.
MU_EHL = {"mineral": 0.05, "synthetic": 0.04, "transmission": 0.1}


@dataclass(frozen=True)
class SkfConstants:
    """Geometry constants of one bearing series in the SKF model (catalogue Table 2b).

    Attributes
    ----------
    key : series designation, e.g. "62", "72B"
    bearing_type : "deep_groove" or "angular_contact" (selects the Table 2a formulas)
    r1, r2, r3 : rolling constants R1, R2, R3 [catalogue units, r3 = 0 for deep-groove]
    s1, s2, s3 : sliding constants S1, S2, S3 [catalogue units, s3 = 0 for deep-groove]
    kz : geometry constant Kz of φrs (and of the drag loss) [-]
    provenance : ((field, source), ...)
    """

    key: str
    bearing_type: str
    r1: float
    r2: float
    s1: float
    s2: float
    kz: float
    r3: float = 0.0
    s3: float = 0.0
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_choice("bearing_type", self.bearing_type, BEARING_TYPES)
        for name in ("r1", "r2", "s1", "s2", "kz"):
            check_positive(name, getattr(self, name))
        check_nonnegative("r3", self.r3)
        check_nonnegative("s3", self.s3)

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")


@dataclass(frozen=True)
class SkfTorques:
    """The SKF model's moments of one bearing [N·m] and the factors behind them [-].

    ``total = phi_ish·phi_rs·rolling + sliding + seal + drag``; ``starting = Msl(n → 0) +
    seal`` (μsl = μbl, no centrifugal term). Fields are floats or arrays of one shape.
    """

    rolling: float | np.ndarray
    sliding: float | np.ndarray
    seal: float | np.ndarray
    drag: float | np.ndarray
    starting: float | np.ndarray
    phi_ish: float | np.ndarray
    phi_rs: float | np.ndarray
    phi_bl: float | np.ndarray
    mu_sl: float | np.ndarray

    @property
    def rolling_reduced(self):
        """φish·φrs·Mrr [N·m]: the rolling moment as it enters the total."""
        return self.phi_ish * self.phi_rs * self.rolling

    @property
    def total(self):
        """M = φish·φrs·Mrr + Msl + Mseal + Mdrag [N·m]."""
        return self.rolling_reduced + self.sliding + self.seal + self.drag


def _rpm(speed):
    return np.abs(speed) / RPM


def _cst(nu):
    return np.asarray(nu, dtype=float) / CST


def _scalar(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def mean_diameter(bore, outer_diameter):
    """Bearing mean diameter dm = 0.5·(d + D) [m] (the SKF model's dm).

    Parameters
    ----------
    bore : d [m]
    outer_diameter : D [m], > d

    Returns
    -------
    dm [m]

    >>> round(mean_diameter(0.020, 0.047) * 1e3, 3)  # 6204
    33.5
    """
    d = check_positive("bore", bore, "m")
    big_d = check_positive("outer_diameter", outer_diameter, "m")
    if np.any(np.asarray(big_d) <= np.asarray(d)):
        raise ValueError(f"outer_diameter = {outer_diameter!r} m must exceed bore = {bore!r} m")
    return 0.5 * (d + big_d)


def inlet_shear_factor(kinematic_viscosity, speed, mean_diameter):
    """Inlet shear heating reduction factor φish = 1/(1 + 1.84e-9·(n·dm)^1.28·ν^0.64) [-]
    (SKF 10000 EN, "Inlet shear heating reduction factor"; n in r/min, dm in mm, ν in mm²/s).

    Parameters
    ----------
    kinematic_viscosity : ν [m²/s] of the oil, or of the grease's base oil, at the operating
        temperature
    speed : ω [rad/s] (sign ignored)
    mean_diameter : dm = 0.5·(d + D) [m]

    Returns
    -------
    φish [-], in (0, 1]

    >>> round(inlet_shear_factor(20e-6, 3000 * 2 * 3.141592653589793 / 60, 0.0335), 4)
    0.9693
    """
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m²/s")
    check_finite("speed", speed, "rad/s")
    dm = check_positive("mean_diameter", mean_diameter, "m")
    return _scalar(_phi_ish(_cst(nu), _rpm(speed), dm / MM))


def _exp(x):
    return math.exp(x) if type(x) is float else np.exp(x)


# The equations in the catalogue's own units (ν mm²/s, n r/min, lengths mm, loads N, moments
# N·mm), elementwise on Python floats (the per-step path of an FMU) or numpy arrays: the one
# place each is written; the public functions check and convert, then call these.
def _phi_ish(nu_cst, n_rpm, dm_mm):
    """φish = 1/(1 + 1.84e-9·(n·dm)^1.28·ν^0.64) [-]."""
    return 1.0 / (1.0 + 1.84e-9 * (n_rpm * dm_mm) ** 1.28 * nu_cst**0.64)


def _phi_rs(nu_cst, n_rpm, d_mm, big_d_mm, kz, krs):
    """φrs = 1/e^(Krs·ν·n·(d + D)·√(Kz/(2·(D − d)))) [-]."""
    return _exp(-krs * nu_cst * n_rpm * (d_mm + big_d_mm) * (kz / (2.0 * (big_d_mm - d_mm))) ** 0.5)


def _phi_bl(nu_cst, n_rpm, dm_mm):
    """φbl = 1/e^(2.6e-8·(n·ν)^1.4·dm) [-]."""
    return _exp(-2.6e-8 * (n_rpm * nu_cst) ** 1.4 * dm_mm)


def _angular_contact_g(c, dm_mm, fr, fa, n_rpm):
    """(Grr, Gsl) of an angular-contact ball bearing (SKF Table 2a; catalogue units):
    Grr = R1·dm^1.97·(Fr + Fg + R2·Fa)^0.54, Fg = R3·dm^4·n²;
    Gsl = S1·dm^0.26·((Fr + Fg)^(4/3) + S2·Fa^(4/3)), Fg = S3·dm^4·n²."""
    centrifugal = dm_mm**4 * n_rpm * n_rpm
    grr = c.r1 * dm_mm**1.97 * (fr + c.r3 * centrifugal + c.r2 * fa) ** 0.54
    radial = fr + c.s3 * centrifugal
    gsl = c.s1 * dm_mm**0.26 * (radial ** (4.0 / 3.0) + c.s2 * fa ** (4.0 / 3.0))
    return grr, gsl


def replenishment_factor(kinematic_viscosity, speed, bore, outer_diameter, kz, krs):
    """Kinematic replenishment/starvation reduction factor [-] (SKF 10000 EN):

        φrs = 1/e^(Krs·ν·n·(d + D)·√(Kz/(2·(D − d))))     (n r/min, ν mm²/s, d, D mm)

    Parameters
    ----------
    kinematic_viscosity : ν [m²/s] at the operating temperature
    speed : ω [rad/s] (sign ignored)
    bore, outer_diameter : d, D [m]
    kz : bearing-type geometry constant Kz [-] (``data/skf_friction.toml``)
    krs : replenishment/starvation constant [-]: :data:`REPLENISHMENT_KRS` (3e-8 oil bath or
        jet, 6e-8 grease or oil-air)

    Returns
    -------
    φrs [-], in (0, 1]

    >>> round(replenishment_factor(20e-6, 3000 * 2 * 3.141592653589793 / 60,
    ...                            0.020, 0.047, 3.1, 6e-8), 4)
    0.9438
    """
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m²/s")
    check_finite("speed", speed, "rad/s")
    mean_diameter(bore, outer_diameter)  # checks 0 < d < D
    check_positive("kz", kz)
    check_nonnegative("krs", krs)
    d_mm, big_d_mm = np.asarray(bore) / MM, np.asarray(outer_diameter) / MM
    return _scalar(_phi_rs(_cst(nu), _rpm(speed), d_mm, big_d_mm, kz, krs))


def boundary_weighting(kinematic_viscosity, speed, mean_diameter):
    """Weighting factor of the sliding friction coefficient φbl = 1/e^(2.6e-8·(n·ν)^1.4·dm)
    [-] (SKF 10000 EN p. 103; n r/min, ν mm²/s, dm mm). 1 at rest (boundary friction), → 0
    in full film.

    Parameters
    ----------
    kinematic_viscosity : ν [m²/s]
    speed : ω [rad/s] (sign ignored)
    mean_diameter : dm [m]

    Returns
    -------
    φbl [-], in (0, 1]

    >>> boundary_weighting(20e-6, 0.0, 0.0335)
    1.0
    >>> round(boundary_weighting(20e-6, 3000 * 2 * 3.141592653589793 / 60, 0.0335), 6)
    0.014119
    """
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m²/s")
    check_finite("speed", speed, "rad/s")
    dm = check_positive("mean_diameter", mean_diameter, "m")
    return _scalar(_phi_bl(_cst(nu), _rpm(speed), dm / MM))


def sliding_friction_coefficient(phi_bl, mu_bl=MU_BOUNDARY, mu_ehl=MU_EHL["mineral"]):
    """Sliding friction coefficient μsl = φbl·μbl + (1 − φbl)·μEHL [-] (SKF 10000 EN p. 103).

    Parameters
    ----------
    phi_bl : weighting factor φbl [-] (:func:`boundary_weighting`)
    mu_bl : boundary coefficient μbl [-], "generally ≈ 0,15"
    mu_ehl : full-film coefficient μEHL [-]: :data:`MU_EHL`

    Returns
    -------
    μsl [-]

    >>> sliding_friction_coefficient(1.0)
    0.15
    >>> round(sliding_friction_coefficient(0.5, 0.15, 0.05), 6)
    0.1
    """
    p = check_range("phi_bl", phi_bl, 0.0, 1.0)
    check_range("mu_bl", mu_bl, 0.0, 1.0)
    check_range("mu_ehl", mu_ehl, 0.0, 1.0)
    return _scalar(p * mu_bl + (1.0 - p) * mu_ehl)


def _loads(radial_load, axial_load):
    fr = check_nonnegative("radial_load", radial_load, "N")
    fa = check_nonnegative("axial_load", axial_load, "N")
    return np.asarray(fr, dtype=float), np.asarray(fa, dtype=float)


def _deep_groove_angle(axial_load, static_load_rating):
    """αF [rad] = 24.6·(Fa/C0)^0.24 [°] (Table 2a, deep-groove ball bearings)."""
    if static_load_rating is None:
        raise ValueError(
            "static_load_rating (C0) [N] is needed for a deep-groove ball bearing under axial "
            "load: αF = 24.6·(Fa/C0)^0.24 [°] (SKF Table 2a)"
        )
    c0 = check_positive("static_load_rating", static_load_rating, "N")
    return np.deg2rad(24.6 * (axial_load / c0) ** 0.24)


def _g_rolling(c: SkfConstants, dm_mm, fr, fa, n, static_load_rating):
    """Grr (Table 2a), catalogue units: dm mm, F N, n r/min."""
    if c.bearing_type == "angular_contact":
        return _angular_contact_g(c, dm_mm, fr, fa, n)[0]
    loaded = fa > 0.0
    if not np.any(loaded):
        return c.r1 * dm_mm**1.96 * fr**0.54
    alpha = _deep_groove_angle(np.where(loaded, fa, 1.0), static_load_rating)
    axial = np.where(loaded, c.r2 / np.sin(alpha) * fa, 0.0)
    return c.r1 * dm_mm**1.96 * (fr + axial) ** 0.54


def _g_sliding(c: SkfConstants, dm_mm, fr, fa, n, static_load_rating):
    """Gsl (Table 2a), catalogue units. For deep-groove bearings the catalogue has two
    branches, Fa = 0: S1·dm^−0.26·Fr^(5/3) and Fa > 0: S1·dm^−0.145·(Fr^5 + S2·dm^1.5/sin αF·
    Fa^4)^(1/3). They are not continuous as Fa → 0 (the dm exponents differ); both are kept
    as printed, so a deep-groove bearing's sliding moment jumps by dm^0.115 when an axial
    load appears."""
    if c.bearing_type == "angular_contact":
        return _angular_contact_g(c, dm_mm, fr, fa, n)[1]
    loaded = fa > 0.0
    pure_radial = c.s1 * dm_mm**-0.26 * fr ** (5.0 / 3.0)
    if not np.any(loaded):
        return pure_radial
    alpha = _deep_groove_angle(np.where(loaded, fa, 1.0), static_load_rating)
    combined = (
        c.s1 * dm_mm**-0.145 * (fr**5 + c.s2 * dm_mm**1.5 / np.sin(alpha) * fa**4) ** (1.0 / 3.0)
    )
    return np.where(loaded, combined, pure_radial)


def _geometry(bore, outer_diameter, radial_load, axial_load, speed):
    dm = mean_diameter(bore, outer_diameter)
    fr, fa = _loads(radial_load, axial_load)
    check_finite("speed", speed, "rad/s")
    return dm, fr, fa, _rpm(speed)


def rolling_torque(
    constants: SkfConstants,
    bore,
    outer_diameter,
    radial_load,
    axial_load,
    kinematic_viscosity,
    speed,
    static_load_rating=None,
):
    """Rolling frictional moment Mrr = Grr·(ν·n)^0.6 [N·m], before the reduction factors
    (SKF 10000 EN, "Rolling frictional moment"; Grr from Table 2a with the series' constants).

    Parameters
    ----------
    constants : :class:`SkfConstants` of the bearing series (:func:`skf_constants`)
    bore, outer_diameter : d, D [m]
    radial_load, axial_load : Fr, Fa [N] on this bearing, ≥ 0
    kinematic_viscosity : ν [m²/s] of the oil or the grease's base oil
    speed : ω [rad/s] (sign ignored)
    static_load_rating : C0 [N]; needed for a deep-groove bearing with Fa > 0

    Returns
    -------
    Mrr [N·m]

    >>> c = SkfConstants("62", "deep_groove", r1=3.9e-7, r2=1.7, s1=3.23e-3, s2=36.5, kz=3.1)
    >>> w = 1000 * 2 * 3.141592653589793 / 60                  # 1000 r/min
    >>> round(rolling_torque(c, 0.020, 0.047, 1000.0, 0.0, 20e-6, w) * 1e3, 3)  # N·mm
    6.036
    """
    dm, fr, fa, n = _geometry(bore, outer_diameter, radial_load, axial_load, speed)
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m²/s")
    grr = _g_rolling(constants, dm / MM, fr, fa, n, static_load_rating)
    return _scalar(grr * (_cst(nu) * n) ** 0.6 * NMM)


def sliding_torque(
    constants: SkfConstants,
    bore,
    outer_diameter,
    radial_load,
    axial_load,
    kinematic_viscosity,
    speed,
    mu_bl=MU_BOUNDARY,
    mu_ehl=MU_EHL["mineral"],
    static_load_rating=None,
):
    """Sliding frictional moment Msl = Gsl·μsl [N·m] (SKF 10000 EN p. 103, Table 2a), with
    μsl = φbl·μbl + (1 − φbl)·μEHL (:func:`sliding_friction_coefficient`).

    Parameters
    ----------
    constants : :class:`SkfConstants` of the bearing series
    bore, outer_diameter : d, D [m]
    radial_load, axial_load : Fr, Fa [N], ≥ 0
    kinematic_viscosity : ν [m²/s]
    speed : ω [rad/s] (sign ignored; 0 gives the starting value μsl = μbl)
    mu_bl, mu_ehl : μbl, μEHL [-]
    static_load_rating : C0 [N] (deep-groove with Fa > 0)

    Returns
    -------
    Msl [N·m]

    >>> c = SkfConstants("62", "deep_groove", r1=3.9e-7, r2=1.7, s1=3.23e-3, s2=36.5, kz=3.1)
    >>> round(sliding_torque(c, 0.020, 0.047, 1000.0, 0.0, 20e-6, 0.0) * 1e3, 3)  # at rest
    19.444
    """
    dm, fr, fa, n = _geometry(bore, outer_diameter, radial_load, axial_load, speed)
    phi = boundary_weighting(kinematic_viscosity, speed, dm)
    mu = sliding_friction_coefficient(phi, mu_bl, mu_ehl)
    gsl = _g_sliding(constants, dm / MM, fr, fa, n, static_load_rating)
    return _scalar(gsl * mu * NMM)


def seal_torque(counterface_diameter, ks1, ks2, beta):
    """Frictional moment of the seals of one bearing, Mseal = KS1·ds^β + KS2 [N·m] (SKF 10000
    EN, "Frictional moment of seals"; ds in mm, Mseal in N·mm; KS1, KS2 and β from the
    catalogue's seal table for the seal type and bearing series).

    Parameters
    ----------
    counterface_diameter : seal counterface diameter ds [m]
    ks1 : KS1 [catalogue units], ks2 : KS2 [N·mm], beta : β [-]

    Returns
    -------
    Mseal [N·m]

    >>> round(seal_torque(0.025, 0.028, 2.0, 2.25) * 1e3, 3)  # illustrative constants, N·mm
    41.131
    """
    ds = check_positive("counterface_diameter", counterface_diameter, "m")
    check_nonnegative("ks1", ks1)
    check_nonnegative("ks2", ks2)
    check_range("beta", beta, 0.0, 5.0)
    return _scalar((ks1 * (ds / MM) ** beta + ks2) * NMM)


def oil_bath_drag_torque(
    drag_factor, oil_level, bore, outer_diameter, kinematic_viscosity, speed, kz, rows=1
):
    """Drag losses of a ball bearing in an oil bath [N·m] (SKF 10000 EN, "Drag losses in oil
    bath lubrication", ball bearings):

        Mdrag = 0.4·Vm·Kball·dm^5·n² + 1.093e-7·n²·dm³·(n·dm²·ft/ν)^−1.379·Rs
        Kball = irw·Kz·(d + D)/(D − d)·1e-12,   fA = 0.05·Kz·(D + d)/(D − d)
        Rs = 0.36·dm²·(t − sin t)·fA,   t = 2·acos((0.6·dm − H)/(0.6·dm))
        ft = sin(0.5·t) for 0 ≤ t ≤ π, else 1

    (dm, d, D, H in mm, n r/min, ν mm²/s, Mdrag N·mm). Vm, the drag loss factor, is read by
    the user from the catalogue's diagram as a function of H/dm; it is not digitised here.
    For grease, oil-air and oil-jet lubrication the catalogue has no drag term: use 0.

    Parameters
    ----------
    drag_factor : Vm [-] from the catalogue diagram
    oil_level : H [m], oil level above the lowest point of the outer raceway, ≥ 0
    bore, outer_diameter : d, D [m]
    kinematic_viscosity : ν [m²/s], > 0
    speed : ω [rad/s] (sign ignored)
    kz : geometry constant Kz [-]
    rows : number of ball rows irw

    Returns
    -------
    Mdrag [N·m]

    >>> w = 3000 * 2 * 3.141592653589793 / 60
    >>> round(oil_bath_drag_torque(0.0003, 0.005, 0.020, 0.047, 20e-6, w, 3.1) * 1e3, 4)
    0.6354
    """
    vm = check_nonnegative("drag_factor", drag_factor)
    h = check_nonnegative("oil_level", oil_level, "m") / MM
    dm_m = mean_diameter(bore, outer_diameter)
    nu = check_positive("kinematic_viscosity", kinematic_viscosity, "m²/s") / CST
    check_finite("speed", speed, "rad/s")
    check_positive("kz", kz)
    if not (isinstance(rows, int) and rows >= 1):
        raise ValueError(f"rows = {rows!r} must be an integer >= 1")
    n = _rpm(speed)
    dm, d_mm, big_d = dm_m / MM, bore / MM, outer_diameter / MM
    k_ball = rows * kz * (d_mm + big_d) / (big_d - d_mm) * 1e-12
    f_a = 0.05 * kz * (big_d + d_mm) / (big_d - d_mm)
    t = 2.0 * np.arccos(np.clip((0.6 * dm - h) / (0.6 * dm), -1.0, 1.0))
    f_t = np.where(t <= math.pi, np.sin(0.5 * t), 1.0)
    r_s = 0.36 * dm**2 * (t - np.sin(t)) * f_a
    wet = (n > 0.0) & (r_s > 0.0)  # no speed or no oil: no viscous drag (and no 0^-1.379)
    n_w, f_w = np.where(wet, n, 1.0), np.where(wet, f_t, 1.0)
    viscous = 1.093e-7 * n_w**2 * dm**3 * (n_w * dm**2 * f_w / nu) ** -1.379 * r_s
    viscous = np.where(wet, viscous, 0.0)
    return _scalar((0.4 * vm * k_ball * dm**5 * n**2 + viscous) * NMM)


def skf_friction(
    constants: SkfConstants,
    bore,
    outer_diameter,
    radial_load,
    axial_load,
    kinematic_viscosity,
    speed,
    *,
    lubrication: str = "grease",
    mu_bl: float = MU_BOUNDARY,
    mu_ehl: float = MU_EHL["mineral"],
    static_load_rating=None,
    seal=0.0,
    drag=0.0,
) -> SkfTorques:
    """The SKF model's moments of one bearing: M = φish·φrs·Mrr + Msl + Mseal + Mdrag and the
    starting torque Mstart = Msl(n → 0) + Mseal (SKF 10000 EN, "The SKF model for
    calculating the frictional moment"; "Starting torque").

    Parameters
    ----------
    constants : :class:`SkfConstants` of the series (:func:`skf_constants`)
    bore, outer_diameter : d, D [m]
    radial_load, axial_load : Fr, Fa [N] on this bearing (for a preloaded pair: each
        bearing's own, preload included; :func:`bearing_loads` sums per-ball contacts)
    kinematic_viscosity : ν [m²/s] at the operating temperature (oil, or grease base oil)
    speed : ω [rad/s] (sign ignored)
    lubrication : "grease", "oil_air", "oil_bath" or "oil_jet" (selects Krs of φrs)
    mu_bl, mu_ehl : μbl, μEHL [-] (:data:`MU_BOUNDARY`, :data:`MU_EHL`)
    static_load_rating : C0 [N] (deep-groove bearings under axial load)
    seal : Mseal [N·m] (:func:`seal_torque`; 0 for an open or shielded bearing)
    drag : Mdrag [N·m] (:func:`oil_bath_drag_torque`; 0 except in an oil bath)

    Returns
    -------
    :class:`SkfTorques` [N·m and -]; ``.total`` is M.

    >>> c = SkfConstants("62", "deep_groove", r1=3.9e-7, r2=1.7, s1=3.23e-3, s2=36.5, kz=3.1)
    >>> w = 1000 * 2 * 3.141592653589793 / 60
    >>> t = skf_friction(c, 0.020, 0.047, 1000.0, 0.0, 20e-6, w, lubrication="oil_bath")
    >>> round(t.total * 1e3, 2), round(t.starting * 1e3, 2)  # N·mm
    (17.61, 19.44)
    """
    krs = REPLENISHMENT_KRS.get(check_choice("lubrication", lubrication, REPLENISHMENT_KRS))
    dm = mean_diameter(bore, outer_diameter)
    args = (constants, bore, outer_diameter, radial_load, axial_load, kinematic_viscosity)
    m_rr = rolling_torque(*args, speed, static_load_rating)
    m_sl = sliding_torque(*args, speed, mu_bl, mu_ehl, static_load_rating)
    m_start = sliding_torque(*args, 0.0, mu_bl, mu_ehl, static_load_rating)
    seal = check_nonnegative("seal", seal, "N·m")
    drag = check_nonnegative("drag", drag, "N·m")
    phi_bl = boundary_weighting(kinematic_viscosity, speed, dm)
    return SkfTorques(
        rolling=m_rr,
        sliding=m_sl,
        seal=seal,
        drag=drag,
        starting=_scalar(m_start + seal),
        phi_ish=inlet_shear_factor(kinematic_viscosity, speed, dm),
        phi_rs=replenishment_factor(
            kinematic_viscosity, speed, bore, outer_diameter, constants.kz, krs
        ),
        phi_bl=phi_bl,
        mu_sl=sliding_friction_coefficient(phi_bl, mu_bl, mu_ehl),
    )


def _pair_moments(c, d_mm, big_d_mm, fa_a, fa_b, fr, nu_cst, n_rpm, krs, mu_bl, mu_ehl):
    """(φish·φrs·ΣMrr, ΣMsl) [N·mm] of two angular-contact bearings of one size with axial
    loads fa_a, fa_b and radial load fr each [N], in the catalogue's units, elementwise on
    floats or arrays (see :func:`pair_moments`)."""
    dm_mm = 0.5 * (d_mm + big_d_mm)
    reduction = _phi_ish(nu_cst, n_rpm, dm_mm) * _phi_rs(nu_cst, n_rpm, d_mm, big_d_mm, c.kz, krs)
    phi_bl = _phi_bl(nu_cst, n_rpm, dm_mm)
    mu_sl = phi_bl * mu_bl + (1.0 - phi_bl) * mu_ehl
    grr_a, gsl_a = _angular_contact_g(c, dm_mm, fr, fa_a, n_rpm)
    grr_b, gsl_b = _angular_contact_g(c, dm_mm, fr, fa_b, n_rpm)
    return reduction * (grr_a + grr_b) * (nu_cst * n_rpm) ** 0.6, mu_sl * (gsl_a + gsl_b)


def _pair_starting(c, d_mm, big_d_mm, fa_a, fa_b, fr, mu_bl):
    """ΣMsl(n → 0) = μbl·(Gsl,A + Gsl,B) at n = 0 [N·mm] (SKF "Starting torque": μsl = μbl
    since φbl = 1, no centrifugal load), elementwise on floats or arrays."""
    dm_mm = 0.5 * (d_mm + big_d_mm)
    gsl_a = _angular_contact_g(c, dm_mm, fr, fa_a, 0.0)[1]
    gsl_b = _angular_contact_g(c, dm_mm, fr, fa_b, 0.0)[1]
    return mu_bl * (gsl_a + gsl_b)


def pair_moments(
    constants: SkfConstants,
    bore,
    outer_diameter,
    axial_loads,
    radial_load,
    kinematic_viscosity,
    speed,
    krs=REPLENISHMENT_KRS["grease"],
    mu_bl=MU_BOUNDARY,
    mu_ehl=MU_EHL["mineral"],
):
    """The SKF model of a preloaded pair of angular-contact ball bearings: each bearing with
    its own axial load (preload included) and its share of the radial load, the moments added
    ("The SKF model ...": a single bearing under its own Fr and Fa). Open bearings (Mseal = 0)
    without an oil bath (Mdrag = 0). Returns the reduced rolling moment φish·φrs·(Mrr,A +
    Mrr,B), the sliding moment Msl,A + Msl,B and the starting torque Msl,A + Msl,B at n → 0
    (μsl = μbl, no centrifugal load; SKF "Starting torque").

    Parameters
    ----------
    constants : :class:`SkfConstants` of an angular-contact series (:func:`series_constants`)
    bore, outer_diameter : d, D [m] of each bearing
    axial_loads : (Fa,A, Fa,B) [N], each ≥ 0
    radial_load : Fr [N] on each bearing, ≥ 0
    kinematic_viscosity : ν [m²/s] at the operating temperature (0: a dry film, no rolling
        moment, μsl = μbl)
    speed : ω [rad/s] (sign ignored)
    krs : replenishment/starvation constant (:data:`REPLENISHMENT_KRS`)
    mu_bl, mu_ehl : μbl, μEHL [-]

    Returns
    -------
    (rolling, sliding, starting) [N·m]

    >>> c = skf_constants("72B")
    >>> w = 1000 * 2 * 3.141592653589793 / 60
    >>> m = pair_moments(c, 0.025, 0.052, (300.0, 100.0), 50.0, 20e-6, w)
    >>> [round(x * 1e3, 3) for x in m]  # N·mm
    [12.932, 5.966, 10.326]
    """
    if constants.bearing_type != "angular_contact":
        raise ValueError(
            f"SKF series {constants.key!r} is {constants.bearing_type}: a preloaded pair takes "
            "angular-contact constants"
        )
    d, big_d = np.asarray(bore, float), np.asarray(outer_diameter, float)
    mean_diameter(d, big_d)  # checks 0 < d < D
    fa_a = check_nonnegative("axial_loads[0]", axial_loads[0], "N")
    fa_b = check_nonnegative("axial_loads[1]", axial_loads[1], "N")
    fr = check_nonnegative("radial_load", radial_load, "N")
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m²/s")
    check_finite("speed", speed, "rad/s")
    check_nonnegative("krs", krs)
    check_range("mu_bl", mu_bl, 0.0, 1.0)
    check_range("mu_ehl", mu_ehl, 0.0, 1.0)
    d_mm, big_d_mm = d / MM, big_d / MM
    out = _pair_moments(
        constants, d_mm, big_d_mm, fa_a, fa_b, fr, _cst(nu), _rpm(speed), krs, mu_bl, mu_ehl
    )
    start = _pair_starting(constants, d_mm, big_d_mm, fa_a, fa_b, fr, mu_bl)
    return tuple(_scalar(x * NMM) for x in (*out, start))


def bearing_loads(ball_load, contact_angle, azimuth=None):
    """Axial and radial load of one bearing from its per-ball contacts (static equilibrium of
    the ring): Fa = Σ Qj·sin αj, Fr = |Σ Qj·cos αj·(cos ψj, sin ψj)| [N].

    Parameters
    ----------
    ball_load : Qj [N], shape S + (Z,) (the ball index last)
    contact_angle : αj [rad], same shape
    azimuth : ψj [rad], same shape or (Z,); default 2π·j/Z (balls equally spaced from ψ = 0)

    Returns
    -------
    (Fa, Fr) [N], shape S each

    >>> import numpy as np
    >>> fa, fr = bearing_loads(np.full(10, 5.0), np.full(10, np.deg2rad(30.0)))
    >>> round(float(fa), 6), round(float(fr), 6)
    (25.0, 0.0)
    """
    q = np.asarray(check_nonnegative("ball_load", ball_load, "N"), dtype=float)
    a = np.asarray(check_finite("contact_angle", contact_angle, "rad"), dtype=float)
    if q.ndim == 0 or q.shape != np.broadcast_shapes(q.shape, a.shape):
        raise ValueError(
            f"ball_load shape {q.shape} must have the ball index last and match "
            f"contact_angle shape {a.shape}"
        )
    z = q.shape[-1]
    psi = 2.0 * np.pi * np.arange(z) / z if azimuth is None else np.asarray(azimuth, float)
    fa = np.sum(q * np.sin(a), axis=-1)
    radial = q * np.cos(a)
    fr = np.hypot(np.sum(radial * np.cos(psi), axis=-1), np.sum(radial * np.sin(psi), axis=-1))
    return _scalar(fa), _scalar(fr)


def skf_constants(key: str) -> SkfConstants:
    """The :class:`SkfConstants` of series ``key`` from ``data/skf_friction.toml``.

    Parameters
    ----------
    key : series, e.g. "62" (deep-groove) or "72B" (angular-contact)

    Returns
    -------
    :class:`SkfConstants` with the per-value provenance of the data file

    >>> skf_constants("62").r1
    3.9e-07
    """
    from ...parameters.catalog import _table, quantity

    data = _table("skf_friction")
    if key not in data:
        raise ValueError(f"SKF series key = {key!r} is not one of {sorted(data)}")
    entry = data[key]
    values, prov = {}, []
    for field, spec in entry.items():
        if isinstance(spec, dict) and field != "contact_angle":  # the series' angle: a key
            values[field], src = quantity(spec, field)
            prov.append((field, src))
    return SkfConstants(
        key=key, bearing_type=entry["bearing_type"], provenance=tuple(prov), **values
    )


#: The angular-contact series whose constants stand in for one that the transcribed Table 2b
#: lacks (``data/skf_friction.toml`` lists only verified series).
FALLBACK_SERIES = "72B"


def series_constants(designation: str, contact_angle: float) -> SkfConstants:
    """The SKF constants of an angular-contact ball bearing: the entry of
    ``data/skf_friction.toml`` whose ``series_prefix`` starts the designation (followed by the
    bore code's digits) and whose ``contact_angle`` is within 1° of the bearing's; else the
    constants of :data:`FALLBACK_SERIES` (72 B(E), 40°), every value's provenance prefixed
    "fallback (assumed)" and naming the bearing.

    The fallback is a stated rule, not catalogue data: SKF's angular-contact constants differ
    by series and contact angle, and only 72 B(E) could be verified here. A 15° bearing
    (suffix C) carries more ball load per newton of axial load than a 40° one (Q ∝ 1/sin α),
    which R2 and S2 of a 40° series do not see: the fallback's axial share is low for it.

    Parameters
    ----------
    designation : bearing designation (a catalogue key such as "71803", "7205B", or
        "parameters" for a bearing given by numbers)
    contact_angle : nominal contact angle α0 [rad]

    Returns
    -------
    :class:`SkfConstants` with per-value provenance

    >>> series_constants("7205B", math.radians(40.0)).source("r1")[:40]
    'catalogue: SKF, Rolling bearings, PUB BU'
    >>> series_constants("71803", math.radians(15.0)).source("r1")[:20]
    'fallback (assumed): '
    """
    from ...parameters.catalog import _table

    angle = math.degrees(check_range("contact_angle", contact_angle, 0.0, math.pi / 2, unit="rad"))
    for key, entry in _table("skf_friction").items():
        prefix = entry.get("series_prefix")
        if entry.get("bearing_type") != "angular_contact" or prefix is None:
            continue
        rest = designation[len(prefix) :]
        if (
            designation.startswith(prefix)
            and rest[:1].isdigit()
            and abs(entry["contact_angle"]["value"] - angle) <= 1.0
        ):
            return skf_constants(key)
    base = skf_constants(FALLBACK_SERIES)
    why = (
        f"fallback (assumed): SKF Table 2b as transcribed (data/skf_friction.toml) has no "
        f"angular-contact series for {designation} ({angle:.4g}°); the constants of series "
        f"{FALLBACK_SERIES} (40°) are used"
    )
    return SkfConstants(
        **{f: getattr(base, f) for f in ("key", "bearing_type", "r1", "r2", "s1", "s2", "kz")},
        r3=base.r3,
        s3=base.s3,
        provenance=tuple((f, f"{why}: {src}") for f, src in base.provenance),
    )


# ------------------------------------------------------------------ the pair's model


def skf_loads(force_a, force_b, radial_load):
    """(Fa,A, Fa,B, Fr) [N]: each bearing's axial load from the equilibrium and its share of
    the external radial load [N] (the pair solve makes Fr,A = Fr,B = F_r/2). A bearing that has
    lost its preload under a radial load can have Σ Q·sin α slightly below 0 (balls past the
    groove bottom on the far side): the SKF model's Fa is a thrust, so it counts as 0.

    Parameters
    ----------
    force_a, force_b : float or ndarray
        The bearings' axial forces [N].
    radial_load : float or ndarray
        F_r [N].

    Returns
    -------
    tuple
        (Fa,A, Fa,B, Fr) [N], negative thrusts counted as 0.

    Examples
    --------
    >>> skf_loads(40.0, -1e-9, 10.0)  # N: a tiny negative thrust counts as 0; F_r/2 each
    (40.0, 0.0, 5.0)
    """
    if type(force_a) is float and type(force_b) is float:
        return max(force_a, 0.0), max(force_b, 0.0), 0.5 * abs(radial_load)
    return np.maximum(force_a, 0.0), np.maximum(force_b, 0.0), 0.5 * abs(radial_load)


#: The friction model's gathering of its data (:mod:`.friction.registry`, data "loads"): the
#: bearings' loads (Fa,A, Fa,B, Fr) [N] of :func:`skf_loads`.
rolling_loads = skf_loads


def skf_torques(pair, loads, kinematic_viscosity, speed):
    """(φish·φrs·ΣMrr, ΣMsl) [N·m] of the pair (:func:`.friction.skf2004.pair_moments`
    without its checks) at the loads of :func:`skf_loads`, viscosity ν [m²/s] and speed ω
    [rad/s].

    Parameters
    ----------
    pair : BearingPair
        The pair (its SKF constants).
    loads : tuple
        :func:`skf_loads` [N].
    kinematic_viscosity : float or ndarray
        ν [m²/s].
    speed : float or ndarray
        ω [rad/s].

    Returns
    -------
    tuple
        (rolling, sliding) [N·m].

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="skf2004")
    >>> rr, sl = skf_torques(pair, skf_loads(40.0, 40.0, 0.0), 100e-6, 10.0)
    >>> round(float(rr) * 1e3, 4), round(float(sl) * 1e3, 4)  # N·mm
    (1.0816, 0.6943)
    """
    fm, b = pair.friction, pair.bearing
    fa_a, fa_b, fr = loads
    rolling, sliding = _pair_moments(
        fm.skf,
        b.bore / MM,
        b.outer_diameter / MM,
        fa_a,
        fa_b,
        fr,
        kinematic_viscosity / CST,
        abs(speed) / RPM,
        fm.skf_replenishment,
        fm.skf_boundary_friction,
        fm.skf_film_friction,
    )
    return rolling * NMM, sliding * NMM


def skf_starting(pair, loads):
    """SKF's starting torque of the pair ΣMsl(n → 0) [N·m] at the loads of :func:`skf_loads`
    (open bearings: no seal moment).

    Parameters
    ----------
    pair : BearingPair
        The pair.
    loads : tuple
        :func:`skf_loads` [N].

    Returns
    -------
    float or ndarray
        [N·m].

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="skf2004")
    >>> round(float(skf_starting(pair, skf_loads(40.0, 40.0, 0.0))) * 1e3, 4)  # N·mm
    0.8055
    """
    fm, b = pair.friction, pair.bearing
    fa_a, fa_b, fr = loads
    start = _pair_starting(
        fm.skf, b.bore / MM, b.outer_diameter / MM, fa_a, fa_b, fr, fm.skf_boundary_friction
    )
    return start * NMM


def running_terms(pair, kinematic_viscosity, pitch_diameter, rolling, speed):
    """The friction model's speed terms (:mod:`.friction.registry`): (φish·φrs·ΣMrr, ΣMsl)
    [N·m] of :func:`skf_torques` at the bearings' loads ``rolling`` (:func:`skf_loads`), ν
    [m²/s] and ω [rad/s]; the pitch diameter is not used (SKF's dm is nominal).

    Returns
    -------
    tuple
        (rolling, sliding) [N·m].

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="skf2004")
    >>> rr, sl = running_terms(pair, 100e-6, 21.5e-3, skf_loads(40.0, 40.0, 0.0), 10.0)
    >>> round(float(rr) * 1e3, 4), round(float(sl) * 1e3, 4)  # N·mm, as skf_torques
    (1.0816, 0.6943)
    """
    return skf_torques(pair, rolling, kinematic_viscosity, speed)


def starting_torque(pair, rolling):
    """The friction model's torque at rest (:mod:`.friction.registry`): :func:`skf_starting`
    at the bearings' loads ``rolling`` [N].

    Returns
    -------
    float or ndarray
        [N·m].

    Examples
    --------
    >>> from servofmu.physics.bearing import BearingPair
    >>> pair = BearingPair.from_catalog("yu2017_gimbal", "krytox_143aa", friction_model="skf2004")
    >>> round(float(starting_torque(pair, skf_loads(40.0, 40.0, 0.0))) * 1e3, 4)  # N·mm
    0.8055
    """
    return skf_starting(pair, rolling)


def check_numbers(friction) -> None:
    """Raise ValueError when the pair's friction numbers (a
    :class:`~.friction.models.FrictionModel`) lack the SKF series constants.

    Returns
    -------
    None

    Examples
    --------
    >>> from servofmu.physics.friction.models import FrictionModel
    >>> FrictionModel(model="skf2004")
    Traceback (most recent call last):
    ...
    ValueError: friction_model = 'skf2004' needs the SKF series constants (skf)
    """
    if friction.skf is None:
        raise ValueError(
            f"friction_model = {friction.model!r} needs the SKF series constants (skf)"
        )


# ------------------------------------------------------------------ the pair's numbers

#: This model's numbers in a pair's :class:`~.friction.models.FrictionModel` that depend on
#: neither bearing nor lubricant, as {field: (default, source)}.
NUMBERS = {
    "skf_replenishment": (
        REPLENISHMENT_KRS["grease"],
        "catalogue: SKF 10000 EN, Krs = 6e-8 for grease and oil-air",
    ),
    "skf_boundary_friction": (
        MU_BOUNDARY,
        "catalogue: SKF 10000 EN p. 103, μbl 'generally ≈ 0,15'",
    ),
}


def bearing_numbers(bearing) -> dict:
    """{field: (value, source)} of this model's numbers for a catalogue bearing: the SKF
    constants of its series (:func:`series_constants`, their sources inside them).

    Parameters
    ----------
    bearing : :class:`~.contact.geometry.BallBearing` (its ``key`` is the designation)

    Returns
    -------
    dict
        ``{"skf": (SkfConstants, "")}``.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> bearing_numbers(catalog.bearing("71803"))["skf"][0].r1
    5.03e-07
    """
    return {"skf": (series_constants(bearing.key, float(bearing.nominal_contact_angle)), "")}


def lubricant_numbers(lubricant) -> dict:
    """{field: (value, source)} of this model's numbers for a lubricant record (or None): SKF's
    μEHL of its base oil's ``oil_class`` (mineral when unknown, labelled assumed).

    Returns
    -------
    dict
        ``{"skf_film_friction": (μEHL [-], source)}``.

    Examples
    --------
    >>> lubricant_numbers(None)["skf_film_friction"][0]
    0.05
    """
    oil_class = getattr(lubricant, "oil_class", "") or ""
    if oil_class:
        return {
            "skf_film_friction": (
                MU_EHL[oil_class],
                f"catalogue: SKF 10000 EN p. 103, μEHL of {oil_class} oils (lubricant "
                f"{lubricant.key}: {oil_class} base oil)",
            )
        }
    return {
        "skf_film_friction": (
            MU_EHL["mineral"],
            "catalogue: SKF 10000 EN p. 103, μEHL of mineral oils (assumed: oil class unknown)",
        )
    }


def parameter_numbers(p) -> dict:
    """{field: value} of this model's numbers in a full, checked parameter set ``p`` (the
    parameter table's ``skf_*``; a bearing given by numbers is an angular-contact one).

    Returns
    -------
    dict
        ``skf`` (:class:`SkfConstants`), ``skf_replenishment``, ``skf_boundary_friction``,
        ``skf_film_friction``.

    Examples
    --------
    >>> from servofmu.parameters.presets import default_parameters
    >>> parameter_numbers(default_parameters())["skf"].key
    'parameters'
    """
    skf = SkfConstants(
        key="parameters",
        bearing_type="angular_contact",
        **{f: p[f"skf_{f}"] for f in ("r1", "r2", "r3", "s1", "s2", "s3", "kz")},
    )
    numbers = ("skf_replenishment", "skf_boundary_friction", "skf_film_friction")
    return {"skf": skf} | {f: p[f] for f in numbers}


#: Names :mod:`.models` offered before this model had a module of its own: importable from it
#: still (its ``__getattr__``).
FORMER_NAMES = ("skf_loads", "skf_starting", "skf_torques")
