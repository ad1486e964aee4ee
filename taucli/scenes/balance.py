"""Balancing of rotating masses: one plane, two planes along a shaft, and the loads on its bearings.

Each mass mᵢ turns with the shaft at radius rᵢ and angle θᵢ (counter-clockwise from a reference
line fixed in the shaft), in the plane at lᵢ along it. Written as complex numbers in the plane
of rotation, its centrifugal force at speed ω is mᵢ rᵢ ω² e^(iθᵢ), so the masses together give

    U = Σ mᵢ rᵢ e^(iθᵢ)                  (kg·m: the unbalance; the force ω²U)
    C = Σ mᵢ rᵢ (lᵢ − l_A) e^(iθᵢ)        (kg·m²: the couple unbalance about the plane at l_A; the couple ω²C)

One balancing mass (any plane) closes the force polygon: m_b r_b e^(iθ_b) = −U. Two balancing
masses in planes A and B close both polygons (the couple taken about A, where A's own mass has no
arm): B_B (l_B − l_A) = −C and B_A = −U − B_B.

Between bearings A and B (at a and b along the shaft) turning at ω, the shaft's loads F_A, F_B
(in the frame that turns with it) balance the masses' centrifugal forces and their moments:

    F_A + F_B = ω²U,    (b − a) F_B = ω² C_a + g U   (C_a the couple unbalance about a)

where g U is the moment of the masses' weights about the bearing, counted only on a vertical
shaft (positions measured upward; each weight mᵢg at radius rᵢ has the moment mᵢ g rᵢ, which
turns with the shaft). A horizontal shaft's weights are a steady load, not a turning one, and
the balancing books leave them out.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.balance import COMMAND as TABLE
from taucli.options.table import Results
from taucli.scenes.assumed import Assumed
from taucli.scenes.given import Revolving
from taucli.writing.report import Report, Step, Table, fmt, pretty_unit, quantity_text, term

_EXAMPLE = "{mass} 'mass=2kg radius=0.3m angle=0deg' {mass} 'mass=3kg radius=0.2m angle=90deg'"
_TWO_PLANES = "{plane} 0m {plane} 0.8m"
_ROUNDING = 16 * 2.0**-52  # a sum below this share of its terms' sizes is rounding: zero


def balance(
    *,
    mass: Sequence[Revolving] = (),
    plane: Sequence[float] = (),
    balance_radius: Sequence[float] = (),
    speed: float | None = None,
    bearing: Sequence[float] = (),
    vertical: bool = False,
    g: float | None = None,
) -> Report:
    """``taucli balance``: the balancing mass·radius and angle in one plane or two, the unbalanced
    force and couple at a speed, the bearings' loads."""
    _check(mass, plane, balance_radius, bearing, speed, vertical)
    assumed = Assumed()
    results = Results(TABLE)
    steps: list[Step] = []
    notes: list[str] = []
    along = bool(plane) or bool(bearing) or any(m.plane is not None for m in mass)
    reference = plane[0] if plane else 0.0
    rows = [_row(m, reference) for m in mass]
    unbalance = _sum([row[0] for row in rows])
    couple = _sum([row[1] for row in rows])
    tables = _tables(mass, rows, along, reference)
    steps.append(_polygon_step(mass, rows))
    size, angle = _polar(unbalance, [abs(r[0]) for r in rows])
    results.put("unbalance", size)
    results.put("unbalance_angle", angle)
    couple_size, couple_angle = _polar(couple, [abs(r[1]) for r in rows])
    about = f" about the plane at {quantity_text(reference, 'm')}"
    if along:  # all in one plane (no plane=, --plane or --bearing): no couple to speak of
        results.put("unbalance_couple", couple_size, about)
        steps.append(_couple_step(mass, rows, reference, couple, couple_size, couple_angle))
    if len(plane) == 2:
        _two_planes(results, steps, notes, unbalance, couple, rows, plane, balance_radius)
    else:
        _one_plane(results, steps, notes, unbalance, rows, balance_radius, couple_size, along)
    if speed is not None:
        results.put("force_unbalanced", speed * speed * size)
        if along:
            results.put("couple_unbalanced", speed * speed * couple_size, about)
        couple_text = f";  ({quantity_text(speed, 'rad/s')})² × {quantity_text(couple_size, 'kg*m**2')}" if along else ""
        steps.append(Step("Unbalanced force and couple at the speed" if along else "Unbalanced force at the speed",
                          "F = ω²|Σ m·r|,  C = ω²|Σ m·r·l|" if along else "F = ω²|Σ m·r|",
                          f"({quantity_text(speed, 'rad/s')})² × {quantity_text(size, 'kg*m')}{couple_text}",
                          quantity_text(speed * speed * size, 'N') + (f", {quantity_text(speed * speed * couple_size, 'N*m')}" if along else ""),
                          "each mass pulls outward with m r ω² along its radius: the forces add as the vectors m·r do, times ω²"
                          + (", and their moments about the plane as the m·r·l do" if along else "")))
        if bearing:
            gravity = assumed.gravity(g) if vertical else 0.0
            _bearings(results, steps, notes, mass, speed, bearing, gravity)
    model = ("two-plane balancing: Σ m·r and Σ m·r·l closed by masses in planes A and B" if len(plane) == 2 else
             "one-plane balancing: the balancing mass closes the polygon of m·r")
    if bearing and speed is not None:
        model += "; bearing loads" + (" with the weights on a vertical shaft" if vertical else " from the turning masses alone")
    return assumed.applied(Report("balance", model, "closed form", results, steps, notes, tables=tables))


