"""The fuzz suite's grammar for the commands that are not scenes (#43): fit with the CSV files it
reads, bench, completions, convert, and taucli with no command.

fit's vectors start from docs/fit.md's own runs (their tables as the page shows them with
`$ cat FILE`), with their tables and options changed, or from tables of any shape made here:
headers with and without units (right, wrong, unclosed), the separators a spreadsheet writes,
quoted cells with a separator inside, blank and missing cells, extra cells, huge, tiny and
non-numbers, decimal commas, a byte-order mark, CRLF, Latin-1 and UTF-16 bytes, NUL bytes, an
empty file, a header alone; the table on stdin (``-``) as often as in a file. Each is judged by
tests/fuzzing.py's contract. A fit's time limit is lowered (FIT_LIMIT) so that a vector that would
run long is refused by fit's own budget, and the run is judged against FIT_SECONDS.
"""

from __future__ import annotations

import hashlib
import re
import shlex
from pathlib import Path

from hypothesis import strategies as st

from fuzzing import SCENES, UNITS, WRONG_UNITS, Vector, command_options, numbers, option_value, quantity_texts, sane_value

ROOT = Path(__file__).resolve().parent.parent
FIT_LIMIT = 1.5  # seconds: fit's budget in the fuzz (60 s on the command line)
FIT_SECONDS = 6.0  # the longest a fit vector may take: the budget, its one solve past it, numpy and scipy's imports
BENCH_SECONDS = 3.0
COMMANDS = ("fit", "bench", "completions", "convert", "")  # "": taucli with no command


def docs_runs() -> tuple[dict[str, str], list[list[str]]]:
    """docs/fit.md's tables ({name: text}, as `$ cat NAME` shows them) and its fit runs (argv after "taucli")."""
    text = (ROOT / "docs" / "fit.md").read_text(encoding="utf-8")
    tables: dict[str, str] = {}
    runs: list[list[str]] = []
    for block in re.findall(r"```console\n(.*?)```", text, flags=re.S):
        for entry in re.split(r"^\$ ", block, flags=re.M)[1:]:
            command, _, printed = entry.partition("\n")
            if command.startswith("cat ") and " " not in command[4:]:
                tables[command[4:]] = printed
            elif command.startswith("taucli fit ") and not re.search(r"[|<>]", command):
                runs.append(shlex.split(command)[1:])
    return tables, runs


def write_docs_tables(folder: Path) -> list[list[str]]:
    """docs/fit.md's tables written into ``folder`` (with docs/ linked, for docs/data/…); its runs."""
    tables, runs = docs_runs()
    for name, table in tables.items():
        (folder / name).write_text(table, encoding="utf-8")
    if not (folder / "docs").exists():
        (folder / "docs").symlink_to(ROOT / "docs", target_is_directory=True)
    return [run for run in runs if all(not word.endswith(".csv") or (folder / word).exists() for word in run)]


# Headers: a time, results and inputs of the scenes with units, and columns of no use.
HEADER_NAMES = ["t", "time", "Time", "omega", "theta", "period", "a", "v", "angle", "amplitude", "mass", "length", "torque", "omega0", "u", "sigma",
                "Gyroscope z", "x", "", " ", "t_stop", "I", "inertia", "friction", "g", "distance", "T1", "ω", "θ", "\x1b[31mred", "a,b", 'q"uote']
HEADER_UNITS = ["", " (s)", " [s]", " (ms)", " (rad/s)", " [rad/s]", " (rpm)", " (deg)", " (rad)", " (m/s^2)", " (g)", " (kg)", " (m)", " (N*m)",
                " (kg·m²)", " (furlong)", " (", " [s", " ()", " (1e400 s)", " (s) (s)", " (m/s/0)", " (%)"]
CELLS_ODD = ["", " ", "nan", "NaN", "inf", "-inf", "1e308", "1e-320", "5e-324", "-0", "1e400", "1,5", "1.5.5", "abc", "0x10", "½", "１２", "1_000",
             "3 kg", "=1+1", '"', '"3"', "'3'", "1e", "\x00", "−2", "1 000", "9" * 400]
SEPARATORS = [",", ";", "\t", " ", "|", ", "]


@st.composite
def any_table(draw) -> bytes:
    """A table of any shape, as the bytes of a file."""
    columns = draw(st.integers(0, 5))
    headers = [draw(st.sampled_from(HEADER_NAMES)) + draw(st.sampled_from(HEADER_UNITS)) for _ in range(columns)]
    separator = draw(st.sampled_from(SEPARATORS))
    good = st.one_of(st.integers(0, 100).map(str), st.floats(min_value=0.001, max_value=100).map(lambda x: f"{x:.4g}"))
    cell = st.one_of(good, good, good, good, numbers, st.sampled_from(CELLS_ODD), st.text(max_size=6))
    rows = []
    for _ in range(draw(st.integers(0, 14))):
        width = columns if draw(st.integers(0, 9)) else draw(st.integers(0, columns + 2))  # now and then a row too short or too long
        rows.append([draw(cell) for _ in range(width)])
    quote = draw(st.integers(0, 5)) == 0
    lines = [separator.join(f'"{h}"' if quote else h for h in headers)] if draw(st.integers(0, 9)) else []
    lines += [separator.join(f'"{c}"' if quote and draw(st.booleans()) else c for c in row) for row in rows]
    if draw(st.integers(0, 5)) == 0:
        lines.insert(draw(st.integers(0, len(lines))), draw(st.sampled_from(["", "# comment", "#", "\f", "\u2028", "\x85", ";;;", '"a\nb"'])))
    text = draw(st.sampled_from(["\n", "\r\n", "\r"])).join(lines) + draw(st.sampled_from(["\n", "", "\n\n", "\r\n"]))
    return encoded(draw, text)


