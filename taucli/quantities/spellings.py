"""Engineering spellings of units, rewritten to pint's before a unit is looked up; numbers side by side.

Datasheets, textbooks and people write units in ways pint reads wrongly or not at all: ``Nm``
(pint: "number metre"), ``N-m`` (a subtraction), ``ftlb`` (pint: "femto troy pound"), ``kgm^2``,
``kg m2``, ``m/s2``, ``RPM``, ``min-1``. ``respell`` rewrites them to the spelling pint reads as
meant ("N*m", "kg*m**2", "rpm", "min**-1"). It works on the text alone, without pint, so that it
runs before the unit cache's key is formed: "Nm" and "N*m" share one entry. It only changes what
sits between two names or right after a name: a minus sign (``-2 N*m``), an exponent (``s^-1``,
``1e-3 kg``) and a subtraction (``4kg-200g``, ``4 kg - 200 g``) are left as they are.

Here too: a whole number and a fraction read as a mixed number (``33 1/3 rpm``), where numbers
stand side by side that pint would multiply (``3 4 kg``), and the words of the notes and fixes.
What a unit then *means* (a pound in a torque is a pound-force; 1/s for a speed is revolutions
per second) is decided in units.py, which asks pint. A change here changes only the text pint is
given, never pint's answer for a text, so the factors units.py keeps (stamped with units.py
alone) stay valid.
"""

from __future__ import annotations

import re
from typing import NamedTuple

_TOKEN = re.compile(
    r"(?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)|(?P<name>[A-Za-zµμΩ_][A-Za-z0-9µμΩ_]*)|(?P<space>\s+)|(?P<op>\*\*|[-+*/^])|(?P<other>.)"
)

# A force or a mass, then a length, written as one word: the torque and inertia spellings of
# datasheets ("Nm", "kNm", "lbft", "kgcm", "gcm" in g*cm^2). Glued the other way round only for
# the imperial ones ("ftlb", "inoz"): "mN" is a millinewton, not a metre-newton.
_FORCES = ("N", "kN", "mN", "MN", "cN", "daN", "µN", "uN", "lbf", "kgf", "ozf", "gf", "lb", "kg", "oz", "g")
_LENGTHS = ("m", "cm", "mm", "ft", "in")
GLUED: dict[str, str] = {
    **{force + length: f"{force}*{length}" for force in _FORCES for length in _LENGTHS if force + length != "gm"},  # "gm" is a gram
    **{length + force: f"{length}*{force}" for length in ("ft", "in") for force in ("lb", "lbf", "oz", "ozf")},
    "Nms": "N*m*s",
    "lbm": "lb",  # pound-mass, not a pound-metre
}
# Names read whatever their case: no other unit is spelled with these letters.
CASELESS = {"rpm": "rpm", "rps": "rps", "hz": "Hz"}
# "r/min" and "U/min" (German datasheets: Umdrehungen) are revolutions per minute.
_REVOLUTION_LETTERS = ("r", "U")
# Units that a 2 or 3 right after stands for a power of: "m2", "cm3", "s2" in "m/s2".
POWERABLE = frozenset({"m", "cm", "mm", "km", "µm", "um", "in", "ft", "yd", "s", "ms", "min", "h", "hr", "sec"})
# Units that "-1" right after, at the end, is a power of: "3000 min-1" (DIN style), "s-2".
_TIMES = frozenset({"s", "ms", "min", "h", "hr", "sec"})


class Token(NamedTuple):
    kind: str  # number, name, space, op, other
    text: str


def tokens(text: str) -> list[Token]:
    return [Token(match.lastgroup or "other", match.group()) for match in _TOKEN.finditer(text)]


