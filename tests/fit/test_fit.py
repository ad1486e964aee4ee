"""taucli fit, the library: parameters recovered from the scenes' own forward models with their
uncertainties (the 1σ interval covers the true value in about 68 % of seeds), linear fits against
the closed-form normal equations in mpmath, and the refusals (inputs the samples cannot tell apart,
too few samples, a value past its bound, a fit that does not converge).
"""

from __future__ import annotations

import io
import math
import random

import mpmath
import numpy as np
import pytest

from fit_synthetic import COAST, coast_down, csv, solve
from taucli.core.errors import InputError
from taucli.fit import command, nonlinear

MP_DPS = 40


def fitted(scene: str, text: str, fit: str, **options):
    """(report, fit) for the table ``text`` (as stdin), the scene's options as keywords."""
    known = {key: options.pop(key) for key in ("x", "y", "sigma", "ranges", "every") if key in options}
    return command.fit_of(scene, ["-"], options, fit=fit, stdin=io.StringIO(text), **known)


def sigma_of(found, name: str) -> float:
    j = found.model.names.index(name)
    return math.sqrt(found.covariance[j, j])


def value_of(found, name: str) -> float:
    return float(found.p[found.model.names.index(name)])


# A wheel with friction alone stops at ω₀I/τ = 10 s: the samples before it are a straight line.
LINE = {"inertia": 0.1, "omega0": 30.0, "friction": 0.3}
LINE_TIMES = [0.5 * i for i in range(17)]


def line_table(seed: int, noise: float = 0.05) -> str:
    rng = random.Random(seed)
    rows = [(t, solve("spin-down", **LINE, time=t)["omega"] + rng.gauss(0, noise)) for t in LINE_TIMES]
    return csv("t (s),omega (rad/s)", rows, ("g", ".12g"))


def test_a_coast_down_under_friction_alone_is_solved_as_a_linear_model():
    report, found = fitted("spin-down", line_table(1), "friction,omega0", inertia="0.1 kg*m^2")
    assert found.linear
    assert report.method.startswith("linear least squares (the model is linear in friction, omega0")
    assert any(step.title.startswith("The model is linear") for step in report.steps)
    assert "ω(t) = ω₀ + ((τ − τ_f)/I)·t" in next(step.equation for step in report.steps if step.title.startswith("The model is linear"))


def test_the_linear_fit_is_the_solution_of_the_normal_equations_in_mpmath():
    """ω = ω₀ − (τ/I)t: the least squares over (ω₀, τ) from the normal equations at 40 digits, and
    the covariance s²(XᵀX)⁻¹ with s² = Σr²/(n − 2)."""
    text = line_table(2)
    _, found = fitted("spin-down", text, "friction,omega0", inertia="0.1 kg*m^2")
    rows = [line.split(",") for line in text.splitlines()[1:]]
    t = [mpmath.mpf(a) for a, _ in rows]
    y = [mpmath.mpf(b) for _, b in rows]
    X = mpmath.matrix([[-ti / mpmath.mpf("0.1"), 1] for ti in t])  # columns: friction, omega0
    Y = mpmath.matrix(y)
    normal = X.T * X
    p = mpmath.lu_solve(normal, X.T * Y)
    r = Y - X * p
    s2 = sum(ri**2 for ri in r) / (len(y) - 2)
    covariance = s2 * normal**-1
    assert value_of(found, "friction") == pytest.approx(float(p[0]), rel=1e-10)
    assert value_of(found, "omega0") == pytest.approx(float(p[1]), rel=1e-12)
    assert sigma_of(found, "friction") == pytest.approx(float(mpmath.sqrt(covariance[0, 0])), rel=1e-7)
    assert sigma_of(found, "omega0") == pytest.approx(float(mpmath.sqrt(covariance[1, 1])), rel=1e-7)
    rho = covariance[0, 1] / mpmath.sqrt(covariance[0, 0] * covariance[1, 1])
    assert found.quality.correlation[0, 1] == pytest.approx(float(rho), rel=1e-6)


