"""#42 item 7: every view of a sweep shows the uncertainty --json keeps: --get (with
--uncertainty, a column after each result), the table, and --format md, csv, latex and html.

The reference is first-order propagation written by hand for the massless-pulley Atwood machine,
a = g(m1 − m2)/(m1 + m2), T = 2 m1 m2 g/(m1 + m2): ∂a/∂m1 = 2 g m2/(m1 + m2)²,
∂T/∂m1 = 2 g m2²/(m1 + m2)², so σ = |∂/∂m1| σ_m1 (evaluated in mpmath).
"""

from __future__ import annotations

import csv
import io
import json

import mpmath
import pytest

from conftest import run_taucli

G = 9.80665
M1, SIGMA, M2S = 4, "0.1", (1, 2, 3)
ARGS = ("atwood", "--m1", "4+/-0.1kg", "--m2", "1..3kg", "--points", "3")


def expected(m2: int) -> dict[str, tuple[float, float]]:
    mpmath.mp.dps = 30
    m1, m2, s, g = mpmath.mpf(M1), mpmath.mpf(m2), mpmath.mpf(SIGMA), mpmath.mpf(G)
    total = m1 + m2
    a, tension = g * (m1 - m2) / total, 2 * m1 * m2 * g / total
    return {"a": (float(a), float(2 * g * m2 / total**2 * s)), "T1": (float(tension), float(2 * g * m2**2 / total**2 * s))}


def test_sweep_get_with_uncertainty_gives_each_results_sigma_in_the_next_column():
    run = run_taucli(*ARGS, "--get", "a", "--get", "T1", "--uncertainty")
    assert run.code == 0, run.err
    rows = [line.split("\t") for line in run.out.splitlines()]
    assert len(rows) == 3
    for m2, row in zip(M2S, rows):
        want = expected(m2)
        assert float(row[0]) == m2
        assert float(row[1]) == pytest.approx(want["a"][0], rel=1e-12)
        assert float(row[2]) == pytest.approx(want["a"][1], rel=1e-6)
        assert float(row[3]) == pytest.approx(want["T1"][0], rel=1e-12)
        assert float(row[4]) == pytest.approx(want["T1"][1], rel=1e-6)


def test_sweep_csv_has_an_uncertainty_column_beside_each_uncertain_result():
    run = run_taucli(*ARGS, "--format", "csv")
    assert run.code == 0, run.err
    table = list(csv.DictReader(io.StringIO(run.out)))
    assert len(table) == 3
    for m2, row in zip(M2S, table):
        want = expected(m2)
        assert float(row["a (m/s**2)"]) == pytest.approx(want["a"][0], rel=1e-12)
        assert float(row["a uncertainty (m/s**2)"]) == pytest.approx(want["a"][1], rel=1e-6)
        assert float(row["T1 uncertainty (N)"]) == pytest.approx(want["T1"][1], rel=1e-6)


def test_a_single_runs_csv_keeps_the_uncertainty_too():
    run = run_taucli("atwood", "--m1", "4+/-0.1kg", "--m2", "1kg", "--format", "csv")
    assert run.code == 0, run.err
    row = next(csv.DictReader(io.StringIO(run.out)))
    assert float(row["a uncertainty (m/s**2)"]) == pytest.approx(expected(1)["a"][1], rel=1e-6)


# a at m2 = 1, 2, 3 kg: 5.88399 ± 0.0784532, 3.26888 ± 0.108963, 1.40095 ± 0.120081 (from expected()):
# shown to the uncertainty's first digit (two where it begins 10-35)
SHOWN = ("5.88 ± 0.08", "3.27 ± 0.11", "1.40 ± 0.12")


@pytest.mark.parametrize("view", [(), ("--format", "md"), ("--format", "html"), ("--format", "latex")])
def test_sweep_table_and_documents_show_the_uncertainty(view):
    run = run_taucli(*ARGS, *view, env={"COLUMNS": "100"})
    assert run.code == 0, run.err
    for text in SHOWN:
        if view[-1:] == ("latex",):
            value, sigma = text.split(" ± ")
            assert f"\\num[uncertainty-mode=separate]{{{value} +- {sigma}}}" in run.out
        else:
            assert text in run.out, run.out


def test_the_views_agree_with_the_json():
    documents = json.loads(run_taucli(*ARGS, "--json").out)
    got = run_taucli(*ARGS, "--get", "a", "--uncertainty").out.splitlines()
    for document, line in zip(documents, got):
        sigma = document["results"]["a"]["uncertainty"]
        assert float(line.split("\t")[2]) == pytest.approx(sigma, rel=1e-14)
