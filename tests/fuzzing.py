"""The fuzz suite's grammar of hostile command lines, and the harness that runs one (issue #9).

A vector is a scene, its arguments and what stdin holds. Option values come from a grammar of
numbers (huge, tiny, signed, odd spellings), units (right, wrong, look-alike), operators and
typography (· × − µ ² °), ranges and lists, empty and very long text, and random unicode; options
are repeated and combined with conflicting output options. Options come from the Typer app
itself, so a new option is fuzzed without a change here.

``run`` calls ``taucli.__main__.main``, the console script's entry point, in this process (a
subprocess per vector would take hours for 50,000 of them), with stdin, stdout and stderr as
text buffers that are not terminals, and checks the contract: exit 0 or 2 only, no traceback,
one line on stderr for an error, no run over a second, strict JSON with finite numbers after
``--json``/``--jsonl``, no NaN or infinity after ``--get``, no ANSI codes anywhere.
"""

from __future__ import annotations

import contextlib
import functools
import io
import json
import math
import os
import re
import signal
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from conftest import strict_json
from hypothesis import strategies as st

SCENES = ("inertia", "spin-down", "atwood", "rolling", "impulse", "pendulum", "torque", "gyro", "drive", "flywheel", "balance")  # every scene of taucli.options (tests/front/test_fuzz.py checks)
SECONDS = 1.0  # the longest a run may take

# Units by the metavar of the option that takes them.
UNITS = {
    "MASS": ["kg", "g", "lb", "oz", "tonne", "mg", "µg"],
    "LENGTH": ["m", "cm", "mm", "km", "in", "ft", "µm", "nm"],
    "I": ["kg*m^2", "g*cm^2", "lb*ft^2", "kg·m²", "kg m**2"],
    "TORQUE": ["N*m", "mN*m", "kN*m", "lbf*ft", "N·m", "N m", "J"],
    "FORCE": ["N", "kN", "lbf", "dyn"],
    "ANGLE": ["deg", "rad", "rev", "°", "arcmin", "grad"],
    "OMEGA": ["rad/s", "rpm", "rev/s", "deg/s", "Hz", "1/s", "s^-1", "rps"],
    "TIME": ["s", "ms", "min", "h", "µs", "ns", "day", "year"],
    "SPEED": ["m/s", "km/h", "ft/s", "mph", "knot"],
    "ACCEL": ["m/s^2", "ft/s^2", "g0", "m/s²", "gal"],
    "B": ["N*m*s", "N*m/(rad/s)", "N·m·s"],
    "K": ["N*m*s^2", "N*m*s**2", "kg*m^2"],
    "NUMBER": ["", "%", "dimensionless"],
    "N": ["", "1"],
    "LEAD": ["mm", "in", "mm/rev", "in/rev", "m/rad", "rev/in"],
}
WRONG_UNITS = ["kgg", "furlong", "m/s", "kg", "s", "N", "degC", "K", "Ω", "mol", "bit", "%", "ppm", "dozen", "Hz", "c", "1/(", "m^", "**", "xyz"]
CHOICES = {  # metavar: (valid, not valid)
    "SHAPE": (["point", "ring", "disc", "tube", "sphere", "shell", "thick-shell", "rod", "plate", "box", "cone"], ["Disc", "disk", "cylinder", "hoop", "ball"]),
    "AXIS": (["central", "diameter", "center", "end", "normal", "center-width", "edge-height", "height", "width", "depth"], ["middle", ""]),
    "METHOD": (["auto", "exact", "euler", "rk4", "rk45"], ["RK4", "newton", "simpson", "trapezoid"]),
    "disc|ring": (["disc", "ring"], ["hoop", "sphere", "DISC"]),
}
RESULT_NAMES = ["I", "a", "T1", "T2", "alpha", "alpha0", "omega", "omega_inf", "t_stop", "theta_stop", "revs_stop", "v", "t",
                "distance", "friction", "rolls", "v_bottom", "L", "impulse", "torque", "duration", "omega1", "a_massless", "k2", "x", "nope", ""]
