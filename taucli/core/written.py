"""How a number and a unit are written for a person: the digits shown, the unit's symbols; and
any text a person is shown, its control characters escaped (``printable``).

Plain text, no taucli import: the solvers write their steps with these, and so do the writers
(the human view, --format md, latex, html) and a Report shown in Python.
"""

from __future__ import annotations

import math
import re


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


# What no text taucli shows may carry raw (#43 item 14): C0 and C1 controls (ESC starts a
# terminal's escape sequences, OSC 8 links and OSC 52 clipboard writes among them; a newline or
# carriage return splits or overwrites a line), DEL, the line and paragraph separators, the
# invisible marks that reorder or hide text (bidi overrides, zero-width joiners, BOM), and a lone
# surrogate (a byte of a file's name that was not UTF-8, as Python's surrogateescape reads it).
_UNPRINTABLE = re.compile("[\x00-\x1f\x7f-\x9f\u00ad\u061c\u200b-\u200f\u2028-\u202e\u2060-\u2069\ufeff\ud800-\udfff]")
_ESCAPES = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def _escape(found: re.Match) -> str:
    char = found.group()
    code = ord(char)
    if char in _ESCAPES:
        return _ESCAPES[char]
    if 0xDC80 <= code <= 0xDCFF:  # an undecoded byte: its value, \xff
        return f"\\x{code - 0xDC00:02x}"
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def printable(text: str) -> str:
    """``text`` with each control or invisible character written as Python's repr writes it
    (\\x1b, \\n, \\u202e), as a header or cell of a data file is quoted in a message: the name
    of a file, a path or anything else typed, shown on one line and unable to drive the terminal.
    A text with none (nearly all) is returned as it is."""
    return _UNPRINTABLE.sub(_escape, text) if _UNPRINTABLE.search(text) else text
