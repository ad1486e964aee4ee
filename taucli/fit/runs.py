"""Several runs fitted together (#44): the runs of a fit are its files and the runs side by side in
one (taucli.fit.columns.split_runs); the inputs --fit names are shared by every run, and those
--per-run names as well are fitted for each run on its own (each run's ω₀, or its start time):

    f(xᵢ; p_shared, p_r(i))   with r(i) the run of sample i,

so ``--fit friction,viscous,omega0 --per-run omega0`` on two coasts fits one friction and one
viscous coefficient to both, and ``omega0_run1``, ``omega0_run2`` (each ± its uncertainty, from
the one covariance of the joint fit).

The start: each run fitted alone first (an ordinary fit of its samples, with every input of
--fit its own), then each shared input starts at the median of the runs' values and each
per-run one at its own run's; a run whose own fit fails starts at the others' median.

Plain Python over the fit's own types: no numpy here.
"""

from __future__ import annotations

import statistics
from collections.abc import Callable
from dataclasses import dataclass

from taucli.answering.unknowns import Unknown
from taucli.core.errors import InputError
from taucli.fit.samples import Samples

OPTION = "per_run"


@dataclass(frozen=True)
class OfRun(Unknown):
    """An input fitted for one run alone (taucli.fit.model applies it to that run's samples)."""

    run: int = 0  # the run's index in the samples' run_names
    run_name: str = ""
    shared: str = ""  # the input's own name (omega0), as --fit and --per-run name it

    @property
    def label(self) -> str:
        return f"{Unknown(self.shared, self.option, self.kind, self.sign, self.key, self.number).label} of run {self.run + 1} ({self.run_name})"


def names(text) -> list[str]:
    """The inputs --per-run names ("omega0", "omega0,time0", or several such)."""
    text = ",".join(str(part) for part in text) if isinstance(text, (list, tuple)) else str(text or "")
    return [name.strip().lstrip("-").replace("-", "_") for name in text.replace(" ", ",").split(",") if name.strip()]


def expand(unknowns: list[Unknown], per_run: list[str], samples: Samples) -> list[Unknown]:
    """The unknowns with each that --per-run names replaced by one for each run, in its place."""
    if not per_run:
        return list(unknowns)
    fitted = [unknown.name for unknown in unknowns]
    for name in per_run:
        if name not in fitted:
            raise InputError(OPTION, f"names {name}, which {{fit}} does not fit: an input fitted for each run is one {{fit}} names",
                             example=f"{{fit}} {','.join([*fitted, name])} {{per_run}} {name}", got=repr(name))
    runs = len(samples.run_names)
    if runs < 2:
        raise InputError(OPTION, f"fits {', '.join(per_run)} for each run, and the samples are one run: give several files, "
                         "or a table of several runs side by side (Run 1: Time (s), Run 2: Time (s))")
    if len(per_run) * runs > samples.count - len(unknowns):
        raise InputError(OPTION, f"fits {len(per_run) * runs} inputs over {runs} runs, and there are {samples.count} samples: "
                         "a fit needs more samples than inputs", hint="give more samples, or fewer inputs for each run")
    found: list[Unknown] = []
    for unknown in unknowns:
        if unknown.name not in per_run:
            found.append(unknown)
            continue
        found += [OfRun(f"{unknown.name}_run{run + 1}", unknown.option, unknown.kind, unknown.sign, unknown.key, unknown.number,
                        run=run, run_name=samples.run_names[run], shared=unknown.name) for run in range(runs)]
    return found


def starts(samples: Samples, unknowns: list[Unknown], given: dict[str, float], fit_run: Callable[[Samples], dict[str, float]]) -> dict[str, float]:
    """The joint fit's start (the module's rule): ``fit_run`` fits one run's samples alone and
    gives each input's value (or raises InputError)."""
    found: list[dict[str, float] | None] = []
    for run in range(len(samples.run_names)):
        try:
            found.append(fit_run(samples.of_runs({run})))
        except InputError:
            found.append(None)
    start: dict[str, float] = {}
    for unknown in unknowns:
        shared = getattr(unknown, "shared", unknown.name)
        values = [values[shared] for values in found if values is not None and shared in values]
        if isinstance(unknown, OfRun) and found[unknown.run] is not None and shared in found[unknown.run]:
            start[unknown.name] = found[unknown.run][shared]
        elif values:
            start[unknown.name] = statistics.median(values)
        elif shared in given:
            start[unknown.name] = given[shared]
    return start