LOOK_ALIKES = ["·", "×", "−", "–", "µ", "μ", "²", "³", "⁻¹", "°", "÷", "\u00a0", "\u202f", "，", "．", "５", "٣", "e", "E", "_", "'"]
OPERATORS = ["+", "-", "*", "/", "**", "^", "(", ")", " ", "..", ",", "e", "**-", "^(", "))"]

numbers = st.one_of(
    st.integers(-10**6, 10**6).map(str),
    st.floats(allow_nan=False, allow_infinity=False).map(repr),
    st.floats(min_value=1e-3, max_value=1e3).map(lambda x: f"{x:.4g}"),
    st.sampled_from(["0", "-0", "+3", ".5", "5.", "1e308", "1e309", "1e-320", "-1e400", "1e999999", "9" * 40, "0x10", "1_000", "1,5",
                     "nan", "inf", "-inf", "NaN", "Infinity", "1e", "e5", "--2", "2..", "1/0", "0/0", "3.14.15", "²", "½"]),
)


def quantity_texts(metavar: str) -> st.SearchStrategy[str]:
    """Values for an option that takes a quantity: mostly plausible, often hostile."""
    units = UNITS.get(metavar, ["kg", "m", "s"])
    plausible = st.tuples(numbers, st.sampled_from(["", " "]), st.sampled_from(units)).map("".join)
    sane = st.tuples(st.floats(min_value=0.01, max_value=100).map(lambda x: f"{x:.3g}"), st.sampled_from(units)).map("".join)
    tokens = st.lists(st.one_of(numbers, st.sampled_from(units + WRONG_UNITS), st.sampled_from(OPERATORS), st.sampled_from(LOOK_ALIKES)), max_size=8).map("".join)
    sweep = st.one_of(
        st.tuples(sane, st.just(".."), sane).map("".join),
        st.lists(sane, min_size=2, max_size=4).map(",".join),
        st.tuples(sane, st.integers(2, 20_000)).map(lambda pair: ",".join([pair[0]] * pair[1])),  # a list as long as a command line allows
        st.tuples(numbers, st.just(".."), numbers, st.sampled_from(units)).map("".join),
    )
    hostile = st.one_of(
        st.sampled_from(["", " ", "\t", "\n", "-", "--", "..", ",", "kg", "9**9**9 kg", "2^2^2^2 m", "(" * 200 + "1" + ")" * 200, "1" * 5000,
                         "kg*" * 2000 + "kg", "10**400 kg", "1e-400 kg", "4 kg + 200 g", "4 kg - 4 kg", "4 kg * 0", "__import__('os')",
                         "exp(10000)", "1 kg / 0 m", "$(rm -rf /)", "; ls", "1\x00kg", "\x1b[31m4kg", "4 kg\r", "∞", "4 m/s / 0 s"]),
        st.text(max_size=40),
        st.text(alphabet="0123456789.eE+-*/^() kgmsNHzrpdλ·×−µ²°,", max_size=60),
    )
    return st.one_of(sane, sane, plausible, tokens, sweep, hostile)


def sane_value(option: str, metavar: str | None, files: dict[str, str]) -> st.SearchStrategy[str]:
    """A value a careful user might give: a plain positive number with a unit of the right kind."""
    if metavar in CHOICES:
        return st.sampled_from(CHOICES[metavar][0])
    if option in ("--get", "--y", "--to", "--points", "--out", "--torque-profile", "--part", "--side1", "--side2", "--pull") or (metavar or "").startswith('"mass='):
        return option_value(option, metavar, files)
    units = [unit for unit in UNITS.get(metavar, ["kg"]) if unit] or [""]
    return st.tuples(st.floats(min_value=0.01, max_value=50).map(lambda x: f"{x:.3g}"), st.sampled_from(units)).map("".join)


