"""The motion that follows: m1's time and speed after --distance, its speed and displacement at
--time, and the trajectory to plot. The masses move under constant forces, in uniform phases
(motion.evolve's: a stop, static friction, a second phase the other way), each one

    x = u t + ½ a t²,   v = u + a t,   so the time to a path length d: t = 2d / (u + √(u² + 2ad))
"""

from __future__ import annotations

import math

from taucli.writing.report import Trajectory, Value, fmt, quantity_text
from taucli.scenes.motion import Evolver, Loads, Method, Motion, evolve
from taucli.options.table import Results


def evolve_exact(mass: float, loads: Loads, v0: float) -> Motion:
    """The motion of ``mass`` under ``loads`` from speed v0, in closed form."""
    return evolve(mass, loads, v0, Evolver(Method("exact")))


def put_motion(results: Results, motion, distance: float | None, time: float | None, notes: list[str], *, stop: bool = False) -> None:
    """t and v after --distance, v and the displacement at --time: m1's, as solve gives them;
    with ``stop``, when and where the masses first stop (t_stop, distance_stop: 0 where they
    never move, null where they never stop)."""
    if distance is not None:
        reached = time_to_travel(motion, distance)
        if reached is None:
            notes.append(_never_travel(motion, distance))
        results.put("t", reached, f" {fmt(distance)} m")
        results.put("v", None if reached is None else motion.state_at(reached)[0] + 0.0, f" after {fmt(distance)} m")  # + 0.0: 0, not −0
    if time is not None:
        speed, displacement = motion.state_at(time)
        speed, displacement = speed + 0.0, displacement + 0.0  # at rest, or at --time 0: 0, not −0 (#42 item 22)
        if "v" not in results:
            results.put("v", speed, f" at t = {fmt(time)} s")
        results.put("distance", displacement, f" at t = {fmt(time)} s")
        if distance is not None:
            notes.append("v is given at the distance; distance at the time")
    if stop:
        if motion.held_from_start:
            results.put("t_stop", 0.0)
            results.put("distance_stop", 0.0)
        elif motion.stop is None:
            results.put("t_stop", None)
            results.put("distance_stop", None)
            notes.append("t_stop, distance_stop: null, because the masses never stop: "
                         + ("the net force is along their motion" if motion.first.closed.omega0 else "set going from rest, they speed up"))
        elif not all(map(math.isfinite, motion.signed_stop)):  # friction so slight the stop is beyond a double's reach
            results.put("t_stop", None)
            results.put("distance_stop", None)
            notes.append("t_stop, distance_stop: null, because the stop is too far off to be represented (the friction against the motion is that slight)")
        else:
            results.put("t_stop", motion.signed_stop[0])
            results.put("distance_stop", motion.signed_stop[1])


def time_to_travel(motion, distance: float) -> float | None:
    """The time at which m1 is ``distance`` from its start along the way the masses first move
    (its displacement's size that way); None where they stop short of it: held there, or turning
    back (#42 item 5: a path length out and back again was taken for a displacement)."""
    if motion.held_from_start:
        return 0.0 if distance == 0 else None
    first, stop = motion.first.closed, motion.stop
    if stop is None or distance <= stop[1]:
        return _uniform_time(first.omega0, first.constant / first.inertia, distance)
    return None


def _never_travel(motion, distance: float) -> str:
    """Why t and v after --distance are null: the masses never move, or stop short and stay or turn back."""
    what = f"the masses never travel {quantity_text(distance, 'm')}"
    if motion.held_from_start or motion.stop is None:
        return what
    then = "turn back" if motion.second is not None else "stay there"
    return (f"{what} that way: they stop after {quantity_text(motion.stop[1], 'm')} and {then} "
            "(t_stop, distance_stop give the stop; --time follows them on)")


def _uniform_time(speed: float, acceleration: float, distance: float) -> float:
    """The first t ≥ 0 with speed·t + ½at² = distance: 2d/(u + √(u² + 2ad)), free of cancellation."""
    if distance == 0:
        return 0.0
    return 2 * distance / (speed + math.sqrt(max(speed * speed + 2 * acceleration * distance, 0.0)))


def trajectory(motion, distance: float | None, time: float | None, results: dict[str, Value]) -> Trajectory:
    """Position and velocity of m1 (down positive): to --time, or to --distance, or past the stop.
    ``motion`` is the Motion, or (mass, loads, v0) to evolve it from."""
    if not isinstance(motion, Motion):
        motion = evolve_exact(*motion)
    stop, note, marks = motion.stop, "", []
    reached = results["t"].value if distance is not None else None
    if time is not None and time > 0:
        t_end = time
    elif reached:
        t_end = reached
    elif stop is not None and stop[0] > 0:
        t_end = 1.25 * stop[0]
    else:
        t_end, note = 1.0, "plotted for 1 s; --time or --distance to change"
    if reached:
        marks.append((reached, f"has moved {fmt(distance)} m"))
    if stop is not None and stop[0] > 0:
        marks.append((stop[0], "stops"))
    curves = (("x", "m", "position of m1, down positive"), ("v", "m/s", "velocity of m1"))
    return Trajectory(curves, t_end, lambda t: motion.state_at(t)[::-1], marks=tuple(marks), note=note)
