"""Quantities from text: the one pint registry, and ``parse`` that turns "4 kg" into an SI float.

The registry is built on first use only (``--help`` and completion never build it), pint's
definition cache is kept in taucli's cache folder, and pint's SI factor for each unit text is
remembered there too (taucli.cache), so a run whose units were seen before never imports pint.
Text is screened before pint sees it: pint evaluates ``**`` with Python integers, so
``9**9**9 kg`` would run for hours if it got that far.

How text is read (README, "Quantities carry units", has the table): engineering spellings are
rewritten first (taucli.spellings: ``Nm``, ``N-m``, ``ft-lb``, ``kgm^2``, ``RPM``, ``min-1``); a
whole number then a fraction is a mixed number (``33 1/3 rpm``), and any other numbers side by
side are refused (pint would multiply them); 1/time for an angular velocity or acceleration
(``Hz``, ``1/s``, ``min^-1``) is revolutions per unit time, ω = 2πn; an angle needs its unit
(``60deg``), 0 apart; a weight for a mass is the mass W/g, and a mass for a force (``lb*ft`` for
a torque) its weight at standard gravity. Every reading that is not plain says so in a note.
Each kind has its bounds (``Kind.bounds``), the same for a quantity typed or computed
(``check_bounds``).
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass
from functools import lru_cache
from typing import NamedTuple

from taucli import cache, spellings
from taucli.errors import InputError

TWO_PI = 2.0 * math.pi


# Every quantity is 0 or within its kind's bounds in SI: wider than physics asks of a turning body
# (an electron's mass is 9e-31 kg, the observable universe 9e26 m across; an O2 molecule's moment of
# inertia is 2e-46 kg*m^2, the Sun's 4e47), and narrow enough that the products a solver forms stay
# inside a double's range, 1e-308..1.8e308: with I within 1e-60..1e60 and the rest within
# 1e-40..1e40, m*r^2, I*omega^2 and omega^2*I*t^2 (at most 1e60 * 1e80 * 1e80 = 1e220) neither
# overflow nor underflow to a zero divisor. A moment of inertia computed from a shape is held to
# the same bounds (check_bounds, called by scenes.inertia).
BOUNDS = (1e-40, 1e40)
INERTIA_BOUNDS = (1e-60, 1e60)


@dataclass(frozen=True)
class Kind:
    """A physical kind of quantity an option takes."""

    name: str  # "moment of inertia"
    si_unit: str  # the unit a bare number means; pint reads it back
    example: str  # shown in messages, as typed in bash, zsh and fish (quoted where it holds * or ^)
    common_units: tuple[str, ...] = ()  # offered for "did you mean" and completion
    bounds: tuple[float, float] = BOUNDS  # the smallest and largest size in SI (0 aside)


KINDS: dict[str, Kind] = {
    kind.name: kind
    for kind in (
        Kind("mass", "kg", "4 kg", ("kg", "g", "lb", "oz", "tonne")),
        Kind("length", "m", "0.2 m", ("m", "cm", "mm", "km", "in", "ft")),
        Kind("angle", "rad", "30 deg", ("deg", "rad", "rev")),
        Kind("time", "s", "4 s", ("s", "ms", "min", "h")),
        Kind("angular velocity", "rad/s", "300 rpm", ("rad/s", "rpm", "rev/s", "deg/s", "Hz")),
        Kind("angular acceleration", "rad/s**2", "'6 rad/s^2'", ("rad/s^2", "rpm/s", "rev/s^2")),
        Kind("torque", "N*m", "'0.3 N*m'", ("N*m", "mN*m", "kN*m", "lbf*ft", "lbf*in")),
        Kind("moment of inertia", "kg*m**2", "'0.1 kg*m^2'", ("kg*m^2", "g*cm^2", "lb*ft^2"), INERTIA_BOUNDS),
        Kind("force", "N", "6 N", ("N", "kN", "lbf")),
        Kind("acceleration", "m/s**2", "'9.81 m/s^2'", ("m/s^2", "ft/s^2", "g0")),
        Kind("velocity", "m/s", "2 m/s", ("m/s", "km/h", "ft/s", "mph")),
        Kind("viscous coefficient", "N*m*s", "'0.01 N*m*s'", ("N*m*s", "N*m/(rad/s)")),
        Kind("drag coefficient", "N*m*s**2", "'0.001 N*m*s^2'", ("N*m*s^2",)),
        Kind("dimensionless", "", "0.5", ()),
        Kind("power", "W", "1 kW", ("W", "kW", "MW", "hp")),
        Kind("energy", "J", "1 MJ", ("J", "kJ", "MJ", "kW*h", "Wh")),
        Kind("density", "kg/m**3", "'7800 kg/m^3'", ("kg/m^3", "g/cm^3", "lb/ft^3")),
        Kind("torsion constant", "N*m/rad", "0.5 N*m/rad", ("N*m/rad", "N*m/deg", "mN*m/rad")),
    )
}
STANDARD_GRAVITY = 9.80665  # m/s^2: what lbf and kgf are defined with
ANGULAR = frozenset({"angular velocity", "angular acceleration"})
FORCES = frozenset({"force", "torque", "viscous coefficient", "drag coefficient"})  # a mass here is its weight
# How a unit is read, kept beside its SI factor: as pint reads it; revolutions per unit time
# (the factor holds the 2*pi); a weight for a mass (the factor gives newtons, parse divides by g);
# a mass for a force (the factor holds standard gravity).
AS_GIVEN, REVOLUTIONS, WEIGHT, MASS_AS_WEIGHT = 0, 1, 2, 3

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
    ("°", " deg"), ("÷", "/"), ("½", " 1/2"), ("⅓", " 1/3"), ("⅔", " 2/3"), ("¼", " 1/4"), ("¾", " 3/4"),
]  # fmt: skip


class Parsed(NamedTuple):
    """A quantity read from the command line: its SI value, and a note if a reading needs one."""

    value: float
    note: str | None = None


@lru_cache(maxsize=1)
def registry():
    """The one pint registry, built on first use, its definitions cached on disk between runs."""
    import pint  # deferred: pint (about 150 ms with its registry), only for a text the cache has not seen

    where = cache.folder()
    try:
        ureg = pint.UnitRegistry(cache_folder=None if where is None else os.path.join(where, "pint"))
    except Exception:  # an unreadable, unwritable or corrupt cache must not cost the answer
        ureg = pint.UnitRegistry()
    ureg.define("rev = revolution")
    ureg.define("rps = revolution / second")
    ureg.define("taucli_angle = [taucli_angle]")  # to tell a sum of angled and angle-free units (_mixes_angles)
    return ureg


def _screen(text: str, option: str, kind: Kind) -> str:
    """Normalise typography and spellings; refuse text that is unreadable or would be slow to evaluate."""
    cleaned = text.strip()
    for old, new in _NORMALISE:
        cleaned = cleaned.replace(old, new)
    cleaned = cleaned.strip()
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
    cleaned = spellings.respell(cleaned)
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


def _expected(kind: Kind) -> str:
    return "expected a plain number" if kind.name == "dimensionless" else f"expected {_article(kind.name)}"


def _pint_quantity(cleaned: str, option: str, kind: Kind, shown: str):
    """pint's Quantity for screened text, as pint reads it (a bare number stays without units)."""
    import pint  # deferred: pint, as in registry()

    ureg = registry()
    try:
        q = ureg.Quantity(cleaned)
    except pint.UndefinedUnitError as err:
        name = str(getattr(err, "unit_names", [""])[0] if getattr(err, "unit_names", None) else err)
        raise InputError(option, _expected(kind), example=kind.example, got=f"{shown!r}: unknown unit {name!r}", hint=_suggest(name, kind)) from None
    except (OverflowError, ZeroDivisionError):
        raise InputError(option, _expected(kind), example=kind.example, got=f"{shown!r}: out of range") from None
    except Exception:  # pint's tokenizer and evaluator raise many kinds; none may escape as a traceback
        raise InputError(option, _expected(kind), example=kind.example, got=f"{shown!r}, which is not a quantity") from None
    return q if isinstance(q, ureg.Quantity) else ureg.Quantity(1, q)  # a bare unit name such as "kg"


