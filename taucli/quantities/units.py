"""Quantities from text: the one pint registry, and ``parse`` that turns "4 kg" into an SI float.

The registry is built on first use only (``--help`` and completion never build it), pint's
definition cache is kept in taucli's cache folder, and pint's SI factor for each unit text is
remembered there too (taucli.quantities.cache), so a run whose units were seen before never imports pint.
Text is screened before pint sees it: pint evaluates ``**`` with Python integers, so
``9**9**9 kg`` would run for hours if it got that far.

How text is read (docs/units.md has the table): engineering spellings are
rewritten first (taucli.quantities.spellings: ``Nm``, ``N-m``, ``ft-lb``, ``kgm^2``, ``RPM``, ``min-1``); a
whole number then a fraction is a mixed number (``33 1/3 rpm``), and any other numbers side by
side are refused (pint would multiply them); for an angular velocity or acceleration, ``Hz`` and
``min^-1`` are revolutions per unit time (ω = 2πn), a speed over a length is ω = v/R in radians,
and a bare 1/time (``1/s``, ``s^-2``) is refused as ambiguous; an angle, an angular velocity and
an angular acceleration need their unit (``60deg``, ``300rpm``), 0 apart; a weight for a mass is
the mass W/g, and a mass for a force (``lb*ft`` for a torque) its weight at standard gravity.
Every reading that is not plain says so in a note.
Each kind has its bounds (``Kind.bounds``), the same for a quantity typed or computed
(``check_bounds``).
"""

from __future__ import annotations

import math
import re
from typing import NamedTuple

from taucli.quantities import cache
from taucli.quantities import expressions
from taucli.quantities import meanings
from taucli.quantities import spellings
from taucli.core.errors import InputError
from taucli.quantities.kinds import ANGULAR, KINDS, STANDARD_GRAVITY, Kind, article, check_bounds, out_of_bounds
from taucli.quantities.unit_text import number_times_unit
from taucli.quantities.registry import (
    AS_GIVEN, GD2, HOWS, KGF_INERTIA, MASS_AS_WEIGHT, NEEDS_ITS_UNIT, OVER_RADIUS, REVOLUTIONS, WEIGHT, WEIGHT_INERTIA, Ambiguous, bare_number, expected, from_pint,
)
from taucli.quantities.screen import MAX_DIGITS, MAX_TEXT_LENGTH, screen


class Parsed(NamedTuple):
    """A quantity read from the command line: its SI value, and a note if a reading needs one."""

    value: float
    note: str | None = None
    weight: bool = False  # a weight read as a mass, W/g: the reading used gravity


def _factor_key(unit: str, kind: Kind) -> str:
    return f"{kind.si_unit}|{kind.name}|{unit}"


_FACTORS: dict[str, tuple[float, int]] = {}  # this process's copy of the store, checked once


def _cached_factor(unit: str, kind: Kind) -> tuple[float, int] | None:
    key = _factor_key(unit, kind)
    found = _FACTORS.get(key)
    if found is None:
        stored = cache.unit_factors().get(key)
        if stored is None:  # a first run: the factors shipped with taucli, if they hold for this pint
            stored = cache.shipped_unit_factors().get(key)
        if isinstance(stored, list) and len(stored) == 2 and isinstance(stored[0], float) and isinstance(stored[1], int):
            if math.isfinite(stored[0]) and stored[0] and stored[1] in HOWS:
                found = _FACTORS[key] = (stored[0], stored[1])
    return found


def unit_factor(unit: str, text: str, option: str, kind: Kind) -> tuple[float, int]:
    """SI value of one ``unit`` of ``kind``, and how it was read (AS_GIVEN, REVOLUTIONS, ...).

    pint is asked once per unit text; its answer is kept in memory and on disk (taucli.quantities.cache).
    A bare number is the kind's SI unit, so "" needs no pint at all. ``text`` is what the user
    typed, for messages.
    """
    if not unit:
        return 1.0, AS_GIVEN
    found = _cached_factor(unit, kind)
    if found is None:
        found = from_pint(unit, text, option, kind)
        if math.isfinite(found[0]) and found[0] != 0:
            cache.unit_factors().put(_factor_key(unit, kind), list(found))
    return found


def factor_entry(text: str, kind_name: str) -> tuple[str, list] | None:
    """(cache key, [SI factor, how]) of the unit in ``text`` ("1 rpm") as pint reads it for
    ``kind_name``, asking pint itself (for building the shipped table), or None where the text
    is not a number times a unit of that kind."""
    kind = KINDS[kind_name]
    try:
        cleaned = screen(text, "unit", kind)
        split = number_times_unit(cleaned)
        if split is None or not split[1]:
            return None
        found = from_pint(split[1], text, "unit", kind)
    except InputError:  # (Ambiguous too: 1/s for an angular velocity)
        return None
    if not (math.isfinite(found[0]) and found[0]):
        return None
    return _factor_key(split[1], kind), [float(found[0]), int(found[1])]


