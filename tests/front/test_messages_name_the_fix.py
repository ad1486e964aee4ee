"""Messages that name the fix (#42 items 18-20): a result that needs another option says which,
each surface spells names as it takes them, and every example in a message works as typed."""

from __future__ import annotations

import ast
import io
import re
import shlex
import subprocess
from pathlib import Path

import pytest

import taucli
from conftest import Run, assert_usage_error, run_taucli
from taucli.core.errors import spelled
from taucli.front.cli import Environment, main
from taucli.options import SCENES
from taucli.options.table import shell_word
from taucli.quantities.kinds import KINDS

NEEDING = [(command, result) for command in SCENES.values() for result in command.results if result.needs]


def test_results_that_need_an_option_say_so_in_the_table():
    """Each way to make a result names options of its scene, and the first comes with an example
    that names its options, each with a value (a flag with none)."""
    keys = {(command.name, result.key) for command, result in NEEDING}
    assert {("atwood", "v"), ("atwood", "t"), ("spin-down", "omega"), ("spin-down", "theta_total")} <= keys
    for command, result in NEEDING:
        assert all(command.option(name) is not None for alternative in result.alternatives for name in alternative), (command.name, result.key)
        example = command.needs_example(result)
        assert example is not None, (command.name, result.key)
        named = re.findall(r"\{([a-z][a-z0-9_]*)\}", example)  # the first way's options, and any setting it is made in (on the flat: {angle} 0deg)
        assert set(result.alternatives[0]) <= set(named) and all(command.option(name) is not None for name in named), (command.name, result.key, example)


def test_what_makes_a_result_reads_as_a_sentence():
    from taucli.options.table import Result

    def said(*needs: str) -> str:
        return Result("x", None, "x", needs=needs).needed(lambda name: "--" + name)

    assert said("distance") == "--distance"
    assert said("distance", "time") == "--distance or --time"
    assert said("time", "until_omega", "until_angle") == "--time, --until_omega or --until_angle"
    assert said("time+alpha", "in_time") == "--time with --alpha, or --in_time"
    assert said("a+b", "c+d+e+f", "g") == "--a with --b, or --c with --d, --e and --f, or --g"
    assert said("ratio+ratio") == "--ratio twice"
    made = Result("x", None, "x", needs=("ratio+ratio", "a+b"))
    assert made.made_by({"ratio": [5, 3]}.get) and not made.made_by({"ratio": [5]}.get) and not made.made_by({"a": 1}.get)
    assert made.made_by({"a": 1, "b": "2 m"}.get) and not made.made_by({"a": 1, "b": False}.get)
    assert made.made_by({"a": 0.0, "b": 0}.get) and not made.made_by({"a": 1, "b": ()}.get)  # a sweep's point 0 is given


def _run(*args: str) -> Run:
    """taucli ARGS in this process (a subprocess each would take minutes over every result)."""
    out, err = io.StringIO(), io.StringIO()
    code = main(list(args), Environment(stdin=io.StringIO(), stdout=out, stderr=err))
    return Run(code, out.getvalue(), err.getvalue())


def _words(command, args: list[str]) -> list[list[str]]:
    """A command line's words in groups: an option and its value, a flag alone, a positional word."""
    groups, words = [], iter(args)
    for word in words:
        option = command.option(word[2:].replace("-", "_")) if word.startswith("--") else None
        groups.append([word, next(words)] if option is not None and option.takes_value else [word])
    return groups


def _made_with(command, args: list[str], added: list[str], get: str) -> Run:
    """ARGS and ADDED, --get GET; where that is refused naming an option of ARGS (one ADDED conflicts
    with: --friction beside --work, --angle beside --yoyo, or gives again: --angle 0deg), that
    option of ARGS left out, as the user would, and again."""
    groups = _words(command, args)
    for _ in range(4):
        run = _run(*(word for group in groups for word in group), *added, "--get", get)
        named = set(re.findall(r"--[a-z0-9-]+", run.err))
        kept = [group for group in groups if group[0] not in named]
        if run.code != 2 or kept == groups:
            return run
        groups = kept
    return run


