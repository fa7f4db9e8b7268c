# cython: language_level=3, auto_pickle=False, embedsignature=False
"""The per-step state of a bearing pair at one operating point, :class:`PointState`: the
record both solver paths fill (the continuation, :mod:`.continuation`, and the exact path,
:func:`.state.exact_point`). One class in a process: compiled when the compiled modules run
(:mod:`servofmu.physics.compiled`), whichever path fills it.

Examples
--------
>>> POINT_FIELDS[:3]
('hysteresis_torque', 'spin_torque', 'sliding_torque')
"""

try:
    import cython
except ImportError:  # no Cython: its pure-Python mode's names as no-ops
    from ..kernels import _cython_shadow as cython


@cython.dataclasses.dataclass
@cython.final
@cython.cclass
class PointState:
    """Everything BearingFriction reports at one operating point except what moves with speed,
    as floats: the per-step state of :class:`~.model.BearingModel` (from the continuation or
    the exact path), with the Coulomb torque, breakaway excess, pitch diameter [m], kinematic
    viscosity [m²/s] and friction model data (``rolling``, :func:`~.state.rolling_data`
    as floats: JSON-serialisable) that the speed terms need. Fields as
    :class:`~.state.BearingOutputs` (torques [N·m], forces [N], angle [rad], lengths
    [m], stiffness [N/m], pressures [Pa]); ``sliding_torque`` is that of the contacts (the SKF
    model's moves with speed)."""

    hysteresis_torque: cython.double
    spin_torque: cython.double
    sliding_torque: cython.double
    inner_ring_torque: cython.double
    outer_ring_torque: cython.double
    coulomb_torque: cython.double
    breakaway_excess: cython.double
    breakaway_torque: cython.double
    preload: cython.double
    contact_angle: cython.double
    radial_clearance: cython.double
    kinematic_viscosity: cython.double
    pitch_diameter: cython.double
    axial_stiffness: cython.double
    max_contact_pressure: cython.double
    outer_fit_pressure: cython.double
    inner_fit_pressure: cython.double
    outer_interference: cython.double
    inner_interference: cython.double
    force_a: cython.double
    force_b: cython.double
    axial_displacement: cython.double
    overloaded: cython.bint
    locked: cython.bint
    unloaded: cython.bint
    reverse_loaded: cython.bint
    outside_lubricant_range: cython.bint
    axial_play: cython.double
    rolling: object = None

    def as_dict(self) -> dict:
        """The fields as a JSON-serialisable dict.

        Returns
        -------
        dict
        """
        return {name: getattr(self, name) for name in POINT_FIELDS}


#: The fields of :class:`PointState`, in order.
POINT_FIELDS = (
    "hysteresis_torque",
    "spin_torque",
    "sliding_torque",
    "inner_ring_torque",
    "outer_ring_torque",
    "coulomb_torque",
    "breakaway_excess",
    "breakaway_torque",
    "preload",
    "contact_angle",
    "radial_clearance",
    "kinematic_viscosity",
    "pitch_diameter",
    "axial_stiffness",
    "max_contact_pressure",
    "outer_fit_pressure",
    "inner_fit_pressure",
    "outer_interference",
    "inner_interference",
    "force_a",
    "force_b",
    "axial_displacement",
    "overloaded",
    "locked",
    "unloaded",
    "reverse_loaded",
    "outside_lubricant_range",
    "axial_play",
    "rolling",
)
