"""--bound NAME=FROM..TO: a fitted input held within a range the user gives (#44 item 13).

Before, fit had no such option ("--bound is not an option of fit"); an input could only be held
fixed (given as the scene's option, not named in --fit), which still holds. The reference is the
least squares of the physics, not taucli: a coast under friction alone is ω = ω₀ − (τ/I)t, so with
τ held at a bound the best ω₀ is the mean of ω + (τ/I)t.
"""

from __future__ import annotations

import io

import pytest

from taucli.fit import command
from tests.conftest import assert_usage_error, run_taucli

ROWS = [(0, 30.02), (1, 29.41), (2, 28.83), (3, 28.17), (4, 27.63)]  # τ/I ≈ 0.602 rad/s²: friction ≈ 0.0602 N·m at I = 0.1
TEXT = "t (s),omega (rad/s)\n" + "".join(f"{t},{w}\n" for t, w in ROWS)


def _fit(bounds=(), **options):
    return command.fitted("spin-down", ["-"], {"inertia": "0.1 kg*m^2", **options}, fit="friction,omega0", stdin=io.StringIO(TEXT), bounds=bounds)


def test_a_bound_that_holds_the_best_changes_nothing():
    free, bounded = _fit(), _fit(("friction=0.01..0.1N*m",))
    assert bounded.results["friction"].value == pytest.approx(free.results["friction"].value, rel=1e-9)
    assert not any("--bound" in note for note in bounded.notes)


@pytest.mark.parametrize("bound, at", [("friction=0..0.05N*m", 0.05), ("friction=70mN*m..", 0.07)])
def test_a_bound_the_best_lies_past_holds_it_there_and_warns(bound, at):
    report = _fit((bound,))
    assert report.results["friction"].value == pytest.approx(at, rel=1e-12)
    omega0 = sum(w + at / 0.1 * t for t, w in ROWS) / len(ROWS)
    assert report.results["omega0"].value == pytest.approx(omega0, rel=1e-9)
    assert any(note.startswith("warning: friction ends on the bound given") for note in report.notes)
    assert "friction_ci95" not in report.results  # no interval about a best the bound cuts off


def test_bound_is_in_the_table_and_refused_for_an_input_not_fitted(tmp_path):
    path = tmp_path / "coast.csv"
    path.write_text(TEXT, encoding="utf-8")
    assert "--bound" in run_taucli("fit", "--help").out
    base = ("fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", "--fit", "friction,omega0")
    assert_usage_error(run_taucli(*base, "--bound", "viscous=0..1"), "--bound: expected an input named in --fit")
    assert_usage_error(run_taucli(*base, "--bound", "friction=0.1..0.05N*m"), "--bound: expected FROM below TO")
    assert_usage_error(run_taucli(*base, "--bound", "friction"), "--bound: expected NAME=FROM..TO")
