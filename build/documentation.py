"""``documentation/`` of each FMU, for a user of any FMI tool: ``index.html`` (what the FMU
computes, its equations, every variable with unit, start, range and provenance, the host
requirements) and ``characteristic.png``, the FMU's characteristic curve computed by the
FMU's own Python code at build time.

The equations are the docstrings of the FMU module and of the physics modules it names
(``PHYSICS``), rendered from reStructuredText to HTML with docutils. Nothing here is part of
the servofmu package that the FMU carries, so documentation changes leave the package hash
(and the built FMU's identity) alone.
"""

from __future__ import annotations

import contextlib
import importlib
import math
import platform
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import servofmu
from servofmu.physics.friction import registry

IMAGE = "characteristic.png"


def slave_class(name: str):
    """The slave class ``name`` from ``servofmu.fmus``.

    Parameters
    ----------
    name : str
        The FMU's model identifier, e.g. "BearingFriction" (module and class of that name).

    Returns
    -------
    type
        The pythonfmu slave class (not an instance).

    Examples
    --------
    >>> cls = slave_class("DCMotor")
    >>> cls.__name__, cls.__module__, cls.PHYSICS
    ('DCMotor', 'servofmu.fmus.DCMotor', ('servofmu.physics.drives.motor',))
    """
    return getattr(importlib.import_module(f"servofmu.fmus.{name}"), name)


# ----------------------------------------------------------------------------- driving
class _Slave:
    """One instance of an FMU's slave class driven in this process through pythonfmu's
    Python API (set/get by value reference, initialization, fmi2DoStep): the FMU's own code,
    without the binary."""

    def __init__(self, name: str, integers=None, **inputs):
        self.slave = slave_class(name)(instance_name="documentation")
        self.vr = {v.name: ref for ref, v in self.slave.vars.items()}
        self.slave.setup_experiment(0.0, None, None)
        self.slave.enter_initialization_mode()
        self.set(**inputs)
        if integers:  # choices (FMI Integer)
            self.slave.set_integer([self.vr[k] for k in integers], list(integers.values()))
        self.slave.exit_initialization_mode()

    def set(self, **values):
        if values:
            self.slave.set_real([self.vr[k] for k in values], [float(v) for v in values.values()])

    def get(self, *names) -> list[float]:
        return self.slave.get_real([self.vr[n] for n in names])

    def step(self, t: float, h: float):
        if not self.slave.do_step(t, h):
            raise RuntimeError(f"{type(self.slave).__name__}: step at t = {t} s refused")


@dataclass(frozen=True)
class Curve:
    """A characteristic curve: x values and labelled series (all in display units)."""

    title: str
    xlabel: str
    ylabel: str
    x: np.ndarray
    series: tuple[tuple[str, np.ndarray], ...]
    caption: str
    right: tuple[str, str, np.ndarray] | None = None  # (axis label, series label, values)
    log_y: bool = False
    y_min: float | None = None  # lower end of the y axis (what lies below is cut off)


def _build_start(name: str) -> bool:
    """True when this build gives FMU ``name`` start values of its own (a preset)."""
    from servofmu.fmus.declarations import BUILD_START

    return bool(BUILD_START.get(name))


