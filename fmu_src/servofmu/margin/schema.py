"""The schema of the margin input's tables whose values the reader hands on without knowing
their types: the parameter changes of the mechanism (``mechanism.parameters``,
``end_of_life.parameters``: a Boolean is not a number, a count is an integer, a choice is an
item's name), the tolerance bands (``tolerances.bands``: the unit of the dimension of the
parameter they draw), and the title. The rest of the file (sections, keys, quantities and their
units by kind) is checked by :mod:`.inputs` as it is read.

JSON Schema checked with :mod:`jsonschema`, the units' dimensions from :mod:`pint`
(:mod:`servofmu.build.schema`); none of them is imported by an FMU.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping


def _value_schema(spec) -> dict:
    """The schema of a value given to parameter ``spec`` (a ParameterSpec)."""
    if spec.type == "Real":
        return {"type": "number"}
    if spec.type == "Integer":
        return {"type": "integer"}
    return {"enum": [c.key for c in spec.choices if c.key]}


@functools.cache
def input_schema() -> dict:
    """The JSON Schema of the parts of a margin input file listed in the module docstring.

    Returns
    -------
    dict

    Examples
    --------
    >>> input_schema()["properties"]["mechanism"]["properties"]["parameters"]["properties"][
    ...     "shim"]
    {'type': 'number'}
    """
    from servofmu.build.schema import TEXT, tolerance_band
    from servofmu.harness.tolerance import SEAT_BANDS
    from servofmu.parameters.bearing import PARAMETERS, PRESETS
    from servofmu.physics.kernels.units import TO_SI

    changes = {
        "type": "object",
        "properties": {
            **{spec.name: _value_schema(spec) for spec in PARAMETERS},
            **{name: TEXT for name in PRESETS},
        },
    }
    bands = {name: tolerance_band("m") for name in SEAT_BANDS}
    for spec in PARAMETERS:
        if spec.type == "Real" and spec.name not in bands:
            bands[spec.name] = tolerance_band(spec.unit if spec.unit in TO_SI else None)
    for band in bands.values():
        band["required"] = ["low", "high", "unit"]  # kind and ref optional here
    return {
        "type": "object",
        "properties": {
            "title": TEXT,
            "mechanism": {"type": "object", "properties": {"parameters": changes}},
            "end_of_life": {"type": "object", "properties": {"parameters": changes}},
            "tolerances": {
                "type": "object",
                "properties": {
                    "bands": {
                        "anyOf": [
                            {"const": "catalogue"},
                            {"type": "object", "properties": bands},
                        ]
                    }
                },
            },
        },
    }


def schema_problems(data: Mapping) -> list[str]:
    """The problems of margin input ``data`` (as read from TOML) against :func:`input_schema`,
    each naming the key, what was given and what is allowed.

    Parameters
    ----------
    data : mapping
        The input file as read.

    Returns
    -------
    list of str
        Empty when it fits.

    Examples
    --------
    >>> schema_problems({"mechanism": {"parameters": {"shim": True}}})
    ['mechanism.parameters.shim = true is a Boolean, not a number']
    >>> band = {"low": -1, "high": 1, "unit": "MPa"}
    >>> schema_problems({"tolerances": {"bands": {"shim": band}}})  # doctest: +ELLIPSIS
    ["tolerances.bands.shim.unit = 'MPa' (a unit of pressure) is not a unit of length: ..."]
    """
    import jsonschema

    from servofmu.build.schema import message

    validator = jsonschema.Draft202012Validator(input_schema())
    out = []
    for error in sorted(validator.iter_errors(data), key=lambda e: list(e.absolute_path)):
        if error.validator == "anyOf":  # the bands: name the error of the table's branch
            inner = [e for e in error.context if e.validator != "const"]
            out += [message(e, "").strip() for e in inner] or [message(error, "").strip()]
        else:
            out.append(message(error, "").strip())
    return out
