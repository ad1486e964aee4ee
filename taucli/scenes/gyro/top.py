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

from taucli.errors import InputError
from taucli.options.gyro import COMMAND as TABLE
from taucli.report import DeferredSteps, Report, Step, fmt, quantity_text, term
from taucli.scenes.assumed import Assumed
from taucli.table import Results
from taucli.scenes.inertia import body
from taucli.scenes.shapes import SHAPES

TWO_PI = 2.0 * math.pi
HALF_PI = 0.5 * math.pi
TILT_SLACK = 4.5e-16  # two ulps of π/2: "90deg" and "0.25rev" read as the float nearest π/2, or next to it
APPROXIMATION_NOTED = 1e-3  # the approximation's relative error is noted above this


def tilt_cos_sin(theta: float) -> tuple[float, float]:
    """cos θ and sin θ, exact at 0, 90 and 180 degrees (a float near π/2 has cos 6e-17, not 0:
    that would turn "one root at 90°" into a fast root of 1e16)."""
    if abs(theta - HALF_PI) <= TILT_SLACK:
        return 0.0, 1.0
    if abs(theta - math.pi) <= 2 * TILT_SLACK:
        return -1.0, 0.0
    if theta == 0:
        return 1.0, 0.0
    return math.cos(theta), math.sin(theta)


def discriminant_ratio(a: float, c: float, b: float) -> float:
    """ρ = 4ac/b², from mantissas and exponents: b² and ac are never formed, so nothing
    overflows or underflows on the way to a ρ that is in range (±inf and 0 where ρ is not)."""
    if a == 0 or c == 0:
        return 0.0
    ma, ea = math.frexp(a)
    mc, ec = math.frexp(c)
    mb, eb = math.frexp(b)
    try:
        return math.ldexp(4.0 * ma * mc / (mb * mb), ea + ec - 2 * eb)
    except OverflowError:
        return math.copysign(math.inf, a * c)


def precession_roots(inertia_perp_cos: float, angular_momentum: float, weight_torque: float) -> tuple[float, float | None] | None:
    """The roots (slow, fast) of I⊥cosθ·Ω² − LΩ + mgr = 0 for L > 0 and mgr ≥ 0; fast is None
    where the equation is linear (cos θ = 0) or the root is out of range; None where no real
    root exists (ρ > 1: no steady precession)."""
    rho = discriminant_ratio(inertia_perp_cos, weight_torque, angular_momentum)
    if rho > 1:
        return None
    s = math.sqrt(1.0 - rho)
    slow = (weight_torque / angular_momentum) * (2.0 / (1.0 + s))
    if inertia_perp_cos == 0:
        return slow, None
    fast = angular_momentum * (1.0 + s) / (2.0 * inertia_perp_cos)
    return slow, fast if math.isfinite(fast) else None


def approximation_error(inertia_perp_cos: float, angular_momentum: float, weight_torque: float) -> float:
    """mgr/(Iω_s) over the slow root, less 1: (s − 1)/2 = −ρ/(2(1 + s)), free of cancellation.
    It equals −I⊥Ω_slow cos θ/(Iω_s), the share of the term the approximation leaves out."""
    rho = discriminant_ratio(inertia_perp_cos, weight_torque, angular_momentum)
    return -rho / (2.0 * (1.0 + math.sqrt(1.0 - rho)))


def least_spin(inertia: float, inertia_perp_cos: float, weight_torque: float) -> float:
    """ω_min = √(4·I⊥·mgr·cos θ)/I (cos θ > 0), as a product of square roots (no overflow)."""
    return 2.0 * math.sqrt(inertia_perp_cos) * math.sqrt(weight_torque) / inertia


def _finite(x: float | None) -> float | None:
    return x if x is not None and math.isfinite(x) else None


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