def quantity(text: str, option: str, kind_name: str, *, original: str | None = None):
    """Read text as a pint Quantity of the given kind (bare numbers take the kind's SI unit).

    ``original`` is the text as the user typed it, for messages, when ``text`` is a part of it.
    """
    kind = KINDS[kind_name]
    q = _pint_quantity(_screen(text, option, kind), option, kind, text if original is None else original)
    if not list(q.unit_items()) and kind.si_unit:
        q = registry().Quantity(q.magnitude, kind.si_unit)
    return q, kind


def _a_unit(name: str) -> bool:
    """Whether pint knows ``name`` as a unit. ``name in registry`` raises for some names (it reads
    "nan" as a number with no unit, looks "__dict__" up as an attribute): those are not units."""
    try:
        return name in registry()
    except Exception:  # noqa: BLE001 - whatever pint raises, the name is not one of its units
        return False


def _suggest(name: str, kind: Kind, *, typo: bool = True) -> str | None:
    """'did you mean ...?' for a unit name in the wrong case ("KG", "MG", "nm" for a torque), or
    (``typo``) for a misspelling of one of the kind's common units."""
    ureg = registry()
    wanted = ureg.Quantity(1, kind.si_unit).dimensionality
    folded = name.lower().replace("*", "")
    close = [unit for unit in (*kind.common_units, *spellings.GLUED.values()) if unit.lower().replace("*", "") == folded and unit != name]
    for variant in (name.lower(), name.upper(), name.capitalize(), name[:1].lower() + name[1:].upper()):
        if variant != name and _a_unit(variant):
            close.append(variant)
    close = list({spellings.respell(unit): unit for unit in reversed(close) if _fits(unit, wanted)}.values())[::-1]
    if close:
        return "did you mean " + " or ".join(repr(unit) for unit in close[:2]) + "?"
    if not typo:
        return None
    import difflib  # deferred: only a mistyped unit asks for a did-you-mean

    lowered = {unit.lower(): unit for unit in kind.common_units}
    guess = difflib.get_close_matches(name.lower(), list(lowered), n=1, cutoff=0.5)
    return f"did you mean {lowered[guess[0]]!r}?" if guess else None


