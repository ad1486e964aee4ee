"""A body on a pivot under gravity, a torsion spring, or both: the physical pendulum.

    I d²θ/dt² = −mgd sin θ − κθ        (θ from the downward vertical, d pivot to centre of mass)

Energy gives the speeds and the pivot's forces at any angle, exactly, for every method:
½Iω² + mgd(1 − cos θ) + ½κθ² is constant (swing.py, pivot.py). The motion in time is

- gravity alone (κ = 0): exact, with k = sin(θ_max/2): sin(θ/2) = k sn(ω₀t + u₀, k), ω = 2kω₀ cn,
  period 4K(k)/ω₀, ω₀ = √(mgd/I); over the top (k > 1) it circulates with modulus 1/k
  (taucli/numerics/elliptic.py, every function from k' = cos(θ_max/2) so that 179.999° keeps its digits)
  (exact.py);
- torsion alone (d = 0): exact, harmonic, period 2π√(I/κ) (harmonic.py);
- both: no closed form, but the energy integral t = ∫dθ/ω between the turning angles, by
  tanh-sinh quadrature (by_energy.py);
- euler, rk4, rk45, verlet on request: θ'' = α(θ) stepped, events located, each checked against
  the exact model (stepped.py);
- small-angle: the harmonic model sin θ ≈ θ at any amplitude, its period error stated
  (small_angle.py).

motion.py picks the model for --method and asks it; body.py reads the body, point.py the point at
--at, steps.py writes the worked steps.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.pendulum import COMMAND as TABLE
from taucli.options.pendulum import COMPONENTS
from taucli.writing.report import DeferredSteps, Report, deferred, fmt
from taucli.scenes.assumed import Assumed
from taucli.scenes.pendulum import clock
from taucli.scenes.pendulum.body import moved, on_pivot, read_body
from taucli.scenes.pendulum.damped_scene import damped_swing
from taucli.scenes.pendulum.exact import exact_model
from taucli.scenes.pendulum.harmonic import Harmonic
from taucli.scenes.pendulum.motion import choose, pick_model, put_motion, put_state, solve, trajectory
from taucli.scenes.pendulum.pivot import put_pivot
from taucli.scenes.pendulum.reach import put_reach
from taucli.scenes.pendulum.rough_answer import rough_report
from taucli.scenes.pendulum.point import put_point
from taucli.scenes.pendulum.small_angle import small_angle_note
from taucli.scenes.pendulum.stepped import DEFAULT_DT, DEFAULT_RTOL, BlewUp, Stepped, withhold_if_off
from taucli.scenes.pendulum.steps import method_words, model_words, worked_steps
from taucli.scenes.pendulum.swing import Swing, put_energy
from taucli.scenes.pendulum.zero import Zero
from taucli.options.table import Results

__all__ = ["BlewUp", "Harmonic", "Stepped", "Swing", "exact_model", "pendulum"]


def pendulum(
    *,
    inertia: float | None = None,
    shape: str | None = None,
    mass: float | None = None,
    axis: str | None = None,
    offset: float | None = None,
    part: Sequence = (),
    gyration: float | None = None,
    density=None,
    cm_distance: float | None = None,
    length_offset: float | None = None,
    angle0: float | None = None,
    omega0: float | None = None,
    omega_bottom: float | None = None,
    from_top: bool | None = None,
    torsion: float | None = None,
    viscous: float | None = None,
    pivot_friction: float | None = None,
    g: float | None = None,
    start_time: float | None = None,
    angle: float | None = None,
    time: float | None = None,
    at: float | None = None,
    components: bool | None = None,
    method: str | None = None,
    dt: float | None = None,
    rtol: float | None = None,
    **dims: float | None,
) -> Report:
    """``taucli pendulum``: the body (--inertia with --mass and --cm-distance, or --shape ...), its
    start (--angle0 from the downward vertical, or the upward one --from-top; --omega0, or
    --omega-bottom from the bottom), gravity, --torsion and a couple at the pivot (--pivot-friction,
    rough_answer.py), what to report."""
    assumed = Assumed()
    zero = Zero(bool(from_top))
    if from_top and torsion:
        raise InputError("from_top", "is for a body under gravity alone: a spring's torque κθ is zero at the bottom, where θ is measured from")
    for name, given in (("angle0", angle0), ("angle", angle)):
        if from_top and given is not None and abs(given) > math.pi:
            raise InputError(name, "expected an angle from −180 to 180 deg from the top", got=f"{fmt(math.degrees(given))} deg")
    if from_top and angle0 is None and omega_bottom is None:
        angle0 = 0.0  # --angle0's default, 0: from the top, the top
    angle0, angle = zero.inward(angle0), zero.inward(angle)
    if omega_bottom is not None:
        angle0, omega0 = start_at_the_bottom(omega_bottom, angle0, omega0, zero)
    body = moved(read_body(inertia, shape, mass, axis, offset, part, cm_distance, dims, torsion, assumed, gyration, density), length_offset)
    swing, gravity = on_pivot(body, torsion, g, angle0, omega0, angle, assumed)
    if pivot_friction and (viscous is not None or start_time is not None):
        raise InputError("pivot_friction", "is not taken with {viscous} or {start_time} yet: a rough pivot's swing is stepped leg by leg "
                         "from its own start", hint="give one of them")
    if pivot_friction:
        return assumed.applied(rough_report(body, swing, gravity, pivot_friction, method, rtol, angle, time, at, bool(components), body.words, zero))
    since = clock.since(time, start_time, swing)
    if viscous is not None:
        return assumed.applied(damped_swing(swing, body, viscous, method or "auto", dt or DEFAULT_DT, rtol or DEFAULT_RTOL, time, since, start_time,
                                            zero, angle=angle, at=at, components=components))
    clocked, time = time, since  # the motion's own time from here (the clock's where --start-time is given)
    method = choose(method or "auto", swing.gravity_torque > 0, swing.torsion > 0)
    dt, rtol = dt or DEFAULT_DT, rtol or DEFAULT_RTOL
    results = Results(TABLE)
    notes: list[str] = []

    exact = exact_model(swing)
    put_energy(results, notes, swing, body.cm_distance, angle, exact, zero)  # energy and the exact motion: the same for every method
    put_reach(results, notes, swing, body.cm_distance, exact, zero)
    model = pick_model(swing, method, exact, dt, rtol)
    motion = solve(model, exact, method, angle, time if not (time is not None and time < 0) else None, notes)
    if time is not None and time < 0:  # before the start: held at θ₀
        motion = motion._replace(state=(swing.theta0, 0.0))

    put_motion(results, notes, swing, exact, method, motion, angle, zero)
    speed_at_angle = results["omega"].value if angle is not None else None
    put_pivot(results, swing, body.mass, body.cm_distance, gravity, angle, None if speed_at_angle is None else abs(speed_at_angle), zero)
    if not components:
        for key in COMPONENTS:
            results.pop(key, None)
    put_state(results, notes, motion.state, angle, clocked, zero)
    if method == "small-angle" and swing.gravity_torque:
        notes.append(small_angle_note(swing, exact))
    if isinstance(model, Stepped) and not (time is not None and time < 0):
        withhold_if_off(results, notes, model, exact, motion.period, motion.t_bottom, motion.state, time, angle, zero)
    if start_time is not None and clocked is not None:
        notes.append(clock.note(clocked, start_time))

    steps = DeferredSteps(worked_steps, swing, body.mass, body.cm_distance, gravity, body.steps, dict(results), exact, method, angle, zero)
    report = Report(
        "pendulum", model_words(swing, method, exact, body.words), method_words(swing, method, dt, rtol), results, steps, notes,
        trajectory=deferred(clock.on_clock, deferred(trajectory, model, time if time is None or time > 0 else None, motion.period, motion.t_bottom, zero),
                            start_time, zero.outward(swing.theta0)),
    )
    if at is not None:
        put_point(report, swing, at, angle, gravity, zero)
    return assumed.applied(report)


def start_at_the_bottom(omega_bottom: float, angle0: float | None, omega0: float | None, zero: Zero) -> tuple[float, float]:
    """(θ₀, ω₀) for --omega-bottom: the body starts at the bottom with that angular velocity."""
    if omega0 is not None:
        raise InputError("omega_bottom", "conflicts with {omega0}: give the speed at the start or at the bottom", example="{omega_bottom} 3rad/s")
    if angle0 is not None and angle0 != 0:
        bottom = "180deg" if zero.top else "0"
        raise InputError("omega_bottom", f"starts the body at the bottom: {{angle0}} is then {bottom}; for a start elsewhere give {{angle0}} with {{omega0}}",
                         example="{angle0} 30deg {omega0} 2rad/s")
    return 0.0, omega_bottom
