"""A hoist: the drive on the pulley lifts m1 (a cage, a load) with m2 as its counterweight; and
the energy the axle friction (a brake) takes.

Along the string (machine.py), with D₀ = G1 − ρG2 what gravity and the pulls drive toward m1
going down, and F = μk1N1 + |ρ|μk2N2 + τa/r1 the kinetic friction against the motion:

- a steady lift at speed V (m1 up; V < 0 lowers it): a = 0 needs the drive τ_d = r1(D₀ + F sgn V),
  whose power is P = τ_d ω = D₀V + F|V| (negative: the drive holds back, as a brake or a
  regenerating motor);
- a trip of height H from rest to rest: the kinetic energy comes back to 0, so the drive gives the
  rise in potential energy and what friction takes, W = D₀H + F|H|; over the trip's time T its
  mean power is W/T;
- the axle friction takes τa|Δθ| = (τa/r1)·(the path of the string): over --distance, to the stop
  after --v0, or over the trip.
"""

from __future__ import annotations

from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.options.table import Results
from taucli.writing.report import Step, fmt, quantity_text


class Hoist(NamedTuple):
    speed: float | None = None  # --hoist-speed, m1 up positive
    height: float | None = None  # --hoist-height, m1 up positive
    trip_time: float | None = None

    @property
    def asked(self) -> bool:
        return self.speed is not None or self.height is not None


def check_hoist(hoist: Hoist) -> None:
    if hoist.trip_time is not None and hoist.height is None:
        raise InputError("trip_time", "needs {hoist_height} (the trip it times)", example="{hoist_height} 54m {trip_time} 3min")


def put_hoist(results: Results, notes: list[str], hoist: Hoist, gravity_drive: float, friction: float | None, r1: float | None,
              torque_given: bool) -> list[Step]:
    """power_steady and torque_steady at --hoist-speed; energy_trip and power_trip over --hoist-height.
    ``gravity_drive`` D₀ (without --torque), ``friction`` F (None where a sliding coefficient is not known)."""
    steps: list[Step] = []
    if not hoist.asked:
        return steps
    if friction is None:
        notes.append("power_steady, torque_steady, energy_trip: need the sliding friction under each block on a surface (its mu-k)")
    if torque_given:
        notes.append("the hoist's results are the drive's own for a steady lift and a trip from rest to rest: --torque plays no part in them")
    if hoist.speed is not None:
        speed = hoist.speed
        power = None if friction is None else gravity_drive * speed + friction * abs(speed)
        results.put("power_steady", power)
        torque = None if friction is None or r1 is None else r1 * (gravity_drive + (friction if speed > 0 else -friction if speed < 0 else 0.0))
        results.put("torque_steady", torque)
        if r1 is None:
            notes.append("torque_steady: give --pulley-radius (the drive's torque is its pull on the string times r)")
        if power is not None:
            steps.append(Step(
                "Drive power for a steady lift (a = 0)",
                "P = D₀V + F|V|",
                f"{quantity_text(gravity_drive, 'N')} × {quantity_text(speed, 'm/s')} + {quantity_text(friction, 'N')} × {quantity_text(abs(speed), 'm/s')}",
                quantity_text(power, "W"),
                "D₀ is what gravity (and any pull) drives along the string toward m₁'s side, F the sliding and axle friction against it; "
                "at a steady speed nothing speeds up, so the drive balances them, and its power is that force times the speed" + ("; negative: it holds back (lowering)" if power < 0 else ""),
            ))
    if hoist.height is not None:
        height = hoist.height
        work = None if friction is None else gravity_drive * height + friction * abs(height)
        results.put("energy_trip", work)
        if hoist.trip_time is not None:
            results.put("power_trip", None if work is None else work / hoist.trip_time)
        if work is not None:
            steps.append(Step(
                "Drive energy per trip, from rest to rest",
                "W = D₀H + F|H|",
                f"{quantity_text(gravity_drive, 'N')} × {quantity_text(height, 'm')} + {quantity_text(friction, 'N')} × {quantity_text(abs(height), 'm')}",
                quantity_text(work, "J") + (f"; over {fmt(hoist.trip_time)} s, {quantity_text(work / hoist.trip_time, 'W')}" if hoist.trip_time else ""),
                "it starts and ends at rest, so the kinetic energy it gave comes back: the drive pays for the rise of the load "
                "less the fall of the counterweight, and for what friction takes",
            ))
    return steps


def put_work_brake(results: Results, axle_force: float, path: float | None, over: str) -> None:
    """work_brake = (τa/r1)·(the string's path), ``over`` naming the path; None where the path is not known."""
    results.put("work_brake", None if path is None else axle_force * abs(path), over)
