"""A fit's data are held to the bounds a typed value is, with file and line (#43 item 7): measured
values that overflow by their unit (1e306 in a column of rad/ms) or exceed the bounds (1e160 rad/s)
gave exit 1, or exit 0 with numpy warnings and a JSON error. Every column a fit reads (an input,
the measured one, its σ), past a double by its unit, out of bounds, or nonzero and read as 0."""

from __future__ import annotations

import io

import pytest

from taucli.front.cli import Environment, main

GOOD = [(1, "27.012", "0.05"), (2, "23.986", "0.05"), (3, "20.976", "0.05")]


def _table(header: str, bad: tuple[str, str, str]) -> str:
    rows = [("0", "29.928", "0.05"), bad, *GOOD]
    return header + "\n" + "".join(",".join(map(str, row)) + "\n" for row in rows)


CASES = {
    "measured past a double by its unit": ("t (s),omega (rad/ms),sigma (rad/s)", ("0.5", "1e306", "0.05"), "which its unit makes too large"),
    "measured over the bounds": ("t (s),omega (rad/s),sigma (rad/s)", ("0.5", "1e160", "0.05"), "(the measured omega) expected a value of 0 or between 1e-40"),
    "measured under the bounds": ("t (s),omega (rad/s),sigma (rad/s)", ("0.5", "1e-60", "0.05"), "(the measured omega) expected a value of 0 or between 1e-40"),
    "measured below a double": ("t (s),omega (rad/s),sigma (rad/s)", ("0.5", "1e-400", "0.05"), "too small for a double"),
    "time below a double": ("t (s),omega (rad/s),sigma (rad/s)", ("1e-400", "29", "0.05"), "too small for a double"),
    "time made 0 by its unit": ("t (ms),omega (rad/s),sigma (rad/s)", ("1e-323", "29", "0.05"), "which its unit makes too small"),
    "sigma over the bounds": ("t (s),omega (rad/s),sigma (rad/s)", ("0.5", "29", "1e50"), "(the measured omega, its σ) expected a value"),
    "sigma past a double by its unit": ("t (s),omega (rad/s),sigma (rad/ms)", ("0.5", "29", "1e306"), "which its unit makes too large"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_value_out_of_bounds_is_refused_with_file_and_line(tmp_path, case, capfd):
    header, bad, message = CASES[case]
    path = tmp_path / "coast.csv"
    path.write_text(_table(header, bad), encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    code = main(["fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--sigma", header.split(",")[2], "--json"],
                Environment(stdin=io.StringIO(), stdout=out, stderr=err))
    assert code == 2 and out.getvalue() == "" and len(err.getvalue().splitlines()) == 1, (code, out.getvalue(), err.getvalue())
    assert "coast.csv line 3:" in err.getvalue(), err.getvalue()  # the bad row, after the header and a good row
    assert message in err.getvalue(), err.getvalue()
    assert capfd.readouterr().err == ""  # no numpy warning beside it
