"""A constant torque over a time: τΔt = I(ω₁ − ω₀), any four of I, ω₀, ω₁, τ, Δt giving the fifth.

τ = Iα times Δt, with τ and I constant while the torque acts: αΔt = Δω. With two or more left
out, the one equation fixes only what the rest determine (J = τΔt, Δω = ω₁ − ω₀).
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, Trajectory, deferred, fmt, quantity_text, term
from taucli.scenes.impulse.common import BRIEF_BLOW, CURVES, put_momentum
from taucli.options.table import Results

AGREEMENT = 1e-9  # relative: all five given must satisfy τΔt = IΔω this closely
SOLVED = " (solved for)"  # what a solved result's label adds
UNKNOWNS = ("inertia", "omega0", "omega1", "torque", "duration")


def solve_balance(
    inertia: float | None,
    omega0: float | None,
    omega1: float | None,
    torque: float | None,
    duration: float | None,
    *,
    inertia_steps: Sequence[Step] = (),
) -> Report:
    """τΔt = I(ω₁ − ω₀), τ constant over Δt and I fixed, with any four given: the fifth, then
    J = τΔt, Δω, and L = Iω and KE = ½Iω² before and after. I, τ, Δt given with neither ω: ω₀ = 0.
    All five given: they must agree to AGREEMENT."""
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
    delta_omega = None  # Δω = τΔt/I where ω₀ or ω₁ is solved for: kept before that ω is rounded
    if unknown == "omega1":
        delta_omega = tau * dt / i
        w1 = w0 + delta_omega
    elif unknown == "omega0":
        delta_omega = tau * dt / i
        w0 = w1 - delta_omega
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
        impulse, momentum_change = tau * dt, i * (w1 - w0)
        if abs(impulse - momentum_change) > AGREEMENT * max(abs(impulse), abs(i * w0), abs(i * w1), 1e-300):
            raise InputError("omega1",
                f"and the other four disagree: τΔt = {fmt(impulse, 6)} N·m·s but I(ω₁ − ω₀) = {fmt(momentum_change, 6)} N·m·s",
                hint="leave out the one to solve for",
            )
    impulse = tau * dt
    results = Results(TABLE)
    results.put("J", impulse, " τΔt")
    results.put("delta_omega", w1 - w0 if delta_omega is None else delta_omega)
    for name, value in (("inertia", i), ("omega0", w0), ("omega1", w1), ("torque", tau)):
        results.put(name, value, SOLVED if unknown == name else "")
    results.put("duration", dt, " the torque acts" + (SOLVED if unknown == "duration" else ""))
    put_momentum(results, i, w0, w1)
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
    delta_omega = None if w0 is None or w1 is None else w1 - w0
    state = i is not None and w0 is not None  # a spinning body's own state, L₀ and KE₀, with nothing acting on it (#42 item 16)
    if impulse is None and delta_omega is None and not state:
        raise InputError(
            " and ".join("{" + name + "}" for name in missing),
            "are missing: give four of {inertia}, {omega0}, {omega1}, {torque}, {duration}, and the fifth is solved for",
            example="{inertia} '0.1kg*m^2' {omega0} 0 {torque} '2N*m' {duration} 0.5s",
        )
    results = Results(TABLE)
    results.put("J", impulse, " τΔt")
    results.put("delta_omega", delta_omega)
    for name, value in (("inertia", i), ("omega0", w0), ("omega1", w1), ("torque", tau)):
        results.put(name, value)
    results.put("duration", dt, " the torque acts")
    put_momentum(results, i, w0, w1)
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
    if delta_omega is not None:
        steps.append(Step("The change of angular velocity", "Δω = ω₁ − ω₀", f"{term(w1, 'rad/s')} − {term(w0, 'rad/s')}", quantity_text(delta_omega, "rad/s"), "from the two given"))
    if state:
        steps.append(Step("Angular momentum before", "L₀ = Iω₀", f"{term(i, 'kg*m**2')} × {term(w0, 'rad/s')}", quantity_text(i * w0, "kg*m**2/s"),
                          "the body's angular momentum about its axis"))
        steps.append(Step("Kinetic energy before", "KE₀ = ½Iω₀²", f"½ × {term(i, 'kg*m**2')} × ({term(w0, 'rad/s')})²", quantity_text(0.5 * i * w0 * w0, "J"),
                          "the energy of its spin"))
    known = " and ".join(name for name, value in (("J", impulse), ("Δω", delta_omega), ("L₀ and KE₀", i * w0 if state else None)) if value is not None)
    if impulse is None and delta_omega is None:  # the state alone: nothing acts on the body
        steps = [step for step in steps if not step.title.startswith("Angular impulse")]
        return Report("impulse", "a spinning body's state: L₀ = Iω₀, KE₀ = ½Iω₀² (no torque, no change given)", "closed form", results, steps, notes)
    return Report("impulse", f"constant torque: τΔt = IΔω, which fixes only {known} here", "closed form", results, steps, notes)
