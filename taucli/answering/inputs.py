"""Reading a command's inputs: one loop over its table, from text (or SI numbers) to SI values.

Every way in (a command line, a sweep's point, a batch line, a Python call) arrives here as a
mapping of option names to what was given, and leaves as the keyword arguments of the scene's
library function, with the inputs echoed in SI for the report and any notes their reading raised.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TextIO

from taucli.quantities import units
from taucli.core.errors import InputError, did_you_mean
from taucli.quantities.formula import mentions_time
from taucli.quantities.kinds import article
from taucli.answering.reading import Inputs, Origin, word
from taucli.writing.report import Value
from taucli.options.table import BAND, BRAKE, CALIPER, CENTRIFUGAL, CHOICE, COUNT, COUPLE, CURVE, FACE, FILE, FLAG, LOAD, MOTOR_CURVE, PART, PARTICLE, PHASE, PULL, REVOLVING, ROTOR, SEGMENT, SIDE, TEXT, VECTOR, Command, Option


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
    plain = _plain_quantities(command)
    for name in command.in_order(given):  # what was given, not the whole table: a scene has dozens of options
        value = given[name]
        if value is None or (value.__class__ is not str and (value == () or value == [])) or value is False or name in arguments:
            continue
        found = plain.get(name)
        if found is not None:  # most values of most runs: one quantity, read at once
            arguments[name] = inputs.quantity(name, value, found[0], sign=found[1])
            continue
        option = command.option(name)
        arguments[name] = READERS[option.kind](option, value, inputs, stdin)
    return arguments, inputs


_PLAIN: dict[str, tuple[Command, dict[str, tuple[str, str]]]] = {}  # command's name -> (its table, its one-quantity options: name -> (kind, sign))


def _plain_quantities(command: Command) -> dict[str, tuple[str, str]]:
    """The options ``_repeated`` would read as one quantity (no words, no other kind, not
    repeatable, no formula of t): looked up once per command, not per run (a batch reads thousands
    of lines). tests/answering/test_plain_quantities.py holds the two to the same options."""
    found = _PLAIN.get(command.name)
    if found is None or found[0] is not command:  # (a test may make a table of the same name)
        found = command, {option.name: (option.kind, option.sign) for option in command.options
                          if option.kind in units.KINDS and not option.words and option.also is None and not option.repeatable and not option.of_time}
        _PLAIN[command.name] = found
    return found[1]


def _quantity(option: Option, given, inputs: Inputs, stdin) -> float | None:
    return inputs.quantity(option.name, given, option.kind, sign=option.sign)


def _choice(option: Option, given, inputs: Inputs, stdin):
    if option.repeatable:
        return tuple(word(option, item) for item in (given if isinstance(given, (list, tuple)) else [given]))
    return word(option, given)



def _flag(option: Option, given, inputs: Inputs, stdin) -> bool:
    if not isinstance(given, bool):
        raise InputError(option.name, "expected true or false", got=repr(given))
    return given


def _file(option: Option, given, inputs: Inputs, stdin):
    """A torque profile from its CSV file (or stdin for -), streamed: its samples as they are read."""
    from taucli.answering.profile import read_profile  # deferred: the CSV reader, only for a torque profile

    source = word(option, given)
    if source == "-":
        if stdin is None:
            raise InputError(option.name, "cannot be - here: no stdin to read it from", example='"torque_profile": "pulse.csv"')
        profile = read_profile(stdin, "stdin")
    else:
        try:
            handle = open(source, encoding="utf-8")  # noqa: SIM115 (closed when its samples are read, or by the collector)
            profile = read_profile(handle, source)
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
        if isinstance(given, str) and (not given.strip().isascii() or "_" in given):  # as cli._whole_number
            raise ValueError(given)
        return int(given)
    except (TypeError, ValueError):
        raise InputError(option.name, "expected a whole number", example=f"{{{option.name}}} 50", got=repr(given)) from None


def _as_given(option: Option, given, inputs: Inputs, stdin):
    return given


def _repeated(option: Option, given, inputs: Inputs, stdin):
    """A quantity option: one value, or (repeatable) each value given, as a tuple."""
    if option.words and isinstance(given, str) and given.strip().lower() in option.words:
        inputs.values[option.name] = Value(given.strip().lower(), None, "")
        return given.strip().lower()
    if option.also is not None and isinstance(given, str):
        return _either(option, given, inputs)
    if option.of_time and isinstance(given, str) and mentions_time(given):
        return _of_time(option, given, inputs)
    if not option.repeatable:
        return _quantity(option, given, inputs, stdin)
    items = list(given) if isinstance(given, (list, tuple)) else [given]
    if None in items:  # [2, null]: each item given must be a value
        raise InputError(option.name, "expected a value for each item, not null (None)", example=f"{{{option.name}}} {units.KINDS[option.kind].typed}", got=repr(given))
    keys = [option.name + (str(number) if len(items) > 1 else "") for number in range(1, len(items) + 1)]
    names = [f"{{{option.name}}}" + (f" {number}" if len(items) > 1 else "") for number in range(1, len(items) + 1)]
    si = units.KINDS[option.kind].si_unit
    return tuple(inputs.quantity(name, item, option.kind, sign=option.sign, key=key, origin=Origin(option.name, index, None, name, si, option.sign))
                 for index, (name, item, key) in enumerate(zip(names, items, keys)))


def _of_time(option: Option, given: str, inputs: Inputs):
    """A formula of t (--torque '(10 N*m/s)*t'): an OfTime in SI, echoed as typed."""
    from taucli.quantities.formula import read_formula  # deferred: the formula parser, only for a formula

    formula = read_formula(given, option.name, units.KINDS[option.kind])
    inputs.values[option.name] = Value(given, None, "")
    return formula


def _either(option: Option, given: str, inputs: Inputs):
    """A text of the option's own kind (a float), or else of one of its other kinds, ``option.also``:
    a Value (SI value and unit), so the scene tells them apart (rolling's --at 0.05m, a radius, and
    --at 30deg, an angle on the rim; --density 20kg/m^2, a plate's mass per area). A number alone is
    the option's own kind; a value of another kind takes no uncertainty, whose spread would be
    moved as the option's own kind."""
    try:
        return _quantity(option, given, inputs, None)
    except InputError as own:
        try:
            float(given)
        except ValueError:
            pass
        else:  # a number alone is only ever the option's own kind
            raise _of_neither(option, own) from None
        for kind_name in option.also_kinds:
            kind = units.KINDS[kind_name]
            aside = Inputs(gravity=inputs.gravity)  # the other reading, kept only if it reads
            try:
                value = aside.quantity(option.name, given, kind_name, sign="any")
            except InputError as other:
                try:
                    units.read(given, "{" + option.name + "}", kind)
                except InputError:
                    continue  # not of this kind
                raise other from None  # of this kind, but not a value it takes (out of bounds)
            if aside.uncertainties:
                raise InputError(option.name, f"takes {article(kind.name)} with no uncertainty", example=f"{{{option.name}}} {kind.typed}", got=repr(given))
            inputs.values.update(aside.values)
            inputs.notes.extend(aside.notes)
            return Value(value, kind.si_unit, "")
        raise _of_neither(option, own) from None


def _of_neither(option: Option, own: InputError) -> InputError:
    words = "".join(f", {word}" for word in option.words)
    kinds = [article(units.KINDS[kind].name) for kind in option.also_kinds]
    listed = f"{words} or {kinds[0]}" if len(kinds) == 1 else f"{words}, {', '.join(kinds[:-1])} or {kinds[-1]}"
    return InputError(option.name, f"{own.expected}{listed}", example=own.example, got=own.got, hint=own.hint)


def _spec(name: str, module: str = "specs"):
    """The reader of a "key=value" spec option (or a vector, or a turning-moment diagram),
    ``name`` in taucli.answering.``module``, imported when first read."""

    def read(option: Option, given, inputs: Inputs, stdin):
        import importlib  # deferred: the spec readers and the records they read into (4 ms), only for a spec option

        return getattr(importlib.import_module(f"taucli.answering.{module}"), name)(option, given, inputs, stdin)

    return read


READERS = {FLAG: _flag, CHOICE: _choice, FILE: _file, COUNT: _count, TEXT: _as_given}
READERS.update({kind: _repeated for kind in units.KINDS})
READERS.update({PART: _spec("parts"), VECTOR: _spec("vectors"), PARTICLE: _spec("particles"), COUPLE: _spec("couples"), BRAKE: _spec("brakes", "contact_specs"),
                FACE: _spec("faces", "contact_specs"), BAND: _spec("bands", "contact_specs"), CENTRIFUGAL: _spec("centrifugals", "contact_specs"),
                CALIPER: _spec("calipers", "contact_specs")})
READERS.update({SIDE: _spec("sides"), PULL: _spec("pulls"), ROTOR: _spec("rotors"), LOAD: _spec("loads", "drive_loads"), MOTOR_CURVE: _spec("motor_curve", "drive_loads")})
READERS.update({REVOLVING: _spec("revolving", "revolving"), SEGMENT: _spec("segments", "duty"), PHASE: _spec("phases", "phase_spec"),
                CURVE: _spec("turning_moment", "turning")})  # balance's --mass, drive's --segment, spin-down's --phase, flywheel's --turning-moment