def respell(text: str) -> str:
    """``text`` with engineering spellings of units rewritten to the ones pint reads as meant."""
    found = tokens(text)
    out: list[Token] = []
    for i, token in enumerate(found):
        after = found[i + 1] if i + 1 < len(found) else None
        before = out[-1] if out else None
        if token.kind == "name":
            name, power = _POWERED.fullmatch(token.text).groups()
            if name in GLUED:
                name = GLUED[name]
            elif name.lower() in CASELESS:
                name = CASELESS[name.lower()]
            elif name in _REVOLUTION_LETTERS and after is not None and after.text == "/":
                name = "rev"
            if power and _last_unit(name) in POWERABLE and power in ("2", "3"):
                name += "**" + power  # "kg m2", "m/s2", "cm3", "kgm2"
            elif power:
                name = token.text  # "g0" is pint's standard gravity, "kg3" no unit at all: pint says which
            token = Token("name", name)
            if before is not None and before.kind == "space" and len(out) > 1 and out[-2].kind == "name":
                out[-1] = Token("op", "*")  # "kg m^2": pint multiplies names side by side; one spelling, one cache entry
        elif token.kind in ("op", "other") and token.text in "-." and _between_names(found, i):
            token = Token("op", "*")  # "N-m", "ft-lbf", "N.m", "kg.m^2"
        elif token.kind == "op" and token.text == "-" and _minus_one_at_end(found, i) and before is not None and _last_unit(before.text) in _TIMES:
            token = Token("op", "**-")  # "min-1", "s-2"
        elif token.text == "^":
            token = Token("op", "**")
        out.append(token)
    return "".join(token.text for token in out)


_POWERED = re.compile(r"(.*?)(\d*)")  # "m2": "m", "2"


def _last_unit(name: str) -> str:
    return name.rsplit("*", 1)[-1]


def _between_names(found: list[Token], i: int) -> bool:
    return 0 < i < len(found) - 1 and found[i - 1].kind == "name" and found[i + 1].kind == "name"


def _minus_one_at_end(found: list[Token], i: int) -> bool:
    rest = found[i + 1 :]
    return bool(rest) and rest[0].text in ("1", "2") and all(token.kind == "space" for token in rest[1:])


# A whole number then a simple fraction: "33 1/3 rpm", "-1 1/2 kg" (the rest is the unit).
MIXED = re.compile(r"\s*(?P<sign>[-+]?)\s*(?P<whole>\d+)\s+(?P<numerator>\d+)\s*/\s*(?P<denominator>\d+)(?P<rest>.*)")
_NOT_A_UNIT = re.compile(r"\s*(?:[\d.*/^]|[eE][-+]?\d)")  # "2 3/4/5", "1 1/2.5", "1 1/2**2", "1 1/2e3" are not mixed numbers


class Mixed(NamedTuple):
    value: float
    shown: str  # "33 1/3"
    rest: str  # what follows, the unit


def mixed_number(text: str) -> Mixed | None:
    """The mixed number at the start of ``text`` ("33 1/3 rpm": 33⅓, "rpm"), or None."""
    found = MIXED.fullmatch(text)
    if found is None or _NOT_A_UNIT.match(found["rest"]):
        return None
    whole, numerator, denominator = (int(found[name]) for name in ("whole", "numerator", "denominator"))
    if not 0 < numerator < denominator or len(found["whole"]) > 15 or len(found["denominator"]) > 15:
        return None
    value = whole + numerator / denominator
    return Mixed(-value if found["sign"] == "-" else value, f"{found['whole']} {numerator}/{denominator}", found["rest"].strip())


class SideBySide(NamedTuple):
    """Where two numbers (or a unit and a number) stand side by side, which pint would multiply."""

    first: str  # the text up to the second number
    second: str  # the text from it
    after_unit: bool  # the second number follows a unit ("5 ft 3 in"), not a number ("3 4 kg")
    glued: bool  # right after a unit's name, with no space: "N.5"

    def said(self) -> tuple[str, str]:
        """What is wrong, and the fix, as typed in a shell: quoted where it holds * or spaces."""
        number = re.match(r"[\d.eE+-]+", self.second)
        if self.glued and number:
            unit = re.split(r"[\s*/]", self.first)[-1]
            return f"a number right after the unit {unit!r}", f"for a power write '{unit}^{number.group()}'"
        if self.after_unit and re.search(r"[A-Za-zµμΩ]", self.second):
            return f"a number after a unit ({self.first} {self.second})", f"to add them write '{self.first} + {self.second}'"
        if self.after_unit:
            return f"a number after its unit ({self.first} {self.second})", "write each number before its unit, as in 4 kg"
        return (
            f"two numbers side by side ({self.first} {self.second})",
            f"write one number, or an operator between them ('{self.first}*{self.second}'); "
            "a mixed number is a whole number and a fraction below 1 ('33 1/3 rpm')",
        )


