"""A time series is one run of the scene per trial, not a solve per sample (#44 item 12).

A coast under a drag kωⁿ with n other than 1 or 2 has no closed form: each sample was a solve of
its own, integrated from 0 to its time, and the drag exponent's start was the roots of single
samples (thousands of solves): `--fit drag,drag_exponent,omega0` on 50 samples took 13–17 s
(13,461 solves). Now the start is a least squares of the integrated equation at each n, and each
trial's samples are read off one run of the scene through its trajectory (taucli.fit.series).

The reference is the physics, not taucli: I dω/dt = −kωⁿ gives
ω(t) = (ω₀^(1−n) + (n − 1)(k/I)t)^(1/(1−n)) (mpmath, 30 digits), with Gaussian noise.
"""

from __future__ import annotations

import io
import random

import mpmath
import numpy as np
import pytest

from taucli.fit import data, samples, series, solve
from taucli.options import SCENES

mpmath.mp.dps = 30


def coast(t, inertia, k, n, omega0):
    return (mpmath.mpf(omega0) ** (1 - n) + (n - 1) * (mpmath.mpf(k) / inertia) * t) ** (1 / (1 - mpmath.mpf(n)))


def _model(scene: str, text: str, fit: str, sigma=None, **options):
    command = SCENES[scene]
    table = data.read("-", io.StringIO(text))
    names = solve.names_of(fit)
    found = samples.build(command, [table], sigma=sigma, fitted=names, given=set(options))
    return solve.model_of(command, options, names, found)


def _count_solves(monkeypatch) -> list[int]:
    """The scene's own solves (pipeline.solve) from here on, counted: what a fit costs, whatever
    the model's accounting calls a solve (the arrays count one a sample, for the time budget)."""
    from taucli.answering import pipeline
    real, count = pipeline.solve, [0]

    def counted(*args, **kwargs):
        count[0] += 1
        return real(*args, **kwargs)

    monkeypatch.setattr(pipeline, "solve", counted)
    return count


def _table(rows) -> str:
    return "t (s),omega (rad/s)\n" + "".join(f"{t!r},{w!r}\n" for t, w in rows)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_drag_exponent_fits_in_few_solves_and_within_3_sigma(seed, monkeypatch):
    solved = _count_solves(monkeypatch)
    rng = random.Random(seed)
    inertia, k, n, omega0, noise = 0.1, rng.uniform(1e-3, 3e-3), rng.uniform(1.3, 2.7), rng.uniform(20, 40), 0.05
    times = [20 * i / 49 for i in range(50)]
    rows = [(t, float(coast(t, inertia, k, n, omega0)) + rng.gauss(0, noise)) for t in times]
    model, starts, _ = _model("spin-down", _table(rows), "drag,drag_exponent,omega0", sigma=f"{noise} rad/s", inertia="0.1 kg*m^2")
    found = solve.fit(model, starts)
    spread = np.sqrt(np.diag(found.covariance))
    for value, truth, s in zip(found.p, (k, n, omega0), spread):
        assert abs(value - truth) <= 3 * s, (found.p, (k, n, omega0), spread)
    assert solved[0] < 300, solved[0]  # the scene's solves: 13,461 before, a root search over the exponent, a solve per sample per trial


CASES = {
    "spin-down, drag exponent 1.5": ("spin-down", "omega", "drag,drag_exponent", [1e-3, 1.5], dict(inertia="0.1 kg*m^2", omega0="30 rad/s")),
    "spin-down, friction and drag 2.5 (a stop)": ("spin-down", "omega", "friction,drag_exponent", [0.05, 2.5],
                                                 dict(inertia="0.1 kg*m^2", omega0="30 rad/s", drag="0.001 N*m*s^2")),
    "spin-down, rk45 on request": ("spin-down", "theta", "friction,viscous", [0.05, 0.01], dict(inertia="0.1 kg*m^2", omega0="30 rad/s", method="rk45")),
    "pendulum, exact": ("pendulum", "theta", "g,angle0", [9.81, 0.5], dict(shape="point", mass="1 kg", radius="1 m")),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_one_run_gives_what_each_sample_solved_alone_gives(case):
    """The series read off one run agrees with the scene solved for each sample, in every scene with a trajectory."""
    scene, key, fit, p, options = CASES[case]
    times = [0.37 * i for i in range(30)]
    text = f"t (s),{key} ({'rad/s' if key == 'omega' else 'rad'})\n" + "".join(f"{t!r},1\n" for t in times)
    model, _, _ = _model(scene, text, fit, **options)
    assert model.series
    one_run = series.predict(model, np.array(p))
    assert one_run is not None
    each = np.array([model.value(np.array(p), i) for i in range(len(times))])
    scale = np.max(np.abs(each))
    assert np.max(np.abs(one_run - each)) <= 1e-7 * scale, (one_run, each)