def option_value(option: str, metavar: str | None, files: dict[str, str]) -> st.SearchStrategy[str]:
    if metavar in CHOICES:
        return st.one_of(st.sampled_from(sum(CHOICES[metavar], [])), st.text(max_size=12))
    if option in ("--get", "--y"):
        return st.one_of(st.sampled_from(RESULT_NAMES), st.text(max_size=12))
    if option == "--to":
        to = st.tuples(st.sampled_from(RESULT_NAMES), st.sampled_from(["=", "", "=="]), st.sampled_from(sum(UNITS.values(), []) + WRONG_UNITS + ["", "9**9**9"]))
        return st.one_of(to.map("".join), st.text(max_size=20))
    if option == "--points":
        return st.one_of(st.integers(-3, 60).map(str), st.sampled_from(["10001", "1e3", "99999999999999999999", "", "5.5", "two"]))
    if option == "--out":
        return st.sampled_from(["chart.svg", "chart.png", "chart.txt", "", "/nonexistent/dir/c.svg", "/proc/c.svg", ".svg"])
    if option in ("--torque-profile",):
        return st.sampled_from(sorted(files.values()) + ["-", "/dev/null", "/nonexistent.csv", "/dev/zero", "/proc/self/status"])
    if option in ("--side1", "--side2"):  # atwood's blocks (#34)
        mu = st.tuples(st.sampled_from([" mu-k=", " mu-s=", " mu=", " mu-k = "]), numbers).map("".join)
        side = st.tuples(st.sampled_from(["hang", "table", "incline", "incline angle=30deg", "shelf", "", "angle=1rad"]),
                         st.sampled_from(["", " angle=", " angle=-"]), st.sampled_from(["", "10deg", "90deg", "2rad"]), st.lists(mu, max_size=2).map("".join))
        return st.one_of(side.map("".join), st.text(max_size=30))
    if option == "--pull":
        pull = st.tuples(st.sampled_from(["force=", "force=-", "", "angle=1 force="]), quantity_texts("FORCE"),
                         st.sampled_from(["", " angle=30deg", " angle=-89deg", " angle=120deg"]), st.sampled_from(["", " on=1", " on=2", " on=3", " on=x"]))
        return st.one_of(pull.map("".join), st.text(max_size=30))
    if metavar and metavar.startswith('"mass='):  # balance's masses
        mass = st.tuples(st.sampled_from(["mass=", "mass = ", "m=", ""]), quantity_texts("MASS"), st.sampled_from([" radius=", " length=", " radius=-", " "]),
                         quantity_texts("LENGTH"), st.sampled_from(["", " angle=", " angle=-"]), st.sampled_from(["", "45deg", "1e308deg", "2"]),
                         st.sampled_from(["", " plane=", " plane=-"]), st.sampled_from(["", "0.3m", "1e-300m", "x"])).map("".join)
        return st.one_of(mass, st.text(max_size=30))
    if option == "--part":
        part = st.tuples(st.sampled_from(sum(CHOICES["SHAPE"], [])), st.sampled_from([" mass=", " mass = ", " m="]), quantity_texts("MASS"),
                         st.sampled_from([" radius=", " offset=", " length=", " "]), quantity_texts("LENGTH")).map("".join)
        return st.one_of(part, st.text(max_size=30))
    return quantity_texts(metavar or "")


# Batch lines of shapes that once met a bug (#33): nesting past Python's recursion limit, "to" that
# is not a text, a key that is not UTF-8 (as stdin's surrogateescape reads it), a line of 1 MiB.
HOSTILE_LINES = [
    "[" * 1000 + "]" * 1000, '{"a":' * 1000 + "1" + "}" * 1000, '{"m1": "4kg", "to": true}', '{"m1": "4kg", "to": 5}',
    '{"m1": "4kg", "to": [1]}', '{"m1": "4kg", "to": {}}', '{"m\udcff1": "4kg"}', '{"m1": "' + "4" * (1 << 20) + 'kg"}',
]


