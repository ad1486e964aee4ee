"""The one pint registry, and what it makes of a unit's text under taucli's rules.

pint is imported and its registry built only here, and only for a text taucli has not read before
(taucli.quantities.units keeps each unit's SI factor, taucli.quantities.cache keeps it between runs). The rules: for an
angular velocity or acceleration, a 1/time with no angle in it is revolutions where it says so
(``Hz``, ``min^-1``: ω = 2πn), radians where it is a speed over a length (``(90 km/h)/(60 m)``:
ω = v/R), and refused as ambiguous otherwise (``1/s``, ``s^-2``); an angle, an angular velocity
and an angular acceleration need their unit, 0 apart; a sum may not add a unit with an angle to
one without; a weight for a mass is read in newtons (taucli.quantities.units divides by g), a mass for a force
is its weight at standard gravity; a prefix's name glued to a unit's symbol (``kilos``: pint's
kilosecond) is no unit. Hz inside any unit with an angle, a power as torque times speed, and the
power of the angle each kind's unit must hold are taucli.quantities.meanings' rule, applied here.
"""

from __future__ import annotations

import math
import os
import re
from functools import lru_cache

from taucli.quantities import cache
from taucli.quantities import meanings
from taucli.quantities import spellings
from taucli.core.errors import InputError
from taucli.quantities.kinds import (  # noqa: F401 - NEEDS_ITS_UNIT, bare_number: read from here by units
    ANGLE_POWERS, ANGULAR, FORCES, KINDS, NEEDS_ITS_UNIT, STANDARD_GRAVITY, Kind, article, bare_angle, bare_number,
)
from taucli.quantities.screen import screen
from taucli.quantities.unit_text import NUMBER, number_times_unit


TWO_PI = 2.0 * math.pi


# How a unit is read, kept beside its SI factor: as pint reads it; revolutions per unit time
# (the factor holds the 2*pi); a weight for a mass (the factor gives newtons, parse divides by g);
# a mass for a force (the factor holds standard gravity); a speed (or a tangential acceleration)
# over a length, ω = v/R, in radians.
AS_GIVEN, REVOLUTIONS, WEIGHT, MASS_AS_WEIGHT, OVER_RADIUS = 0, 1, 2, 3, 4
WEIGHT_INERTIA = 5  # lb*ft^2 for a moment of inertia: a mass-pound, which is also the number of a WR² (weight-inertia)
# A weight times a length² for a moment of inertia: a GD² (a motor's flywheel effect, kgf·m²), J = GD²/4g; and
# kgf·length·s², the technical units' inertia: both read with standard gravity, the kgf's own, and a note saying so.
GD2, KGF_INERTIA = 12, 13
HOWS = (AS_GIVEN, REVOLUTIONS, WEIGHT, MASS_AS_WEIGHT, OVER_RADIUS, WEIGHT_INERTIA, *meanings.HOWS, GD2, KGF_INERTIA)  # and the notes of taucli.quantities.meanings
_POUND_MASSES = frozenset({"pound", "ounce"})


_KGF = frozenset({"force_kilogram", "kilogram_force"})


def _in_kgf(q) -> bool:
    """Whether ``q``'s unit holds a kgf: kgf·m² for an inertia is the metric books' GD² (J = GD²/4g). A
    lbf·ft² could as well be a US WR² (J = WR²/g, a factor of 4 apart) and N·m² either: both stay refused."""
    return bool(_KGF & {name for name, _ in q.unit_items()})


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


@lru_cache(maxsize=1)
def registry():
    """The one pint registry, built on first use, its definitions cached on disk between runs."""
    import pint  # deferred: pint (about 150 ms with its registry), only for a text the cache has not seen

    where = cache.folder()
    kept = None if where is None else os.path.join(where, "pint")
    if kept is not None and not cache.checked_folder(kept):  # pint's pickles, checked: an edited one is not read
        kept = None
    try:
        ureg = pint.UnitRegistry(cache_folder=kept)
    except Exception:  # an unreadable, unwritable or corrupt cache must not cost the answer
        ureg = pint.UnitRegistry()
    else:
        if kept is not None:
            cache.seal(kept)
    ureg.define("rev = revolution")
    ureg.define("rps = revolution / second")
    ureg.define("@alias metric_horsepower = PS")  # Pferdestärke, not pint's petasiemens (taucli.quantities.meanings)
    ureg.define("taucli_angle = [taucli_angle]")  # to tell a sum of angled and angle-free units (_mixes_angles)
    return ureg


