"""The exports labs have, generated from the physics with noise and fitted (#44, "Done when"):
phyphox's zip, Vernier (one run and several side by side), PASCO (several runs, milliseconds)
and an encoder's counts; each fit within 3σ of the truth.

The truth is a wheel coasting under a constant friction torque τ_f and a viscous one bω
(I dω/dt = −τ_f − bω), written here from the equation, not from taucli:

    ω(t) = (ω₀ + τ_f/b) e^{−bt/I} − τ_f/b,   θ(t) = (I/b)(ω₀ + τ_f/b)(1 − e^{−bt/I}) − (τ_f/b) t,

before the wheel stops (every table here ends before it does).
"""

from __future__ import annotations

import math
import random
import zipfile

import pytest

from conftest import run_taucli

INERTIA, FRICTION, VISCOUS = 0.05, 0.02, 0.004  # kg·m², N·m, N·m·s
FITTED = "friction,viscous,omega0"
COMMON = ("--inertia", "0.05 kg*m^2", "--fit", FITTED)


def omega(t: float, omega0: float) -> float:
    ratio = FRICTION / VISCOUS
    return (omega0 + ratio) * math.exp(-VISCOUS * t / INERTIA) - ratio


def theta(t: float, omega0: float) -> float:
    ratio = FRICTION / VISCOUS
    return INERTIA / VISCOUS * (omega0 + ratio) * -math.expm1(-VISCOUS * t / INERTIA) - ratio * t


def java(x: float) -> str:
    mantissa, exponent = f"{x:.9E}".split("E")
    return f"{mantissa}E{int(exponent)}"


def fitted(*args: str) -> dict[str, tuple[float, float]]:
    result = run_taucli("fit", "spin-down", *args, "--uncertainty", timeout=180)  # (the machine may be busy: a fit of runs is several fits)
    assert result.code == 0, result.err
    names = [args[i + 1] for i, word in enumerate(args) if word == "--get"]
    values = [tuple(float(x) for x in line.split()) for line in result.out.splitlines()]
    return dict(zip(names, values))


def assert_within_3_sigma(found: dict[str, tuple[float, float]], truth: dict[str, float]) -> None:
    for name, value in truth.items():
        best, sigma = found[name]
        assert sigma > 0 and abs(best - value) <= 3 * sigma, (name, best, sigma, value)


def gets(*names: str) -> tuple[str, ...]:
    return tuple(word for name in names for word in ("--get", name))


def test_phyphox_zip_export(tmp_path):
    rng = random.Random(11)
    rows = []
    for i in range(500):  # 50 Hz, 10 s; the x and y axes noise alone, the last rows NaN as phyphox pads them
        t = 0.02 * i
        rows.append((t, rng.gauss(0, 0.01), rng.gauss(0, 0.01), omega(t, 12.0) + rng.gauss(0, 0.01)))
    text = '"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)","Gyroscope z (rad/s)","Absolute (rad/s)"\n'
    text += "".join(",".join(java(v) for v in row) + "," + java(math.hypot(*row[1:])) + "\n" for row in rows) + "1.000000000E1,NaN,NaN,NaN,NaN\n"
    path = tmp_path / "Gyroscope rotation rate 2026-11-29 10-00-00.zip"
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("Raw Data.csv", text)
        archive.writestr("meta/device.csv", '"property","value"\n"deviceModel","phone"\n')
        archive.writestr("meta/time.csv", '"event","experiment time","system time"\n"START",0.000000000E0,1.7E9\n')
    found = fitted(str(path), "--x", "Time (s)", "--y", "Gyroscope z (rad/s)=omega", *COMMON, *gets("friction", "viscous", "omega0"))
    assert_within_3_sigma(found, {"friction": FRICTION, "viscous": VISCOUS, "omega0": 12.0})


def vernier(runs: list[list[tuple[float, float]]]) -> str:
    header = ",".join(f'"Run {k}: Time (s)","Run {k}: Angular Velocity (rad/s)"' for k in range(1, len(runs) + 1))
    longest = max(len(run) for run in runs)
    lines = [",".join(f"{run[i][0]:.2f},{run[i][1]:.4f}" if i < len(run) else "," for run in runs) for i in range(longest)]
    return header + "\n" + "\n".join(lines) + "\n"


