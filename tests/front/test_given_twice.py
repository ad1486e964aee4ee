"""One value for one input (#43 items 1, 2): a key given twice in any spec of any scene, an option
that takes one value given twice on any command's line, and a key given twice in a batch line are
refused, naming it, in the command line, batch and the Python API alike; typer and json.loads
would keep the last and drop the first unsaid."""

from __future__ import annotations

import io
import json
import shlex

import pytest

import taucli
from conftest import example_keys
from taucli.front.cli import Environment, main
from taucli.options import COMMANDS, SCENES
from taucli.options import table

# A spec of each kind whose first key is given twice.
TWICE = {
    table.PART: "point mass=100g mass=200g offset=20cm",
    table.PARTICLE: "mass=30kg mass=1kg speed=4m/s radius=2m",
    table.COUPLE: "inertia=3kg*m^2 inertia=1kg*m^2 omega0=0",
    table.BRAKE: "force=100N force=200N mu=0.4 radius=0.5m",
    table.FACE: "mu=0.2 mu=0.3",
    table.BAND: "mu=0.25 mu=0.3 wrap=270deg radius=0.3m tension=100N",
    table.CALIPER: "mu=0.3 mu=0.4 force=1kN inner-radius=80mm outer-radius=130mm",
    table.CENTRIFUGAL: "shoes=4 shoes=3 mass=6kg radius=160mm spring-force=1450N mu=0.35 drum-radius=250mm",
    table.SIDE: "incline angle=30deg angle=40deg",
    table.PULL: "force=20N force=30N",
    table.ROTOR: "inertia=0.3kg*m^2 inertia=1kg*m^2 spin=5000rpm sense=cw-from-right",
    table.REVOLVING: "mass=2kg mass=3kg radius=0.3m angle=45deg",
    table.SEGMENT: "time=1min time=2min torque=1N*m",
    table.LOAD: "inertia=1kg*m^2 inertia=2kg*m^2 ratio=5",
    table.MOTOR_CURVE: "tmax=400N*m tmax=300N*m slip-max=0.2 sync=1500rpm",
}
SPECS = [(scene, option) for scene, command in sorted(SCENES.items()) for option in command.options if option.kind in TWICE]


def _run(args: list[str], stdin: str = "") -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    code = main(args, Environment(stdin=io.StringIO(stdin), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


def _example(command) -> list[str]:
    return shlex.split(command.example)[2:]


def test_every_spec_kind_is_covered():
    assert {option.kind for _, option in SPECS} == set(TWICE)


@pytest.mark.parametrize(("scene", "option"), SPECS, ids=[f"{scene}-{option.name}" for scene, option in SPECS])
def test_a_spec_key_given_twice_is_refused_in_cli_batch_and_api(scene, option):
    command = SCENES[scene]
    spec = TWICE[option.kind]
    key = spec.split("=")[0].split()[-1]
    code, out, err = _run([scene, *_example(command), option.flag, spec])
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1, (code, out, err)
    assert f"has {key}= twice" in err, err
    code, out, err = _run([scene, "--batch"], json.dumps({option.name: spec}) + "\n")
    assert code == 2 and f"has {key}= twice" in json.loads(out)["error"]["message"], out
    with pytest.raises(taucli.InputError, match=f"has {key}= twice"):
        getattr(taucli, command.function_name)(**{option.name: spec})


VALUED = [(name, option) for name, command in sorted(COMMANDS.items()) for option in (*command.options, *command.output)
          if not option.positional and option.takes_value and not option.repeatable]


@pytest.mark.parametrize(("name", "option"), VALUED, ids=[f"{name}{option.flag}" for name, option in VALUED])
def test_an_option_of_one_value_given_twice_is_refused(name, option):
    for args in ([option.flag, "100", option.flag, "200"], [f"{option.flag}=100", f"{option.flag}=200"]):
        code, out, err = _run([name, *args])
        assert code == 2 and out == "", (code, out, err)
        assert err.startswith(f"taucli: error: {option.flag} is given twice (100 and 200)") and len(err.splitlines()) == 1, err


def test_the_issues_example_and_repeatable_options_stay_repeatable():
    code, _, err = _run(["flywheel", "--inertia", "100", "--inertia", "200", "--omega-mean", "300rpm", "--fluctuation", "0.02"])
    assert code == 2 and "--inertia is given twice (100 and 200)" in err
    code, out, _ = _run(["inertia", "disc", "--mass", "1kg", "--radius", "0.1m", "--part", "point mass=1kg offset=1m", "--part",
                         "point mass=1kg offset=1m", "--get", "I", "--get", "k"])
    assert code == 0 and float(out.split()[0]) == pytest.approx(0.5 * 0.01 + 2.0, rel=1e-15)


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_a_batch_key_given_twice_is_refused_in_every_scene(scene):
    command = SCENES[scene]
    names = [option.name for option in command.options] + ["to", "no_steps", "find", "want"]
    lines = [f'{{"{name}": "1", "{name}": "2"}}' for name in names]
    lines += [f'{{"{name}": "1", "{name.replace("_", "-")}": "2"}}' for name in names if "_" in name]
    lines.append(f'{{{", ".join(json.dumps(key) + ": " + json.dumps(value) for key, value in example_keys(command).items())}}}')
    code, out, err = _run([scene, "--batch"], "\n".join(lines) + "\n")
    documents = [json.loads(line) for line in out.splitlines()]
    assert len(documents) == len(lines) and code == 2
    for document, name in zip(documents, [*names, *(name for name in names if "_" in name)]):
        assert document["error"]["option"] == name and "given twice in one line" in document["error"]["message"], document
    assert "results" in documents[-1], documents[-1]  # the line that gives each key once is answered