def gyro(
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
    spin: float | None = None,
    cm_distance: float | None = None,
    torque: float | None = None,
    tilt: float | None = None,
    inertia_perp: float | None = None,
    g: float | None = None,
) -> Report:
    """``taucli gyro``: the body (--inertia or --shape ...), its --spin, and the torque on it:
    the weight (--mass at --cm-distance, with --g) or --torque; the axis at --tilt (default
    90°, horizontal) from the upward vertical."""
    dims = {"radius": radius, "inner_radius": inner_radius, "outer_radius": outer_radius, "length": length, "width": width, "height": height, "depth": depth}
    if part and shape is None:
        raise InputError("part", "goes with {shape}: the parts are added to the shape's body", example='{shape} disc {mass} 1kg {radius} 5cm {part} "ring mass=100g radius=5cm"')
    moment, body_steps = body(inertia=inertia, shape=shape, mass=mass if shape is not None else None, axis=axis, offset=offset, part=part, **dims)
    if spin is None:
        raise InputError("spin", "is required: the spin about the body's axis", example="{spin} 4000rpm")
    theta = HALF_PI if tilt is None else tilt
    if not 0 <= theta <= math.pi + 2 * TILT_SLACK:
        raise InputError("tilt", "expected an angle from 0 to 180 deg from the upward vertical", example="{tilt} 30deg", got=f"{fmt(math.degrees(theta))} deg")
    cos_t, sin_t = tilt_cos_sin(theta)
    body_mass = None
    if shape is not None:
        body_mass = mass + math.fsum(p.mass for p in part)
    elif mass is not None:
        body_mass = mass

    assumed = Assumed()
    notes: list[str] = []
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
        steps = DeferredSteps(_torque_steps, moment, spin, angular_momentum, torque, theta, sin_t, rate, period, body_steps)
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
        perp = _perp_from_shape(shape, mass, axis, dims, cm_distance, perp_steps, notes)
    if perp is not None and inertia_perp is not None:
        _check_perp(perp, moment, body_mass, cm_distance)
    if perp is None:
        notes.append(
            "omega_p only: the exact steady precession needs the moment of inertia about a perpendicular axis through the pivot "
            "({inertia_perp}, or a ring, disc, tube, sphere, shell or cone as {shape})"
        )
        period = _period(rate, notes)
        results.put("period_p", period, " 2π/Ω")
        steps = DeferredSteps(_steps, moment, spin, angular_momentum, body_mass, gravity, cm_distance, theta, sin_t, cos_t, rate, None, None, None, period, body_steps, perp_steps)
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
    steps = DeferredSteps(
        _steps, moment, spin, angular_momentum, body_mass, gravity, cm_distance, theta, sin_t, cos_t, rate, perp, roots, minimum, period, body_steps, perp_steps
    )
    where = "above" if cos_t > 0 else "level with" if cos_t == 0 else "below"
    model = f"heavy symmetric top in steady precession, centre of mass {where} the pivot: the exact rates beside Ω = mgr/(Iω_s)"
    return assumed.applied(Report("gyro", model, "closed form", results, steps, notes))


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


def _degrees(theta: float) -> str:
    return f"{fmt(math.degrees(theta))}°"


def _common_steps(moment, spin, angular_momentum, body_steps) -> list[Step]:
    steps = list(body_steps)
    steps.append(
        Step(
            "Spin angular momentum",
            "L = Iω_s",
            f"{quantity_text(moment, 'kg*m**2')} × {quantity_text(spin, 'rad/s')}",
            quantity_text(angular_momentum, "kg*m**2/s"),
            "the body spins about its symmetry axis, so L points along that axis",
        )
    )
    return steps


def _turning_steps(angular_momentum, theta, sin_t, about: str = "the vertical") -> list[Step]:
    level = sin_t == 1.0
    across = "horizontal and at right angles to L" if about == "the vertical" else f"at right angles to L and to {about}"
    return [
        Step(
            "The torque changes L's direction, not its size",
            "τ = dL/dt",
            "",
            "",
            f"the torque is {across}, so in dt it adds dL = τ dt across L: "
            "L swings round without changing its size, and the axis follows it instead of falling",
        ),
        Step(
            "How far L turns",
            "|dL| = L dφ" if level else "|dL| = L sin θ dφ",
            "" if level else f"{quantity_text(angular_momentum, 'kg*m**2/s')} × sin {_degrees(theta)} × dφ",
            "" if level else f"{quantity_text(angular_momentum * sin_t, 'kg*m**2/s')} × dφ",
            f"the part of L across {about} (all of it at 90°) turns through dφ about {about}; the arc it sweeps is its length times dφ",
        ),
    ]


def _torque_steps(moment, spin, angular_momentum, torque, theta, sin_t, rate, period, body_steps) -> list[Step]:
    steps = _common_steps(moment, spin, angular_momentum, body_steps)
    steps.append(
        Step(
            "The torque on the body (given)",
            f"τ = {quantity_text(torque, 'N*m')}",
            "",
            "",
            "the Sun's and Moon's pull on the Earth's equatorial bulge, or any torque across the spin axis, turning it about the axis it precesses round",
        )
    )
    steps += _turning_steps(angular_momentum, theta, sin_t, "the axis it precesses round")
    steps.append(
        Step(
            "Precession rate",
            "Ω = dφ/dt = τ/(L sin θ)",
            f"{quantity_text(torque, 'N*m')} / ({quantity_text(angular_momentum, 'kg*m**2/s')} × sin {_degrees(theta)})",
            "out of range" if rate is None else quantity_text(rate, "rad/s"),
            "divide |dL| = τ dt by L sin θ dt",
        )
    )
    if period is not None:
        steps.append(Step("Precession period", "T = 2π/Ω", f"2π / {quantity_text(rate, 'rad/s')}", _period_text(period), "one full turn of the spin axis round its cone"))
    return steps


def _period_text(period: float) -> str:
    text = quantity_text(period, "s")
    year = 365.25 * 86400.0
    if period >= 10 * year:
        text += f" ({fmt(period / year)} years)"
    return text


