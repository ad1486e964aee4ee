"""The screen every quantity's text passes before pint sees it: typography normalised (· × − ²
°), engineering spellings rewritten (taucli.quantities.spellings), and text refused at once that is
unreadable or would be slow to evaluate (pint evaluates ``**`` with Python integers, so
``9**9**9 kg`` would run for hours if it got that far).
"""

from __future__ import annotations

import math
import re

from taucli.quantities import spellings
from taucli.core.errors import InputError
from taucli.quantities.kinds import Kind, article


MAX_TEXT_LENGTH = 80


MAX_DIGITS = 25  # digits in one numeric literal


MAX_EXPONENT = 12  # |n| in x**n


MAX_POWERS = 6


MAX_PAREN_DEPTH = 4


_ALLOWED = re.compile(r"[A-Za-z0-9_ .+\-*/^()µμΩ]*")


_POWER = re.compile(r"(\*\*|\^)\s*(\(\s*[-+]?\s*\d+(?:\.\d+)?\s*\)|[-+]?\s*\d+(?:\.\d+)?)?")  # x^2, x^-1, x^(1.5)


_DIGIT_RUN = re.compile(r"\d+")


_UNSIGNED = r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


# A number, a dash and a number with its unit, as prose writes a range (an en dash is a "-" by now).
_DASHED = re.compile(rf"\s*(?P<low>[-+]?{_UNSIGNED})\s*-\s*(?P<high>{_UNSIGNED})\s*(?P<unit>[A-Za-zµμΩ_][^-+]*?)?\s*")


def _quoted(text: str) -> str:
    """``text`` as typed in bash, zsh and fish: quoted where it holds * ^ ( or a space."""
    return f"'{text}'" if re.search(r"[*^() ]", text) else text


_NORMALISE = [
    ("\u00a0", " "), ("\u202f", " "), ("·", "*"), ("⋅", "*"), ("×", "*"), ("∙", "*"),
    ("−", "-"), ("–", "-"), ("π", " pi "), ("%", " percent"),
    ("°", " deg"), ("÷", "/"), ("½", " 1/2"), ("⅓", " 1/3"), ("⅔", " 2/3"), ("¼", " 1/4"), ("¾", " 3/4"),
]  # fmt: skip


_SUPERSCRIPT = re.compile(r"([⁻⁺]?)([⁰¹²³⁴⁵⁶⁷⁸⁹]+)")  # m·s⁻², kg·m², 10⁻³


_DIGITS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789")


# A ratio as a book or a gearbox's plate writes one, "10:1": the first number over the second.
_RATIO = re.compile(rf"\s*({_UNSIGNED})\s*:\s*({_UNSIGNED})\s*")


def screen(text: str, option: str, kind: Kind) -> str:
    """Normalise typography and spellings; refuse text that is unreadable or would be slow to evaluate."""
    cleaned = _SUPERSCRIPT.sub(lambda m: "**" + m[1].replace("⁻", "-").replace("⁺", "") + m[2].translate(_DIGITS), text.strip())
    for old, new in _NORMALISE:
        cleaned = cleaned.replace(old, new)
    cleaned = cleaned.strip()
    example = kind.typed
    ratio = _RATIO.fullmatch(cleaned) if kind.name == "dimensionless" else None
    if ratio is not None:  # 10:1 is 10; 1:10 could be a reducer's ratio written the other way round
        if float(ratio[1]) < float(ratio[2]):
            raise InputError(option, "expected a plain number", example=f"{ratio[2]}:{ratio[1]} or {float(ratio[1]) / float(ratio[2]):.6g}",
                             got=f"{text!r}: a ratio below 1:1 could be meant either way round")
        cleaned = f"{ratio[1]}/{ratio[2]}"

    def refuse(why: str) -> InputError:
        return InputError(option, f"expected {article(kind.name)}", example=example, got=f"{text!r}: {why}")

    if not cleaned:
        raise refuse("an empty value")
    if len(cleaned) > MAX_TEXT_LENGTH:
        raise refuse(f"longer than {MAX_TEXT_LENGTH} characters")
    if "," in cleaned:
        raise refuse("a comma (write decimals with a point: 4.5 kg)")
    if ".." in cleaned:  # 0.5..4kg read on would be 0.5 × .4 kg: a range is an option's sweep, split before any value is read
        raise refuse("a range FROM..TO, which only an option on the command line takes (a sweep); give one value here")
    if not _ALLOWED.fullmatch(cleaned):
        bad = next(ch for ch in cleaned if not _ALLOWED.fullmatch(ch))
        raise refuse(f"the character {bad!r} is not part of a quantity")
    dashed = _DASHED.fullmatch(cleaned)
    if dashed is not None:  # "1-5kg", "1 - 5 kg", "1–5kg": a range as prose writes one, not 1 − 5 kg
        low, high, unit = dashed["low"], dashed["high"], re.sub(r"\s+", "*", dashed["unit"] or "")
        fix = f"{low}..{high}{unit}"
        raise InputError(option, f"expected {article(kind.name)}", example=example, got=f"{text!r}: a dash between two numbers",
                         hint=f"a range is written {_quoted(fix)}, a list {_quoted(fix.replace('..', ','))}")
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
    raised = []  # (where a power is, its size, the parenthesised group it raises, if any)
    for power in powers:
        exponent = power.group(2)
        if exponent is None:
            raise refuse("a power must be a plain number, as in m^2")
        size = abs(float(exponent.strip("() ").replace(" ", "")))
        if size > MAX_EXPONENT:
            raise refuse(f"a power larger than {MAX_EXPONENT}")
        if re.match(r"\s*(\*\*|\^)", cleaned[power.end() :]):
            raise refuse("a power of a power")
        raised.append((power.start(), size, _group_before(cleaned, power.start())))
    # a power of a group that holds powers multiplies them: ((3m)^2 + (2m)^2)^0.5 is fine, (9^9)^9 is 9^81
    for where, size, _ in raised:
        total = size * math.prod(outer for _, outer, group in raised if group is not None and group[0] < where < group[1])
        if total > MAX_EXPONENT:
            raise refuse(f"powers of powers that make one larger than {MAX_EXPONENT}")
    return cleaned


def _group_before(text: str, end: int) -> tuple[int, int] | None:
    """The span of the parenthesised group that ends just before ``end`` (spaces aside), or None."""
    close = len(text[:end].rstrip()) - 1
    if close < 0 or text[close] != ")":
        return None
    depth = 0
    for i in range(close, -1, -1):
        depth += (text[i] == ")") - (text[i] == "(")
        if depth == 0:
            return i, close
    return None
