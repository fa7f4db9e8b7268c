r"""Axial thermal coupling: preload of a bearing pair in a frame–shaft loop (Yu 2017 eq 14–17;
Ning §2.2).

The two bearings (A and B, face-to-face or back-to-back: identical for axial and radial
loads, tilt is not modelled; tandem below) sit in a closed loop of parts: "opening" members
(Yu: the frame of length L + 2·b0) whose growth relieves the preload, and "closing" members
(Yu: the shaft L and the two bearing widths; Ning: the bearings and the spacer) whose growth
increases it.

Compatibility (Yu eq 14–15 rewritten with the general geometry of :mod:`.contact.geometry`):

.. math::

   a_A + a_B + \frac{N}{k_\mathrm{loop}} = C(T), \qquad
   C(T) = 2\,h(T_0) + s - \sum_j \sigma_j L_j \alpha_j (T - T_0)

with :math:`a_A`, :math:`a_B` the axial offsets of the groove curvature centres of the two
bearings, :math:`h(T_0)` the first-contact offset at assembly, s the shim (Yu's washer δp: the
axial interference added after the play is taken up), :math:`\sigma_j = +1` for opening and −1
for closing members, :math:`N = (F_A + F_B)/2` the loop force and :math:`k_\mathrm{loop}` the
structural axial stiffness of the loop (Yu eq 15's 1/C1, by default Σ L/(E·A) of the members
with a section; a compliant yoke is modelled by setting it). Equilibrium adds
:math:`F_A - F_B = F_\mathrm{ext}`.

A tandem pair (both bearings facing the same way, :data:`ARRANGEMENTS`) has no such loop: a
spring or a constant force pushes the set, the two bearings share that thrust and the
external load, and the members between them only set how far B sits along the thrust
relative to A (:func:`tandem_offsets`, :func:`tandem_equilibrium`):

.. math::

   F_A(a_A) + F_B(a_A + d) + k_s\,a_A = T + F_\mathrm{ext}, \qquad
   d(T) = -\sum_j \sigma_j L_j \alpha_j (T_j - T_0).

Notes on the printed equations:

- Yu eq 14 assigns steel's expansion and modulus to the frame and aluminium's to the shaft,
  against the stated materials (cast-aluminium frame, 45-steel shaft). Both readings are
  offered as data (mountings ``yu2017_gimbal`` and ``yu2017_gimbal_printed``); the stated
  reading also lets the steel bearing widths 2·b0 grow, which eq 14 leaves out.
- Yu eq 16–17 (Harris's thrust relation in terms of the free contact angle) are singular once
  the clearance is negative; the general geometry (:func:`.contact.equilibrium.axial_state`)
  replaces them and reduces to them for positive clearance.
- Yu's Pe (axial play) and δp: read literally, eq 14 with Pe = 2·h (≈ 96 µm for the mounted
  71803) would leave a 0.03 mm washer without any preload; the washer is read here as the
  interference added after the play is taken up at assembly.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, root
from scipy.optimize.elementwise import bracket_root, find_root

from .._checks import (
    check_choice,
    check_finite,
    check_nonnegative,
    check_positive,
    check_temperature,
)
from ..contact.equilibrium import (
    _geometry_args,
    _geometry_from_args,
    axial_force,
    offset_for_axial_force,
)
from ..contact.geometry import RaceGeometry
from ..materials import Material
from ..thermal.temperatures import MEMBER_PARTS, part_temperatures
from .rows import PairRows

ROLES = {"opening": 1.0, "closing": -1.0}
#: The part whose temperature a loop member takes, by member name, when the data do not say.
DEFAULT_PARTS = {
    "frame": "housing",
    "housing": "housing",
    "shaft": "shaft",
    "spacer": "shaft",
    "bearings": "rings",
}


@dataclass(frozen=True)
class LoopMember:
    """One part of the preload loop.

    Attributes
    ----------
    name : e.g. "frame", "shaft", "bearings", "spacer"
    role : "opening" (growth relieves the preload) or "closing"
    length : axial length L [m]
    material : its :class:`Material`
    area : cross-section A [m²] for the loop compliance L/(E·A); None: not counted
    part : whose temperature it takes (:data:`~.thermal.temperatures.MEMBER_PARTS`): "housing",
        "shaft" or "rings"; None: from the name (frame/housing → housing, shaft and spacer →
        shaft, bearings → rings)
    """

    name: str
    role: str
    length: float
    material: Material
    area: float | None = None
    part: str | None = None

    def __post_init__(self):
        check_choice("role", self.role, ROLES)
        if self.part is None:
            object.__setattr__(self, "part", DEFAULT_PARTS.get(self.name, "rings"))
        check_choice("part", self.part, MEMBER_PARTS)
        check_positive("length", self.length, "m")
        if self.area is not None:
            check_positive("area", self.area, "m²")


@dataclass(frozen=True)
class YokeArm:
    """A cantilever arm of a yoke (fork) frame that holds one bearing at its tip: the preload
    bends it along the shaft axis.

    Attributes
    ----------
    name : e.g. "arm"
    length : L from the arm's root to the bearing centre [m]
    width : section width b, across the bending plane [m]
    thickness : section depth h, in the bending direction (along the shaft) [m]
    material : its :class:`Material`
    count : how many such arms the loop passes through (a yoke: 2)
    """

    name: str
    length: float
    width: float
    thickness: float
    material: Material
    count: int = 1

    def __post_init__(self):
        check_positive("arm length", self.length, "m")
        check_positive("arm width", self.width, "m")
        check_positive("arm thickness", self.thickness, "m")
        if not (isinstance(self.count, int) and self.count >= 1):
            raise ValueError(f"arm count = {self.count!r} must be an integer >= 1")

    @property
    def compliance(self) -> float:
        """Axial compliance of the arms at their tips [m/N]: count·L³/(3·E·I), I = b·h³/12
        (Euler–Bernoulli cantilever under a tip load; Roark's Formulas for Stress and Strain,
        7th ed., Table 8.1 case 1a).

        >>> from servofmu.parameters.catalog import material
        >>> arm = YokeArm("arm", 0.040, 0.036, 0.006, material("cast_aluminium"), count=2)
        >>> round(1.0 / arm.compliance / 1e6, 2)  # N/µm: the two arms in series
        1.09
        """
        second_moment = self.width * self.thickness**3 / 12.0
        e = self.material.youngs_modulus
        return self.count * self.length**3 / (3.0 * e * second_moment)


#: How the structure of a preload loop is compliant: the members' axial E·A/L (a tube-like
#: frame), or a yoke whose arms bend (the frame's members then count for their thermal growth
#: only; the shaft and the other members with a section stay in series).
LOOP_MODELS = ("members", "yoke")


@dataclass(frozen=True)
class PreloadLoop:
    """The preload loop of a bearing pair.

    Attributes
    ----------
    members : the parts (their thermal growth closes or opens the loop)
    shim : axial interference added after the play is taken up at assembly [m] (Yu's δp)
    stiffness : structural axial stiffness of the loop [N/m]; None: from the model
    model : :data:`LOOP_MODELS`: "members" (Σ L/(E·A)) or "yoke" (the arms bend)
    arms : the :class:`YokeArm` s of a yoke
    spring_stiffness : a preload spring in series with the structure [N/m]; None: no spring
    spring_compression : the spring's compression at assembly [m] (its force k·c is the
        assembly preload); None: no spring
    provenance : ((field, source), ...)
    """

    members: tuple[LoopMember, ...]
    shim: float = 0.0
    stiffness: float | None = None
    model: str = "members"
    arms: tuple[YokeArm, ...] = ()
    spring_stiffness: float | None = None
    spring_compression: float | None = None
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_finite("shim", self.shim, "m")
        check_choice("loop model", self.model, LOOP_MODELS)
        if self.stiffness is not None:
            check_positive("stiffness", self.stiffness, "N/m")
        if self.model == "yoke" and not self.arms:
            raise ValueError("loop model = 'yoke' needs at least one arm")
        if self.spring_stiffness is not None:
            check_positive("spring_stiffness", self.spring_stiffness, "N/m")
        if (self.spring_compression is None) != (self.spring_stiffness is None):
            raise ValueError(
                f"a preload spring needs both spring_stiffness = {self.spring_stiffness!r} N/m "
                f"and spring_compression = {self.spring_compression!r} m"
            )
        if self.spring_compression is not None:
            check_positive("spring_compression", self.spring_compression, "m")

    @property
    def frame_stiffness(self) -> float:
        """Stiffness of the structure [N/m]: the override, else 1/(Σ L/(E·A) of the members
        with a section + Σ arm compliances) (Yu eq 15's C1; in a yoke the frame's own members
        do not count, its arms do); inf when nothing is compliant (a rigid loop)."""
        if self.stiffness is not None:
            return self.stiffness
        yoke = self.model == "yoke"
        compliance = sum(
            m.length / (m.material.youngs_modulus * m.area)
            for m in self.members
            if m.area and not (yoke and m.part == "housing")
        )
        compliance += sum(a.compliance for a in self.arms) if yoke else 0.0
        return 1.0 / compliance if compliance > 0 else np.inf

    @property
    def structural_stiffness(self) -> float:
        """k_loop [N/m]: the structure (:attr:`frame_stiffness`) in series with the preload
        spring, if any."""
        k = self.frame_stiffness
        if self.spring_stiffness is None:
            return k
        return 1.0 / (1.0 / k + 1.0 / self.spring_stiffness)


#: How the two bearings of the pair face each other, and with it which parts of the loop
#: relieve the preload when they grow (role "opening") and which increase it ("closing").
#: Members are of four kinds: the housing (frame) between the pair's outer-ring abutments,
#: the shaft between its inner-ring abutments, a spacer between the bearings, and the rings'
#: own widths (:func:`member_kind`).
#:
#: - face_to_face (DF, "X": the contact lines converge outside the pair): the housing holds
#:   the outer rings from outside and is stretched by the preload; the shaft, the spacer and
#:   the rings in between are compressed. A growing housing relieves the preload, a growing
#:   shaft increases it (Yu 2017 eq 14: frame (L + 2·b0) against shaft L and the two widths).
#: - back_to_back (DB, "O"): the shaft clamps the inner rings from outside (shoulder and nut)
#:   and is stretched; the outer stack (rings, spacer, housing between the outer rings) is
#:   compressed. A growing shaft relieves the preload, a growing housing increases it
#:   (Ning's space shaft).
#:
#: - tandem (DT): both bearings face the same way and share one thrust; they cannot preload
#:   each other. The preload is a force on the set (a spring, or a constant force: the
#:   ``assembly_preload``), so the loop between the two bearings does not close on them: its
#:   members set how far bearing B is displaced along the thrust relative to A,
#:   a_B − a_A = −Σ σ_j·L_j·α_j·(T_j − T0) (:func:`tandem_offsets`; a matched set, so 0 at
#:   assembly). The inner path (shaft,
#:   an inner spacer) is "closing": its growth moves B's inner ring further along the thrust
#:   than A's, so B (the bearing further along the thrust) takes more of it; the housing (and
#:   an outer spacer, entered as housing length) is "opening". The rings' widths lie in both
#:   paths and cancel, so a tandem loop has no "bearings" member.
#:
#: So the shaft's axial growth relative to the housing raises the preload of a face-to-face
#: pair and lowers that of a back-to-back pair (SKF, "Angular contact ball bearings: bearing
#: arrangements"; Harris & Kotzalas 2007, *Advanced Concepts*, ch. 1 on preloading): with the
#: same parts and temperatures the thermal terms of the shaft and the housing change sign
#: between the two (tests/physics/test_preload.py). In a tandem pair it leaves the thrust alone and
#: shifts it between the bearings (tests/physics/test_tandem.py). The radial effects (fits, ring
#: growth) are the same in all three.
ARRANGEMENTS = {
    "face_to_face": {"housing": "opening", "shaft": "closing", "spacer": "closing",
                     "bearings": "closing"},
    "back_to_back": {"housing": "closing", "shaft": "opening", "spacer": "closing",
                     "bearings": "closing"},
    "tandem": {"housing": "opening", "shaft": "closing", "spacer": "closing"},
}  # fmt: skip
#: The arrangement whose bearings share a thrust instead of preloading each other.
TANDEM = "tandem"
#: Member kind by member name.
MEMBER_KINDS = {"frame": "housing", "housing": "housing", "shaft": "shaft", "spacer": "spacer",
                "bearings": "bearings"}  # fmt: skip


def member_kind(name: str) -> str:
    """The kind of a loop member ("housing", "shaft", "spacer", "bearings") from its name
    (frame and housing are the housing); ValueError for another name.

    Returns
    -------
    str
        "housing", "shaft", "spacer" or "bearings".

    >>> member_kind("frame")
    'housing'
    """
    if name not in MEMBER_KINDS:
        raise ValueError(f"loop member name = {name!r} is not one of {sorted(MEMBER_KINDS)}")
    return MEMBER_KINDS[name]


def member_role(name: str, arrangement: str) -> str:
    """The role ("opening" or "closing") of loop member ``name`` in a pair of
    ``arrangement`` (:data:`ARRANGEMENTS`).

    Returns
    -------
    str
        "opening" or "closing".

    >>> member_role("shaft", "face_to_face"), member_role("shaft", "back_to_back")
    ('closing', 'opening')
    """
    check_choice("arrangement", arrangement, ARRANGEMENTS)
    kind = member_kind(name)
    if kind not in ARRANGEMENTS[arrangement]:
        raise ValueError(
            f"a {arrangement} pair has no loop member of kind {kind!r} (the rings' widths lie "
            "in both paths between its bearings and cancel)"
        )
    return ARRANGEMENTS[arrangement][kind]


def arrangement_problems(loop: PreloadLoop, arrangement: str) -> list[str]:
    """Every member of ``loop`` whose role contradicts ``arrangement``, or that a tandem pair
    cannot have (empty: none).

    Parameters
    ----------
    loop : PreloadLoop
        The loop and its members.
    arrangement : str
        A key of :data:`ARRANGEMENTS`.

    Returns
    -------
    list of str
        One message per member in the wrong role or not allowed.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> loop = catalog.mounting("yu2017_gimbal_rigid").loop
    >>> arrangement_problems(loop, "face_to_face")
    []
    >>> arrangement_problems(loop, "back_to_back")[0]
    "loop member 'frame' has role 'opening', but in a back_to_back pair it is 'closing'"
    """
    check_choice("arrangement", arrangement, ARRANGEMENTS)
    found = []
    for m in loop.members:
        if m.name not in MEMBER_KINDS:
            continue
        if member_kind(m.name) not in ARRANGEMENTS[arrangement]:
            found.append(
                f"loop member {m.name!r} cannot be in a {arrangement} pair (the rings' widths "
                "lie in both paths between its bearings and cancel)"
            )
        elif m.role != member_role(m.name, arrangement):
            found.append(
                f"loop member {m.name!r} has role {m.role!r}, but in a {arrangement} pair it "
                f"is {member_role(m.name, arrangement)!r}"
            )
    return found


#: Smallest loop stiffness [N/m] accepted: below it the loop carries no preload worth the
#: name, and the compatibility residual F/k overflows (5e-324 N/m did, in the FMU fuzzing).
SMALLEST_LOOP_STIFFNESS = 1.0


def check_loop_stiffness(value) -> float:
    """Loop stiffness [N/m]: ≥ 1 N/m, with +inf meaning a rigid loop.

    Parameters
    ----------
    value : float
        k_loop [N/m].

    Returns
    -------
    float
        ``value``; ValueError below 1 N/m or for nan.

    Examples
    --------
    >>> check_loop_stiffness(2.5e7)
    25000000.0
    >>> check_loop_stiffness(float("inf"))  # rigid
    inf
    """
    k = float(value)
    if not k >= SMALLEST_LOOP_STIFFNESS:
        raise ValueError(
            f"loop_stiffness = {k!r} N/m is outside the valid range "
            f"[{SMALLEST_LOOP_STIFFNESS:g}, inf]"
        )
    return k


def loop_interference(loop: PreloadLoop, temperature, assembly_temperature: float):
    """Axial interference of the loop [m]: s − Σ_j σ_j·L_j·α_j·(T_j − T0) (Yu 2017 eq 14–15,
    the thermal part C2 − 2·b0 with sign), each member j at the temperature T_j of its part.

    Parameters
    ----------
    loop : the :class:`PreloadLoop`
    temperature : uniform T [K] (float or array) or a
        :class:`~.thermal.temperatures.PartTemperatures`
    assembly_temperature : T0 [K]

    Returns
    -------
    float or ndarray
        The interference [m] (positive: the loop squeezes the pair).

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> loop = catalog.mounting("yu2017_gimbal_rigid").loop
    >>> cold = loop_interference(loop, 253.15, 293.15)
    >>> round(float(cold - loop.shim) * 1e6, 3)  # µm: 40 K colder, the frame shrinks most
    47.2
    """
    temps = part_temperatures(temperature)
    t0 = check_temperature("assembly_temperature", assembly_temperature)
    growth = 0.0
    for m in loop.members:
        dt = np.asarray(temps.of(m.part)) - t0
        growth = growth + ROLES[m.role] * m.length * m.material.expansion * dt
    return loop.shim - growth


def _axial_rows(rows: PairRows, p, z, closure, load, geom):
    """(r1 [N], r4 [m]) of the arrangement's rows (:meth:`PairRows.residuals`) at the mean
    offset ``p`` and shaft displacement ``z`` [m] without radial load: the residuals of the
    bracketing solves below (floats or arrays)."""
    r1, _, _, r4 = rows.residuals(
        axial_force(p + z, geom), axial_force(p - z, geom), 0.0, 0.0, p, z, closure, load, 0.0
    )
    return r1, r4


def _pair_residual(p, z, closure, k_loop, geom):
    """The loop's row r4 [m] of a face-to-face or back-to-back pair: 2p + (F_A + F_B)/(2k) − C."""
    return _axial_rows(PairRows(False, k_loop, 0.0), p, z, closure, 0.0, geom)[1]


