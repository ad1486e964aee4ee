"""Every result agrees with its definition, in every scene and every way of giving its inputs.

A silent wrong number once came out of ``impulse``: with all five of I, ω₀, ω₁, τ, Δt given,
``delta_omega`` was I(ω₁ − ω₀). This is the check that catches that class of defect. For each
scene, seeded random draws build keyword sets (a model's base that works, then random subsets of
the scene's other options, values over several orders of magnitude with both signs where a sign
means something, one value in five written as a text in another unit); each is solved through
the Python API; the draws the scene refuses with taucli.InputError are counted, and a fair share
must be accepted and every model and branch reached, so that the check is not vacuous. On each
accepted report every definition whose results are present and not null must hold:

    |got − want| ≤ 1e-12 · max(|got|, |want|, scale)

scale is 0 for a product or a quotient (agreement relative to the result); for a sum or a
difference it is the size of its largest term, because the terms themselves carry a rounding of
~1e-16 of their size, and a solver rightly computes a difference of near-equal numbers without
the cancellation (KE_lost, a stop's ω₀ + αt): it and the difference of the two rounded results
then agree to ulps of the terms, not of the difference; for an angle it is 1 rad (atan2 of two
rounded sides is good to ulps of a radian). One definition is not an identity of the rounded
numbers alone: spin-down's energy balance, KE0 − KE = Σ losses − work_drive, ties an ω and a θ
found by stepping where there is no closed form (a motor against losses); there it is held to
1e-9, rk45's accuracy at its default rtol 1e-10, and not at all for euler and rk4 (good to 1e-3
by design).

The definitions (tests/definitions/, one module per scene; conventions from docs/SCENE.md and
DESIGN.md's "Names and signs"):

- a point at r (--at; scenes/point.py): v_t = |ω|r (a speed), a_c = ω²r, a_t = αr along the
  motion (−αr while ω < 0), a_total = √(a_t² + a_c²), a_angle = atan2(a_t, a_c) (signed,
  positive toward the motion), s = rθ with θ the angle the scene reports (net, in spin-down);
  v_t0, a_c0, a_total0, a_angle0 at the start; α that of the instant (after a stop: held or
  turned back); from rest a_t = |α|r (it sets off along α). The pendulum's ω at --angle is signed
  as it first gets there, its a_t along the motion.
- spin-down: KE0 = ½Iω₀², KE = ½Iω² at the end (--time, else the target, else the stop), the balance above, work_drive = τθ (constant
  drive) or Pt (motor), the friction's work τ_f × the angle swept and each contact's its torque ×
  that angle, the power of the drive (τω, P = τω for a motor) and of each loss (τ_f|ω|, bω²,
  k|ω|ⁿ⁺¹, brakes' and faces' τ|ω|) at one instant, power_mean = work_drive/t, torque_net = Iα₀,
  Iα₀ = the net torque at ω₀, the steady speed where the torques balance, revs = θ/2π (_stop,
  _total), θ_total = |θ_stop| + |θ − θ_stop|, a constant α's drive and kinematics (ω = ω₀ + αt,
  θ = ω₀t + ½αt², ω² = ω₀² + 2αθ, the stop), --in-time meeting its target, ω₀ from --ke0
  (√(2E/I)) and --rim-speed (v/R), μNr and (2/3)μF(Ro³ − Ri³)/(Ro² − Ri²) or μF(Ro + Ri)/2
  (pressed by the body's weight).
- impulse: Δω = ω₁ − ω₀; J = τΔt, = ΔL = L1 − L0 (τΔt = IΔω), = I(ω₁ − ω₀) the body's own where
  particles and couples meet it, = 0 for the skater, = ∫τ dt for a profile (trapezoid; Simpson
  exact for a quadratic); J_net = IΔω; L0 = Iω₀ and L1 = I₁ω₁ (+ what meets or leaves the body),
  L0 = L1 where no torque acts; KE = ½Iω² (+ ½mv²); work = KE1 − KE0; KE_lost = KE0 − KE1;
  KE_lost_fraction = KE_lost/KE0; a rebound's v′ − ω₁r⊥ = −e(v − ω₀r⊥); each part's J = L₁ − L₀,
  adding to zero; under a brake ω₁ from constant α in each stretch (held at rest), each
  contact's τ|ω₀| and τ × angle swept, KE1 − KE0 = τθ − their work; peak_torque the largest in
  size.
- atwood: each block along its path, T1 = G1 − s μk1 N1 − m1 a and T2 = G2 + s sgn(ρ) μk2 N2 + m2 a2
  (G the pull of gravity, m g sin θ, and of the pulls away from the pulley; N = m g cos θ − P sin φ;
  hanging θ = 90°), T1r1 − σT2r2 − τd − τa sgn ω = Iα, α = a/r1, a2 = ρa (ρ = σ r2/r1, σ = −1 both on
  one side), T ≥ 0 (a string only pulls), N ≥ 0, at rest each balance within its static limit,
  a_massless, the capstan ratio e^{μβ} sliding and e^{μ_min β} at the limit, grips ⇔ μ ≥ rim_mu_min,
  a_rim = αR, uniform motion before a stop (v = v₀ + at, x = v₀t + ½at², v² = v₀² + 2ax), t_stop =
  −v₀/a and distance_stop = −v₀²/2a, the work of the forces = ΔKE of the blocks and the pulley.
- rolling: ma = ΣF and Iα = Στ (I = k²mR²), α = a/R rolling, mu_min = |f|/N, |f| = μk N
  slipping, rolls ⇔ μs ≥ mu_min, v² = v₀² + 2aL and L = −v₀t + ½at² (v₀ up the slope), the climb
  (v₀²/2a, d sin θ, v₀/a), KE_trans = ½mv², KE_rot = ½Iω², KE = their sum; a skid's v_roll (μk g
  and L about the contact), d_roll, ω_roll = v_roll/R, energy_lost; a yo-yo's T = m(g − a),
  Iα = Tr, v² = v₀² + 2ah, ΔKE = mgh; a spool's critical angle (a = 0 there); a body and a
  hanging mass: Ma = T − Mg sin θ − f, Iα = fR + cTR, m a_h = mg − T₂, T₂ − T = ½m_p a_h,
  a_h = a + cRα, T and T₂ ≥ 0; a yo-yo spun in place: T = mg, Iα = Tr, a_hand = rα,
  ½I(ω² − ω₀²) = TL; a rim point from the ground: |v + ω × r| and |a + α × r − ω²r| and their
  directions, the bottom at rest while it rolls.
- pendulum: period_small = 2π√(I/(mgd + κ)), equivalent_length = centre_of_percussion = I/(md),
  alpha0 = |mgd sin θ₀ + κθ₀|/I, ½Iω² + mgd(1 − cos θ) + ½κθ² the same at the start, the
  bottom, --angle and (exact models) --time, omega0_over, goes_over, the pivot's force
  m√((dω² + g cos θ)² + (dα + g sin θ)²), a torsion pendulum's 2π√(I/κ).
- torque: τ = Σ r × F (rF sin θ in the plane), tau = |τ|, lever_arm = |r × F|/|F|;
  L = Σ m r × v, L = |L|. gyro: L = Iω_s, Ω = mgr/L (τ/(L sin θ)), period_p = 2π/|Ω_slow|
  (2π/|Ω| without exact rates), the roots of I⊥Ω²cos θ − LΩ + mgr = 0 (residual, sum and
  product), spin_min = √(4I⊥ mgr cos θ)/I. inertia: the shapes' closed forms, I = I_cm + Md²,
  k = √(I/M), a body's I and mass the sums of its parts'. drive: J/N² and m r², m(p/2π)² at the
  motor, the load torque T/(Nη) (ηT/N regenerating), the motor torque at α through the train,
  t = ω/α and the energy balance of a run-up, the line's α₀, ω_ss and τ_m, a move's times,
  angle, phase torques, peak, RMS and mean power (tests/definitions/drive.py).

Each defect this check found has a test below with its minimal call: a face pressed by a body
of parts, a linear drag reported as viscous, a profile beside --inertia-final, a point under a
brake (α without the friction, the angle past the stop).
"""

