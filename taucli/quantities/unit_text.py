"""The plain form of a quantity's text, read without pint: a number (or none) times a product of
unit powers, "4.5 kg", "300 rpm", "-2 N*m", "1e-3 kg*m^2". Its unit, in one spelling for one
meaning, is the key of the SI factor the unit cache keeps (taucli.quantities.cache); any other
text ("4 kg + 200 g") goes to pint whole (taucli.quantities.registry).
"""

from __future__ import annotations

import re

from taucli.quantities.screen import MAX_DIGITS, MAX_TEXT_LENGTH


# "4.5 kg", "300 rpm", "-2 N*m", "1e-3 kg*m^2", "kg", "4", "50 1/s": a number (or none) times a
# product of unit powers. For such text the value is the number times pint's SI factor for the
# unit text, and that factor is cached (taucli.quantities.cache); anything else ("4 kg + 200 g") goes to
# pint whole.
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


# Each part matches one way only: a name ends where its letters end, and the space between two
# factors is a separator or part of one, never both. Else a failed match ("kkkk...k+") would try
# every way of cutting the letters into names: 2^n of them, minutes for 30 letters.
_NAME = r"[A-Za-zµμΩ_][A-Za-z0-9µμΩ_]*(?![A-Za-z0-9µμΩ_])"


_POWER_OF = r"(?:\s*(?:\*\*|\^)\s*-?\d{1,2})?"


_BETWEEN = r"(?:\s*[*/]\s*|\s+)?"


_FACTOR = rf"(?:{_NAME}|\(\s*{_NAME}{_POWER_OF}(?:{_BETWEEN}{_NAME}{_POWER_OF})*\s*\)){_POWER_OF}"


_UNIT = rf"(?:(?:1\s*)?/\s*)?{_FACTOR}(?:{_BETWEEN}{_FACTOR})*"


_NUMBER_TIMES_UNIT = re.compile(rf"\s*(?P<number>{NUMBER})?\s*(?P<unit>{_UNIT})?\s*")


def number_times_unit(text: str) -> tuple[float, str] | None:
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
