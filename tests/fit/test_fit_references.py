"""taucli fit against references written from the physics in mpmath, not from taucli's scenes.

Each table is made from a closed form of the motion at known parameters (40 digits), with Gaussian
noise of a stated σ given to the fit (``--sigma``):

- a coast-down under friction and viscous drag, ω(t) = (ω₀ + τ/b)e^(−bt/I) − τ/b;
- a coast-down under friction and quadratic drag, ω(t) = √(τ/k) tan(arctan(ω₀√(k/τ)) − √(τk) t/I);
- a pendulum's exact period at each amplitude, T = 4√(L/g) K(sin²(θ₀/2));
- a pendulum's swing from rest, sin(θ/2) = sin(θ₀/2) sn(K − √(g/L) t | sin²(θ₀/2));
- an Atwood machine's time to fall d, t = √(2d(m₁ + m₂ + I/R²)/((m₁ − m₂)g − τ/R));
- a body rolling down a slope of length L, t = √(2L(1 + k²)/(g sin θ)).

The fit must give the parameters back within their stated uncertainties: each within 5σ in every
seed, and the 1σ intervals covering the truth in about 68 % of them (pooled over the scenes);
χ²/ν averages 1. Then Richmond's published Atwood runs (docs/fit.md) against a least squares
solved in mpmath, its covariance s²(JᵀJ)⁻¹ included.
"""

from __future__ import annotations

import io
import math
import random

import mpmath
import pytest

from taucli.fit import data, samples, solve
from taucli.options import SCENES

DIGITS = 40
SEEDS = 40


def fitted(scene: str, text: str, fit: str, *, sigma: str, x=(), **options) -> solve.Fit:
    """The fit alone (no report: the scene at the fitted values is not needed here)."""
    command = SCENES[scene]
    table = data.read("-", io.StringIO(text))
    names = solve.names_of(fit)
    found = samples.build(command, [table], x=x, sigma=sigma, fitted=names, given=set(options))
    model, starts, _ = solve.model_of(command, options, names, found)
    return solve.fit(model, starts)


def table(header: str, rows) -> str:
    return header + "\n" + "".join(",".join(repr(float(v)) for v in row) + "\n" for row in rows)


def coast_viscous(t, I, tau, b, omega0):
    return (omega0 + tau / b) * mpmath.exp(-b * t / I) - tau / b


def coast_drag(t, I, tau, k, omega0):
    return mpmath.sqrt(tau / k) * mpmath.tan(mpmath.atan(omega0 * mpmath.sqrt(k / tau)) - mpmath.sqrt(tau * k) * t / I)


def period_exact(length, g, amplitude):
    return 4 * mpmath.sqrt(length / g) * mpmath.ellipk(mpmath.sin(amplitude / 2) ** 2)


def swing(t, length, g, amplitude):
    m = mpmath.sin(amplitude / 2) ** 2
    return 2 * mpmath.asin(mpmath.sin(amplitude / 2) * mpmath.ellipfun("sn", mpmath.ellipk(m) - mpmath.sqrt(g / length) * t, m=m))


def atwood_time(m1, m2, d, radius, inertia, friction, g):
    return mpmath.sqrt(2 * d * (m1 + m2 + inertia / radius**2) / ((m1 - m2) * g - friction / radius))


def rolling_time(length, angle, k2, g):
    return mpmath.sqrt(2 * length * (1 + k2) / (g * mpmath.sin(angle)))


mpf = mpmath.mpf
STANDARD_GRAVITY = "9.80665"


def _coast_viscous(rng):
    truth = {"friction": mpf("0.06"), "viscous": mpf("0.01"), "omega0": mpf(30)}
    rows = [(t, coast_viscous(mpf(t), mpf("0.1"), truth["friction"], truth["viscous"], truth["omega0"]) + rng.gauss(0, 0.05))
            for t in [0.5 * i for i in range(34)]]  # the wheel stops at 17.9 s
    return truth, fitted("spin-down", table("t (s),omega (rad/s)", rows), "friction,viscous,omega0", sigma="0.05 rad/s", inertia="0.1 kg*m^2")


def _coast_drag(rng):
    truth = {"friction": mpf("0.02"), "drag": mpf("0.0004"), "omega0": mpf(40)}
    rows = [(t, coast_drag(mpf(t), mpf("0.05"), truth["friction"], truth["drag"], truth["omega0"]) + rng.gauss(0, 0.03))
            for t in [0.25 * i for i in range(40)]]  # the wheel stops at 11.1 s
    return truth, fitted("spin-down", table("t (s),omega (rad/s)", rows), "friction,drag,omega0", sigma="0.03 rad/s", inertia="0.05 kg*m^2")