def _fits(unit: str, wanted) -> bool:
    try:
        return registry().Quantity(spellings.respell(unit)).dimensionality == wanted
    except Exception:
        return False


# "4.5 kg", "300 rpm", "-2 N*m", "1e-3 kg*m^2", "kg", "4", "50 1/s": a number (or none) times a
# product of unit powers. For such text the value is the number times pint's SI factor for the
# unit text, and that factor is cached (taucli.cache); anything else ("4 kg + 200 g") goes to
# pint whole.
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
# Each part matches one way only: a name ends where its letters end, and the space between two
# factors is a separator or part of one, never both. Else a failed match ("kkkk...k+") would try
# every way of cutting the letters into names: 2^n of them, minutes for 30 letters.
_NAME = r"[A-Za-zµμΩ_][A-Za-z0-9µμΩ_]*(?![A-Za-z0-9µμΩ_])"
_POWER_OF = r"(?:\s*(?:\*\*|\^)\s*-?\d{1,2})?"
_BETWEEN = r"(?:\s*[*/]\s*|\s+)?"
_FACTOR = rf"(?:{_NAME}|\(\s*{_NAME}{_POWER_OF}(?:{_BETWEEN}{_NAME}{_POWER_OF})*\s*\)){_POWER_OF}"
_UNIT = rf"(?:(?:1\s*)?/\s*)?{_FACTOR}(?:{_BETWEEN}{_FACTOR})*"
_NUMBER_TIMES_UNIT = re.compile(rf"\s*(?P<number>{_NUMBER})?\s*(?P<unit>{_UNIT})?\s*")


def _number_times_unit(text: str) -> tuple[float, str] | None:
    """(4.5, "kg") read from "4.5 kg"; (50.0, "1/s") from "50 1/s"; None for any other form of text.

    The unit comes back in one spelling for one meaning (no spaces, "1/s" for "/s"), the key of
    its cached factor.
    """
    if len(text) > 2 * MAX_TEXT_LENGTH:
        return None
    split = _NUMBER_TIMES_UNIT.fullmatch(text)
    if split is None:
        return None
    number, unit = split.group("number"), re.sub(r"\s+", "", split.group("unit") or "")
    if unit.startswith("/"):
        unit = "1" + unit
    if number is None:
        return (1.0, unit) if unit else None
    if len(number) > MAX_DIGITS + 8:
        return None
    return float(number), unit


