"""Random scenes and their comparison with the references, shared by the tests and the benchmark.

A ``draw_*`` function takes a random.Random and returns the keywords of one scene (SI numbers,
angles and angular velocities as "… rad" and "… rad/s" texts, read exactly); a ``check_*``
function runs taucli's Python API on them and returns a list of Row: each result that has a
reference, taucli's value, the reference's, its relative error and the budget it is held to.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from references import DPS, mp, mpf, relative_error


@dataclass
class Row:
    name: str
    got: object
    exact: object
    budget: float
    known: str = ""  # a disagreement the project knows of (its own strict-xfail test names it)
    floor: object = 0  # the error is relative to max(|exact|, floor) (a quantity passing through 0)

    @property
    def error(self) -> float:
        if self.exact is None or self.got is None:
            return 0.0 if self.exact is None and self.got is None else math.inf
        if isinstance(self.exact, bool):
            return 0.0 if bool(self.got) == self.exact else math.inf
        if self.floor:
            with mp.workdps(DPS):
                return float(abs(mpf(self.got) - mpf(self.exact)) / max(abs(mpf(self.exact)), mpf(self.floor)))
        return relative_error(self.got, self.exact)

    @property
    def ok(self) -> bool:
        return self.error <= self.budget


def rad(x: float) -> str:
    return f"{x!r} rad"


def rad_s(x: float) -> str:
    return f"{x!r} rad/s"


def value(report, key):
    item = report.results.get(key)
    return None if item is None else item.value


def log_uniform(rng, lo: float, hi: float) -> float:
    return 10 ** rng.uniform(lo, hi)


def as_float(x) -> float:
    return float(mpf(x))
