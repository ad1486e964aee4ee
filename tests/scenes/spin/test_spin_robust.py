"""spin-down's new options in any combination: an answer or a usage error, never a traceback, and
never an infinite or NaN result (a result that does not exist is None with a note)."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError

CHOICES = {
    "omega0": [0, 5, -5, 100, 1e-3],
    "alpha": [0, 2, -2, 1e-6],
    "time": [0, 1, 10, 1e4],
    "until_omega": [0, 3, -3, 50],
    "until_angle": [0, 3, -3, 100],
    "in_time": [0.5, 3],
    "power": [100, -100, 0],
    "ke0": [0, 10],
    "friction": [0, 0.5],
    "viscous": [0, 0.1],
    "drag": [0, 0.01],
    "drag_exponent": [1.5, 2, 3],
    "torque": [0, 1, -1],
    "inertia": [1, 0.01],
    "energy": [True],
    "method": ["auto", "rk4", "rk45", "euler", "exact"],
    "rim_speed": [3, -3],
    "radius": [0.5],
    "until_arc": [1, -1],
}

options = st.dictionaries(st.sampled_from(sorted(CHOICES)), st.just(None), min_size=1, max_size=6).flatmap(
    lambda keys: st.fixed_dictionaries({key: st.sampled_from(CHOICES[key]) for key in keys})
)


@settings(max_examples=400, deadline=None)
@given(options)
def test_any_combination_answers_or_refuses(given_):
    try:
        report = taucli.spin_down(**given_)
    except InputError:
        return
    for name, value in report.results.items():
        assert not (isinstance(value.value, float) and not math.isfinite(value.value)), (name, value)
