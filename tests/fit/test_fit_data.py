"""taucli fit's tables: CSV as sensor apps and loggers export it, every bad file refused in one
line (never a traceback, never a row skipped in silence), and columns matched to the scene in SI."""

from __future__ import annotations

import io

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taucli.core.errors import InputError
from taucli.fit import data, samples
from taucli.options import SCENES


def table(text: str) -> data.DataTable:
    return data.read("-", io.StringIO(text))


def refused(text: str) -> str:
    with pytest.raises(InputError) as caught:
        table(text)
    return str(caught.value)


@pytest.mark.parametrize("header,name,unit", [("Time (s)", "Time", "s"), ("t [ms]", "t", "ms"), ("omega", "omega", ""),
                                              ("Orientation (Azimuth) (°)", "Orientation (Azimuth)", "°"), ("a (m/s^2)", "a", "m/s^2")])
def test_a_header_may_carry_its_unit_in_parentheses_or_brackets(header, name, unit):
    assert data.split_header(header) == (name, unit)


def test_a_phyphox_export_is_read_quoted_headers_and_exponents_alike():
    found = table('"Time (s)","Gyroscope z (rad/s)"\n4.300000000E-3,1.191268054E1\n2.43E-2,-2.142682186E-3\n')
    assert [c.header for c in found.columns] == ["Time (s)", "Gyroscope z (rad/s)"]
    assert found.column("Gyroscope z (rad/s)").values == (11.91268054, -0.002142682186)
    assert found.lines == (2, 3)


@pytest.mark.parametrize("text", ["t;omega (rad/s)\n0;1.5\n1;2.5\n", "t\tomega (rad/s)\n0\t1.5\n1\t2.5\n", "t,omega (rad/s)\n0,1.5\n1,2.5\n"])
def test_tabs_semicolons_or_commas_separate_the_columns(text):
    assert table(text).column("omega (rad/s)").values == (1.5, 2.5)


def test_a_decimal_comma_is_read_where_the_file_shows_it_is_one():
    found = table("t (s);omega (rad/s)\n0;30,25\n0,5;29,1234\n")
    assert found.decimal_comma and found.column("omega (rad/s)").values == (30.25, 29.1234) and found.column("t (s)").values == (0.0, 0.5)
    assert table("t (s)\tomega (rad/s)\n1,5\t2,308300800E-2\n").column("omega (rad/s)").values == (0.023083008,)


@pytest.mark.parametrize("text,said", [
    ("t;m (kg)\n1;1,500\n2;2,250\n", "every comma could group thousands (three digits after it, one to three before), so it could be a thousands separator or a decimal comma"),
    ('t,m\n1,"1,5"\n', "a comma inside a cell of a comma-separated table could be a decimal comma or a thousands separator"),
    ("t;m\n1;1,5\n2;2.5\n", "numbers with a comma beside numbers with a point"),
])  # fmt: skip
def test_a_comma_that_could_be_a_thousands_separator_is_refused_not_guessed(text, said):
    assert said in refused(text)


@pytest.mark.parametrize("text,said", [
    ("t,omega\n0,1\n1,inf\n", "is inf, not a finite number"),
    ("t,omega\n0,1\n1,1e999\n", "too large for a double"),
    ("t,omega\n0,one\n", "line 2: expected a number in column 'omega', got 'one'"),
    ("t,omega\n0,1_000\n", "expected a number in column 'omega', got '1_000'"),
    ("t,omega\n0,1\n1,2,3\n", "line 3: expected 2 cells, as the header names, got 3"),
    ("", "holds no table"),
    ("# only a comment\n\n", "holds no table"),
    ("t,omega\n", "has a header and no rows of numbers"),
    ("0,1\n1,2\n", "expected a header naming the columns before the numbers"),
    ("t,t\n0,1\n", "names a column twice: t"),
    ("t,\n0,1\n", "a cell under no column's name"), ("t,,omega\n0,,1\n", "expected a name for every column"),
    ("t,omega\n0," + "1" * 200_000 + "\n", "cannot be read as a table"),
])  # fmt: skip
def test_a_bad_table_is_refused_in_one_line_naming_where(text, said):
    message = refused(text)
    assert said in message and "\n" not in message