_BASES = (("[length]", "length", "m"), ("[time]", "time", "s"), ("[mass]", "mass", "kg"))


def _describe(dimensionality) -> str:
    """What a dimension is, in words: "a force", "a torque or energy times a length", else its SI
    units ("a quantity in kg·m³/s²"): never pint's "[length] ** 3 * [mass]" (#42)."""
    dims = {name: power for name, power in dict(dimensionality).items() if power}
    named = _DIMENSION_NAMES.get(frozenset(dims.items()))
    if named:
        return named
    for base, word, _ in _BASES:
        for power, joiner in ((1, f"times a {word}"), (-1, f"per {word}")):
            rest = {name: left for name, left in {**dims, base: dims.get(base, 0) - power}.items() if left}
            if rest and (named := _DIMENSION_NAMES.get(frozenset(rest.items()))):
                return f"{named} {joiner}"
    symbols = {base: symbol for base, _, symbol in _BASES}
    up = [symbols.get(name, name.strip("[]")) + _power(power) for name, power in sorted(dims.items()) if power > 0]
    down = [symbols.get(name, name.strip("[]")) + _power(-power) for name, power in sorted(dims.items()) if power < 0]
    return "a quantity in " + ("·".join(up) or "1") + ("/" + "·".join(down) if down else "")


def _power(power) -> str:
    return "" if power == 1 else str(power).translate(str.maketrans("0123456789.-", "⁰¹²³⁴⁵⁶⁷⁸⁹·⁻"))


def expected(kind: Kind) -> str:
    return "expected a plain number" if kind.name == "dimensionless" else f"expected {article(kind.name)}"


def _pint_quantity(cleaned: str, option: str, kind: Kind, shown: str):
    """pint's Quantity for screened text, as pint reads it (a bare number stays without units)."""
    import pint  # deferred: pint, as in registry()

    ureg = registry()
    for token in spellings.tokens(cleaned):
        if token.kind == "name" and token.text in meanings.AMBIGUOUS_TONS:
            number = re.match(rf"\s*({NUMBER})", shown)
            why, fix = meanings.ton_refusal(token.text, number[1] if number else "1", kind.name in FORCES)
            raise InputError(option, expected(kind), example=kind.typed, got=f"{shown!r}: {why}", hint=fix)
        if token.kind == "name" and (mixed := _prefix_name_on_symbol(token.text)) is not None:
            meant = _unmixed(mixed, kind)
            raise InputError(option, expected(kind), example=kind.typed, got=f"{shown!r}: unknown unit {token.text!r}",
                             hint=f"did you mean {meant!r}?" if meant else None)
    try:
        q = ureg.Quantity(cleaned)
    except pint.UndefinedUnitError as err:
        name = str(getattr(err, "unit_names", [""])[0] if getattr(err, "unit_names", None) else err)
        raise InputError(option, expected(kind), example=kind.typed, got=f"{shown!r}: unknown unit {name!r}", hint=_suggest(name, kind)) from None
    except (OverflowError, ZeroDivisionError):
        raise InputError(option, expected(kind), example=kind.typed, got=f"{shown!r}: out of range") from None
    except Exception:  # pint's tokenizer and evaluator raise many kinds; none may escape as a traceback
        raise InputError(option, expected(kind), example=kind.typed, got=f"{shown!r}, which is not a quantity") from None
    return q if isinstance(q, ureg.Quantity) else ureg.Quantity(1, q)  # a bare unit name such as "kg"