def side_by_side(text: str) -> SideBySide | None:
    """The first number in ``text`` that pint would multiply by what stands before it, or None.

    A number is fine at the start, after an operator (``2 * 3 kg``, ``m**-2``) or an opening
    parenthesis that follows one, and as the 1 of a unit ``1/s`` (``50 1/s``). After a number,
    a closing parenthesis or a unit name it is a second number side by side: ``3 4 kg``, ``(2)(3)``,
    ``5 ft 3 in``, ``N.5``.
    """
    found = tokens(text)
    significant = [(i, token) for i, token in enumerate(found) if token.kind != "space"]
    for place, (i, token) in enumerate(significant):
        if token.kind != "number":
            continue
        back = place - 1
        while back >= 0 and significant[back][1].text == "(":
            back -= 1
        if back < 0 or significant[back][1].kind == "op":
            continue
        previous = significant[back][1]
        if previous.kind not in ("number", "name") and previous.text != ")":
            continue
        ahead = [t for _, t in significant[place + 1 :]]
        if token.text == "1" and ahead[:1] == [Token("op", "/")] and next((t.kind for t in ahead[1:] if t.text != "("), None) == "name":
            continue  # "50 1/s", "60 1/(min*s)": the unit 1/s
        start = sum(len(t.text) for t in found[: significant[back + 1][0]])  # from the "(" the number is in, if any
        glued = previous.kind == "name" and found[i - 1] is previous
        return SideBySide(text[:start].strip(), text[start:].strip(), previous.kind == "name", glued)
    return None


# How a reading is said in its note.

_PER = {"s": "second", "sec": "second", "second": "second", "min": "minute", "minute": "minute", "h": "hour", "hr": "hour", "hour": "hour",
        "ms": "millisecond", "d": "day", "day": "day"}  # fmt: skip


def revolutions(unit: str | None, *, squared: bool = False) -> str:
    """ "min^-1 read as revolutions per minute": what a unit of 1/time was read as."""
    if not unit:
        return "1/time read as revolutions per unit time"
    shown = unit.replace("**", "^")
    prefixed = re.fullmatch(r"(kilo|mega|giga|milli|micro|[kMGmµu])(?:Hz|hertz)", unit)
    if prefixed and not squared:
        scale = {"k": "1000", "M": "10⁶", "G": "10⁹", "m": "1/1000", "µ": "10⁻⁶", "u": "10⁻⁶"}[
            {"kilo": "k", "mega": "M", "giga": "G", "milli": "m", "micro": "µ"}.get(prefixed.group(1), prefixed.group(1))]
        return f"{shown} read as {scale} revolutions per second"
    if unit == "Hz" or (squared and unit in ("Hz/s", "Hz**2")):
        per = "second"
    else:
        found = re.fullmatch(r"(?:1/)?(\w+)(?:\*\*-?(\d))?", unit)
        per = _PER.get(found.group(1)) if found and (unit.startswith("1/") or (found.group(2) and "-" in unit)) else None
        if per is None:
            return f"{shown} read as revolutions per unit time"
    return f"{shown} read as revolutions per {per}{' squared' if squared else ''}"


_MASS_NAMES = {"lb": "lbf", "kg": "kgf", "oz": "ozf", "g": "gf", "pound": "lbf", "ounce": "ozf", "gram": "gf", "kilogram": "kgf", "tonne": "tf", "t": "tf"}
_FORCE_WORDS = {"lbf": "pound-force", "kgf": "kilogram-force", "ozf": "ounce-force", "gf": "gram-force", "tf": "tonne-force"}


def as_force(unit: str | None) -> str:
    """ "lb read as pound-force, lbf*ft": a mass unit given for a force, named as its force unit."""
    names = [name for name in re.findall(r"[A-Za-z]+", unit or "") if name in _MASS_NAMES]
    if len(names) != 1 or unit is None:
        return "a mass for a force: read as its weight at standard gravity (9.80665 m/s²)"
    fixed = re.sub(rf"\b{names[0]}\b", _MASS_NAMES[names[0]], unit).replace("**", "^")
    return f"{names[0]} read as {_FORCE_WORDS[_MASS_NAMES[names[0]]]}, {fixed} (its weight at standard gravity)"
