"""The drive train: what the motor sees of the load through the ratio N and the efficiency η.

The output shaft turns at ω/N. Its kinetic energy ½J(ω/N)² is that of J/N² on the motor shaft,
so the load inertia reflected to the motor is J_r = J_g + J/N² (J_g: gearing referred to the
motor shaft already). A mass m moved by a drum of radius r, or a screw of lead p, travels at
v = ωr or ωp/2π: its kinetic energy is that of m·r² or m(p/2π)² on that shaft.

The torque the output shaft asks for, while the motor turns at ω and accelerates at α, is

    T_out = J·α/N + T      (T: the load's torque against the motion, at the output shaft)

and the efficiency takes its share of the power that flows through the teeth, whichever way:

    τ_motor = (J_m + J_g)·α + T_out/(Nη)   where T_out ≥ 0: the motor drives the load
    τ_motor = (J_m + J_g)·α + η·T_out/N    where T_out < 0: the load drives the motor (regenerating)

So the motor gives P_out/η while driving, and gets η′P_out back while the load drives it: the
losses always take power, never give it. η′ is η unless --efficiency-back says otherwise (a worm
or a screw drives back with less, and not at all below η = 0.5). A friction torque τ_mf at the
motor shaft (--motor-friction: a ball-nut's, the motor's bearings) is against the motion and
passes through no teeth, so η does not divide it: τ_motor gains +τ_mf while the load moves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.scenes.drive.loads import Loads, torque_step as loads_torque_step
from taucli.writing.report import Step, fmt, quantity_text, term

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Train:
    """The motor, the stages and the load, in SI at the shafts they belong to."""

    ratio: float  # N: motor speed over output speed
    efficiency: float  # η of the whole train
    rotor: float | None  # J_m (None: not given)
    gearing: float  # J_g, referred to the motor shaft
    load: float  # J about the output shaft: the rotating load's and the moving mass's
    torque: float  # T: the load's torque at the output shaft against the motion while it moves
    gravity: float  # the part of T that gravity makes, which acts at rest too
    lever: float | None  # r (drum) or p/2π (screw): the mass's travel per radian of the output; None without one
    efficiency_back: float | None = None  # η′ where the load drives the motor (None: η)
    motor_friction: float = 0.0  # τ_mf at the motor shaft, against the motion

    @property
    def back(self) -> float:
        """η′: the train's efficiency where the load drives the motor."""
        return self.efficiency if self.efficiency_back is None else self.efficiency_back

    def train_loss(self, output: float, driving: bool) -> float:
        """The energy the teeth take of ``output`` (the work at the output shaft): (1/η − 1)W driving, (1 − η′)(−W) driven."""
        return (1 / self.efficiency - 1) * output if driving else (1 - self.back) * -output

    @property
    def input_inertia(self) -> float:
        """J_m + J_g: what the motor turns directly, before any loss in the teeth."""
        return (self.rotor or 0.0) + self.gearing

    @property
    def reflected(self) -> float:
        """J_r = J_g + J/N²: the load's inertia as the motor shaft feels it."""
        return self.gearing + self.load / (self.ratio * self.ratio)

    @property
    def total(self) -> float:
        return (self.rotor or 0.0) + self.reflected

    def passed(self, demand: float) -> float:
        """The torque at the motor for an output torque ``demand``: T/(Nη) while the motor drives
        the load, η′T/N while the load drives the motor."""
        if demand >= 0:
            return demand / (self.ratio * self.efficiency)
        return self.back * demand / self.ratio

    def demand(self, alpha: float) -> float:
        """T_out = J·α/N + T: the torque the output shaft asks for at motor acceleration α."""
        return self.load * alpha / self.ratio + self.torque

    def motor_torque(self, alpha: float) -> float:
        """τ = (J_m + J_g)α + T_out/(Nη) or η′T_out/N, + τ_mf, with the load moving (α signed: negative slows it)."""
        return self.input_inertia * alpha + self.passed(self.demand(alpha)) + self.motor_friction

    @property
    def running(self) -> float:
        """The motor's torque at a constant speed: the load's T passed through the teeth, and τ_mf."""
        return self.motor_torque(0.0)

    @property
    def hold(self) -> float:
        """The torque that holds the load at rest: gravity's, T_g/N (no power flows, so no η)."""
        return self.gravity / self.ratio

    def speed_of(self, omega: float) -> float | None:
        """The moving mass's speed at motor speed ω, v = ω·r/N."""
        return None if self.lever is None else omega * self.lever / self.ratio

    def run_loss(self, alpha: float, omega: float, theta: float) -> float:
        """The teeth's loss and the motor shaft's friction over a run-up from rest to ω through θ at α."""
        output = self.load * omega * omega / (2 * self.ratio * self.ratio) + self.torque * theta / self.ratio
        return self.train_loss(output, self.demand(alpha) >= 0) + self.motor_friction * theta

    def regenerating(self, alpha: float) -> bool:
        return self.demand(alpha) < 0


