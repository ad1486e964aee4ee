"""taucli drive: the published problems of docs/drive.md, with their printed answers, and how the
command reads, refuses and answers (one line on stderr and exit 2 for what it cannot take).

Published problems:
- Yaskawa Σ-V-MD servo manual, §2.2.2 "Selection Calculations": a 250 kg table on a 10 mm ball
  screw (1.0 m × 20 mm, 7.87 × 10³ kg/m³) through 2:1, J_G = 0.40 × 10⁻⁴ kg·m², μ = 0.2,
  η = 0.9, g = 9.8; 40 moves/min of 0.275 m at 15 m/min in 1.2 s. Printed: t = 1.5 s, ta = 0.1 s,
  tc = 1.0 s, n_M = 3000 min⁻¹, T_L = 0.43 N·m, J_L1 = 1.58e-4, J_B = 0.31e-4, J_L = 2.29e-4 kg·m²,
  P_O = 135 W (at T_L rounded to 0.43).
- Yaskawa Σ-S servo manual, §2.4.1: J_M = 0.00629e-4, J_L = 0.474e-4 kg·m², T_L = 0.035 N·m,
  3000 min⁻¹ in 0.1 s: T_P = 0.186 N·m.
- Reliance Electric servomotor application data: 1000 lb of thrust on a leadscrew asks 31.84 lb·in
  at 0.200 in/rev, 79.61 at 0.500, 159.23 at 1.000 (their 1/2π to three figures).
- Techno (Isel) linear-motion catalogue, technical section, rack and pinion: 5 lb on a 3 in pinion
  of 4.5 lb·in², a 2.5 lb·in² rotor, 15 ft/s: I(eq) = 11.25 lb·in², I(total) = 18.25 lb·in²,
  19.1 rev/s.
"""

from __future__ import annotations

import json
import math

import pytest

import taucli
from conftest import assert_usage_error, run_taucli

G_YASKAWA = 9.8
LB, IN, FT = 0.45359237, 0.0254, 0.3048
LBF = LB * 9.80665
RPM = 2 * math.pi / 60

YASKAWA = dict(load_mass="250 kg", lead="10 mm", part=["disc density=7870kg/m^3 radius=1cm length=1m"], ratio=[2],
               gear_inertia="0.4e-4 kg*m^2", efficiency=0.9, mu=0.2, g="9.8 m/s^2", motor_inertia="0.3e-4 kg*m^2")


def values(report) -> dict:
    return {key: value.value for key, value in report.results.items()}


def test_yaskawa_sigma_v_md_ball_screw_selection():
    found = values(taucli.drive(**YASKAWA, speed="15 m/min", accel_time="0.1 s", run_time="1 s", dwell_time="0.3 s"))
    assert found["t_cycle"] == pytest.approx(1.5, rel=1e-12)  # t = 60/n = 1.5 s
    assert found["t_accel"] == pytest.approx(0.1, rel=1e-12) and found["t_decel"] == pytest.approx(0.1, rel=1e-12)
    assert found["t_run"] == pytest.approx(1.0, rel=1e-12)  # tc = 1.0 s
    assert found["omega_top"] / RPM == pytest.approx(3000, rel=1e-12)  # n_M = 3000 min⁻¹
    assert found["travel"] == pytest.approx(0.275, rel=1e-12)  # ℓ = 0.275 m
    assert round(found["load_torque_motor"], 2) == 0.43  # T_L = 0.43 N·m
    assert round(found["linear_inertia"] / 4 * 1e4, 2) == 1.58  # J_L1 = 1.58e-4 (the table at the motor)
    assert round(found["reflected_inertia"] * 1e4, 2) == 2.29  # J_L = 2.29e-4
    assert round(found["load_torque_motor"] * found["omega_top"]) == 136  # P_O: 135 W printed, from T_L rounded to 0.43
    assert round(0.43 * found["omega_top"]) == 135
    screw = found["reflected_inertia"] - 0.4e-4 - found["linear_inertia"] / 4  # the screw's share at the motor
    assert round(screw * 1e4, 2) == 0.31  # J_B = 0.31e-4
    assert screw * 4 == pytest.approx(math.pi / 32 * 7870 * 1.0 * 0.02**4, rel=1e-12)  # the manual's πρℓd⁴/32


