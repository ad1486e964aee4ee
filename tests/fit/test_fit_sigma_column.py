"""--sigma naming a column the fit uses otherwise is refused (#43 item 5): `--sigma 'omega (rad/s)'`
(the measured column as its own σ) was taken with --y and weighed each sample by its size, and
without --y blamed --y; an input's column (t) gave a misleading unit error. A σ column of its
own still weighs the samples."""

from __future__ import annotations

import io

import pytest

from taucli.front.cli import Environment, main

ROWS = [(0, 29.928), (1, 27.012), (2, 23.986), (3, 20.976), (4, 18.048), (5, 15.003), (6, 11.986), (7, 9.090), (8, 5.975), (9, 2.937)]  # docs/fit.md


def _run(args):
    out, err = io.StringIO(), io.StringIO()
    code = main(args, Environment(stdin=io.StringIO(), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


@pytest.fixture
def table(tmp_path):
    path = tmp_path / "friction.csv"
    path.write_text("t (s),omega (rad/s),sigma (rad/s)\n" + "".join(f"{t},{w},0.05\n" for t, w in ROWS), encoding="utf-8")
    return str(path)


FIT = ["--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--get", "friction"]


@pytest.mark.parametrize("sigma", ["omega (rad/s)", "omega", "t (s)", "t"])
@pytest.mark.parametrize("mapping", [[], ["--y", "omega (rad/s)"], ["--x", "t (s)=time"]])
def test_sigma_naming_a_used_column_is_refused(table, sigma, mapping):
    code, out, err = _run(["fit", "spin-down", table, *FIT, *mapping, "--sigma", sigma])
    assert code == 2 and out == "" and len(err.splitlines()) == 1, (code, out, err)
    assert err.startswith("taucli: error: --sigma: names column ") and ("which is the measured omega" in err or "which is the input time" in err), err


def test_a_sigma_column_of_its_own_is_used(table):
    code, by_column, _ = _run(["fit", "spin-down", table, *FIT, "--sigma", "sigma (rad/s)"])
    assert code == 0
    code, by_value, _ = _run(["fit", "spin-down", table, *FIT, "--sigma", "0.05rad/s"])
    assert code == 0 and float(by_column) == pytest.approx(float(by_value), rel=1e-9)
