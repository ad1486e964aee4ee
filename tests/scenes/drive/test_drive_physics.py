"""taucli drive against references written from the physics, not from the solver's formulas.

- The motor torque, shaft by shaft: the output shaft needs τ_out = Jα/N + T; the teeth pass power
  with the loss on its way, P_in = P_out/η while the motor drives, ηP_out while the load does;
  τ_in = P_in/ω; the motor gives (J_m + J_g)α + τ_in. In mpmath, at 30 digits.
- The run-up on a torque–speed line by quadrature: ω̇(ω) from the shaft balance at each speed,
  t = ∫dω/ω̇, θ = ∫ω dω/ω̇, W = ∫τ(ω)ω dω/ω̇ (mpmath.quad, split where the power turns round).
- The RMS torque, mean and peak power by integrating τ(t)² and τ(t)ω(t) over the cycle.
- Energy: the motor's work is the load's kinetic energy plus the work against it plus the
  losses (P_in − P_out integrated), in a run-up and over a whole cycle.
- Units: a scene written in US customary units gives the SI results of the same scene in SI.
- Continuity where a regime changes: a trapezoid that shrinks to a triangle, the power through
  the teeth turning round (in a phase, and in the run-up on the line).
"""

from __future__ import annotations

import math

import mpmath as mp
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import taucli

mp.mp.dps = 30
TWO_PI = 2 * math.pi
LB, IN, FT, G0 = 0.45359237, 0.0254, 0.3048, 9.80665
LBF = LB * G0


def values(report) -> dict:
    return {key: value.value for key, value in report.results.items()}


def close(got, want, rel):
    assert got == pytest.approx(float(want), rel=rel, abs=0), (got, want)


class Ref:
    """The drive in mpmath: J_m, J_g at the motor; J, T at the output; N, η."""

    def __init__(self, jm, jg, j, t, n, eta):
        self.jm, self.jg, self.j, self.t, self.n, self.eta = (mp.mpf(x) for x in (jm, jg, j, t, n, eta))

    def motor_torque(self, alpha):
        alpha = mp.mpf(alpha)
        tau_out = self.j * alpha / self.n + self.t  # the output shaft's balance
        p_out = tau_out  # per unit output speed
        p_in = p_out / self.eta if p_out >= 0 else self.eta * p_out  # the teeth keep their share of whatever flows
        tau_in = p_in / self.n  # per unit motor speed: ω_in = N ω_out
        return (self.jm + self.jg) * alpha + tau_in

    def loss_rate(self, alpha, omega):
        """P_in − P_out at motor speed ω and acceleration α: what the teeth keep, ≥ 0."""
        tau_out = self.j * alpha / self.n + self.t
        p_out = tau_out * omega / self.n
        p_in = p_out / self.eta if p_out >= 0 else self.eta * p_out
        return p_in - p_out

    def alpha_at(self, line_torque):
        """ω̇ with the motor giving ``line_torque``: the balance is increasing in α, so bisect it."""
        lo, hi = mp.mpf(-1), mp.mpf(1)
        while self.motor_torque(lo) > line_torque:
            lo *= 2
        while self.motor_torque(hi) < line_torque:
            hi *= 2
        return mp.findroot(lambda a: self.motor_torque(a) - line_torque, (lo, hi), solver="anderson", tol=mp.mpf(10) ** -28)


def run_up_reference(ref: Ref, stall, no_load, target):
    """(t, θ, W_motor) from rest to ``target`` on τ = τ_s(1 − ω/ω_nl), by quadrature in ω."""
    stall, no_load = mp.mpf(stall), mp.mpf(no_load)

    def line(w):
        return stall * (1 - w / no_load)

    def rate(w):
        return ref.alpha_at(line(w))

    points = [mp.mpf(0)]
    if ref.j > 0 and ref.t < 0:  # where J ω̇/N + T = 0 the motor torque is (J_m + J_g)ω̇ at ω̇ = −TN/J
        switch = no_load * (1 - (ref.jm + ref.jg) * (-ref.t * ref.n / ref.j) / stall)
        if 0 < switch < target:
            points.append(switch)
    points.append(mp.mpf(target))
    t = mp.quad(lambda w: 1 / rate(w), points)
    theta = mp.quad(lambda w: w / rate(w), points)
    work = mp.quad(lambda w: line(w) * w / rate(w), points)
    loss = mp.quad(lambda w: ref.loss_rate(rate(w), w) / rate(w), points)
    return t, theta, work, loss


