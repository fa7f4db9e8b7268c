"""Seats and preload loop of a bearing pair: the :class:`Mounting` record (catalogue:
``data/mountings.toml``, loaded by :func:`catalog.mounting`)."""

from __future__ import annotations

from dataclasses import dataclass

from ._checks import check_positive, check_temperature
from .fits import RadialFit
from .preload import PreloadLoop


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
    """

    key: str
    name: str
    bearing_key: str
    assembly_temperature: float
    fit: RadialFit
    loop: PreloadLoop
    assembly_preload: float | None = None
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_temperature("assembly_temperature", self.assembly_temperature)
        if self.assembly_preload is not None:
            check_positive("assembly_preload", self.assembly_preload, "N")

    def source(self, field: str) -> str:
        return dict(self.provenance).get(field, "")
