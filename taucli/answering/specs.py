"""Options given as "key=value" specs, and vectors: a part of a body, a particle, another body on
the axis, a block of the Atwood machine; "x,y,z UNIT" (the contacts, brakes, faces and bands, in
taucli.answering.contact_specs). Each spec's keys are quantities read as
every quantity is (taucli.answering.reading), into the records of taucli.scenes.given.
"""

from __future__ import annotations

import math
import re

from taucli.quantities import units
from taucli.core.errors import InputError
from taucli.answering.reading import Inputs, Origin, word
from taucli.writing.report import Value, fmt
from taucli.scenes.given import SURFACES, Couple, Part, Particle, Pull, Rotor, Side
from taucli.options.table import Option


def coefficients(source: str, values: dict) -> tuple[float, float | None]:
    """μk and μs from mu= (the kinetic value) or mu-k= and mu-s=."""
    mu, mu_k, mu_s = values.get("mu"), values.get("mu_k"), values.get("mu_s")
    if mu is not None and mu_k is not None:
        raise InputError(source, "has mu= and mu-k=: mu= is the kinetic value, give it once")
    mu_k = mu if mu_k is None else mu_k
    if mu_k is None:
        raise InputError(source, "needs mu= (or mu-k=, with mu-s= for the static value)")
    if mu_s is not None and mu_s < mu_k:
        raise InputError(source, "has mu-s= below the kinetic μ (static friction is at least kinetic)", got=f"{fmt(mu_s)} < {fmt(mu_k)}")
    return mu_k, mu_s


def parts(option: Option, given, inputs: Inputs, stdin) -> tuple:
    specs = given if isinstance(given, (list, tuple)) else [given]
    signed = option.sign == "any"  # (pendulum: a part on the other side of the pivot has a negative offset=)
    name = option.name  # part, or part_after (impulse: the body after a change)
    start = 2 if name == "part" else 1
    return tuple(parse_part_spec(word(option, spec), number, inputs, signed_offset=signed, name=name, index=number - start) for number, spec in enumerate(specs, start=start))


PART_DIMENSIONS = ("radius", "inner_radius", "outer_radius", "length", "width", "height", "depth")
PART_FIELDS = {  # key: (kind, sign), as parse_part_spec reads each
    **{key: ("length", "nonnegative" if key == "inner_radius" else "positive") for key in PART_DIMENSIONS},
    "offset": ("length", "nonnegative"),
    "mass": ("mass", "positive"),
    "inertia": ("moment of inertia", "positive"),
    "gyration": ("length", "positive"),
    "density": ("density", "positive"),
    "angle": ("angle", "any"),
}


def parse_part_spec(spec: str, number: int, inputs: Inputs, *, signed_offset: bool = False, name: str = "part", index: int = 0):
    """A ``--part`` value such as "point mass=100g offset=20cm" as an inertia Part.

    A part is a shape with mass= (or density=) and its dimensions, or its own I: inertia=
    (with mass= and offset=, I_cm moved by the parallel-axis theorem) or gyration= with mass=;
    those need no shape word. Keys read with - or _ (inner-radius=, inner_radius=).
    """
    source = f"{{{name}}} {number}"
    example = '{part} "point mass=100g offset=20cm"'
    if not spec.strip():
        raise InputError(source, "expected a shape then key=value pairs", example=example, got=repr(spec))
    known = {"mass", "axis", "offset", "inertia", "gyration", "density", "angle", *PART_DIMENSIONS}
    shape, fields = _spec_fields(spec, source, known, example, shape_word=True)  # the one reader of every spec: a key twice is refused
    shape = shape or ""
    given_inertia = "inertia" in fields or "gyration" in fields
    if not shape and not given_inertia:
        raise InputError(source, "expected a shape then key=value pairs (or inertia= or gyration=)", example='{part} "point mass=100g offset=20cm"', got=repr(spec))
    if shape and given_inertia:
        raise InputError(source, "takes a shape or inertia=/gyration=, not both", got=repr(spec))
    if "mass" not in fields and "density" not in fields and "inertia" not in fields:
        raise InputError(source, "needs mass= (or density=, or inertia=)", example='{part} "point mass=100g offset=20cm"', got=repr(spec))

    def read_field(key: str) -> float:
        kind, sign = PART_FIELDS[key]
        if key == "offset" and signed_offset:
            sign = "any"  # (pendulum: a part on the other side of the pivot)
        spelled = f"{source} {key.replace('_', '-')}="
        origin = Origin(name, index, key, spelled, units.KINDS[kind].si_unit, sign)
        return inputs.quantity(spelled, fields[key], kind, sign=sign, key=f"{name}{number}_{key}", origin=origin)

    dims = {key: read_field(key) for key in PART_DIMENSIONS if key in fields}
    offset = read_field("offset") if "offset" in fields else None
    mass = read_field("mass") if "mass" in fields else None
    inertia = read_field("inertia") if "inertia" in fields else None
    gyration = read_field("gyration") if "gyration" in fields else None
    angle = read_field("angle") if "angle" in fields else None
    density, per = _read_density(source, fields["density"], inputs, f"{name}{number}_density") if "density" in fields else (None, "kg/m**3")
    if density is not None:  # its unit (per volume, area or length) known only now
        inputs.origins[f"{name}{number}_density"] = Origin(name, index, "density", f"{source} density=", per, "positive")
    return Part(shape, mass, dims, fields.get("axis"), offset, source, inertia, gyration, density, per, angle)


