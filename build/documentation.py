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

import functools
import html
import importlib
import math
import platform
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import servofmu

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
    ('DCMotor', 'servofmu.fmus.DCMotor', ('servofmu.physics.motor',))
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
    from servofmu.fmus.slave import BUILD_START

    return bool(BUILD_START.get(name))


def _bearing_curve() -> Curve:
    """Running and breakaway torque versus temperature, −60…+80 °C, at 10 °/s (default
    friction model), and the running torque of the other friction models."""
    celsius = np.arange(-60.0, 80.0 + 1e-9, 2.5)
    speed = math.radians(10.0)
    fmus = [_Slave("BearingFriction", speed=speed)]
    fmus += [_Slave("BearingFriction", {"friction_model": i}, speed=speed) for i in (2, 3)]
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
            ("running torque at 10 °/s (yu2017, default)", torque[:, 0]),
            ("breakaway torque", torque[:, 1]),
            ("running torque, friction_model skf2004", torque[:, 2]),
            ("running torque, friction_model ehl_per_contact", torque[:, 4]),
        ),
        "Default parameters (friction_model yu2017, no grease term) and the other friction "
        "models' running torque, no external load, shaft speed 10 °/s (logarithmic torque "
        "axis). The thermal coupling of frame, shaft and bearings changes fits and preload with "
        "temperature; the lubricant's viscosity adds the viscous part of the running torque. "
        "skf2004 and ehl_per_contact see the bearings' loads: once the preload is lost they "
        "fall below 0.01 N·mm (the axis' end), and SKF's replenishment factor cuts its rolling "
        "torque as the base oil thickens. Outside the range of the lubricant's data "
        "(lubricant_minimum_temperature … lubricant_maximum_temperature; the default Krytox "
        "143AA: −40…+60 °C, Yu's) the output outside_lubricant_range is set, and below its "
        "flow limit (the default's −40 °C) the viscosity is held at its value there: the "
        "torque there follows the fits and the preload only. "
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
@functools.lru_cache(maxsize=1)
def _docutils():
    """docutils' publisher with the Sphinx cross-reference roles of the docstrings
    (``:func:`x```…) rendered as code."""
    from docutils import nodes
    from docutils.core import publish_parts
    from docutils.parsers.rst import roles

    def code(name, rawtext, text, lineno, inliner, options=None, content=None):
        label = text.split(".")[-1] if text.startswith("~") else text.lstrip(".")
        return [nodes.literal(rawtext, label)], []

    for role in ("func", "class", "mod", "meth", "data", "attr", "obj", "exc"):
        roles.register_local_role(role, code)
    return publish_parts


def rst_to_html(text: str) -> str:
    """HTML body of a reStructuredText docstring. ``|x|`` is an absolute value in the
    docstrings, not a substitution; docutils' messages stay out of the page.

    Parameters
    ----------
    text : str or None
        The docstring (reStructuredText; Sphinx roles such as ``:func:`` become code).

    Returns
    -------
    str
        The HTML body (section titles from ``<h4>`` on); empty for an empty docstring.

    Examples
    --------
    >>> print(rst_to_html("The torque ``M`` grows with |F| (:func:`friction_torque`)."))
    <p>The torque <span class="docutils literal">M</span> grows with |F| (<span \
class="docutils literal">friction_torque</span>).</p>
    <BLANKLINE>
    >>> rst_to_html(None)
    ''
    """
    publish_parts = _docutils()
    source = (text or "").replace("|", "\\|")
    parts = publish_parts(
        source,
        writer="html5",
        settings_overrides={
            "report_level": 5,
            "halt_level": 5,
            "doctitle_xform": False,
            "initial_header_level": 4,
            "input_encoding": "unicode",
            "embed_stylesheet": False,
        },
    )
    return parts["body"]


def _range(v) -> str:
    if v.min is None and v.max is None:
        return ""
    lo = "−∞" if v.min is None else f"{v.min:g}"
    hi = "+∞" if v.max is None else f"{v.max:g}"
    return f"[{lo}, {hi}]"


def _start(v) -> str:
    items = getattr(v, "items", None)  # an Enumeration: start is the item's number
    if items and isinstance(v.start, int) and 0 < v.start <= len(items):
        item = items[v.start - 1]
        return f"{v.start} ({getattr(item, 'name', item)})"
    if isinstance(v.start, float):
        return f"{v.start:.10g}"
    return "" if v.start is None else repr(v.start)


