"""#44 items 1, 2 and 8: how taucli fit maps a file's columns to the scene, on the files labs have.

- Two columns that would give one input (``length (m)`` and ``length (cm)``; ``t (s)`` and
  ``time (ms)``) are refused, naming both, the input and the --x that picks one: taking both
  interleaved them (sample i got row i//2's value) or crashed.
- A header's unit is read wherever it stands (PASCO's ``Time (ms) Run #1`` was read as seconds);
  a used column with no unit is SI only where its name is the input's or result's own, with a
  note, and refused otherwise, naming the mapping that gives it a unit (a bare ``millis`` column).
- A blank or NaN cell (phyphox pads with NaN, Vernier and PASCO pad shorter runs with blanks) is
  no measurement: the rows whose used cells hold one are left out and counted in a note; an
  unused column's never refuses the file.

The data: a wheel coasting under friction alone, ω(t) = ω₀ − (τ_f/I)t until it stops (written
here in mpmath), and a shell rolling down a slope, t = √(2L(1 + k²)/(g sin θ)); Gaussian noise
from fixed seeds. Every fit is checked within 3σ of the truth.
"""

from __future__ import annotations

import io
import math
import random

import mpmath
import pytest

import taucli.fit
from conftest import assert_usage_error, run_taucli
from taucli.answering.profile import read_profile
from taucli.core.errors import InputError
from taucli.fit import data, samples
from taucli.options import SCENES
from taucli.quantities import units

MP_DPS = 30
INERTIA, OMEGA0, FRICTION = mpmath.mpf("0.1"), mpmath.mpf(30), mpmath.mpf("0.3")  # stops at ω₀I/τ_f = 10 s
NOISE = 0.05  # rad/s
TIMES = [0.25 * i for i in range(36)]  # 0 .. 8.75 s: before the stop


def omega(t: float) -> float:
    return float(OMEGA0 - FRICTION / INERTIA * mpmath.mpf(t))


def coast(seed: int, times=TIMES) -> list[tuple[float, float]]:
    """(t in s, ω in rad/s) of the coast, with noise."""
    rng = random.Random(seed)
    return [(t, omega(t) + rng.gauss(0.0, NOISE)) for t in times]


def table(header: str, rows) -> str:
    return header + "\n" + "".join(",".join(str(cell) for cell in row) + "\n" for row in rows)


def fit_coast(text: str, **options):
    """The report of friction and ω₀ fitted to ``text`` (as stdin), I given."""
    return taucli.fit.fit("spin-down", "-", fit="friction,omega0", inertia="0.1 kg*m^2", stdin=io.StringIO(text), **options)


def assert_friction_within_3_sigma(report) -> None:
    value, sigma = report.results["friction"].value, report.uncertainties["friction"]
    assert sigma > 0 and abs(value - float(FRICTION)) < 3 * sigma, (value, sigma)
    assert abs(report.results["omega0"].value - float(OMEGA0)) < 3 * report.uncertainties["omega0"]


def refused(run) -> str:
    with pytest.raises(InputError) as caught:
        run()
    assert "\n" not in str(caught.value)
    return str(caught.value)


# Item 1: two columns for one input

def test_two_time_columns_are_refused_naming_both_and_the_x_that_picks_one(tmp_path):
    """Before: t (s) and time (ms) both appended to the times, and the fit crashed (exit 1, IndexError)."""
    rows = [(t, 1000 * t, f"{w:.6f}") for t, w in coast(11)]
    path = tmp_path / "coast.csv"
    path.write_text(table("t (s),time (ms),omega (rad/s)", rows))
    done = run_taucli("fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--get", "friction")
    assert_usage_error(done, "columns 't (s)' and 'time (ms)' would both give --time for each sample", "pick one: --x 't (s)=time'")
    report = fit_coast(path.read_text(), x="t (s)")  # the way out the message gives
    assert_friction_within_3_sigma(report)
    assert "column 'time (ms)' not used: --x gives time from column 't (s)'" in report.notes