def mean_offset(z, closure, k_loop, geom: RaceGeometry):
    """Mean offset p [m] of the pair (a_A = p + z, a_B = p − z) that satisfies the loop
    compatibility for shaft displacement z [m] (elementwise bracketing root), for loop closure
    ``closure`` [m] and loop stiffness ``k_loop`` [N/m] (inf: rigid).

    Returns
    -------
    float or ndarray
        p [m].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> c = 2 * float(g.first_contact_offset) + 30e-6  # m: 30 µm of interference
    >>> p = float(mean_offset(0.0, c, float("inf"), g))
    >>> round(p * 1e6, 6) == round(c / 2 * 1e6, 6)  # a rigid loop: p = C/2
    True
    """
    z = check_finite("z", z, "m")
    closure = check_finite("closure", closure, "m")
    k_loop = check_loop_stiffness(k_loop)
    z, closure = np.broadcast_arrays(np.asarray(z, float), np.asarray(closure, float))
    if np.isinf(k_loop):
        return 0.5 * closure
    # The residual 2p + (F(p+z) + F(p−z))/(2k) − C rises with p (F is odd and non-decreasing),
    # and is < 0 at lo and > 0 at hi below: both offsets ≤ 0 at lo, ≥ 0 at hi.
    span = np.abs(z) + 1e-12
    lo = np.minimum(0.0, 0.5 * closure) - span
    hi = np.maximum(0.0, 0.5 * closure) + span
    if z.shape == () and np.ndim(geom.clearance) == 0:  # one state: scalar Brent (per-step path)
        zz, cc = float(z), float(closure)
        return np.asarray(
            brentq(
                lambda p: float(_pair_residual(p, zz, cc, k_loop, geom)),
                float(lo),
                float(hi),
                xtol=1e-16,
            )
        )
    shape = z.shape
    args = _geometry_args(geom, shape)

    def residual(p, zz, cc, *g):
        return _pair_residual(
            p, zz, cc, k_loop, _geometry_from_args(g, geom.n_balls, geom.compliance)
        )

    br = bracket_root(residual, lo, hi, args=(z, closure, *args))
    return find_root(residual, br.bracket, args=(z, closure, *args), tolerances={"xatol": 1e-16}).x


