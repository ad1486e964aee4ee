"""``taucli impulse``: what is given picks the model, and that model's module solves it."""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from taucli.core.errors import InputError, Unused
from taucli.writing.report import Report, Step
from taucli.scenes.assumed import Assumed
from taucli.scenes.centrifugal import with_centrifugal
from taucli.options.impulse import COMMAND as TABLE
from taucli.scenes.given import Band, Brake, Couple, Face, Particle
from taucli.scenes.impulse.after import body_after, body_centre, inertia_change, with_period
from taucli.scenes.impulse.balance import solve_balance
from taucli.scenes.impulse.caught import inertia_after, then_torque
from taucli.scenes.impulse.braked import braked_kinematics, solve_braked
from taucli.scenes.impulse.changing_inertia import solve_changing_inertia
from taucli.scenes.impulse.clutch import solve_clutch
from taucli.scenes.impulse.meeting import solve_meeting
from taucli.scenes.impulse.momentum import solve_momentum
from taucli.scenes.impulse.of_time import formula_impulse
from taucli.numerics.of_time import OfTime
from taucli.scenes.impulse.point import point_after
from taucli.scenes.impulse.sampled import solve_profile
from taucli.scenes.inertia import body, body_notes, part_inertia
from taucli.scenes.push import Push, drive_steps


@with_centrifugal(TABLE)
def impulse(
    *,
    omega0: float | None = None,
    omega1: float | None = None,
    momentum0: float | None = None,
    momentum1: float | None = None,
    impulse: float | None = None,
    torque: float | None = None,
    force: float | None = None,
    lever: float | None = None,
    push_angle: float | None = None,
    duration: float | None = None,
    inertia_final: float | None = None,
    part_after: Sequence = (),
    torque_profile: Iterable[tuple[float, float]] | None = None,
    method: str = "auto",
    particle: Sequence[Particle] = (),
    couple: Sequence[Couple] = (),
    at: float | str | None = None,
    brake: Sequence[Brake] = (),
    face: Sequence[Face] = (),
    band: Sequence[Band] = (),
    caliper: Sequence = (),
    g: float | None = None,
    **body_options,
) -> Report:
    """``taucli impulse``: τΔt = IΔω solved for the one left out; or a moment of inertia that
    changes with no torque (--inertia-final); or a sampled torque (--torque-profile); --at r, a
    point of the body before and after.

    The model, by what is given: --brake or --face, a constant torque against friction
    (braked); --particle or --couple, L conserved as they meet the body (meeting; a couple
    with torque=, through a clutch that slips: clutch);
    --inertia-final, I₀ω₀ = I₁ω₁ (changing_inertia); --torque-profile, J = ∫τ dt (sampled);
    else τΔt = I(ω₁ − ω₀) (balance). Each refuses what does not belong to it, then solves.
    A push (--force at --lever) adds its torque F r sin φ to --torque's. --part-after gives the
    body after a change (its I is --inertia-final's); after each model, the period 2π/|ω₁|."""
    after_steps: list[Step] = []
    change = None
    if part_after:
        inertia_final, after_steps = body_after(part_after, inertia_final, body_options)
        change = inertia_change(part_after, body_options)
    momenta = {"momentum0": momentum0, "momentum1": momentum1, "impulse": impulse}
    if isinstance(torque, OfTime):
        others = {"force": force, "lever": lever, "push_angle": push_angle, "inertia_final": inertia_final, "part_after": part_after or None,
                  "torque_profile": torque_profile, "particle": particle, "couple": couple, "at": at, "brake": brake, "face": face, "band": band,
                  "caliper": caliper, "g": g, **momenta}
        inertia, steps = _body(body_options)
        return with_period(formula_impulse(torque, duration, inertia, omega0, omega1, others, method, steps))
    report = _impulse(omega0, omega1, torque, force, lever, push_angle, duration, inertia_final, after_steps, torque_profile, method, particle, couple,
                      at, brake, face, band, g, body_options, change, momenta, tuple(caliper or ()))
    said = body_notes(body_options) + (body_notes({**body_options, "part": tuple(part_after)}) if part_after else [])
    said += [note for c in couple if c.part is not None for note in part_inertia(c.part).notes]  # a body met, by its shape
    report.notes[:0] = [note for note in dict.fromkeys(said) if note not in report.notes]  # what was assumed of a body, first (#42 item 3)
    return with_period(report)


