"""Hostile input stays bounded and answered (#33): batch lines of any length, echoes of any size,
odd JSON shapes, profile values out of bounds, bytes that are not UTF-8."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from conftest import assert_usage_error, strict_json

GOOD = '{"m1": "4kg", "m2": "1kg"}'


def _batch(stdin: bytes | str, *args: str) -> tuple[int, list[dict], str]:
    data = stdin.encode("utf-8", "surrogateescape") if isinstance(stdin, str) else stdin
    done = subprocess.run([sys.executable, "-m", "taucli", "atwood", "--batch", "--no-steps", *args], input=data, capture_output=True, timeout=60)
    text = done.stdout.decode("utf-8")  # strict: every line out is UTF-8
    return done.returncode, [strict_json(line) for line in text.splitlines()], done.stderr.decode("utf-8")


def test_a_batch_line_longer_than_a_mebibyte_gives_an_error_object_and_the_run_goes_on():
    long_line = '{"m1": "' + "4" * (1 << 20) + 'kg"}'
    code, out, err = _batch(f"{GOOD}\n{long_line}\n{GOOD}\n")
    assert code == 2 and "1 of 3 lines failed (the first: line 2)" in err
    assert [doc.get("line") for doc in out] == [None, 2, None]
    message = out[1]["error"]["message"]
    assert "at most 1,048,576 characters" in message and len(message) < 300
    assert out[2]["results"]["a"]["value"] == pytest.approx(3 * 9.80665 / 5, rel=1e-15)


def test_a_line_just_under_the_cap_is_read():
    padded = '{"m1": "4kg", "m2": "1kg"' + " " * ((1 << 20) - len(GOOD)) + "}"
    assert len(padded) == 1 << 20
    code, out, _ = _batch(padded + "\n")
    assert code == 0 and out[0]["results"]["a"]["value"] == pytest.approx(3 * 9.80665 / 5, rel=1e-15)


def test_endless_input_with_no_line_end_keeps_memory_flat():
    """/dev/zero: the error object comes out at once, and memory stays flat (it grew by 330 MB/s)."""
    script = (
        "import resource, subprocess, sys, time\n"
        "child = subprocess.Popen([sys.executable, '-m', 'taucli', 'atwood', '--batch'], stdin=open('/dev/zero', 'rb'), stdout=subprocess.PIPE)\n"
        "first = child.stdout.readline()\n"
        "time.sleep(2)\n"
        "child.kill(); child.wait()\n"
        "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
        "sys.stdout.write(first.decode())\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    peak_kb, first = done.stdout.split("\n", 1)
    assert int(peak_kb) < 150_000, peak_kb
    assert "at most 1,048,576 characters" in json.loads(first)["error"]["message"]


def test_an_error_quotes_at_most_about_80_characters_of_what_was_typed(taucli):
    huge = "4" * 100_000
    for args in (["--m1", huge + "kg"], ["--m1", "x" + huge], ["--m1", "4kg", "--to", "a=" + huge], ["--m1", "4kg", "--get", "a" + huge],
                 ["--m1", "4kg", "--pull", huge + "=4"], ["--m1", "4kg", "--" + huge]):
        done = taucli("atwood", "--m2", "1kg", *args)
        assert_usage_error(done)
        assert len(done.err) < 400, (args[-1][:10], done.err)
        assert max(len(word) for word in done.err.split()) <= 90
    code, out, _ = _batch(f'{{"m1": "{huge}", "{huge}": 1}}\n{{"m1": "{"4 " * 50_000}kg"}}\n')
    assert code == 2 and all(len(json.dumps(doc)) < 600 for doc in out), out


@pytest.mark.parametrize(
    "line",
    [
        "[" * 1000 + "]" * 1000,
        '{"a":' * 1000 + "1" + "}" * 1000,
        '{"m1": "4kg", "to": true}',
        '{"m1": "4kg", "to": 5}',
        '{"m1": "4kg", "to": [1]}',
        '{"m1": "4kg", "to": {}}',
        '{"m1": "4kg", "to": ["a=ft/s^2", null]}',
    ],
)
def test_odd_json_shapes_are_bad_input_not_bugs(line):
    code, out, err = _batch(line + "\n")
    assert code == 2, (out, err)
    assert "this is a bug" not in out[0]["error"]["message"]


def test_a_key_with_a_byte_that_is_not_utf8_is_escaped_in_the_error_object():
    code, out, _ = _batch(b'{"m\xff1": "4kg"}\n{"m1": "4k\xffg"}\n')  # _batch decodes the output strictly
    assert code == 2
    assert out[0]["error"]["option"] == "m\\xff1" and "m\\xff1 is not an option" in out[0]["error"]["message"]
    assert "4k" in out[1]["error"]["message"]


def test_a_profile_is_held_to_the_bounds_a_typed_value_is(tmp_path, taucli):
    cases = {
        "t [s], torque [N*m]\n0, 1e308\n1, 1e308\n": "torque of 0 or between 1e-40 and 1e40 N*m",
        "t [s], torque [N*m]\n0, 1\n1e-200, 2\n2e-200, 3\n": "time of 0 or between 1e-40 and 1e40 s",
        "t [s], torque [N*m]\n0, 1\n1e50, 2\n": "time of 0 or between 1e-40 and 1e40 s",
        "t [s], torque [N*m]\n1e-40, 1\n1.0000001e-40, 2\n": "time steps of at least 1e-40 s",
    }
    for number, (text, expected) in enumerate(cases.items()):
        path = tmp_path / f"p{number}.csv"
        path.write_text(text)
        for method in ("auto", "trapezoid"):
            done = taucli("impulse", "--inertia", "1kg*m^2", "--omega0", "0", "--torque-profile", str(path), "--method", method)
            assert_usage_error(done, "--torque-profile", expected)
    typed = taucli("impulse", "--inertia", "1kg*m^2", "--omega0", "0", "--torque", "1e308", "--duration", "1s")
    assert_usage_error(typed, "torque of 0 or between 1e-40 and 1e40 N*m")


def test_charts_and_tables_are_drawn_at_20_to_400_columns(taucli):
    """COLUMNS=100000 took 5 s and 434 MB for one chart (#33 item 2)."""
    args = ("atwood", "--m1", "4kg", "--m2", "1kg", "--distance", "1m", "--plot")
    wide = taucli(*args, env={"COLUMNS": "100000"})
    assert wide.code == 0 and max(len(line) for line in wide.out.splitlines()) == 400
    swept = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "1..3kg", "--points", "3", env={"COLUMNS": "10000000"})
    assert swept.code == 0 and max(len(line) for line in swept.out.splitlines()) <= 400
    narrow = taucli(*args, env={"COLUMNS": "5"})
    assert narrow.code == 0 and 20 <= max(len(line) for line in narrow.out.splitlines()) <= 40