@dataclass(frozen=True)
class PairOffsets:
    """Axial state of the pair (arrays).

    Attributes
    ----------
    offset_a, offset_b : axial offsets of bearings A and B [m]
    force_a, force_b : their axial forces [N]
    loop_force : N = (F_A + F_B)/2 [N] (the preload)
    """

    offset_a: np.ndarray
    offset_b: np.ndarray
    force_a: np.ndarray
    force_b: np.ndarray

    @property
    def loop_force(self):
        return 0.5 * (self.force_a + self.force_b)


def pair_offsets(geom: RaceGeometry, closure, loop_stiffness: float, external_load=0.0):
    """Offsets and forces of the pair under an axial load F_ext [N] on the shaft (pressing
    bearing A), for loop closure C [m] and loop stiffness k [N/m] (elementwise over arrays).

    Solves F_A − F_B = F_ext and a_A + a_B + (F_A + F_B)/(2k) = C with a_A = p + z,
    a_B = p − z: an outer bracketing root in z around an inner one in p (both monotonic,
    scipy.optimize.elementwise.find_root), so it cannot fail to converge. Yu 2017 eq 14–17
    with the general geometry; returns :class:`PairOffsets`.

    Returns
    -------
    PairOffsets
        offset_a, offset_b [m]; force_a, force_b [N]; loop_force [N].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> c = 2 * float(g.first_contact_offset) + 30e-6
    >>> o = pair_offsets(g, c, 2e7, external_load=10.0)
    >>> round(float(o.force_a - o.force_b), 9), round(float(o.loop_force), 3)  # N
    (10.0, 112.522)
    """
    c = np.asarray(check_finite("closure", closure, "m"), dtype=float)
    f_ext = np.asarray(check_finite("external_load", external_load, "N"), dtype=float)
    k = check_loop_stiffness(loop_stiffness)
    shape = np.broadcast_shapes(c.shape, f_ext.shape, np.shape(geom.clearance))
    c, f_ext = np.broadcast_to(c, shape), np.broadcast_to(f_ext, shape)
    args = _geometry_args(geom, shape)

    rows = PairRows(False, k, 0.0)

    def residual(z, ff, cc, *g):  # the rows' r1, F_A − F_B − F_ext, at p(z) of the loop's row
        gg = _geometry_from_args(g, geom.n_balls, geom.compliance)
        return _axial_rows(rows, mean_offset(z, cc, k, gg), z, cc, ff, gg)[0]

    z = np.zeros(shape)
    loaded = f_ext != 0
    if loaded.any():
        flat = (f_ext[loaded], c[loaded], *(a[loaded] for a in args))
        step = 0.01 * np.broadcast_to(geom.curvature_distance, shape)[loaded]
        lo = np.where(flat[0] > 0, 0.0, -step)
        hi = np.where(flat[0] > 0, step, 0.0)
        br = bracket_root(residual, lo, hi, args=flat)
        z[loaded] = find_root(residual, br.bracket, args=flat, tolerances={"xatol": 1e-16}).x
    p = mean_offset(z, c, k, geom)
    a_a, a_b = p + z, p - z
    return PairOffsets(a_a, a_b, axial_force(a_a, geom), axial_force(a_b, geom))


