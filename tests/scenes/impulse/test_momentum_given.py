"""#46 item 2 (and #48 item 6): angular momentum and impulse given as such, --momentum0, --momentum1, --impulse.

L₀ = Iω₀, L₁ = Iω₁, J = L₁ − L₀ = τΔt: a book's "L from 2.4 to 3.6 kg·m²/s in 4 s" needs no I or ω.
References: tests/references/momentum.py (from these equations alone, at 50 digits).
"""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli as api
from conftest import assert_usage_error
from references import DPS, mp, mpf, relative_error
from references.momentum import momentum

CLOSED = 1e-13
BOOK = ("--momentum0", "2.4kg*m^2/s", "--momentum1", "3.6kg*m^2/s")


def test_the_published_disc_torque_from_the_change_of_angular_momentum(taucli):
    """A spinning disc's L rises from 2.4 to 3.6 kg·m²/s in 4.0 s under a constant torque: τ = 0.30 N·m."""
    run = taucli("impulse", *BOOK, "--duration", "4s", "--json")
    assert run.code == 0, run.err
    results = run.json()["results"]
    assert results["torque"]["value"] == pytest.approx(0.30, rel=1e-14)
    assert results["J"]["value"] == pytest.approx(1.2, rel=1e-14)
    assert results["inertia"]["value"] is None and results["omega0"]["value"] is None  # nothing assumed of the body


def test_each_surface_gives_the_same_answer(taucli):
    """Command line, batch (the option names as keys) and Python."""
    single = taucli("impulse", *BOOK, "--torque", "0.3N*m", "--inertia", "0.2kg*m^2", "--json").json()["results"]
    line = {"momentum0": "2.4kg*m^2/s", "momentum1": "3.6kg*m^2/s", "torque": "0.3N*m", "inertia": "0.2kg*m^2"}
    batch = taucli("impulse", "--batch", stdin=json.dumps(line) + "\n")
    assert batch.code == 0, batch.err
    document = json.loads(batch.out.splitlines()[0])["results"]
    report = api.impulse(**line)
    for name, want in (("duration", 4.0), ("omega0", 12.0), ("omega1", 18.0), ("J", 1.2), ("KE0", 14.4), ("KE1", 32.4), ("work", 18.0)):
        assert single[name]["value"] == pytest.approx(want, rel=1e-13), name
        assert document[name]["value"] == pytest.approx(want, rel=1e-13), name
        assert report.results[name].value == pytest.approx(want, rel=1e-13), name


def test_an_impulse_given_as_such_on_a_body_at_rest(taucli):
    """#48 item 6: a torque–time graph's area, 1.80 N·m·s, on a body of 0.5 kg·m² at rest: ω₁ = J/I = 3.6 rad/s."""
    run = taucli("impulse", "--impulse", "1.80N*m*s", "--inertia", "0.5kg*m^2", "--json")
    assert run.code == 0, run.err
    document = run.json()
    assert document["results"]["omega1"]["value"] == pytest.approx(3.6, rel=1e-14)
    assert document["results"]["L1"]["value"] == pytest.approx(1.8, rel=1e-14)
    assert any("starts at rest" in note for note in document["notes"])


@pytest.mark.parametrize("args, named", [
    (("--momentum0", "2.4kg*m^2/s", "--inertia", "0.2kg*m^2", "--omega0", "10rad/s", "--momentum1", "3.6kg*m^2/s", "--duration", "4s"),
     ("--momentum0", "--inertia", "--omega0")),
    ((*BOOK, "--impulse", "1N*m*s"), ("--momentum0", "--momentum1", "--impulse")),
    ((*BOOK, "--torque", "0.3N*m", "--duration", "5s"), ("--momentum0", "--momentum1", "--torque", "--duration")),
    ((*BOOK, "--torque", "0"), ("--torque",)),
    (("--momentum0", "2.4kg*m^2/s", "--omega0", "0rad/s"), ("--momentum0", "--omega0")),
])
def test_givens_that_disagree_are_refused_naming_them(taucli, args, named):
    assert_usage_error(taucli("impulse", *args), "disagree", *named)


@pytest.mark.parametrize("args, fragment", [
    (("--momentum0", "2.4kg*m^2/s"), "--momentum0"),
    ((*BOOK, "--torque", "-0.3N*m"), "--torque"),
    ((*BOOK, "--duration", "4s", "--inertia-final", "1kg*m^2"), "--inertia-final"),
    ((*BOOK, "--duration", "4s", "--particle", "mass=1kg radius=1m speed=1m/s"), "--particle"),
    (("--momentum0", "2.4kg*m/s", "--momentum1", "3kg*m^2/s", "--duration", "1s"), "--momentum0"),
])
def test_what_cannot_be_answered_is_refused(taucli, args, fragment):
    assert_usage_error(taucli("impulse", *args), fragment)


