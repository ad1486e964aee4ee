"""A batch line's output is, byte for byte, the document a command line run of that line alone
prints with --json (its notes naming options by their keys, #42): whatever the lines before it
left in the writer's and the readers' caches (#45 item 6 took per-line work out of the batch path).

The reference text is the stdlib encoder's (compact, not ASCII-only) of the single run's document,
so the batch's own writer (taucli.writing.document.document_text) is checked against it too.
"""

from __future__ import annotations

import json

import pytest

from conftest import run_taucli, with_notes_as_keys

# Varied lines of one scene each: models that differ, notes that differ (and repeat), units typed
# in several ways, --to and --no-steps per line, an uncertainty, a --find, and error lines between.
LINES = {
    "atwood": [
        {"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg", "pulley_radius": "10cm"},
        {"m1": "3.217kg", "m2": "1.5 kg", "pulley_mass": "1.20kg", "pulley_radius": "10cm", "no_steps": True},
        {"m1": "4kg", "m2": "1kg"},
        {"m1": "4 kg", "m2": "5m"},  # an error line: the lines after it are answered as if it were not there
        {"m1": "2lb", "m2": 0, "pulley_shape": "ring", "pulley_mass": "1lb", "distance": "1ft", "pulley_radius": "3in"},
        {"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg", "g": 9.8, "to": ["a=ft/s^2", "T1=lbf"]},
        {"m1": "4kg", "m2": "4kg", "pulley_mass": "2kg", "pulley_radius": "10cm", "no_steps": True},
        {"m1": "5kg", "m2": "2kg", "incline": "30deg", "mu_k": 0.2, "mu_s": 0.3, "time": "2s", "no_steps": True},
        {"m1": "1kg", "m2": "3kg", "incline": "30deg", "mu_k": 0.1, "no_steps": True},
        {"m1": "4kg", "m2": "1kg", "pulley_inertia": "0.02 kg*m^2", "pulley_radius": "0.1m", "axle_friction": "0.5 N*m", "v0": "-1 m/s"},
        {"m1": "3kg", "m2": "2kg", "radius1": "10cm", "radius2": "5cm", "pulley_mass": "1kg", "no_steps": True},
        {"m1": "3kg", "m2": "2kg", "rim_mu": 0.1, "pulley_mass": "1kg", "pulley_radius": "0.1m", "no_steps": True},
        {"m1": "4.0+/-0.1 kg", "m2": "1kg", "pulley_mass": "2kg", "no_steps": True},
        {"m1": "4kg", "m2": "1kg", "pulley_radius": "10cm", "find": "pulley_mass", "want": "a=4.9m/s^2", "no_steps": True},
        {"m1": "3.217kg", "m2": "1.5 kg", "pulley_mass": "1.20kg", "pulley_radius": "10cm", "no_steps": True},
    ],
    "spin-down": [
        {"shape": "disc", "mass": "5kg", "radius": "20cm", "omega0": "300rpm", "friction": "0.3 N*m", "no_steps": True},
        {"inertia": 2, "omega0": "10 rad/s", "friction": "1 N*m", "viscous": "0.1 N*m*s", "time": "3s"},
        {"inertia": "0.1 kg*m^2", "omega0": "300"},  # an error line: a bare number for an angular velocity
        {"shape": "disc", "mass": "5kg", "radius": "20cm", "omega0": "300rpm", "friction": "0.3 N*m", "energy": True, "no_steps": True},
    ],
    "inertia": [
        {"shape": "disc", "mass": "5kg", "radius": "0.2m"},
        {"shape": "rod", "mass": "1kg", "length": "2m", "axis": "end", "part": ["point mass=1kg offset=2m"], "no_steps": True},
    ],
}


def _argv(scene: str, line: dict) -> list[str]:
    argv: list[str] = []
    for key, value in line.items():
        flag = "--" + key.replace("_", "-")
        if (scene, key) == ("inertia", "shape"):  # inertia's SHAPE is its argument
            argv.insert(0, value)
        elif value is True:
            argv.append(flag)
        else:
            for item in value if isinstance(value, list) else [value]:
                argv += [flag, str(item)]
    return argv


def _compact(document: dict) -> str:
    return json.dumps(document, ensure_ascii=False, allow_nan=False, separators=(",", ":"))


@pytest.mark.parametrize("scene", sorted(LINES))
def test_a_varied_batch_writes_each_line_as_its_own_run_does(scene):
    lines = LINES[scene]
    batch = run_taucli(scene, "--batch", stdin="".join(json.dumps(line) + "\n" for line in lines))
    written = batch.out.splitlines()
    assert len(written) == len(lines), batch.err
    compared = 0
    for line, text in zip(lines, written):
        single = run_taucli(scene, *_argv(scene, line), "--json")
        if single.code != 0:  # an error line: an error object in its place, with the same message
            assert single.code == 2 and json.loads(text)["error"]["message"] in single.err.replace("--", ""), (text, single.err)
            continue
        assert text == _compact(with_notes_as_keys(single.json())), line
        compared += 1
    assert compared >= len(lines) - 1