# the motor torque at an acceleration, every way of giving the load


@settings(max_examples=60, deadline=None)
@given(jm=st.floats(1e-6, 1e-2), jg=st.sampled_from([0.0, 1e-5, 3e-4]), j=st.one_of(st.just(0.0), st.floats(1e-3, 10.0)),
       n=st.floats(1.0, 50.0), eta=st.floats(0.3, 1.0), t=st.one_of(st.just(0.0), st.floats(0.01, 50.0), st.floats(-50.0, -0.01)),
       alpha=st.floats(1.0, 5e3))
def test_torque_accel_is_the_shaft_by_shaft_balance(jm, jg, j, n, eta, t, alpha):
    report = taucli.drive(motor_inertia=jm, gear_inertia=jg, load_inertia=j if j else None, load_torque=t if t or not j else None,
                          ratio=[n], efficiency=eta, alpha=f"{alpha!r} rad/s^2") if (j or t) else None
    if report is None:
        return
    want = Ref(jm, jg, j, t, n, eta).motor_torque(alpha)
    close(report.results["torque_accel"].value, want, 1e-12)


@settings(max_examples=40, deadline=None)
@given(m=st.floats(0.1, 1000.0), r=st.floats(0.005, 0.5), screw=st.booleans(), mu=st.one_of(st.just(0.0), st.floats(0.01, 0.5)),
       incline=st.one_of(st.sampled_from([0.0, 90.0, -90.0]), st.floats(0.5, 89.0), st.floats(-89.0, -0.5)),
       force=st.one_of(st.just(0.0), st.floats(1.0, 100.0), st.floats(-100.0, -1.0)), n=st.floats(1.0, 20.0), eta=st.floats(0.5, 1.0), g=st.floats(1.0, 20.0))
def test_the_load_of_a_moving_mass_is_its_force_at_the_lever(m, r, screw, mu, incline, force, n, eta, g):
    """F = F_ext + μmg cos θ + mg sin θ along the travel; at the shaft F·r (drum) or F·p/2π (screw): T = dW/dθ."""
    lever = r / TWO_PI if screw else r
    kw = dict(load_mass=m, ratio=[n], efficiency=eta, mu=mu or None, incline=f"{incline!r} deg", load_force=force or None, g=g)
    kw["lead" if screw else "drum_radius"] = r
    if not mu and not incline:
        kw.pop("g")
    found = values(taucli.drive(**kw))
    theta = mp.radians(incline)
    cos = mp.mpf(0) if abs(incline) == 90 else mp.cos(theta)
    f = mp.mpf(force) + mp.mpf(mu) * m * g * cos + m * g * mp.sin(theta)
    torque = f * lever  # the work F ds over the shaft's dθ, ds = lever dθ
    close(found.get("load_torque_motor", 0.0), Ref(0, 0, 0, torque, n, eta).motor_torque(0), 1e-11)  # absent where nothing resists
    close(found["linear_inertia"], m * mp.mpf(lever) ** 2, 1e-12)
    if incline:
        close(found["torque_hold"], m * g * mp.sin(theta) * lever / n, 1e-11)


def test_reflected_inertia_is_the_kinetic_energy_seen_from_the_motor():
    """½J_total ω² = ½J_mω² + ½J_gω² + ½J(ω/N)² + ½mv², v = (ω/N)·r."""
    found = values(taucli.drive(motor_inertia=2e-4, gear_inertia=5e-5, load_inertia=0.3, load_mass=40, drum_radius=0.08,
                                ratio=[3, 4], until_omega="2000 rpm", in_time=0.5, energy=True))
    w = mp.mpf(2000) * 2 * mp.pi / 60
    ke = (mp.mpf(2e-4) + mp.mpf(5e-5)) * w**2 / 2 + mp.mpf(0.3) * (w / 12) ** 2 / 2 + 40 * (w / 12 * mp.mpf(0.08)) ** 2 / 2
    close(found["KE"], ke, 1e-13)
    close(found["total_inertia"], 2 * ke / w**2, 1e-13)
    close(found["ratio_total"], 12, 1e-15)


# the torque–speed line