def test_yaskawa_as_a_trapezoid_from_its_travel_is_the_same_move():
    times = values(taucli.drive(**YASKAWA, speed="15 m/min", accel_time="0.1 s", run_time="1 s", dwell_time="0.3 s"))
    trapezoid = values(taucli.drive(**YASKAWA, distance="0.275 m", speed="15 m/min", accel="2.5 m/s^2", dwell_time="0.3 s"))
    for key in ("t_run", "t_accel", "torque_accel", "torque_decel", "torque_rms", "power_mean", "power_peak"):
        assert trapezoid[key] == pytest.approx(times[key], rel=1e-12), key


def test_yaskawa_sigma_s_acceleration_torque():
    found = values(taucli.drive(motor_inertia="0.00629e-4 kg*m^2", load_inertia="0.474e-4 kg*m^2", load_torque="0.035 N*m",
                                until_omega="3000 min^-1", in_time="0.1 s"))
    assert round(found["torque_accel"], 3) == 0.186  # T_P = 0.186 N·m


@pytest.mark.parametrize("lead,printed", [("0.200 in/rev", 31.84), ("0.500 in/rev", 79.61), ("1.000 in/rev", 159.23)])
def test_reliance_leadscrew_thrust_torque(lead, printed):
    torque = taucli.drive(lead=lead, load_force="1000 lbf").results["load_torque_motor"].value / (LBF * IN)
    assert torque == pytest.approx(printed, rel=6e-4)  # the table's 1/2π is 0.1592
    assert torque == pytest.approx(1000 * float(lead.split()[0]) / (2 * math.pi), rel=1e-12)


def test_techno_rack_and_pinion_inertias():
    found = values(taucli.drive(motor_inertia="2.5 lb*in^2", load_inertia="4.5 lb*in^2", load_mass="5 lb", drum_radius="1.5 in",
                                speed="15 ft/s", in_time="0.5 s"))
    lb_in2 = LB * IN * IN
    assert found["linear_inertia"] / lb_in2 == pytest.approx(11.25, rel=1e-12)  # I(eq) = wr²
    assert found["total_inertia"] / lb_in2 == pytest.approx(18.25, rel=1e-12)  # I(total)
    omega = found["alpha"] * found["t_accel"]
    assert round(omega / (2 * math.pi), 1) == 19.1  # 19.1 rev/s


def test_the_docs_command_line_gives_the_printed_answers():
    done = run_taucli("drive", "--motor-inertia", "0.00629e-4 kg*m^2", "--load-inertia", "0.474e-4 kg*m^2", "--load-torque", "0.035 N*m",
                      "--until-omega", "3000 min^-1", "--in-time", "0.1s", "--get", "torque_accel")
    assert done.code == 0 and round(float(done.out), 3) == 0.186
    done = run_taucli("drive", "--lead", "0.2in/rev", "--load-force", "1000lbf", "--to", "load_torque_motor=lbf*in", "--get", "load_torque_motor")
    assert done.code == 0 and float(done.out) == pytest.approx(200 / (2 * math.pi), rel=1e-12)


# reading and refusing