def _periods(rng):
    truth = {"g": mpf("9.81")}
    rows = [(a, period_exact(mpf(1), truth["g"], mpmath.radians(a)) + rng.gauss(0, 0.002)) for a in (10, 20, 30, 40, 50, 60, 70, 80)]
    return truth, fitted("pendulum", table("amplitude (deg),period (s)", rows), "g", sigma="2 ms", x=("amplitude=angle0",),
                         shape="point", mass="50 g", radius="1 m")


def _swing(rng):
    truth = {"g": mpf("9.81"), "angle0": mpmath.radians(40)}
    rows = [(t, swing(mpf(t), mpf("0.75"), truth["g"], truth["angle0"]) + rng.gauss(0, 0.005)) for t in [0.05 * i for i in range(60)]]
    return truth, fitted("pendulum", table("t (s),theta (rad)", rows), "g,angle0", sigma="0.005 rad", shape="point", mass="100 g", radius="75 cm")


def _atwood(rng):
    truth = {"pulley_inertia": mpf("4e-5"), "axle_friction": mpf("0.002")}
    runs = [(0.21, 0.2), (0.22, 0.2), (0.23, 0.2), (0.25, 0.2), (0.3, 0.2), (0.3, 0.25), (0.4, 0.3), (0.5, 0.3)]
    rows = [(m1, m2, atwood_time(mpf(m1), mpf(m2), mpf(1), mpf("0.03"), truth["pulley_inertia"], truth["axle_friction"], mpf(STANDARD_GRAVITY)) + rng.gauss(0, 0.01))
            for m1, m2 in runs]
    return truth, fitted("atwood", table("m1 (kg),m2 (kg),t (s)", rows), "pulley_inertia,axle_friction", sigma="10 ms",
                         distance="1 m", pulley_radius="3 cm")


def _rolling(rng):
    truth = {"k2": mpf(2) / 5}
    rows = [(a, length, rolling_time(mpf(length), mpmath.radians(a), truth["k2"], mpf(STANDARD_GRAVITY)) + rng.gauss(0, 0.005))
            for a in (3, 6, 9, 12) for length in (0.5, 1.0, 1.5)]
    return truth, fitted("rolling", table("angle (deg),length (m),t (s)", rows), "k2", sigma="5 ms")


CASES = {"coast, viscous": _coast_viscous, "coast, quadratic drag": _coast_drag, "periods": _periods, "swing": _swing,
         "atwood": _atwood, "rolling": _rolling}


def _sigma(found: solve.Fit, j: int) -> float:
    return math.sqrt(found.covariance[j, j])


@pytest.fixture(scope="module")
def outcomes():
    """(scene, [(|p − truth|/σ for each input, χ²/ν, ν)] for every seed)."""
    found = {}
    with mpmath.workdps(DIGITS):
        for name, case in CASES.items():
            rows = []
            for seed in range(SEEDS):
                truth, fit = case(random.Random(f"{name} {seed}"))
                pulls = [abs(float(fit.p[j]) - float(truth[n])) / _sigma(fit, j) for j, n in enumerate(fit.model.names)]
                rows.append((pulls, fit.quality.chi2_dof, fit.quality.dof))
            found[name] = rows
    return found


@pytest.mark.parametrize("name", list(CASES))
def test_every_seed_gives_the_parameters_back_within_5_sigma(outcomes, name):
    worst = max(max(pulls) for pulls, _, _ in outcomes[name])
    assert worst < 5, worst


@pytest.mark.parametrize("name", list(CASES))
def test_chi2_per_degree_of_freedom_averages_1(outcomes, name):
    """The mean of χ²/ν over the seeds: 1 ± √(2/ν)/√seeds for noise of the σ given."""
    rows = outcomes[name]
    mean = sum(chi2 for _, chi2, _ in rows) / len(rows)
    assert abs(mean - 1) < 4 * math.sqrt(2 / rows[0][2]) / math.sqrt(len(rows)), mean


def test_the_1_sigma_intervals_cover_the_truth_in_68_percent_of_seeds(outcomes):
    """Pooled over the six scenes (40 seeds each, 11 inputs): 440 intervals, 68.3 % expected; the
    binomial scatter is ±2.2 %, more for the inputs correlated within a fit: ±8 % holds it at 3σ."""
    pulls = [p for rows in outcomes.values() for row, _, _ in rows for p in row]
    rate = sum(p < 1 for p in pulls) / len(pulls)
    assert 0.60 < rate < 0.76, rate
    for name, rows in outcomes.items():  # each scene alone: loose (40 seeds), a gross error in one still shows
        alone = [p for row, _, _ in rows for p in row]
        assert 0.45 < sum(p < 1 for p in alone) / len(alone) < 0.9, name


# Richmond, "Measurements from an Atwood's Machine" (RIT Physics 369): d = 98 cm, three times for
# each of five pairs of masses (docs/fit.md shows the table and the fit).
RICHMOND = [(207, 200, (4.06, 4.03, 3.88)), (206.5, 200.5, (4.53, 4.59, 4.62)), (206, 201, (5.00, 5.00, 5.06)),
            (205.5, 201.5, (6.13, 6.16, 6.19)), (205, 202, (8.00, 7.75, 7.87))]


