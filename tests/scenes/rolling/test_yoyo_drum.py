"""#46 item 7 (first kind): a yo-yo whose string is wound at its top on a drum that turns on a
fixed axle. Irodov 1.258: two identical uniform solid cylinders, the lower hanging from two light
threads wound on both, the upper turning freely: each thread's tension is mg/10 (the two together
mg/5). Kleppner & Kolenkow 7.24 (two drums, equal masses and radii, a metal tape): the lower
drum's acceleration is 4g/5.

The reference is written from Newton's equations, not from the solver's closed forms: the four
unknowns (a, T, α, α_d) of

    m a + T = m g − F,   I α − r T = −F d,   I_d α_d − R T = −τ_f,   a − r α − R α_d = 0

solved by mpmath.lu_solve at 40 digits (the drum held, α_d = 0 and the last equation without it,
where the plain yo-yo's T R does not beat τ_f); the end state from rest by constant accelerations,
and the energy balance checked in mpmath.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli

G = 9.80665


def reference(m, I, r, Id, R, g, F=0.0, d=0.0, tau=0.0, t=None, h=None):
    """a, T, alpha, alpha_drum (and after t or h from rest: v, omega, omega_drum, the energies)
    from Newton's four equations, in mpmath."""
    with mpmath.workdps(40):
        m, I, r, Id, R, g, F, d, tau = (mpmath.mpf(x) for x in (m, I, r, Id, R, g, F, d, tau))
        held_a = mpmath.lu_solve(mpmath.matrix([[m, 1, 0], [0, -r, I], [1, 0, -r]]), mpmath.matrix([m * g - F, -F * d, 0]))
        if tau > 0 and held_a[1] * R <= tau:  # the drum's friction holds it
            a, T, alpha, alpha_d = held_a[0], held_a[1], held_a[2], mpmath.mpf(0)
        else:
            A = mpmath.matrix([[m, 1, 0, 0], [0, -r, I, 0], [0, -R, 0, Id], [1, 0, -r, -R]])
            a, T, alpha, alpha_d = mpmath.lu_solve(A, mpmath.matrix([m * g - F, -F * d, -tau, 0]))
        out = {"a": a, "T": T, "alpha": alpha, "alpha_drum": alpha_d}
        if t is None and h is not None:
            t = mpmath.sqrt(2 * mpmath.mpf(h) / a)
            out["t"] = t
        if t is not None:
            t = mpmath.mpf(t)
            x, v, w, wd = a * t * t / 2, a * t, alpha * t, alpha_d * t
            theta, theta_d = alpha * t * t / 2, alpha_d * t * t / 2
            out.update(v=v, omega=w, omega_drum=wd, KE_trans=m * v * v / 2, KE_rot=I * w * w / 2, KE_drum=Id * wd * wd / 2)
            out["KE"] = out["KE_trans"] + out["KE_rot"] + out["KE_drum"]
            out["work_pull"] = -F * (x + d * theta)
            out["work_drum_friction"] = tau * theta_d
            if h is None:
                out["drop"] = x
            balance = m * g * x + out["work_pull"] - out["work_drum_friction"] - out["KE"]
            assert abs(balance) <= mpmath.mpf(10) ** -30 * (m * g * abs(x) + abs(out["work_pull"]) + out["KE"])  # the reference's own check
        return {key: float(value) for key, value in out.items()}


def close(got, want, rel=1e-12, scale=0.0):
    return abs(got - want) <= rel * max(abs(got), abs(want), scale)


IRODOV = ("rolling", "disc", "--yoyo", "--mass", "2kg", "--radius", "0.1m", "--drum-mass", "2kg", "--drum-radius", "0.1m")


