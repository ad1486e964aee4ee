"""--format latex: a run or a sweep as LaTeX, the steps as an ``align*`` with units set by siunitx.

The solvers write their steps in Unicode (ω₀², ½MR², τ_rms, θ̇); here each is turned into LaTeX
math ({\\omega}_{0}^{2}, \\tfrac{1}{2}MR^{2}), each "number unit" of a numbers line into
``\\qty{5}{kg.m^{2}}``, and every text (a title, a label, a part's name, a note) is escaped for
text mode. The fragment needs amsmath and siunitx (version 3: ``\\qty``, ``\\unit``), and compiles
with pdflatex (utf8 input, T1 fonts, as LaTeX has by default since 2018) and lualatex.
"""

from __future__ import annotations

import re
import unicodedata

from taucli.writing.formats import Grid, Sheet, grid_cells, heading, shown, step_lines
from taucli.core.version import __version__
from taucli.core.written import printable

PREAMBLE = "% needs \\usepackage{amsmath} and \\usepackage{siunitx} (version 3)"

GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "varepsilon", "ζ": "zeta", "η": "eta", "θ": "theta",
    "ι": "iota", "κ": "kappa", "λ": "lambda", "μ": "mu", "µ": "mu", "ν": "nu", "ξ": "xi", "π": "pi", "ρ": "rho",
    "σ": "sigma", "τ": "tau", "υ": "upsilon", "φ": "varphi", "χ": "chi", "ψ": "psi", "ω": "omega",
    "Γ": "Gamma", "Δ": "Delta", "Θ": "Theta", "Λ": "Lambda", "Ξ": "Xi", "Π": "Pi", "Σ": "Sigma", "Φ": "Phi",
    "Ψ": "Psi", "Ω": "Omega",
}  # fmt: skip
SYMBOLS = {
    "−": "-", "–": "-", "—": "-", "×": "\\times ", "·": "\\cdot ", "⋅": "\\cdot ", "∙": "\\cdot ", "÷": "\\div ",
    "±": "\\pm ", "∓": "\\mp ", "√": "\\surd ", "°": "^{\\circ}", "≈": "\\approx ", "≠": "\\neq ", "≤": "\\leq ",
    "≥": "\\geq ", "≪": "\\ll ", "≫": "\\gg ", "⊂": "\\subset ", "⊥": "\\perp ", "⋯": "\\cdots ", "…": "\\ldots ",
    "∞": "\\infty ", "∫": "\\int ", "∂": "\\partial ", "∈": "\\in ", "∩": "\\cap ", "→": "\\to ", "⇒": "\\Rightarrow ",
    "′": "'", "ℓ": "\\ell ", "•": "\\bullet ", "│": "|", "“": "``", "”": "''",
    "½": "\\tfrac{1}{2}", "¼": "\\tfrac{1}{4}", "¾": "\\tfrac{3}{4}", "⅓": "\\tfrac{1}{3}", "⅔": "\\tfrac{2}{3}",
    "⅖": "\\tfrac{2}{5}", "ŷ": "\\hat{y}", "ẑ": "\\hat{z}", "x̂": "\\hat{x}",
}  # fmt: skip
SUBSCRIPTS = dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋ᵢₐₓₖₙₜ", "0123456789+-iaxknt"))
SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁻ⁿᵇ", "0123456789-nb"))
ACCENTS = {"\u0307": "dot", "\u0304": "bar", "\u0302": "hat"}
FUNCTIONS = frozenset({"sin", "cos", "tan", "ln", "exp", "log", "sinh", "cosh", "tanh", "arcsin", "arccos", "arctan", "max", "min"})
MATH_ESCAPES = {"#": "\\#", "$": "\\$", "%": "\\%", "&": "\\&", "~": "\\sim ", "\\": "\\backslash ", "{": "\\{", "}": "\\}"}
TEXT_ESCAPES = {
    "\\": "\\textbackslash{}", "{": "\\{", "}": "\\}", "#": "\\#", "$": "\\$", "%": "\\%", "&": "\\&", "_": "\\_",
    "~": "\\textasciitilde{}", "^": "\\textasciicircum{}", "<": "\\textless{}", ">": "\\textgreater{}", "|": "\\textbar{}",
    "–": "--", "—": "---", "“": "``", "”": "''", "…": "\\ldots{}", "′": "'", "\n": " ",
    "-": "-{}", "`": "\\textasciigrave{}",  # no ligature: --g stays two hyphens, !` no ¡
}  # fmt: skip
_LATIN = re.compile(r"[\u00c0-\u00d6\u00d8-\u00f6\u00f8-\u00ff]")  # letters utf8 input with T1 fonts sets in text


def _plain(char: str) -> str:
    """A character no table names, as ASCII where it decomposes to it (ǎ -> a), else '?'."""
    ascii_text = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode()
    return ascii_text or "?"


