"""The motion in time: the method chosen, the model it picks, what the model is asked (the
period, the times to the bottom and to --angle, (θ, ω) at --time) and the plot.

Each model gives state(t) = (θ, ω), time_to(θ) (the first time it reaches an angle) and its period:

- exact: under gravity alone elliptic (exact.py), under a torsion spring alone harmonic, under both
  the energy integral t = ∫dθ/ω by quadrature (by_energy.py);
- small-angle: harmonic, sin θ ≈ θ (small_angle.py);
- euler, rk4, rk45, verlet: stepped (stepped.py), each checked against the exact model.
"""

from __future__ import annotations

from typing import NamedTuple

from taucli.numerics import steppers as numerics
from taucli.core.errors import InputError
from taucli.options.pendulum import COMMAND as TABLE
from taucli.writing.report import Trajectory, fmt
from taucli.scenes.pendulum.exact import Circulation, Separatrix
from taucli.scenes.pendulum.small_angle import small_angle_model
from taucli.scenes.pendulum.stepped import STEPPERS, BlewUp, Stepped
from taucli.scenes.pendulum.swing import Swing, fall_sense
from taucli.scenes.pendulum.zero import Zero
from taucli.options.table import Results


def choose(method: str, gravity: bool, torsion: bool) -> str:
    """--method, with auto read as exact: a closed form under gravity or a spring alone, the energy
    integral by quadrature under both."""
    if method == "auto":
        return "exact"
    if method not in ("exact", "small-angle", *STEPPERS):
        raise InputError("method", f"expected one of {', '.join(TABLE.option('method').choices)}", got=repr(method))
    return method


def pick_model(swing: Swing, method: str, exact, dt: float, rtol: float):
    """The model of the method: the exact one, the small-angle one, or a stepper that looks for
    its events up to three exact periods (20 small-swing periods where there is none)."""
    if method == "small-angle":
        return small_angle_model(swing)
    if method == "exact":
        return exact
    horizon = 20 * swing.small_period() if exact.period is None else 3 * exact.period
    return Stepped(swing, method, dt, rtol, horizon)


class Motion(NamedTuple):
    """What the model answered: None where it has no answer (or the stepper gave up)."""
    period: float | None
    t_bottom: float | None
    t_angle: float | None
    state: tuple[float, float] | None  # (θ, ω) at --time


def solve(model, exact, method: str, angle: float | None, time: float | None, notes: list[str]) -> Motion:
    """The model's period, times to the bottom and to --angle, and (θ, ω) at --time. A stepper
    that would take more steps than its budget, or blows up, answers none of them; with just the
    energy to reach the top there is no period (it takes forever to get there)."""
    try:
        if isinstance(model, Stepped):
            period = model.period(isinstance(exact, Circulation))
            if period is None:
                notes.append(f"period: {method} found no full swing within {fmt(model.horizon)} s")
        else:
            period = model.period
        t_bottom = model.time_to(0.0)
        t_angle = model.time_to(angle) if angle is not None else None
        if t_angle is None and angle is not None and isinstance(model, Stepped) and model.swing.speed_at(angle) is not None:
            notes.append(f"t_angle: the energy reaches θ = {fmt(angle)} rad, but {method} (whose swing turns within its tolerance of it) "
                         "did not: the angle is a hair short of a turning point, where the time hangs on the last digits; --method exact gives it")
        state = model.state(time) if time is not None else None
    except numerics.TooManySteps:
        limit = numerics.MAX_ANGLE_STEPS[method]
        step = f"rtol = {fmt(model.rtol)}" if method == "rk45" else f"dt = {fmt(model.dt)} s"
        notes.append(f"--method {method} would take more than {limit} steps at {step}; its answers are left out (a larger {{dt}}, or rk45)")
        period = t_bottom = t_angle = state = None
    except BlewUp:
        notes.append(f"--method {method} blew up at dt = {fmt(model.dt)} s (the step is far too large for it): its answers are left out")
        period = t_bottom = t_angle = state = None
    if isinstance(exact, Separatrix) and method != "small-angle":
        period = None
        notes.append(
            "period: none: the body is balanced at the top, an unstable balance: it stays there unless disturbed"
            if exact.balanced
            else "period: none: the body has just the energy to reach the top, and takes forever to get there"
        )
    return Motion(period, t_bottom, t_angle, state)