LINE_CASES = [  # (J_m, J_g, J, T, N, η, τ_s, ω_nl, ω₁): driving; regenerating from the start; switching on the way
    (1.2e-4, 0.0, 0.05, 5.0, 10, 0.9, 2.0, 3000 * TWO_PI / 60, 2000 * TWO_PI / 60),
    (1.2e-4, 0.0, 0.05, 0.0, 10, 1.0, 2.0, 3000 * TWO_PI / 60, 2999 * TWO_PI / 60),
    (1.2e-4, 2e-5, 0.05, -5.0, 10, 0.9, 2.0, 3000 * TWO_PI / 60, 3500 * TWO_PI / 60),
    (1.2e-4, 2e-5, 0.05, -5.0, 10, 0.9, 2.0, 3000 * TWO_PI / 60, 2500 * TWO_PI / 60),
    (1e-3, 0.0, 0.02, -30.0, 5, 0.7, 0.5, 100.0, 150.0),
    (3e-5, 0.0, 2.0, 40.0, 40, 0.85, 1.5, 500.0, 1e-6),
]


@pytest.mark.parametrize("jm,jg,j,t,n,eta,stall,no_load,target", LINE_CASES)
def test_the_run_up_on_the_line_is_the_quadrature_of_dw_over_wdot(jm, jg, j, t, n, eta, stall, no_load, target):
    report = taucli.drive(motor_inertia=jm, gear_inertia=jg or None, load_inertia=j, load_torque=t or None, ratio=[n], efficiency=eta,
                          stall_torque=stall, no_load_speed=f"{no_load!r} rad/s", until_omega=f"{target!r} rad/s", energy=True)
    found = values(report)
    ref = Ref(jm, jg, j, t, n, eta)
    time, theta, work, loss = run_up_reference(ref, stall, no_load, target)
    close(found["t_accel"], time, 1e-11)
    close(found["theta_accel"], theta, 1e-11)
    close(found["work_motor"], work, 1e-10)
    close(found["work_loss"], loss, 1e-9) if loss > 1e-30 * work else None
    # energy: the motor's work is KE + the work against the load + the losses
    ke = (mp.mpf(jm) + jg) * mp.mpf(target) ** 2 / 2 + mp.mpf(j) * (mp.mpf(target) / n) ** 2 / 2
    close(found["work_motor"], ke + mp.mpf(t) * theta / n + loss, 1e-10)
    assert found["alpha0"] == pytest.approx(float(ref.alpha_at(stall)), rel=1e-12)


def test_unloaded_the_line_is_the_textbook_exponential():
    """ω(t) = ω_nl(1 − e^(−t/τ_m)), τ_m = Jω_nl/τ_s: t(ω₁) = −τ_m ln(1 − ω₁/ω_nl), θ = ω_nl t − τ_m ω₁."""
    jm, j, n, stall, no_load = mp.mpf("1e-4"), mp.mpf("0.02"), 5, mp.mpf(3), mp.mpf(400)
    for fraction in ("1e-9", "0.001", "0.5", "0.99", "0.999999"):
        target = no_load * mp.mpf(fraction)
        found = values(taucli.drive(motor_inertia=float(jm), load_inertia=float(j), ratio=[n], stall_torque=float(stall),
                                    no_load_speed=f"{float(no_load)!r} rad/s", until_omega=f"{float(target)!r} rad/s"))
        tau = (jm + j / n**2) * no_load / stall
        x = mp.mpf(float(target)) / no_load
        t = -tau * mp.log1p(-x)
        # near ω_nl the time is ill-conditioned, t'(x)x/t = x/((1 − x)|ln(1 − x)|): an ulp of any input moves it that much
        condition = max(1, float(x / ((1 - x) * -mp.log1p(-x))))
        close(found["time_constant"], tau, 1e-14)
        close(found["t_accel"], t, 1e-14 * condition)
        close(found["theta_accel"], no_load * t - tau * float(target), 2e-14 * condition)


@settings(max_examples=30, deadline=None)
@given(stall=st.floats(0.2, 5.0), fraction=st.floats(0.05, 0.95), t=st.one_of(st.just(0.0), st.floats(0.01, 20.0), st.floats(-20.0, -0.01)),
       eta=st.floats(0.5, 1.0))
def test_the_run_up_with_a_constant_torque(stall, fraction, t, eta):
    jm, j, n = 1e-4, 0.05, 10
    ref = Ref(jm, 0, j, t, n, eta)
    target = 300.0 * fraction
    report = taucli.drive(motor_inertia=jm, load_inertia=j, load_torque=t or None, ratio=[n], efficiency=eta, motor_torque=stall,
                          until_omega=f"{target!r} rad/s", energy=True)
    alpha = ref.alpha_at(stall)
    if alpha <= 0:
        assert report.results["t_accel"].value is None
        return
    close(report.results["t_accel"].value, target / alpha, 1e-12)
    close(report.results["work_motor"].value, stall * target * target / alpha / 2, 1e-12)