def _bearing_curve() -> Curve:
    """Running and breakaway torque versus temperature, −60…+80 °C, at 10 °/s (default
    friction model), and the running torque of the other friction models."""
    celsius = np.arange(-60.0, 80.0 + 1e-9, 2.5)
    speed = math.radians(10.0)
    default, *others = registry.names()  # the FMU's enumeration items, numbered from 1
    loaded = [e.name for e in registry.entries() if e.data]  # torques of the loads or contacts
    fmus = [_Slave("BearingFriction", speed=speed)]
    fmus += [
        _Slave("BearingFriction", {"friction_model": i}, speed=speed)
        for i in range(2, len(others) + 2)
    ]
    rows = []
    for c in celsius:
        row = []
        for fmu in fmus:
            fmu.set(temperature=c + 273.15)
            row += fmu.get("running_torque", "breakaway_torque")
        rows.append(row)
    torque = 1e3 * np.array(rows)  # N·m → N·mm
    return Curve(
        "BearingFriction: friction torque versus temperature",
        "temperature [°C]",
        "torque [N·mm]",
        celsius,
        (
            (f"running torque at 10 °/s ({default}, default)", torque[:, 0]),
            ("breakaway torque (a lower bound where breakaway_lower_bound is set)", torque[:, 1]),
            *(
                (f"running torque, friction_model {name}", torque[:, 2 * k + 2])
                for k, name in enumerate(others)
            ),
        ),
        f"Default parameters (friction_model {default}, no grease term) and the other friction "
        "models' running torque, no external load, shaft speed 10 °/s (logarithmic torque "
        "axis). The thermal coupling of frame, shaft and bearings changes fits and preload with "
        "temperature; the lubricant's viscosity adds the viscous part of the running torque. "
        f"{registry.listed(loaded, 'and')} see the bearings' loads: once the preload is lost "
        "they fall below 0.01 N·mm (the axis' end), and SKF's replenishment factor cuts its "
        "rolling torque as the base oil thickens. Outside the range of the lubricant's data "
        "(lubricant_data_minimum_temperature … lubricant_maximum_temperature; the default "
        "Krytox 143AA: −40…+60 °C, Yu's) the output outside_lubricant_range is set and the "
        "viscosity law is extrapolated (the default has no published flow limit, "
        "lubricant_minimum_temperature 0; below one, lubricant_below_flow_limit holds or "
        "extrapolates). "
        + (
            "The start values are this build's preset (see the parameters' provenance)."
            if _build_start("BearingFriction")
            else "With the default mounting the preload is lost above about 36 °C (unloaded)."
        ),
        log_y=True,
        y_min=0.01,
    )


def _actuator_curve() -> Curve:
    """Stiffness at the output shaft versus hinge moment, at neutral and at +10°."""
    moments = np.linspace(10.0, 400.0, 40)
    series = []
    for degrees in (0.0, 10.0):
        fmu = _Slave("ActuatorStiffness", angle=math.radians(degrees))
        k = []
        for m in moments:
            fmu.set(load_torque=m)
            k.append(fmu.get("stiffness")[0])
        series.append((f"output angle {degrees:+g}°", math.radians(1.0) * np.array(k)))
    return Curve(
        "ActuatorStiffness: stiffness versus hinge moment",
        "hinge moment [N·m]",
        "stiffness at the output shaft [N·m/°]",
        moments,
        tuple(series),
        "Default parameters (Liu 2014's actuator with the support-bearing extension), 20 °C. "
        "The Hertzian support bearings stiffen with load; every other element is linear. "
        "The kink at 30–50 N·m is where one bearing of the preloaded support pair unloads.",
    )


def _motor_curve() -> Curve:
    """Speed and current after a 1 V step from rest, no load."""
    cls = slave_class("DCMotor")
    p = {v.name: v.start for v in cls.VARIABLES}
    tau = p["resistance"] * p["inertia"] / (p["torque_constant"] * p["back_emf_constant"])
    h = tau / 100.0
    fmu = _Slave("DCMotor", voltage=1.0)
    t = h * np.arange(501)
    rows = [fmu.get("speed", "current")]
    for k in range(500):
        fmu.step(t[k], h)
        rows.append(fmu.get("speed", "current"))
    speed, current = np.array(rows).T
    return Curve(
        "DCMotor: response to a 1 V voltage step",
        "time [ms]",
        "speed [rad/s]",
        1e3 * t,
        (("speed", speed),),
        f"Default parameters, from rest, no load or friction; mechanical time constant "
        f"R·J/(k_t·k_e) = {1e3 * tau:.3g} ms (the current rises with L/R, then falls as "
        "the back-EMF builds up). The FMU integrates exactly over each step.",
        right=("current [A]", "current", current),
    )


def _controller_curve() -> Curve:
    """Command after a unit step of the reference, measurement held at 0 (open loop)."""
    cls = slave_class("ServoController")
    period = {v.name: v.start for v in cls.VARIABLES}["sample_period"]
    fmu = _Slave("ServoController", reference=1.0, measurement=0.0)
    t = period * np.arange(3001)
    command = [fmu.get("command")[0]]
    for k in range(3000):
        fmu.step(t[k], period)
        command.append(fmu.get("command")[0])
    return Curve(
        "ServoController: step response of the command",
        "time [s]",
        "command [V]",
        t,
        (("command", np.array(command)),),
        "Default parameters (speed mode); the reference steps from 0 to 1 rad/s at t = 0 and "
        "the measurement stays 0 (open loop): proportional step, integral ramp, clamped at "
        "the output limit (anti-windup).",
    )


