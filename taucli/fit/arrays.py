"""The model on arrays: a scene's result at every sample at once, where it has a closed form.

taucli.fit.model solves the scene once per sample per trial (``pipeline.solve``: about a
millisecond each). Where the samples differ only in their time and the scene's motion has a
closed form, the motion is set up once per trial by the scene's own code (``motion.evolve``: the
phases, the stop, a turn back after it) and only ω(t), θ(t) of each phase are evaluated here, on
numpy arrays, by the same closed forms as taucli.scenes.closed_forms (I dω/dt = A − bω − kω²):

    ω(t) = [ω₀E + (A + k r₊ ω₀) G/I] / [E + (kω₀ + β) G/I],  E = e^(−λt), G = (1 − E)/λ, λ = √D/I
    θ(t) = ω₀ G L(x) + r₊√D t² g2(λt)/I + t g1(λt) M(x) k r₊(ω₀ − r₊) G/I,  x = k(ω₀ − r₊)G/I

with g1, g2, L, M the series-guarded fractions of closed_forms (complex where D < 0), on arrays in
taucli.scenes.closed_arrays (which --mc's draws share). A power-law drag (n ≠ 1, 2) has no closed
form: its motion is stepped once per trial by the scene's own stepper, each sample read on from the
one before (``Motion.sampler``), not solved from t = 0.

Held to the scene: every trial also solves the scene itself at one sample (the ANCHOR), which
gives the refusals and notes as before, and the array's value there must agree with it to
AGREE (relative), else the trial falls back to the per-sample path for good. tests/fit/
test_fit_arrays.py holds the arrays to ``pipeline.solve`` on random scenes at every sample.
"""

from __future__ import annotations

import math

import numpy as np

from taucli.answering.inputs import read
from taucli.core.errors import InputError
from taucli.fit.budget import Spent
from taucli.numerics.elliptic import complete_k
from taucli.scenes.closed_arrays import phase_state
from taucli.scenes.motion import Evolver, Method, evolve
from taucli.scenes.spin.steps import TWO_PI, Torques

REFUSALS = (InputError, OverflowError, ZeroDivisionError, ValueError, ArithmeticError)
AGREE = 1e-9  # the anchor's relative difference past which the arrays are not used (they agree to about 1e-14)

# spin-down's inputs the arrays take (any other: the per-sample path); the results they give
SPIN_INPUTS = {"inertia", "omega0", "torque", "friction", "viscous", "drag", "drag_exponent", "time", "method"}
SPIN_RESULTS = {"omega": 0, "theta": 1, "revs": 1}
TRACED_AS = {("atwood", "distance"): "x"}  # a result the trajectory draws under another name (held to it at the anchor)