def _from_pint(cleaned: str, text: str, option: str, kind: Kind) -> tuple[float, int]:
    """The SI value of ``cleaned`` as pint reads it under taucli's rules, and how it was read
    (AS_GIVEN, REVOLUTIONS, WEIGHT: the value is in newtons, MASS_AS_WEIGHT)."""
    import pint  # deferred: pint, as in registry()

    ureg = registry()
    q = _pint_quantity(cleaned, option, kind, text)
    if kind.name in ANGULAR | {"angle", "dimensionless"} and _mixes_angles(cleaned):
        fix = {"angle": "'30 deg + 1 deg'", "dimensionless": "no angle"}.get(kind.name, "'1 rpm + 60 rpm'")
        raise InputError(option, _expected(kind), example=kind.example, got=f"{text!r}: it adds a unit with an angle to one without", hint=f"give every term the same kind of unit: {fix}")
    if not list(q.unit_items()):  # a number, or numbers with operators: the kind's SI unit
        try:
            value = float(q.magnitude)
        except (OverflowError, TypeError, ValueError):
            raise InputError(option, _expected(kind), example=kind.example, got=f"{text!r}: out of range") from None
        if kind.name == "angle" and value != 0:
            raise _bare_angle(option, text)
        return value, AS_GIVEN
    how, target = AS_GIVEN, kind.si_unit
    wanted = ureg.Quantity(1, kind.si_unit).dimensionality
    try:
        if kind.name == "mass" and q.dimensionality == ureg.Quantity(1, "N").dimensionality:
            how, target = WEIGHT, "N"
        elif kind.name in FORCES and q.dimensionality != wanted and (q * ureg.Quantity(1, "m/s**2")).dimensionality == wanted:
            how, q = MASS_AS_WEIGHT, q * ureg.Quantity(STANDARD_GRAVITY, "m/s**2")
        value = float(q.to(target).magnitude)
    except pint.errors.OffsetUnitCalculusError:  # degC, degF: a temperature, which pint will not multiply
        raise InputError(option, _expected(kind), example=kind.example, got=f"{text!r}, which is a temperature") from None
    except pint.DimensionalityError:
        raise InputError(
            option, _expected(kind), example=kind.example, got=f"{text!r}, which is {_describe(q.dimensionality)}", hint=_case_of(cleaned, kind)
        ) from None
    except (OverflowError, TypeError, ValueError):
        raise InputError(option, _expected(kind), example=kind.example, got=f"{text!r}: out of range") from None
    radians = _radians(q.units)
    if kind.name in ANGULAR and radians == 0:  # 1/time for a rotation: revolutions per unit time
        how, value = REVOLUTIONS, value * TWO_PI
    elif kind.name == "angle" and radians == 0 and value != 0:
        raise _bare_angle(option, text)
    elif kind.name == "dimensionless" and radians != 0:
        raise InputError(option, "expected a plain number", example=kind.example, got=f"{text!r}, which is an angle")
    return value, how


def _radians(unit) -> int:
    """The power of the radian in a unit: 1 in rpm and deg/s, 0 in Hz and 1/s, -1 in N*m/rpm."""
    return dict(registry().Quantity(1, unit).to_root_units().unit_items()).get("radian", 0)


def _mixes_angles(cleaned: str) -> bool:
    """Whether text adds terms with an angle to terms without ("1 rpm + 1 Hz", "30 deg + 1"), which
    pint does by reading the radian as 1: the check gives every angle unit a dimension of its own."""
    import pint  # deferred: pint, as in registry()

    ureg = registry()
    marked = [f"({t.text}*taucli_angle)" if t.kind == "name" and _a_unit(t.text) and _radians(t.text) else t.text for t in spellings.tokens(cleaned)]
    try:
        ureg.Quantity("".join(marked))
    except pint.DimensionalityError:
        return True
    except Exception:  # not pint's to read either way: the reading itself says so
        return False
    return False


