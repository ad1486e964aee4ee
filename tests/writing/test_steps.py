"""Worked steps read as the article writes them (#16 item 14).

Over every command in README and docs/ (and each scene's working example): a numbers line that
substitutes numbers carries their units; a negative number after an operator is in parentheses
with a true minus (never "+ -3" or "× -1.5"); a step's result shows the figures the results
table shows for the same quantity (one rule for both).
"""

from __future__ import annotations

import json
import re
import shlex
import subprocess
import sys
from functools import cache

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import documents_text
from taucli.options import SCENES
from taucli.writing.human import shown
from taucli.writing.report import pretty_unit
from test_table import WORKING

NUMBER = re.compile(r"(?<![\w.^])[-−]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
UNIT_AFTER = re.compile(r"\s*(?:[a-zA-Zµ°Ω]|rad|rev)")
MP_DPS = 40  # the references' precision, set for each test by conftest


def _commands() -> list[list[str]]:
    """Each command of README and docs/ (and working example) that answers a single scene, as --json."""
    found = []
    for line in (line for _, text in documents_text() for line in text.splitlines()):
        text = line.removeprefix("$ ").strip()
        if not text.startswith("taucli ") or any(mark in text for mark in ("|", "<", "--batch", "completions", " bench", "--help")):
            continue
        args = [a for a in shlex.split(text)[1:] if a != "--no-steps"]
        if args[0] not in SCENES:  # fit, convert: documents with no steps
            continue
        if any(a.startswith(("--get", "--plot", "--out", "--mc", "--jsonl")) or ".." in a for a in args):
            continue
        found.append(args)
    found += [[name, *argv] for name, argv in WORKING.items()]
    found.append(["spin-down", "--inertia", "2", "--omega0", "30rad/s", "--torque", "-3", "--friction", "1", "--time", "30"])
    return found


@cache
def _documents() -> list[dict]:
    documents = []
    for args in _commands():
        done = subprocess.run([sys.executable, "-m", "taucli", *args, "--json"], capture_output=True, text=True, encoding="utf-8")
        if done.returncode == 0:
            doc = json.loads(done.stdout)
            documents.extend(doc if isinstance(doc, list) else [doc])
    assert len(documents) > 40
    return documents


def _steps():
    for doc in _documents():
        for step in doc["steps"]:
            yield doc, step


def test_every_numbers_line_keeps_its_units():
    """A step whose result has a unit substitutes numbers with theirs (a plain count, μ or k² may
    stand beside them): "30 rad/s / 3 rad/s²", not "30 / 3"."""
    missing = []
    for doc, step in _steps():
        numbers, result = step["numbers"], step["result"]
        if not re.search(r"\d", numbers) or "samples over" in numbers:
            continue
        has_unit = any(UNIT_AFTER.match(result, m.end()) for m in NUMBER.finditer(result))
        if has_unit and not any(UNIT_AFTER.match(numbers, m.end()) for m in NUMBER.finditer(numbers)):
            missing.append(f"{doc['scene']}: {step['title']}: {numbers!r} -> {result!r}")
    assert not missing, "\n".join(sorted(set(missing)))


def test_the_issues_examples_read_with_units():
    numbers = {(doc["scene"], step["title"]): step["numbers"] for doc, step in _steps()}
    assert numbers["spin-down", "Time to stop"].endswith("rad/s / 3 rad/s²") or "rad/s / " in numbers["spin-down", "Time to stop"]
    assert re.fullmatch(r"√\(2 × [\d.]+ m/s² × [\d.]+ m\),  2 × [\d.]+ m / [\d.]+ m/s",
                        numbers["rolling", "Speed and time at the bottom (uniform acceleration from rest)"])


def test_a_negative_number_after_an_operator_is_in_parentheses_with_a_true_minus():
    bad = [f"{doc['scene']}: {step['title']}: {step['numbers']!r}" for doc, step in _steps()
           if re.search(r"(?:^|[+×/−(]\s*)-\d|(?<![\d.e])-\d", step["numbers"])]
    assert not bad, "\n".join(bad)


def test_a_steps_result_shows_the_tables_figures():
    """Where a step's result is a quantity the table also shows, the two read the same."""
    differing = []
    for doc, step in _steps():
        for match in NUMBER.finditer(step["result"]):
            text = match[0].replace("−", "-")
            value = float(text)
            unit = re.match(r"\s*([^\s,]*)", step["result"][match.end():])[1]
            for key, entry in doc["results"].items():
                table = entry["value"]
                same_kind = pretty_unit(entry["unit"]) == unit
                if same_kind and isinstance(table, (int, float)) and not isinstance(table, bool) and table and value and abs(value - table) <= 2e-4 * abs(table):
                    table_text = shown(table).replace("−", "-")  # the human view writes − for every sign
                    if text != table_text and table_text not in step["result"].replace("−", "-"):
                        differing.append(f"{doc['scene']}: {step['title']}: step {text}, table {key} = {shown(table)}")
    assert not differing, "\n".join(differing[:20])


def test_the_steps_of_a_drive_that_reverses_the_wheel():
    """spin-down --torque -3 --friction 1: it stops at 15 s and turns back at α₂ = −1 rad/s²;
    the net angle and the total turned both ways, against the motion worked here in mpmath."""
    doc = next(doc for doc in _documents() if doc["scene"] == "spin-down" and doc["inputs"].get("torque", {}).get("value") == -3)
    inertia, omega0, drive, friction, t = map(mpmath.mpf, (2, 30, -3, 1, 30))
    slowing = (drive - friction) / inertia  # friction against +ω while it turns forward
    t_stop = -omega0 / slowing
    theta_stop = omega0 * t_stop / 2
    back = (drive + friction) / inertia  # friction against −ω on the way back
    theta_back = back * (t - t_stop) ** 2 / 2
    results = {key: entry["value"] for key, entry in doc["results"].items()}
    assert results["theta"] == pytest.approx(float(theta_stop + theta_back), rel=1e-14)
    assert results["theta_total"] == pytest.approx(float(theta_stop - theta_back), rel=1e-14)
    assert results["revs_total"] == pytest.approx(float((theta_stop - theta_back) / (2 * mpmath.pi)), rel=1e-14)
    assert results["omega"] == pytest.approx(float(back * (t - t_stop)), rel=1e-14)
    numbers = {step["title"]: step["numbers"] for step in doc["steps"]}
    assert numbers["Net torque at the start"] == "(−3 N·m) − 1 N·m"
    assert numbers["Angular acceleration after the stop"] == "((−3 N·m) + 1 N·m) / 2 kg·m²"
    assert doc["results"]["theta"]["label"].startswith("net angle")


def test_no_total_angle_where_the_wheel_does_not_turn_back():
    doc = next(doc for doc in _documents() if doc["scene"] == "spin-down" and "time" in doc["inputs"] and "torque" not in doc["inputs"])
    assert "theta_total" not in doc["results"]


def _first_number(text: str) -> float:
    return float(NUMBER.search(text)[0].replace("−", "-"))


@settings(max_examples=150, deadline=None)
@given(
    omega0=st.floats(-50, 50).filter(lambda w: abs(w) > 1e-3),
    alpha=st.floats(-20, 20).filter(lambda a: abs(a) > 1e-3),
    time=st.floats(0.01, 30),
    target=st.sampled_from(["time", "until_omega", "until_angle"]),
)
def test_a_given_alpha_shows_its_kinematics(omega0, alpha, time, target):
    """spin-down --alpha: the steps work out what the table gives (ω = ω₀ + αt, θ = ω₀t + ½αt²,
    the stop, the time to a target), each result against constant-α motion worked in mpmath."""
    import taucli

    w0, a, t = map(mpmath.mpf, (omega0, alpha, time))
    omega_at, theta_at = w0 + a * t, w0 * t + a * t * t / 2
    keyword = {"time": time, "until_omega": float(omega_at), "until_angle": float(theta_at)}[target]
    report = taucli.spin_down(alpha=alpha, omega0=omega0, **{target: keyword})
    steps = {step.title: step for step in report.steps}
    expected = {}
    if w0 * a < 0:  # it stops on the way
        expected["Time to stop"] = -w0 / a
        expected["Angle turned while stopping"] = abs(w0 * w0 / (2 * a))
    if target == "time":
        expected["Angular velocity after t"] = omega_at
        expected["Angle turned in t"] = theta_at
        expected["Convert to revolutions"] = theta_at / (2 * mpmath.pi)
        if w0 * a < 0 and t > -w0 / a:
            stop_angle = -w0 * w0 / (2 * a)
            expected["Total angle turned, both ways"] = abs(stop_angle) + abs(theta_at - stop_angle)
    elif target == "until_omega":
        expected["Time to reach ω₁"] = t
        expected["Angle turned by then"] = theta_at
    elif report.results["t_until"].value is not None:  # the first time at θ may come before t
        first = report.results["t_until"].value
        assert float(w0 * first + a * first * first / 2) == pytest.approx(float(theta_at), rel=1e-9, abs=1e-9)
        expected["Angular velocity at the angle"] = w0 + a * first
        if "Time to turn it" in steps:
            expected["Time to turn it"] = first
    for title, value in expected.items():
        assert title in steps, f"no step {title!r}: {list(steps)}"
        assert _first_number(steps[title].result) == pytest.approx(float(value), rel=1e-5, abs=float(1e-5 * (abs(w0) + abs(a) * t) * t)), title
        assert re.search(r"\d", steps[title].numbers), title