def _impulse(omega0, omega1, torque, force, lever, push_angle, duration, inertia_final, after_steps, torque_profile, method, particle, couple,
             at, brake, face, band, g, body_options: dict, change: float | None = None, momenta: dict | None = None, caliper: tuple = ()) -> Report:
    """The model by what is given (see ``impulse``)."""
    momenta = {name: value for name, value in (momenta or {}).items() if value is not None}
    if at is not None:
        # the run without --at (its ΔI from the parts that changed, where --part-after gave them), then the point
        report = with_period(_impulse(omega0, omega1, torque, force, lever, push_angle, duration, inertia_final, after_steps, torque_profile, method,
                                      particle, couple, None, brake, face, band, g, body_options, change, momenta, caliper))
        given = {"omega0": omega0, "omega1": omega1, "torque": _with_push(torque, force, lever, push_angle)[0], "duration": duration, "inertia": _body(body_options)[0]}
        if brake or face or band or caliper:  # friction acts too: α and the angle from the braked motion (it may stop, or turn back)
            w0 = report.inputs["omega0"].value if "omega0" in report.inputs else omega0
            g_face = g if g is not None else (report.inputs["g"].value if "g" in report.inputs else None)
            given.update(braked_kinematics(given["inertia"], w0, given["torque"], duration, tuple(brake), tuple(face), g_face, body_options, tuple(band),
                                           caliper))
        return point_after(report, at, body_options.get("radius", body_options.get("outer_radius")), given)

    inertia, inertia_steps = _body(body_options)
    torque, formed = _with_push(torque, force, lever, push_angle)
    inertia_steps = (*inertia_steps, *formed)
    if momenta:  # L₀, L₁ or J given as such: ΔL = J = τΔt, L = Iω
        others = {"brake": brake or None, "face": face or None, "band": band or None, "caliper": caliper or None, "particle": particle or None, "couple": couple or None,
                  "inertia_final": inertia_final, "torque_profile": torque_profile, "g": g}
        for name, value in others.items():
            if value is not None:
                raise InputError(name, f"does not combine with {{{next(iter(momenta))}}}: an angular momentum or impulse given as such is for "
                                 "one body and a torque (ΔL = J = τΔt)", example="{momentum0} '2.4kg*m^2/s' {momentum1} '3.6kg*m^2/s' {duration} 4s")
        if method != "auto":
            raise InputError("method", "applies to {torque_profile} (trapezoid or simpson)")
        return solve_momentum(inertia, omega0, omega1, torque, duration, momenta.get("momentum0"), momenta.get("momentum1"), momenta.get("impulse"),
                              inertia_steps=inertia_steps)
    if brake or face or band or caliper:
        _check_braked(method, g, face, inertia, omega1, torque, duration,
                      {"inertia_final": inertia_final, "torque_profile": torque_profile, "particle": particle or None, "couple": couple or None})
        assumed = Assumed()
        omega0 = _at_rest_unless_given(omega0, assumed)
        gravity = assumed.gravity(g) if any(plate.by_weight for plate in face) else None
        return assumed.applied(solve_braked(inertia, omega0, torque, duration, tuple(brake), tuple(face), gravity, body_options,
                                            inertia_steps=inertia_steps, bands=tuple(band), calipers=caliper))
    if g is not None:
        raise Unused("g", "is used only for the weight on a {face} with no force=, or to read a weight given for a mass")
    if particle or couple:
        # a torque after the collision (catch a ball, then stop the arm): two of τ, Δt, ω₁
        afterwards = any(value is not None for value in (omega1, torque, duration))
        _check_meeting("particle" if particle else "couple", method, inertia,
                       {"inertia_final": inertia_final, "torque_profile": torque_profile,
                        **({} if afterwards else {"omega1": omega1, "torque": torque, "duration": duration})})
        assumed = Assumed()
        omega0 = _at_rest_unless_given(omega0, assumed)
        if any(c.torque is not None for c in couple):
            if particle or len(couple) > 1:
                raise InputError("couple", "with torque= (a clutch that slips) is solved for one {couple} and the body alone: "
                                 "give the other bodies and the particles a run each", example='{couple} "inertia=3kg*m^2 omega0=0 torque=50N*m"')
            if afterwards:
                given = " or ".join(f"{{{name}}}" for name, value in (("torque", torque), ("duration", duration), ("omega1", omega1)) if value is not None)
                raise InputError("couple", f"with torque= (a clutch that slips) takes no {given} after: give the torque a run of its own")
            return assumed.applied(solve_clutch(inertia, omega0, couple[0], inertia_steps=inertia_steps))
        centre = body_centre(body_options) if particle and not couple else None
        collision = solve_meeting(inertia, omega0, tuple(particle), tuple(couple), inertia_steps=inertia_steps, centre=centre)
        if afterwards:
            couple_inertias = [part_inertia(c.part).inertia if c.part is not None else c.inertia for c in couple]
            left = len(particle) == 1 and not couple and particle[0].speed is not None and (particle[0].speed_after is not None or particle[0].e is not None)
            collision = then_torque(collision, inertia_after(inertia, tuple(particle), tuple(couple), couple_inertias), omega1, torque, duration, left)
        return assumed.applied(collision)
    if inertia_final is None and torque_profile is None:
        if method != "auto":
            raise InputError("method", "applies to {torque_profile} (trapezoid or simpson); constant torque has a closed form")
        return solve_balance(inertia, omega0, omega1, torque, duration, inertia_steps=inertia_steps)
    mode = "inertia_final" if inertia_final is not None else "torque_profile"
    _check_changing_or_sampled(mode, inertia, {"omega1": omega1, "torque": torque, "duration": duration,
                                       "inertia_final": inertia_final if mode != "inertia_final" else None,
                                       "torque_profile": torque_profile if mode != "torque_profile" else None})
    if mode == "inertia_final":
        return solve_changing_inertia(inertia, inertia_final, omega0 or 0.0, inertia_steps=(*inertia_steps, *after_steps), change=change)
    assumed = Assumed()
    omega0 = _at_rest_unless_given(omega0, assumed)
    return assumed.applied(solve_profile(inertia, omega0, torque_profile, rule=method, inertia_steps=inertia_steps))


