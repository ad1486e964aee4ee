"""A motor of constant power P: I dω/dt = P/ω − τ_f − bω − kωⁿ (τ = P/ω; P < 0 a load).

With no losses ½Iω² changes at the rate P: a closed form. With losses there is none, and ω is
stepped by the method from a start just off rest, where P/ω dominates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.numerics import steppers as numerics
from taucli.core.errors import InputError
from taucli.numerics.quadrature import adaptive_gauss, gauss_legendre
from taucli.numerics.roots import falling_root
from taucli.options.spin_down import COMMAND as TABLE
from taucli.writing.report import Report, Step, deferred, fmt, quantity_text, term
from taucli.scenes.motion import DEFAULT_DT, DEFAULT_RTOL, Method
from taucli.scenes.spin.energy import energy_steps
from taucli.scenes.spin.methods import REFERENCE_RTOL, error_estimate
from taucli.scenes.spin.steps import TWO_PI, Torques, curves
from taucli.options.table import Results


@dataclass(frozen=True)
class PowerMotion:
    """The motion under a constant power P, in the frame where u = |ω| ≥ 0 (``sense`` = ±1).

    Without losses, ½Iu² grows (or, for P < 0, falls) at the rate P: u² = u₀² + 2Pt/I and
    θ = 2t(u² + uu₀ + u₀²)/(3(u + u₀)), which has no difference of near-equal numbers. With
    losses there is no closed form: u is stepped by the method, from a start just off rest where
    P/u dominates (so the lossless law carries the first ~1e-12 of the energy exactly enough),
    and a load (P < 0) is stopped the same way just before rest.
    """
    inertia: float
    power: float
    torques: Torques
    u0: float
    method: Method
    sense: float

    @property
    def lossless(self) -> bool:
        t = self.torques
        return not (t.friction or t.viscous or t.drag)

    def rate(self, u: float) -> float:
        t = self.torques
        drag = t.drag * u**t.drag_exponent if t.drag and u > 0 else 0.0
        u = max(u, 1e-300)  # finite below rest, so that a trial step past it is rejected, not accepted as NaN
        return (self.power / u - t.friction - t.viscous * u - drag) / self.inertia

    def stiffness(self, u: float) -> float:
        t = self.torques
        drag = t.drag_exponent * t.drag * u ** (t.drag_exponent - 1) if t.drag else 0.0
        return (abs(self.power) / (u * u) + t.viscous + drag) / self.inertia

    def _edge(self) -> float:
        """A speed near rest below which the losses are under 1e-7 of P/u."""
        t, p = self.torques, abs(self.power)
        scales = [p / t.friction if t.friction else math.inf, math.sqrt(p / t.viscous) if t.viscous else math.inf,
                  (p / t.drag) ** (1 / (t.drag_exponent + 1)) if t.drag else math.inf]
        return 1e-7 * min(scales)

    def lossless_state(self, t: float) -> tuple[float, float]:
        u0 = self.u0
        square = u0 * u0 + 2 * self.power * t / self.inertia
        u = math.sqrt(max(square, 0.0))
        return u, (2 * t * (u * u + u * u0 + u0 * u0) / (3 * (u + u0)) if u + u0 else 0.0)

    def stop(self) -> tuple[float, float] | None:
        """(t, θ) where a load brings the wheel to rest (None while P > 0)."""
        if self.power >= 0 or self.u0 == 0:
            return None if self.u0 or self.power >= 0 else (0.0, 0.0)
        if self.lossless:
            t = self.inertia * self.u0 * self.u0 / (2 * -self.power)
            return t, 2 * t * self.u0 / 3
        edge = self._edge()
        if self.u0 <= 2 * edge:  # already where the losses are under 1e-7 of P/ω: the lossless law
            return PowerMotion(self.inertia, self.power, Torques(), self.u0, self.method, self.sense).stop()
        solution = self._run(self.u0, math.inf, edge)
        tail = self.inertia * edge * edge / (2 * -self.power)
        return solution.t + tail, solution.theta + 2 * tail * edge / 3

    def _start(self) -> tuple[float, float, float]:
        """(t, u, θ) to step from: the start, or just off rest on the lossless law."""
        if self.u0 > 0 or self.power <= 0:
            return 0.0, self.u0, 0.0
        edge = self._edge()
        t = self.inertia * edge * edge / (2 * self.power)
        return t, edge, 2 * t * edge / 3

    def _run(self, u: float, t_end: float, event: float | None):

        method = self.method
        name = "rk45" if method.name == "exact" else method.name
        if t_end == math.inf:  # a bound on the time to the event: the energy to go, over the least net power on the way
            span = abs(self.inertia * (event - u) * (event + u) / 2)
            if self.power < 0:
                net = -self.power  # a load drains at least P; the losses only add to it
            else:
                steady = self.steady_speed()
                if steady is not None and (event - steady) * (u - steady) <= 0:  # at or past the steady speed: never
                    return None
                net = event * self.inertia * abs(self.rate(event))  # |P − ω·losses(ω)|, least at the event
            t_end = 1.01 * span / net
        try:
            return numerics.integrate(
                self.rate, u, t_end, name, dt=method.dt, rtol=method.rtol / 20, event_at=event, stiffness=self.stiffness,
            )
        except numerics.TooManySteps:
            raise InputError("rtol" if name == "rk45" else "dt", f"this run needs more than {numerics.MAX_STEPS[name]:,} {name} steps",
                             hint="use a looser --rtol, or a larger --dt") from None

    def state(self, t: float) -> tuple[float, float]:
        """(ω, θ) at t, signed."""
        omega, theta, _ = self.state_change(t)
        return omega, theta

    def state_change(self, t: float) -> tuple[float, float, float]:
        """(ω, θ, Δu) at t, ω and θ signed, Δu = |ω| − |ω₀| formed from what makes it (#42 item 8):
        2Pt/(I(u + u₀)) without losses (u² − u₀² = 2Pt/I), the sum of the steps' increments when
        stepped, never the difference of two speeds a heavy wheel's motor hardly parts."""
        stop = self.stop()
        if stop is not None and t >= stop[0]:
            return 0.0, self.sense * stop[1], -self.u0
        if self.lossless:
            u, theta = self.lossless_state(t)
            return self.sense * u, self.sense * theta, (2 * self.power * t / (self.inertia * (u + self.u0)) if u + self.u0 else 0.0)
        t0, u0, theta0 = self._start()
        if t <= t0:
            u, theta = PowerMotion(self.inertia, self.power, Torques(), self.u0, self.method, self.sense).lossless_state(t)
            return self.sense * u, self.sense * theta, u - self.u0
        solution = self._run(u0, t - t0, None)
        return self.sense * solution.omega, self.sense * (theta0 + solution.theta), solution.change + (u0 - self.u0)

    def time_to(self, target: float) -> tuple[float, float] | None:
        """(t, θ) when |ω| = target, or None."""
        u1 = target * self.sense
        if u1 == self.u0:
            return 0.0, 0.0
        rising = self.rate(self.u0) > 0  # above a motor's steady speed the wheel slows
        if u1 < 0 or (u1 > self.u0) != rising:
            return None
        if self.lossless:
            t = self.inertia * (u1 - self.u0) * (u1 + self.u0) / (2 * self.power)
            return t, self.sense * self.lossless_state(t)[1]
        if u1 == 0:
            stop = self.stop()
            return None if stop is None else (stop[0], self.sense * stop[1])
        t0, u0, theta0 = self._start()
        solution = self._run(u0, math.inf, u1)
        if solution is None or not solution.event:
            return None
        return t0 + solution.t, self.sense * (theta0 + solution.theta)

    def viscous_work(self, end: float, u_end: float, change: float, coefficient: float | None = None, exponent: float = 2.0) -> float:
        """b∫ω²dt over [0, end], the wheel at u_end = u₀ + ``change`` then (the change as the motion
        formed it, ``state_change``). dω/dt = f(ω) alone, so ω is monotone and the integral is
        b∫ω²/f(ω) dω from u₀ to u_end, where a fast fall from a high speed (drag) is resolved
        however short it is; it is taken as Δu∫₀¹ over u₀ + sΔu, so that its width is the change
        itself, not u_end − u₀ of two near-equal speeds (a heavy wheel; #42 item 8). The last
        approach to a steady speed ω*, where f → 0 and that integral turns ill-conditioned, is
        taken in time instead."""
        viscous, u0 = (self.torques.viscous if coefficient is None else coefficient), self.u0  # or c∫|ω|ᵖdt, the drag's
        steady = self.steady_speed()
        if steady is not None and u0 == steady:
            return viscous * u0 ** exponent * end

        def per_speed(u: float) -> float:  # ω²/f(ω): dt = dω/f(ω)
            return u ** exponent / self.rate(u) if u > 0 else 0.0

        if steady is None or abs(u_end - steady) > 1e-3 * abs(u0 - steady):
            return viscous * change * adaptive_gauss(lambda s: per_speed(u0 + s * change), 0.0, 1.0)
        near = steady + 1e-3 * (u0 - steady)
        reached = self.time_to(self.sense * near)
        if reached is None:  # the stepper does not resolve the approach: the time integral throughout
            return viscous * gauss_legendre(lambda t: abs(self.state(t)[0]) ** exponent, 0.0, end, panels=16)
        return viscous * (adaptive_gauss(per_speed, u0, near) + gauss_legendre(lambda t: abs(self.state(t)[0]) ** exponent, reached[0], end, panels=16))

    def steady_speed(self) -> float | None:
        """Where P/u balances the losses (P > 0 with losses), by bisection; None otherwise."""
        if self.power <= 0 or self.lossless:
            return None
        return falling_root(self.rate)


def power_report(inertia, inertia_steps, power, torques: Torques, omega0, *, time, until_omega, until_angle, method, dt, rtol) -> Report:
    """spin-down under a motor of constant power."""
    if torques.drive:
        raise InputError("power", "conflicts with {torque}: the motor's torque is P/ω")
    if until_angle is not None and (time is not None or until_omega is not None):
        raise InputError("until_angle", "conflicts with {time} and {until_omega}: ask for one target at a time (a run each)")
    lossless = not (torques.friction or torques.viscous or torques.drag)
    if method == "exact" and not lossless:
        raise InputError("method", "exact has no closed form for a constant power against losses", hint="use {method} auto or rk45")
    results, notes = Results(TABLE), []
    if lossless:
        chosen = Method("exact")
        if method not in ("auto", "exact"):
            notes.append(f"{{method}} {method}: a constant power with no losses has a closed form, ½Iω² = ½Iω₀² + Pt, which is used instead")
    elif method in ("euler", "rk4") or method == "rk45":
        chosen = Method(method, dt or (DEFAULT_DT if method != "rk45" else None), rtol or DEFAULT_RTOL)
    else:
        chosen = Method("rk45", None, rtol or DEFAULT_RTOL)
    sense = -1.0 if omega0 < 0 else 1.0
    motion = PowerMotion(inertia, power, torques, abs(omega0), chosen, sense)
    results.put("I", inertia)
    rate = motion.rate(abs(omega0)) if omega0 else None
    results.put("alpha0", None if rate is None or not math.isfinite(rate) else sense * rate)
    if omega0 == 0:
        notes.append("alpha0 and the torque at the start: none, a constant power from rest asks for an unbounded torque P/ω at ω = 0")
    if power < 0 and omega0 == 0:
        notes.append("a load with the wheel at rest: nothing turns")
    stop = motion.stop()
    steady = motion.steady_speed()
    if stop is None:  # a motor (P > 0) keeps it turning: its stop does not apply (#42 item 23)
        results.not_applicable("t_stop", "theta_stop", "revs_stop")
        notes.append("the motor keeps it turning, so the wheel never stops and t_stop, theta_stop, revs_stop do not apply"
                     + ("; nor has it a steady speed (with no losses the motor's power all goes into the wheel, so ω grows without bound): "
                        "omega_inf does not apply either" if steady is None else ""))
    else:
        results.put("t_stop", stop[0])
        results.put("theta_stop", sense * stop[1])
        results.put("revs_stop", sense * stop[1] / TWO_PI)
    if power > 0 and steady is None:
        results.not_applicable("omega_inf")
    else:
        results.put("omega_inf", 0.0 if power < 0 else sense * steady)
    omega_at = omega0
    at = None
    if time is not None:
        omega_at, theta = motion.state(time)
        at = time
        results.put("omega", omega_at, f" at t = {fmt(time)} s")
        results.put("theta", theta, f" by t = {fmt(time)} s")
        results.put("revs", theta / TWO_PI, f" by t = {fmt(time)} s")
    if until_omega is not None:
        reached = motion.time_to(until_omega)
        if reached is None:
            notes.append(f"the wheel never reaches ω = {quantity_text(until_omega, 'rad/s')}")
        results.put("t_until", None if reached is None else reached[0], f" ω = {fmt(until_omega)} rad/s")
        results.put("theta_until", None if reached is None else reached[1], f" ω = {fmt(until_omega)} rad/s")
        if reached is not None:
            at, omega_at = reached[0], until_omega
    if until_angle is not None:
        reached = _power_time_at_angle(motion, until_angle)
        if reached is None:
            notes.append(f"the wheel never reaches θ = {fmt(until_angle)} rad")
        results.put("t_until", None if reached is None else reached[0], f" θ = {fmt(until_angle)} rad")
        results.put("omega", None if reached is None else reached[1], f" at θ = {fmt(until_angle)} rad")
        if reached is not None:
            at, omega_at = reached
    when = " at the start" if at is None else f" at t = {fmt(at)} s"
    results.put("torque", power / omega_at if omega_at else None, when)
    # the load drains P right up to the stop; once the wheel is at rest nothing turns and nothing is drained
    resting = power < 0 and (omega0 == 0 or (stop is not None and at is not None and at > stop[0]))
    results.put("power", 0.0 if resting else power, when)
    results.put("KE0", inertia * omega0 * omega0 / 2)
    end = at if at is not None else (stop[0] if stop is not None else None)
    if end is not None:
        stepped_end, theta_end, speed_change = motion.state_change(end)
        omega_end = stepped_end if at is None else omega_at
        if at is not None and omega_at != stepped_end:  # the target's speed as given: its change from ω₀ is of two inputs
            speed_change = abs(omega_at) - abs(omega0)
        ke = inertia * omega_end * omega_end / 2
        results.put("KE", ke, f" at t = {fmt(end)} s" if at is not None else " at the stop")
        driving_time = min(end, stop[0]) if stop is not None else end
        work = power * driving_time
        by = f" by t = {fmt(end)} s" if at is not None else " until it stops"
        results.put("work_drive", work, by)
        if end > 0:
            results.put("power_mean", work / end, by)
        friction = torques.friction * abs(theta_end)
        if torques.friction:
            results.put("work_friction", friction, by)
        # ½I(ω₀² − ω²) with ω − ω₀ the motion's own change, not the difference of two near-equal speeds (#42 item 8)
        rest = -inertia * speed_change * (abs(omega0) + abs(omega_end)) / 2 + work - friction
        # a loss much smaller than the terms it is the difference of is its own integral (#42 item 8)
        cancels = abs(rest) < 1e-2 * max(abs(work), friction, inertia * omega0 * omega0 / 2, ke)
        if torques.viscous and torques.drag and cancels:
            results.put("work_viscous", motion.viscous_work(end, abs(omega_end), speed_change), by)
            results.put("work_drag", motion.viscous_work(end, abs(omega_end), speed_change, torques.drag, torques.drag_exponent + 1), by)
        elif torques.viscous and torques.drag:
            viscous = motion.viscous_work(end, abs(omega_end), speed_change)
            results.put("work_viscous", viscous, by)
            results.put("work_drag", max(0.0, rest - viscous), by)
        elif torques.viscous:
            results.put("work_viscous", motion.viscous_work(end, abs(omega_end), speed_change) if cancels else max(0.0, rest), by)
        elif torques.drag:
            results.put("work_drag", motion.viscous_work(end, abs(omega_end), speed_change, torques.drag, torques.drag_exponent + 1) if cancels else max(0.0, rest), by)
    tables, checked = {}, ""
    if chosen.name in ("euler", "rk4"):
        against = f"rk45 at rtol {REFERENCE_RTOL:g}"
        try:
            reference = power_report(inertia, (), power, torques, omega0, time=time, until_omega=until_omega, until_angle=until_angle,
                                     method="rk45", dt=None, rtol=REFERENCE_RTOL).results
        except InputError:
            reference = None
        estimate = error_estimate(results, reference, against, chosen, notes)
        if estimate is not None:
            tables["error_estimate"], worst = estimate
            checked = f"; estimated error at most {fmt(worst, 2)} relative" if worst is not None else ""
    steps = list(inertia_steps)
    if lossless:
        steps.append(Step("Energy from a constant power", "½Iω² = ½Iω₀² + Pt  ⇒  t = I(ω₁² − ω₀²)/(2P)", "", "",
                          "a motor of constant power adds energy at the rate P; with no losses it all goes into the wheel"))
        if until_omega is not None and results["t_until"].value is not None:
            steps.append(Step("Time to reach ω₁", "t = I(ω₁ − ω₀)(ω₁ + ω₀)/(2P)",
                              f"{term(inertia, 'kg*m**2')} × ({term(until_omega, 'rad/s')} − {term(omega0, 'rad/s')}) × ({term(until_omega, 'rad/s')} + {term(omega0, 'rad/s')}) / (2 × {term(power, 'W')})",
                              quantity_text(results["t_until"].value, "s"), "the energy ½I(ω₁² − ω₀²) delivered at the rate P"))
        model = ("constant power P (τ = P/ω), no losses: ½Iω² grows linearly in time" if power > 0
                 else "a load of constant power P < 0 (τ = P/ω), no losses: ½Iω² falls linearly in time, to rest")
    else:
        steps.append(Step("Integrate the equation of motion", "I dω/dt = P/ω − τ_f − bω − kωⁿ,  dθ/dt = ω", chosen.name, "",
                          "no closed form exists for a constant power against these losses"))
        model = "constant power P (τ = P/ω) against losses: no closed form"
    described = {"exact": "closed form", "rk45": f"rk45 (Dormand-Prince, adaptive), rtol = {chosen.rtol:g}"}.get(
        chosen.name, f"{chosen.name}, dt = {fmt(chosen.dt or 0.0)} s"
    ) + checked
    steps.extend(energy_steps(results, inertia, torques.friction, power=power))
    return Report("spin-down", model, described, results, steps, notes, tables=tables, trajectory=deferred(curves, motion.state, end, stop))


def _power_time_at_angle(motion: PowerMotion, theta: float) -> tuple[float, float] | None:
    """(t, ω) when the wheel under constant power has turned θ: bisection on the motion."""
    distance = theta * motion.sense
    if distance < 0:
        return None
    if distance == 0:
        return 0.0, motion.sense * motion.u0
    stop = motion.stop()
    if stop is not None and distance > stop[1]:
        return None
    low, high = 0.0, None
    if stop is not None:
        high = stop[0]
    else:
        guess = max(distance / motion.u0 if motion.u0 else 0.0, math.sqrt(distance * motion.inertia / max(motion.power, 1e-300)), 1e-9)
        for _ in range(200):
            if abs(motion.state(guess)[1]) >= distance:
                high = guess
                break
            low, guess = guess, 2 * guess
        if high is None:
            return None
    for _ in range(200):
        mid = (low + high) / 2
        if mid in (low, high):
            break
        if abs(motion.state(mid)[1]) < distance:
            low = mid
        else:
            high = mid
    return high, motion.state(high)[0]
