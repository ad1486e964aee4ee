"""taucli gyro: precession of a spinning top or gyroscope.

References are written from the physics, not from the solver's formulas: the steady precession
is where the weight's torque turns the horizontal part of the whole angular momentum at Ω,

    mgr sin θ = Ω · (Iω_s − I⊥Ω cos θ) sin θ,

solved by mpmath's root finder at 50 digits from the two physical guesses (the gyroscopic rate,
and the rate at which I⊥Ω cos θ takes up all of Iω_s); the textbook numbers are the books'.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taucli
from conftest import run_taucli
from taucli.core.errors import InputError
from taucli.scenes import gyro as scene

G0 = 9.80665
ULP = 2.0**-52


def balance_roots(a: float, angular_momentum: float, weight_torque: float) -> tuple[mpmath.mpf, mpmath.mpf | None]:
    """The steady rates Ω where mgr = Ω(L − I⊥cosθ·Ω) (``a`` = I⊥ cos θ), to 50 digits: the
    schoolbook roots (L ∓ √(L² − 4ac))/2a, at enough digits that the cancellation in the slow one
    (log10(1/ρ) digits, ρ = 4ac/L²) still leaves 60, each checked against the balance of the
    torque and the rate at which L turns."""
    exact_a, exact_l, exact_c = mpmath.mpf(a), mpmath.mpf(angular_momentum), mpmath.mpf(weight_torque)
    if a == 0:
        return exact_c / exact_l, None
    rho = abs(4 * exact_a * exact_c / exact_l**2)
    with mpmath.workdps(70 + max(0, int(-mpmath.log10(rho)))):
        root = mpmath.sqrt(exact_l**2 - 4 * exact_a * exact_c)
        slow, fast = (exact_l - root) / (2 * exact_a), (exact_l + root) / (2 * exact_a)
        for omega in (slow, fast):
            assert abs(omega * (exact_l - exact_a * omega) - exact_c) <= mpmath.mpf(10) ** -60 * max(exact_c, abs(exact_l * omega))
        assert abs(slow) <= abs(fast)
        return +slow, +fast


def relative(x: float, reference) -> float:
    return float(abs((mpmath.mpf(x) - reference) / reference))


# --- the textbook problems -----------------------------------------------------------------


def test_openstax_gyroscope_precesses_once_in_two_seconds():
    """University Physics (OpenStax) vol. 1, Example 11.10: a 0.3 kg disc of radius 5.0 cm at
    20 rev/s, its centre 5.0 cm from the pivot: the precessional period is 2.0 s (g = 9.8)."""
    report = taucli.gyro(shape="disc", mass="0.3 kg", radius="5 cm", spin="20 rev/s", cm_distance="5 cm", g="9.8 m/s^2")
    assert report.results["period_p"].value == pytest.approx(2.0, abs=0.02)
    inertia = 0.5 * 0.3 * 0.05**2
    assert report.results["omega_p"].value == pytest.approx(0.3 * 9.8 * 0.05 / (inertia * 20 * 2 * math.pi), rel=1e-14)


def test_openstax_problem_75():
    """University Physics (OpenStax) vol. 1, ch. 11, problem 75: a 0.5 kg disc of radius 10 cm
    at 40 rev/s, its centre 15 cm from the pivot: ω_P = rMg/(Iω) = 1.17 rad/s (g = 9.8)."""
    report = taucli.gyro(shape="disc", mass="0.5 kg", radius="10 cm", spin="40 rev/s", cm_distance="15 cm", g="9.8 m/s^2")
    assert round(report.results["omega_p"].value, 2) == 1.17


def test_the_4000_rpm_gyroscope_approximate_and_exact_rates_side_by_side():
    """The same disc at 4000 rpm: horizontal, the one exact root is the approximation; tilted
    30° above the horizontal plane's normal, the exact slow rate is 0.49% above it."""
    inertia = 0.5 * 0.3 * 0.05**2
    spin = 4000 * 2 * math.pi / 60
    weight_torque = 0.3 * G0 * 0.05
    level = taucli.gyro(shape="disc", mass="300 g", radius="5 cm", spin="4000 rpm", cm_distance="5 cm").results
    assert level["L"].value == pytest.approx(inertia * spin, rel=1e-15)
    assert level["omega_p"].value == pytest.approx(weight_torque / (inertia * spin), rel=1e-15)
    assert level["omega_p_slow"].value == level["omega_p"].value
    assert level["omega_p_fast"].value is None
    assert "spin_min" not in level
    tilted = taucli.gyro(shape="disc", mass="300 g", radius="5 cm", spin="4000 rpm", cm_distance="5 cm", tilt="30 deg")
    perp = 0.3 * 0.05**2 / 4 + 0.3 * 0.05**2
    slow, fast = balance_roots(perp * math.cos(math.radians(30)), inertia * spin, weight_torque)
    assert relative(tilted.results["omega_p_slow"].value, slow) < 1e-14
    assert relative(tilted.results["omega_p_fast"].value, fast) < 1e-14
    assert tilted.results["omega_p"].value == level["omega_p"].value  # sin θ cancels
    assert any("0.486% below the exact slow rate" in note for note in tilted.notes)
    assert tilted.results["period_p"].value == pytest.approx(2 * math.pi / float(slow), rel=1e-14)


