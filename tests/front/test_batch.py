"""Batch mode: JSON lines in, one --json document (or error object) per line out, in order."""

from __future__ import annotations

import json
import re
import os
import signal
import subprocess
import sys
import time

import pytest

from conftest import run_taucli


def _lines(out: str) -> list[dict]:
    return [json.loads(line) for line in out.splitlines()]


def test_each_line_gives_the_document_a_single_run_gives(taucli):
    scenes = [
        {"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg", "pulley_radius": "0.1m", "g": 9.8},
        {"m1": 3, "m2": "1500 g", "pulley-mass": "0.5kg"},
        {"m1": "2lb", "m2": 0, "pulley_shape": "ring", "pulley_mass": "1lb", "distance": "1ft"},
    ]
    batch = taucli("atwood", "--batch", stdin="".join(json.dumps(scene) + "\n" for scene in scenes))
    assert batch.code == 0 and batch.err == ""
    documents = _lines(batch.out)
    assert len(documents) == len(scenes)
    for scene, document in zip(scenes, documents):
        argv = []
        for key, value in scene.items():
            argv += ["--" + key.replace("_", "-"), str(value)]
        single = taucli("atwood", *argv, "--json").json()
        # the notes name options as each surface takes them: a key in batch, a flag on the command line (#42)
        single["notes"] = [re.sub(r"--([a-z][a-z0-9-]*)", lambda m: m[1].replace("-", "_"), note) for note in single["notes"]]
        assert document == single


def test_the_first_scene_of_the_article_in_a_batch(taucli):
    out = taucli("atwood", "--batch", "--no-steps", stdin='{"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg", "g": "9.8 m/s^2"}\n')
    (document,) = _lines(out.out)
    assert document["results"]["a"]["value"] == pytest.approx(4.9, rel=1e-15)
    assert document["results"]["T1"]["value"] == pytest.approx(19.6, rel=1e-15)
    assert document["results"]["T2"]["value"] == pytest.approx(14.7, rel=1e-15)
    assert document["steps"] == []


def test_bad_lines_give_error_objects_in_place_and_the_run_goes_on(taucli):
    stdin = "\n".join(
        [
            '{"m1": "4kg", "m2": "1kg"}',
            '{"m1": "4kg", "m2": "5m"}',  # wrong dimension
            "",  # blank: skipped, no line out
            '{"m1": "4kg"',  # not JSON
            '{"m1": "4kg", "pully_mass": 1}',  # unknown option
            '{"m1": NaN}',  # not strict JSON
            '{"m1": 1e400}',  # not finite
            '["m1"]',  # not an object
            '{"m1": true}',  # a flag where a quantity goes
            '{"m1": "2kg", "m2": "1kg"}',
        ]
    )
    done = taucli("atwood", "--batch", "--no-steps", stdin=stdin + "\n")
    assert done.code == 2
    assert done.err.strip() == "taucli: error: 7 of 9 lines failed (the first: line 2)"
    out = _lines(done.out)
    assert len(out) == 9  # one out for each line in but the blank ones (#16 item 18)
    assert [entry.get("line") for entry in out] == [None, 2, 4, 5, 6, 7, 8, 9, None]
    assert out[0]["results"]["a"]["value"] == pytest.approx(3 * 9.80665 / 5, rel=1e-15)
    assert out[8]["results"]["a"]["value"] == pytest.approx(9.80665 / 3, rel=1e-15)
    # A batch line names its options by their keys, and so does its error.
    assert out[1]["error"] == {"option": "m2", "message": "m2: expected a mass (e.g. 4kg), got '5m', which is a length"}
    assert out[3]["error"]["option"] == "pully_mass" and "pulley_mass" in out[3]["error"]["message"]
    assert out[5]["error"]["option"] == "m1"
    for entry in out[1:8]:
        assert entry["taucli"] and entry["error"]["message"]


def test_command_line_options_apply_to_every_line_that_does_not_give_its_own(taucli):
    stdin = '{"m1": "2kg", "m2": "1kg"}\n{"m1": "2kg", "m2": "1kg", "g": 10}\n'
    out = _lines(taucli("atwood", "--batch", "--g", "9", "--no-steps", stdin=stdin).out)
    assert [doc["results"]["a"]["value"] for doc in out] == pytest.approx([3.0, 10 / 3], rel=1e-15)


