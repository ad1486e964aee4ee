"""A torque or an angular acceleration given as a formula of time (taucli.numerics.of_time):

    α(t) = τ(t)/I  (or given),   ω(t) = ω₀ + ∫₀ᵗ α ds,   θ(t) = ω₀ t + ∫₀ᵗ (t − s) α(s) ds

the integrals exact for a polynomial (α = 2 − 3t: ω = ω₀ + 2t − 1.5t², θ = ω₀t + t² − t³/2) and
by adaptive Gauss–Legendre quadrature otherwise. With a body: L = Iω, KE = ½Iω², and the work of
the drive W = ΔKE (no other torque acts). ``--until-omega``: the first time ω(t) meets the target
(a scan of ω over times growing geometrically, then Brent's method on the first bracket).
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.numerics.of_time import FormulaFailed, OfTime
from taucli.numerics.roots import brent
from taucli.options.spin_down import COMMAND as TABLE
from taucli.options.table import Results
from taucli.scenes.inertia import body
from taucli.writing.report import DeferredSteps, Report, Step, Trajectory, deferred, fmt, quantity_text, term

TWO_PI = 2 * math.pi
SCAN = [1e-6 * 10 ** (k / 40) for k in range(40 * 12 + 1)]  # 1 µs to 1e6 s, 40 times a decade


def formula_report(inertia: float | None, omega0: float, torque: OfTime | None, alpha: OfTime | None, time: float | None,
                   until_omega: float | None, inertia_steps=()) -> Report:
    """The wheel under a torque τ(t) (with its body's I) or an angular acceleration α(t), from ω₀,
    to --time or to --until-omega (else only its start)."""
    given = torque if torque is not None else alpha
    name = "torque" if torque is not None else "alpha"
    if torque is not None and inertia is None:
        raise InputError("torque", "as a formula of t needs the body ({inertia} or a shape): α = τ(t)/I", example="{inertia} '2kg*m^2'")
    if time is not None and until_omega is not None:
        raise InputError("until_omega", "conflicts with {time}: the run ends at one of them", example="{time} 2s")
    scale = 1.0 if torque is None else 1.0 / inertia

    def acc(t):
        return scale * given.at(t)

    def omega(t):
        return omega0 + scale * given.first(t)

    def theta(t):
        return omega0 * t + scale * given.second(t)

    results = Results(TABLE)
    if inertia is not None:
        results.put("I", inertia)
    try:
        results.put("alpha0", acc(0.0))
        end = time
        if until_omega is not None:
            end = _first_time(omega, until_omega, name)
        if end is not None:
            _put_end(results, end, acc, omega, theta, inertia, omega0, given if torque is not None else None, until_omega)
    except FormulaFailed as failed:
        raise InputError(name, f"has no finite value at t = {fmt(failed.at)} s ({failed.why}) within the run", example="{time} 1s") from None
    if end is None:
        notes = ["give --time (or --until-omega) for ω and θ: the formula is integrated from 0 to it"]
    else:
        notes = []
    way = "integrated exactly (a polynomial)" if given.exact else "integrated by adaptive Gauss–Legendre quadrature"
    model = f"{'torque' if torque is not None else 'angular acceleration'} given as a formula of time, {given.describe()} ({_si(given.si_unit)})"
    steps = DeferredSteps(_steps, given, torque is not None, inertia, omega0, end, results, inertia_steps)
    trajectory = deferred(_trajectory, omega, theta, end)
    return Report("spin-down", model, "closed form" if given.exact else "quadrature", results, steps, [way, *notes], trajectory=trajectory)


def formula_run(others: dict, method: str, torque, alpha, omega0, time, until_omega, body_options: dict) -> Report:
    """A torque or α given as a formula of t (scenes.spin.of_time): alone on the body, from ω₀."""
    formula = "torque" if isinstance(torque, OfTime) else "alpha"
    for name, value in others.items():
        if value is not None:
            raise InputError(name, f"does not combine with {{{formula}}} as a formula of t: the formula is the one torque on the body "
                             "(with {omega0}, {time} or {until_omega})", example="{time} 2s")
    if method != "auto":
        raise InputError("method", f"does not apply with {{{formula}}} as a formula of t: a polynomial is integrated exactly, any other formula by quadrature")
    given = any(body_options.get(name) not in (None, (), []) for name in ("inertia", "shape", "gyration", "part"))
    inertia, steps = body(**body_options) if given else (None, ())
    return formula_report(inertia, omega0 or 0.0, torque if formula == "torque" else None, alpha if formula == "alpha" else None, time, until_omega, steps)


def _first_time(omega, target: float, name: str) -> float:
    """The first t > 0 where ω(t) meets the target (from ω₀ = target: where it gets back to it)."""
    previous_t, previous = 0.0, omega(0.0) - target
    scan = SCAN
    if previous == 0:  # it starts at the target (from rest, --until-omega 0): the next time it gets back there
        moved = next((k for k, t in enumerate(SCAN) if omega(t) != target), None)
        if moved is None:
            return 0.0
        previous_t, previous, scan = SCAN[moved], omega(SCAN[moved]) - target, SCAN[moved + 1:]
    for t in scan:
        value = omega(t) - target
        if value == 0:
            return t
        if (value > 0) != (previous > 0):
            root, _ = brent(lambda x: omega(x) - target, previous_t, t, previous, value)
            return root
        previous_t, previous = t, value
    raise InputError("until_omega", f"is not reached within {fmt(SCAN[-1])} s under this {'torque' if name == 'torque' else 'α'}", example="{time} 2s")


def _put_end(results: Results, end: float, acc, omega, theta, inertia, omega0, torque: OfTime | None, until: float | None) -> None:
    part = f" at t = {fmt(end)} s"
    w, angle = omega(end), theta(end)
    if until is not None:
        results.put("t_until", end, f" {fmt(until)} rad/s")
        results.put("theta_until", angle, f" {fmt(until)} rad/s")
        results.put("revs_until", angle / TWO_PI, f" {fmt(until)} rad/s")
    results.put("omega", w, part)
    results.put("theta", angle, part)
    results.put("revs", angle / TWO_PI, part)
    results.put("alpha_end", acc(end), part)
    if end > 0:
        results.put("omega_mean", angle / end, f" over {fmt(end)} s")
    if inertia is not None:
        results.put("L", inertia * w, part)
        results.put("KE0", 0.5 * inertia * omega0 * omega0)
        results.put("KE", 0.5 * inertia * w * w, part)
        results.put("torque_net", inertia * acc(end), part)
        if torque is not None:
            results.put("torque", torque.at(end), part)
            results.put("work_drive", 0.5 * inertia * (w - omega0) * (w + omega0), f" over {fmt(end)} s")


def _si(unit: str) -> str:
    return unit.replace("**", "^").replace("*", "·")


def _steps(given: OfTime, is_torque: bool, inertia, omega0, end, results, inertia_steps) -> list[Step]:
    steps = list(inertia_steps)
    unit = _si(given.si_unit)
    rule = "∫ of each term cₖtᵏ is cₖtᵏ⁺¹/(k+1)" if given.exact else "adaptive Gauss–Legendre quadrature, to 1e-13 of the integral"
    if is_torque:
        steps.append(Step("The torque as a formula of time", "τ(t) = " + given.describe() + f"  ({unit}, t in s)", "", "",
                          "as given; the body's α(t) = τ(t)/I"))
        steps.append(Step("Angular acceleration at the start", "α₀ = τ(0)/I", f"{term(given.at(0.0), 'N*m')} / {term(inertia, 'kg*m**2')}",
                          quantity_text(results["alpha0"].value, "rad/s**2"), "Newton's second law for rotation"))
    else:
        steps.append(Step("The angular acceleration as a formula of time", "α(t) = " + given.describe() + f"  ({unit}, t in s)", "", "", "as given"))
    if end is None:
        return steps
    over = "τ(s)/I" if is_torque else "α(s)"
    steps.append(Step(f"Angular velocity at t = {fmt(end)} s", f"ω = ω₀ + ∫₀ᵗ {over} ds", f"{term(omega0, 'rad/s')} + ∫₀^{fmt(end)} {over} ds",
                      quantity_text(results["omega"].value, "rad/s"), rule))
    steps.append(Step(f"Angle at t = {fmt(end)} s", f"θ = ω₀ t + ∫₀ᵗ (t − s) {over} ds", f"{term(omega0, 'rad/s')} × {term(end, 's')} + ∫₀^{fmt(end)} (t − s) {over} ds",
                      quantity_text(results["theta"].value, "rad") + f" = {fmt(results['revs'].value)} rev", "θ = ∫ω dt, the double integral of α written as one"))
    if is_torque and "work_drive" in results:
        steps.append(Step("Work of the drive", "W = ½ I (ω² − ω₀²)", "", quantity_text(results["work_drive"].value, "J"),
                          "the work-energy theorem: no other torque acts"))
    return steps


def _trajectory(omega, theta, end: float | None) -> Trajectory:
    curves = (("omega", "rad/s", "angular velocity"), ("theta", "rad", "angle turned"))
    if end is None or end == 0:
        return Trajectory(curves, 1.0, lambda t: (omega(t), theta(t)), note="plotted for 1 s; --time to change")
    return Trajectory(curves, end, lambda t: (omega(t), theta(t)), marks=((end, "the end"),))
