"""#42 item 21: --torque-profile reads every header and separator taucli fit reads."""

from __future__ import annotations

import pytest

from taucli.answering.profile import read_profile
from taucli.fit import data

HEADERS = [
    ("t [ms],torque [N*m]", ",", 1e-3, 1.0),
    ("time (s),torque (N m)", ",", 1.0, 1.0),
    ("Time (ms)\tTorque (N*m)", "\t", 1e-3, 1.0),
    ("t (s);torque (kN*m)", ";", 1.0, 1e3),
    ('"time (s)","torque (N*m)"', ",", 1.0, 1.0),
    ('"t [ms]";"torque [N*cm]"', ";", 1e-3, 1e-2),
]


@pytest.mark.parametrize("header, separator, time_factor, torque_factor", HEADERS)
def test_a_profile_takes_the_headers_and_separators_fit_takes(header, separator, time_factor, torque_factor, tmp_path):
    text = f"{header}\n0{separator}1\n2{separator}3\n"
    profile = read_profile(text.splitlines(keepends=True))
    assert list(profile.samples) == [(0.0, 1.0 * torque_factor), (2 * time_factor, 3 * torque_factor)]
    path = tmp_path / "data.csv"
    path.write_text(text)
    table = data.read(str(path))  # fit reads the same file, to the same names and units
    assert table.delimiter == separator and [column.values for column in table.columns] == [(0.0, 2.0), (1.0, 3.0)]


def test_a_header_without_units_is_si_with_a_note():
    profile = read_profile(["time,torque\n", "0,1\n", "1,2\n"])
    assert list(profile.samples) == [(0.0, 1.0), (1.0, 2.0)]
    assert any("no unit for the time column" in note and "read as SI (s)" in note for note in profile.notes)
    assert any("no unit for the torque column" in note for note in profile.notes)