def axial_offsets(geom: RaceGeometry, rows, closure, external_load=0.0) -> PairOffsets:
    """Offsets and forces of the pair under an axial load F_ext [N] in its arrangement
    (elementwise over arrays): :func:`pair_offsets` for a face-to-face or back-to-back pair in
    its loop, :func:`tandem_offsets` for a tandem pair, from the arrangement's rows
    (:class:`~.pair.continuation.PairRows`).

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry.
    rows : PairRows
        The arrangement (:func:`.pair.configuration.pair_rows`).
    closure : float or array_like
        Loop closure C [m] (a tandem pair: the mismatch d [m]).
    external_load : float or array_like
        F_ext [N].

    Returns
    -------
    PairOffsets
        offset_a, offset_b [m]; force_a, force_b [N]; loop_force [N].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> o = axial_offsets(g, PairRows(True, 0.0, 40.0), 0.0)
    >>> round(float(o.force_a), 6), round(float(o.force_b), 6)  # a tandem set: equal shares, N
    (20.0, 20.0)
    """
    if rows.is_tandem:
        return tandem_offsets(geom, closure, rows.spring, rows.thrust, external_load)
    return pair_offsets(geom, closure, rows.k_loop, external_load)


def pair_axial_stiffness(stiffness_a, stiffness_b, loop_stiffness: float):
    """Axial stiffness of the shaft in the pair [N/m] from the bearings' dFa/da [N/m] and the
    loop stiffness k [N/m]: K = k_A + k_B − (k_A − k_B)²/(4k + k_A + k_B) (differentiating the
    two conditions of :func:`pair_offsets`); 2·k_b for a symmetric pair.

    Returns
    -------
    float or ndarray
        K [N/m].

    Examples
    --------
    >>> float(pair_axial_stiffness(1e7, 1e7, 2e7))  # N/m: 2·k_b when symmetric
    20000000.0
    >>> round(float(pair_axial_stiffness(1.5e7, 0.5e7, float("inf"))))  # N/m: k_A + k_B
    20000000
    """
    ka = np.asarray(check_nonnegative("stiffness_a", stiffness_a, "N/m"))
    kb = np.asarray(check_nonnegative("stiffness_b", stiffness_b, "N/m"))
    return PairRows(False, check_loop_stiffness(loop_stiffness), 0.0).axial_stiffness(ka, kb)


