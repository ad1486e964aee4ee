"""Angular impulse and angular momentum: J = ∫τ dt = ΔL, L = Iω.

Three cases:
- constant torque: τΔt = I(ω₁ − ω₀), any four of I, ω₀, ω₁, τ, Δt giving the fifth;
- inertia that changes with no external torque (the skater, the diver): I₀ω₀ = I₁ω₁;
- a torque that varies in time, sampled: J by quadrature, then ω₁ = ω₀ + J/I.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from taucli.errors import InputError
from taucli.numerics import StreamingQuadrature
from taucli.options.impulse import COMMAND as TABLE
from taucli.report import (
    Report,
    Step,
    Table,
    Trajectory,
    deferred,
    fmt,
    quantity_text,
    term,
)
from taucli.scenes.point import put_point, put_start, rim_radius
from taucli.scenes.angles import cos_exact
from taucli.scenes.assumed import Assumed
from taucli.scenes.given import Couple, Particle
from taucli.table import Results
from taucli.scenes.contact import contacts
from taucli.scenes.inertia import body, part_inertia
from taucli.scenes.motion import Evolver, Loads, Method, evolve

BRIEF_BLOW = 0.1  # s: a blow this short is remembered by its impulse alone
SAMPLES_SHOWN = 10_000  # ω at the samples is reported for profiles up to this many rows
PLOTTED = 500  # a profile's plot keeps between this many and twice as many of its samples
CURVES = (("torque", "N*m", "torque τ"), ("omega", "rad/s", "angular velocity ω"))  # what its plot shows
AGREEMENT = 1e-9  # relative: all five given must satisfy τΔt = IΔω this closely

SOLVED = " (solved for)"  # what a solved result's label adds
UNKNOWNS = ("inertia", "omega0", "omega1", "torque", "duration")


def _momentum_results(results: Results, inertia: float | None, omega0: float | None, omega1: float | None) -> None:
    """L and KE before and after, where the inertia and that speed are known."""
    known0 = inertia is not None and omega0 is not None
    known1 = inertia is not None and omega1 is not None
    results.put("L0", inertia * omega0 if known0 else None)
    results.put("L1", inertia * omega1 if known1 else None)
    results.put("KE0", 0.5 * inertia * omega0 * omega0 if known0 else None)
    results.put("KE1", 0.5 * inertia * omega1 * omega1 if known1 else None)


def solve_balance(
    inertia: float | None,
    omega0: float | None,
    omega1: float | None,
    torque: float | None,
    duration: float | None,
    *,
    inertia_steps: Sequence[Step] = (),
) -> Report:
    """τΔt = I(ω₁ − ω₀) with any four given: the fifth, J, Δω, L and KE before and after."""
    notes: list[str] = []
    if omega0 is None and omega1 is None and None not in (inertia, torque, duration):
        omega0 = 0.0  # as spin-down takes it: what the torque does to a body at rest
        notes.append("no --omega0: the body starts at rest (ω₀ = 0); give --omega0 for another start")
    given = {"inertia": inertia, "omega0": omega0, "omega1": omega1, "torque": torque, "duration": duration}
    missing = [name for name, value in given.items() if value is None]
    if len(missing) > 1:
        return _partial_balance(given, missing, notes, inertia_steps)
    unknown = missing[0] if missing else None
    i, w0, w1, tau, dt = inertia, omega0, omega1, torque, duration
    change = None  # Δω where it is known before ω₀ or ω₁ is rounded
    if unknown == "omega1":
        change = tau * dt / i
        w1 = w0 + change
    elif unknown == "omega0":
        change = tau * dt / i
        w0 = w1 - change
    elif unknown == "torque":
        tau = i * (w1 - w0) / dt
    elif unknown == "duration":
        if tau == 0:
            raise InputError("torque", "must not be zero when the duration is solved for: no torque, no change of ω")
        dt = i * (w1 - w0) / tau
        if dt <= 0:
            raise InputError("torque", "must act in the sense of the change ω₁ − ω₀ for a positive duration", got=f"τ = {fmt(tau)} N·m, Δω = {fmt(w1 - w0)} rad/s")
    elif unknown == "inertia":
        if w1 == w0:
            raise InputError("omega1", "must differ from {omega0} when the inertia is solved for")
        i = tau * dt / (w1 - w0)
        if i <= 0:
            raise InputError("torque", "must act in the sense of the change ω₁ − ω₀ for a positive inertia", got=f"τΔt = {fmt(tau * dt)} N·m·s, Δω = {fmt(w1 - w0)} rad/s")
    else:
        impulse, change = tau * dt, i * (w1 - w0)
        if abs(impulse - change) > AGREEMENT * max(abs(impulse), abs(i * w0), abs(i * w1), 1e-300):
            raise InputError("omega1",
                f"and the other four disagree: τΔt = {fmt(impulse, 6)} N·m·s but I(ω₁ − ω₀) = {fmt(change, 6)} N·m·s",
                hint="leave out the one to solve for",
            )
    impulse = tau * dt
    results = Results(TABLE)
    results.put("J", impulse, " τΔt")
    results.put("delta_omega", w1 - w0 if change is None else change)
    for name, value in (("inertia", i), ("omega0", w0), ("omega1", w1), ("torque", tau)):
        results.put(name, value, SOLVED if unknown == name else "")
    results.put("duration", dt, " the torque acts" + (SOLVED if unknown == "duration" else ""))
    _momentum_results(results, i, w0, w1)
    if dt <= BRIEF_BLOW:
        notes.append(f"a brief blow ({fmt(dt)} s): the motion remembers only the impulse J = τΔt, not how the torque was shaped within it")
    steps = list(inertia_steps)
    steps.append(
        Step(
            "Angular impulse equals the change of angular momentum",
            "J = τΔt = IΔω = I(ω₁ − ω₀)",
            "",
            "",
            "multiply τ = Iα by Δt: with the torque constant, αΔt = Δω",
        )
    )
    solved = {
        "omega1": ("ω₁ = ω₀ + τΔt/I", f"{term(w0, 'rad/s')} + {term(tau, 'N*m')} × {term(dt, 's')} / {term(i, 'kg*m**2')}", quantity_text(w1, "rad/s")),
        "omega0": ("ω₀ = ω₁ − τΔt/I", f"{term(w1, 'rad/s')} − {term(tau, 'N*m')} × {term(dt, 's')} / {term(i, 'kg*m**2')}", quantity_text(w0, "rad/s")),
        "torque": ("τ = I(ω₁ − ω₀)/Δt", f"{term(i, 'kg*m**2')} × ({term(w1, 'rad/s')} − {term(w0, 'rad/s')}) / {term(dt, 's')}", quantity_text(tau, "N*m")),
        "duration": ("Δt = I(ω₁ − ω₀)/τ", f"{term(i, 'kg*m**2')} × ({term(w1, 'rad/s')} − {term(w0, 'rad/s')}) / {term(tau, 'N*m')}", quantity_text(dt, "s")),
        "inertia": ("I = τΔt/(ω₁ − ω₀)", f"{term(tau, 'N*m')} × {term(dt, 's')} / ({term(w1, 'rad/s')} − {term(w0, 'rad/s')})", quantity_text(i, "kg*m**2")),
    }
    if unknown is not None:
        equation, numbers, result = solved[unknown]
        steps.append(Step(f"Solve for {unknown}", equation, numbers, result, "the one quantity not given"))
    steps.append(Step("The impulse", "J = τΔt", f"{term(tau, 'N*m')} × {term(dt, 's')}", quantity_text(impulse, "N*m*s"), "the same as the change of angular momentum ΔL = IΔω"))
    model = "constant torque: τΔt = IΔω" + (f", solved for {unknown}" if unknown else ", all five given and consistent")
    trajectory = deferred(Trajectory, CURVES, dt, lambda t: (tau, w0 + tau * t / i))
    return Report("impulse", model, "closed form", results, steps, notes, trajectory=trajectory)


def _partial_balance(given: dict[str, float | None], missing: list[str], notes: list[str], inertia_steps: Sequence[Step]) -> Report:
    """Two or more of I, ω₀, ω₁, τ, Δt left out: one equation, τΔt = I(ω₁ − ω₀), cannot fix them
    all, but J = τΔt (or I(ω₁ − ω₀)) and Δω = ω₁ − ω₀ may still be known. Those are given, the
    rest null with a note; refused where neither is known."""
    i, w0, w1, tau, dt = (given[name] for name in UNKNOWNS)
    impulse = tau * dt if tau is not None and dt is not None else None
    if impulse is None and None not in (i, w0, w1):
        impulse = i * (w1 - w0)
    change = None if w0 is None or w1 is None else w1 - w0
    if impulse is None and change is None:
        raise InputError(
            " and ".join("{" + name + "}" for name in missing),
            "are missing: give four of {inertia}, {omega0}, {omega1}, {torque}, {duration}, and the fifth is solved for",
            example="{inertia} 0.1kg*m^2 {omega0} 0 {torque} 2N*m {duration} 0.5s",
        )
    results = Results(TABLE)
    results.put("J", impulse, " τΔt")
    results.put("delta_omega", change)
    for name, value in (("inertia", i), ("omega0", w0), ("omega1", w1), ("torque", tau)):
        results.put(name, value)
    results.put("duration", dt, " the torque acts")
    _momentum_results(results, i, w0, w1)
    unfixed = [name for name, value in results.items() if value.value is None]
    notes.append(
        f"{', '.join(unfixed)}: not fixed by what is given: τΔt = I(ω₁ − ω₀) is one equation, and "
        f"{', '.join('{' + name + '}' for name in missing)} are all left out; give all but one of them to solve for it"
    )
    steps = [*inertia_steps, Step("Angular impulse equals the change of angular momentum", "J = τΔt = IΔω = I(ω₁ − ω₀)", "", "",
                                  "multiply τ = Iα by Δt: with the torque constant, αΔt = Δω")]
    if impulse is not None:
        by_torque = tau is not None and dt is not None
        steps.append(Step("The impulse", "J = τΔt" if by_torque else "J = I(ω₁ − ω₀)",
                          f"{term(tau, 'N*m')} × {term(dt, 's')}" if by_torque else f"{term(i, 'kg*m**2')} × ({term(w1, 'rad/s')} − {term(w0, 'rad/s')})", quantity_text(impulse, "N*m*s"),
                          "all the motion remembers of the torque"))
    if change is not None:
        steps.append(Step("The change of angular velocity", "Δω = ω₁ − ω₀", f"{term(w1, 'rad/s')} − {term(w0, 'rad/s')}", quantity_text(change, "rad/s"), "from the two given"))
    known = " and ".join(name for name, value in (("J", impulse), ("Δω", change)) if value is not None)
    return Report("impulse", f"constant torque: τΔt = IΔω, which fixes only {known} here", "closed form", results, steps, notes)


def solve_changing_inertia(inertia0: float, inertia1: float, omega0: float, *, inertia_steps: Sequence[Step] = ()) -> Report:
    """No external torque: L = Iω is conserved while I changes; kinetic energy is not."""
    omega1 = inertia0 * omega0 / inertia1
    momentum = inertia0 * omega0
    energy0 = 0.5 * inertia0 * omega0 * omega0
    energy1 = 0.5 * momentum * omega1  # ½ I₁ω₁² = ½ L ω₁
    results = Results(TABLE)
    results.put("omega1", omega1, " the change")
    results.put("delta_omega", omega1 - omega0)
    results.put("J", 0.0, ": no external torque")
    results.put("L0", momentum)
    results.put("L1", inertia1 * omega1, " (the same)")
    results.put("KE0", energy0)
    results.put("KE1", energy1)
    results.put("work", energy1 - energy0)
    steps = [
        *inertia_steps,
        Step("No external torque: angular momentum is conserved", "τ = dL/dt = 0  ⇒  I₀ω₀ = I₁ω₁", "", "",
             "τ = Iα does not hold while I changes; τ = d(Iω)/dt does, and with τ = 0, Iω stays constant"),
        Step("Angular velocity after", "ω₁ = I₀ω₀ / I₁", f"{term(inertia0, 'kg*m**2')} × {term(omega0, 'rad/s')} / {term(inertia1, 'kg*m**2')}", quantity_text(omega1, "rad/s"),
             "less inertia, faster spin: the skater pulling in her arms"),
        Step("Kinetic energy is not conserved", "KE = L²/(2I)  ⇒  KE₁/KE₀ = I₀/I₁",
             f"{term(energy0, 'J')} × {term(inertia0, 'kg*m**2')} / {term(inertia1, 'kg*m**2')}", quantity_text(energy1, "J"),
             "pulling mass inward against the outward pull of the spin takes work, done by the body's own muscles; "
             "spreading out gives it back"),
    ]
    model = "changing moment of inertia, no external torque: L conserved"
    return Report("impulse", model, "closed form", results, steps, [])


def solve_profile(
    inertia: float,
    omega0: float,
    samples: Iterable[tuple[float, float]],
    *,
    rule: str = "auto",
    inertia_steps: Sequence[Step] = (),
) -> Report:
    """A sampled torque τ(t): J by quadrature, ω at the samples, ω₁ = ω₀ + J/I, the peak torque."""
    if rule not in ("auto", *StreamingQuadrature.RULES):
        raise InputError("method", "expected auto, trapezoid or simpson for a torque profile", got=repr(rule))
    notes: list[str] = []
    quadrature = StreamingQuadrature()
    shown: list[tuple[float, float, float]] = []
    chosen = "simpson" if rule == "auto" else rule
    plotted: list[tuple[float, float, float]] = []  # every stride-th sample, so memory stays flat
    stride = 1
    start = None
    for t, torque in samples:
        if start is None:
            start = t
        quadrature.add(t, torque)
        if quadrature.count <= SAMPLES_SHOWN:
            shown.append((t, torque, omega0 + quadrature.result(chosen) / inertia))
        if (quadrature.count - 1) % stride == 0:
            plotted.append((t, torque, omega0 + quadrature.result(chosen) / inertia))
            if len(plotted) == 2 * PLOTTED:
                plotted, stride = plotted[::2], 2 * stride
    count = quadrature.count
    if count < 2:
        raise InputError("torque_profile", "needs at least two samples for an integral")
    if rule == "auto" and count < 3:
        chosen = "trapezoid"
    impulse = quadrature.result(chosen)
    duration = t - start
    omega1 = omega0 + impulse / inertia
    results = Results(TABLE)
    results.put("J", impulse, f" ∫τ dt ({chosen})")
    results.put("delta_omega", impulse / inertia)
    results.put("omega1", omega1, " the last sample")
    results.put("duration", duration, " from the first sample to the last")
    results.put("peak_torque", quadrature.peak[1], f", at t = {fmt(quadrature.peak[0])} s")
    _momentum_results(results, inertia, omega0, omega1)
    if rule == "auto":
        notes.append(
            f"method: {chosen} ("
            + ("composite Simpson, exact for quadratics, O(h⁴) on smooth data" if chosen == "simpson" else "two samples: only the trapezoid rule applies")
            + "; --method trapezoid for data with corners, where Simpson's higher order does not hold)"
        )
    if duration <= BRIEF_BLOW:
        notes.append(f"a brief blow ({fmt(duration)} s): the motion remembers only the impulse J, not the shape of τ(t)")
    tables = {}
    if count <= SAMPLES_SHOWN:
        columns = (("t", "s", "t"), ("torque", "N*m", "τ"), ("omega", "rad/s", "ω"))
        tables["samples"] = Table(columns, tuple(shown))
    else:
        notes.append(f"ω at the samples is reported for up to {SAMPLES_SHOWN:,} rows; this profile has {count:,}")
    steps = [
        *inertia_steps,
        Step("Angular impulse of a varying torque", "J = ∫τ dt = ΔL = I(ω₁ − ω₀)", f"{count} samples over {fmt(duration)} s, {chosen} rule",
             quantity_text(impulse, "N*m*s"), "the torque changes in time, so its impulse is an integral, taken here from the samples"),
        Step("Angular velocity after", "ω₁ = ω₀ + J/I", f"{term(omega0, 'rad/s')} + {term(impulse, 'N*m*s')} / {term(inertia, 'kg*m**2')}", quantity_text(omega1, "rad/s"),
             "the impulse is all the motion remembers of the torque"),
    ]
    model = f"sampled torque profile ({count} samples), J by the {chosen} rule"
    if plotted[-1][0] != t:
        plotted.append((t, torque, omega1))
    points = tuple((sample - start, torque_at, omega_at) for sample, torque_at, omega_at in plotted)
    note = "" if stride == 1 else f"plotted at every {stride}th sample"
    return Report("impulse", model, chosen, results, steps, notes, {}, tables, deferred(Trajectory, CURVES, duration, points=points, note=note))


def _check_particle(p: Particle) -> None:
    example = '{particle} "mass=30kg speed=4m/s radius=2m"'
    if p.angle is not None and not 0 <= p.angle <= math.pi * (1 + 1e-15):
        raise InputError(p.source, "angle= is between the velocity and the radius, from 0 to 180 deg", example=example, got=f"{fmt(math.degrees(p.angle))} deg")
    leaving = [name for name, value in (("speed-after=", p.speed_after), ("e=", p.e), ("radius-after=", p.radius_after)) if value is not None]
    if len(leaving) > 1:
        raise InputError(p.source, f"takes one of speed-after= (it leaves), e= (it rebounds), radius-after= (it stays); got {' and '.join(leaving)}", example=example)
    if p.speed is None:
        if p.speed_after is not None or p.e is not None or p.angle is not None:
            raise InputError(p.source, "needs speed= to meet the body (with no speed= it rides on the body at radius=)", example=example)
    if p.e is not None and p.e > 1:
        raise InputError(p.source, "e= is at most 1 (a rebound faster than the approach would make energy)", example=example, got=fmt(p.e))


def solve_meeting(inertia: float, omega0: float, particles: Sequence[Particle], couples: Sequence[Couple], *, inertia_steps: Sequence[Step] = ()) -> Report:
    """No external torque about the axis while a particle meets the body or bodies lock: L about
    the axis is conserved; the kinetic energy is not (the difference is the heat of the sliding
    or the deformation while they come to move together).

    With the body (I, ω₀), locking bodies (I_c, ω_c), particles that stick (m at r, line at r⊥ =
    r sin φ, sticking where they meet or at radius-after ρ), ride (m at r moving with the body), leave
    (speed v′ along their line) or rebound with e (v′ − ω₁r⊥ = −e(v − ω₀r⊥)):

        I ω₀ + Σ I_c ω_c + Σ m v r⊥ = (I + Σ I_c + Σ m ρ²) ω₁ + Σ m v′ r⊥,

    linear in ω₁. Where all join (nothing leaves), the energy lost is written without a
    difference of near-equal energies: ½ Σ_{j<k} I_j I_k (ω_j − ω_k)² / Σ I + ½ (Σ I ω̄²)·ΔI/I₁
    + the particles' radial ½m(v cos φ)², every term ≥ 0 when ρ ≥ r (I_k = m r², ω_k = v sin φ / r
    for a particle)."""
    for p in particles:
        _check_particle(p)

    notes: list[str] = []
    steps = list(inertia_steps)
    # Each thing that turns: (name, I before, ω before), for the ones that end up locked together.
    joined: list[tuple[str, float, float]] = [("body", inertia, omega0)]
    couple_rows = []
    for number, c in enumerate(couples, start=1):
        if c.part is not None:
            found = part_inertia(c.part)
            i_c = found.inertia
        else:
            i_c = c.inertia
        w_c = 0.0 if c.omega0 is None else c.omega0
        if c.omega0 is None:
            notes.append(f"{c.source}: no omega0=, taken at rest (ω = 0)")
        name = f"couple {number}" if len(couples) > 1 else "couple"
        joined.append((name, i_c, w_c))
        couple_rows.append((name, i_c, w_c))
        steps.append(Step(f"Angular momentum of the {name}", "L = I_c ω_c", f"{term(i_c, 'kg*m**2')} × {term(w_c, 'rad/s')}", quantity_text(i_c * w_c, "kg*m**2/s"), "a second body on the same axis"))
    stick, ride, leave, bounce = [], [], [], []
    extra_inertia = []  # m(ρ² − r²) of each particle that stays, r where it is before
    radial_energy = []  # ½m(v cos φ)²: a particle's motion toward the axis, stopped by the axle
    for number, p in enumerate(particles, start=1):
        name = f"particle {number}" if len(particles) > 1 else "particle"
        if p.speed is None:
            ride.append((name, p))
            joined.append((name, p.mass * p.radius**2, omega0))
            rho = p.radius if p.radius_after is None else p.radius_after
            extra_inertia.append(p.mass * (rho - p.radius) * (rho + p.radius))
            steps.append(Step(f"Angular momentum of the {name} (riding on the body)", "L = m r² ω₀", f"{term(p.mass, 'kg')} × ({term(p.radius, 'm')})² × {term(omega0, 'rad/s')}",
                              quantity_text(p.mass * p.radius**2 * omega0, "kg*m**2/s"), "it moves with the body, a point mass at r"))
            continue
        momentum = p.mass * p.speed * p.arm
        steps.append(Step(f"Angular momentum of the {name}", "L = m v r⊥,  r⊥ = r sin φ", f"{term(p.mass, 'kg')} × {term(p.speed, 'm/s')} × {term(p.radius, 'm')}"
                          + (f" × sin {fmt(math.degrees(p.angle))}°" if p.angle is not None else ""), quantity_text(momentum, "kg*m**2/s"),
                          "a particle moving along a line has angular momentum about the axis m v times the line's distance from the axis"))
        if p.speed_after is not None:
            leave.append((name, p))
        elif p.e is not None:
            bounce.append((name, p))
        else:
            stick.append((name, p))
            tangential = p.speed * p.sine
            if p.radius == 0:
                # A particle that meets the body on the axis has no angular momentum and adds no inertia there:
                # the axle stops all of its motion.
                joined.append((name, 0.0, 0.0))
                radial_energy.append(0.5 * p.mass * p.speed**2)
            else:
                joined.append((name, p.mass * p.radius**2, tangential / p.radius))
                if p.angle is not None:
                    radial_energy.append(0.5 * p.mass * (p.speed * cos_exact(p.angle)) ** 2)
            rho = p.radius if p.radius_after is None else p.radius_after
            extra_inertia.append(p.mass * (rho - p.radius) * (rho + p.radius))
    if bounce and (len(particles) > 1 or couples):
        raise InputError(bounce[0][1].source, "e= (a rebound) is solved for one particle meeting the body alone: impacts at once have no single "
                         "answer; give them one run each, in the order they happen", example='{particle} "mass=0.2kg speed=5m/s radius=1m e=0.5"')
    i_before = math.fsum(i for _, i, _ in joined)
    momentum_joined = math.fsum(i * w for _, i, w in joined)
    # I₁ summed from what turns after (not I before + ΔI, which cancels when a rider walks to the axis).
    staying = [p for _, p in (*stick, *ride)]
    i_after = math.fsum([inertia, *(i_c for _, i_c, _ in couple_rows),
                         *(p.mass * (p.radius if p.radius_after is None else p.radius_after) ** 2 for p in staying)])
    if i_after <= 0 and (bounce or not leave):
        raise InputError("inertia", "must be more than zero here: nothing would be left to turn", example="{inertia} 2kg*m^2")
    momentum0 = momentum_joined + math.fsum(p.mass * p.speed * p.arm for _, p in (*leave, *bounce))
    # ω₁ (I₁ + Σ_e m r⊥²) = L₀ − Σ_leave m v′ r⊥ + Σ_e m r⊥ e (v − ω₀ r⊥)
    i_effective = i_after + math.fsum(p.mass * p.arm**2 for _, p in bounce)
    numerator = momentum0 - math.fsum(p.mass * p.speed_after * p.arm for _, p in leave) + math.fsum(p.mass * p.arm * p.e * (p.speed - omega0 * p.arm) for _, p in bounce)
    if i_effective <= 0:
        raise InputError("inertia", "must be more than zero here", example="{inertia} 2kg*m^2")
    omega1 = numerator / i_effective
    after = {name: p.speed_after for name, p in leave}
    after.update({name: omega1 * p.arm - p.e * (p.speed - omega0 * p.arm) for name, p in bounce})
    # Energies.
    energy0_terms = [0.5 * i * w * w for _, i, w in joined] + radial_energy
    energy0_terms += [0.5 * p.mass * p.speed**2 for _, p in (*leave, *bounce)]
    energy0 = math.fsum(energy0_terms)
    energy1 = math.fsum([0.5 * i_after * omega1 * omega1] + [0.5 * p.mass * after[name] ** 2 for name, p in (*leave, *bounce)])
    if bounce:
        name, p = bounce[0]  # alone with the body: a collision along its line with the body's point, of mass I/r⊥² there
        approach = p.speed - omega0 * p.arm
        lost = 0.5 * p.mass * inertia / (inertia + p.mass * p.arm**2) * (1 - p.e) * (1 + p.e) * approach * approach
    elif not leave:
        spread = math.fsum(i_j * i_k * (w_j - w_k) ** 2 for n, (_, i_j, w_j) in enumerate(joined) for (_, i_k, w_k) in joined[n + 1:])
        lost = (0.5 * spread / i_before if i_before else 0.0) + (0.5 * momentum_joined**2 / i_before * math.fsum(extra_inertia) / i_after if i_before else 0.0)
        lost += math.fsum(radial_energy)
    else:
        lost = math.fsum([*energy0_terms, *(-0.5 * i_after * omega1 * omega1,), *(-0.5 * p.mass * after[name] ** 2 for name, p in (*leave, *bounce))])
    results = Results(TABLE)
    results.put("omega1", omega1, " (the body and all that stays on it)" if len(joined) > 1 else "")
    results.put("delta_omega", omega1 - omega0)
    results.put("inertia", inertia)
    results.put("omega0", omega0)
    results.put("J", inertia * (omega1 - omega0), " the body receives, I(ω₁ − ω₀)")
    results.put("L0", momentum0)
    momentum1 = math.fsum([i_after * omega1] + [p.mass * after[name] * p.arm for name, p in (*leave, *bounce)])
    results.put("L1", momentum1, " (the same: no external torque about the axis)")
    system = ", particles' ½mv² included" if particles else (", both bodies" if len(couples) == 1 else ", all the bodies")
    results.put("KE0", energy0, system)
    results.put("KE1", energy1, system)
    results.put("KE_lost", lost, " into heat and deformation" if lost >= 0 else ": negative, energy was added")
    results.put("KE_lost_fraction", lost / energy0 if energy0 > 0 else None)
    if energy0 == 0:
        notes.append("KE_lost_fraction: nothing moved before, so no fraction of it can be lost")
    # Each one's part: L before and after, the angular impulse it receives, its speed after.
    rows = [("body", inertia * omega0, inertia * omega1, inertia * (omega1 - omega0), None)]
    for name, i_c, w_c in couple_rows:
        rows.append((name, i_c * w_c, i_c * omega1, i_c * (omega1 - w_c), None))
    for name, p in (*stick, *ride):
        rho = p.radius if p.radius_after is None else p.radius_after
        l_before = p.mass * p.radius**2 * omega0 if p.speed is None else p.mass * p.speed * p.arm
        rows.append((name, l_before, p.mass * rho**2 * omega1, p.mass * rho**2 * omega1 - l_before, omega1 * rho))
    for name, p in (*leave, *bounce):
        rows.append((name, p.mass * p.speed * p.arm, p.mass * after[name] * p.arm, p.mass * p.arm * (after[name] - p.speed), after[name]))
    order = {name: n for n, name in enumerate(["body", *(r[0] for r in couple_rows), *(f"particle {k}" if len(particles) > 1 else "particle" for k in range(1, len(particles) + 1))])}
    rows.sort(key=lambda row: order[row[0]])
    columns = (("part", None, "part"), ("L0", "kg*m**2/s", "L₀"), ("L1", "kg*m**2/s", "L₁"), ("J", "N*m*s", "J = ΔL"), ("speed_after", "m/s", "v after"))
    tables = {"parts": Table(columns, tuple(rows))}
    # Steps.
    steps.insert(len(inertia_steps), Step(
        "No external torque about the axis: angular momentum is conserved",
        "L₀ = L₁:  Iω₀ + Σ I_c ω_c + Σ m v r⊥ = I₁ω₁ + Σ m v′ r⊥",
        "", "",
        "the forces the bodies exert on each other (the grip, the clutch's friction, the particle's push) come in equal and "
        "opposite pairs along one line, so their torques about the axis cancel; the axle's force passes through the axis, "
        "so it has no torque about it",
    ))
    steps.append(Step("Angular momentum before", "L₀ = Σ of the parts", " + ".join(term(row[1], "kg*m**2/s") for row in rows), quantity_text(momentum0, "kg*m**2/s"),
                      "angular momenta about one axis add"))
    stays = [(name, p) for name, p in (*stick, *ride)]
    if stays or couple_rows:
        steps.append(Step("Moment of inertia after", "I₁ = I + Σ I_c + Σ m ρ²",
                          " + ".join([term(inertia, "kg*m**2"), *(term(i_c, "kg*m**2") for _, i_c, _ in couple_rows),
                                      *(f"{term(p.mass, 'kg')} × ({term(p.radius if p.radius_after is None else p.radius_after, 'm')})²" for _, p in stays)]),
                          quantity_text(i_after, "kg*m**2"), "what stays on the axis turns together at ω₁; a particle that stays is a point mass at ρ"))
    if bounce:
        name, p = bounce[0]
        steps.append(Step("Restitution along the particle's line", "v′ − ω₁r⊥ = −e (v − ω₀r⊥)", f"e = {fmt(p.e)}, r⊥ = {fmt(p.arm)} m", "",
                          "the speed at which the particle and the body's point separate is e times the speed at which they approached"))
    top = "L₀" + (" − Σ m v′ r⊥" if leave else "") + (" + Σ m r⊥ e (v − ω₀r⊥)" if bounce else "")
    bottom = "I₁" + (" + Σ m r⊥²" if bounce else "")
    equation = f"ω₁ = {f'({top})' if top != 'L₀' else top} / {f'({bottom})' if bottom != 'I₁' else bottom}"
    steps.append(Step("Angular velocity after", equation, f"{term(numerator, 'kg*m**2/s')} / {term(i_effective, 'kg*m**2')}", quantity_text(omega1, "rad/s"),
                      "L₀ = L₁ solved for the one unknown"))
    for name, p in bounce:
        steps.append(Step(f"Speed of the {name} after", "v′ = ω₁r⊥ − e (v − ω₀r⊥)", f"{term(omega1, 'rad/s')} × {term(p.arm, 'm')} − {fmt(p.e)} × ({term(p.speed, 'm/s')} − {term(omega0, 'rad/s')} × {term(p.arm, 'm')})",
                          quantity_text(after[name], "m/s"),
                          "the restitution law solved for v′: " + ("negative, it bounces back" if after[name] < 0 else "it follows the body's point, which now moves away at least as fast")))
    why_energy = ("kinetic energy is not conserved: while the two come to move together they slide on each other (or the particle deforms, "
                  "the bullet tears the wood), and that friction turns kinetic energy into heat; only a perfectly elastic rebound (e = 1) keeps it all")
    steps.append(Step("Kinetic energy before and after", "KE = ½Iω² + ½mv²", f"{quantity_text(energy0, 'J')} → {quantity_text(energy1, 'J')}",
                      f"lost {quantity_text(lost, 'J')}" + (f" ({fmt(100 * lost / energy0, 3)}%)" if energy0 > 0 else ""), why_energy))
    if bounce:
        name, p = bounce[0]
        steps.append(Step("The energy lost in the rebound", "KE_lost = ½ μ (1 − e²)(v − ω₀r⊥)²,  μ = m I / (I + m r⊥²)",
                          f"½ × {term(p.mass * inertia / (inertia + p.mass * p.arm**2), 'kg')} × (1 − {fmt(p.e)}²) × ({term(p.speed, 'm/s')} − {term(omega0, 'rad/s')} × {term(p.arm, 'm')})²",
                          quantity_text(lost, "J"),
                          "along the particle's line the body's point acts as a mass I/r⊥²: a collision of two masses, which keeps "
                          "the fraction e² of the energy of their approach"))
    if not leave and not bounce:
        steps.append(Step("The energy lost, as the bodies' spread of speeds", "KE_lost = ½ Σ_{j<k} I_j I_k (ω_j − ω_k)² / ΣI + ½ I ω̄² ΔI/I₁ + ½m(v cos φ)²",
                          "", quantity_text(lost, "J"),
                          "zero only when all already turned at one speed: the loss is the energy of their motion relative to each other "
                          "(with what moving a particle outward takes, and any motion straight at the axis, which the axle stops)"))
    if particles and any(p.speed is not None for p in particles):
        notes.append("the axle (pivot) pushes on the body while the particle strikes: its force has no torque about the axis, so L about "
                     "the axis is conserved, but it changes the linear momentum of the system (the pivot force carries linear momentum away), "
                     "so linear momentum is not conserved")
    if lost < 0:
        notes.append("KE_lost is negative: the system gained kinetic energy, so something did work inside it (a person walking inward, "
                     "a spring, a push); a passive collision cannot do this")
    if any(p.radius_after is not None for p in particles):
        notes.append("a particle that moves along the body (radius-after=) is taken to move with the body's rotation, its own muscles doing the work")
    what = []
    if couple_rows:
        what.append("bodies that lock together")
    if stick:
        what.append("a particle that sticks" if len(stick) == 1 else "particles that stick")
    if ride:
        what.append("a particle riding on the body" if len(ride) == 1 else "particles riding on the body")
    if leave:
        what.append("a particle that leaves" if len(leave) == 1 else "particles that leave")
    if bounce:
        what.append("a particle that rebounds (restitution)" if len(bounce) == 1 else "particles that rebound (restitution)")
    model = "no external torque about the axis: L conserved; " + ", ".join(what)
    return Report("impulse", model, "closed form", results, steps, notes, {}, tables)


def impulse(
    *,
    omega0: float | None = None,
    omega1: float | None = None,
    torque: float | None = None,
    duration: float | None = None,
    inertia_final: float | None = None,
    torque_profile: Iterable[tuple[float, float]] | None = None,
    method: str = "auto",
    particle: Sequence[Particle] = (),
    couple: Sequence[Couple] = (),
    at: float | None = None,
    brake: Sequence = (),
    face: Sequence = (),
    g: float | None = None,
    **body_options,
) -> Report:
    """``taucli impulse``: τΔt = IΔω solved for the one left out; or a moment of inertia that
    changes with no torque (--inertia-final); or a sampled torque (--torque-profile); --at r, a
    point of the body before and after."""
    if at is not None:
        report = impulse(omega0=omega0, omega1=omega1, torque=torque, duration=duration, inertia_final=inertia_final,
                         torque_profile=torque_profile, method=method, particle=particle, couple=couple, brake=brake, face=face, g=g, **body_options)
        body_given = body_options.get("inertia") is not None or body_options.get("shape") is not None or bool(body_options.get("part"))
        given = {"omega0": omega0, "omega1": omega1, "torque": torque, "duration": duration,
                 "inertia": body(**body_options)[0] if body_given else None}
        r, note = rim_radius(at, body_options.get("radius", body_options.get("outer_radius")), "a body with {radius}")
        report = _point_after(report, r, given)
        report.notes += [note] if note else []
        return report

    body_given = body_options.get("inertia") is not None or body_options.get("shape") is not None or bool(body_options.get("part"))
    moment, body_steps = body(**body_options) if body_given else (None, ())
    if brake or face:
        if method != "auto":
            raise InputError("method", "applies to {torque_profile} (trapezoid or simpson); a braked impulse has a closed form")
        if g is not None and not any(plate.force is None for plate in face):
            raise InputError("g", "is used only for the weight on a {face} with no force=")
        return _braked(moment, body_steps, body_options, omega0, omega1, torque, duration, tuple(brake), tuple(face), g,
                       {"inertia_final": inertia_final, "torque_profile": torque_profile, "particle": particle or None, "couple": couple or None})
    if g is not None:
        raise InputError("g", "is used only for the weight on a {face} with no force=")
    if particle or couple:
        mode = "particle" if particle else "couple"
        for name, value in (("omega1", omega1), ("torque", torque), ("duration", duration), ("inertia_final", inertia_final), ("torque_profile", torque_profile)):
            if value is not None:
                raise InputError(name, f"conflicts with {{{mode}}}: while they meet, no external torque acts and L is conserved")
        if method != "auto":
            raise InputError("method", "applies to {torque_profile} (trapezoid or simpson)")
        if moment is None:
            raise InputError("inertia", f"or {{shape}} is required with {{{mode}}}: the body they meet", example="{inertia} 500kg*m^2")
        assumed = Assumed()
        if omega0 is None:
            omega0 = assumed.value("omega0", 0.0, "rad/s", "no --omega0: the body starts at rest")
        return assumed.applied(solve_meeting(moment, omega0, tuple(particle), tuple(couple), inertia_steps=body_steps))
    if inertia_final is None and torque_profile is None:
        if method != "auto":
            raise InputError("method", "applies to {torque_profile} (trapezoid or simpson); constant torque has a closed form")
        return solve_balance(moment, omega0, omega1, torque, duration, inertia_steps=body_steps)
    mode = "inertia_final" if inertia_final is not None else "torque_profile"
    for name, value in (("omega1", omega1), ("torque", torque), ("duration", duration), ("inertia_final", inertia_final if mode != "inertia_final" else None)):
        if value is not None:
            raise InputError(name, f"conflicts with {{{mode}}}")
    if moment is None:
        raise InputError("inertia", f"or {{shape}} is required with {{{mode}}}", example="{inertia} 2kg*m^2")
    if mode == "inertia_final":
        return solve_changing_inertia(moment, inertia_final, omega0 or 0.0, inertia_steps=body_steps)
    assumed = Assumed()
    if omega0 is None:
        omega0 = assumed.value("omega0", 0.0, "rad/s", "no --omega0: the body starts at rest")
    return assumed.applied(solve_profile(moment, omega0, torque_profile, rule=method, inertia_steps=body_steps))


def _point_after(report: Report, r: float, given: dict) -> Report:
    """A point of the body at r: at the start (ω₀) and at the end of the impulse (ω₁). A constant
    torque still acts at the end (α = τ/I) and the body has turned θ = ½(ω₀ + ω₁)Δt; after a
    meeting or a change of shape no torque acts (α = 0) and the angle is not followed; a sampled
    torque's α at its end is not kept (null, with a note)."""
    values = {**given, **{key: value.value for key, value in (*report.inputs.items(), *report.results.items()) if value.value is not None}}
    omega0, omega1 = values.get("omega0"), values.get("omega1")
    torque, inertia, duration = values.get("torque"), values.get("inertia"), values.get("duration")
    results = Results(TABLE)
    results.update(report.results)
    notes, steps = list(report.notes), list(report.steps)
    if torque is not None and inertia:
        alpha, theta = torque / inertia, None if duration is None or omega0 is None or omega1 is None else (omega0 + omega1) * duration / 2
        alpha0, when = alpha, " at the end of the impulse"
    elif report.model.startswith("sampled"):
        alpha = alpha0 = theta = None
        when = " after the impulse"
    else:
        alpha = alpha0 = 0.0
        theta, when = None, " after"
    if omega0 is None or omega1 is None:
        steps += put_point(results, r, None, None, None, when, notes)
        notes[-1] = "v_t, a_t, a_c, a_total, a_angle, s: ω before or after is not determined by what is given"
    else:
        steps += put_point(results, r, omega1, alpha, theta, when, notes)
        put_start(results, r, omega0, alpha0)
        if theta is None:
            notes.append("s: the angle turned while it changes is not followed here")
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)


