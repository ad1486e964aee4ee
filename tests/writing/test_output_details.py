"""What a person reads, in details (#36 item 7): one width in a pipe, --out says where it wrote,
a sweep's note tied to its point, one minus sign, equations broken between terms only, and
--get's numbers without a double's rounding noise (--json keeps every digit).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest

from conftest import run_taucli
from taucli.writing.display import MINUS, equation_text, minus_signs, wrap_expression
from terminal import SHELLS, WIDTHS, Terminal

OPERATORS = ("=", "+", MINUS, "-", "×", "/", "⇒", "≈", "<", ">", "≤", "≥", "→")
SPIN = ("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "30rad/s", "--friction", "0.3N*m")
GYRO = ("gyro", "--shape", "disc", "--mass", "0.3kg", "--radius", "5cm", "--spin", "4000rpm", "--cm-distance", "5cm", "--tilt", "60deg")
ATWOOD = ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m", "--axle-friction", "0.5N*m")
SCENES = [SPIN, GYRO, ATWOOD, ("pendulum", "--shape", "rod", "--length", "1m", "--mass", "2kg", "--axis", "end", "--angle0", "90deg"),
          ("rolling", "sphere", "--angle", "30deg", "--length", "2m", "--mass", "1kg", "--radius", "0.1m", "--mu-s", "0.1")]


def _piped(*args: str) -> subprocess.CompletedProcess:
    """taucli in a pipe with no COLUMNS: the width it picks by itself."""
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")}
    return subprocess.run([sys.executable, "-m", "taucli", *args], capture_output=True, text=True, encoding="utf-8", env={**env, "PYTHONIOENCODING": "utf-8"}, timeout=120)


def test_a_chart_in_a_pipe_is_as_wide_as_a_table():
    table = _piped(*SPIN, "--no-steps").stdout.splitlines()
    chart = _piped(*SPIN, "--plot").stdout.splitlines()
    swept = _piped("spin-down", "--inertia", "0.5..4kg*m^2", "--torque", "3N*m").stdout.splitlines()
    assert max(map(len, table)) <= 80 and max(map(len, chart)) == 80 and max(map(len, swept)) <= 80


def test_out_says_where_it_wrote_on_stderr_and_leaves_stdout_alone(tmp_path):
    pytest.importorskip("matplotlib")
    path = tmp_path / "chart.svg"
    plain = run_taucli(*SPIN, "--get", "t_stop")
    drawn = run_taucli(*SPIN, "--get", "t_stop", "--out", str(path))
    assert drawn.code == 0 and drawn.out == plain.out == "10\n"
    assert drawn.err == f"taucli: wrote the chart to {path}\n" and path.stat().st_size > 1000
    swept = run_taucli("atwood", "--m1", "4kg", "--m2", "1..3kg", "--points", "3", "--json", "--out", str(tmp_path / "a.png"))
    assert swept.code == 0 and len(json.loads(swept.out)) == 3 and swept.err == f"taucli: wrote the chart to {tmp_path / 'a.png'}\n"


def test_a_note_true_at_one_point_of_a_sweep_says_which():
    shown = run_taucli("atwood", "--m1", "4kg", "--m2", "2,4,6kg", "--pulley-mass", "2kg").out
    notes = [line for line in " ".join(shown.split("note: ")[1:]).split("\n")]
    text = " ".join(shown.split())
    assert "note: at m2 = 4 kg: nothing moves: the masses balance" in text
    assert "note: g = 9.80665 m/s² (standard gravity)" in text  # true at every point: said once, plainly
    assert notes
    many = " ".join(run_taucli("atwood", "--m1", "4kg", "--m2", "1..8kg", "--points", "15", "--axle-friction", "1N*m", "--pulley-radius", "0.1m").out.split())
    assert "note: at m2 = 4.0 kg: nothing moves" in many and "note: at m2 = 3.0 kg; m2 = 5.0 kg: nothing moves" in many
    assert "note: nothing moves" not in many


def test_one_minus_sign_in_the_human_view():
    shown = run_taucli(*SPIN).out
    assert "−3" in shown and "(−0.3 N·m)" in shown and "= −0.3 N·m" in shown
    assert not re.search(r"(?<![\w.)\]-])-[\d.]", shown), shown  # no ASCII hyphen as a sign
    document = run_taucli(*SPIN, "--json").json()
    assert document["results"]["alpha0"]["value"] == pytest.approx(-3.0, rel=1e-15)
    raw = run_taucli(*SPIN, "--json").out
    assert MINUS not in re.sub(r'"(?:[^"\\]|\\.)*"', "", raw)  # numbers in JSON stay ASCII
    assert run_taucli(*SPIN, "--get", "alpha0").out == "-3\n"


@pytest.mark.parametrize("text,shown", [("-3", "−3"), ("= -0.3 N·m", "= −0.3 N·m"), ("(-0.3 N·m) / 0.1", "(−0.3 N·m) / 0.1"), ("1e-5", "1e−5"),
                                        ("a - b", "a − b"), ("rk4-5", "rk4-5"), ("--m1 3", "--m1 3"), ("τ_net = − τ_f", "τ_net = − τ_f")])
def test_minus_signs(text, shown):
    assert equation_text(text) == shown
    assert minus_signs("rk4-5 and --m1 -3") == "rk4-5 and --m1 −3"


def test_the_minus_sign_shown_is_read_back():
    shown = run_taucli("spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--torque", "−0.3N*m", "--get", "alpha0")
    assert shown.code == 0 and shown.out == "-3\n"


def _continuations(lines: list[str], text: str) -> list[str] | None:
    """The lines ``text`` was written over, or None where it is not found."""
    for i, line in enumerate(lines):
        if not text.startswith(line.strip()) or not line.strip():
            continue
        joined, j = line.strip(), i
        while len(joined) < len(text) and j + 1 < len(lines):
            j += 1
            joined += " " + lines[j].strip()
        if joined == text:
            return [lines[k].strip() for k in range(i, j + 1)]
    return None


@pytest.mark.parametrize("columns", [40, 80])
@pytest.mark.parametrize("args", SCENES, ids=[scene[0] for scene in SCENES])
def test_an_equation_is_broken_only_before_an_operator(args, columns):
    shown = run_taucli(*args, env={"COLUMNS": str(columns)}).out.splitlines()
    steps = run_taucli(*args, "--json").json()["steps"]
    checked = broken = 0
    for step in steps:
        for part, text in (("equation", step["equation"]), ("numbers", step["numbers"]), ("result", step["result"])):
            if not text or (part == "result" and text == step["numbers"]):
                continue
            text = equation_text(text) if part == "equation" else f"= {equation_text(text)}"
            later = _continuations(shown, text)
            assert later is not None, (columns, text)
            checked += 1
            for previous, line in zip(later, later[1:]):
                broken += 1
                # before an operator; else (a bracket of words longer than a line) at a space,
                # and never between a number and its unit
                assert line.startswith(OPERATORS) or not re.search(r"\d$", previous), (columns, text, line)
    assert checked > 5
    if columns == 40 and args is GYRO:
        assert broken > 3


def test_wrap_expression_keeps_terms_whole():
    text = "= Ω(0.15708 kg·m²/s − 0.00046875 kg·m² × Ω)"
    assert wrap_expression(text, 40, 8) == ["        = Ω(0.15708 kg·m²/s", "          − 0.00046875 kg·m² × Ω)"]
    assert wrap_expression("mgr = Ω(Iω_s − I⊥Ω cos θ)", 80, 4) == ["    mgr = Ω(Iω_s − I⊥Ω cos θ)"]
    lines = wrap_expression("a = 0.98 m/s² + 1.5 m/s² + 2.25 m/s² + 3.125 m/s²", 30, 4)
    assert all(len(line) <= 30 for line in lines) and all("m/s²" in line for line in lines)


def test_get_prints_at_most_15_significant_digits_and_json_every_digit():
    args = ("spin-down", "--inertia", "1", "--omega0", "0.7rad/s", "--friction", "0.07", "--no-steps")
    assert 0.7 / 0.07 == 9.999999999999998  # the double the solver's t = Iω₀/τ_f gives
    assert run_taucli(*args, "--get", "t_stop").out == "10\n"
    value = run_taucli(*args, "--json").json()["results"]["t_stop"]["value"]
    assert value == 0.7 / 0.07 and repr(value) == "9.999999999999998" and float(repr(value)) == value
    third = run_taucli("spin-down", "--inertia", "3", "--omega0", "1rad/s", "--friction", "1", "--get", "t_stop").out
    assert third == "3\n"
    many = run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--g", "9.81", "--get", "a", "--get", "T1").out.split()
    assert all(len(re.sub(r"[^\d]", "", number).lstrip("0")) <= 15 for number in many)


@pytest.mark.parametrize("shell", SHELLS)
@pytest.mark.parametrize("columns", WIDTHS)
def test_steps_in_a_real_terminal(shell, columns):
    """In a terminal of that width: the steps fit, one minus sign, --get plain."""
    terminal = Terminal(shell, columns)
    try:
        shown, status = terminal.run("taucli " + " ".join(GYRO))
        assert status == 0 and "Steps" in shown
        assert max(len(line) for line in shown.split("Steps", 1)[1].split("note:", 1)[0].splitlines()) <= columns
        shown, status = terminal.run("taucli " + " ".join(SPIN[:-1]) + " '0.3N*m'")
        assert status == 0 and "= −0.3 N·m" in shown and not re.search(r"(?<![\w.)\]-])-[\d.]", shown)
        shown, status = terminal.run("taucli spin-down --inertia 1 --omega0 0.7rad/s --friction 0.07 --get t_stop")
        assert status == 0 and shown == "10\n"
    finally:
        terminal.close()


def test_a_note_at_many_points_gives_their_count_and_ends():
    from types import SimpleNamespace

    from taucli.answering.sweep import Point, Swept, _notes_where

    swept = Swept("m2", "1..8kg", tuple(f"{x} kg" for x in range(1, 9)), tuple(range(1, 9)), "kg", True)
    points = [Point(i, 0, SimpleNamespace(notes=["everywhere", *(["held"] if 2 <= i <= 6 else [])])) for i in range(8)]
    assert _notes_where(points, [swept]) == ["everywhere", "at 5 of the 8 points, m2 = 3 kg to m2 = 7 kg: held"]
