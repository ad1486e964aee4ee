"""#42 item 23: what a new user met in two hours, each small."""

from __future__ import annotations

import math
import re
import subprocess
from pathlib import Path

import pytest

from conftest import assert_usage_error, run_taucli

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]


@pytest.mark.parametrize("page", PAGES, ids=[page.name for page in PAGES])
def test_every_code_fence_of_the_docs_is_closed_before_the_next_opens(page):
    """A fence opened with a language (```console) inside an open block is a broken page: the
    spin-down page's --work example sat inside the band brake's block."""
    opened = None
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), start=1):
        if not line.startswith("```"):
            continue
        if opened is None:
            opened = number
        else:
            assert line.strip() == "```", f"{page.name}:{number}: {line!r} opens a block inside the one opened on line {opened}"
            opened = None
    assert opened is None, f"{page.name}: the block opened on line {opened} is never closed"


def test_a_drive_conflict_names_the_fix_and_the_fix_runs():
    base = ("drive", "--motor-inertia", "1e-4 kg*m^2", "--load-mass", "10kg", "--drum-radius", "0.1m", "--ratio", "10")
    refused = run_taucli(*base, "--distance", "1m", "--speed", "1m/s", "--accel-time", "0.5s")
    assert_usage_error(refused, "--distance conflicts with the top speed", "(e.g. --distance 1m --accel-time 0.5s)", "leave out one of them")
    fixed = run_taucli(*base, "--distance", "1m", "--accel-time", "0.5s", "--no-steps")
    assert fixed.code == 0 and fixed.out.startswith("drive:"), fixed


def test_bench_help_counts_its_scenes():
    from taucli.options.tools import BENCH_SCENES

    out = run_taucli("bench", "--help").out
    assert "default both" not in out and f"default all {len(BENCH_SCENES)}" in out


def test_fit_y_names_the_close_result_not_sixty(tmp_path):
    data = tmp_path / "spin.csv"
    data.write_text("t (s),omega (rad/s)\n0,30\n1,28\n2,26.1\n3,24\n")
    close = run_taucli("fit", "spin-down", str(data), "--inertia", "1", "--fit", "friction", "--y", "omega (rad/s)=omegga")
    assert_usage_error(close, "did you mean 'omega'?")
    assert "theta_stop" not in close.err
    far = run_taucli("fit", "spin-down", str(data), "--inertia", "1", "--fit", "friction", "--y", "omega (rad/s)=zzz")
    assert_usage_error(far, "in all: docs/spin-down.md")
    assert len(far.err) < 300, far.err


_SIGN = re.compile(r"(?<![\w.)\]\\])-(?=[\d.∞])")  # a hyphen written as a number's sign


@pytest.mark.parametrize("form", ["md", "html"])
def test_a_document_writes_one_minus_in_its_steps_and_labels(form):
    """--format md and html: steps and labels write −, as the human view does; only a result's value
    (a number a spreadsheet reads) keeps the ASCII sign."""
    run = run_taucli("spin-down", "--inertia", "2", "--omega0", "-30rad/s", "--friction", "1", "--until-angle", "-10rev", "--format", form)
    assert run.code == 0, run
    assert "θ = −62.8319 rad" in run.out
    for line in run.out.splitlines():
        text = re.sub(r"^\| [^|]+ \| -?[\d.e+-]+ \|", "", line) if form == "md" else re.sub(r"<td[^>]*>-?[\d.e+-]+</td>", "", line)
        assert not _SIGN.search(text), line


@pytest.mark.parametrize("flag", ["--to", "--want"])
def test_tab_completes_a_result_before_its_equals_sign(flag):
    """--to and --want take RESULT=...: TAB offers the results, each with its "=" (bash)."""
    script = ROOT / "completions" / "taucli.bash"
    completed = subprocess.run(
        ["bash", "-c", f'source "{script}"; COMP_WORDS=(taucli atwood {flag} T); COMP_CWORD=3; _taucli 2>/dev/null; echo "${{COMPREPLY[@]}}"'],
        capture_output=True, text=True, timeout=30,
    )
    assert completed.stdout.split() == ["T1=", "T2="], completed


def test_a_spin_up_gives_its_revolutions_until_the_target():
    run = run_taucli("spin-down", "--inertia", "2", "--omega0", "0", "--torque", "4", "--until-omega", "100rad/s", "--json")
    results = run.json()["results"]
    assert results["revs_until"]["unit"] == "rev" and results["revs_until"]["label"] == "revolutions until ω = 100 rad/s"
    assert results["revs_until"]["value"] * 2 * math.pi == pytest.approx(results["theta_until"]["value"], rel=1e-15)


def test_get_says_the_notes_about_an_option_given():
    """--get prints bare numbers; a note that an option given plays no part (or looks wrong) goes to
    stderr beside them, as the human view says it: a script must not take the number as using it."""
    from conftest import run_taucli
    ran = run_taucli("atwood", "--m1", "100kg", "--m2", "40kg", "--g", "10", "--side1", "table", "--mu-k", "0.2", "--get", "a")
    assert ran.code == 0 and "--mu-k and --mu-s play no part" in ran.err, ran.err
    quiet = run_taucli("atwood", "--m1", "100kg", "--m2", "40kg", "--g", "10", "--get", "a")
    assert quiet.code == 0 and quiet.err == "", quiet.err


@pytest.mark.parametrize("args", [
    ("drive", "--segment", "time=10s", "power=100kW"),
    ("spin-down", "--inertia", "1kg*m^2", "--phase", "alpha=2rad/s^2", "time=5s"),
    ("balance", "--mass", "mass=10kg", "radius=0.1m", "angle=30deg"),
    ("atwood", "--m1", "4kg", "--pull", "force=20N", "angle=30deg"),
])
def test_a_spec_split_by_the_shell_is_offered_only_in_quotes(args):
    """key=value words of a spec left unquoted: the fix offered is the quoted spec, never the keys run together."""
    from conftest import assert_usage_error, run_taucli
    ran = run_taucli(*args)
    assert_usage_error(ran, "in quotes")
    assert "without spaces" not in ran.err, ran.err
