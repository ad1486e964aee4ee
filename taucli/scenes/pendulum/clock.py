"""A start on a clock (--start-time): the motion's own time is the clock's less the start's, and
before the start the body is held at θ₀ (a recording started before the release). A start with a
speed has no motion before it in this scene: a time before it is refused."""

from __future__ import annotations

import dataclasses

from taucli.core.errors import InputError
from taucli.writing.report import Trajectory, fmt


def since(time: float | None, start_time: float | None, swing) -> float | None:
    """The motion's own time at clock time ``time`` (negative: before the start, held)."""
    if time is None or start_time is None:
        return time
    elapsed = time - start_time
    if elapsed < 0 and swing.omega0 != 0:
        raise InputError("time", "is before {start_time}, and the body moves at its start ({omega0}): the scene has no motion before it",
                         example="{time} 2s {start_time} 0.5s")
    return elapsed


def note(time: float, start_time: float) -> str:
    elapsed = time - start_time
    if elapsed < 0:
        return f"t = {fmt(time)} s on the clock is {fmt(-elapsed)} s before the start ({{start_time}} {fmt(start_time)} s): the body is held at θ₀ there"
    return f"t = {fmt(time)} s on the clock is {fmt(elapsed)} s after the start ({{start_time}} {fmt(start_time)} s)"


def on_clock(build, start_time: float | None, theta0: float) -> Trajectory:
    """The trajectory ``build()`` (on the motion's own time) on the clock of --start-time: held at
    θ₀ before the start."""
    base = build()
    if not start_time:
        return base
    def state(t: float, inner=base.state) -> tuple[float, ...]:
        return (theta0, 0.0) if t < start_time else inner(t - start_time)

    return dataclasses.replace(
        base, t_end=base.t_end + max(start_time, 0.0), state=state if base.state is not None else None,
        points=tuple((t + start_time, *rest) for t, *rest in base.points), marks=tuple((t + start_time, what) for t, what in base.marks),
    )