def _table(variables, columns) -> str:
    head = "".join(f"<th>{html.escape(c)}</th>" for c, _ in columns)
    rows = [
        "<tr>" + "".join(f"<td>{html.escape(str(get(v)))}</td>" for _, get in columns) + "</tr>"
        for v in variables
    ]
    return f"<table><tr>{head}</tr>\n" + "\n".join(rows) + "\n</table>"


def _variable_tables(cls) -> str:
    from servofmu.fmus.slave import variables_of

    variables = variables_of(cls)  # a build's start values (user catalogue, preset) included
    by = {c: [v for v in variables if v.causality == c] for c in ("input", "output")}
    params = [v for v in variables if v.causality == "parameter"]
    unit = ("unit", lambda v: v.unit or "")
    display = ("display unit", lambda v: v.display_unit or "")
    name = ("name", lambda v: v.name)
    desc = ("description", lambda v: v.description)
    return "\n".join(
        (
            "<h3>Inputs</h3>",
            _table(by["input"], (name, unit, display, ("start", _start), ("range", _range), desc)),
            "<h3>Outputs</h3>",
            _table(
                by["output"],
                (
                    name,
                    ("type", lambda v: v.type),
                    unit,
                    display,
                    desc,
                    ("depends directly on", lambda v: ", ".join(v.depends) or "no input"),
                ),
            ),
            "<h3>Parameters</h3>",
            _table(
                params,
                (
                    name,
                    ("type", lambda v: v.type),
                    unit,
                    ("start", _start),
                    ("range", _range),
                    desc,
                    ("provenance", lambda v: v.source),
                ),
            ),
        )
    )


def _host_requirements() -> str:
    import numpy
    import scipy

    python = platform.python_version()
    return f"""<h2>Host requirements</h2>
<ul>
<li>FMI 2.0 co-simulation, built with pythonfmu 0.7 (binaries for linux64 and win64). The FMU
runs inside a CPython interpreter that has numpy and scipy; the servofmu package and
pythonfmu's runtime are inside the FMU (<code>resources/</code>). Built with Python {python},
numpy {numpy.__version__}, scipy {scipy.__version__}.</li>
<li><b>Python hosts</b> (fmpy, libcosimpy, ecospy): the FMU uses the running interpreter and
its site-packages; nothing to set.</li>
<li><b>Other hosts on Linux</b> (C/C++ programs): the binary does not link libpython. Export
<code>LD_PRELOAD=&lt;libpython3.x.so&gt;</code> and
<code>PYTHONPATH=&lt;site-packages with numpy and scipy&gt;</code>
(<code>servofmu host-env</code> prints both); the interpreter must be built with
<code>--enable-shared</code>. The host may end with a normal <code>exit()</code>: the FMU
registers pythonfmu's interpreter finaliser to run before the static destructors of the
C++ extensions (see <code>servofmu.fmus.interpreter_exit</code>).</li>
<li><b>Windows</b>: <code>python3x.dll</code> on PATH and PYTHONPATH set
(<code>servofmu host-env</code>); not tested by the project. <b>macOS</b>: no binary.</li>
<li>Every servofmu FMU in one process must come from the same servofmu build: Python imports
the package once per process, and the FMU refuses to instantiate, naming both versions, when
it differs.</li>
<li>Bad inputs or parameters (outside the range, or not finite) make the next step return
fmi2Discard with a logged message naming the variable and its value. State can be saved,
restored and serialised (<code>canGetAndSetFMUstate</code>,
<code>canSerializeFMUstate</code>).</li>
</ul>"""


def _presets(name: str) -> str:
    """What the presets inside the FMU are, and the catalogue entries they come from."""
    if name not in ("BearingFriction", "ActuatorStiffness"):
        return ""
    from servofmu.physics import catalog

    prefix = "support_" if name == "ActuatorStiffness" else ""
    kinds = ("mountings", "bearings") if prefix else ("mountings", "bearings", "lubricants")
    rows = "".join(
        f"<li><code>resources/presets/{k}/</code>: "
        + ", ".join(
            f"<code>{html.escape(key)}</code>"
            + ("" if catalog.origin(k, key).startswith("data/") else " (user catalogue)")
            for key in catalog.keys(k)
        )
        + "</li>"
        for k in kinds
    )
    return f"""<h3>Presets</h3>
<p>Every physical input is a numeric parameter{" (support_…)" if prefix else ""}, and the
model uses exactly these numbers. The catalogue's entries are presets of them: the start
values below are one preset's numbers, filled in when the FMU was built (with the provenance of
each value), and the FMU carries every preset as an SSP 1.0 parameter set (bind one to the
component, or copy its values): a mounting gives the whole set, a bearing or a lubricant its
own numbers.</p>
<ul>{rows}</ul>"""


