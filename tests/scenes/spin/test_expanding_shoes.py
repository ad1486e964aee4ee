"""Internal expanding shoes (#48 item 5): --brake "expanding=yes …". The reference is written from
the geometry at 50 digits, never the solver's closed forms: the drum's centre at the origin, the
hinge pin at (a, 0); a rigid shoe turning a small angle δ about the pin moves the lining point
Q(θ) = r(cos θ, sin θ) by δ ẑ × (Q − A), and the lining's compression (the pressure) is that
move's radial part, scaled so that its largest over the arc is p_a. Each strip of lining dθ then
pushes on the shoe with p·b·r·dθ towards the centre and rubs along the drum with μ times that; the
moments about the pin are the cross products (Q − A) × force and the torque on the drum Q × force,
all integrated by mpmath.quad. The actuating force balances the moments about the pin.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.answering.contact_specs import BRAKE_FIELDS, EXPANDING_KEYS

mpmath.mp.dps = 30

SHIGLEY = "expanding=yes pmax=1MPa mu=0.32 width=32mm radius=150mm hinge=123mm lever=212mm heel-angle=0deg shoe-angle=126deg"


def values(report):
    return {name: value.value for name, value in report.results.items()}


def _cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def shoe_per_pressure(mu, width, radius, hinge, heel, arc):
    """(M_N, M_f, T) of one shoe whose largest pressure is 1 Pa, from the geometry (module docstring).
    M_f is the size of the friction's moment about the pin (it turns a leading shoe on)."""
    mu, b, r, a, heel, arc = (mpmath.mpf(x) for x in (mu, width, radius, hinge, heel, arc))
    toe = heel + arc
    pin = (a, mpmath.mpf(0))

    def compression(theta):  # radial part of the move δ ẑ × (Q − A), δ = 1, taken outwards
        q = (r * mpmath.cos(theta), r * mpmath.sin(theta))
        move = (-(q[1] - pin[1]), q[0] - pin[0])
        return -(move[0] * mpmath.cos(theta) + move[1] * mpmath.sin(theta))

    candidates = [heel, toe] + ([mpmath.pi / 2] if heel <= mpmath.pi / 2 <= toe else [])
    largest = max(compression(theta) for theta in candidates)

    def forces(theta):
        """The strip's point, the normal force on the shoe and the friction on it, per dθ."""
        q = (r * mpmath.cos(theta), r * mpmath.sin(theta))
        normal = compression(theta) / largest * b * r
        inward = (-mpmath.cos(theta) * normal, -mpmath.sin(theta) * normal)
        along = (-mpmath.sin(theta) * mu * normal, mpmath.cos(theta) * mu * normal)
        return q, inward, along

    def moment_normal(theta):
        q, inward, _ = forces(theta)
        return _cross((q[0] - pin[0], q[1] - pin[1]), inward)

    def moment_friction(theta):
        q, _, along = forces(theta)
        return _cross((q[0] - pin[0], q[1] - pin[1]), along)

    def torque(theta):
        q, _, along = forces(theta)
        return _cross(q, along)

    span = [heel, toe]
    return (abs(mpmath.quad(moment_normal, span)), abs(mpmath.quad(moment_friction, span)), abs(mpmath.quad(torque, span)))


def reference(mu, width, radius, hinge, lever, heel, arc, shoes="both", force=None, pmax=None):
    """{shoe: (p_a, T)}, F: each shoe's largest pressure and torque, and the actuating force."""
    normal, friction, torque = shoe_per_pressure(mu, width, radius, hinge, heel, arc)
    lever = mpmath.mpf(lever)
    per = {"leading": (normal - friction) / lever, "trailing": (normal + friction) / lever}  # F per unit p_a
    kinds = ("leading", "trailing") if shoes == "both" else (shoes,)
    force = mpmath.mpf(pmax) * per[kinds[0]] if force is None else mpmath.mpf(force)
    return {kind: (force / per[kind], force / per[kind] * torque) for kind in kinds}, force