@pytest.mark.parametrize(
    "scene,line,result,expected",
    [
        ("inertia", {"shape": "disc", "mass": "5kg", "radius": "0.2m"}, "I", 0.1),
        ("inertia", {"shape": "rod", "mass": "1kg", "length": "2m", "axis": "end", "part": ["point mass=1kg offset=2m"]}, "I", 4 / 3 + 4),
        ("spin-down", {"inertia": 2, "omega0": "10 rad/s", "friction": "1 N*m"}, "t_stop", 20.0),
        ("rolling", {"shape": "sphere", "angle": "30deg", "g": 9.8}, "a", 3.5),
        ("impulse", {"inertia": "0.1 kg*m^2", "omega0": 0, "torque": 2, "duration": "0.5s"}, "omega1", 10.0),
    ],
)
def test_every_scene_takes_a_batch(taucli, scene, line, result, expected):
    done = taucli(scene, "--batch", stdin=json.dumps(line) + "\n")
    assert done.code == 0, done.out
    (document,) = _lines(done.out)
    assert document["scene"] == scene
    assert document["results"][result]["value"] == pytest.approx(expected, rel=1e-12)


def test_batch_refuses_get_and_a_closed_stdin():
    done = run_taucli("atwood", "--batch", "--get", "a", stdin="")
    assert done.code == 2 and "--get does not combine with --batch" in done.err
    closed = subprocess.run(
        [sys.executable, "-m", "taucli", "atwood", "--batch"], stdin=subprocess.DEVNULL, capture_output=True, text=True
    )
    assert closed.returncode == 0 and closed.stdout == ""  # no lines, no documents
    shut = subprocess.run(
        [sys.executable, "-c", "import os, sys, runpy; os.close(0); sys.stdin = None; sys.argv = ['taucli', 'atwood', '--batch']; runpy.run_module('taucli', run_name='__main__')"],
        capture_output=True,
        text=True,
    )
    assert shut.returncode == 2 and "stdin is closed" in shut.stderr and "Traceback" not in shut.stderr


def test_a_killed_batch_leaves_only_whole_lines(tmp_path):
    """Lines are flushed one by one: whatever was written before the kill parses."""
    scenes = tmp_path / "scenes.jsonl"
    scenes.write_text('{"m1": "4kg", "m2": "1kg"}\n' * 200_000)
    output = tmp_path / "out.jsonl"
    with scenes.open() as source, output.open("w") as sink:
        child = subprocess.Popen([sys.executable, "-m", "taucli", "atwood", "--batch"], stdin=source, stdout=sink, env=os.environ.copy())
        deadline = time.monotonic() + 30
        while output.stat().st_size < 200_000 and time.monotonic() < deadline:
            time.sleep(0.05)
        child.send_signal(signal.SIGKILL)
        child.wait()
    text = output.read_text()
    assert text.endswith("\n") and len(text) >= 200_000
    for line in text.splitlines():
        assert json.loads(line)["scene"] == "atwood"


LONG_LINE = '{"shape": "rod", "length": "1m", "mass": "2kg", "axis": "end", "angle0": "90deg", "angle": "30deg", "at": "0.5m"}\n'  # ~7 KB out


@pytest.mark.parametrize("signal_number", [signal.SIGTERM, signal.SIGINT])
def test_sigterm_and_sigint_leave_whole_lines_with_a_slow_reader(tmp_path, signal_number):
    """#33 item 5: lines of ~7 KB, more than a pipe takes at once, read slowly; each signal lands
    while taucli is blocked writing, and the line in hand is finished before it stops."""
    scenes = tmp_path / "scenes.jsonl"
    scenes.write_text(LONG_LINE * 2000)
    for attempt in range(4):
        with scenes.open() as source:
            child = subprocess.Popen([sys.executable, "-m", "taucli", "pendulum", "--batch"], stdin=source, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=os.environ.copy())
            received = child.stdout.read(100_000 + 1_537 * attempt)
            time.sleep(0.5)  # the pipe fills, and taucli blocks part way through writing a line
            child.send_signal(signal_number)
            chunks = [received]
            while chunk := child.stdout.read(997):  # a slow reader: small reads, with pauses
                chunks.append(chunk)
                time.sleep(0.001)
            child.wait(timeout=60)
            child.stderr.close()
            child.stdout.close()
        text = b"".join(chunks).decode("utf-8")
        assert text.endswith("\n"), (signal_number, attempt, text[-200:])
        documents = [json.loads(line) for line in text.splitlines()]
        assert len(documents) < 2000 and all(document["scene"] == "pendulum" for document in documents)
        assert child.returncode == (130 if signal_number == signal.SIGINT else -signal.SIGTERM)
