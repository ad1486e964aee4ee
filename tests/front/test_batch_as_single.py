"""A batch answers each line as the command line answers the same scene with --json (#45 item 6).

The batch's per-line path is trimmed for speed (what does not depend on a line's values is made
once per batch); this holds it to the single run, value for value (floats exactly), on a fixed
mix of lines: several scenes, units written many ways, numbers as SI, options given by their
keys and their flags' spellings, and lines that fail among them (a failing line fails alone
too). Both are run in this process (cli.main), so the lines can be many.
"""

from __future__ import annotations

import io
import json
import re

import pytest

from taucli.front.cli import Environment, main
from taucli.options import COMMANDS

LINES = {
    "atwood": [
        {"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg", "pulley_radius": "0.1m"},
        {"m1": "3.217kg", "m2": "1.5 kg", "pulley_mass": "0.75kg", "pulley_radius": "10cm"},
        {"m1": 3, "m2": "1500 g", "pulley-mass": "0.5kg", "g": 9.8},
        {"m1": "2lb", "m2": 0, "pulley_shape": "ring", "pulley_mass": "1lb", "distance": "1ft"},
        {"m1": "4kg", "m2": "4kg"},
        {"m1": "5kg", "m2": "2kg", "incline": "30deg", "mu_k": 0.2, "mu_s": 0.3},
        {"m1": "1kg", "m2": "5kg", "incline": "20deg", "mu_s": 0.9},
        {"m1": "4kg", "m2": "1kg", "pulley_inertia": "0.01 kg*m^2", "pulley_radius": "0.1m", "axle_friction": "0.05 N*m", "v0": "1 m/s"},
        {"m1": "4kg", "m2": "1kg", "radius1": "5cm", "radius2": "10cm", "pulley_mass": "1kg"},
        {"m1": "4kg", "m2": "1kg", "time": "2s", "g": "9.7 m/s^2"},
        {"m1": "4kg", "m2": "5m"},
        {"m1": "-3kg", "m2": "1kg"},
        {"m1": "4kg", "pully_mass": 1},
        {"m1": "1e400 kg", "m2": "1kg"},
        {"m1": "4 kg", "m2": "1 kg", "pulley_mass": "2 kg", "pulley_radius": "0.1 m"},
    ],
    "spin-down": [
        {"shape": "disc", "mass": "2.5 kg", "radius": "20 cm", "omega0": "1200 rpm", "friction": "0.3 N*m"},
        {"inertia": 2, "omega0": "10 rad/s", "friction": "1 N*m"},
        {"inertia": "0.5 kg*m^2", "omega0": "300 rpm", "viscous": "0.01 N*m*s", "friction": "0.1 N*m"},
        {"shape": "ring", "mass": "1kg", "radius": "0.3m", "omega0": "50 rad/s", "friction": "0.2 N*m", "time": "3s"},
        {"shape": "disc", "mass": "3kg", "radius": "0.2m", "omega0": "10 rad/s"},
        {"shape": "disc", "mass": "3kg", "radius": "0.2m", "omega0": "10 rad/s", "friction": "2 kg"},
    ],
    "inertia": [
        {"shape": "disc", "mass": "5kg", "radius": "0.2m"},
        {"shape": "rod", "mass": "1kg", "length": "2m", "axis": "end"},
        {"shape": "sphere", "mass": "2 kg", "radius": "10 cm", "offset": "0.3 m"},
        {"shape": "disk", "mass": "5kg", "radius": "0.2m"},
    ],
    "rolling": [
        {"shape": "sphere", "angle": "30deg", "g": 9.8},
        {"shape": "hoop", "angle": "15deg", "length": "2m", "mu_s": 0.05},
        {"shape": "cylinder", "angle": "100deg"},
    ],
    "impulse": [
        {"inertia": "0.1 kg*m^2", "omega0": 0, "torque": 2, "duration": "0.5s"},
        {"inertia": "0.1 kg*m^2", "omega0": "100 rpm", "omega1": "300 rpm", "duration": "2s"},
    ],
}


def _run(args: list[str], stdin: str = "") -> tuple[int, str]:
    out = io.StringIO()
    env = Environment(stdin=io.StringIO(stdin), stdout=out, stderr=io.StringIO())
    return main(args, env), out.getvalue()


def _argv(scene: str, line: dict) -> list[str]:
    positional = [option.name for option in COMMANDS[scene].options if option.positional]
    argv = []
    for key, value in line.items():
        if key in positional:
            argv.insert(0, str(value))
        else:
            argv += ["--" + key.replace("_", "-"), str(value)]
    return argv


@pytest.mark.parametrize("scene", list(LINES))
def test_each_line_of_a_batch_is_the_single_runs_document(scene):
    lines = LINES[scene]
    code, out = _run([scene, "--batch"], "".join(json.dumps(line) + "\n" for line in lines))
    answers = out.splitlines()
    assert len(answers) == len(lines)
    failed = 0
    for line, answer in zip(lines, answers):
        document = json.loads(answer)
        single_code, single_out = _run([scene, *_argv(scene, line), "--json"])
        if "error" in document:
            failed += 1
            assert single_code == 2, (line, single_out)
            continue
        assert single_code == 0, line
        single = json.loads(single_out)
        # the notes name options as each surface takes them: a key in a batch, a flag on the command line (#42)
        single["notes"] = [re.sub(r"--([a-z][a-z0-9-]*)", lambda m: m[1].replace("-", "_"), note) for note in single["notes"]]
        assert document == single, line
    assert code == (2 if failed else 0)


def test_a_batch_writes_the_same_document_on_every_line_that_gives_the_same_scene():
    """What a batch keeps from one line to the next (units read, texts written, frames) changes no answer."""
    line = json.dumps({"m1": "3.217kg", "m2": "1.5 kg", "pulley_mass": "0.75kg", "pulley_radius": "10cm"})
    other = json.dumps({"m1": "2lb", "m2": "1 kg", "pulley_shape": "ring", "pulley_mass": "1lb", "distance": "1ft"})
    code, out = _run(["atwood", "--batch", "--no-steps"], "\n".join([line, other, line, other, line]) + "\n")
    answers = out.splitlines()
    assert code == 0 and len(answers) == 5
    assert answers[0] == answers[2] == answers[4] and answers[1] == answers[3] != answers[0]
    _, alone = _run(["atwood", "--batch", "--no-steps"], line + "\n")
    assert alone.splitlines() == [answers[0]]