def test_shigley_example_16_2():
    """Shigley's Mechanical Engineering Design, Example 16-2: a brake 300 mm in diameter, two
    identical shoes of face width 32 mm pushed by the same force F, molded asbestos μ = 0.32,
    pressure limited to 1000 kPa; θ₁ = 0°, θ₂ = 126°, θ_a = 90°, the hinge pins a = 123 mm from the
    centre, F at c = 212 mm from them. The book's braking capacity: 366 N·m from the right-hand
    (self-energizing, leading) shoe and 162 N·m from the left-hand one, 528 N·m in all (neither
    depends on c)."""
    report = taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake=SHIGLEY)
    result = values(report)
    assert result["torque_brake"] == pytest.approx(528, abs=0.5)
    shoes, force = reference(0.32, 0.032, 0.15, 0.123, 0.212, 0, mpmath.radians(126), pmax=1e6)
    assert float(shoes["leading"][1]) == pytest.approx(366, abs=0.5)
    assert float(shoes["trailing"][1]) == pytest.approx(162, abs=0.5)
    assert result["torque_brake"] == pytest.approx(float(shoes["leading"][1] + shoes["trailing"][1]), rel=1e-13)
    assert result["force_actuating"] == pytest.approx(float(force), rel=1e-13)
    assert result["pressure_brake"] == 1e6
    shown = {step.title: step.result for step in report.steps}
    assert shown["Braking torque of the leading shoe"] == "365.826 N·m"
    assert shown["Braking torque of the trailing shoe"] == "162.433 N·m"
    assert shown["Largest pressure on the trailing shoe"] == "444017 Pa"
    assert "internal expanding shoes" in report.model


@pytest.mark.parametrize("shoes", ["both", "leading", "trailing"])
@pytest.mark.parametrize(("heel", "arc", "hinge"), [(0, 126, 0.123), (10, 110, 0.1), (5, 60, 0.12), (30, 140, 0.08), (90, 45, 0.14), (60, 0.01, 0.12), (20, 160, 0.149)])
@pytest.mark.parametrize("by", ["force", "pmax"])
def test_against_the_lining_integrated(shoes, heel, arc, hinge, by):
    """τ, F and the largest pressure from the strips of lining integrated about the pin, for θ_a =
    90° and θ_a = θ₂ (a shoe short of 90°), a shoe beyond 90°, and a sliver."""
    given = "force=1.5kN" if by == "force" else "pmax=800kPa"
    spec = f"expanding=yes {given} mu=0.3 width=40mm radius=0.15m hinge={hinge}m lever=0.2m heel-angle={heel}deg shoe-angle={arc}deg shoes={shoes}"
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake=spec))
    found, force = reference(0.3, 0.04, 0.15, hinge, 0.2, mpmath.radians(heel), mpmath.radians(arc), shoes,
                             force=1500 if by == "force" else None, pmax=8e5 if by == "pmax" else None)
    assert result["torque_brake"] == pytest.approx(float(sum(torque for _, torque in found.values())), rel=1e-12)
    assert result["force_actuating"] == pytest.approx(float(force), rel=1e-12)
    assert result["pressure_brake"] == pytest.approx(float(max(pressure for pressure, _ in found.values())), rel=1e-12)


@settings(max_examples=30, deadline=None)
@given(mu=st.floats(0.05, 0.6), heel=st.sampled_from([0.0]) | st.floats(0.01, 60), arc=st.floats(1, 120), hinge=st.floats(0.2, 0.95), lever=st.floats(0.05, 0.5),
       force=st.floats(10, 1e5), shoes=st.sampled_from(["both", "leading", "trailing"]))