def quantity(text: str, option: str, kind_name: str, *, original: str | None = None):
    """Read text as a pint Quantity of the given kind (bare numbers take the kind's SI unit).

    ``original`` is the text as the user typed it, for messages, when ``text`` is a part of it.
    """
    kind = KINDS[kind_name]
    q = _pint_quantity(screen(text, option, kind), option, kind, text if original is None else original)
    if not list(q.unit_items()) and kind.si_unit:
        q = registry().Quantity(q.magnitude, kind.si_unit)
    return q, kind


def _a_unit(name: str) -> bool:
    """Whether pint knows ``name`` as a unit (and taucli takes it: not "kilos"). ``name in
    registry`` raises for some names (it reads "nan" as a number with no unit, looks "__dict__" up
    as an attribute): those are not units."""
    try:
        return name in registry() and _prefix_name_on_symbol(name) is None
    except Exception:  # noqa: BLE001 - whatever pint raises, the name is not one of its units
        return False


def _prefix_name_on_symbol(name: str) -> tuple[str, str] | None:
    """(the prefix's symbol, the unit's symbol) where pint would read ``name`` as a prefix written
    as its name glued to a unit written as its symbol ("kilos": kilo + s, a kilosecond; "megas",
    "millim", "kiloN"), else None. SI writes a prefix's name with a unit's name (kilogram) and its
    symbol with a symbol (kg): the mixed word is no unit a person means ("kilos" are kilograms),
    so it is refused as unknown rather than read as pint reads it. A prefix's symbol on a unit's
    name ("kmeter", "mbar") reads as meant and is left to pint. The first reading found is
    pint's own (PlainRegistry._yield_unit_triplets, same order)."""
    ureg = registry()
    units = ureg._units
    if name in units:
        return None
    for suffix, prefix in ((suffix, prefix) for suffix in ureg._suffixes for prefix in ureg._prefixes):
        if not (name.startswith(prefix) and name.endswith(suffix)):
            continue
        rest = name[len(prefix) : len(name) - len(suffix)]
        if suffix and len(rest) == 1 or rest not in units:
            continue
        if not prefix:
            return None  # a unit with a plural s ("mins"): pint's first reading has no prefix
        definition, prefixed = units[rest], ureg._prefixes[prefix]
        named = prefix == prefixed.name or (prefix in prefixed.aliases and len(prefix) >= 4)  # "kilo", "deka"; not "mu"
        symbol = rest != definition.name and not (rest in definition.aliases and len(rest) >= 4)  # "s", "min", "sec"; not "litre"
        return (prefixed.symbol, definition.symbol) if named and symbol else None
    return None


def _unmixed(mixed: tuple[str, str], kind: Kind) -> str | None:
    """What a prefix's name on a unit's symbol may have meant, as a unit of ``kind``: the prefix's
    symbol on it ("ks" for "kilos" given as a time), or on one of the kind's units ("kg" for
    "kilos" given as a mass); None where neither is of the kind."""
    prefix, symbol = mixed
    wanted = registry().Quantity(1, kind.si_unit).dimensionality
    return next((unit for unit in (prefix + symbol, *(prefix + common for common in kind.common_units)) if _a_unit(unit) and _fits(unit, wanted)), None)


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
        elif variant != name and (mixed := _prefix_name_on_symbol(variant)) is not None and (meant := _unmixed(mixed, kind)):
            close.append(meant)  # "Kilos" for a mass: "kilos", no unit, meant "kg"
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