@dataclass
class Vector:
    scene: str
    args: list[str]
    stdin: str = ""

    def __repr__(self) -> str:  # as a shell line, to paste into a terminal
        import shlex

        return f"taucli {shlex.join([self.scene, *self.args] if self.scene else self.args)}" + (f"  <<< {self.stdin[:200]!r}" if self.stdin else "")


@functools.lru_cache(maxsize=None)
def command_options(scene: str) -> list[tuple[str, str | None, bool]]:
    """(flag or "" for the positional, metavar, is_flag) of each option in the scene's table."""
    from taucli.options import SCENES
    from taucli.options.table import FLAG

    command = SCENES[scene]
    return [("" if o.positional else o.flag, o.shown_metavar, o.kind == FLAG) for o in (*command.options, *command.output)]


# The options a scene needs to get past "required", included more often than the rest.
CORE = {
    "inertia": ["", "--mass", "--radius"],
    "spin-down": ["--inertia", "--omega0", "--friction", "--torque"],
    "atwood": ["--m1", "--m2", "--pulley-mass", "--pulley-radius"],
    "rolling": ["", "--angle", "--mu-s", "--length"],
    "impulse": ["--inertia", "--torque", "--duration", "--omega0"],
    "pendulum": ["--shape", "--mass", "--length", "--angle0"],
    "torque": ["--r", "--force"],
    "gyro": ["--inertia", "--spin", "--mass", "--cm-distance"],
    "drive": ["--motor-inertia", "--ratio", "--load-inertia", "--until-omega"],
    "flywheel": ["--inertia", "--omega-mean", "--fluctuation", "--energy-swing"],
    "balance": ["--mass", "--mass", "--plane", "--speed"],
}


