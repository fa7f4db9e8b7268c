"""Seats and preload loop of a bearing pair: the :class:`Mounting` record (catalogue:
``data/mountings.toml``, loaded by :func:`catalog.mounting`)."""

from __future__ import annotations

from dataclasses import dataclass

from .._checks import check_operating_temperature, check_positive
from ..thermal.fits import RadialFit
from .preload import ARRANGEMENTS, TANDEM, PreloadLoop, arrangement_problems

#: How the preload is set at assembly: a rigid shim (axial interference), a force at the
#: assembly temperature (the shim that gives it, then rigid: a nut tightened to a force), or a
#: spring of stiffness k compressed by c (force k·c at assembly, the spring in series with the
#: structure).
PRELOAD_METHODS = ("shim", "force", "spring")


@dataclass(frozen=True)
class Mounting:
    """Seats and preload loop of a bearing pair (catalogue: ``data/mountings.toml``).

    Attributes
    ----------
    key, name : catalogue key and description
    bearing_key : designation of the bearing it was made for
    assembly_temperature : T0 [K] at which fits, shim and preload are set
    fit : :class:`fits.RadialFit`
    loop : :class:`preload.PreloadLoop`
    assembly_preload : preload at T0 [N]; when given, the shim is derived from it
    provenance : ((field, source), ...)
    arrangement : :data:`~.pair.preload.ARRANGEMENTS`: "face_to_face", "back_to_back" or
        "tandem" (then preloaded by a spring or a force); the loop members' roles must agree
        with it
    """

    key: str
    name: str
    bearing_key: str
    assembly_temperature: float
    fit: RadialFit
    loop: PreloadLoop
    assembly_preload: float | None = None
    provenance: tuple[tuple[str, str], ...] = ()
    arrangement: str = "face_to_face"

    def __post_init__(self):
        check_operating_temperature("assembly_temperature", self.assembly_temperature)
        if self.assembly_preload is not None:
            check_positive("assembly_preload", self.assembly_preload, "N")
        if self.arrangement not in ARRANGEMENTS:
            raise ValueError(
                f"arrangement = {self.arrangement!r} is not one of {sorted(ARRANGEMENTS)}"
            )
        problems = arrangement_problems(self.loop, self.arrangement)
        if self.arrangement == TANDEM and self.assembly_preload is None:
            problems.append(
                "a tandem pair has no opposed bearing to be shimmed against: its preload is "
                "a spring or a force (preload_method = spring or force)"
            )
        if problems:
            raise ValueError(f"mounting {self.key!r}: " + "; ".join(problems))

    @property
    def preload_method(self) -> str:
        """How the preload is set (:data:`PRELOAD_METHODS`): "spring" with a preload spring,
        "force" with an assembly preload, else "shim"."""
        if self.loop.spring_stiffness is not None:
            return "spring"
        return "shim" if self.assembly_preload is None else "force"

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")