def test_same_in_other_units_and_as_the_reference(mu, heel, arc, hinge, lever, force, shoes):
    """Property: any shoe that does not lock gives the reference's torque, in SI and in inches,
    pounds-force and radians alike."""
    radius = 0.2
    normal, friction, _ = shoe_per_pressure(mu, 0.05, radius, hinge * radius, math.radians(heel), math.radians(arc))
    if shoes != "trailing" and friction >= normal * (1 - 1e-6):
        return  # locks itself (refused: tested below)
    spec = (f"expanding=yes force={force!r}N mu={mu!r} width=0.05m radius={radius}m hinge={hinge * radius!r}m lever={lever!r}m "
            f"heel-angle={heel!r}deg shoe-angle={arc!r}deg shoes={shoes}")
    si = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s", brake=spec))
    us = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s", brake=(
        f"expanding=yes force={force / 4.4482216152605!r}lbf mu={mu!r} width={0.05 / 0.0254!r}in radius={radius / 0.0254!r}in "
        f"hinge={hinge * radius / 0.0254!r}in lever={lever / 0.0254!r}in heel-angle={math.radians(heel)!r}rad shoe-angle={math.radians(arc)!r}rad shoes={shoes}")))
    assert us["torque_brake"] == pytest.approx(si["torque_brake"], rel=1e-11)
    found, _ = reference(mu, 0.05, radius, hinge * radius, lever, math.radians(heel), math.radians(arc), shoes, force=force)
    assert si["torque_brake"] == pytest.approx(float(sum(torque for _, torque in found.values())), rel=1e-10)


def test_a_sliver_of_lining_is_a_short_shoe():
    """Limit: a lining of arc Δ → 0 at θ presses the drum with N = p_a·b·r·Δ and takes τ = μ·N·r
    (the short shoe); the leading shoe's force is N·(a·sin θ − μ·(r − a·cos θ))/c."""
    arc = 1e-6
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm",
                                     brake=f"expanding=yes pmax=1MPa mu=0.3 width=40mm radius=0.15m hinge=0.1m lever=0.2m heel-angle=60deg shoe-angle={arc!r}rad shoes=leading"))
    middle = math.radians(60) + arc / 2
    normal = 1e6 * math.sin(middle) / math.sin(math.radians(60) + arc) * 0.04 * 0.15 * arc
    assert result["torque_brake"] == pytest.approx(0.3 * normal * 0.15, rel=1e-9)
    assert result["force_actuating"] == pytest.approx(normal * (0.1 * math.sin(middle) - 0.3 * (0.15 - 0.1 * math.cos(middle))) / 0.2, rel=1e-9)


def test_two_shoes_are_a_leading_and_a_trailing_one():
    """shoes=both is the leading shoe and the trailing shoe pushed by the same force."""
    common = "expanding=yes force=2kN mu=0.32 width=32mm radius=150mm hinge=123mm lever=212mm heel-angle=0deg shoe-angle=126deg"
    both = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake=common))
    lead = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake=common + " shoes=leading"))
    trail = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake=common + " shoes=trailing"))
    assert both["torque_brake"] == pytest.approx(lead["torque_brake"] + trail["torque_brake"], rel=1e-15)
    assert lead["torque_brake"] > trail["torque_brake"]
    assert both["pressure_brake"] == lead["pressure_brake"] > trail["pressure_brake"]


def test_the_brake_slows_the_wheel_as_a_loss():
    """The shoes' torque is a constant friction torque: spin-down's α₀ = −T/I, its stop, the
    energy the brake takes (all of ½Iω₀²), and impulse's ω₁ after Δt."""
    shoes, _ = reference(0.32, 0.032, 0.15, 0.123, 0.212, 0, mpmath.radians(126), pmax=1e6)
    torque = shoes["leading"][1] + shoes["trailing"][1]
    result = values(taucli.spin_down(inertia="20kg*m^2", omega0="600rpm", brake=SHIGLEY, energy=True))
    omega0 = 600 * 2 * mpmath.pi / 60
    assert result["alpha0"] == pytest.approx(float(-torque / 20), rel=1e-13)
    assert result["t_stop"] == pytest.approx(float(20 * omega0 / torque), rel=1e-13)
    assert result["work_brake"] == pytest.approx(float(20 * omega0**2 / 2), rel=1e-12)
    after = values(taucli.impulse(inertia="20kg*m^2", omega0="600rpm", torque="100N*m", duration="0.5s", brake=SHIGLEY))
    assert after["omega1"] == pytest.approx(float(omega0 + (100 - torque) * mpmath.mpf("0.5") / 20), rel=1e-12)
    assert after["torque_brake"] == pytest.approx(float(torque), rel=1e-13)


