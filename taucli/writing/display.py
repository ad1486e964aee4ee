"""How the human view writes numbers and equations: one minus sign, and expressions broken only
between their terms.

- The minus sign is − (U+2212) wherever a number is negative or a term is taken away, whether a
  solver wrote "-" or "−" (taucli reads either back). ``--json`` and ``--get`` keep ASCII numbers.
- An equation too long for the terminal is broken before an ``=``, ``+``, ``−``, ``×``, ``/`` or
  ``⇒`` outside brackets, never inside a term: ``I⊥Ω cos θ`` and ``0.98 m/s²`` stay whole.
"""

from __future__ import annotations

import re

MINUS = "\u2212"
_SIGN = re.compile(r"(?<![\w.)\]])-(?=[\d.∞])|(?<=\de)-(?=\d)")


def minus_signs(text: str) -> str:
    """``text`` with each hyphen that is a number's sign (``-3``, ``(-0.3``, ``1e-5``) written −;
    a hyphen inside a word (``rk4-5``, ``--m1``) is left as it is."""
    return _SIGN.sub(MINUS, text) if "-" in text else text


def equation_text(text: str) -> str:
    """An equation, its numbers or its result as shown: − for every sign and every subtraction."""
    return minus_signs(text).replace(" - ", f" {MINUS} ")


_OPERATORS = ("=", "+", MINUS, "-", "×", "/", "⇒", "≈", "<", ">", "≤", "≥", "→")
_OPENING, _CLOSING = "([{", ")]}"


def _break_points(text: str, deepest: int = 0) -> list[int]:
    """Where ``text`` may be broken: at a space before an operator, at most ``deepest`` brackets in."""
    points, depth = [], 0
    for i, c in enumerate(text):
        if c in _OPENING:
            depth += 1
        elif c in _CLOSING:
            depth = max(depth - 1, 0)
        elif c == " " and depth <= deepest and text[i + 1 : i + 2] in _OPERATORS and text[i + 2 : i + 3] in (" ", ""):
            points.append(i)
    return points


def _pieces(text: str, deepest: int) -> list[str]:
    cuts = [0, *(i + 1 for i in _break_points(text, deepest)), len(text) + 1]
    return [text[a : b - 1] for a, b in zip(cuts, cuts[1:])]


_NUMBER = re.compile(r"[-−+]?[\d.]+(e[-−]?\d+)?")


def _words(text: str) -> list[str]:
    """A term too long for a line, last of all: at its spaces, a number kept with what follows it
    (its unit: ``5.42402 rad/s``). Such a term is words more than an expression: "(F(φ, k)
    measured from the start to the bottom)"."""
    words: list[str] = []
    for word in text.split(" "):
        if words and _NUMBER.fullmatch(words[-1].split(" ")[-1]):
            words[-1] += " " + word
        else:
            words.append(word)
    return words


def wrap_expression(text: str, columns: int, indent: int, hang: int = 2) -> list[str]:
    """``text`` (indented by ``indent``) in lines of at most ``columns``, broken only at a space
    before an operator: outside brackets, and inside them only for a bracket too long for a line.
    A line that goes on is indented ``hang`` more. A term longer than a whole line is left whole
    (the line is then longer than ``columns``)."""
    if indent + len(text) <= columns:
        return [" " * indent + text]
    pieces = []
    room = columns - indent - hang
    for piece in _pieces(text, 0):  # between the terms outside brackets; inside them only where a term is too long
        for inner in (_pieces(piece, 9) if len(piece) > room else [piece]):
            pieces += _words(inner) if len(inner) > room else [inner]
    lines: list[str] = []
    line = ""
    for piece in pieces:
        lead = indent if not lines else indent + hang
        joined = f"{line} {piece}" if line else piece
        if line and lead + len(joined) > columns:
            lines.append(" " * lead + line)
            line = piece
        else:
            line = joined
    lines.append(" " * (indent if not lines else indent + hang) + line)
    return lines
