"""Several loads, each through its own train (--load): what the motor sees of them all.

Load i turns at ω/Nᵢ (Nᵢ its ratio, motor speed over its speed; the books' aᵢ = 1/Nᵢ) through a
train of efficiency ηᵢ. Its kinetic energy ½Jᵢ(ω/Nᵢ)² is that of Jᵢ/Nᵢ² on the motor shaft, and
the torque its shaft asks while the motor accelerates at α, T_out,i = Jᵢα/Nᵢ + Tᵢ, reaches the
motor as T_out,i/(Nᵢηᵢ) while the motor drives it and as η′ᵢT_out,i/Nᵢ where the load drives the
motor back (η′ᵢ its efficiency-back=, ηᵢ unless given): the losses always take power. So

    J = J_m + J_g + Σ Jᵢ/Nᵢ²,     T_l = Σ G_i(Tᵢ)/Nᵢ + τ_mf       (Dubey (2.8), (2.9))
    τ(α) = (J_m + J_g)α + Σ Gᵢ(Jᵢα/Nᵢ + Tᵢ)/Nᵢ + τ_mf,   Gᵢ(x) = x/ηᵢ for x ≥ 0, η′ᵢx for x < 0.

A mass m moved at v while the motor turns at ω_m (speed= with --motor-speed) is m(v/ω_m)² at the
motor shaft (Nᵢ = 1), its force F a torque F·v/ω_m there (the power F·v over ω_m); a mass on a
drum of radius r at a shaft of ratio Nᵢ (radius=) is m r² at that shaft, its force F·r there.

``Loads`` answers as train.Train does (motor_torque, running, hold, total...), so the constant-α
run-up and the move profile take it as they take one train.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.writing.report import Step, Table, fmt, quantity_text, term


@dataclass(frozen=True)
class Load:
    """One --load as given, in SI (None: not given)."""

    source: str
    inertia: float | None = None
    mass: float | None = None
    radius: float | None = None
    speed: float | None = None
    ratio: float | None = None
    efficiency: float | None = None
    efficiency_back: float | None = None
    torque: float | None = None
    force: float | None = None


@dataclass(frozen=True)
class Branch:
    """A load at its own shaft and the train to it: N, η, η′, J and T there, and what makes them."""

    ratio: float
    efficiency: float
    back: float
    inertia: float
    torque: float
    lever: float | None = None  # a mass's travel per radian of this shaft (r, or v/ω_m at the motor shaft)
    mass: float | None = None
    force: float = 0.0
    back_given: bool = False
    by_speed: bool = False  # the lever is v/ω_m, at the motor shaft (speed=), not a drum's r

    def demand(self, alpha: float) -> float:
        """T_out = Jα/N + T: the torque this load's shaft asks at motor acceleration α."""
        return self.inertia * alpha / self.ratio + self.torque

    def passed(self, demand: float) -> float:
        """At the motor: T_out/(Nη) while the motor drives, η′T_out/N while the load drives it."""
        return demand / (self.ratio * self.efficiency) if demand >= 0 else self.back * demand / self.ratio

    def loss(self, output: float, driving: bool) -> float:
        """The energy this train takes of ``output`` (the work at the load's shaft)."""
        return (1 / self.efficiency - 1) * output if driving else (1 - self.back) * -output

    @property
    def reflected(self) -> float:
        return self.inertia / (self.ratio * self.ratio)