# a move profile


def cycle_reference(ref: Ref, top, ta, tr, td, tw, hold):
    """τ(t), ω(t) over one cycle from the shaft balance, and the integrals of τ², τω and the loss."""
    top = mp.mpf(top)
    ends = [mp.mpf(0), mp.mpf(ta), mp.mpf(ta) + tr, mp.mpf(ta) + tr + td, mp.mpf(ta) + tr + td + tw]
    up, down = top / ta, (top / td if td else mp.mpf(0))

    def state(t):
        if t < ends[1]:
            return up, up * t
        if t < ends[2]:
            return mp.mpf(0), top
        if t < ends[3]:
            return -down, top - down * (t - ends[2])
        return None, mp.mpf(0)

    def torque(t):
        alpha, _ = state(t)
        return mp.mpf(hold) if alpha is None else ref.motor_torque(alpha)

    def power(t):
        return torque(t) * state(t)[1]

    def loss(t):
        alpha, w = state(t)
        return mp.mpf(0) if alpha is None else ref.loss_rate(alpha, w)

    pieces = ends
    square = sum(mp.quad(lambda t: torque(t) ** 2, [a + mp.mpf(10) ** -25, b - mp.mpf(10) ** -25]) for a, b in zip(pieces, pieces[1:]) if b > a)
    work = sum(mp.quad(power, [a + mp.mpf(10) ** -25, b - mp.mpf(10) ** -25]) for a, b in zip(pieces, pieces[1:]) if b > a)
    lost = sum(mp.quad(loss, [a + mp.mpf(10) ** -25, b - mp.mpf(10) ** -25]) for a, b in zip(pieces, pieces[1:]) if b > a)
    samples = [power(ends[-1] * k / 4000) for k in range(4000)] + [power(ends[1] - mp.mpf(10) ** -20), power(ends[2] + mp.mpf(10) ** -20)]
    return mp.sqrt(square / ends[-1]), work / ends[-1], max(samples), lost, ends[-1]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(j=st.one_of(st.just(0.0), st.floats(1e-3, 1.0)), t=st.one_of(st.just(0.0), st.floats(0.01, 3.0), st.floats(-3.0, -0.01)), n=st.floats(1.0, 30.0), eta=st.floats(0.4, 1.0), ta=st.floats(0.01, 1.0),
       tr=st.one_of(st.just(0.0), st.floats(0.01, 2.0)), td=st.floats(0.01, 1.0), tw=st.one_of(st.just(0.0), st.floats(0.01, 2.0)),
       rpm=st.floats(100.0, 6000.0))
def test_rms_mean_and_peak_are_the_integrals_over_the_cycle(j, t, n, eta, ta, tr, td, tw, rpm):
    jm = 1e-4
    if not j and not t:
        return
    report = taucli.drive(motor_inertia=jm, load_inertia=j or None, load_torque=t or None, ratio=[n], efficiency=eta,
                          until_omega=f"{rpm!r} rpm", accel_time=ta, run_time=tr, decel_time=td, dwell_time=tw)
    found = values(report)
    ref = Ref(jm, 0, j, t, n, eta)
    rms, mean, peak, lost, cycle = cycle_reference(ref, rpm * TWO_PI / 60, ta, tr, td, tw, 0.0)
    close(found["torque_rms"], rms, 1e-10)
    close(found["t_cycle"], cycle, 1e-14)
    scale = float(max(abs(peak), 1e-300))
    assert found["power_mean"] == pytest.approx(float(mean), rel=1e-9, abs=1e-12 * scale)
    assert found["power_peak"] == pytest.approx(float(peak), rel=1e-9)
    # energy over a cycle: the motor's net work is the work against the load and the losses (KE comes back to 0)
    theta = found["theta_move"]
    assert found["power_mean"] * cycle == pytest.approx(float(t * theta / n + lost), rel=1e-9, abs=1e-12 * scale * float(cycle))