class Reading(NamedTuple):
    """What ``read`` made of a text."""

    value: float  # SI (a weight for a mass in newtons: parse divides by g)
    how: int  # AS_GIVEN, REVOLUTIONS, WEIGHT, MASS_AS_WEIGHT, OVER_RADIUS
    unit: str | None  # the unit as looked up: "" for a bare number, None for an expression pint read whole
    mixed: str | None = None  # "33 1/3" when a mixed number was read
    said: tuple[str, ...] = ()  # how a function or a grouping was read (sqrt(13) = 3.60555)


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
    for anything else, which ``parse`` then reads the whole way (and refuses, if it must).

    The number is matched and the rest looked up as it is (less the spaces after it): a unit in
    _READ_BEFORE came from _PLAIN's unit group, which holds no space, so a text found this way
    is one _PLAIN matches, split the same way; and the short match costs a batch line less."""
    number = _PLAIN_NUMBER.match(text) if len(text) <= MAX_TEXT_LENGTH else None
    if number is None or len(number[1]) > MAX_DIGITS:
        return None
    found = _READ_BEFORE.get((text[number.end():].rstrip(), kind_name))
    if found is None or found[1] != AS_GIVEN:
        return None
    value = float(number[1]) * found[0]
    low, high = KINDS[kind_name].bounds
    return value if low <= abs(value) <= high and (value > 0 or sign == "any") else None


def _read(text: str, option: str, kind: Kind) -> tuple[Reading, float | None, float | None]:
    """``read``'s whole way, and the number and the unit's factor where it read number × unit."""
    cleaned = screen(text, option, kind)
    said: list[str] = []
    expressions.refuse_other_calls(cleaned, text, option, kind)
    if expressions.has_calls(cleaned):
        cleaned, said = expressions.calls(cleaned, text, option, kind)
    cleaned, grouping = expressions.grouped(cleaned)
    if grouping:
        said.append(grouping)
    if said:  # an expression: pint reads it whole, numbers side by side refused as everywhere
        beside = spellings.side_by_side(cleaned)
        if beside is not None:
            raise _side_by_side(beside, text, option, kind)
        return Reading(*from_pint(cleaned, text, option, kind), None, said=tuple(said)), None, None
    mixed = spellings.mixed_number(cleaned)
    split = None
    if mixed is not None:
        split = number_times_unit(mixed.rest) if mixed.rest else (1.0, "")
        split = split and (mixed.value, split[1])
    if split is None:
        beside = spellings.side_by_side(cleaned)
        if beside is not None:
            raise _side_by_side(beside, text, option, kind)
        split = number_times_unit(cleaned)
        if split is not None and split[1] and all(t.kind != "name" or t.text in meanings.CONSTANTS for t in spellings.tokens(split[1])):
            split = None  # "2 pi": a number, read whole
        if split is None:
            return Reading(*from_pint(cleaned, text, option, kind), None), None, None
    number, unit = split
    factor, how = unit_factor(unit, text, option, kind)
    return Reading(number * factor, how, unit, mixed and mixed.shown), number, factor


def _side_by_side(beside: spellings.SideBySide, text: str, option: str, kind: Kind) -> InputError:
    why, fix = beside.said()
    return InputError(option, expected(kind), example=kind.typed, got=f"{text!r}: {why}", hint=fix)


def parse(text: str, option: str, kind_name: str, *, sign: str = "positive", gravity: float | None = None) -> Parsed:
    """Read ``text`` as a quantity of ``kind_name`` and return its SI value, and a note on how it
    was read where that is not plain.

    ``sign`` is "positive" (> 0), "nonnegative" (>= 0) or "any". A bare number means the kind's
    SI unit, except for an angle, an angular velocity and an angular acceleration, which need
    their unit (0 aside). For an angular velocity or acceleration, Hz and min^-1 are revolutions
    per unit time (omega = 2 pi n), a speed over a length is v/R in radians, and any other 1/time
    (1/s) is refused as ambiguous. A weight for a mass is the mass W/g, with ``gravity`` in m/s^2
    (None: standard gravity, 9.80665).
    """
    kind = KINDS[kind_name]
    reading = read(text, option, kind)
    value = reading.value
    if reading.unit == "" and kind.name in NEEDS_ITS_UNIT and value != 0:
        raise bare_number(option, text, kind, value)
    g = STANDARD_GRAVITY if gravity is None else gravity
    if reading.how == WEIGHT:
        if not (math.isfinite(g) and g > 0):
            raise InputError(option, "is a weight, which needs a positive gravity to give a mass", example="--g 9.81", got=f"g = {g!r}")
        value /= g
    if value == 0 and underflowed(text):
        raise out_of_bounds(kind.name, option, sign=sign, got=f"{text!r}, nonzero but below what a double holds (it would be read as 0)")
    _check(value, text, option, kind, sign)
    return Parsed(value, _note(option, text.strip(), reading, value, gravity, kind), reading.how == WEIGHT)


def _check(value: float, text: str, option: str, kind: Kind, sign: str) -> None:
    """A value read from ``text`` must be finite, within its kind's bounds, and of its sign."""
    if not math.isfinite(value):
        raise InputError(option, f"expected a finite {kind.name}", example=kind.typed, got=repr(text))
    low, high = kind.bounds
    if value and not low <= abs(value) <= high:  # (the message's "got" is worked out only then)
        check_bounds(value, kind.name, option, sign=sign, got=repr(text) if _is_number(text) else None, text=text)
    if sign == "positive" and value <= 0:
        raise InputError(option, f"expected a positive {kind.name}", example=kind.typed, got=repr(text))
    if sign == "nonnegative" and value < 0:
        raise InputError(option, f"expected {article(kind.name)} of zero or more", example=kind.typed, got=repr(text))