def test_a_top_spun_too_slowly_has_no_steady_precession():
    """A 100 g disc top of radius 3 cm, its centre 4 cm up, leaning 20°: ω_min = √(4 I⊥ mgr cos θ)/I
    is 115.3 rad/s; at 10 rev/s it cannot precess steadily, at 20 rev/s it can."""
    inertia = 0.5 * 0.1 * 0.03**2
    perp = 0.1 * 0.03**2 / 4 + 0.1 * 0.04**2
    weight_torque = 0.1 * G0 * 0.04
    with mpmath.workdps(50):
        least = mpmath.sqrt(4 * mpmath.mpf(perp) * mpmath.mpf(weight_torque) * mpmath.cos(mpmath.radians(20))) / mpmath.mpf(inertia)
    slow = taucli.gyro(shape="disc", mass="100 g", radius="3 cm", cm_distance="4 cm", spin="10 rev/s", tilt="20 deg")
    assert slow.results["omega_p_slow"].value is None and slow.results["omega_p_fast"].value is None
    assert slow.results["period_p"].value is None
    assert relative(slow.results["spin_min"].value, least) < 1e-14
    assert any("no steady precession" in note for note in slow.notes)
    fast = taucli.gyro(shape="disc", mass="100 g", radius="3 cm", cm_distance="4 cm", spin="20 rev/s", tilt="20 deg")
    assert fast.results["omega_p_slow"].value > 0 and fast.results["omega_p_fast"].value > fast.results["omega_p_slow"].value


def test_the_earths_precession_from_the_torque_on_it():
    """College Physics (OpenStax) ch. 10, problem 48: the average torque 1.38e22 N·m. With the
    Earth's I = 8.0e37 kg·m², ω = 7.29e-5 rad/s and tilt 23.44°: Ω = τ/(L sin θ)."""
    report = taucli.gyro(inertia="8.0e37 kg*m^2", spin="7.29e-5 rad/s", torque="1.38e22 N*m", tilt="23.44 deg")
    with mpmath.workdps(50):
        rate = mpmath.mpf("1.38e22") / (mpmath.mpf("8.0e37") * mpmath.mpf("7.29e-5") * mpmath.sin(mpmath.radians(mpmath.mpf("23.44"))))
    assert relative(report.results["omega_p"].value, rate) < 1e-14
    assert relative(report.results["period_p"].value, 2 * mpmath.pi / rate) < 1e-14
    assert set(report.results) == {"L", "omega_p", "period_p"}
    # The steady torque that turns L sin θ once in 25,772 years gives that period back.
    year = 365.25 * 86400
    steady = 2 * math.pi / (25772 * year) * 8.0e37 * 7.29e-5 * math.sin(math.radians(23.44))
    back = taucli.gyro(inertia=8.0e37, spin=7.29e-5, torque=steady, tilt="23.44 deg")
    assert back.results["period_p"].value / year == pytest.approx(25772, rel=1e-12)


# --- the roots: accuracy against 50 digits --------------------------------------------------


@pytest.mark.parametrize("share", [1e-1, 1e-4, 1e-8, 1e-12, 1e-16, 1e-24])
def test_the_slow_root_keeps_full_precision_when_the_spin_dominates(share):
    """Where Iω_s is 1/share times I⊥Ω cos θ (1e8 and beyond), the slow root is within a few ulp
    of the 50-digit root, and so is the fast one."""
    inertia, perp, weight_torque = 3.75e-4, 9.375e-4, 0.3 * G0 * 0.05
    cos_t = math.cos(math.radians(30))
    # I⊥Ω cos θ/(Iω_s) ≈ I⊥ cos θ mgr/(Iω_s)² = share: the spin that makes it so.
    spin = math.sqrt(perp * cos_t * weight_torque / share) / inertia
    angular_momentum = inertia * spin
    slow, fast = scene.precession_roots(perp * cos_t, angular_momentum, weight_torque)
    reference_slow, reference_fast = balance_roots(perp * cos_t, angular_momentum, weight_torque)
    assert relative(slow, reference_slow) <= 4 * ULP
    assert relative(fast, reference_fast) <= 4 * ULP
    assert float(perp * cos_t * reference_slow / angular_momentum) == pytest.approx(share, rel=1.5 * share)
    naive = (angular_momentum - math.sqrt(angular_momentum**2 - 4 * perp * cos_t * weight_torque)) / (2 * perp * cos_t)
    if share <= 1e-8:  # the textbook form would have lost most or all of its digits here
        assert relative(naive, reference_slow) > 1e-9


def test_the_gyroscope_at_1e5_rpm_end_to_end():
    """The 0.3 kg disc at 10⁵ rpm, tilted 30°, against the balance at 50 digits from the inputs
    themselves (I, I⊥ and cos 30° exact): the slow root within a few ulp (here I·ω_s is 1.3e5
    times I⊥Ω cos θ)."""
    report = taucli.gyro(shape="disc", mass="0.3 kg", radius="5 cm", spin="1e5 rpm", cm_distance="5 cm", tilt="30 deg")
    with mpmath.workdps(60):
        m, radius, r = mpmath.mpf("0.3"), mpmath.mpf("0.05"), mpmath.mpf("0.05")
        angular_momentum = m * radius**2 / 2 * mpmath.mpf(10) ** 5 * 2 * mpmath.pi / 60
        a = (m * radius**2 / 4 + m * r**2) * mpmath.cos(mpmath.pi / 6)
        c = m * mpmath.mpf(G0) * r
        slow = 2 * c / (angular_momentum + mpmath.sqrt(angular_momentum**2 - 4 * a * c))
        assert abs(slow * (angular_momentum - a * slow) - c) < mpmath.mpf(10) ** -55
    assert relative(report.results["omega_p_slow"].value, slow) <= 4 * ULP
    assert float(a * slow / angular_momentum) == pytest.approx(7.74e-6, rel=1e-3)