def test_comments_blank_lines_a_bom_and_windows_1252_are_read(tmp_path):
    path = tmp_path / "a.csv"
    path.write_bytes("\ufeff# logger v2\nT (°C),t (s)\n\n20,1\n# pause\n21,2\n".encode("utf-8"))
    assert data.read(str(path)).column("t (s)").values == (1.0, 2.0)
    path.write_bytes("T (°C),t (s)\n20,1\n".encode("cp1252"))
    assert data.read(str(path)).columns[0].unit == "°C"


def test_a_missing_or_binary_file_is_refused(tmp_path):
    with pytest.raises(InputError, match="expected a readable data file"):
        data.read(str(tmp_path / "none.csv"))
    binary = tmp_path / "b.csv"
    binary.write_bytes(b"t,omega\n\x00\x01\x02")
    with pytest.raises(InputError, match="is not a text table"):
        data.read(str(binary))
    with pytest.raises(InputError, match="expected a readable data file"):
        data.read(str(tmp_path))


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=st.sampled_from(list("0123456789.,;\t\n-+eE# ()[]abcst\"'\x00\r")), max_size=120))
def test_any_text_is_read_as_a_table_or_refused_in_one_line(text):
    try:
        found = table(text)
    except InputError as err:
        assert "\n" not in str(err)
    else:
        assert found.columns and all(len(column.values) == len(found.lines) for column in found.columns)


def build(text: str, scene: str, **options):
    return samples.build(SCENES[scene], [table(text)], **options)


def test_columns_are_matched_by_name_and_read_in_si_with_their_units_notes():
    found = build("t (ms),omega (rpm)\n0,300\n500,270\n", "spin-down")
    assert found.inputs == {"time": [0.0, 0.5]} and found.y_key == "omega"
    assert found.y == pytest.approx([10 * 3.141592653589793, 9 * 3.141592653589793], rel=1e-15)
    hertz = build("t (s),omega (Hz)\n0,5\n", "spin-down")
    assert hertz.y == pytest.approx([10 * 3.141592653589793], rel=1e-15)
    assert hertz.notes == ["column 'omega (Hz)': Hz read as revolutions per second (ω = 2πn)"]


def test_x_and_y_map_columns_and_a_unit_a_header_lacks():
    found = build("Time (s),Gyroscope z (rad/s),Absolute (rad/s)\n0,1,1\n1,2,2\n", "spin-down", x=("Time (s)",), y="Gyroscope z (rad/s)=omega")
    assert found.inputs == {"time": [0.0, 1.0]} and found.y == [1.0, 2.0]
    assert found.notes == ["columns not used: 'Absolute (rad/s)' (neither an input of spin-down nor the result measured)"]
    assert build("tt,w\n0,1\n1,2\n", "spin-down", x=("tt=time (min)",), y="w=omega (rad/s)").inputs == {"time": [0.0, 60.0]}


def test_a_run_table_maps_options_and_the_result_measured():
    found = build("m1 (g),m2 (g),distance (cm),t (s)\n207,200,98,4.06\n", "atwood")
    assert {name: pytest.approx(values, rel=1e-15) for name, values in found.inputs.items()} == {"m1": [0.207], "m2": [0.2], "distance": [0.98]}
    assert found.y_key == "t"