def si_number(value: float, option: str, kind_name: str, *, sign: str = "positive") -> float:
    """A number given as SI (a JSON number in a batch line, a float from Python), checked as a
    text would be: finite, within bounds, of its sign. No unit to read, so an angle is radians."""
    try:
        number = float(value)
    except OverflowError:  # an int past a double's range (10**400): as far out of bounds as inf
        number = math.inf if value > 0 else -math.inf
        check_bounds(number, kind_name, option, sign=sign, got=f"a whole number of about {int(abs(value).bit_length() * math.log10(2)) + 1} digits")
    _check(number, repr(value), option, KINDS[kind_name], sign)
    return number


_LITERAL = re.compile(r"(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")
_CALL = re.compile(r"[A-Za-z_]\s*\(")
_BINARY_SIGN = re.compile(r"[\w).][-+]")  # a sign after a term: a sum or difference, which may be 0 (1 - 1)


def underflowed(text: str) -> bool:
    """Whether a text read as 0 is nonzero as written: a number below a double's range
    (1e-400), or a product of nonzero numbers that underflows (1e-200*1e-200, 1×10^-400), which a
    double rounds to 0 and which must be bounded as what was typed, not as 0. A sum or difference
    (1 - 1) or a function (sin(180deg)) may be 0: only its numbers are looked at."""
    literals = _LITERAL.findall(text)
    if any(float(digits + exponent) == 0 and any(c in "123456789" for c in digits) for digits, exponent in literals):
        return True  # a number written nonzero that a double cannot hold
    if not literals or not all(any(c in "123456789" for c in digits) for digits, _ in literals):
        return False  # a 0 written somewhere: the 0 may be meant
    if _CALL.search(text):
        return False  # a function may be 0 at nonzero numbers (sin(180deg))
    return _BINARY_SIGN.search(_LITERAL.sub("1", "".join(text.split()))) is None


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _note(option: str, text: str, reading: Reading, value: float, gravity: float | None, kind: Kind) -> str | None:
    """What a reader should know about how ``text`` was read, or None when it was read plainly."""
    said = list(reading.said)
    if reading.mixed:
        said.append(f"{reading.mixed} read as the mixed number {reading.mixed.replace(' ', ' + ')}")
    if reading.how == REVOLUTIONS and (kind.name not in ANGULAR or reading.unit is None and "hz" in text.lower()):  # Hz inside a unit
        said.append(meanings.revolutions_note(reading.unit))
    elif reading.how == REVOLUTIONS:
        squared = kind.name == "angular acceleration"
        said.append(f"{spellings.revolutions(reading.unit, squared=squared)} ({'1 rev = 2π rad' if squared else 'ω = 2πn'})")
    elif reading.how == WEIGHT:
        g = f"standard gravity g = {STANDARD_GRAVITY} m/s²" if gravity is None else f"g = {gravity:g} m/s²"
        said.append(f"a weight, read as the mass W/g = {value:.6g} kg ({g})")
    elif reading.how == MASS_AS_WEIGHT:
        said.append(spellings.as_force(reading.unit))
    elif reading.how == WEIGHT_INERTIA:
        said.append(_WR2_NOTE)
    elif reading.how in _BOOK_NOTES:
        said.append(_BOOK_NOTES[reading.how])
    elif reading.how == OVER_RADIUS:
        said.append(f"α = a_t/R = {value:.6g} rad/s²" if kind.name == "angular acceleration" else f"ω = v/R = {value:.6g} rad/s")
    elif reading.how == meanings.POWER_AS_TORQUE_SPEED:
        said.append(f"{meanings.NOTES[reading.how]}; read as {value:.6g} {kind.si_unit.replace('**', '^')}".rstrip())
    elif reading.how in meanings.NOTES:
        said.append(meanings.NOTES[reading.how])
    return f"{option} {text}: " + "; ".join(said) if said else None