@settings(max_examples=300, deadline=None)
@given(
    exponent_l=st.floats(-30, 30),
    exponent_c=st.floats(-30, 30),
    rho=st.one_of(st.floats(-1e6, 0.9), st.floats(1e-30, 1e-3)),
)
def test_both_roots_are_within_a_few_ulp_of_50_digits(exponent_l, exponent_c, rho):
    """Over magnitudes from 1e-30 to 1e30 and ρ = 4ac/L² from −1e6 (far below the pivot) to 0.9."""
    angular_momentum, weight_torque = 10.0**exponent_l, 10.0**exponent_c
    a = rho * angular_momentum**2 / (4 * weight_torque)
    assume(a != 0 and math.isfinite(a))
    slow, fast = scene.precession_roots(a, angular_momentum, weight_torque)
    reference_slow, reference_fast = balance_roots(a, angular_momentum, weight_torque)
    assert relative(slow, reference_slow) <= 4 * ULP
    if fast is None:  # beyond the largest double: null, never inf
        assert abs(reference_fast) > 1.7e308
        return
    assert relative(fast, reference_fast) <= 4 * ULP
    assert abs(slow) <= abs(fast)
    if a < 0:  # below the pivot: opposite signs
        assert slow > 0 > fast


@settings(max_examples=200, deadline=None)
@given(spin=st.floats(1.0, 1e4), factor=st.floats(1.5, 1e3))
def test_the_exact_slow_root_tends_to_the_approximation_as_the_spin_grows(spin, factor):
    """Spinning faster brings the slow root closer to mgr/(Iω_s), as 1/ω_s² (the relative gap
    is I⊥Ω cos θ/(Iω_s), and Ω itself falls as 1/ω_s)."""
    inertia, perp, weight_torque, cos_t = 3.75e-4, 9.375e-4, 0.3 * G0 * 0.05, math.cos(math.radians(40))
    least = scene.least_spin(inertia, perp * cos_t, weight_torque)
    assume(spin > 1.01 * least)

    def gap(omega):
        slow, _ = scene.precession_roots(perp * cos_t, inertia * omega, weight_torque)
        return abs(slow / (weight_torque / (inertia * omega)) - 1)

    assert gap(spin * factor) < gap(spin)
    if spin > 10 * least:
        assert gap(spin * factor) == pytest.approx(gap(spin) / factor**2, rel=0.05)


def test_the_approximations_error_is_the_neglected_share_and_noted_above_1e_3():
    for spin, noted in (("60 rad/s", True), ("4000 rpm", True), ("40000 rpm", False)):
        report = taucli.gyro(shape="disc", mass=0.3, radius=0.05, spin=spin, cm_distance=0.05, tilt="30 deg")
        gap = report.results["omega_p"].value / report.results["omega_p_slow"].value - 1
        error = scene.approximation_error(9.375e-4 * math.cos(math.radians(30)), report.results["L"].value, 0.3 * G0 * 0.05)
        assert error == pytest.approx(gap, rel=1e-9, abs=1e-15)
        assert any("below the exact slow rate" in note for note in report.notes) == noted


# --- regimes and their boundaries -----------------------------------------------------------


def test_below_the_pivot_the_roots_have_opposite_signs_and_the_slow_one_is_smaller():
    report = taucli.gyro(inertia=0.01, spin="50 rad/s", mass=2, cm_distance=0.2, inertia_perp=0.2, tilt="120 deg")
    slow, fast = report.results["omega_p_slow"].value, report.results["omega_p_fast"].value
    reference_slow, reference_fast = balance_roots(0.2 * math.cos(math.radians(120)), 0.5, 2 * G0 * 0.2)
    assert relative(slow, reference_slow) < 1e-14 and relative(fast, reference_fast) < 1e-14
    assert slow > 0 > fast and abs(slow) < abs(fast)
    assert "spin_min" not in report.results  # every spin precesses below the pivot
    assert any("below the pivot" in note for note in report.notes)


def test_the_roots_meet_at_the_least_spin_and_are_continuous_through_90_degrees():
    inertia, perp, weight_torque = 0.01, 0.2, 2 * G0 * 0.2
    cos_t = math.cos(math.radians(30))
    least = scene.least_spin(inertia, perp * cos_t, weight_torque)
    meet = inertia * least / (2 * perp * cos_t)  # the double root L/(2a)
    slow, fast = scene.precession_roots(perp * cos_t, inertia * least * (1 + 1e-12), weight_torque)
    assert slow == pytest.approx(meet, rel=1e-5) and fast == pytest.approx(meet, rel=1e-5)
    assert scene.precession_roots(perp * cos_t, inertia * least * (1 - 1e-9), weight_torque) is None
    # Through 90°: the slow root passes smoothly through the approximation.
    at_90 = taucli.gyro(inertia=inertia, spin=least, mass=2, cm_distance=0.2, inertia_perp=perp).results
    for degrees in (89.999999, 90.000001):
        near = taucli.gyro(inertia=inertia, spin=least, mass=2, cm_distance=0.2, inertia_perp=perp, tilt=f"{degrees} deg").results
        assert near["omega_p_slow"].value == pytest.approx(at_90["omega_p_slow"].value, rel=1e-6)
        assert abs(near["omega_p_fast"].value) > 1e5  # the fast root goes off to infinity, and is gone at 90°
    assert at_90["omega_p_fast"].value is None


def test_ninety_degrees_read_in_any_unit_has_one_root_exactly():
    for tilt in ("90 deg", "0.25 rev", f"{math.pi / 2!r} rad", "100 grad"):
        report = taucli.gyro(inertia=0.01, spin=50, mass=2, cm_distance=0.2, inertia_perp=0.2, tilt=tilt)
        assert report.results["omega_p_fast"].value is None
        assert report.results["omega_p_slow"].value == report.results["omega_p"].value


