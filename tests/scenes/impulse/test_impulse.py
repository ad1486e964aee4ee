"""Angular impulse: exact cases, quadrature order, round trips, L conservation, malformed CSVs."""

from __future__ import annotations

import math
import subprocess
import sys

import mpmath
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from conftest import assert_usage_error
from taucli.core.errors import InputError
from taucli.answering.profile import read_profile
from taucli.scenes.impulse import UNKNOWNS, solve_balance, solve_changing_inertia, solve_profile


def values(report):
    return {name: value.value for name, value in report.results.items()}


def profile(function, t_end, samples, header="t [s], torque [N*m]"):
    lines = [header] + [f"{t_end * k / (samples - 1)!r},{function(t_end * k / (samples - 1))!r}" for k in range(samples)]
    return read_profile(lines).samples


def test_constant_torque_solved_for_omega1():
    result = values(solve_balance(0.1, 0.0, None, 2.0, 0.5))
    assert result["omega1"] == pytest.approx(10.0, rel=1e-15)
    assert result["J"] == pytest.approx(1.0, rel=1e-15)
    assert result["KE1"] == pytest.approx(5.0, rel=1e-15)


finite = st.floats(-1e3, 1e3).filter(lambda x: abs(x) > 1e-3)


@settings(max_examples=200, deadline=None)
@given(inertia=st.floats(1e-3, 1e3), omega0=finite, torque=finite, duration=st.floats(1e-3, 1e3))
def test_round_trips_recover_every_input(inertia, omega0, torque, duration):
    """Solve for ω₁, then leave out each of the five in turn and recover it.

    ω₁ is stored as a double, so Δω = ω₁ − ω₀ is known only to about ulp(max |ω|); recovering
    I, τ or Δt from it is good to that over |Δω| (a small change on a fast spin), and no better.
    """
    forward = values(solve_balance(inertia, omega0, None, torque, duration))
    full = {name: forward[name] for name in UNKNOWNS}
    change = abs(full["omega1"] - full["omega0"])
    conditioning = 4 * 2.0**-52 * max(abs(full["omega0"]), abs(full["omega1"])) / change if change else math.inf
    for unknown in UNKNOWNS:
        given_values = {name: (None if name == unknown else value) for name, value in full.items()}
        recovered = values(solve_balance(**given_values))
        if unknown.startswith("omega"):
            assert recovered[unknown] == pytest.approx(full[unknown], rel=1e-14, abs=1e-14 * change)
        else:
            assert recovered[unknown] == pytest.approx(full[unknown], rel=1e-14 + conditioning)


def test_all_five_must_agree():
    assert values(solve_balance(0.1, 0.0, 10.0, 2.0, 0.5))["J"] == pytest.approx(1.0)
    with pytest.raises(InputError, match="disagree"):
        solve_balance(0.1, 0.0, 11.0, 2.0, 0.5)


@pytest.mark.parametrize(
    "args,fragment",
    [
        ((0.1, None, None, None, 0.5), "omega0 and omega1 and torque are missing"),  # (I and ω₀ alone: the body's state, #42 item 16)
        ((None, 0.0, None, 2.0, None), "inertia and omega1 and duration are missing"),
        ((0.1, 0.0, 10.0, 0.0, None), "torque must not be zero"),
        ((0.1, 0.0, 10.0, -2.0, None), "torque must act in the sense"),
        ((None, 0.0, 0.0, 2.0, 0.5), "omega1 must differ"),
        ((None, 0.0, 10.0, -2.0, 0.5), "torque must act in the sense"),
    ],
)
def test_impossible_balances_are_input_errors(args, fragment):
    with pytest.raises(InputError) as caught:
        solve_balance(*args)
    assert fragment in str(caught.value)


@settings(max_examples=300, deadline=None)
@given(inertia0=st.floats(1e-3, 1e3), inertia1=st.floats(1e-3, 1e3), omega0=st.floats(-1e3, 1e3))
def test_changing_inertia_conserves_angular_momentum_to_a_few_ulp(inertia0, inertia1, omega0):
    """L₁ = I₁ω₁ against L₀ = I₀ω₀: measured at most 1 ulp (two roundings that mostly cancel)."""
    result = values(solve_changing_inertia(inertia0, inertia1, omega0))
    assert abs(result["L1"] - result["L0"]) <= 2 * math.ulp(abs(result["L0"])) + 1e-300
    with mpmath.workdps(40):
        exact = mpmath.mpf(inertia0) * omega0**2 / 2 * (mpmath.mpf(inertia0) / inertia1 - 1)
    assert result["work"] == pytest.approx(float(exact), rel=1e-12, abs=1e-12 * abs(result["KE0"]) + 1e-300)