def test_an_atwood_machines_measured_accelerations_are_linear_in_g_and_the_axle_friction():
    """a = ((m₁ − m₂)g − τ/R)/M, M = m₁ + m₂ + I/R², with the pulley's I known: weighted least
    squares (σ given per run) against the normal equations XᵀWX p = XᵀWy in mpmath."""
    runs = [(0.5, 0.3, 0.021), (0.6, 0.3, 0.02), (0.7, 0.3, 0.03), (0.8, 0.4, 0.025), (0.9, 0.4, 0.02), (1.0, 0.5, 0.04)]
    rng = random.Random(3)
    rows = [(m1, m2, solve("atwood", m1=m1, m2=m2, pulley_inertia=0.002, pulley_radius=0.05, axle_friction=0.02, g=9.79)["a"] + rng.gauss(0, u), u)
            for m1, m2, u in runs]
    text = csv("m1 (kg),m2 (kg),a (m/s^2),u (m/s^2)", rows, ("g", "g", ".12g", "g"))
    report, found = fitted("atwood", text, "g,axle_friction", pulley_inertia="0.002 kg*m^2", pulley_radius="5 cm", sigma="u")
    assert found.linear and "chi2_dof" in report.results
    R, I = mpmath.mpf("0.05"), mpmath.mpf("0.002")
    X, Y, W = [], [], []
    for line in text.splitlines()[1:]:
        m1, m2, a, u = (mpmath.mpf(v) for v in line.split(","))
        M = m1 + m2 + I / R**2
        X.append([(m1 - m2) / M, -1 / (R * M)])
        Y.append(a)
        W.append(1 / u**2)
    X, Y, W = mpmath.matrix(X), mpmath.matrix(Y), mpmath.diag(W)
    normal = X.T * W * X
    p = mpmath.lu_solve(normal, X.T * W * Y)
    covariance = normal**-1
    assert value_of(found, "g") == pytest.approx(float(p[0]), rel=1e-10)
    assert value_of(found, "axle_friction") == pytest.approx(float(p[1]), rel=1e-8)
    assert sigma_of(found, "g") == pytest.approx(float(mpmath.sqrt(covariance[0, 0])), rel=1e-7)
    assert sigma_of(found, "axle_friction") == pytest.approx(float(mpmath.sqrt(covariance[1, 1])), rel=1e-7)
    r = Y - X * p
    chi2 = sum(W[i, i] * r[i] ** 2 for i in range(len(Y)))
    assert report.results["chi2_dof"].value == pytest.approx(float(chi2 / (len(Y) - 2)), rel=1e-8)


def _coverage(fits: int, make, fit: str, truth: dict[str, float], **options) -> float:
    hits = total = 0
    for seed in range(fits):
        _, found = fitted("spin-down", make(seed), fit, **options)
        for name, true in truth.items():
            hits += abs(value_of(found, name) - true) < sigma_of(found, name)
            total += 1
    return hits / total


def test_the_1_sigma_interval_of_a_linear_fit_covers_the_truth_in_68_percent_of_seeds():
    """300 seeds, the samples' σ given: the fraction is 68.3 % for a linear model with Gaussian
    noise; 3σ of the binomial scatter (seeds are independent, the two inputs correlated) is ±8 %."""
    rate = _coverage(300, line_table, "friction,omega0", {"friction": 0.3, "omega0": 30.0}, inertia="0.1 kg*m^2", sigma="0.05 rad/s")
    assert 0.60 < rate < 0.76, rate


def test_the_1_sigma_interval_of_a_nonlinear_fit_covers_the_truth_in_68_percent_of_seeds():
    """Friction, viscous drag and ω₀ of a coast-down (exponential: nonlinear in b), 25 samples, no
    σ given (the covariance scaled by the residual variance): 120 seeds, three inputs each."""
    times = [0.5 * i for i in range(25)]

    def table(seed: int) -> str:
        return csv("t (s),omega (rad/s)", coast_down(times, 0.05, 1000 + seed), ("g", ".12g"))

    truth = {"friction": COAST["friction"], "viscous": COAST["viscous"], "omega0": COAST["omega0"]}
    rate = _coverage(120, table, "friction,viscous,omega0", truth, inertia="0.1 kg*m^2")
    assert 0.57 < rate < 0.79, rate


