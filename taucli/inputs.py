"""Reading a command's inputs: one loop over its table, from text (or SI numbers) to SI values.

Every way in (a command line, a sweep's point, a batch line, a Python call) arrives here as a
mapping of option names to what was given, and leaves as the keyword arguments of the scene's
library function, with the inputs echoed in SI for the report and any notes their reading raised.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TextIO

from taucli import units
from taucli.errors import InputError, did_you_mean
from taucli.report import Value
from taucli.table import CHOICE, COUNT, FILE, FLAG, PART, TEXT, Command, Option
from taucli.table import VECTOR
from taucli.table import COUPLE, PARTICLE
from taucli.table import BRAKE, FACE


@dataclass
class Inputs:
    """What was read: each value as given, in SI, and any notes on reading it."""

    values: dict[str, Value] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    gravity: float | None = None  # the scene's --g, for a weight given as a mass
    uncertainties: dict[str, float] | None = None  # "4.0+/-0.1 kg": each σ in SI (taucli.uncertain)

    def quantity(self, name: str, given, kind: str, *, sign: str = "positive", key: str | None = None) -> float | None:
        """The SI value of ``given``: text with a unit, or a number, which is SI."""
        if given is None:
            return None
        if given.__class__ is str and (value := units.known(given, kind, sign)) is not None:  # most texts of a batch
            self.values[key or name] = Value(value, units.KINDS[kind].si_unit, "")
            return value
        option = name if name.startswith("{") else "{" + name + "}"
        if isinstance(given, str):
            if "±" in given or "+/-" in given or ")" in given:
                given = self._uncertain(given, option, kind, key or name)
            parsed = units.parse(given, option, kind, sign=sign, gravity=self.gravity)
            value, note = parsed.value, parsed.note
        elif isinstance(given, (int, float)) and not isinstance(given, bool):
            value, note = units.si_number(given, option, kind, sign=sign), None
        else:
            raise InputError(name, "expected a number or a text with a unit", example='"4kg"', got=repr(given))
        self.values[key or name] = Value(value, units.KINDS[kind].si_unit, "")
        if note:
            self.notes.append(note)
        return value

    def _uncertain(self, given: str, option: str, kind: str, key: str) -> str:
        """The value's text of "4.0+/-0.1 kg", its uncertainty kept (SI) under ``key``."""
        from taucli.uncertain import split

        parts = split(given)
        if parts is None:
            return given
        spread = units.parse(parts[1], option + " (its uncertainty)", kind, sign="nonnegative", gravity=self.gravity).value
        self.uncertainties = {**(self.uncertainties or {}), key: spread}
        return parts[0]


def read(command: Command, given: Mapping[str, object], *, stdin: TextIO | None = None) -> tuple[dict[str, object], Inputs]:
    """The keyword arguments of ``command``'s library function from the options ``given``.

    ``given`` holds option names (``pulley_mass``; ``pulley-mass`` reads too) and what was given
    for each (None: not given). Names that are not the command's options are refused.
    """
    inputs = Inputs()
    arguments: dict[str, object] = {}
    if not command.input_names.issuperset(given):
        name = next(name for name in given if name not in command.input_names)
        raise InputError(name, f"is not an option of {command.name}", hint=did_you_mean(name, sorted(command.input_names)))
    gravity = command.option("g")
    if gravity is not None and given.get("g") is not None:  # first: a weight given for a mass needs it
        inputs.gravity = arguments["g"] = READERS[gravity.kind](gravity, given["g"], inputs, stdin)
    for name in command.in_order(given):  # what was given, not the whole table: a scene has dozens of options
        value = given[name]
        if value is None or value == () or value == [] or value is False or name in arguments:
            continue
        option = command.option(name)
        arguments[name] = READERS[option.kind](option, value, inputs, stdin)
    return arguments, inputs


def _quantity(option: Option, given, inputs: Inputs, stdin) -> float | None:
    return inputs.quantity(option.name, given, option.kind, sign=option.sign)


def _choice(option: Option, given, inputs: Inputs, stdin):
    if option.repeatable:
        return tuple(_word(option, item) for item in (given if isinstance(given, (list, tuple)) else [given]))
    return _word(option, given)