def test_irodov_1_258_each_thread_carries_mg_over_10():
    """T (both threads) = mg/5, so each of the two threads mg/10; a = 4g/5; each cylinder turns at
    α = 2g/(5r). Before: --drum-mass was no option of rolling (exit 2)."""
    run = run_taucli(*IRODOV, "--height", "1m", "--json")
    assert run.code == 0, run.err
    res = {key: value["value"] for key, value in run.json()["results"].items()}
    assert res["T"] / 2 == pytest.approx(2 * G / 10, rel=1e-14)
    assert res["a"] == pytest.approx(4 * G / 5, rel=1e-14)
    assert res["alpha"] == pytest.approx(2 * G / 5 / 0.1, rel=1e-14) and res["alpha_drum"] == pytest.approx(res["alpha"], rel=1e-14)
    want = reference(2, 0.5 * 2 * 0.01, 0.1, 0.5 * 2 * 0.01, 0.1, G, h=1.0)
    for key in ("a", "T", "alpha", "alpha_drum", "v", "omega", "omega_drum", "t", "KE_trans", "KE_rot", "KE_drum", "KE"):
        assert close(res[key], want[key], 1e-13), (key, res[key], want[key])
    assert res["KE"] == pytest.approx(2 * G * 1.0, rel=1e-14)  # all of m g h, shared three ways


def test_kleppner_7_24_two_drums_a_is_4g_over_5_whatever_the_mass_and_radius():
    """Two equal uniform drums: a = 4g/5 needs neither mass (given, it cancels) nor radius."""
    for mass, radius in (("1kg", "0.2m"), ("7 lb", "3 in")):
        run = run_taucli("rolling", "cylinder", "--yoyo", "--mass", mass, "--radius", radius, "--drum-mass", mass, "--get", "a")
        assert run.code == 0, run.err
        assert float(run.out) == pytest.approx(4 * G / 5, rel=1e-14)
    no_radius = taucli.rolling("disc", yoyo=True, mass=1.0, drum_mass=1.0)
    assert no_radius.results["a"].value == pytest.approx(4 * G / 5, rel=1e-14)
    assert no_radius.results["alpha_drum"].value is None and any("alpha_drum: give drum_radius" in note for note in no_radius.notes)


def test_batch_and_python_are_the_command_line():
    keys = {"shape": "disc", "yoyo": True, "mass": "2kg", "radius": "10cm", "drum_inertia": "0.03 kg*m^2", "drum_radius": "15cm",
            "drum_friction": "0.2 N*m", "pull": "3N", "pull_at": "5cm", "time": "2s"}
    line = run_taucli("rolling", "--batch", stdin=json.dumps(keys) + "\n")
    assert line.code == 0, line.err
    batch = json.loads(line.out)["results"]
    api = taucli.rolling(**keys).results
    cli = run_taucli("rolling", "disc", "--yoyo", "--mass", "2kg", "--radius", "10cm", "--drum-inertia", "0.03 kg*m^2", "--drum-radius", "15cm",
                     "--drum-friction", "0.2 N*m", "--pull", "3N", "--pull-at", "5cm", "--time", "2s", "--json").json()["results"]
    want = reference(2, 0.01, 0.1, 0.03, 0.15, G, F=3, d=0.05, tau=0.2, t=2)
    for key in ("a", "T", "alpha", "alpha_drum", "omega", "omega_drum", "drop", "work_pull", "work_drum_friction", "KE_drum", "KE"):
        assert batch[key]["value"] == api[key].value == cli[key]["value"], key
        assert close(api[key].value, want[key], 1e-13), (key, api[key].value, want[key])


def tidy(x: float) -> float:
    """0 for a size below 1e-6 (a pull or a lever of 1e-300 is no scene anyone types)."""
    return 0.0 if abs(x) < 1e-6 else x


bodies = st.fixed_dictionaries({
    "m": st.floats(0.05, 50), "k2": st.floats(0.02, 1.2), "R": st.floats(0.005, 1.0), "axle": st.floats(0.05, 1.0),
    "Q": st.floats(1e-3, 1e3), "Rd": st.floats(0.005, 2.0), "by_mass": st.booleans(),
    "pull": st.floats(0.0, 1.5).map(tidy), "at": st.floats(-1.0, 1.2).map(tidy), "friction": st.floats(0.0, 1.5).map(tidy),
    "end": st.sampled_from(("time", "height", None)), "span": st.floats(0.01, 10.0),
})