def shim_for_preload(geom_assembly: RaceGeometry, preload: float, loop_stiffness: float) -> float:
    """Shim s [m] that gives the preload ``preload`` [N] at assembly (inverse of the loop
    compatibility at T0): s = 2·a(P) + P/k − 2·h(T0), a(P) the offset carrying P.

    Returns
    -------
    float
        s [m].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> s = shim_for_preload(g, 50.0, float("inf"))
    >>> o = pair_offsets(g, 2 * float(g.first_contact_offset) + s, float("inf"))
    >>> round(float(o.loop_force), 9)  # N: the shim gives the preload back
    50.0
    """
    p_force = check_positive("preload", preload, "N")
    loop_stiffness = check_loop_stiffness(loop_stiffness)
    a = float(offset_for_axial_force(geom_assembly, p_force))
    h = float(geom_assembly.first_contact_offset)
    loop_term = 0.0 if np.isinf(loop_stiffness) else p_force / loop_stiffness
    return 2.0 * a + loop_term - 2.0 * h


@dataclass(frozen=True)
class PairState:
    """Pair under combined axial and radial load (scalar; see :func:`pair_equilibrium`).

    Attributes
    ----------
    offset_a, offset_b : axial offsets [m]
    radial_a, radial_b : radial displacements of the shaft in A and B [m]
    balls_a, balls_b : per-ball :class:`equilibrium.BallLoads`
    converged : force balance met to a relative 1e-9
    """

    offset_a: float
    offset_b: float
    radial_a: float
    radial_b: float
    balls_a: object
    balls_b: object
    converged: bool