def test_batch_cli_and_python_agree():
    python = taucli.spin_down(omega0="1500rpm", inertia="2kg*m^2", brake=SHIGLEY).results["torque_brake"].value
    line = run_taucli("spin-down", "--batch", stdin=json.dumps({"omega0": "1500rpm", "inertia": "2kg*m^2", "brake": SHIGLEY}) + "\n")
    assert line.code == 0 and line.json()["results"]["torque_brake"]["value"] == python
    cli = run_taucli("spin-down", "--omega0", "1500rpm", "--inertia", "2kg*m^2", "--brake", SHIGLEY, "--get", "torque_brake", "--get", "force_actuating")
    assert cli.code == 0 and float(cli.out.split()[0]) == pytest.approx(python, rel=1e-14)
    document = run_taucli("spin-down", "--omega0", "1500rpm", "--inertia", "2kg*m^2", "--brake", SHIGLEY, "--json").json()
    assert document["results"]["pressure_brake"]["unit"] == "Pa" and document["results"]["force_actuating"]["unit"] == "N"


def test_a_leading_shoe_that_locks_itself_is_refused_and_a_trailing_one_is_not():
    """M_f ≥ M_N on the leading shoe: the drum drags it on with no force; the trailing shoe of the same geometry is pushed off."""
    locking = "expanding=yes force=2kN mu=0.9 width=32mm radius=150mm hinge=60mm lever=212mm heel-angle=0deg shoe-angle=126deg"
    normal, friction, _ = shoe_per_pressure(0.9, 0.032, 0.15, 0.06, 0, mpmath.radians(126))
    assert friction > normal
    for shoes in ("both", "leading"):
        assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", f"{locking} shoes={shoes}"), "--brake", "locks itself", "M_f")
    trailing = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s", brake=locking + " shoes=trailing"))
    found, _ = reference(0.9, 0.032, 0.15, 0.06, 0.212, 0, mpmath.radians(126), "trailing", force=2000)
    assert trailing["torque_brake"] == pytest.approx(float(found["trailing"][1]), rel=1e-12)


def test_a_shoe_that_locks_only_at_rest_holds_the_wheel():
    """μs past the locking point, μk short of it: it slides, and at rest holds any torque (noted)."""
    normal, friction, _ = shoe_per_pressure(1, 0.032, 0.15, 0.123, 0, mpmath.radians(126))
    locking_mu = normal / friction
    spec = (f"expanding=yes force=2kN mu-k={float(locking_mu) * 0.9!r} mu-s={float(locking_mu) * 1.1!r} width=32mm radius=150mm hinge=123mm "
            "lever=212mm heel-angle=0deg shoe-angle=126deg")
    report = taucli.spin_down(inertia="1kg*m^2", omega0=0, torque="1000N*m", time="1s", brake=spec)
    assert report.results["omega"].value == 0
    assert any("locks itself" in note for note in report.notes)


def test_a_lone_shoe_refuses_a_drive_that_would_turn_the_drum_back():
    """One shoe alone is leading one way and trailing the other: refused where a drive against ω₀
    would turn the drum back; a pair is the same either way."""
    lone = SHIGLEY + " shoes=leading"
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--torque", "-2000N*m", "--time", "1s", "--brake", lone),
                       "--brake", "turn")
    pair = run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--torque", "-2000N*m", "--time", "1s", "--brake", SHIGLEY, "--get", "omega")
    assert pair.code == 0, pair.err


BASE = "expanding=yes force=2kN mu=0.32 width=32mm radius=150mm hinge=123mm lever=212mm heel-angle=0deg shoe-angle=126deg"


def _without(key):
    return " ".join(pair for pair in BASE.split() if not pair.startswith(key + "="))


