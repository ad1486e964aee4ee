"""flywheel from the turning-moment diagram T(θ) itself (#47 item 4): a formula of theta, or its
samples in a CSV file (crank angle and torque), giving the mean torque, the mean power and ΔE.

References are written from the physics in mpmath: T_mean = (1/Θ)∫₀^Θ T dθ by mpmath.quad, the
flywheel's energy E(θ) = ∫₀^θ (T − T_mean) dθ at its stationary points, the roots of T = T_mean
found by mpmath.findroot from a fine grid's sign changes, and ΔE = max E − min E. For samples the
curve is the polyline through them (the trapezoid rule's), integrated by mpmath.quad piece by piece;
and samples of a formula converge to the formula's ΔE as they get denser (O(h²))."""

from __future__ import annotations

import json
import math
import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error

KHURMI = "(15000 + 10000*sin(2*theta) - 6000*cos(2*theta)) N*m"


def _reference(torque, cycle):
    """(T_mean, ΔE) of T(θ) (an mpmath function) over [0, cycle], from the physics."""
    cycle = mpmath.mpf(cycle)
    mean = mpmath.quad(torque, mpmath.linspace(0, cycle, 17)) / cycle
    excess = lambda theta: torque(theta) - mean  # noqa: E731
    grid = mpmath.linspace(0, cycle, 721)
    roots = []
    for a, b in zip(grid, grid[1:]):
        if excess(a) * excess(b) < 0:
            roots.append(mpmath.findroot(excess, (a, b), solver="anderson"))
    points = sorted([mpmath.mpf(0), *roots, cycle])
    energies, energy = [mpmath.mpf(0)], mpmath.mpf(0)
    for a, b in zip(points, points[1:]):
        energy += mpmath.quad(excess, [a, b])
        energies.append(energy)
    return mean, max(energies) - min(energies)


def _polyline(samples):
    """The polyline through SI samples, as an mpmath function, and its breakpoints."""
    xs = [mpmath.mpf(a) for a, _ in samples]
    ys = [mpmath.mpf(t) for _, t in samples]

    def torque(theta):
        for k in range(len(xs) - 1):
            if xs[k] <= theta <= xs[k + 1]:
                return ys[k] + (ys[k + 1] - ys[k]) * (theta - xs[k]) / (xs[k + 1] - xs[k])
        return ys[-1]

    return torque, xs


def _polyline_reference(samples):
    torque, xs = _polyline(samples)
    cycle = xs[-1] - xs[0]
    mean = mpmath.fsum(mpmath.quad(torque, [a, b]) for a, b in zip(xs, xs[1:])) / cycle
    excess = lambda theta: torque(theta) - mean  # noqa: E731
    points = [xs[0]]
    for a, b in zip(xs, xs[1:]):
        if excess(a) * excess(b) < 0:
            points.append(mpmath.findroot(excess, (a, b), solver="bisect"))
        points.append(b)
    energies, energy = [mpmath.mpf(0)], mpmath.mpf(0)
    for a, b in zip(points, points[1:]):
        energy += mpmath.quad(excess, [a, b])
        energies.append(energy)
    return mean, max(energies) - min(energies)


def test_khurmi_engine_formula():
    """Khurmi & Gupta, Theory of Machines ch. 16: T = 15000 + 10000 sin 2θ − 6000 cos 2θ N·m at a mean
    600 rpm, the speed within ±1 % of it. T_mean = 15000 N·m, P = 942.5 kW, ΔE = 2√(5000² + 3000²)
    = 11 662 N·m, I = ΔE/(ω²Cs) = 147.7 kg·m² (the book's, to its rounding)."""
    report = taucli.flywheel(turning_moment=KHURMI, omega_mean="600 rpm", speed_variation=0.01)
    results = report.results
    mean, swing = _reference(lambda th: 15000 + 10000 * mpmath.sin(2 * th) - 6000 * mpmath.cos(2 * th), 2 * mpmath.pi)
    assert results["torque_mean"].value == pytest.approx(float(mean), rel=1e-12)
    assert results["energy_swing"].value == pytest.approx(float(swing), rel=1e-10)
    assert float(swing) == pytest.approx(2 * math.hypot(5000, 3000), rel=1e-12)
    assert results["power_mean"].value == pytest.approx(float(mean * 20 * mpmath.pi), rel=1e-12)
    assert round(results["power_mean"].value / 1000, 1) == 942.5
    assert round(results["energy_swing"].value) == 11662
    assert round(results["I"].value, 1) == 147.7
    titles = [step.title for step in report.steps]
    assert "Mean torque" in titles and "Maximum fluctuation of energy" in titles and "Mean power" in titles