def _word(option: Option, given) -> str:
    if not isinstance(given, str):
        raise InputError(option.name, f"expected one of {', '.join(option.choices)}", got=repr(given))
    return given.strip()


def _flag(option: Option, given, inputs: Inputs, stdin) -> bool:
    if not isinstance(given, bool):
        raise InputError(option.name, "expected true or false", got=repr(given))
    return given


def _parts(option: Option, given, inputs: Inputs, stdin) -> tuple:
    specs = given if isinstance(given, (list, tuple)) else [given]
    return tuple(parse_part_spec(_word(option, spec), number, inputs) for number, spec in enumerate(specs, start=2))


def _file(option: Option, given, inputs: Inputs, stdin):
    """A torque profile from its CSV file (or stdin for -), streamed: its samples as they are read."""
    from taucli.profile import read_profile

    source = _word(option, given)
    if source == "-":
        if stdin is None:
            raise InputError(option.name, "cannot be - here: no stdin to read it from", example='"torque_profile": "pulse.csv"')
        profile = read_profile(stdin)
    else:
        try:
            handle = open(source, encoding="utf-8")  # noqa: SIM115 (closed when its samples are read, or by the collector)
            profile = read_profile(handle)
        except OSError as err:
            raise InputError(option.name, "expected a readable CSV file (or - for stdin)", got=f"{source!r}: {err.strerror}") from None
        except UnicodeDecodeError:
            raise InputError(option.name, "expected a UTF-8 text file", got=repr(source)) from None
        profile.samples = _decoded(profile.samples, source, option.name)
    inputs.notes.extend(profile.notes)
    return profile.samples


def _decoded(samples, source: str, name: str):
    try:
        yield from samples
    except UnicodeDecodeError:
        raise InputError(name, "expected a UTF-8 text file", got=repr(source)) from None


def _count(option: Option, given, inputs: Inputs, stdin) -> int:
    try:
        return int(given)
    except (TypeError, ValueError):
        raise InputError(option.name, "expected a whole number", example=f"{{{option.name}}} 50", got=repr(given)) from None


def _as_given(option: Option, given, inputs: Inputs, stdin):
    return given


READERS = {FLAG: _flag, CHOICE: _choice, PART: _parts, FILE: _file, COUNT: _count, TEXT: _as_given}
READERS.update({kind: _quantity for kind in units.KINDS})


_PART_KEY = re.compile(r"\s+(?=[a-z][a-z_-]*=)")
PART_DIMENSIONS = ("radius", "inner_radius", "outer_radius", "length", "width", "height", "depth")


def parse_part_spec(spec: str, number: int, inputs: Inputs):
    """A ``--part`` value such as "point mass=100g offset=20cm" as an inertia Part.

    A part is a shape with mass= (or density=) and its dimensions, or its own I: inertia=
    (with mass= and offset=, I_cm moved by the parallel-axis theorem) or gyration= with mass=;
    those need no shape word. Keys read with - or _ (inner-radius=, inner_radius=).
    """
    from taucli.scenes.inertia import Part

    source = f"{{part}} {number}"
    words = _PART_KEY.split(spec.strip())
    shape, *pairs = words
    if shape and "=" in shape:
        shape, pairs = "", words
    if not words or not words[0]:
        raise InputError(source, "expected a shape then key=value pairs", example='{part} "point mass=100g offset=20cm"', got=repr(spec))
    fields: dict[str, str] = {}
    for pair in pairs:
        key, _, text = pair.partition("=")
        fields[key.replace("-", "_")] = text.strip()
    known = {"mass", "axis", "offset", "inertia", "gyration", "density", *PART_DIMENSIONS}
    for key in fields:
        if key not in known:
            raise InputError(source, f"knows {', '.join(sorted(k.replace('_', '-') for k in known))}", got=repr(key.replace("_", "-")))
    given_inertia = "inertia" in fields or "gyration" in fields
    if not shape and not given_inertia:
        raise InputError(source, "expected a shape then key=value pairs (or inertia= or gyration=)", example='{part} "point mass=100g offset=20cm"', got=repr(spec))
    if shape and given_inertia:
        raise InputError(source, "takes a shape or inertia=/gyration=, not both", got=repr(spec))
    if "mass" not in fields and "density" not in fields and "inertia" not in fields:
        raise InputError(source, "needs mass= (or density=, or inertia=)", example='{part} "point mass=100g offset=20cm"', got=repr(spec))

    def read_field(key: str, kind: str, sign: str = "positive") -> float:
        return inputs.quantity(f"{source} {key.replace('_', '-')}=", fields[key], kind, sign=sign, key=f"part{number}_{key}")

    dims = {key: read_field(key, "length", "nonnegative" if key == "inner_radius" else "positive") for key in PART_DIMENSIONS if key in fields}
    offset = read_field("offset", "length", "nonnegative") if "offset" in fields else None
    mass = read_field("mass", "mass") if "mass" in fields else None
    inertia = read_field("inertia", "moment of inertia") if "inertia" in fields else None
    gyration = read_field("gyration", "length") if "gyration" in fields else None
    density = _read_density(source, fields["density"], inputs, number) if "density" in fields else None
    return Part(shape, mass, dims, fields.get("axis"), offset, source, inertia, gyration, density)