def _check(mass, plane, balance_radius, bearing, speed, vertical) -> None:
    if not mass:
        raise InputError("mass", "is required: each mass turning with the shaft, \"mass=… radius=… angle=…\" (repeatable)", example=_EXAMPLE)
    placed = [m.plane is not None for m in mass]
    if any(placed) and not all(placed):
        raise InputError("mass", "takes plane= on every mass or on none (none: all in one plane)", example=_EXAMPLE.replace("deg'", "deg plane=0.2m'"))
    if len(plane) > 2:
        raise InputError("plane", "takes one balancing plane or two (A, then B)", example=_TWO_PLANES, got=f"{len(plane)} planes")
    if len(plane) == 2 and plane[0] == plane[1]:
        raise InputError("plane", "takes two different positions: two balancing planes at one place balance no couple", example=_TWO_PLANES,
                         got=f"both at {quantity_text(plane[0], 'm')}")
    if len(balance_radius) > max(1, len(plane)):
        raise InputError("balance_radius", f"is given once for each balancing plane ({max(1, len(plane))}), or once for all", example="{balance_radius} 0.25m",
                         got=f"{len(balance_radius)} radii")
    if bearing and len(bearing) != 2:
        raise InputError("bearing", "takes two bearings (A, then B)", example="{bearing} 0m {bearing} 1m", got=f"{len(bearing)} bearing")
    if len(bearing) == 2 and bearing[0] == bearing[1]:
        raise InputError("bearing", "takes two different positions", example="{bearing} 0m {bearing} 1m", got=f"both at {quantity_text(bearing[0], 'm')}")
    if bearing and speed is None:
        raise InputError("speed", "is required with {bearing}: the loads come from the masses turning at it", example="{speed} 300rpm")
    if vertical and not bearing:
        raise InputError("vertical", "goes with two {bearing} and a {speed}: the weights change only the bearings' loads", example="{bearing} 0m {bearing} 1m {speed} 300rpm")


def _row(m: Revolving, reference: float) -> tuple[complex, complex]:
    """A mass's m·r and m·r·l (about the reference plane) as complex numbers."""
    mr = m.mass * m.centre
    c, s = _cos_sin(m.angle)
    arm = _arm(m, reference)
    return complex(mr * c, mr * s), complex(mr * arm * c, mr * arm * s)


def _cos_sin(angle: float) -> tuple[float, float]:
    """cos θ and sin θ, exact at the quarter turns the books use (sin 180° is 0, not 1.2e-16)."""
    quarters = angle / (math.pi / 2)
    if quarters == round(quarters):
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(round(quarters)) % 4]
    return math.cos(angle), math.sin(angle)


def _sum(values: Sequence[complex]) -> complex:
    return complex(math.fsum(v.real for v in values), math.fsum(v.imag for v in values))


def _polar(value: complex, sizes: Sequence[float]) -> tuple[float, float | None]:
    """|value| and its angle in [0, 2π); (0, None) where the sum is rounding of its terms."""
    size = abs(value)
    if size <= _ROUNDING * math.fsum(sizes):
        return 0.0, None
    angle = math.atan2(value.imag, value.real)
    return size, angle + 2 * math.pi if angle < 0 else angle


def _signed(x: float) -> str:
    """A number with a true minus: −1.6, so that a numbers line never shows "× -0.1"."""
    return "−" + fmt(-x) if x < 0 else fmt(x)


def _paren(x: float, unit: str) -> str:
    return f"({_signed(x)} {pretty_unit(unit)})"


def _vec(value: complex, unit: str) -> str:
    """A vector of the plane by its components along and across the reference line: (21.6 kg·m, −8.4 kg·m)."""
    shown = pretty_unit(unit)
    return f"({_signed(value.real)} {shown}, {_signed(value.imag)} {shown})"


