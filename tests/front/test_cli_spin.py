"""`taucli spin-down` through the real entry point."""

from __future__ import annotations

import pytest

from conftest import assert_usage_error

WHEEL = ("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "30rad/s", "--friction", "0.3N*m")


def test_article_potters_wheel_with_its_steps(taucli):
    result = taucli(*WHEEL)
    assert result.code == 0, result.err
    out = result.out
    for text in ("I = ½MR²", "τ_net = − τ_f", "α = τ_net / I", "= −3 rad/s²", "t = ω₀/|α|", "= 30 rad/s / 3 rad/s²", "= 10 s", "uniform deceleration"):
        assert text in out, text


def test_article_example_1_in_json(taucli):
    doc = taucli("spin-down", "--shape", "disc", "--mass", "8kg", "--radius", "0.25m", "--force", "6N", "--lever", "0.25m", "--time", "4s", "--json").json()
    results = {name: entry["value"] for name, entry in doc["results"].items()}
    assert results["alpha0"] == pytest.approx(6.0)
    assert results["omega"] == pytest.approx(24.0)
    assert results["revs"] == pytest.approx(48 / (2 * 3.141592653589793))
    assert results["t_stop"] is None and results["omega_inf"] is None
    assert any("never stops" in note for note in doc["notes"])
    assert doc["steps"][1]["equation"] == "τ = F r"


def test_get_and_to_in_revolutions_per_minute(taucli):
    out = taucli("spin-down", "--inertia", "0.1", "--omega0", "300rpm", "--viscous", "0.01", "--time", "5s", "--to", "omega=rpm", "--get", "omega", "--get", "t_stop").out
    omega, t_stop = out.splitlines()
    assert float(omega) == pytest.approx(300 * 2.718281828459045**-0.5, rel=1e-12)
    assert t_stop == "null"


def test_hz_is_read_as_revolutions_per_second_with_a_note(taucli):
    doc = taucli("spin-down", "--inertia", "0.1", "--omega0", "5Hz", "--friction", "0.1", "--json").json()
    assert doc["inputs"]["omega0"]["value"] == pytest.approx(10 * 3.141592653589793)
    assert any("Hz" in note for note in doc["notes"])


def test_numerical_method_is_named_and_unstable_runs_say_so(taucli):
    doc = taucli("spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--viscous", "0.5", "--method", "euler", "--dt", "0.5s", "--time", "3s", "--json").json()
    assert doc["method"].startswith("euler, dt = 0.5 s")
    assert doc["results"]["omega"]["value"] is None
    assert any("unstable" in note for note in doc["notes"])
    assert doc["results"]["I"]["value"] == 0.1


def test_power_law_drag_uses_rk45_under_auto(taucli):
    doc = taucli("spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--friction", "0.3", "--drag", "0.001", "--drag-exponent", "1.5", "--json").json()
    assert doc["method"].startswith("rk45")
    assert "no closed form" in doc["model"]


@pytest.mark.parametrize(
    "args,fragments",
    [
        (("--inertia", "0", "--omega0", "30rad/s"), ("--inertia", "positive")),
        (("--inertia", "-1 kg*m^2", "--omega0", "30rad/s"), ("--inertia", "positive")),
        (("--inertia", "0.1", "--friction", "0.3 N"), ("--friction", "expected a torque", "force")),
        (("--inertia", "0.1", "--viscous", "-1"), ("--viscous", "zero or more")),
        (("--inertia", "0.1", "--drag", "-0.1"), ("--drag", "zero or more")),
        (("--inertia", "0.1", "--omega0", "30 m"), ("--omega0", "angular velocity")),
        (("--omega0", "30rad/s"), ("--inertia", "--shape")),
        (("--inertia", "0.1", "--shape", "disc"), ("--inertia", "conflicts")),
        (("--inertia", "0.1", "--mass", "3kg"), ("--mass", "--shape")),
        (("--inertia", "0.1", "--force", "3N"), ("--lever", "required")),
        (("--inertia", "0.1", "--method", "midpoint"), ("--method", "rk45")),
        (("--inertia", "0.1", "--drag", "0.1", "--drag-exponent", "1.5", "--method", "exact", "--friction", "0.3", "--omega0", "3rad/s"), ("--method", "exact")),
        (("--inertia", "0.1", "--drag", "0.1", "--drag-exponent", "11", "--omega0", "3rad/s"), ("--drag-exponent", "above 0 and at most 10")),  # 0 < n < 1 is a model since #34
        (("--inertia", "0.1", "--omega0", "3rad/s", "--friction", "0.1", "--method", "euler", "--dt", "1ns", "--time", "1h"), ("--dt", "steps")),
        (("--inertia", "0.1", "--time", "-1s"), ("--time", "zero or more")),
        (("--shape", "disc", "--mass", "5kg"), ("--radius is needed",)),
    ],
)
def test_bad_input_exits_2_with_one_line(taucli, args, fragments):
    assert_usage_error(taucli("spin-down", *args), *fragments)
