"""The package's layers, read from its source (ast): no import cycle between
its modules, and only the application layer writes files.

Both walk every module of ``sizing/``, imports inside functions included,
so a lazy import cannot hide a cycle or a writer."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[2] / "sizing"

# The modules that may write files: the application layer, the command
# line over it, and the atomic writer they call.
WRITERS = ("sizing.api", "sizing.cli", "sizing.io.atomic")

# Calls that create, change or remove files.
WRITING_FUNCTIONS = {("os", n) for n in ("replace", "rename", "remove", "unlink", "mkdir", "makedirs", "fdopen",
                                         "link", "symlink", "rmdir", "truncate")} | \
    {("shutil", n) for n in ("copy", "copy2", "copyfile", "copytree", "move", "rmtree")} | \
    {("tempfile", n) for n in ("mkstemp", "mkdtemp", "NamedTemporaryFile", "TemporaryDirectory")} | \
    {("numpy", "save"), ("np", "save"), ("np", "savetxt"), ("pickle", "dump"), ("json", "dump")}
WRITING_METHODS = {"write_text", "write_bytes", "to_csv", "write_html", "write_image", "savefig", "mkdir",
                   "touch", "unlink", "rmdir", "symlink_to", "hardlink_to"}
ATOMIC_WRITERS = {"write_folder", "write_files", "write_text", "scratch_folder", "store_cache"}


def _modules() -> dict[str, Path]:
    """{dotted name: file} of every module of the package."""
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        out[name] = path
    return out


MODULES = _modules()


def _base(name: str, path: Path, level: int) -> str:
    """The package a relative import of ``level`` dots starts from."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    for _ in range(level - 1):
        package = package.rpartition(".")[0]
    return package


def _targets(node, name: str, path: Path) -> list[str]:
    """The package modules an import statement names (the most specific
    that exists: ``from . import output`` names the module ``output``)."""
    if isinstance(node, ast.Import):
        wanted = [alias.name for alias in node.names]
    else:
        base = _base(name, path, node.level) if node.level else ""
        module = ".".join(p for p in (base, node.module) if p)
        wanted = [f"{module}.{alias.name}" if f"{module}.{alias.name}" in MODULES else module
                  for alias in node.names]
    found = []
    for target in wanted:
        while target and target not in MODULES:
            target = target.rpartition(".")[0]
        if target and target != name:
            found.append(target)
    return found


def _trees() -> dict[str, ast.AST]:
    return {name: ast.parse(path.read_text(encoding="utf-8"), str(path)) for name, path in MODULES.items()}


TREES = _trees()


def import_graph() -> dict[str, set[str]]:
    """{module: the package modules it imports, at any depth of its code}."""
    return {name: {t for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))
                   for t in _targets(node, name, MODULES[name])}
            for name, tree in TREES.items()}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_no_import_cycle():
    assert cycles(import_graph()) == []


def test_the_fits_do_not_import_the_diagnosis():
    """``sizing fit`` and ``sizing diagnose`` share the spectral lines
    (sizing/spectrum.py) and the sensor mount (sizing/physics/sensor_mount.py);
    the fits import nothing of the diagnosis."""
    graph = import_graph()
    reached = {t for m, targets in graph.items() if m.startswith("sizing.fit") for t in targets}
    assert not {t for t in reached if t.startswith("sizing.diagnose")}
    assert "sizing.spectrum" in graph["sizing.fit.common"]


def test_the_cycle_finder_finds_a_cycle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert cycles(graph) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_function_level_imports_are_edges():
    """``fit.bouc_wen`` imports ``fit.prior``; a function-level import counts too."""
    graph = import_graph()
    assert "sizing.fit.prior" in graph["sizing.fit.bouc_wen"]
    assert "sizing.api.output" in graph["sizing.api.solution"]      # ``from . import output``
    assert "sizing.engine.solve" in graph["sizing.api.solution"]    # inside run_solve


def _dotted(node) -> tuple[str, ...]:
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        parts.append(node.id)
    return tuple(reversed(parts))


def _mode(call: ast.Call, position: int):
    for kw in call.keywords:
        if kw.arg == "mode":
            return kw.value.value if isinstance(kw.value, ast.Constant) else "?"
    if len(call.args) > position:
        arg = call.args[position]
        return arg.value if isinstance(arg, ast.Constant) else "?"
    return "r"