def ratio_step(stages: tuple[float, ...], ratio: float) -> Step:
    return Step("Overall ratio of the stages in series", "N = " + " × ".join(f"N{_sub(i + 1)}" for i in range(len(stages))),
                " × ".join(fmt(n) for n in stages), fmt(ratio),
                "each stage divides the speed it is given: the output turns at ω/(N₁N₂…)")


def linear_step(mass: float, lever: float, screw: bool, inertia: float) -> Step:
    if screw:
        return Step("Inertia of the mass on the screw, at the screw", "J = m (p/2π)²",
                    f"{quantity_text(mass, 'kg')} × ({quantity_text(lever * TWO_PI, 'm')}/2π)²", quantity_text(inertia, "kg*m**2"),
                    "the nut advances p per turn, v = ω·p/2π, so ½mv² = ½·m(p/2π)²·ω²")
    return Step("Inertia of the mass on the drum, at the drum", "J = m r²", f"{quantity_text(mass, 'kg')} × ({quantity_text(lever, 'm')})²",
                quantity_text(inertia, "kg*m**2"), "the mass moves with the rim, v = ωr, so ½mv² = ½·m r²·ω²: a ring of radius r")


def reflected_step(train: Train, body: float, linear: float) -> Step:
    """J_r = J_g + (J_body + J_lin)/N²."""
    terms, numbers = [], []
    if train.gearing:
        terms.append("J_g")
        numbers.append(quantity_text(train.gearing, "kg*m**2"))
    parts = [(name, value) for name, value in (("J_load", body), ("J_mass", linear)) if value]
    inside = " + ".join(name for name, _ in parts) or "J_load"
    shown = " + ".join(quantity_text(value, "kg*m**2") for _, value in parts) or "0 kg·m²"
    terms.append(f"({inside})/N²" if len(parts) > 1 else f"{inside}/N²")
    numbers.append(f"({shown}) / {fmt(train.ratio)}²" if len(parts) > 1 else f"{shown} / {fmt(train.ratio)}²")
    return Step("Load inertia reflected to the motor shaft", "J_r = " + " + ".join(terms), " + ".join(numbers),
                quantity_text(train.reflected, "kg*m**2"),
                "the output turns at ω/N: its kinetic energy ½J(ω/N)² is that of J/N² on the motor shaft (no η: energy stored, not passed)")


def inertia_ratio_step(train: Train) -> Step:
    return Step("Inertia ratio", "J_r / J_m", f"{quantity_text(train.reflected, 'kg*m**2')} / {quantity_text(train.rotor, 'kg*m**2')}",
                fmt(train.reflected / train.rotor),
                "how much of the inertia the motor accelerates is the load's: vendors ask for a few to ten for a stiff, quick servo")


def optimal_step(train: Train, optimal: float) -> Step:
    return Step("The ratio that matches the inertias", "N* = √(J/J_m)", f"√({quantity_text(train.load, 'kg*m**2')} / {quantity_text(train.rotor, 'kg*m**2')})",
                fmt(optimal), "τ = J_mαN + Jα/N at a given output α is least where J/N² = J_m: the reflected load equals the rotor")


def force_step(parts: list[tuple[str, str, float]], force: float) -> Step:
    """F = F_ext + μmg cos θ + mg sin θ: each term as (symbol, numbers, value)."""
    said = {"F": "the force given, against the motion", "μ": "friction: μ times the weight's part across the guides",
            "m": "gravity's part along the travel: against it uphill, with it downhill"}
    return Step("Force against the moving mass", "F = " + " + ".join(symbol for symbol, _, _ in parts),
                " + ".join(numbers for _, numbers, _ in parts), quantity_text(force, "N"), "; ".join(said[symbol[0]] for symbol, _, _ in parts))


def load_torque_step(load_torque: float, force: float, lever: float | None, screw: bool, total: float) -> Step:
    arm = "p/2π" if screw else "r"
    symbols = [s for s, v in (("T_L", load_torque), (f"F·{arm}", force)) if v]
    numbers = []
    if load_torque:
        numbers.append(term(load_torque, "N*m"))
    if force:
        numbers.append(f"{term(force, 'N')} × {quantity_text(lever, 'm')}")
    return Step("Load torque at the output shaft", "T = " + " + ".join(symbols), " + ".join(numbers), quantity_text(total, "N*m"),
                f"a force F at {'a screw' if screw else 'a drum'} asks for F·{arm} at its shaft (the work F·ds = T·dθ)")


