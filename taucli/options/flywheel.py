"""taucli flywheel: the fluctuation of a flywheel's speed and energy over a cycle, and its rim."""

from taucli.options.common import ANSWER, BODY_OPTIONS
from taucli.options.table import CURVE, TEXT, Command, Option, Result

SPEED = "Speed and its fluctuation"
ENERGY = "Energy"
RIM = "Rim (a flywheel whose mass is in its rim)"
DIAGRAM = "A turning-moment diagram"

COMMAND = Command(
    name="flywheel",
    summary="A flywheel's fluctuation of speed: Cs = (ω_max − ω_min)/ω_mean and ΔE = Iω²Cs, any two of I, ΔE, Cs; its rim's stress.",
    description=(
        "The mean speed (--omega-mean, or the band --omega-max and --omega-min, or a rim's --rim-speed) and two of the "
        "flywheel's moment of inertia (--inertia, --shape, --part), the energy it gives up and takes back each cycle "
        "(--energy-swing, or a punch's --energy-per-cycle with --punch-fraction) and the coefficient of fluctuation "
        "(--fluctuation, or ± --speed-variation) give the third. With the rim's mean radius, its mass; with its "
        "--density, the hoop stress ρv² the rim speed puts in it, against --allowable-stress."
    ),
    example="taucli flywheel --omega-mean 300rpm --fluctuation 0.02 --energy-swing 5kJ --rim-radius 0.6m --density '7200kg/m^3'",
    options=(
        # its --density is the rim's, for the hoop stress; --gyration with --mass is the body's I = Mk² (#42 item 15)
        *(option for option in BODY_OPTIONS if option.name != "density"),
        Option("omega_mean", "angular velocity", "Mean speed ω_mean, e.g. 300rpm.", panel=SPEED),
        Option("omega_max", "angular velocity", "Greatest speed in the cycle (with --omega-min: the mean is their average).", panel=SPEED),
        Option("omega_min", "angular velocity", "Least speed in the cycle.", sign="nonnegative", panel=SPEED),
        Option("fluctuation", "dimensionless", "Coefficient of fluctuation of speed Cs = (ω_max − ω_min)/ω_mean, e.g. 0.02.", panel=SPEED),
        Option("speed_variation", "dimensionless", "The speed's swing either side of the mean, as a fraction: 0.01 for ±1% (Cs = 0.02).", panel=SPEED),
        Option("energy_swing", "energy", "Maximum fluctuation of energy ΔE: what the flywheel gives up and takes back each cycle, e.g. 5kJ.", panel=ENERGY),
        Option("energy_per_cycle", "energy", "Energy a punch or shear takes each cycle, which the motor supplies evenly over the cycle.", panel=ENERGY),
        Option("punch_fraction", "dimensionless", "Share of the cycle during which the punch takes that energy (0 to 1): ΔE = E(1 − f).",
               sign="nonnegative", default="0", panel=ENERGY),
        Option("turning_moment", CURVE, "The turning-moment diagram T(θ): a CSV file of crank angle and torque (a header such as "
               "'theta [deg], torque [N*m]', then rows), or a formula of theta, e.g. '(15000 + 10000*sin(2*theta)) N*m': "
               "ΔE, the mean torque and power.", panel=DIAGRAM, metavar="FILE|FORMULA",
               example="'(15000 + 10000*sin(2*theta) - 6000*cos(2*theta)) N*m'"),
        Option("cycle_angle", "angle", "The crank angle of one cycle, with --turning-moment: 360deg (a two-stroke engine, a steam engine), "
               "720deg (a four-stroke); default the samples' span, or the formula's period (2π, else 4π).", panel=DIAGRAM),
        Option("torque_mean", "torque", "The diagram's mean torque, with --loops (the loops are measured from its line): the mean power.",
               panel=DIAGRAM),
        Option("loops", TEXT, "A turning-moment diagram's loops, in order: their areas in mm², + above the mean torque line and − below, "
               'e.g. "295,-685,390" (with --scale-torque and --scale-angle): ΔE.', panel=DIAGRAM, metavar='"a1,a2,…"'),
        Option("scale_torque", "torque", "The diagram's torque scale: the torque one mm stands for, e.g. '5N*m'.", panel=DIAGRAM),
        Option("scale_angle", "angle", "The diagram's crank-angle scale: the angle one mm stands for, e.g. 1deg.", panel=DIAGRAM),
        Option("cycle_time", "time", "The time of one cycle, with --energy-per-cycle: the motor's power, which supplies that energy evenly.", panel=ENERGY),
        Option("rim_radius", "length", "Mean radius of the rim, taken as the radius of gyration (the arms and hub neglected): the rim's mass I/R².", panel=RIM),
        Option("rim_speed", "velocity", "Mean speed of the rim, v = ω_mean R (instead of --omega-mean; alone, the rim's mass from ΔE = mv²Cs).", panel=RIM),
        Option("rim_speed_max", "velocity", "The rim's greatest speed in the cycle (with --rim-speed-min: the band as the rim's speeds).", panel=RIM),
        Option("rim_speed_min", "velocity", "The rim's least speed in the cycle.", sign="nonnegative", panel=RIM),
        Option("density", "density", "Density of the rim, for its hoop stress ρv² and cross-section, e.g. '7200kg/m^3'.", panel=RIM),
        Option("allowable_stress", "stress", "The stress the rim's material may carry, against the hoop stress at the top speed, e.g. 6MPa.", panel=RIM),
    ),
    results=(
        Result("cs", "", "coefficient of fluctuation of speed…"),
        Result("energy_swing", "J", "maximum fluctuation of energy ΔE…"),
        Result("I", "kg*m**2", "moment of inertia of the flywheel…"),
        Result("omega_mean", "rad/s", "mean speed"),
        Result("omega_max", "rad/s", "greatest speed, ω_mean(1 + Cs/2)"),
        Result("omega_min", "rad/s", "least speed, ω_mean(1 − Cs/2)"),
        Result("KE_mean", "J", "kinetic energy at the mean speed, ½Iω²"),
        Result("mass", "kg", "mass of the rim…"),
        Result("rim_speed", "m/s", "mean rim speed v = ω_mean R"),
        Result("rim_speed_max", "m/s", "rim speed at ω_max"),
        Result("hoop_stress", "Pa", "hoop stress in the rim at the mean speed, ρv²"),
        Result("hoop_stress_max", "Pa", "hoop stress at the top speed, ρv_max²"),
        Result("rim_area", "m**2", "cross-section of the rim, m/(2πRρ)"),
        Result("power_motor", "W", "motor power that supplies the energy per cycle evenly, E/t", needs=("energy_per_cycle+cycle_time",),
               example="{energy_per_cycle} 26.7kJ {punch_fraction} 0.16 {cycle_time} 3s {omega_mean} 300rpm {fluctuation} 0.1"),
        Result("torque_mean", "N*m", "mean torque over the cycle…", needs=("turning_moment", "loops+torque_mean")),
        Result("power_mean", "W", "mean power, T_mean ω_mean", needs=("turning_moment", "loops+torque_mean")),
        Result("stress_margin", "", "allowable stress over the hoop stress at the top speed", needs=("allowable_stress",)),
    ),
    output=ANSWER,
    headline="energy_swing",
    library="taucli.scenes.flywheel:flywheel",
)
