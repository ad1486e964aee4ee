"""The time-stepped methods (euler, rk4, rk45, verlet): θ' = ω, ω' = α(θ) = −(mgd sin θ + κθ)/I
stepped by numerics.integrate_angle from t = 0 for each answer, the turning points, the bottom and
--angle located by re-stepping the step that crosses them; and their error checks.

A stepper's period (and its (θ, ω) at --time) is checked against the exact ones, or against
rk45's at rtol 1e-11 where there is no closed form; its answers are withheld where they are
further off than WITHHELD_ABOVE, relative.
"""

from __future__ import annotations

import math

from taucli.numerics import steppers as numerics
from taucli.writing.report import fmt
from taucli.scenes.pendulum.swing import TWO_PI, Swing
from taucli.scenes.pendulum.zero import Zero
from taucli.options.table import Results

STEPPERS = ("euler", "rk4", "rk45", "verlet")
DEFAULT_DT = 1e-3
DEFAULT_RTOL = 1e-10
REFERENCE_RTOL = 1e-11  # rk45's, for a stepper's error where there is no closed form
WITHHELD_ABOVE = 1e-3  # a stepper's answers are withheld when its period is further off, relative (as in spin-down)


class BlewUp(Exception):
    """A stepped run left the finite numbers: the step is far outside the method's stable range."""


class Stepped:
    """θ'' = α(θ) stepped by a method of numerics.integrate_angle, each answer from t = 0, all of
    them within one budget of steps (numerics.MAX_ANGLE_STEPS)."""
    def __init__(self, swing: Swing, method: str, dt: float, rtol: float, horizon: float):
        self.swing, self.method, self.dt, self.rtol, self.horizon = swing, method, dt, rtol, horizon
        natural = math.sqrt((swing.gravity_torque + swing.torsion) / swing.inertia)
        size = max(abs(swing.theta0), abs(swing.omega0) / natural, 1e-3)
        self.scale = (size, size * natural + abs(swing.omega0))
        self.steps = 0
        self.budget = numerics.MAX_ANGLE_STEPS[method]
        self._last = (0.0, swing.theta0, swing.omega0)  # where state() got to, to carry on from

    def _run(self, t_end: float, event=None, theta0=None, omega0=None) -> numerics.AngleSolution:
        start = (self.swing.theta0 if theta0 is None else theta0, self.swing.omega0 if omega0 is None else omega0)
        solution = numerics.integrate_angle(
            self.swing.accel, *start, t_end, self.method, dt=self.dt, rtol=self.rtol, scale=self.scale, event=event,
            max_steps=max(self.budget - self.steps, 1),
        )
        self.steps += solution.steps
        if not (math.isfinite(solution.theta) and math.isfinite(solution.omega)):
            raise BlewUp()
        return solution

    def state(self, t: float) -> tuple[float, float]:
        """(θ, ω) at t, carried on from the last time asked for when t is later (a plot's samples)."""
        t_last, theta, omega = self._last
        if t < t_last:
            t_last, theta, omega = 0.0, self.swing.theta0, self.swing.omega0
        if t > t_last:
            solution = self._run(t - t_last, theta0=theta, omega0=omega)
            theta, omega = solution.theta, solution.omega
        self._last = (t, theta, omega)
        return theta, omega

    def time_to(self, theta: float) -> float | None:
        if theta == self.swing.theta0:
            return 0.0
        if self.swing.speed_at(theta) is None:
            return None
        if self.swing.torsion:
            solution = self._run(self.horizon, lambda angle, _: angle - theta)
        else:  # under gravity alone θ and θ ± 2π are the same place (it may have gone over the top)
            solution = self._run(self.horizon, lambda angle, _: math.sin((angle - theta) / 2))
        return solution.t if solution.event else None

    def period(self, circulates: bool) -> float | None:
        if circulates:
            target = self.swing.theta0 + math.copysign(TWO_PI, self.swing.omega0)
            solution = self._run(self.horizon, lambda angle, _: angle - target)
            return solution.t if solution.event else None
        if self.swing.theta0 == 0 and self.swing.omega0 == 0:  # at rest at the bottom: the limit of small swings
            return self.swing.small_period()
        first = self._run(self.horizon, lambda _, speed: speed)
        if not first.event:
            return None
        second = self._run(self.horizon, lambda _, speed: speed, first.theta, first.omega)
        return 2 * second.t if second.event else None