def pair_equilibrium(geom: RaceGeometry, closure: float, rows, axial_load: float,
                     radial_load: float) -> PairState:  # fmt: skip
    """Equilibrium of the pair under an axial load F_ext [N] (pressing bearing A; a tandem
    pair: along its thrust) and a radial load F_r [N] shared equally by A and B (load midway
    between them; the tilt of each bearing is neglected, the span being long against the ball
    set). Scalar geometry; every arrangement.

    Unknowns: mean offset p and shaft displacement z (a_A = p + z, a_B = p − z), radial
    displacements δr_A, δr_B; the conditions are the arrangement's rows
    (:class:`~.pair.continuation.PairRows`: F_A − F_B = F_ext and the loop compatibility of
    :func:`pair_offsets` for a pair in its loop, p = C/2 held in a rigid one; F_A + F_B +
    k_s·a_A = T + F_ext with z = −d/2 held for a tandem pair, :func:`tandem_offsets`) and
    Fr_A = Fr_B = F_r/2. Newton–Powell (scipy.optimize.root, hybr) with the analytic
    stiffness, started from the axial solution (:func:`axial_offsets`). Jones (1960) ball
    loads per bearing.

    Parameters
    ----------
    geom : RaceGeometry
        Operating geometry (scalar fields).
    closure : float
        Loop closure C [m] (a tandem pair: the mismatch d [m]).
    rows : PairRows or float
        The arrangement's rows, or the loop stiffness k [N/m] of a face-to-face or
        back-to-back pair (inf: rigid).
    axial_load, radial_load : float
        F_ext, F_r [N].

    Returns
    -------
    PairState
        Offsets and radial displacements [m], the per-ball loads, and whether the force
        balance was met to a relative 1e-9.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> c = 2 * float(g.first_contact_offset) + 30e-6
    >>> st = pair_equilibrium(g, c, 2e7, 5.0, 20.0)
    >>> fa, fb = float(st.balls_a.axial_force[0]), float(st.balls_b.axial_force[0])
    >>> st.converged, round(fa - fb, 9), round(float(st.balls_a.radial_force[0]), 9)  # N
    (True, 5.0, 10.0)
    """
    from ..contact.equilibrium import _ball_loads, _ring_stiffness

    f_ext = check_finite("axial_load", axial_load, "N")
    f_r = check_finite("radial_load", radial_load, "N")
    closure = check_finite("closure", closure, "m")
    if not isinstance(rows, PairRows):
        rows = PairRows(False, check_loop_stiffness(rows), 0.0)
    start = axial_offsets(geom, rows, closure, f_ext)
    a_len = float(geom.curvature_distance)
    a0, b0 = float(start.offset_a[()]), float(start.offset_b[()])
    scale = max(abs(rows.thrust + f_ext), abs(f_r), float(start.loop_force), 1e-3)
    zero = np.zeros(1)
    # the free unknowns of (p, z, δr_A, δr_B) and the rows that hold the others (r4 counts as
    # a force, k·r4, in a compliant loop)
    held = rows.held
    free = [i for i, name in enumerate("pz") if name != held] + [2, 3]
    r4_force = rows.held == ""
    fixed = {"p": 0.5 * closure, "z": -0.5 * closure}.get(held)

    def loads(p, z, da, db):
        la = _ball_loads(geom, np.atleast_1d(p + z)[:, None], np.atleast_1d(da)[:, None], zero)
        lb = _ball_loads(geom, np.atleast_1d(p - z)[:, None], np.atleast_1d(db)[:, None], zero)
        return la, lb

    def unpack(x):
        full = [0.0, 0.0, 0.0, 0.0]
        for i, v in zip(free, x * a_len, strict=True):
            full[i] = float(v)
        if held == "p":
            full[0] = fixed
        elif held == "z":
            full[1] = fixed
        return full

    def fun(x):
        p, z, da, db = unpack(x)
        la, lb = loads(p, z, da, db)
        ja, jb = _ring_stiffness(geom, la)[0], _ring_stiffness(geom, lb)[0]
        r = rows.residuals(
            la.axial_force[0], lb.axial_force[0], la.radial_force[0], lb.radial_force[0],
            p, z, closure, f_ext, f_r,
        )  # fmt: skip
        jac = rows.jacobian(((ja[0, 0], ja[0, 1]), (ja[1, 0], ja[1, 1])),
                            ((jb[0, 0], jb[0, 1]), (jb[1, 0], jb[1, 1])))  # fmt: skip
        if r4_force:  # the loop's row as a force, k·r4
            res, jac = [*r[:3], rows.k_loop * r[3]], [*jac[:3], [rows.k_loop * v for v in jac[3]]]
        else:
            res, jac = list(r[:3]), jac[:3]
        jac = np.array(jac)[:, free] * a_len
        return np.array(res, dtype=float) / scale, jac / scale

    x0 = (
        np.array(
            [(0.5 * (a0 + b0), 0.5 * (a0 - b0))[i] for i in free[:-2]]
            + [_radial_start(geom, a0, f_r), _radial_start(geom, b0, f_r)]
        )
        / a_len
    )
    x, resid = _best_root(fun, x0)
    p, z, da, db = unpack(x)
    la, lb = loads(p, z, da, db)
    return PairState(p + z, p - z, da, db, la, lb, resid < 1e-9)