# Scenes that work (the README's), for vectors that change a few of their numbers to extremes.
BASES = {
    "inertia": ["disc --mass 5kg --radius 0.2m", "rod --mass 2kg --length 1m --axis end", "thick-shell --mass 1kg --inner-radius 1m --outer-radius 2m",
                "box --mass 1kg --width 1m --height 2m --depth 3m", "cone --mass 1kg --radius 1m --height 1m --offset 1m",
                "disc --mass 5kg --radius 0.2m --part 'point mass=100g offset=20cm'"],
    "spin-down": ["--shape disc --mass 5kg --radius 0.2m --omega0 30rad/s --friction 0.3N*m", "--inertia 2kg*m^2 --torque 1N*m --viscous 0.1N*m*s --time 4s",
                  "--inertia 1kg*m^2 --omega0 100rad/s --drag 0.01N*m*s^2 --drag-exponent 2.5 --until-omega 10rad/s",
                  "--inertia 1kg*m^2 --omega0 10rad/s --friction 1N*m --viscous 0.5N*m*s --method rk4 --dt 10ms",
                  "--shape disc --mass 8kg --radius 0.25m --force 6N --lever 0.25m --push-angle 60deg --time 4s --method rk45"],
    "atwood": ["--m1 4kg --m2 1kg --pulley-mass 2kg --pulley-radius 0.1m --g 9.8", "--m1 1kg --m2 3kg --incline 30deg --mu-k 0.2 --mu-s 0.3 --distance 1m",
               "--m1 2kg --m2 2kg --axle-friction 0.5N*m --pulley-radius 0.1m --v0 1m/s --time 2s", "--m1 1kg --pulley-inertia 0.01kg*m^2 --pulley-radius 0.05m --pulley-shape ring",
               "--m1 6kg --side1 'incline angle=30deg mu-k=0.36' --m2 2kg --side2 'table mu-k=0.36' --pulley-mass 10kg --pulley-radius 0.25m --v0 -1m/s --time 2s",
               "--pull 'force=15N' --pull 'force=5N on=2' --pulley-radius 33cm --axle-friction 1.1N*m --pulley-inertia 0.385kg*m^2 --v0 -2m/s --distance 1m",
               "--m1 4t --pulley-radius 0.75m --torque 40kN*m --axle-friction 3kN*m --pulley-mass 750kg --v0 -6m/s --at rim",
               "--m1 2kg --m2 3kg --radius1 0.1m --radius2 0.2m --part 'disc mass=1kg radius=0.1m' --same-side --time 1s"],
    "rolling": ["sphere --angle 30deg --length 2m --mass 1kg --radius 0.1m", "disc --angle 40deg --mu-s 0.2 --mu-k 0.15", "sphere --v0 7m/s --mu-k 0.2",
                "ring --angle 10deg --height 1m --v0 1m/s", "--k2 0.3 --angle 20deg --mu-s 0.1 --length 3m --omega0 5rad/s --radius 0.1m"],
    "impulse": ["--inertia 0.1kg*m^2 --omega0 0 --torque 2N*m --duration 0.5s", "--inertia 4kg*m^2 --inertia-final 1.5kg*m^2 --omega0 1rev/s --to omega1=rev/s",
                "--inertia 0.01kg*m^2 --torque-profile {good} --method simpson", "--shape rod --mass 1kg --length 1m --omega0 10rpm --omega1 60rpm --duration 2s"],
    "pendulum": ["--shape rod --length 1m --mass 2kg --axis end --angle0 90deg --angle 0deg", "--shape point --radius 1m --mass 1kg --angle0 179deg",
                 "--inertia 0.02kg*m^2 --torsion 0.5N*m/rad --cm-distance 0 --mass 1kg --angle0 30deg --time 1s --method verlet --dt 1ms"],
    "torque": ["--r '0.3,0.4,0 m' --force '0,0,10 N'", "--force 80N --lever 0.25m --angle 60deg", "--r '0,0.8,0 m' --mass 0.5kg --velocity '3,0,0 m/s'"],
    "gyro": ["--shape disc --mass 0.3kg --radius 5cm --spin 4000rpm --cm-distance 5cm --tilt 30deg",
             "--inertia 8.0e37kg*m^2 --spin 7.29e-5rad/s --torque 1.79e22N*m --tilt 23.44deg",
             "--inertia 36kg*m^2 --spin 2400rpm --precession 1.1rad/s --spin-sense cw-from-rear --turn left --craft aircraft --bearing-span 1m"],
    "drive": ["--motor-inertia 1.2kg*cm^2 --ratio 10 --load-inertia 0.05kg*m^2 --until-omega 3000rpm --in-time 0.2s",
              "--load-mass 250kg --lead 10mm --ratio 2 --efficiency 0.9 --mu 0.2 --motor-inertia 0.3e-4kg*m^2 --speed 15m/min --accel-time 0.1s --run-time 1s --dwell-time 0.3s --rated-torque 0.637N*m",
              "--motor-inertia 1.2kg*cm^2 --ratio 10 --efficiency 0.9 --load-inertia 0.05kg*m^2 --load-torque -5N*m --stall-torque 2N*m --no-load-speed 3000rpm --until-omega 3500rpm",
              "--load-mass 20kg --drum-radius 5cm --incline 90deg --motor-inertia 1e-4kg*m^2 --ratio 5 --distance 0.5m --speed 1m/s --accel 5m/s^2 --dwell-time 1s",
              "--motor-inertia 2.5lb*in^2 --load-inertia 4.5lb*in^2 --load-mass 5lb --drum-radius 1.5in --motor-torque 100ozf*in --speed 15ft/s"],
    "flywheel": ["--omega-mean 300rpm --fluctuation 0.02 --energy-swing 5kJ --rim-radius 0.6m --density 7200kg/m^3 --allowable-stress 6MPa",
                 "--energy-per-cycle 26741J --punch-fraction 0.16 --rim-speed 25m/s --fluctuation 0.03",
                 "--shape ring --mass 6.5t --radius 1.8m --energy-swing 56kJ --omega-mean 120rpm",
                 "--inertia 250kg*m^2 --omega-max 303rpm --omega-min 297rpm --rim-radius 0.6m --density 7200kg/m^3"],
    "balance": ["--mass 'mass=200kg radius=0.2m angle=0deg' --mass 'mass=300kg radius=0.15m angle=45deg' --balance-radius 0.2m",
                "--mass 'mass=2kg radius=80mm angle=0deg plane=0mm' --mass 'mass=3kg radius=70mm angle=45deg plane=300mm' --plane 100mm --plane 500mm "
                "--balance-radius 100mm --speed 300rpm --bearing 0m --bearing 0.7m",
                "--mass 'mass=1.4kg length=100cm' --bearing -27.5cm --bearing 27.5cm --vertical --speed 6rad/s --g 9.8"],
}
extreme_numbers = st.one_of(
    st.sampled_from(["0", "-0", "-1", "1e-320", "5e-324", "1e-300", "1e-30", "1e-9", "1e9", "1e30", "1e300", "1.7e308", "-1e308", "1e-16", "0.9999999999999999", "1.0000000000000002"]),
    st.floats(min_value=-1e308, max_value=1e308, allow_nan=False).map(repr),
    st.integers(-12, 12).map(lambda e: f"{10.0 ** e:g}"),
)


