"""What ``--find NAME`` may solve for, and how each trial value takes its place among the options.

NAME is one of (docs/find-and-uncertainty.md):

- a quantity option of the scene, by its name (``pulley_inertia``; ``pulley-inertia`` and
  ``--pulley-inertia`` read too), left out of the options given;
- an option given once for each of several things (torque's ``--lever``, ``--angle``, ``--mass``,
  and ``--force`` as a size in the plane): the one value left out, after those given (the last);
- a key inside a spec: the spec option's name, a dot and the key, as a batch writes names
  (``particle.speed``, ``particle.speed_after``, ``brake.mu``, ``part.mass``,
  ``face.outer_radius``; dashes read too), the key left out of the spec. Where the option is given
  more than once, the number of the spec says which: ``particle2.speed`` is the second
  ``--particle`` (``particle1.speed`` the first); a name that could be several is refused,
  naming each spelling.

Plain data and text: no pint, no solver.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass

from taucli.core.errors import InputError, did_you_mean
from taucli.answering.contact_specs import BAND_FIELDS, BRAKE_FIELDS, CALIPER_FIELDS, CENTRIFUGAL_FIELDS, FACE_FIELDS
from taucli.answering.specs import with_key, COUPLE_FIELDS, PARTICLE_FIELDS, PART_FIELDS, ROTOR_FIELDS
from taucli.answering.duty import SEGMENT_FIELDS
from taucli.answering.drive_loads import CURVE_FIELDS, LOAD_FIELDS
from taucli.answering.phase_spec import PHASE_FIELDS
from taucli.answering.revolving import REVOLVING_FIELDS
from taucli.options.table import BAND, BRAKE, CALIPER, CENTRIFUGAL, COUPLE, FACE, LOAD, MOTOR_CURVE, PART, PARTICLE, PHASE, REVOLVING, ROTOR, SEGMENT, VECTOR, Command, Option
from taucli.quantities.units import KINDS

# The keys of each spec that --find may solve for: (kind, sign). Not a face's surfaces= nor a
# band's blocks= nor a clutch's shoes= nor a caliper's surfaces= (whole numbers), nor a part's density= (its unit says whether it is per volume, area or length).
SPEC_KEYS: dict[str, dict[str, tuple[str, str]]] = {
    PART: {key: value for key, value in PART_FIELDS.items() if key != "density"},
    PARTICLE: PARTICLE_FIELDS,
    COUPLE: COUPLE_FIELDS,
    ROTOR: ROTOR_FIELDS,
    REVOLVING: REVOLVING_FIELDS,
    BRAKE: BRAKE_FIELDS,
    FACE: {key: value for key, value in FACE_FIELDS.items() if key != "surfaces"},
    BAND: {key: value for key, value in BAND_FIELDS.items() if key != "blocks"},
    CENTRIFUGAL: {key: value for key, value in CENTRIFUGAL_FIELDS.items() if key != "shoes"},
    CALIPER: {key: value for key, value in CALIPER_FIELDS.items() if key != "surfaces"},
    PHASE: PHASE_FIELDS,
    SEGMENT: SEGMENT_FIELDS,
    LOAD: LOAD_FIELDS,
    MOTOR_CURVE: CURVE_FIELDS,
}

# Options read as vectors that a scene also takes as one signed size (a force in the plane).
SIZES = {("torque", "force")}

_NAME = re.compile(r"([a-z][a-z_]*?)(\d*)\.([a-z][a-z0-9_]*)")
_KEYS_IN_SPEC = re.compile(r"(?:^|\s)([a-z][a-z0-9_-]*)\s*=")


@dataclass(frozen=True)
class Unknown:
    """The input --find solves for."""

    name: str  # the solved result's key: "pulley_inertia", "particle.speed", "particle2.speed"
    option: Option  # the option it is, or the spec option it is a key of
    kind: str
    sign: str
    key: str | None = None  # a spec's key ("speed")
    number: int = 0  # which of the spec option's values (from 1); 0: the only one

    @property
    def spelled(self) -> str:
        """How a message names it: {pulley_inertia}, or "{particle} 2 speed="."""
        if self.key is None:
            return "{" + self.option.name + "}"
        return "{" + self.option.name + "}" + (f" {self.number}" if self.number else "") + f" {self.key.replace('_', '-')}="

    @property
    def label(self) -> str:
        """What it is, for the solved result's label."""
        if self.key is not None:
            return f"{self.key.replace('_', '-')}= of the {self.option.name}" + (f" {self.number}" if self.number else "")
        if self.option.kind == VECTOR:
            return f"{self.option.name} in the plane, signed (the last one)"
        return self.option.help.split("(")[0].split(",")[0].rstrip(". ")

    def given_with(self, given: Mapping[str, object], x: float) -> dict:
        """The options ``given`` with the trial value x (SI) in this unknown's place."""
        moved = dict(given)
        if self.key is None and not self.option.repeatable:
            moved[self.option.name] = x
            return moved
        unit = KINDS[self.kind].si_unit
        text = f"{x!r} {unit}" if unit else repr(x)
        values = _items(given.get(self.option.name))
        if self.key is None:
            moved[self.option.name] = [*values, text]  # a text, not a number: three numbers would read as one vector
        else:
            index = max(self.number, 1) - 1
            values[index] = f"{values[index]} {self.key.replace('_', '-')}={text}"
            moved[self.option.name] = values
        return moved


