"""--find and --mc are bounded in time (#33 item 3): work estimated past a stated limit is refused,
with the setting that would fit, unless --no-limit; a progress bar on stderr only on a terminal."""

from __future__ import annotations

import io
import re
import time

import pytest

import taucli
from conftest import assert_usage_error
from taucli.answering import answer
from taucli.front.cli import Environment, main
from taucli.options import SCENES
from taucli.answering.propagate import OverBudget

SLOW_MC = ("spin-down", "--inertia", "1+/-0.1 kg*m^2", "--omega0", "100rad/s", "--drag", "0.01N*m*s^2", "--drag-exponent", "2.5",
           "--until-omega", "10rad/s", "--method", "rk45", "--mc", "100000", "--get", "t_until")


def test_a_monte_carlo_past_the_limit_is_refused_at_once_with_the_draws_that_fit(taucli):
    """--mc 100000 on an rk45 scene took about ten minutes, silent all the while."""
    started = time.monotonic()
    done = taucli(*SLOW_MC)
    assert time.monotonic() - started < 30
    assert_usage_error(done, "--mc is estimated to take about", "over the 60 s limit", "--no-limit runs it as asked")
    fits = int(re.search(r"--mc (\d+) fits", done.err).group(1))
    assert 2 <= fits < 100_000


def test_a_find_past_the_limit_is_refused_and_no_limit_lifts_it():
    command = SCENES["atwood"]
    given = {"m1": "4kg", "m2": "1kg", "pulley_radius": "0.1m"}
    with pytest.raises(OverBudget, match=r"^find is estimated to take about .* over the 0 s limit; a faster solve fits"):
        answer.solve(command, given, find="pulley_inertia", want="a=4m/s^2", limit=1e-9)
    report = answer.solve(command, given, find="pulley_inertia", want="a=4m/s^2", limit=None)
    # a = (m1 - m2) g / (m1 + m2 + I/R²): I = R²((m1 - m2) g / a - m1 - m2)
    assert report.results["pulley_inertia"].value == pytest.approx(0.01 * (3 * 9.80665 / 4 - 5), rel=1e-9)
    assert isinstance(taucli.atwood(**given, find="pulley_inertia", want="a=4m/s^2"), taucli.Report)  # the Python API has no limit


def test_no_limit_runs_the_monte_carlo_as_asked(taucli):
    done = taucli("atwood", "--m1", "4+/-0.1kg", "--m2", "1kg", "--mc", "200", "--no-limit", "--get", "a")
    assert done.code == 0 and float(done.out) == pytest.approx(3 * 9.80665 / 5, rel=1e-12)


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_a_progress_bar_on_stderr_only_when_it_is_a_terminal():
    args = ["atwood", "--m1", "4+/-0.1kg", "--m2", "1kg", "--mc", "300", "--get", "a"]
    for stderr, shown in ((io.StringIO(), False), (_Terminal(), True)):
        stdout = io.StringIO()
        assert main(args, Environment(stdin=None, stdout=stdout, stderr=stderr)) == 0
        assert float(stdout.getvalue()) == pytest.approx(3 * 9.80665 / 5, rel=1e-12)
        assert ("solving" in stderr.getvalue()) is shown, stderr.getvalue()[:200]