def test_a_vertical_top_gives_the_sleeping_top_limit():
    """At θ = 0 the least spin is the sleeping top's stability limit, ω² > 4 I⊥ mgr / I²."""
    report = taucli.gyro(inertia=0.01, spin=10, mass=2, cm_distance=0.2, inertia_perp=0.2, tilt="0 deg")
    assert report.results["spin_min"].value == pytest.approx(math.sqrt(4 * 0.2 * 2 * G0 * 0.2) / 0.01, rel=1e-15)
    assert report.results["omega_p_slow"].value is None
    assert any("sleeping top's stability limit" in note for note in report.notes)


def test_without_a_perpendicular_moment_only_the_approximation():
    report = taucli.gyro(inertia="3.75e-4 kg*m^2", spin="4000 rpm", mass="0.3 kg", cm_distance="5 cm")
    assert set(report.results) == {"L", "omega_p", "period_p", "L_orbital", "pivot_force_vertical", "pivot_force_horizontal"}
    assert any("omega_p only" in note for note in report.notes)
    assert report.results["period_p"].value == pytest.approx(2 * math.pi / report.results["omega_p"].value, rel=1e-15)
    rod = taucli.gyro(shape="rod", mass=1, length=0.3, spin=100, cm_distance=0.1)  # no symmetric I⊥ known
    assert "omega_p_slow" not in rod.results


def test_a_centre_of_mass_at_the_pivot_does_not_precess():
    report = taucli.gyro(inertia=0.01, spin=50, mass=2, cm_distance=0, inertia_perp=0.02, tilt="60 deg")
    assert report.results["omega_p"].value == 0 and report.results["omega_p_slow"].value == 0
    assert report.results["period_p"].value is None
    assert any("no torque" in note for note in report.notes)


def test_perpendicular_moments_from_shapes():
    """I⊥ = I about a diameter (thin disc ¼MR², a thick one + ML²/12, ring ½MR², sphere ⅖MR²,
    cone (3/20)MR² + (3/80)MH²) plus Mr², read back from the equation the exact roots solve."""
    cases = {
        ("disc", ()): 0.25 * 0.04,
        ("disc", (("length", 0.1),)): 0.25 * 0.04 + 0.01 / 12,
        ("ring", ()): 0.5 * 0.04,
        ("sphere", ()): 0.4 * 0.04,
        ("shell", ()): 2 / 3 * 0.04,
        ("cone", (("height", 0.3),)): 3 / 20 * 0.04 + 3 / 80 * 0.09,
    }
    r = 0.15
    for (shape, extra), centre in cases.items():
        report = taucli.gyro(shape=shape, mass=1, radius=0.2, spin=300, cm_distance=r, tilt="45 deg", **dict(extra))
        results = report.results
        slow, fast, big_l = results["omega_p_slow"].value, results["omega_p_fast"].value, results["L"].value
        perp_cos = big_l / (slow + fast)  # sum of the roots = L/(I⊥ cos θ)
        assert perp_cos / math.cos(math.radians(45)) == pytest.approx(centre + r * r, rel=1e-12), shape


def test_a_value_in_other_units_gives_the_same_answer():
    si = taucli.gyro(shape="disc", mass=0.3, radius=0.05, spin=4000 * 2 * math.pi / 60, cm_distance=0.05, tilt=f"{math.radians(30)!r} rad").results
    other = taucli.gyro(shape="disc", mass="300 g", radius="50 mm", spin="4000 rpm", cm_distance="5 cm", tilt="30 deg").results
    for key, value in si.items():
        assert other[key].value == pytest.approx(value.value, rel=1e-14), key


# --- refusals ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("given", "option", "fragment"),
    [
        ({"inertia": 0.01, "mass": 1, "cm_distance": 0.1}, "spin", "is required"),
        ({"inertia": 0.01, "spin": 10, "mass": 1}, "cm_distance", "is required"),
        ({"inertia": 0.01, "spin": 10, "cm_distance": 0.1}, "mass", "is required"),
        ({"inertia": 0.01, "spin": 10, "torque": 1, "cm_distance": 0.1}, "cm_distance", "conflicts with torque"),
        ({"inertia": 0.01, "spin": 10, "torque": 1, "inertia_perp": 0.1}, "inertia_perp", "conflicts with torque"),
        ({"inertia": 0.01, "spin": 10, "torque": 1, "mass": 2}, "mass", "goes with cm_distance"),
        ({"inertia": 0.01, "spin": 10, "torque": 1, "tilt": 0}, "tilt", "must be between 0 and 180 deg"),
        ({"inertia": 0.01, "spin": 10, "mass": 1, "cm_distance": 0.1, "tilt": "200 deg"}, "tilt", "expected an angle from 0 to 180"),
        ({"inertia": 0.01, "spin": 10, "mass": 1, "cm_distance": 0.1, "inertia_perp": 0.001}, "inertia_perp", "is less than I/2 + mr²"),
        ({"spin": 10, "mass": 1, "cm_distance": 0.1}, "inertia", "or shape is required"),
    ],
)
def test_what_cannot_be_used_is_refused_naming_the_parameter(given, option, fragment):
    with pytest.raises(InputError) as caught:
        taucli.gyro(**given)
    assert caught.value.option == option
    assert fragment in str(caught.value)


