"""A body of parts placed round an axis, and its moment of inertia about a parallel axis
anywhere, at 50 digits (#46 item 8).

Each part has a mass m, its moment of inertia I_c about the axis through its own centre of
mass (parallel to the rotation axis) and the position p of that centre in the plane normal to
the axes. About a parallel axis through the point A, I = Σ m r² over all the mass is, part by
part (each part's own parallel-axis theorem: its mass is spread about its own centre),

    I_A = Σ (I_c + m |p − A|²)

The body's centre of mass is c = Σ m p / M, and I_cm = I_c(body) is I_A with A = c. A body
"moved D off its centre of mass" turns about a point A at distance D from c: the sum above at
A = c + D u, for any unit u (the cross term Σ m (p − c)·u vanishes: that the direction does
not matter is the theorem, which the tests check by taking two directions).

The parts' own I_c, from Σ m r² over their shapes:
    point 0;  ring (about its axis) m R²;  disc ½ m R²;
    rod (thin, the axes normal to it) m L²/12, its centre L/2 from an end;
    given: as given.

Hibbeler, Engineering Mechanics: Dynamics, 17-14: a thin ring of 10 kg and four slender spokes
of 2 kg each, radius 0.5 m, about a point A on the rim; the book's I_A = 7.67 kg·m². The
reference integrates r² dm over the ring and along each spoke directly (wheel_about_rim).
"""

from __future__ import annotations

import mpmath

from references import DPS, mp, mpf

WORK = DPS + 10


def own_inertia(kind: str, mass, size=0):
    """I_c of a part about the axis through its own centre: kind point, ring, disc, rod, given."""
    m, a = mpf(mass), mpf(size)
    return {"point": 0 * m, "ring": m * a * a, "disc": m * a * a / 2, "rod": m * a * a / 12, "given": a}[kind]


def _about(parts, point):
    """Σ (I_c + m|p − A|²) over parts [(m, I_c, (x, y))] about the axis through A = point."""
    ax, ay = point
    return mpmath.fsum(I + m * ((x - ax) ** 2 + (y - ay) ** 2) for m, I, (x, y) in parts)


def body(parts, distance=None, direction=0):
    """dict of M, c (the centre of mass's distance from the axis the parts were placed about),
    I_O (about that axis), I_cm and, with ``distance`` D, I about an axis D from the centre of
    mass towards ``direction`` (radians). ``parts``: (mass, own I_c, (x, y)) in SI."""
    with mp.workdps(WORK):
        parts = [(mpf(m), mpf(I), (mpf(x), mpf(y))) for m, I, (x, y) in parts]
        M = mpmath.fsum(m for m, _, _ in parts)
        cx = mpmath.fsum(m * x for m, _, (x, _) in parts) / M
        cy = mpmath.fsum(m * y for m, _, (_, y) in parts) / M
        out = {"M": M, "c": mpmath.hypot(cx, cy), "I_O": _about(parts, (0, 0)), "I_cm": _about(parts, (cx, cy))}
        if distance is not None:
            D, u = mpf(distance), mpf(direction)
            out["I"] = _about(parts, (cx + D * mpmath.cos(u), cy + D * mpmath.sin(u)))
    with mp.workdps(DPS):
        return {key: +value for key, value in out.items()}


def placed(offset, angle):
    """The position (x, y) of a centre at ``offset`` from the axis, ``angle`` radians round it."""
    with mp.workdps(WORK):
        d, a = mpf(offset), mpf(angle)
        return d * mpmath.cos(a), d * mpmath.sin(a)


def wheel_about_rim(ring_mass=10, spoke_mass=2, radius="0.5", spokes=4):
    """Hibbeler 17-14 by ∫ r² dm: a thin ring and ``spokes`` slender spokes from the centre to
    the rim, evenly spaced, about the point A = (R, 0) on the rim."""
    with mp.workdps(WORK):
        M, m, R = mpf(ring_mass), mpf(spoke_mass), mpf(radius)
        ring = mpmath.quad(lambda phi: M / (2 * mpmath.pi) * ((R * mpmath.cos(phi) - R) ** 2 + (R * mpmath.sin(phi)) ** 2), [0, mpmath.pi, 2 * mpmath.pi])
        total = ring
        for k in range(spokes):
            a = 2 * mpmath.pi * k / spokes
            total += mpmath.quad(lambda s: m / R * ((s * mpmath.cos(a) - R) ** 2 + (s * mpmath.sin(a)) ** 2), [0, R])
    with mp.workdps(DPS):
        return +total
