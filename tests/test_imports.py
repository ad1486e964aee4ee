"""The imports of taucli/: an import graph with no cycle, imports inside functions only to defer a
heavy module (each says which), and no module over about 500 lines (#30).

The graph is read from the source (``ast``), imports inside functions included: an import
deferred into a function is still a dependency, and a loop hidden that way is still a loop.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).parent.parent / "taucli"
MOST_LINES = 450  # "about 450": past it, a module's docstring says why it is kept whole
MOST_LINES_WITH_A_REASON = 520
KEPT_WHOLE = "Kept whole:"  # how that docstring says why
DEFERRED = "# deferred"  # the comment an import inside a function carries, saying what it defers


def modules(root: Path = PACKAGE) -> dict[str, Path]:
    found = {}
    for path in sorted(root.rglob("*.py")):
        parts = path.relative_to(root.parent).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        found[name] = path
    return found


def _imported(node: ast.AST, package: str, known: dict[str, Path]) -> set[str]:
    """The taucli modules one import statement names (``from taucli.quantities import units`` names taucli.quantities.units)."""
    if isinstance(node, ast.Import):
        return {alias.name for alias in node.names if alias.name in known}
    base = node.module or ""
    if node.level:
        parts = package.split(".")[: len(package.split(".")) - node.level + 1]
        base = ".".join(parts + ([node.module] if node.module else []))
    if not base.startswith("taucli"):
        return set()
    names = {f"{base}.{alias.name}" for alias in node.names}
    return {name for name in names if name in known} | ({base} if base in known and not names <= set(known) else set())


def graph(root: Path = PACKAGE) -> dict[str, set[str]]:
    """Each module of taucli/ and the taucli modules it imports, anywhere in it."""
    known = modules(root)
    edges = {}
    for name, path in known.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                found |= _imported(node, package, known)
        edges[name] = found - {name}
    return edges


def cycle(edges: dict[str, set[str]]) -> list[str] | None:
    """One cycle of the graph (its modules in order, the first repeated at the end), or None."""
    state: dict[str, int] = {}  # 1: on the path being walked, 2: done
    path: list[str] = []

    def walk(node: str) -> list[str] | None:
        state[node] = 1
        path.append(node)
        for after in sorted(edges[node]):
            if state.get(after) == 1:
                return path[path.index(after):] + [after]
            if after not in state and (found := walk(after)):
                return found
        state[node] = 2
        path.pop()
        return None

    for start in sorted(edges):
        if start not in state and (found := walk(start)):
            return found
    return None


def test_the_import_graph_of_taucli_has_no_cycle():
    found = cycle(graph())
    assert found is None, "import cycle: " + " -> ".join(found)


def test_the_cycle_check_finds_a_cycle_hidden_in_a_function(tmp_path):
    """The check can fail: the loop #30 found (find -> uncertain at the top; uncertain -> find,
    pipeline and inputs inside functions; inputs -> uncertain inside a function; pipeline ->
    inputs), written small."""
    package = tmp_path / "taucli"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "find.py").write_text("from taucli.uncertain import split\n")
    (package / "uncertain.py").write_text("def solve():\n    from taucli import find, pipeline\n")
    (package / "pipeline.py").write_text("from taucli.inputs import read\n")
    (package / "inputs.py").write_text("def quantity():\n    from taucli.uncertain import split\n")
    found = cycle(graph(package))
    assert found is not None and found[0] == found[-1]
    assert set(found) <= {"taucli.find", "taucli.uncertain", "taucli.pipeline", "taucli.inputs"}


def _imports_inside_functions(path: Path):
    source = path.read_text(encoding="utf-8")
    lines = source.splitlines()
    for function in ast.walk(ast.parse(source)):
        if isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
            for node in ast.walk(function):
                if isinstance(node, (ast.Import, ast.ImportFrom)):
                    yield node.lineno, lines


def _says_why(lineno: int, lines: list[str]) -> bool:
    """The import's line says what it defers, or the first import of the run of imports it is in does."""
    at = lineno - 1
    while True:
        if DEFERRED in lines[at]:
            return True
        if at == 0 or not lines[at - 1].strip().startswith(("import ", "from ")):
            return False
        at -= 1


def test_an_import_inside_a_function_defers_a_heavy_module_and_says_which():
    unexplained = [f"{path.relative_to(PACKAGE.parent)}:{lineno}: {lines[lineno - 1].strip()}"
                   for path in modules().values() for lineno, lines in _imports_inside_functions(path) if not _says_why(lineno, lines)]
    assert not unexplained, "imports inside functions with no '# deferred: …' comment:\n" + "\n".join(unexplained)