def from_pint(cleaned: str, text: str, option: str, kind: Kind) -> tuple[float, int]:
    """The SI value of ``cleaned`` as pint reads it under taucli's rules, and how it was read
    (AS_GIVEN, REVOLUTIONS, WEIGHT: the value is in newtons, MASS_AS_WEIGHT)."""
    import pint  # deferred: pint, as in registry()

    ureg = registry()
    revolutions = False
    if kind.name in ANGLE_POWERS or kind.name == "dimensionless":  # Hz is rev/s wherever it stands (taucli.quantities.meanings)
        cleaned, revolutions = meanings.with_revolutions(ureg, cleaned)
    q = _pint_quantity(cleaned, option, kind, text)
    if kind.name in ANGULAR | {"angle", "dimensionless", "lead"} and _mixes_angles(cleaned):
        fix = {"angle": "'30 deg + 1 deg'", "dimensionless": "no angle", "lead": "'5 mm + 1 mm'"}.get(kind.name, "'1 rpm + 60 rpm'")
        raise InputError(option, expected(kind), example=kind.typed, got=f"{text!r}: it adds a unit with an angle to one without", hint=f"give every term the same kind of unit: {fix}")
    if list(q.unit_items()) and all(name in meanings.CONSTANTS for name, _ in q.unit_items()):
        q = ureg.Quantity(float(q.to("").magnitude))  # 2 pi: a number
    if not list(q.unit_items()):  # a number, or numbers with operators: the kind's SI unit
        try:
            value = float(q.magnitude)
        except (OverflowError, TypeError, ValueError):
            raise InputError(option, expected(kind), example=kind.typed, got=f"{text!r}: out of range") from None
        if kind.name in NEEDS_ITS_UNIT and value != 0:
            raise bare_number(option, text, kind, value)
        return value, AS_GIVEN
    how, target = AS_GIVEN, kind.si_unit
    wanted = ureg.Quantity(1, kind.si_unit).dimensionality
    try:
        if kind.name == "mass" and q.dimensionality == ureg.Quantity(1, "N").dimensionality:
            how, target = WEIGHT, "N"
        elif kind.name == "moment of inertia" and q.dimensionality == ureg.Quantity(1, "N*m**2").dimensionality and _in_kgf(q):
            how, q = GD2, q / ureg.Quantity(4 * STANDARD_GRAVITY, "m/s**2")  # GD² = 4gJ: G the weight, D the diameter of gyration
        elif kind.name in FORCES and q.dimensionality != wanted and (q * ureg.Quantity(1, "m/s**2")).dimensionality == wanted:
            how, q = MASS_AS_WEIGHT, q * ureg.Quantity(STANDARD_GRAVITY, "m/s**2")
        value = float(q.to(target).magnitude)
    except pint.errors.OffsetUnitCalculusError:  # degC, degF: a temperature, which pint will not multiply
        raise InputError(option, expected(kind), example=kind.typed, got=f"{text!r}, which is a temperature") from None
    except pint.DimensionalityError:
        per_length = kind.name == "lead" and dict(q.dimensionality) == {"[length]": -1}  # threads per inch
        raise InputError(
            option, expected(kind), example=kind.typed, got=f"{text!r}, which is {_describe(q.dimensionality)}",
            hint="a lead is the advance per turn: 1/(threads per inch) for a single start, e.g. 0.2in for 5 per inch" if per_length else _case_of(cleaned, kind),
        ) from None
    except (OverflowError, TypeError, ValueError):
        raise InputError(option, expected(kind), example=kind.typed, got=f"{text!r}: out of range") from None
    if kind.name == "moment of inertia" and how == AS_GIVEN and _POUND_MASSES & {name for name, _ in q.unit_items()}:
        how = WEIGHT_INERTIA  # lb*ft^2, oz*in^2: read as mass × length², which is a WR²'s number too (a note says so)
    elif kind.name == "moment of inertia" and how == AS_GIVEN and _in_kgf(q):
        how = KGF_INERTIA  # kgf*cm*s^2: the technical units' inertia, with standard gravity in the kgf (a note says so)
    radians = _radians(q.units)
    if kind.name in _RATES or kind.name == "dimensionless" and radians != 0:
        value, how = _angled(cleaned, q, text, option, kind, value, how, revolutions)
    elif kind.name == "angle" and radians == 0 and value != 0:
        raise bare_angle(option, text, value)
    elif kind.name == "angle" and radians not in (0, 1):
        raise InputError(option, expected(kind), example=kind.typed, got=f"{text!r}: its unit has {meanings.angle_power_words(radians)}; an angle has it once")
    elif kind.name == "lead" and radians != -1:  # pint reads rev as 2π: m/rev is m/(2π) to it
        if radians != 0:
            raise InputError(option, "expected a lead, a length per revolution", example=kind.typed, got=f"{text!r}, which is not a length per turn")
        value /= TWO_PI  # a length alone is the advance per revolution
    if how == AS_GIVEN:
        how = meanings.named(ureg, q, kind.name) or AS_GIVEN
    return value, how