def test_skater_pulling_in_her_arms():
    result = values(solve_changing_inertia(4.0, 1.5, 2.0))
    assert result["omega1"] == pytest.approx(16 / 3)
    assert result["KE1"] / result["KE0"] == pytest.approx(4.0 / 1.5)


def test_exact_profiles_constant_and_linear_ramp():
    """Both rules are exact for a straight line: the ramp 0 -> 6 N·m over 0.5 s gives J = 1.5 N·m·s."""
    for rule in ("trapezoid", "simpson"):
        constant = values(solve_profile(0.1, 0.0, profile(lambda t: 2.0, 0.5, 11), rule=rule))
        assert constant["J"] == pytest.approx(1.0, rel=1e-14)
        ramp = values(solve_profile(0.1, 0.0, profile(lambda t: 12 * t, 0.5, 8), rule=rule))
        assert ramp["J"] == pytest.approx(1.5, rel=1e-14)
        assert ramp["peak_torque"] == pytest.approx(6.0)


HALF_SINE_PEAK, HALF_SINE_LENGTH = 50.0, 0.01  # a 10 ms, 50 N·m blow


def half_sine_error(rule: str, samples: int) -> float:
    report = solve_profile(1.0, 0.0, profile(lambda t: HALF_SINE_PEAK * math.sin(math.pi * t / HALF_SINE_LENGTH), HALF_SINE_LENGTH, samples), rule=rule)
    exact = 2 * HALF_SINE_PEAK * HALF_SINE_LENGTH / math.pi
    return abs(report.results["J"].value - exact) / exact


@pytest.mark.parametrize("rule,order", [("trapezoid", 2), ("simpson", 4)])
def test_quadrature_error_falls_at_each_rules_order_on_a_half_sine(rule, order):
    """Measured relative errors at 10, 100, 1000 samples: trapezoid 1.0e-2, 8.4e-5, 8.2e-7;
    Simpson 3.7e-4, 2.7e-8, 2.6e-12."""
    errors = [half_sine_error(rule, n) for n in (11, 101, 1001)]
    for coarse, fine in zip(errors, errors[1:]):
        observed = math.log10(coarse / fine)  # ten times the samples: 10^order times smaller
        assert order - 0.3 < observed < order + 0.3
    assert errors[-1] < (1e-6 if rule == "trapezoid" else 1e-11)


def test_simpson_loses_its_order_on_a_profile_with_a_corner():
    """A triangle pulse whose apex falls between samples: Simpson drops to second order."""
    def triangle(t):
        return 100 * min(t, 0.01 - t) if 0 <= t <= 0.01 else 0.0

    errors = []
    for n in (12, 102, 1002):  # the apex at 5 ms is never a sample
        report = solve_profile(1.0, 0.0, profile(triangle, 0.01, n), rule="simpson")
        errors.append(abs(report.results["J"].value - 0.0025) / 0.0025)
    observed = math.log10(errors[1] / errors[2])
    assert observed < 2.5  # not the fourth order it has on smooth data


@pytest.mark.parametrize(
    "text,fragment",
    [
        ("", "empty"),
        ("t [s], torque [N*m]\n0, 1\n", "1 row"),
        ("t [s], torque [N*m]\n0, 1\n1, two\n", "line 3: expected numbers"),
        ("t [s], torque [N*m]\n0, 1\n1, 2\n0.5, 3\n", "line 4: time must increase"),
        ("t [s], torque [N*m]\n0, 1\n1\n", "line 3: expected two numbers"),
        ("t [s] torque [N*m]\n0, 1\n1, 2\n", "line 1: expected a header"),
        ("t [kg], torque [N*m]\n0, 1\n1, 2\n", "expected a time"),
        ("t [s], torque [N]\n0, 1\n1, 2\n", "expected a torque"),
        ("t [s], torque [N*m]\n0, nan\n1, 2\n", "finite"),
    ],
)
def test_malformed_profiles_are_input_errors(taucli, text, fragment):
    assert_usage_error(taucli("impulse", "--inertia", "0.1", "--torque-profile", "-", stdin=text), fragment)