def test_the_command_line_answers_in_strict_json_with_steps():
    done = run_taucli("gyro", "--shape", "disc", "--mass", "0.3kg", "--radius", "5cm", "--spin", "4000rpm", "--cm-distance", "5cm", "--tilt", "30deg", "--json")
    assert done.code == 0, done.err
    document = done.json()
    assert document["scene"] == "gyro" and document["method"] == "closed form"
    titles = [step["title"] for step in document["steps"]]
    assert "The torque changes L's direction, not its size" in titles and "Why the approximation holds" in titles
    for extreme in (
        ("--shape", "disc", "--mass", "1e30", "--radius", "1e14", "--spin", "1e-40rad/s", "--cm-distance", "1e40", "--g", "1e40", "--tilt", "1deg"),
        ("--shape", "disc", "--mass", "1e30", "--radius", "1e14", "--spin", "1e40rad/s", "--cm-distance", "1e-40", "--tilt", "1e-30deg"),
        ("--shape", "disc", "--mass", "1e-30", "--radius", "1e-14", "--spin", "1e-40rad/s", "--cm-distance", "1e40", "--tilt", "179.99999deg"),
        ("--inertia", "1e-40", "--spin", "1e-40rad/s", "--mass", "1e-40", "--cm-distance", "1e-40", "--inertia-perp", "1e40", "--tilt", "89.9999999deg"),
        ("--inertia", "1e40", "--spin", "1e40rad/s", "--torque", "1e-40", "--tilt", "1e-30deg"),
    ):
        done = run_taucli("gyro", *extreme, "--json")
        assert done.code == 0, (extreme, done.err)
        done.json()  # strict: no NaN or Infinity
    refused = run_taucli("gyro", "--inertia", "0.01", "--spin", "10rad/s", "--torque", "1N*m", "--cm-distance", "5cm")
    assert refused.code == 2
    assert refused.err.strip() == "taucli: error: --cm-distance conflicts with --torque: with the torque given, only the gyroscopic rate Ω = τ/(L sin θ) is formed"


# --- a rotor whose axis a vehicle turns: the gyroscopic couple (#35 item 5) ---------------------


def reactive_couple(inertia, spin, spin_axis, rate, turn_axis):
    """The couple the rotor puts on the vehicle, from the physics: L(t) = R(Ωt) L₀ (L₀ turned
    about the turn's axis at Ω, Rodrigues' rotation), the frame applies dL/dt at t = 0 (mpmath's
    numerical derivative at 40 digits), and the rotor pushes back with minus that."""
    k = [mpmath.mpf(c) for c in turn_axis]
    l0 = [mpmath.mpf(inertia) * mpmath.mpf(spin) * mpmath.mpf(c) for c in spin_axis]

    def turned(t, i):
        angle = mpmath.mpf(rate) * t
        k_cross_l = [k[1] * l0[2] - k[2] * l0[1], k[2] * l0[0] - k[0] * l0[2], k[0] * l0[1] - k[1] * l0[0]]
        k_dot_l = sum(a * b for a, b in zip(k, l0))
        return l0[i] * mpmath.cos(angle) + k_cross_l[i] * mpmath.sin(angle) + k[i] * k_dot_l * (1 - mpmath.cos(angle))

    return [-mpmath.diff(lambda t: turned(t, i), 0) for i in range(3)]


def test_khurmi_aeroplane_in_a_left_turn():
    """Khurmi & Gupta, Theory of Machines, Example 14.2: an aeroplane makes a half circle of 50 m
    radius to the left at 200 km/h; engine and propeller 400 kg, radius of gyration 0.3 m, 2400 rpm
    clockwise seen from the rear. The book: C = 10.046 kN·m (with ω and Ω rounded to 251.4 and
    1.11 rad/s); the effect is to raise the nose and dip the tail."""
    report = taucli.gyro(inertia="400kg*(0.3m)^2", spin="2400 rpm", precession="(200 km/h)/(50 m)",
                         spin_sense="cw-from-rear", turn="left", craft="aircraft")
    couple = report.results["couple"].value
    assert couple == pytest.approx(10046, rel=1e-3)
    with mpmath.workdps(40):
        want = mpmath.mpf(36) * 2400 * 2 * mpmath.pi / 60 * (mpmath.mpf(200) / 3.6 / 50)
    assert relative(couple, want) < 1e-14
    assert report.results["effect"].value == "raises the nose and dips the tail"


@pytest.mark.parametrize(
    "sense, turn, effect",
    [  # the four cases of the problem's variants (as the theory-of-machines texts tabulate them)
        ("cw-from-rear", "left", "raises the nose and dips the tail"),
        ("cw-from-rear", "right", "lowers the nose and raises the tail"),
        ("cw-from-front", "left", "lowers the nose and raises the tail"),
        ("cw-from-front", "right", "raises the nose and dips the tail"),
    ],
)
def test_aircraft_effects_as_the_books_tabulate_them(sense, turn, effect):
    report = taucli.gyro(inertia=36, spin="2400 rpm", precession="1 rad/s", spin_sense=sense, turn=turn, craft="aircraft")
    assert report.results["effect"].value == effect


def test_khurmi_ship_steering_left():
    """Khurmi & Gupta, Theory of Machines, Example 14.3: a ship's turbine rotor, 8 tonnes, radius of
    gyration 0.6 m, 1800 rpm clockwise seen from the stern; the ship at 100 km/h steers to the left
    on a curve of 75 m radius. The book: C = 200.866 kN·m (ω and Ω rounded to 188.5 and 0.37 rad/s);
    the effect is to raise the bow and lower the stern."""
    report = taucli.gyro(inertia="8000kg*(0.6m)^2", spin="1800 rpm", precession="(100 km/h)/(75 m)",
                         spin_sense="cw-from-rear", turn="left", craft="ship")
    assert report.results["couple"].value == pytest.approx(200866, rel=2e-3)
    assert report.results["effect"].value == "raises the bow and lowers the stern"