def test_a_coast_down_starts_from_the_integrated_equation_of_motion_and_recovers_the_torques():
    report, found = fitted("spin-down", csv("t (s),omega (rad/s)", coast_down([0.4 * i for i in range(40)], 0.02, 5), ("g", ".12g")),
                           "friction,viscous,omega0", inertia="0.1 kg*m^2")
    assert not found.linear and found.starts == ["closed form"] * 3
    assert "A start from the equation of motion, integrated over the samples" in [step.title for step in report.steps]
    for name in ("friction", "viscous", "omega0"):
        assert abs(value_of(found, name) - COAST[name]) < 4 * sigma_of(found, name)
    assert report.results["t_stop"].value == pytest.approx(solve("spin-down", **COAST)["t_stop"], rel=0.01)
    assert report.uncertainties["t_stop"] > 0


def test_the_scenes_results_carry_the_fitted_inputs_correlated_uncertainties():
    """t_stop = ω₀I/τ for friction alone: σ² = gᵀCg with g = (∂t/∂τ, ∂t/∂ω₀), C the fit's covariance."""
    report, found = fitted("spin-down", line_table(4), "friction,omega0", inertia="0.1 kg*m^2")
    tau, omega0 = value_of(found, "friction"), value_of(found, "omega0")
    g = np.array([-omega0 * 0.1 / tau**2, 0.1 / tau])
    assert report.results["t_stop"].value == pytest.approx(omega0 * 0.1 / tau, rel=1e-12)
    assert report.uncertainties["t_stop"] == pytest.approx(math.sqrt(g @ found.covariance @ g), rel=1e-5)


def test_an_option_held_with_an_uncertainty_moves_the_fit_by_it():
    """ω(t) depends on τ/I only: an I known to 5 % makes τ uncertain by 5 % more, in quadrature."""
    _, alone = fitted("spin-down", line_table(5), "friction,omega0", inertia="0.1 kg*m^2")
    report, held = fitted("spin-down", line_table(5), "friction,omega0", inertia="0.1+/-0.005 kg*m^2")
    tau = value_of(alone, "friction")
    assert value_of(held, "friction") == pytest.approx(tau, rel=1e-12)
    assert sigma_of(held, "friction") == pytest.approx(math.hypot(sigma_of(alone, "friction"), 0.05 * tau), rel=1e-4)
    assert sigma_of(held, "omega0") == pytest.approx(sigma_of(alone, "omega0"), rel=1e-4)
    assert report.input_uncertainties == {"inertia": 0.005}
    assert report.uncertainties["I"] == pytest.approx(0.005, rel=1e-6)


def test_a_pendulums_exact_period_gives_g_back_from_noise_free_runs():
    rows = [(a, solve("pendulum", shape="point", mass=0.05, radius=1.0, angle0=math.radians(a), g=9.81)["period"]) for a in (10, 30, 50, 70, 85)]
    report, found = fitted("pendulum", csv("amplitude (deg),period (s)", rows, ("g", ".17g")), "g", shape="point", mass="50 g", radius="1 m",
                           x=("amplitude=angle0",))
    assert value_of(found, "g") == pytest.approx(9.81, rel=1e-9)
    assert found.starts == ["closed form"]
    start = next(step for step in report.steps if step.title.startswith("A start from the periods"))
    assert start.result == "g = 9.81 m/s²"  # T ∝ 1/√g: the start is the least squares itself


def test_a_rolling_bodys_runs_give_its_k2():
    rng = random.Random(6)
    rows = [(a, L, solve("rolling", shape="shell", angle=math.radians(a), length=L)["t"] + rng.gauss(0, 0.003)) for a in (4, 8, 12, 16) for L in (0.5, 1.0)]
    report, found = fitted("rolling", csv("angle (deg),length (m),t (s)", rows, ("g", "g", ".12g")), "k2")
    assert found.starts == ["closed form"]
    assert abs(value_of(found, "k2") - 2 / 3) < 4 * sigma_of(found, "k2")