REFUSED = [
    (["--motor-inertia", "1e-4"], "--load-inertia or another load is required"),
    (["--load-inertia", "0.05", "--until-omega", "100rpm"], "--until-omega needs a way to get there"),
    (["--load-inertia", "0.05", "--mass", "3kg"], "--mass goes with --shape; with --load-inertia"),
    (["--mass", "3kg", "--radius", "1m"], "--mass goes with --shape"),
    (["--load-inertia", "1", "--shape", "disc", "--mass", "1kg", "--radius", "1m"], "--load-inertia conflicts with --shape"),
    (["--load-mass", "3kg"], "--load-mass needs what moves it"),
    (["--load-mass", "3kg", "--drum-radius", "1m", "--lead", "5mm"], "--lead conflicts with --drum-radius"),
    (["--load-mass", "3kg", "--drum-radius", "1m", "--g", "9.8"], "--g is used only for gravity"),
    (["--load-inertia", "1", "--incline", "30deg"], "--incline goes with --load-mass"),
    (["--load-inertia", "1", "--mu", "0.1"], "--mu goes with --load-mass"),
    (["--load-inertia", "1", "--load-force", "10N"], "--load-force needs"),
    (["--load-inertia", "1", "--efficiency", "1.2"], "--efficiency: expected a number above 0 and at most 1"),
    (["--load-inertia", "1", "--efficiency", "0"], "--efficiency: expected a positive"),
    (["--load-inertia", "1", "--ratio", "0"], "--ratio: expected a positive"),
    (["--load-inertia", "1", "--ratio", "1e30", "--ratio", "1e30"], "--ratio: expected a dimensionless between 1e-40 and 1e40"),
    (["--load-inertia", "1", "--ratio", "2,3"], "--ratio"),
    (["--load-inertia", "1", "--stall-torque", "3"], "--no-load-speed is required"),
    (["--load-inertia", "1", "--motor-torque", "3", "--stall-torque", "3", "--no-load-speed", "100rpm"], "--motor-torque conflicts"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--until-omega", "3rad/s", "--in-time", "1s", "--alpha", "3rad/s^2"], "--in-time conflicts with --alpha"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--in-time", "1s"], "--in-time needs the speed to reach"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--motor-torque", "1", "--until-omega", "3rad/s", "--in-time", "1s"], "--in-time conflicts with the motor's law"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--accel-time", "1s"], "is required with --accel-time"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--accel-time", "1s", "--until-omega", "10rad/s", "--move-angle", "3rev"], "--move-angle conflicts with the top speed"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--accel-time", "1s", "--until-omega", "10rad/s", "--alpha", "3rad/s^2"], "--alpha conflicts with --accel-time"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--move-angle", "3rev"], "--accel or --alpha is required"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--move-angle", "3rev", "--alpha", "1rad/s^2", "--run-time", "1s"], "--run-time goes with --accel-time"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--rated-torque", "3"], "--rated-torque goes with a move profile"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--speed", "3m/s", "--in-time", "1s"], "--speed needs what the mass's motion turns"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--accel", "3m/s^2"], "--accel needs"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--distance", "3m", "--alpha", "1rad/s^2"], "--distance needs"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--until-omega", "3rad/s", "--speed", "1m/s", "--lead", "5mm"], "--speed conflicts with --until-omega"),
    (["--load-mass", "10kg", "--lead", "5rev/in"], "1/(threads per inch)"),
    (["--load-mass", "10kg", "--lead", "5mm*rad"], "--lead: expected a lead, a length per revolution"),
    (["--load-mass", "10kg", "--lead", "5 mm + 0.1 in/rev"], "adds a unit with an angle to one without"),
    (["--load-mass", "10kg", "--lead", "5mm", "--incline", "100deg"], "--incline: expected an angle from -90 to 90 deg"),
    (["--load-inertia", "1", "--motor-inertia", "1", "--distance", "1m", "--move-angle", "1rev", "--lead", "5mm", "--alpha", "1rad/s^2"], "--distance conflicts with --move-angle"),
]