def test_a_hoist_holds_its_load_in_the_dwell():
    """A vertical mass: at rest the motor holds mg·r/N; it counts in the RMS over the dwell."""
    kw = dict(load_mass=20, drum_radius=0.05, incline="90 deg", motor_inertia=1e-4, ratio=[5], efficiency=0.8,
              speed="1 m/s", accel_time=0.2, run_time=0.3, dwell_time=1.0)
    found = values(taucli.drive(**kw))
    hold = 20 * G0 * 0.05 / 5
    close(found["torque_hold"], hold, 1e-14)
    ref = Ref(1e-4, 0, 20 * 0.05**2, 20 * G0 * 0.05, 5, 0.8)
    rms, *_ = cycle_reference(ref, 1 * 5 / 0.05, 0.2, 0.3, 0.2, 1.0, hold)
    close(found["torque_rms"], rms, 1e-10)
    lowering = values(taucli.drive(**{**kw, "incline": "-90 deg"}))
    close(lowering["load_torque_motor"], -0.8 * hold, 1e-14)  # the load drives: ηT/N
    close(lowering["torque_hold"], -hold, 1e-14)


# units


@settings(max_examples=30, deadline=None)
@given(m=st.floats(1.0, 500.0), lead_in=st.floats(0.05, 1.0), jm=st.floats(1e-4, 1e-2), jl=st.floats(0.01, 5.0),
       force=st.one_of(st.just(0.0), st.floats(1.0, 200.0)), v=st.floats(0.5, 5.0), ta=st.floats(0.05, 0.5), rated=st.floats(1.0, 100.0))
def test_results_are_the_same_in_us_customary_units(m, lead_in, jm, jl, force, v, ta, rated):
    """lb, in/rev, lb·in·s², lb·in², lbf, ft/s, ozf·in, ms, lbf·ft: the SI results of the same scene in SI."""
    si = dict(load_mass=m * LB, lead=lead_in * IN, motor_inertia=jm * LBF * IN, load_inertia=jl * LB * IN * IN, load_force=force * LBF or None,
              speed=v * FT, accel_time=ta, run_time=0.5, dwell_time=0.25, ratio=[3], efficiency=0.9, mu=0.1, rated_torque=rated * LBF * IN / 16)
    us = dict(load_mass=f"{m!r} lb", lead=f"{lead_in!r} in/rev", motor_inertia=f"{jm!r} lb*in*s^2", load_inertia=f"{jl!r} lb*in^2",
              load_force=f"{force!r} lbf" if force else None, speed=f"{v!r} ft/s", accel_time=f"{ta * 1000!r} ms", run_time="0.5 s",
              dwell_time="250 ms", ratio=["3"], efficiency="0.9", mu="0.1", rated_torque=f"{rated!r} ozf*in")
    a, b = values(taucli.drive(**si)), values(taucli.drive(**us))
    assert set(a) == set(b)
    for key, value in a.items():
        if isinstance(value, float):
            assert b[key] == pytest.approx(value, rel=1e-11, abs=1e-13 * abs(a["torque_peak"])), key
        else:
            assert b[key] == value, key


# continuity where a regime changes


def test_a_trapezoid_shrinks_continuously_into_a_triangle():
    base = dict(motor_inertia=1e-4, load_inertia=0.05, load_torque=2, ratio=[10], efficiency=0.9, until_omega="300 rad/s",
                alpha="1000 rad/s^2", dwell_time=0.1)
    edge = 300.0**2 / 1000  # θ = ω²/α
    at = values(taucli.drive(**base, move_angle=f"{edge!r} rad"))
    for eps in (1e-6, 1e-9):
        for side in (-1, 1):
            near = values(taucli.drive(**base, move_angle=f"{edge * (1 + side * eps)!r} rad"))
            for key in ("omega_top", "t_accel", "t_run", "t_cycle", "torque_rms", "power_mean", "power_peak"):
                assert near[key] == pytest.approx(at[key], rel=10 * eps, abs=10 * eps * at["t_cycle"]), (key, side, eps)


def test_the_motor_torque_is_continuous_where_the_power_turns_round():
    """τ_out = Jα/N + T = 0: driving (÷η) and regenerating (×η) give the same torque there."""
    j, n, alpha = 0.05, 10.0, 1000.0
    balance = -j * alpha / n  # T at which T_out = 0
    at = taucli.drive(motor_inertia=1e-4, load_inertia=j, load_torque=balance, ratio=[n], efficiency=0.6, alpha=f"{alpha!r} rad/s^2")
    for eps in (1e-6, 1e-10):
        for side in (-1, 1):
            near = taucli.drive(motor_inertia=1e-4, load_inertia=j, load_torque=balance * (1 + side * eps), ratio=[n], efficiency=0.6,
                                alpha=f"{alpha!r} rad/s^2")
            assert near.results["torque_accel"].value == pytest.approx(at.results["torque_accel"].value, rel=10 * eps)


