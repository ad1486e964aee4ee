"""--find finds every root, or says where it may not have (#31 items 5, 6, 7, and 2's --want note).

The references are independent of taucli.numerics.steppers.roots and taucli.answering.find: closed forms written from the
physics with mpmath, and a brute-force scan of the forward scene (its library function over a
fine grid, each sign change bisected).
"""

from __future__ import annotations

import io
import math
import random

import mpmath
import pytest

import taucli
from taucli import options
from taucli.front import cli
from taucli.front import completions
from taucli.answering import pipeline
from taucli.numerics import roots
from taucli.core.errors import InputError
from taucli.answering.inputs import read

MP_DPS = 40
with mpmath.workdps(MP_DPS):
    G = mpmath.mpf("9.80665")


def run(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    code = cli.main(list(args), cli.Environment(stdin=io.StringIO(""), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


def found_roots(report, name: str) -> list[float]:
    roots_value = report.results.get("roots")
    return list(roots_value.value) if roots_value is not None else [report.results[name].value]


# --- item 5: every root ------------------------------------------------------------------------


def test_every_angle_where_the_pendulums_point_has_the_tangential_acceleration():
    # A rod (2 kg, 1 m) on a pivot at its end, let go at 170°: at θ, a point 1 m out has
    # |a_t| = (m g d / I) r |sin θ| = 1.5 g |sin θ|, along the motion (#32): positive on the way down to the
    # bottom (it speeds up), negative past it. a_t = +9.8 m/s² at asin(9.8 / 1.5g) and at π minus it; the
    # search once found only the first (the issue's ±0.73 rad, found where ±2.41 rad also were, as sizes).
    report = taucli.pendulum(shape="rod", length="1m", mass="2kg", axis="end", angle0="170deg", at="1m", find="angle", want="a_t=9.8m/s^2")
    with mpmath.workdps(MP_DPS):
        small = mpmath.asin(mpmath.mpf("9.8") / (mpmath.mpf("1.5") * G))
        expected = sorted(float(x) for x in (small, mpmath.pi - small))
    assert found_roots(report, "angle") == pytest.approx(expected, rel=1e-12)
    assert any("2 values" in note for note in report.notes)
    slowing = taucli.pendulum(shape="rod", length="1m", mass="2kg", axis="end", angle0="170deg", at="1m", find="angle", want="a_t=-9.8m/s^2")
    assert found_roots(slowing, "angle") == pytest.approx(sorted(-x for x in expected), rel=1e-12)


def test_the_search_never_calls_its_roots_all_without_grounds():
    """Where the samples do not resolve the result (it turns at neighbouring samples), the search
    says where, and the report says which range it searched and that it may hold more roots."""
    xs = roots.grid((1e-3, 1e6), "positive")
    search = roots.search(lambda x: math.sin(x) - 0.5, xs, 0.5)
    assert not search.complete and search.doubts
    # a result the grid resolves: one root, and no doubt
    tame = roots.search(lambda x: math.log(x) - 0.5, xs, 0.5)
    assert tame.complete and tame.roots == pytest.approx([math.exp(0.5)], rel=1e-14)


def test_the_report_says_which_range_it_searched_where_it_may_miss(monkeypatch):
    # Were the search blind to τ = r F sin θ repeating every turn, the grid beyond a turn (a few values a
    # decade) could not resolve it: the report must say so, not call its roots all there are.
    monkeypatch.setattr(roots, "_repeats", lambda *args: False)
    report = taucli.torque(force="80N", lever="0.25m", find="angle", want="tau_z=10N*m")
    solution = next(step for step in report.steps if step.title == "Solve for angle")
    said = " ".join(report.notes)
    assert "may have missed roots" in said and "from -1e40 rad to 1e40 rad" in said and "may hold more" in said
    assert "the only root" not in solution.why and "in all" not in solution.why and "may hold more" in solution.why
    assert "every angle" not in report.results["roots"].label
    assert all(any(abs(x - r) < 1e-12 for r in found_roots(report, "angle")) for x in (math.pi / 6, 5 * math.pi / 6))


def test_an_angle_the_result_repeats_every_turn_of_is_searched_over_one_turn():
    # τ = r F sin θ = 10 N·m with r F = 20 N·m: θ = 30° and 150°, and each plus whole turns
    report = taucli.torque(force="80N", lever="0.25m", find="angle", want="tau_z=10N*m")
    assert found_roots(report, "angle") == pytest.approx([math.pi / 6, 5 * math.pi / 6], rel=1e-13)
    assert any("repeats every turn" in note for note in report.notes)


# The class check: --find against a brute-force scan of the forward scene, on random scenes.

SCAN = 20_000


def _forward(scene: str, given: dict, name: str):
    """The scene's library function with ``name`` moved (SI), its numeric results or None."""
    command = options.scene(scene)
    arguments, _ = read(command, given)
    library = pipeline.library(command.library)

    def at(x: float) -> dict | None:
        try:
            report = library(**{**arguments, name: x})
        except (InputError, ArithmeticError, ValueError):
            return None
        return {key: float(v.value) for key, v in report.results.items()
                if isinstance(v.value, (int, float)) and not isinstance(v.value, bool) and math.isfinite(v.value)}

    return command, at


def _scan_roots(values: list, xs: list, g) -> list[float]:
    """Each sign change of g over the scan, bisected to the last bit; a jump is not a root."""
    found = []
    for (a, ga), (b, gb) in zip(zip(xs, values), zip(xs[1:], values[1:])):
        if ga is None or gb is None:
            continue
        if ga == 0:
            found.append(a)
            continue
        if ga * gb > 0:
            continue
        for _ in range(200):
            m = (a + b) / 2
            if m in (a, b):
                break
            gm = g(m)
            if gm is None:
                break
            if (gm > 0) == (ga > 0):
                a, ga = m, gm
            else:
                b, gb = m, gm
        scale = max(abs(v) for v in values if v is not None) or 1.0
        if gb is not None and min(abs(ga), abs(gb)) <= 1e-7 * scale:
            found.append((a + b) / 2)
    return found


def _pendulum(rng: random.Random):
    shape = rng.choice(["rod", "disc", "point"])
    given = {"shape": shape, "mass": f"{rng.uniform(0.5, 5):.3f}kg", "angle0": f"{rng.uniform(20, 178):.2f}deg", "at": f"{rng.uniform(0.2, 1.5):.3f}m"}
    given.update({"rod": {"length": "1m", "axis": "end"}, "disc": {"radius": "0.3m", "offset": "0.4m"}, "point": {"radius": "0.8m"}}[shape])
    if rng.random() < 0.3:
        given["omega0"] = f"{rng.uniform(-2, 2):.3f}rad/s"
    return "pendulum", given, "angle", (-math.pi, math.pi), ["a_t", "omega", "t_angle", "a_c"]


def _spin_down(rng: random.Random):
    omega0, t = rng.uniform(5, 50), rng.uniform(0.5, 10)
    given = {"shape": "disc", "mass": "5kg", "radius": "0.2m", "omega0": f"{omega0:.3f}rad/s", "time": f"{t:.3f}s"}
    if rng.random() < 0.6:
        given["viscous"] = f"{rng.uniform(0.001, 0.05):.4f} N*m*s"
    return "spin-down", given, "friction", (0.0, 3 * 0.1 * omega0 / t), ["omega", "theta", "t_stop", "theta_stop"]


def _atwood(rng: random.Random):
    m1, m2, radius = rng.uniform(0.5, 5), rng.uniform(0, 5), 0.1
    given = {"m1": f"{m1:.3f}kg", "m2": f"{m2:.3f}kg", "pulley_radius": f"{radius}m", "distance": f"{rng.uniform(0.1, 2):.3f}m",
             "v0": f"{rng.uniform(-3, 3):.3f}m/s"}
    if rng.random() < 0.4:
        given["axle_friction"] = f"{rng.uniform(0, 0.3):.3f} N*m"
    return "atwood", given, "pulley_inertia", (0.0, 20 * (m1 + m2) * radius**2), ["a", "T1", "v", "t"]


def _rolling(rng: random.Random):
    given = {"shape": rng.choice(["disc", "ring", "sphere"]), "mass": "1kg", "radius": "0.1m", "length": f"{rng.uniform(0.5, 5):.2f}m"}
    mu_s = rng.uniform(0.05, 0.6)
    given.update({"mu_s": f"{mu_s:.3f}", "mu_k": f"{mu_s * rng.uniform(0.5, 1):.3f}"})
    return "rolling", given, "angle", (0.0, math.pi / 2), ["a", "friction", "v", "t"]


@pytest.mark.parametrize("draw", [_pendulum, _spin_down, _atwood, _rolling], ids=["pendulum angle", "spin-down friction", "atwood pulley_inertia", "rolling angle"])
def test_find_has_every_root_a_brute_force_scan_finds(draw):
    rng = random.Random(f"31-{draw.__name__}")
    for _ in range(3):
        scene, given, name, (low, high), keys = draw(rng)
        command, at = _forward(scene, given, name)
        xs = [low + (high - low) * (k + 0.5) / SCAN for k in range(SCAN)]
        scan = [at(x) for x in xs]
        for key in rng.sample(keys, 2):
            valued = [x for x, values in zip(xs, scan) if values is not None and key in values]
            if not valued:
                continue
            x0 = rng.choice(valued)
            target = at(x0)[key]
            unit = command.result(key).unit
            try:
                report = getattr(taucli, scene.replace("-", "_"))(**given, find=name, want=f"{key}={target!r} {unit}")
            except InputError as err:
                assert "over an interval" in str(err), (scene, given, key, target, str(err))
                continue

            def g(x, key=key, target=target):
                values = at(x)
                return None if values is None or key not in values else values[key] - target

            brute = _scan_roots([None if v is None or key not in v else v[key] - target for v in scan], xs, g)
            found = found_roots(report, name)
            missed = [r for r in brute if not any(abs(r - f) <= 1e-8 * (high - low) + 1e-12 * abs(r) for f in found)]
            if missed:
                said = " ".join(report.notes)
                assert "may have missed roots" in said and "may hold more" in said, (scene, given, key, target, missed, found)


# --- item 6: a root at the edge of where the result exists --------------------------------------


def test_the_brake_that_stops_a_lowered_load_exactly_at_the_distance():
    # 10 kg lowered at 2 m/s on a 5 kg disc drum (R = 0.2 m): an axle friction τ stops it in d = 1 m when
    # (m + M/2) a = m g − τ/R with v0² + 2 a d = 0, so τ = R (m g + (m + M/2) v0² / (2d)). Past it the
    # load stops short, and v after 1 m has no value.
    with mpmath.workdps(MP_DPS):
        expected = mpmath.mpf("0.2") * (10 * G + (10 + mpmath.mpf(5) / 2) * 4 / 2)
    report = taucli.atwood(m1="10kg", m2=0, pulley_mass="5kg", pulley_radius="0.2m", v0="2m/s", distance="1m", find="axle_friction", want="v=0m/s")
    assert report.results["axle_friction"].value == pytest.approx(float(expected), rel=1e-12)
    assert abs(report.results["v"].value) < 1e-6


def test_an_input_that_may_be_negative_is_searched_to_its_edges_on_both_sides():
    # m1 = 10 kg against m2 = 5 kg on a drum (5 kg, R = 0.2 m) braked by τ = 20 N·m, which opposes the
    # motion either way: going down (v0 > 0) m1 slows at (τ/R − (m1 − m2) g)/(m1 + m2 + M/2), going up
    # (v0 < 0) at (τ/R + (m1 − m2) g)/(m1 + m2 + M/2), under g, so both strings stay taut. v after 1 m
    # is 0 where v0² = 2 × that × d, one root each side of 0, each at an edge of where v exists.
    # (The drum once used here, m2 = 0 and τ = 24.6 N·m, slowed a rising load at 1.8 g: its string
    # would push, and a slack string is now refused.)
    with mpmath.workdps(MP_DPS):
        tau, radius, m1, m2, drum = mpmath.mpf(20), mpmath.mpf("0.2"), 10, 5, mpmath.mpf(5)
        total = m1 + m2 + drum / 2
        down = mpmath.sqrt(2 * (tau / radius - (m1 - m2) * G) / total)
        up = -mpmath.sqrt(2 * (tau / radius + (m1 - m2) * G) / total)
    report = taucli.atwood(m1="10kg", m2="5kg", pulley_mass="5kg", pulley_radius="0.2m", axle_friction="20 N*m", distance="1m", find="v0", want="v=0m/s")
    assert sorted(found_roots(report, "v0")) == pytest.approx([float(up), float(down)], rel=1e-9)
    assert report.results["v0"].value == pytest.approx(float(down), rel=1e-9)


# --- item 7: the right thing blamed; a force in the plane; keys inside specs --------------------


def test_options_that_conflict_are_refused_for_that_not_for_the_range():
    code, _, err = run("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--ke0", "5J",
                       "--find", "friction", "--want", "alpha0=-1rad/s^2")
    assert code == 2 and "--ke0 conflicts with --omega0" in err and "anywhere in the range" not in err


def test_a_force_in_the_plane_is_solved_for():
    # τ = r F sin θ: 10 N·m at 0.25 m and 60° needs F = 10 / (0.25 sin 60°), either sign for the size |τ|
    with mpmath.workdps(MP_DPS):
        expected = float(10 / (mpmath.mpf("0.25") * mpmath.sin(mpmath.pi / 3)))
    report = taucli.torque(lever="0.25m", angle="60deg", find="force", want="tau_z=10N*m")
    assert report.results["force"].value == pytest.approx(expected, rel=1e-13)
    code, out, err = run("torque", "--lever", "0.25m", "--angle", "60deg", "--find", "force", "--want", "tau_z=10N*m", "--get", "force")
    assert code == 0 and float(out) == pytest.approx(expected, rel=1e-13)


@pytest.mark.parametrize("scene, given, name, want, expected", [
    # L conserved: I ω1 = m v r with the particle stuck at r: (2 + 1 × 0.5²) × 1 = 1 × v × 0.5, so v = 4.5 m/s
    ("impulse", {"inertia": "2 kg*m^2", "omega0": 0, "particle": "mass=1kg radius=0.5m"}, "particle.speed", "omega1=1rad/s", 4.5),
    # the second particle of two: (2 + 2 × 0.25) × 1 = 0.5 v + 0.5 × 1, so v = 4
    ("impulse", {"inertia": "2 kg*m^2", "omega0": 0, "particle": ["mass=1kg speed=1m/s radius=0.5m", "mass=1kg radius=0.5m"]},
     "particle2.speed", "omega1=1rad/s", 4.0),
    # a brake μ N r stops I ω0 in t: μ = I ω0 / (N r t) = 1 × 10 / (100 × 0.5 × 2) = 0.1
    ("spin_down", {"inertia": "1 kg*m^2", "omega0": "10rad/s", "brake": "force=100N radius=0.5m"}, "brake.mu", "t_stop=2s", 0.1),
    # a point part 0.1 m out on a disc (½ × 1 × 0.1²): I = 0.005 + m × 0.01 = 0.02, so m = 1.5 kg
    ("inertia", {"shape": "disc", "mass": "1kg", "radius": "0.1m", "part": "point offset=0.1m"}, "part.mass", "I=0.02kg*m^2", 1.5),
])
def test_a_key_inside_a_spec_is_solved_for(scene, given, name, want, expected):
    report = getattr(taucli, scene)(**given, find=name, want=want)
    assert report.results[name].value == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("name, fragment", [
    ("particle.speed", "particle1.speed or particle2.speed"),  # two particles: which?
    ("speed", "particle.speed"),  # a key alone
    ("particle3.speed", "particle1.speed or particle2.speed"),  # no third
    ("particle1.speed", "leave it out of the spec"),  # given in that spec
    ("particle.colour", "particle.mass"),
])
def test_a_spec_key_that_is_ambiguous_or_unknown_is_refused_naming_the_spellings(name, fragment):
    code, _, err = run("impulse", "--inertia", "2kg*m^2", "--omega0", "0", "--particle", "mass=1kg speed=1m/s radius=0.5m",
                       "--particle", "mass=1kg radius=0.5m", "--find", name, "--want", "omega1=1rad/s")
    assert code == 2 and fragment in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_the_shells_offer_what_find_may_solve_for():
    _, commands = completions.spec()
    offered = {command.name: next(option.choices for option in command.options if option.flag == "--find") for command in commands if command.name == "impulse" or command.name == "torque"}
    assert {"particle.speed", "couple.omega0", "inertia"} <= set(offered["impulse"])
    assert "force" in offered["torque"]


# --- item 2 (part): the note of a --want value that is not plain ---------------------------------


def test_the_want_values_reading_has_its_note():
    # 1 Hz is read as 1 rev/s = 2π rad/s, with a note, as it is for an option
    report = taucli.spin_down(inertia="1 kg*m^2", omega0="10rad/s", time="1s", find="friction", want="omega=1Hz")
    assert report.results["omega"].value == pytest.approx(2 * math.pi, rel=1e-12)
    assert any("Hz read as revolutions per second" in note for note in report.notes)


def test_of_two_roots_of_one_size_the_positive_is_the_result():
    """t_stop = 3 s under friction 1 N·m on 2 kg·m² holds for ω₀ = ±1.5 rad/s: the result is +1.5
    (it was −1.5, the first found), and both are listed."""
    report = taucli.spin_down(inertia=2.0, friction=1.0, find="omega0", want="t_stop=3s")
    assert report.results["omega0"].value == pytest.approx(1.5, rel=1e-12)
    assert sorted(report.results["roots"].value) == pytest.approx([-1.5, 1.5], rel=1e-12)