def _build_defaults(name: str, mechanism) -> str:
    """What this build's start values are: the mechanism's mounting, bearing, lubricant and
    coefficient set (BearingFriction), its network (ThermalNetwork), the support pair
    (ActuatorStiffness)."""
    if mechanism is None or name not in ("BearingFriction", "ThermalNetwork", "ActuatorStiffness"):
        return ""
    from servofmu.physics import catalog

    m = mechanism
    where = ", ".join(f for f, _ in m.catalogue_hashes) or "the package's catalogue"
    if name == "BearingFriction":
        text = (
            f"The start values are the preset of mounting <code>{html.escape(m.mounting)}"
            f"</code> ({html.escape(m.name)}; bearing <code>{html.escape(m.bearing)}</code>, "
            f"lubricant <code>{html.escape(m.lubricant)}</code>), from "
            f"{html.escape(catalog.origin('mountings', m.mounting))} ({html.escape(where)}). "
            f"Friction coefficients: {html.escape(m.coefficients.label)}."
        )
    elif name == "ThermalNetwork":
        text = (
            "The start values are the network of the parts of mounting "
            f"<code>{html.escape(m.mounting)}</code> in the air of a climatic chamber, derived "
            "when the FMU was built (the provenance of each value says which rest on assumed "
            "values)."
            if _build_start(name)
            else "The start values are the preset <code>yu2017_gimbal_chamber</code>: Yu "
            "2017's seeker gimbal in the air of a climatic chamber."
        )
    else:
        support = m.defaults.support_mounting
        text = (
            f"The support pair's start values are the preset of mounting <code>"
            f"{html.escape(support)}</code> ({html.escape(where)})."
            if support
            else "The start values are Liu 2014's actuator with its screw's support pair "
            "(preset <code>liu2014_screw_support</code>)."
        )
    return f"<h2>Defaults of this build</h2>\n<p>{text}</p>"


def render(name: str, curve: Curve | None = None, mechanism=None) -> str:
    """The HTML page of FMU ``name``; with ``curve``, it shows :data:`IMAGE` and its caption.

    Parameters
    ----------
    name : str
        The FMU's model identifier, e.g. "DCMotor".
    curve : Curve, optional
        Its characteristic curve (:data:`CURVES`); without it the page has no figure.
    mechanism : Mechanism, optional
        The build's mechanism (:mod:`.mechanism`): the page says what its start values are.

    Returns
    -------
    str
        The whole HTML page: description, module docstring, figure, variables with units,
        start values, ranges and provenance, the physics modules' docstrings, host
        requirements.

    Examples
    --------
    >>> page = render("DCMotor")
    >>> page.splitlines()[0], "<h1>DCMotor</h1>" in page, IMAGE in page
    ('<!DOCTYPE html>', True, False)
    >>> IMAGE in render("DCMotor", CURVES["DCMotor"]())
    True
    """
    cls = slave_class(name)
    module = importlib.import_module(cls.__module__)
    physics = "".join(
        f"<h3><code>{m}</code></h3>\n{rst_to_html(importlib.import_module(m).__doc__)}"
        for m in cls.PHYSICS
    )
    figure = ""
    if curve is not None:
        figure = (
            f'<h2>Characteristic curve</h2>\n<figure><img src="{IMAGE}" '
            f'alt="{html.escape(curve.title)}"><figcaption>{html.escape(curve.caption)}'
            "</figcaption></figure>"
        )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{name}</title>
<style>body{{font-family:sans-serif;max-width:75em;margin:2em auto;line-height:1.4}}
table{{border-collapse:collapse}}td,th{{border:1px solid #ccc;padding:2px 6px;font-size:90%}}
blockquote{{font-family:serif;font-size:105%;background:#f6f6f6;margin:0.5em 2em;
padding:0.3em 1em}}figure img{{max-width:100%}}code{{background:#f2f2f2}}</style></head><body>
<h1>{name}</h1>
<p>{html.escape(cls.description)}</p>
<p>servofmu {servofmu.__version__}: FMI 2.0 co-simulation FMU, model identifier
<code>{name}</code>.</p>
{rst_to_html(module.__doc__)}
{_build_defaults(name, mechanism)}
{figure}
<h2>Variables</h2>
<p>SI units; display units are declared in the modelDescription.</p>
{_presets(name)}
{_variable_tables(cls)}
<h2>Equations</h2>
{physics}
{_host_requirements()}
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
    path.write_text(render(name, curve, mechanism), encoding="utf-8")
    return path
