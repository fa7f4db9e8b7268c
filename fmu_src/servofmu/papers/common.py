"""Parameter listings shared by the paper reproductions (records → report parameters)."""

from __future__ import annotations

from ..physics.bearing import BearingPair, loop_stiffness
from ..physics.kernels.units import DEG, MM, UM, kelvin_to_celsius
from .report import Parameter


def bearing_parameters(pair: BearingPair) -> list[Parameter]:
    """Geometry of the pair's bearing with provenance."""
    b = pair.bearing
    ps = [Parameter("bearing", b.key, "", b.name)]
    for f in ("bore", "outer_diameter", "width", "ball_diameter", "pitch_diameter"):
        ps.append(Parameter(f, getattr(b, f) / MM, "mm", b.source(f)))
    for f in ("inner_groove_diameter", "outer_groove_diameter"):
        ps.append(Parameter(f, getattr(b, f) / MM, "mm", b.source(f)))
    ps += [
        Parameter("n_balls", b.n_balls, "", b.source("n_balls")),
        Parameter("inner_curvature", b.inner_curvature, "", b.source("inner_curvature")),
        Parameter("outer_curvature", b.outer_curvature, "", b.source("outer_curvature")),
        Parameter(
            "nominal_contact_angle",
            b.nominal_contact_angle / DEG,
            "deg",
            b.source("nominal_contact_angle"),
        ),
        Parameter("free_clearance", b.clearance / UM, "um", "derived: 2·A·(1 − cos α0)"),
    ]
    return ps


def material_parameters(pair: BearingPair) -> list[Parameter]:
    """Materials of rings, balls, housing, shaft and loop members with provenance."""
    m = pair.mounting
    mats = [pair.bearing.ring_material, pair.bearing.ball_material]
    mats += [m.fit.housing_material, m.fit.shaft_material]
    mats += [mem.material for mem in m.loop.members]
    ps, seen = [], set()
    for mat in mats:
        if mat.key in seen:
            continue
        seen.add(mat.key)
        ps += [
            Parameter(
                f"{mat.key}.youngs_modulus",
                mat.youngs_modulus / 1e9,
                "GPa",
                mat.source("youngs_modulus"),
            ),
            Parameter(
                f"{mat.key}.poisson_ratio", mat.poisson_ratio, "", mat.source("poisson_ratio")
            ),
            Parameter(f"{mat.key}.expansion", mat.expansion, "1/K", mat.source("expansion")),
        ]
    return ps


def mounting_parameters(pair: BearingPair, label: str = "") -> list[Parameter]:
    """Fits and preload loop of the pair with provenance (``label`` tags the loop entries)."""
    m = pair.mounting
    tag = f"[{label}]" if label else ""
    ps = [
        Parameter("mounting", m.key, "", m.name),
        Parameter(
            "assembly_temperature",
            kelvin_to_celsius(m.assembly_temperature),
            "degC",
            m.source("assembly_temperature"),
        ),
        Parameter(
            "housing_outer_diameter",
            m.fit.housing_outer_diameter / MM,
            "mm",
            m.source("housing_outer_diameter"),
        ),
        Parameter(
            "outer_interference (diametral)",
            m.fit.outer_interference / UM,
            "um",
            m.source("outer_interference"),
        ),
        Parameter("shaft_bore", m.fit.shaft_bore / MM, "mm", m.source("shaft_bore")),
        Parameter(
            "inner_interference (diametral)",
            m.fit.inner_interference / UM,
            "um",
            m.source("inner_interference"),
        ),
    ]
    if m.assembly_preload is not None:
        ps.append(
            Parameter("assembly_preload", m.assembly_preload, "N", m.source("assembly_preload"))
        )
    else:
        ps.append(Parameter("shim", m.loop.shim / MM, "mm", m.source("shim")))
    for mem in m.loop.members:
        ps.append(
            Parameter(
                f"loop{tag}.{mem.name}",
                f"{mem.length / MM:g} mm, {mem.material.key}, role {mem.role}"
                + (f", A = {mem.area / MM**2:g} mm²" if mem.area else ""),
                "",
                m.source(f"loop.{mem.name}.length"),
            )
        )
    ps.append(
        Parameter(
            f"loop_stiffness{tag}",
            loop_stiffness(pair),
            "N/m",
            "derived: 1/Σ L/(E·A) (Yu eq 15's 1/C1)",
        )
    )
    return ps