from __future__ import annotations

import pytest
from definitions import atwood, drive, flywheel, impulse, inertia, pendulum, rolling, rolling_drum, spin, vectors
from definitions.check import G0, run_scene, values

import taucli


def test_spin_down_results_agree_with_their_definitions():
    branches = {"laws": 150, "alpha": 40, "kinematics": 40, "power": 40, "in_time": 40, "closed": 15, "bisection": 10, "friction": 80,
                "viscous": 60, "drag": 50, "drag_exponent": 5, "torque": 60, "push": 8, "brake": 30, "face": 8, "face weight": 8,
                "band": 30, "caliper": 30, "brake lever": 15, "face pmax": 10, "time": 100, "until_omega": 50, "until_angle": 30, "until_arc": 4, "energy": 100, "at": 60, "ke0": 8, "rim_speed": 8,
                "stepper": 5, "held": 3, "units": 200}
    _, checker = run_scene("spin_down", spin.draw_spin, spin.check_spin, 2600, 31, 0.5, branches)
    assert checker.checked["KE0 − KE = Σ losses − work_drive"] > 100
    assert checker.checked["theta_until = s/R (--until-arc)"] >= 4


def test_spin_down_energy_balances_agree_with_their_definitions():
    """#34 item 2: --work, --lift-mass, --vehicle-mass (their own draws, so the others' seeds keep their draws)."""
    branches = {"transfer": 300, "work": 60, "lift_mass": 60, "vehicle_mass": 60, "both": 60, "until_omega": 30, "units": 40}
    _, checker = run_scene("spin_down", spin.draw_transfer, spin.check_spin, 400, 34, 0.9, branches)
    for name in ("KE_after = KE0 + W (work-energy)", "m g h = energy_delivered", "½ m v² = energy_delivered"):
        assert checker.checked[name] > 15, (name, checker.checked[name])


