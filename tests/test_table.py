"""One table per command: the command line, help, batch keys, sweeps, completions, the fuzz grammar,
the README and the Python API all come from it, and the scenes' libraries take exactly its names."""

from __future__ import annotations

import inspect
import io
import json
import re
from pathlib import Path

import pytest

from conftest import run_taucli, strict_json
from taucli.front import help as helptext
from taucli.options import COMMANDS, SCENES
from taucli.options.table import FLAG, FILLED

ROOT = Path(__file__).resolve().parent.parent
SCENE_NAMES = list(SCENES)

# One scene of each command that works, to see what its library returns.
WORKING = {
    "inertia": ["disc", "--mass", "5kg", "--radius", "0.2m", "--offset", "0.1m"],
    "spin-down": ["--inertia", "0.1", "--omega0", "30rad/s", "--friction", "0.3", "--time", "4s", "--until-omega", "10rad/s"],
    "atwood": ["--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m", "--distance", "1m"],
    "rolling": ["sphere", "--angle", "30deg", "--length", "2m", "--mass", "1kg", "--radius", "0.1m"],
    "impulse": ["--inertia", "0.1", "--omega0", "0", "--torque", "2", "--duration", "0.5s"],
    "torque": ["--r", "0.3,0.4,0 m", "--force", "0,0,10 N", "--mass", "2kg", "--velocity", "0,1,0 m/s"],
    "gyro": ["--shape", "disc", "--mass", "0.3kg", "--radius", "5cm", "--spin", "4000rpm", "--cm-distance", "5cm", "--tilt", "30deg"],
    "pendulum": ["--shape", "rod", "--length", "1m", "--mass", "2kg", "--axis", "end", "--angle0", "90deg", "--angle", "0deg", "--time", "1s"],
    "drive": ["--load-mass", "250kg", "--lead", "10mm", "--ratio", "2", "--efficiency", "0.9", "--mu", "0.2", "--incline", "10deg",
              "--motor-inertia", "0.3e-4kg*m^2", "--speed", "15m/min", "--accel-time", "0.1s", "--run-time", "1s", "--dwell-time", "0.3s",
              "--rated-torque", "0.637N*m", "--stall-torque", "3N*m", "--no-load-speed", "5000rpm"],
    "balance": ["--mass", "mass=3kg radius=70mm angle=45deg plane=300mm", "--plane", "100mm", "--balance-radius", "100mm", "--speed", "300rpm"],
    "flywheel": ["--omega-mean", "300rpm", "--fluctuation", "0.02", "--energy-swing", "5kJ", "--rim-radius", "0.6m", "--density", "7200kg/m^3",
                 "--allowable-stress", "6MPa"],
}


@pytest.mark.parametrize("name", list(COMMANDS))
def test_the_typer_command_has_exactly_the_tables_options(name):
    import typer.main

    from taucli.front.cli import Environment, build_app

    command = COMMANDS[name]
    made = typer.main.get_command(build_app(Environment(), only=name)).commands[name]
    params = {param.name: param for param in made.params}
    assert list(params) == [option.name for option in (*command.options, *command.output)]
    for option in (*command.options, *command.output):
        param = params[option.name]
        if option.positional:
            assert param.param_type_name == "argument"
            continue
        assert param.opts == [option.flag]
        assert param.is_flag == (option.kind == FLAG)
        assert param.multiple == option.repeatable
        assert param.help == option.help_text()


@pytest.mark.parametrize("name", list(COMMANDS))
def test_help_lists_every_option_and_result_of_the_table(name):
    command = COMMANDS[name]
    text = run_taucli(name, "--help", env={"COLUMNS": "200"}).out
    for option in (*command.options, *command.output):
        assert option.flag in text
    if command.results:
        assert f"Results: {', '.join(result.key for result in command.results)}." in " ".join(text.split())
    assert f"Example: {command.example}" in " ".join(text.replace(" \\\n", " ").split())  # a long one goes on over lines