def _read_density(source: str, text: str, inputs: Inputs, number: int) -> float:
    """A part's density (kg/m³), read as every quantity is."""
    return inputs.quantity(f"{source} density=", text, "density", key=f"part{number}_density")


# Vectors ("0.3,0.4,0 m") and quantities given more than once (--mass 2kg --mass 3kg).
_NUMBER_THEN_UNIT = re.compile(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*?)\s*$")
AXES = ("x", "y", "z")


def _vectors(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each value of a VECTOR option: "x,y,z UNIT" as its three SI components (a tuple), or a lone
    "20 N" as one signed SI number (a scene that takes a size alone says so; the others refuse it).
    Python and batch may give a vector as three SI numbers: [0.3, 0.4, 0]."""
    items = [given] if isinstance(given, str) or _is_triple(given) else list(given) if isinstance(given, (list, tuple)) else [given]
    read = []
    for number, item in enumerate(items, start=1):
        name = f"{{{option.name}}}" + (f" {number}" if len(items) > 1 else "")
        key = option.name + (str(number) if len(items) > 1 else "")
        read.append(read_vector(item, name, option.of, inputs, key))
    return tuple(read)


def _text(given, name: str) -> str:
    """An SI number as the text a bare number is (a bare number means the SI unit)."""
    if isinstance(given, str):
        return given
    if isinstance(given, (int, float)) and not isinstance(given, bool):
        if isinstance(given, float) and not math.isfinite(given):
            raise InputError(name, "expected a finite number", got=repr(given))
        return repr(float(given)) if isinstance(given, float) else str(given)
    raise InputError(name, "expected a number or a text with a unit", example='"4kg"', got=repr(given))


def _is_triple(given) -> bool:
    return isinstance(given, (list, tuple)) and len(given) == 3 and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in given)


def read_vector(given, name: str, kind: str, inputs: Inputs, key: str):
    """One vector "x,y,z UNIT" (one unit after the last component, or a unit on each) in SI."""
    si = units.KINDS[kind].si_unit
    example = f'{name.split()[0]} "0.3,0.4,0 {si or "1"}"'
    if _is_triple(given):
        components = [_text(x, name) for x in given]
    else:
        text = _text(given, name).strip()
        if text[:1] + text[-1:] in ("()", "[]", "<>"):
            text = text[1:-1]
        components = [part.strip() for part in text.split(",")]
    if len(components) == 1:
        return inputs.quantity(name, components[0], kind, sign="any", key=key)
    if len(components) != 3:
        raise InputError(name, "expected three components x,y,z with a unit", example=example, got=repr(given))
    split = [_NUMBER_THEN_UNIT.fullmatch(part) for part in components]
    bare = [match is not None and not match[2] for match in split]
    if bare[0] and bare[1] and not bare[2] and split[2] is not None:
        components = [f"{part} {split[2][2]}" for part in components[:2]] + components[2:]
    elif any(bare) and not all(bare):
        raise InputError(name, "expected one unit after the last component, or a unit on each", example=example, got=repr(given))
    vector = tuple(units.parse(part, f"{name} ({axis})", kind, sign="any") for part, axis in zip(components, AXES))
    inputs.notes.extend(parsed.note for parsed in vector if parsed.note)
    inputs.values[key] = Value([parsed.value for parsed in vector], si, "")
    return tuple(parsed.value for parsed in vector)


def _repeated(option: Option, given, inputs: Inputs, stdin):
    """A quantity option: one value, or (repeatable) each value given, as a tuple."""
    if option.words and isinstance(given, str) and given.strip().lower() in option.words:
        inputs.values[option.name] = Value(given.strip().lower(), None, "")
        return given.strip().lower()
    if not option.repeatable:
        return _quantity(option, given, inputs, stdin)
    items = list(given) if isinstance(given, (list, tuple)) else [given]
    keys = [option.name + (str(number) if len(items) > 1 else "") for number in range(1, len(items) + 1)]
    names = [f"{{{option.name}}}" + (f" {number}" if len(items) > 1 else "") for number in range(1, len(items) + 1)]
    return tuple(inputs.quantity(name, item, option.kind, sign=option.sign, key=key) for name, item, key in zip(names, items, keys))


READERS.update({kind: _repeated for kind in units.KINDS})
READERS[VECTOR] = _vectors


# --particle and --couple of impulse (#20): "key=value ..." specs like --part's.
PARTICLE_FIELDS = {  # key: (kind, sign)
    "mass": ("mass", "positive"),
    "speed": ("velocity", "any"),
    "radius": ("length", "nonnegative"),
    "angle": ("angle", "nonnegative"),
    "speed_after": ("velocity", "any"),
    "radius_after": ("length", "nonnegative"),
    "e": ("dimensionless", "nonnegative"),
}
COUPLE_FIELDS = {"inertia": ("moment of inertia", "nonnegative"), "omega0": ("angular velocity", "any"), "mass": ("mass", "positive"),
                 "offset": ("length", "nonnegative"), **{key: ("length", "nonnegative" if key == "inner_radius" else "positive") for key in PART_DIMENSIONS}}


_SPEC_KEY = re.compile(r"\s+(?=[a-z][a-z0-9_-]*\s*=)")


def _spec_fields(spec: str, source: str, known, example: str, *, shape_word: bool) -> tuple[str | None, dict[str, str]]:
    """A spec's leading word (where it may have one) and its key=value pairs, keys in snake case."""
    words = _SPEC_KEY.split(" " + spec.strip())
    first, *pairs = [word for word in words if word.strip()] or [""]
    shape = None
    if "=" not in first:
        if not shape_word or not first:
            raise InputError(source, "expected key=value pairs", example=example, got=repr(spec))
        shape = first.strip()
    else:
        pairs = [first, *pairs]
    fields: dict[str, str] = {}
    for pair in pairs:
        key, _, text = pair.partition("=")
        key = key.strip().replace("-", "_")
        if key not in known:
            raise InputError(source, f"knows {', '.join(sorted(k.replace('_', '-') for k in known))}", example=example, got=repr(key.replace("_", "-")))
        if key in fields:
            raise InputError(source, f"has {key.replace('_', '-')}= twice", example=example, got=repr(spec))
        fields[key] = text.strip()
    return shape, fields


def _read_fields(fields: dict[str, str], table: dict, source: str, prefix: str, inputs: Inputs) -> dict[str, float]:
    return {key: inputs.quantity(f"{source} {key.replace('_', '-')}=", text, table[key][0], sign=table[key][1], key=f"{prefix}_{key}")
            for key, text in fields.items() if key in table}


def _specs(option: Option, given):
    """Each "key=value ..." spec given for a repeatable spec option: (its number, the name its
    messages use: "{brake}", or "{brake} 2" where several are given, the spec's text)."""
    specs = given if isinstance(given, (list, tuple)) else [given]
    for number, spec in enumerate(specs, start=1):
        source = "{" + option.name + "}" + (f" {number}" if len(specs) > 1 else "")
        yield number, source, _word(option, spec)


def _particles(option: Option, given, inputs: Inputs, stdin) -> tuple:
    from taucli.scenes.impulse import Particle

    example = '{particle} "mass=30kg speed=4m/s radius=2m"'
    particles = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, PARTICLE_FIELDS, example, shape_word=False)
        for needed in ("mass", "radius"):
            if needed not in fields:
                raise InputError(source, f"needs {needed}=", example=example, got=repr(spec))
        values = _read_fields(fields, PARTICLE_FIELDS, source, f"particle{number}", inputs)
        particles.append(Particle(source=source, **values))
    return tuple(particles)


