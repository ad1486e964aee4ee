"""A motor's duty cycle as a table of segments (--segment): its RMS torque and power.

A motor heats as the square of its current, so of its torque (and at a steady speed, of its
power): over a cycle of segments each with its time tᵢ and its torque τᵢ (or power Pᵢ), the steady
load that heats it as much is

    τ_rms = √(Σ τᵢ² tᵢ / Σ tᵢ′),   P_rms = √(Σ Pᵢ² tᵢ / Σ tᵢ′)

where tᵢ′ = tᵢ for a segment the motor runs in (loaded or idle), and tᵢ/k for one it stands
still in (rest=yes): a self-ventilated motor cools more slowly at rest, and the books weight its
rest time by 1/k (k = --rest-factor, 1 by default: a motor cooled as well at rest; the duty
class or the maker gives k, often 3 or 4).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.options.drive import COMMAND as TABLE
from taucli.options.table import Results
from taucli.writing.report import Report, Step, fmt, quantity_text


class Segment(NamedTuple):
    source: str
    time: float
    torque: float | None
    power: float | None
    rest: bool = False


def duty_cycle(segments: tuple[Segment, ...], rest_factor: float | None, rated_torque: float | None, rated_power: float | None) -> Report:
    """torque_rms (segments by torque) or power_rms (by power), with the cycle's time and peak."""
    by_torque = [s for s in segments if s.torque is not None]
    if by_torque and len(by_torque) != len(segments):
        raise InputError("segment", "expected every segment by torque= or every one by power=: their squares add only alike",
                         example='{segment} "time=10min power=100kW" {segment} "time=5min power=0"')
    factor = 1.0 if rest_factor is None else rest_factor
    if factor < 1:
        raise InputError("rest_factor", "expected a number of at least 1: the rest time counts 1/k of itself", example="{rest_factor} 3", got=fmt(factor))
    weighted = math.fsum(s.time / factor if s.rest else s.time for s in segments)
    quantity, unit, key = ("torque", "N*m", "torque_rms") if by_torque else ("power", "W", "power_rms")
    loads = [getattr(s, quantity) for s in segments]
    scale = max(abs(value) for value in loads) or 1.0
    rms = scale * math.sqrt(math.fsum((value / scale) ** 2 * s.time for value, s in zip(loads, segments)) / weighted)
    results = Results(TABLE)
    results.put(key, rms, "" if key == "power_rms" else " over the cycle")
    results.put("t_cycle", math.fsum(s.time for s in segments))
    results.put("torque_peak" if by_torque else "power_peak", max(abs(value) for value in loads))
    notes = []
    rated = rated_torque if by_torque else rated_power
    other = rated_power if by_torque else rated_torque
    if other is not None:
        raise InputError("rated_power" if by_torque else "rated_torque", f"goes with segments by {'power' if by_torque else 'torque'}: the segments here are by {quantity}",
                         example="{rated_torque} '10N*m'" if by_torque else "{rated_power} 5kW")
    if rated is not None:
        results.put("rms_to_rated", rms / rated)
        if rms > rated:
            notes.append(f"the RMS {quantity} {quantity_text(rms, unit)} is over the rating {quantity_text(rated, unit)}: the motor would run hot")
    symbol = "τ" if by_torque else "P"
    rests = any(s.rest for s in segments)
    terms = " + ".join(f"({quantity_text(value, unit)})² × {quantity_text(s.time, 's')}" for value, s in zip(loads, segments))
    times = " + ".join((f"{quantity_text(s.time, 's')}/{fmt(factor)}" if s.rest and factor != 1 else quantity_text(s.time, "s")) for s in segments)
    steps = [Step(f"RMS {quantity} over the duty cycle", f"{symbol}_rms = √(Σ {symbol}ᵢ² tᵢ / Σ tᵢ′)" + (",  tᵢ′ = tᵢ/k at rest" if rests else ""),
                  f"√(({terms}) / ({times}))", quantity_text(rms, unit),
                  f"the motor heats as the square of its current; the steady {quantity} that heats it as much is the RMS"
                  + ("; at rest it cools more slowly, so its rest time counts 1/k of itself" if rests else ""))]
    return Report("drive", f"a duty cycle of {len(segments)} segment{'s' if len(segments) != 1 else ''}, by {quantity}", "closed form", results, steps, notes)
