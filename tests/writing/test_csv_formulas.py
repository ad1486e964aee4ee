"""--format csv writes no cell a spreadsheet would take for a formula (#43 item 16, OWASP's CSV
injection): a cell that is not a number and starts with =, +, - or @ (a tab or a carriage return
too) is written after a single quote ('-2.0 2.0: --find's roots); a number, -2.5 or 1e-05, is
written as it is, every digit of --json's double."""

from __future__ import annotations

import csv
import io
import json

import pytest

from pages import examples_as
from taucli.front.cli import Environment, main
from taucli.options import SCENES
from taucli.writing import formats

FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def is_number(cell: str) -> bool:
    return formats._CSV_NUMBER.fullmatch(cell) is not None


def run(words: list[str]) -> tuple[int, str, str]:
    env = Environment(stdin=io.StringIO(""), stdout=io.StringIO(), stderr=io.StringIO())
    code = main(words, env)
    return code, env.stdout.getvalue(), env.stderr.getvalue()


def unsafe_cells(text: str) -> list[str]:
    return [cell for row in csv.reader(io.StringIO(text)) for cell in row if cell.startswith(FORMULA_START) and not is_number(cell)]


def test_no_cell_of_any_examples_csv_reads_as_a_formula(tmp_path, monkeypatch):
    """Every scene's example (its --help example, and every one of README and docs/, sweeps
    included) as --format csv: no text cell that starts as a formula. Before #43 two did
    (impulse --find omega1's roots, '-2.0 2.0'; spin-down --vehicle-mass's, '-128.3… 128.3…')."""
    monkeypatch.chdir(tmp_path)
    written = [(command, out) for command, _, code, out, _ in examples_as("csv", tmp_path) if code == 0]
    written += [(command.example, run([*command.example.split()[1:], "--format", "csv"])[1]) for command in SCENES.values()]
    assert len(written) >= 150
    found = [(command, cell) for command, out in written for cell in unsafe_cells(out)]
    assert not found, found
    quoted = [cell for _, out in written for row in csv.reader(io.StringIO(out)) for cell in row if cell.startswith("'")]
    assert "'-2.0 2.0" in quoted  # the roots as text, after the quote that says so


def test_negative_numbers_stay_numbers_to_the_last_digit():
    """A run whose every result is negative: each cell the number --json holds, no quote."""
    command = ["impulse", "--inertia", "2kg*m^2", "--omega0", "-1rad/s", "--omega1", "-3.3rad/s", "--duration", "0.7s"]
    rows = list(csv.reader(io.StringIO(run([*command, "--format", "csv"])[1])))
    results = json.loads(run([*command, "--json"])[1])["results"]
    negative = [(cell, r["value"]) for cell, r in zip(rows[1], results.values()) if isinstance(r["value"], float) and r["value"] < 0]
    assert len(negative) >= 4
    for cell, value in negative:
        assert cell == repr(value) and float(cell) == value


@pytest.mark.parametrize(
    "text, written",
    [
        ("=1+2", "'=1+2"), ("+1 2", "'+1 2"), ("-2.0 2.0", "'-2.0 2.0"), ("@SUM(A1:A2)", "'@SUM(A1:A2)"), ("-x", "'-x"),
        ("\t1", "'\t1"), ("-2.5", "-2.5"), ("+3", "+3"), ("1e-05", "1e-05"), ("-1.5e+300", "-1.5e+300"), ("disc", "disc"), ("", ""),
    ],
)  # fmt: skip
def test_a_cell_that_starts_as_a_formula_is_quoted_and_a_number_is_not(text, written):
    assert formats.spreadsheet_text(text) == written


def test_a_header_or_word_that_starts_as_a_formula_is_quoted():
    grid = formats.Grid("t", "m", (("=cmd()", None), ("x", "kg")), (("@a", -2.5), ("-b", 1.0)), ())
    rows = list(csv.reader(io.StringIO(formats.csv_grid(grid))))
    assert rows == [["'=cmd()", "x (kg)"], ["'@a", "-2.5"], ["'-b", "1.0"]]