def test_help_is_the_same_in_process_and_through_the_console_script():
    from taucli.front.cli import Environment, main

    out = io.StringIO()
    assert main(["atwood", "--help"], Environment(stdout=out)) == 0
    assert out.getvalue() == helptext.text(SCENES["atwood"])


@pytest.mark.parametrize("name", SCENE_NAMES)
def test_the_library_takes_exactly_the_tables_names(name):
    """Each option's name is a keyword of the scene's library function (directly or, for a body,
    through the inertia module's ``body``), and nothing else is."""
    from taucli.answering import pipeline
    from taucli.scenes.inertia import body

    command = SCENES[name]
    parameters = inspect.signature(pipeline.library(command.library)).parameters
    taken = {p for p, kind in parameters.items() if kind.kind is not inspect.Parameter.VAR_KEYWORD}
    if any(kind.kind is inspect.Parameter.VAR_KEYWORD for kind in parameters.values()):
        taken |= set(inspect.signature(body).parameters) - {"dims"} | {"radius", "inner_radius", "outer_radius", "length", "width", "height", "depth"}
    names = {option.name for option in command.options}
    assert names <= taken
    assert {p for p in parameters if parameters[p].kind is inspect.Parameter.KEYWORD_ONLY} <= names


@pytest.mark.parametrize("name", SCENE_NAMES)
def test_every_result_a_scene_gives_is_in_its_table(name):
    document = run_taucli(name, *WORKING[name], "--json").json()
    keys = {result.key for result in SCENES[name].results}
    assert set(document["results"]) <= keys
    for key, entry in document["results"].items():
        result = SCENES[name].result(key)
        assert entry["unit"] == result.unit
        assert FILLED not in entry["label"]


@pytest.mark.parametrize("name", SCENE_NAMES)
def test_the_batch_keys_are_the_option_names(name):
    """A line may use every option's name, and its answer is the single run's."""
    from taucli.front.cli import Environment, main

    argv = WORKING[name]
    single = run_taucli(name, *argv, "--json").json()
    command = SCENES[name]
    line = {}
    words = iter(argv)
    for word in words:
        if not word.startswith("--"):
            line[next(o.name for o in command.options if o.positional)] = word
            continue
        option = next(o for o in command.options if o.flag == word)
        line[option.name] = True if option.kind == FLAG else next(words)
    out = io.StringIO()
    assert main([name, "--batch"], Environment(stdin=io.StringIO(json.dumps(line) + "\n"), stdout=out)) == 0
    # the notes name options as each surface takes them: a key in batch, a flag on the command line (#42)
    flags = {option.flag: option.name for option in command.options if not option.positional}
    single["notes"] = [re.sub(r"--[a-z][a-z0-9-]*", lambda m: flags.get(m[0], m[0]), note) for note in single["notes"]]
    assert strict_json(out.getvalue()) == single


@pytest.mark.parametrize("name", SCENE_NAMES)
def test_sweeps_take_the_tables_quantities_and_nothing_else(name):
    from taucli.answering import sweep

    command = SCENES[name]
    for option in command.options:
        given = {option.name: "1,2"}
        ranges, lists = sweep.marked(command, given)
        assert (lists == [option.name]) == option.sweepable, option.name


@pytest.mark.parametrize("name", list(COMMANDS))
def test_completions_offer_the_tables_options_choices_and_results(name):
    from taucli.front import completions

    _, commands = completions.spec()
    offered = next(c for c in commands if c.name == name)
    command = COMMANDS[name]
    flags = {option.flag: option for option in offered.options}
    assert set(flags) == {o.flag for o in (*command.options, *command.output) if not o.positional} | {"--help"}
    first = next((o for o in command.options if o.positional), None)
    for option in (*command.options, *command.output):
        if option.positional:
            assert option is not first or offered.positional == option.choices  # the first argument's words (fit's FILE… after it: files)
        elif option.choices:
            assert flags[option.flag].choices == option.choices
    if command.results:
        assert flags["--get"].choices == tuple(result.key for result in command.results)