def _braked(moment, body_steps, body_options: dict, omega0, omega1, torque, duration, brakes, faces, g, others: dict) -> Report:
    """A constant torque τ over Δt on a body that brakes or faces rub (#24): a constant Coulomb
    torque τ_f against the turning (static μ holding it at rest), so I dω/dt = τ − τ_f·sgn ω:
    it may stop within Δt, stay held, or turn back with the friction reversed (motion.evolve).
    ω₁ follows; the net angular impulse I(ω₁ − ω₀) = τΔt − ∫τ_f sgn ω dt."""
    for name, value in others.items():
        if value is not None:
            raise InputError(name, "does not combine with {brake} or {face} here: they act with a constant {torque} over {duration}")
    if omega1 is not None:
        raise InputError("omega1", "is what {brake} and {face} let this solve for: leave it out")
    for name, value in (("inertia", moment), ("torque", torque), ("duration", duration)):
        if value is None:
            raise InputError(name, "is required with {brake} or {face}: the friction's share is worked out over the motion, from the start",
                             example={"inertia": "{inertia} 0.5kg*m^2", "torque": "{torque} 5N*m", "duration": "{duration} 2s"}[name])
    assumed = Assumed()
    if omega0 is None:
        omega0 = assumed.value("omega0", 0.0, "rad/s", "no --omega0: the body starts at rest")
    weight = assumed.gravity(g) if any(plate.force is None for plate in faces) else None
    contact = contacts(brakes, faces, body_options, body_options.get("mass"), weight)
    loads = Loads(drive=torque, friction=contact.kinetic, static=contact.static)
    motion = evolve(moment, loads, omega0, Evolver(Method("exact")))
    omega_end, theta = motion.state_at(duration)
    stop = motion.stop if motion.stop is not None and motion.stop[0] < duration else None
    # the angle swept both ways: to the stop, then (turned back) from there
    swept = abs(theta) if stop is None else abs(stop[1]) + abs(theta - motion.signed_stop[1])
    results = Results(TABLE)
    impulse = torque * duration
    results.put("omega1", omega_end, " Δt")
    results.put("delta_omega", omega_end - omega0)
    results.put("J", impulse, " of the applied torque, τΔt")
    results.put("J_net", moment * (omega_end - omega0))
    results.put("L0", moment * omega0)
    results.put("L1", moment * omega_end, " Δt")
    energy0, energy1 = moment * omega0 * omega0 / 2, moment * omega_end * omega_end / 2
    results.put("KE0", energy0, "")
    results.put("KE1", energy1, " Δt")
    results.put("work", energy1 - energy0)
    speed0 = abs(omega0)
    for name, share in (("brake", contact.brake), ("face", contact.face)):
        if (name == "brake" and brakes) or (name == "face" and faces):
            results.put(f"torque_{name}", share)
            results.put(f"work_{name}", share * swept, " during Δt")
            results.put(f"power_{name}", share * speed0, " at the start")
    notes = list(contact.notes)
    if motion.held_from_start:
        notes.append(f"static friction holds the body: |τ| = {quantity_text(abs(torque), 'N*m')} does not exceed {quantity_text(contact.static, 'N*m')}")
    elif stop is not None:
        notes.append(f"the body stops at t = {quantity_text(stop[0], 's')} within Δt"
                     + (", and the torque turns it back, friction reversed" if motion.second is not None else ", and static friction holds it"))
    steps = [*body_steps, *contact.steps]
    steps.append(Step("Friction torques add", "τ_f = " + " + ".join(s for s, v in (("τ_b", contact.brake), ("τ_face", contact.face)) if v),
                      " + ".join(term(v, "N*m") for v in (contact.brake, contact.face) if v), quantity_text(contact.kinetic, "N*m"),
                      "each is a constant torque against the motion: together one friction torque τ_f"))
    if not motion.held_from_start:
        alpha = motion.initial_rate
        steps.append(Step("Angular acceleration while it turns", "α = (τ − τ_f·sgn ω)/I",
                          f"({term(torque, 'N*m')} {'−' if motion.direction > 0 else '+'} {term(contact.kinetic, 'N*m')}) / {term(moment, 'kg*m**2')}",
                          quantity_text(alpha, "rad/s**2"), "Newton's second law for rotation, friction against the motion"))
    if stop is None:
        how = f"{term(omega0, 'rad/s')} + {term(motion.initial_rate, 'rad/s**2')} × {term(duration, 's')}"
    else:
        then = ("static friction holds it" if motion.second is None else
                f"then α₂ = {term(motion.second.direction * motion.second.rate(0.0), 'rad/s**2')} for {term(duration - stop[0], 's')}")
        how = f"stops at t = |ω₀/α| = {term(stop[0], 's')}; {then}"
    steps.append(Step("Angular velocity after Δt", "ω₁ = ω₀ + αΔt (to the stop, if it comes first; then held, or turned back)", how,
                      quantity_text(omega_end, "rad/s"), "constant α within each stretch of motion one way"))
    steps.append(Step("Angular impulse: applied and net", "J = τΔt;  J_net = IΔω = J − ∫τ_f sgn ω dt",
                      f"{term(torque, 'N*m')} × {term(duration, 's')};  {term(moment, 'kg*m**2')} × ({term(omega_end, 'rad/s')} − {term(omega0, 'rad/s')})",
                      f"{quantity_text(impulse, 'N*m*s')};  {quantity_text(moment * (omega_end - omega0), 'N*m*s')}",
                      "the friction's angular impulse is the difference: what the brakes and faces took from the torque's"))
    steps.append(Step("Energy the friction takes", "W_f = τ_f × angle swept", f"{term(contact.kinetic, 'N*m')} × {term(swept, 'rad')}",
                      quantity_text(contact.kinetic * swept, "J"), "a constant friction torque takes its torque for every radian swept, either way"))
    model = "constant torque with " + ", ".join(contact.models) + ": I dω/dt = τ − τ_f sgn ω (static μ holding at rest)"
    return assumed.applied(Report("impulse", model, "closed form", results, steps, notes))