def _angle_text(angle: float | None) -> str:
    return "—" if angle is None else f"{fmt(math.degrees(angle))}°"


def _tables(mass, rows, along: bool, reference: float) -> dict[str, Table]:
    """The books' tables: each mass's m, r, m·r, θ and components; along a shaft, its l and m·r·l."""
    columns = (("mass", None, "mass"), ("m", "kg", "m"), ("r", "m", "r"), ("mr", "kg*m", "m·r"), ("angle", "deg", "θ"),
               ("mr_x", "kg*m", "m·r cos θ"), ("mr_y", "kg*m", "m·r sin θ"))
    tables = {"masses": Table(columns, tuple((n, m.mass, m.centre, m.mass * m.centre, math.degrees(m.angle), mr.real, mr.imag)
                                             for n, (m, (mr, _)) in enumerate(zip(mass, rows), start=1)))}
    if along:
        columns = (("mass", None, "mass"), ("l", "m", "l"), ("mrl", "kg*m**2", "m·r·l"), ("angle", "deg", "θ"),
                   ("mrl_x", "kg*m**2", "m·r·l cos θ"), ("mrl_y", "kg*m**2", "m·r·l sin θ"))
        tables["couples"] = Table(columns, tuple((n, _arm(m, reference), m.mass * m.centre * _arm(m, reference), math.degrees(m.angle), mrl.real, mrl.imag)
                                                 for n, (m, (_, mrl)) in enumerate(zip(mass, rows), start=1)))
    return tables


def _arm(m: Revolving, reference: float) -> float:
    """l: the mass's plane from the reference plane (a mass with no plane= is in the plane at 0)."""
    return (m.plane if m.plane is not None else 0.0) - reference


def _polygon_step(mass, rows) -> Step:
    terms = "; ".join(f"{term(m.mass, 'kg')} × {term(m.centre, 'm')} at {_signed(math.degrees(m.angle))}°" for m in mass)
    total = _sum([r[0] for r in rows])
    rods = [m for m in mass if m.length is not None]
    why = ("each mass's centrifugal pull m r ω² lies along its radius: the m·r add as vectors, the polygon of the books, "
           "its sides resolved along the reference line (cos θ) and across it (sin θ)")
    if rods:
        why += "; a rod along the radius counts at its centre of mass, r + L/2"
    return Step("The masses as vectors m·r, resolved (the table)", "Σ m·r = (Σ m r cos θ, Σ m r sin θ)", terms,
                _vec(total, "kg*m"), why)


def _couple_step(mass, rows, reference, couple, size, angle) -> Step:
    terms = "; ".join(f"{term(m.mass * m.centre, 'kg*m')} × {term(_arm(m, reference), 'm')} at {_signed(math.degrees(m.angle))}°" for m in mass)
    return Step(f"The couples m·r·l about the plane at {quantity_text(reference, 'm')}", "Σ m·r·l = (Σ m r l cos θ, Σ m r l sin θ)", terms,
                f"{_vec(couple, 'kg*m**2')}, |Σ m·r·l| = {quantity_text(size, 'kg*m**2')} at {_angle_text(angle)}",
                "a mass at l from the reference plane adds the moment m r ω² l about it: the couple polygon, each vector m·r·l drawn along its "
                "mass's radius (l negative: drawn the other way)")


def _closing(value: complex, sizes) -> tuple[float, float | None]:
    return _polar(-value, sizes)


def _one_plane(results, steps, notes, unbalance, rows, radii, couple_size, along) -> None:
    mr, angle = _closing(unbalance, [abs(r[0]) for r in rows])
    results.put("balance_mr", mr)
    results.put("balance_angle", angle)
    steps.append(Step("The balancing mass: the vector that closes the polygon", "m_b r_b = |Σ m·r|,  θ_b = θ(Σ m·r) + 180°",
                      f"√({_paren(unbalance.real, 'kg*m')}² + {_paren(unbalance.imag, 'kg*m')}²)", f"{quantity_text(mr, 'kg*m')} at {_angle_text(angle)}",
                      "the balancing mass's m·r is equal and opposite to the resultant, so the polygon closes and no force is left"))
    if angle is None:
        notes.append("the masses balance already (Σ m·r = 0): no balancing mass is needed, and it has no angle")
    if radii:
        results.put("balance_mass", mr / radii[0])
        steps.append(Step("Balancing mass at its radius", "m_b = m_b r_b / r_b", f"{quantity_text(mr, 'kg*m')} / {quantity_text(radii[0], 'm')}",
                          quantity_text(mr / radii[0], "kg"), "the product m·r is what balances: the mass follows from the radius it is put at"))
    if along and couple_size > 0:
        notes.append("one balancing mass balances the force only: the couple Σ m·r·l is left (give --plane twice to balance both)")