def _math_char(char: str) -> str | None:
    if char in GREEK:
        return "{\\" + GREEK[char] + "}"
    return SYMBOLS.get(char)


# Words a step writes between its symbols ("the root of f(m2) − 0.2 in [100, 177] kg"): set as
# text, never as a product of letters, and "in" never as inches.
WORDS = frozenset({"in", "of", "the", "and", "or", "for", "if"})
# A name written with two underscores or more (rim_mu_min, rms_to_rated): a name, set as text
# (r_{mu}_{min} would be a subscript of a subscript, which TeX refuses).
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+){2,}(?![A-Za-z0-9])")


def _script(atoms: list[str], mark: str, body: str) -> None:
    """A subscript or superscript ``mark{body}`` after the atoms, never a second one of the same
    kind on one base (TeX's "Double subscript"): ω_s then ᵢ is ω_{s,i}; a superscript after a
    superscript, or a subscript after x_0^2, starts on an empty base ({})."""
    scripts = []
    for atom in reversed(atoms):
        if not atom.startswith(("_{", "^{")):
            break
        scripts.append(atom[0])
    if atoms and mark == "_" and atoms[-1].startswith("_{"):
        atoms[-1] = atoms[-1][:-1] + "," + body + "}"
    else:
        atoms.append(("{}" if mark in scripts else "") + mark + "{" + body + "}")


def _words(atoms: list[str], word: str) -> None:
    """A word set as text; words one space apart in one \\text, "\\text{the root of}", whose space
    math mode would drop between two."""
    if len(atoms) >= 2 and atoms[-1] == "\\ " and atoms[-2].startswith("\\text{") and atoms[-2].endswith("}"):
        atoms.pop()
        atoms[-1] = atoms[-1][:-1] + " " + word + "}"
    else:
        if atoms and atoms[-1] == " ":
            atoms[-1] = "\\ "  # "0.2 in": the space kept before a word
        atoms.append(f"\\text{{{word}}}")


def math(text: str) -> str:
    """Unicode math as a step writes it, as LaTeX math: ω₀²/(2|α|) -> {\\omega}_{0}^{2}/(2|{\\alpha}|)."""
    text = printable(text)  # no control character (a file's name in a step) reaches the document
    atoms: list[str] = []
    i, n = 0, len(text)
    while i < n:
        char = text[i]
        if char.isascii() and char.isalpha():
            if (name := _NAME.match(text, i)) is not None and (i == 0 or not text[i - 1].isalnum()):
                _words(atoms, _text_only(name[0]))
                i = name.end()
                continue
            j = i
            while j < n and text[j].isascii() and text[j].isalpha():
                j += 1
            word = text[i:j]
            if word in FUNCTIONS:
                atoms.append(f"\\{word} ")
            elif len(word) >= 4 or word in WORDS:
                _words(atoms, word)
            else:
                atoms.append(word)
            i = j
            continue
        if char in SUBSCRIPTS or char in SUPERSCRIPTS:
            table, mark = (SUBSCRIPTS, "_") if char in SUBSCRIPTS else (SUPERSCRIPTS, "^")
            j = i
            while j < n and text[j] in table:
                j += 1
            _script(atoms, mark, "".join(table[c] for c in text[i:j]))
            i = j
            continue
        if char in "_^" and i + 1 < n and (text[i + 1].isascii() and text[i + 1].isalnum() or text[i + 1] == "-"):
            j = i + 1 + (text[i + 1] == "-")
            while j < n and text[j].isascii() and text[j].isalnum():
                j += 1
            body = text[i + 1 : j]
            _script(atoms, char, f"\\mathrm{{{body}}}" if sum(c.isalpha() for c in body) >= 2 else body)
            i = j
            continue
        if char == "^" and i + 1 < n and text[i + 1] == "(" and (close := _closing(text, i + 1)) is not None:
            _script(atoms, "^", math(text[i + 1 : close + 1]))  # e^(−t/τ): the bracket raised whole
            i = close + 1
            continue
        if char == "√" and i + 1 < n and text[i + 1] == "(" and (close := _closing(text, i + 1)) is not None:
            atoms.append("\\sqrt{" + math(text[i + 2 : close]) + "}")  # √(I/M): the root over the bracket's content
            i = close + 1
            continue
        if char in ACCENTS:
            base = atoms.pop() if atoms else "{}"
            atoms.append(f"\\{ACCENTS[char]}{{{base}}}")
        elif char == " ":
            j = i
            while j < n and text[j] == " ":
                j += 1
            atoms.append("\\quad " if j - i >= 2 else "\\ " if atoms and atoms[-1].startswith("\\text{") else " ")  # after a word, kept
            i = j
            continue
        elif char in MATH_ESCAPES:
            atoms.append(MATH_ESCAPES[char])
        elif char == "_":
            atoms.append("\\_")
        elif char == "^":
            atoms.append("\\wedge ")
        elif char.isascii():
            atoms.append(char)
        elif (found := _math_char(char)) is not None:
            atoms.append(found)
        elif _LATIN.fullmatch(char):
            atoms.append(f"\\text{{{char}}}")
        else:
            atoms.append(_plain(char))
        i += 1
    return "".join(atoms)