def _radial_start(geom: RaceGeometry, offset: float, radial_load: float) -> float:
    """Start δr [m] of a bearing at axial offset ``offset`` [m] carrying half of
    ``radial_load`` [N]: from its radial stiffness there, or half the clearance without
    contact."""
    from ..contact.equilibrium import _ball_loads, _ring_stiffness

    zero = np.zeros(1)
    balls = _ball_loads(geom, np.atleast_1d(offset)[:, None], zero[:, None], zero)
    krr = float(_ring_stiffness(geom, balls)[0, 1, 1])
    if krr > 0:
        return 0.5 * radial_load / krr
    return np.sign(radial_load) * 0.5 * max(float(geom.clearance), 0.0)


def _best_root(fun, x0):
    """(x, largest scaled residual) of scipy.optimize.root on ``fun`` (residuals and their
    Jacobian) from ``x0``: Powell's hybrid method, then Levenberg–Marquardt when it misses;
    then Newton's steps with the analytic Jacobian while they shrink the residual (hybr's
    relative xtol can stop where lightly loaded balls leave a soft direction with a residual
    of 1e-10 N; the polish takes it to rounding, as the per-step path does)."""
    best = None
    for method in ("hybr", "lm"):
        sol = root(fun, x0, jac=True, method=method, options={"xtol": 1e-14})
        resid = float(np.abs(fun(sol.x)[0]).max())
        if best is None or resid < best[1]:
            best = (sol.x, resid)
        if resid < 1e-9:
            break
    return _polish(fun, *best)


def _polish(fun, x, resid, steps: int = 4):
    """Newton's steps from ``x`` (largest scaled residual ``resid``) while each lowers it."""
    for _ in range(steps):
        r, jac = fun(x)
        try:
            dx = np.linalg.solve(jac, r)
        except np.linalg.LinAlgError:
            break
        trial = x - dx
        new = float(np.abs(fun(trial)[0]).max())
        if not new < resid:
            break
        x, resid = trial, new
    return x, resid