def encoded(draw, text: str) -> bytes:
    how = draw(st.sampled_from(["utf-8"] * 8 + ["bom", "bom", "utf-16", "latin-1", "nul", "junk"]))
    if how == "bom":
        return "\ufeff".encode() + text.encode("utf-8", "surrogatepass")
    if how == "utf-16":
        return text.encode("utf-16", "surrogatepass")
    if how == "latin-1":
        return text.encode("latin-1", "replace")
    if how == "nul":
        return text.encode("utf-8", "surrogatepass").replace(b"\n", b"\x00\n", 1)
    if how == "junk":
        return text.encode("utf-8", "surrogatepass") + bytes(draw(st.lists(st.integers(0, 255), max_size=20)))
    return text.encode("utf-8", "surrogatepass")


@st.composite
def changed_table(draw, text: str) -> bytes:
    """A docs table with a few of its cells, its header or its separators changed."""
    lines = text.splitlines()
    for _ in range(draw(st.integers(1, 3))):
        i = draw(st.integers(0, max(len(lines) - 1, 0)))
        if not lines:
            break
        cells = re.split(r"([,;\t])", lines[i])
        j = draw(st.integers(0, len(cells) - 1))
        if cells[j] not in (",", ";", "\t"):
            scaled = st.sampled_from([0.5, 0.9, 1.1, 2.0, 10.0, 1e3, 1e-3, -1.0, 0.0, 1e30, 1e-30]).map(lambda k, cell=cells[j]: _scaled(cell, k))
            odd = st.sampled_from(HEADER_NAMES).map(lambda n: n + " (s)") if i == 0 else numbers
            cells[j] = draw(st.one_of(scaled, scaled, scaled, st.sampled_from(CELLS_ODD), odd))
        lines[i] = "".join(cells)
        what = draw(st.integers(0, 9))
        if what == 0:
            del lines[i]
        elif what == 1:
            lines.insert(i, lines[i])
        elif what == 2:
            lines[i] = lines[i].replace(",", ";")
    return encoded(draw, draw(st.sampled_from(["\n", "\r\n"])).join(lines) + "\n")


def _scaled(cell: str, k: float) -> str:
    try:
        return repr(float(cell.replace(",", ".")) * k)
    except ValueError:
        return cell


def file_of(folder: Path, content: bytes) -> str:
    path = folder / f"t-{hashlib.sha1(content).hexdigest()[:16]}.csv"
    if not path.exists():
        path.write_bytes(content)
    return str(path)


FIT_OWN = ["--fit", "--x", "--y", "--sigma", "--range", "--every", "--no-limit", "--json", "--get", "--to", "--no-steps", "--uncertainty", "--plot", "--out"]
FIT_VALUES = {
    "--fit": ["friction", "viscous,omega0", "g", "inertia,friction,viscous,omega0", "pulley_inertia,axle_friction", "k2", "part.inertia", "radius,g", "nope",
              "friction,friction", "", ",", "mass", "time", "omega"],
    "--x": ["t (s)", "time", "amplitude=angle0", "mass=mass", "Time (s)", "x=nope", "=", "t=", "angle (deg)", "nope"],
    "--y": ["omega (rad/s)", "period", "Gyroscope z (rad/s)=omega", "t=t", "x=", "=omega", "nope=omega", "theta"],
    "--sigma": ["0.05rad/s", "2ms", "u", "t", "omega (rad/s)", "0", "-1", "nan", "1e999", "u (rad/s)", "", "0.01"],
    "--range": ["t=2s..", "t=2s..30s", "t=..", "t=5..1", "nope=1..2", "time=0..1e999s", "t=1s", "=..", "amplitude=10deg..40deg"],
    "--every": ["1", "2", "10", "0", "-1", "1e3", "x", "99999999999999999999", ""],
}