def test_gate_two_stroke_power():
    """GATE (ME): T = 10000 + 1000 sin 2θ − 1200 cos 2θ N·m on a two-stroke engine at 100 rpm, the
    resisting torque constant: the power is 104.719 kW."""
    results = taucli.flywheel(turning_moment="(10000 + 1000*sin(2*theta) - 1200*cos(2*theta)) N*m", omega_mean="100 rpm", fluctuation=0.01).results
    assert round(results["power_mean"].value / 1000, 3) == 104.720  # the book's 104.719 kW: 10000 × 10.472 rad/s
    assert results["power_mean"].value == pytest.approx(10000 * 100 * 2 * math.pi / 60, rel=1e-12)


@pytest.mark.parametrize("seed", range(3))
def test_random_periodic_formulas_against_mpmath(seed):
    """T = a + Σ bₖ sin(kθ/n) + cₖ cos(kθ/n): n = 1 repeats over 360°, n = 2 only over 720° (a
    four-stroke's cycle, found by itself)."""
    rng = random.Random(4747 + seed)
    for _ in range(2):
        n = rng.choice((1, 2))
        a = round(rng.uniform(500, 20000), 1)
        terms = [(k, round(rng.uniform(-0.6, 0.6) * a, 1), round(rng.uniform(-0.6, 0.6) * a, 1)) for k in (1, 2, 3)]
        inner = "theta" if n == 1 else "theta/2"
        text = f"({a!r}" + "".join(f" + {b!r}*sin({k}*{inner}) + {c!r}*cos({k}*{inner})" for k, b, c in terms).replace("+ -", "- ") + ") N*m"
        results = taucli.flywheel(turning_moment=text, inertia="30 kg*m^2", omega_mean="300 rpm").results

        def torque(th, a=a, terms=terms, n=n):
            return mpmath.mpf(a) + mpmath.fsum(mpmath.mpf(b) * mpmath.sin(k * th / n) + mpmath.mpf(c) * mpmath.cos(k * th / n) for k, b, c in terms)

        mean, swing = _reference(torque, 2 * n * mpmath.pi)
        assert results["torque_mean"].value == pytest.approx(float(mean), rel=1e-11), text
        assert results["energy_swing"].value == pytest.approx(float(swing), rel=1e-9), text


def test_a_polynomial_over_the_cycle_given_is_integrated_exactly():
    """T = θ(Θ − θ)·(100 N·m) over Θ = 180° (a polynomial: no period of its own, so --cycle-angle)."""
    results = taucli.flywheel(turning_moment="theta*(pi - theta)*(100 N*m)", cycle_angle="180 deg", inertia="1 kg*m^2", omega_mean="100 rad/s").results
    mean, swing = _reference(lambda th: th * (mpmath.pi - th) * 100, mpmath.pi)
    assert results["torque_mean"].value == pytest.approx(float(mean), rel=1e-13)
    assert results["energy_swing"].value == pytest.approx(float(swing), rel=1e-12)


@pytest.mark.parametrize("seed", range(3))
def test_random_samples_against_their_polyline(seed):
    rng = random.Random(474 + seed)
    for _ in range(4):
        count = rng.randint(3, 40)
        angles = sorted(rng.sample(range(0, 7200), count))
        samples = [(math.radians(a / 10), rng.uniform(-2000, 9000)) for a in angles]
        results = taucli.flywheel(turning_moment=samples, inertia="10 kg*m^2", omega_mean="500 rpm").results
        mean, swing = _polyline_reference(samples)
        assert results["torque_mean"].value == pytest.approx(float(mean), rel=1e-11)
        assert results["energy_swing"].value == pytest.approx(float(swing), rel=1e-9, abs=1e-9 * float(max(abs(t) for _, t in samples)))