@st.composite
def near_base(draw, scene: str, files: dict[str, str]) -> list[str]:
    """A working scene with a few of its numbers made extreme, and an output option or two."""
    import re
    import shlex

    args = shlex.split(draw(st.sampled_from(BASES[scene])).format(**files))
    numeric = [i for i, word in enumerate(args) if re.match(r"-?\d", word) and i > 0 and args[i - 1].startswith("--")]
    for i in draw(st.lists(st.sampled_from(numeric), max_size=3, unique=True)) if numeric else []:
        unit = re.sub(r"^-?[\d.e+-]*", "", args[i])
        args[i] = draw(extreme_numbers) + unit
    args += draw(st.lists(st.sampled_from(["--json", "--no-steps", "--plot", "--jsonl", "--get", "--to"]), max_size=2, unique=True))
    for i, word in enumerate(args):
        if word in ("--get", "--to") and (i + 1 == len(args) or args[i + 1].startswith("--")):
            args.insert(i + 1, draw(option_value(word, None, files)))
    return args


@st.composite
def vectors(draw, scene: str, files: dict[str, str]) -> Vector:
    if draw(st.integers(0, 2)) == 0:
        return Vector(scene, draw(near_base(scene, files)))
    options = command_options(scene)
    core = [o for o in options if o[0] in CORE[scene]]
    rest = [o for o in options if o[0] not in CORE[scene]]
    chosen = [o for o in core if draw(st.integers(0, 9)) < 8]
    chosen += draw(st.lists(st.sampled_from(rest), max_size=6))
    if draw(st.integers(0, 9)) == 0:  # the same option again, maybe with another value
        chosen += draw(st.lists(st.sampled_from(options), min_size=1, max_size=3))
    args: list[str] = []
    careful = draw(st.booleans())  # half the vectors mostly sane, so that they reach the solvers
    for flag, metavar, is_flag in draw(st.permutations(chosen)):
        values = sane_value if careful and draw(st.integers(0, 9)) else option_value
        if is_flag:
            args.append(flag)
        elif flag == "":
            args.append(draw(values("", metavar, files)))
        else:
            value = draw(values(flag, metavar, files))
            args += [f"{flag}={value}"] if draw(st.integers(0, 9)) == 0 else [flag, value]
    stdin = ""
    if "--batch" in args or "-" in args:
        line = st.dictionaries(st.sampled_from([o[0].lstrip("-").replace("-", "_") or "shape" for o in options]), st.one_of(quantity_texts("MASS"), st.floats(), st.integers(), st.none(), st.booleans()), max_size=5)
        stdin = "\n".join(draw(st.lists(st.one_of(line.map(json.dumps), st.text(max_size=30), st.sampled_from(HOSTILE_LINES)), max_size=5)))
    return Vector(scene, args, stdin)