# The files the examples of FILE options name, as the user would have them.
_FILES = {"torque.csv": "t [s], torque [N*m]\n0, 0\n0.1, 2\n0.2, 0\n"}


@pytest.mark.parametrize("command, result", NEEDING, ids=[f"{c.name}-{r.key}" for c, r in NEEDING])
def test_a_result_that_needs_an_option_names_it(command, result, tmp_path, monkeypatch):
    """--get RESULT where no way to make it was given: "RESULT needs --a, or --b with --c (e.g. ...)",
    and the first way, typed as the example says, makes it: exit 0 and a number."""
    for name, text in _FILES.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    args = shlex.split(command.example)[1:]
    given = {arg[2:].replace("-", "_") for arg in args if arg.startswith("--")}
    assert not result.made_by(lambda name: name in given or None)
    refused = _run(*args, "--get", result.key)
    example = spelled(command.needs_example(result, lambda name: name in given or None), lambda name: command.option(name).flag, command.option)
    assert_usage_error(refused, f"--get: {result.key} needs {result.needed(lambda name: command.option(name).flag)} (e.g. {example})")
    made = _made_with(command, args, shlex.split(example), result.key)
    assert made.code == 0 and made.out.strip() not in ("", "null"), (made, example)


@pytest.mark.parametrize("command", list(SCENES.values()), ids=list(SCENES))
def test_every_result_is_made_by_the_example_or_says_what_makes_it(command):
    """Class check of item 18: a result the docs example does not make declares the options that
    make it (needs=), or a flag turns it on (makes=), or --get of it takes the point on the rim."""
    from taucli.options.common import POINT_RESULTS

    words, given = _keywords(command)
    made = set(getattr(taucli, command.function_name)(*words, **given).results)
    turned_on = {key for option in command.options for key in option.makes}
    at_the_rim = {result.key for result in POINT_RESULTS} if command.option("at") is not None else set()
    silent = [result.key for result in command.results
              if result.key not in made | turned_on | at_the_rim and not result.needs]
    assert silent == [], (command.name, silent)


def test_the_two_messages_of_the_issue():
    assert_usage_error(run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--get", "v"),
                       "--get: v needs --distance or --time (e.g. --distance '0.2 m')")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2", "--omega0", "30rad/s", "--friction", "1", "--get", "omega"),
                       "--get: omega needs --time, --until-omega, --until-angle or --phase")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2", "--omega0", "30rad/s", "--friction", "1", "--to", "omega=rpm"),
                       "--to: omega needs --time")


def test_python_names_the_keyword_that_makes_a_result():
    report = taucli.atwood(m1="4kg", m2="1kg")
    with pytest.raises(taucli.MissingResult) as raised:
        report.results["v"]
    assert "distance= or time=" in str(raised.value)
    with pytest.raises(taucli.MissingResult, match=r"it needs time= with alpha=, or time= with torque= \(--time with --alpha, or --time with --torque on the command line\)"):
        taucli.spin_down(inertia=2, omega0="30 rad/s", friction=1).results["theta_total"]


# item 19: each surface spells names as it takes them


def _keywords(command) -> tuple[list[str], dict[str, str]]:
    """A scene's example as the Python API takes it: positional words, and keywords."""
    words, given = [], {}
    args = iter(shlex.split(command.example)[2:])
    for arg in args:
        if arg.startswith("--"):
            given[arg[2:].replace("-", "_")] = next(args)
        else:
            words.append(arg)
    return words, given


def _variants(command):
    """The example, and the example with each keyword left out in turn (a note or an error each)."""
    words, given = _keywords(command)
    yield words, given
    for name in given:
        yield words, {key: value for key, value in given.items() if key != name}


def _flags_in(text: str, command) -> list[str]:
    return [option.flag for option in command.options if option.flag in text.replace("—", " ")]


