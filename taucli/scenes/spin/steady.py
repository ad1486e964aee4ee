"""Where the torques on a wheel balance, without a body: a motor's line meeting its load's.

The inertia sets how fast a wheel gets to a steady speed, not where that speed is. Turning in the
drive's sense (ω > 0 there), the net torque is

    τ(ω) = D − F + (s − b)ω − kωⁿ

D the drive at rest, s its rise with speed (--drive-slope: a motor's line; negative, it falls),
F the friction, b the viscous coefficient, k the drag. A balance ω* (τ = 0) is stable where the
net torque falls as the speed rises, dτ/dω = s − b − nkω*ⁿ⁻¹ < 0: a little faster, it slows back.
τ is concave (n > 1), convex (n < 1) or straight (k = 0 or n = 1) on ω > 0, so it has at most two
balances, found by bisection on each stretch where τ is monotonic. From ω₀ the wheel runs to
the balance ahead of it the way τ(ω₀) pushes it: omega_inf; it stops where it runs down to 0 and
the drive at rest, D, is no more than F (friction holds it); it runs away where τ stays
positive above it (no steady speed).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.options.spin_down import COMMAND as TABLE
from taucli.options.table import Results
from taucli.writing.report import Report, Step, quantity_text


class Balance(NamedTuple):
    """The steady speed from ω₀ (None: it runs away), whether it is stable, and the unstable balance (None if none)."""
    omega_inf: float | None
    stable: bool | None
    unstable: float | None


def net_torque(drive: float, friction: float, slope_net: float, drag: float, exponent: float, omega: float) -> float:
    """τ(ω) = D − F + (s − b)ω − kωⁿ for ω ≥ 0 (slope_net = s − b)."""
    return drive - friction + slope_net * omega - drag * omega**exponent


def balances(drive: float, friction: float, slope_net: float, drag: float, exponent: float) -> list[tuple[float, bool]]:
    """Every ω > 0 where τ = 0, with whether it is stable, in order."""
    tau = lambda w: net_torque(drive, friction, slope_net, drag, exponent, w)  # noqa: E731
    edges = [0.0]
    if drag and exponent != 1 and slope_net / (exponent * drag) > 0:
        edges.append((slope_net / (exponent * drag)) ** (1 / (exponent - 1)))  # where dτ/dω = 0
    top, sign = max(edges[-1], 1.0), _end_sign(drive - friction, slope_net, drag, exponent)
    while (tau(top) > 0) != (sign > 0) and top < 1e300:  # past the one extremum τ is monotonic: once it has its end's sign, no more balances
        top *= 2
    edges.append(top)
    found = []
    for low, high in zip(edges, edges[1:]):
        a, b = tau(low), tau(high)
        if a == 0 and low > 0:
            found.append(low)
        elif a * b < 0:
            found.append(_bisect(tau, low, high, a > 0))
    if tau(edges[-1]) == 0:
        found.append(edges[-1])
    slope = lambda w: slope_net - (exponent * drag * w ** (exponent - 1) if drag else 0.0)  # noqa: E731
    return [(w, slope(w) < 0) for w in sorted(set(found)) if w > 0]


def _end_sign(constant: float, slope_net: float, drag: float, exponent: float) -> float:
    """The sign τ keeps as ω → ∞: the drag's −kωⁿ where it grows fastest, else the line's slope, else the constant."""
    if drag and exponent > 1:
        return -1.0
    line = slope_net - drag if drag and exponent == 1 else slope_net
    if line:
        return math.copysign(1.0, line)
    return -1.0 if drag else math.copysign(1.0, constant) if constant else -1.0


def _bisect(f, low: float, high: float, low_positive: bool) -> float:
    for _ in range(2000):
        mid = (low + high) / 2
        if not low < mid < high:
            break
        if (f(mid) > 0) == low_positive:
            low = mid
        else:
            high = mid
    return (low + high) / 2


def steady(drive: float, friction: float, slope_net: float, drag: float, exponent: float, omega0: float) -> Balance:
    """From ω₀ ≥ 0 (in the drive's sense): where the wheel settles, and the unstable balance."""
    found = balances(drive, friction, slope_net, drag, exponent)
    unstable = next((w for w, stable in found if not stable), None)
    push = net_torque(drive, friction, slope_net, drag, exponent, omega0) if omega0 > 0 else drive - friction
    if omega0 > 0 and any(w == omega0 for w, _ in found):
        stable = next(s for w, s in found if w == omega0)
        return Balance(omega0, stable, unstable)
    if push > 0:  # speeds up to the balance above it, or runs away
        above = [(w, s) for w, s in found if w > omega0]
        return Balance(above[0][0], above[0][1], unstable) if above else Balance(None, None, unstable)
    below = [(w, s) for w, s in found if w < omega0]
    if below:
        return Balance(below[-1][0], below[-1][1], unstable)
    return Balance(0.0, True, unstable)  # runs down and stops; friction (or nothing) holds it at rest


def steady_report(torques, slope: float, omega0: float | None, front) -> Report:
    """spin-down with no body and a torque that changes with speed: the balances, the steady
    speed from ω₀ (omega_inf), whether it is stable, and the drive's power there."""
    sense = math.copysign(1.0, torques.drive) if torques.drive else math.copysign(1.0, omega0) if omega0 else 1.0
    start = sense * (omega0 or 0.0)
    if start < 0:
        raise InputError("omega0", "turns against the drive: with no body the balance is found for a wheel turning the way the drive pushes it",
                         example="{omega0} 100rad/s")
    drive, slope_net = abs(torques.drive), slope - torques.viscous  # T = T₀ + sω read in the drive's sense: |T₀| + sω' either way
    found = balances(drive, torques.friction, slope_net, torques.drag, torques.drag_exponent)
    settled = steady(drive, torques.friction, slope_net, torques.drag, torques.drag_exponent, start)
    results = Results(TABLE)
    results.update(front.results)
    notes = [*front.notes, "no body: the speeds where the torques balance, which the inertia does not change; "
             "give --inertia or --shape for the motion in time"]
    if settled.omega_inf is None:
        results.not_applicable("omega_inf")
        notes.append("omega_inf: none: the net torque stays positive above the start, so the wheel runs away (an unstable drive)")
    else:
        results.put("omega_inf", sense * settled.omega_inf + 0.0)
    results.put("stable", settled.stable)
    results.put("omega_unstable", None if settled.unstable is None else sense * settled.unstable)
    if settled.unstable is None:
        notes.append("omega_unstable: none: no balance where a little faster speeds it up further")
    if settled.omega_inf is not None:
        speed = settled.omega_inf
        results.put("torque", sense * (drive + slope * speed), " at the steady speed")
        results.put("power", (drive + slope * speed) * speed, " at the steady speed")
    law = "D − F + (s − b)ω − kω" + ("²" if torques.drag_exponent == 2 else "ⁿ")
    shown = ", ".join(f"{quantity_text(sense * w, 'rad/s')} ({'stable' if s else 'unstable'})" for w, s in found) or "none"
    steps = [
        *front.steps,
        Step("Where the torques balance", f"τ(ω) = {law} = 0",
             f"D = {quantity_text(drive, 'N*m')}, F = {quantity_text(torques.friction, 'N*m')}, s − b = {quantity_text(slope_net, 'N*m*s')}, "
             f"k = {quantity_text(torques.drag, 'N*m*s**2') if torques.drag_exponent == 2 else torques.drag}",
             shown,
             "the inertia sets how fast the wheel gets there, not where: at a balance the net torque is zero"),
        Step("Stable or not", "stable where dτ/dω = (s − b) − nkω^(n−1) < 0",
             "" if settled.omega_inf is None or settled.omega_inf == 0 else
             f"dτ/dω = {quantity_text(slope_net - torques.drag_exponent * torques.drag * settled.omega_inf ** (torques.drag_exponent - 1), 'N*m*s')} "
             f"at {quantity_text(sense * settled.omega_inf, 'rad/s')}",
             "stable" if settled.stable else "unstable" if settled.stable is False else "—",
             "a little faster, the net torque must slow it back; where it speeds it up further the balance is unstable "
             "(a motor's line rising more steeply than its load's)"),
    ]
    return Report("spin-down", "the torques' balance (no body)", "closed form (roots of the net torque, by bisection)", results, steps, notes)