def _couples(option: Option, given, inputs: Inputs, stdin) -> tuple:
    from taucli.scenes.impulse import Couple
    from taucli.scenes.inertia import Part

    example = '{couple} "inertia=3kg*m^2 omega0=0", or {couple} "disc mass=2kg radius=0.1m omega0=100rpm"'
    couples = []
    for number, source, spec in _specs(option, given):
        shape, fields = _spec_fields(spec, source, {*COUPLE_FIELDS, "axis"}, example, shape_word=True)
        values = _read_fields(fields, COUPLE_FIELDS, source, f"couple{number}", inputs)
        if (shape is None) == ("inertia" not in values):
            raise InputError(source, "needs inertia= or a shape with its mass and dimensions (one of them)", example=example, got=repr(spec))
        dims = {key: values[key] for key in PART_DIMENSIONS if key in values}
        if shape is None and (dims or "mass" in values or "offset" in values or "axis" in fields):
            raise InputError(source, "takes a shape's mass and dimensions only after a shape word; with inertia= they are not used", example=example, got=repr(spec))
        part = None if shape is None else Part(shape, values.get("mass", 0.0), dims, fields.get("axis"), values.get("offset"), source)
        if part is not None and "mass" not in values:
            raise InputError(source, "needs mass= with a shape", example=example, got=repr(spec))
        couples.append(Couple(source=source, inertia=values.get("inertia"), part=part, omega0=values.get("omega0")))
    return tuple(couples)