def _case_of(cleaned: str, kind: Kind) -> str | None:
    """A unit of the kind that ``cleaned``'s unit is in another case of ("nm" for a torque: N*m)."""
    split = _number_times_unit(cleaned)
    return _suggest(split[1], kind, typo=False) if split and re.fullmatch(r"[A-Za-z]+", split[1]) else None


def _bare_angle(option: str, text: str) -> InputError:
    return InputError(option, "expected an angle with its unit", example="60deg or 1.05rad", got=f"{text!r}: a number alone could be degrees or radians")


def _factor_key(unit: str, kind: Kind) -> str:
    return f"{kind.si_unit}|{kind.name}|{unit}"


_FACTORS: dict[str, tuple[float, int]] = {}  # this process's copy of the store, checked once


def _cached_factor(unit: str, kind: Kind) -> tuple[float, int] | None:
    key = _factor_key(unit, kind)
    found = _FACTORS.get(key)
    if found is None:
        stored = cache.unit_factors().get(key)
        if isinstance(stored, list) and len(stored) == 2 and isinstance(stored[0], float) and isinstance(stored[1], int):
            if math.isfinite(stored[0]) and stored[0] and stored[1] in (AS_GIVEN, REVOLUTIONS, WEIGHT, MASS_AS_WEIGHT):
                found = _FACTORS[key] = (stored[0], stored[1])
    return found


def unit_factor(unit: str, text: str, option: str, kind: Kind) -> tuple[float, int]:
    """SI value of one ``unit`` of ``kind``, and how it was read (AS_GIVEN, REVOLUTIONS, ...).

    pint is asked once per unit text; its answer is kept in memory and on disk (taucli.cache).
    A bare number is the kind's SI unit, so "" needs no pint at all. ``text`` is what the user
    typed, for messages.
    """
    if not unit:
        return 1.0, AS_GIVEN
    found = _cached_factor(unit, kind)
    if found is None:
        found = _from_pint(unit, text, option, kind)
        if math.isfinite(found[0]) and found[0] != 0:
            cache.unit_factors().put(_factor_key(unit, kind), list(found))
    return found


class Reading(NamedTuple):
    """What ``read`` made of a text."""

    value: float  # SI (a weight for a mass in newtons: parse divides by g)
    how: int  # AS_GIVEN, REVOLUTIONS, WEIGHT, MASS_AS_WEIGHT
    unit: str | None  # the unit as looked up: "" for a bare number, None for an expression pint read whole
    mixed: str | None = None  # "33 1/3" when a mixed number was read


# A number alone, or a number and a plain unit ("4.5kg", "-2 N*m", "300 rpm", "0.1 kg*m^2"): a
# unit read once in this process is read again as number × the factor found then, without the
# screen and the respelling (which give a plain unit the same reading every time). A batch of
# scenes sends thousands of such texts. Anything else takes the whole way.
_PLAIN_NUMBER = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*")
_PLAIN_NAME = r"[A-Za-zµμΩ°][A-Za-zµμΩ°.]*(?:(?:\^|\*\*)-?\d{1,2})?"  # kg, N.m, m^2, s**-1
_PLAIN_UNIT = rf"{_PLAIN_NAME}(?:[*/·]{_PLAIN_NAME})*"  # one way only to match: no backtracking to speak of
_PLAIN = re.compile(rf"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*({_PLAIN_UNIT})\s*")
_READ_BEFORE: dict[tuple[str, str], tuple[float, int, str]] = {}  # (unit as typed, kind) -> (factor, how, unit read)


def read(text: str, option: str, kind: Kind) -> Reading:
    """``text`` read as ``kind``: screened and respelled, numbers side by side refused, then
    number times the unit's (cached) factor, or pint's reading of the whole expression."""
    plain = _PLAIN.fullmatch(text) if len(text) <= MAX_TEXT_LENGTH else None
    if plain is not None and len(plain[1]) <= MAX_DIGITS:
        found = _READ_BEFORE.get((plain[2], kind.name))
        if found is not None:
            return Reading(float(plain[1]) * found[0], found[1], found[2])
    elif len(text) <= MAX_TEXT_LENGTH and (bare := _PLAIN_NUMBER.fullmatch(text)) is not None and len(bare[1]) <= MAX_DIGITS:
        return Reading(float(bare[1]), AS_GIVEN, "")
    reading, number, factor = _read(text, option, kind)
    if plain is not None and reading.mixed is None and reading.unit and number == float(plain[1]):
        _READ_BEFORE[(plain[2], kind.name)] = (factor, reading.how, reading.unit)  # the number was read as typed
    return reading