def test_a_table_every_15_degrees_from_a_file_and_denser_samples_approach_the_formula(tmp_path, taucli):
    """The Khurmi engine tabulated every 15° (as a book prints its table) in kN·m: the CSV file gives
    the polyline's ΔE; samples every ½° come within 1e-4 of the formula's (the trapezoid's O(h²))."""
    def khurmi(th):
        return 15000 + 10000 * math.sin(2 * th) - 6000 * math.cos(2 * th)

    table = [(d, khurmi(math.radians(d)) / 1000) for d in range(0, 361, 15)]
    path = tmp_path / "engine.csv"
    path.write_text("crank angle [deg], torque [kN*m]\n" + "".join(f"{d}, {t!r}\n" for d, t in table), encoding="utf-8")
    done = taucli("flywheel", "--turning-moment", str(path), "--omega-mean", "600rpm", "--speed-variation", "0.01", "--json")
    assert done.code == 0, done.err
    results = done.json()["results"]
    mean, swing = _polyline_reference([(math.radians(d), t * 1000) for d, t in table])
    assert results["energy_swing"]["value"] == pytest.approx(float(swing), rel=1e-10)
    assert results["torque_mean"]["value"] == pytest.approx(float(mean), rel=1e-12)
    dense = [(math.radians(k / 2), khurmi(math.radians(k / 2))) for k in range(0, 721)]
    close = taucli_api_swing(dense)
    assert close == pytest.approx(2 * math.hypot(5000, 3000), rel=1e-4)


def taucli_api_swing(samples):
    import taucli as api

    return api.flywheel(turning_moment=samples, fluctuation=0.02, omega_mean="600 rpm").results["energy_swing"].value


def test_a_cycle_longer_than_the_samples_closes_on_the_first_torque():
    """Samples 0°…300° of a 360° cycle: the last segment runs back to T(0) at 360°."""
    samples = [(math.radians(d), t) for d, t in ((0, 100.0), (60, 400.0), (120, 50.0), (180, 300.0), (240, 0.0), (300, 200.0))]
    closed = taucli.flywheel(turning_moment=samples, cycle_angle="360 deg", inertia="1 kg*m^2", omega_mean="100 rad/s").results
    mean, swing = _polyline_reference([*samples, (2 * math.pi, 100.0)])
    assert closed["torque_mean"].value == pytest.approx(float(mean), rel=1e-12)
    assert closed["energy_swing"].value == pytest.approx(float(swing), rel=1e-10)


def test_batch_python_and_the_command_line_agree(taucli, tmp_path):
    line = {"turning_moment": KHURMI, "omega_mean": "600 rpm", "speed_variation": 0.01}
    done = taucli("flywheel", "--batch", "--no-steps", stdin=json.dumps(line) + "\n")
    assert done.code == 0, done.err
    batch = json.loads(done.out.splitlines()[0])["results"]
    api = taucli_results(line)
    for key in ("energy_swing", "torque_mean", "power_mean", "I"):
        assert batch[key]["value"] == api[key].value


def taucli_results(line):
    import taucli as api

    return api.flywheel(**line).results


def test_the_loops_with_their_mean_torque_give_the_mean_power():
    """The loops are measured from the mean torque line: given its height, P = T_mean ω_mean; without
    it, the loops give no mean torque, and none is invented."""
    loops = dict(loops="295,-685,40,-340,960,-270", scale_torque="5 N*m", scale_angle="1 deg", inertia="1 kg*m^2", omega_mean="300 rpm")
    results = taucli.flywheel(**loops, torque_mean="2.5 kN*m").results
    assert results["torque_mean"].value == 2500.0
    assert results["power_mean"].value == pytest.approx(2500 * 10 * math.pi, rel=1e-14)
    alone = taucli.flywheel(**loops).results
    assert "torque_mean" not in alone and "power_mean" not in alone


@pytest.mark.parametrize(("args", "named"), [
    (["--turning-moment", "no-such-diagram.csv"], "--turning-moment"),
    (["--turning-moment", "(15000 + 100*sin(2*x)) N*m"], "'x' is not a unit"),
    (["--turning-moment", "(15000 + 100*sin(2*t)) N*m"], "t is not its variable"),
    (["--turning-moment", "(15000 + 100*sin(2*theta)) N"], "not a torque"),
    (["--turning-moment", "15000 N*m"], "constant torque"),
    (["--turning-moment", "theta*(1 N*m)"], "--cycle-angle"),
    (["--turning-moment", KHURMI, "--energy-swing", "3kJ"], "--energy-swing"),
    (["--turning-moment", KHURMI, "--loops", "1,-1", "--scale-torque", "1N*m", "--scale-angle", "1deg"], "--loops"),
    (["--turning-moment", KHURMI, "--torque-mean", "1N*m"], "--torque-mean"),
    (["--cycle-angle", "360deg"], "--cycle-angle"),
    (["--torque-mean", "1N*m"], "--torque-mean"),
])
def test_refusals(taucli, args, named):
    assert_usage_error(taucli("flywheel", *args, "--omega-mean", "600rpm", "--speed-variation", "0.01"), named)