@dataclass(frozen=True)
class Loads:
    """The motor, its own gearing and friction, and the loads' branches."""

    branches: tuple[Branch, ...]
    rotor: float | None
    gearing: float = 0.0
    motor_friction: float = 0.0
    gravity: float = 0.0  # no held weight: a --load's force acts while it moves
    lever: None = None
    ratio: float = 1.0  # the loads' sums below are at the motor shaft already

    @property
    def load(self) -> float:
        """Σ Jᵢ/Nᵢ²: the loads' inertia at the motor shaft (without the gearing's)."""
        return math.fsum(b.reflected for b in self.branches)

    @property
    def torque(self) -> float:
        """Σ Tᵢ/Nᵢ: the loads' torques at the motor shaft before any loss (their work per radian of the motor)."""
        return math.fsum(b.torque / b.ratio for b in self.branches)

    @property
    def input_inertia(self) -> float:
        return (self.rotor or 0.0) + self.gearing

    @property
    def reflected(self) -> float:
        return self.gearing + self.load

    @property
    def total(self) -> float:
        return (self.rotor or 0.0) + self.reflected

    @property
    def efficiency(self) -> float:
        return 1.0

    def motor_torque(self, alpha: float) -> float:
        return self.input_inertia * alpha + math.fsum(b.passed(b.demand(alpha)) for b in self.branches) + self.motor_friction

    def demand(self, alpha: float) -> float:
        """The loads' torque at the motor, through their trains (positive: the motor drives them on the whole)."""
        return math.fsum(b.passed(b.demand(alpha)) for b in self.branches)

    @property
    def running(self) -> float:
        return self.motor_torque(0.0)

    @property
    def hold(self) -> float:
        return 0.0

    def speed_of(self, omega: float) -> None:
        return None

    def run_loss(self, alpha: float, omega: float, theta: float) -> float:
        """The trains' losses and the motor shaft's friction over a run-up from rest to ω through θ at α."""
        outputs = [(b, b.inertia * omega * omega / (2 * b.ratio * b.ratio) + b.torque * theta / b.ratio) for b in self.branches]
        return math.fsum(b.loss(w, b.demand(alpha) >= 0) for b, w in outputs) + self.motor_friction * theta


def branches(loads: tuple[Load, ...], motor_speed: float | None) -> tuple[Branch, ...]:
    """Each load at its own shaft: N, η, η′, J = J_body + m r² (or m(v/ω_m)² at the motor), T = T_given + F r."""
    found = []
    for load in loads:
        for name, value in (("efficiency", load.efficiency), ("efficiency-back", load.efficiency_back)):
            if value is not None and value > 1:
                raise InputError(load.source, f"has {name}={fmt(value)}: an efficiency is above 0 and at most 1",
                                 example='{load} "inertia=10kg*m^2 ratio=10 efficiency=0.9"', got=fmt(value))
        lever = load.radius
        if load.speed is not None:
            if motor_speed is None:
                raise InputError("motor_speed", f"is required with speed= in {load.source}: the mass's speed is at the motor's speed",
                                 example="{motor_speed} 1420rpm")
            lever = load.speed / motor_speed
        mass_inertia = load.mass * lever * lever if load.mass is not None else 0.0
        eta = 1.0 if load.efficiency is None else load.efficiency
        found.append(Branch(1.0 if load.ratio is None else load.ratio, eta, eta if load.efficiency_back is None else load.efficiency_back,
                            (load.inertia or 0.0) + mass_inertia, (load.torque or 0.0) + (load.force or 0.0) * (lever or 0.0), lever,
                            load.mass, load.force or 0.0, load.efficiency_back is not None, load.speed is not None))
    return tuple(found)


def table(train: Loads) -> Table:
    """The books' table of loads: each one's N, η, J and T at its shaft, and what the motor sees of them."""
    columns = (("load", None, "load"), ("N", "", "N"), ("efficiency", "", "η"), ("J", "kg*m**2", "J"), ("J_motor", "kg*m**2", "J/N²"),
               ("T", "N*m", "T"), ("T_motor", "N*m", "T at motor"))
    return Table(columns, tuple((n, b.ratio, b.efficiency, b.inertia, b.reflected, b.torque, b.passed(b.torque))
                                for n, b in enumerate(train.branches, start=1)))


def _sub(n: int) -> str:
    return "".join("₀₁₂₃₄₅₆₇₈₉"[int(d)] for d in str(n))