def _thermal_curve() -> Curve:
    """Part temperatures after a 20 → 60 °C step of the chamber (ambient and sink), 3 h."""
    names = ("housing", "shaft", "outer_ring", "inner_ring")
    outputs = tuple(f"{n}_temperature" for n in names)
    h = 30.0
    fmu = _Slave("ThermalNetwork", ambient_temperature=293.15, sink_temperature=293.15)
    t = h * np.arange(361)
    rows = [fmu.get(*outputs)]
    for k in range(360):
        fmu.set(ambient_temperature=333.15, sink_temperature=333.15)
        fmu.step(t[k], h)
        rows.append(fmu.get(*outputs))
    celsius = np.array(rows) - 273.15
    return Curve(
        "ThermalNetwork: chamber step from 20 to 60 °C",
        "time [min]",
        "temperature [°C]",
        t / 60.0,
        tuple((n.replace("_", " "), celsius[:, i]) for i, n in enumerate(names)),
        (
            "This build's parameters (the network of its mechanism's parts in chamber air), "
            if _build_start("ThermalNetwork")
            else "Default parameters (Yu's seeker gimbal in chamber air, preset "
            "yu2017_gimbal_chamber), "
        )
        + "no bearing loss: the frame follows the air first, the shaft and the inner rings "
        "lag behind the balls' small conductance. The FMU integrates exactly over each step.",
    )


CURVES = {
    "BearingFriction": _bearing_curve,
    "ActuatorStiffness": _actuator_curve,
    "DCMotor": _motor_curve,
    "ServoController": _controller_curve,
    "ThermalNetwork": _thermal_curve,
}