# -- random scenes against the reference -----------------------------------------------------------

PATTERNS = (  # what a book gives: each pattern's givens fix the rest that they can, with no redundancy
    ("L0", "L1", "duration"), ("L0", "L1", "torque"), ("L0", "L1", "duration", "inertia"), ("L0", "torque", "duration"),
    ("L1", "torque", "duration"), ("L0", "J"), ("J", "inertia"), ("J", "inertia", "omega0"), ("J", "duration"),
    ("L0", "omega0", "torque", "duration"), ("L0", "L1", "inertia"), ("J", "omega0", "omega1"), ("L0", "J", "inertia", "duration"),
    ("L1", "J", "torque"), ("L1", "omega1", "J"),
)
KEYS = {"L0": "momentum0", "L1": "momentum1", "J": "impulse"}
NAMES = ("L0", "L1", "J", "torque", "duration", "inertia", "omega0", "omega1", "delta_omega", "KE0", "KE1", "work")


@settings(max_examples=300, deadline=None)
@given(pattern=st.sampled_from(PATTERNS), inertia=st.floats(1e-4, 1e4), omega0=st.floats(-1e3, 1e3).filter(lambda x: x == 0 or abs(x) > 1e-6),
       torque=st.floats(-1e4, 1e4).filter(lambda x: abs(x) > 1e-6), duration=st.floats(1e-4, 1e2))
def test_random_scenes_agree_with_the_reference(pattern, inertia, omega0, torque, duration):
    """A body (I, ω₀) under τ for Δt; taucli is given only the pattern's quantities (floats, read exactly)
    and each result it gives is checked against the 50-digit reference of the same givens."""
    scene = {"inertia": inertia, "omega0": omega0, "torque": torque, "duration": duration}
    scene.update(L0=inertia * omega0, J=torque * duration)
    scene["omega1"] = omega0 + scene["J"] / inertia
    scene["L1"] = inertia * scene["omega1"]
    givens = {name: scene[name] for name in pattern}
    if pattern == ("J", "omega0", "omega1") and givens["omega0"] == givens["omega1"]:
        return
    if "inertia" in givens and not {"L0", "L1", "omega0", "omega1"} & set(givens):
        givens["omega0"] = 0.0  # as documented: a body given an impulse and no state starts at rest
    kw = {KEYS.get(name, name): (f"{value!r} rad/s" if name.startswith("omega") else value) for name, value in givens.items()}
    report = api.impulse(**kw)
    exact = momentum(**givens)
    cond = _condition(exact)
    for name in NAMES:
        got = report.results[name].value if name in report.results else None
        want = exact.get(name)
        if want is None:
            assert got is None, (name, got, kw)
            continue
        assert got is not None, (name, kw)
        with mp.workdps(DPS):
            error = relative_error(got, want) if want != 0 else abs(float(mpf(got)))
        assert error <= CLOSED * cond, (name, got, want, error, kw)
    # the balances: J = τΔt = L₁ − L₀, and the torque's work is the change of kinetic energy
    res = {name: report.results[name].value for name in NAMES if name in report.results}
    if res.get("KE0") is not None and res.get("KE1") is not None and res.get("work") is not None:
        assert res["KE1"] - res["KE0"] == pytest.approx(res["work"], rel=1e-9, abs=1e-9 * max(res["KE0"], res["KE1"]))
    if None not in (res.get("torque"), res.get("duration"), res.get("J")):
        assert res["J"] == pytest.approx(res["torque"] * res["duration"], rel=1e-12 * cond)


def _condition(exact) -> float:
    """The largest |terms|/|sum| of the differences the quantities are made of (L₁ − L₀, ω₀ + J/I, ω₀ + ω₁)."""
    with mp.workdps(DPS):
        worst = mpf(1)
        pairs = [("L0", "J", "L1"), ("L1", "J", "L0"), ("L0", "L1", "J"), ("omega0", "delta_omega", "omega1"), ("omega1", "delta_omega", "omega0"),
                 ("omega0", "omega1", "delta_omega")]
        for a, b, total in pairs:
            if None not in (exact.get(a), exact.get(b), exact.get(total)) and exact[total] != 0:
                worst = max(worst, (abs(exact[a]) + abs(exact[b])) / abs(exact[total]))
        if None not in (exact.get("omega0"), exact.get("omega1")) and exact["omega0"] + exact["omega1"] != 0:
            worst = max(worst, (abs(exact["omega0"]) + abs(exact["omega1"])) / abs(exact["omega0"] + exact["omega1"]))
        return float(worst)
