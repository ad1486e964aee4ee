"""taucli spin-down: a wheel on a fixed axle, slowing or spun up."""

from taucli.options.common import ANSWER, BODY_OPTIONS, DT, METHOD, MOTION, RTOL
from taucli.table import Command, Option, Result

COMMAND = Command(
    name="spin-down",
    summary="A wheel on a fixed axle, slowing or spun up: I dω/dt = τ_drive − τ_f − bω − kω².",
    example="taucli spin-down --shape disc --mass 5kg --radius 0.2m --omega0 30rad/s --friction 0.3N*m",
    options=(
        *BODY_OPTIONS,
        Option("omega0", "angular velocity", "Initial angular velocity, e.g. 300rpm.", sign="any", default="0", panel=MOTION),
        Option("torque", "torque", "Driving torque along +ω (negative: against it), e.g. 1.5N*m.", sign="any"),
        Option("force", "force", "A push at --lever that makes the driving torque, e.g. 6N.", sign="any"),
        Option("lever", "length", "Distance of the push from the axle, e.g. 0.25m."),
        Option("push_angle", "angle", "Angle between lever arm and force.", sign="any", default="90deg"),
        Option("friction", "torque", "Constant friction torque at the axle (also holds it at rest), e.g. 0.3N*m.", sign="nonnegative"),
        Option("viscous", "viscous coefficient", "Viscous coefficient b (torque bω), e.g. 0.01N*m*s.", sign="nonnegative"),
        Option("drag", "drag coefficient", "Drag coefficient k (torque kωⁿ), e.g. 0.001N*m*s^2.", sign="nonnegative"),
        Option("drag_exponent", "dimensionless", "Exponent n of the drag torque kωⁿ, 1 to 10.", default="2", metavar="N"),
        Option("time", "time", "Report ω, θ and revolutions at this time, e.g. 4s.", sign="nonnegative", panel=MOTION),
        Option("until_omega", "angular velocity", "Report the time and angle to reach this speed.", sign="any", panel=MOTION),
        METHOD,
        DT,
        RTOL,
    ),
    results=(
        Result("I", "kg*m**2", "moment of inertia about the axle"),
        Result("alpha0", "rad/s**2", "angular acceleration at the start"),
        Result("t_stop", "s", "time until the wheel stops"),
        Result("theta_stop", "rad", "angle turned until it stops"),
        Result("revs_stop", "rev", "revolutions until it stops"),
        Result("omega_inf", "rad/s", "steady speed as t -> ∞"),
        Result("omega", "rad/s", "angular velocity…"),
        Result("theta", "rad", "angle turned…"),
        Result("revs", "rev", "revolutions…"),
        Result("t_until", "s", "time to reach…"),
        Result("theta_until", "rad", "angle turned until…"),
    ),
    output=ANSWER,
    headline="alpha0",
    library="taucli.scenes.spin:spin_down",
)