def coast(omega0: float, count: int, step: float, noise: float, rng: random.Random) -> list[tuple[float, float]]:
    return [(step * i, omega(step * i, omega0) + rng.gauss(0, noise)) for i in range(count)]


def test_vernier_one_run(tmp_path):
    path = tmp_path / "vernier.csv"
    path.write_text(vernier([coast(12.0, 60, 0.2, 0.01, random.Random(3))]))
    found = fitted(str(path), "--y", "Angular Velocity (rad/s)=omega", *COMMON, *gets("friction", "viscous", "omega0"))
    assert_within_3_sigma(found, {"friction": FRICTION, "viscous": VISCOUS, "omega0": 12.0})


def test_vernier_runs_side_by_side_fitted_together_each_its_own_omega0(tmp_path):
    rng = random.Random(5)
    path = tmp_path / "vernier.csv"
    path.write_text(vernier([coast(12.0, 60, 0.2, 0.01, rng), coast(9.0, 45, 0.2, 0.01, rng)]))  # run 2 shorter: padded with blanks
    found = fitted(str(path), "--y", "Angular Velocity (rad/s)=omega", *COMMON, "--per-run", "omega0",
                   *gets("friction", "viscous", "omega0_run1", "omega0_run2", "samples"))
    assert found["samples"][0] == 105
    assert_within_3_sigma(found, {"friction": FRICTION, "viscous": VISCOUS, "omega0_run1": 12.0, "omega0_run2": 9.0})


def test_pasco_runs_in_milliseconds_fitted_together(tmp_path):
    rng = random.Random(8)
    runs = [coast(omega0, 30, 0.4, 0.02, rng) for omega0 in (11.0, 8.0, 10.0)]
    header = ",".join(f"Time (ms) Run #{k},Angular Velocity (rad/s) Run #{k}" for k in (1, 2, 3))
    lines = [",".join(f"{run[i][0] * 1000:.0f},{run[i][1]:.4f}" for run in runs) for i in range(30)]
    path = tmp_path / "pasco.csv"
    path.write_text(header + "\n" + "\n".join(lines) + "\n")
    found = fitted(str(path), "--y", "Angular Velocity (rad/s)=omega", *COMMON, "--per-run", "omega0",
                   *gets("friction", "viscous", "omega0_run1", "omega0_run2", "omega0_run3"))
    assert_within_3_sigma(found, {"friction": FRICTION, "viscous": VISCOUS, "omega0_run1": 11.0, "omega0_run2": 8.0, "omega0_run3": 10.0})


def test_several_files_are_runs_fitted_together(tmp_path):
    rng = random.Random(9)
    paths = []
    for k, omega0 in enumerate((12.0, 7.5), start=1):
        path = tmp_path / f"coast{k}.csv"
        path.write_text("t (s),omega (rad/s)\n" + "".join(f"{t:.2f},{w:.4f}\n" for t, w in coast(omega0, 40, 0.25, 0.01, rng)))
        paths.append(str(path))
    found = fitted(*paths, *COMMON, "--per-run", "omega0", *gets("friction", "viscous", "omega0_run1", "omega0_run2"))
    assert_within_3_sigma(found, {"friction": FRICTION, "viscous": VISCOUS, "omega0_run1": 12.0, "omega0_run2": 7.5})


@pytest.mark.parametrize("how", ["cumulative", "interval"])
def test_an_encoders_counts_with_its_counts_per_revolution(tmp_path, how):
    rng = random.Random(13)
    per_rev = 360
    phase = rng.random()  # where in a count the encoder started: an offset no θ(t) has a place for
    counts = [math.floor(theta(0.05 * i, 12.0) / (2 * math.pi) * per_rev + phase) - math.floor(phase) for i in range(200)]
    cells = counts if how == "cumulative" else [c - b for c, b in zip(counts, [0, *counts])]
    path = tmp_path / "encoder.csv"
    path.write_text("Time (s),Counts\n" + "".join(f"{0.05 * i:.2f},{c}\n" for i, c in enumerate(cells)))
    found = fitted(str(path), "--counts-per-rev", str(per_rev), "--counts", how, *COMMON, *gets("friction", "viscous", "omega0"))
    assert_within_3_sigma(found, {"friction": FRICTION, "viscous": VISCOUS, "omega0": 12.0})