def test_impulse_results_agree_with_their_definitions(tmp_path):
    branches = {"balance": 150, "all five": 15, "solve inertia": 15, "solve omega0": 15, "solve omega1": 15, "solve torque": 15,
                "solve duration": 15, "partial": 15, "skater": 30, "meeting": 60, "particle stick": 20, "particle angle": 10, "particle ride": 10,
                "particle leave": 10, "particle rebound": 5, "particle walks": 10, "couple": 20, "clutch": 5, "braked": 30, "brake": 20, "face": 10, "face weight": 4, "band": 8, "profile": 30,
                "quadratic": 10, "samples": 10, "at": 60, "units": 100}
    run_scene("impulse", lambda rng: impulse.draw_impulse(rng, tmp_path), impulse.check_impulse, 1600, 20, 0.5, branches)


def test_atwood_results_agree_with_their_definitions():
    branches = {"hanging": 100, "incline": 60, "stepped": 50, "rim": 50, "pulley mass": 80, "pulley inertia": 50, "part": 15,
                "axle friction": 40, "mu_k": 30, "mu_s": 20, "v0": 50, "distance": 60, "time": 60, "at": 50, "units": 60,
                "general": 150, "side1 table": 15, "side1 incline": 30, "side2 table": 15, "side2 incline": 30, "side friction": 40, "pull": 60,
                "pull in place of m1": 5, "drive": 40, "same side": 25, "steps": 60, "fixed drum": 20}
    _, checker = run_scene("atwood", atwood.draw_atwood, atwood.check_atwood, 1600, 11, 0.4, branches)
    for definition in ("T1 = G1 − s μk1 N1 − m1 a", "T2 = G2 + s sgn(ρ) μk2 N2 + m2 a2", "T1 r1 − σ T2 r2 − τd − τa sgn ω = I α",
                       "W_gravity + W_pulls + W_drive − W_friction = ΔKE", "t_stop = −v₀/a", "a2 = ρ a (the strings' constraint)"):
        assert checker.checked[definition] > 20, (definition, checker.checked[definition])


