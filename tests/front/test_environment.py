"""Odd environments (issue #9): terminals without colour or width, homes and caches that cannot be
written, a decimal-comma locale, a reader that leaves early, Ctrl-C, and stdin for --batch that
is closed or a terminal. Every run goes through the real entry point in a subprocess.
"""

from __future__ import annotations

import json
import os
import pty
import select
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import run_taucli

ANSI = "\x1b["
ONE_OF_EACH = [
    ("inertia", "disc", "--mass", "5kg", "--radius", "0.2m"),
    ("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "30rad/s", "--friction", "0.3N*m", "--plot"),
    ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m"),
    ("rolling", "sphere", "--angle", "30deg", "--length", "2m", "--plot"),
    ("impulse", "--inertia", "0.1kg*m^2", "--omega0", "0", "--torque", "2N*m", "--duration", "0.5s"),
    ("atwood", "--m1", "1..4kg", "--m2", "1kg", "--points", "5"),  # a sweep: table and chart
]


@pytest.mark.parametrize("env", [{"NO_COLOR": "1"}, {"TERM": "dumb"}, {"COLUMNS": "20"}, {}], ids=["NO_COLOR", "TERM=dumb", "COLUMNS=20", "a pipe"])
@pytest.mark.parametrize("args", ONE_OF_EACH, ids=lambda args: " ".join(args[:2]))
def test_plain_text_in_terminals_without_colour_or_width(env, args):
    result = run_taucli(*args, env=env)
    assert result.code == 0, result.err
    assert ANSI not in result.out and ANSI not in result.err
    assert result.out.strip()


def test_a_narrow_terminal_lists_the_results_whole():
    """At 20 columns a table would cut numbers to '…'; each result gets a line of its own instead."""
    result = run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--g", "9.8", "--no-steps", env={"COLUMNS": "20"})
    assert "…" not in result.out
    lines = result.out.splitlines()
    assert "a = 4.9 m/s²" in lines  # (4 − 1) 9.8 / (4 + 1 + 2/2)
    assert "T1 = 19.6 N" in lines  # 4 (9.8 − 4.9)
    assert max(len(line.rstrip()) for line in lines) <= 20
    sweep = run_taucli("atwood", "--m1", "1..4kg", "--m2", "1kg", "--g", "9.8", "--points", "4", env={"COLUMNS": "30"})
    assert sweep.code == 0 and "…" not in sweep.out  # a narrow sweep table folds its cells, it does not cut them


REFERENCE = ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--g", "9.8", "--get", "a")


@pytest.mark.parametrize(
    "env",
    [
        {"HOME": None, "XDG_CACHE_HOME": None, "TAUCLI_CACHE_DIR": None},  # no home at all
        {"HOME": "/proc", "XDG_CACHE_HOME": None, "TAUCLI_CACHE_DIR": None},  # a home nothing can be made in
        {"HOME": "/nowhere/at/all", "XDG_CACHE_HOME": None, "TAUCLI_CACHE_DIR": None},  # a home that does not exist
        {"XDG_CACHE_HOME": "/proc/cache", "TAUCLI_CACHE_DIR": None},
        {"TAUCLI_CACHE_DIR": "/proc/taucli"},  # read-only
        {"TAUCLI_CACHE_DIR": "/dev/null"},  # a file, not a folder
    ],
    ids=["no HOME", "read-only HOME", "missing HOME", "read-only XDG cache", "read-only cache", "cache is a file"],
)
def test_homes_and_caches_that_cannot_be_written_still_give_the_answer(env):
    full = {key: value for key, value in os.environ.items() if env.get(key, value) is not None}
    full.update({key: value for key, value in env.items() if value is not None})
    for attempt in range(2):  # the second run would read what the first kept
        done = subprocess.run([sys.executable, "-m", "taucli", *REFERENCE], capture_output=True, text=True, env=full, timeout=60)
        assert done.returncode == 0 and done.stderr == "", done.stderr
        assert float(done.stdout) == pytest.approx(3 * 9.8 / 6, rel=1e-15)


@pytest.fixture(scope="module")
def decimal_comma_locale(tmp_path_factory) -> dict[str, str]:
    """de_DE.UTF-8 compiled into a temporary LOCPATH (no root needed); its decimal point is ','."""
    if shutil.which("localedef") is None or not Path("/usr/share/i18n/locales/de_DE").exists():
        if os.environ.get("CI"):
            pytest.fail("localedef and Debian's locales package are needed (.ci/run installs them)")
        pytest.skip("no localedef or locale sources here")
    folder = tmp_path_factory.mktemp("locale")
    subprocess.run(["localedef", "-i", "de_DE", "-f", "UTF-8", str(folder / "de_DE.UTF-8")], check=True, capture_output=True)
    env = {"LOCPATH": str(folder), "LC_ALL": "de_DE.UTF-8", "LANG": "de_DE.UTF-8"}
    probe = subprocess.run(
        [sys.executable, "-c", "import locale; locale.setlocale(locale.LC_ALL, ''); print(locale.localeconv()['decimal_point'])"],
        capture_output=True, text=True, env={**os.environ, **env},
    )
    assert probe.stdout.strip() == ",", probe  # the locale is real: a program that asked for it would write 3,5
    return env


@pytest.mark.parametrize(
    "args",
    [
        ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m"),
        ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--json"),
        ("spin-down", "--inertia", "0.5..4kg*m^2", "--torque", "3N*m,6N*m", "--points", "4"),
        ("rolling", "sphere", "--angle", "30deg", "--length", "2m", "--plot", "--no-steps"),
        ("impulse", "--inertia", "0.1", "--omega0", "0", "--torque", "2", "--duration", "0.5", "--get", "omega1"),
    ],
    ids=lambda args: " ".join(args[:3]),
)
def test_a_decimal_comma_locale_changes_nothing(decimal_comma_locale, args):
    plain = run_taucli(*args, env={"LC_ALL": "C.UTF-8", "COLUMNS": "80"})
    comma = run_taucli(*args, env={**decimal_comma_locale, "COLUMNS": "80"})
    assert plain.code == comma.code == 0, comma.err
    assert comma.out == plain.out and comma.err == plain.err == ""


def test_input_numbers_are_read_with_a_point_under_a_decimal_comma_locale(decimal_comma_locale):
    comma = run_taucli("inertia", "disc", "--mass", "4,5kg", "--radius", "1m", "--get", "I", env=decimal_comma_locale)
    assert comma.code == 2 and "4.5" in comma.err  # refused, with the reading it might have meant
    assert float(run_taucli("inertia", "disc", "--mass", "4.5kg", "--radius", "1m", "--get", "I", env=decimal_comma_locale).out) == 2.25


@pytest.mark.parametrize(
    "args",
    [
        ("atwood", "--m1", "1..4kg", "--m2", "1kg", "--pulley-mass", "1kg", "--points", "200", "--json"),  # ~1 MB of JSON
        ("atwood", "--m1", "1..4kg", "--m2", "1kg", "--points", "200"),  # the human table and chart
        ("atwood", "--batch", "--no-steps"),
        ("--help",),  # the cached help, printed without typer
    ],
    ids=["json", "human", "batch", "help"],
)
def test_a_reader_that_leaves_early_gets_a_quiet_exit(args, tmp_path):
    """`taucli ... | head -c1`: no traceback, no 'Exception ignored', exit status 0."""
    stdin = "".join('{"m1": "%dkg", "m2": "1kg"}\n' % (1 + n % 9) for n in range(20000)) if "--batch" in args else ""
    (tmp_path / "in").write_text(stdin)
    script = f'"{sys.executable}" -m taucli "$@" < "{tmp_path / "in"}" 2> "{tmp_path / "err"}" | head -c1 > /dev/null; echo "${{PIPESTATUS[0]}}"'
    for attempt in range(2):  # the help is rendered by typer the first time, from the cache the second
        done = subprocess.run(["bash", "-c", script, "taucli", *args], capture_output=True, text=True, timeout=120)
        assert done.stdout.strip() == "0", ((tmp_path / "err").read_text(), done.stderr)
        assert (tmp_path / "err").read_text() == ""


def _start(*args: str, **kwargs) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "taucli", *args], text=True, **kwargs)