def rolling_time(length: float, angle_deg: float, k2) -> float:
    g = mpmath.mpf("9.80665")
    return float(mpmath.sqrt(2 * mpmath.mpf(length) * (1 + k2) / (g * mpmath.sin(mpmath.radians(angle_deg)))))


def test_a_length_in_metres_and_in_centimetres_is_refused_not_interleaved():
    """The issue's runs table: before, both columns appended to length and k² came out wrong, exit 0."""
    k2, rng = mpmath.mpf(2) / 3, random.Random(6)  # a thin shell
    rows = [(a, L, round(100 * L, 6), f"{rolling_time(L, a, k2) + rng.gauss(0, 0.003):.6f}") for a in (4, 8, 12, 16) for L in (0.5, 1.0)]
    text = table("angle (deg),length (m),length (cm),t (s)", rows)
    said = refused(lambda: taucli.fit.fit("rolling", "-", fit="k2", stdin=io.StringIO(text)))
    assert "columns 'length (m)' and 'length (cm)' would both give length for each sample" in said
    assert "pick one: x 'length (m)=length'" in said
    report = taucli.fit.fit("rolling", "-", fit="k2", x="length (cm)=length", stdin=io.StringIO(text))
    assert abs(report.results["k2"].value - float(k2)) < 3 * report.uncertainties["k2"]


def _name_matched_inputs(command):
    """Each input a column's name gives (the options the name matching takes, and --time as t)."""
    return [option.name for option in command.options
            if option.name in command.input_names and option.is_quantity and not option.repeatable]


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_in_every_scene_two_columns_named_for_one_input_are_refused(scene):
    """The class: every input of every scene, spelled two ways a header may spell it (pulley_mass
    and PULLEY-MASS, each in its SI unit), beside a result measured: never both taken (the old
    tree took both, two values of the input for one row)."""
    command = SCENES[scene]
    result = next(r for r in command.results if r.unit and command.option(r.key) is None and r.key not in ("t", "time"))
    measured = f"{result.key} ({result.unit})"

    def build(first: str, second: str):
        text = f"{first},{second},{measured}\n1,1,1\n"
        with pytest.raises(InputError) as caught:
            samples.build(command, [data.read("-", io.StringIO(text))])
        return str(caught.value)

    for name in _name_matched_inputs(command):
        unit = units.KINDS[command.option(name).kind].si_unit
        said = build(f"{name} ({unit})" if unit else name, f"{name.replace('_', '-').upper()} [{unit}]" if unit else name.upper())
        assert f"would both give {name} for each sample" in said and "pick one: x" in said, (scene, name, said)
    if command.option("time") is not None and command.result("t") is None:
        assert "columns 'Time (s)' and 't' would both give time" in build("Time (s)", "t")


def test_x_giving_one_input_two_columns_is_refused_and_x_naming_a_column_twice_too():
    text = table("a (s),b (s),omega (rad/s)", [(t, t, w) for t, w in coast(1, TIMES[:5])])
    assert "x: gives time from two columns, 'a (s)' and 'b (s)'" in refused(lambda: fit_coast(text, x=["a (s)", "b (s)=time"]))
    assert "x: names column 'a (s)' again" in refused(lambda: fit_coast(text, x=["a (s)", "a (s)=omega0"]))
    assert "y: names column 'a (s)' again" in refused(lambda: fit_coast(text, x=["a (s)"], y="a (s)=omega"))


# Item 2: a unit after words, and columns with no unit

@pytest.mark.parametrize("header,options", [
    ("Time (ms) Run #1,Angular Velocity (rad/s) Run #1", {"x": "Time (ms) Run #1", "y": "Angular Velocity (rad/s) Run #1=omega"}),
    ("Time (ms) Run #1,Angular Velocity (rad/s) Run #1", {"y": "Angular Velocity=omega"}),  # Time is --time by its name
    ("Run 1: Time (ms),Run 1: omega (rad/s)", {}),  # Vernier's mark: every column matched by name
    ("time [ms] run 1,omega [rad/s] run 1", {}),
])  # fmt: skip
def test_a_unit_after_words_is_read_pascos_time_in_milliseconds(header, options):
    """Before: 'Time (ms) Run #1' named no unit and was read as seconds: friction 3.0e-4 for 0.3 N·m,
    t_stop 9,981 s; or the headers were not matched at all."""
    report = fit_coast(table(header, [(f"{1000 * t:g}", f"{w:.6f}") for t, w in coast(2)]), **options)
    assert_friction_within_3_sigma(report)
    assert abs(report.results["t_stop"].value - 10) < 3 * report.uncertainties["t_stop"]


