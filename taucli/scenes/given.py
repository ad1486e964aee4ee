"""What a scene is given in a spec option: a part of a body, a particle that meets it, another
body on its axis, a brake shoe, a pressed face. Plain records in SI (taucli.answering.specs reads them from
their "key=value" texts); the scenes that use them hold the physics.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from taucli.scenes.angles import sin_exact


@dataclass(frozen=True)
class Part:
    """One part of a body: a shape, its mass and dimensions, its axis and its parallel shift.

    ``source`` names where the part came from in messages ("" for the main options, else
    "{part} 2": the option's name, spelled by whoever shows the message).
    """

    shape: str
    mass: float | None
    dims: Mapping[str, float] = field(default_factory=dict)
    axis: str | None = None
    offset: float | None = None
    source: str = ""
    inertia: float | None = None  # its own I (about its centre when an offset moves it)
    gyration: float | None = None  # its radius of gyration k (I = Mk²)
    density: float | None = None  # its mass from its shape's volume (or area, or length: density_unit)
    density_unit: str = "kg/m**3"  # kg/m**2 for a plate's or disc's mass per area, kg/m for a rod's or ring's per length
    angle: float | None = None  # where its centre lies round the axis (inertia --body-offset: the body's centre of mass)

    def option(self, name: str) -> str:
        flag = name.replace("_", "-")
        return f"{self.source} {flag}=" if self.source else name

    def mention(self, name: str) -> str:
        """The input as a message's text names it: {name} (spelled by the surface showing it) for
        the main options, "flag=" inside a part's spec."""
        return f"{name.replace('_', '-')}=" if self.source else f"{{{name}}}"

    def example(self, name: str, value: str) -> str:
        flag = name.replace("_", "-")
        lead = self.shape or ("gyration=0.3m" if self.gyration is not None else "inertia=0.05kg*m^2")
        if flag == "mass":
            return f'{{part}} "{lead} mass={value}"' if self.source else f"{{{name}}} {value}"
        return f'{{part}} "{lead} mass=1kg {flag}={value}"' if self.source else f"{{{name}}} {value}"


@dataclass(frozen=True)
class Particle:
    """A particle that meets the body (--particle): its mass, its signed speed along its line
    (positive when its angular momentum is in the body's positive sense; None: it rides on the
    body), the radius where it meets the body and the angle there between its velocity and the
    radius (90°: its line passes at ``radius`` from the axis), and what it does after; with
    ``speed_relative``, it moves after along the rim at that speed relative to the body (a toy
    train on a free wheel, a person walking on a turntable): v′ = ω₁ρ + v_rel."""

    source: str
    mass: float
    radius: float
    speed: float | None = None
    angle: float | None = None
    speed_after: float | None = None
    radius_after: float | None = None
    e: float | None = None
    speed_relative: float | None = None

    @property
    def sine(self) -> float:
        return 1.0 if self.angle is None else sin_exact(self.angle)

    @property
    def arm(self) -> float:
        """r⊥ = r sin φ: the distance of its line of motion from the axis."""
        return self.radius * self.sine


@dataclass(frozen=True)
class Couple:
    """Another body on the same axis (--couple) that locks to the first: I, or a shape, and its ω₀;
    with ``torque``, through a clutch that slips until the speeds meet, passing that torque."""

    source: str
    inertia: float | None = None
    part: Part | None = None  # where a shape is given
    omega0: float | None = None
    torque: float | None = None


@dataclass(frozen=True)
class Rotor:
    """Another rotor on the vehicle (gyro --rotor): its I, its spin and the sense a book gives it."""

    source: str
    inertia: float
    spin: float
    sense: str


@dataclass(frozen=True)
class Revolving:
    """A mass turning with a shaft (balance --mass): m at radius r and angle θ, in the plane at
    ``plane`` along the shaft (None: not given); a uniform rod along the radius from r outwards
    where ``length`` is given (its centre of mass at r + L/2)."""

    source: str
    mass: float
    radius: float
    angle: float
    plane: float | None = None
    length: float | None = None

    @property
    def centre(self) -> float:
        """The radius of its centre of mass: r, or r + L/2 for a rod along the radius."""
        return self.radius if self.length is None else self.radius + self.length / 2


@dataclass(frozen=True)
class Phase:
    """One phase of a spin-down run (--phase), in order: its rate (α, or a torque with the body's
    I; a coast: α = 0; or neither, α then following from two ends) and how it ends (a time, a net
    angle, a speed reached): the values a book gives, in SI, None where not given."""

    source: str
    alpha: float | None = None
    torque: float | None = None
    time: float | None = None
    angle: float | None = None
    until_omega: float | None = None


PRESSURES = ("uniform", "wear")  # a face's pressure models (model=)
SHOES = ("both", "leading", "trailing")  # an internal expanding brake's shoes (shoes=): leading is self-energizing


@dataclass(frozen=True)
class Brake:
    """A shoe pressed at ``radius`` (None: the body's radius); μ kinetic and static. Without
    ``lever``, ``force`` is the normal force N on the shoe; with it, ``force`` is the force F
    applied to a lever at ``lever`` from the lever's pivot, the shoe at ``pivot`` from it, and the
    line of the shoe's friction force at ``offset`` from the pivot (positive where its moment
    adds to F's: self-energizing).

    ``expanding``: internal expanding shoes (taucli.scenes.expanding), each hinged on a pin
    ``hinge`` from the drum's centre, its lining of ``width`` from ``heel_angle`` θ₁ to θ₁ +
    ``shoe_angle`` (angles from the line through the pin and the centre), pushed out by the
    actuating ``force`` at ``lever`` from the pin (or that force from ``pmax``, the largest
    lining pressure); ``shoes`` the leading one (self-energizing), the trailing one, or both."""

    source: str
    force: float | None  # None: an internal expanding brake given by pmax
    mu_k: float
    mu_s: float | None = None
    radius: float | None = None
    lever: float | None = None
    pivot: float | None = None
    offset: float = 0.0
    shoe_angle: float | None = None  # a long shoe's arc 2θ (None: a short shoe, its pressure at one point); an expanding shoe's lining arc θ₂ − θ₁
    expanding: bool = False
    heel_angle: float | None = None  # θ₁ of an expanding shoe, from the line through its hinge pin and the drum's centre
    width: float | None = None  # the lining's face width b
    hinge: float | None = None  # a: the hinge pin's distance from the drum's centre
    pmax: float | None = None  # the largest lining pressure p_a (in place of force)
    shoes: str = "both"

    @property
    def sided(self) -> bool:
        """Its torque depends on the sense the drum turns: a lever whose friction has a moment
        about its pivot, or one internal shoe alone (leading one way, trailing the other)."""
        if self.expanding:
            return self.shoes != "both"
        return self.lever is not None and bool(self.offset)


PADS = ("annular", "circular")  # a caliper's pad shapes (pad=)


@dataclass(frozen=True)
class Caliper:
    """A caliper disc brake (taucli.scenes.caliper): ``surfaces`` pads, each pressed on the disc
    with ``force``; μ kinetic and static; ``model`` uniform pressure or uniform wear. An annular
    pad between ``inner_radius`` and ``outer_radius`` over ``angle`` (None: not given, for the
    pressure only); a circular pad of ``pad_radius`` with its centre at ``centre_distance`` from the axis."""

    source: str
    mu_k: float
    force: float
    pad: str = "annular"
    mu_s: float | None = None
    inner_radius: float = 0.0
    outer_radius: float | None = None
    angle: float | None = None
    pad_radius: float | None = None
    centre_distance: float | None = None
    model: str = "uniform"
    surfaces: int = 2


@dataclass(frozen=True)
class Centrifugal:
    """A centrifugal clutch (taucli.scenes.centrifugal): ``shoes`` shoes of ``mass`` each, their
    centres of mass at ``radius`` from the axis when they touch the drum, each pulled in there by
    its spring with ``spring_force``; μ between shoe and drum, the drum's inner radius ``drum_radius``."""

    source: str
    shoes: int
    mass: float
    radius: float
    spring_force: float
    mu: float
    drum_radius: float


@dataclass(frozen=True)
class Band:
    """A band brake: a band wrapped ``wrap`` radians round a drum of ``radius`` (None: the body's),
    μ kinetic and static, ``width`` (None: not given). Pulled by ``tension`` at its slack end, or
    by a lever: ``force`` at ``lever`` from the lever's pivot, the slack end at ``slack_arm`` and
    the tight end at ``tight_arm`` from it (None: that end is fixed at the pivot; both: a
    differential band brake, the ends on opposite sides of the pivot). With ``blocks``, a band-and-block
    brake: n blocks of angle 2θ on the band press the drum (``wrap`` = 2nθ), the band ``thickness``
    out from the drum."""

    source: str
    mu_k: float
    wrap: float
    mu_s: float | None = None
    radius: float | None = None
    width: float | None = None
    tension: float | None = None
    force: float | None = None
    lever: float | None = None
    slack_arm: float | None = None
    tight_arm: float | None = None
    blocks: int | None = None  # a band-and-block brake: n blocks, each of angle 2θ (block_angle), lined on the band
    block_angle: float | None = None
    thickness: float = 0.0  # the blocks' thickness: the band's line at radius + thickness


@dataclass(frozen=True)
class Face:
    """A flat face pressed with ``force`` (None: the body's weight, or from ``pmax``) between the
    radii (None: the body's)."""

    source: str
    mu_k: float
    mu_s: float | None = None
    force: float | None = None
    inner_radius: float | None = None
    outer_radius: float | None = None
    pressure: str = "uniform"  # the model: uniform pressure or uniform wear
    surfaces: int = 1
    pmax: float | None = None  # the largest lining pressure, giving the clamp force with the radii
    cone: float | None = None  # a cone clutch's semi-cone angle α (None: a flat face, α = 90°); force is then the axial force

    @property
    def by_weight(self) -> bool:
        """Pressed by the body's weight (no force=, no pmax=): it needs gravity."""
        return self.force is None and self.pmax is None


SURFACES = ("hang", "table", "incline")  # where a block of the Atwood machine is (--side1, --side2)


@dataclass(frozen=True)
class Side:
    """Where a block of the Atwood machine is (--side1, --side2): it hangs, lies on a table, or on
    its own incline at ``angle``; the friction coefficients under it (None: not given)."""

    source: str
    surface: str  # "hang", "table" or "incline"
    angle: float | None = None  # an incline's, from the horizontal
    mu_k: float | None = None
    mu_s: float | None = None


@dataclass(frozen=True)
class Pull:
    """A constant pull on a block of the Atwood machine (--pull): ``force`` along the block's path
    away from the pulley (negative: towards it), tilted ``angle`` off its surface (positive lifting
    it), on block ``on`` (1 or 2)."""

    source: str
    force: float
    angle: float = 0.0
    on: int = 1