@pytest.mark.parametrize("name", SCENE_NAMES)
def test_the_fuzz_grammar_reads_the_table(name):
    import fuzzing

    assert [flag for flag, _, _ in fuzzing.command_options(name)] == [
        "" if o.positional else o.flag for o in (*SCENES[name].options, *SCENES[name].output)
    ]


def test_each_scenes_page_shows_its_options_and_results_as_its_table_has_them():
    for command in SCENES.values():
        page = ROOT / helptext.page(command)
        text = page.read_text(encoding="utf-8")
        start = helptext.TABLE_START.format(name=command.name)
        end = helptext.TABLE_END.format(name=command.name)
        assert start in text and end in text, f"{page.name} has no generated table for {command.name}"
        shown = text.split(start, 1)[1].split(end, 1)[0].strip()
        assert shown == helptext.markdown(command), f"{page.name}'s table of {command.name} is stale: python -m taucli.front.help docs"


def test_each_scenes_help_ends_with_its_page_which_readme_links_to():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for command in SCENES.values():
        assert helptext.text(command).rstrip().endswith("lists every page).")
        assert helptext.page(command) in helptext.text(command).replace("\n  ", " ")
        assert f"({helptext.page(command)})" in readme


@pytest.mark.parametrize("name", SCENE_NAMES)
def test_the_python_api_has_one_function_per_scene_named_like_its_command(name):
    import taucli

    command = SCENES[name]
    function = getattr(taucli, command.function_name)
    assert list(inspect.signature(function).parameters) == [option.name for option in command.options]
    assert command.summary in function.__doc__


def test_the_python_api_answers_as_the_command_line_does():
    import taucli

    report = taucli.atwood(m1="4 kg", m2=1, pulley_mass="2 kg", g=9.8)
    assert report.results["a"].value == pytest.approx(4.9, rel=1e-14)
    assert report.results["T1"].value == pytest.approx(19.6, rel=1e-14)
    assert taucli.inertia("disc", mass="5 kg", radius=0.2).results["I"].value == pytest.approx(0.1, rel=1e-15)
    stop = taucli.spin_down(shape="disc", mass=5, radius="20 cm", omega0="30 rad/s", friction="0.3 N*m")
    assert stop.results["t_stop"].value == pytest.approx(10.0, rel=1e-14)


def test_the_python_api_raises_input_error_naming_the_parameter():
    import taucli

    with pytest.raises(taucli.InputError) as caught:
        taucli.atwood(m1="4 m", m2="1 kg")
    assert caught.value.option == "m1"
    assert str(caught.value).startswith("m1: expected a mass")
    assert isinstance(caught.value, ValueError)
    with pytest.raises(taucli.InputError) as unknown:
        taucli.atwood(m1="4 kg", pully_mass="1 kg")
    assert unknown.value.option == "pully_mass" and "pulley_mass" in str(unknown.value)
    with pytest.raises(taucli.InputError) as conflict:
        taucli.spin_down(inertia=1, shape="disc", omega0=3)
    assert str(conflict.value) == "inertia conflicts with shape: give one of them"


def test_the_command_line_spells_the_same_error_with_flags():
    done = run_taucli("spin-down", "--inertia", "1", "--shape", "disc", "--omega0", "3rad/s")
    assert done.code == 2
    assert done.err.strip() == "taucli: error: --inertia conflicts with --shape: give one of them"


def test_a_tables_default_is_what_the_library_assumes():
    """The default help shows is the value the library uses when the option is left out."""
    from taucli.answering import pipeline
    from taucli.quantities import units
    from taucli.scenes.assumed import STANDARD_GRAVITY

    assert units.parse(SCENES["atwood"].option("g").default, "g", "acceleration").value == STANDARD_GRAVITY
    for name, command in SCENES.items():
        library = inspect.signature(pipeline.library(command.library)).parameters
        for option in command.options:
            if option.default is not None and option.name in library and library[option.name].default is not None:
                assert option.default == library[option.name].default, (name, option.name)