def test_a_bare_millis_column_is_refused_naming_the_mapping_that_gives_it_a_unit(tmp_path):
    """Before: --x millis read milliseconds as seconds, exit 0."""
    path = tmp_path / "logger.csv"
    path.write_text(table("millis,omega (rad/s)", [(f"{1000 * t:g}", f"{w:.6f}") for t, w in coast(3)]))
    done = run_taucli("fit", "spin-down", str(path), "--x", "millis", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--get", "friction")
    assert_usage_error(done, "column 'millis' (--time) has no unit, and only a column named t or time is read in SI (s) without one",
                       "give the unit its numbers are in: --x 'millis=time (ms)'")
    assert_friction_within_3_sigma(fit_coast(path.read_text(), x="millis=time (ms)"))


@pytest.mark.parametrize("name", ["t", "time", "Time", "T"])
def test_a_column_named_as_its_input_is_si_without_a_unit_and_says_so(name):
    report = fit_coast(table(f"{name},omega (rad/s)", [(t, f"{w:.6f}") for t, w in coast(4)]))
    assert_friction_within_3_sigma(report)
    assert f"column '{name}' has no unit: read in s, the SI unit of --time" in report.notes


def test_a_result_with_no_unit_is_si_under_its_own_name_and_refused_under_another():
    rows = "m1 (g),m2 (g),{}\n207,200,4.06\n206,201,5.00\n"
    found = samples.build(SCENES["atwood"], [data.read("-", io.StringIO(rows.format("t")))])
    assert found.y == [4.06, 5.0] and "column 't' has no unit: read in s, the SI unit of the result t" in found.notes
    with pytest.raises(InputError, match=r"column 'secs' \(the result t\) has no unit, and only a column named t is read in SI \(s\) without one; "
                                         r"give the unit its numbers are in: y 'secs=t \(ms\)'"):
        samples.build(SCENES["atwood"], [data.read("-", io.StringIO(rows.format("secs")))], y="secs=t")
    pure = samples.build(SCENES["rolling"], [data.read("-", io.StringIO("angle (deg),ratio,t (s)\n10,0.4,1\n"))], x=("ratio=k2",))
    assert pure.inputs["k2"] == [0.4] and not any("ratio" in note for note in pure.notes)  # a pure number has no unit to read


# What each matching names, the name forms the reader takes for it, its unit, and the table around it
# ({} the header under test, its cell 50 in that unit).
TARGETS = {
    "input": ("atwood", "pulley_mass", ["pulley_mass", "pulley-mass", "Pulley Mass", "PULLEY-MASS"], "g", 0.05, ["m1 (g)", "m2 (g)", "{}", "t (s)"], ["207", "200", "50", "4.06"]),
    "time": ("spin-down", "time", ["t", "time", "Time", "T"], "ms", 0.05, ["{}", "omega (rad/s)"], ["50", "3"]),
    "result": ("atwood", "t", ["t", "T"], "ms", 0.05, ["m1 (g)", "m2 (g)", "{}"], ["207", "200", "50"]),
}
UNIT_FORMS = ["({})", "[{}]", "( {} )", "({} )"]
PLACES = ["{name} {unit}", "{name}{unit}", "{name} {unit} Run #1", "Run 1: {name} {unit}", '"{name} {unit}"', "{name} {unit} run 3"]


@pytest.mark.parametrize("place", PLACES)
@pytest.mark.parametrize("unit_form", UNIT_FORMS)
@pytest.mark.parametrize("target", sorted(TARGETS))
def test_every_way_a_header_names_a_column_gives_the_same_input_in_the_same_unit(target, unit_form, place):
    """The class: for an input, --time and a result, each name form the reader takes × each unit
    form × where the unit stands (and a single run's mark) × each separator gives the same input
    (or result) in the same unit, matched by name and by --x or --y alike."""
    scene, key, names, unit, expected, cells, values = TARGETS[target]
    command = SCENES[scene]
    for name in names:
        header = place.format(name=name, unit=unit_form.format(unit))
        for separator in (",", ";", "\t"):
            text = separator.join(cell.format(header) for cell in cells) + "\n" + separator.join(values) + "\n"
            by_name = samples.build(command, [data.read("-", io.StringIO(text))])
            mapped = {"x": (f"{header.strip(chr(34))}={key}",)} if target != "result" else {"y": f"{header.strip(chr(34))}={key}"}
            by_mapping = samples.build(command, [data.read("-", io.StringIO(text))], **mapped)
            for found in (by_name, by_mapping):
                got = found.y if target == "result" else found.inputs[key]
                assert got == pytest.approx([expected], rel=1e-15), (header, separator, found.notes)
                assert (found.y_key == key) if target == "result" else (found.y_key != key)


@pytest.mark.parametrize("place", [p for p in PLACES if "Run" not in p and "run" not in p] + ["{name} {unit} Run #1"])
@pytest.mark.parametrize("unit", ["(ms)", "[ms]", "( ms )"])
def test_a_torque_profile_reads_a_headers_unit_where_fit_does(place, unit):
    """csv_text.split_header is the one reader of a header's unit, for --torque-profile too."""
    header = place.format(name="t", unit=unit)
    profile = read_profile([f"{header},torque (N*m)\n", "0,1\n", "2,3\n"])
    assert list(profile.samples) == [(0.0, 1.0), (0.002, 3.0)]


def test_several_runs_keep_their_marks_so_their_names_differ():
    text = "Time (s) Run #1,omega (rad/s) Run #1,Time (s) Run #2,omega (rad/s) Run #2\n0,30,0,20\n1,27,1,18\n"
    from taucli.fit import columns  # (new in #44: imported here so that the other tests run on the old tree)

    found = data.read("-", io.StringIO(text))
    assert [column.name for column in columns.one_run_named(found).columns] == ["Time Run #1", "omega Run #1", "Time Run #2", "omega Run #2"]
    one = samples.build(SCENES["spin-down"], [found], x=("Time Run #2",), y="omega Run #2=omega")
    assert one.inputs == {"time": [0.0, 1.0]} and one.y == [20.0, 18.0]


# Item 8: blank and NaN cells

def test_a_phyphox_export_padded_with_nan_is_fitted_and_the_rows_left_out_counted():
    """Before: any NaN refused the whole file, in a column used or not."""
    lines = ['"Time (s)","Gyroscope z (rad/s)","Gyroscope x (rad/s)","Pressure (hPa)"']
    for i, (t, w) in enumerate(coast(5)):
        lines.append(f"{t:.9E},{w:.9E},{'NaN' if i % 4 else '1.0E-2'},{'NaN' if i else '1013.2'}")
    lines += ["NaN,NaN,NaN,NaN", "9.25E0,NaN,NaN,NaN"]  # the sensor stopped before the clock
    report = fit_coast("\n".join(lines) + "\n", x="Time (s)", y="Gyroscope z (rad/s)=omega")
    assert_friction_within_3_sigma(report)
    assert report.results["samples"].value == len(TIMES)
    assert any(note.startswith("2 rows left out (lines 38, 39): a column the fit uses ('Gyroscope z (rad/s)', 'Time (s)') is blank or NaN there")
               for note in report.notes), report.notes


def test_vernier_runs_of_different_lengths_padded_with_blanks_are_each_fitted():
    first, second = coast(8), coast(9, TIMES[:20])
    header = "Run 1: Time (s),Run 1: Angular velocity (rad/s),Run 2: Time (s),Run 2: Angular velocity (rad/s)"
    rows = [(t1, f"{w1:.6f}", *((t2, f"{w2:.6f}") if i < len(second) else ("", ""))) for i, ((t1, w1), (t2, w2)) in
            enumerate(zip(first, second + first[len(second):]))]
    text = table(header, rows)
    run1 = fit_coast(text, x="Run 1: Time (s)", y="Run 1: Angular velocity (rad/s)=omega")
    assert_friction_within_3_sigma(run1)
    assert run1.results["samples"].value == len(first) and not any("left out (" in note for note in run1.notes)
    run2 = fit_coast(text, x="Run 2: Time", y="Run 2: Angular velocity=omega")
    assert_friction_within_3_sigma(run2)
    assert run2.results["samples"].value == len(second)
    assert f"{len(first) - len(second)} rows left out (lines 22, 23, 24, … ({len(first) - len(second)} in all))" in " ".join(run2.notes)


@pytest.mark.parametrize("empty", ["", "NaN", "nan", " "])
def test_a_blank_or_nan_used_cell_in_the_middle_is_skipped_and_counted_and_text_is_refused_with_its_line(empty, tmp_path):
    rows = [(t, f"{w:.6f}") for t, w in coast(10)]
    rows[7] = (rows[7][0], empty)
    rows[20] = (empty, rows[20][1])
    report = fit_coast(table("t (s),omega (rad/s)", rows))
    assert_friction_within_3_sigma(report)
    assert report.results["samples"].value == len(TIMES) - 2 and report.results["dropped"].value == 0
    assert any(note.startswith("2 rows left out (lines 9, 22)") for note in report.notes)
    rows[7] = (rows[7][0], "n/a")
    path = tmp_path / "coast.csv"
    path.write_text(table("t (s),omega (rad/s)", rows))
    done = run_taucli("fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", "--fit", "friction,omega0")
    assert_usage_error(done, "coast.csv line 9: expected a number in column 'omega (rad/s)', got 'n/a'")


def test_empty_rows_are_not_samples_for_every_nor_range_and_a_table_of_none_is_refused():
    rows = [(t, f"{w:.6f}" if i % 2 else "NaN") for i, (t, w) in enumerate(coast(12))]
    found = samples.build(SCENES["spin-down"], [data.read("-", io.StringIO(table("t (s),omega (rad/s)", rows)))], every="2", ranges=("t=..5s",))
    assert found.inputs["time"] == [0.25, 0.75, 1.25, 1.75, 2.25, 2.75, 3.25, 3.75, 4.25, 4.75][::2]
    assert (len(found.empty), found.outside, found.thinned) == (18, 8, 5)
    with pytest.raises(InputError, match=r"has no row with a number in every column the fit uses \('omega \(rad/s\)', 't \(s\)'\)"):
        samples.build(SCENES["spin-down"], [data.read("-", io.StringIO("t (s),omega (rad/s),u\n0,,1\n1,NaN,2\n"))])
    runs = samples.build(SCENES["atwood"], [data.read("-", io.StringIO("note,t (s)\nNaN,4.06\n,4.03\nNaN,3.88\n"))])
    assert runs.count == 3 and math.isnan(data.read("-", io.StringIO("note,t (s)\nNaN,4.06\n")).columns[0].values[0])


@pytest.mark.parametrize("shell", ["bash", "zsh", "fish"])
def test_the_mapping_a_refusal_names_works_as_typed_in_each_shell(shell):
    """The --x a message gives quotes the header as bash, zsh and fish read it, a header with a
    quote, a $ or a # too (the old quoting wrapped "Newton's t (s)" in single quotes, broken)."""
    import shutil
    import subprocess

    from taucli.fit.columns import quoted

    if shutil.which(shell) is None:
        pytest.skip(f"{shell} is not installed")
    for header in ["t (s)", "Newton's t (s)", 'a$b "q" (s)', "x#1", "Run #1: w\\x (s)"]:
        typed = quoted(f"{header}=time")
        done = subprocess.run([shell, "-c", f"printf '%s' {typed}"], capture_output=True, text=True, timeout=30)
        assert done.stdout == f"{header}=time", (shell, typed, done.stdout)