READERS[PARTICLE] = _particles
READERS[COUPLE] = _couples


# --brake and --face of spin-down (#24): "key=value ..." specs like --particle's.
_MU_FIELDS = {"mu": ("dimensionless", "nonnegative"), "mu_k": ("dimensionless", "nonnegative"), "mu_s": ("dimensionless", "nonnegative")}
BRAKE_FIELDS = {**_MU_FIELDS, "force": ("force", "nonnegative"), "radius": ("length", "positive")}
FACE_FIELDS = {**_MU_FIELDS, "force": ("force", "nonnegative"), "inner_radius": ("length", "nonnegative"), "outer_radius": ("length", "positive"),
               "surfaces": ("dimensionless", "positive")}


def _brakes(option: Option, given, inputs: Inputs, stdin) -> tuple:
    from taucli.scenes.contact import Brake, coefficients

    example = '{brake} "force=100N mu=0.4 radius=0.5m"'
    brakes = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, BRAKE_FIELDS, example, shape_word=False)
        if "force" not in fields:
            raise InputError(source, "needs force=", example=example, got=repr(spec))
        values = _read_fields(fields, BRAKE_FIELDS, source, f"brake{number}", inputs)
        mu_k, mu_s = coefficients(source, values)
        brakes.append(Brake(source, values["force"], mu_k, mu_s, values.get("radius")))
    return tuple(brakes)


def _faces(option: Option, given, inputs: Inputs, stdin) -> tuple:
    from taucli.scenes.contact import PRESSURES, Face, coefficients

    example = '{face} "mu=0.2", or {face} "mu=0.3 force=2kN inner-radius=5cm outer-radius=12cm pressure=wear surfaces=2"'
    faces = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, {*FACE_FIELDS, "pressure"}, example, shape_word=False)
        values = _read_fields(fields, FACE_FIELDS, source, f"face{number}", inputs)
        mu_k, mu_s = coefficients(source, values)
        pressure = fields.get("pressure", "uniform")
        if pressure not in PRESSURES:
            raise InputError(source, f"pressure= is one of {', '.join(PRESSURES)}", example=example, got=repr(pressure))
        surfaces = values.get("surfaces", 1.0)
        if surfaces != int(surfaces):
            raise InputError(source, "surfaces= is a whole number", example=example, got=repr(fields["surfaces"]))
        faces.append(Face(source, mu_k, mu_s, values.get("force"), values.get("inner_radius"), values.get("outer_radius"), pressure, int(surfaces)))
    return tuple(faces)


READERS[BRAKE] = _brakes
READERS[FACE] = _faces