def plot_curve(curve: Curve, path: Path) -> Path:
    """Write ``curve`` as a PNG (labelled axes with units) to ``path``.

    Parameters
    ----------
    curve : Curve
        The curve: x values, series and labels in display units.
    path : str or pathlib.Path
        The PNG file to write (its folder must exist).

    Returns
    -------
    pathlib.Path
        ``path``.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> curve = Curve("y = x²", "x [-]", "y [-]", np.arange(3.0), (("x²", np.arange(3.0) ** 2),),
    ...               "a parabola")  # fmt: skip
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     png = plot_curve(curve, Path(tmp) / "curve.png")
    ...     print(png.name, png.read_bytes()[1:4])
    curve.png b'PNG'
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.4, 4.0), dpi=100)
    ax = fig.add_subplot()
    lines = [ax.plot(curve.x, y, label=label)[0] for label, y in curve.series]
    if curve.right is not None:
        axis_label, label, y = curve.right
        twin = ax.twinx()
        lines += twin.plot(curve.x, y, color="C3", label=label)
        twin.set_ylabel(axis_label)
    if curve.log_y:
        ax.set_yscale("log")
    if curve.y_min is not None:
        ax.set_ylim(bottom=curve.y_min)
    ax.set_title(curve.title, fontsize=10)
    ax.set_xlabel(curve.xlabel)
    ax.set_ylabel(curve.ylabel)
    ax.grid(True, which="both", alpha=0.3)
    if len(lines) > 1:
        ax.legend(handles=lines, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, metadata={"Software": None})
    return Path(path)


# ----------------------------------------------------------------------------- text
# One reStructuredText source per FMU (page_rst): the FMU's documentation/index.html renders it
# with docutils (equations as MathML), and the documentation site's FMU reference renders the
# same text with Sphinx.

#: The reStructuredText roles of the docstrings that are Sphinx cross-references: on an FMU's
#: page (no Sphinx) they render as code.
XREF_ROLES = ("func", "class", "mod", "meth", "data", "attr", "obj", "exc")

#: Docutils settings of the FMU page: MathML for the equations, no stylesheet, and the
#: section titles of the generated text from <h2> on.
_SETTINGS = {
    "math_output": "MathML",
    "doctitle_xform": True,
    "initial_header_level": 2,
    "input_encoding": "unicode",
    "embed_stylesheet": False,
    "stylesheet_path": "",
    "syntax_highlight": "none",
}


@contextlib.contextmanager
def _docutils():
    """docutils' publisher with its own directives and roles only (a Sphinx build running in
    the same process, as the examples gallery does, registers patched ones that need Sphinx),
    the Sphinx cross-reference roles of the docstrings (``:func:`x```…) rendered as code and
    Sphinx's ``currentmodule`` directive accepted (it only sets the scope of those references
    in Sphinx)."""
    from docutils import nodes
    from docutils.core import publish_parts
    from docutils.parsers.rst import Directive, directives, roles

    def code(name, rawtext, text, lineno, inliner, options=None, content=None):
        label = text.split(".")[-1] if text.startswith("~") else text.lstrip(".")
        return [nodes.literal(rawtext, label)], []

    class CurrentModule(Directive):
        required_arguments = 1

        def run(self):
            return []

    saved = directives._directives, roles._roles
    directives._directives, roles._roles = {}, {}
    try:
        for role in XREF_ROLES:
            roles.register_local_role(role, code)
        directives.register_directive("currentmodule", CurrentModule)
        yield publish_parts
    finally:
        directives._directives, roles._roles = saved


def escape_bars(text: str) -> str:
    """``text`` (a docstring) with every ``|`` outside math escaped: in the docstrings ``|x|``
    is an absolute value, never a reStructuredText substitution. Math (``.. math::`` blocks and
    ``:math:`` roles) keeps its bars.

    Parameters
    ----------
    text : str
        reStructuredText.

    Returns
    -------
    str
        The same text with ``\\|`` for ``|`` outside math.

    Examples
    --------
    >>> print(escape_bars("|F| and :math:`|x|`"))
    \\|F\\| and :math:`|x|`
    >>> print(escape_bars(".. math::\\n\\n   |x| = 1\\n\\nafter |y|"))
    .. math::
    <BLANKLINE>
       |x| = 1
    <BLANKLINE>
    after \\|y\\|
    """
    out, math_indent = [], None
    for line in text.split("\n"):
        indent = len(line) - len(line.lstrip())
        if math_indent is not None and line.strip() and indent <= math_indent:
            math_indent = None
        if math_indent is None and line.lstrip().startswith(".. math::"):
            math_indent = indent
            out.append(line)
            continue
        if math_indent is not None:
            out.append(line)
            continue
        parts = re.split(r"(:math:`[^`]*`)", line)
        out.append("".join(p if p.startswith(":math:") else p.replace("|", "\\|") for p in parts))
    return "\n".join(out)


def rst_to_html(text: str, strict: bool = False) -> str:
    """HTML body of reStructuredText ``text``, equations as MathML (docutils' converter).

    Parameters
    ----------
    text : str or None
        reStructuredText (Sphinx's cross-reference roles such as ``:func:`` become code).
    strict : bool, optional
        Raise on any docutils warning (a markup error, a formula the converter cannot read)
        instead of leaving docutils' messages out of the page.

    Returns
    -------
    str
        The HTML body; empty for an empty text.

    Examples
    --------
    >>> print(rst_to_html("The torque ``M`` grows with :math:`F^2` (:func:`friction_torque`)."))
    <p>The torque <span class="docutils literal">M</span> grows with <math xmlns=...
    >>> rst_to_html(None)
    ''
    """
    if not text:
        return ""
    level = 2 if strict else 5
    with _docutils() as publish_parts:
        parts = publish_parts(
            text,
            writer="html5",
            settings_overrides=_SETTINGS | {"report_level": level, "halt_level": level},
        )
    return parts["html_title"] + parts["body"]


def _escape(text) -> str:
    """Plain text as reStructuredText (inline markup characters escaped)."""
    return re.sub(r"([\\*`|_<>\[\]:])", r"\\\1", str(text)).replace("\n", " ")


def _list_table(title: str, header, rows, css: str = "variables") -> str:
    lines = [f".. list-table:: {title}", "   :header-rows: 1", f"   :class: {css}", ""]
    for row in (header, *rows):
        cells = [_escape(c) if c != "" else r"\ " for c in row]
        lines.append(f"   * - {cells[0]}")
        lines += [f"     - {c}" for c in cells[1:]]
    return "\n".join(lines) + "\n"


def _range(v) -> str:
    if v.min is None and v.max is None:
        return ""
    lo = "−∞" if v.min is None else f"{v.min:g}"
    hi = "+∞" if v.max is None else f"{v.max:g}"
    return f"[{lo}, {hi}]"


def _start(v) -> str:
    items = getattr(v, "items", None)  # a choice: start is the item's number
    if items and isinstance(v.start, int) and 0 < v.start <= len(items):
        item = items[v.start - 1]
        return f"{v.start} ({getattr(item, 'name', item)})"
    if isinstance(v.start, float):
        return f"{v.start:.10g}"
    return "" if v.start is None else repr(v.start)


def variables_rst(cls) -> str:
    """The inputs, outputs and parameters of slave class ``cls`` as reStructuredText tables:
    the modelDescription's own variable list (:func:`servofmu.fmus.declarations.variables_of`, a
    build's start values and provenance included).

    Parameters
    ----------
    cls : type
        A slave class of :mod:`servofmu.fmus`.

    Returns
    -------
    str
        Three subsections (Inputs, Outputs, Parameters), one table each.

    Examples
    --------
    >>> text = variables_rst(slave_class("ServoController"))
    >>> [line for line in text.splitlines() if line.startswith(".. list-table")]
    ['.. list-table:: Inputs', '.. list-table:: Outputs', '.. list-table:: Parameters']
    """
    from servofmu.fmus.declarations import variables_of

    variables = variables_of(cls)
    by = {c: [v for v in variables if v.causality == c] for c in ("input", "output", "parameter")}
    tables = {
        "Inputs": (
            ("name", "unit", "display unit", "start", "range", "description"),
            [
                (v.name, v.unit or "", v.display_unit or "", _start(v), _range(v), v.description)
                for v in by["input"]
            ],
        ),
        "Outputs": (
            ("name", "type", "unit", "display unit", "description", "depends directly on"),
            [
                (
                    v.name,
                    v.type,
                    v.unit or "",
                    v.display_unit or "",
                    v.description,
                    ", ".join(v.depends) or "no input",
                )
                for v in by["output"]
            ],
        ),
        "Parameters": (
            ("name", "type", "unit", "start", "range", "description", "provenance"),
            [
                (v.name, v.type, v.unit or "", _start(v), _range(v), v.description, v.source)
                for v in by["parameter"]
            ],
        ),
    }
    return "\n".join(
        f"{title}\n{'~' * len(title)}\n\n{_list_table(title, head, rows)}"
        for title, (head, rows) in tables.items()
        if rows
    )


def _presets_rst(name: str) -> str:
    """What the presets inside the FMU are, and the catalogue entries they come from."""
    if name not in ("BearingFriction", "ActuatorStiffness"):
        return ""
    from servofmu.parameters import catalog

    prefix = "support\\_…" if name == "ActuatorStiffness" else ""
    kinds = ("mountings", "bearings") if prefix else ("mountings", "bearings", "lubricants")
    items = "\n".join(
        f"- ``resources/presets/{k}/``: "
        + ", ".join(
            f"``{key}``"
            + ("" if catalog.origin(k, key).startswith("data/") else " (user catalogue)")
            for key in catalog.keys(k)
        )
        for k in kinds
    )
    return f"""Presets
~~~~~~~

Every physical input is a numeric parameter{f" ({prefix})" if prefix else ""}, and the model uses
exactly these numbers. The catalogue's entries are presets of them: the start values below are
one preset's numbers, filled in when the FMU was built (with the provenance of each value), and
the FMU carries every preset as an SSP 1.0 parameter set (bind one to the component, or copy its
values): a mounting gives the whole set, a bearing or a lubricant its own numbers.

{items}

"""


def _host_requirements_rst() -> str:
    import numpy
    import scipy

    return f"""Host requirements
-----------------

- FMI 2.0 co-simulation, built with pythonfmu 0.7 (binaries for linux64 and win64). The FMU
  runs inside a CPython interpreter that has numpy and scipy; the servofmu package and
  pythonfmu's runtime are inside the FMU (``resources/``). Built with Python
  {platform.python_version()}, numpy {numpy.__version__}, scipy {scipy.__version__}.
- **Python hosts** (fmpy, libcosimpy, ecospy): the FMU uses the running interpreter and its
  site-packages; nothing to set.
- **Other hosts on Linux** (C/C++ programs): the binary does not link libpython. Export
  ``LD_PRELOAD=<libpython3.x.so>`` and ``PYTHONPATH=<site-packages with numpy and scipy>``
  (``servofmu host-env`` prints both); the interpreter must be built with
  ``--enable-shared``. The host may end with a normal ``exit()``: the FMU registers
  pythonfmu's interpreter finaliser to run before the static destructors of the C++
  extensions.
- **Windows**: ``python3x.dll`` on PATH and PYTHONPATH set (``servofmu host-env``); not
  tested by the project. **macOS**: no binary.
- Every servofmu FMU in one process must come from the same servofmu build: Python imports
  the package once per process, and the FMU refuses to instantiate, naming both versions,
  when it differs.
- Bad inputs or parameters (outside the range, or not finite) make the next step return
  fmi2Discard with a logged message naming the variable and its value. State can be saved,
  restored and serialised (``canGetAndSetFMUstate``, ``canSerializeFMUstate``).
"""


def _docstring(obj) -> str:
    """The docstring of ``obj``, dedented, ``|`` outside math escaped (:func:`escape_bars`)."""
    import inspect

    return escape_bars(inspect.cleandoc(obj.__doc__ or ""))


def _build_defaults_rst(name: str, mechanism) -> str:
    """What this build's start values are: the mechanism's mounting, bearing, lubricant and
    coefficient set (BearingFriction), its network (ThermalNetwork), the support pair
    (ActuatorStiffness); "" for the other FMUs or without a mechanism."""
    if mechanism is None or name not in ("BearingFriction", "ThermalNetwork", "ActuatorStiffness"):
        return ""
    from servofmu.parameters import catalog

    m = mechanism
    where = ", ".join(f for f, _ in m.catalogue_hashes) or "the package's catalogue"
    if name == "BearingFriction":
        text = (
            f"The start values are the preset of mounting ``{m.mounting}`` ({_escape(m.name)}; "
            f"bearing ``{m.bearing}``, lubricant ``{m.lubricant}``), from "
            f"{_escape(catalog.origin('mountings', m.mounting))} ({_escape(where)}). Friction "
            f"coefficients: {_escape(m.coefficients.label)}."
        )
    elif name == "ThermalNetwork":
        text = (
            f"The start values are the network of the parts of mounting ``{m.mounting}`` in "
            "the air of a climatic chamber, derived when the FMU was built (the provenance of "
            "each value says which rest on assumed values)."
            if _build_start(name)
            else "The start values are the preset ``yu2017_gimbal_chamber``: Yu 2017's seeker "
            "gimbal in the air of a climatic chamber."
        )
    else:
        support = m.defaults.support_mounting
        text = (
            f"The support pair's start values are the preset of mounting ``{support}`` "
            f"({_escape(where)})."
            if support
            else "The start values are Liu 2014's actuator with its screw's support pair "
            "(preset ``liu2014_screw_support``)."
        )
    return f"Defaults of this build\n----------------------\n\n{text}\n"


def page_rst(name: str, figure: str | None = None, caption: str = "", mechanism=None) -> str:
    """The documentation of FMU ``name`` as reStructuredText: the source of both its
    ``documentation/index.html`` and its page in the documentation site's FMU reference.

    Parameters
    ----------
    name : str
        The FMU's model identifier, e.g. "DCMotor".
    figure : str, optional
        Path of the characteristic curve's image, relative to the page; without it the page
        has no figure.
    caption : str, optional
        The figure's caption (plain text).
    mechanism : Mechanism, optional
        The build's mechanism (:mod:`.mechanism`): the page says what its start values are.

    Returns
    -------
    str
        Title, description (the modelDescription's, then the FMU module's docstring after its
        summary line), figure, variables (presets; inputs, outputs and parameters with unit,
        start, range and provenance), the equations (the docstrings of the physics modules
        the FMU names in ``PHYSICS``) and the host requirements.

    Examples
    --------
    >>> text = page_rst("DCMotor")
    >>> text.splitlines()[:2], "Equations\\n---------" in text
    (['DCMotor', '======='], True)
    """
    cls = slave_class(name)
    module = importlib.import_module(cls.__module__)
    body = _docstring(module).split("\n\n", 1)  # the summary line repeats the description
    parts = [
        f"{name}\n{'=' * len(name)}\n",
        _escape(cls.description) + ".\n",
        f"servofmu {servofmu.__version__}: FMI 2.0 co-simulation FMU, model identifier "
        f"``{name}``.\n",
        (body[1] + "\n") if len(body) > 1 else "",
        _build_defaults_rst(name, mechanism),
    ]
    if figure is not None:
        parts.append(
            f"Characteristic curve\n--------------------\n\n.. figure:: {figure}\n"
            f"   :alt: characteristic curve of {name}\n\n   {_escape(caption)}\n"
        )
    parts.append(
        "Variables\n---------\n\nSI units; display units are declared in the "
        "modelDescription.\n\n" + _presets_rst(name) + variables_rst(cls)
    )
    equations = ["Equations\n---------\n"]
    for m in cls.PHYSICS:
        title = f"``{m}``"
        equations.append(
            f"{title}\n{'~' * len(title)}\n\n.. currentmodule:: {m}\n\n"
            + _docstring(importlib.import_module(m))
            + "\n"
        )
    parts += equations
    parts.append(_host_requirements_rst())
    return "\n".join(parts)


_STYLE = """body{font-family:sans-serif;max-width:75em;margin:2em auto;padding:0 1em;
line-height:1.4}table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px;
font-size:90%;vertical-align:top}figure img{max-width:100%}code,.literal{background:#f2f2f2}
math[display=block]{margin:0.6em 0;overflow-x:auto}caption{text-align:left;font-weight:bold}"""


def render(name: str, curve: Curve | None = None, strict: bool = False, mechanism=None) -> str:
    """The HTML page of FMU ``name`` (:func:`page_rst` through docutils, equations as
    MathML); with ``curve``, it shows :data:`IMAGE` and its caption.

    Parameters
    ----------
    name : str
        The FMU's model identifier, e.g. "DCMotor".
    curve : Curve, optional
        Its characteristic curve (:data:`CURVES`); without it the page has no figure.
    strict : bool, optional
        Raise on any docutils warning (the tests render every page so).
    mechanism : Mechanism, optional
        The build's mechanism (the page says what its start values are).

    Returns
    -------
    str
        The whole HTML page.

    Examples
    --------
    >>> page = render("DCMotor")
    >>> title = '<h1 class="title">DCMotor</h1>'
    >>> page.splitlines()[0], title in page, IMAGE in page, "<math" in page
    ('<!DOCTYPE html>', True, False, True)
    >>> IMAGE in render("DCMotor", CURVES["DCMotor"]())
    True
    """
    text = page_rst(name, IMAGE if curve else None, curve.caption if curve else "", mechanism)
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{name}</title>
<style>{_STYLE}</style></head><body>
{rst_to_html(text, strict=strict)}
</body></html>
"""


def write_documentation(name: str, folder: Path, mechanism=None) -> Path:
    """Write ``index.html`` and :data:`IMAGE` (the characteristic curve) of FMU ``name`` into
    ``folder``; returns the page's path.

    Parameters
    ----------
    name : str
        The FMU's model identifier, one of :data:`CURVES`.
    folder : str or pathlib.Path
        The folder to write into (created with its parents if missing).
    mechanism : Mechanism, optional
        The build's mechanism (the page says what its start values are).

    Returns
    -------
    pathlib.Path
        ``folder/index.html``.

    Examples
    --------
    DCMotor's curve (500 steps of the motor's own code) is the quickest to compute:

    >>> import tempfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     page = write_documentation("DCMotor", Path(tmp) / "documentation")
    ...     print(page.name, sorted(f.name for f in page.parent.iterdir()))
    index.html ['characteristic.png', 'index.html']
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    curve = CURVES[name]()
    plot_curve(curve, folder / IMAGE)
    path = folder / "index.html"
    path.write_text(render(name, curve, mechanism=mechanism), encoding="utf-8")
    return path