def _closing(text: str, at: int) -> int | None:
    """Where the bracket opened at ``at`` closes, or None."""
    depth = 0
    for index in range(at, len(text)):
        depth += {"(": 1, ")": -1}.get(text[index], 0)
        if depth == 0:
            return index
    return None


def _text_only(words: str) -> str:
    out = []
    for char in words:
        if char in TEXT_ESCAPES:
            out.append(TEXT_ESCAPES[char])
        elif char.isascii() or _LATIN.fullmatch(char):
            out.append(char)
        else:
            out.append(TEXT_ESCAPES.get(_plain(char), _plain(char)))
    return "".join(out)


_MATHY = "".join(sorted({*GREEK, *SYMBOLS, *SUBSCRIPTS, *SUPERSCRIPTS, *ACCENTS} - set(TEXT_ESCAPES) - {"x̂"}))
# a run of math in a text: its symbols with the letters and digits they touch (T₁, Iα, ½MR², 30°),
# or a root over a bracket, √(I/M)
_MATH_RUN = re.compile(rf"√\([^()]*(?:\([^()]*\)[^()]*)*\)|[A-Za-z0-9]*(?:[{re.escape(_MATHY)}]+[A-Za-z0-9]*)+")


def text(words: str) -> str:
    """Text escaped for text mode, its Greek letters and math in $…$: "ω₀ = 30 rad/s" -> "${\\omega}_{0}$ = 30 rad/s"."""
    words = printable(words)  # a control character (a newline in a file's name) as its escape, \n
    out, at = [], 0
    for found in _MATH_RUN.finditer(words):
        out += [_text_only(words[at : found.start()]), "$" + math(found[0]) + "$"]
        at = found.end()
    out.append(_text_only(words[at:]))
    return "".join(out)


# siunitx's literal units: kg.m^{2}, rad/s^{2}. Anything else is set as text beside the number.
_UNIT_ATOM = r"(?:[A-Za-z]+|\\percent|\\degree)(?:\^\{-?\d+\})?"
_SIUNITX = re.compile(rf"{_UNIT_ATOM}(?:[./]{_UNIT_ATOM})*")


def unit(name: str | None) -> str | None:
    """A unit string (kg*m**2, or as shown, kg·m²) as siunitx's literal unit kg.m^{2}, or None
    where siunitx could misread it."""
    if not name:
        return None
    literal = name.replace("**", "^").replace("*", ".").replace("·", ".").replace("%", "\\percent").replace("°", "\\degree")
    literal = re.sub(r"⁻?[¹²³⁴⁵]+", lambda m: "^" + "".join(SUPERSCRIPTS[c] for c in m[0]), literal)
    literal = re.sub(r"\^(-?\d+)", r"^{\1}", literal)
    literal = re.sub(r"(?<![A-Za-z\\])deg(?![A-Za-z])", r"\\degree", literal)
    return literal if _SIUNITX.fullmatch(literal) else None


_NUMBER = r"[-−]?\d+(?:\.\d+)?(?:e[-+−]?\d+)?"
_ATOM = r"(?:kg|mg|g|km|cm|mm|m|ms|min|s|h|kN|mN|N|MJ|kJ|J|MW|kW|W|rad|rev|rpm|Hz|GPa|MPa|kPa|Pa|lbf|lb|ft|in|hp)(?:⁻?[¹²³])?"
QUANTITY = re.compile(rf"(?<![\w.])({_NUMBER}) ({_ATOM}(?:[·/]{_ATOM})*)(?![\w])|(?<![\w.])({_NUMBER}e[-+−]?\d+)(?![\w])")


def _number(digits: str) -> str:
    return digits.replace("−", "-")


def quantities(line: str) -> str:
    """A numbers line as math, each "number unit" as \\qty{…}{…} and each 1.2e-5 as \\num{…}."""
    out, at = [], 0
    for found in QUANTITY.finditer(line):
        if found[2] == "in":  # "0.2 in [100, 178] kg": the word, set with the math around it (#43 item 15)
            continue
        out.append(math(line[at : found.start()]))
        if found[1] is not None and (literal := unit(found[2])) is not None:
            out.append(f"\\qty{{{_number(found[1])}}}{{{literal}}}")
        elif found[1] is not None:
            out.append(math(found[0]))
        else:
            out.append(f"\\num{{{_number(found[3])}}}")
        at = found.end()
    out.append(math(line[at:]))
    return "".join(out)


