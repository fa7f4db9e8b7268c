"""Material record: elastic constants and thermal expansion (SI).

The values live in ``data/materials.toml`` with their provenance; load them with
:func:`servofmu.physics.catalog.material`.
"""

from __future__ import annotations

from dataclasses import dataclass

from ._checks import check_positive, check_range


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
    """

    key: str
    name: str
    youngs_modulus: float
    poisson_ratio: float
    expansion: float
    provenance: tuple[tuple[str, str], ...] = ()

    def __post_init__(self):
        check_positive("youngs_modulus", self.youngs_modulus, "Pa")
        check_range("poisson_ratio", self.poisson_ratio, -1.0, 0.5, lo_open=True, hi_open=True)
        check_range("expansion", self.expansion, -1e-4, 1e-4, unit="1/K")

    def source(self, field: str) -> str:
        """Provenance of one field ("" when not recorded)."""
        return dict(self.provenance).get(field, "")


def reduced_compliance(m1: Material, m2: Material) -> float:
    """Hertz elastic compliance η = (1-ν1²)/E1 + (1-ν2²)/E2 [1/Pa] of two bodies in contact.

    Harris & Kotzalas (2007), *Essential Concepts of Bearing Technology*, ch. 6 (Hertz
    point contact); η appears as the bracket in the semi-axis formulas.
    """
    return (1.0 - m1.poisson_ratio**2) / m1.youngs_modulus + (
        1.0 - m2.poisson_ratio**2
    ) / m2.youngs_modulus
