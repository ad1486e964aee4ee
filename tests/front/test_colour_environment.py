"""Escape codes only where docs/running.md says (#43 item 17): the human view is coloured on a
terminal, or with FORCE_COLOR set (force-color.org), never under NO_COLOR or TERM=dumb; what a
program reads (--json, --get, --format, --batch, the lines on stderr beside them) never holds an
escape code, whatever the environment says.
"""

from __future__ import annotations

import io
import json

import pytest

from conftest import ROOT, run_taucli
from taucli.front.cli import Environment, main

# Every variable a colour library reads to force colour, alone and together.
FORCING = [
    {"FORCE_COLOR": "1"}, {"FORCE_COLOR": "3", "TERM": "xterm-256color", "COLORTERM": "truecolor"}, {"TTY_COMPATIBLE": "1"},
    {"CLICOLOR_FORCE": "1", "CLICOLOR": "1"}, {"PY_COLORS": "1"}, {"FORCE_COLOR": "1", "TTY_COMPATIBLE": "1", "TERM": "xterm-256color"},
]  # fmt: skip
ATWOOD = ["atwood", "--m1", "4+/-0.1kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m"]
SPIN = ["spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "30rad/s", "--friction", "0.3N*m"]
# Each machine format, for a run, a sweep, a batch, --find and --plot's samples; stderr's notes and errors beside them.
MACHINE = [
    [*ATWOOD, "--json"], [*ATWOOD, "--get", "a", "--get", "T1", "--uncertainty"], [*SPIN, "--json", "--plot"], [*SPIN, "--get", "t_stop"],
    *([*ATWOOD, "--format", fmt] for fmt in ("csv", "md", "latex", "html")),
    ["atwood", "--m1", "1..4kg", "--m2", "1kg", "--points", "4", "--get", "a"], ["atwood", "--m1", "1..4kg", "--m2", "1kg", "--points", "4", "--json"],
    ["atwood", "--m1", "1..4kg", "--m2", "1kg", "--points", "4", "--format", "csv"],
    ["atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--find", "pulley_inertia", "--want", "a=4m/s^2", "--json"],
    ["spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--viscous", "0.1N*m*s", "--get", "t_stop"],  # null, its note on stderr
    ["atwood", "--m1", "4kg", "--m2", "1kg", "--json", "--m3", "1kg"],  # an error
    ["atwood", "--batch", "--no-steps"],
]  # fmt: skip
BATCH = '{"m1": "4kg", "m2": "1kg"}\n{"m1": "4kg", "m2": "x"}\n'


def run(words: list[str]) -> tuple[int, str, str]:
    env = Environment(stdin=io.StringIO(BATCH), stdout=io.StringIO(), stderr=io.StringIO())
    code = main(words, env)
    return code, env.stdout.getvalue(), env.stderr.getvalue()


@pytest.mark.parametrize("forced", FORCING, ids=lambda env: " ".join(f"{k}={v}" for k, v in env.items()))
def test_no_machine_format_holds_an_escape_code_whatever_the_environment(forced, monkeypatch):
    for name, value in forced.items():
        monkeypatch.setenv(name, value)
    for words in MACHINE:
        code, out, err = run(words)
        assert "\x1b" not in out and "\x1b" not in err, (words, out[:200], err[:200])
        if "--json" in words and code == 0:
            json.loads(out)


def test_a_fit_for_a_program_holds_no_escape_code_under_force_color(tmp_path):
    data = tmp_path / "coast.csv"
    data.write_text("t (s),omega (rad/s)\n0,30\n1.5,27.6\n3,25.3\n4.5,23.1\n6,21\n7.5,19\n", encoding="utf-8")
    for more in (["--json"], ["--get", "friction", "--uncertainty"]):
        result = run_taucli("fit", "spin-down", str(data), "--inertia", "0.1 kg*m^2", "--fit", "friction,omega0", *more, env={"FORCE_COLOR": "1", "TTY_COMPATIBLE": "1"})
        assert result.code == 0, result.err
        assert "\x1b" not in result.out and "\x1b" not in result.err


def test_the_human_view_and_its_chart_colour_a_pipe_with_force_color_only():
    """As docs/running.md says: FORCE_COLOR colours the human view (its table and --plot's chart
    alike) in a pipe; rich's own TTY_COMPATIBLE does not, and NO_COLOR or TERM=dumb wins."""
    forced = run_taucli(*SPIN, "--plot", env={"FORCE_COLOR": "1", "TERM": "xterm"})
    table, _, chart = forced.out.partition(") ^\n")  # the chart begins at its first y axis
    assert "\x1b[" in table and "\x1b[" in chart
    for env in ({"TTY_COMPATIBLE": "1"}, {"FORCE_COLOR": "1", "NO_COLOR": "1"}, {"FORCE_COLOR": "1", "TERM": "dumb"}):
        assert "\x1b" not in run_taucli(*SPIN, "--plot", env=env).out, env


def test_the_docs_say_when_there_is_colour():
    text = (ROOT / "docs" / "running.md").read_text(encoding="utf-8")
    said = " ".join(text.split())
    assert "FORCE_COLOR" in said and "NO_COLOR" in said
    assert "--json, --get, --format and --batch" in said.replace("`", "")
