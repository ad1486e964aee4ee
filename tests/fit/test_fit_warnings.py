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