def profile_files(folder: Path) -> dict[str, str]:
    """Torque profiles to name in --torque-profile: good, odd and bad."""
    files = {
        "good": "t [s], torque [N*m]\n0, 1\n0.5, 2\n1, 1\n",
        "bare": "t,torque\n0,1\n1,1\n",
        "unsorted": "t [s], torque [N*m]\n1, 1\n0, 1\n",
        "nan": "t [s], torque [N*m]\n0, nan\n1, 1\n",
        "huge": "t [s], torque [N*m]\n0, 1e308\n1, 1e308\n2, -1e308\n",
        "long_line": "t [s], torque [N*m]\n" + "1" * 100_000 + ", 1\n",
        "binary": "\x00\x01\x02\xff",
        "tiny_steps": "t [s], torque [N*m]\n0, 1\n1e-200, 2\n2e-200, 3\n",  # (#33) Simpson's weights underflowed to a zero divisor
        "empty": "",
    }
    paths = {}
    for name, text in files.items():
        path = folder / f"{name}.csv"
        path.write_text(text, encoding="utf-8", errors="surrogateescape")
        paths[name] = str(path)
    (folder / "a_folder.csv").mkdir(exist_ok=True)
    paths["folder"] = str(folder / "a_folder.csv")
    return paths


@dataclass
class Outcome:
    status: int
    out: str
    err: str
    seconds: float
    problems: list[str] = field(default_factory=list)


class TookTooLong(BaseException):
    """Raised by the alarm in a run that has gone on far past the limit (a hang)."""


def _alarm(signum, frame):
    raise TookTooLong()


def _numbers(node):
    if isinstance(node, dict):
        for value in node.values():
            yield from _numbers(value)
    elif isinstance(node, list):
        for value in node:
            yield from _numbers(value)
    elif isinstance(node, float):
        yield node


def run(vector: Vector, workdir: str, seconds: float = SECONDS) -> Outcome:
    """Run the vector through taucli's entry point in this process; list what breaks the contract.

    A run over the time limit is run once more and judged by the faster of the two: taucli's work
    for a vector is the same each time, so a hang repeats, while a stall of the machine (another
    process, the disk) seldom does.
    """
    outcome = _run_once(vector, workdir, seconds)
    if outcome.seconds > seconds and outcome.status != -1:
        again = _run_once(vector, workdir, seconds)
        if again.seconds < outcome.seconds:
            outcome = again
    _judge(vector, outcome, seconds)
    return outcome


# Warnings a user's stderr would show (Python's default filters hide these categories alone).
_HIDDEN = (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning)


def _run_once(vector: Vector, workdir: str, seconds: float = SECONDS) -> Outcome:
    import warnings

    from taucli.__main__ import main

    stdin, stdout, stderr = io.StringIO(vector.stdin), io.StringIO(), io.StringIO()
    saved = sys.argv, sys.stdin, os.getcwd()
    signal.signal(signal.SIGALRM, _alarm)
    hang = max(20 * SECONDS, 4 * seconds)
    signal.setitimer(signal.ITIMER_REAL, hang)
    start = time.perf_counter()
    try:
        sys.argv, sys.stdin = ["taucli", *([vector.scene] if vector.scene else []), *vector.args], stdin
        os.chdir(workdir)
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr), warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")  # (pytest records warnings itself: a warning that would reach a user's stderr is caught here)
            try:
                status = main()
            except SystemExit as err:  # main returns its status; an exit from inside is a finding
                status = f"SystemExit({err.code!r})"
            except TookTooLong:
                status = f"hung: stopped after {hang:.0f} s"
            except BaseException as err:  # noqa: BLE001 - anything escaping main is a finding
                import traceback

                status = f"escaped: {type(err).__name__}: {err}"
                stderr.write(traceback.format_exc())
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        sys.argv, sys.stdin = saved[0], saved[1]
        os.chdir(saved[2])
    outcome = Outcome(status if isinstance(status, int) else -1, stdout.getvalue(), stderr.getvalue(), time.perf_counter() - start)
    if not isinstance(status, int):
        outcome.problems.append(f"status {status}")
    shown = sorted({f"{w.category.__name__}: {w.message} ({Path(w.filename).name}:{w.lineno})" for w in caught if not issubclass(w.category, _HIDDEN)})
    if shown:
        outcome.problems.append(f"warnings on stderr: {shown[:3]}")
    return outcome