def known(text: str, kind_name: str, sign: str) -> float | None:
    """``parse``'s value for a plain "number unit" whose unit was read before as given, within
    its kind's bounds and of its sign: there is no note to make and nothing to refuse. None
    for anything else, which ``parse`` then reads the whole way (and refuses, if it must)."""
    plain = _PLAIN.fullmatch(text) if len(text) <= MAX_TEXT_LENGTH else None
    if plain is None or len(plain[1]) > MAX_DIGITS:
        return None
    found = _READ_BEFORE.get((plain[2], kind_name))
    if found is None or found[1] != AS_GIVEN:
        return None
    value = float(plain[1]) * found[0]
    low, high = KINDS[kind_name].bounds
    return value if low <= abs(value) <= high and (value > 0 or sign == "any") else None


def _read(text: str, option: str, kind: Kind) -> tuple[Reading, float | None, float | None]:
    """``read``'s whole way, and the number and the unit's factor where it read number × unit."""
    cleaned = _screen(text, option, kind)
    mixed = spellings.mixed_number(cleaned)
    split = None
    if mixed is not None:
        split = _number_times_unit(mixed.rest) if mixed.rest else (1.0, "")
        split = split and (mixed.value, split[1])
    if split is None:
        beside = spellings.side_by_side(cleaned)
        if beside is not None:
            raise _side_by_side(beside, text, option, kind)
        split = _number_times_unit(cleaned)
        if split is None:
            return Reading(*_from_pint(cleaned, text, option, kind), None), None, None
    number, unit = split
    factor, how = unit_factor(unit, text, option, kind)
    return Reading(number * factor, how, unit, mixed and mixed.shown), number, factor


def _side_by_side(beside: spellings.SideBySide, text: str, option: str, kind: Kind) -> InputError:
    why, fix = beside.said()
    return InputError(option, _expected(kind), example=kind.example, got=f"{text!r}: {why}", hint=fix)


def parse(text: str, option: str, kind_name: str, *, sign: str = "positive", gravity: float | None = None) -> Parsed:
    """Read ``text`` as a quantity of ``kind_name`` and return its SI value, and a note on how it
    was read where that is not plain.

    ``sign`` is "positive" (> 0), "nonnegative" (>= 0) or "any". A bare number means the kind's
    SI unit, except for an angle, which needs its unit (0 aside). 1/time for an angular velocity
    or acceleration (Hz, 1/s, min^-1) means revolutions per unit time (omega = 2 pi n). A weight
    for a mass is the mass W/g, with ``gravity`` in m/s^2 (None: standard gravity, 9.80665).
    """
    kind = KINDS[kind_name]
    reading = read(text, option, kind)
    value = reading.value
    if reading.unit == "" and kind.name == "angle" and value != 0:
        raise _bare_angle(option, text)
    g = STANDARD_GRAVITY if gravity is None else gravity
    if reading.how == WEIGHT:
        if not (math.isfinite(g) and g > 0):
            raise InputError(option, "is a weight, which needs a positive gravity to give a mass", example="--g 9.81", got=f"g = {g!r}")
        value /= g
    _check(value, text, option, kind, sign)
    return Parsed(value, _note(option, text.strip(), reading, value, gravity, kind))


def _check(value: float, text: str, option: str, kind: Kind, sign: str) -> None:
    """A value read from ``text`` must be finite, within its kind's bounds, and of its sign."""
    if not math.isfinite(value):
        raise InputError(option, f"expected a finite {kind.name}", example=kind.example, got=repr(text))
    low, high = kind.bounds
    if value and not low <= abs(value) <= high:  # (the message's "got" is worked out only then)
        check_bounds(value, kind.name, option, sign=sign, got=repr(text) if _is_number(text) else None, text=text)
    if sign == "positive" and value <= 0:
        raise InputError(option, f"expected a positive {kind.name}", example=kind.example, got=repr(text))
    if sign == "nonnegative" and value < 0:
        raise InputError(option, f"expected a {kind.name} of zero or more", example=kind.example, got=repr(text))