def put_motion(results: Results, notes: list[str], swing: Swing, exact, method: str, motion: Motion, angle: float | None, zero: Zero) -> None:
    """The period (of one turn where it goes over the top), the time to the bottom and to --angle."""
    circulating = isinstance(exact, Circulation)
    label = " of one turn (it goes over the top)" if circulating else " of the swing" + (" at this amplitude" if method != "small-angle" else ", small-angle model")
    results.put("period", motion.period, label)
    results.put("t_bottom", motion.t_bottom)
    balanced = isinstance(exact, Separatrix) and exact.balanced
    if motion.t_bottom is None and not balanced and results["omega_bottom"].value is not None and motion.period is not None:
        notes.append("t_bottom: not found")
    if balanced:
        way = (f"toward {zero.text(angle)}" if angle else "the way θ decreases") + f" (ω {'negative' if fall_sense(angle) < 0 else 'positive'})"
        notes.append(f"balanced at the top: speeds at an angle are those of a body that has just left the top, taken to fall {way}; "
                     "it takes forever to leave")
    if angle is not None:
        results.put("t_angle", motion.t_angle, f" {zero.text(angle)}")


def put_state(results: Results, notes: list[str], state: tuple[float, float] | None, angle: float | None, time: float | None, zero: Zero) -> None:
    """θ at --time (in the user's angles), and ω there unless --angle has ω already."""
    if time is None:
        return
    theta_t, omega_t = state if state is not None else (None, None)
    results.put("theta", zero.outward(theta_t), f" from the {'upward' if zero.top else 'downward'} vertical at t = {fmt(time)} s")
    if angle is None:
        results.put("omega", omega_t, f" at t = {fmt(time)} s")
    else:
        notes.append("omega is given at --angle; theta at --time (run without --angle for ω at the time)")


def trajectory(model, time: float | None, period: float | None, t_bottom: float | None, zero: Zero) -> Trajectory:
    """θ(t) and ω(t) to --time, else for two periods, else for 10 s (θ in the user's angles); a
    stepper is stepped once through 200 samples, within a budget of its own, and stops where it
    cannot go further."""
    if time:
        t_end, note = time, ""
    elif period:
        t_end, note = 2 * period, "plotted for two periods; --time to change"
    else:
        t_end, note = 10.0, "plotted for 10 s; --time to change"
    curves = (("theta", "rad", f"angle from the {'upward' if zero.top else 'downward'} vertical"), ("omega", "rad/s", "angular velocity ω"))
    if isinstance(model, Stepped):
        stepper = Stepped(model.swing, model.method, model.dt, model.rtol, model.horizon)
        points = [(0.0, zero.outward(stepper.swing.theta0), stepper.swing.omega0)]
        for i in range(1, 201):
            t = t_end * i / 200
            try:
                theta, omega = stepper.state(t)
                points.append((t, zero.outward(theta), omega))
            except (numerics.TooManySteps, BlewUp):
                t_end, note = points[-1][0], f"plotted for {fmt(points[-1][0])} s: {stepper.method} cannot go further"
                break
        marks = ((t_bottom, "at the bottom"),) if t_bottom and t_bottom <= t_end else ()
        return Trajectory(curves, t_end, None, points=tuple(points), marks=marks, note=note)
    marks = ((t_bottom, "at the bottom"),) if t_bottom else ()
    state = model.state if not zero.top else lambda t: _outward(zero, *model.state(t))
    return Trajectory(curves, t_end, state, marks=marks, note=note)


def _outward(zero: Zero, theta: float, omega: float) -> tuple[float, float]:
    return zero.outward(theta), omega
