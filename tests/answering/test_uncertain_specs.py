"""An uncertainty given inside a spec (a part's, a brake's, a particle's key...) or on one value of
a repeated option is carried through as an option's is (#43 item 3): it was dropped, and
`--get I --uncertainty` printed `0.009 0`. Every spec option of every scene: each numeric result's
σ is its change when that key moves by σ (σ small, so first order is exact to the tolerance)."""

from __future__ import annotations

import io
import json
import math

import pytest

import taucli
from conftest import example_keys
from taucli.front import cli
from taucli.options import SCENES, table

SPEC_KINDS = {table.PART, table.PARTICLE, table.COUPLE, table.BRAKE, table.FACE, table.BAND, table.CALIPER, table.CENTRIFUGAL, table.SIDE, table.PULL, table.ROTOR, table.REVOLVING,
              table.LOAD, table.MOTOR_CURVE}


# (scene, option, its value with {u} where "value ± σ" goes, value, σ, unit, keywords changed from the scene's example (None: left out))
CASES = [
    ("inertia", "part", "point mass={u} offset=20cm", 0.1, 1e-4, "kg", {}),
    ("inertia", "part", "plate density={u} width=1m height=0.5m", 20.0, 1e-3, "kg/m^2", {}),
    ("spin-down", "part", "point mass=1kg offset={u}", 0.2, 1e-4, "m", {}),
    ("spin-down", "brake", "force={u} mu=0.4 radius=0.1m", 10.0, 1e-3, "N", {}),
    ("spin-down", "face", "mu={u} force=10N inner-radius=5cm outer-radius=12cm", 0.3, 1e-4, "", {}),
    ("spin-down", "band", "mu=0.25 wrap={u} radius=0.1m tension=10N", 4.0, 1e-4, "rad", {}),
    ("spin-down", "caliper", "mu=0.4 force={u} inner-radius=80mm outer-radius=130mm angle=60deg", 100.0, 1e-3, "N", {}),
    ("spin-down", "centrifugal", "shoes=4 mass={u} radius=160mm spring-force=1450N mu=0.35 drum-radius=250mm", 6.0, 1e-4, "kg", {"omega0": "400rpm"}),
    ("atwood", "part", "point mass={u} offset=5cm", 0.5, 1e-4, "kg", {}),
    ("atwood", "side1", "incline angle={u}", 0.5, 1e-4, "rad", {}),
    ("atwood", "side2", "table mu={u}", 0.2, 1e-4, "", {}),
    ("atwood", "pull", "force={u}", 2.0, 1e-4, "N", {}),
    ("impulse", "part", "point mass={u} offset=20cm", 0.1, 1e-4, "kg", {}),
    ("impulse", "brake", "force={u} mu=0.4 radius=0.1m", 1.0, 1e-4, "N", {}),
    ("impulse", "face", "mu={u} force=10N inner-radius=5cm outer-radius=12cm", 0.3, 1e-4, "", {}),
    ("impulse", "band", "mu=0.25 wrap={u} radius=0.1m tension=10N", 4.0, 1e-4, "rad", {}),
    ("impulse", "caliper", "mu=0.4 force=10N pad-radius={u} centre-distance=50mm model=wear", 0.012, 1e-6, "m", {}),
    ("impulse", "centrifugal", "shoes=4 mass=6kg radius=160mm spring-force={u} mu=0.35 drum-radius=250mm", 1450.0, 1e-2, "N", {"omega0": "400rpm"}),
    ("impulse", "part_after", "point mass={u} offset=20cm", 0.1, 1e-4, "kg", {"omega0": "10rad/s", "torque": None, "duration": None}),
    ("impulse", "particle", "mass={u} speed=4m/s radius=0.5m", 0.3, 1e-4, "kg", {"torque": None, "duration": None}),
    ("impulse", "couple", "inertia={u} omega0=0", 0.2, 1e-4, "kg*m^2", {"omega0": "10rad/s", "torque": None, "duration": None}),
    ("pendulum", "part", "point mass={u} offset=1m", 0.5, 1e-4, "kg", {}),
    ("gyro", "part", "ring mass={u} radius=5cm", 0.1, 1e-5, "kg", {}),
    ("gyro", "rotor", "inertia={u} spin=5000rpm sense=cw-from-right", 0.3, 1e-4, "kg*m^2",
     {"precession": "0.5rad/s", "spin_sense": "cw-from-right", "turn": "left", "cm_distance": None}),
    ("drive", "part", "disc mass={u} radius=0.1m", 2.0, 1e-4, "kg", {"load_inertia": None}),
    ("drive", "ratio", ["{u}", "3"], 10.0, 1e-3, "", {}),
    ("flywheel", "part", "ring mass={u} radius=0.6m", 100.0, 1e-3, "kg", {"rim_radius": None, "density": None, "energy_swing": None}),
    ("balance", "mass", "mass={u} radius=0.3m angle=45deg", 2.0, 1e-4, "kg", {}),
    *(("drive", "load", spec, x, sigma, unit, {"ratio": None, "load_inertia": None, **extra}) for spec, x, sigma, unit, extra in (
        ("inertia={u} ratio=5 efficiency=0.9 torque=2N*m", 0.5, 1e-4, "kg*m^2", {}),
        ("inertia=0.5kg*m^2 ratio={u} torque=2N*m", 5.0, 1e-3, "", {}),
        ("inertia=0.5kg*m^2 ratio=5 efficiency={u} torque=2N*m", 0.9, 1e-4, "", {}),
        ("inertia=0.5kg*m^2 ratio=5 efficiency-back={u} torque=-500N*m", 0.6, 1e-4, "", {}),
        ("inertia=0.5kg*m^2 ratio=5 torque={u}", 2.0, 1e-4, "N*m", {}),
        ("mass={u} radius=0.1m ratio=5", 20.0, 1e-3, "kg", {}),
        ("mass=20kg radius={u} ratio=5", 0.1, 1e-5, "m", {}),
        ("mass=20kg radius=0.1m ratio=5 force={u}", 50.0, 1e-3, "N", {}),
        ("mass=20kg speed={u} force=50N", 1.5, 1e-4, "m/s", {"motor_speed": "1420rpm"}),
    )),
    *(("drive", "motor_curve", spec, x, sigma, unit, {"in_time": None}) for spec, x, sigma, unit in (
        ("tmax={u} slip-max=0.2 sync=3600rpm", 2.0, 1e-4, "N*m"),
        ("tmax=2N*m slip-max={u} sync=3600rpm", 0.2, 1e-5, ""),
        ("tmax=2N*m slip-max=0.2 sync={u}", 377.0, 1e-3, "rad/s"),
    )),
    ("torque", "lever", ["2m", "{u}"], 1.0, 1e-4, "m", {"r": None, "force": ["10N", "5N"], "angle": ["90deg", "90deg"]}),
]


