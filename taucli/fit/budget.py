"""A fit's time bound (#43 item 12): its cost estimated before the fit, and refused past the limit.

Each evaluation of the model solves the scene once per sample, so

    cost ≈ (seconds per solve) × (samples) × (evaluations expected),

with the seconds per solve timed on a few samples spread over the table (a solve by steps costs in
proportion to the sample's time), and the evaluations the least a fit takes (a linear model:
f at p₀ and at p₀ + Δ, p₀ + 2Δ along each input, all moved together, and at the solution) until
the model is known to be nonlinear, then what a bounded search typically takes. The estimate is
made again as the fit goes, and the fit is refused once the time spent passes the limit, whatever
was estimated. The refusal names the setting that fits (--every N, a faster --method or a larger
--dt), as --find's and --mc's do (taucli.answering.propagate), with the same limit and --no-limit.
"""

from __future__ import annotations

import math
import time

from taucli.answering.propagate import OverBudget, solve_time
from taucli.fit import series

TIMED = 5  # samples timed before the fit, spread over the table


def linear_evaluations(m: int) -> int:
    """The least a fit of m inputs takes: f at p₀, at p₀ + Δ and p₀ + 2Δ along each input, with all
    moved (m > 1), at the solution, and for the diagnostics."""
    return 2 * m + 4


def nonlinear_evaluations(m: int) -> int:
    """What a bounded search over m inputs typically takes, its Jacobians and the covariance's
    (central, Richardson) included: 21 for a pendulum's g, 37 for g and angle0 together."""
    return 4 + 16 * m


class Spent(Exception):
    """The fit passed its budget: carries the refusal (an OverBudget) out through the fit's own
    handlers, which take an InputError from a solve for a sample the scene refuses (taucli.fit.command
    raises the refusal)."""

    def __init__(self, refusal: OverBudget):
        super().__init__(str(refusal))
        self.refusal = refusal


def before(model, p) -> None:
    """Time the scene's solve at p on a few samples spread over the table (after one untimed: the
    first solve imports its solver), or the model on arrays at every sample (taucli.fit.arrays),
    and plan the least a fit takes: refused here where even that passes the limit."""
    n = model.samples.count
    kept, model.budget = model.budget, None
    model.value(p, 0)
    on_arrays = model.arrays is not None and model.arrays.predict(p) is not None  # (the model at every sample at once: timed so)
    model.budget = kept
    if on_arrays and model.arrays.predict(p, None, model._timed) is not None:
        kept.plan(n, linear_evaluations(len(p)), len(p))
        return
    for i in sorted({round(k * (n - 1) / max(TIMED - 1, 1)) for k in range(min(TIMED, n))}):
        model.value(p, i)
    if model.series:  # one run read at every sample's time, where the scene's trajectory gives it (else model.series is cleared)
        series.predict(model, p)
    kept.plan(n, linear_evaluations(len(p)), len(p), per_evaluation(model))


def per_evaluation(model) -> int:
    """The solves an evaluation of f at every sample costs, in solves of one sample: n, or about 2
    where the samples are read off one run to the last sample's time (taucli.fit.series)."""
    return min(2, model.samples.count) if model.series else model.samples.count


class Budget:
    """Seconds spent in the scene's solves, against ``limit`` (None: no bound); ``progress`` is
    told (solves done, solves planned) after each solve. ``every``: the --every the samples were
    thinned by; ``faster``: the scene's options that make a solve faster (method, dt), where it has them."""

    def __init__(self, limit: float | None, progress=None, *, every: int = 1, faster=()):
        self.limit, self.progress, self.every, self.faster = limit, progress, every, tuple(faster)
        self.spent = 0.0
        self.solves = 0
        self.planned = 0  # solves in all
        self.samples = 0
        self.evaluations = 0  # of f at every sample, as planned
        self.inputs = 1

    def plan(self, samples: int, evaluations: int, inputs: int, per_evaluation: int | None = None) -> None:
        """``evaluations`` more of f at every one of ``samples`` (``inputs`` fitted), each
        ``per_evaluation`` solves (one a sample, or 2 for a time series read off one run, which
        costs about two of its samples' solves: taucli.fit.series): estimated now, and refused
        where the whole passes the limit."""
        self.samples, self.evaluations, self.inputs = samples, evaluations, inputs
        self.planned = self.solves + (samples if per_evaluation is None else per_evaluation) * evaluations
        self._check()

    def timed(self, solve, solves: int = 1):
        """``solve()``, its time counted as ``solves`` solves' (the model on arrays stands for one a
        sample: taucli.fit.arrays), and the fit refused once the time spent passes the limit."""
        started = time.perf_counter()
        try:
            return solve()
        finally:
            self.spent += time.perf_counter() - started
            self.solves += solves
            if self.progress is not None and self.planned:
                self.progress(min(self.solves, self.planned), self.planned)
            if self.limit is not None and self.spent > self.limit:
                self._check()

    def _check(self) -> None:
        if self.limit is None or not self.solves:
            return
        each = self.spent / self.solves
        estimate = max(each * max(self.planned, self.solves), self.spent)
        if estimate > self.limit:
            raise Spent(self._refusal(each, estimate))

    def _refusal(self, each: float, estimate: float) -> OverBudget:
        took = (f"is estimated to take about {estimate:,.0f} s ({_count(self.evaluations, 'evaluation')} of the scene at "
                f"{_count(self.samples, 'sample')}, a solve of about {solve_time(each)} each), over the {self.limit:.0f} s limit")
        ways = []
        most = max(estimate, each * self.samples * nonlinear_evaluations(self.inputs))  # (--every's N fits a search too)
        thinned = math.ceil(most / self.limit * 1.25)  # (a margin: the estimate is one)
        if self.samples // thinned >= 3:
            ways.append(f"{{every}} {thinned * self.every} fits")
        if self.faster:
            ways.append("a faster solve (" + ", or ".join("{method} auto where a closed form exists" if name == "method" else f"a larger {{{name}}}"
                                                          for name in self.faster) + ")")
        hint = (" or ".join(ways) if ways else "fewer samples ({range})") + "; {no_limit} runs it as asked"
        return OverBudget("fit", took, hint=hint)


def _count(n: int, what: str) -> str:
    return f"{n:,} {what}{'' if n == 1 else 's'}"
