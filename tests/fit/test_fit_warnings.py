"""A fit that may be wrong says so, to a person and to a script alike (#44 items 4 and 5).

Every table here is made from the physics (closed forms of the motion, numpy's random numbers at
a fixed seed), never from taucli's own output:

- a coast-down under friction alone, ω(t) = ω₀ − (τ/I)t until it stops;
- a coast-down under viscous drag alone, ω(t) = ω₀e^(−bt/I);
- a pendulum's swing from rest, sin(θ/2) = sin(θ₀/2) sn(K − √(g/L) t | sin²(θ₀/2)).

Item 5: under --get and --json each warning goes to stderr, one line each ("taucli: warning: …"),
and the JSON keeps it among its notes. Item 4: the checks flag gross failures (residuals that
alternate, R² < 0, χ²/ν far from 1 either way), say when a test is too weak to run, and a model
that fits, with the σ of its noise given, raises no warning over many seeds.
"""

from __future__ import annotations

import io
import json

import numpy as np
import pytest

pytest.importorskip("scipy")

from taucli.fit import command  # noqa: E402
from taucli.front.cli import Environment, main  # noqa: E402

INERTIA = 0.1  # kg·m²


def line(t, omega0=30.0, friction=0.3):
    """ω(t) under friction alone, I = 0.1 kg·m²: a straight line until it stops."""
    return np.maximum(omega0 - friction / INERTIA * np.asarray(t, dtype=float), 0.0)


def viscous(t, omega0, b=0.02):
    """ω(t) under viscous drag alone, I = 0.1 kg·m²."""
    return omega0 * np.exp(-b * np.asarray(t, dtype=float) / INERTIA)


def table(t, y, header="t (s),omega (rad/s)") -> str:
    return header + "\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(np.asarray(t, float).tolist(), np.asarray(y, float).tolist()))