def test_rolling_results_agree_with_their_definitions():
    branches = {"incline": 100, "flat": 50, "pull": 100, "yoyo": 40, "k2": 40, "inertia": 40, "mu_s": 30, "mu_k": 30, "length": 50,
                "height": 15, "climb": 15, "skid": 20, "rolls along": 15, "pull up a slope": 20, "spool": 25, "pull height": 20,
                "yoyo by I": 4, "axle": 10, "drop": 20, "at": 60, "units": 60, "hanging": 100, "string top": 40, "pulley mass": 40,
                "hanging slope": 30, "in place": 40, "in place by I": 8, "string pulled": 20, "on the rim": 60, "climb and back": 20}
    _, checker = run_scene("rolling", rolling.draw_rolling, rolling.check_rolling, 1400, 5, 0.4, branches)
    for name in ("v_ground = |v + ω × r|", "a_ground = |a + α × r − ω² r|", "v_ground = 0 at the bottom while it rolls", "T₂ − T = ½ m_p a_h (the pulley)",
                 "I α = f R + c T R", "|f| = μk N (slipping)", "I α = T r", "½ I (ω² − ω₀²) = T L", "v = −v₀ + at at the bottom"):
        assert checker.checked[name] >= 5, (name, checker.checked[name])


def test_drum_yoyo_results_agree_with_their_definitions():
    """#46 item 7: a yo-yo on a drum that turns (its own draws): Newton's equations for the body and
    the drum, the string's condition, the energy of all three motions."""
    branches = {"drum yoyo": 300, "drum mass": 120, "drum inertia": 120, "drum friction": 60, "no pull": 80, "time": 100, "drop": 40, "units": 40}
    _, checker = run_scene("rolling", rolling_drum.draw_drum_yoyo, rolling.check_rolling, 700, 47, 0.6, branches)
    for name in ("I_d α_d = T R − τ_f", "a = r α + R α_d (the string)", "the drum held: T R ≤ τ_f", "KE = m g x + W_pull − W_friction (body and drum)",
                 "omega = α t (the body's, not v/r)", "KE_drum = ½ I_d ω_d²", "W_friction = τ_f θ_d"):
        assert checker.checked[name] >= 10, (name, checker.checked[name])


def test_pulled_yoyo_results_agree_with_their_definitions():
    """#46 item 1: a yo-yo pulled or held besides its string, after a drop or a time (its own draws)."""
    branches = {"pulled yoyo": 300, "pull at": 150, "time": 100, "drop": 40, "axle": 100, "inertia": 80, "v0": 60, "units": 40}
    _, checker = run_scene("rolling", rolling.draw_pulled_yoyo, rolling.check_rolling, 700, 46, 0.6, branches)
    for name in ("I α = T r − F d", "a_hand = −a − α d (the pulled point, upward)", "KE − KE₀ = m g x + W_pull", "W_pull = F × the pulled point's rise",
                 "KE − KE₀ = m g h + W_pull", "v² = v₀² + 2ax"):
        assert checker.checked[name] >= 20, (name, checker.checked[name])


def test_pendulum_results_agree_with_their_definitions():
    branches = {"inertia": 60, "rod": 40, "disc": 30, "point": 30, "plate": 20, "torsion": 50, "at the top": 20, "angle": 60, "time": 60,
                "at": 40, "method small-angle": 4, "method rk45": 4, "method verlet": 4, "method exact": 4, "units": 50}
    run_scene("pendulum", pendulum.draw_pendulum, pendulum.check_pendulum, 700, 7, 0.5, branches)


def test_torque_results_agree_with_their_definitions():
    run_scene("torque", vectors.draw_torque, vectors.check_torque, 600, 3, 0.8, {"vectors": 60, "plane": 30, "particles": 30, "both": 20, "nearly parallel": 10,
                                                                                        "momentum": 15, "about": 40})


def test_gyro_results_agree_with_their_definitions():
    run_scene("gyro", vectors.draw_gyro, vectors.check_gyro, 600, 13, 0.6, {"inertia": 60, "shape": 80, "torque": 30, "inertia_perp": 40, "units": 50,
                                                                                 "precession": 40, "senses": 20, "rotors": 5})


def test_inertia_results_agree_with_their_definitions():
    branches = {"offset": 30, "part point": 15, "part disc": 15, "part inertia": 15, "part gyration": 15, "part density": 15, "units": 60,
                **{shape: 10 for shape in inertia.SHAPE_DIMENSIONS}}
    run_scene("inertia", inertia.draw_inertia, inertia.check_inertia, 800, 17, 0.8, branches)