def motion_state(motion, t: np.ndarray, angle: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Motion.state_at at every t ≥ 0 of the array: (v, x) signed in the user's frame."""
    if motion.held_from_start:
        return np.zeros_like(t), np.zeros_like(t)
    direction, stop, second = motion.direction, motion.stop, motion.second
    if stop is None:
        speed, distance = phase_state(motion.first.closed, t, angle)
        return direction * speed, direction * distance
    before = t <= stop[0]
    if np.all(before):  # (every sample before the stop: no copies)
        speed, distance = phase_state(motion.first.closed, t, angle)
        return direction * speed, direction * distance
    v, x = np.empty_like(t), np.empty_like(t)
    speed, distance = phase_state(motion.first.closed, t[before], angle)
    v[before], x[before] = direction * speed, direction * distance
    after = ~before
    if second is None:
        v[after], x[after] = 0.0, direction * stop[1]
    else:
        speed, distance = phase_state(second.closed, t[after] - stop[0], angle)
        v[after], x[after] = second.direction * speed, direction * stop[1] + second.direction * distance
    return v, x


def stepped_state(motion, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Motion.state_at for a stepped motion: one run over the times in increasing order, each
    read on from the one before (Motion.sampler), not stepped from 0 for every sample."""
    order = np.argsort(t, kind="stable")
    sample = motion.sampler()
    v, x = np.empty_like(t), np.empty_like(t)
    for i in order:
        v[i], x[i] = sample(float(t[i]))
    return v, x


class SpinDown:
    """spin-down's ω, θ or revs at each sample's --time, under the torque laws (a drive, friction,
    viscous, drag kωⁿ), the body given by --inertia."""

    def __init__(self, y_key: str):
        self.index = SPIN_RESULTS[y_key]
        self.scale = 1 / TWO_PI if y_key == "revs" else 1.0

    @staticmethod
    def takes(arguments: dict) -> bool:
        if not set(arguments) <= SPIN_INPUTS or arguments.get("inertia") is None:
            return False
        return arguments.get("method", "auto") in ("auto", "exact") or (arguments.get("method") == "rk45" and arguments.get("drag")
                                                                        and arguments.get("drag_exponent", 2.0) not in (1.0, 2.0))

    def values(self, arguments: dict, t: np.ndarray) -> np.ndarray:
        drag, exponent = arguments.get("drag") or 0.0, arguments.get("drag_exponent")
        exponent = 2.0 if exponent is None else exponent
        viscous = arguments.get("viscous") or 0.0
        if drag and exponent == 1:  # kω is a viscous torque (torque_laws.solve)
            viscous, drag, exponent = viscous + drag, 0.0, 2.0
        torques = Torques(arguments.get("torque") or 0.0, arguments.get("friction") or 0.0, viscous, drag, exponent, None)
        closed = drag == 0 or exponent == 2
        motion = evolve(arguments["inertia"], torques, arguments.get("omega0") or 0.0, Evolver(Method("exact" if closed else "rk45")))
        state = motion_state(motion, t, self.index == 1) if closed else stepped_state(motion, t)
        return state[self.index] * self.scale


class Traced:
    """Any scene's result that its trajectory draws (taucli.writing.report.Trajectory: θ(t), ω(t),
    d(t), …), read at every sample time from the trajectory of the anchor's solve: the scene's own
    state(t), set up once per trial (its phases, its elliptic modulus, a stepper run on from one
    sample to the next), each sample a call of it, not a solve of the whole scene."""

    def __init__(self, y_key: str, scene: str):
        self.y_key = TRACED_AS.get((scene, y_key), y_key)

    def values(self, report, given: dict, t: np.ndarray) -> np.ndarray:
        trajectory = report.trajectory() if report.trajectory is not None else None
        keys = [key for key, _, _ in trajectory.curves] if trajectory is not None else []
        if trajectory is None or trajectory.state is None or self.y_key not in keys:
            raise ValueError("no state(t) of this result")
        index = keys.index(self.y_key)
        found = np.empty_like(t)
        for i in np.argsort(t, kind="stable"):  # in increasing time: a stepper steps on from the sample before
            found[i] = trajectory.state(float(t[i]))[index]
        return found


def of(model):
    """The array form of the fit's model, or None where the per-sample path is the only one: the
    samples vary in their time alone (each finite, ≥ 0) and no spec's key is fitted; spin-down's
    ω, θ, revs under the torque laws on numpy arrays (SpinDown), any other scene's result that its
    trajectory draws from its state(t) (Traced: found out at the first trial)."""
    samples = model.samples
    if any(unknown.key is not None for unknown in model.unknowns):
        return None
    if model.command.name == "pendulum" and set(samples.inputs) == {"angle0"} and samples.y_key == "period":
        return Periods.of(model)
    if set(samples.inputs) != {"time"}:
        return None
    t = np.asarray(samples.inputs["time"], dtype=float)
    if not (t.size and np.all(np.isfinite(t)) and np.all(t >= 0)):
        return None
    form = Traced(samples.y_key, model.command.name)
    if model.command.name == "spin-down" and samples.y_key in SPIN_RESULTS:
        try:
            arguments, _ = read(model.command, model.given([1.0] * len(model.unknowns), {"time": 0.0}))
        except Exception:  # noqa: BLE001 (a refusal here is the per-sample path's to give, with its reason)
            return None
        if SpinDown.takes({name: value for name, value in arguments.items() if value is not None}):
            form = SpinDown(samples.y_key)
    return Arrays(model, form, t)


class Periods:
    """A pendulum's period at each sample's amplitude θ₀ (from rest), under gravity alone:

        T(θ₀) = 4K(k)/ω₀ₙ,  k' = cos(θ₀/2)  (exact; the small-angle model: T₀ = 2π/ω₀ₙ at every θ₀)

    so T(θ₀ᵢ) = T(θ₀ₐ)·K(kᵢ)/K(kₐ): the scene solved at the anchor sample a gives ω₀ₙ's part,
    whatever the body (shape, parts, pivot) and g, and the ratios K(kᵢ) are the scene's own
    (taucli.numerics.elliptic.complete_k), worked out once. A second sample, the CHECK, solved
    each trial too, must agree: a scene whose period is not of this form (a torsion spring, a
    damping) is the per-sample path's after the first trial."""

    def __init__(self, ratio: np.ndarray):
        self.ratio = ratio

    @staticmethod
    def of(model):
        angles = np.asarray(model.samples.inputs["angle0"], dtype=float)
        if not (angles.size > 1 and np.all(np.isfinite(angles)) and np.all(np.abs(angles) < math.pi)):
            return None
        small = str(model.held.get("method", "")).replace("_", "-") == "small-angle"
        ratio = np.ones_like(angles) if small else np.array([complete_k(math.cos(a / 2)) for a in angles.tolist()])
        found = Arrays(model, Periods(ratio), angles)
        found.anchor, found.check, found.alone = int(np.argmax(np.abs(angles))), int(np.argmin(np.abs(angles))), 2
        return found

    def values(self, anchor: float, at: int) -> np.ndarray:
        return anchor / self.ratio[at] * self.ratio


class Arrays:
    """f(xᵢ; p) at every sample: the scene solved at the anchor sample (its refusals, and the
    check), the array form at all of them."""

    def __init__(self, model, form, t: np.ndarray):
        self.model, self.form, self.t = model, form, t
        self.anchor = int(np.argmax(t))  # the latest sample: past a stop, if there is one
        self.check: int | None = None  # a second sample solved each trial (Periods)
        self.alone = 1  # the samples the scene solves alone each trial (the anchor, and the check)
        self.failed = False

    def predict(self, p, moved=None, timed=lambda work, solves: work()) -> np.ndarray | None:
        """The values at every sample, or None where this trial is the per-sample path's (the
        arrays disagree with the scene at the anchor, or the form does not apply: never again for
        this fit). ``timed(work, solves)`` runs the array's work, counted as the solves it stands for."""
        model = self.model
        try:
            report = model.report(p, model.samples.row(self.anchor), moved)
        except REFUSALS as err:
            model.refusal = err  # (the per-sample path gives NaN with the reason kept, as before)
            return None
        result = report.results.get(model.samples.y_key)
        anchor = None if result is None else result.value
        if not isinstance(anchor, (int, float)) or isinstance(anchor, bool) or not math.isfinite(anchor):
            return None
        if isinstance(self.form, Periods):
            checked = model.value(p, self.check, moved)
            found = timed(lambda: self.form.values(float(anchor), self.anchor), len(self.t) - self.alone)
            if not abs(found[self.check] - checked) <= AGREE * abs(checked):
                self.failed = True
                return None
            found[self.check], found[self.anchor] = checked, float(anchor)
            return found
        try:
            arguments, _ = read(model.command, model.given(p, {"time": 0.0}, moved))
            given = {name: value for name, value in arguments.items() if value is not None}
            found = timed(lambda: self.form.values(report, given, self.t) if isinstance(self.form, Traced) else self.form.values(given, self.t),
                          len(self.t) - self.alone)
        except Spent:  # the fit's time limit, passed
            raise
        except Exception:  # noqa: BLE001 (a trajectory that cannot be read so, whatever the reason: the per-sample path, as before)
            self.failed = True
            return None
        if not abs(found[self.anchor] - anchor) <= AGREE * abs(anchor):
            self.failed = True
            return None
        found[self.anchor] = float(anchor)
        return found