@pytest.mark.parametrize(
    ("spec", "fragments"),
    [
        # each new key with a wrong value
        (BASE.replace("expanding=yes", "expanding=maybe"), ["expanding="]),
        (BASE + " shoes=left", ["shoes=", "leading"]),
        (BASE.replace("heel-angle=0deg", "heel-angle=2m"), ["heel-angle="]),
        (BASE.replace("heel-angle=0deg", "heel-angle=10"), ["heel-angle="]),
        (BASE.replace("heel-angle=0deg", "heel-angle=-5deg"), ["heel-angle="]),
        (BASE.replace("width=32mm", "width=3s"), ["width="]),
        (BASE.replace("width=32mm", "width=0m"), ["width="]),
        (BASE.replace("hinge=123mm", "hinge=1kg"), ["hinge="]),
        (BASE.replace("hinge=123mm", "hinge=150mm"), ["hinge=", "inside the drum"]),
        (BASE.replace("force=2kN", "pmax=2N"), ["pmax="]),
        (BASE.replace("force=2kN", "pmax=-1MPa"), ["pmax="]),
        (BASE.replace("shoe-angle=126deg", "shoe-angle=200deg"), ["heel-angle=", "180deg"]),
        (BASE.replace("heel-angle=0deg", "heel-angle=60deg"), ["heel-angle=", "180deg"]),
        # keys that need one another
        (BASE + " pmax=1MPa", ["force=", "pmax="]),
        (_without("force"), ["force=", "pmax="]),
        (_without("width"), ["width="]),
        (_without("hinge"), ["hinge="]),
        (_without("lever"), ["lever="]),
        (_without("heel-angle"), ["heel-angle="]),
        (_without("shoe-angle"), ["shoe-angle="]),
        (_without("mu"), ["mu="]),
        (BASE + " pivot=0.3m", ["pivot="]),
        (BASE + " offset=0.05m", ["offset="]),
        # the expanding keys without expanding=yes
        ("force=100N mu=0.4 radius=0.5m heel-angle=0deg", ["heel-angle=", "expanding=yes"]),
        ("force=100N mu=0.4 radius=0.5m width=3cm", ["width=", "expanding=yes"]),
        ("force=100N mu=0.4 radius=0.5m hinge=3cm", ["hinge=", "expanding=yes"]),
        ("force=100N mu=0.4 radius=0.5m pmax=1MPa", ["pmax=", "expanding=yes"]),
        ("force=100N mu=0.4 radius=0.5m shoes=both", ["shoes=", "expanding=yes"]),
        ("expanding=no force=100N mu=0.4 radius=0.5m hinge=3cm", ["hinge=", "expanding=yes"]),
    ],
)
def test_refusals_name_the_key(spec, fragments):
    """Every new key, and every pairing of keys, refused with exit 2 and one line naming it."""
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", spec), "--brake", *fragments)


def test_no_radius_from_a_body_without_one():
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", _without("radius")), "--brake", "radius=", "expanding=yes")
    disc = values(taucli.spin_down(shape="disc", mass="10kg", radius="150mm", omega0="10rad/s", brake=_without("radius")))
    with_radius = values(taucli.spin_down(shape="disc", mass="10kg", radius="150mm", omega0="10rad/s", brake=BASE))
    assert disc["torque_brake"] == with_radius["torque_brake"]


def _keyed(key, text):
    """BASE with ``key`` (snake case) set to ``text``, added where BASE has no such key."""
    spelled = key.replace("_", "-")
    pairs = [pair for pair in BASE.split() if pair.split("=")[0] != spelled and not (key in ("force", "pmax") and pair.startswith("force="))]
    return " ".join([*pairs, f"{spelled}={text}"])


@pytest.mark.parametrize("key", sorted(BRAKE_FIELDS))
def test_every_quantity_key_of_an_expanding_brake_refuses_a_wrong_dimension(key):
    """Class check: each quantity key the --brake spec reads, in an expanding spec (mu-k= and
    mu-s= in place of mu=), given a value of no kind it takes, is refused naming that key."""
    spec = _keyed(key, "3 kg*s")
    if key in ("mu_k", "mu_s"):
        spec = spec.replace("mu=0.32 ", "")
    if key in ("pivot", "offset"):  # not read at all with expanding=yes
        assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", spec), "--brake", f"{key}=")
        return
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", spec), "--brake", f"{key.replace('_', '-')}=")


@pytest.mark.parametrize("key", EXPANDING_KEYS)
def test_every_expanding_key_needs_expanding_yes(key):
    """Class check: each key that only internal shoes read is refused on a plain shoe, naming it."""
    text = {"heel_angle": "0deg", "width": "3cm", "hinge": "3cm", "pmax": "1MPa", "shoes": "both"}[key]
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", f"force=100N mu=0.4 radius=0.5m {key.replace('_', '-')}={text}"),
                       "--brake", f"{key.replace('_', '-')}=", "expanding=yes")
