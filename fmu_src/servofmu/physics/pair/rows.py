# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The equations of a bearing pair in its arrangement, floats or arrays: the preload, the
axial play and the flags of a state, the loop closure at the parts' temperatures (Yu 2017
eq 14–15), and the equilibrium rows of a face-to-face or back-to-back pair in its loop or a
tandem pair under its thrust (:class:`PairRows`), with their Jacobian and Newton correction:
one residual per arrangement for the exact bracketing solves (:mod:`.preload`), the exact
Newton–Powell solve (:func:`.preload.pair_equilibrium`) and the continuation
(:mod:`.continuation`).

Examples
--------
>>> preload_force(60.0, 20.0)  # N
40.0
"""

import math

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython

if cython.compiled:
    from cython.cimports.servofmu.physics.kernels._elementary import maximum
else:
    from ..kernels.elementary import maximum

_INF: cython.double = math.inf
#: Arrangement of a pair (:class:`PairRows`): a face-to-face or back-to-back pair in a
#: compliant loop, the same in a rigid loop (its mean offset held at C/2), a tandem pair (its
#: offsets' half difference held at −d/2).
_LOOP: cython.int = 0
_RIGID: cython.int = 1
_TANDEM: cython.int = 2
# A Newton correction (PairRows.newton_step): a C struct compiled (declared in rows.pxd), a tuple
# uncompiled.
if not cython.compiled:
    Step = cython.typedef(
        tuple[cython.bint, cython.double, cython.double, cython.double, cython.double]
    )


@cython.ccall
def preload_force(force_a: cython.double, force_b: cython.double) -> cython.double:
    """The preload [N]: the mean axial force of the two bearings, (F_A + F_B)/2, the loop's
    compression (a tandem pair: half the thrust the set carries, the spring's or force's plus
    the external load), and 0 where that mean is not a compression (both bearings pushed onto
    the other flanks of their grooves, ``reverse_loaded``). Under an external load one bearing
    carries more than the preload, the other less; once one carries nothing (``unloaded``) the
    mean is half the load the other carries, and :func:`axial_play` says how far the shaft can
    move.

    Parameters
    ----------
    force_a, force_b : float or ndarray
        Axial forces of bearings A and B [N] (negative: on the other flanks).

    Returns
    -------
    float or ndarray
        [N], ≥ 0.

    Examples
    --------
    >>> preload_force(60.0, 20.0), preload_force(-10.0, -30.0)  # N
    (40.0, 0.0)
    """
    return maximum(0.5 * (force_a + force_b), 0.0)


@cython.ccall
def axial_play(
    first_contact_offset: cython.double,
    offset_a: cython.double,
    offset_b: cython.double,
    force_a: cython.double,
    force_b: cython.double,
) -> cython.double:
    """Axial play of the pair [m]: for each bearing that carries no axial load (F ≤ 0), the
    axial offset its groove centres lack to first contact, h − a (the balls' gap to the flanks
    that carry a preload); summed over the two bearings, 0 when both carry load. At zero
    external load it is how far the loop is short of closing on the two bearings, 2h − C (loop
    closure C); under a load, how far the shaft can move back before the unloaded bearing
    touches (its elastic deflections aside). Harris & Kotzalas 2007 ch. 2 (axial play 2h).

    Parameters
    ----------
    first_contact_offset : float or ndarray
        h [m] (:func:`.contact.geometry.first_contact_offset`).
    offset_a, offset_b : float or ndarray
        Axial offsets of bearings A and B [m].
    force_a, force_b : float or ndarray
        Their axial forces [N].

    Returns
    -------
    float or ndarray
        [m], ≥ 0.

    Examples
    --------
    >>> round(axial_play(60e-6, 40e-6, 40e-6, 0.0, 0.0) * 1e6, 9)  # µm: two 20 µm gaps
    40.0
    >>> axial_play(60e-6, 65e-6, 50e-6, 30.0, 10.0)  # both in contact
    0.0
    """
    h: cython.double = first_contact_offset
    return maximum(h - offset_a, 0.0) * (force_a <= 0.0) + maximum(h - offset_b, 0.0) * (
        force_b <= 0.0
    )


@cython.ccall
def pair_flags(
    pressure_limit: cython.double,
    clearance: cython.double,
    max_contact_pressure: cython.double,
    force_a: cython.double,
    force_b: cython.double,
) -> tuple[cython.bint, cython.bint, cython.bint, cython.bint]:
    """What the model knows about a state of the pair, as four flags (elementwise over
    arrays):

    - ``overloaded``: the largest Hertz pressure ``max_contact_pressure`` [Pa] reaches the
      pair's ``pressure_limit`` [Pa] (ISO 76: 4200 MPa, permanent deformation of the races);
    - ``locked``: no operating clearance is left (diametral ``clearance`` [m] ≤ 0: the balls
      are pinched between the rings already without axial offset, the contact angle has
      collapsed and the pair can no longer set its own contact angle);
    - ``unloaded``: the preload is lost: one bearing's axial force ``force_a``/``force_b`` [N]
      is zero or negative, so the shaft has axial play (with no external load: both are zero);
    - ``reverse_loaded``: a bearing's axial force is negative: its balls are pushed past the
      axial play onto the other flanks of its grooves (the loop pulled apart, or a tandem set
      under a load against its thrust larger than the thrust). The model takes the grooves as
      symmetric there (a deep-groove bearing); an angular-contact bearing has a low shoulder
      on that side and may not carry the load: its numbers are the symmetric groove's.

    Returns
    -------
    tuple
        (overloaded, locked, unloaded, reverse_loaded): bools, or boolean arrays.

    Examples
    --------
    >>> pair_flags(4.2e9, 2e-6, 1.5e9, 40.0, 0.0)  # Pa, m, Pa, N, N: B lost its load
    (False, False, True, False)
    """
    return (
        max_contact_pressure >= pressure_limit,
        clearance <= 0.0,
        (force_a <= 0.0) | (force_b <= 0.0),
        (force_a < 0.0) | (force_b < 0.0),
    )


@cython.ccall
def loop_closure_at(
    assembly: cython.double,
    housing: cython.double,
    shaft: cython.double,
    rings: cython.double,
    t0: cython.double,
    t_housing: cython.double,
    t_shaft: cython.double,
    t_rings: cython.double,
) -> cython.double:
    """The loop closure C = C0 − Σ_parts c_part·(T_part − T0) [m] (Yu 2017 eq 14–15; see
    :mod:`.pair.preload`) from the closure at assembly C0 [m] and the loop members' Σ σ·L·α of the
    housing, the shaft and the rings [m/K] (:func:`.pair.configuration.closure_coefficients`), at
    the temperatures of housing, shaft and rings (the rings' mean) [K] from T0 [K]. A tandem pair:
    B's mismatch d(T) along the thrust (C0 = 0). Floats or arrays.

    Returns
    -------
    float or ndarray
        C [m].

    Examples
    --------
    A frame 10 mm of aluminium (23e-6 /K, opening) 40 K colder closes the loop by 9.2 µm:

    >>> c = loop_closure_at(0.0, 10e-3 * 23e-6, 0.0, 0.0, 293.15, 253.15, 293.15, 293.15)
    >>> round(c * 1e6, 9)  # µm
    9.2
    """
    return assembly - (housing * (t_housing - t0) + shaft * (t_shaft - t0) + rings * (t_rings - t0))


# ------------------------------------------------------------------ the pair's equilibrium rows
@cython.final
@cython.cclass
class PairRows:
    """The equilibrium conditions of a pair in its arrangement, as residual rows over the
    unknowns x = (p, z, δr_A, δr_B) [m] (a_A = p + z, a_B = p − z the axial offsets of the
    bearings' groove curvature centres, δr the radial displacements), from the bearings'
    axial and radial forces F, Fr [N] and their Jacobians; floats or arrays.

    - r1, the axial balance [N]: F_A − F_B − F_ext for a face-to-face or back-to-back pair
      (Yu 2017 eq 14–17 with the external load), F_A + F_B + k_s·a_A − T − F_ext for a tandem
      pair under its preload spring k_s and thrust T (:func:`preload.tandem_offsets`);
    - r2, r3, the radial balances [N]: Fr_A − F_r/2, Fr_B − F_r/2 (the load midway);
    - r4 [m]: a pair in a compliant loop closes it, 2p + (F_A + F_B)/(2k) − C (loop closure C,
      stiffness k); a rigid loop holds 2p − C; a tandem pair holds 2z + d (B displaced by the
      mismatch d along the thrust).

    Parameters
    ----------
    tandem : bool
        A tandem pair.
    stiffness : float
        Loop stiffness k [N/m] (inf: rigid), or a tandem pair's spring k_s [N/m] (0: a
        constant force).
    thrust : float
        A tandem pair's thrust T [N] (0 otherwise).

    Examples
    --------
    A rigid loop under 3 N with bearings of 2 and 1 N/µm: dz = 1 µm (by hand 3 N / 3 N/µm):

    >>> rows = PairRows(False, float("inf"), 0.0)
    >>> ok, dp, dz, da, db = rows.newton_step(2e6, 0, 0, 1, 1e6, 0, 0, 1, -3.0, 0, 0, 0, False)
    >>> ok, dp, round(dz * 1e6, 9)
    (True, 0.0, 1.0)
    """

    kind: cython.int
    rigid: cython.bint
    tandem: cython.bint
    sign_b: cython.double
    spring: cython.double
    thrust: cython.double
    k_loop: cython.double
    __slots__ = ("k_loop", "kind", "rigid", "sign_b", "spring", "tandem", "thrust")

    def __init__(self, tandem: cython.bint, stiffness: cython.double, thrust: cython.double):
        if tandem:
            self.kind, self.sign_b, self.spring, self.thrust = _TANDEM, 1.0, stiffness, thrust
            self.k_loop = _INF
        else:
            self.kind = _RIGID if stiffness == _INF else _LOOP
            self.sign_b, self.spring, self.thrust, self.k_loop = -1.0, 0.0, 0.0, stiffness
        self.rigid, self.tandem = self.kind == _RIGID, self.kind == _TANDEM

    @property
    def is_tandem(self) -> bool:
        """A tandem pair."""
        return self.kind == _TANDEM

    @property
    def stiffness(self) -> float:
        """The loop's stiffness k [N/m] (inf: rigid), or a tandem pair's spring k_s [N/m]."""
        return self.spring if self.kind == _TANDEM else self.k_loop

    @property
    def held(self) -> str:
        """The unknown the rows hold fixed: "p" (rigid loop), "z" (tandem) or "" (none)."""
        return {_RIGID: "p", _TANDEM: "z"}.get(self.kind, "")

    @cython.ccall
    def residuals(
        self,
        fa_a: cython.double,
        fa_b: cython.double,
        fr_a: cython.double,
        fr_b: cython.double,
        p: cython.double,
        z: cython.double,
        closure: cython.double,
        f_ext: cython.double,
        f_r: cython.double,
    ) -> tuple[cython.double, cython.double, cython.double, cython.double]:
        """(r1, r2, r3 [N], r4 [m]) at the bearings' axial forces ``fa_a``, ``fa_b`` and
        radial forces ``fr_a``, ``fr_b`` [N], the unknowns p, z [m], the loop closure (a
        tandem pair: the mismatch d) [m] and the external loads [N]. Floats or arrays.

        Returns
        -------
        tuple
            (r1 [N], r2 [N], r3 [N], r4 [m]).

        Examples
        --------
        >>> rows = PairRows(True, 0.0, 40.0)  # a tandem pair under a constant 40 N
        >>> rows.residuals(20.0, 20.0, 0.0, 0.0, 1e-6, 0.0, 0.0, 0.0, 0.0)  # balanced
        (0.0, 0.0, 0.0, 0.0)
        """
        r1 = fa_a + self.sign_b * fa_b + self.spring * (p + z) - self.thrust - f_ext
        half = 0.5 * f_r
        if self.kind == _TANDEM:
            r4 = 2.0 * z + closure
        elif self.kind == _RIGID:
            r4 = 2.0 * p - closure
        else:
            r4 = 2.0 * p + 0.5 * (fa_a + fa_b) / self.k_loop - closure
        return r1, fr_a - half, fr_b - half, r4

    def jacobian(self, ja, jb):
        """d(r1, r2, r3, r4)/d(p, z, δr_A, δr_B) from the bearings' 2×2 Jacobians ``ja``,
        ``jb`` = ((dFa/da, dFa/dδr), (dFr/da, dFr/dδr)) [N/m].

        Returns
        -------
        list
            Four rows of four entries ([N/m] for r1–r3, [-] for r4).

        Examples
        --------
        >>> rows = PairRows(False, 2e7, 0.0)
        >>> rows.jacobian(((1e7, 0.0), (0.0, 1e7)), ((1e7, 0.0), (0.0, 1e7)))[0]
        [0.0, 20000000.0, 0.0, -0.0]
        """
        s, ks = self.sign_b, self.spring
        rows = [
            [ja[0][0] + ks + s * jb[0][0], ja[0][0] + ks - s * jb[0][0], ja[0][1], s * jb[0][1]],
            [ja[1][0], ja[1][0], ja[1][1], 0.0],
            [jb[1][0], -jb[1][0], 0.0, jb[1][1]],
        ]
        if self.kind == _TANDEM:
            rows.append([0.0, 2.0, 0.0, 0.0])
        elif self.kind == _RIGID:
            rows.append([2.0, 0.0, 0.0, 0.0])
        else:
            k2 = 0.5 / self.k_loop
            rows.append(
                [
                    2.0 + (ja[0][0] + jb[0][0]) * k2,
                    (ja[0][0] - jb[0][0]) * k2,
                    ja[0][1] * k2,
                    jb[0][1] * k2,
                ]
            )
        return rows

    @cython.ccall
    def newton_step(
        self,
        a11: cython.double,
        a12: cython.double,
        a21: cython.double,
        a22: cython.double,
        b11: cython.double,
        b12: cython.double,
        b21: cython.double,
        b22: cython.double,
        r1: cython.double,
        r2: cython.double,
        r3: cython.double,
        r4: cython.double,
        radial: cython.bint,
    ) -> Step:
        """Newton correction (ok, dp, dz, dδr_A, dδr_B) [m] from the bearings' Jacobians
        (``a11`` = dFa_A/da, ``a12`` = dFa_A/dδr, ``a21`` = dFr_A/da, ``a22`` = dFr_A/dδr
        [N/m], ``b..`` bearing B's) and the residuals of :meth:`residuals`. The radial rows
        hold one bearing each: dδr_A = (−r2 − dFr_A/da·u)/(dFr_A/dδr) with u, v the changes
        of a_A, a_B, which leaves a 2×2 system in (u, v) with e = dFa/da −
        (dFa/dδr)(dFr/da)/(dFr/dδr) each bearing's axial stiffness at balanced radial load:

            (e_A + k_s)·u + σ·e_B·v = −r1 + t_A·r2 + σ·t_B·r3   (σ = −1 in a loop, +1 tandem)

        and the loop row (1 + e_A/2k)·u + (1 + e_B/2k)·v = −r4 + (t_A·r2 + t_B·r3)/(2k), or
        u + v = −r4 (rigid loop), or v − u = r4 (tandem). ``ok`` is False when the system is
        singular (its determinant not positive: no stiffness).

        Returns
        -------
        tuple
            (ok, dp [m], dz [m], dδr_A [m], dδr_B [m]).

        Examples
        --------
        A tandem pair under axial load only: u = −r1/(e_A + e_B + k_s), by hand
        3 N / (3 N/µm) = 1 µm:

        >>> rows = PairRows(True, 0.0, 40.0)
        >>> ok, dp, dz, _, _ = rows.newton_step(2e6, 0, 0, 0, 1e6, 0, 0, 0, -3.0, 0, 0, 0, False)
        >>> ok, round(dp * 1e6, 9), dz
        (True, 1.0, 0.0)
        """
        s: cython.double = self.sign_b
        ta: cython.double = 0.0
        tb: cython.double = 0.0
        if radial:
            if a22 == 0.0 or b22 == 0.0:
                return False, 0.0, 0.0, 0.0, 0.0
            ta, tb = a12 / a22, b12 / b22
            a11, b11 = a11 - ta * a21, b11 - tb * b21
        m11: cython.double = a11 + self.spring
        m12: cython.double = s * b11
        g1: cython.double = -r1 + ta * r2 + s * tb * r3
        m21: cython.double
        m22: cython.double
        g2: cython.double
        if self.kind == _LOOP:
            k2 = 0.5 / self.k_loop
            m21, m22 = 1.0 + a11 * k2, 1.0 + b11 * k2
            g2 = -r4 + (ta * r2 + tb * r3) * k2
        elif self.kind == _RIGID:
            m21, m22, g2 = 1.0, 1.0, -r4
        else:
            m21, m22, g2 = -1.0, 1.0, r4
        det = m11 * m22 - m12 * m21
        if not det > 0.0:
            return False, 0.0, 0.0, 0.0, 0.0
        u = (g1 * m22 - m12 * g2) / det
        v = (m11 * g2 - m21 * g1) / det
        if radial:
            return True, 0.5 * (u + v), 0.5 * (u - v), (-r2 - a21 * u) / a22, (-r3 - b21 * v) / b22
        return True, 0.5 * (u + v), 0.5 * (u - v), 0.0, 0.0

    @cython.ccall
    def axial_stiffness(self, ka: cython.double, kb: cython.double) -> cython.double:
        """Axial stiffness of the shaft in the pair [N/m] from the bearings' dFa/da [N/m]:
        K = k_A + k_B − (k_A − k_B)²/(4k + k_A + k_B) in a loop of stiffness k (differentiating
        its two conditions; k_A + k_B when rigid), K = k_A + k_B + k_s for a tandem pair (its
        spring relaxing as the shaft moves along the thrust). Floats or arrays.

        Returns
        -------
        float or ndarray
            K [N/m].

        Examples
        --------
        >>> PairRows(False, 2e7, 0.0).axial_stiffness(1e7, 1e7)  # N/m: 2·k_b when symmetric
        20000000.0
        >>> PairRows(True, 1e5, 40.0).axial_stiffness(1.0e7, 1.2e7)  # N/m
        22100000.0
        """
        if self.kind == _TANDEM:
            return ka + kb + self.spring
        if self.kind == _RIGID:
            return ka + kb
        return ka + kb - (ka - kb) ** 2 / (4.0 * self.k_loop + ka + kb)
