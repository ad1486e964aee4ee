"""A flywheel's fluctuation of speed and energy over a cycle, and the stress in its rim.

Over a cycle (an engine's, a punch's) the flywheel's speed swings between ω_max and ω_min about
the mean ω_mean = (ω_max + ω_min)/2; the coefficient of fluctuation of speed is

    Cs = (ω_max − ω_min)/ω_mean,

and the energy it gives up between the two, the maximum fluctuation of energy, is exactly

    ΔE = ½I(ω_max² − ω_min²) = I·ω_mean·(ω_max − ω_min) = I·ω_mean²·Cs,

so any two of I, ΔE and Cs give the third. A flywheel whose mass is in its rim, of mean radius
R, has I = mR² and its rim moves at v = ω_mean R: ΔE = m v² Cs, and a thin rim carries the hoop
stress σ = ρv² (the centripetal force of each element, taken by the tension around the ring),
greatest at the top speed. A punch taking E each cycle during a share f of it, from a motor
that supplies E evenly over the cycle, leaves the flywheel to give ΔE = E(1 − f).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.flywheel import COMMAND as TABLE
from taucli.writing.report import Report, Step, fmt, quantity_text
from taucli.scenes.inertia import body
from taucli.scenes.turning_moment import LOOPS_EXAMPLE, read_loops, swing_from_loops
from taucli.scenes.diagram import EXAMPLE as DIAGRAM_EXAMPLE, swing_from_curve
from taucli.options.table import Results

_EXAMPLE = "{omega_mean} 300rpm {fluctuation} 0.02 {energy_swing} 5kJ"
DIAGRAM_MODEL = "a turning-moment diagram T(θ): ΔE = max − min of ∫(T − T_mean)dθ"


def flywheel(
    *,
    inertia: float | None = None,
    shape: str | None = None,
    mass: float | None = None,
    axis: str | None = None,
    offset: float | None = None,
    part: Sequence = (),
    gyration: float | None = None,
    omega_mean: float | None = None,
    omega_max: float | None = None,
    omega_min: float | None = None,
    fluctuation: float | None = None,
    speed_variation: float | None = None,
    energy_swing: float | None = None,
    energy_per_cycle: float | None = None,
    punch_fraction: float | None = None,
    rim_radius: float | None = None,
    rim_speed: float | None = None,
    density: float | None = None,
    allowable_stress: float | None = None,
    loops: str | None = None,
    scale_torque: float | None = None,
    scale_angle: float | None = None,
    cycle_time: float | None = None,
    rim_speed_max: float | None = None,
    rim_speed_min: float | None = None,
    turning_moment=None,
    cycle_angle: float | None = None,
    torque_mean: float | None = None,
    **dims: float | None,
) -> Report:
    """``taucli flywheel``: the mean speed (or the band, or a rim's speed) and two of I, ΔE, Cs;
    ΔE also from a turning-moment diagram's loops (turning_moment.py) or from T(θ) itself, a
    formula of θ (an OfTime) or its samples, SI (θ, T) pairs (diagram.py), with its mean torque."""
    steps: list[Step] = []
    notes: list[str] = []
    results = Results(TABLE)
    torque_mean_given, method = torque_mean is not None, "closed form"
    if turning_moment is not None:
        _diagram_alone(loops, energy_swing, energy_per_cycle, scale_torque, scale_angle, torque_mean)
        energy_swing, torque_mean, method = swing_from_curve(turning_moment, cycle_angle, steps, notes)
    elif cycle_angle is not None:
        raise InputError("cycle_angle", "goes with {turning_moment}: the crank angle of the diagram's cycle", example=DIAGRAM_EXAMPLE + " {cycle_angle} 360deg")
    elif torque_mean is not None and loops is None:
        raise InputError("torque_mean", "goes with {loops}: the mean torque line the loops are measured from", example=LOOPS_EXAMPLE + " {torque_mean} '2.5kN*m'")
    if loops is not None:
        if energy_swing is not None or energy_per_cycle is not None:
            given = "energy_swing" if energy_swing is not None else "energy_per_cycle"
            raise InputError("loops", f"conflicts with {{{given}}}: the diagram's loops give ΔE", example=LOOPS_EXAMPLE)
        energy_swing = swing_from_loops(read_loops(loops), scale_torque, scale_angle, steps, notes)
    elif scale_torque is not None or scale_angle is not None:
        raise InputError("scale_torque" if scale_torque is not None else "scale_angle", "goes with {loops}: the scales of the diagram whose loops are given",
                         example=LOOPS_EXAMPLE)
    if cycle_time is not None and energy_per_cycle is None:
        raise InputError("cycle_time", "goes with {energy_per_cycle}: the motor supplies that energy over the cycle", example="{energy_per_cycle} 26.7kJ {cycle_time} 3s")
    if (rim_speed_max is None) != (rim_speed_min is None):
        raise InputError("rim_speed_min" if rim_speed_min is None else "rim_speed_max", "goes with {rim_speed_max}/{rim_speed_min}: the band needs both ends",
                         example="{rim_speed_max} 30m/s {rim_speed_min} 29m/s")
    if rim_speed_max is not None:
        rim_speed, fluctuation = _rim_band(rim_speed_max, rim_speed_min, rim_speed, fluctuation, speed_variation, steps)
    given_body = inertia is not None or shape is not None or gyration is not None or bool(part)
    if not given_body and mass is not None and rim_radius is not None and density is not None and all(
            value is None for value in (omega_mean, omega_max, omega_min, rim_speed, offset, *dims.values())):
        return _rim_section(mass, rim_radius, density, fluctuation=fluctuation, speed_variation=speed_variation, energy_swing=energy_swing,
                            energy_per_cycle=energy_per_cycle, allowable_stress=allowable_stress)
    moment = None
    if given_body:
        moment, body_steps = body(inertia=inertia, shape=shape, mass=mass, axis=axis, offset=offset, part=part, gyration=gyration, notes=notes, **dims)
        steps += body_steps
    elif mass is not None or offset is not None or any(v is not None for v in dims.values()):
        raise InputError("shape", "is required with the body's mass and dimensions (or give {inertia})", example="{shape} ring {mass} 500kg {radius} 0.6m")

    mean, cs = _speeds(omega_mean, omega_max, omega_min, rim_speed, rim_radius, fluctuation, speed_variation, steps)
    swing = _swing(energy_swing, energy_per_cycle, punch_fraction, steps)
    rim_only = mean is None  # a rim's speed alone: ΔE = m v² Cs, the rim's mass in place of I
    if rim_only and given_body:
        raise InputError("rim_speed", "without {rim_radius} goes with the rim's mass, not a body: give {rim_radius} (ω = v/R) or {omega_mean}",
                         example="{rim_speed} 25m/s {rim_radius} 0.5m")
    if moment is None and cs is None and swing is not None and (turning_moment is not None or loops is not None):
        return _diagram_only(results, steps, notes, swing, torque_mean, torque_mean_given, None if rim_only else mean, method,
                             "turning_moment" if turning_moment is not None else "loops")
    square = rim_speed**2 if rim_only else mean**2
    symbol, unknown = ("v²", "m") if rim_only else ("ω_mean²", "I")
    known = {"I": moment, "energy_swing": swing, "cs": cs}
    missing = [name for name, value in known.items() if value is None]
    if not missing:
        raise InputError("energy_swing" if energy_swing is not None else "energy_per_cycle",
                         "is one too many: ΔE = Iω²Cs, so two of the body (I), the energy swing and the fluctuation give the third",
                         example=_EXAMPLE)
    if len(missing) > 1:
        wanted = {"I": "the body ({inertia} or {shape})", "energy_swing": "{energy_swing} (or {energy_per_cycle})", "cs": "{fluctuation} (or the speed band)"}
        raise InputError(missing[0] if missing[0] != "I" else "inertia", "and " + " or ".join(wanted[m] for m in missing[1:])
                         + " are not given: ΔE = Iω²Cs needs two of I, ΔE and Cs", example=_EXAMPLE)
    if missing == ["I"]:
        moment = swing / (square * cs)
        steps.append(Step("The flywheel it takes" if not rim_only else "The rim's mass it takes", f"{unknown} = ΔE/({symbol}Cs)",
                          f"{quantity_text(swing, 'J')} / (({_speed_text(rim_only, rim_speed, mean)})² × {fmt(cs)})",
                          quantity_text(moment, "kg" if rim_only else "kg*m**2"),
                          "ΔE = ½I(ω_max² − ω_min²) = I·ω_mean·(ω_max − ω_min) = Iω_mean²Cs: the energy between the top and the bottom speed"
                          + ("; for a rim, Iω² = mR²ω² = mv²" if rim_only else "")))
    elif missing == ["energy_swing"]:
        swing = moment * square * cs
        steps.append(Step("Maximum fluctuation of energy", f"ΔE = {unknown}{symbol}Cs",
                          f"{quantity_text(moment, 'kg*m**2')} × ({_speed_text(rim_only, rim_speed, mean)})² × {fmt(cs)}", quantity_text(swing, "J"),
                          "the kinetic energy between the top and the bottom speed: ½I(ω_max² − ω_min²) = Iω_mean(ω_max − ω_min)"))
    else:
        cs = swing / (moment * square)
        steps.append(Step("Coefficient of fluctuation of speed", f"Cs = ΔE/({unknown}{symbol})",
                          f"{quantity_text(swing, 'J')} / ({quantity_text(moment, 'kg*m**2')} × ({_speed_text(rim_only, rim_speed, mean)})²)", fmt(cs),
                          "ΔE = Iω_mean²Cs read the other way"))
        if cs >= 2:
            source = "turning_moment" if turning_moment is not None else "loops" if loops is not None else "energy_swing"
            raise InputError(source, f"gives more than the flywheel holds over that speed: Cs = {fmt(cs)} would take ω_min below 0", example=_EXAMPLE)
    if torque_mean is not None:
        _mean_power(results, steps, notes, torque_mean, torque_mean_given, None if rim_only else mean)
    if cycle_time is not None:
        results.put("power_motor", energy_per_cycle / cycle_time)
        steps.append(Step("The motor's power", "P = E/t", f"{quantity_text(energy_per_cycle, 'J')} / {quantity_text(cycle_time, 's')}",
                          quantity_text(energy_per_cycle / cycle_time, "W"), "the motor supplies the energy of each cycle evenly over it; the flywheel evens out the rest"))
    results.put("cs", cs, " (ω_max − ω_min)/ω_mean")
    results.put("energy_swing", swing, ", from the diagram" if turning_moment is not None or loops is not None else ", Iω²Cs" if not rim_only else ", mv²Cs")
    if not rim_only:
        results.put("I", moment)
        results.put("omega_mean", mean)
        results.put("omega_max", mean * (1 + cs / 2))
        results.put("omega_min", mean * (1 - cs / 2))
        results.put("KE_mean", 0.5 * moment * mean * mean)
    rim_mass = moment if rim_only else (moment / rim_radius**2 if rim_radius is not None else None)
    if rim_mass is not None:
        results.put("mass", rim_mass, ", I/R²" if not rim_only else ", ΔE/(v²Cs)")
        if not rim_only:
            steps.append(Step("Mass of the rim", "m = I/R²", f"{quantity_text(moment, 'kg*m**2')} / ({quantity_text(rim_radius, 'm')})²",
                              quantity_text(rim_mass, "kg"), "the rim's mass sits at its mean radius (the arms and hub are left out, as the books do)"))
        speed = rim_speed if rim_speed is not None else mean * rim_radius
        results.put("rim_speed", speed)
        results.put("rim_speed_max", speed * (1 + cs / 2))
    _rim_stress(results, steps, notes, rim_mass, rim_radius, rim_speed if rim_speed is not None else (mean * rim_radius if rim_radius is not None else None),
                cs, density, allowable_stress)
    model = ("a rim flywheel: ΔE = mv²Cs" if rim_only else "flywheel fluctuation: ΔE = Iω_mean²Cs") + ", Cs = (ω_max − ω_min)/ω_mean"
    if turning_moment is not None:
        model = f"{DIAGRAM_MODEL}; {model}"
    return Report("flywheel", model, method, results, steps, notes)


def _diagram_alone(loops, energy_swing, energy_per_cycle, scale_torque, scale_angle, torque_mean) -> None:
    """T(θ) gives ΔE and the mean torque: refused beside another way of giving them."""
    for name, value, why in (("loops", loops, "give the diagram one way"), ("energy_swing", energy_swing, "the diagram gives ΔE"),
                             ("energy_per_cycle", energy_per_cycle, "the diagram gives the work per cycle"),
                             ("torque_mean", torque_mean, "the diagram gives the mean torque")):
        if value is not None:
            raise InputError(name, f"conflicts with {{turning_moment}}: {why}", example=DIAGRAM_EXAMPLE)
    for name, value in (("scale_torque", scale_torque), ("scale_angle", scale_angle)):
        if value is not None:
            raise InputError(name, "goes with {loops}: the scales of a drawn diagram's areas ({turning_moment} is the curve itself)", example=LOOPS_EXAMPLE)


def _diagram_only(results, steps, notes, swing: float, torque_mean, torque_mean_given: bool, mean: float | None, method: str, source: str) -> Report:
    """What a turning-moment diagram gives alone, with the mean speed: ΔE, the mean torque and
    power; I and Cs wait for one of them (ΔE = Iω²Cs), said in a note, not refused (a result
    the diagram makes is never hidden behind the flywheel it does not)."""
    if torque_mean is not None:
        _mean_power(results, steps, notes, torque_mean, torque_mean_given, mean)
    results.put("energy_swing", swing, ", from the diagram")
    if mean is not None:
        results.put("omega_mean", mean)
    results.put("cs", None, " (ω_max − ω_min)/ω_mean")
    results.put("I", None)
    notes.append("I and cs: give --inertia (the flywheel) or --fluctuation (its speed band) for the other: ΔE = Iω_mean²Cs")
    model = (DIAGRAM_MODEL if source == "turning_moment"
             else "a turning-moment diagram's loops: ΔE from the running sum of their areas")
    needs = {"I": ("fluctuation", "is needed for I with the diagram's ΔE: I = ΔE/(ω_mean²Cs) (or give --inertia for cs)"),
             "cs": ("inertia", "is needed for cs with the diagram's ΔE: Cs = ΔE/(Iω_mean²) (or give --fluctuation for I)")}
    return Report("flywheel", model, method, results, steps, notes, needs=needs)


def _mean_power(results, steps, notes, torque_mean: float, given: bool, mean: float | None) -> None:
    """The mean torque (the diagram's, or given with its loops) and the mean power T_mean ω_mean."""
    results.put("torque_mean", torque_mean, " (given)" if given else ", W/Θ")
    if mean is None:
        notes.append("power_mean needs the mean speed ω (a rim's speed alone does not give it): give --rim-radius or --omega-mean")
        return
    power = torque_mean * mean
    results.put("power_mean", power)
    steps.append(Step("Mean power", "P = T_mean ω_mean", f"{quantity_text(torque_mean, 'N*m')} × {quantity_text(mean, 'rad/s')}", quantity_text(power, "W"),
                      "the work per cycle over the time of a cycle: T_mean Θ / (Θ/ω_mean)"))


def _rim_section(mass: float, rim_radius: float, density: float, **speed_options: float | None) -> Report:
    """A rim's cross-section from its mass, mean radius and density, with no speed (#42 item 16):
    A = m/(2πRρ), the rim's volume 2πR·A times ρ its mass."""
    for name, value in speed_options.items():
        if value is not None:
            raise InputError(name, "needs the flywheel's speed: {omega_mean} (or {omega_max} and {omega_min}, or {rim_speed})", example=_EXAMPLE)
    area = mass / (2 * math.pi * rim_radius * density)
    results = Results(TABLE)
    results.put("mass", mass, " (given)")
    results.put("rim_area", area)
    step = Step("Cross-section of the rim", "A = m/(2πRρ)", f"{quantity_text(mass, 'kg')} / (2π × {quantity_text(rim_radius, 'm')} × {quantity_text(density, 'kg/m**3')})",
                quantity_text(area, "m**2"), "the rim's mass is its volume 2πR·A times ρ")
    return Report("flywheel", "a thin rim: its section from its mass, mean radius and density (no speed given)", "closed form", results, [step], [])


def _speed_text(rim_only: bool, rim_speed: float | None, mean: float | None) -> str:
    return quantity_text(rim_speed, "m/s") if rim_only else quantity_text(mean, "rad/s")


def _speeds(omega_mean, omega_max, omega_min, rim_speed, rim_radius, fluctuation, speed_variation, steps) -> tuple[float | None, float | None]:
    """The mean speed (None where a rim's speed stands alone) and Cs where the speeds give it."""
    if (omega_max is None) != (omega_min is None):
        raise InputError("omega_min" if omega_min is None else "omega_max", "goes with {omega_max}/{omega_min}: the band needs both ends", example="{omega_max} 303rpm {omega_min} 297rpm")
    given = [name for name, value in (("omega_mean", omega_mean), ("omega_max", omega_max), ("rim_speed", rim_speed)) if value is not None]
    if len(given) > 1:
        raise InputError(given[1], f"conflicts with {{{given[0]}}}: give the mean speed one way (the band's mean is its ends' average)", example=_EXAMPLE)
    if not given:
        raise InputError("omega_mean", "is required (or {omega_max} and {omega_min}, or {rim_speed})", example=_EXAMPLE)
    if fluctuation is not None and speed_variation is not None:
        raise InputError("speed_variation", "conflicts with {fluctuation}: ±x of the mean is Cs = 2x; give one")
    cs = fluctuation if fluctuation is not None else (2 * speed_variation if speed_variation is not None else None)
    if speed_variation is not None:
        steps.append(Step("Coefficient of fluctuation from the ± swing", "Cs = 2 × (±x)", f"2 × {fmt(speed_variation)}", fmt(cs),
                          "the speed goes from ω_mean(1 − x) to ω_mean(1 + x): their difference over the mean is 2x"))
    if omega_max is not None:
        if cs is not None:
            raise InputError("fluctuation" if fluctuation is not None else "speed_variation", "conflicts with the band {omega_max} and {omega_min}, which gives Cs")
        return _band(omega_max, omega_min, "omega", "rad/s", "ω", "the mean of the two ends, and the band's width over it", steps)
    if cs is not None and not 0 < cs < 2:
        raise InputError("fluctuation" if fluctuation is not None else "speed_variation", "expected Cs between 0 and 2 (ω_min = ω_mean(1 − Cs/2) ≥ 0), e.g. 0.02",
                         got=fmt(cs))
    if rim_speed is not None:
        if rim_radius is None:
            return None, cs
        mean = rim_speed / rim_radius
        steps.append(Step("Mean speed from the rim's", "ω_mean = v/R", f"{quantity_text(rim_speed, 'm/s')} / {quantity_text(rim_radius, 'm')}",
                          quantity_text(mean, "rad/s"), "the rim moves at ω R"))
        return mean, cs
    return omega_mean, cs


def _rim_band(top: float, bottom: float, rim_speed, fluctuation, speed_variation, steps) -> tuple[float, float]:
    """The mean rim speed and Cs from the rim's band: v_mean = (v_max + v_min)/2, Cs = (v_max − v_min)/v_mean."""
    for name, value in (("rim_speed", rim_speed), ("fluctuation", fluctuation), ("speed_variation", speed_variation)):
        if value is not None:
            raise InputError(name, "conflicts with the band {rim_speed_max} and {rim_speed_min}, which gives the mean rim speed and Cs")
    return _band(top, bottom, "rim_speed", "m/s", "v", "the rim's speed is ωR, so its band has the same Cs as the shaft's", steps)


def _band(top: float, bottom: float, name: str, unit: str, symbol: str, why: str, steps) -> tuple[float, float]:
    """The mean and Cs of a speed band (the shaft's, --omega-max/--omega-min, or the rim's): the mean
    of its ends, and its width over the mean; refused where the top is not above the bottom."""
    if top <= bottom:
        example = "{omega_max} 303rpm {omega_min} 297rpm" if name == "omega" else "{rim_speed_max} 30m/s {rim_speed_min} 29m/s"
        raise InputError(f"{name}_max", f"must be above {{{name}_min}}", example=example)
    mean = (top + bottom) / 2
    cs = (top - bottom) / mean
    title = "Mean speed and coefficient of fluctuation" if name == "omega" else "Mean rim speed and coefficient of fluctuation"
    steps.append(Step(title, f"{symbol}_mean = ({symbol}_max + {symbol}_min)/2,  Cs = ({symbol}_max − {symbol}_min)/{symbol}_mean",
                      f"({quantity_text(top, unit)} + {quantity_text(bottom, unit)})/2", f"{quantity_text(mean, unit)}, Cs = {fmt(cs)}", why))
    return mean, cs


def _swing(energy_swing, energy_per_cycle, punch_fraction, steps) -> float | None:
    """ΔE given, or left by a punch: the motor gives E evenly, so during the share f it gives Ef and the flywheel E(1 − f)."""
    if energy_per_cycle is None:
        if punch_fraction is not None:
            raise InputError("punch_fraction", "goes with {energy_per_cycle}", example="{energy_per_cycle} 26.7kJ {punch_fraction} 0.16")
        return energy_swing
    if energy_swing is not None:
        raise InputError("energy_per_cycle", "conflicts with {energy_swing}: the punch's energy gives ΔE")
    share = punch_fraction or 0.0
    if not 0 <= share < 1:
        raise InputError("punch_fraction", "expected a share of the cycle from 0 to below 1", example="{punch_fraction} 0.16", got=fmt(share))
    swing = energy_per_cycle * (1 - share)
    steps.append(Step("Energy the flywheel gives during the punch", "ΔE = E − E·f = E(1 − f)", f"{quantity_text(energy_per_cycle, 'J')} × (1 − {fmt(share)})",
                      quantity_text(swing, "J"),
                      "the motor supplies E evenly over the cycle, so while the punch works (a share f of the cycle) it gives only Ef; "
                      "the flywheel gives the rest, slowing from its top speed to its least"))
    return swing


def _rim_stress(results, steps, notes, rim_mass, rim_radius, speed, cs, density, allowable) -> None:
    """The hoop stress ρv² in a thin rim at the mean and top speeds, its section m/(2πRρ), the margin."""
    if density is None:
        if allowable is not None:
            raise InputError("allowable_stress", "goes with {density}: the hoop stress is ρv²", example="{density} 7200kg/m^3 {allowable_stress} 6MPa")
        return
    if speed is None:
        raise InputError("density", "needs the rim's speed: {rim_radius} (with the mean speed) or {rim_speed}", example="{rim_radius} 0.6m {density} 7200kg/m^3")
    top = speed * (1 + cs / 2)
    stress, stress_max = density * speed**2, density * top**2
    results.put("hoop_stress", stress)
    results.put("hoop_stress_max", stress_max)
    steps.append(Step("Hoop stress in the rim", "σ = ρv²", f"{quantity_text(density, 'kg/m**3')} × ({quantity_text(speed, 'm/s')})²", quantity_text(stress, "Pa"),
                      "each element of a thin rim needs a centripetal force ρAv²/R, which the tension σA around the ring gives: σ = ρv², "
                      "whatever the section; at the top speed it is (1 + Cs/2)² as much"))
    if rim_mass is not None and rim_radius is not None:
        area = rim_mass / (2 * math.pi * rim_radius * density)
        results.put("rim_area", area)
        steps.append(Step("Cross-section of the rim", "A = m/(2πRρ)", f"{quantity_text(rim_mass, 'kg')} / (2π × {quantity_text(rim_radius, 'm')} × {quantity_text(density, 'kg/m**3')})",
                          quantity_text(area, "m**2"), "the rim's mass is its volume 2πR·A times ρ"))
    if allowable is not None:
        margin = allowable / stress_max
        results.put("stress_margin", margin)
        if margin < 1:
            notes.append(f"stress_margin {fmt(margin)}: the rim's hoop stress at the top speed is above the allowable stress; it would burst first")
