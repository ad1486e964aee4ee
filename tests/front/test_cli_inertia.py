"""`taucli inertia` through the real entry point: human view, --json, --get, --to, bad input."""

from __future__ import annotations

import math

import pytest

from conftest import assert_usage_error

DISC = ("inertia", "disc", "--mass", "5kg", "--radius", "0.2m")


def test_human_view_shows_result_and_the_article_steps(taucli):
    result = taucli(*DISC)
    assert result.code == 0, result.err
    assert result.err == ""
    out = result.out
    assert "\x1b[" not in out  # no ANSI codes when stdout is not a terminal
    assert "solid disc" in out
    assert "kg·m²" in out
    for line in ("I = ½MR²", "= ½ × 5 kg × (0.2 m)²", "= 0.1 kg·m²", "why:"):
        assert line in out
    row = next(line for line in out.splitlines() if line.strip().startswith("I "))
    assert row.split()[1] == "0.1"


def test_no_steps_hides_the_steps(taucli):
    out = taucli(*DISC, "--no-steps").out
    assert "½MR²" not in out
    assert "0.1" in out


def test_no_color_and_forced_terminal_colour_only_with_a_terminal(taucli):
    assert "\x1b[" not in taucli(*DISC, env={"NO_COLOR": "1", "FORCE_COLOR": "1"}).out
    assert "\x1b[" not in taucli(*DISC, env={"TERM": "dumb", "FORCE_COLOR": "1"}).out
    assert "\x1b[" in taucli(*DISC, env={"FORCE_COLOR": "1", "TERM": "xterm"}).out


def test_json_has_the_documented_shape(taucli):
    result = taucli(*DISC, "--json")
    assert result.code == 0
    doc = result.json()
    assert list(doc) == ["taucli", "scene", "model", "method", "inputs", "results", "steps", "notes"]
    assert doc["scene"] == "inertia"
    assert doc["method"] == "closed form"
    assert doc["inputs"] == {"mass": {"value": 5.0, "unit": "kg"}, "radius": {"value": 0.2, "unit": "m"}}
    assert doc["results"]["I"]["unit"] == "kg*m**2"
    assert doc["results"]["I"]["value"] == pytest.approx(0.1, rel=1e-15)
    assert doc["results"]["k"]["value"] == pytest.approx(math.sqrt(0.1 / 5), rel=1e-15)
    assert {"title", "equation", "why"} <= set(doc["steps"][0])
    assert doc["notes"] == []


def test_get_prints_only_the_numbers(taucli):
    result = taucli(*DISC, "--get", "I", "--get", "k")
    assert result.code == 0
    lines = result.out.splitlines()
    assert len(lines) == 2
    assert float(lines[0]) == pytest.approx(0.1, rel=1e-15)
    assert float(lines[1]) == pytest.approx(math.sqrt(0.02), rel=1e-15)


def test_to_converts_a_result(taucli):
    doc = taucli(*DISC, "--to", "I=g*cm^2", "--json").json()
    assert doc["results"]["I"] == {"value": pytest.approx(1e6, rel=1e-12), "unit": "g*cm^2", "label": doc["results"]["I"]["label"]}
    assert float(taucli(*DISC, "--to", "I=lb*ft^2", "--get", "I").out) == pytest.approx(0.1 / (0.45359237 * 0.3048**2), rel=1e-12)


def test_units_in_pounds_and_inches(taucli):
    value = float(taucli("inertia", "ring", "--mass", "2 lb", "--radius", "3 in", "--get", "I").out)
    assert value == pytest.approx(2 * 0.45359237 * (3 * 0.0254) ** 2, rel=1e-14)


def test_body_of_several_parts_lists_each_share(taucli):
    args = (*DISC, *sum((("--part", "point mass=100g offset=20cm") for _ in range(4)), ()))
    doc = taucli(*args, "--json").json()
    assert doc["results"]["I"]["value"] == pytest.approx(0.116, rel=1e-14)
    assert len(doc["parts"]) == 5
    assert doc["parts"][1]["shape"] == "point"
    assert sum(part["share"] for part in doc["parts"]) == pytest.approx(100)
    human = taucli(*args).out
    assert "share of I" in human and "Add the parts" in human