_PLAIN_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?")


_UNCERTAIN = re.compile(r"(-?\d+(?:\.\d+)?) ± (\d+(?:\.\d+)?)")


def _value(cell: str) -> str:
    """A value as shown: \\num{4.90}, or \\num{4.90 +- 0.08} with its uncertainty; a word as text."""
    if _PLAIN_NUMBER.fullmatch(cell):
        return f"\\num{{{cell}}}"
    if found := _UNCERTAIN.fullmatch(cell):
        return f"\\num[uncertainty-mode=separate]{{{found[1]} +- {found[2]}}}"  # 4.90 ± 0.08, as shown elsewhere
    return text(cell)


def _unit_cell(name: str | None) -> str:
    literal = unit(name)
    return f"\\unit{{{literal}}}" if literal else text(name or "")


def _tabular(headings, rows, right) -> list[str]:
    spec = " ".join("r" if r else "l" for r in right)
    return [f"\\begin{{tabular}}{{{spec}}}", "\\hline", " & ".join(text(h) for h in headings) + " \\\\", "\\hline",
            *(" & ".join(rows_cell for rows_cell in row) + " \\\\" for row in rows), "\\hline", "\\end{tabular}"]  # fmt: skip


def _steps(steps) -> list[str]:
    """The steps as one align*: each step's title (and why) as \\intertext, its lines aligned at "="."""
    rows: list[str] = []
    for number, step in enumerate(steps, start=1):
        rows.append(f"\\intertext{{{number}.\\ {text(step.title)}}}")
        lines = step_lines(step)
        for index, line in enumerate(lines):
            if index == 0 and "=" in line:
                left, _, right = line.partition("=")
                rows.append(f"{quantities(left.strip())} &= {quantities(right.strip())} \\\\")
            elif index == 0:
                rows.append(f"&{quantities(line.strip())} \\\\")
            else:
                rows.append(f"&= {quantities(line.strip()[1:].strip())} \\\\")
        if step.why:
            rows.append(f"\\intertext{{\\emph{{why:}} {text(step.why)}}}")
    if rows and rows[-1].startswith("\\intertext"):
        rows.append("& \\\\")  # an \intertext goes between two rows
    if rows and rows[-1].endswith(" \\\\"):
        rows[-1] = rows[-1][: -len(" \\\\")]
    return ["\\begin{align*}", *rows, "\\end{align*}"] if rows else []


def _notes(notes) -> list[str]:
    return ["", "\\begin{itemize}", *(f"\\item \\emph{{note:}} {text(note)}" for note in notes), "\\end{itemize}"] if notes else []


def document(sheet: Sheet) -> str:
    """The run as a LaTeX fragment: the model line, the results table, tables, steps, notes."""
    out = [f"% taucli {__version__}: {sheet.scene}", PREAMBLE,
           f"\\noindent\\textbf{{{text(sheet.scene)}}}: {text(sheet.model)}\\\\", f"\\emph{{method: {text(sheet.method)}}}", ""]  # fmt: skip
    rows = [(f"\\texttt{{{text(r.name)}}}", _value(r.value), _unit_cell(r.unit), text(r.label)) for r in sheet.results]
    out += ["\\medskip", "", "\\noindent", *_tabular(("result", "value", "unit", "what it is"), rows, (False, True, False, False))]
    for part in sheet.tables:
        out += ["", "\\medskip", "", f"\\noindent\\textbf{{{text(part.title)}}}\\\\"]
        out += _tabular([heading(*column) for column in part.columns], [[_value(cell) for cell in row] for row in part.rows], [u is not None for _, u in part.columns])
    if sheet.steps:
        out += ["", "\\paragraph{Steps}", *_steps(sheet.steps)]
    return "\n".join(out + _notes(sheet.notes)) + "\n"


def grid(sweep: Grid) -> str:
    """A sweep as a LaTeX table, one row per point."""
    out = [f"% taucli {__version__}", PREAMBLE, f"\\noindent\\textbf{{{text(sweep.title)}}}\\\\", f"\\emph{{model: {text(sweep.model)}}}", "", "\\medskip", "", "\\noindent"]
    headings = [text(name) + (f" (\\unit{{{unit(u)}}})" if unit(u) else f" ({text(u)})" if u else "") for name, u in sweep.columns]
    rows = [[_value(cell) for cell in row] for row in grid_cells(sweep)]
    spec = " ".join("r" for _ in headings)
    out += [f"\\begin{{tabular}}{{{spec}}}", "\\hline", " & ".join(headings) + " \\\\", "\\hline", *(" & ".join(row) + " \\\\" for row in rows), "\\hline", "\\end{tabular}"]
    return "\n".join(out + _notes(sweep.notes)) + "\n"