def _writes(call: ast.Call) -> str | None:
    """What a call writes, or None when it only reads or computes."""
    name = _dotted(call.func)
    if not name:
        return None
    if name == ("open",) or name[-2:] in (("io", "open"), ("os", "fdopen")):
        mode = _mode(call, 1)
    elif isinstance(call.func, ast.Attribute) and name[-1] == "open":      # Path.open(mode)
        mode = _mode(call, 0)
    else:
        mode = "r"
    if not isinstance(mode, str) or set(mode) & set("wax+?"):
        return f"{'.'.join(name)}(mode {mode!r})"
    if name[-2:] in WRITING_FUNCTIONS or (isinstance(call.func, ast.Attribute) and name[-1] in WRITING_METHODS):
        return ".".join(name)
    if name[-1] in ATOMIC_WRITERS:
        return ".".join(name)
    return None


def _calls(node, function: str = ""):
    """(enclosing function, call) of every call below ``node``."""
    for child in ast.iter_child_nodes(node):
        inner = child.name if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)) else function
        if isinstance(child, ast.Call):
            yield function, child
        yield from _calls(child, inner)


def _allowed(module: str, function: str, what: str) -> bool:
    if any(module == w or module.startswith(w + ".") for w in WRITERS):
        return True
    if what.endswith("scratch_folder") and module.startswith(SCRATCH_USERS):
        return True
    return what.endswith("store_cache") and (module, function) in CACHES


# The file layer reads back what a command would write, or a git
# revision's catalog, from a scratch folder the atomic writer makes and
# removes (``io.atomic.scratch_folder``); nothing else of it writes.
SCRATCH_USERS = "sizing.io."
# A cache outside every output folder, written by the atomic writer:
# parsed catalogs keyed by content, and slow computations' results
# (``disk_cache``: the plate's finite-element solves) keyed by their code.
CACHES = {("sizing.io.catalog", "_store"), ("sizing.disk_cache", "_store")}


def file_writers(trees: dict[str, ast.AST]) -> list[str]:
    """``module:line call`` of every call that writes a file where it may not."""
    return [f"{name}:{call.lineno} {what}" for name, tree in trees.items() for function, call in _calls(tree)
            if (what := _writes(call)) and not _allowed(name, function, what)]


def test_only_the_application_layer_writes_files():
    assert file_writers(TREES) == []


@pytest.mark.parametrize("source, writes", [
    ("open(p, 'w')", True), ("open(p, mode='ab')", True), ("open(p)", False), ("open(p, 'rb')", False),
    ("p.open('w')", True), ("p.open()", False), ("p.write_text(t)", True), ("p.write_bytes(b)", True),
    ("frame.to_csv(p)", True), ("fig.write_html(p)", True), ("shutil.copy(a, b)", True),
    ("os.replace(a, b)", True), ("write_files({p: t})", True), ("atomic.write_text(p, t)", True),
    ("tempfile.TemporaryDirectory()", True), ("text.replace('a', 'b')", False),
    ("dataclasses.replace(x, a=1)", False), ("p.read_text()", False), ("json.dumps(x)", False),
    ("def f():\n    def g():\n        p.write_text(t)", True), ("scratch_folder(files)", True),
])
def test_the_writer_scan_tells_writes_from_reads(source, writes):
    tree = {"sizing.physics.example": ast.parse(source)}
    assert bool(file_writers(tree)) is writes


def test_the_writer_scan_allows_only_the_named_exceptions():
    cache = "def _store(d):\n    store_cache(path, data, 200)"
    assert file_writers({"sizing.io.catalog": ast.parse(cache)}) == []
    assert file_writers({"sizing.io.catalog": ast.parse(cache.replace("_store", "load"))}) != []
    assert file_writers({"sizing.io.catalog": ast.parse(cache.replace("store_cache", "os.replace"))}) != []
    assert file_writers({"sizing.io.catalog_diff": ast.parse("scratch_folder(files)")}) == []
    assert file_writers({"sizing.api.solution": ast.parse("write_folder(d, files)")}) == []
