"""How a number and a unit are written for a person: the digits shown, the unit's symbols.

Plain text, no taucli import: the solvers write their steps with these, and so do the writers
(the human view, --format md, latex, html) and a Report shown in Python.
"""

from __future__ import annotations

import math


DIGITS = 6  # significant figures of every number a person is shown: the results table and the steps alike


def fmt(x: float, digits: int = DIGITS) -> str:
    """A number as a person writes it in a worked solution: ``digits`` significant figures."""
    if x == 0:
        return "0"
    if not math.isfinite(x):
        return str(x)
    magnitude = math.floor(math.log10(abs(x)))
    if -4 <= magnitude < 7:
        decimals = max(0, digits - 1 - magnitude)
        text = f"{x:.{decimals}f}"
        if "." in text:
            text = text.rstrip("0").rstrip(".")
        return "0" if text in ("-0", "") else text
    mantissa, exponent = f"{x:.{digits - 1}e}".split("e")
    if "." in mantissa:
        mantissa = mantissa.rstrip("0").rstrip(".")
    return f"{mantissa}e{int(exponent)}"


_SUPERSCRIPTS = {"**2": "²", "**3": "³", "**-1": "⁻¹", "**-2": "⁻²", "^2": "²", "^3": "³", "^-1": "⁻¹", "^-2": "⁻²"}


_PRETTY: dict[str, str] = {}  # a unit string -> as shown: the same few dozen units are shown over and over


def pretty_unit(unit: str | None) -> str:
    """A unit string as a person reads it: kg*m**2 -> kg·m², rad/s**2 -> rad/s²."""
    if not unit:
        return ""
    shown = _PRETTY.get(unit)
    if shown is None:
        shown = unit
        for power, superscript in _SUPERSCRIPTS.items():
            shown = shown.replace(power, superscript)
        shown = _PRETTY[unit] = shown.replace("*", "·") if len(_PRETTY) < 4096 else shown.replace("*", "·")
    return shown


def quantity_text(x: float, unit: str, digits: int = DIGITS) -> str:
    """A number with its unit, for the numbers line of a step: 0.2 m, 5 kg."""
    shown = pretty_unit(unit)
    return f"{fmt(x, digits)} {shown}" if shown else fmt(x, digits)


def term(x: float, unit: str | None = None) -> str:
    """A number (with its unit) as a term of a numbers line: 30 rad/s; a negative one in
    parentheses with a true minus, (−1.5 rad/s²), so that "+ (−1.5 rad/s²) × 20 s" reads right."""
    text = quantity_text(x, unit) if unit else fmt(x)
    return f"(−{text[1:]})" if text.startswith("-") else text


def shown(value, digits: int = DIGITS) -> str:
    """A value as a person reads it: 6 significant figures, yes/no, — where there is none."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        return fmt(float(value), digits)
    if isinstance(value, list):  # --find's roots (#22)
        return ", ".join(shown(item, digits) for item in value)
    return str(value)