def test_ctrl_c_in_a_batch_exits_130_without_a_traceback():
    child = _start("atwood", "--batch", "--no-steps", stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    child.stdin.write('{"m1": "4kg", "m2": "1kg"}\n')
    child.stdin.flush()
    assert json.loads(child.stdout.readline())["results"]["a"]["value"] > 0  # it is in the loop, waiting for a line
    child.send_signal(signal.SIGINT)
    _, err = child.communicate(timeout=30)
    assert child.returncode == 130
    assert "Traceback" not in err and "KeyboardInterrupt" not in err


def test_ctrl_c_in_the_middle_of_a_long_batch_exits_130_without_a_traceback(tmp_path):
    """Nothing a single run may do takes a second; a batch of 200,000 scenes takes half a minute."""
    scenes = tmp_path / "scenes.jsonl"
    scenes.write_text('{"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg"}\n' * 200_000)
    with scenes.open() as source:
        child = _start("atwood", "--batch", "--no-steps", stdin=source, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        for _ in range(1000):  # a thousand answers in: it is busy solving, not starting
            child.stdout.readline()
        child.send_signal(signal.SIGINT)
        _, err = child.communicate(timeout=60)
    assert child.returncode == 130
    assert "Traceback" not in err and "KeyboardInterrupt" not in err


def test_batch_with_stdin_closed_is_refused_in_one_line():
    done = subprocess.run(
        [sys.executable, "-m", "taucli", "atwood", "--batch"], stdin=None, capture_output=True, text=True, timeout=60,
        preexec_fn=lambda: os.close(0),
    )
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.count("\n") == 1 and "stdin is closed" in done.stderr


def test_batch_reads_a_terminal_line_by_line_until_ctrl_d():
    """stdin a terminal: a prompt on stderr, and each line's answer as soon as the line is typed."""
    leader, follower = pty.openpty()
    child = _start("atwood", "--batch", "--no-steps", stdin=follower, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    os.close(follower)
    try:
        os.write(leader, b'{"m1": "4kg", "m2": "1kg", "g": 9.8}\n')
        ready, _, _ = select.select([child.stdout], [], [], 30)
        assert ready, "no answer to the first line while stdin stays open"
        first = json.loads(child.stdout.readline())
        assert first["results"]["a"]["value"] == pytest.approx(3 * 9.8 / 5, rel=1e-15)
        os.write(leader, b"\x04")  # Ctrl-D at the start of a line: end of input
        out, err = child.communicate(timeout=30)
    finally:
        os.close(leader)
    assert child.returncode == 0 and out == ""
    assert "Ctrl-D ends" in err


def test_batch_gives_one_line_per_input_line_in_order_even_when_lines_fail():
    """Blank lines aside (skipped, #16 item 18), one line out for each in, in order."""
    lines = ['{"m1": "%dkg", "m2": "1kg", "g": 10}' % n if n % 3 else ["  ", "{", '{"m1": "-1kg"}', "[1]", '{"m1": "4 furlong"}'][n % 5] for n in range(1, 301)]
    done = run_taucli("atwood", "--batch", "--no-steps", stdin="\n".join(lines) + "\n")
    documents = [json.loads(line) for line in done.out.splitlines()]
    numbered = [(number, line) for number, line in enumerate(lines, start=1) if line.strip()]
    assert len(documents) == len(numbered) == len(lines) - sum(not line.strip() for line in lines)
    for (number, line), document in zip(numbered, documents):
        if "error" in document:
            assert document["line"] == number
        else:
            m1 = json.loads(line)["m1"]
            assert document["inputs"]["m1"]["value"] == float(m1.removesuffix("kg"))
    assert done.code == 2


def test_an_internal_error_shows_a_traceback_only_with_debug(monkeypatch, capsys):
    from taucli.front import cli
    from taucli.scenes import atwood

    def broken(*args, **kwargs):
        raise RuntimeError("a planted bug")

    monkeypatch.setattr(atwood, "solve_machine", broken)
    monkeypatch.delenv("TAUCLI_DEBUG", raising=False)
    assert cli.main(["atwood", "--m1", "4kg"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "a planted bug" in err and "bug in taucli" in err and "Traceback" not in err
    assert cli.main(["--debug", "atwood", "--m1", "4kg"]) == 1
    err = capsys.readouterr().err
    assert "Traceback" in err and 'raise RuntimeError("a planted bug")' in err
    assert err.rstrip().splitlines()[-1].startswith("taucli: error: internal error (RuntimeError: a planted bug)")


@pytest.mark.parametrize("extra", [("--json",), (), ("--get", "a")])
def test_a_stdout_that_cannot_write_the_symbols_gets_utf8_not_a_crash(extra):
    """PYTHONIOENCODING=ascii made every answer exit 1 on ², ½ or α (UnicodeEncodeError)."""
    import json
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-m", "taucli", "atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", *extra],
                          capture_output=True, env={**__import__("os").environ, "PYTHONIOENCODING": "ascii"})
    assert done.returncode == 0, done.stderr
    text = done.stdout.decode("utf-8")
    if extra == ("--json",):
        assert json.loads(text)["results"]["a"]["value"] == pytest.approx(4.9 * 9.80665 / 9.8, rel=1e-12)
    elif not extra:
        assert "½" in text
