"""Command-line text to SI floats, remembering what was given for the report's ``inputs``."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from taucli import units
from taucli.errors import InputError
from taucli.report import Value

# The dimension options of a shape, as in ``taucli inertia`` and ``--shape``.
SHAPE_DIMENSIONS = ("radius", "inner_radius", "outer_radius", "length", "width", "height", "depth")


@dataclass
class Inputs:
    """Reads options one by one; keeps each value as given in SI, and any notes on reading it."""

    values: dict[str, Value] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def quantity(self, option: str, text: str | None, kind: str, *, sign: str = "positive", key: str | None = None) -> float | None:
        """The SI value of ``text`` read as ``kind``; None when the option was not given."""
        if text is None:
            return None
        parsed = units.parse(text, option, kind, sign=sign)
        name = key or option.lstrip("-").replace("-", "_")
        self.values[name] = Value(parsed.value, units.KINDS[kind].si_unit, "")
        if parsed.note:
            self.notes.append(parsed.note)
        return parsed.value

    def assume(self, name: str, value: float, kind: str, note: str) -> float:
        """A value the user did not give, recorded as an input, with a note that says so."""
        self.values[name] = Value(value, units.KINDS[kind].si_unit, "")
        self.notes.append(note)
        return value

    def required(self, option: str, text: str | None, kind: str, *, sign: str = "positive", why: str = "") -> float:
        """As ``quantity``, but the option must be given."""
        if text is None:
            raise InputError(option, f"is required{why}", example=f"{option} {units.KINDS[kind].example.replace(' ', '')}")
        value = self.quantity(option, text, kind, sign=sign)
        assert value is not None
        return value


_PART_KEY = re.compile(r"\s+(?=[a-z][a-z-]*=)")


def parse_part_spec(spec: str, number: int, inputs: Inputs):
    """A ``--part`` value such as "point mass=100g offset=20cm" as an inertia Part."""
    from taucli.scenes.inertia import Part

    source = f"--part {number}"
    words = _PART_KEY.split(spec.strip())
    shape, *pairs = words
    if not shape or "=" in shape:
        raise InputError(source, "expected a shape then key=value pairs", example='--part "point mass=100g offset=20cm"', got=repr(spec))
    fields: dict[str, str] = {}
    for pair in pairs:
        key, _, text = pair.partition("=")
        fields[key.replace("-", "_")] = text.strip()
    known = {"mass", "axis", "offset", *SHAPE_DIMENSIONS}
    for key in fields:
        if key not in known:
            raise InputError(source, f"knows {', '.join(sorted(k.replace('_', '-') for k in known))}", got=repr(key.replace("_", "-")))
    if "mass" not in fields:
        raise InputError(source, "needs mass=", example='--part "point mass=100g offset=20cm"', got=repr(spec))

    def read(key: str, kind: str, sign: str = "positive") -> float:
        return inputs.quantity(f"{source} {key.replace('_', '-')}=", fields[key], kind, sign=sign, key=f"part{number}_{key}")

    dims = {key: read(key, "length", "nonnegative" if key == "inner_radius" else "positive") for key in SHAPE_DIMENSIONS if key in fields}
    offset = read("offset", "length", "nonnegative") if "offset" in fields else None
    return Part(shape, read("mass", "mass"), dims, fields.get("axis"), offset, source)