@settings(max_examples=150, deadline=None)
@given(bodies)
def test_random_scenes_against_newtons_equations(s):
    """Any body, axle, drum (by mass or by I_d), friction (holding the drum or not), pull on either
    side of the centre, after a time or a drop: every result to 1e-12 of the mpmath reference."""
    m, R = s["m"], s["R"]
    r, I = R * s["axle"], s["k2"] * s["m"] * R * R
    Rd = s["Rd"]
    Id = s["Q"] * m * Rd * Rd
    drum = {"drum_mass": 2 * Id / (Rd * Rd)} if s["by_mass"] else {"drum_inertia": Id}
    F, d = s["pull"] * m * G * 0.6, s["at"] * r
    tau = s["friction"] * m * G * Rd * 0.6
    kw = dict(k2=s["k2"], yoyo=True, mass=m, radius=R, axle_radius=r, drum_radius=Rd, **drum)
    if F:
        kw.update(pull=F, pull_at=d)
    if tau:
        kw["drum_friction"] = tau
    end = {} if s["end"] is None else {s["end"]: s["span"] * (1.0 if s["end"] == "time" else R)}
    want = reference(m, I, r, Id, Rd, G, F, d, tau, t=end.get("time"), h=end.get("height")) if "height" not in end else None
    plain = reference(m, I, r, Id, Rd, G, F, d, tau)
    if plain["T"] < -1e-12 * (m * G + F):  # a slack string: refused
        assert_usage_error_api(kw | end, "pull")
        return
    if "height" in end and plain["a"] <= 0:
        assert_usage_error_api(kw | end, "height")
        return
    if want is None:
        want = reference(m, I, r, Id, Rd, G, F, d, tau, h=end["height"])
    res = {key: value.value for key, value in taucli.rolling(**kw, **end).results.items()}
    size_a = G + F / m
    scales = {"a": size_a, "T": m * G + F, "alpha": size_a / r, "alpha_drum": size_a / Rd, "a_hand": size_a * (1 + abs(d) / r)}
    for key, want_value in want.items():
        if (key == "work_pull" and not F) or (key == "work_drum_friction" and not tau):
            continue  # no pull, no friction: not a result
        got = res.get(key)
        assert got is not None, key
        scale = scales.get(key, 0.0)
        if key in ("v", "omega", "omega_drum", "KE", "KE_trans", "KE_rot", "KE_drum", "work_pull", "work_drum_friction", "drop"):
            span = want.get("t", end.get("time", 0.0))
            scale = {"v": size_a * span, "omega": size_a * span / r, "omega_drum": size_a * span / Rd, "drop": size_a * span * span}.get(
                key, m * size_a * size_a * span * span * (1 + 1 / s["k2"] * R * R / (r * r) + 1 / s["Q"]) + F * size_a * span * span * (1 + abs(d) / r))
        assert close(got, want_value, 1e-12, scale), (key, got, want_value, kw, end)


def assert_usage_error_api(kw, name):
    with pytest.raises(taucli.InputError) as refused:
        taucli.rolling(**kw)
    assert name in str(refused.value)


