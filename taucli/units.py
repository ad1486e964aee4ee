"""Quantities from text: the one pint registry, and ``parse`` that turns "4 kg" into an SI float.

The registry is built on first use only (``--help`` and completion never build it), pint's
definition cache is kept in taucli's cache folder, and pint's SI factor for each unit text is
remembered there too (taucli.cache), so a run whose units were seen before never imports pint.
Text is screened before pint sees it: pint evaluates ``**`` with Python integers, so
``9**9**9 kg`` would run for hours if it got that far.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass
from functools import lru_cache
from typing import NamedTuple

from taucli import cache
from taucli.errors import InputError, did_you_mean

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Kind:
    """A physical kind of quantity an option takes."""

    name: str  # "moment of inertia"
    si_unit: str  # the unit a bare number means; pint reads it back
    example: str  # shown in messages
    common_units: tuple[str, ...] = ()  # offered for "did you mean" and completion


KINDS: dict[str, Kind] = {
    kind.name: kind
    for kind in (
        Kind("mass", "kg", "4 kg", ("kg", "g", "lb", "oz", "tonne")),
        Kind("length", "m", "0.2 m", ("m", "cm", "mm", "km", "in", "ft")),
        Kind("angle", "rad", "30 deg", ("deg", "rad", "rev")),
        Kind("time", "s", "4 s", ("s", "ms", "min", "h")),
        Kind("angular velocity", "rad/s", "300 rpm", ("rad/s", "rpm", "rev/s", "deg/s", "Hz")),
        Kind("angular acceleration", "rad/s**2", "6 rad/s^2", ("rad/s^2", "rpm/s", "rev/s^2")),
        Kind("torque", "N*m", "0.3 N*m", ("N*m", "mN*m", "kN*m", "lbf*ft", "lbf*in")),
        Kind("moment of inertia", "kg*m**2", "0.1 kg*m^2", ("kg*m^2", "g*cm^2", "lb*ft^2")),
        Kind("force", "N", "6 N", ("N", "kN", "lbf")),
        Kind("acceleration", "m/s**2", "9.81 m/s^2", ("m/s^2", "ft/s^2", "g0")),
        Kind("velocity", "m/s", "2 m/s", ("m/s", "km/h", "ft/s", "mph")),
        Kind("viscous coefficient", "N*m*s", "0.01 N*m*s", ("N*m*s", "N*m/(rad/s)")),
        Kind("drag coefficient", "N*m*s**2", "0.001 N*m*s^2", ("N*m*s^2",)),
        Kind("dimensionless", "", "0.5", ()),
        Kind("torsion constant", "N*m/rad", "0.5 N*m/rad", ("N*m/rad", "N*m/deg", "mN*m/rad")),
    )
}

# Names for dimensionalities that show up in "got ..." messages, keyed by exponents.
_DIMENSION_NAMES = {
    frozenset(dims.items()): name
    for dims, name in (
        ({"[mass]": 1}, "a mass"),
        ({"[length]": 1}, "a length"),
        ({"[time]": 1}, "a time"),
        ({}, "a plain number or angle"),
        ({"[time]": -1}, "an angular velocity or frequency"),
        ({"[time]": -2}, "an angular acceleration"),
        ({"[length]": 1, "[time]": -1}, "a velocity"),
        ({"[length]": 1, "[time]": -2}, "an acceleration"),
        ({"[mass]": 1, "[length]": 1, "[time]": -2}, "a force"),
        ({"[mass]": 1, "[length]": 2, "[time]": -2}, "a torque or energy"),
        ({"[mass]": 1, "[length]": 2}, "a moment of inertia"),
        ({"[mass]": 1, "[length]": 2, "[time]": -1}, "a viscous coefficient or angular momentum"),
    )
}

# Every quantity is 0 or within 1e-40..1e40 in SI: wider than physics asks of a turning body (an
# electron's mass is 9e-31 kg, the observable universe 9e26 m across), and narrow enough that the
# products a solver forms (m r², ω² I t², ...) stay inside a double's range, 1e-308..1.8e308,
# so that nothing underflows to a zero divisor or overflows.
SMALLEST, LARGEST = 1e-40, 1e40
MAX_TEXT_LENGTH = 80
MAX_DIGITS = 25  # digits in one numeric literal
MAX_EXPONENT = 12  # |n| in x**n
MAX_POWERS = 6
MAX_PAREN_DEPTH = 4

_ALLOWED = re.compile(r"[A-Za-z0-9_ .+\-*/^()µμΩ]*")
_POWER = re.compile(r"(\*\*|\^)\s*(\(?\s*[-+]?\s*\d+(?:\.\d+)?\s*\)?)?")
_DIGIT_RUN = re.compile(r"\d+")
_NORMALISE = [
    ("\u00a0", " "), ("\u202f", " "), ("·", "*"), ("⋅", "*"), ("×", "*"), ("∙", "*"),
    ("−", "-"), ("–", "-"), ("²", "**2"), ("³", "**3"), ("⁻¹", "**-1"), ("⁻²", "**-2"),
    ("°", " deg"), ("÷", "/"),
]  # fmt: skip


class Parsed(NamedTuple):
    """A quantity read from the command line: its SI value, and a note if a reading needs one."""

    value: float
    note: str | None = None


@lru_cache(maxsize=1)
def registry():
    """The one pint registry, built on first use, its definitions cached on disk between runs."""
    import pint

    where = cache.folder()
    try:
        ureg = pint.UnitRegistry(cache_folder=None if where is None else os.path.join(where, "pint"))
    except Exception:  # an unreadable, unwritable or corrupt cache must not cost the answer
        ureg = pint.UnitRegistry()
    ureg.define("rev = revolution")
    ureg.define("rps = revolution / second")
    return ureg


def _screen(text: str, option: str, kind: Kind) -> str:
    """Normalise typography and refuse text that is unreadable or would be slow to evaluate."""
    cleaned = text.strip()
    for old, new in _NORMALISE:
        cleaned = cleaned.replace(old, new)
    example = kind.example

    def refuse(why: str) -> InputError:
        return InputError(option, f"expected {_article(kind.name)}", example=example, got=f"{text!r}: {why}")

    if not cleaned:
        raise refuse("an empty value")
    if len(cleaned) > MAX_TEXT_LENGTH:
        raise refuse(f"longer than {MAX_TEXT_LENGTH} characters")
    if "," in cleaned:
        raise refuse("a comma (write decimals with a point: 4.5 kg)")
    if not _ALLOWED.fullmatch(cleaned):
        bad = next(ch for ch in cleaned if not _ALLOWED.fullmatch(ch))
        raise refuse(f"the character {bad!r} is not part of a quantity")
    if any(len(run) > MAX_DIGITS for run in _DIGIT_RUN.findall(cleaned)):
        raise refuse(f"a number longer than {MAX_DIGITS} digits")
    depth = 0
    for ch in cleaned:
        depth += (ch == "(") - (ch == ")")
        if depth > MAX_PAREN_DEPTH:
            raise refuse("parentheses nested too deeply")
    powers = list(_POWER.finditer(cleaned))
    if len(powers) > MAX_POWERS:
        raise refuse("too many powers")
    for power in powers:
        exponent = power.group(2)
        if exponent is None:
            raise refuse("a power must be a plain number, as in m^2")
        if abs(float(exponent.strip("() ").replace(" ", ""))) > MAX_EXPONENT:
            raise refuse(f"a power larger than {MAX_EXPONENT}")
        if re.match(r"\s*(\*\*|\^)", cleaned[power.end() :]):
            raise refuse("a power of a power")
    return cleaned


def _article(name: str) -> str:
    return ("an " if name[0] in "aeiou" else "a ") + name


def _describe(dimensionality) -> str:
    return _DIMENSION_NAMES.get(frozenset(dict(dimensionality).items()), str(dimensionality))


def quantity(text: str, option: str, kind_name: str, *, original: str | None = None):
    """Read text as a pint Quantity of the given kind (bare numbers take the kind's SI unit).

    ``original`` is the text as the user typed it, for messages, when ``text`` is a part of it.
    """
    import pint

    kind = KINDS[kind_name]
    shown = text if original is None else original
    cleaned = _screen(text, option, kind)
    ureg = registry()
    try:
        q = ureg.Quantity(cleaned)
    except pint.UndefinedUnitError as err:
        name = str(getattr(err, "unit_names", [""])[0] if getattr(err, "unit_names", None) else err)
        raise InputError(
            option,
            f"expected {_article(kind.name)}",
            example=kind.example,
            got=f"{shown!r}: unknown unit {name!r}",
            hint=did_you_mean(name, kind.common_units, cutoff=0.5),
        ) from None
    except (OverflowError, ZeroDivisionError):
        raise InputError(option, f"expected {_article(kind.name)}", example=kind.example, got=f"{shown!r}: out of range") from None
    except Exception:  # pint's tokenizer and evaluator raise many kinds; none may escape as a traceback
        raise InputError(
            option, f"expected {_article(kind.name)}", example=kind.example, got=f"{shown!r}, which is not a quantity"
        ) from None
    if not isinstance(q, ureg.Quantity):  # a bare unit name such as "kg"
        q = ureg.Quantity(1, q)
    if q.unitless and kind.si_unit:
        q = ureg.Quantity(q.magnitude, kind.si_unit)
    return q, kind


# "4.5 kg", "300 rpm", "-2 N*m", "1e-3 kg*m^2", "kg", "4": a number (or none) times a product of
# unit powers. For such text the value is the number times pint's SI factor for the unit text,
# and that factor is cached (taucli.cache); anything else ("4 kg + 200 g") goes to pint whole.
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_NAME = r"[A-Za-zµμΩ_][A-Za-z0-9µμΩ_]*"
_POWER_OF = r"(?:\s*(?:\*\*|\^)\s*-?\d{1,2})?"
_FACTOR = rf"(?:{_NAME}|\(\s*{_NAME}{_POWER_OF}(?:\s*[*/]?\s*{_NAME}{_POWER_OF})*\s*\)){_POWER_OF}"
_NUMBER_TIMES_UNIT = re.compile(rf"\s*(?P<number>{_NUMBER})?\s*(?P<unit>{_FACTOR}(?:\s*[*/]?\s*{_FACTOR})*)?\s*")


def _number_times_unit(text: str) -> tuple[float, str] | None:
    """("4.5", "kg") read from "4.5 kg" as (4.5, "kg"); None for any other form of text."""
    split = _NUMBER_TIMES_UNIT.fullmatch(text)
    if split is None or len(text) > MAX_TEXT_LENGTH:
        return None
    number, unit = split.group("number"), split.group("unit") or ""
    if number is None:
        return (1.0, unit) if unit else None
    if len(number) > MAX_DIGITS:
        return None
    return float(number), unit


def _from_pint(cleaned: str, text: str, option: str, kind: Kind) -> tuple[float, int]:
    """The SI value of ``cleaned`` as pint reads it, and the power of Hz in it (already applied)."""
    import pint

    q, _ = quantity(cleaned, option, kind.name, original=text)
    hertz_power = int(dict(q.unit_items()).get("hertz", 0))
    try:
        value = float(q.to(kind.si_unit).magnitude) if kind.si_unit else float(q.to("").magnitude)
    except pint.DimensionalityError:
        raise InputError(
            option,
            f"expected {_article(kind.name)}",
            example=kind.example,
            got=f"{text!r}, which is {_describe(q.dimensionality)}",
        ) from None
    except (OverflowError, TypeError, ValueError):
        raise InputError(option, f"expected {_article(kind.name)}", example=kind.example, got=f"{text!r}: out of range") from None
    if hertz_power and kind.name in ("angular velocity", "angular acceleration"):
        value *= TWO_PI**hertz_power
    else:
        hertz_power = 0
    return value, hertz_power


def _factor_key(unit: str, kind: Kind) -> str:
    return f"{kind.si_unit}|{kind.name}|{unit}"


_FACTORS: dict[str, tuple[float, int]] = {}  # this process's copy of the store, checked once


def _cached_factor(unit: str, kind: Kind) -> tuple[float, int] | None:
    key = _factor_key(unit, kind)
    found = _FACTORS.get(key)
    if found is None:
        stored = cache.unit_factors().get(key)
        if isinstance(stored, list) and len(stored) == 2 and isinstance(stored[0], float) and isinstance(stored[1], int):
            if math.isfinite(stored[0]) and stored[0]:
                found = _FACTORS[key] = (stored[0], stored[1])
    return found


def unit_factor(unit: str, text: str, option: str, kind: Kind) -> tuple[float, int]:
    """SI value of one ``unit`` of ``kind`` (Hz read as rev/s), and the power of Hz in it.

    pint is asked once per unit text; its answer is kept in memory and on disk (taucli.cache).
    A bare number is the kind's SI unit, so "" needs no pint at all. ``text`` is what the user
    typed, for messages.
    """
    if not unit:
        return 1.0, 0
    found = _cached_factor(unit, kind)
    if found is None:
        found = _from_pint(unit, text, option, kind)
        if math.isfinite(found[0]) and found[0] != 0:
            cache.unit_factors().put(_factor_key(unit, kind), list(found))
    return found


def read(text: str, option: str, kind: Kind) -> tuple[float, int]:
    """The SI value of ``text`` read as ``kind``, and the power of Hz in it (already applied).

    Text of a unit seen before is read without pint, and without screening: its unit passed the
    screen when it was first read, and the pattern bounds the number.
    """
    split = _number_times_unit(text)
    if split is not None:
        number, unit = split
        found = _cached_factor(unit, kind) if unit else (1.0, 0)
        if found is not None:
            return number * found[0], found[1]
    cleaned = _screen(text, option, kind)
    split = _number_times_unit(cleaned)
    if split is None:
        return _from_pint(cleaned, text, option, kind)
    number, unit = split
    factor, hertz_power = unit_factor(unit, text, option, kind)
    return number * factor, hertz_power


def parse(text: str, option: str, kind_name: str, *, sign: str = "positive") -> Parsed:
    """Read ``text`` as a quantity of ``kind_name`` and return its SI value.

    ``sign`` is "positive" (> 0), "nonnegative" (>= 0) or "any". A bare number means the kind's
    SI unit. ``Hz`` for an angular velocity or acceleration means revolutions per second
    (omega = 2 pi f), with a note that says so.
    """
    kind = KINDS[kind_name]
    value, hertz_power = read(text, option, kind)
    note = f"{option} {text.strip()}: Hz read as revolutions per second (omega = 2*pi*f)" if hertz_power else None
    if not math.isfinite(value):
        raise InputError(option, f"expected a finite {kind.name}", example=kind.example, got=repr(text))
    if value and not SMALLEST <= abs(value) <= LARGEST:
        raise InputError(
            option,
            f"expected {_article(kind.name)} {'' if sign == 'positive' else 'of 0 or '}between 1e-40 and 1e40 {kind.si_unit} in size".replace("  ", " "),
            example=kind.example, got=repr(text) if _is_number(text) else f"{text!r} = {value:g} {kind.si_unit}".rstrip(),
        )
    if sign == "positive" and value <= 0:
        raise InputError(option, f"expected a positive {kind.name}", example=kind.example, got=repr(text))
    if sign == "nonnegative" and value < 0:
        raise InputError(option, f"expected a {kind.name} of zero or more", example=kind.example, got=repr(text))
    return Parsed(value, note)


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def convert(value: float, si_unit: str, target: str, option: str) -> float:
    """Express an SI value in the unit ``target`` (``--to``), with Hz read as rev/s."""
    return converted(value, si_unit, target, option).value


def converted(value: float, si_unit: str, target: str, option: str) -> Parsed:
    """``convert``, with a note when Hz was read as revolutions per second."""
    kind = next((k for k in KINDS.values() if k.si_unit == si_unit), Kind("quantity", si_unit, si_unit))
    example = kind.common_units[0] if kind.common_units else si_unit
    cleaned = _screen(target, option, kind)
    split = _number_times_unit(cleaned)
    if split is None or split[0] != 1.0 or not split[1] or cleaned.strip() != split[1]:
        raise InputError(option, f"expected a unit of {_article(kind.name)}", example=example, got=repr(target))
    try:
        factor, hertz_power = unit_factor(split[1], target, option, kind)
    except InputError:
        raise InputError(option, f"expected a unit of {_article(kind.name)}", example=example, got=repr(target)) from None
    note = f"{option} {target.strip()}: Hz read as revolutions per second (f = omega/(2*pi))" if hertz_power else None
    return Parsed(value / factor, note)