_RATES = ANGULAR | {"viscous coefficient", "drag coefficient", "torsion constant", "angular momentum"}  # L = Iω: kg*m^2*rpm


def _angled(cleaned: str, q, text: str, option: str, kind: Kind, value: float, how: int, revolutions: bool) -> tuple[float, int]:
    """The value and how it was read, for a kind with an angle in its unit (or a plain number
    whose unit holds one), by the rule of taucli.quantities.meanings: the unit holds the kind's
    power of the angle, a power counting as a torque times an angular velocity in rad/s; or none,
    where SI leaves the radian out (N*m*s) or registry._per_time decides (a 1/time alone)."""
    wanted = ANGLE_POWERS.get(kind.name, 0)
    radians = _radians(q.units)
    powers = meanings.power_units(registry(), q)
    held = radians + powers
    if held == wanted:
        if powers and radians != wanted or meanings.names_a_power(registry(), cleaned):  # (in a sum, q has the first term's unit)
            return value, meanings.POWER_AS_TORQUE_SPEED
        return value, REVOLUTIONS if revolutions else how
    if kind.name == "dimensionless":
        raise InputError(option, "expected a plain number", example=kind.typed, got=f"{text!r}, which is an angle")
    if held == 0 and kind.name in ANGULAR:  # 1/time for a rotation: revolutions, v/R in radians, or ambiguous
        how = _per_time(cleaned, q, text, option, kind)
        return value * (TWO_PI if how == REVOLUTIONS else 1.0), how
    if held == 0:  # N*m*s, N*m: SI's coherent unit, the radian left out
        times = meanings.other_times(q)
        if times == ["minute"] and dict(q.unit_items())["minute"] * wanted < 0:  # N*m/min^-1: min^-1 is rev/min, as for ω
            return value * TWO_PI**wanted, REVOLUTIONS
        if kind.name == "angular momentum" and all(dict(q.unit_items()).get(t, 0) > 0 for t in times):  # N*m*min: a torque for a time, J = τt
            return value, how
        if times:
            raise _ambiguous_in(times[0], text, option, kind)
        return value, how
    raise InputError(option, expected(kind), example=kind.typed,
                     got=f"{text!r}: its unit has {meanings.angle_power_words(held)}; {article(kind.name)} has {meanings.angle_power_words(wanted)}")


def _ambiguous_in(time: str, text: str, option: str, kind: Kind) -> InputError:
    """The refusal of a time other than the second in a coefficient's unit with no angle in it
    (``N*m*min``): per radian or per revolution per minute."""
    number = re.match(rf"\s*({NUMBER})", screen(text, option, kind))
    return meanings.ambiguous_time(registry().get_symbol(time), time, number[1] if number else "1", text, option, kind)


def _radians(unit) -> int:
    """The power of the radian in a unit: 1 in rpm and deg/s, 0 in Hz and 1/s, -1 in N*m/rpm."""
    return dict(registry().Quantity(1, unit).to_root_units().unit_items()).get("radian", 0)


def _mixes_angles(cleaned: str) -> bool:
    """Whether text adds terms with an angle to terms without ("1 rpm + 1 Hz", "30 deg + 1"), which
    pint does by reading the radian as 1: the check gives every angle unit a dimension of its own."""
    import pint  # deferred: pint, as in registry()

    ureg = registry()
    marked = [f"({t.text}*taucli_angle)" if t.kind == "name" and _a_unit(t.text) and (_radians(t.text) or meanings.power_units(ureg, ureg.Quantity(1, t.text)))
              else t.text for t in spellings.tokens(cleaned)]  # a power is a torque times an angular velocity (P = τω)
    try:
        ureg.Quantity("".join(marked))
    except pint.DimensionalityError:
        return True
    except Exception:  # not pint's to read either way: the reading itself says so
        return False
    return False


def _case_of(cleaned: str, kind: Kind) -> str | None:
    """A unit of the kind that ``cleaned``'s unit is in another case of ("nm" for a torque: N*m)."""
    split = number_times_unit(cleaned)
    return _suggest(split[1], kind, typo=False) if split and re.fullmatch(r"[A-Za-z]+", split[1]) else None


