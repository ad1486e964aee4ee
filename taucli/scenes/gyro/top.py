"""A spinning top or gyroscope on a pivot: the precession of its axis.

The weight mg, its centre of mass r from the pivot along the spin axis, the axis at θ from the
upward vertical, makes a torque τ = mgr sin θ about the pivot, horizontal and perpendicular to
the axis. τ = dL/dt turns the spin angular momentum L = Iω_s without changing its size: its
horizontal part L sin θ swings round at Ω = τ/(L sin θ) = mgr/(Iω_s), the gyroscopic
approximation.

Exactly, the precession adds a part of its own to L (I⊥Ω sin θ across the axis, I⊥ about the
pivot), and steady precession at θ needs

    I⊥Ω² cos θ − Iω_sΩ + mgr = 0,

whose roots are the slow and the fast steady precession. With ρ = 4·I⊥ cos θ·mgr/(Iω_s)² and
s = √(1 − ρ) they are written here as

    Ω_slow = (mgr/(Iω_s)) · 2/(1 + s),     Ω_fast = Iω_s(1 + s)/(2 I⊥ cos θ),

the forms 2c/(−b ± √D) and (−b ± √D)/2a whose sums have no cancellation (s ≥ 0): the slow root
stays accurate to a few ulp however large Iω_s is, where the textbook (−b − √D)/2a would lose
every digit. ρ itself is formed from mantissas and exponents, so that neither (Iω_s)² nor the
product above it overflows. No steady precession exists where ρ > 1, that is below
ω_min = √(4·I⊥·mgr·cos θ)/I.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence

from taucli.core.errors import InputError
from taucli.options.gyro import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, fmt, quantity_text
from taucli.scenes.assumed import Assumed
from taucli.scenes.gyro.roots import APPROXIMATION_NOTED, HALF_PI, TILT_SLACK, TWO_PI, approximation_error, finite as _finite, least_spin, precession_roots, tilt_cos_sin
from taucli.scenes.gyro.steps import orbit_steps, top_steps, torque_steps
from taucli.scenes.inertia import body, body_mass as whole_mass
from taucli.scenes.shapes import SHAPES
from taucli.options.table import Results


# I about a perpendicular axis through the centre of mass, for the shapes that spin about an
# axis of symmetry (their central axis): the inertia table's diameter axis, or the cone's own.
def _perpendicular_centre(shape: str, mass: float, dims: Mapping[str, float]) -> tuple[float, str, Callable[[], str]] | None:
    """(I⊥ about the centre of mass, its equation, what writes its numbers), or None where the
    shape has none here. The numbers are written only when the steps are read."""
    def filled(template: str) -> Callable[[], str]:
        def numbers() -> str:
            lengths = {symbol: f"({quantity_text(dims.get(name, 0.0), 'm')})" for name, symbol in _SYMBOLS.items()}
            return template.format(M=quantity_text(mass, "kg"), **lengths)

        return numbers

    if shape in ("ring", "disc", "tube"):
        axis = SHAPES[shape].axis("diameter")
        return axis.moment(mass, **dims), axis.equation.replace("I =", "I⊥cm =", 1), filled(axis.numbers)
    if shape in ("sphere", "shell", "thick-shell"):
        axis = SHAPES[shape].axes[0]
        return axis.moment(mass, **dims), axis.equation.replace("I =", "I⊥cm =", 1) + " (every diameter alike)", filled(axis.numbers)
    if shape == "cone" and "height" in dims:
        radius, height = dims["radius"], dims["height"]
        moment = mass * (3 * radius**2 / 20 + 3 * height**2 / 80)
        return moment, "I⊥cm = M(3R²/20 + 3H²/80)", filled("{M} × (3{R}²/20 + 3{H}²/80)")
    return None


_SYMBOLS = {"radius": "R", "inner_radius": "R1", "outer_radius": "R2", "length": "L", "width": "W", "height": "H", "depth": "D"}


def top(
    *,
    inertia: float | None = None,
    shape: str | None = None,
    mass: float | None = None,
    radius: float | None = None,
    inner_radius: float | None = None,
    outer_radius: float | None = None,
    length: float | None = None,
    width: float | None = None,
    height: float | None = None,
    depth: float | None = None,
    axis: str | None = None,
    offset: float | None = None,
    part: Sequence = (),
    gyration: float | None = None,
    density=None,
    spin: float | None = None,
    cm_distance: float | None = None,
    torque: float | None = None,
    tilt: float | None = None,
    inertia_perp: float | None = None,
    g: float | None = None,
) -> Report:
    """A top or gyroscope on a pivot: the body (--inertia or --shape ...), its --spin, and the torque on it:
    the weight (--mass at --cm-distance, with --g) or --torque; the axis at --tilt (default
    90°, horizontal) from the upward vertical."""
    dims = {"radius": radius, "inner_radius": inner_radius, "outer_radius": outer_radius, "length": length, "width": width, "height": height, "depth": depth}
    if part and shape is None:
        raise InputError("part", "goes with {shape}: the parts are added to the shape's body", example='{shape} disc {mass} 1kg {radius} 5cm {part} "ring mass=100g radius=5cm"')
    own_mass = shape is not None or gyration is not None  # --mass is the body's, not only the weight's
    body_notes: list[str] = []
    moment, body_steps = body(inertia=inertia, shape=shape, mass=mass if own_mass else None, axis=axis, offset=offset, part=part,
                              gyration=gyration, density=density, notes=body_notes, **dims)
    if spin is None:
        raise InputError("spin", "is required: the spin about the body's axis", example="{spin} 4000rpm")
    theta = HALF_PI if tilt is None else tilt
    if not 0 <= theta <= math.pi + 2 * TILT_SLACK:
        raise InputError("tilt", "expected an angle from 0 to 180 deg from the upward vertical", example="{tilt} 30deg", got=f"{fmt(math.degrees(theta))} deg")
    cos_t, sin_t = tilt_cos_sin(theta)
    body_mass = None
    if own_mass:  # the shape's (by --mass or --density) and its parts'
        body_mass = whole_mass(shape=shape, mass=mass, axis=axis, offset=offset, part=part, gyration=gyration, density=density, **dims)
    elif mass is not None:
        body_mass = mass

    assumed = Assumed()
    notes: list[str] = [*body_notes]
    results = Results(TABLE)
    angular_momentum = moment * spin
    results.put("L", _finite(angular_momentum))
    if angular_momentum == 0 or not math.isfinite(angular_momentum):
        raise InputError("spin", "gives no usable angular momentum Iω_s with this body (out of range)", got=f"I = {fmt(moment)} kg·m², ω_s = {fmt(spin)} rad/s")

    if torque is not None:
        for name, value in (("cm_distance", cm_distance), ("inertia_perp", inertia_perp)):
            if value is not None:
                raise InputError(name, "conflicts with {torque}: with the torque given, only the gyroscopic rate Ω = τ/(L sin θ) is formed")
        if shape is None and mass is not None:
            raise InputError("mass", "goes with {cm_distance} (the weight's torque) or {shape}; with {torque} and {inertia} it is not used")
        if g is not None:
            notes.append("g plays no part: the torque is given")
        if sin_t == 0:
            raise InputError("tilt", "must be between 0 and 180 deg with {torque}: along the axis it precesses round, L has no part across it to turn (Ω = τ/(L sin θ))", example="{tilt} 23.44deg")
        rate = _finite(torque / (angular_momentum * sin_t))
        results.put("omega_p", rate, " τ/(L sin θ)")
        period = _period(rate, notes)
        results.put("period_p", period, " 2π/Ω")
        steps = DeferredSteps(torque_steps, moment, spin, angular_momentum, torque, theta, sin_t, rate, period, body_steps)
        model = "steady precession under a given torque: Ω = τ/(L sin θ) (gyroscopic approximation)"
        return assumed.applied(Report("gyro", model, "closed form", results, steps, notes))

    if cm_distance is None:
        raise InputError("cm_distance", "is required (or {torque}): the distance from the pivot to the centre of mass", example="{cm_distance} 5cm")
    if body_mass is None:
        raise InputError("mass", "is required with {cm_distance}: the weight mg makes the torque", example="{mass} 0.3kg")
    gravity = assumed.gravity(g)
    weight_torque = body_mass * gravity * cm_distance  # mgr; the torque is mgr sin θ
    rate = _finite(weight_torque / angular_momentum)
    results.put("omega_p", rate, " mgr/(Iω_s)")

    perp_steps: list[Callable[[], list[Step]]] = []
    perp = inertia_perp
    if perp is None and shape is not None and not part and offset is None:
        perp = _perp_from_shape(shape, body_mass, axis, dims, cm_distance, perp_steps, notes)
    if perp is not None and inertia_perp is not None:
        _check_perp(perp, moment, body_mass, cm_distance)
    if perp is None:
        notes.append(
            "omega_p only: the exact steady precession needs the moment of inertia about a perpendicular axis through the pivot "
            "({inertia_perp}, or a ring, disc, tube, sphere, shell or cone as {shape})"
        )
        period = _period(rate, notes)
        results.put("period_p", period, " 2π/Ω")
        orbit = _orbit(results, body_mass, gravity, cm_distance, sin_t, rate, "Ω", notes)
        steps = DeferredSteps(_with_orbit, (moment, spin, angular_momentum, body_mass, gravity, cm_distance, theta, sin_t, cos_t, rate, None, None, None, period, body_steps, perp_steps), orbit)
        model = "gyroscopic approximation Ω = mgr/(Iω_s) (no I⊥: exact rates not formed)"
        return assumed.applied(Report("gyro", model, "closed form", results, steps, notes))

    if sin_t == 0:
        notes.append(
            "the axis is vertical: the weight has no lever arm and the axis stays put; the rates given are the limit of a "
            "steady precession round a narrow cone" + (", and spin_min is the sleeping top's stability limit" if cos_t > 0 else "")
        )
    a = perp * cos_t
    roots = precession_roots(a, angular_momentum, weight_torque)
    slow = fast = minimum = None
    if cos_t > 0:
        minimum = least_spin(moment, a, weight_torque)
    if roots is None:
        notes.append(
            f"no steady precession at this tilt: the spin is below ω_min = {fmt(minimum)} rad/s ({fmt(minimum / TWO_PI * 60)} rpm), "
            "where the roots of I⊥Ω²cos θ − Iω_sΩ + mgr = 0 stop being real; the top nutates widely or falls. "
            "omega_p is only the formula's value"
        )
        period = None
    else:
        slow, fast = roots
        if cos_t == 0:
            notes.append("at 90° the equation is linear: its one root is the approximation, exactly; omega_p_fast does not exist")
        elif fast is None:
            notes.append("omega_p_fast: out of range (I⊥ cos θ too small beside Iω_s)")
        elif cos_t < 0:
            notes.append("below the pivot (tilt over 90°): the fast root is negative, a precession the other way round")
        error = approximation_error(a, angular_momentum, weight_torque)
        if abs(error) > APPROXIMATION_NOTED:
            notes.append(
                f"the approximation mgr/(Iω_s) is {fmt(abs(error) * 100, 3)}% {'below' if error < 0 else 'above'} the exact slow rate: "
                "I⊥Ω cos θ is not small beside Iω_s"
            )
        period = _period(slow, notes)
    results.put("period_p", period, " 2π/Ω_slow" if roots is not None else " 2π/Ω")
    results.put("omega_p_slow", _finite(slow))
    results.put("omega_p_fast", _finite(fast))
    if minimum is not None:
        results.put("spin_min", _finite(minimum))
    orbit = _orbit(results, body_mass, gravity, cm_distance, sin_t, slow, "Ω_slow", notes)
    steps = DeferredSteps(
        _with_orbit, (moment, spin, angular_momentum, body_mass, gravity, cm_distance, theta, sin_t, cos_t, rate, perp, roots, minimum, period, body_steps, perp_steps), orbit
    )
    where = "above" if cos_t > 0 else "level with" if cos_t == 0 else "below"
    model = f"heavy symmetric top in steady precession, centre of mass {where} the pivot: the exact rates beside Ω = mgr/(Iω_s)"
    return assumed.applied(Report("gyro", model, "closed form", results, steps, notes))


def _orbit(results: Results, mass: float, g: float, r: float, sin_t: float, rate: float | None, symbol: str, notes: list[str]) -> tuple | None:
    """The centre of mass's orbit in steady precession at ``rate``: it goes round a horizontal
    circle of radius r sin θ, so its angular momentum about the pivot is m(r sin θ)Ω·r (r ⊥ v),
    and the pivot pushes up with mg (the height is steady) and in with mΩ²r sin θ (the
    centripetal force). Returns what the steps need, or None where there is no steady rate."""
    if rate is None:
        for key in ("L_orbital", "pivot_force_horizontal"):
            results.put(key, None)
        results.put("pivot_force_vertical", None)
        notes.append("L_orbital, pivot_force_vertical, pivot_force_horizontal: no steady precession, so no steady orbit of the centre of mass")
        return None
    circle = r * sin_t
    orbital = _finite(mass * r * circle * abs(rate))
    inward = _finite(mass * rate * rate * circle)
    results.put("L_orbital", orbital, f", m r²{symbol} sin θ")
    results.put("pivot_force_vertical", _finite(mass * g))
    results.put("pivot_force_horizontal", inward, f", m{symbol}²r sin θ")
    return mass, g, r, circle, rate, symbol, orbital, inward


def _with_orbit(top_args: tuple, orbit: tuple | None) -> list[Step]:
    return top_steps(*top_args) + (orbit_steps(*orbit) if orbit is not None else [])


def _period(rate: float | None, notes: list[str]) -> float | None:
    if rate is None:
        return None
    if rate == 0:
        notes.append("no torque: the axis keeps its direction, and there is no precession period")
        return None
    return _finite(TWO_PI / abs(rate))


def _perp_from_shape(shape: str, mass: float, axis: str | None, dims: Mapping[str, float | None], r: float, steps: list, notes: list[str]) -> float | None:
    """I⊥ about the pivot from the shape: I⊥cm about a diameter, plus mr² (parallel axes);
    ``steps`` gets what writes its steps, called when the steps are read."""
    found = SHAPES[shape]
    if axis is not None and axis != found.axes[0].name:
        notes.append(f"the spin axis is not the {found.title}'s symmetry axis, so I⊥ is not taken from the shape")
        return None
    given = {name: value for name, value in dims.items() if value is not None}
    centre = _perpendicular_centre(shape, mass, given)
    if centre is None:
        if shape == "cone":
            notes.append("a cone's I⊥ needs its {height}")
        return None
    moment, equation, numbers = centre
    if shape in ("disc", "tube") and "length" not in given:
        notes.append(f"the {found.title} taken as thin for I⊥ (¼MR² about a diameter); {{length}} gives its thickness")
    perp = moment + mass * r * r

    def write() -> list[Step]:
        return [
            Step(
                "Moment of inertia about a diameter through the centre of mass",
                equation,
                numbers(),
                quantity_text(moment, "kg*m**2"),
                "the precession turns the body about an axis across its spin axis; a thin disc's is ¼MR² (perpendicular axes: ½MR² = 2 × ¼MR²)"
                if shape == "disc"
                else "the precession turns the body about an axis across its spin axis",
            ),
            Step(
                "Shift to the pivot (parallel-axis theorem)",
                "I⊥ = I⊥cm + Mr²",
                f"{quantity_text(moment, 'kg*m**2')} + {quantity_text(mass, 'kg')} × ({quantity_text(r, 'm')})²",
                quantity_text(perp, "kg*m**2"),
                "the body turns about the pivot, r from its centre of mass",
            ),
        ]

    steps.append(write)
    return perp


def _check_perp(perp: float, moment: float, mass: float, r: float) -> None:
    """A rigid body symmetric about its spin axis has I⊥cm ≥ I/2 (perpendicular axes), so
    I⊥ about the pivot is at least I/2 + mr²."""
    least = moment / 2 + mass * r * r
    if perp < least * (1 - 1e-9):
        raise InputError(
            "inertia_perp",
            "is less than I/2 + mr², the least a body symmetric about its spin axis can have about a perpendicular axis through the pivot",
            got=f"{fmt(perp)} kg·m² < {fmt(least)} kg·m²",
        )