@pytest.mark.parametrize(("text", "named"), [
    ("theta [deg], torque [N*m]\n0, 1\n30, 2\n20, 3\n", "line 4: the angle must increase"),
    ("theta [deg], torque [N*m]\n0, 1\n30, 2\n", "at least 3"),
    ("theta, torque [N*m]\n0, 1\n30, 2\n60, 1\n", "the angle column's unit"),
    ("theta [deg], torque [N]\n0, 1\n30, 2\n60, 1\n", "torque column"),
    ("theta [deg], torque [N*m]\n0, 1\n30, x\n60, 1\n", "line 3"),
    ("theta [deg], torque [N*m]\n0, 1\n300, 2\n360, 1\n", "--cycle-angle"),
])
def test_a_bad_file_is_refused_naming_the_option(taucli, tmp_path, text, named):
    path = tmp_path / "diagram.csv"
    path.write_text(text, encoding="utf-8")
    extra = ["--cycle-angle", "180deg"] if "360, 1" in text else []
    assert_usage_error(taucli("flywheel", "--turning-moment", str(path), *extra, "--omega-mean", "600rpm", "--speed-variation", "0.01"), named)


def test_sines_and_cosines_of_theta_are_integrated_in_closed_form():
    """A polynomial plus sines and cosines of multiples of θ (with phases, numbers and units) is
    integrated exactly: ∫₀^θ and ∫₀^θ∫ against mpmath to rounding; a formula of t keeps its quadrature."""
    from taucli.quantities import units
    from taucli.quantities.formula import ANGLE, read_formula

    text = "(3*sin(theta/2 + 0.3) + 2 kN*m/(1 N*m)*cos(-3*theta) - 2*theta + 5*(4*sin(theta)) - cos(2 theta)/4)*(2 N*m)/2"
    formula = read_formula(text, "turning_moment", units.KINDS["torque"], ANGLE)
    assert formula.exact and formula.coefficients is None

    def torque(x):
        return 3 * mpmath.sin(x / 2 + mpmath.mpf("0.3")) + 2000 * mpmath.cos(3 * x) - 2 * x + 20 * mpmath.sin(x) - mpmath.cos(2 * x) / 4

    for theta in (1e-7, 0.01, 0.7, 2.5, 9.0):
        first = mpmath.quad(torque, [0, theta])
        second = mpmath.quad(lambda x: (theta - x) * torque(x), [0, theta])
        assert formula.first(theta) == pytest.approx(float(first), rel=1e-13, abs=1e-15)
        assert formula.second(theta) == pytest.approx(float(second), rel=1e-13, abs=1e-15)
        assert formula.at(theta) == pytest.approx(float(torque(theta)), rel=1e-13, abs=1e-12)
    assert not read_formula("3 N*m * sin(2 rad/s * t)", "torque", units.KINDS["torque"]).exact
    report = taucli.flywheel(turning_moment=KHURMI, omega_mean="600 rpm", speed_variation=0.01)
    assert report.method.startswith("closed-form")


def test_a_formula_the_grammar_cannot_integrate_goes_to_quadrature():
    text = "(1000 + 300*sqrt(1 + 0.5*sin(theta)) - 200*cos(theta)^2) N*m"
    report = taucli.flywheel(turning_moment=text, inertia="5 kg*m^2", omega_mean="300 rpm")
    assert report.method.startswith("Gauss")
    mean, swing = _reference(lambda th: 1000 + 300 * mpmath.sqrt(1 + mpmath.sin(th) / 2) - 200 * mpmath.cos(th) ** 2, 2 * mpmath.pi)
    assert report.results["torque_mean"].value == pytest.approx(float(mean), rel=1e-12)
    assert report.results["energy_swing"].value == pytest.approx(float(swing), rel=1e-9)


