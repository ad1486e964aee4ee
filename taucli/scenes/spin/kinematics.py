"""Rotation at constant angular acceleration: ω = ω₀ + αt, θ = ω₀t + ½αt², ω² = ω₀² + 2αθ.

Any three of ω₀, ω₁, α, t and θ give the other two. A constant α carries the wheel on through
ω = 0 (it turns back); the first stop is still reported. Where θ = ω₀t + ½αt² has two positive
roots, the earlier is the answer and the later is when the wheel, turned back, passes θ again.
Every formula here is written without differences of near-equal numbers where one can be
avoided: the roots of the quadratic by the stable pair 2q/α and −θ/q (see ``times_at_angle``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError


@dataclass(frozen=True)
class Uniform:
    """ω(t) = ω₀ + αt and θ(t) = ω₀t + ½αt², for all t ≥ 0 (through ω = 0 and on)."""

    omega0: float
    alpha: float

    def omega(self, t: float) -> float:
        return self.omega0 + self.alpha * t

    def theta(self, t: float) -> float:
        return t * (self.omega0 + self.alpha * t / 2)

    def path(self, t: float) -> float:
        """The angle swept (always ≥ 0): |θ| up to the stop, plus |θ| back after it."""
        stop = self.stop()
        if stop is None or t <= stop[0]:
            return abs(self.theta(t))
        back = t - stop[0]
        return abs(stop[1]) + abs(self.alpha) * back * back / 2

    def stop(self) -> tuple[float, float] | None:
        """(t, θ) of the first stop, where α opposes ω₀; None where the wheel never stops."""
        if self.omega0 == 0 or self.alpha == 0 or (self.omega0 > 0) == (self.alpha > 0):
            return None
        t = -self.omega0 / self.alpha
        return t, self.omega0 * t / 2

    def time_to_omega(self, target: float) -> float | None:
        """When ω = target (None: never, or only before t = 0)."""
        if target == self.omega0:
            return 0.0
        if self.alpha == 0:
            return None
        t = (target - self.omega0) / self.alpha
        return t if t > 0 else None

    def times_at_angle(self, theta: float) -> list[float]:
        """Every t ≥ 0 with θ(t) = theta, earliest first (one or two).

        ½αt² + ω₀t − θ = 0 has roots 2q/α and −θ/q with q = −½(ω₀ + sgn(ω₀)√(ω₀² + 2αθ)):
        neither subtracts near-equal numbers.
        """
        w0, a = self.omega0, self.alpha
        if theta == 0:
            return [0.0] + ([-2 * w0 / a] if a and w0 and (w0 > 0) != (a > 0) else [])
        if a == 0:
            return [theta / w0] if w0 and theta / w0 > 0 else []
        discriminant = w0 * w0 + 2 * a * theta
        if discriminant < 0:
            return []
        root = math.sqrt(discriminant)
        q = -(w0 + math.copysign(root, w0 if w0 else theta * a)) / 2
        roots = sorted({2 * q / a, -theta / q} if q else {math.sqrt(2 * theta / a)})
        return [t for t in roots if t > 0]


def solve_unknowns(
    omega0: float | None, alpha: float | None, time: float | None, omega1: float | None, theta: float | None
) -> tuple[float, float, list[str]]:
    """(ω₀, α) from any three of ω₀, α, t, ω₁, θ (ω₀ = 0 when it is not given and two others are),
    and notes. Raises InputError where the values given have no constant-α motion."""
    notes: list[str] = []
    targets = {name: value for name, value in (("time", time), ("until_omega", omega1), ("until_angle", theta)) if value is not None}
    if alpha is not None and (omega0 is not None or len(targets) < 2):
        return (omega0 or 0.0), alpha, notes
    if len(targets) + (alpha is not None) + (omega0 is not None) > 3:
        names = ", ".join("{" + name + "}" for name in targets)
        raise InputError(
            next(iter(targets)), f"too many of {names} with {{omega0}} and {{alpha}}: at constant α any three of ω₀, ω₁, α, t, θ give the rest",
        )
    if alpha is None and omega0 is None and len(targets) == 2:
        notes.append("ω₀ = 0: the wheel starts from rest ({omega0} to change it)")
        omega0 = 0.0
    if alpha is None and len(targets) < 2:
        raise InputError(
            "inertia", "or {shape} (a body), or {alpha}, is required; without them, give two of {time}, {until_omega}, {until_angle} besides {omega0}",
            example="{inertia} '0.1kg*m^2', or {omega0} 100rpm {until_omega} 500rpm {time} 10s",
        )
    t, w1, th = time, omega1, theta
    if t is not None and t <= 0 and (w1 is not None or th is not None):
        raise InputError("time", "expected a positive time to reach the target in", got=repr(t))
    if alpha is None:  # ω₀ known; two of t, ω₁, θ (or all three, then ω₀ unknown)
        if omega0 is None:  # t, ω₁ and θ: ω₀ = 2θ/t − ω₁
            omega0 = 2 * th / t - w1
            return omega0, (w1 - omega0) / t, notes
        w0 = omega0
        if th is None:
            return w0, (w1 - w0) / t, notes
        if w1 is None:
            return w0, 2 * (th - w0 * t) / (t * t), notes
        # ω₁ and θ: α = (ω₁ − ω₀)(ω₁ + ω₀)/(2θ), reached at t = 2θ/(ω₀ + ω₁) > 0
        if w1 == w0 and th == 0:
            raise InputError("until_angle", "with {until_omega} equal to {omega0} leaves α open: give {time} or {alpha}")
        if th == 0 or w0 + w1 == 0 or th / (w0 + w1) <= 0:
            raise InputError(
                "until_angle", "cannot be reached at constant α with these speeds: the mean speed (ω₀ + ω₁)/2 must turn the wheel that way",
                got=f"θ = {th:g} rad, ω₀ = {w0:g} rad/s, ω₁ = {w1:g} rad/s",
            )
        return w0, (w1 - w0) * (w1 + w0) / (2 * th), notes
    # α known, ω₀ not given, two of t, ω₁, θ: ω₀ from them
    a = alpha
    if th is None:
        return w1 - a * t, a, notes
    if w1 is None:
        return th / t - a * t / 2, a, notes
    square = w1 * w1 - 2 * a * th
    if square < 0:
        raise InputError("until_angle", "cannot be reached: ω₀² = ω₁² − 2αθ would be negative", got=f"{square:g} rad²/s²")
    sign = math.copysign(1.0, w1 if w1 else th)
    w0 = sign * math.sqrt(square)
    if w0 + w1 == 0 or th / (w0 + w1) <= 0:
        w0 = -w0
    elif square > 0 and w1 != w0 and th / (w1 - w0) > 0:
        notes.append(f"ω₀ = {-w0:g} rad/s would also do, the wheel turning back on the way; the one that does not turn back is given")
    if th == 0 or w0 + w1 == 0 or th / (w0 + w1) <= 0:
        raise InputError(
            "until_angle", "cannot be reached at this α from any ω₀: the mean speed (ω₀ + ω₁)/2 must turn the wheel that way",
            got=f"θ = {th:g} rad, ω₁ = {w1:g} rad/s, α = {a:g} rad/s²",
        )
    return w0, a, notes