@st.composite
def fit_vectors(draw, folder: Path, runs: list[list[str]], files: dict[str, str]) -> Vector:
    stdin = ""
    kind = draw(st.integers(0, 2))
    if kind == 0 and runs:  # a docs run, its table and a few of its values changed
        args = list(draw(st.sampled_from(runs)))
        for i in [i for i, word in enumerate(args) if word.endswith(".csv")]:
            if draw(st.integers(0, 2)) == 0:
                args[i] = file_of(folder, draw(changed_table((folder / args[i]).read_text(encoding="utf-8") if (folder / args[i]).exists() else "")))
        if draw(st.booleans()):  # mild: the run as the page gives it, answered another way (a fit that runs, so that its answer is checked)
            return Vector("fit", args[1:] + draw(st.lists(st.sampled_from(["--json", "--no-steps", "--uncertainty", "--plot"]), unique=True, max_size=2)))
        for i in draw(st.lists(st.integers(2, len(args) - 1), max_size=2)):
            if args[i - 1].startswith("--") and not args[i].startswith("--"):
                args[i] = draw(st.sampled_from(FIT_VALUES.get(args[i - 1], [])) if args[i - 1] in FIT_VALUES else quantity_texts(""))
    else:
        scene = draw(st.sampled_from([*SCENES, "spin_down", "nope", ""]))
        data = draw(any_table())
        if kind == 2:
            source, stdin = "-", data.decode("utf-8", "surrogateescape")
        else:
            source = file_of(folder, data)
        args = ["fit", scene, source]
        if draw(st.integers(0, 9)) == 0:
            args.append(draw(st.sampled_from(["/nonexistent.csv", "/dev/null", "/dev/zero", "-", source, files.get("folder", "/"), "/proc/self/status"])))
        options = command_options(scene) if scene in SCENES else []
        for flag, metavar, is_flag in draw(st.lists(st.sampled_from(options), max_size=4)) if options else []:
            if flag:
                args += [flag] if is_flag else [flag, draw(sane_value(flag, metavar, files) if draw(st.booleans()) else option_value(flag, metavar, files))]
        args += ["--fit", draw(st.sampled_from(FIT_VALUES["--fit"]))] if draw(st.integers(0, 4)) else []
    for flag in draw(st.lists(st.sampled_from(FIT_OWN), max_size=3)):
        if flag in FIT_VALUES:
            args += [flag, draw(st.sampled_from(FIT_VALUES[flag]) if draw(st.integers(0, 4)) else st.text(max_size=10))]
        elif flag in ("--get", "--to"):
            args += [flag, draw(option_value(flag, None, files))]
        elif flag == "--out":
            args += [flag, draw(option_value(flag, None, files))]
        else:
            args.append(flag)
    return Vector(args[0], args[1:], stdin)


@st.composite
def bench_vectors(draw, files: dict[str, str]) -> Vector:
    """bench's refusals: a run that would start its benchmark (seconds) is left to tests/front/test_bench.py."""
    args: list[str] = []
    for flag in draw(st.lists(st.sampled_from(["--scene", "--quick", "--out", "--json", "--nope", "spin-down", "-h"]), min_size=1, max_size=4)):
        if flag == "--scene":
            args += [flag, draw(st.one_of(st.sampled_from(["Spin-down", "spin_down", "", "fit", "atwood", "impulse,pendulum"]), st.text(max_size=10)))]
        elif flag == "--out":
            args += [flag, draw(st.sampled_from(["c.txt", "", ".svg", "/nonexistent/dir/c.svg", "/proc/c.svg"]))]
        else:
            args.append(flag)
    if "--scene" not in args and "--nope" not in args and "spin-down" not in args and "-h" not in args:
        args += ["--scene", "nope"]  # (else the benchmark itself would run)
    return Vector("bench", args)


@st.composite
def completions_vectors(draw) -> Vector:
    shells = st.one_of(st.sampled_from(["bash", "zsh", "fish", "Bash", "powershell", "", "-", "--json"]), st.text(max_size=8))
    return Vector("completions", draw(st.lists(shells, max_size=3)))


@st.composite
def convert_vectors(draw) -> Vector:
    """QUANTITY [UNIT]: a quantity of any kind (the grammar of the scenes' values), a unit right,
    wrong or odd, and --json or --get."""
    metavar = draw(st.sampled_from(sorted(UNITS)))
    args = [draw(quantity_texts(metavar))] if draw(st.integers(0, 9)) else []
    if draw(st.integers(0, 3)):
        args.append(draw(st.one_of(st.sampled_from(sum(UNITS.values(), []) + WRONG_UNITS), st.text(max_size=8))))
    if draw(st.integers(0, 5)) == 0:
        args.insert(0, "--")
    for flag in draw(st.lists(st.sampled_from(["--json", "--get", "--to", "--nope"]), max_size=2)):
        args += [flag, draw(st.sampled_from(["value", "uncertainty", "unit", "kind", "si_value", "si_uncertainty", "si_unit", "nope", ""]))] if flag == "--get" else [flag]
    return Vector("convert", args)


@st.composite
def top_vectors(draw) -> Vector:
    words = st.one_of(st.sampled_from(["--version", "--debug", "-h", "--help", "nope", "Atwood", "spin_down", "fit", "--json", "-", "--", ""]),
                      st.text(max_size=10))
    return Vector("", draw(st.lists(words, max_size=3)))


def vectors_of(command: str, folder: Path, runs: list[list[str]], files: dict[str, str]) -> st.SearchStrategy[Vector]:
    if command == "fit":
        return fit_vectors(folder, runs, files)
    if command == "bench":
        return bench_vectors(files)
    if command == "completions":
        return completions_vectors()
    if command == "convert":
        return convert_vectors()
    return top_vectors()
