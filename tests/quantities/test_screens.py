"""What a person reads at any width: every number whole, no line longer than the terminal, no
trailing spaces in a file or pipe (#16 items 15 and 18)."""

from __future__ import annotations

import re

import pytest

from conftest import run_taucli
from taucli.writing.human import shown

WIDTHS = [30, 40, 50, 60, 70, 80, 100]
PARTS = ("inertia", "disc", "--mass", "5kg", "--radius", "0.2m", "--part", "point mass=100g offset=0.2m", "--part", "rod mass=360g length=0.31m axis=end")


def _tokens(text: str) -> set[str]:
    return set(re.split(r"[\s=]+", text))


@pytest.mark.parametrize("columns", WIDTHS)
def test_a_tables_numbers_are_never_split(columns):
    document = run_taucli(*PARTS, "--json").json()
    human = run_taucli(*PARTS, "--no-steps", env={"COLUMNS": str(columns)})
    assert human.code == 0
    tokens = _tokens(human.out)
    for row in document["parts"]:
        for key in ("mass", "I_cm", "offset", "I", "share"):
            assert shown(row[key]) in tokens, (columns, key, row[key])
    for name, result in document["results"].items():
        assert shown(result["value"]) in tokens, (columns, name)


@pytest.mark.parametrize("columns", WIDTHS)
def test_a_sweeps_numbers_are_never_split(columns):
    args = ("atwood", "--m1", "1..4kg", "--m2", "1kg", "--pulley-mass", "0.37kg", "--points", "5", "--g", "9.8")
    documents = run_taucli(*args, "--json").json()
    human = run_taucli(*args, env={"COLUMNS": str(columns)})
    assert human.code == 0
    tokens = _tokens(human.out)
    for document in documents:
        for name in ("a", "T1", "T2", "a_massless"):
            assert shown(document["results"][name]["value"]) in tokens, (columns, name)


@pytest.mark.parametrize("columns", WIDTHS)
@pytest.mark.parametrize(
    "args",
    [PARTS, ("spin-down", "--inertia", "0.01", "--omega0", "100rad/s", "--friction", "0.05", "--viscous", "2", "--method", "rk4", "--dt", "1e-4"),
     ("atwood", "--m1", "1..4kg", "--m2", "1kg", "--points", "5")],
    ids=["parts", "error estimate", "sweep"],
)  # fmt: skip
def test_no_line_is_wider_than_the_terminal_or_ends_in_a_space(args, columns):
    done = run_taucli(*args, env={"COLUMNS": str(columns)})
    assert done.code == 0, done.err
    for line in done.out.splitlines():
        assert not line.endswith(" "), repr(line)
        assert len(line) <= columns or "⠀" in line, (columns, line)  # chart rows are drawn to the width