def test_header_without_units_reads_si_with_a_note(taucli):
    doc = taucli("impulse", "--inertia", "0.1", "--torque-profile", "-", "--json", stdin="t, torque\n0, 2\n0.5, 2\n").json()
    assert doc["results"]["J"]["value"] == pytest.approx(1.0)
    assert any("no unit for the time column" in note for note in doc["notes"])


def test_a_million_rows_stream_in_flat_memory():
    """1,000,000 rows through stdin: the right integral, and peak memory far below the data's size."""
    rows = 1_000_000
    script = (
        "import sys\nsys.stdout.write('t [us], torque [N*m]\\n')\n"
        f"sys.stdout.writelines(f'{{k}},{{2.0}}\\n' for k in range({rows}))\n"
    )
    producer = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE)
    # The child reports its own peak, VmHWM of its address space. getrusage's ru_maxrss would not
    # do: Linux carries it across exec, so a child of a large pytest reports pytest's size.
    measured = (
        "import runpy, sys\n"
        "sys.argv = ['taucli', 'impulse', '--inertia', '1', '--torque-profile', '-', '--get', 'J']\n"
        "try:\n    runpy.run_module('taucli', run_name='__main__')\n"
        "finally:\n    status = open('/proc/self/status').read()\n"
        "    print('peak', status.split('VmHWM:')[1].split()[0], file=sys.stderr)\n"
    )
    done = subprocess.run([sys.executable, "-c", measured], stdin=producer.stdout, capture_output=True, text=True, timeout=300)
    producer.wait()
    assert done.returncode == 0, done.stderr
    assert float(done.stdout) == pytest.approx(2.0 * (rows - 1) * 1e-6, rel=1e-9)
    peak_kib = int(done.stderr.split("peak")[-1])
    # Measured: 20 MB streaming (46 MB when pint is loaded, cold unit cache); holding just the
    # lines of text in a list adds 61 MB.
    assert peak_kib < 80 * 1024


# Digits of Δω (#16, item 8) -------------------------------------------------------------------


@settings(max_examples=300, deadline=None)
@given(inertia=st.floats(1e-3, 1e3), omega=st.floats(-1e6, 1e6), torque=st.floats(-1e3, 1e3).filter(lambda x: abs(x) > 1e-100), duration=st.floats(1e-6, 1e3))
@example(inertia=1.0, omega=1e6, torque=1e-3, duration=1.0)
def test_delta_omega_keeps_its_digits_when_an_angular_velocity_is_solved_for(inertia, omega, torque, duration):
    """#16: Δω was ω₁ − ω₀ after solving for one of them, which loses the digits of a small
    change on a fast spin (1e-3 on 1e6 rad/s kept 7 of 16). It is τΔt/I: within 2 ulp of the
    40-digit value, whichever of ω₀, ω₁ is solved for."""
    with mpmath.workdps(40):
        exact = mpmath.mpf(torque) * mpmath.mpf(duration) / mpmath.mpf(inertia)
    for given_values in ((inertia, omega, None, torque, duration), (inertia, None, omega, torque, duration)):
        got = solve_balance(*given_values).results["delta_omega"].value
        assert abs(mpmath.mpf(got) - exact) <= 2 * abs(exact) * mpmath.mpf(2) ** -53


@settings(max_examples=100, deadline=None)
@given(inertia=st.floats(1e-3, 1e3), omega0=finite, torque=finite, duration=st.floats(1e-3, 1e3))
@example(inertia=2.0, omega0=0.0, torque=10.0, duration=1.0)
def test_delta_omega_is_omega1_minus_omega0_when_all_five_are_given(inertia, omega0, torque, duration):
    """All five given: delta_omega was I(ω₁ − ω₀), the angular impulse in N·m·s, where the name
    it was read from held Δω in the other branches (10 for I = 2 kg·m², ω₁ − ω₀ = 5 rad/s).
    It is ω₁ − ω₀ in rad/s, taken here from the two given."""
    omega1 = omega0 + torque * duration / inertia
    assert values(solve_balance(inertia, omega0, omega1, torque, duration))["delta_omega"] == omega1 - omega0