@pytest.mark.parametrize("command", list(SCENES.values()), ids=list(SCENES))
def test_python_notes_and_errors_name_keywords_not_flags(command):
    function = getattr(taucli, command.function_name)
    said = []
    for words, given in _variants(command):
        try:
            said += function(*words, **given).notes
        except taucli.InputError as err:
            said.append(str(err))
    for text in said:
        assert not _flags_in(text, command), (text, command.name)


def test_python_and_batch_spell_the_pulley_as_keywords():
    notes = taucli.atwood(m1="4kg", m2="1kg", pulley_mass="2kg").notes
    assert any("give pulley_radius for" in note for note in notes) and any("pulley_shape ring" in note for note in notes), notes
    with pytest.raises(taucli.InputError, match=r"radius2 is required with radius1 \(or pulley_radius for it\)"):
        taucli.atwood(m1="4kg", m2="1kg", radius1="0.1m")
    lines = '{"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg"}\n{"m1": "4kg", "m2": "1kg", "radius1": "0.1m"}\n'
    run = run_taucli("atwood", "--batch", stdin=lines)
    assert "give pulley_radius for" in run.out and "--pulley" not in run.out, run.out
    cli = run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--radius1", "0.1m")
    assert_usage_error(cli, "--radius2 is required with --radius1 (or --pulley-radius for it)")


# item 20: every example in a message works as typed in zsh (and so in bash: the words shlex gives)

_SOURCE = Path(taucli.__file__).parent