def test_the_run_up_is_continuous_where_the_switch_reaches_the_target():
    """On the line with an overhauling load, the switch speed moves with T; t_accel and θ carry on as it passes the target."""
    jm, j, n, eta, stall, no_load, target = 1.2e-4, 0.05, 10.0, 0.9, 2.0, 314.159, 250.0
    # the switch is at ω_sw = ω_nl(1 + J_m T N/(J τ_s)); it equals the target at:
    t_edge = (target / no_load - 1) * j * stall / (jm * n)

    def run(t):
        return values(taucli.drive(motor_inertia=jm, load_inertia=j, load_torque=t, ratio=[n], efficiency=eta, stall_torque=stall,
                                   no_load_speed=f"{no_load!r} rad/s", until_omega=f"{target!r} rad/s", energy=True))

    at = run(t_edge)
    for eps in (1e-7, 1e-10):
        for side in (-1, 1):
            near = run(t_edge * (1 + side * eps))
            for key in ("t_accel", "theta_accel", "work_motor"):
                assert near[key] == pytest.approx(at[key], rel=100 * eps), (key, side)


def test_a_load_heavier_than_the_stall_torque_runs_the_motor_backwards():
    """#42 item 11: 100 kg hung on a 0.1 m drum through N = 10 pulls 9.80665 N·m at the motor, more
    than its 0.5 N·m stall torque: the load runs down and turns the motor backwards,
    α₀ = (τ_s − mgr/N)/(J_m + mr²/N²) = (0.5 − 9.80665)/(1e-4 + 0.01) = −921.45 rad/s² (not 0)."""
    r = taucli.drive(motor_inertia="1e-4 kg*m^2", load_mass="100 kg", drum_radius="0.1 m", incline="90 deg", ratio=10,
                     stall_torque="0.5 N*m", no_load_speed="3000 rpm").results
    assert r["alpha0"].value == pytest.approx((0.5 - 9.80665) / (1e-4 + 100 * 0.1**2 / 10**2), rel=1e-14)
    assert r["alpha0"].value == pytest.approx(-921.45, abs=0.005)


def test_running_back_with_losses_and_friction_that_turns_to_hold():
    """Going down, the guide's friction μmg cos θ acts up the slope and the load drives the motor
    through the teeth, which keep (1 − η): α₀ = (τ_s − η(mg sin θ − μmg cos θ)r/N)/(J_m + ηmr²/N²).
    Where friction and the motor together hold the load, it stays: α₀ = 0."""
    m, g, r_drum, n, eta, mu, stall, jm = 100, 9.80665, 0.1, 10, 0.8, 0.1, 0.5, 1e-4
    theta = math.radians(60)
    r = taucli.drive(motor_inertia=jm, load_mass=m, drum_radius=r_drum, incline="60 deg", ratio=n, efficiency=eta, mu=mu,
                     stall_torque=stall, no_load_speed="3000 rpm").results
    down = m * g * (math.sin(theta) - mu * math.cos(theta)) * r_drum
    assert r["alpha0"].value == pytest.approx((stall - eta * down / n) / (jm + eta * m * r_drum**2 / n**2), rel=1e-12)
    held = taucli.drive(motor_inertia=jm, load_mass=m, drum_radius=r_drum, incline="10 deg", ratio=100, mu=0.1, stall_torque="0.05 N*m", no_load_speed="3000 rpm").results
    # uphill it asks mg(sin 10° + 0.1 cos 10°)r/100 = 0.267 N·m > 0.05: cannot start; downhill pull mg(sin 10° − 0.1 cos 10°)r/100 = 0.074 N·m
    # through η = 1 beats 0.05 too, so it runs back: check the arithmetic of both sides
    pull = m * g * (math.sin(math.radians(10)) - 0.1 * math.cos(math.radians(10))) * r_drum / 100
    assert held["alpha0"].value == pytest.approx((0.05 - pull) / (jm + m * r_drum**2 / 100**2), rel=1e-12)
    stays = taucli.drive(motor_inertia=jm, load_mass=m, drum_radius=r_drum, incline="5 deg", ratio=100, mu=0.1, stall_torque="0.05 N*m", no_load_speed="3000 rpm").results
    # at 5°: sin 5° = 0.087 < μ cos 5° = 0.0996: friction alone holds it, and the motor cannot lift it (0.18 N·m asked)
    assert stays["alpha0"].value == 0