def test_delta_omega_with_all_five_given_at_the_command_line(taucli):
    done = taucli("impulse", "--inertia", "2kg*m^2", "--omega0", "0rad/s", "--omega1", "5rad/s", "--torque", "10N*m",
                  "--duration", "1s", "--get", "delta_omega")
    assert done.code == 0, done.err
    assert float(done.out) == 5.0


# What the inputs determine (#16, item 13) ------------------------------------------------------


def test_torque_and_duration_on_a_body_at_rest_give_the_spin_up():
    """#16: `impulse --inertia 0.1 --torque 2N*m --duration 0.5s` refused, though J = τΔt = 1
    N·m·s and Δω = J/I = 10 rad/s are fixed. ω₀ is taken as 0 (at rest, as spin-down does),
    with a note, and the answer is the one for ω₀ = 0 given."""
    report = solve_balance(0.1, None, None, 2.0, 0.5)
    assert values(report) == values(solve_balance(0.1, 0.0, None, 2.0, 0.5))
    assert values(report)["omega1"] == pytest.approx(10.0, rel=1e-15) and values(report)["J"] == pytest.approx(1.0, rel=1e-15)
    assert any("--omega0" in note and "at rest" in note for note in report.notes)


@pytest.mark.parametrize(
    "args,known,unknown",
    [
        ((None, None, None, 2.0, 0.5), {"J": 1.0, "torque": 2.0, "duration": 0.5}, ("delta_omega", "inertia", "omega0", "omega1", "L0", "L1", "KE0", "KE1")),
        ((None, 3.0, None, 2.0, 0.5), {"J": 1.0, "omega0": 3.0}, ("delta_omega", "inertia", "omega1", "L0", "KE1")),
        ((0.1, 0.0, 10.0, None, None), {"J": 1.0, "delta_omega": 10.0, "L1": 1.0, "KE1": 5.0}, ("torque", "duration")),
        ((None, 1.0, 3.0, 2.0, None), {"delta_omega": 2.0}, ("J", "inertia", "duration", "L0", "KE1")),
        ((None, 1.0, 3.0, None, None), {"delta_omega": 2.0}, ("J", "inertia", "torque", "duration")),
    ],
)
def test_two_or_more_left_out_answer_what_the_rest_determine(args, known, unknown):
    """J = τΔt needs τ and Δt (or I, ω₀ and ω₁); Δω = ω₁ − ω₀ needs both (or τΔt/I): each is
    given where its inputs are, the rest null with a note naming them; refused only where
    neither J nor Δω is fixed."""
    report = solve_balance(*args)
    result = values(report)
    for name, value in known.items():
        assert result[name] == pytest.approx(value, rel=1e-15), name
    for name in unknown:
        assert result[name] is None, name
    assert any("not fixed" in note for note in report.notes)
    report.steps[:]


@settings(max_examples=100, deadline=None)
@given(inertia=st.floats(1e-2, 1e2), omega0=finite, mass=st.floats(1e-2, 1e2), radius=st.floats(1e-2, 10), radius_after=st.one_of(st.just(0.0), st.floats(1e-3, 10)))
def test_a_rider_moving_along_the_body_is_the_skater_changing_her_inertia(inertia, omega0, mass, radius, radius_after):
    """--particle with no speed (riding) moving from r to ρ is --inertia-final with I + mr² -> I + mρ²
    (#20): the same ω₁ and KE₁, and KE_lost = −work."""
    import taucli

    riding = taucli.impulse(inertia=inertia, omega0=omega0, particle=f"mass={mass!r}kg radius={radius!r}m radius-after={radius_after!r}m")
    skater = taucli.impulse(inertia=inertia + mass * radius**2, inertia_final=inertia + mass * radius_after**2, omega0=omega0)
    a, b = values(riding), values(skater)
    assert a["omega1"] == pytest.approx(b["omega1"], rel=1e-12)
    assert a["KE1"] == pytest.approx(b["KE1"], rel=1e-12)
    assert a["KE_lost"] == pytest.approx(-b["work"], rel=1e-9, abs=1e-12 * b["KE0"])