# A pound in an inertia with no s² is a pound of mass; the WR² of US drive catalogues (weight × radius of
# gyration², in lb·ft²) has the same number, J = WR²/g with W in lbf, so both readings agree.
_WR2_NOTE = "a pound or ounce of mass, the same number as a WR² (J = WR²/g)"
# A kgf × a length² (kgf·m²) for an inertia is a GD², the flywheel effect of motor catalogues in
# the technical units (G the weight, D the diameter of gyration): J = GD²/4g. A kgf is the weight of a kg
# at standard gravity, so J in kg·m² is GD² in kgf·m² over 4; a book that divides by 9.81 is 0.03% low.
_BOOK_NOTES = {
    GD2: "a weight times a length², read as GD² (weight × diameter of gyration², a motor's flywheel effect): J = GD²/4g, "
         "g = 9.80665 m/s², the kgf's own (J in kg·m² = GD² in kgf·m² / 4; a book dividing by g = 9.81 finds 0.03% less)",
    KGF_INERTIA: "kgf·length·s², the technical units' inertia, with the kgf at standard gravity 9.80665 m/s² "
                 "(1 kgf·cm·s² = 0.0980665 kg·m²; a book taking g = 9.81 finds 0.03% more)",
}


def convert(value: float, si_unit: str, target: str, option: str) -> float:
    """Express an SI value in the unit ``target`` (``--to``), a unit of 1/time read as ``parse`` reads it."""
    return converted(value, si_unit, target, option).value


def converted(value: float, si_unit: str, target: str, option: str) -> Parsed:
    """``convert``, with a note when a unit was read as revolutions, or a mass as a force."""
    kind = next((k for k in KINDS.values() if k.si_unit == si_unit), Kind("quantity", si_unit, si_unit))
    example = kind.common_units[0] if kind.common_units else si_unit
    example = f"'{example}'" if re.search(r"[*^()]", example) else example  # as typed in zsh, where * and ^ glob

    def refuse() -> InputError:
        return InputError(option, f"expected a unit of {article(kind.name)}", example=example, got=repr(target))

    cleaned = screen(target, option, kind)
    split = number_times_unit(cleaned)
    if split is None or not split[1] or (re.match(r"\s*[-+\d.]", cleaned) and not re.match(r"\s*1\s*/", cleaned)):
        raise refuse()  # a unit alone: "rpm", "1/s", not "2 rpm"
    try:
        factor, how = unit_factor(split[1], target, option, kind)
    except Ambiguous as err:  # 1/s: radians or revolutions per second
        squared = kind.name == "angular acceleration"
        both = f"'rad/{err.per}^2' or 'rev/{err.per}^2'" if squared else f"rad/{err.per} or rev/{err.per}"
        raise InputError(option, f"expected a unit of {article(kind.name)} that names its angle", example=both, got=f"{target!r}: {err.why}") from None
    except InputError:
        raise refuse() from None
    if how == WEIGHT:  # a mass in newtons would depend on g
        raise refuse()
    note = None
    if how == REVOLUTIONS and kind.name not in ANGULAR:
        note = f"{option} {target.strip()}: {meanings.revolutions_note(split[1])}"
    elif how == REVOLUTIONS:
        note = f"{option} {target.strip()}: {spellings.revolutions(split[1], squared=kind.name == 'angular acceleration')} (n = ω/2π)"
    elif how == MASS_AS_WEIGHT:
        note = f"{option} {target.strip()}: {spellings.as_force(split[1])}"
    elif how == WEIGHT_INERTIA:
        note = f"{option} {target.strip()}: {_WR2_NOTE}"
    elif how in _BOOK_NOTES:
        note = f"{option} {target.strip()}: {_BOOK_NOTES[how]}"
    elif how == OVER_RADIUS:
        note = f"{option} {target.strip()}: a speed over a length, in radians ({'α = a_t/R' if kind.name == 'angular acceleration' else 'ω = v/R'})"
    elif how in meanings.NOTES:
        note = f"{option} {target.strip()}: {meanings.NOTES[how]}"
    return Parsed(value / factor, note)
