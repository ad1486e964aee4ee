"""The grammar of a measured value: a quantity's text with its standard uncertainty.

    4.0+/-0.1 kg    4.0 ± 0.1 kg    (4.0 ± 0.1) kg    4.0 kg ± 0.1 kg    4.0(1) kg

``split`` reads such a text into the value's text and the uncertainty's (taucli.answering.inputs reads
both, in SI); ``with_uncertainty`` writes a value and its σ back as a person reads them. Nothing
here knows how an uncertainty travels through a scene (taucli.answering.propagate does).
"""

from __future__ import annotations

import math
import re

from taucli.core.written import fmt

PLUS_MINUS = ("±", "+/-")
_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
NUMBER_THEN_UNIT = re.compile(rf"\s*({_NUMBER})\s*(.*?)\s*$")
_PARENTHESISED = re.compile(rf"\s*\(\s*({_NUMBER})\s*(?:±|\+/-)\s*({_NUMBER})\s*\)\s*(.*?)\s*$")
# The concise notation: a number, then the uncertainty of its last digits in parentheses, glued
# to it ("4.0(1) kg", "1.234(56)e3 m"). Any other parenthesis ("250kg*(0.6m)^2") is arithmetic.
CONCISE = re.compile(r"\s*([+-]?)(\d+)(?:\.(\d*))?\((\d+)\)((?:[eE][+-]?\d+)?)\s*(.*?)\s*$")


def marked(value) -> bool:
    """Whether ``value`` carries an uncertainty by its grammar: ± or +/- (a malformed one is then
    refused by the reading), or the concise "4.0(1) kg". Cheap, as answer.plain's copy is (each
    batch line asks it of each value): the pattern runs only on a text with a ")" in it."""
    return isinstance(value, str) and ("±" in value or "+/-" in value or (")" in value and CONCISE.fullmatch(value) is not None))


def split(text: str) -> tuple[str, str] | None:
    """("4.0 kg", "0.1 kg") for "4.0+/-0.1 kg", "4.0 ± 0.1 kg", "(4.0 ± 0.1) kg", "4.0 kg ± 0.1"
    or "4.0(1) kg"; None for a text with no uncertainty. The uncertainty takes the value's unit
    where it has none of its own."""
    concise = CONCISE.fullmatch(text)
    if concise:
        sign, whole, decimals, digits, exponent, unit = concise.groups()
        decimals = decimals or ""
        places = len(decimals) - (int(exponent[1:]) if exponent else 0)
        spread = f"{int(digits)}e{-places}"
        return f"{sign}{whole}{'.' + decimals if decimals else ''}{exponent} {unit}".strip(), f"{spread} {unit}".strip()
    marker = next((m for m in PLUS_MINUS if m in text), None)
    if marker is None:
        return None
    bracketed = _PARENTHESISED.fullmatch(text)
    if bracketed:
        value, spread, unit = bracketed.groups()
        return f"{value} {unit}".strip(), f"{spread} {unit}".strip()
    left, _, right = text.partition(marker)
    value, spread = NUMBER_THEN_UNIT.fullmatch(left), NUMBER_THEN_UNIT.fullmatch(right)
    if value is None or spread is None:
        return None
    unit = value[2] or spread[2]
    return f"{value[1]} {value[2] or unit}".strip(), f"{spread[1]} {spread[2] or unit}".strip()


def with_uncertainty(value: float, sigma: float | None) -> str:
    """``4.90 ± 0.08``: the uncertainty to one significant digit (two where they begin 10-35),
    the value to the same decimal place."""
    if sigma is None or not math.isfinite(sigma) or not math.isfinite(value):
        return fmt(value, 6)
    if sigma == 0:
        return f"{fmt(value, 6)} ± 0"
    place = math.floor(math.log10(sigma))
    leading = sigma / 10.0 ** (place - 1)
    digits = 2 if leading < 35.5 else 1
    last = place - digits + 1  # the decimal place of the last digit shown
    size = max(abs(value), sigma)
    top = math.floor(math.log10(size)) if size else 0
    if -5 <= last and top < 7:
        decimals = max(0, -last)
        return f"{round(value, -last):.{decimals}f} ± {round(sigma, -last):.{decimals}f}"
    scale = 10.0 ** top
    decimals = max(0, top - last)
    return f"({value / scale:.{decimals}f} ± {sigma / scale:.{decimals}f})e{top}"
