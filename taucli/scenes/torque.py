"""Torque and angular momentum as vectors about a point: τ = r × F, L = r × p = m (r × v).

A force is given as a vector F acting at r (measured from the point), or in the plane as a size
F at a lever of length r, at an angle θ from the lever to the force (counter-clockwise positive):
τ_z = r F sin θ. A particle of mass m at r moving with velocity v has L = r × mv. Several forces
give the net torque Σ rᵢ × Fᵢ; several particles the total angular momentum.

Each component of a cross product is a difference of two products, a·b − c·d, which cancels
when r is nearly along F; it is formed with the exact error of each product (Dekker's
two-product), so that it keeps full precision where the two nearly cancel.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError, Unused
from taucli.options.torque import COMMAND as TABLE
from taucli.writing.report import Report, Step, Table, fmt, pretty_unit, quantity_text, term
from taucli.scenes.angles import sin_exact
from taucli.options.table import Results

Vector = tuple[float, float, float]
_SPLIT = 134217729.0  # 2**27 + 1: Veltkamp's splitter for doubles
_EXAMPLE_FORCE = '{r} "0.3,0.4,0 m" {force} "0,0,10 N"'


def _two_product(a: float, b: float) -> tuple[float, float]:
    """a·b as p + e exactly (Dekker): p the rounded product, e its rounding error."""
    p = a * b
    if not math.isfinite(p) or abs(a) > 1e150 or abs(b) > 1e150:
        return p, 0.0
    ca, cb = _SPLIT * a, _SPLIT * b
    a_hi, b_hi = ca - (ca - a), cb - (cb - b)
    a_lo, b_lo = a - a_hi, b - b_hi
    return p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo


def difference_of_products(a: float, b: float, c: float, d: float) -> float:
    """a·b − c·d to within a few ulp of its own size, even where the two products nearly cancel."""
    p, ep = _two_product(a, b)
    q, eq = _two_product(c, d)
    return (p - q) + (ep - eq)


def cross(u: Sequence[float], v: Sequence[float]) -> Vector:
    """u × v, each component a difference of products kept accurate where it cancels."""
    return (
        difference_of_products(u[1], v[2], u[2], v[1]),
        difference_of_products(u[2], v[0], u[0], v[2]),
        difference_of_products(u[0], v[1], u[1], v[0]),
    )


def size(v: Sequence[float]) -> float:
    """|v|, without overflow or underflow in the squares."""
    return math.hypot(*v)


def sense(v: Vector) -> str:
    """The sense of a rotation vector in words: counter-clockwise seen from the tip of the vector."""
    if not any(v):
        return "none (zero)"
    if v[0] == 0 and v[1] == 0:
        return ("counter-clockwise" if v[2] > 0 else "clockwise") + " seen from +z"
    length = size(v)
    along = ", ".join(fmt(c / length, 3) for c in v)
    words = f"counter-clockwise about ({along})"
    if v[2]:
        words += f"; about z, {'counter-clockwise' if v[2] > 0 else 'clockwise'} seen from +z"
    return words


def _vec(v: Sequence[float]) -> str:
    return "(" + ", ".join(fmt(c) for c in v) + ")"


def _determinant_step(title: str, name: str, row1: Vector, row2: Vector, result: Vector, unit: str, why: str, mass: float | None = None,
                      letter: str | None = None) -> Step:
    """r × B as the determinant |x̂ ŷ ẑ; r; B| expanded along its first row (times m for L from a
    velocity; ``letter`` "p" for L from a momentum)."""
    a, b = [term(c) for c in row1], [term(c) for c in row2]
    if letter is None:
        letter, row_unit = ("v", "m/s") if mass is not None else ("F", "N")
    else:
        row_unit = "kg·m/s"
    expanded = (f"x̂({a[1]}×{b[2]} − {a[2]}×{b[1]}) + ŷ({a[2]}×{b[0]} − {a[0]}×{b[2]}) "
                f"+ ẑ({a[0]}×{b[1]} − {a[1]}×{b[0]})")
    rows = f"|x̂ ŷ ẑ; {' '.join(a)} m; {' '.join(b)} {row_unit}|"
    product = pretty_unit("m**2/s" if mass is not None else "kg*m**2/s" if letter == "p" else "N*m")
    numbers = (f"{term(mass, 'kg')} × {rows} = {term(mass, 'kg')} × [{expanded}] {product}" if mass is not None
               else f"{rows} = [{expanded}] {product}")
    return Step(title, f"{name} = {'m ' if mass is not None else ''}|x̂ ŷ ẑ; rₓ r_y r_z; {letter}ₓ {letter}_y {letter}_z|", numbers, f"{_vec(result)} {unit}", why)


def _size_step(title: str, symbol: str, v: Vector, unit: str) -> Step:
    squares = " + ".join(f"({term(c, unit).strip('()')})²" for c in v)
    return Step(title, f"|{symbol}| = √({symbol}ₓ² + {symbol}_y² + {symbol}_z²)", f"√({squares})", quantity_text(size(v), unit), "the length of the vector")


def _pairs(r: tuple, vector_forces: list, velocities: tuple) -> tuple[list, list]:
    """The positions of the forces and of the particles, from the --r values in order."""
    n, f, p = len(r), len(vector_forces), len(velocities)
    if f and p and n == f == p:
        return list(r), list(r)
    if n == f + p:
        return list(r[:f]), list(r[f:])
    wanted = f"{f} for the forces given as vectors and {p} for the particles" if f and p else (f"{f} (one for each force given as a vector)" if f else f"{p} (one for each particle)")
    raise InputError("r", f"is given {n} times; it takes {wanted}", example=_EXAMPLE_FORCE)


def torque(
    *,
    r: tuple | None = None,
    force: tuple | None = None,
    lever: tuple | None = None,
    angle: tuple | None = None,
    mass: tuple | None = None,
    velocity: tuple | None = None,
    momentum: tuple | None = None,
    about: tuple | None = None,
    g: float | None = None,
) -> Report:
    """``taucli torque``: τ = r × F for each force and their sum; L = r × mv for each particle and
    their sum (or r × p for a momentum given); or τ = r F sin θ in the plane; about the origin, or
    about a point a given (--about), with r − a for each r. --g serves only to read a weight given for a mass."""
    if g is not None:
        raise Unused("g", "is used only to read a weight given for a mass", example="{mass} 10N {g} 9.8m/s^2")
    r, force, lever, angle, mass, velocity, momentum = (tuple(x or ()) for x in (r, force, lever, angle, mass, velocity, momentum))
    point = _about(about)
    if momentum:
        if velocity or mass:
            raise InputError("momentum", "conflicts with {velocity} and {mass}: a particle is given by its momentum, or by its mass and velocity",
                             example='{r} "2,0,0 m" {momentum} "0,12,0 kg*m/s"')
        for value in momentum:
            if not isinstance(value, tuple):
                raise InputError("momentum", "expected a vector x,y,z with a unit", example='{momentum} "0,12,0 kg*m/s"', got=fmt(value))
    if not force and not velocity and not momentum:
        if mass:
            raise InputError("velocity", "is required with {mass}: a particle is {r}, {mass} and {velocity}", example='{r} "2,0,0 m" {mass} 3kg {velocity} "0,4,0 m/s"')
        raise InputError("force", "or {velocity} is required: a torque needs a force, an angular momentum a particle", example=_EXAMPLE_FORCE)
    for name, values in (("r", r), ("velocity", velocity)):
        for value in values:
            if not isinstance(value, tuple):
                hint = "for a force in the plane, give its size with {lever} and {angle}" if name == "r" else None
                raise InputError(name, "expected a vector x,y,z with a unit", example='{r} "0.3,0.4,0 m"' if name == "r" else '{velocity} "0,4,0 m/s"', got=fmt(value), hint=hint)
    vector_forces = [f for f in force if isinstance(f, tuple)]
    planar_forces = [f for f in force if not isinstance(f, tuple)]
    if len(mass) != len(velocity):
        raise InputError("mass", f"is given {len(mass)} times and {{velocity}} {len(velocity)}: each particle takes one of each", example='{r} "2,0,0 m" {mass} 3kg {velocity} "0,4,0 m/s"')
    if planar_forces:
        if len(lever) != len(planar_forces):
            raise InputError("lever", f"is given {len(lever)} times for {len(planar_forces)} force(s) given as a size: one each", example="{force} 20N {lever} 0.5m {angle} 60deg")
        if angle and len(angle) != len(planar_forces):
            raise InputError("angle", f"is given {len(angle)} times for {len(planar_forces)} force(s) given as a size: one each, or none (90°)", example="{force} 20N {lever} 0.5m {angle} 60deg")
    elif lever or angle:
        raise InputError("lever" if lever else "angle", "goes with a force given as a size (a vector force takes {r})", example="{force} 20N {lever} 0.5m {angle} 60deg")
    if point is not None and planar_forces:
        raise InputError("about", "goes with forces given as vectors: a force given as a size in the plane has its own lever", example='{about} "1,0,0 m" {r} "3,0,0 m" {force} "0,10,0 N"')
    force_r, particle_r = _pairs(r, vector_forces, velocity or momentum)
    given_r = [*force_r, *particle_r]
    if point is not None:
        force_r, particle_r = [_from(where, point) for where in force_r], [_from(where, point) for where in particle_r]

    notes: list[str] = []
    steps: list[Step] = []
    results = Results(TABLE)
    tables: dict[str, Table] = {}
    if force:
        torques, arms, net_force = [], [], None
        for number, (where, f) in enumerate(zip(force_r, vector_forces), start=1):
            tau = cross(where, f)
            torques.append(tau)
            arm = size(tau) / size(f) if any(f) else None
            arms.append(arm)
            label = f" {number}" if len(force) > 1 else ""
            steps.append(_determinant_step(f"Torque of force{label}: the determinant", "τ = r × F", tuple(where), tuple(f), tau, "N·m",
                                           "the torque about the point is r × F, r from the point to where the force acts; "
                                           "the rows of the determinant are the unit vectors, r and F"))
            if arm is not None:
                steps.append(Step(f"Lever arm{label}", "r⊥ = |r × F| / |F| = |r| sin φ", f"{term(size(tau), 'N*m')} / {term(size(f), 'N')}", quantity_text(arm, "m"),
                                  "the lever arm is the distance from the point to the force's line of action (φ between r and F): "
                                  "only the force's part perpendicular to r turns"))
            net_force = tuple(math.fsum(c) for c in zip(net_force, f)) if net_force else tuple(f)
        angles = angle or (math.pi / 2,) * len(planar_forces)
        if planar_forces and not angle:
            notes.append("no {angle}: each force in the plane taken perpendicular to its lever (θ = 90°)")
        for number, (size_f, arm_length, theta) in enumerate(zip(planar_forces, lever, angles), start=len(vector_forces) + 1):
            sine = sin_exact(theta)
            tau_z = arm_length * size_f * sine
            torques.append((0.0, 0.0, tau_z))
            arms.append(arm_length * abs(sine) if size_f else None)
            label = f" {number}" if len(force) > 1 else ""
            steps.append(Step(f"Torque of force{label} in the plane", "τ = r F sin θ,  r⊥ = r |sin θ|",
                              f"{term(arm_length, 'm')} × {term(size_f, 'N')} × sin {fmt(math.degrees(theta))}°", f"{quantity_text(tau_z, 'N*m')}, r⊥ = {quantity_text(arm_length * abs(sine), 'm')}",
                              "only the force's part perpendicular to the lever turns; θ from the lever to the force, "
                              "counter-clockwise positive, so a positive τ turns counter-clockwise seen from +z"))
            if sine == 0 and size_f:
                notes.append(f"force{label} acts along its lever (θ = {fmt(math.degrees(theta))}°): its line passes through the axis, no torque")
        net = tuple(math.fsum(t[i] for t in torques) for i in range(3))
        several = len(force) > 1
        part = f" (net of {len(force)} forces)" if several else ""
        for key, value in zip(("tau_x", "tau_y", "tau_z"), net):
            results.put(key, value, part)
        results.put("tau", size(net), part)
        if vector_forces:
            steps.append(_size_step("Size of the net torque" if several else "Size of the torque", "τ", net, "N*m"))
        results.put("sense", sense(net))
        results.put("lever_arm", *_net_arm(net, net_force, arms, planar_forces, several, notes, steps))
        if several:
            steps.append(Step("The net torque", "τ_net = Σ rᵢ × Fᵢ", " + ".join(_vec(t) for t in torques), f"{_vec(net)} N·m",
                              "torques about the same point add as vectors"))
            columns = (("force", None, "force"), ("tau_x", "N*m", "τₓ"), ("tau_y", "N*m", "τ_y"), ("tau_z", "N*m", "τ_z"),
                       ("tau", "N*m", "|τ|"), ("lever_arm", "m", "r⊥"))
            tables["forces"] = Table(columns, tuple((n, *t, size(t), arm) for n, (t, arm) in enumerate(zip(torques, arms), start=1)))
    particles = velocity or momentum
    if particles:
        momenta = []
        for number, where in enumerate(particle_r, start=1):
            label = f" {number}" if len(particles) > 1 else ""
            if velocity:
                m, v = mass[number - 1], velocity[number - 1]
                spin = tuple(m * c for c in cross(where, v))
                steps.append(_determinant_step(f"Angular momentum of particle{label}: the determinant", "L = r × mv", tuple(where), tuple(v), spin,
                                               "kg·m²/s", "a particle's angular momentum about the point is r × p, p = mv: the rows are the unit vectors, "
                                               "r and v, times m", mass=m))
            else:
                spin = cross(where, momentum[number - 1])
                steps.append(_determinant_step(f"Angular momentum of particle{label}: the determinant", "L = r × p", tuple(where), tuple(momentum[number - 1]), spin,
                                               "kg·m²/s", "a particle's angular momentum about the point is r × p: the rows are the unit vectors, r and p", letter="p"))
            momenta.append(spin)
        total = tuple(math.fsum(p[i] for p in momenta) for i in range(3))
        part = f" (total of {len(particles)} particles)" if len(particles) > 1 else ""
        for key, value in zip(("L_x", "L_y", "L_z"), total):
            results.put(key, value, part)
        results.put("L", size(total), part)
        steps.append(_size_step("Size of the total angular momentum" if len(particles) > 1 else "Size of the angular momentum", "L", total, "kg*m**2/s"))
        results.put("L_sense", sense(total))
        if len(particles) > 1:
            steps.append(Step("The total angular momentum", "L = Σ rᵢ × pᵢ", " + ".join(_vec(p) for p in momenta), f"{_vec(total)} kg·m²/s",
                              "angular momenta about the same point add as vectors"))
            columns = (("particle", None, "particle"), ("L_x", "kg*m**2/s", "Lₓ"), ("L_y", "kg*m**2/s", "L_y"), ("L_z", "kg*m**2/s", "L_z"),
                       ("L", "kg*m**2/s", "|L|"))
            tables["particles"] = Table(columns, tuple((n, *p, size(p)) for n, p in enumerate(momenta, start=1)))
    what = [w for w, given in (("τ = r × F", vector_forces), ("τ = r F sin θ in the plane", planar_forces), ("L = r × mv", velocity),
                               ("L = r × p", momentum)) if given]
    if point is not None:
        model = " and ".join(what) + f", about the point {_vec(point)} m"
        steps.insert(0, Step("Positions from the point", f"r' = r − a,  a = {_vec(point)} m", "; ".join(f"{_signed_vec(w)} − {_signed_vec(point)}" for w in given_r),
                             "; ".join(_vec(w) + " m" for w in [*force_r, *particle_r]),
                             "a torque or an angular momentum is about a point: each position is measured from it, r' = r − a "
                             "(a force through the point has no torque about it)"))
    else:
        model = " and ".join(what) + (", about the point r is measured from" if r else "")
    return Report("torque", model, "closed form", results, steps, notes, {}, tables)


def _about(about) -> Vector | None:
    """The point of --about, a vector (Python may give three SI numbers)."""
    if about is None:
        return None
    points = about if about and isinstance(about[0], tuple) else (about,)
    if len(points) != 1 or not isinstance(points[0], tuple) or len(points[0]) != 3:
        raise InputError("about", "expected one point x,y,z with a unit", example='{about} "1,0,0 m"')
    return points[0]


def _signed_vec(v: Sequence[float]) -> str:
    """(0, 0.5, −2): a vector in a numbers line, its minus signs true minus signs."""
    return "(" + ", ".join("−" + fmt(c)[1:] if fmt(c).startswith("-") else fmt(c) for c in v) + ")"


def _from(where: Vector, point: Vector) -> Vector:
    """r − a, the position from the point a."""
    return tuple(w - a for w, a in zip(where, point))


def _net_arm(net: Vector, net_force, arms: list, planar_forces: list, several: bool, notes: list[str], steps: list[Step]) -> tuple[float | None, str]:
    """The lever arm of one force, or of the resultant of several: the distance from the point
    to the line of action of their sum, |F × τ| / |F|² (the central axis, where τ has a part
    along F)."""
    if not several:
        if arms[0] is None:
            notes.append("lever_arm: the force is zero, so it has no line of action")
        return arms[0], ""
    if planar_forces:
        notes.append("lever_arm: forces given as sizes in the plane have no direction to add, so the resultant's lever arm is not known; "
                     "each force's is in the forces table")
        return None, " of the resultant"
    if not any(net_force):
        notes.append("lever_arm: the forces add to zero (a couple): the torque is the same about every point, and there is no single line of action")
        return None, " of the resultant"
    arm = size(cross(net_force, net)) / size(net_force) ** 2
    along = math.fsum(f * t for f, t in zip(net_force, net)) / size(net_force)
    if abs(along) > 1e-12 * size(net):
        notes.append(f"lever_arm: the net torque has a part along the resultant force ({fmt(along)} N·m): no single force gives it "
                     "(a wrench); lever_arm is the distance from the point to the line (the central axis) where the rest is the resultant's r × F")
    steps.append(Step("Lever arm of the resultant", "r⊥ = |F × τ| / |F|²,  F = Σ Fᵢ", f"F = {_vec(net_force)} N, τ = {_vec(net)} N·m",
                      quantity_text(arm, "m"), "the distance from the point to the line along which the sum of the forces gives the same torque"))
    return arm, " of the resultant"
