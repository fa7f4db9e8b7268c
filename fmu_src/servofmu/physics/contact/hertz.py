"""Hertz point contact of a ball in a groove.

References: Harris & Kotzalas (2007), *Essential Concepts of Bearing Technology*, 5th ed.,
ch. 2 (curvature sum and difference) and ch. 6 (contact stress and deformation); Johnson (1985),
*Contact Mechanics*, ch. 4. Yu 2017 eq 1–6 use the semi-axes a, b and the complete elliptic
integral of the second kind computed here.

Notation: Σρ curvature sum [1/m], F(ρ) curvature difference [-], k = a/b ellipticity (a across
the rolling direction), m = e² = 1 − 1/k² the parameter of the complete elliptic integrals K(m),
E(m) (scipy.special.ellipk / ellipe), η = (1 − ν1²)/E1 + (1 − ν2²)/E2 [1/Pa].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.special import ellipe, ellipk

from .._checks import check_choice, check_nonnegative, check_positive, check_range
from ..kernels import contact as kernels

RACES = ("inner", "outer")


def curvature_sum_difference(ball_diameter, pitch_diameter, groove_curvature, contact_angle, race):
    """Curvature sum Σρ [1/m] and difference F(ρ) [-] of a ball–groove contact.

    Parameters
    ----------
    ball_diameter : Dw [m]
    pitch_diameter : dm [m]
    groove_curvature : f = r/Dw [-], > 0.5
    contact_angle : α [rad]
    race : "inner" or "outer"

    With γ = Dw·cos α/dm (Harris & Kotzalas 2007, ch. 2):
    inner  Σρ = (4 − 1/f + 2γ/(1−γ))/Dw,  F = (1/f + 2γ/(1−γ)) / (4 − 1/f + 2γ/(1−γ));
    outer  Σρ = (4 − 1/f − 2γ/(1+γ))/Dw,  F = (1/f − 2γ/(1+γ)) / (4 − 1/f − 2γ/(1+γ)).

    Returns
    -------
    tuple
        (Σρ [1/m], F(ρ) [-]).

    Examples
    --------
    >>> s, f = curvature_sum_difference(2.381e-3, 21.5e-3, 0.52, 0.26, "inner")
    >>> round(float(s)), round(float(f), 4)  # 1/m, -
    (973, 0.9336)
    """
    check_choice("race", race, RACES)
    dw = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    f = check_range("groove_curvature", groove_curvature, 0.5, None, lo_open=True)
    alpha = check_range("contact_angle", contact_angle, -np.pi / 2, np.pi / 2, unit="rad")
    return _curvature(dw, dm, f, alpha, race)


def _curvature(dw, dm, f, alpha, race):
    total, difference = kernels.race_curvature(dw * np.cos(alpha) / dm, 1.0 / f, race == "inner")
    return total / dw, difference


def curvature_difference_of_ellipticity(k):
    """F(ρ) as an explicit function of the ellipticity k = a/b ≥ 1 (the Hertz relation):
    F = ((k² + 1)·E(m) − 2·K(m)) / ((k² − 1)·E(m)),  m = 1 − 1/k².
    Harris & Kotzalas 2007, ch. 6. Returns 0 at k = 1 (circular contact).

    Examples
    --------
    >>> float(curvature_difference_of_ellipticity(1.0))  # circular contact
    0.0
    >>> round(float(curvature_difference_of_ellipticity(ellipticity(0.9))), 12)  # the inverse
    0.9
    """
    k = np.asarray(check_range("k", k, 1.0, None), dtype=float)
    m = 1.0 - 1.0 / k**2
    e_int = ellipe(m)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = ((k**2 + 1.0) * e_int - 2.0 * ellipk(m)) / ((k**2 - 1.0) * e_int)
    out = np.where(k == 1.0, 0.0, out)
    return out if out.ndim else float(out)


def hertz_relation(k, k_integral, e_integral):
    """F(k) and dF/dk of the Hertz relation F = ((k² + 1)·E − 2·K)/((k² − 1)·E) for the
    ellipticity k > 1 [-], given K = K(m) and E = E(m) at m = 1 − 1/k² [-]
    (:func:`~servofmu.physics.kernels.contact.hertz_relation`, Harris & Kotzalas 2007, ch. 6).
    Floats or arrays; the Newton step of :func:`ellipticity`.

    Parameters
    ----------
    k : float or array_like
        Ellipticity k > 1 [-].
    k_integral, e_integral : float or array_like
        K(m), E(m) [-] at m = 1 − 1/k².

    Returns
    -------
    tuple
        (F(k) [-], dF/dk [-]).

    Examples
    --------
    >>> from scipy.special import ellipe, ellipk
    >>> k = 8.0
    >>> f, df = hertz_relation(k, ellipk(1 - 1 / k**2), ellipe(1 - 1 / k**2))
    >>> round(float(f), 6), float(df) > 0  # F rises with k
    (0.923924, True)
    """
    f, df, _ = kernels.hertz_relation(k, k_integral, e_integral)
    return f, df


# The inverse k(F) has no closed form. F(k) above is explicit and monotonic: it is tabulated
# once on a dense logarithmic grid of k and inverted by monotone (PCHIP) interpolation of ln k
# against F (error about 1e-10), then polished by Newton steps on the exact relation to
# machine precision wherever k > 1 + 1e-3 (nearer a circle F(k) loses its digits to
# cancellation, and the interpolant is kept: ball–groove contacts have k > 5). Tests check the
# inverse against a bracketing root finder.
_K_MAX = 1.0e4
_LOG_K = np.concatenate([[0.0], np.linspace(np.log(1.0 + 1e-4), np.log(_K_MAX), 6000)])
_F_OF_K = curvature_difference_of_ellipticity(np.exp(_LOG_K))
_F_MAX = float(_F_OF_K[-1])
_LOG_K_OF_F = PchipInterpolator(_F_OF_K, _LOG_K, extrapolate=False)
_POLISH_K = 1.0 + 1e-3


def ellipticity(curvature_difference):
    """Ellipticity k = a/b [-] of the contact ellipse for curvature difference F(ρ) [-].

    Solves F(ρ) = ((k² + 1)E(m) − 2K(m)) / ((k² − 1)E(m)), m = 1 − 1/k² (Harris & Kotzalas
    2007, ch. 6) for k in [1, 1e4]; F(ρ) must lie in [0, F(k=1e4)) ≈ [0, 0.99999).

    Parameters
    ----------
    curvature_difference : float or array_like
        F(ρ) in [0, 1) [-].

    Returns
    -------
    float or ndarray
        k ≥ 1 [-] (1 at F = 0).

    Examples
    --------
    >>> float(ellipticity(0.0))  # a circle
    1.0
    >>> round(float(ellipticity(0.9)), 4)
    6.7133
    """
    if type(curvature_difference) is float and 1e-3 < curvature_difference < 0.9999:
        k = _ellipticity_float(curvature_difference)
        if k is not None:  # the scalar per-step path
            return k
    f = check_range("curvature_difference", curvature_difference, 0.0, _F_MAX, hi_open=True)
    k = np.exp(_LOG_K_OF_F(f))
    polish = k > _POLISH_K
    if np.any(polish):
        kp, fp = k[polish] if k.ndim else k, f[polish] if k.ndim else f
        for _ in range(2):  # from 1e-10: the first step reaches rounding, the second checks
            m = 1.0 - 1.0 / (kp * kp)
            f_k, df_dk = hertz_relation(kp, ellipk(m), ellipe(m))
            kp = kp - (f_k - fp) / df_dk
        if k.ndim:
            k[polish] = kp
        else:
            k = kp
    return k if np.ndim(k) else float(k)


def _ellipticity_float(f: float) -> float | None:
    """:func:`ellipticity` of one float F(ρ) without the interpolant: Newton's method on the
    Hertz relation (:func:`hertz_relation`) from Hamrock & Brewe's approximation
    k ≈ 1.0339·(R_y/R_x)^0.636 with R_y/R_x = (1 + F)/(1 − F) (Hamrock B. J., Brewe D. E.,
    "Simplified solution for stresses and deformations", J. Lubrication Technology 105 (1983)
    171–177; within a few per cent), to rounding; None when it does not settle (the caller
    takes the interpolant)."""
    k = max(1.0339 * ((1.0 + f) / (1.0 - f)) ** 0.636, _POLISH_K)
    for _ in range(12):
        m = 1.0 - 1.0 / (k * k)
        f_k, df_dk = hertz_relation(k, float(ellipk(m)), float(ellipe(m)))
        step = (f_k - f) / df_dk
        k = k - step
        if not k > 1.0:
            return None
        if abs(step) <= 1e-15 * k:
            return k
    return None


@dataclass(frozen=True)
class ContactConstants:
    """Load-independent constants of one ball–groove contact (arrays broadcast together).

    The load-dependent quantities follow as a = a_coef·Q^(1/3), b = b_coef·Q^(1/3),
    δ = (Q/stiffness)^(2/3), p0 = 3Q/(2πab).

    Attributes
    ----------
    curvature_sum : Σρ [1/m]
    ellipticity : k = a/b [-]
    k_integral, e_integral : complete elliptic integrals K(m), E(m), m = 1 − 1/k² [-]
    a_coef, b_coef : semi-axis coefficients [m/N^(1/3)]
    stiffness : load–deflection constant K in Q = K·δ^1.5 [N/m^1.5]
    """

    curvature_sum: np.ndarray
    ellipticity: np.ndarray
    k_integral: np.ndarray
    e_integral: np.ndarray
    a_coef: np.ndarray
    b_coef: np.ndarray
    stiffness: np.ndarray

    def semi_axes(self, load):
        """(a, b) [m] for normal load ``load`` [N] ≥ 0."""
        q13 = np.cbrt(check_nonnegative("load", load, "N"))
        return self.a_coef * q13, self.b_coef * q13

    def deflection(self, load):
        """Normal approach δ [m] for load [N] ≥ 0."""
        return (check_nonnegative("load", load, "N") / self.stiffness) ** (2.0 / 3.0)

    def max_pressure(self, load):
        """Maximum Hertz pressure p0 = 3Q/(2πab) [Pa] (0 where the load is 0)."""
        a, b = self.semi_axes(load)
        with np.errstate(invalid="ignore", divide="ignore"):
            p = kernels.hertz_pressure(load, a * b)
        return np.where(load > 0, p, 0.0)


def contact_constants(curvature_sum, curvature_difference, compliance) -> ContactConstants:
    """Hertz constants of a point contact (Harris & Kotzalas 2007, ch. 6; Johnson 1985, ch. 4).

    Parameters
    ----------
    curvature_sum : Σρ [1/m], > 0
    curvature_difference : F(ρ) [-] in [0, 1)
    compliance : η = (1 − ν1²)/E1 + (1 − ν2²)/E2 [1/Pa], > 0

    a = (3k²·E·η·Q/(π·Σρ))^(1/3),  b = (3·E·η·Q/(π·k·Σρ))^(1/3),
    δ = (K/π)·(π/(2k²E))^(1/3)·(3ηQ/(2Σρ))^(2/3)·Σρ,
    with K, E the complete elliptic integrals of parameter m = 1 − 1/k².
    For k = 1 (E = K = π/2) these reduce to Hertz's sphere: a = (3QR/(4E*))^(1/3), δ = a²/R.

    Returns
    -------
    ContactConstants
        Σρ [1/m], k [-], K(m), E(m) [-], the semi-axis coefficients [m/N^(1/3)] and the
        load–deflection constant [N/m^1.5].

    Examples
    --------
    >>> c = contact_constants(9000.0, 0.9, 9.7e-12)
    >>> round(float(c.ellipticity), 4), round(float(c.stiffness) / 1e9, 4)  # -, GN/m^1.5
    (6.7133, 3.6549)
    """
    rho = check_positive("curvature_sum", curvature_sum, "1/m")
    eta = check_positive("compliance", compliance, "1/Pa")
    k = ellipticity(curvature_difference)
    return _constants(rho, k, eta)


def _constants(rho, k, eta) -> ContactConstants:
    m = 1.0 - 1.0 / k**2
    k_int = ellipk(m)
    e_int = ellipe(m)
    a_coef, b_coef, c_delta = kernels.hertz_coefficients(rho, k, k_int, e_int, eta)
    return ContactConstants(
        curvature_sum=rho,
        ellipticity=k,
        k_integral=k_int,
        e_integral=e_int,
        a_coef=a_coef,
        b_coef=b_coef,
        stiffness=c_delta**-1.5,
    )


def groove_contact(
    ball_diameter, pitch_diameter, groove_curvature, contact_angle, compliance, race
) -> ContactConstants:
    """Hertz constants of the ball–inner or ball–outer groove contact at contact angle α [rad].

    Combines :func:`curvature_sum_difference` and :func:`contact_constants`; all arguments
    broadcast (ball_diameter [m], pitch_diameter [m], groove_curvature [-], compliance [1/Pa]).

    Parameters
    ----------
    ball_diameter, pitch_diameter : float or array_like
        Dw, dm [m].
    groove_curvature : float or array_like
        f = r/Dw [-].
    contact_angle : float or array_like
        α [rad].
    compliance : float
        η [1/Pa] (:func:`~.materials.reduced_compliance`).
    race : {"inner", "outer"}

    Returns
    -------
    ContactConstants

    Examples
    --------
    >>> c = groove_contact(2.381e-3, 21.5e-3, 0.52, 0.26, 9.7e-12, "inner")
    >>> round(float(c.max_pressure(10.0)) / 1e6)  # MPa under a 10 N ball load
    1098
    """
    rho, f_rho = curvature_sum_difference(
        ball_diameter, pitch_diameter, groove_curvature, contact_angle, race
    )
    return contact_constants(rho, f_rho, compliance)


def combined_stiffness(k_inner, k_outer):
    """Load–deflection constant of the two contacts of one ball in series [N/m^1.5]:
    K_n = (K_i^(−2/3) + K_o^(−2/3))^(−3/2) (Harris & Kotzalas 2007, ch. 7).

    Parameters
    ----------
    k_inner, k_outer : float or array_like
        K_i, K_o [N/m^1.5].

    Returns
    -------
    float or ndarray
        K_n [N/m^1.5].

    Examples
    --------
    >>> round(float(combined_stiffness(1e10, 1e10)) / 1e9, 6)  # GN/m^1.5: 2^(−3/2) of one
    3.535534
    """
    check_positive("k_inner", k_inner, "N/m^1.5")
    check_positive("k_outer", k_outer, "N/m^1.5")
    return kernels.series_stiffness(k_inner ** (-2.0 / 3.0), k_outer ** (-2.0 / 3.0))


def hertz_load(stiffness, deflection):
    """Normal load Q = K·max(δ, 0)^1.5 [N] (Harris & Kotzalas 2007, ch. 7).

    Parameters
    ----------
    stiffness : float or array_like
        K [N/m^1.5].
    deflection : float or array_like
        δ [m].

    Returns
    -------
    float or ndarray
        Q [N] (0 where δ ≤ 0).

    Examples
    --------
    >>> round(float(hertz_load(1e10, 1e-6)), 9), float(hertz_load(1e10, -1e-6))  # N: K·δ^1.5
    (10.0, 0.0)
    """
    check_nonnegative("stiffness", stiffness, "N/m^1.5")
    check_range("deflection", deflection, unit="m")
    return kernels.hertz_load(stiffness, deflection)