@pytest.mark.parametrize(
    "turn, effect",
    [  # a rotor clockwise seen from the stern (the texts' table of a ship's gyroscopic effects)
        ("left", "raises the bow and lowers the stern"),
        ("right", "lowers the bow and raises the stern"),
        ("pitch-up", "turns the ship towards starboard"),
        ("pitch-down", "turns the ship towards port"),
    ],
)
def test_a_ships_effects_steering_and_pitching(turn, effect):
    report = taucli.gyro(inertia=700, spin="3000 rpm", precession="0.1 rad/s", spin_sense="cw-from-rear", turn=turn, craft="ship")
    assert report.results["effect"].value == effect


def test_khurmi_ship_pitching_bow_falling():
    """Khurmi & Gupta, Theory of Machines, Example 14.4: a rotor of 3500 kg, radius of gyration 0.45 m,
    3000 rpm clockwise seen from the stern; (1) steering left on 100 m at 36 km/h: 22.27 kN·m, raising
    the bow; (2) pitching in SHM of period 40 s through 12° in all, the bow falling at its fastest:
    Ω_max = (6° in rad)(2π/40 s), the couple turns the ship towards port."""
    inertia = "3500kg*(0.45m)^2"
    steering = taucli.gyro(inertia=inertia, spin="3000 rpm", precession="(36 km/h)/(100 m)", spin_sense="cw-from-rear", turn="left", craft="ship")
    assert round(steering.results["couple"].value / 1000, 2) == 22.27
    assert steering.results["effect"].value == "raises the bow and lowers the stern"
    peak_rate = math.radians(6) * 2 * math.pi / 40
    pitching = taucli.gyro(inertia=inertia, spin="3000 rpm", precession=peak_rate, spin_sense="cw-from-rear", turn="pitch-down", craft="ship")
    assert pitching.results["couple"].value == pytest.approx(3500 * 0.45**2 * 100 * math.pi * peak_rate, rel=1e-14)
    assert pitching.results["effect"].value == "turns the ship towards port"


def test_irodov_ship_on_an_arc_bearing_moment():
    """Irodov, Problems in General Physics, §1.6: a ship at 36 km/h on an arc of radius 200 m; a
    flywheel of I = 3.8·10³ kg·m² at 300 rpm along the ship's length. The moment of the gyroscopic
    forces on the bearings: N = 2πnIv/R = 6 kN·m."""
    report = taucli.gyro(inertia="3.8e3 kg*m^2", spin="300 rpm", precession="(36 km/h)/(200 m)", bearing_span="2 m")
    assert round(report.results["couple"].value / 1000, 1) == 6.0
    assert report.results["bearing_force"].value == pytest.approx(report.results["couple"].value / 2, rel=1e-15)
    assert any("spin_sense and turn" in note for note in report.notes)  # Python spells keywords (#42)


SENSES = [f"{t}-from-{e}" for t in ("cw", "ccw") for e in ("rear", "front", "left", "right", "above", "below")]
TURN_AXES = {"left": (0, 0, 1), "right": (0, 0, -1), "pitch-up": (0, -1, 0), "pitch-down": (0, 1, 0), "roll-right": (1, 0, 0), "roll-left": (-1, 0, 0)}
# Where a viewer stands, from the rotor: clockwise seen from there is a spin pointing away from them.
VIEWERS = {"rear": (-1, 0, 0), "front": (1, 0, 0), "left": (0, 1, 0), "right": (0, -1, 0), "above": (0, 0, 1), "below": (0, 0, -1)}


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(SENSES), st.sampled_from(sorted(TURN_AXES)), st.floats(0.01, 10), st.floats(1, 1e4), st.one_of(st.just(0.0), st.floats(0.01, 1.4), st.floats(-1.4, -0.01)))
def test_the_couple_against_the_turned_angular_momentum(sense, turn, inertia, rate, lean):
    """The couple's size against −dL/dt of L turned about the turn's axis (mpmath), the spin axis
    first turned by the lean about the forward axis; and the words name the largest component."""
    report = taucli.gyro(inertia=inertia, spin="1000 rpm", precession=rate, spin_sense=sense, turn=turn, lean=lean)
    clockwise, _, viewer = sense.split("-", 2)
    axis = [(-1 if clockwise == "cw" else 1) * c for c in VIEWERS[viewer]]
    c, s = mpmath.cos(lean), mpmath.sin(lean)
    axis = [axis[0], c * axis[1] - s * axis[2], s * axis[1] + c * axis[2]]
    with mpmath.workdps(40):
        want = reactive_couple(inertia, 1000 * 2 * mpmath.pi / 60, axis, rate, TURN_AXES[turn])
        size = mpmath.sqrt(sum(w * w for w in want))
    scale = inertia * 1000 * 2 * math.pi / 60 * rate
    assert abs(report.results["couple"].value - float(size)) <= 1e-13 * scale
    effect = report.results["effect"].value
    if float(size) < 1e-9 * scale:
        assert report.results["couple"].value <= 1e-12 * scale
        return
    biggest = max(range(3), key=lambda i: abs(want[i]))
    words = {(0, 1): "rolls the vehicle to the right", (0, -1): "rolls the vehicle to the left", (1, -1): "raises the front", (1, 1): "lowers the front",
             (2, 1): "turns the vehicle to the left", (2, -1): "turns the vehicle to the right"}
    assert words[(biggest, 1 if want[biggest] > 0 else -1)] in effect