def test_bodies_by_density_and_gyration_agree_with_their_definitions():
    """#34: --density per volume, area or length (by its unit), --gyration with --mass."""
    branches = {"gyration": 20, "density kg/m^3": 40, "density kg/m^2": 60, "density kg/m": 30}
    run_scene("inertia", inertia.draw_by_density, inertia.check_by_density, 300, 34, 0.95, branches)


def test_drive_results_agree_with_their_definitions():
    branches = {"ratio": 150, "stages": 60, "efficiency": 150, "gear": 50, "load inertia": 100, "body": 40, "drum": 80, "screw": 80,
                "incline": 50, "mu": 50, "force": 30, "load torque": 100, "reflect": 40, "alpha": 40, "in_time": 40, "line": 40,
                "constant": 40, "times": 50, "trapezoid": 80, "rated": 30, "energy": 60, "units": 80}
    run_scene("drive", drive.draw_drive, drive.check_drive, 1200, 41, 0.6, branches)


@pytest.mark.parametrize("scene", ["spin_down", "impulse"])
def test_face_weight_includes_the_parts(scene):
    # a 2 kg disc of radius 0.1 m with a 1 kg point on it, lying on its face, μ = 0.5 under uniform pressure:
    # τ = μ (3 kg) g (2/3) R
    extra = {"torque": 0.0, "duration": 1.0} if scene == "impulse" else {}
    report = getattr(taucli, scene)(shape="disc", mass=2, radius=0.1, part=["point mass=1kg offset=0.05m"], omega0=10.0, face=["mu=0.5"], **extra)
    assert report.results["torque_face"].value == pytest.approx(0.5 * 3 * G0 * 2 * 0.1 / 3, rel=1e-12)


def test_spin_linear_drag_is_reported_as_drag():
    found = values(taucli.spin_down(inertia=1, omega0=10.0, drag=0.1, drag_exponent=1, energy=True, time=1))
    omega = found["omega"]
    assert found.get("power_viscous") is None and found.get("work_viscous") is None
    assert found["power_drag"] == pytest.approx(0.1 * omega * omega, rel=1e-12)


def test_impulse_profile_with_inertia_final_is_not_ignored(tmp_path):
    profile = tmp_path / "blow.csv"
    profile.write_text("t [s], torque [N*m]\n0, 1\n1, 1\n")  # J = 1 N·m·s
    try:
        report = taucli.impulse(inertia=2, inertia_final=1, omega0=1.0, torque_profile=str(profile))
    except taucli.InputError:
        return  # refused: as good as taking the profile in
    assert report.results["J"].value == pytest.approx(1.0, rel=1e-12)


def test_impulse_point_under_a_brake_has_the_net_alpha():
    # I = 2.5 kg·m², τ = 5 N·m against a brake of 0.4 × 100 N × 0.5 m = 20 N·m: α = (5 − 20)/2.5 = −6 rad/s²; ω 10 -> 4 rad/s in 1 s
    found = values(taucli.impulse(inertia=2.5, omega0=10.0, torque=5, duration=1, brake=["force=100N mu=0.4 radius=0.5m"], at=0.5))
    assert found["omega1"] == pytest.approx(4.0, rel=1e-12)
    assert found["a_t"] == pytest.approx(-6 * 0.5, rel=1e-12)


def test_impulse_point_under_a_brake_travels_to_the_stop():
    # α = −6 rad/s² (above): the body stops at t = 10/6 s after θ = 10²/12 rad; the brake's 20 N·m then holds it against 5 N·m
    found = values(taucli.impulse(inertia=2.5, omega0=10.0, torque=5, duration=3, brake=["force=100N mu=0.4 radius=0.5m"], at=0.5))
    assert found["omega1"] == 0
    assert found["s"] == pytest.approx(0.5 * 100 / 12, rel=1e-12)



def test_flywheel_results_agree_with_their_definitions():
    branches = {"mean": 100, "band": 50, "rim": 50, "rim radius": 20, "solve I": 80, "solve energy": 80, "solve cs": 80, "punch": 40, "±": 30,
                "density": 80, "units": 40}
    run_scene("flywheel", flywheel.draw_flywheel, flywheel.check_flywheel, 600, 43, 0.6, branches)