_PER = (("density", "kg/m**3"), ("areal density", "kg/m**2"), ("linear density", "kg/m"))


def _read_density(source: str, text: str, inputs: Inputs, key: str) -> tuple[float, str]:
    """A part's density and its unit, read by its unit: kg/m³ (a number alone too), kg/m² (a
    plate's or disc's mass per area) or kg/m (a rod's or ring's per length)."""
    option = f"{source} density="
    if not isinstance(text, str):
        return inputs.quantity(option, text, "density", key=key), "kg/m**3"
    first = None
    for kind, unit in _PER:
        try:
            return inputs.quantity(option, text, kind, key=key), unit
        except InputError as err:
            first = first or err
            if _of_kind(text, option, kind):
                raise  # of this kind, but not a value it takes
    raise InputError(option, "expected a density, an areal density or a linear density", example='{part} "plate density=20kg/m^2 width=1m height=0.5m"',
                     got=first.got) from None


def _of_kind(text: str, option: str, kind: str) -> bool:
    try:
        units.read(text, option, units.KINDS[kind])
    except InputError:
        return False
    return True


# Vectors ("0.3,0.4,0 m") and quantities given more than once (--mass 2kg --mass 3kg).
_NUMBER_THEN_UNIT = re.compile(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*?)\s*$")
AXES = ("x", "y", "z")


