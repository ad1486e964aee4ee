"""docs/units.md's table of spellings, read as a test table (#31): every way in reads a spelling alike.

Each row of the table ("typed | read as | note") names spellings, and either the value they are
read as (before any "="; one for all the row's spellings, or one each) with the words its note
holds, or "refused:" with the words the refusal holds (in backticks: one fragment for all, or one
each). A row's kind is the kind of its value's unit, or the one it names ("for a mass"). Each
spelling is then read through every way in that takes its kind: an option on the command line,
a batch line, the Python API, a key of a spec (--couple "omega0=…", --part "mass=…", --particle
"angle=…") and --want (--find INPUT --want RESULT=VALUE, the result being of the row's kind), and
must give the stated value in SI (to 1e-12) and note, or the stated refusal: exit status 2 and one
line, an error line in a batch, an InputError in Python.

The SI values of the units the table shows come from their definitions (1 lbf = 0.45359237 kg ×
9.80665 m/s², 1 ft = 0.3048 m, 1 in = 0.0254 m, 1 rev = 2π rad), written out here.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass

import pytest

import taucli
from conftest import ROOT, run_taucli
from taucli.front import cli
from taucli.core.errors import InputError

PI = math.pi
G0 = 9.80665  # m/s²
LBF = 0.45359237 * G0  # N
FT = 0.3048  # m

# The units of the "read as" column: the kind each is of, and the SI value of one.
SHOWN = {
    "N·m": ("torque", 1.0), "kN·m": ("torque", 1e3), "mN·m": ("torque", 1e-3), "daN·m": ("torque", 10.0), "N·cm": ("torque", 0.01),
    "lbf·ft": ("torque", LBF * FT), "kgf·cm": ("torque", G0 * 0.01), "kgf·m": ("torque", G0),
    "lbf·ft·s²": ("moment of inertia", LBF * FT), "lb·ft²": ("moment of inertia", 0.45359237 * FT * FT), "hp": ("power", 550 * LBF * FT),
    "kg·m²": ("moment of inertia", 1.0), "lbf·in·s²": ("moment of inertia", LBF * 0.0254), "ozf·in·s²": ("moment of inertia", LBF / 16 * 0.0254), "m/s²": ("acceleration", 1.0), "kg": ("mass", 1.0), "in": ("length", 0.0254), "°": ("angle", PI / 180),
    "rad/s": ("angular velocity", 1.0), "rpm": ("angular velocity", 2 * PI / 60), "rev/s": ("angular velocity", 2 * PI),
    "rad/s²": ("angular acceleration", 1.0), "rev/s²": ("angular acceleration", 2 * PI),
    "m": ("length", 1.0), "N": ("force", 1.0), "W": ("power", 1.0), "J": ("energy", 1.0), "": ("dimensionless", 1.0),
    "N·m·s": ("viscous coefficient", 1.0), "N·m/(rev/s)": ("viscous coefficient", 1 / (2 * PI)), "N·m/(rev/s)²": ("drag coefficient", 1 / (2 * PI) ** 2),
}  # fmt: skip


@dataclass(frozen=True)
class Way:
    """Where each way in takes a kind: an option (scene and the other options, the option's key),
    a spec key (scene and options, the spec option, its text with {} for the value, the key the
    report echoes it under), and --want (scene and options, the input solved for, the result)."""

    option: tuple[tuple[str, ...], str]
    spec: tuple[tuple[str, ...], str, str, str] | None
    want: tuple[tuple[str, ...], str, str] | None


WAYS = {
    "torque": Way(
        (("spin-down", "--inertia", "1"), "torque"),
        None,
        (("impulse", "--inertia", "1", "--omega0", "0rad/s", "--omega1", "10rad/s"), "duration", "torque"),  # τ = IΔω/Δt
    ),
    "moment of inertia": Way(
        (("spin-down", "--friction", "1", "--omega0", "1rad/s"), "inertia"),
        (("inertia", "disc", "--mass", "1kg", "--radius", "1m"), "part", "inertia={}", "part2_inertia"),
        (("inertia", "disc", "--radius", "1m"), "mass", "I"),  # I = MR²/2
    ),
    "acceleration": Way(
        (("atwood", "--m1", "4kg", "--m2", "1kg"), "g"),
        None,
        (("atwood", "--m1", "1kg", "--m2", "0"), "g", "a"),  # a mass falling freely: a = g
    ),
    "angular velocity": Way(
        (("spin-down", "--inertia", "1", "--friction", "1"), "omega0"),
        (("impulse", "--inertia", "1", "--omega0", "0rad/s"), "couple", "inertia=1 omega0={}", "couple1_omega0"),
        (("spin-down", "--inertia", "1", "--torque", "1", "--time", "1s"), "omega0", "omega"),  # ω = ω0 + 1 rad/s
    ),
    "angular acceleration": Way(
        (("spin-down", "--time", "1s"), "alpha"),
        None,
        (("spin-down", "--inertia", "1"), "torque", "alpha0"),  # α = τ/I
    ),
    "power": Way(
        (("spin-down", "--inertia", "2", "--until-omega", "100rpm"), "power"),
        None,
        None,
    ),
    "angle": Way(
        (("spin-down", "--inertia", "1", "--force", "1N", "--lever", "1m"), "push_angle"),
        (("impulse", "--inertia", "1", "--omega0", "0rad/s"), "particle", "mass=1kg speed=1m/s radius=1m angle={}", "particle1_angle"),
        (("spin-down", "--inertia", "1", "--torque", "1", "--time", "1s"), "omega0", "theta"),  # θ = ω0·1 s + ½ rad
    ),
    "mass": Way(
        (("atwood", "--m2", "1kg"), "m1"),
        (("inertia", "disc", "--mass", "1kg", "--radius", "1m"), "part", "point mass={} offset=1m", "part2_mass"),
        (("inertia", "disc", "--radius", "1m", "--part", "point mass=0.5kg offset=1m"), "mass", "mass"),  # the total mass
    ),
    "force": Way(
        (("spin-down", "--inertia", "1", "--lever", "1m"), "force"),
        (("spin-down", "--inertia", "1", "--omega0", "10rad/s"), "brake", "force={} mu=0.5 radius=1m", "brake1_force"),
        (("pendulum", "--shape", "rod", "--length", "1m", "--axis", "end", "--angle0", "90deg"), "mass", "pivot_force0"),  # mg/4 at the release
    ),
    "viscous coefficient": Way((("spin-down", "--inertia", "1", "--omega0", "1rad/s"), "viscous"), None, None),
    "drag coefficient": Way((("spin-down", "--inertia", "1", "--omega0", "1rad/s"), "drag"), None, None),
    "energy": Way((("spin-down", "--inertia", "2", "--friction", "1"), "ke0"), None, None),
    "dimensionless": Way((("drive", "--motor-inertia", "1.2 kg*cm^2", "--load-inertia", "0.05 kg*m^2"), "ratio"), None, None),
    "length": Way(
        (("atwood", "--m1", "4kg", "--m2", "1kg"), "distance"),
        (("inertia", "disc", "--mass", "1kg", "--radius", "1m"), "part", "point mass=1kg offset={}", "part2_offset"),
        (("inertia", "disc", "--mass", "1kg"), "radius", "k"),  # k = R/√2
    ),
}


@dataclass(frozen=True)
class Spelling:
    """One spelling of the table, and what it must give."""

    typed: str
    kind: str
    value: float | None  # in SI; None where it is refused
    refusal: str | None  # words the refusal holds
    note: str  # words the note holds ("" for no note)


def _number(text: str) -> float:
    """A number of the "read as" column: 90, 4.5359237, 5/12, π/2, 33⅓, 40/9.80665."""
    python = re.sub(r"(\d)π", r"\1*pi", text.replace("⅓", "+1/3")).replace("π", "pi")
    assert re.fullmatch(r"[\d.+*/pi]+", python), text
    return float(eval(python, {"__builtins__": {}, "pi": PI}))  # noqa: S307 - the table's own numbers, checked above


def _cells(line: str) -> list[str]:
    return [cell.strip() for cell in line.strip().strip("|").split("|")]


def table() -> list[Spelling]:
    """The spellings of docs/units.md's table, each with what it must give."""
    text = (ROOT / "docs" / "units.md").read_text(encoding="utf-8")
    lines = text[text.index("| typed | read as | note |") :].splitlines()
    found = []
    for line in lines[2:]:
        if not line.startswith("|"):
            break
        typed_cell, read_cell, note_cell = _cells(line)
        typed = re.findall(r"`([^`]+)`", typed_cell)
        named = re.search(r"\bfor an? ([a-z ]+)$", typed_cell)
        named = named and [named[0], {"plain number": "dimensionless"}.get(named[1], named[1])]  # a plain number: the dimensionless kind
        if read_cell.startswith("refused"):
            fragments = re.findall(r"`([^`]+)`", read_cell)
            assert named and fragments and len(fragments) in (1, len(typed)), line
            found += [Spelling(t, named[1], None, fragments[i if len(fragments) > 1 else 0], "") for i, t in enumerate(typed)]
            continue
        items = [item.split(" = ")[0] for item in re.split(r" \(", read_cell)[0].split(", ")]
        assert len(items) in (1, len(typed)), line
        for i, spelling in enumerate(typed):
            number, unit = re.fullmatch(r"([\d.π/⅓]+)\s*(\S*)", items[i if len(items) > 1 else 0]).groups()
            kind, one = SHOWN[unit]
            found.append(Spelling(spelling, named[1] if named else kind, _number(number) * one, None, note_cell.strip("`")))
    return found


SPELLINGS = table()


def test_the_table_is_read_whole_and_holds_this_issues_rows():
    typed = {s.typed: s for s in SPELLINGS}
    assert len(SPELLINGS) >= 70
    assert {s.kind for s in SPELLINGS} <= set(WAYS)
    assert typed["80 s^-1"].refusal == "80rad/s or 80rev/s"
    assert typed["(90 km/h)/(60 m)"].value == pytest.approx(25 / 60, rel=1e-15)
    assert typed["300"].kind == "angular velocity" and typed["300"].refusal == "300rpm or 300rad/s"
    assert typed["5kilos"].refusal == "unknown unit 'kilos'; did you mean 'kg'?"
    assert typed["1-5kg"].refusal == "a range is written 1..5kg"
    # #42: Hz is revolutions inside a coefficient's unit too; ton is refused; PS, %, N:1 and π are read
    assert typed["0.01 N*m/Hz"].value == pytest.approx(0.01 / (2 * PI), rel=1e-15) and typed["0.01 N*m/Hz"].kind == "viscous coefficient"
    assert typed["0.001 N*m/Hz^2"].value == pytest.approx(0.001 / (4 * PI**2), rel=1e-15)
    assert typed["2 long_ton"].value == pytest.approx(2 * 2240 * 0.45359237, rel=1e-15)
    assert typed["1 PS"].value == pytest.approx(75 * G0, rel=1e-15)  # 735.49875 W
    assert typed["2 ton"].refusal and typed["16ton"].refusal
    assert typed["10:1"].value == 10 and typed["85%"].value == pytest.approx(0.85, rel=1e-15)
    assert typed["0.135*20*pi/15 N*m"].value == pytest.approx(0.135 * 20 * PI / 15, rel=1e-15)
    # #47 item 7: a GD² (weight × diameter of gyration²): 4 kgf·m² is a ring weighing 1 kgf (1 kg) of diameter 2 m, J = mR² = 1 kg·m²;
    # the technical units' kgf·cm·s² is 9.80665 N × 0.01 m × 1 s²
    assert typed["4 kgf*m^2"].value == pytest.approx(1.0 * 1.0**2, rel=1e-15) and "GD²" in typed["4 kgf*m^2"].note
    assert typed["1 kgf*cm*s^2"].value == pytest.approx(G0 * 0.01, rel=1e-15) and typed["1 kgf*cm*s^2"].note
    assert typed["1 lbf*ft^2"].refusal  # a WR² or a GD²: a factor of 4 apart, so refused


def _run(argv: list[str], capsys) -> tuple[int, str, str]:
    status = cli.main([*argv, "--json", "--no-steps"])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def _gives(spelling: Spelling, status: int, out: str, err: str, where: str, *, key: str | None = None, result: str | None = None) -> None:
    """What one way in gave for ``spelling``: its value (an input ``key`` or a ``result``) and
    note, or its refusal, as the table says."""
    if spelling.value is None:
        assert status == 2, (where, out)
        assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, (where, err)
        assert spelling.refusal in err, (where, err)
        return
    assert status == 0, (where, err)
    document = json.loads(out)
    read = document["inputs"][key]["value"] if key else document["results"][result]["value"]
    assert read == pytest.approx(spelling.value, rel=1e-12), where
    _noted(spelling, document["notes"], where)


def _noted(spelling: Spelling, notes: list[str], where: str) -> None:
    """The note the table states is there; with none stated, no note is about this spelling."""
    mine = [note for note in notes if spelling.typed.strip() in note]
    if spelling.note:
        assert any(spelling.note in note for note in mine), (where, notes)
    else:
        assert not mine, (where, notes)


def _ids(spelling: Spelling) -> str:
    return f"{spelling.typed} ({spelling.kind})"


@pytest.mark.parametrize("spelling", SPELLINGS, ids=_ids)
def test_each_spelling_as_an_option(spelling, capsys):
    (scene, *base), key = WAYS[spelling.kind].option
    option = "--" + key.replace("_", "-")
    _gives(spelling, *_run([scene, *base, option, spelling.typed], capsys), f"{option} {spelling.typed}", key=key)


def _python(args: tuple[str, ...]) -> tuple[object, list[str], dict[str, str]]:
    """The API function, positional arguments and keywords of a command line's words."""
    scene, *rest = args
    positional, keywords, i = [], {}, 0
    while i < len(rest):
        if rest[i].startswith("--"):
            keywords[rest[i][2:].replace("-", "_")] = rest[i + 1]
            i += 2
        else:
            positional.append(rest[i])
            i += 1
    return getattr(taucli, scene.replace("-", "_")), positional, keywords


def _called(spelling: Spelling, function, positional, keywords, where: str, *, key: str | None = None, result: str | None = None) -> None:
    if spelling.value is None:
        with pytest.raises(InputError) as refused:
            function(*positional, **keywords)
        assert spelling.refusal in str(refused.value), (where, str(refused.value))
        return
    report = function(*positional, **keywords)
    read = report.inputs[key].value if key else report.results[result].value
    assert read == pytest.approx(spelling.value, rel=1e-12), where
    _noted(spelling, report.notes, where)


@pytest.mark.parametrize("spelling", SPELLINGS, ids=_ids)
def test_each_spelling_in_python(spelling):
    base, key = WAYS[spelling.kind].option
    function, positional, keywords = _python(base)
    _called(spelling, function, positional, {**keywords, key: spelling.typed}, f"{key}={spelling.typed!r}", key=key)


@pytest.mark.parametrize("kind", sorted({s.kind for s in SPELLINGS}))
def test_each_spelling_in_a_batch_line(kind):
    (scene, *base), key = WAYS[kind].option
    spellings = [s for s in SPELLINGS if s.kind == kind]
    done = run_taucli(scene, *base, "--batch", "--no-steps", stdin="".join(json.dumps({key: s.typed}) + "\n" for s in spellings))
    lines = done.out.splitlines()
    assert len(lines) == len(spellings), done.err
    for spelling, line in zip(spellings, lines):
        document = json.loads(line)
        where = f"batch {key}: {spelling.typed}"
        if spelling.value is None:
            assert spelling.refusal in document["error"]["message"], (where, document)
            continue
        assert "error" not in document, (where, document)
        assert document["inputs"][key]["value"] == pytest.approx(spelling.value, rel=1e-12), where
        _noted(spelling, document["notes"], where)


WITH_SPEC = [s for s in SPELLINGS if WAYS[s.kind].spec is not None]


@pytest.mark.parametrize("spelling", WITH_SPEC, ids=_ids)
def test_each_spelling_as_a_spec_key(spelling, capsys):
    (scene, *base), option, spec, key = WAYS[spelling.kind].spec
    text = spec.format(spelling.typed)
    _gives(spelling, *_run([scene, *base, f"--{option}", text], capsys), f'--{option} "{text}"', key=key)
    function, positional, keywords = _python((scene, *base))
    _called(spelling, function, positional, {**keywords, option: text}, f"{option}={text!r}", key=key)


WITH_WANT = [s for s in SPELLINGS if WAYS[s.kind].want is not None]


@pytest.mark.parametrize("spelling", WITH_WANT, ids=_ids)
def test_each_spelling_as_a_want(spelling, capsys):
    """--find INPUT --want RESULT=VALUE: the target is read as the option would be, and the
    result at the input found is it."""
    (scene, *base), find, result = WAYS[spelling.kind].want
    want = f"{result}={spelling.typed}"
    _gives(spelling, *_run([scene, *base, "--find", find, "--want", want], capsys), f"--want {want}", result=result)
    function, positional, keywords = _python((scene, *base))
    _called(spelling, function, positional, {**keywords, "find": find, "want": want}, f"want={want!r}", result=result)