def test_the_inputs_of_a_coast_down_without_a_known_torque_cannot_be_told_apart():
    text = csv("t (s),omega (rad/s)", coast_down([0.5 * i for i in range(30)], 0.05, 7), ("g", ".12g"))
    with pytest.raises(InputError) as refused:
        fitted("spin-down", text, "inertia,friction,viscous,omega0")
    said = str(refused.value)
    assert said.startswith("fit: the samples cannot tell inertia, friction and viscous apart")
    assert "give one of inertia, friction and viscous" in said


def test_a_pendulums_length_and_g_cannot_be_told_apart_nor_its_mass_found():
    rows = [(a, solve("pendulum", shape="point", mass=0.05, radius=1.0, angle0=math.radians(a))["period"]) for a in (10, 40, 70)]
    text = csv("angle0 (deg),period (s)", rows, ("g", ".12g"))
    with pytest.raises(InputError, match="cannot tell radius and g apart"):
        fitted("pendulum", text, "radius,g", shape="point", mass="50 g")
    with pytest.raises(InputError, match="the samples do not depend on mass"):
        fitted("pendulum", text, "mass", shape="point", radius="1 m")


def test_too_few_samples_are_refused():
    with pytest.raises(InputError, match="gives 2 samples for 2 inputs to fit: a fit needs more samples than inputs"):
        fitted("spin-down", "t (s),omega (rad/s)\n0,30\n1,27\n", "friction,omega0", inertia="0.1 kg*m^2")


def test_samples_that_ask_for_a_value_past_its_bound_are_refused():
    """A wheel speeding up asks for a negative friction torque."""
    text = csv("t (s),omega (rad/s)", [(t, 10 + 0.5 * t) for t in range(8)], ("g", "g"))
    with pytest.raises(InputError, match=r"the samples ask for friction at or past its least value"):
        fitted("spin-down", text, "friction,omega0", inertia="0.1 kg*m^2")


def test_a_line_through_an_exponential_coast_down_is_said_to_be_the_wrong_model():
    text = csv("t (s),omega (rad/s)", coast_down([0.25 * i for i in range(60)], 0.02, 8), ("g", ".12g"))
    report, found = fitted("spin-down", text, "friction,omega0", inertia="0.1 kg*m^2")
    assert found.quality.structured
    assert any(note.startswith("warning: the residuals have a shape") for note in report.notes)


def test_a_model_that_fits_is_not_said_to_be_structured_and_its_chi2_matches():
    report, found = fitted("spin-down", line_table(9), "friction,omega0", inertia="0.1 kg*m^2", sigma="0.05 rad/s")
    assert not found.quality.structured
    assert report.results["chi2_dof"].value == pytest.approx(1, abs=0.8)
    assert not any("warning" in note for note in report.notes)


def test_uncertainties_given_too_small_are_said_to_be_so():
    report, _ = fitted("spin-down", line_table(10, noise=0.5), "friction,omega0", inertia="0.1 kg*m^2", sigma="0.01 rad/s")
    assert any(note.startswith("warning: χ²/ν = ") and "the residuals are larger than the uncertainties" in note for note in report.notes)


def test_a_fit_that_does_not_converge_is_refused(monkeypatch):
    monkeypatch.setattr(nonlinear, "MOST_EVALUATIONS", 1)
    text = csv("t (s),omega (rad/s)", coast_down([0.5 * i for i in range(25)], 0.05, 11), ("g", ".12g"))
    with pytest.raises(InputError, match=r"fit: did not converge \(.*\) after \d+ steps from the start friction = "):
        fitted("spin-down", text, "friction,viscous,omega0", inertia="0.1 kg*m^2")


def test_a_value_given_for_a_fitted_input_is_its_start():
    text = csv("t (s),omega (rad/s)", coast_down([0.5 * i for i in range(25)], 0.05, 12), ("g", ".12g"))
    report, found = fitted("spin-down", text, "friction,viscous,omega0", inertia="0.1 kg*m^2", friction="0.05 N*m", viscous="0.02 N*m*s", omega0="29 rad/s")
    assert found.starts == ["given"] * 3
    _, closed = fitted("spin-down", text, "friction,viscous,omega0", inertia="0.1 kg*m^2")
    assert found.p == pytest.approx(closed.p, rel=1e-6)


