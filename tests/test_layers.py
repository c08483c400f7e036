"""wtvib's packages are its layers, each importing only its own and the ones below it, and
the import graph has no cycles: every module can be read, and changed, without the ones
that depend on it. Imports inside functions count (they are how
the last cycles hid); imports under ``if TYPE_CHECKING:`` never run, and form no cycle
either (they say which module knows which: a protocol, not the other module's class,
where a lower layer reads a higher one's object)."""

import ast
from pathlib import Path

import wtvib

ROOT = Path(wtvib.__file__).parent


def modules() -> dict[str, Path]:
    out = {}
    for path in ROOT.rglob("*.py"):
        parts = path.relative_to(ROOT.parent).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        out[name] = path
    return out


def imports(name: str, path: Path, known: dict[str, Path], typing: bool = False) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    typing_only = (
        set()
        if typing
        else {
            id(sub)
            for node in ast.walk(tree)
            if isinstance(node, ast.If) and getattr(node.test, "id", None) == "TYPE_CHECKING"
            for sub in ast.walk(node)
        }
    )
    package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    found: set[str] = set()
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.ImportFrom) and node.level:
            base = package
            for _ in range(node.level - 1):
                base = base.rsplit(".", 1)[0]
            mod = f"{base}.{node.module}" if node.module else base
            for alias in node.names:
                sub = f"{mod}.{alias.name}"
                found.add(sub if sub in known else mod)
        elif isinstance(node, ast.ImportFrom) and node.module:
            found.add(node.module)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
    return {m for m in found if m in known and m != name}


def cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """One import cycle of the graph, or None (depth-first search)."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(v: str) -> list[str] | None:
        state[v] = 1
        stack.append(v)
        for w in sorted(graph[v]):
            if state.get(w) == 1:
                return [*stack[stack.index(w) :], w]
            if w not in state and (found := visit(w)):
                return found
        stack.pop()
        state[v] = 2
        return None

    for v in sorted(graph):
        if v not in state and (found := visit(v)):
            return found
    return None


def test_the_import_graph_has_no_cycle():
    known = modules()
    graph = {name: imports(name, path, known) for name, path in known.items()}
    assert len(graph) > 30 and graph["wtvib.audit"]  # the graph was really read
    assert cycle(graph) is None, " → ".join(cycle(graph) or [])


def test_type_only_imports_close_no_circle_either():
    known = modules()
    graph = {name: imports(name, path, known, typing=True) for name, path in known.items()}
    assert graph["wtvib.numerics.rigid"] and "wtvib.spec" not in graph["wtvib.numerics.rigid"]
    assert (
        "wtvib.subsystems.coupled"
        not in graph["wtvib.subsystems.multiblade"] | graph["wtvib.subsystems.periodic"]
    )
    assert cycle(graph) is None, " → ".join(cycle(graph) or [])


def test_the_cycle_finder_finds_a_cycle():
    assert cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert cycle({"a": {"b"}, "b": set()}) is None


def test_models_never_import_the_rendering_layer():
    """Calculate first, draw second: nothing below the outputs imports matplotlib, rich or
    the report and figure modules (STYLE.md habit 3)."""
    known = modules()
    rendering = {m for m in known if m.startswith("wtvib.outputs")}
    models = {m for m in known if layer(m) < layer("wtvib.outputs")}
    assert "wtvib.subsystems.coupled" in models and "wtvib.audit" in models
    for name in sorted(models):
        text = known[name].read_text(encoding="utf-8")
        assert "import matplotlib" not in text and "from rich" not in text, name
        assert not imports(name, known[name], known) & rendering, name


#: The layers, lowest first (docs/DESIGN.md): a module imports from its own layer and the
#: ones below, never from above — at run time or for its types alone.
LAYERS = (
    ("core", ("wtvib", "wtvib.errors", "wtvib.units", "wtvib.rules", "wtvib.document",
              "wtvib.results")),
    ("numerics", ("wtvib.numerics",)),
    ("spec", ("wtvib.spec",)),
    ("importers", ("wtvib.importers",)),
    ("judge", ("wtvib.judge",)),
    ("subsystems", ("wtvib.subsystems",)),
    ("aero", ("wtvib.aero",)),
    ("studies", ("wtvib.studies",)),
    ("audit", ("wtvib.audit",)),
    ("outputs", ("wtvib.outputs",)),
    ("workflows", ("wtvib.workflows",)),
    ("cli", ("wtvib.cli", "wtvib.__main__")),
)  # fmt: skip


def layer(module: str) -> int:
    """The index of a module's layer in LAYERS: its package's, or its own."""
    for i, (_, members) in enumerate(LAYERS):
        if module in members or any(module.startswith(m + ".") for m in members if m != "wtvib"):
            return i
    raise AssertionError(f"{module} belongs to no layer: add it to LAYERS and docs/DESIGN.md")


def test_every_import_goes_down_the_layers():
    """No module imports one of a higher layer (an importer calling a subsystem's model,
    the reader of linearisations the coupled model's machinery, a model the writer of
    files: each was once so)."""
    known = modules()
    upward = []
    for name, path in sorted(known.items()):
        for target in sorted(imports(name, path, known, typing=True)):
            if layer(target) > layer(name):
                upward.append(f"{name} ({LAYERS[layer(name)][0]}) imports {target} "
                              f"({LAYERS[layer(target)][0]})")  # fmt: skip
    assert not upward, "\n".join(upward)


def test_the_layer_check_sees_an_upward_import():
    assert layer("wtvib.importers.elastodyn") < layer("wtvib.subsystems.blade")
    assert layer("wtvib.outputs.plots.campbell") > layer("wtvib.audit")
    assert layer("wtvib.spec.yamlio") == layer("wtvib.spec")


def test_a_dozen_modules_at_most_at_the_top():
    """The top of the package holds the shared types, the orchestrator and the command line;
    everything else lives in its layer's package."""
    top = sorted(p.name for p in ROOT.glob("*.py"))
    assert len(top) <= 12, top


def _function_lengths(path: Path) -> dict[str, int]:
    """Every function's lines in ``path`` (decorators and docstring included)."""
    tree = ast.parse(path.read_text())
    return {
        f"{path.relative_to(ROOT.parent)}:{node.name}": node.end_lineno - node.lineno + 1
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) and node.end_lineno
    }


def test_the_command_line_is_thin():
    """The CLI declares options and makes one library call per command: at most 450 lines,
    no function over 40 (the work is in ``workflows/``)."""
    cli = ROOT / "cli.py"
    assert len(cli.read_text().splitlines()) <= 450
    long = {k: n for k, n in _function_lengths(cli).items() if n > 40}
    assert not long, long


def test_no_function_is_longer_than_80_lines():
    lengths: dict[str, int] = {}
    for path in ROOT.rglob("*.py"):
        lengths.update(_function_lengths(path))
    long = {k: n for k, n in lengths.items() if n > 80}
    assert not long, long
    assert max(lengths.values()) > 20  # the walk found the functions
