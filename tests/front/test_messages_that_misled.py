"""Refusals that were right (exit 2) but misleading (#43 item 18): each now says what is wrong.

- a bare number that is not finite (nan, 1e999) for an angle or a rate suggested adding a unit to
  it (nanrpm); now: not a finite number, for every kind that needs its unit;
- a function taucli does not read (exp(1) m) suggested `exp + (1) m`; now it is named as such;
- fit's --sigma naming no column was read as a unit ("which is a mass"); now: no such column, and
  the columns there are;
- an option of the scenes' own runs (fit … --format) suggested --force; now: whose option it is;
- fit printed its answer, then failed to write --out; now the file first, as the scenes do.
"""

from __future__ import annotations

import io
import resource

import pytest

from conftest import assert_usage_error
from taucli.core.errors import InputError
from taucli.front.cli import Environment, main
from taucli.options import SCENES
from taucli.options.fit import COMMAND as FIT
from taucli.quantities import units
from taucli.quantities.kinds import KINDS, NEEDS_ITS_UNIT

NOT_FINITE = ["nan", "NaN", "inf", "-inf", "Infinity", "1e999", "-1e400", "1e309"]


@pytest.mark.parametrize("kind", sorted(NEEDS_ITS_UNIT))
@pytest.mark.parametrize("text", NOT_FINITE)
def test_a_bare_number_that_is_not_finite_is_refused_as_such_not_given_a_unit(kind, text):
    with pytest.raises(InputError) as refused:
        units.parse(text, "{omega0}", kind, sign="any")
    message = str(refused.value)
    assert f"expected a finite {KINDS[kind].name}" in message and "not a finite number" in message, message
    assert text not in (refused.value.example or ""), message  # never "nanrpm" nor "1e999rpm"


def test_omega0_nan_on_the_command_line(taucli):
    for text in ("nan", "1e999"):
        done = taucli("spin-down", "--inertia", "1", "--omega0", text, "--friction", "1")
        assert_usage_error(done, "--omega0: expected a finite angular velocity", "not a finite number")
        assert f"{text}rpm" not in done.err


@pytest.mark.parametrize("call", ["exp(1) m", "exp (2) m", "EXP(1)m", "ln(2) m", "log(10) m", "log10(3) m", "2*exp(1) m", "atan(1) m", "abs(-2) m", "cosh(1) m"])
def test_a_function_taucli_does_not_read_is_named_not_split_into_a_sum(call):
    with pytest.raises(InputError) as refused:
        units.parse(call, "{radius}", "length")
    message = str(refused.value)
    assert "is not a function taucli reads (it reads sqrt, sin, cos and tan)" in message, message
    assert " + " not in message


def test_the_four_functions_are_still_read():
    assert units.parse("sqrt(4) m", "{radius}", "length").value == 2.0
    assert units.parse("2 sin(30deg) m", "{radius}", "length").value == 1.0


@pytest.fixture
def coast(tmp_path):
    path = tmp_path / "coast.csv"
    path.write_text("time (s),omega (rad/s)\n0,30\n1,29.4\n2,28.8\n3,28.2\n4,27.6\n")
    return str(path)


FIT_ARGS = ("--inertia", "0.1kg*m^2", "--omega0", "30rad/s", "--fit", "friction")


@pytest.mark.parametrize("word", ["u", "t", "w", "sigma", "rpm/s"])
def test_sigma_naming_no_column_says_so_and_lists_the_columns(taucli, coast, word):
    done = taucli("fit", "spin-down", coast, *FIT_ARGS, "--sigma", word)
    assert_usage_error(done, "--sigma: expected a column of", "('time (s)', 'omega (rad/s)') or one value for all", f"got {word!r}, which is no column of it")
    assert "which is a mass" not in done.err


def test_sigma_as_a_value_is_still_read(taucli, coast):
    done = taucli("fit", "spin-down", coast, *FIT_ARGS, "--sigma", "0.05rad/s", "--get", "friction")
    assert done.code == 0, done.err
    assert float(done.out) == pytest.approx(0.1 * 0.6, rel=1e-9)  # I·|dω/dt| for ω falling 0.6 rad/s each second


def test_an_option_of_the_scenes_own_runs_is_said_to_be_theirs_not_a_misspelling(taucli, coast):
    command = SCENES["spin-down"]
    fits = {option.flag for option in (*FIT.options, *FIT.output)}
    for option in command.output:
        if option.flag in fits:
            continue
        stdout, stderr = io.StringIO(), io.StringIO()
        args = ["fit", "spin-down", coast, *FIT_ARGS, option.flag, *(["x"] if option.kind != "flag" else [])]
        assert main(args, Environment(stdin=None, stdout=stdout, stderr=stderr)) == 2 and stdout.getvalue() == ""
        assert stderr.getvalue().startswith(f"taucli: error: {option.flag} is an option of taucli spin-down's own runs, not of fit"), stderr.getvalue()
        assert "did you mean" not in stderr.getvalue()
    done = taucli("fit", "spin-down", coast, *FIT_ARGS, "--jsonl")  # (--format is fit's too since #44 item 14)
    assert_usage_error(done, "--jsonl is an option of taucli spin-down's own runs, not of fit", "--json", "--get NAME", "--format md|latex|html|csv")
    done = taucli("fit", "spin-down", coast, *FIT_ARGS, "--m1", "4kg")
    assert_usage_error(done, "--m1 is not an input of spin-down nor an option of fit (atwood takes it)")


def _small_files():
    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))  # a chart (about 20 KB) cannot be written: EFBIG, as on a full disk


@pytest.mark.parametrize("scene", ["fit", "spin-down"])
def test_a_chart_that_cannot_be_written_is_refused_before_any_answer(tmp_path, coast, scene):
    import subprocess
    import sys

    args = ["fit", "spin-down", coast, *FIT_ARGS] if scene == "fit" else ["spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--friction", "0.06"]
    done = subprocess.run([sys.executable, "-m", "taucli", *args, "--get", "friction" if scene == "fit" else "t_stop", "--out", str(tmp_path / "c.svg")],
                          capture_output=True, text=True, preexec_fn=_small_files, timeout=60)
    assert done.returncode == 2 and done.stdout == "", (done.stdout, done.stderr)
    assert done.stderr.startswith("taucli: error: --out: expected a file that can be written") and "File too large" in done.stderr


@pytest.mark.parametrize("shape", ["dics", "19.8kg", ",".join(["19.8kg"] * 2000)])
def test_a_held_option_the_scene_refuses_is_said_as_the_scene_says_it_not_as_no_start(taucli, tmp_path, shape):
    """fit … --shape dics said "finds no start for g"; a 2,000-value --shape took seconds a solve in difflib."""
    path = tmp_path / "periods.csv"
    path.write_text("amplitude (deg),period (s)\n10,2.01\n20,2.02\n30,2.04\n40,2.07\n")
    done = taucli("fit", "pendulum", str(path), "--shape", shape, "--mass", "50g", "--radius", "1m", "--x", "amplitude=angle0", "--fit", "g")
    assert_usage_error(done, "--shape: expected a shape: point, ring, disc")
    assert ("did you mean 'disc'?" in done.err) is (shape == "dics")
