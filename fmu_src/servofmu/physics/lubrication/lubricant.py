"""Lubricant records: what a datasheet says about an oil or a grease's base oil (SI).

The values live in ``data/lubricants.toml`` with their provenance; load them with
:func:`servofmu.parameters.catalog.lubricant_record` (the viscosity model alone:
:func:`servofmu.parameters.catalog.lubricant`).
"""

from __future__ import annotations

from dataclasses import dataclass

from .._checks import check_nonnegative, check_positive, check_temperature
from .viscosity import ViscosityRange

LUBRICANT_TYPES = ("oil", "grease", "solid")
#: Classes of base oil for the SKF model's full-film sliding coefficient μEHL (SKF 10000 EN
#: p. 103: mineral 0.05, synthetic 0.04, transmission fluids 0.1); "" when not recorded.
OIL_CLASSES = ("", "mineral", "synthetic", "transmission")


@dataclass(frozen=True)
class TorqueTest:
    """One low-temperature torque result of a grease, as its datasheet reports it.

    Attributes
    ----------
    standard : test method, e.g. "ASTM D1478", "FED-STD-791 3458", "JIS K 2220"
    bearing : test bearing as the standard or datasheet names it
    temperature : test temperature [K]
    starting_torque : breakaway torque [N·m] (None: not reported)
    running_torque : torque after the method's running time [N·m] (None: not reported)
    provenance : ((field, source), ...)
    """

    standard: str
    bearing: str
    temperature: float
    starting_torque: float | None = None
    running_torque: float | None = None
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_temperature("temperature", self.temperature)
        for name in ("starting_torque", "running_torque"):
            if getattr(self, name) is not None:
                check_nonnegative(name, getattr(self, name), "N·m")
        if self.starting_torque is None and self.running_torque is None:
            raise ValueError("a torque test needs starting_torque or running_torque")


@dataclass(frozen=True)
class LubricantRecord:
    """A lubricant's datasheet values (of the base oil for a grease), SI units.

    Attributes
    ----------
    key, name : catalogue key and description
    lubricant_type : "oil", "grease" or "solid"
    base_oil : the base oil as the datasheet names it ("" for a solid film)
    viscosity : the base oil's viscosity model with its range (:mod:`.lubrication.viscosity`: the
    ASTM
        D341 line through ν40 and ν100, or Vogel's law through them and ``viscosity_points``);
        None for a solid film
    viscosity_40, viscosity_100 : kinematic viscosity at 40 and 100 °C [m²/s] (None: solid)
    viscosity_points : further published (temperature [K], viscosity [m²/s]) points; the
        model passes through them (three points in all) or is fitted to them (more)
    density : base-oil density [kg/m³] at ``density_temperature`` [K] (None: not published)
    pour_point : base-oil pour point [K] (None: not published): its flow limit
    minimum_temperature : the maker's lower operating temperature [K] (None: not given): the
        flow limit where no pour point is published
    data_minimum_temperature : the coldest temperature its viscosity data reach where no
        viscosity point is recorded there (the lowest temperature a paper used its fit at) [K]
        (None: its coldest viscosity point); a data end, not a flow limit
    maximum_temperature : the upper end of the lubricant's data (the maker's upper operating
        temperature, or the highest temperature a paper used its fit at) [K] (None: the
        highest viscosity point is the upper end)
    oil_class : "mineral", "synthetic" or "transmission" (:data:`OIL_CLASSES`; "" unknown), from
        the base oil the entry names
    low_temperature_torque : datasheet torque tests, :class:`TorqueTest`
    provenance : ((field, source), ...)
    """

    key: str
    name: str
    lubricant_type: str
    base_oil: str = ""
    viscosity: ViscosityRange | None = None
    viscosity_40: float | None = None
    viscosity_100: float | None = None
    viscosity_points: tuple[tuple[float, float], ...] = ()
    density: float | None = None
    density_temperature: float | None = None
    pour_point: float | None = None
    minimum_temperature: float | None = None
    data_minimum_temperature: float | None = None
    maximum_temperature: float | None = None
    oil_class: str = ""
    low_temperature_torque: tuple[TorqueTest, ...] = ()
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        if self.lubricant_type not in LUBRICANT_TYPES:
            raise ValueError(
                f"lubricant_type = {self.lubricant_type!r} is not one of {LUBRICANT_TYPES}"
            )
        if self.oil_class not in OIL_CLASSES:
            raise ValueError(f"oil_class = {self.oil_class!r} is not one of {OIL_CLASSES}")
        fluid = self.lubricant_type != "solid"
        if fluid != (self.viscosity is not None):
            raise ValueError(
                f"lubricant_type = {self.lubricant_type!r} needs "
                f"{'a viscosity model' if fluid else 'no viscosity model'}"
            )
        if fluid:
            nu40 = check_positive("viscosity_40", self.viscosity_40, "m²/s")
            nu100 = check_positive("viscosity_100", self.viscosity_100, "m²/s")
            if not nu100 < nu40:
                raise ValueError(
                    f"viscosity_100 = {nu100!r} m²/s must be below viscosity_40 = {nu40!r} m²/s"
                )
        for t, nu in self.viscosity_points:
            check_temperature("viscosity_points temperature", t)
            check_positive("viscosity_points viscosity", nu, "m²/s")
        if self.density is not None:
            check_positive("density", self.density, "kg/m³")
        if self.density_temperature is not None:
            check_temperature("density_temperature", self.density_temperature)
        for name in ("pour_point", "minimum_temperature", "data_minimum_temperature",
                     "maximum_temperature"):  # fmt: skip
            if getattr(self, name) is not None:
                check_temperature(name, getattr(self, name))

    def source(self, field: str) -> str:
        """Provenance of one field ("" when not recorded)."""
        return dict(self.provenance).get(field, "")
