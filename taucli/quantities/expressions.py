"""What a student types beyond pint's grammar: sqrt(…), sin(…), cos(…), tan(…), and a number with
its unit after a slash.

- ``sqrt(13) m``, ``sqrt(13 m^2)``, ``sin(30deg)*5N``: each call is worked out (innermost first)
  by pint on its own text, which has passed the screen with the rest (taucli.quantities.screen: length,
  digits, powers, parentheses), and put back as a number with its unit: ``(3.605551275463989) m``.
  sin, cos and tan take an angle with its unit (``sin(30)`` is refused, as a bare angle is
  everywhere); at a whole number of 30° or 45° they give the exact values 0, ±½, ±1 a book
  prints. Nothing is run as code: the four names are looked up in a table.
- ``36km/h/200m``: pint multiplies by what follows a number after a slash (36 km/h / 200 × m); a
  student means the number and its unit together, (36 km/h)/(200 m). After a unit or a ``)``, a
  slash then a number and its unit are grouped so, with a note. ``1/2 rpm`` (a fraction before
  the unit) and ``(90 km/h)/(60 m)`` are left as they are.
"""

from __future__ import annotations

import math
import re

from taucli.quantities import meanings
from taucli.quantities import spellings
from taucli.core.errors import InputError
from taucli.quantities.kinds import Kind, article
from taucli.quantities.registry import _pint_quantity, _radians
from taucli.core.written import fmt

_CALL = re.compile(r"(?<![A-Za-z_])(sqrt|sin|cos|tan)\s*\(", re.IGNORECASE)
_EXACT_SIN = {0: 0.0, 30: 0.5, 90: 1.0, 150: 0.5, 180: 0.0, 210: -0.5, 270: -1.0, 330: -0.5}  # sin at whole degrees where it is exact in binary
MAX_CALLS = 6


# Functions a student may type that are not among the four: refused by name (pint would read
# exp(1) m as a unit "exp" times 1 m, and the message then spoke of numbers side by side).
_NOT_TAKEN = re.compile(r"(?<![A-Za-z_])(exp|ln|log|log10|log2|sinh|cosh|tanh|asin|acos|atan|arcsin|arccos|arctan|cot|sec|csc|abs|cbrt|pow|"
                        r"round|floor|ceil|hypot|degrees|radians)\s*\(", re.IGNORECASE)


def refuse_other_calls(cleaned: str, shown: str, option: str, kind: Kind) -> None:
    """A call of a function that is not sqrt, sin, cos or tan (exp(1) m) is refused by its name."""
    found = _NOT_TAKEN.search(cleaned)
    if found is not None:
        raise InputError(option, f"expected {_article(kind)}", example=kind.typed,
                         got=f"{shown!r}: {found.group(1)}(…) is not a function taucli reads (it reads sqrt, sin, cos and tan)", hint="write its value as a number")


def has_calls(text: str) -> bool:
    return _CALL.search(text) is not None


def calls(cleaned: str, shown: str, option: str, kind: Kind) -> tuple[str, list[str]]:
    """``cleaned`` with each sqrt/sin/cos/tan call replaced by its value, and what each was read as."""
    said = []
    for _ in range(MAX_CALLS + 1):
        found = list(_CALL.finditer(cleaned))
        if not found:
            return cleaned, said
        if len(said) == MAX_CALLS:
            break
        call = found[-1]  # the last to open holds no other
        close = _closing(cleaned, call.end() - 1)
        if close is None:
            raise InputError(option, f"expected {_article(kind)}", example=kind.typed, got=f"{shown!r}: a ( without its )")
        name, inner = call.group(1).lower(), cleaned[call.end() : close].strip()
        value, unit, short = _evaluate(name, inner, shown, option, kind)
        written = f"({value!r} {unit})" if unit else f"({value!r})"
        if re.search(r"[\w.)]\s*$", cleaned[: call.start()]):
            written = "*" + written  # 2sqrt(3), N sin(30deg): a product, as written
        said.append(f"{name}({inner}) = {fmt(value)}" + (f" {short}" if short else ""))
        cleaned = cleaned[: call.start()] + written + cleaned[close + 1 :]
    raise InputError(option, f"expected {_article(kind)}", example=kind.typed, got=f"{shown!r}: more than {MAX_CALLS} functions")


def _article(kind: Kind) -> str:
    return article(kind.name)


def _closing(text: str, opening: int) -> int | None:
    depth = 0
    for i in range(opening, len(text)):
        depth += (text[i] == "(") - (text[i] == ")")
        if depth == 0:
            return i
    return None


