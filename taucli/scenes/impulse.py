"""Angular impulse and angular momentum: J = ∫τ dt = ΔL, L = Iω.

Three cases:
- constant torque: τΔt = I(ω₁ − ω₀), any four of I, ω₀, ω₁, τ, Δt giving the fifth;
- inertia that changes with no external torque (the skater, the diver): I₀ω₀ = I₁ω₁;
- a torque that varies in time, sampled: J by quadrature, then ω₁ = ω₀ + J/I.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from taucli.errors import InputError
from taucli.numerics import StreamingQuadrature
from taucli.options.impulse import COMMAND as TABLE
from taucli.report import Report, Step, Table, Trajectory, deferred, fmt, quantity_text
from taucli.scenes.assumed import Assumed
from taucli.table import Results

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
        "omega1": ("ω₁ = ω₀ + τΔt/I", f"{fmt(w0)} + {fmt(tau)} × {fmt(dt)} / {fmt(i)}", quantity_text(w1, "rad/s")),
        "omega0": ("ω₀ = ω₁ − τΔt/I", f"{fmt(w1)} − {fmt(tau)} × {fmt(dt)} / {fmt(i)}", quantity_text(w0, "rad/s")),
        "torque": ("τ = I(ω₁ − ω₀)/Δt", f"{fmt(i)} × ({fmt(w1)} − {fmt(w0)}) / {fmt(dt)}", quantity_text(tau, "N*m")),
        "duration": ("Δt = I(ω₁ − ω₀)/τ", f"{fmt(i)} × ({fmt(w1)} − {fmt(w0)}) / {fmt(tau)}", quantity_text(dt, "s")),
        "inertia": ("I = τΔt/(ω₁ − ω₀)", f"{fmt(tau)} × {fmt(dt)} / ({fmt(w1)} − {fmt(w0)})", quantity_text(i, "kg*m**2")),
    }
    if unknown is not None:
        equation, numbers, result = solved[unknown]
        steps.append(Step(f"Solve for {unknown}", equation, numbers, result, "the one quantity not given"))
    steps.append(Step("The impulse", "J = τΔt", f"{fmt(tau)} × {fmt(dt)}", quantity_text(impulse, "N*m*s"), "the same as the change of angular momentum ΔL = IΔω"))
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
                          f"{fmt(tau)} × {fmt(dt)}" if by_torque else f"{fmt(i)} × ({fmt(w1)} − {fmt(w0)})", quantity_text(impulse, "N*m*s"),
                          "all the motion remembers of the torque"))
    if change is not None:
        steps.append(Step("The change of angular velocity", "Δω = ω₁ − ω₀", f"{fmt(w1)} − {fmt(w0)}", quantity_text(change, "rad/s"), "from the two given"))
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
        Step("Angular velocity after", "ω₁ = I₀ω₀ / I₁", f"{fmt(inertia0)} × {fmt(omega0)} / {fmt(inertia1)}", quantity_text(omega1, "rad/s"),
             "less inertia, faster spin: the skater pulling in her arms"),
        Step("Kinetic energy is not conserved", "KE = L²/(2I)  ⇒  KE₁/KE₀ = I₀/I₁",
             f"{fmt(energy0)} J × {fmt(inertia0)} / {fmt(inertia1)}", quantity_text(energy1, "J"),
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
        Step("Angular velocity after", "ω₁ = ω₀ + J/I", f"{fmt(omega0)} + {fmt(impulse)} / {fmt(inertia)}", quantity_text(omega1, "rad/s"),
             "the impulse is all the motion remembers of the torque"),
    ]
    model = f"sampled torque profile ({count} samples), J by the {chosen} rule"
    if plotted[-1][0] != t:
        plotted.append((t, torque, omega1))
    points = tuple((sample - start, torque_at, omega_at) for sample, torque_at, omega_at in plotted)
    note = "" if stride == 1 else f"plotted at every {stride}th sample"
    return Report("impulse", model, chosen, results, steps, notes, {}, tables, deferred(Trajectory, CURVES, duration, points=points, note=note))


def impulse(
    *,
    omega0: float | None = None,
    omega1: float | None = None,
    torque: float | None = None,
    duration: float | None = None,
    inertia_final: float | None = None,
    torque_profile: Iterable[tuple[float, float]] | None = None,
    method: str = "auto",
    **body_options,
) -> Report:
    """``taucli impulse``: τΔt = IΔω solved for the one left out; or a moment of inertia that
    changes with no torque (--inertia-final); or a sampled torque (--torque-profile)."""
    from taucli.scenes.inertia import body

    body_given = body_options.get("inertia") is not None or body_options.get("shape") is not None or bool(body_options.get("part"))
    moment, body_steps = body(**body_options) if body_given else (None, ())
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