CHART = ("atwood", "--m1", "4kg", "--m2", "1kg", "--distance", "1m", "--no-steps")


def test_out_refuses_a_link_and_a_name_with_no_stem(tmp_path, taucli):
    """#33 item 7: a dangling link was deleted and the chart written beside it; .svg wrote .svg.png."""
    link = tmp_path / "link.svg"
    link.symlink_to(tmp_path / "elsewhere.svg")
    done = taucli(*CHART, "--out", str(link))
    assert_usage_error(done, "--out: expected a file, not a symbolic link")
    assert link.is_symlink() and not (tmp_path / "elsewhere.svg").exists()
    for name in (".svg", ".png", str(tmp_path / ".svg")):
        assert_usage_error(taucli(*CHART, "--out", name), f"--out: expected a name before {name[-4:]}")
    assert sorted(path.name for path in tmp_path.iterdir()) == ["link.svg"]


def test_a_chart_that_cannot_be_written_is_refused_before_the_answer(tmp_path):
    """#33 item 6: a full disk (here a file size limit) after the answer printed it and exited 2.
    The file is written first, through a temporary file renamed onto it: the old one stays whole."""
    chart = tmp_path / "chart.svg"
    chart.write_text("the old chart")

    def small_files():
        import resource

        resource.setrlimit(resource.RLIMIT_FSIZE, (2000, 2000))

    done = subprocess.run([sys.executable, "-m", "taucli", *CHART, "--out", str(chart)], capture_output=True, text=True, preexec_fn=small_files,
                          env={**os.environ, "TAUCLI_CACHE_DIR": "", "PYTHONIOENCODING": "utf-8"}, timeout=120)
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.startswith("taucli: error: --out: expected a file that can be written") and len(done.stderr.splitlines()) == 1
    assert chart.read_text() == "the old chart" and sorted(path.name for path in tmp_path.iterdir()) == ["chart.svg"]
    written = subprocess.run([sys.executable, "-m", "taucli", *CHART, "--out", str(chart), "--get", "a"], capture_output=True, text=True, timeout=120)
    assert written.returncode == 0 and chart.read_text().lstrip().startswith("<?xml")
    assert sorted(path.name for path in tmp_path.iterdir()) == ["chart.svg"]


def test_digits_follow_one_rule_everywhere(tmp_path, taucli):
    """1_000 and fullwidth digits are refused in quantities; --mc, --points and the CSV reader took them."""
    assert_usage_error(taucli("atwood", "--m1", "1_000kg", "--m2", "1kg"), "--m1")
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "1..2kg", "--points", "５", "--get", "a"),
                       "--points: expected a whole number", "got '５'")
    assert_usage_error(taucli("atwood", "--m1", "4+/-0.1kg", "--m2", "1kg", "--mc", "1_000", "--get", "a"), "--mc: expected a whole number", "got '1_000'")
    profile = tmp_path / "p.csv"
    profile.write_text("t [s], torque [N*m]\n0, 1_0\n1, 1\n", encoding="utf-8")
    assert_usage_error(taucli("impulse", "--inertia", "1kg*m^2", "--omega0", "0", "--torque-profile", str(profile)), "line 2: expected numbers")


def test_an_angle0_just_past_180_deg_shows_the_digits_that_matter(taucli):
    done = taucli("pendulum", "--shape", "point", "--radius", "1m", "--mass", "1kg", "--angle0", "180.00000001deg")
    assert_usage_error(done, "expected an angle from −180 to 180 deg under gravity alone, got 180.00000001")


def test_rk4_blown_up_by_stiff_drag_says_it_went_unstable(taucli):
    """--drag 1e10 --drag-exponent 2.5 --method rk4 was refused as 'out of range' (an OverflowError
    in the stiffness, |ω|^1.5 past a double; the Python API raised it bare)."""
    args = ("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--drag", "1e10", "--drag-exponent", "2.5", "--method", "rk4", "--time", "1s")
    done = taucli(*args, "--no-steps")
    said = " ".join(done.out.split()).replace("\u2212", "-")  # the table's notes write one minus sign, U+2212 (#36)
    assert done.code == 0 and "rk4 went unstable" in said and "Use --dt below 3.5e-12 s" in said
    # stiffness at ω₀ = 10 rad/s: n k ω^(n−1)/I = 2.5e10 · 10^1.5; rk4's limit 2.785 over it
    assert 2.785 / (2.5e10 * 10**1.5) == pytest.approx(3.5e-12, rel=0.01)
    report = taucli_api().spin_down(inertia=1, omega0="10rad/s", drag=1e10, drag_exponent=2.5, method="rk4", time="1s")
    assert report.results["omega"].value is None


def taucli_api():
    import taucli

    return taucli