@mpmath.workdps(DIGITS)
def test_richmonds_atwood_runs_against_a_least_squares_solved_in_mpmath():
    """min Σ(tᵢ − t(m₁, m₂; I, τ))² at 40 digits: the gradient's zero by Newton's method from
    taucli's answer (a start only: findroot converges to the zero, not to the start), and the
    covariance s²(JᵀJ)⁻¹ with s² = S/(n − 2)."""
    runs = [(mpf(str(m1)) / 1000, mpf(str(m2)) / 1000, mpf(str(t))) for m1, m2, times in RICHMOND for t in times]
    text = table("m1 (g),m2 (g),t (s)", [(m1 * 1000, m2 * 1000, t) for m1, m2, t in runs])
    command = SCENES["atwood"]
    names = ["pulley_inertia", "axle_friction"]
    options = {"distance": "98 cm", "pulley_radius": "2.5 cm"}
    built = samples.build(command, [data.read("-", io.StringIO(text))], fitted=names, given=set(options))
    model, starts, _ = solve.model_of(command, options, names, built)
    found = solve.fit(model, starts)
    d, R, G = mpf("0.98"), mpf("0.025"), mpf(STANDARD_GRAVITY)
    scale = (mpf("1e-5"), mpf("1e-4"))  # I and τ in units of their size: Newton's steps of like size

    def residuals(u, v):
        return [t - atwood_time(m1, m2, d, R, u * scale[0], v * scale[1], G) for m1, m2, t in runs]

    def squares(u, v):
        return sum(r**2 for r in residuals(u, v))

    gradient = [lambda u, v: mpmath.diff(squares, (u, v), (1, 0)), lambda u, v: mpmath.diff(squares, (u, v), (0, 1))]
    u, v = mpmath.findroot(gradient, (mpf(found.p[0]) / scale[0], mpf(found.p[1]) / scale[1]))
    inertia, friction = u * scale[0], v * scale[1]
    J = mpmath.matrix([[mpmath.diff(lambda x: atwood_time(m1, m2, d, R, x, friction, G), inertia),
                        mpmath.diff(lambda x: atwood_time(m1, m2, d, R, inertia, x, G), friction)] for m1, m2, _ in runs])
    s2 = squares(u, v) / (len(runs) - 2)
    covariance = s2 * (J.T * J) ** -1
    assert float(found.p[0]) == pytest.approx(float(inertia), rel=1e-7)
    assert float(found.p[1]) == pytest.approx(float(friction), rel=1e-8)
    assert _sigma(found, 0) == pytest.approx(float(mpmath.sqrt(covariance[0, 0])), rel=1e-5)
    assert _sigma(found, 1) == pytest.approx(float(mpmath.sqrt(covariance[1, 1])), rel=1e-5)
    assert found.quality.correlation[0, 1] == pytest.approx(float(covariance[0, 1] / mpmath.sqrt(covariance[0, 0] * covariance[1, 1])), rel=1e-5)
    assert found.quality.rms == pytest.approx(float(mpmath.sqrt(squares(u, v) / len(runs))), rel=1e-10)


# Seth, George Mason University, computational physics notes "pass6" (physics.gmu.edu/~mrseth/pass6.html):
# the exact period of a 1 m pendulum at g = 9.81 m/s², T = 4√(L/g)K(sin(θ₀/2)), for 10° to 80°.
SETH = {10: "2.00989262729860052", 20: "2.02145125782457619", 30: "2.04098988951913023", 40: "2.06893785189358914",
        50: "2.10593461928364287", 60: "2.15287466688051548", 70: "2.21097618054218626", 80: "2.28188592401963935"}


def test_a_published_table_of_exact_periods_gives_its_g_back():
    """Seth's table agrees with the elliptic integral in mpmath to 1e-16; the fit's g is the
    table's 9.81 to the last digits a double holds, with an uncertainty of rounding size."""
    with mpmath.workdps(DIGITS):
        for amplitude, period in SETH.items():
            exact = period_exact(mpf(1), mpf("9.81"), mpmath.radians(amplitude))
            assert abs(mpf(period) / exact - 1) < 1e-15
    text = "amplitude (deg),period (s)\n" + "".join(f"{a},{t}\n" for a, t in SETH.items())
    command = SCENES["pendulum"]
    options = {"shape": "point", "mass": "1 kg", "radius": "1 m"}
    built = samples.build(command, [data.read("-", io.StringIO(text))], x=("amplitude=angle0",), fitted=["g"], given=set(options))
    model, starts, _ = solve.model_of(command, options, ["g"], built)
    found = solve.fit(model, starts)
    assert float(found.p[0]) == pytest.approx(9.81, rel=1e-14)
    assert _sigma(found, 0) < 1e-12
