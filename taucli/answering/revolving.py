"""balance's --mass: "mass=… radius=… angle=… [plane=…] [length=…]", a mass turning with a shaft,
read as every spec is (taucli.answering.specs) into a taucli.scenes.given.Revolving.
"""

from __future__ import annotations

from taucli.answering.reading import Inputs
from taucli.answering.specs import _read_fields, _spec_fields, _specs
from taucli.core.errors import InputError
from taucli.options.table import Option
from taucli.scenes.given import Revolving

REVOLVING_FIELDS = {  # key: (kind, sign)
    "mass": ("mass", "positive"),
    "radius": ("length", "nonnegative"),
    "angle": ("angle", "any"),
    "plane": ("length", "any"),
    "length": ("length", "positive"),
}
EXAMPLE = '{mass} "mass=2kg radius=0.3m angle=45deg"'


def revolving(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each mass: mass= and radius= (or length=, a rod along the radius from radius=, default 0),
    angle= (default 0, counter-clockwise from the reference line), plane= (its position along the shaft)."""
    found = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, REVOLVING_FIELDS, EXAMPLE, shape_word=False)
        if "mass" not in fields:
            raise InputError(source, "needs mass=", example=EXAMPLE, got=repr(spec))
        if "radius" not in fields and "length" not in fields:
            raise InputError(source, "needs radius= (or length=, a rod along the radius from the axis)", example=EXAMPLE, got=repr(spec))
        values = _read_fields(fields, REVOLVING_FIELDS, source, f"mass{number}", inputs, option.name, number - 1)
        found.append(Revolving(source, values["mass"], values.get("radius", 0.0), values.get("angle", 0.0), values.get("plane"), values.get("length")))
    return tuple(found)
