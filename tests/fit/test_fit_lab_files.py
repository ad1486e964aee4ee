"""The files labs have (#44 item 10): Excel's trailing empty columns, a row of units under the
header, UTF-16 text, a decimal-comma file whose numbers all have three decimals, an .xlsx
workbook and phyphox's zip export read directly; a file that is refused says what it is."""

from __future__ import annotations

import io
import zipfile

import pytest

from taucli.core.errors import InputError
from taucli.fit import data

from conftest import run_taucli

ROWS = [(0.0, 12.5), (1.0, 11.25), (2.0, 10.0)]


def table(text: str) -> data.DataTable:
    return data.read("-", io.StringIO(text))


def values(found: data.DataTable) -> dict[str, list[float]]:
    return {(column.name, column.unit): list(column.values) for column in found.columns}


EXPECTED = {("t", "s"): [0.0, 1.0, 2.0], ("omega", "rad/s"): [12.5, 11.25, 10.0]}


@pytest.mark.parametrize("text", [
    "t (s),omega (rad/s),,\n" + "".join(f"{t},{w},,\n" for t, w in ROWS),  # Excel's trailing empty columns
    "t (s);omega (rad/s);;;\n" + "".join(f"{t};{w};\n" for t, w in ROWS),  # (fewer separators on some rows)
    "t,omega\ns,rad/s\n" + "".join(f"{t},{w}\n" for t, w in ROWS),  # a row of units under the header
    "t\tomega\n(s)\t[rad/s]\n" + "".join(f"{t}\t{w}\n" for t, w in ROWS),
    "t (s);omega (rad/s)\n" + "".join(f"{t:.3f};{w:.3f}\n".replace(".", ",") for t, w in ROWS),  # 0,000;12,500: decimal, by the whole file
    "t (s);omega (rad/s)\n1,000;12,500\n1234,000;11,250\n".replace("1,000;12,500\n1234,000;11,250", "0,000;12,500\n1,000;11,250\n2,000;10,000"),
])  # fmt: skip
def test_the_tables_spreadsheets_and_loggers_write_are_read(text):
    assert values(table(text)) == EXPECTED


def test_a_decimal_comma_is_decided_by_the_whole_file_not_one_cell():
    # 1234,500 cannot group thousands (four digits before the comma): every comma of the file is a decimal one
    assert values(table("t (s);m (kg)\n1,500;1234,500\n2,250;2,000\n"))[("m", "kg")] == [1234.5, 2.0]
    with pytest.raises(InputError, match="could be a thousands separator"):
        table("t (s);m (kg)\n1,500;1,500\n2,250;12,000\n")  # every comma could group thousands: refused, not guessed


def test_a_cell_under_a_trailing_empty_column_is_refused_naming_it():
    with pytest.raises(InputError, match="a cell under no column's name: '7'") as caught:
        table("t (s),omega (rad/s),,\n0,1,,\n1,2,7,\n")
    assert "line 3" in str(caught.value)


def test_a_unit_in_the_header_and_another_below_is_refused():
    with pytest.raises(InputError, match="has the unit s in its header and ms in the row of units"):
        table("t (s),omega\nms,rad/s\n0,1\n")


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-le", "utf-16-be"])
def test_utf16_text_with_or_without_a_bom_is_read_degrees_too(tmp_path, encoding):
    path = tmp_path / "unicode.txt"
    path.write_bytes("Zeit (s)\tWinkel (°)\tω (rad/s)\n0\t1,5\t2\n1\t2,5\t3\n".encode(encoding))
    found = data.read(str(path))
    assert [column.unit for column in found.columns] == ["s", "°", "rad/s"] and list(found.columns[1].values) == [1.5, 2.5]


def workbook(path, rows, sheets=()) -> None:
    openpyxl = pytest.importorskip("openpyxl")
    book = openpyxl.Workbook()
    for row in rows:
        book.active.append(row)
    for title in sheets:
        book.create_sheet(title).append(["x", 1])
    book.save(path)


def test_an_xlsx_workbook_is_read_directly(tmp_path):
    path = tmp_path / "coast.xlsx"
    workbook(path, [["t (s)", "omega (rad/s)", None], *([t, w] for t, w in ROWS), [3.0, None]], sheets=["Metadata Device"])
    found = data.read(str(path))
    assert values(found)[("t", "s")] == [0.0, 1.0, 2.0, 3.0] and values(found)[("omega", "rad/s")][:3] == [12.5, 11.25, 10.0]
    assert list(found.lines) == [2, 3, 4, 5]