def si_number(value: float, option: str, kind_name: str, *, sign: str = "positive") -> float:
    """A number given as SI (a JSON number in a batch line, a float from Python), checked as a
    text would be: finite, within bounds, of its sign. No unit to read, so an angle is radians."""
    _check(float(value), repr(value), option, KINDS[kind_name], sign)
    return float(value)


def check_bounds(value: float, kind_name: str, option: str, *, sign: str = "nonnegative", got: str | None = None, text: str | None = None) -> None:
    """Refuse a nonzero ``value`` (SI) outside its kind's bounds, typed or computed, as parse does.

    ``got`` says what was given ("I = 4e+119 kg*m**2"); by default the text and its SI value.
    """
    kind = KINDS[kind_name]
    low, high = kind.bounds
    if math.isfinite(value) and (not value or low <= abs(value) <= high):
        return
    zero = "" if sign == "positive" else "of 0 or "
    shown = got or f"{text!r} = {value:g} {kind.si_unit}".rstrip()
    raise InputError(option, f"expected {_article(kind.name)} {zero}between {_power_of_ten(low)} and {_power_of_ten(high)} {kind.si_unit} in size", example=kind.example, got=shown)


def _power_of_ten(x: float) -> str:
    return f"{x:.0e}".replace("e+", "e").replace("e0", "e").replace("e-0", "e-")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _note(option: str, text: str, reading: Reading, value: float, gravity: float | None, kind: Kind) -> str | None:
    """What a reader should know about how ``text`` was read, or None when it was read plainly."""
    said = []
    if reading.mixed:
        said.append(f"{reading.mixed} read as the mixed number {reading.mixed.replace(' ', ' + ')}")
    if reading.how == REVOLUTIONS:
        squared = kind.name == "angular acceleration"
        said.append(f"{spellings.revolutions(reading.unit, squared=squared)} ({'1 rev = 2π rad' if squared else 'ω = 2πn'})")
    elif reading.how == WEIGHT:
        g = f"standard gravity g = {STANDARD_GRAVITY} m/s²" if gravity is None else f"g = {gravity:g} m/s²"
        said.append(f"a weight, read as the mass W/g = {value:.6g} kg ({g})")
    elif reading.how == MASS_AS_WEIGHT:
        said.append(spellings.as_force(reading.unit))
    return f"{option} {text}: " + "; ".join(said) if said else None


def convert(value: float, si_unit: str, target: str, option: str) -> float:
    """Express an SI value in the unit ``target`` (``--to``), with 1/time read as revolutions."""
    return converted(value, si_unit, target, option).value


def converted(value: float, si_unit: str, target: str, option: str) -> Parsed:
    """``convert``, with a note when a unit was read as revolutions, or a mass as a force."""
    kind = next((k for k in KINDS.values() if k.si_unit == si_unit), Kind("quantity", si_unit, si_unit))
    example = kind.common_units[0] if kind.common_units else si_unit
    example = f"'{example}'" if re.search(r"[*^()]", example) else example  # as typed in zsh, where * and ^ glob

    def refuse() -> InputError:
        return InputError(option, f"expected a unit of {_article(kind.name)}", example=example, got=repr(target))

    cleaned = _screen(target, option, kind)
    split = _number_times_unit(cleaned)
    if split is None or not split[1] or (re.match(r"\s*[-+\d.]", cleaned) and not re.match(r"\s*1\s*/", cleaned)):
        raise refuse()  # a unit alone: "rpm", "1/s", not "2 rpm"
    try:
        factor, how = unit_factor(split[1], target, option, kind)
    except InputError:
        raise refuse() from None
    if how == WEIGHT:  # a mass in newtons would depend on g
        raise refuse()
    note = None
    if how == REVOLUTIONS:
        note = f"{option} {target.strip()}: {spellings.revolutions(split[1], squared=kind.name == 'angular acceleration')} (n = ω/2π)"
    elif how == MASS_AS_WEIGHT:
        note = f"{option} {target.strip()}: {spellings.as_force(split[1])}"
    return Parsed(value / factor, note)