def run(text: str, *args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    code = main(["fit", *args[:1], "-", *args[1:]], Environment(stdin=io.StringIO(text), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


def notes_of(text: str, scene: str, fit: str, **options) -> list[str]:
    known = {key: options.pop(key) for key in ("x", "y", "sigma", "ranges", "every") if key in options}
    report, _ = command.fit_of(scene, ["-"], options, fit=fit, stdin=io.StringIO(text), **known)
    return list(report.notes)


def warnings_of(notes: list[str]) -> list[str]:
    return [note for note in notes if note.startswith("warning: ")]


def _too_small_sigma():
    rng = np.random.default_rng(44)
    t = np.arange(0, 10, 0.5)
    return table(t, line(t) + rng.normal(0, 0.5, len(t))), ("spin-down", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--sigma", "0.01rad/s")


def _wrong_model():
    rng = np.random.default_rng(45)
    t = np.arange(0, 15, 0.25)
    return table(t, viscous(t, 30.0) + rng.normal(0, 0.02, len(t))), ("spin-down", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0")


WARNED = {"σ given 50× too small": _too_small_sigma, "a line through an exponential": _wrong_model}


@pytest.mark.parametrize("case", list(WARNED))
def test_every_warning_reaches_stderr_under_get_and_json(case):
    """χ²/ν = 2,400 once printed as a bare `0.2984 0.00008` on stdout and nothing on stderr."""
    text, args = WARNED[case]()
    code, out, err = run(text, *args, "--json")
    assert code == 0
    said = warnings_of(json.loads(out)["notes"])
    assert said, "the case is one that warns"
    expected = [f"taucli: warning: {' '.join(note[len('warning: '):].split())}" for note in said]
    assert err.splitlines() == expected
    code, out, err = run(text, *args, "--get", "friction", "--uncertainty")
    assert code == 0 and len(out.splitlines()) == 1
    assert err.splitlines() == expected
    code, out, err = run(text, *args, "--no-steps")  # the person reads them among the notes, as before
    assert err == "" and all(note.split()[0] in out for note in said)


def test_a_fit_without_warnings_prints_numbers_alone():
    rng = np.random.default_rng(46)
    t = np.arange(0, 10, 0.5)
    code, out, err = run(table(t, line(t) + rng.normal(0, 0.05, len(t))), "spin-down", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0",
                         "--sigma", "0.05rad/s", "--get", "friction")
    assert code == 0 and err == "" and float(out) == pytest.approx(0.3, rel=0.02)


def test_two_coasts_fitted_with_one_omega0_are_said_to_be_the_wrong_model():
    """Two coasts from 12 and 9 rad/s (b = 0.02 N·m·s, σ = 0.01 rad/s), their rows one after the
    other, fitted with one ω₀: the residuals alternate between the runs at each time (too many runs,
    r₁ near −1), which the one-sided tests never flagged ("no shape seen beyond chance")."""
    rng = np.random.default_rng(47)
    t = np.arange(0, 12, 0.5)
    rows = np.concatenate([viscous(t, 12.0), viscous(t, 9.0)]) + rng.normal(0, 0.01, 2 * len(t))
    notes = notes_of(table(np.concatenate([t, t]), rows), "spin-down", "viscous,omega0", inertia="0.1 kg*m^2")
    said = [note for note in warnings_of(notes) if note.startswith("warning: the residuals have a shape")]
    assert said and "alternate" in said[0]


def test_the_wrong_scene_is_said_to_fit_worse_than_the_mean():
    """A coast-down fitted as a pendulum's ω(t): R² below 0, once without a warning."""
    rng = np.random.default_rng(48)
    t = np.arange(0, 18, 1.5)
    text = table(t, np.maximum(30.0 - 0.6 * t, 0) + rng.normal(0, 0.05, len(t)))
    notes = notes_of(text, "pendulum", "g", shape="point", mass="1 kg", radius="1 m", angle0="90 deg")
    assert any(note.startswith("warning: R² = ") and "is below 0" in note and "worse than their mean" in note for note in notes)


@pytest.mark.parametrize("factor,said", [(10.0, "the uncertainties given are larger than the scatter"),
                                         (0.1, "the residuals are larger than the uncertainties")])
def test_chi2_far_from_1_either_way_is_a_warning(factor, said):
    """σ given 10× too large gave χ²/ν = 0.01 and no word; 10× too small a warning already."""
    rng = np.random.default_rng(49)
    t = np.arange(0, 10, 0.5)
    text = table(t, line(t) + rng.normal(0, 0.05, len(t)))
    notes = notes_of(text, "spin-down", "friction,omega0", inertia="0.1 kg*m^2", sigma=f"{0.05 * factor!r} rad/s")
    assert any(note.startswith("warning: χ²/ν = ") and said in note for note in notes)


@pytest.mark.parametrize("n", [10, 12, 14])
def test_a_test_too_weak_for_the_samples_is_said_to_be_left_out(n):
    """With 10 to 14 samples the runs test cannot reach a chance of 0.1 % (its least is
    2·2/C(n, n/2) or so); it once reported "no shape seen beyond chance" all the same."""
    rng = np.random.default_rng(50 + n)
    t = np.linspace(0, 9, n)
    report, found = command.fit_of("spin-down", ["-"], {"inertia": "0.1 kg*m^2"}, fit="friction,omega0",
                                   stdin=io.StringIO(table(t, line(t) + rng.normal(0, 0.05, n))))
    step = next(step for step in report.steps if step.title == "The fit's quality")
    assert "the runs test of their signs cannot reach a chance of 0.1 %" in step.why
    assert found.quality.runs_weak


def test_too_few_samples_for_any_shape_test_is_a_note():
    rng = np.random.default_rng(51)
    t = np.arange(0, 8, 1.0)
    notes = notes_of(table(t, line(t) + rng.normal(0, 0.05, len(t))), "spin-down", "friction,omega0", inertia="0.1 kg*m^2")
    assert any(note.startswith("the residuals are not tested for a shape: 8 samples are too few") for note in notes)


SEEDS = 200


@pytest.mark.parametrize("n", [12, 20, 40])
def test_a_model_that_fits_with_its_sigma_given_raises_no_warning_in_98_percent_of_seeds(n):
    """The right model (friction alone, a line) with the σ of its noise given: each test flags at a
    chance of 0.1 % (the runs, the autocorrelation, χ² either way): together about 0.4 %, so over
    200 seeds at most 4 warnings (2 %), and χ²/ν, R² and the shape of a fit that is right stay quiet."""
    rng = np.random.default_rng(1000 + n)
    t = np.linspace(0, 9, n)
    warned = 0
    for _ in range(SEEDS):
        notes = notes_of(table(t, line(t) + rng.normal(0, 0.05, n)), "spin-down", "friction,omega0", inertia="0.1 kg*m^2", sigma="0.05 rad/s")
        warned += bool(warnings_of(notes))
    assert warned <= 0.02 * SEEDS, warned