def test_a_workbook_with_data_on_two_sheets_is_refused_naming_them(tmp_path):
    path = tmp_path / "two.xlsx"
    workbook(path, [["t (s)", "omega (rad/s)"], [0, 1]], sheets=["Run 2"])
    with pytest.raises(InputError, match="data on 2 sheets .'Sheet', 'Run 2'.: fit reads one"):
        data.read(str(path))


def phyphox_zip(path, members: dict[str, str]) -> None:
    with zipfile.ZipFile(path, "w") as archive:
        for name, text in members.items():
            archive.writestr(name, text)


def test_phyphox_zip_export_is_read_directly_its_meta_folder_aside(tmp_path):
    path = tmp_path / "Gyroscope 2026-11-29.zip"
    csv = '"Time (s)","Gyroscope z (rad/s)"\n' + "".join(f"{t:.9E},{w:.9E}\n" for t, w in ROWS)
    phyphox_zip(path, {"Raw Data.csv": csv, "meta/device.csv": '"property","value"\n"model","x"\n', "meta/time.csv": "a,b\n"})
    found = data.read(str(path))
    assert list(found.column("Gyroscope z (rad/s)").values) == [12.5, 11.25, 10.0]


def test_a_zip_of_several_tables_names_them_and_the_command_that_gives_one(tmp_path):
    path = tmp_path / "export.zip"
    phyphox_zip(path, {"Accelerometer.csv": "t,a\n0,1\n", "Gyroscope.csv": "t,w\n0,1\n"})
    with pytest.raises(InputError) as caught:
        data.read(str(path))
    said = str(caught.value)
    assert "'Accelerometer.csv', 'Gyroscope.csv'" in said and "unzip -p" in said and "Accelerometer.csv | taucli fit SCENE -" in said


@pytest.mark.parametrize("head,said", [
    (b"PK\x03\x04" + b"\x00" * 40, "is a zip archive"),
    (b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1" + b"\x00" * 40, "is an old Excel workbook (.xls), not a text table; save it as .xlsx or CSV"),
    (b"%PDF-1.7\n\x00\x00", "is a PDF document"),
    (b"\x89PNG\r\n\x1a\n\x00\x00", "is a PNG image"),
])  # fmt: skip
def test_a_refused_file_says_what_it_is_and_what_to_do(head, said):
    with pytest.raises(InputError) as caught:
        data.read("-", io.BytesIO(head))
    assert said in str(caught.value) and "binary file?" not in str(caught.value)


def test_a_phyphox_state_file_is_refused_as_what_it_is(tmp_path):
    path = tmp_path / "state.phyphox"
    path.write_text('<?xml version="1.0" encoding="UTF-8"?>\n<phyphox version="1.14">\n</phyphox>\n')
    with pytest.raises(InputError, match="is XML or HTML .a phyphox experiment"):
        data.read(str(path))


def test_the_command_line_fits_a_workbook_and_a_phyphox_zip(tmp_path):
    import math

    rows = [(0.5 * i, 30.0 - 0.6 * 0.5 * i) for i in range(12)]  # friction 0.06 N·m on 0.1 kg·m²: α = −0.6 rad/s²
    book = tmp_path / "coast.xlsx"
    workbook(book, [["Time (s)", "omega (rad/s)", None], *([t, w] for t, w in rows)])
    archive = tmp_path / "coast.zip"
    phyphox_zip(archive, {"Raw Data.csv": "Time (s),omega (rad/s)\n" + "".join(f"{t},{w}\n" for t, w in rows)})
    for path in (book, archive):
        result = run_taucli("fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--get", "friction")
        assert result.code == 0, result.err
        assert math.isclose(float(result.out), 0.06, rel_tol=1e-9)


def test_an_ods_and_a_workbook_without_openpyxl_say_what_to_do(tmp_path, monkeypatch):
    ods = tmp_path / "sheet.ods"
    phyphox_zip(ods, {"mimetype": "application/vnd.oasis.opendocument.spreadsheet", "content.xml": "<office:document-content/>"})
    with pytest.raises(InputError, match=r"is an OpenDocument file .*save the sheet as .xlsx or CSV"):
        data.read(str(ods))
    book = tmp_path / "coast.xlsx"
    workbook(book, [["t (s)", "omega (rad/s)"], [0, 1]])
    monkeypatch.setitem(__import__("sys").modules, "openpyxl", None)  # not installed
    with pytest.raises(InputError, match=r"is an Excel workbook \(.xlsx\), and reading one needs openpyxl; pip install 'taucli\[fit\]'"):
        data.read(str(book))