def vectors(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each value of a VECTOR option: "x,y,z UNIT" as its three SI components (a tuple), or a lone
    "20 N" as one signed SI number (a scene that takes a size alone says so; the others refuse it).
    Python and batch may give a vector as three SI numbers: [0.3, 0.4, 0]."""
    items = [given] if isinstance(given, str) or _is_triple(given) else list(given) if isinstance(given, (list, tuple)) else [given]
    read = []
    for number, item in enumerate(items, start=1):
        name = f"{{{option.name}}}" + (f" {number}" if len(items) > 1 else "")
        key = option.name + (str(number) if len(items) > 1 else "")
        read.append(read_vector(item, name, option.of, inputs, key, Origin(option.name, number - 1, None, name, units.KINDS[option.of].si_unit, "any")))
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


def read_vector(given, name: str, kind: str, inputs: Inputs, key: str, origin: Origin | None = None):
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
        return inputs.quantity(name, components[0], kind, sign="any", key=key, origin=origin)
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


# --particle and --couple of impulse (#20): "key=value ..." specs like --part's.
PARTICLE_FIELDS = {  # key: (kind, sign)
    "mass": ("mass", "positive"),
    "speed": ("velocity", "any"),
    "radius": ("length", "nonnegative"),
    "angle": ("angle", "nonnegative"),
    "speed_after": ("velocity", "any"),
    "radius_after": ("length", "nonnegative"),
    "e": ("dimensionless", "nonnegative"),
    "speed_relative": ("velocity", "any"),
}
ROTOR_FIELDS = {"inertia": ("moment of inertia", "positive"), "spin": ("angular velocity", "any")}
COUPLE_FIELDS = {"inertia": ("moment of inertia", "nonnegative"), "omega0": ("angular velocity", "any"), "mass": ("mass", "positive"),
                 "torque": ("torque", "positive"),
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


def with_key(spec: str, key: str, change) -> str:
    """``spec`` with the text of its ``key`` (snake case) replaced by ``change(text)``, the rest
    as it was: how a key's value is moved (an uncertainty carried through, a --find trial)."""
    words = [word.strip() for word in _SPEC_KEY.split(" " + spec.strip()) if word.strip()]
    for i, pair in enumerate(words):
        name, equals, text = pair.partition("=")
        if equals and name.strip().replace("-", "_") == key:
            words[i] = f"{name.strip()}={change(text.strip())}"
    return " ".join(words)


def _read_fields(fields: dict[str, str], table: dict, source: str, prefix: str, inputs: Inputs, option: str, index: int) -> dict[str, float]:
    """Each key of ``table`` in the spec, read in SI; ``option`` and ``index`` say which value of
    which option the spec is, so that an uncertainty given in a key is carried through."""
    read = {}
    for key, text in fields.items():
        if key in table:
            kind, sign = table[key]
            spelled = f"{source} {key.replace('_', '-')}="
            origin = Origin(option, index, key, spelled, units.KINDS[kind].si_unit, sign)
            read[key] = inputs.quantity(spelled, text, kind, sign=sign, key=f"{prefix}_{key}", origin=origin)
    return read


def _specs(option: Option, given):
    """Each "key=value ..." spec given for a repeatable spec option: (its number, the name its
    messages use: "{brake}", or "{brake} 2" where several are given, the spec's text)."""
    specs = given if isinstance(given, (list, tuple)) else [given]
    for number, spec in enumerate(specs, start=1):
        source = "{" + option.name + "}" + (f" {number}" if len(specs) > 1 else "")
        yield number, source, word(option, spec)


def particles(option: Option, given, inputs: Inputs, stdin) -> tuple:
    example = '{particle} "mass=30kg speed=4m/s radius=2m"'
    particles = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, PARTICLE_FIELDS, example, shape_word=False)
        for needed in ("mass", "radius"):
            if needed not in fields:
                raise InputError(source, f"needs {needed}=", example=example, got=repr(spec))
        values = _read_fields(fields, PARTICLE_FIELDS, source, f"particle{number}", inputs, option.name, number - 1)
        particles.append(Particle(source=source, **values))
    return tuple(particles)


def couples(option: Option, given, inputs: Inputs, stdin) -> tuple:
    example = '{couple} "inertia=3kg*m^2 omega0=0", or {couple} "disc mass=2kg radius=0.1m omega0=100rpm", or through a clutch {couple} "inertia=3kg*m^2 torque=50N*m"'
    couples = []
    for number, source, spec in _specs(option, given):
        shape, fields = _spec_fields(spec, source, {*COUPLE_FIELDS, "axis"}, example, shape_word=True)
        values = _read_fields(fields, COUPLE_FIELDS, source, f"couple{number}", inputs, option.name, number - 1)
        if (shape is None) == ("inertia" not in values):
            raise InputError(source, "needs inertia= or a shape with its mass and dimensions (one of them)", example=example, got=repr(spec))
        dims = {key: values[key] for key in PART_DIMENSIONS if key in values}
        if shape is None and (dims or "mass" in values or "offset" in values or "axis" in fields):
            raise InputError(source, "takes a shape's mass and dimensions only after a shape word; with inertia= they are not used", example=example, got=repr(spec))
        part = None if shape is None else Part(shape, values.get("mass", 0.0), dims, fields.get("axis"), values.get("offset"), source)
        if part is not None and "mass" not in values:
            raise InputError(source, "needs mass= with a shape", example=example, got=repr(spec))
        couples.append(Couple(source=source, inertia=values.get("inertia"), part=part, omega0=values.get("omega0"), torque=values.get("torque")))
    return tuple(couples)