def test_parallel_axis_through_the_cli(taucli):
    doc = taucli("inertia", "rod", "--mass", "1.2kg", "--length", "1m", "--offset", "0.5m", "--json").json()
    assert doc["results"]["I"]["value"] == pytest.approx(0.4)
    assert doc["results"]["I_cm"]["value"] == pytest.approx(0.1)
    assert "parallel-axis" in doc["model"]


@pytest.mark.parametrize(
    "args,fragments",
    [
        (("disc", "--mass", "5m", "--radius", "0.2m"), ("--mass", "expected a mass", "e.g.", "length")),
        (("disc", "--mass", "5kgg", "--radius", "0.2m"), ("--mass", "did you mean 'kg'")),
        (("disc", "--mass", "five", "--radius", "0.2m"), ("--mass", "unknown unit")),
        (("disc", "--mass", "nan", "--radius", "0.2m"), ("--mass", "finite")),
        (("disc", "--mass", "inf kg", "--radius", "0.2m"), ("--mass", "finite")),
        (("disc", "--mass", "1e999 kg", "--radius", "0.2m"), ("--mass", "finite")),
        (("disc", "--mass", "-5kg", "--radius", "0.2m"), ("--mass", "positive")),
        (("disc", "--mass", "0 kg", "--radius", "0.2m"), ("--mass", "positive")),
        (("disc", "--mass", "", "--radius", "0.2m"), ("--mass", "empty")),
        (("disc", "--mass", "9**9**9 kg", "--radius", "0.2m"), ("--mass", "power")),
        (("disc", "--mass", "4,5 kg", "--radius", "0.2m"), ("--mass", "comma")),
        (("disc", "--radius", "0.2m", "--get", "I"), ("--mass is required for I", "e.g.")),  # asked for: refused (#42 item 14)
        (("disc", "--mass", "5kg"), ("--radius is needed", "e.g.")),
        (("disc", "--mass", "5kg", "--radius", "0.2 s"), ("--radius", "expected a length")),
        (("disk", "--mass", "5kg", "--radius", "0.2m"), ("SHAPE", "did you mean 'disc'")),
        ((), ("SHAPE is required", "e.g.")),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--bogus"), ("is not an option of inertia", "--bogus")),
        (("disc", "--mass"), ("--mass",)),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--get", "omega"), ("--get", "I, k")),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--to", "I=s"), ("--to", "moment of inertia")),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--to", "I"), ("--to", "NAME=UNIT")),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--axis", "edge"), ("--axis", "central, diameter")),
        (("tube", "--mass", "1kg", "--inner-radius", "2m", "--outer-radius", "1m"), ("--inner-radius", "outer radius")),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--part", "point"), ("--part 2", "mass=")),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--part", "point mass=1kg colour=red"), ("--part 2", "colour")),
        (("disc", "--mass", "5kg", "--radius", "0.2m", "--part", "point mass=1 m offset=1m"), ("--part 2 mass=", "length")),
    ],
)
def test_bad_input_exits_2_with_one_line(taucli, args, fragments):
    assert_usage_error(taucli("inertia", *args), *fragments)


def test_unknown_command_is_a_usage_error(taucli):
    assert_usage_error(taucli("inertai"), "inertia")


def test_help_and_version(taucli):
    help_text = taucli("inertia", "--help")
    assert help_text.code == 0
    assert "Example: taucli inertia disc --mass 5kg --radius 0.2m" in help_text.out
    top = taucli("--help")
    assert top.code == 0 and "inertia" in top.out
    assert taucli("--version").out.strip() == "taucli 0.1.0"


def test_taucli_alone_shows_the_help_on_stderr_and_exits_2(taucli):
    alone = taucli()
    assert alone.code == 2 and alone.out == ""
    assert alone.err.startswith("Usage: taucli [OPTIONS] COMMAND") and "atwood" in alone.err