def test_too_long_a_table_is_refused_before_it_is_held(taucli, tmp_path):
    from taucli.answering.turning import MAX_SAMPLES

    path = tmp_path / "long.csv"
    path.write_text("theta [deg], torque [N*m]\n" + "".join(f"{k / 1000!r}, {k % 7}\n" for k in range(MAX_SAMPLES + 1)), encoding="utf-8")
    assert_usage_error(taucli("flywheel", "--turning-moment", str(path), "--omega-mean", "600rpm", "--speed-variation", "0.01"), "more than")
    with pytest.raises(taucli_input_error()):
        import taucli as api

        api.flywheel(turning_moment=[(k, 1.0) for k in range(MAX_SAMPLES + 1)], omega_mean="600 rpm", speed_variation=0.01)


def taucli_input_error():
    from taucli.core.errors import InputError

    return InputError


def test_python_pairs_are_checked(tmp_path):
    from taucli.core.errors import InputError

    for bad, named in (([(0, 1), (1, 2)], "at least 3"), ([(0, 1), (2, 2), (1, 3)], "sample 3"), ([(0, 1), (1, "x"), (2, 3)], "pairs"),
                       ([(0, 1), (1, float("nan")), (2, 3)], "finite"), (42, "formula of theta")):
        with pytest.raises(InputError, match=named):
            taucli.flywheel(turning_moment=bad, omega_mean="600 rpm", speed_variation=0.01)


def test_samples_that_stop_short_of_a_turn_are_noted():
    """A book's table 0°…330° every 30°: the span (330°) is taken as the cycle, with a note naming
    --cycle-angle 360deg; given it, the table closes on its first torque, and no note."""
    samples = [(math.radians(d), 15000 + 10000 * math.sin(math.radians(2 * d)) - 6000 * math.cos(math.radians(2 * d))) for d in range(0, 331, 30)]
    short = taucli.flywheel(turning_moment=samples, omega_mean="600 rpm", speed_variation=0.01)
    assert any("cycle_angle 360deg" in note for note in short.notes)  # spelled as Python spells it
    whole = taucli.flywheel(turning_moment=samples, cycle_angle="360 deg", omega_mean="600 rpm", speed_variation=0.01)
    assert not any("span" in note or "ends at" in note for note in whole.notes)
    assert whole.results["torque_mean"].value == pytest.approx(15000.0, rel=1e-13)  # the trapezoids are exact for a whole period's sines


def test_a_fast_wave_is_followed_or_refused():
    """sin(300θ): 600 crossings a turn; the grid follows the fastest wave, 16 points a period
    (ΔE = 2·(100/300) exactly), and a wave past what a grid can follow is refused."""
    results = taucli.flywheel(turning_moment="(1000 + 100*sin(300*theta)) N*m", inertia="1 kg*m^2", omega_mean="300 rpm").results
    assert results["energy_swing"].value == pytest.approx(2 * 100 / 300, rel=1e-12)
    from taucli.core.errors import InputError

    with pytest.raises(InputError, match="too fast"):
        taucli.flywheel(turning_moment="(1000 + 100*sin(1e6*theta)) N*m", inertia="1 kg*m^2", omega_mean="300 rpm")


def test_the_diagram_alone_gives_what_it_makes():
    """T = 1000 + 500 sin θ N·m: T_mean 1000 N·m, E(θ) = 500(1 − cos θ) J, so ΔE = 1000 J, and
    P = T_mean ω. Without the flywheel (I) or its speed band (Cs) these are still the diagram's
    answer (before, the whole run was refused for want of two of I, ΔE and Cs); I and cs are
    null, and --get I names what makes it."""
    from conftest import run_taucli
    args = ("flywheel", "--turning-moment", "(1000 + 500*sin(theta)) N*m", "--omega-mean", "300rpm")
    document = json.loads(run_taucli(*args, "--json").out)
    results = {key: value["value"] for key, value in document["results"].items()}
    assert results["torque_mean"] == pytest.approx(1000, rel=1e-12)
    assert results["energy_swing"] == pytest.approx(1000, rel=1e-12)
    assert results["power_mean"] == pytest.approx(1000 * 300 * 2 * math.pi / 60, rel=1e-12)
    assert results["I"] is None and results["cs"] is None
    refused = run_taucli(*args, "--get", "I")
    assert refused.code == 2 and "--fluctuation" in refused.err and refused.err.count("\n") == 1
    assert float(run_taucli(*args, "--fluctuation", "0.02", "--get", "I").out) == pytest.approx(1000 / ((10 * math.pi) ** 2 * 0.02), rel=1e-12)
