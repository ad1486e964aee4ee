"""The report of a damped swing (--viscous): the body, the decay of small swings, and θ and ω at
--time from the damped model (damped.py). The answers that energy gives hold only without a loss:
each is null here, with one note saying why."""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.numerics import steppers as numerics
from taucli.options.pendulum import COMMAND as TABLE
from taucli.options.table import Results
from taucli.scenes.pendulum import clock
from taucli.scenes.pendulum.damped import Stepped, decay_results, model_of, words
from taucli.scenes.pendulum.motion import put_state
from taucli.scenes.pendulum.swing import Swing
from taucli.scenes.pendulum.zero import Zero
from taucli.writing.report import Report, Step, Trajectory, deferred, fmt, quantity_text

BY_ENERGY = ("omega_bottom", "KE_bottom", "amplitude", "rise", "t_bottom", "period", "pivot_force0", "pivot_force_bottom", "goes_over", "omega0_over")


def damped_swing(swing: Swing, body, viscous: float, method: str, dt: float, rtol: float, time: float | None, since: float | None,
                 start_time: float | None, zero: Zero, *, angle=None, at=None, components=None) -> Report:
    for name, given in (("angle", angle), ("at", at), ("components", components), ("from_top", zero.top or None)):
        if given is not None:
            raise InputError(name, "is answered from the energy, which a damped swing ({viscous}) does not keep: not with {viscous}",
                             hint="leave out {viscous}, or ask for θ and ω at {time}")
    model = model_of(swing, viscous, method, dt, rtol)
    results = Results(TABLE)
    notes: list[str] = []
    results.put("I", swing.inertia)
    results.put("cm_distance", body.cm_distance)
    alpha0 = abs(model.accel(swing.theta0, swing.omega0)) if isinstance(model, Stepped) else abs(
        (swing.gravity_torque * math.sin(swing.theta0) + swing.torsion * swing.theta0 + viscous * swing.omega0) / swing.inertia)
    results.put("alpha0", alpha0)
    results.put("period_small", swing.small_period())
    tau, quality = decay_results(swing, viscous)
    results.put("decay_time", tau)
    results.put("quality_factor", quality)
    if body.mass and body.cm_distance > 0:
        results.put("equivalent_length", swing.inertia / (body.mass * body.cm_distance))
        results.put("centre_of_percussion", swing.inertia / (body.mass * body.cm_distance))
    results.not_applicable(*BY_ENERGY)
    notes.append("a damped swing loses energy: the answers energy gives (the speed at the bottom, the turning angle, the period at "
                 "an amplitude, the pivot's forces) are not given; θ and ω at {time} are")
    state = None
    if since is not None:
        try:
            state = (swing.theta0, 0.0) if since < 0 else model.state(since)
        except numerics.TooManySteps:
            notes.append(f"rk45 would take more than {numerics.MAX_ANGLE_STEPS['rk45']} steps to reach t = {fmt(time)} s at rtol = {fmt(rtol)}: "
                         "θ and ω there are left out (a larger {rtol})")
        put_state(results, notes, state, None, time, zero)
        if start_time is not None:
            notes.append(clock.note(time, start_time))
    steps = [Step(
        "The damped swing",
        "I θ'' = −mgd sin θ − κθ − bθ',  γ = b/2I,  Ω₀² = (mgd + κ)/I",
        f"I = {quantity_text(swing.inertia, 'kg*m**2')}, b = {fmt(viscous)} N·m·s/rad",
        f"τ = 2I/b = {quantity_text(tau, 's')}, Q = Ω₀I/b = {fmt(quality)}" if tau is not None and quality is not None else "",
        "a torque bω against the motion; small swings decay as e^(−t/τ)" + (" (the small-angle model: the damped harmonic oscillator)"
                                                                            if method == "small-angle" else "; θ(t) stepped by rk45"),
    )]
    method_text = "closed form (damped harmonic, small-angle)" if method == "small-angle" else f"rk45 (rtol = {fmt(rtol)})"
    horizon = time if time is not None and time > 0 else 3 * (tau or 0.0) or 10 * swing.small_period()
    return Report("pendulum", words(method, viscous), method_text, results, steps, notes,
                  trajectory=deferred(clock.on_clock, deferred(_trajectory, swing, viscous, method, dt, rtol, horizon if since is None or since > 0 else
                                                               10 * swing.small_period(), zero), start_time, swing.theta0))


def _trajectory(swing: Swing, viscous: float, method: str, dt: float, rtol: float, t_end: float, zero: Zero) -> Trajectory:
    """θ(t) and ω(t) on the motion's own time, from a model of its own (stepping on sample by sample)."""
    model = model_of(swing, viscous, method, dt, rtol)
    curves = (("theta", "rad", "angle from the downward vertical"), ("omega", "rad/s", "angular velocity ω"))
    return Trajectory(curves, t_end, model.state)