def _steps(moment, spin, angular_momentum, mass, g, r, theta, sin_t, cos_t, rate, perp, roots, minimum, period, body_steps, perp_steps) -> list[Step]:
    steps = _common_steps(moment, spin, angular_momentum, body_steps)
    weight_torque = mass * g * r
    steps.append(
        Step(
            "Torque of the weight about the pivot",
            "τ = mgr sin θ",
            f"{quantity_text(mass, 'kg')} × {quantity_text(g, 'm/s**2')} × {quantity_text(r, 'm')}" + ("" if sin_t == 1.0 else f" × sin {_degrees(theta)}"),
            quantity_text(weight_torque * sin_t, "N*m"),
            "the weight acts at the centre of mass, r along the axis from the pivot; its lever arm is r sin θ",
        )
    )
    steps += _turning_steps(angular_momentum, theta, sin_t)
    steps.append(
        Step(
            "Precession rate (gyroscopic approximation)",
            "Ω = τ/(L sin θ) = mgr/(Iω_s)",
            f"{quantity_text(weight_torque, 'N*m')} / {quantity_text(angular_momentum, 'kg*m**2/s')}",
            "out of range" if rate is None else quantity_text(rate, "rad/s"),
            "sin θ cancels: the rate is the same at every tilt; this takes L to be the spin's alone",
        )
    )
    if perp is None:
        if period is not None:
            steps.append(Step("Precession period", "T = 2π/Ω", f"2π / {quantity_text(rate, 'rad/s')}", _period_text(period), "one full turn of the axis about the vertical"))
        return steps
    for write in perp_steps:
        steps += write()
    a = perp * cos_t
    steps.append(
        Step(
            "The exact steady precession",
            "mgr = Ω(Iω_s − I⊥Ω cos θ)",
            f"Ω({term(angular_momentum, 'kg*m**2/s')} − {term(a, 'kg*m**2')} × Ω)",
            quantity_text(weight_torque, "N*m"),
            "the precession turns the body too, adding I⊥Ω sin θ across the axis to L; the horizontal part of L is then "
            "(Iω_s − I⊥Ω cos θ) sin θ, and turning it at Ω takes τ = mgr sin θ: a quadratic, I⊥Ω²cos θ − Iω_sΩ + mgr = 0"
            + ("; at 90° cos θ = 0 and its one root is mgr/(Iω_s) exactly" if cos_t == 0 else ""),
        )
    )
    if roots is None:
        steps.append(
            Step(
                "No real root: the spin is too slow",
                "ω_min = √(4·I⊥·mgr·cos θ)/I",
                f"√(4 × {term(perp, 'kg*m**2')} × {term(weight_torque, 'N*m')} × {term(cos_t)}) / {term(moment, 'kg*m**2')}",
                quantity_text(minimum, "rad/s"),
                f"the discriminant (Iω_s)² − 4I⊥ cos θ·mgr is negative below ω_min; at ω_s = {fmt(spin)} rad/s no steady precession exists",
            )
        )
        return steps
    slow, fast = roots
    if cos_t == 0:
        if period is not None:
            steps.append(Step("Precession period", "T = 2π/Ω", f"2π / {quantity_text(slow, 'rad/s')}", _period_text(period), "one full turn of the axis about the vertical"))
        return steps
    root_d = angular_momentum * math.sqrt(1.0 - discriminant_ratio(a, weight_torque, angular_momentum))
    steps.append(
        Step(
            "The slow root, written without cancellation",
            "Ω_slow = 2mgr / (Iω_s + √D),  D = (Iω_s)² − 4I⊥ cos θ·mgr",
            f"2 × {term(weight_torque, 'N*m')} / ({term(angular_momentum, 'kg*m**2/s')} + {term(root_d, 'kg*m**2/s')})",
            quantity_text(slow, "rad/s"),
            "the usual (Iω_s − √D)/(2I⊥ cos θ) subtracts two nearly equal numbers when the spin is fast; this form adds them",
        )
    )
    if fast is not None:
        steps.append(
            Step(
                "The fast root",
                "Ω_fast = (Iω_s + √D) / (2I⊥ cos θ)",
                f"({term(angular_momentum, 'kg*m**2/s')} + {term(root_d, 'kg*m**2/s')}) / (2 × {term(a, 'kg*m**2')})",
                quantity_text(fast, "rad/s"),
                "the other steady motion: a precession so fast that I⊥Ω²cos θ carries the torque almost alone, "
                "Ω ≈ Iω_s/(I⊥ cos θ); a top seldom settles into it"
                if cos_t > 0
                else "negative: below the pivot the second steady motion goes round the other way",
            )
        )
    neglected = a * slow / angular_momentum
    steps.append(
        Step(
            "Why the approximation holds",
            "ε = I⊥Ω_slow cos θ / (Iω_s)",
            f"{term(a * slow, 'kg*m**2/s')} / {term(angular_momentum, 'kg*m**2/s')}",
            fmt(neglected),
            "in mgr = Ω(Iω_s − I⊥Ω cos θ), where Iω_s ≫ I⊥Ω cos θ (ε ≪ 1) the second term drops out and Ω ≈ mgr/(Iω_s); "
            "mgr/(Iω_s) = Ω_slow(1 − ε) exactly",
        )
    )
    if period is not None:
        steps.append(Step("Precession period", "T = 2π/Ω_slow", f"2π / {quantity_text(slow, 'rad/s')}", _period_text(period), "one full turn of the axis about the vertical"))
    return steps