def motor_load_step(train: Train) -> Step:
    torque = train.running
    friction = (" + τ_mf", f" + {quantity_text(train.motor_friction, 'N*m')}") if train.motor_friction else ("", "")
    if train.torque >= 0:
        return Step("Load torque at the motor, running at constant speed", "T_m = T/(Nη)" + friction[0],
                    f"{term(train.torque, 'N*m')} / ({fmt(train.ratio)} × {fmt(train.efficiency)})" + friction[1], quantity_text(torque, "N*m"),
                    "the ratio divides the torque as it multiplies the speed; the losses in the teeth come on top of it, so the motor gives T/η")
    return Step("Load torque at the motor, running at constant speed: the load drives the motor", f"T_m = {_eta_back(train)}T/N" + friction[0],
                f"{fmt(train.back)} × {term(train.torque, 'N*m')} / {fmt(train.ratio)}" + friction[1], quantity_text(torque, "N*m"),
                f"the load pushes power back through the teeth (it regenerates): the losses take their share on the way, so the motor holds back only {_eta_back(train)}T/N")


def hold_step(train: Train) -> Step:
    return Step("Torque that holds the load at rest", "T_hold = T_g/N", f"{term(train.gravity, 'N*m')} / {fmt(train.ratio)}",
                quantity_text(train.hold, "N*m"), "at rest no power flows, so no η; friction in the gearing that could help hold is not counted on")


def _sub(n: int) -> str:
    return "".join("₀₁₂₃₄₅₆₇₈₉"[int(d)] for d in str(n))


def torque_step(title: str, train: Train, alpha: float, torque: float) -> Step:
    """τ = (J_m + J_g)α + (Jα/N + T)/(Nη), or η(Jα/N + T)/N while the load drives: the terms there are."""
    if isinstance(train, Loads):  # several loads, each through its own train
        return loads_torque_step(title, train, alpha, torque)
    driving = train.demand(alpha) >= 0
    j_in = "(J_m + J_g)α" if train.gearing and train.rotor else ("J_gα" if train.gearing else "J_mα")
    j_in_numbers = f"{quantity_text(train.input_inertia, 'kg*m**2')} × {term(alpha, 'rad/s**2')}"
    inner = [(s, n) for s, n, v in (("Jα/N", f"{quantity_text(train.load, 'kg*m**2')} × {term(alpha, 'rad/s**2')}/{fmt(train.ratio)}", train.load),
                                     ("T", term(train.torque, "N*m"), train.torque)) if v]
    equation, numbers = f"τ = {j_in}", j_in_numbers
    power = "N"
    if len(inner) == 1 and train.load:  # Jα/N/N: written Jα/N²
        inner, power = [("Jα", f"{quantity_text(train.load, 'kg*m**2')} × {term(alpha, 'rad/s**2')}")], "N²"
    if inner:
        symbols = " + ".join(s for s, _ in inner)
        shown = " + ".join(n for _, n in inner)
        symbols, shown = (f"({symbols})", f"({shown})") if len(inner) > 1 else (symbols, shown)
        n = f"{fmt(train.ratio)}²" if power == "N²" else fmt(train.ratio)
        if not driving:
            equation += f" + {_eta_back(train)}{symbols}/{power}"
            numbers += f" + {fmt(train.back)} × {shown} / {n}"
        elif train.efficiency != 1:
            equation += f" + {symbols}/({power}η)"
            numbers += f" + {shown} / ({n} × {fmt(train.efficiency)})"
        else:
            equation += f" + {symbols}/{power}"
            numbers += f" + {shown} / {n}"
    if train.motor_friction:
        equation += " + τ_mf"
        numbers += f" + {quantity_text(train.motor_friction, 'N*m')}"
    why = ("the output asks Jα/N + T of its shaft; the ratio divides it by N, and the motor pays the losses in the teeth on top (1/η)"
           if driving else f"the load gives power back through the teeth (it regenerates): the motor holds it back, and the losses keep (1 − {_eta_back(train)}) of it")
    if train.motor_friction:
        why += "; the friction at the motor shaft, against the motion, passes no teeth"
    return Step(title, equation, numbers, quantity_text(torque, "N*m"), why)


def _eta_back(train: Train) -> str:
    return "η′" if train.efficiency_back is not None else "η"
