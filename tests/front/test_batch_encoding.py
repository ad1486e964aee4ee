"""Batch lines are UTF-8 whatever the locale says, decoded line by line (#43 item 9): under
PYTHONIOENCODING=ascii a line with `·` ended the run (exit 1) and the valid line before it was
lost; under latin-1 `kg·m²` was read as `kgÂ·mÂ²`. Each line is answered on its own: a byte that
is not UTF-8 gives that line its error object, and the others their answers."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

LINES = [
    '{"m1": "4kg", "m2": "1kg"}',
    '{"m1": "4kg", "m2": "1kg", "pulley_inertia": "0.01 kg·m²", "pulley_radius": "0.1 m"}',
    None,  # a line with a byte that is not UTF-8
    '{"m1": "4kg", "m2": "1kg", "pulley_mass": "2 kg", "pulley_radius": "10 cm", "to": "a=m/s²"}',
]
DATA = b"".join((line.encode("utf-8") if line else b'{"m1": "4k\xffg", "m2": "1kg"}') + b"\n" for line in LINES)
G = 9.80665


@pytest.mark.parametrize("encoding", [{"PYTHONIOENCODING": "ascii"}, {"PYTHONIOENCODING": "latin-1"}, {"PYTHONIOENCODING": "utf-8"},
                                      {"LC_ALL": "C", "LANG": "C", "PYTHONUTF8": "0", "PYTHONIOENCODING": ""}],
                         ids=["ascii", "latin-1", "utf-8", "C-locale"])
def test_every_line_is_read_as_utf8_whatever_the_locale(encoding):
    env = {**os.environ, **encoding}
    env.pop("TAUCLI_DEBUG", None)
    done = subprocess.run([sys.executable, "-m", "taucli", "atwood", "--batch", "--no-steps"], input=DATA, capture_output=True, env=env, timeout=120)
    documents = [json.loads(line) for line in done.stdout.decode("utf-8").splitlines()]
    assert done.returncode == 2 and len(documents) == 4, (done.returncode, done.stderr)
    assert documents[0]["results"]["a"]["value"] == pytest.approx(3 * G / 5, rel=1e-15)
    assert documents[1]["inputs"]["pulley_inertia"]["value"] == pytest.approx(0.01, rel=1e-15)
    assert documents[1]["results"]["a"]["value"] == pytest.approx(3 * G / (5 + 0.01 / 0.1**2), rel=1e-15)
    assert documents[2]["line"] == 3 and documents[2]["error"]["option"] == "m1"
    assert documents[3]["results"]["a"]["value"] == pytest.approx(3 * G / 6, rel=1e-15) and documents[3]["results"]["a"]["unit"] == "m/s²"
    assert done.stderr.decode("utf-8").strip() == "taucli: error: 1 of 4 lines failed (the first: line 3)"