def load_steps(train: Loads) -> list[Step]:
    """Each mass's inertia and force at its shaft, the inertia at the motor and the load torque there, load by load."""
    found = []
    for n, b in enumerate(train.branches, start=1):
        if b.mass is not None or b.force:
            arm = "v/ω_m" if b.by_speed else "r"
            i = _sub(n)
            symbols, numbers = [], []
            body = b.inertia - (b.mass * b.lever * b.lever if b.mass is not None else 0.0)
            if b.mass is not None:
                symbols.append(f"J{i} = " + (f"J_body + m({arm})²" if body else f"m({arm})²"))
                numbers.append((f"{quantity_text(body, 'kg*m**2')} + " if body else "") + f"{quantity_text(b.mass, 'kg')} × ({quantity_text(b.lever, 'm')})²")
            if b.force:
                symbols.append(f"T{i} = " + ("T + " if b.torque != b.force * b.lever else "") + f"F·{arm}")
                numbers.append((f"{term(b.torque - b.force * b.lever, 'N*m')} + " if b.torque != b.force * b.lever else "") + f"{term(b.force, 'N')} × {quantity_text(b.lever, 'm')}")
            found.append(Step(f"Load {n}: a mass moved in a line, at {'the motor' if b.by_speed else 'its'} shaft" + (" (v/ω_m = " + quantity_text(b.lever, "m") + " per radian)" if b.by_speed else ""),
                              ",  ".join(symbols), ";  ".join(numbers), ", ".join(
                                  x for x in ((f"J{i} = {quantity_text(b.inertia, 'kg*m**2')}" if b.mass is not None else ""),
                                              (f"T{i} = {quantity_text(b.torque, 'N*m')}" if b.force else "")) if x),
                              "the mass moves " + ("v/ω_m per radian of the motor: ½mv² = ½·m(v/ω_m)²·ω_m², and its force's power F·v is a torque F·v/ω_m"
                                                   if b.by_speed else "r per radian of its shaft: ½mv² = ½·m r²·ω², and its force F·r there")))
    names = " + ".join(f"J{_sub(n)}/N{_sub(n)}²" for n in range(1, len(train.branches) + 1))
    numbers = " + ".join(f"{quantity_text(b.inertia, 'kg*m**2')}/{fmt(b.ratio)}²" for b in train.branches)
    head = [("J_m", train.rotor), ("J_g", train.gearing)]
    shown = [(s, v) for s, v in head if v]
    found.append(Step("Inertia of the loads at the motor shaft, and the whole", "J = " + " + ".join([*(s for s, _ in shown), names]),
                      " + ".join([*(quantity_text(v, "kg*m**2") for _, v in shown), numbers]), quantity_text(train.total, "kg*m**2"),
                      "each load turns at ω/Nᵢ: its kinetic energy ½Jᵢ(ω/Nᵢ)² is that of Jᵢ/Nᵢ² on the motor shaft (no η: energy stored, not passed)"))
    symbols, numbers = [], []
    for n, b in enumerate(train.branches, start=1):
        if not b.torque:
            continue
        if b.torque >= 0:
            symbols.append(f"T{_sub(n)}/(N{_sub(n)}η{_sub(n)})")
            numbers.append(f"{term(b.torque, 'N*m')}/({fmt(b.ratio)} × {fmt(b.efficiency)})")
        else:
            symbols.append(f"{'η′' if b.back_given else 'η'}{_sub(n)}T{_sub(n)}/N{_sub(n)}")
            numbers.append(f"{fmt(b.back)} × {term(b.torque, 'N*m')}/{fmt(b.ratio)}")
    if train.motor_friction:
        symbols.append("τ_mf")
        numbers.append(quantity_text(train.motor_friction, "N*m"))
    if symbols:
        back = any(b.torque < 0 for b in train.branches)
        found.append(Step("Load torque at the motor, running at constant speed", "T_l = " + " + ".join(symbols), " + ".join(numbers),
                          quantity_text(train.running, "N*m"),
                          "each train divides its load's torque by its ratio and the motor pays its losses on top (1/ηᵢ)"
                          + ("; a load that drives (T < 0) gives back through its train, which keeps (1 − η′) of it" if back else "")))
    return found


