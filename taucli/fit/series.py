"""A time series from one run of the scene: its own trajectory at every sample's time.

Where the samples differ in their time alone and what was measured is a curve of the scene's
trajectory (spin-down's ``omega`` or ``theta``, a pendulum's ``theta``), f(tᵢ; p) for every i is
read off one run of the scene at p, solved to the last sample's time, through its trajectory's
sampler in increasing time: a stepping method (a drag kωⁿ with n other than 1 or 2, a damped
swing) steps on from the previous sample instead of from 0, so n samples cost one integration,
not n (50 samples of a drag exponent's coast: 13 s before, a few tenths of a second after).

Checked on the scene, not assumed: at every p, the trajectory at the last sample must give the
scene's own answer at --time there (within AGREE of the samples' size), else that p's samples
are each solved by the scene as before (taucli.fit.model).
"""

from __future__ import annotations

import math

import numpy as np

from taucli.core.errors import InputError

REFUSALS = (InputError, OverflowError, ZeroDivisionError, ValueError)  # what a solve of the scene may raise for inputs it refuses (taucli.fit.model's)
AGREE = 1e-7  # of the samples' largest size: the trajectory and the scene's own answer at the last sample agree within it


def usable(model) -> bool:
    """The samples differ in their time alone (their other inputs, if any, are one value)."""
    samples = model.samples
    return samples.count > 1 and samples.varying == ["time"]


def predict(model, p, moved=None) -> np.ndarray | None:
    """f(tᵢ; p) for every sample from one run of the scene, or None where it cannot be read so
    (no trajectory, a curve it does not draw, a refusal, or a trajectory that disagrees with the
    scene's answer): the caller then solves each sample."""
    samples = model.samples
    times = np.asarray(samples.inputs["time"], dtype=float)
    last = int(np.argmax(times))
    try:
        report = model.report(p, samples.row(last), moved)
        if report.trajectory is None:
            model.series = False  # (the scene draws no trajectory: each sample is solved, and the time budget counts so)
            return None
        trajectory = report.trajectory()
        keys = [key for key, _, _ in trajectory.curves]
        if samples.y_key not in keys or trajectory.state is None:
            model.series = False
            return None
        column = keys.index(samples.y_key)
        answer = report.results.get(samples.y_key)
        answer = None if answer is None else answer.value
        if not isinstance(answer, (int, float)) or isinstance(answer, bool) or not math.isfinite(answer):
            return None
        found = np.full(len(times), math.nan)
        for i in np.argsort(times, kind="stable"):
            found[i] = float(trajectory.state(float(times[i]))[column])
    except REFUSALS:
        return None
    size = max(float(np.max(np.abs(samples.y))), abs(answer))
    if not (np.all(np.isfinite(found)) and abs(found[last] - answer) <= AGREE * size):
        return None
    found[times == times[last]] = answer  # the scene's own answer where it was asked for
    return found
