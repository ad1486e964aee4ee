"""A fit is bounded in time (#43 item 12), as --find and --mc are: its cost is estimated before the
fit (a solve timed on a few samples × samples × evaluations) and refused past the same 60 s limit,
naming the setting that fits; a progress bar on stderr only where it is a terminal."""

from __future__ import annotations

import io
import math
import re
import time

import pytest

from conftest import assert_usage_error, run_taucli
from fit_synthetic import coast_down, csv
from taucli.answering.answer import LIMIT_SECONDS
from taucli.answering.propagate import OverBudget
from taucli.fit import command
from taucli.front.cli import Environment, main

# A swing θ(t) = 0.5 rad·cos(√(g/L) t) sampled at 50 Hz for 20 s: each rk4 solve (dt = 1 ms) steps
# up to 20,000 times, and a fit solves every sample 20 times or more: tens of minutes (killed at 20).
SWING = "t (s),theta (rad)\n" + "".join(f"{0.02 * i:.2f},{0.5 * math.cos(math.sqrt(9.81) * 0.02 * i):.5f}\n" for i in range(1000))
SWING_FIT = ("--shape", "point", "--mass", "1kg", "--radius", "1m", "--angle0", "0.5rad", "--fit", "g")


@pytest.fixture
def swing(tmp_path):
    path = tmp_path / "swing.csv"
    path.write_text(SWING)
    return str(path)


@pytest.fixture
def coast(tmp_path):
    path = tmp_path / "coast.csv"
    path.write_text(csv("t (s),omega (rad/s)", coast_down([0.5 * i for i in range(30)], 0.05, 21), ("g", ".4f")))
    return str(path)


def test_a_fit_estimated_past_the_limit_is_refused_in_seconds_naming_every_and_the_method(swing):
    started = time.monotonic()
    done = run_taucli("fit", "pendulum", swing, *SWING_FIT, "--method", "rk4", "--no-steps", timeout=60)
    assert time.monotonic() - started < 20
    assert_usage_error(done, "--fit is estimated to take about", "1,000 samples", f"over the {LIMIT_SECONDS:.0f} s limit",
                       "a larger --dt, or --method auto", "--no-limit runs it as asked")
    every = int(re.search(r"--every (\d+) fits", done.err).group(1))
    estimate = float(re.search(r"about ([\d,]+) s", done.err).group(1).replace(",", ""))
    assert estimate > LIMIT_SECONDS and 2 <= every < 1000 // 3


def test_a_fit_under_the_limit_runs_and_gives_what_it_gives_without_one(coast):
    args = dict(fit="friction,viscous,omega0")
    bounded = command.fitted("spin-down", [coast], {"inertia": "0.1kg*m^2"}, **args)
    limited, _ = command.fit_of("spin-down", [coast], {"inertia": "0.1kg*m^2"}, **args, limit=LIMIT_SECONDS)
    assert {k: v.value for k, v in limited.results.items()} == {k: v.value for k, v in bounded.results.items()}
    with pytest.raises(OverBudget, match=r"^fit is estimated to take about .* over the 0 s limit; .*no_limit runs it as asked$"):
        command.fit_of("spin-down", [coast], {"inertia": "0.1kg*m^2"}, **args, limit=1e-9)


def test_no_limit_lifts_it(coast):
    done = run_taucli("fit", "spin-down", coast, "--inertia", "0.1kg*m^2", "--omega0", "30rad/s", "--fit", "friction", "--get", "friction", "--no-limit")
    assert done.code == 0 and float(done.out) > 0, done.err


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_a_progress_bar_on_stderr_only_when_it_is_a_terminal(coast, monkeypatch):
    monkeypatch.setattr(command, "BAR_AFTER", 0.0)  # (a fit's bar shows after a second: tests/fit/test_fit_reporting.py)
    args = ["fit", "spin-down", coast, "--inertia", "0.1kg*m^2", "--fit", "friction,viscous,omega0", "--get", "friction"]
    for stderr, shown in ((io.StringIO(), False), (_Terminal(), True)):
        stdout = io.StringIO()
        assert main(args, Environment(stdin=None, stdout=stdout, stderr=stderr)) == 0, stderr.getvalue()
        assert float(stdout.getvalue()) > 0
        assert ("solving" in stderr.getvalue()) is shown, stderr.getvalue()[:200]


def test_the_limit_passed_inside_a_search_that_takes_a_sample_the_scene_refuses_still_refuses(tmp_path, monkeypatch):
    """The start's root search (and the model) take an InputError from a solve as a sample the scene
    refuses: the budget's refusal passes through them, not read as "finds no start"."""
    from taucli.fit import budget

    monkeypatch.setattr(budget, "before", lambda model, p: None)  # no estimate first: the limit is passed in the search
    path = tmp_path / "periods.csv"
    path.write_text("amplitude (deg),period (s)\n10,2.01\n20,2.02\n30,2.04\n40,2.07\n")
    with pytest.raises(OverBudget, match=r"^fit is estimated to take about"):
        command.fit_of("pendulum", [str(path)], {"shape": "point", "mass": "50g", "radius": "1m"}, fit="g", x=("amplitude=angle0",), limit=1e-9)