def period_error(swing: Swing, exact, model: Stepped, period: float | None, notes: list[str]) -> float | None:
    """How far a stepper's period is from the exact one (or rk45's at rtol 1e-11 where there is
    none), relative; inf where it found no swing and the reference did; None with no reference."""
    if exact is not None:
        reference = exact.period
    else:
        try:
            reference = Stepped(swing, "rk45", model.dt, REFERENCE_RTOL, model.horizon).period(False)
        except (numerics.TooManySteps, BlewUp):
            reference = None
    if reference is None:
        notes.append(f"{model.method}'s error is not estimated: there is no reference period here")
        return None
    if period is None:
        return math.inf
    error = abs(period / reference - 1)
    against = "the exact one" if exact is not None else "rk45's at rtol 1e-11"
    step = f"rtol = {fmt(model.rtol)}" if model.method == "rk45" else f"dt = {fmt(model.dt)} s"
    notes.append(f"{model.method} at {step}: period {fmt(error, 2)} off {against} (relative)")
    return error


def state_error(swing: Swing, exact, model: Stepped, time: float, state: tuple[float, float], notes: list[str]) -> float:
    """How far a stepper's (θ, ω) at --time is from the exact one (or rk45's), as a fraction of
    the sizes the motion reaches (model.scale); 0 where there is no reference."""
    try:
        reference = exact.state(time) if exact is not None else Stepped(swing, "rk45", model.dt, REFERENCE_RTOL, model.horizon).state(time)
    except (numerics.TooManySteps, BlewUp):
        return 0.0
    error = max(abs(state[0] - reference[0]) / model.scale[0], abs(state[1] - reference[1]) / model.scale[1])
    notes.append(f"{model.method}: θ and ω at t = {fmt(time)} s {fmt(error, 2)} off {'the exact ones' if exact is not None else 'rk45' + chr(39) + 's'} (relative to the swing's size)")
    return error


def withhold_if_off(results: Results, notes: list[str], model: Stepped, exact, period: float | None, t_bottom: float | None,
                    state: tuple[float, float] | None, time: float | None, angle: float | None, zero: Zero = Zero()) -> None:
    """The stepper's error (period_error, then state_error at --time), with a note each; where it
    is more than WITHHELD_ABOVE its answers are withheld (null), with a note of what it gave and,
    for a fixed-step method of order p, the dt that would do: dt × (WITHHELD_ABOVE/10/error)^(1/p)."""
    # rk45 with no closed form to check it against is the reference itself: its tolerance holds
    if not (period is not None or t_bottom is not None or state is not None) or (exact is None and model.method == "rk45"):
        return
    error = period_error(model.swing, exact, model, period, notes)
    if state is not None and error is not None and error <= WITHHELD_ABOVE:
        error = max(error, state_error(model.swing, exact, model, time, state, notes))
    if not (error is not None and error > WITHHELD_ABOVE):
        return
    order = {"euler": 1, "verlet": 2, "rk4": 4}.get(model.method)
    shown = "no full swing" if period is None else f"a period of {fmt(period, 6)} s"
    shown += f" and {'φ' if zero.top else 'θ'} = {fmt(zero.outward(state[0]), 6)} rad at t = {fmt(time)} s" if state is not None else ""
    better = f"; --dt {fmt(model.dt * (WITHHELD_ABOVE / 10 / error) ** (1 / order), 2)}s would do" if order and math.isfinite(error) else ""
    notes.append(
        f"{model.method}'s answers are withheld: it gave {shown}, {fmt(error, 2) if math.isfinite(error) else 'far'} off the "
        f"{'exact' if exact is not None else 'rk45 (rtol 1e-11)'} one (more than {fmt(WITHHELD_ABOVE)}){better}"
    )
    for key in ("period", "t_bottom", "t_angle", "theta"):
        if key in results:
            results[key] = results[key]._replace(value=None)
    if time is not None and angle is None:
        results["omega"] = results["omega"]._replace(value=None)
