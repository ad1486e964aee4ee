"""A quantity as a formula of time: ``(2 - 3*t/s) rad/s^2``, ``10 N*m/s * t``,
``5 N*m * exp(-t/(2 s))``, read into a taucli.numerics.of_time.OfTime in SI; or of the crank
angle, ``(15000 + 10000*sin(2*theta)) N*m`` (a turning-moment diagram: ``theta``, or θ, is the
one variable, a number of radians, as sin and cos take it).

The grammar is the one a quantity is written in (numbers, units, + − * / ^ and parentheses, a
number beside its unit multiplying it, as in ``3 t`` or ``2 N*m``), with ``t`` the one variable,
the time in its own unit (``t/s`` is a number of seconds), and the functions of FUNCTIONS. It is
parsed here by recursive descent and never run as code. Each part is kept as a polynomial in t
while it is one (numbers, units, t, sums, products, a division by a part free of t, a whole
power up to MAX_POWER), so that a polynomial is integrated exactly; anything else becomes a
function of t, integrated by quadrature (of theta, a polynomial plus sines and cosines of
multiples of it, sin(φ + wθ) and cos(φ + wθ) times numbers and summed, is kept exact too). Units are pint's, each looked up once by name; a sum of
parts of different dimensions, a function of a dimensioned part, or a result not of the option's
kind is refused, naming the option. An angular quantity (α) needs its angle unit written, as a
number does everywhere.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.numerics.of_time import OfTime
from taucli.quantities.kinds import Kind
from taucli.quantities.registry import registry

MAX_LENGTH = 200
MAX_POWER = 8  # t^8: a whole power beyond it is refused (a formula of a book is of low degree)
MAX_DEPTH = 40
FUNCTIONS = {"sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan, "exp": math.exp}
_TOKEN = re.compile(r"\s*(?:(?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<name>[A-Za-zµμΩ_][A-Za-z0-9_µμΩ]*)|(?P<op>\*\*|[-+*/^()]))")
_SPELLED = {"−": "-", "·": "*", "×": "*", "⋅": "*", "²": "^2", "³": "^3"}
_T = re.compile(r"(?<![A-Za-z0-9_])t(?![A-Za-z0-9_])")
_THETA = re.compile(r"(?<![A-Za-z0-9_])theta(?![A-Za-z0-9_])|θ")
TIME, ANGLE = "t", "theta"  # the variables: the time (in its own unit, t/s a number of seconds), the crank angle (radians, a number)
_ABOUT = {TIME: "a formula of t (the time)", ANGLE: "a formula of theta (the crank angle, in radians)"}
_EXAMPLES = {TIME: "'(2 - 3*t/s) {unit}'", ANGLE: "'(15000 + 10000*sin(2*theta)) {unit}'"}


def mentions_time(text: str) -> bool:
    """Whether ``text`` is a formula of t (t standing alone, not a letter of a unit's name)."""
    return isinstance(text, str) and _T.search(text) is not None


def mentions_angle(text: str) -> bool:
    """Whether ``text`` is a formula of the crank angle: theta standing alone, or θ."""
    return isinstance(text, str) and _THETA.search(text) is not None


@dataclass
class _Part:
    """A part of the formula: a polynomial (coefficients in SI, powers of t in seconds) or a
    function of t; its dimensions (pint's); whether an angle unit was written in it."""

    dims: object
    coefficients: list[float] | None = None
    function: object = None
    angled: bool = False
    # A formula of theta that is a polynomial plus sines and cosines of multiples of theta, kept as
    # ((c₀, c₁, …), ((w, s, c), …)) beside its function: Σcₖθᵏ + Σ(s sin wθ + c cos wθ), integrated exactly.
    waves: tuple | None = None

    def form(self) -> tuple | None:
        """The part as a polynomial and its waves, where it is one (a polynomial has none)."""
        return (tuple(self.coefficients), ()) if self.coefficients is not None else self.waves

    def call(self):
        if self.coefficients is not None:
            cs = tuple(self.coefficients)

            def poly(t: float) -> float:
                total = 0.0
                for c in reversed(cs):
                    total = total * t + c
                return total

            return poly
        return self.function


def read_formula(text: str, option: str, kind: Kind, variable: str = TIME) -> OfTime:
    """``text`` (a formula of ``variable``: t, the time, or theta, the crank angle in radians) as an
    OfTime in ``kind``'s SI unit, or an InputError naming ``option``."""
    shown = text
    for spelled, plain in _SPELLED.items():
        text = text.replace(spelled, plain)
    if variable == ANGLE:
        text = text.replace("θ", " theta ")
        if mentions_time(text):
            raise _error(option, kind, shown, "t is not its variable: theta (the crank angle) is", variable)
    if len(text) > MAX_LENGTH:
        raise _error(option, kind, shown, f"longer than {MAX_LENGTH} characters", variable)
    tokens = _tokens(text, option, kind, shown, variable)
    depth = 0
    for _, token in tokens:
        depth += (token == "(") - (token == ")")
        if depth < 0:
            raise _error(option, kind, shown, "a ) without its (", variable)
    if depth > 0:
        raise _error(option, kind, shown, "a ( without its )", variable)
    parser = _Parser(tokens, option, kind, shown, variable)
    part = parser.sum(0)
    if parser.position != len(tokens):
        raise _error(option, kind, shown, f"unexpected {tokens[parser.position][1]!r}", variable)
    ureg = registry()
    wanted = ureg.Quantity(1, kind.si_unit)
    if part.dims != wanted.dimensionality:
        aside = "t/s is a number of seconds" if variable == TIME else "theta is a number of radians"
        raise _error(option, kind, shown, f"it is not {_an(kind.name)} (its units make {_dims(part.dims)}; {aside})", variable)
    if "rad" in kind.si_unit and not part.angled:
        raise _error(option, kind, shown, "its angle unit is not written (rad or rev: a number alone is ambiguous)", variable)
    if part.coefficients is not None:
        cs = list(part.coefficients)
        while len(cs) > 1 and cs[-1] == 0:
            cs.pop()
        return OfTime(shown, kind.si_unit, coefficients=tuple(cs), variable=variable)
    return OfTime(shown, kind.si_unit, function=part.function, variable=variable, waves=part.waves)


def _an(name: str) -> str:
    return ("an " if name[:1] in "aeiou" else "a ") + name


def _error(option: str, kind: Kind, shown: str, why: str, variable: str = TIME) -> InputError:
    return InputError(option, f"expected {_an(kind.name)} or {_ABOUT[variable]} giving one",
                      example=_EXAMPLES[variable].format(unit=kind.si_unit.replace("**", "^")), got=f"{shown!r}: {why}")


def _tokens(text: str, option: str, kind: Kind, shown: str, variable: str = TIME) -> list[tuple[str, str]]:
    tokens, position = [], 0
    text = text.rstrip()
    while position < len(text):
        found = _TOKEN.match(text, position)
        if found is None or found.end() == position:
            raise _error(option, kind, shown, f"{text[position:].strip()[:1]!r} is not part of a formula", variable)
        kind_of = found.lastgroup
        tokens.append((kind_of, found.group(kind_of)))
        position = found.end()
    return tokens


class _Parser:
    """sum := product (('+'|'-') product)*;  product := signed (('*'|'/'|nothing) signed)*;
    signed := ('-'|'+') signed | power;  power := atom (('^'|'**') signed)?;
    atom := number | t | unit | function '(' sum ')' | '(' sum ')'."""

    def __init__(self, tokens, option, kind, shown, variable=TIME):
        self.tokens, self.position, self.option, self.kind, self.shown, self.variable = tokens, 0, option, kind, shown, variable
        self.ureg = registry()
        self.none = self.ureg.Quantity(1, "").dimensionality
        # t is a time; theta an angle in radians, a number (pint's radian is dimensionless)
        self.unit_of_variable = self.ureg.Quantity(1, "s" if variable == TIME else "").dimensionality

    def fail(self, why: str) -> InputError:
        return _error(self.option, self.kind, self.shown, why, self.variable)

    def peek(self):
        return self.tokens[self.position] if self.position < len(self.tokens) else (None, None)

    def take(self):
        token = self.peek()
        self.position += 1
        return token

    def sum(self, depth: int) -> _Part:
        if depth > MAX_DEPTH:
            raise self.fail("nested too deeply")
        part = self.product(depth)
        while self.peek() in (("op", "+"), ("op", "-")):
            sign = -1.0 if self.take()[1] == "-" else 1.0
            other = self.product(depth)
            part = self.add(part, other, sign)
        return part

    def product(self, depth: int) -> _Part:
        part = self.signed(depth)
        while True:
            kind_of, text = self.peek()
            if (kind_of, text) in (("op", "*"), ("op", "/")):
                self.take()
                other = self.signed(depth)
                part = self.multiply(part, other) if text == "*" else self.divide(part, other)
            elif kind_of in ("number", "name") or (kind_of, text) == ("op", "("):
                part = self.multiply(part, self.signed(depth))  # 3 t, 2 N*m, 3(t/s): side by side
            else:
                return part

    def signed(self, depth: int) -> _Part:
        if self.peek() in (("op", "-"), ("op", "+")):
            sign = -1.0 if self.take()[1] == "-" else 1.0
            return self.scale(self.signed(depth + 1), sign)
        return self.power(depth)

    def power(self, depth: int) -> _Part:
        base = self.atom(depth)
        if self.peek() in (("op", "^"), ("op", "**")):
            self.take()
            exponent = self.signed(depth + 1)
            return self.raise_to(base, exponent)
        return base

    def atom(self, depth: int) -> _Part:
        kind_of, text = self.take()
        if kind_of == "number":
            return _Part(self.none, [float(text)])
        if (kind_of, text) == ("op", "("):
            inner = self.sum(depth + 1)
            if self.take() != ("op", ")"):
                raise self.fail("a ( without its )")
            return inner
        if kind_of == "name" and text == self.variable:
            return _Part(self.unit_of_variable, [0.0, 1.0])
        if kind_of == "name" and text.lower() in FUNCTIONS:
            if self.take() != ("op", "("):
                raise self.fail(f"{text} takes its argument in parentheses: {text}(…)")
            inner = self.sum(depth + 1)
            if self.take() != ("op", ")"):
                raise self.fail("a ( without its )")
            return self.function(text.lower(), inner)
        if kind_of == "name":
            return self.unit(text)
        raise self.fail("it ends too soon" if kind_of is None else f"unexpected {text!r}")

    def unit(self, name: str) -> _Part:
        try:
            quantity = self.ureg.Quantity(1, name)
            base = quantity.to_base_units()
        except Exception:  # pint's UndefinedUnitError and its kin: not a unit
            one = "t is the time" if self.variable == TIME else "theta is the crank angle"
            raise self.fail(f"{name!r} is not a unit ({one}, the one variable)") from None
        angled = "radian" in str(base.units) or "revolution" in str(quantity.units)
        return _Part(quantity.dimensionality, [float(base.magnitude)], angled=angled)

    def add(self, a: _Part, b: _Part, sign: float) -> _Part:
        if a.dims != b.dims:
            number = "t/s for a number of seconds" if self.variable == TIME else "theta alone, a number of radians"
            raise self.fail(f"it adds parts of different kinds ({_dims(a.dims)} and {_dims(b.dims)}): write each term's unit, or {number}")
        angled = a.angled or b.angled
        if a.coefficients is not None and b.coefficients is not None:
            size = max(len(a.coefficients), len(b.coefficients))
            cs = [(a.coefficients[k] if k < len(a.coefficients) else 0.0) + sign * (b.coefficients[k] if k < len(b.coefficients) else 0.0) for k in range(size)]
            return _Part(a.dims, cs, angled=angled)
        f, g = a.call(), b.call()
        fa, fb = a.form(), b.form()
        waves = (_sum(fa[0], fb[0], sign), _merged(fa[1], fb[1], sign)) if fa is not None and fb is not None else None
        return _Part(a.dims, function=lambda t: f(t) + sign * g(t), angled=angled, waves=waves)

    def scale(self, a: _Part, factor: float) -> _Part:
        if a.coefficients is not None:
            return _Part(a.dims, [factor * c for c in a.coefficients], angled=a.angled)
        f = a.call()
        return _Part(a.dims, function=lambda t: factor * f(t), angled=a.angled, waves=_times(a.waves, factor))

    def multiply(self, a: _Part, b: _Part) -> _Part:
        dims, angled = a.dims * b.dims, a.angled or b.angled
        if a.coefficients is not None and b.coefficients is not None:
            if len(a.coefficients) + len(b.coefficients) - 2 > MAX_POWER:
                raise self.fail(f"a power of {self.variable} above {MAX_POWER}")
            cs = [0.0] * (len(a.coefficients) + len(b.coefficients) - 1)
            for i, x in enumerate(a.coefficients):
                for j, y in enumerate(b.coefficients):
                    cs[i + j] += x * y
            return _Part(dims, cs, angled=angled)
        f, g = a.call(), b.call()
        waves = None
        for wave, other in ((a, b), (b, a)):  # a wave times a number: still a wave
            if wave.waves is not None and other.coefficients is not None and len(other.coefficients) == 1:
                waves = _times(wave.waves, other.coefficients[0])
        return _Part(dims, function=lambda t: f(t) * g(t), angled=angled, waves=waves)

    def divide(self, a: _Part, b: _Part) -> _Part:
        dims, angled = a.dims / b.dims, a.angled or b.angled
        if b.coefficients is not None and len(b.coefficients) == 1:
            if b.coefficients[0] == 0:
                raise self.fail("a division by zero")
            scaled = self.scale(a, 1.0 / b.coefficients[0])
            return _Part(dims, scaled.coefficients, scaled.function, angled, scaled.waves)
        f, g = a.call(), b.call()
        return _Part(dims, function=lambda t: f(t) / g(t), angled=angled)

    def raise_to(self, base: _Part, exponent: _Part) -> _Part:
        if exponent.coefficients is None or len(exponent.coefficients) != 1 or exponent.dims != self.none:
            raise self.fail(f"a power must be a number ({self.variable}^2, not 2^{self.variable})")
        n = exponent.coefficients[0]
        if not math.isfinite(n) or abs(n) > MAX_POWER:
            raise self.fail(f"a power beyond ±{MAX_POWER}")
        dims = base.dims**n
        if base.coefficients is not None and n == int(n) and n >= 0:
            result = _Part(self.none, [1.0])
            for _ in range(int(n)):
                result = self.multiply(result, base)
            return _Part(dims, result.coefficients, angled=base.angled)
        if base.coefficients is not None and len(base.coefficients) == 1:
            return _Part(dims, [base.coefficients[0] ** n], angled=base.angled)
        f = base.call()
        return _Part(dims, function=lambda t: f(t) ** n, angled=base.angled)

    def function(self, name: str, inner: _Part) -> _Part:
        if name == "sqrt":
            dims = inner.dims**0.5
        elif inner.dims != self.none:
            example = "t/s is a number of seconds, e.g. {name}(2 rad/s * t)" if self.variable == TIME else "e.g. {name}(2*theta)"
            raise self.fail(f"{name}(…) takes a number or an angle, not {_dims(inner.dims)}: " + example.format(name=name))
        else:
            dims = self.none
        rule, f = FUNCTIONS[name], inner.call()
        if inner.coefficients is not None and len(inner.coefficients) == 1:
            try:
                return _Part(dims, [rule(inner.coefficients[0])])
            except (ValueError, OverflowError):
                raise self.fail(f"{name} has no value there") from None
        waves = None
        if self.variable == ANGLE and name in ("sin", "cos") and inner.coefficients is not None and len(inner.coefficients) == 2:
            phase, w = inner.coefficients  # sin(φ + wθ) = sin φ cos wθ + cos φ sin wθ; cos(φ + wθ) = cos φ cos wθ − sin φ sin wθ
            terms = ((w, math.cos(phase), math.sin(phase)),) if name == "sin" else ((w, -math.sin(phase), math.cos(phase)),)
            waves = ((0.0,), terms)
        return _Part(dims, function=lambda t: rule(f(t)), waves=waves)


def _sum(a: tuple, b: tuple, sign: float) -> tuple:
    size = max(len(a), len(b))
    return tuple((a[k] if k < len(a) else 0.0) + sign * (b[k] if k < len(b) else 0.0) for k in range(size))


def _merged(a: tuple, b: tuple, sign: float) -> tuple:
    """Σ(s sin wθ + c cos wθ) of both, a term per w (a cosine of −w is of w; a sine changes sign)."""
    found: dict[float, list[float]] = {}
    for terms, factor in ((a, 1.0), (b, sign)):
        for w, s, c in terms:
            key, s = (w, s) if w > 0 else (-w, -s)
            held = found.setdefault(key, [0.0, 0.0])
            held[0] += factor * s
            held[1] += factor * c
    return tuple((w, s, c) for w, (s, c) in found.items())


def _times(waves: tuple | None, factor: float) -> tuple | None:
    if waves is None:
        return None
    return tuple(factor * c for c in waves[0]), tuple((w, factor * s, factor * c) for w, s, c in waves[1])


def _dims(dims) -> str:
    text = str(dims)
    return "a number" if text in ("", "dimensionless") else text
