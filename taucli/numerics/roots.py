"""Every root of a result over the range an input may take: the search behind ``--find`` (#22, #31).

f(x) is a result of the scene minus its target with the input at x, or None where the scene refuses
x or the result has no value there. Every forward solve is kept, and each pass below works on all
the samples taken before it:

1. A grid over the range: a few values a decade within the kind's bounds (0, and both signs where
   the sign allows); an angle also densely over a turn each side of 0. Where the result repeats
   every turn, that turn is the range: each root holds again a whole number of turns on.
2. Each edge of where the result has a value (a sample beside one without) is bisected to full
   precision. A result that tends to the target there has its root at the edge (a load that just
   stops at the distance asked: beyond it, it stops short and its speed there has no value).
3. Each place the samples turn toward the target (their differences change sign, and the sample
   between is nearer the target than its neighbours) is refined: the extremum between the
   neighbours, by golden-section search, until it crosses the target or is found. So two roots in
   one cell, and a root where the result just touches the target, are seen.
4. Each cell between neighbouring samples where f changes sign is a bracket: Brent's method finds
   the root in it to full precision (a crossing that is a jump, not a root, is counted apart).

This finds every root where the result turns at most once between neighbouring samples. Where the
samples show that it does not (turns at neighbouring samples of the grid), or there were more edges
or turns than are refined, ``Search.doubts`` says where, and that the range may hold more roots.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

PER_DECADE = 4  # grid values a decade
PER_TURN = 128  # grid values a turn, for an angle (2.8° apart)
TURN = 2 * math.pi
EPS = 2.0**-52
MAX_EDGES = 24  # edges of where the result has a value, bisected
MAX_TURNS = 48  # places the result turns toward the target, refined
EDGE_TOLERANCE = 1e-6  # a result this near its target at an edge (relative), and nearing it, meets it there
TOUCH_TOLERANCE = 1e-10  # an extremum this near the target (relative) touches it: a root
NOISE = 1e-12  # differences below this (relative) are rounding, not a turn

Function = Callable[[float], "float | None"]


@dataclass
class Search:
    """What the search found: every root it can see, how each was found, and where it may miss."""

    roots: list[float] = field(default_factory=list)
    found: list[str] = field(default_factory=list)  # for each root, how: "Brent's method, 9 steps"
    brackets: list[tuple[float, float]] = field(default_factory=list)  # for each root, the cell it was found in
    jumps: int = 0  # sign changes that are jumps, not roots
    low: float = 0.0  # the range searched
    high: float = 0.0
    solves: int = 0
    turns: int = 0  # places refined where the result turns toward the target
    edges: list[float] = field(default_factory=list)  # where the result stops having a value
    at_edge: list[float] = field(default_factory=list)  # roots that are edges
    doubts: list[str] = field(default_factory=list)  # why the roots may not be all there are: empty where they are
    period: bool = False  # the result repeats every turn (an angle): the roots of one turn
    interval: tuple[float, float | None] | None = None  # f = 0 over an interval from low (to high, or upward)
    samples: list[tuple[float, float | None]] = field(default_factory=list)  # every (x, f(x)) taken, in order of x

    @property
    def complete(self) -> bool:
        return not self.doubts


def grid(bounds: tuple[float, float], sign: str, *, angle: bool = False) -> list[float]:
    """The first samples: a few values a decade within ``bounds`` (sizes), 0 and the negative side
    where ``sign`` allows; for an angle also PER_TURN values a turn from −1 turn to 1 turn."""
    low, high = bounds
    first, last = math.floor(math.log10(low) * PER_DECADE), math.ceil(math.log10(high) * PER_DECADE)
    sizes = [10.0 ** (k / PER_DECADE) for k in range(first, last + 1)]
    if angle:
        step = TURN / PER_TURN
        sizes = sorted({*(s for s in sizes if s < step or s > TURN), *(TURN * k / PER_TURN for k in range(1, PER_TURN + 1))})
    if sign == "positive":
        return sizes
    if sign == "nonnegative":
        return [0.0, *sizes]
    return [-s for s in reversed(sizes)] + [0.0] + sizes


def meets(v: float, target: float) -> bool:
    return v == 0 or abs(v) <= 1e-13 * abs(target)


def search(f: Function, xs: list[float], target: float, *, angle: bool = False, say: Callable[[float], str] = "{:.6g}".format) -> Search:
    """Every root of ``f`` the search can see, starting from the samples ``xs`` (sorted); ``say``
    writes a value of x in the doubts."""
    seen: dict[float, float | None] = {}

    def sample(x: float) -> float | None:
        if x not in seen:
            seen[x] = f(x)
        return seen[x]

    found = Search(low=xs[0], high=xs[-1])
    if angle and _repeats(sample, xs, target):
        found.period = True
        xs = [x for x in xs if abs(x) <= TURN * (1 + 1e-12)]
        found.low, found.high = (-math.pi, math.pi) if xs[0] < 0 else (0.0, TURN)
    values = [sample(x) for x in xs]
    found.interval = _interval(sample, xs, values, target)
    if found.interval is None:
        _edges(sample, seen, target, found)
        _turns(sample, seen, xs, target, found, say)
        if angle and not found.period:
            _beyond_a_turn(seen, xs, target, found)
        _brackets(sample, seen, target, found)
    if found.period:
        keep = [i for i, x in enumerate(found.roots) if (found.low < x <= found.high if found.low < 0 else found.low <= x < found.high)]
        found.roots, found.found, found.brackets = ([items[i] for i in keep] for items in (found.roots, found.found, found.brackets))
    found.samples = sorted(seen.items())
    found.solves = len(seen)
    return found


def _scale(target: float, *values: float | None) -> float:
    """The size a result has near here: of its target, or of its values (f + target)."""
    return max([abs(target), *(abs(v + target) for v in values if v is not None)]) or 1e-300


def _repeats(sample, xs: list[float], target: float) -> bool:
    """Whether the result has a value beyond a turn and repeats every turn (checked at 64 angles)."""
    probes = [TURN * k / 64 for k in range(64)]
    pairs = [(sample(x), sample(x + TURN)) for x in probes]
    pairs = [(a, b) for a, b in pairs if a is not None or b is not None]
    if len(pairs) < 8 or any(a is None or b is None for a, b in pairs):
        return False
    return all(abs(a - b) <= 1e-9 * _scale(target, a, b) for a, b in pairs)


def _interval(sample, xs: list[float], values: list, target: float) -> tuple[float, float | None] | None:
    """Where the target holds over an interval (two neighbouring grid values meet it): its ends."""
    holds = [i for i, v in enumerate(values) if v is not None and meets(v, target)]
    first = next((i for i, j in zip(holds, holds[1:]) if j == i + 1), None)
    if first is None:
        return None
    last = first
    while last + 1 < len(xs) and values[last + 1] is not None and meets(values[last + 1], target):
        last += 1
    low = _holds_edge(sample, xs[first], xs[first - 1], target) if first > 0 else xs[first]
    high = _holds_edge(sample, xs[last], xs[last + 1], target) if last + 1 < len(xs) else None
    return low, high


def _holds_edge(sample, inside: float, outside: float, target: float) -> float:
    """Where "the target holds" ends between ``inside`` (holds) and ``outside`` (does not)."""
    for _ in range(200):
        middle = (inside + outside) / 2
        if middle in (inside, outside):
            break
        v = sample(middle)
        if v is not None and meets(v, target):
            inside = middle
        else:
            outside = middle
    return inside


def _edges(sample, seen: dict, target: float, found: Search) -> None:
    """Bisect each edge of where the result has a value; a root where it tends to the target."""
    points = sorted(seen.items())
    cells = [(a, va, b, vb) for (a, va), (b, vb) in zip(points, points[1:]) if (va is None) != (vb is None)]
    if len(cells) > MAX_EDGES:
        found.doubts.append(f"the result has a value in {len(cells) // 2 + 1} or more separate stretches, more than the search refines")
        cells = cells[:MAX_EDGES]
    for a, va, b, vb in cells:
        inside, outside = (a, b) if va is not None else (b, a)
        start = inside
        for _ in range(200):
            middle = inside + (outside - inside) / 2
            if middle in (inside, outside):
                break
            if sample(middle) is None:
                outside = middle
            else:
                inside = middle
        found.edges.append(inside)
        value = seen[inside]
        if value == 0:
            found.at_edge.append(inside)
            continue
        width = abs(outside - inside) or abs(inside) * EPS or 1e-300
        towards = math.copysign(1.0, start - inside)
        probes = [inside + towards * width * 10.0**k for k in (3, 6)]
        probes = [p for p in probes if min(start, inside) <= p <= max(start, inside)]
        far = [sample(p) for p in probes]
        scale = _scale(target, seen[start], *far)
        nearing = any(v is not None and v * value > 0 and abs(v) >= 30 * abs(value) for v in far)
        if abs(value) <= EDGE_TOLERANCE * scale and (nearing or abs(value) <= 1e-12 * scale):
            found.at_edge.append(inside)


def _turns(sample, seen: dict, xs: list[float], target: float, found: Search, say) -> None:
    """Refine each place the samples turn toward the target; doubt where they turn at neighbours
    (and refine nothing there: the grid does not resolve it)."""
    unresolved = _unresolved([(x, seen[x]) for x in xs], target)
    if unresolved:
        stretches = [f"from {say(low)} to {say(high)}" for low, high in unresolved[:3]]
        more = f" and {len(unresolved) - 3} more stretches" if len(unresolved) > 3 else ""
        found.doubts.append(f"the result turns at neighbouring samples, faster than the search resolves, {', '.join(stretches)}{more}")
    points = [(x, v) for x, v in sorted(seen.items())]
    places = []
    for (a, va), (m, vm), (b, vb) in zip(points, points[1:], points[2:]):
        if va is None or vm is None or vb is None or vm == 0 or va * vm <= 0 or vm * vb <= 0:
            continue
        noise = NOISE * _scale(target, va, vm, vb)
        if abs(vm) < abs(va) - noise and abs(vm) < abs(vb) - noise and not any(low <= m <= high for low, high in unresolved):
            places.append((a, m, b))
    if len(places) > MAX_TURNS:
        found.doubts.append(f"the result turns toward the target at {len(places)} places, more than the search refines")
        places = places[:MAX_TURNS]
    for a, m, b in places:
        found.turns += 1
        _dip(sample, a, m, b, target)


def _unresolved(grid_values: list, target: float) -> list[list[float]]:
    """Where the result turns at neighbouring grid values: the grid does not resolve it there."""
    stretches: list[list[float]] = []
    for i in range(1, len(grid_values) - 2):
        window = grid_values[i - 1:i + 3]
        if any(v is None for _, v in window):
            continue
        v = [value for _, value in window]
        noise = NOISE * _scale(target, *v)
        d = [v[k + 1] - v[k] for k in range(3)]
        if all(abs(step) > noise for step in d) and d[0] * d[1] < 0 and d[1] * d[2] < 0:
            low, high = window[0][0], window[-1][0]
            if stretches and stretches[-1][1] >= low:
                stretches[-1][1] = high
            else:
                stretches.append([low, high])
    return stretches


def _beyond_a_turn(seen: dict, xs: list[float], target: float, found: Search) -> None:
    """An angle's grid beyond a turn each way is a few values a decade, a turn or more apart: a
    result that turns within a turn may turn between them, unseen."""
    outside = any(v is not None for x, v in seen.items() if abs(x) > TURN * (1 + 1e-12))
    inside = [(x, seen[x]) for x in xs if abs(x) <= TURN * (1 + 1e-12)]
    turning = any(a is not None and m is not None and b is not None and (m - a) * (b - m) < 0
                  and min(abs(m - a), abs(b - m)) > NOISE * _scale(target, a, m, b)
                  for (_, a), (_, m), (_, b) in zip(inside, inside[1:], inside[2:]))
    if outside and turning:
        found.doubts.append("beyond a turn each way (±360°) the samples are a turn or more apart, and the result turns within a turn")


def _dip(sample, a: float, m: float, b: float, target: float) -> None:
    """Golden-section search for the extremum of f between a and b (f(m) nearest the target), until
    f crosses the target or the extremum is found: its samples are what the brackets then see."""
    sign = math.copysign(1.0, sample(m))
    g = 0.3819660112501051  # 2 − the golden ratio
    for _ in range(80):
        if b - a <= 4 * EPS * max(abs(a), abs(b)) + 1e-300:
            break
        x = m + g * (b - m) if b - m > m - a else m - g * (m - a)
        if x in (a, m, b):
            break
        vx = sample(x)
        if vx is None:
            break
        if sign * vx <= TOUCH_TOLERANCE * _scale(target, vx):
            return  # it crosses (or touches) the target: the brackets take it from here
        if abs(vx) < abs(sample(m)):
            a, b = (m, b) if x > m else (a, m)
            m = x
        else:
            a, b = (a, x) if x > m else (x, b)


def _brackets(sample, seen: dict, target: float, found: Search) -> None:
    """Brent's method in each cell where f changes sign; a sample at the target, a touch and an
    edge that meets the target are roots as they are."""
    points = sorted(seen.items())
    roots: list[tuple[float, str, tuple[float, float]]] = []
    for x in found.at_edge:
        roots.append((x, "at the edge of where the result has a value, by bisection", (x, x)))
    for i, (x, v) in enumerate(points):
        if v is None:
            continue
        if v == 0 and x not in found.at_edge:
            roots.append((x, "a sample at the target", (x, x)))
            continue
        left = points[i - 1][1] if i > 0 else None
        right = points[i + 1][1] if i + 1 < len(points) else None
        if left is not None and right is not None and left * v > 0 and right * v > 0 and abs(v) < min(abs(left), abs(right)) \
                and abs(v) <= TOUCH_TOLERANCE * _scale(target, v):
            roots.append((x, "where the result touches the target, by golden-section search", (points[i - 1][0], points[i + 1][0])))
    for (a, fa), (b, fb) in zip(points, points[1:]):
        if fa is None or fb is None or fa == 0 or fb == 0 or fa * fb > 0:
            continue
        try:
            x, count = brent(sample, a, b, fa, fb)
        except ArithmeticError:
            continue
        fx = sample(x)
        if fx is None or abs(fx) > 1e-9 * _scale(target, fx) and abs(fx) > 1e-12:
            found.jumps += 1  # a jump across the target, not a root
            continue
        roots.append((x, f"Brent's method, {count} steps", (a, b)))
    roots.sort()
    for x, how, cell in roots:
        if found.roots and math.isclose(x, found.roots[-1], rel_tol=1e-10, abs_tol=1e-300):
            continue
        found.roots.append(x)
        found.found.append(how)
        found.brackets.append(cell)


def brent(f, a: float, b: float, fa: float, fb: float, *, iterations: int = 200) -> tuple[float, int]:
    """A root of f in [a, b] (fa, fb of opposite signs) by Brent's method, to a few ulp of x."""
    if fa == 0:
        return a, 0
    if fb == 0:
        return b, 0
    c, fc, d = a, fa, b - a
    e = d
    for count in range(1, iterations + 1):
        if fb * fc > 0:
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2 * EPS * abs(b) + 1e-300
        m = (c - b) / 2
        if abs(m) <= tol or fb == 0:
            return b, count
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:
                p, q = 2 * m * s, 1 - s
            else:
                q, r = fa / fc, fb / fc
                p = s * (2 * m * q * (q - r) - (b - a) * (r - 1))
                q = (q - 1) * (r - 1) * (s - 1)
            if p > 0:
                q = -q
            p = abs(p)
            if 2 * p < min(3 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b += d if abs(d) > tol else math.copysign(tol, m)
        fb = f(b)
        if fb is None:
            raise ArithmeticError("the scene has no value inside the bracket")
    return b, iterations


def falling_root(rate: Callable[[float], float]) -> float:
    """The speed u > 0 where ``rate`` (positive at 0, falling) crosses zero: bracketed by doubling
    from 1, then bisected until the bracket holds no float between its ends."""
    low, high = 0.0, 1.0
    while rate(high) > 0:
        low, high = high, 2 * high
    for _ in range(200):
        mid = (low + high) / 2
        if mid in (low, high):
            break
        low, high = (mid, high) if rate(mid) > 0 else (low, mid)
    return (low + high) / 2