@pytest.mark.parametrize("name", sorted(modules()))
def test_no_module_is_over_about_450_lines_without_a_reason(name):
    text = modules()[name].read_text(encoding="utf-8")
    lines = len(text.splitlines())
    reason = KEPT_WHOLE in (ast.get_docstring(ast.parse(text)) or "")
    assert lines <= MOST_LINES or (reason and lines <= MOST_LINES_WITH_A_REASON), (
        f"{name} has {lines} lines: split it where it holds two jobs, or say why not in its docstring ({KEPT_WHOLE} …)")


# The layers of taucli/, lowest first: a module may import its own layer and those below it, never
# one above (taucli/__init__.py and __main__.py, the package's faces, stand above them all).
LAYERS = (
    ("core", "errors, numbers as text, the names of choices, the version"),
    ("numerics", "steppers, roots, quadrature, elliptic integrals"),
    ("quantities", "text -> an SI float for a kind: units, spellings, expressions, the unit cache"),
    ("writing", "Report and its writers: the human view, JSON, md/latex/html/csv, charts"),
    ("options", "the vocabulary of a table and one table per command"),
    ("scenes", "pure solvers: SI floats in, a Report out"),
    ("answering", "inputs -> the scene -> Report, and how a run is answered"),
    ("fit", "taucli fit: samples, models on arrays, least squares"),
    ("front", "the command line, batch, the Python API, help, completions, bench"),
)
LAYER_OF = {name: rank for rank, (name, _) in enumerate(LAYERS)}
MOST_TOP_ENTRIES = 11  # "at most about ten": the layers, __init__.py and __main__.py


def layer(module: str) -> int | None:
    """The rank of a module's layer (taucli.quantities.units: 2), None for the package's faces."""
    parts = module.split(".")
    return LAYER_OF.get(parts[1]) if len(parts) > 1 else None


def upward_imports(edges: dict[str, set[str]]) -> list[str]:
    """Each import from a lower layer into a higher one, as "importer (layer) -> imported (layer)"."""
    found = []
    for importer, imported in sorted(edges.items()):
        below = layer(importer)
        for name in sorted(imported):
            above = layer(name)
            if below is not None and above is not None and above > below:
                found.append(f"{importer} ({LAYERS[below][0]}) -> {name} ({LAYERS[above][0]})")
    return found


def test_taucli_is_a_few_folders_one_per_layer_each_saying_what_it_owns():
    entries = sorted(path.name for path in PACKAGE.iterdir() if not path.name.startswith((".", "__pycache__")))
    assert entries == sorted(["__init__.py", "__main__.py", *LAYER_OF]), entries
    assert len(entries) <= MOST_TOP_ENTRIES
    for name in LAYER_OF:
        doc = ast.get_docstring(ast.parse((PACKAGE / name / "__init__.py").read_text(encoding="utf-8")))
        assert doc and "import" in doc, f"taucli/{name}/__init__.py: a docstring saying what the layer owns and what it may import"


def test_every_module_is_in_a_layer():
    faces = {"taucli", "taucli.__main__"}
    assert not [name for name in modules() if name not in faces and layer(name) is None]


def test_imports_run_down_the_layers_never_up():
    found = upward_imports(graph())
    assert not found, "imports from a lower layer into a higher one:\n" + "\n".join(found)


def test_the_layer_check_finds_an_import_that_runs_up(tmp_path):
    """The check can fail: a planted import from the quantities layer up into writing (render),
    and one deferred into a function of a scene up into the answering layer."""
    package = tmp_path / "taucli"
    for folder in ("quantities", "writing", "scenes", "answering"):
        (package / folder).mkdir(parents=True)
        (package / folder / "__init__.py").write_text("")
    (package / "__init__.py").write_text("")
    (package / "writing" / "render.py").write_text("from taucli.quantities import units\n")
    (package / "quantities" / "units.py").write_text("from taucli.writing.render import render\n")
    (package / "answering" / "pipeline.py").write_text("from taucli.scenes import inertia\n")
    (package / "scenes" / "inertia.py").write_text("def solve():\n    from taucli.answering import pipeline  # deferred: planted\n")
    found = upward_imports(graph(package))
    assert found == ["taucli.quantities.units (quantities) -> taucli.writing.render (writing)",
                     "taucli.scenes.inertia (scenes) -> taucli.answering.pipeline (answering)"]