def several(loads: tuple[Load, ...], rotor: float | None, gearing: float | None, friction: float | None, motor_speed: float | None,
            single: dict, results, steps: list[Step]) -> Loads:
    """The train of several --load (the single load's options refused beside them), its inertia and load torque at the motor."""
    given = [name for name, value in single.items() if value not in (None, (), [], False)]
    if given:
        raise InputError(given[0], "conflicts with {load}: with several loads each is given by its own --load (its ratio=, efficiency=, inertia=, "
                         "mass=, torque=, force= inside it)", example='{load} "inertia=10kg*m^2 ratio=10 efficiency=0.9 torque=10N*m"')
    train = Loads(branches(loads, motor_speed), rotor, gearing or 0.0, friction or 0.0)
    steps.extend(load_steps(train))
    results.put("reflected_inertia", train.reflected, ", J_g + Σ Jᵢ/Nᵢ²" if train.gearing else ", Σ Jᵢ/Nᵢ²")
    if rotor is not None:
        results.put("total_inertia", train.total)
        if rotor:
            results.put("inertia_ratio", train.reflected / rotor)
    results.put("load_torque_motor", train.running, ", Σ Tᵢ/(Nᵢηᵢ)" + (" + τ_mf" if train.motor_friction else ""))
    return train


def put_power(train, omega: float, results, steps: list[Step]) -> None:
    """The motor's power running steadily at ω against the load: P = T_l ω."""
    power = train.running * omega
    results.put("power_run", power, f", running at {fmt(omega)} rad/s")
    steps.append(Step("The motor's power, running at its speed", "P = T_l ω_m", f"{quantity_text(train.running, 'N*m')} × {quantity_text(omega, 'rad/s')}",
                      quantity_text(power, "W"), "at a steady speed the motor gives the load's torque at its shaft, losses included, at its own speed"))


def torque_step(title: str, train: Loads, alpha: float, torque: float) -> Step:
    """τ = (J_m + J_g)α + Σ Gᵢ(Jᵢα/Nᵢ + Tᵢ)/Nᵢ + τ_mf, each load's term through its own train, whichever way its power flows."""
    equation, numbers = ["(J_m + J_g)α" if train.gearing else "J_mα"], [f"{quantity_text(train.input_inertia, 'kg*m**2')} × {term(alpha, 'rad/s**2')}"]
    back = False
    for n, b in enumerate(train.branches, start=1):
        i = _sub(n)
        inside = f"J{i}α/N{i} + T{i}" if b.torque else f"J{i}α/N{i}"
        shown = f"{quantity_text(b.inertia, 'kg*m**2')} × {term(alpha, 'rad/s**2')}/{fmt(b.ratio)}" + (f" + {term(b.torque, 'N*m')}" if b.torque else "")
        if b.demand(alpha) >= 0:
            equation.append(f"({inside})/(N{i}η{i})")
            numbers.append(f"({shown})/({fmt(b.ratio)} × {fmt(b.efficiency)})")
        else:
            back = True
            equation.append(f"{'η′' if b.back_given else 'η'}{i}({inside})/N{i}")
            numbers.append(f"{fmt(b.back)} × ({shown})/{fmt(b.ratio)}")
    if train.motor_friction:
        equation.append("τ_mf")
        numbers.append(quantity_text(train.motor_friction, "N*m"))
    why = "each load's shaft asks Jᵢα/Nᵢ + Tᵢ; its train divides it by Nᵢ, and the motor pays that train's losses on top (1/ηᵢ)"
    if back:
        why += "; a load whose shaft gives power back (its term < 0) drives the motor through its train, which keeps (1 − η′ᵢ) of it"
    return Step(title, "τ = " + " + ".join(equation), " + ".join(numbers), quantity_text(torque, "N*m"), why)
