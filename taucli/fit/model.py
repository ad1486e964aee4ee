"""The model a fit matches to the samples: the scene itself, solved for each sample.

f(xᵢ; p) is the result measured (``omega``, ``period``, ``t``) as the scene gives it with the
options held (``--inertia 0.1kg*m^2``), sample i's own inputs (its time, its masses) and the
fitted inputs p in their places (an option, or a key of a spec, as ``--find`` names them:
taucli.answering.unknowns). Every value goes through ``pipeline.solve``, so the model is exactly what
``taucli SCENE`` answers for those options; a sample where the scene refuses the inputs, or has no
value for the result, is NaN here, and the reason is kept.

An option held with an uncertainty (``--inertia "0.100+/-0.002 kg*m^2"``) is held at its value;
``moved`` shifts it (SI) to find how the fit moves with it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from taucli.answering import pipeline
from taucli.core.errors import InputError, spelled
from taucli.fit import arrays, series
from taucli.fit.samples import Samples
from taucli.answering.inputs import read
from taucli.quantities.measurement import split
from taucli.quantities import units
from taucli.writing.report import Report, quantity_text
from taucli.options.table import Command
from taucli.answering.unknowns import Unknown

REFUSALS = series.REFUSALS
KEPT_VALUES = 2**22  # f's values kept for p asked again, over all the p kept (32 MB)


def held(command: Command, given: Mapping[str, object], spell, unknowns: list[Unknown] = ()) -> tuple[dict, dict[str, float], dict[str, float], list[str]]:
    """The options held: (each as given, "value ± σ" as its value; each σ in SI; each quantity's
    SI value; notes), as taucli.answering.answer reads uncertain options. A spec with a key fitted is read
    with a stand-in there (a spec without a key it needs is refused)."""
    readable = dict(given)
    for unknown in unknowns:
        if unknown.key is not None:
            readable = unknown.given_with(readable, 1.0 if unknown.sign == "positive" else 0.0)
    arguments, inputs = read(command, readable)
    central = dict(given)
    spreads: dict[str, float] = {}
    notes: list[str] = []
    for key, sigma in (inputs.uncertainties or {}).items():
        option = command.option(key)
        if option is None or not option.is_quantity or option.repeatable:
            notes.append(spelled(f"the uncertainty given in {key} is not carried through: only a scene's own single quantity options carry one", spell, command.option))
            continue
        central[key] = split(given[key])[0]
        if sigma > 0:
            spreads[key] = sigma
    si = {name: value for name, value in arguments.items() if isinstance(value, float)}
    return central, spreads, si, notes


class Model:
    """f(xᵢ; p) for every sample i: the scene's result ``samples.y_key``."""

    def __init__(self, command: Command, held_options: dict, unknowns: list[Unknown], samples: Samples, *, si: dict[str, float] | None = None,
                 spreads: dict[str, float] | None = None, stdin=None, spell=None):
        self.command, self.held, self.unknowns, self.samples = command, held_options, unknowns, samples
        self.si = dict(si or {})  # the held quantities in SI (to move an uncertain one)
        self.spreads = dict(spreads or {})
        self.stdin, self.spell = stdin, spell or command.flag
        self.solves = 0
        self.evaluations = 0  # of f at every sample (predict's, each n solves or one run of a time series)
        self.budget = None  # a taucli.fit.budget.Budget: the time the solves may take
        self.bounds: dict[str, tuple[float, float]] = {}  # --bound: a fitted input's (low, high), SI
        self.refusal: Exception | None = None
        self._cache: dict[tuple, np.ndarray] = {}
        self._runs = samples.runs if len(samples.runs) else None  # each sample's run, where there are several
        per_run = any(getattr(unknown, "run", None) is not None for unknown in unknowns)
        # f at every sample at once, where the scene has a form on arrays (else None; inputs fitted per run: per sample)
        self.arrays = None if per_run else arrays.of(self)
        self.series = not per_run and series.usable(self)  # else a time series: one run of the scene per p (taucli.fit.series)

    @property
    def names(self) -> list[str]:
        return [unknown.name for unknown in self.unknowns]

    def given(self, p, row: Mapping[str, float] | None = None, moved: Mapping[str, float] | None = None, run: int = 0) -> dict:
        """The scene's options for one sample (``row``: its inputs; ``run``: the run it is of) with
        the fitted inputs at p: an input fitted for each run (taucli.fit.runs) in its own run's alone."""
        given = {**self.held, **(moved or {}), **(row or {})}
        for unknown, x in zip(self.unknowns, p):
            if getattr(unknown, "run", run) == run:
                given = unknown.given_with(given, float(x))
        return given

    def report(self, p, row: Mapping[str, float] | None = None, moved: Mapping[str, float] | None = None, run: int = 0) -> Report:
        self.solves += 1
        given = self.given(p, row, moved, run)
        if self.budget is None:
            return pipeline.solve(self.command, given, stdin=self.stdin, spell=self.spell)
        return self.budget.timed(lambda: pipeline.solve(self.command, given, stdin=self.stdin, spell=self.spell))

    def value(self, p, i: int, moved: Mapping[str, float] | None = None) -> float:
        """f(xᵢ; p), or NaN where the scene refuses or has no value (the reason kept)."""
        try:
            result = self.report(p, self.samples.row(i), moved, 0 if self._runs is None else self._runs[i]).results.get(self.samples.y_key)
        except REFUSALS as err:
            self.refusal = err
            return math.nan
        value = None if result is None else result.value
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
            self.refusal = None
            return math.nan
        return float(value)

    def predict(self, p, moved: Mapping[str, float] | None = None) -> np.ndarray:
        """f(xᵢ; p) for every sample (kept: the same p is asked for again by the steps and the chart);
        a time series from one run of the scene where its trajectory gives it (taucli.fit.series)."""
        key = (tuple(float(x) for x in p), tuple(sorted((moved or {}).items())))
        found = self._cache.get(key)
        if found is None:
            self.evaluations += 1
            found = self._on_arrays(p, moved)
            if found is None and self.series:
                found = series.predict(self, p, moved)
            if found is None:
                found = np.array([self.value(p, i, moved) for i in range(self.samples.count)])
            if len(self._cache) >= min(4096, max(4, KEPT_VALUES // max(self.samples.count, 1))):
                del self._cache[next(iter(self._cache))]  # the oldest: a million samples keep a few, not 4096 × 8 MB
            self._cache[key] = found
        return found

    def _on_arrays(self, p, moved) -> np.ndarray | None:
        """f at every sample from taucli.fit.arrays (None: the per-sample path), counted as as many solves."""
        if self.arrays is None or self.arrays.failed:
            return None
        found = self.arrays.predict(p, moved, self._timed)
        if found is not None:
            self.solves += self.samples.count - self.arrays.alone  # (the samples the scene solved alone counted by themselves)
        return found

    def _timed(self, work, solves: int):
        """``work()``, counted as ``solves`` solves of the scene against the budget."""
        return work() if self.budget is None else self.budget.timed(work, solves)

    def at(self, p, row: Mapping[str, float]) -> float:
        """f at inputs ``row`` that are no sample's (a point of the chart's curve)."""
        try:
            result = self.report(p, row).results.get(self.samples.y_key)
        except REFUSALS:
            return math.nan
        value = None if result is None else result.value
        return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) else math.nan

    def shown(self, values: Mapping[str, float]) -> str:
        """Values of fitted inputs as a step shows them: "friction = 0.06 N·m, omega0 = 30 rad/s"."""
        return ", ".join(f"{name} = {quantity_text(value, units.KINDS[self.unknowns[self.names.index(name)].kind].si_unit)}" for name, value in values.items())

    def sign(self, j: int) -> str:
        return self.unknowns[j].sign

    def natural_lower(self, j: int) -> float:
        """The least value p_j's option takes (its sign): 0, or −∞."""
        return -math.inf if self.sign(j) == "any" else 0.0

    def lower(self, j: int) -> float:
        """The least value p_j may take: its option's (0, or −∞), or the --bound given, the larger."""
        return max(self.natural_lower(j), self.bounds.get(self.names[j], (-math.inf, math.inf))[0])

    def upper(self, j: int) -> float:
        """The largest value p_j may take: the --bound given, or +∞."""
        return self.bounds.get(self.names[j], (-math.inf, math.inf))[1]

    def allowed(self, j: int, x: float) -> bool:
        low = self.natural_lower(j)
        user_low, user_high = self.bounds.get(self.names[j], (-math.inf, math.inf))
        return math.isfinite(x) and (x > low if self.sign(j) == "positive" else x >= low) and user_low <= x <= user_high

    def on_user_bound(self, j: int, x: float, tolerance: float) -> bool:
        """p_j = x lies on a --bound (within ``tolerance``) that is not its option's own."""
        user_low, user_high = self.bounds.get(self.names[j], (-math.inf, math.inf))
        return (user_low > self.natural_lower(j) and x - user_low <= tolerance) or user_high - x <= tolerance

    def why_refused(self) -> str:
        err = self.refusal
        if err is None:
            return f"the scene gives no {self.samples.y_key} there"
        return err.spelled(self.spell) if isinstance(err, InputError) else str(err)