def rotors(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """gyro's --rotor: "inertia=… spin=… sense=cw-from-rear" (the sense a word the scene checks)."""
    example = '{rotor} "inertia=0.3kg*m^2 spin=5000rpm sense=cw-from-right"'
    rotors = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, {*ROTOR_FIELDS, "sense"}, example, shape_word=False)
        for needed in ("inertia", "spin", "sense"):
            if needed not in fields:
                raise InputError(source, f"needs {needed}=", example=example, got=repr(spec))
        values = _read_fields(fields, ROTOR_FIELDS, source, f"rotor{number}", inputs, option.name, number - 1)
        rotors.append(Rotor(source, values["inertia"], values["spin"], fields["sense"]))
    return tuple(rotors)


# μ as a spec gives it: mu= (kinetic) or mu-k= and mu-s= (--brake, --face, --band in taucli.answering.contact_specs; --side1, --side2).
_MU_FIELDS = {"mu": ("dimensionless", "nonnegative"), "mu_k": ("dimensionless", "nonnegative"), "mu_s": ("dimensionless", "nonnegative")}


# --side1, --side2 and --pull of atwood (#34): "key=value ..." specs like --brake's.
SIDE_FIELDS = {**_MU_FIELDS, "angle": ("angle", "any")}
PULL_FIELDS = {"force": ("force", "any"), "angle": ("angle", "any")}


def sides(option: Option, given, inputs: Inputs, stdin):
    """Where a block is: "hang", "table [mu-s=… mu-k=…]" or "incline angle=… [mu-s=… mu-k=…]"
    (mu= is the kinetic value); no coefficient: a smooth surface."""
    source = "{" + option.name + "}"
    example = '{' + option.name + '} "incline angle=30deg mu-s=0.4 mu-k=0.3"'
    spec = word(option, given)
    surface, fields = _spec_fields(spec, source, SIDE_FIELDS, example, shape_word=True)
    if surface is None and "angle" in fields:
        surface = "incline"
    if surface not in SURFACES:
        raise InputError(source, f"expected {', '.join(SURFACES)} then key=value pairs", example=example, got=repr(spec))
    values = _read_fields(fields, SIDE_FIELDS, source, option.name, inputs, option.name, 0)
    if surface == "incline" and "angle" not in values:
        raise InputError(source, "incline needs angle=", example=example, got=repr(spec))
    if surface != "incline" and "angle" in values:
        raise InputError(source, f"{surface}: takes no angle= (incline angle=… for a slope)", example=example, got=repr(spec))
    if surface == "hang" and values:
        raise InputError(source, "hang: takes no keys (a hanging block touches no surface)", example=example, got=repr(spec))
    mu_k, mu_s = values.get("mu"), values.get("mu_s")
    if mu_k is not None and "mu_k" in values:
        raise InputError(source, "has mu= and mu-k=: mu= is the kinetic value, give it once", example=example, got=repr(spec))
    mu_k = values.get("mu_k", mu_k)
    if mu_k is not None and mu_s is not None and mu_s < mu_k:
        raise InputError(source, "has mu-s= below mu-k= (static friction is at least kinetic)", got=f"{fmt(mu_s)} < {fmt(mu_k)}")
    return Side(source, surface, values.get("angle"), mu_k, mu_s)


def pulls(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each "force=… [angle=…] [on=1|2]": a pull on a block, along its path away from the pulley,
    tilted angle= off its surface (positive lifting it); on= the block (default 1)."""
    example = '{pull} "force=20N angle=30deg on=2"'
    found = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, {*PULL_FIELDS, "on"}, example, shape_word=False)
        if "force" not in fields:
            raise InputError(source, "needs force=", example=example, got=repr(spec))
        on = fields.get("on", "1").strip()
        if on not in ("1", "2"):
            raise InputError(source, "on= is 1 or 2 (the block pulled: m1's or m2's)", example=example, got=repr(on))
        values = _read_fields(fields, PULL_FIELDS, source, f"pull{number}", inputs, option.name, number - 1)
        angle = values.get("angle", 0.0)
        if not -math.pi / 2 <= angle <= math.pi / 2:
            raise InputError(source, "angle= is from −90 to 90 deg off the surface (a negative force= pulls the other way)",
                             example=example, got=f"{fmt(math.degrees(angle))} deg")
        found.append(Pull(source, values["force"], angle, int(on)))
    return tuple(found)
