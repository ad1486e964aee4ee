"""#42 item 23: a spin-up printed four "—" rows (t_stop, theta_stop, revs_stop, omega_inf) where
nothing can stop the wheel. A result null only because the scene cannot have it is left out of
every human view (the terminal table, --format md, html and latex, a notebook's views), one note
saying why; JSON and CSV keep its key, null (the contract: keys are stable); --get prints null with
that note. A result null for another reason (an input left out, a target never reached) keeps its
row."""

from __future__ import annotations

import re

import pytest

import taucli

STOP = ("t_stop", "theta_stop", "revs_stop")
SPIN_UPS = {  # scene keywords -> the results it cannot have
    "a drive from rest": ({"inertia": 2, "omega0": "0 rad/s", "torque": "5 N*m"}, STOP + ("omega_inf",)),
    "a drive beating friction": ({"inertia": 2, "omega0": "10 rad/s", "torque": "5 N*m", "friction": "1 N*m", "time": "2 s"}, STOP + ("omega_inf",)),
    "a drive slowing to its steady speed": ({"inertia": 2, "omega0": "100 rad/s", "torque": "1 N*m", "viscous": 0.1}, STOP),
    "no torque at all": ({"inertia": 2, "omega0": "10 rad/s"}, STOP),
    "a motor of constant power": ({"inertia": 2, "omega0": "10 rad/s", "power": "1 kW", "time": "3 s"}, STOP + ("omega_inf",)),
    "a motor against a loss": ({"inertia": 2, "omega0": "10 rad/s", "power": "1 kW", "viscous": 0.1}, STOP),
    "a drive by a stepping method": ({"inertia": 2, "omega0": "10 rad/s", "torque": "5 N*m", "drag": 0.01, "drag_exponent": 3, "time": "1 s"}, STOP),
}
OPTIONS = {"inertia": "--inertia", "omega0": "--omega0", "torque": "--torque", "friction": "--friction", "time": "--time", "viscous": "--viscous",
           "power": "--power", "drag": "--drag", "drag_exponent": "--drag-exponent"}


def _argv(keywords: dict) -> list[str]:
    return [word for key, value in keywords.items() for word in (OPTIONS[key], str(value))]


def _views(report) -> dict[str, str]:
    """A notebook's three views of the report (the same writers as --format md, html, latex)."""
    return {"markdown": report._repr_markdown_(), "html": report._repr_html_(), "latex": report._repr_latex_(), "repr": repr(report)}


def _has_row(text: str, name: str) -> bool:
    """Whether a view shows a row for ``name`` (a table cell, not the note's words)."""
    escaped = name.replace("_", r"\\?_")
    return bool(re.search(rf"^ {escaped} |^\| {escaped} \||<td>{escaped}</td>|\\texttt{{{escaped}}}", text, re.MULTILINE))


@pytest.mark.parametrize("scene", SPIN_UPS)
def test_results_the_scene_cannot_have_leave_the_human_views(scene, taucli):
    keywords, moot = SPIN_UPS[scene]
    report = taucli_api(keywords)
    for name in moot:
        assert report.results[name].value is None, name
    naming = [note for note in report.notes if all(name in note for name in moot)]
    assert len(naming) == 1 and "never stops" in naming[0], report.notes  # one note says why, naming each
    shown = [name for name, value in report.results.items() if name not in moot]
    texts = {**_views(report)}
    for form in ("md", "html", "latex"):
        texts[form] = taucli("spin-down", *_argv(keywords), "--format", form, "--no-steps").out
    texts["table"] = taucli("spin-down", *_argv(keywords), "--no-steps", env={"COLUMNS": "120"}).out
    for form, text in texts.items():
        if form == "repr":
            assert not any(f"{name} =" in text for name in moot), text
            continue
        for name in moot:
            assert not _has_row(text, name), (form, name, text)
        for name in shown[:2]:  # I and alpha0 stay
            assert _has_row(text, name), (form, name, text)
    document = taucli("spin-down", *_argv(keywords), "--json").json()  # the contract: every key, null, with the note
    for name in moot:
        assert name in document["results"] and document["results"][name]["value"] is None
    assert naming[0] in document["notes"]
    header = taucli("spin-down", *_argv(keywords), "--format", "csv").out.splitlines()[0]
    assert all(f"{name} (" in header for name in moot)  # a CSV's columns are data: kept
    got = taucli("spin-down", *_argv(keywords), "--get", "t_stop")
    assert got.code == 0 and got.out.strip() == "null" and "never stops" in got.err


def taucli_api(keywords: dict):
    return taucli.spin_down(**keywords)


def test_results_null_for_another_reason_keep_their_rows(taucli):
    """A target never reached (t_until) and an input left out (atwood's alpha with no pulley radius)
    are answers a person asked for: their rows stay, "—", in every human view."""
    runs = [
        (("spin-down", "--inertia", "2", "--omega0", "10rad/s", "--friction", "1", "--until-omega", "20rad/s"), ("t_until", "theta_until")),
        (("atwood", "--m1", "3kg", "--m2", "1kg"), ("alpha",)),
    ]
    for argv, nulls in runs:
        for extra in ((), ("--format", "md"), ("--format", "html"), ("--format", "latex")):
            text = taucli(*argv, *extra, "--no-steps", env={"COLUMNS": "120"}).out
            for name in nulls:
                assert _has_row(text, name), (argv, extra, name, text)
    report = taucli_api({"inertia": 2, "omega0": "10 rad/s", "friction": "1 N*m"})
    assert all(_has_row(view, "t_stop") for name, view in _views(report).items() if name != "repr")  # a wheel friction stops: its stop