def _per_time(cleaned: str, q, text: str, option: str, kind: Kind) -> int:
    """How a 1/time with no angle in it is read for an angular velocity or acceleration: Hz and
    min^-1 (1/min, min-1) name a rotational frequency n, revolutions per unit time (ISO 80000-3:
    ω = 2πn); a speed over a length (or a tangential acceleration over one) is ω = v/R, in radians;
    any other (1/s, s^-1, /s, s^-2, 1/h) could be either, and is refused."""
    powers = dict(q.unit_items())
    if any(unit.endswith("hertz") and power for unit, power in powers.items()):
        return REVOLUTIONS
    if _over_a_length(cleaned, kind):
        return OVER_RADIUS
    if powers.get("minute", 0) < 0:
        return REVOLUTIONS
    raise _ambiguous(cleaned, q, text, option, kind)


def _over_a_length(cleaned: str, kind: Kind) -> bool:
    """Whether ``cleaned`` is a speed (for an angular acceleration, an acceleration) divided by a
    length: "(90 km/h)/(60 m)", "m/s/m", "(6 m/s^2)/(0.3 m)". It is cut at its last "/" outside
    parentheses, and each side read alone."""
    found = spellings.tokens(cleaned)
    depth, cut = 0, None
    for i, token in enumerate(found):
        depth += (token.text == "(") - (token.text == ")")
        if token.text == "/" and depth == 0:
            cut = i
    if cut is None:
        return False
    ureg = registry()
    try:
        top = ureg.Quantity("".join(token.text for token in found[:cut]))
        bottom = ureg.Quantity("".join(token.text for token in found[cut + 1 :]))
        squared = kind.name == "angular acceleration"
        return top.dimensionality == ureg.Quantity(1, "m/s**2" if squared else "m/s").dimensionality and bottom.dimensionality == ureg.Quantity(1, "m").dimensionality
    except Exception:  # noqa: BLE001 - a side pint cannot read alone is no speed or length
        return False


class Ambiguous(InputError):
    """A 1/time given for an angular velocity or acceleration that could be radians or revolutions."""

    def __init__(self, option: str, kind: Kind, *, got: str, example: str, why: str, per: str) -> None:
        super().__init__(option, f"expected {article(kind.name)} with its angle unit", example=example, got=f"{got}: {why}")
        self.why, self.per = why, per  # "1/s could be radians or revolutions per second", "s"


def _ambiguous(cleaned: str, q, text: str, option: str, kind: Kind) -> Ambiguous:
    """The refusal of a 1/time that names no angle: both readings, in the unit and number typed
    ("80 1/s": 80rad/s or 80rev/s) where that is one time unit to a power, else per second."""
    squared = kind.name == "angular acceleration"
    power = -2 if squared else -1
    items = [(unit, p) for unit, p in q.unit_items() if p]
    whole = screen(text, option, kind)
    split = number_times_unit(whole)
    typed = split is not None and split[1] == cleaned  # number × this unit, as "80 1/s" is
    if len(items) == 1 and items[0][1] == power:
        per, magnitude = items[0][0], float(q.magnitude)
    else:
        per, magnitude = "second", float(q.to(f"1/s**{-power}").magnitude)
    number = re.match(rf"\s*({NUMBER})", whole)
    if typed and magnitude == 1 and number is not None:
        count = number[1]  # as typed
    else:
        count = f"{(split[0] if typed else 1.0) * magnitude:.6g}"
    symbol = registry().get_symbol(per)
    shown = cleaned.replace("**", "^") if typed else f"1/{symbol}" + ("^2" if squared else "")
    why = f"{shown} could be radians or revolutions per {per}{' squared' if squared else ''}"
    example = f"'{count} rad/{symbol}^2' or '{count} rev/{symbol}^2'" if squared else f"{count}rad/{symbol} or {count}rev/{symbol}"
    return Ambiguous(option, kind, got=repr(text), example=example, why=why, per=symbol)