def test_a_key_of_a_spec_is_fitted_as_find_names_it():
    """A brake's μ from a coast-down under it: the spec's key, named as --find names it."""
    rng = random.Random(13)
    rows = [(t, solve("spin-down", inertia=0.1, omega0=30, brake=["force=10N mu=0.3 radius=0.1m"], time=t)["omega"] + rng.gauss(0, 0.02)) for t in range(9)]
    report, found = fitted("spin-down", csv("t (s),omega (rad/s)", rows, ("g", ".12g")), "brake.mu,omega0", inertia="0.1 kg*m^2",
                           brake=["force=10N radius=0.1m"])
    assert found.model.names == ["brake.mu", "omega0"]
    assert abs(value_of(found, "brake.mu") - 0.3) < 4 * sigma_of(found, "brake.mu")
    assert "brake.mu" in report.results and report.results["brake.mu"].label.startswith("mu= of the brake")


def test_a_pendulums_swing_gives_g_and_its_amplitude_from_the_zero_crossings_start():
    """θ(t) over two swings: many values of g meet one sample (faster swings pass through the same
    angle), so the start is the swing's own period and amplitude."""
    rng = random.Random(14)
    rows = [(t, solve("pendulum", shape="point", mass=0.05, radius=1.0, angle0=math.radians(30), g=9.81, time=t)["theta"] + rng.gauss(0, 0.003))
            for t in [0.1 * i for i in range(40)]]
    report, found = fitted("pendulum", csv("t (s),theta (rad)", rows, ("g", ".12g")), "g,angle0", shape="point", mass="50 g", radius="1 m")
    assert found.starts == ["closed form", "closed form"]
    assert abs(value_of(found, "g") - 9.81) < 4 * sigma_of(found, "g")
    assert abs(value_of(found, "angle0") - math.radians(30)) < 4 * sigma_of(found, "angle0")


def test_a_falling_masss_distance_in_time_gives_the_axle_friction():
    rng = random.Random(16)
    given = {"m1": 0.3, "m2": 0.2, "pulley_mass": 0.1, "pulley_radius": 0.05}
    rows = [(t, solve("atwood", **given, axle_friction=0.005, time=t)["distance"] + rng.gauss(0, 0.002)) for t in [0.1 * i for i in range(1, 15)]]
    report, found = fitted("atwood", csv("t (s),distance (m)", rows, ("g", ".12g")), "axle_friction", x=("t",), y="distance",
                           m1="300 g", m2="200 g", pulley_mass="100 g", pulley_radius="5 cm")
    assert abs(value_of(found, "axle_friction") - 0.005) < 4 * sigma_of(found, "axle_friction")
    with pytest.raises(InputError, match="cannot tell axle_friction and pulley_mass apart"):
        fitted("atwood", csv("t (s),distance (m)", rows, ("g", ".12g")), "axle_friction,pulley_mass", x=("t",), y="distance",
               m1="300 g", m2="200 g", pulley_radius="5 cm")


def test_samples_on_the_model_exactly_are_said_to_give_uncertainties_of_rounding_size():
    """ω = 30 − 3t exactly (I = 0.1 kg·m², τ = 0.3 N·m): the residual variance is rounding, and so
    the uncertainties scaled by it; a note says so, where ± 0 alone would read as a measurement's."""
    report, found = fitted("spin-down", "t (s),omega (rad/s)\n0,30\n1,27\n2,24\n3,21\n4,18\n", "friction,omega0", inertia="0.1 kg*m^2")
    assert value_of(found, "friction") == pytest.approx(0.3, rel=1e-12)
    assert any(note.startswith("the samples lie on the model to rounding") for note in report.notes)
    noisy, _ = fitted("spin-down", line_table(7), "friction,omega0", inertia="0.1 kg*m^2")
    assert not any(note.startswith("the samples lie on the model to rounding") for note in noisy.notes)
