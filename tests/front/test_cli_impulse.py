"""`taucli impulse` through the real entry point."""

from __future__ import annotations

import pytest

from conftest import assert_usage_error


def test_constant_torque_with_steps(taucli):
    out = taucli("impulse", "--inertia", "0.1kg*m^2", "--omega0", "0", "--torque", "2N*m", "--duration", "0.5s").out
    for text in ("J = τΔt = IΔω", "ω₁ = ω₀ + τΔt/I", "= 10 rad/s", "solved for omega1"):
        assert text in out, text


def test_solve_for_the_duration_with_get(taucli):
    assert float(taucli("impulse", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "0", "--omega1", "300rpm", "--torque", "0.5N*m", "--get", "duration").out) == pytest.approx(0.1 * 10 * 3.141592653589793 / 0.5)


def test_a_brief_blow_gets_its_note(taucli):
    doc = taucli("impulse", "--inertia", "2e-4", "--omega0", "0", "--torque", "3N*m", "--duration", "5ms", "--json").json()
    assert any("brief blow" in note for note in doc["notes"])


def test_skater_in_json(taucli):
    doc = taucli("impulse", "--inertia", "4kg*m^2", "--inertia-final", "1.5kg*m^2", "--omega0", "1rev/s", "--json").json()
    assert doc["results"]["omega1"]["value"] == pytest.approx(2 * 3.141592653589793 * 4 / 1.5)
    assert doc["results"]["work"]["value"] > 0
    assert "L conserved" in doc["model"]


def test_profile_from_a_file_with_samples(taucli, tmp_path):
    path = tmp_path / "blow.csv"
    path.write_text("t [ms], torque [N*m]\n0, 0\n1, 5\n2, 8\n3, 5\n4, 0\n", encoding="utf-8")
    doc = taucli("impulse", "--inertia", "0.01", "--torque-profile", str(path), "--json").json()
    assert doc["results"]["J"]["value"] == pytest.approx(56 / 3 * 1e-3)
    assert doc["method"] == "simpson"
    assert [row["t"] for row in doc["samples"]] == pytest.approx([0, 0.001, 0.002, 0.003, 0.004])
    trapezoid = taucli("impulse", "--inertia", "0.01", "--torque-profile", str(path), "--method", "trapezoid", "--get", "J").out
    assert float(trapezoid) == pytest.approx(18e-3)


@pytest.mark.parametrize(
    "args,fragments",
    [
        (("--inertia", "0.1", "--omega1", "2rad/s"), ("are missing", "fifth")),
        (("--inertia", "0.1", "--omega0", "0", "--omega1", "11rad/s", "--torque", "2", "--duration", "0.5s"), ("disagree",)),
        (("--inertia", "0.1", "--inertia-final", "0.05", "--torque", "2"), ("--torque conflicts with --inertia-final",)),
        (("--inertia-final", "0.05", "--omega0", "2rad/s"), ("--inertia", "required")),
        (("--inertia", "0.1", "--torque-profile", "/nonexistent.csv"), ("--torque-profile", "readable")),
        (("--inertia", "0.1", "--omega0", "0", "--torque", "2", "--duration", "1s", "--method", "simpson"), ("--method", "--torque-profile")),
        (("--inertia", "0.1", "--omega0", "0", "--torque", "2", "--duration", "-1s"), ("--duration", "positive")),
        (("--inertia", "0.1", "--omega0", "0", "--torque", "2 N", "--duration", "1s"), ("--torque", "force")),
        # a file with no line end: it was read into memory without end (the fuzz suite's hang)
        (("--inertia", "0.1", "--torque-profile", "/dev/zero"), ("--torque-profile", "line 1", "longer than")),
    ],
)
def test_bad_input(taucli, args, fragments):
    assert_usage_error(taucli("impulse", *args), *fragments)