@pytest.mark.parametrize("text,scene,options,said", [
    ("t,omega\n0,1\n", "spin-down", {}, "column 'omega' (the result omega) has no unit, and a bare number is ambiguous for an angular velocity"),
    ("t (s),x\n0,1\n", "spin-down", {}, "names the column that was measured, and no column is named like a result of spin-down"),
    ("t (s),omega (rad/s),theta (rad)\n0,1,1\n", "spin-down", {}, "says which column was measured: 'omega (rad/s)', 'theta (rad)' are each named like a result"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"y": "omega=omegaa"}, "expected a result of spin-down for column 'omega (rad/s)'"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"x": ("tau",)}, "expected a column of stdin: 't (s)', 'omega (rad/s)', got 'tau'"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"x": ("t (s)=blah",)}, "expected an input of spin-down that takes one quantity"),
    ("t (s),friction (N*m),omega (rad/s)\n0,1,1\n", "spin-down", {"fitted": ["friction"]}, "fits friction, and column 'friction (N*m)' gives it for each sample"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"ranges": ("t=5s",)}, "expected COLUMN=FROM..TO"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"ranges": ("t=5s..1s",)}, "expected FROM below TO"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"every": "0"}, "expected a whole number of 1 or more"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"sigma": "0 rad/s"}, "expected an uncertainty greater than 0"),
    ("t (s),omega (rad/s),u\n0,1,0\n", "spin-down", {"sigma": "u"}, "line 2: expected an uncertainty greater than 0 in column 'u'"),
    ("t (s),omega (rad/s)\n-1,1\n", "spin-down", {}, "line 2: column 't (s)' (--time) expected a time of zero or more"),
    ("amplitude (deg),period (s)\n10,2.01\n40,2.07\n", "pendulum", {},  # amplitude is a pendulum result too
     "y: says which column was measured: 'amplitude (deg)', 'period (s)' are each named like a result"),
    ("amplitude (deg),period (s)\n10,2.01\n40,2.07\n", "pendulum", {"y": "period"},
     "x is needed: every sample is the same run of pendulum (no column gives an input that differs between them), and 'amplitude (deg)' "
     "differs between them but is not used; say which input it is: x 'amplitude (deg)=OPTION'"),
    ("amplitude (deg),period (s)\n10,2.01\n40,2.07\n", "pendulum", {"x": ("amplitude",)},
     "x: reads column 'amplitude (deg)' as time (--x COLUMN alone is the time), and its unit deg is not a time; "
     "say which input it is: x 'amplitude (deg)=OPTION'"),
    ("t (s),omega (rad/s)\n0,1\n", "spin-down", {"y": "t (s)=omega"},
     "y: reads column 't (s)' as the result omega, and its unit s is not an angular velocity; say which result it is: y 't (s)=RESULT'"),
])  # fmt: skip
def test_a_column_that_cannot_be_matched_is_refused(text, scene, options, said):
    with pytest.raises(InputError) as caught:
        build(text, scene, **options)
    assert said in str(caught.value)


def test_repeated_runs_of_one_scene_are_fitted_and_a_column_not_used_beside_them_only_noted():
    """Three stopwatch times of one run are samples of one run (nothing varies): fitted as such.
    A column that does not vary and is not used (the run's number) is a note, not a refusal."""
    found = build("run,t (s)\n1,4.06\n1,4.03\n1,3.88\n", "atwood")
    assert found.count == 3 and found.varying == []
    assert found.notes == ["columns not used: 'run' (neither an input of atwood nor the result measured)"]


def test_range_and_every_count_what_they_leave_out():
    text = "t (s),omega (rad/s)\n" + "".join(f"{t},{30 - t}\n" for t in range(20))
    found = build(text, "spin-down", ranges=("t=2s..11s",), every="3")
    assert found.inputs["time"] == [2.0, 5.0, 8.0, 11.0]
    assert (found.outside, found.thinned, found.dropped) == (10, 6, 16)
    assert build(text, "spin-down", ranges=("omega=..15rad/s",)).count == 5
    assert build(text, "spin-down", sigma="0.1rad/s").sigma == [0.1] * 20


def test_no_cap_on_the_samples_below_the_readers_own():
    """#45 item 3: 5,000 samples was the most a fit took (each a solve of the scene); every row the
    reader reads is a sample now (the time a fit takes is bounded by taucli.fit.budget)."""
    text = "t (s),omega (rad/s)\n" + "".join(f"{t},{t}\n" for t in range(20_005))
    found = build(text, "spin-down")
    assert found.count == 20_005 and found.inputs["time"][-1] == 20_004.0