def test_a_roll_about_the_spin_axis_gives_no_couple():
    """A fore-and-aft rotor when the ship rolls: the axis turns about itself, L keeps its direction."""
    report = taucli.gyro(inertia=700, spin="3000 rpm", precession="0.03 rad/s", spin_sense="cw-from-rear", turn="roll-right", craft="ship")
    assert report.results["couple"].value == 0
    assert report.results["effect"].value == "none"
    assert any("no gyroscopic couple" in note for note in report.notes)


def test_a_leaning_two_wheeler_feels_c_cos_lean_and_is_rolled_outward():
    """Road wheels rolling forward spin clockwise seen from the right; in a right-hand turn leaning
    θ into it, the wheels' couple is Iω_sΩ cos θ and rolls the machine outward, to the left (the
    theory-of-machines texts' two-wheeler: C cos θ, an overturning couple)."""
    upright = taucli.gyro(inertia=2.0, spin="100 rad/s", precession="0.5 rad/s", spin_sense="cw-from-right", turn="right")
    leaning = taucli.gyro(inertia=2.0, spin="100 rad/s", precession="0.5 rad/s", spin_sense="cw-from-right", turn="right", lean="30 deg")
    assert upright.results["couple"].value == 100.0
    assert leaning.results["couple"].value == pytest.approx(100 * math.cos(math.radians(30)), rel=1e-15)
    assert upright.results["effect"].value == leaning.results["effect"].value == "rolls the vehicle to the left"


def test_bearing_forces_and_their_senses():
    """F = C/l at each bearing, opposite; the rotor of the ship steering left pushes the bow-end
    bearing up (it raises the bow)."""
    report = taucli.gyro(inertia="8000kg*(0.6m)^2", spin="1800 rpm", precession="(100 km/h)/(75 m)", spin_sense="cw-from-rear",
                         turn="left", craft="ship", bearing_span="3 m")
    assert report.results["bearing_force"].value == pytest.approx(report.results["couple"].value / 3, rel=1e-15)
    assert any("bearing at its bow end up and the one at its stern end down" in note for note in report.notes)


def test_the_couple_is_the_same_in_any_units():
    si = taucli.gyro(inertia=36, spin=251.32741228718345, precession=1.1111111111111112).results["couple"].value
    us = taucli.gyro(inertia="26.552 slug*ft^2", spin="40 rev/s", precession="(200 km/h)/(50 m)").results["couple"].value
    assert us == pytest.approx(si * 26.552 * 1.3558179483314004 / 36, rel=1e-12)


@pytest.mark.parametrize(
    "argv, fragments",
    [
        (("--inertia", "1", "--spin", "100rpm", "--turn", "left"), ("--turn", "goes with --precession")),
        (("--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--turn", "left"), ("--spin-sense", "is required")),
        (("--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--cm-distance", "1m"), ("--cm-distance", "conflicts with --precession")),
        (("--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--lean", "10deg"), ("--lean", "goes with --spin-sense and --turn")),
        (("--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--mass", "2kg"), ("--mass", "goes with --shape")),
        (("--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--spin-sense", "cw-from-rear", "--turn", "left", "--tilt", "30deg"),
         ("--tilt", "conflicts")),
        (("--inertia", "1", "--spin", "100rpm", "--precession", "-1rad/s"), ("--precession",)),
    ],
)
def test_machine_refusals_are_one_line(argv, fragments):
    from conftest import assert_usage_error

    assert_usage_error(run_taucli("gyro", *argv), *fragments)


# --- the orbit of the centre of mass and the pivot's force (#34 item 11) ------------------------


def test_the_openstax_gyroscope_orbit_and_pivot_force():
    """OpenStax's 0.3 kg disc, centre 5 cm from the pivot, horizontal, at 20 rev/s: the centre of
    mass goes round a 5 cm circle at Ω; the pivot holds mg up and pushes mΩ²r in (from the physics:
    the centre's position r(t) = r(cos Ωt, sin Ωt, 0), its acceleration by mpmath's derivative)."""
    report = taucli.gyro(shape="disc", mass="0.3 kg", radius="5 cm", spin="20 rev/s", cm_distance="5 cm", g="9.8 m/s^2")
    rate = report.results["omega_p_slow"].value
    with mpmath.workdps(40):
        position = lambda t: [mpmath.mpf("0.05") * mpmath.cos(rate * t), mpmath.mpf("0.05") * mpmath.sin(rate * t)]  # noqa: E731
        accel = [mpmath.diff(lambda t: position(t)[i], 0, 2) for i in range(2)]
        velocity = [mpmath.diff(lambda t: position(t)[i], 0) for i in range(2)]
        inward = mpmath.mpf("0.3") * mpmath.sqrt(sum(a * a for a in accel))
        orbital = mpmath.mpf("0.3") * (position(0)[0] * velocity[1] - position(0)[1] * velocity[0])
    assert relative(report.results["pivot_force_horizontal"].value, inward) < 1e-13
    assert relative(report.results["L_orbital"].value, orbital) < 1e-13
    assert report.results["pivot_force_vertical"].value == pytest.approx(0.3 * 9.8, rel=1e-15)


def test_a_tilted_tops_orbit_uses_the_exact_rate_and_r_sin_theta():
    """Tilted 30°, the circle is r sin θ across and the rate the exact slow one."""
    report = taucli.gyro(shape="disc", mass="0.3 kg", radius="5 cm", spin="4000 rpm", cm_distance="5 cm", tilt="30 deg")
    slow = report.results["omega_p_slow"].value
    circle = 0.05 * math.sin(math.radians(30))
    assert report.results["pivot_force_horizontal"].value == pytest.approx(0.3 * slow**2 * circle, rel=1e-14)
    assert report.results["L_orbital"].value == pytest.approx(0.3 * 0.05 * slow * circle, rel=1e-14)