def _given(scene, option, value, extra, text):
    base = {key: given for key, given in {**example_keys(SCENES[scene]), **extra}.items() if given is not None}
    base[option] = [item.replace("{u}", text) for item in value] if isinstance(value, list) else value.replace("{u}", text)
    return base


def test_every_spec_option_of_every_scene_is_covered():
    covered = {(scene, option) for scene, option, *_ in CASES}
    specs = {(name, option.name) for name, command in SCENES.items() for option in command.options if option.kind in SPEC_KINDS}
    assert specs <= covered, specs - covered


@pytest.mark.parametrize("option", ["load", "motor_curve"])
def test_every_key_of_drives_load_and_motor_curve_is_covered(option):
    """Each key of --load and --motor-curve moves the results it should (one case a key), not only the option as a whole."""
    from taucli.answering.drive_loads import CURVE_FIELDS, LOAD_FIELDS

    covered = {key.split("=")[0].split()[-1].replace("-", "_") for scene, name, value, *_ in CASES if name == option
               for key in value.split() if "{u}" in key}
    fields = LOAD_FIELDS if option == "load" else CURVE_FIELDS
    assert covered == set(fields), set(fields) ^ covered


@pytest.mark.parametrize(("scene", "option", "value", "x", "sigma", "unit", "extra"), CASES, ids=[f"{case[0]}-{case[1]}-{i}" for i, case in enumerate(CASES)])
def test_an_uncertainty_inside_a_spec_is_carried_through(scene, option, value, x, sigma, unit, extra):
    function = getattr(taucli, SCENES[scene].function_name)
    measured = function(**_given(scene, option, value, extra, f"{x}+/-{sigma} {unit}"))
    low, high = (function(**_given(scene, option, value, extra, f"{at} {unit}")) for at in (x, x + sigma))
    moved = 0
    for key, result in low.results.items():
        if not isinstance(result.value, float):
            continue
        change = abs(high.results[key].value - result.value)
        if change > 1e-9 * max(abs(result.value), 1e-300):
            moved += 1
            assert measured.uncertainties[key] == pytest.approx(change, rel=2e-3), key
    assert moved, "no result moves with the key: the case tests nothing"
    assert [spread for spread in measured.input_uncertainties.values()] == [pytest.approx(sigma, rel=1e-9)]  # each unit here is SI


def test_the_issues_example_on_the_command_line_and_in_batch():
    out, err = io.StringIO(), io.StringIO()
    code = cli.main(["inertia", "disc", "--mass", "1kg", "--radius", "0.1m", "--part", "point mass=100+/-10g offset=20cm", "--get", "I", "--uncertainty"],
                    cli.Environment(stdin=io.StringIO(), stdout=out, stderr=err))
    value, spread = map(float, out.getvalue().split())
    assert code == 0 and value == pytest.approx(0.009, rel=1e-12) and spread == pytest.approx(0.01 * 0.2**2, rel=1e-6)
    line = json.dumps({"inertia": 1, "omega0": "30rad/s", "brake": "force=100+/-5N mu=0.4 radius=0.5m"})
    out = io.StringIO()
    code = cli.main(["spin-down", "--batch", "--no-steps"], cli.Environment(stdin=io.StringIO(line + "\n"), stdout=out, stderr=io.StringIO()))
    document = json.loads(out.getvalue())
    assert code == 0 and document["results"]["t_stop"]["uncertainty"] == pytest.approx(1.5 * 0.05, rel=1e-6)
    assert document["inputs"]["brake1_force"]["uncertainty"] == 5.0
    assert math.isfinite(document["results"]["t_stop"]["value"])