def _asks_for_help(vector: Vector, outcome: Outcome) -> bool:
    """-h or --help, or no command at all (taucli alone prints its help on stderr, exit 2: taucli.front.help),
    or --version before any command: the help or the version is the answer, whatever else the line holds."""
    words = [vector.scene, *vector.args] if vector.scene else vector.args
    no_command = all(word.startswith("-") for word in words)
    if no_command and "--version" in words and re.fullmatch(r"taucli \S+\n", outcome.out):  # --version is answered before anything else
        return True
    shown = (outcome.out or outcome.err).startswith("Usage: taucli")
    return shown and (any(word in ("-h", "--help") for word in words) or no_command)


def _judge(vector: Vector, outcome: Outcome, seconds: float = SECONDS) -> None:
    problems = outcome.problems
    if _asks_for_help(vector, outcome):
        if outcome.status not in (0, 2) or "Traceback" in outcome.out + outcome.err:
            problems.append(f"help with exit {outcome.status}")
        return
    if outcome.status not in (-1, 0, 2):  # -1: main did not return, already listed
        problems.append(f"exit {outcome.status}: {outcome.err.strip()[:300]}")
    if outcome.seconds > seconds:
        problems.append(f"took {outcome.seconds:.2f} s")
    if "Traceback" in outcome.err or "Traceback" in outcome.out:
        problems.append("a traceback")
    if "\x1b[" in outcome.out or "\x1b[" in outcome.err:
        problems.append("ANSI codes in a pipe")
    if outcome.status == 2 and "--batch" not in vector.args and outcome.out:
        problems.append(f"exit 2 after printing an answer: {outcome.out[:100]!r}")
    if outcome.status == 2:
        lines = outcome.err.strip().splitlines()
        if "--batch" not in vector.args and (len(lines) != 1 or not lines[0].startswith("taucli: error: ")):
            problems.append(f"not one error line: {outcome.err[:300]!r}")
    if outcome.status == 0:
        problems += _output_problems(vector, outcome.out)


def _output_problems(vector: Vector, out: str) -> list[str]:
    args = vector.args
    structured = "--batch" in args or "--jsonl" in args or (any(a.startswith("--json") for a in args) and not any(a.startswith("--get") for a in args))
    if not structured:
        if any(a.startswith("--get") for a in args):
            bad = [word for word in out.split() if word.lower().lstrip("-+") in ("nan", "inf", "infinity")]
            return [f"--get printed {bad}"] if bad else []
        return []
    try:
        documents = [strict_json(line) for line in out.splitlines()] if ("--batch" in args or "--jsonl" in args) else [strict_json(out)]
    except ValueError as err:
        return [f"not strict JSON: {err}: {out[:200]!r}"]
    if "--batch" in args and len(documents) != len(vector.stdin.splitlines()):
        return [f"{len(vector.stdin.splitlines())} lines in, {len(documents)} out"]
    if not documents and "--batch" not in args:
        return ["no JSON at all"]
    if any(not math.isfinite(x) for doc in documents for x in _numbers(doc)):
        return ["a number that is not finite"]
    return []


def scratch_folder() -> tempfile.TemporaryDirectory:
    return tempfile.TemporaryDirectory(prefix="taucli-fuzz-")
