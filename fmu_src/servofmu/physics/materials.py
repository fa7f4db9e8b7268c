"""Material record: elastic constants, thermal expansion and, optionally, the thermal
properties a heat-transfer model needs (density, specific heat, conductivity, emissivity), SI.

The values live in ``data/materials.toml`` with their provenance; load them with
:func:`servofmu.parameters.catalog.material`.
"""

from __future__ import annotations

from dataclasses import dataclass

from ._checks import check_positive, check_range

#: Optional thermal properties of a :class:`Material` (emissivity besides) and their units.
THERMAL_FIELDS = {
    "density": "kg/m³",
    "specific_heat": "J/(kg·K)",
    "thermal_conductivity": "W/(m·K)",
}


@dataclass(frozen=True)
class Material:
    """An isotropic, linear-elastic material.

    Attributes
    ----------
    key : catalogue key
    name : human-readable name
    youngs_modulus : Young's modulus E [Pa]
    poisson_ratio : Poisson's ratio ν [-], in (-1, 0.5)
    expansion : linear thermal expansion coefficient [1/K]
    provenance : ((field, source), ...) where each value came from
    density : ρ [kg/m³] (None: not known; only heat-transfer models need it)
    specific_heat : c [J/(kg·K)] (None: not known)
    thermal_conductivity : λ [W/(m·K)] (None: not known)
    emissivity : total hemispherical emissivity ε [-] of its surface as built, in (0, 1]
        (None: not known)
    """

    key: str
    name: str
    youngs_modulus: float
    poisson_ratio: float
    expansion: float
    provenance: tuple[tuple[str, str], ...] = ()
    density: float | None = None
    specific_heat: float | None = None
    thermal_conductivity: float | None = None
    emissivity: float | None = None

    def __post_init__(self):
        check_positive("youngs_modulus", self.youngs_modulus, "Pa")
        check_range("poisson_ratio", self.poisson_ratio, -1.0, 0.5, lo_open=True, hi_open=True)
        check_range("expansion", self.expansion, -1e-4, 1e-4, unit="1/K")
        for field, unit in THERMAL_FIELDS.items():
            value = getattr(self, field)
            if value is not None:
                check_positive(field, value, unit)
        if self.emissivity is not None:
            check_range("emissivity", self.emissivity, 0.0, 1.0, lo_open=True)

    def thermal(self, field: str) -> float:
        """One of the optional thermal properties (:data:`THERMAL_FIELDS`, ``emissivity``);
        a ValueError naming the material and the field when it is not known."""
        value = getattr(self, field)
        if value is None:
            raise ValueError(f"material {self.key!r} has no {field}: add it to data/materials.toml")
        return value

    def source(self, field: str) -> str:
        """Provenance of one field ("" when not recorded)."""
        return dict(self.provenance).get(field, "")


def reduced_compliance(m1: Material, m2: Material) -> float:
    """Hertz elastic compliance η = (1-ν1²)/E1 + (1-ν2²)/E2 [1/Pa] of two bodies in contact.

    Harris & Kotzalas (2007), *Essential Concepts of Bearing Technology*, ch. 6 (Hertz
    point contact); η appears as the bracket in the semi-axis formulas.

    Parameters
    ----------
    m1, m2 : Material
        The two bodies' materials (E [Pa], ν [-]).

    Returns
    -------
    float
        η [1/Pa].

    Examples
    --------
    >>> from servofmu.parameters import catalog
    >>> s = catalog.material("bearing_steel_yu")
    >>> round(reduced_compliance(s, s) * 1e12, 4)  # 1/TPa: 2·(1 − ν²)/E
    8.6515
    """
    return (1.0 - m1.poisson_ratio**2) / m1.youngs_modulus + (
        1.0 - m2.poisson_ratio**2
    ) / m2.youngs_modulus