@pytest.mark.parametrize("body", [{"shape": "disc"}, {"shape": "sphere", "axle_radius": 0.02}, {"inertia": 3e-4, "axle_radius": 0.01}])
@pytest.mark.parametrize("extra", [{}, {"time": 1.5}, {"height": 0.8}, {"pull": 2.0, "pull_at": 0.03, "time": 1.0}])
def test_an_immovable_drum_gives_back_the_plain_yoyo(body, extra):
    """Continuity at I_d → ∞: a, T and the body's α and ω tend to the plain yo-yo's (Q = I_d/(mR²)
    at 1e12: to 1e-11), the drum's α_d to 0; and a drum held by its axle's friction is the plain
    yo-yo exactly."""
    kw = {"yoyo": True, "mass": 1.5, **body, **({} if "inertia" in body else {"radius": 0.05}), **extra}
    plain = taucli.rolling(**kw).results
    heavy = taucli.rolling(**kw, drum_inertia=1.5e12 * 0.01, drum_radius=0.1).results
    held = taucli.rolling(**kw, drum_inertia=1e-3, drum_radius=0.1, drum_friction=1e3).results
    for key, value in plain.items():
        if value.value is None or isinstance(value.value, bool) or key in ("KE",):
            continue
        assert heavy[key].value == pytest.approx(value.value, rel=1e-11, abs=1e-300), key
        assert held[key].value == pytest.approx(value.value, rel=1e-14, abs=1e-300), key
    assert abs(heavy["alpha_drum"].value) < 1e-10 and held["alpha_drum"].value == 0.0
    if "KE" in plain:
        assert heavy["KE"].value == pytest.approx(plain["KE"].value, rel=1e-11) and held["KE_drum"].value == 0.0


def test_without_a_drum_nothing_changes():
    """No drum option: the yo-yo's results are its own (α = a/r, no drum results), as before."""
    report = taucli.rolling("disc", yoyo=True, mass=2.0, radius=0.1, axle_radius=0.02, height=1.0)
    res = report.results
    q = 0.5 * (0.1 / 0.02) ** 2
    assert res["a"].value == pytest.approx(G / (1 + q), rel=1e-15) and res["alpha"].value == pytest.approx(res["a"].value / 0.02, rel=1e-15)
    assert not {"alpha_drum", "omega_drum", "KE_drum", "work_drum_friction"} & set(res)
    assert "drum" not in report.model


def test_energy_balance_over_a_drop():
    """KE of the body's translation, its spin and the drum's spin sum to m g h (no friction); with
    friction, to m g h less what the axle takes."""
    for friction in (0.0, 0.05):
        res = taucli.rolling("ring", yoyo=True, mass=0.3, radius=0.04, drum_inertia=2e-4, drum_radius=0.03, drum_friction=friction or None,
                             height=1.2, g=9.8).results
        parts = res["KE_trans"].value + res["KE_rot"].value + res["KE_drum"].value
        assert res["KE"].value == pytest.approx(parts, rel=1e-15)
        taken = res["work_drum_friction"].value if friction else 0.0
        assert parts + taken == pytest.approx(0.3 * 9.8 * 1.2, rel=1e-14)


def test_find_the_drum_that_gives_an_acceleration():
    """--find drum_inertia: the drum's I_d for a = 0.75 g with a disc on it."""
    run = run_taucli("rolling", "disc", "--yoyo", "--mass", "1kg", "--radius", "0.1m", "--drum-radius", "0.1m",
                     "--g", "10", "--find", "drum_inertia", "--want", "a=7.5 m/s^2", "--get", "drum_inertia")
    assert run.code == 0, run.err
    # a = g u/(1 + u) = 0.75 g → u = 3 = m r²/I + m R²/I_d = 2 + 0.01/I_d → I_d = 0.01
    assert float(run.out) == pytest.approx(0.01, rel=1e-9)