def _texts(node, names: dict, deep: bool = True):
    """The texts an expression may be: a string, an f-string (each hole a 1), either side of an
    if, a concatenation, a dict's values, a name assigned a text in the module."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        yield node.value
    elif isinstance(node, ast.JoinedStr):
        yield "".join(part.value if isinstance(part, ast.Constant) else "1" for part in node.values)
    elif isinstance(node, ast.IfExp):
        yield from _texts(node.body, names, deep)
        yield from _texts(node.orelse, names, deep)
    elif isinstance(node, ast.BinOp):
        yield from (left + right for left in _texts(node.left, names, deep) for right in _texts(node.right, names, deep))
    elif isinstance(node, ast.Dict):
        for value in node.values:
            yield from _texts(value, names, deep)
    elif isinstance(node, ast.Subscript):
        yield from _texts(node.value, names, deep)
    elif isinstance(node, ast.Name) and deep:
        yield from names.get(node.id, ())


def _examples():
    """Every example= a message is given in taucli's source, and each kind's example after a flag."""
    found = [(f"kinds.{kind.name}", "--x " + (kind.example if kind.example.startswith("'") or " " not in kind.example else f"'{kind.example}'"))
             for kind in KINDS.values()]
    found += [(f"{command.name} {option.flag}", f"{option.flag} {shell_word(option.example)}")  # what a message suggests for it (#42 item 18)
              for command in SCENES.values() for option in command.options if option.example]
    for path in sorted(_SOURCE.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        names: dict[str, list[str]] = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
                names.setdefault(node.targets[0].id, []).extend(_texts(node.value, names, deep=False))
        for node in ast.walk(tree):
            if isinstance(node, ast.keyword) and node.arg == "example":
                for text in _texts(node.value, names):
                    if re.search(r"\{[a-z_0-9]+\}|--[a-z]|^taucli ", text):  # a command line (not a CSV header or a JSON line)
                        found.append((f"{path.relative_to(_SOURCE)}:{node.value.lineno}", text))
    return found


def test_every_example_in_a_message_pastes_into_zsh_as_bash_reads_it(tmp_path):
    examples = _examples()
    assert len(examples) > 200
    wrong = []
    for where, text in examples:
        flags = re.sub(r"\{([a-z][a-z0-9_]*)\}", lambda m: "--" + m[1].replace("_", "-"), text)
        for line in flags.split(", or "):
            line = re.split(r" [<>] ", line)[0]  # a redirection is the shell's own
            zsh = subprocess.run(["zsh", "-f", "-c", "print -rl -- " + line], capture_output=True, text=True, cwd=tmp_path)
            if zsh.returncode != 0 or zsh.stdout.splitlines() != shlex.split(line):
                wrong.append((where, line, zsh.stderr.strip()))
    assert not wrong, "\n".join(map(str, wrong))


def test_no_dimension_in_pint_brackets_reaches_a_message():
    """Every dimension a text may have, mass, length and time to the powers -3..3: said in words."""
    from taucli.quantities.registry import _describe

    for mass in range(-3, 4):
        for length in range(-3, 4):
            for time in range(-3, 4):
                said = _describe({"[mass]": mass, "[length]": length, "[time]": time})
                assert "[" not in said and "**" not in said and said.startswith(("a ", "an ")), said
    run = run_taucli("spin-down", "--inertia", "1 lbf*ft^2", "--omega0", "1rad/s")
    assert_usage_error(run, "got '1 lbf*ft^2', which is a torque or energy times a length")


@pytest.mark.parametrize("typed, meant", [("--hlep", "--help"), ("--M1", "--m1")])
def test_a_mistyped_flag_gets_its_did_you_mean(typed, meant):
    assert_usage_error(run_taucli("atwood", typed, "4kg" if typed == "--M1" else "--m1", *(["--m1", "4kg"] if typed == "--M1" else ["4kg"])),
                       f"{typed} is not an option of atwood; did you mean '{meant}'?")


@pytest.mark.parametrize("scene", ["inertia", "rolling", "atwood"])
def test_help_after_a_scene_is_its_help_where_help_is_no_value(scene):
    run = run_taucli(scene, "help")
    assert run.code == 0 and run.out.startswith(f"Usage: taucli {scene} "), run


def test_python_says_a_sweep_is_a_list():
    with pytest.raises(taucli.InputError, match=r"m2: takes one value, or a list of values for a sweep") as raised:
        taucli.atwood(m1="4kg", m2="1..3 kg")
    assert "taucli.atwood(..., m2=[1.0, 2.0, 3.0])" in str(raised.value)


def _parameters_named_bare(err: taucli.InputError, command) -> list[str]:
    """Parameters a message's texts name as words rather than as {name} (which each surface spells:
    --inner-radius on the command line): "it takes mass, inner_radius, outer_radius" reached the
    command line as Python keywords."""
    text = err.spelled(lambda name: "@")
    keywords = {option.name for option in command.options if "_" in option.name}
    return sorted(name for name in keywords if re.search(rf"(?<![\w-]){name}(?![\w=])", text))


@pytest.mark.parametrize("command", list(SCENES.values()), ids=list(SCENES))
def test_errors_name_parameters_as_the_surface_spells_them(command):
    """Class check: every error of the example with a keyword left out, and for inertia every shape
    with each dimension left out, names each parameter through {name}, never as a bare keyword."""
    from taucli.scenes.shapes import SHAPES

    function = getattr(taucli, command.function_name)
    runs = list(_variants(command))
    if command.name == "inertia":
        for shape in SHAPES.values():
            dims = {dim: "0.3m" for dim in shape.dims}
            runs += [([shape.name], {"mass": "1kg", **{d: v for d, v in dims.items() if d != left}}) for left in shape.dims]
            runs.append(([shape.name], {"mass": "1kg", **dims, "inner_radius" if "inner_radius" not in dims else "width": "0.1m"}))
    bare = []
    for words, given in runs:
        try:
            function(*words, **given)
        except taucli.InputError as err:
            bare += [(str(err), name) for name in _parameters_named_bare(err, command)]
    assert not bare, bare


def test_a_result_s_own_example_leaves_out_what_is_given():
    """rolling's omega: its example "--length 2m --radius 0.1m" beside a --length typed already was
    "--length is given twice" when pasted (a new user's trial); it is "--radius 0.1m" there."""
    refused = run_taucli("rolling", "sphere", "--angle", "30deg", "--length", "2m", "--get", "omega")
    assert_usage_error(refused, "(e.g. --radius 0.1m)")
    made = run_taucli("rolling", "sphere", "--angle", "30deg", "--length", "2m", "--radius", "0.1m", "--get", "omega")
    assert made.code == 0 and float(made.out) > 0, made
