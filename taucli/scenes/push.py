"""A push at a lever, which makes a torque or adds to a given one (spin-down, impulse): τ = F r sin φ."""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.writing.report import Step, fmt, quantity_text, term


@dataclass(frozen=True)
class Push:
    """A push at a lever: τ = F r sin φ, with φ between the lever arm and the force."""

    force: float
    lever: float
    angle: float = math.pi / 2

    @property
    def torque(self) -> float:
        return self.force * self.lever * math.sin(self.angle)


def drive_steps(push: Push | None, torque: float | None) -> list[Step]:
    """How the drive was formed: the push's torque F r sin φ, and where a torque is given beside
    it, their sum (a drive and a push, or a load torque and a push, act on the one axle and add)."""
    if push is None:
        return []
    steps = [push_step(push)]
    if torque is not None:
        steps.append(Step("Drive torque: the given torque and the push's add", "τ_drive = τ + F r sin φ",
                          f"{term(torque, 'N*m')} + {term(push.torque, 'N*m')}", quantity_text(torque + push.torque, "N*m"),
                          "torques about one axle add, each with its sign (positive along +ω)"))
    return steps


def push_step(push: Push) -> Step:
    at_right_angle = math.isclose(push.angle, math.pi / 2)
    return Step(
        "Torque of the push",
        "τ = F r" if at_right_angle else "τ = F r sin φ",
        f"{quantity_text(push.force, 'N')} × {quantity_text(push.lever, 'm')}"
        + ("" if at_right_angle else f" × sin {fmt(math.degrees(push.angle))}°"),
        quantity_text(push.torque, "N*m"),
        "the force is tangential, perpendicular to the radius, so all of it turns the wheel"
        if at_right_angle
        else "only the part of the force perpendicular to the lever arm makes torque",
    )
