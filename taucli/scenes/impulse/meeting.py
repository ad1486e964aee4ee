"""Particles and bodies that meet the body with no external torque about the axis: L conserved.

A particle sticks, rides on the body (and may move along it), leaves with a speed after, or
rebounds with restitution e; another body on the axis (a couple) locks to it. A particle that
stays may move along the rim at v_rel relative to the body after (speed-relative=: a toy train
on a free wheel, a person walking on a turntable): its speed is v′ = ω₁ρ + v_rel. Linear in ω₁:

    I ω₀ + Σ I_c ω_c + Σ m v r⊥ = (I + Σ I_c + Σ m ρ²) ω₁ + Σ m v′ r⊥ + Σ m ρ v_rel
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, Table, fmt, quantity_text, term
from taucli.scenes.angles import cos_exact
from taucli.scenes.given import Couple, Particle
from taucli.scenes.impulse.after import put_momentum
from taucli.scenes.inertia import part_inertia
from taucli.options.table import Results


def _check_particle(p: Particle) -> None:
    """A particle's keys make one meeting: 0 ≤ angle ≤ 180°, one of speed-after=, e=, radius-after=,
    speed= for all but a rider, e ≤ 1."""
    example = '{particle} "mass=30kg speed=4m/s radius=2m"'
    if p.angle is not None and not 0 <= p.angle <= math.pi * (1 + 1e-15):
        raise InputError(p.source, "angle= is between the velocity and the radius, from 0 to 180 deg", example=example, got=f"{fmt(math.degrees(p.angle))} deg")
    leaving = [name for name, value in (("speed-after=", p.speed_after), ("e=", p.e), ("radius-after=", p.radius_after)) if value is not None]
    if len(leaving) > 1:
        raise InputError(p.source, f"takes one of speed-after= (it leaves), e= (it rebounds), radius-after= (it stays); got {' and '.join(leaving)}", example=example)
    if p.speed_relative is not None and (p.speed_after is not None or p.e is not None):
        raise InputError(p.source, "speed-relative= is the speed along the body of a particle that stays on it: it takes no speed-after= or e=",
                         example='{particle} "mass=0.2kg radius=0.5m speed-relative=0.3m/s"')
    if p.speed is None:
        if p.speed_after is not None or p.e is not None or p.angle is not None:
            raise InputError(p.source, "needs speed= to meet the body (with no speed= it rides on the body at radius=)", example=example)
    if p.e is not None and p.e > 1:
        raise InputError(p.source, "e= is at most 1 (a rebound faster than the approach would make energy)", example=example, got=fmt(p.e))


def solve_meeting(inertia: float, omega0: float, particles: Sequence[Particle], couples: Sequence[Couple], *, inertia_steps: Sequence[Step] = (),
                  centre: tuple[float, float] | str | None = None) -> Report:
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
        raise InputError("inertia", "must be more than zero here: nothing would be left to turn", example="{inertia} '2kg*m^2'")
    def rho_of(p: Particle) -> float:
        return p.radius if p.radius_after is None else p.radius_after

    momentum0 = momentum_joined + math.fsum(p.mass * p.speed * p.arm for _, p in (*leave, *bounce))
    # ω₁ (I₁ + Σ_e m r⊥²) = L₀ − Σ_leave m v′ r⊥ + Σ_e m r⊥ e (v − ω₀ r⊥)
    i_effective = i_after + math.fsum(p.mass * p.arm**2 for _, p in bounce)
    walk = [(name, p) for name, p in (*stick, *ride) if p.speed_relative is not None]  # they move along the rim after, at v_rel
    if walk and leave:
        raise InputError(walk[0][1].source, "speed-relative= is solved with particles that stay and bodies that lock: give a particle that leaves "
                         "(speed-after=) a run of its own", example='{particle} "mass=0.2kg radius=0.5m speed-relative=0.3m/s"')
    walking = math.fsum(p.mass * rho_of(p) * p.speed_relative for _, p in walk)  # W = Σ m ρ v_rel, the walkers' own L after
    numerator = momentum0 - walking - math.fsum(p.mass * p.speed_after * p.arm for _, p in leave) + math.fsum(p.mass * p.arm * p.e * (p.speed - omega0 * p.arm) for _, p in bounce)
    if i_effective <= 0:
        raise InputError("inertia", "must be more than zero here", example="{inertia} '2kg*m^2'")
    omega1 = numerator / i_effective
    # Δω from what each exchanges with the body, not ω₁ − ω₀, which loses the digits of a small change
    # beside a large ω: (numerator − i_effective ω₀) written term by term; likewise ω₁ − ω for any ω.

    def exchange(ref: float) -> float:
        """(numerator − i_effective·ref) as a sum of what each thing gives up relative to ``ref``: ω₁ − ref times I_eff."""
        return math.fsum([
            inertia * (omega0 - ref),
            *(i_c * (w_c - ref) for _, i_c, w_c in couple_rows),
            *(p.mass * (p.speed * p.arm - rho_of(p) ** 2 * ref) for _, p in stick),
            *(p.mass * (p.radius**2 * omega0 - rho_of(p) ** 2 * ref) for _, p in ride),
            *(p.mass * p.arm * (p.speed - p.speed_after) for _, p in leave),
            *(p.mass * p.arm * ((p.speed - ref * p.arm) + p.e * (p.speed - omega0 * p.arm)) for _, p in bounce),
            *(-p.mass * rho_of(p) * p.speed_relative for _, p in walk),
        ])

    exchange_body = math.fsum([
        *(i_c * (w_c - omega0) for _, i_c, w_c in couple_rows),
        *(p.mass * (p.speed * p.arm - rho_of(p) ** 2 * omega0) for _, p in stick),
        *(-p.mass * (rho_of(p) - p.radius) * (rho_of(p) + p.radius) * omega0 for _, p in ride),
        *(p.mass * p.arm * (p.speed - p.speed_after) for _, p in leave),
        *(p.mass * p.arm * (1 + p.e) * (p.speed - omega0 * p.arm) for _, p in bounce),
        *(-p.mass * rho_of(p) * p.speed_relative for _, p in walk),
    ])
    delta_omega = exchange_body / i_effective
    after = {name: p.speed_after for name, p in leave}
    after.update({name: omega1 * p.arm - p.e * (p.speed - omega0 * p.arm) for name, p in bounce})
    # I_rest: what turns rigidly after (the body, the couples, the particles that stay and do not walk)
    rest = math.fsum([inertia, *(i_c for _, i_c, _ in couple_rows), *(p.mass * rho_of(p) ** 2 for p in staying if p.speed_relative is None)])
    after.update(_walkers_speeds(walk, rest, i_after, momentum0, rho_of))  # along the rim, over the ground
    # Energies.
    energy0_terms = [0.5 * i * w * w for _, i, w in joined] + radial_energy
    energy0_terms += [0.5 * p.mass * p.speed**2 for _, p in (*leave, *bounce)]
    energy0 = math.fsum(energy0_terms)
    energy1 = math.fsum([0.5 * rest * omega1 * omega1] + [0.5 * p.mass * after[name] ** 2 for name, p in (*leave, *bounce, *walk)])
    if bounce:
        name, p = bounce[0]  # alone with the body: a collision along its line with the body's point, of mass I/r⊥² there
        approach = p.speed - omega0 * p.arm
        lost = 0.5 * p.mass * inertia / (inertia + p.mass * p.arm**2) * (1 - p.e) * (1 + p.e) * approach * approach
    elif not leave:
        spread = math.fsum(i_j * i_k * (w_j - w_k) ** 2 for n, (_, i_j, w_j) in enumerate(joined) for (_, i_k, w_k) in joined[n + 1:])
        lost = (0.5 * spread / i_before if i_before else 0.0) + (0.5 * momentum_joined**2 / i_before * math.fsum(extra_inertia) / i_after if i_before else 0.0)
        lost += math.fsum(radial_energy)
        lost -= _walkers_work(walk, rest, i_after, rho_of)
    else:
        # as above, with what each leaving particle takes: ½m(v − v′)[(v − r⊥ω_a) + (v′ − r⊥ω₁)], ω_a = L_joined/I₁, a sum
        # of exchanges rather than the difference of two totals (which a heavy couple makes large)
        spread = math.fsum(i_j * i_k * (w_j - w_k) ** 2 for n, (_, i_j, w_j) in enumerate(joined) for (_, i_k, w_k) in joined[n + 1:])
        omega_a = momentum_joined / i_after
        lost = math.fsum([
            0.5 * spread / i_before if i_before else 0.0,
            0.5 * momentum_joined**2 / i_before * math.fsum(extra_inertia) / i_after if i_before else 0.0,
            *(0.5 * p.mass * (p.speed - p.speed_after) * ((p.speed - p.arm * omega_a) + (p.speed_after - p.arm * omega1)) for _, p in leave),
            *radial_energy,
        ])
    results = Results(TABLE)
    results.put("omega1", omega1, " (the body and all that stays on it)" if len(joined) > 1 else "")
    results.put("delta_omega", delta_omega)
    results.put("inertia", inertia)
    results.put("omega0", omega0)
    results.put("J", inertia * delta_omega, " the body receives, IΔω")
    results.put("L0", momentum0)
    results.put("L1", momentum0, " (the same: no external torque about the axis)")
    system = ", particles' ½mv² included" if particles else (", both bodies" if len(couples) == 1 else ", all the bodies")
    results.put("KE0", energy0, system)
    results.put("KE1", energy1, system)
    results.put("KE_lost", lost, " into heat and deformation" if lost >= 0 else ": negative, energy was added")
    results.put("KE_lost_fraction", lost / energy0 if energy0 > 0 else None)
    if energy0 == 0:
        notes.append("KE_lost_fraction: nothing moved before, so no fraction of it can be lost")
    # Each one's part: L before and after, the angular impulse it receives, its speed after.
    rows = [("body", inertia * omega0, inertia * omega1, inertia * delta_omega, None)]
    for name, i_c, w_c in couple_rows:
        rows.append((name, i_c * w_c, i_c * omega1, i_c * exchange(w_c) / i_effective, None))  # I_c(ω₁ − ω_c), from the exchange
    for name, p in stick:  # m(ρ²ω₁ − v r⊥) = mρ²(ω₁ − v r⊥/ρ²)
        r1 = rho_of(p)
        change = p.mass * r1**2 * exchange(p.speed * p.arm / r1**2) / i_effective if r1 else -p.mass * p.speed * p.arm
        if p.speed_relative is not None:  # m ρ (ω₁ρ + v_rel) − m v r⊥
            change += p.mass * r1 * p.speed_relative
        rows.append((name, p.mass * p.speed * p.arm, p.mass * r1 * after.get(name, omega1 * r1), change, after.get(name, omega1 * r1)))
    for name, p in ride:  # m(ρ²ω₁ − r²ω₀) = m(ρ²Δω + (ρ − r)(ρ + r)ω₀)
        r1 = rho_of(p)
        change = p.mass * math.fsum([r1**2 * delta_omega, (r1 - p.radius) * (r1 + p.radius) * omega0, r1 * (p.speed_relative or 0.0)])
        rows.append((name, p.mass * p.radius**2 * omega0, p.mass * r1 * after.get(name, omega1 * r1), change, after.get(name, omega1 * r1)))
    for name, p in leave:
        rows.append((name, p.mass * p.speed * p.arm, p.mass * after[name] * p.arm, p.mass * p.arm * (p.speed_after - p.speed), after[name]))
    for name, p in bounce:  # v′ − v = r⊥Δω − (1 + e)(v − ω₀r⊥)
        change = p.mass * p.arm * math.fsum([p.arm * delta_omega, -(1 + p.e) * (p.speed - omega0 * p.arm)])
        rows.append((name, p.mass * p.speed * p.arm, p.mass * after[name] * p.arm, change, after[name]))
    order = {name: n for n, name in enumerate(["body", *(r[0] for r in couple_rows), *(f"particle {k}" if len(particles) > 1 else "particle" for k in range(1, len(particles) + 1))])}
    rows.sort(key=lambda row: order[row[0]])
    speeds = [row[4] for row in rows if row[0].startswith("particle")]  # each particle's speed after, signed (#42 item 16)
    if speeds:
        results.put("speed_after", speeds[0] if len(speeds) == 1 else None, " (signed: positive in the body's sense)")
        if len(speeds) > 1:
            notes.append("speed_after: given for one particle; with several, the parts table gives each one's (v after)")
    columns = (("part", None, "part"), ("L0", "kg*m**2/s", "L₀"), ("L1", "kg*m**2/s", "L₁"), ("J", "N*m*s", "J = ΔL"), ("speed_after", "m/s", "v after"))
    tables = {"parts": Table(columns, tuple(rows))}
    # Steps.
    steps.insert(len(inertia_steps), Step(
        "No external torque about the axis: angular momentum is conserved",
        "L₀ = L₁:  Iω₀ + Σ I_c ω_c + Σ m v r⊥ = I₁ω₁ + Σ m v′ r⊥" + (" + Σ m ρ v_rel" if walk else ""),
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
    for name, p in walk:
        steps.append(Step(f"Speed of the {name} after", "v′ = ω₁ρ + v_rel", f"{term(omega1, 'rad/s')} × {term(rho_of(p), 'm')} + {term(p.speed_relative, 'm/s')}",
                          quantity_text(after[name], "m/s"), "it moves along the rim at v_rel relative to the body, whose point there moves at ω₁ρ"))
    if bounce:
        name, p = bounce[0]
        steps.append(Step("Restitution along the particle's line", "v′ − ω₁r⊥ = −e (v − ω₀r⊥)", f"e = {fmt(p.e)}, r⊥ = {fmt(p.arm)} m", "",
                          "the speed at which the particle and the body's point separate is e times the speed at which they approached"))
    top = "L₀" + (" − Σ m ρ v_rel" if walk else "") + (" − Σ m v′ r⊥" if leave else "") + (" + Σ m r⊥ e (v − ω₀r⊥)" if bounce else "")
    bottom = "I₁" + (" + Σ m r⊥²" if bounce else "")
    equation = f"ω₁ = {f'({top})' if top != 'L₀' else top} / {f'({bottom})' if bottom != 'I₁' else bottom}"
    steps.append(Step("Angular velocity after", equation, f"{term(numerator, 'kg*m**2/s')} / {term(i_effective, 'kg*m**2')}", quantity_text(omega1, "rad/s"),
                      "L₀ = L₁ solved for the one unknown"))
    for name, p in bounce:
        steps.append(Step(f"Speed of the {name} after", "v′ = ω₁r⊥ − e (v − ω₀r⊥)", f"{term(omega1, 'rad/s')} × {term(p.arm, 'm')} − {fmt(p.e)} × ({term(p.speed, 'm/s')} − {term(omega0, 'rad/s')} × {term(p.arm, 'm')})",
                          quantity_text(after[name], "m/s"),
                          "the restitution law solved for v′: " + ("negative, it bounces back" if after[name] < 0 else "it follows the body's point, which now moves away at least as fast")))
    why_walk = ("kinetic energy is not conserved: the walker's legs (a train's motor) push on the body and do work inside the system; "
                "the body gains the energy of its turn, the walker that of its speed over the ground")
    why_energy = why_walk if walk else ("kinetic energy is not conserved: while the two come to move together they slide on each other (or the particle deforms, "
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
        steps.append(Step("The energy lost, as the bodies' spread of speeds", "KE_lost = ½ Σ_{j<k} I_j I_k (ω_j − ω_k)² / ΣI + ½ I ω̄² ΔI/I₁ + ½m(v cos φ)²"
                          + (" − ½ I_rest Σ m v_rel² / I₁ (the walkers' work)" if walk else ""),
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
    stick_only = [p for _, p in stick if p.speed_relative is None]
    ride_only = [p for _, p in ride if p.speed_relative is None]
    if stick_only:
        what.append("a particle that sticks" if len(stick_only) == 1 else "particles that stick")
    if walk:
        what.append("a particle moving along the body" if len(walk) == 1 else "particles moving along the body")
    if ride_only:
        what.append("a particle riding on the body" if len(ride_only) == 1 else "particles riding on the body")
    if leave:
        what.append("a particle that leaves" if len(leave) == 1 else "particles that leave")
    if bounce:
        what.append("a particle that rebounds (restitution)" if len(bounce) == 1 else "particles that rebound (restitution)")
    if centre is not None and not couples:
        put_momentum(results, steps, notes, centre, particles, omega0, omega1, after, {row[0]: row[3] for row in rows})
    model = "no external torque about the axis: L conserved; " + ", ".join(what)
    return Report("impulse", model, "closed form", results, steps, notes, {}, tables)


def _walkers_work(walk, rest: float, i_after: float, rho_of) -> float:
    """The energy the walkers' own legs (the trains' motors) add: Σ ½ m v_rel² − (Σ m ρ v_rel)²/(2I₁),
    as ½ [I_rest Σ m v_rel² + Σ_{i<j} m_i m_j (v_i ρ_j − v_j ρ_i)²] / I₁ (Lagrange's identity; I_rest = I₁ − Σ m ρ²
    of the walkers), every term ≥ 0, no difference of near-equal energies."""
    if not walk:
        return 0.0
    pairs = [(p.mass, rho_of(p), p.speed_relative) for _, p in walk]
    cross = math.fsum(m_i * m_j * (v_i * r_j - v_j * r_i) ** 2 for n, (m_i, r_i, v_i) in enumerate(pairs) for (m_j, r_j, v_j) in pairs[n + 1:])
    return 0.5 * math.fsum([rest * math.fsum(m * v * v for m, _, v in pairs), cross]) / i_after


def _walkers_speeds(walk, rest: float, i_after: float, momentum0: float, rho_of) -> dict[str, float]:
    """Each walker's speed over the ground after, v′_k = ω₁ρ_k + v_k, with ω₁ = (L₀ − Σ m ρ v)/I₁ put in:
    [ρ_k L₀ + v_k I_rest + Σ_{j≠k} m_j ρ_j (v_k ρ_j − ρ_k v_j)] / I₁, which keeps its digits where the
    walker barely moves over the ground (a heavy train on a light wheel)."""
    speeds = {}
    for name, p in walk:
        r, v = rho_of(p), p.speed_relative
        others = (q for other, q in walk if other != name)
        speeds[name] = math.fsum([r * momentum0, v * rest, *(q.mass * rho_of(q) * (v * rho_of(q) - r * q.speed_relative) for q in others)]) / i_after
    return speeds