def _evaluate(name: str, inner: str, shown: str, option: str, kind: Kind) -> tuple[float, str, str]:
    """The value of name(inner), its unit as pint writes it and reads it back ("" for a number),
    and its unit as a person reads it."""
    def refuse(why: str, hint: str | None = None) -> InputError:
        return InputError(option, f"expected {_article(kind)}", example=kind.typed, got=f"{shown!r}: {why}", hint=hint)

    if not inner:
        raise refuse(f"{name}() of nothing")
    q = _pint_quantity(inner, option, kind, shown)
    if name == "sqrt":
        if q.magnitude < 0:
            raise refuse(f"sqrt({inner}) of a negative number")
        root = q**0.5
        value = float(root.magnitude)
        unit = "" if not list(root.unit_items()) else str(root.units)
        short = "" if not unit else format(root.units, "~P")
    else:
        if not list(q.unit_items()) or not q.dimensionless or _radians(q.units) != 1:
            raise refuse(f"{name}({inner}) needs an angle with its unit", hint=f"{name}(30deg) or {name}(0.5rad)")
        degrees = float(q.to("degree").magnitude)
        value = _trig(name, float(q.to("radian").magnitude), degrees)
        if value is None:
            raise refuse(f"{name}({inner}) is infinite")
        unit = short = ""
    if not math.isfinite(value):
        raise refuse("out of range")
    return value, unit, short


def _trig(name: str, radians: float, degrees: float) -> float | None:
    """sin, cos or tan, exact where a book's value is (30°: ½; 45°: tan 1; 90°: 1, 0, none)."""
    whole = round(degrees)
    exact = degrees == whole or (whole != 0 and abs(degrees - whole) <= 4 * math.ulp(whole))  # within rounding of a whole degree
    if exact:
        turn = whole % 360
        sin = _EXACT_SIN.get(turn)
        cos = _EXACT_SIN.get((turn + 90) % 360)
        if name == "sin" and sin is not None:
            return sin
        if name == "cos" and cos is not None:
            return cos
        if name == "tan":
            if turn in (90, 270):
                return None
            if turn % 45 == 0:
                return 0.0 if turn % 180 == 0 else 1.0 if turn % 180 == 45 else -1.0
    return {"sin": math.sin, "cos": math.cos, "tan": math.tan}[name](radians)


def _an_exponent(found, significant, place: int) -> bool:
    """Whether the token at ``significant[place]`` is a unit's power (the 2 of m/s**2, the 1 of s^-1)."""
    if found[significant[place]].kind != "number" or place < 1:
        return False
    back = place - 1
    if found[significant[back]].text in ("-", "+") and back >= 1:
        back -= 1
    raised = found[significant[back - 1]].text if back >= 1 else ""  # pi**2 is a number's power, not a unit's
    return found[significant[back]].text in ("**", "^") and raised not in meanings.CONSTANTS


def grouped(cleaned: str) -> tuple[str, str | None]:
    """A number and its unit after a slash grouped as one divisor ("36km/h/200m" ->
    "36km/h/(200m)"), where the slash follows a unit or a ")"; and a note, or None."""
    found = spellings.tokens(cleaned)
    significant = [i for i, token in enumerate(found) if token.kind != "space"]
    wraps = []
    for place, i in enumerate(significant[:-2]):
        if found[i].text != "/" or place == 0:
            continue
        before, number, unit = found[significant[place - 1]], found[significant[place + 1]], found[significant[place + 2]]
        if not (before.kind == "name" and before.text not in meanings.CONSTANTS or before.text == ")" or _an_exponent(found, significant, place - 1)) or number.kind != "number" or unit.kind != "name":
            continue
        end = significant[place + 2]
        rest = significant[place + 3 :]
        if len(rest) >= 2 and found[rest[0]].text in ("**", "^"):
            signed = 2 if found[rest[1]].text in ("-", "+") else 1
            if len(rest) > signed and found[rest[signed]].kind == "number":
                end = rest[signed]  # the unit's power: /2 s^2, /2 s^-1
        wraps.append((significant[place + 1], end))
    if not wraps:
        return cleaned, None
    texts = [token.text for token in found]
    for start, end in reversed(wraps):
        texts[start] = "(" + texts[start]
        texts[end] = texts[end] + ")"
    rewritten = "".join(texts)
    return rewritten, f"read as {rewritten}: a number and its unit after / divide together"
