"""A constant torque on a body that brakes or faces rub (#24): I dω/dt = τ − τ_f·sgn ω.

The friction torque τ_f is constant and against the turning (static μ holds the body at rest), so
within Δt the body may stop, stay held, or turn back with the friction reversed (motion.evolve
follows it in closed form). The net angular impulse I(ω₁ − ω₀) = τΔt − ∫τ_f sgn ω dt.
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, quantity_text, term
from taucli.scenes.inertia import body_mass
from taucli.scenes.contact import contacts
from taucli.core.errors import InputError
from taucli.scenes.given import Band, Brake, Face
from taucli.scenes.motion import Evolver, Loads, Method, evolve
from taucli.options.table import Results


def _motion(inertia: float, omega0: float, torque: float, brakes, faces, gravity, body_options: dict, bands=(), calipers=()):
    """The contacts' torques, and the motion under the torque against them (closed form)."""
    sided = [spec.source for spec in (*bands, *(shoe for shoe in brakes if shoe.sided))]
    if sided and omega0 and torque and (omega0 > 0) != (torque > 0):
        raise InputError(sided[0], "takes the torque for the sense the body turns, and a torque against ω₀ would stop it and turn it back "
                         "(the tight and slack ends, or the friction's moment, change over): give a torque along ω₀, or work the turn back in a second run",
                         example="{torque} '5N*m' {omega0} 100rpm")
    contact = contacts(brakes, faces, body_options, body_mass(**body_options) if faces else body_options.get("mass"), gravity, bands, calipers)
    loads = Loads(drive=torque, friction=contact.kinetic, static=contact.static)
    return contact, evolve(inertia, loads, omega0, Evolver(Method("exact")))


def braked_kinematics(inertia: float, omega0: float, torque: float, duration: float, brakes, faces, gravity, body_options: dict, bands=(),
                      calipers=()) -> dict:
    """α at the start and at the end of Δt (friction against the motion; held: 0), and the net
    angle turned, for a point on the body (--at)."""
    _, motion = _motion(inertia, omega0, torque, brakes, faces, gravity, body_options, bands, calipers)
    return {"alpha0": motion.initial_rate, "alpha": motion.rate_at(duration), "theta": motion.state_at(duration)[1]}


def solve_braked(
    inertia: float,
    omega0: float,
    torque: float,
    duration: float,
    brakes: Sequence[Brake],
    faces: Sequence[Face],
    gravity: float | None,
    body_options: dict,
    *,
    inertia_steps: Sequence[Step] = (),
    bands: Sequence[Band] = (),
    calipers: Sequence = (),
) -> Report:
    """A constant torque τ over Δt against a constant Coulomb torque τ_f of the brakes and faces
    (static μ holding the body at rest): I dω/dt = τ − τ_f·sgn ω in each stretch of motion one
    way; ω₁ at Δt, J = τΔt applied, J_net = I(ω₁ − ω₀), and each friction's torque, work over the
    angle swept both ways, and power at the start. ``gravity`` gives the weight on a face with no
    force= (None where every face has one); ``body_options`` give the radii the contacts take."""
    contact, motion = _motion(inertia, omega0, torque, brakes, faces, gravity, body_options, bands, calipers)
    omega_end, theta = motion.state_at(duration)
    stop = motion.stop if motion.stop is not None and motion.stop[0] < duration else None
    # the angle swept both ways: to the stop, then (turned back) from there
    swept = abs(theta) if stop is None else abs(stop[1]) + abs(theta - motion.signed_stop[1])
    results = Results(TABLE)
    impulse = torque * duration
    results.put("omega1", omega_end, " Δt")
    # with no stop within Δt the net torque is constant, so Δω = αΔt: not ω₁ − ω₀, which loses the
    # digits of a small change of a heavy wheel's speed (#42 item 8); through a stop |Δω| ≥ |ω₀|
    delta = motion.initial_rate * duration if stop is None else omega_end - omega0
    results.put("delta_omega", delta)
    results.put("J", impulse, " of the applied torque, τΔt")
    results.put("J_net", inertia * delta)
    results.put("L0", inertia * omega0)
    results.put("L1", inertia * omega_end, " Δt")
    energy0, energy1 = inertia * omega0 * omega0 / 2, inertia * omega_end * omega_end / 2
    results.put("KE0", energy0, "")
    results.put("KE1", energy1, " Δt")
    results.put("work", inertia * delta * (omega0 + omega_end) / 2)  # ½I(ω₁ − ω₀)(ω₁ + ω₀)
    speed0 = abs(omega0)
    for name, share, given in (("brake", contact.brake, brakes), ("face", contact.face, faces), ("band", contact.band, bands),
                               ("caliper", contact.caliper, calipers)):
        if given:
            results.put(f"torque_{name}", share)
            results.put(f"work_{name}", share * swept, " during Δt")
            results.put(f"power_{name}", share * speed0, " at the start")
    for key, value, part in contact.details:
        results.put(key, value, part)
    notes = list(contact.notes)
    if motion.held_from_start:
        notes.append(f"static friction holds the body: |τ| = {quantity_text(abs(torque), 'N*m')} does not exceed {quantity_text(contact.static, 'N*m')}")
    elif stop is not None:
        notes.append(f"the body stops at t = {quantity_text(stop[0], 's')} within Δt"
                     + (", and the torque turns it back, friction reversed" if motion.second is not None else ", and static friction holds it"))
    steps = [*inertia_steps, *contact.steps]
    steps.append(Step("Friction torques add", "τ_f = " + " + ".join(symbol for _, symbol, _ in contact.shares),
                      " + ".join(term(torque, "N*m") for _, _, torque in contact.shares), quantity_text(contact.kinetic, "N*m"),
                      "each is a constant torque against the motion: together one friction torque τ_f"))
    if not motion.held_from_start:
        alpha = motion.initial_rate
        steps.append(Step("Angular acceleration while it turns", "α = (τ − τ_f·sgn ω)/I",
                          f"({term(torque, 'N*m')} {'−' if motion.direction > 0 else '+'} {term(contact.kinetic, 'N*m')}) / {term(inertia, 'kg*m**2')}",
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
                      f"{term(torque, 'N*m')} × {term(duration, 's')};  {term(inertia, 'kg*m**2')} × ({term(omega_end, 'rad/s')} − {term(omega0, 'rad/s')})",
                      f"{quantity_text(impulse, 'N*m*s')};  {quantity_text(inertia * (omega_end - omega0), 'N*m*s')}",
                      "the friction's angular impulse is the difference: what the brakes and faces took from the torque's"))
    steps.append(Step("Energy the friction takes", "W_f = τ_f × angle swept", f"{term(contact.kinetic, 'N*m')} × {term(swept, 'rad')}",
                      quantity_text(contact.kinetic * swept, "J"), "a constant friction torque takes its torque for every radian swept, either way"))
    model = "constant torque with " + ", ".join(contact.models) + ": I dω/dt = τ − τ_f sgn ω (static μ holding at rest)"
    return Report("impulse", model, "closed form", results, steps, notes)
