"""What a fit prints for a person does not depend on the last digits of its least-squares solve.

The fitted values are known to their uncertainties, and the search stops within its tolerance of
the minimum: the digits past that change with numpy's and scipy's versions and with the path the
search takes. Each `taucli fit` example of the docs is run here with the search started elsewhere
(each input's start moved by up to 1e-6 of itself, one way and the other): the page a person reads
is the same to the character, and the numbers for a machine (--get) agree with the page within the
fit's stated tolerances (tests/pages.py). CI runs the same examples with the oldest numpy
and scipy pyproject.toml allows (.ci/run).
"""

from __future__ import annotations

import io
import re
import shlex

import numpy as np
import pytest

pytest.importorskip("scipy")

from taucli.front.cli import Environment, main  # noqa: E402
from taucli.fit import start  # noqa: E402
from pages import fit_machine_output, fit_numbers_agree, fit_output_agrees, lines_of, sessions, with_docs  # noqa: E402

FIT_EXAMPLES = [(command, printed, files) for command, printed, files in sessions() if command.startswith("taucli fit ") and not re.search(r"[|<>]", command)]
MOVED = 1e-6  # of each start


def test_the_docs_have_fit_examples_for_a_person_and_for_a_machine():
    assert sum(not fit_machine_output(command) for command, _, _ in FIT_EXAMPLES) >= 6
    assert sum(fit_machine_output(command) for command, _, _ in FIT_EXAMPLES) >= 6


@pytest.mark.parametrize("direction", [1.0, -1.0])
@pytest.mark.parametrize("command,printed,files", FIT_EXAMPLES, ids=[command[11:70] for command, _, _ in FIT_EXAMPLES])
def test_a_fit_started_elsewhere_prints_the_same_page(command, printed, files, direction, tmp_path, monkeypatch):
    first = start.start
    moved = []

    def started_elsewhere(model, starts):
        p0, steps, how = first(model, starts)
        shifted = np.asarray(p0, dtype=float) * (1 + direction * MOVED * np.linspace(1.0, -0.5, len(p0)))
        moved.append(bool(np.any(shifted != p0)))
        return shifted, steps, how

    monkeypatch.setattr(start, "start", started_elsewhere)
    monkeypatch.setenv("COLUMNS", "80")
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    with_docs(tmp_path)
    monkeypatch.chdir(tmp_path)
    out, err = io.StringIO(), io.StringIO()
    main(shlex.split(command)[1:], Environment(stdin=io.StringIO(""), stdout=out, stderr=err))
    if moved and not any(moved):
        pytest.skip("every start is 0 here: nothing to move")
    assert fit_output_agrees(command, out.getvalue(), err.getvalue(), printed), (lines_of(out.getvalue() + err.getvalue()), lines_of(printed))


def test_the_tolerances_take_rounding_and_refuse_a_changed_answer():
    page = ["0.0600516905492719 0.000916955", "17.27773613006 0", "null"]
    assert fit_numbers_agree(["0.0600516905492256 0.000916955000001", "17.2777361300601 0", "null"], page)
    assert not fit_numbers_agree(["0.0600526905492719 0.000916955", "17.27773613006 0", "null"], page)  # 1e-6 N·m: a thousandth of σ
    assert not fit_numbers_agree(["0.0600516905492719 0.000917955", "17.27773613006 0", "null"], page)  # σ 0.1 % off
    assert not fit_numbers_agree(["0.0600516905492719 0.000916955", "17.2777371300600 0", "null"], page)  # χ²/ν 6e-8 off
    assert not fit_numbers_agree(["0.0600516905492719 0.000916955", "17.27773613006 0", "0"], page)
    assert not fit_numbers_agree(["0.0600516905492719 0.000916955"], page)