def test_no_steady_precession_has_no_orbit():
    report = taucli.gyro(shape="disc", mass="100 g", radius="3 cm", cm_distance="4 cm", spin="10 rev/s", tilt="20 deg")
    assert report.results["L_orbital"].value is None and report.results["pivot_force_horizontal"].value is None
    assert any("no steady orbit" in note for note in report.notes)


def test_khurmi_automobile_wheels_and_engine_add():
    """Khurmi & Gupta, Theory of Machines, ch. 14: a four-wheeled car, each wheel 2.4 kg·m² and
    660 mm across, the engine's rotating parts 1.2 kg·m² geared 3 : 1 to the back wheels, turning
    the same way as the wheels, on a curve of 80 m: the gyroscopic couple (4I_W + G·I_E)v²/(r_W R)
    = 0.5v² N·m, overturning the car outward. Here at 20 m/s: 200 N·m, as the engine given as a
    rotor of its own beside the four wheels; turned the other way round, it takes away."""
    v, r_w, radius = 20.0, 0.33, 80.0
    report = taucli.gyro(inertia=4 * 2.4, spin=v / r_w, precession=v / radius, spin_sense="cw-from-right", turn="left",
                         rotor=[f"inertia=1.2kg*m^2 spin={3 * v / r_w!r}rad/s sense=cw-from-right"])
    assert report.results["couple"].value == pytest.approx(0.5 * v * v, rel=1e-14)
    assert report.results["effect"].value == "rolls the vehicle to the right"  # outward from a left-hand curve
    against = taucli.gyro(inertia=4 * 2.4, spin=v / r_w, precession=v / radius, spin_sense="cw-from-right", turn="left",
                          rotor=[f"inertia=1.2kg*m^2 spin={3 * v / r_w!r}rad/s sense=ccw-from-right"])
    assert against.results["couple"].value == pytest.approx((4 * 2.4 - 3 * 1.2) * v * v / (r_w * radius), rel=1e-14)


def test_rotors_need_their_senses():
    from conftest import assert_usage_error

    assert_usage_error(run_taucli("gyro", "--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--rotor", "inertia=1 spin=1rad/s sense=cw-from-rear"),
                       "--rotor", "goes with --spin-sense and --turn")
    assert_usage_error(run_taucli("gyro", "--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--spin-sense", "cw-from-rear", "--turn", "left",
                                  "--rotor", "inertia=1 spin=1rad/s sense=sideways"), "--rotor", "sense=")
    assert_usage_error(run_taucli("gyro", "--inertia", "1", "--spin", "100rpm", "--precession", "1rad/s", "--spin-sense", "cw-from-rear", "--turn", "left",
                                  "--rotor", "inertia=1 spin=1rad/s"), "--rotor", "needs sense=")


def test_a_couple_zero_by_the_geometry_is_zero_in_every_direction():
    """#42 item 10: for every spin sense, turn and lean of whole right angles (and 45°), the couple
    is |L × Ω| with L along the spin axis (towards the viewer for ccw: the right-hand rule) leaned
    about the forward axis; where L lies along the turn's axis it is exactly 0 and no effect is
    named (a lean of 90deg read as a float near π/2 once left 6.1e-15 N·m "rolling to the right")."""
    from taucli.options.gyro import SPIN_SENSES, TURNS

    toward = {"rear": (-1, 0, 0), "front": (1, 0, 0), "left": (0, 1, 0), "right": (0, -1, 0), "above": (0, 0, 1), "below": (0, 0, -1)}
    axes = {"left": (0, 0, 1), "right": (0, 0, -1), "pitch-up": (0, -1, 0), "pitch-down": (0, 1, 0), "roll-right": (1, 0, 0), "roll-left": (-1, 0, 0)}
    spin, omega = 100, 1
    with mpmath.workdps(50):
        for sense in SPIN_SENSES:
            turn_word, _, end = sense.split("-", 2)
            x, y, z = (c * (1 if turn_word == "ccw" else -1) for c in toward[end])
            for lean in (0, 45, 90, 180, 270, -90):
                c, s = mpmath.cos(mpmath.radians(lean)), mpmath.sin(mpmath.radians(lean))
                L = [spin * mpmath.mpf(x), spin * (c * y - s * z), spin * (s * y + c * z)]
                for turn in TURNS:
                    a = [omega * k for k in axes[turn]]
                    cross = [L[1] * a[2] - L[2] * a[1], L[2] * a[0] - L[0] * a[2], L[0] * a[1] - L[1] * a[0]]
                    want = mpmath.sqrt(sum(k * k for k in cross))
                    r = taucli.gyro(inertia=1, spin="100 rad/s", precession="1 rad/s", spin_sense=sense, turn=turn, lean=f"{lean} deg").results
                    if want < 1e-30:
                        assert r["couple"].value == 0, (sense, turn, lean, r["couple"].value)
                        assert r["effect"].value == "none", (sense, turn, lean, r["effect"].value)
                    else:
                        assert r["couple"].value == pytest.approx(float(want), rel=1e-14), (sense, turn, lean)


def test_a_rotor_turned_about_its_own_axis_by_tilt_has_no_couple():
    """--tilt 180deg: the spin axis is along the axis it is turned about (sin 180° = 0), so C = 0."""
    assert taucli.gyro(inertia=1, spin="100 rad/s", precession="1 rad/s", tilt="180 deg").results["couple"].value == 0