def _two_planes(results, steps, notes, unbalance, couple, rows, plane, radii) -> None:
    span = plane[1] - plane[0]
    in_b = -couple / span
    in_a = -unbalance - in_b
    sizes = [abs(r[0]) for r in rows]
    mr_b, angle_b = _polar(in_b, [abs(r[1]) / abs(span) for r in rows])
    mr_a, angle_a = _polar(in_a, [*sizes, abs(in_b)])
    steps.append(Step("Plane B: the vector that closes the couple polygon", "m_B r_B l_B = −Σ m·r·l  (l_B = B − A)",
                      f"−{_vec(couple, 'kg*m**2')} / {term(span, 'm')}", f"{quantity_text(mr_b, 'kg*m')} at {_angle_text(angle_b)}",
                      "about plane A the mass in A has no arm, so the mass in B alone closes the couple polygon"))
    steps.append(Step("Plane A: the vector that closes the force polygon", "m_A r_A = −(Σ m·r + m_B r_B)",
                      f"−({_vec(unbalance, 'kg*m')} + {_vec(in_b, 'kg*m')})",
                      f"{quantity_text(mr_a, 'kg*m')} at {_angle_text(angle_a)}",
                      "with B's mass the forces must still add to zero: A's mass closes the force polygon"))
    for key, value in (("balance_mr_A", mr_a), ("balance_angle_A", angle_a), ("balance_mr_B", mr_b), ("balance_angle_B", angle_b)):
        results.put(key, value)
    for name, size, angle in (("A", mr_a, angle_a), ("B", mr_b, angle_b)):
        if angle is None:
            notes.append(f"plane {name} needs no balancing mass (its m·r is 0): its angle is left out")
    if radii:
        r_a, r_b = radii[0], radii[-1]
        results.put("balance_mass_A", mr_a / r_a)
        results.put("balance_mass_B", mr_b / r_b)
        steps.append(Step("Balancing masses at their radii", "m_A = m_A r_A / r_A,  m_B = m_B r_B / r_B",
                          f"{quantity_text(mr_a, 'kg*m')} / {quantity_text(r_a, 'm')};  {quantity_text(mr_b, 'kg*m')} / {quantity_text(r_b, 'm')}",
                          f"{quantity_text(mr_a / r_a, 'kg')}, {quantity_text(mr_b / r_b, 'kg')}", "the product m·r is what balances"))


def _bearings(results, steps, notes, mass, speed, bearing, gravity) -> None:
    a, b = bearing
    span = b - a
    rows = [_row(m, a) for m in mass]
    unbalance, couple = _sum([r[0] for r in rows]), _sum([r[1] for r in rows])
    square = speed * speed
    on_b = (square * couple + gravity * unbalance) / span
    on_a = square * unbalance - on_b
    scale = square * math.fsum(abs(r[0]) for r in rows) * (1 + math.fsum(abs(r[1]) for r in rows) / max(abs(span), 1e-300)) + gravity * math.fsum(
        abs(r[0]) for r in rows) / abs(span)
    size_a, angle_a = _polar(on_a, [scale])
    size_b, angle_b = _polar(on_b, [scale])
    weights = " + g Σ m·r" if gravity else ""
    steps.append(Step("Loads on the bearings", f"F_B (b − a) = ω² Σ m·r·(l − a){weights},  F_A = ω² Σ m·r − F_B",
                      f"({term(square, 'rad**2/s**2')} × {_vec(couple, 'kg*m**2')}"
                      + (f" + {term(gravity, 'm/s**2')} × {_vec(unbalance, 'kg*m')}" if gravity else "") + f") / {term(span, 'm')}",
                      f"F_A = {quantity_text(size_a, 'N')} at {_angle_text(angle_a)}, F_B = {quantity_text(size_b, 'N')} at {_angle_text(angle_b)}",
                      "the shaft presses on its bearings with the masses' centrifugal forces, shared so that their moments balance about either bearing"
                      + ("; on a vertical shaft each weight m g at radius r adds the moment m g r, turning with the shaft" if gravity else "")))
    results.put("bearing_force_A", size_a, f" at {quantity_text(a, 'm')}")
    results.put("bearing_angle_A", angle_a)
    results.put("bearing_force_B", size_b, f" at {quantity_text(b, 'm')}")
    results.put("bearing_angle_B", angle_b)
    if not gravity:
        notes.append("bearing loads from the turning masses alone: a horizontal shaft's weights add a steady load that does not turn (--vertical for a vertical shaft)")
    for name, angle in (("A", angle_a), ("B", angle_b)):
        if angle is None:
            notes.append(f"bearing {name} carries no load at this speed: its angle is left out")