def _body(body_options: dict) -> tuple[float | None, Sequence[Step]]:
    """The body's moment of inertia and the steps that found it, or (None, ()) where no body is given."""
    given = any(body_options.get(name) is not None for name in ("inertia", "shape", "gyration")) or bool(body_options.get("part"))
    return body(**body_options) if given else (None, ())


def _with_push(torque: float | None, force: float | None, lever: float | None, push_angle: float | None) -> tuple[float | None, list[Step]]:
    """The torque with a push's added (--force at --lever, at --push-angle), and the steps that form it."""
    if force is None and lever is None and push_angle is None:
        return torque, []
    if force is None:
        raise InputError("force", "is required with {lever}", example="{force} 6N")
    if lever is None:
        raise InputError("lever", "is required with {force}", example="{lever} 0.2m")
    push = Push(force, lever) if push_angle is None else Push(force, lever, push_angle)
    return (torque or 0.0) + push.torque, drive_steps(push, torque)


def _at_rest_unless_given(omega0: float | None, assumed: Assumed) -> float:
    """ω₀ as given, or 0 (the body starts at rest), assumed with a note."""
    if omega0 is None:
        return assumed.value("omega0", 0.0, "rad/s", "no --omega0: the body starts at rest")
    return omega0


def _check_braked(method: str, g: float | None, faces: Sequence[Face], inertia: float | None, omega1: float | None,
                  torque: float | None, duration: float | None, others: dict) -> None:
    """A braked impulse has a closed form, takes --g only for a face's weight, solves for ω₁ and
    needs I, τ and Δt; it takes none of ``others``."""
    if method != "auto":
        raise InputError("method", "applies to {torque_profile} (trapezoid or simpson); a braked impulse has a closed form")
    if g is not None and not any(plate.by_weight for plate in faces):
        raise Unused("g", "is used only for the weight on a {face} with no force=, or to read a weight given for a mass")
    for name, value in others.items():
        if value is not None:
            raise InputError(name, "does not combine with {brake}, {face}, {band} or {caliper} here: they act with a constant {torque} over {duration}")
    if omega1 is not None:
        raise InputError("omega1", "is what {brake}, {face}, {band} and {caliper} let this solve for: leave it out")
    for name, value in (("inertia", inertia), ("torque", torque), ("duration", duration)):
        if value is None:
            raise InputError(name, "is required with {brake}, {face}, {band} or {caliper}: the friction's share is worked out over the motion, from the start",
                             example={"inertia": "{inertia} '0.5kg*m^2'", "torque": "{torque} '5N*m'", "duration": "{duration} 2s"}[name])


def _check_meeting(mode: str, method: str, inertia: float | None, conflicting: dict) -> None:
    """While particles or couples (``mode``) meet the body no external torque acts: none of
    ``conflicting``, no quadrature, and a body to meet."""
    for name, value in conflicting.items():
        if value is not None:
            raise InputError(name, f"conflicts with {{{mode}}}: while they meet, no external torque acts and L is conserved")
    if method != "auto":
        raise InputError("method", "applies to {torque_profile} (trapezoid or simpson)")
    if inertia is None:
        raise InputError("inertia", f"or {{shape}} is required with {{{mode}}}: the body they meet", example="{inertia} '500kg*m^2'")


def _check_changing_or_sampled(mode: str, inertia: float | None, conflicting: dict) -> None:
    """--inertia-final or --torque-profile (``mode``) takes none of ``conflicting`` and needs a body."""
    for name, value in conflicting.items():
        if value is not None:
            raise InputError(name, f"conflicts with {{{mode}}}")
    if inertia is None:
        raise InputError("inertia", f"or {{shape}} is required with {{{mode}}}", example="{inertia} '2kg*m^2'")