@dataclass(frozen=True)
class Placed:
    """An input with an uncertainty that is not an option of its own: a key of a spec ("{part} 2
    mass="), or one value of a repeated option ("{lever} 2"), moved in its place (its text) as
    uncertainties are carried through; ``origin`` is where it was (taucli.answering.reading.Origin)."""

    name: str  # the key its value is echoed under: "part2_mass", "brake_force", "lever2"
    origin: object

    @property
    def sign(self) -> str:
        return self.origin.sign

    @property
    def spelled(self) -> str:
        return self.origin.spelled

    def changed(self, given: Mapping[str, object], change) -> dict:
        """The options ``given`` with this input's text replaced by ``change(text)``."""
        option, index, key = self.origin.option, self.origin.index, self.origin.key
        moved = dict(given)
        single = not isinstance(given.get(option), (list, tuple))
        values = _items(given.get(option))
        values[index] = change(str(values[index]).strip()) if key is None else with_key(str(values[index]), key, change)
        moved[option] = values[0] if single else values
        return moved

    def given_with(self, given: Mapping[str, object], x: float) -> dict:
        """The options ``given`` with the trial value x (SI) in this input's place."""
        text = f"{x!r} {self.origin.unit}" if self.origin.unit else repr(x)
        return self.changed(given, lambda _: text)


def _items(value) -> list:
    if value is None:
        return []
    return list(value) if isinstance(value, (list, tuple)) else [value]


def _plain(command: Command) -> list[Option]:
    """The options --find may name as they are."""
    return [option for option in command.options
            if option.name in command.input_names and option.is_quantity and option.kind in KINDS
]


def _sized(command: Command) -> list[Option]:
    return [option for option in command.options if option.kind == VECTOR and (command.name, option.name) in SIZES]


def names(command: Command) -> tuple[str, ...]:
    """Every NAME --find takes in ``command`` (spec keys unnumbered): for messages and completion."""
    found = [option.name for option in (*_plain(command), *_sized(command))]
    for option in command.options:
        for key in SPEC_KEYS.get(option.kind, ()):
            found.append(f"{option.name}.{key}")
    return tuple(dict.fromkeys(found))


def resolve(command: Command, text: str, given: Mapping[str, object]) -> Unknown:
    """The unknown ``text`` names in ``command``, with the options ``given``, or a usage error."""
    name = str(text).strip().lstrip("-").replace("-", "_").lower()
    spec = _NAME.fullmatch(name)
    if spec is not None:
        return _spec_key(command, text, spec[1], spec[2], spec[3], given)
    option = command.option(name)
    if option is not None and (option in _plain(command) or option in _sized(command)):
        if not option.repeatable and given.get(option.name) is not None:
            raise InputError(option.name, "is what {find} solves for: leave it out", example=f"{{find}} {option.name}")
        kind = option.of if option.kind == VECTOR else option.kind
        return Unknown(option.name, option, kind, option.sign)
    keys = [spelling for spelling in names(command) if spelling.endswith("." + name)]
    if keys:
        raise InputError("find", f"names a key of a spec: say which, as {' or '.join(keys)}", example="{find} " + keys[0], got=repr(text))
    raise InputError("find", f"expected {described(command)}", got=repr(text), hint=did_you_mean(name, names(command)))


def described(command: Command) -> str:
    """What --find takes in ``command``, in words: its options, and the keys of its specs."""
    options = [spelling for spelling in names(command) if "." not in spelling]
    text = f"a quantity option of {command.name}: {', '.join(options)}"
    for option in command.options:
        keys = SPEC_KEYS.get(option.kind)
        if keys:
            text += f"; or a key of {option.flag}, as {option.name}.{next(iter(keys))} ({option.name}.KEY, KEY one of {', '.join(keys)})"
    return text


def _spec_key(command: Command, text: str, option_name: str, number: str, key: str, given: Mapping[str, object]) -> Unknown:
    option = command.option(option_name)
    table = SPEC_KEYS.get(option.kind) if option is not None else None
    if table is None:
        specs = sorted({spelling.split(".")[0] for spelling in names(command) if "." in spelling})
        expected = f"a key of a spec option of {command.name} ({', '.join(s + '.KEY' for s in specs)})" if specs else f"an input of {command.name}: {command.name} takes no spec"
        raise InputError("find", f"expected {expected}", got=repr(text))
    if key not in table:
        raise InputError("find", f"expected a key of {option.flag} that is a number: {', '.join(f'{option.name}.{k}' for k in table)}", got=repr(text))
    specs = _items(given.get(option.name))
    spellings = [f"{option.name}{n}.{key}" for n in range(1, len(specs) + 1)]
    if not specs:
        raise InputError("find", f"names a key of {option.flag}, and no {option.flag} is given: give the spec without {key.replace('_', '-')}=",
                         example=f"{{find}} {option.name}.{key}", got=repr(text))
    if not number and len(specs) > 1:
        raise InputError("find", f"could be any of {len(specs)} {option.flag} specs: say which, as {' or '.join(spellings)}",
                         example="{find} " + spellings[0], got=repr(text))
    which = int(number or 1)
    if not 1 <= which <= len(specs):
        raise InputError("find", f"names {option.flag} {which}, and {len(specs)} {'is' if len(specs) == 1 else 'are'} given: {' or '.join(spellings)}", got=repr(text))
    present = {found.replace("-", "_") for found in _KEYS_IN_SPEC.findall(str(specs[which - 1]))}
    if key in present:
        raise InputError("find", f"solves for {key.replace('_', '-')}= of {option.flag}" + (f" {which}" if len(specs) > 1 else "") + ": leave it out of the spec",
                         got=repr(str(specs[which - 1])))
    kind, sign = table[key]
    return Unknown(f"{option.name}{which if len(specs) > 1 else ''}.{key}", option, kind, sign, key, which if len(specs) > 1 else 0)