@pytest.mark.parametrize("args,fragment", REFUSED, ids=[" ".join(a)[:60] for a, _ in REFUSED])
def test_what_it_cannot_take_is_one_line_and_exit_2(args, fragment, capsys):
    from taucli.front import cli

    assert cli.main(["drive", *args]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("taucli: error: ") and "Traceback" not in captured.err, captured.err
    assert fragment in lines[0], lines[0]


def test_refusals_in_a_real_shell_are_the_same():
    assert_usage_error(run_taucli("drive", "--load-mass", "10kg", "--lead", "5rev/in"), "--lead", "0.2in for 5 per inch")


def test_a_lead_in_any_unit_is_the_advance_per_turn():
    base = dict(load_mass="100 kg", motor_inertia=1e-4)
    expected = 100 * (0.2 * IN / (2 * math.pi)) ** 2
    for lead in ("0.2 in/rev", "0.2 in", "5.08 mm", "5.08 mm/rev", f"{5.08 / 360!r} mm/deg", f"{0.2 * IN / (2 * math.pi)!r} m/rad", 0.2 * IN):
        assert taucli.drive(lead=lead, **base).results["linear_inertia"].value == pytest.approx(expected, rel=1e-12), lead


def test_us_customary_inertia_and_torque_read_as_their_si():
    """lb·in·s² and oz·in·s² are the pound-force's and ounce-force's (with a note); oz·in a torque is ozf·in."""
    report = taucli.drive(motor_inertia="0.001 lb*in*s^2", load_inertia="0.02 oz-in-s^2", load_torque="10 oz*in")
    inputs = {key: value.value for key, value in report.inputs.items()}
    assert inputs["motor_inertia"] == pytest.approx(0.001 * LBF * IN, rel=1e-12)
    assert inputs["load_inertia"] == pytest.approx(0.02 * LBF / 16 * IN, rel=1e-12)
    assert inputs["load_torque"] == pytest.approx(10 * LBF / 16 * IN, rel=1e-12)
    assert sum("read as pound-force" in note or "read as ounce-force" in note for note in report.notes) == 3


# answers


def test_json_strict_and_every_result_in_the_table():
    from taucli.options import SCENES

    done = run_taucli("drive", *YASKAWA_ARGS, "--speed", "15m/min", "--accel-time", "0.1s", "--run-time", "1s", "--dwell-time", "0.3s",
                      "--rated-torque", "0.637N*m", "--json")
    document = done.json()
    assert document["scene"] == "drive" and set(document["results"]) <= {r.key for r in SCENES["drive"].results}
    assert document["results"]["within_rating"]["value"] is True
    assert document["results"]["torque_rms"]["unit"] == "N*m"
    assert document["inputs"]["lead"] == {"value": 0.01, "unit": "m/rev"}


YASKAWA_ARGS = ["--load-mass", "250kg", "--lead", "10mm", "--part", "disc density=7870kg/m^3 radius=1cm length=1m", "--ratio", "2",
                "--gear-inertia", "0.4e-4 kg*m^2", "--efficiency", "0.9", "--mu", "0.2", "--g", "9.8 m/s^2", "--motor-inertia", "0.3e-4 kg*m^2"]


def test_batch_lines_and_the_python_api_agree():
    from taucli.answering import answer
    from taucli.options import SCENES

    line = {"load_mass": "250 kg", "lead": "10 mm", "ratio": ["2"], "efficiency": 0.9, "mu": 0.2, "g": 9.8, "motor_inertia": 3e-5,
            "speed": "15 m/min", "accel_time": 0.1, "run_time": 1, "dwell_time": 0.3}
    done = run_taucli("drive", "--batch", "--no-steps", stdin=json.dumps(line) + "\n" + json.dumps({**line, "ratio": ["2", "1.5"]}) + "\n")
    first, second = (json.loads(text) for text in done.out.splitlines())
    api = taucli.drive(**line)
    assert first["results"]["torque_rms"]["value"] == api.results["torque_rms"].value
    assert second["results"]["ratio_total"]["value"] == 3.0
    assert answer.solve(SCENES["drive"], line).results["torque_rms"].value == api.results["torque_rms"].value


def test_find_solves_for_an_input_and_uncertainty_carries_through():
    found = taucli.drive(load_mass="250 kg", lead="10 mm", ratio=[2], find="motor_inertia", want="inertia_ratio=5")
    j_load = 250 * (0.01 / (2 * math.pi)) ** 2 / 4
    assert found.results["motor_inertia"].value == pytest.approx(j_load / 5, rel=1e-9)
    found = taucli.drive(lead="10 mm", ratio=[2], efficiency=0.9, mu=0.2, motor_inertia=3e-5, distance="0.275 m", speed="15 m/min",
                         accel="2.5 m/s^2", dwell_time=0.3, find="load_mass", want="torque_rms=0.5 N*m")
    assert found.results["torque_rms"].value == pytest.approx(0.5, rel=1e-9)
    uncertain = taucli.drive(load_mass="250+/-10 kg", lead="10 mm", ratio=[2], motor_inertia=3e-5)
    j = uncertain.results["reflected_inertia"].value
    assert uncertain.uncertainties["reflected_inertia"] == pytest.approx(j * 10 / 250, rel=1e-6)  # J_r ∝ m


def test_a_move_profile_draws_its_speed_and_torque():
    from taucli.writing.plot import motion_points

    report = taucli.drive(load_inertia=0.05, ratio=[10], motor_inertia=1e-4, until_omega="3000 rpm", accel_time=0.1, run_time=0.2,
                          decel_time=0.05, dwell_time=0.1)
    points = motion_points(report)
    assert points[0][0] == 0 and points[-1][0] == pytest.approx(0.45, rel=1e-12)
    assert max(p[1] for p in points) == pytest.approx(100 * math.pi, rel=1e-12)
    torques = {round(p[2], 9) for p in points}
    found = values(report)
    assert {round(found["torque_accel"], 9), round(found["load_torque_motor"], 9), round(found["torque_decel"], 9)} <= torques


def test_a_motor_that_cannot_start_the_load_has_no_time():
    report = taucli.drive(motor_inertia=1e-4, load_inertia=0.05, ratio=[10], motor_torque=1, load_torque=20, until_omega="3000 rpm")
    assert report.results["t_accel"].value is None and report.results["alpha0"].value == 0
    assert any("cannot start" in note for note in report.notes)


def test_a_speed_beyond_the_line_is_never_reached():
    report = taucli.drive(motor_inertia=1e-4, load_inertia=0.05, ratio=[10], stall_torque=2, no_load_speed="3000 rpm", load_torque=5,
                          until_omega="2900 rpm")
    assert report.results["t_accel"].value is None
    assert any("never reaches" in note for note in report.notes)


def test_a_short_move_is_a_triangle_with_a_note():
    report = taucli.drive(motor_inertia=1e-4, load_inertia=0.05, ratio=[10], move_angle="1 rev", until_omega="3000 rpm", alpha="1000 rad/s^2")
    found = values(report)
    assert found["t_run"] == 0 and found["omega_top"] == pytest.approx(math.sqrt(1000 * 2 * math.pi), rel=1e-12)
    assert any("too short" in note for note in report.notes)


def test_within_rating_against_the_peak_torque_and_the_motors_line():
    base = dict(load_inertia=0.05, ratio=[10], motor_inertia=1e-4, until_omega="3000 rpm", accel_time=0.1, run_time=0.2, dwell_time=0.1)
    peak = values(taucli.drive(**base))["torque_peak"]
    assert taucli.drive(**base, peak_torque=peak * 1.01).results["within_rating"].value is True
    over = taucli.drive(**base, peak_torque=peak * 0.99)
    assert over.results["within_rating"].value is False and any("over the motor's peak" in n for n in over.notes)
    weak = taucli.drive(**base, stall_torque=peak, no_load_speed="3500 rpm")
    assert weak.results["within_rating"].value is False and any("cannot follow the move" in n for n in weak.notes)


def test_an_uncertainty_on_a_stage_is_carried_through():
    """--ratio is repeatable: an uncertainty on a stage is carried through as an option's is (#43
    item 3; it was dropped with a note, and --get ... --uncertainty printed 0 for it)."""
    alone = taucli.drive(load_mass="250 kg", lead="10 mm", motor_inertia=3e-5, ratio=["2+/-0.1"])
    reflected = alone.results["reflected_inertia"].value  # m(p/2π)²/N²: σ/value = 2 σN/N
    assert alone.uncertainties["reflected_inertia"] == pytest.approx(reflected * 2 * 0.1 / 2, rel=1e-6)
    beside = taucli.drive(load_mass="250+/-1 kg", lead="10 mm", motor_inertia=3e-5, ratio=[3, "2+/-0.1"])
    relative = math.hypot(1 / 250, 2 * 0.1 / 2)
    assert beside.uncertainties["reflected_inertia"] == pytest.approx(beside.results["reflected_inertia"].value * relative, rel=1e-6)
    done = run_taucli("drive", "--load-mass", "250kg", "--lead", "10mm", "--motor-inertia", "3e-5", "--ratio", "2+/-0.1", "--get", "reflected_inertia",
                      "--uncertainty")
    value, sigma = map(float, done.out.split())
    assert done.code == 0 and sigma == pytest.approx(value * 0.1, rel=1e-6)


def test_find_solves_for_the_ratio():
    """--find ratio with no stage given: the one stage that meets the target."""
    single = taucli.drive(load_mass="250 kg", lead="10 mm", motor_inertia=3e-5, find="ratio", want="inertia_ratio=5")
    j = 250 * (0.01 / (2 * math.pi)) ** 2
    assert single.results["ratio"].value == pytest.approx(math.sqrt(j / (5 * 3e-5)), rel=1e-9)
    assert single.results["inertia_ratio"].value == pytest.approx(5, rel=1e-9)