def tandem_offsets(
    geom: RaceGeometry, mismatch, spring_stiffness: float, thrust, external_load=0.0
) -> PairOffsets:
    """Offsets and forces of a tandem pair (:data:`TANDEM`: both bearings face the same way)
    under its preload and an axial load F_ext [N] along its thrust (elementwise over arrays).

    The set is pushed by a preload spring of stiffness k_s [N/m] (0: a constant force) whose
    force is P = T − k_s·a_A, with ``thrust`` T = k_s·(c + a_A0) [N] fixed at assembly (c the
    spring's compression, a_A0 the assembly offset; T = P for a constant force). Bearing B is
    displaced along the thrust by the ``mismatch`` d [m] relative to A (−Σ σ·L·α·ΔT of the
    members between them, :func:`loop_interference`); the spacers between the bearings are
    taken as rigid against the bearings. Unknown a = a_A, with a_B = a + d:

        F(a) + F(a + d) + k_s·a = T + F_ext

    rises with a (F non-decreasing), so a bracketing root cannot fail (scipy.optimize
    .elementwise.find_root). Jones (1960) / Harris & Kotzalas (2007) for F; the load sharing
    of a tandem set is the textbook one (Harris & Kotzalas, *Essential Concepts*, ch. on
    bearing arrangements: equal shares for equal bearings and d = 0).

    Returns
    -------
    PairOffsets
        offset_a, offset_b [m]; force_a, force_b [N]; loop_force (F_A + F_B)/2 [N].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> o = tandem_offsets(g, 0.0, 0.0, 40.0)
    >>> round(float(o.force_a), 6), round(float(o.force_b), 6)  # equal shares, N
    (20.0, 20.0)
    """
    d = np.asarray(check_finite("mismatch", mismatch, "m"), dtype=float)
    f_ext = np.asarray(check_finite("external_load", external_load, "N"), dtype=float)
    t = np.asarray(check_finite("thrust", thrust, "N"), dtype=float)
    ks = float(check_nonnegative("spring_stiffness", spring_stiffness, "N/m"))
    shape = np.broadcast_shapes(d.shape, f_ext.shape, t.shape, np.shape(geom.clearance))
    d = np.broadcast_to(d, shape)
    target = np.broadcast_to(t + f_ext, shape)
    args = _geometry_args(geom, shape)

    # the rows' r1, F_A + F_B + k_s·a_A − (T + F_ext), at a_A = a, a_B = a + d (p = a, z = 0
    # stand for the two offsets; the thrust is carried in the load ff = T + F_ext)
    rows = PairRows(True, ks, 0.0)

    def residual(a, dd, ff, *g):
        gg = _geometry_from_args(g, geom.n_balls, geom.compliance)
        return rows.residuals(
            axial_force(a, gg), axial_force(a + dd, gg), 0.0, 0.0, a, 0.0, dd, ff, 0.0
        )[0]

    step = 0.01 * np.broadcast_to(geom.curvature_distance, shape)
    lo = np.minimum(0.0, -d) - step
    hi = np.maximum(0.0, -d) + step
    if shape == ():  # one state: scalar Brent (the per-step path), bracket widened as needed
        dd, ff = float(d), float(target)
        lo, hi = float(lo), float(hi)
        while residual(lo, dd, ff, *args) > 0:
            lo -= hi - lo
        while residual(hi, dd, ff, *args) < 0:
            hi += hi - lo
        a = np.asarray(brentq(lambda x: float(residual(x, dd, ff, *args)), lo, hi, xtol=1e-16))
        return PairOffsets(a, a + d, axial_force(a, geom), axial_force(a + d, geom))
    br = bracket_root(residual, lo, hi, args=(d, target, *args))
    a = find_root(residual, br.bracket, args=(d, target, *args), tolerances={"xatol": 1e-16}).x
    return PairOffsets(a, a + d, axial_force(a, geom), axial_force(a + d, geom))


def tandem_axial_stiffness(stiffness_a, stiffness_b, spring_stiffness: float):
    """Axial stiffness of the shaft in a tandem pair [N/m]: K = k_A + k_B + k_s (the bearings
    side by side, the preload spring relaxing as the shaft moves along the thrust; from
    :func:`tandem_offsets`' condition).

    Returns
    -------
    float or ndarray
        K [N/m].

    Examples
    --------
    >>> float(tandem_axial_stiffness(1.0e7, 1.2e7, 1.0e5))
    22100000.0
    """
    ka = np.asarray(check_nonnegative("stiffness_a", stiffness_a, "N/m"))
    kb = np.asarray(check_nonnegative("stiffness_b", stiffness_b, "N/m"))
    ks = float(check_nonnegative("spring_stiffness", spring_stiffness, "N/m"))
    return PairRows(True, ks, 0.0).axial_stiffness(ka, kb)


def tandem_equilibrium(
    geom: RaceGeometry,
    mismatch: float,
    spring_stiffness: float,
    thrust: float,
    axial_load: float,
    radial_load: float,
) -> PairState:
    """Equilibrium of a tandem pair (:func:`tandem_offsets`) under an axial load F_ext [N] along
    its thrust and a radial load F_r [N] shared equally by A and B (as
    :func:`pair_equilibrium`). Scalar geometry.

    Unknowns: a_A (a_B = a_A + d) and the radial displacements δr_A, δr_B [m]; equations
    F_A + F_B + k_s·a_A = T + F_ext and Fr_A = Fr_B = F_r/2, solved by Newton–Powell
    (scipy.optimize.root) with the analytic stiffness from the axial solution.

    Returns
    -------
    PairState
        Offsets and radial displacements [m], the per-ball loads, and whether the force balance
        was met to a relative 1e-9.

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> g = catalog.bearing("71803").race_geometry()
    >>> st = tandem_equilibrium(g, 0.0, 0.0, 40.0, 0.0, 20.0)
    >>> st.converged, round(float(st.balls_a.radial_force[0]), 9)  # each carries half, N
    (True, 10.0)
    """
    d = float(check_finite("mismatch", mismatch, "m"))
    ks = float(check_nonnegative("spring_stiffness", spring_stiffness, "N/m"))
    thrust = float(check_finite("thrust", thrust, "N"))
    return pair_equilibrium(geom, d, PairRows(True, ks, thrust), axial_load, radial_load)
