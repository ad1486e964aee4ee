"""Angular impulse of a torque given as a formula of time (taucli.numerics.of_time):

    J = ∫₀^Δt τ(t) dt = I (ω₁ − ω₀)

exact for a polynomial (τ = 10t: J = 5Δt²), by adaptive Gauss–Legendre quadrature otherwise; then
the balance of a constant torque (balance.py) with the mean torque J/Δt, which has the same J.
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.numerics.of_time import FormulaFailed, OfTime
from taucli.scenes.impulse.balance import solve_balance
from taucli.writing.report import Report, Step, fmt, quantity_text, term


def formula_impulse(torque: OfTime, duration: float | None, inertia: float | None, omega0: float | None, omega1: float | None, others: dict,
                    method: str, inertia_steps: Sequence[Step] = ()) -> Report:
    """J = ∫τ dt over --duration, then τ_mean Δt = I(ω₁ − ω₀) for the one of I, ω₀, ω₁ left out."""
    for name, value in others.items():
        if value is not None and value != () and value != []:
            raise InputError(name, "does not combine with {torque} as a formula of t: J = ∫τ dt over {duration} on one body", example="{duration} 2s")
    if method != "auto":
        raise InputError("method", "does not apply with {torque} as a formula of t: a polynomial is integrated exactly, any other formula by quadrature")
    if duration is None:
        raise InputError("duration", "is required with {torque} as a formula of t: J = ∫τ dt from 0 to it", example="{duration} 2s")
    try:
        impulse, peak = torque.first(duration), torque.at(duration)
    except FormulaFailed as failed:
        raise InputError("torque", f"has no finite value at t = {fmt(failed.at)} s ({failed.why}) within {{duration}}", example="{duration} 1s") from None
    mean = impulse / duration if duration > 0 else torque.at(0.0)
    report = solve_balance(inertia, omega0, omega1, mean, duration, inertia_steps=inertia_steps)
    if "J" in report.results:
        report.results["J"] = report.results["J"]._replace(value=impulse, label="angular impulse ∫τ dt")  # the integral itself, not (J/Δt)·Δt rounded twice
    if "torque" in report.results:
        report.results["torque"] = report.results["torque"]._replace(label="mean torque J/Δt (the formula's)")
    way = "exactly (a polynomial)" if torque.exact else "by adaptive Gauss–Legendre quadrature"
    first = [
        Step("The torque as a formula of time", f"τ(t) = {torque.describe()}  (N·m, t in s)", "", f"τ(Δt) = {quantity_text(peak, 'N*m')}", "as given"),
        Step("Angular impulse", "J = ∫₀^Δt τ(t) dt", f"∫₀^{fmt(duration)} τ dt, {way}", quantity_text(impulse, "N*m*s"),
             f"the mean torque J/Δt = {term(mean, 'N*m')} has the same impulse, and stands in for τ below"),
    ]
    report.steps = [*first, *report.steps]
    report.model = f"angular impulse of a torque given as a formula of time, {torque.describe()} (N·m): J = ∫τ dt = IΔω"
    report.method = "closed form" if torque.exact else "quadrature"
    report.notes = [f"the torque varies: J = ∫τ dt over {fmt(duration)} s, integrated {way}", *report.notes]
    return report