@pytest.mark.parametrize("args, fragments", [
    (("--drum-radius", "0.1m"), ("--drum-radius", "needs --drum-mass or --drum-inertia")),
    (("--drum-friction", "0.1 N*m"), ("--drum-friction", "needs --drum-mass")),
    (("--drum-inertia", "0.01 kg*m^2"), ("--drum-radius", "required with --drum-inertia")),
    (("--drum-mass", "1kg", "--drum-inertia", "0.01 kg*m^2", "--drum-radius", "0.1m"), ("--drum-inertia", "conflicts with --drum-mass")),
    (("--drum-mass", "1kg", "--drum-friction", "0.1 N*m"), ("--drum-radius", "required with --drum-friction")),
    (("--drum-mass", "1kg", "--v0", "1 m/s", "--height", "1m"), ("--v0", "does not apply with a drum")),
    (("--drum-mass", "1kg", "--time", "1s", "--height", "1m"), ("--time", "conflicts with --height")),
    (("--drum-mass", "-1kg",), ("--drum-mass",)),
    (("--drum-mass", "0kg",), ("--drum-mass",)),
    (("--drum-mass", "1kg", "--drum-radius", "0.1m", "--drum-friction", "-1 N*m"), ("--drum-friction",)),
    (("--drum-mass", "nan kg",), ("--drum-mass",)),
    (("--drum-mass", "1kg", "--pull", "40N"), ("--pull", "slack")),
    (("--drum-mass", "1kg", "--pull", "15N", "--pull-at", "0.1m", "--height", "1m"), ("--height", "never reached")),
])
def test_refusals(args, fragments):
    assert_usage_error(run_taucli("rolling", "disc", "--yoyo", "--mass", "1kg", "--radius", "0.1m", *args), *fragments)


def test_refusals_outside_a_yoyo_and_without_a_mass():
    assert_usage_error(run_taucli("rolling", "disc", "--angle", "10deg", "--length", "1m", "--drum-mass", "1kg"), "--drum-mass", "applies with --yoyo")
    assert_usage_error(run_taucli("rolling", "disc", "--in-place", "--radius", "0.1m", "--drum-mass", "1kg"), "--drum-mass", "applies with --yoyo")
    assert_usage_error(run_taucli("rolling", "disc", "--yoyo", "--radius", "0.1m", "--drum-mass", "1kg"), "--mass", "required with a drum")


def test_the_steps_show_each_equation_and_the_shares():
    report = taucli.rolling("disc", yoyo=True, mass=2.0, radius=0.1, drum_mass=2.0, drum_radius=0.1, height=1.0)
    text = " | ".join(f"{step.equation} {step.numbers} {step.result}" for step in report.steps)
    for fragment in ("I_d α_d = T R", "a = r α + R α_d", "T = m g q Q / D", "½ I_d ω_d²", "R α_d ="):
        assert fragment in text, (fragment, text)
    assert math.isclose(report.results["KE"].value, 2.0 * G, rel_tol=1e-14)


def test_uncertain_drum_inputs_move_no_model():
    """The model's words carry no drum value (a value moved within its σ is no change of model), so
    --uncertainty on the drum's mass, I, radius or friction gives no 'far from linear' note; the
    σ of a is the first-order one, against the closed form's derivative."""
    run = run_taucli("rolling", "disc", "--yoyo", "--mass", "2kg", "--radius", "0.1m", "--drum-mass", "1+/-0.05kg", "--drum-radius", "0.1+/-0.001m",
                     "--drum-friction", "0.1+/-0.01 N*m", "--height", "1m", "--get", "a", "--uncertainty")
    assert run.code == 0, run.err
    assert "model becomes" not in run.err and "far from linear" not in run.err, run.err
    value, sigma = (float(x) for x in run.out.split())
    # a = (Q g + q (g − φ))/(qQ + q + Q), q = 1/2, Q = M/(2m), φ = τ/(m R): ∂a/∂M, ∂a/∂R, ∂a/∂τ by mpmath.diff
    def a_of(M, R, tau):
        q, Q, phi = mpmath.mpf(1) / 2, M / 4, tau / (2 * R)
        return (Q * G + q * (G - phi)) / (q * Q + q + Q)
    with mpmath.workdps(30):
        x = (mpmath.mpf(1), mpmath.mpf("0.1"), mpmath.mpf("0.1"))
        slopes = [mpmath.diff(lambda *v: a_of(*v), x, tuple(int(i == j) for j in range(3))) for i in range(3)]
        want = mpmath.sqrt(sum((s * e) ** 2 for s, e in zip(slopes, (0.05, 0.001, 0.01))))
        assert value == pytest.approx(float(a_of(*x)), rel=1e-14)
    assert sigma == pytest.approx(float(want), rel=1e-5)
