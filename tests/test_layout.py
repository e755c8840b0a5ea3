"""The package's layers: who may import whom, read from the source (``ast``, nothing is imported).

Every import of a graphmech module counts, wherever it stands: at module level, inside a function
and under ``if TYPE_CHECKING:``; ``from graphmech.pkg import name`` is an import of the module
``graphmech.pkg.name`` when that file exists, else of ``graphmech.pkg``; relative imports are
resolved. The rules:

* Layers (:data:`CONTRACTS` below). A module belongs to the layer of its longest matching prefix
  (a prefix names a module and everything under it; the root ``graphmech`` names only
  ``graphmech/__init__.py``). A module may import its own layer and the layers listed beside it,
  nothing else. Every module must belong to a layer.
* No import cycle anywhere, through function-level imports too: each strongly connected component
  is reported with the imports that close it.
* No private name (``_x``, not a dunder) taken from another module, whether by
  ``from graphmech.x import _y``, by ``graphmech.x._y`` / ``alias._y`` attribute access, or by
  importing a private module ``graphmech.pkg._m`` from outside ``graphmech.pkg``. Cross-kind
  imports of public names under ``problems/`` are allowed (forces builds on linkage).
* Imports are direct: no ``importlib.import_module`` / ``__import__``, and no graphmech module
  named in a string (the registry's lazy imports are function-level ``from … import``).
* Every graphmech import names a module that exists.
* The registry (``import graphmech.problems``) stays light: no scipy, matplotlib, shapely, and
  no kind's ``check`` / ``figures`` / ``bench`` at start-up. A kind is any package under
  ``graphmech/problems/`` (found on disk, never listed here).

Failures list each offending import as ``module:line imports target (rule)``.
"""
from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
import textwrap
from collections import Counter, defaultdict, deque
from dataclasses import dataclass, field
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "graphmech"

#: The architecture, bottom to top: layer → (its modules, the layers it may import besides itself).
#: Modules are named under graphmech/ by prefix (``methods`` is graphmech/methods/ and all below it;
#: ``__init__`` is graphmech/__init__.py alone); a module is in the layer of its longest prefix.
CONTRACTS: dict[str, tuple[str, str]] = {
    # layer          modules          may import
    "base":         ("version errors tolerances scales files timing accuracy packaged roots minimum spline", ""),
    "geometry":     ("geometry",     "base"),
    "construction": ("construction", "geometry base"),
    "mechanisms":   ("mechanisms",   "construction geometry base"),
    # the independent solution: it shares no code with the constructions
    "exact":        ("exact",        "mechanisms base"),
    "methods":      ("methods",      "mechanisms construction geometry base"),
    # the drawing vocabulary (primitives, lettering); drawing and methods never import each other
    "drawing":      ("drawing",      "base"),
    "render":       ("render",       "drawing base"),
    # the registry, judging, reader and one package per kind (kinds are found on disk)
    "problems":     ("problems",     "methods drawing render exact mechanisms construction geometry base"),
    "scene":        ("scene variants", "problems render drawing mechanisms base"),
    # the Python API (a Problem, its check table and drawing) and what runs many of them
    "api":          ("api batch",    "scene problems render drawing base"),
    # the static HTML page of a folder's figures and checks (graphmech gallery)
    "gallery":      ("gallery",      "api scene problems base"),
    "bench":        ("bench",        "api scene problems methods drawing render exact mechanisms construction geometry "
                                     "base"),
    "cli":          ("cli",          "package gallery bench api scene problems methods drawing render exact mechanisms "
                                     "construction geometry base"),
    # `import graphmech`: the version, and the API loaded on first use (PEP 562)
    "package":      ("__init__",     "api base"),
    # `python -m graphmech`: the only module that may import cli
    "main":         ("__main__",     "cli"),
}


# ------------------------------------------------------------------------------------ the scan


@dataclass(frozen=True)
class Import:
    """One import of a graphmech module (or one dynamic import, whose target may be unknown)."""

    module: str  # the importing module
    line: int
    target: str  # the graphmech module imported (a dynamic import without a literal: the call's source)
    how: str = "import"  # "import", "from", "dynamic" (importlib / __import__), "string" (a module's name)
    names: tuple[str, ...] = ()  # for ``from target import a, b``: the names taken that are not modules
    where: str = ""  # "", "function-level", "TYPE_CHECKING" (or both)

    def say(self, rule: str) -> str:
        where = f"; {self.where}" if self.where else ""
        return f"{self.module}:{self.line} imports {self.target} ({rule}{where})"


@dataclass(frozen=True)
class Access:
    """``module`` reads the attribute ``name`` of the graphmech module ``target`` (``target.name``)."""

    module: str
    line: int
    target: str
    name: str


@dataclass
class Graph:
    package: str
    modules: dict[str, str]  # module → its file's path under the package
    imports: list[Import] = field(default_factory=list)
    accesses: list[Access] = field(default_factory=list)

    def edges(self) -> dict[str, dict[str, list[Import]]]:
        """module → imported module → the imports that make the edge (existing modules, no self-loops)."""
        out: dict[str, dict[str, list[Import]]] = defaultdict(lambda: defaultdict(list))
        for imp in self.imports:
            if imp.target in self.modules and imp.target != imp.module:
                out[imp.module][imp.target].append(imp)
        return out


def _is_private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _within(module: str, package: str) -> bool:
    return module == package or module.startswith(package + ".")


def _dotted(node: ast.AST) -> str | None:
    """``a.b.c`` for a chain of names and attributes, else None."""
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if not isinstance(node, ast.Name):
        return None
    return ".".join([node.id, *reversed(parts)])


def _is_type_checking(test: ast.AST) -> bool:
    return _dotted(test) in ("TYPE_CHECKING", "typing.TYPE_CHECKING")


_DYNAMIC = {"importlib.import_module", "importlib.__import__", "__import__", "builtins.__import__"}
_BODIES = ("body", "orelse", "finalbody", "handlers", "cases")


class _Scanner:
    """One module's imports. Imports are statements, so only statements are walked (parsing is the
    cost); the expressions are walked only in the few modules whose text may hold a dynamic import,
    a module's name in a string or a private attribute of an imported module."""

    def __init__(self, graph: Graph, module: str, is_package: bool, source: str, tree: ast.Module):
        self.g, self.module, self.source, self.tree = graph, module, source, tree
        self.package = module if is_package else module.rpartition(".")[0]
        # name → what imports bind it to (module-wide: a name bound to two things is not used)
        self.aliases: dict[str, set[str]] = defaultdict(set)
        self.spans: list[tuple[int, int, str]] = []  # (first line, last line, "function-level" | "TYPE_CHECKING")

    def run(self) -> None:
        self._statements(self.tree.body, ())
        modules = "|".join(n for n, b in self.aliases.items() if any(t in self.g.modules for t in b))
        if ("import_module" in self.source or "__import__" in self.source
                or re.search(rf"""['"]{re.escape(self.g.package)}\.""", self.source)
                or (modules and re.search(rf"\b(?:{modules})(?:\s*\.\s*\w+)*?\s*\.\s*_", self.source))):
            self._expressions()

    def _add(self, line: int, target: str, how: str, context, names: tuple[str, ...] = ()) -> None:
        self.g.imports.append(Import(self.module, line, target, how, names, ", ".join(dict.fromkeys(context))))

    # -- statements: imports and where they stand
    def _statements(self, body: list[ast.AST], context: tuple[str, ...]) -> None:
        for st in body:
            if isinstance(st, ast.Import):
                self._import(st, context)
            elif isinstance(st, ast.ImportFrom):
                self._import_from(st, context)
            elif isinstance(st, (ast.FunctionDef, ast.AsyncFunctionDef)):
                self.spans.append((st.body[0].lineno, st.end_lineno, "function-level"))
                self._statements(st.body, context + ("function-level",))
            elif isinstance(st, ast.If) and _is_type_checking(st.test):
                self.spans.append((st.body[0].lineno, st.body[-1].end_lineno, "TYPE_CHECKING"))
                self._statements(st.body, context + ("TYPE_CHECKING",))
                self._statements(st.orelse, context)
            else:  # class bodies, if/for/while/with/try/match: the same context
                for name in _BODIES:
                    self._statements(getattr(st, name, None) or [], context)

    def _import(self, node: ast.Import, context) -> None:
        for a in node.names:
            head = a.name.partition(".")[0]
            self.aliases[a.asname or head].add(a.name if a.asname else head)
            if _within(a.name, self.g.package):
                self._add(node.lineno, a.name, "import", context)

    def _import_from(self, node: ast.ImportFrom, context) -> None:
        if node.level:
            base = self.package.split(".")
            base = base[: len(base) - (node.level - 1)]
            source = ".".join(base + ([node.module] if node.module else []))
        else:
            source = node.module or ""
        for a in node.names:
            self.aliases[a.asname or a.name].add(f"{source}.{a.name}")
        if not _within(source, self.g.package):
            return
        names = []
        for a in node.names:
            if f"{source}.{a.name}" in self.g.modules:
                self._add(node.lineno, f"{source}.{a.name}", "from", context)
            else:
                names.append(a.name)
        if names:
            self._add(node.lineno, source, "from", context, tuple(names))

    # -- expressions: dynamic imports, module names in strings, private attributes
    def _expressions(self) -> None:
        nodes = list(ast.walk(self.tree))
        rebound = _assigned_names(nodes)
        spans = self.spans + [(n.lineno, n.end_lineno, "function-level") for n in nodes if isinstance(n, ast.Lambda)]

        def context(node: ast.AST) -> list[str]:
            return [what for first, last, what in spans if first <= node.lineno <= last]

        def qualified(node: ast.AST) -> str | None:
            dotted = _dotted(node)
            if dotted is None:
                return None
            head, _, rest = dotted.partition(".")
            bound = self.aliases.get(head)
            if bound is None:
                return dotted if head == "__import__" else None
            if len(bound) != 1 or head in rebound:  # a local of the same name is not the module
                return None
            return ".".join(filter(None, [next(iter(bound)), rest]))

        skip = _docstring_ids(nodes)
        for node in nodes:
            if isinstance(node, ast.Call) and qualified(node.func) in _DYNAMIC:
                arg = node.args[0] if node.args else None
                if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                    skip.add(id(arg))
                    self._add(node.lineno, arg.value, "dynamic", context(node))
                else:
                    self._add(node.lineno, ast.unparse(node), "dynamic", context(node))
        for node in nodes:
            if (isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in skip
                    and node.value in self.g.modules and node.value != self.g.package):
                self._add(node.lineno, node.value, "string", context(node))
            elif isinstance(node, ast.Attribute):
                owner = qualified(node.value)
                if owner in self.g.modules and f"{owner}.{node.attr}" not in self.g.modules:
                    self.g.accesses.append(Access(self.module, node.lineno, owner, node.attr))


def _docstring_ids(nodes: list[ast.AST]) -> set[int]:
    out = set()
    for node in nodes:
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                out.add(id(first.value))
    return out


def _assigned_names(nodes: list[ast.AST]) -> set[str]:
    """Names bound otherwise than by an import: such a name may not mean the module it imports."""
    out = set()
    for node in nodes:
        if isinstance(node, ast.Name) and isinstance(node.ctx, (ast.Store, ast.Del)):
            out.add(node.id)
        elif isinstance(node, ast.arg):
            out.add(node.arg)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            out.add(node.name)
    return out


def scan(package_dir: Path) -> Graph:
    """The import graph of the package in ``package_dir`` (its name is the directory's)."""
    return scan_sources(package_dir.name, {p.relative_to(package_dir).as_posix(): p.read_text(encoding="utf-8")
                                           for p in sorted(package_dir.rglob("*.py"))})


def scan_sources(package: str, sources: dict[str, str]) -> Graph:
    """The import graph of a package given as its sources by path: ``{"exact/cam.py": "import …"}``."""
    files = {}
    for path in sorted(sources):
        parts = [package, *path.removesuffix(".py").split("/")]
        files[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    g = Graph(package, files)
    for module, path in files.items():
        tree = ast.parse(sources[path], filename=f"{package}/{path}")
        _Scanner(g, module, path.split("/")[-1] == "__init__.py", sources[path], tree).run()
    return g


def kinds(package_dir: Path = PACKAGE) -> list[str]:
    """The kinds of problem: every package under ``problems/``."""
    return sorted(d.name for d in (package_dir / "problems").iterdir() if (d / "__init__.py").is_file())


# ------------------------------------------------------------------------------------ the rules


def layer_of(module: str, contracts=CONTRACTS, package: str = "graphmech") -> str | None:
    """The layer whose longest prefix names ``module`` (None: no layer names it)."""
    name = "__init__" if module == package else module.removeprefix(package + ".")
    best, length = None, -1
    for layer, (prefixes, _) in contracts.items():
        for p in prefixes.split():
            if _within(name, p) and len(p) > length:
                best, length = layer, len(p)
    return best


def may_import(layer: str, contracts=CONTRACTS) -> set[str]:
    return {layer, *contracts[layer][1].split()}


def unplaced(g: Graph, contracts=CONTRACTS) -> list[str]:
    """Modules in no layer, and graphmech imports of modules that do not exist."""
    out = [f"{m}: in no layer (add it to CONTRACTS)" for m in g.modules if layer_of(m, contracts, g.package) is None]
    out += [imp.say("no such module") for imp in g.imports
            if imp.how in ("import", "from") and imp.target not in g.modules]
    return out


def layer_breaks(g: Graph, contracts=CONTRACTS) -> list[tuple[Import, str, str]]:
    """(import, its module's layer, the imported module's layer) for each import the contracts forbid."""
    out = []
    for imp in g.imports:
        if imp.target not in g.modules:
            continue
        a, b = layer_of(imp.module, contracts, g.package), layer_of(imp.target, contracts, g.package)
        if a is None or b is None or b in may_import(a, contracts):
            continue
        out.append((imp, a, b))
    return out


def layer_violations(g: Graph, contracts=CONTRACTS) -> list[str]:
    return [imp.say(f"layers: {a} may not import {b}") for imp, a, b in layer_breaks(g, contracts)]


def cycles(g: Graph) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan), each sorted."""
    edges = g.edges()
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, {})):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(g.modules):
        if v not in index:
            visit(v)
    return sorted(out)


def _shortest_cycle(edges, comp: list[str]) -> list[str]:
    start, members = comp[0], set(comp)
    came: dict[str, str] = {}
    todo = deque([start])
    while todo:
        v = todo.popleft()
        for w in sorted(edges[v]):
            if w == start:
                path = [v]
                while path[-1] != start:
                    path.append(came[path[-1]])
                return [*reversed(path), start]
            if w in members and w not in came:
                came[w] = v
                todo.append(w)
    return comp


def cycle_report(g: Graph) -> list[str]:
    edges = g.edges()
    out = []
    for n, comp in enumerate(cycles(g), 1):
        out.append(f"cycle {n}: {len(comp)} modules, e.g. " + " → ".join(_shortest_cycle(edges, comp)))
        closing = [imp for v in comp for w in edges[v] if w in comp for imp in edges[v][w]]
        out += ["  " + imp.say(f"cycle {n}") for imp in sorted(closing, key=lambda i: (i.module, i.line, i.target))]
    return out


def private_violations(g: Graph) -> list[str]:
    out = []
    for imp in g.imports:
        if imp.how not in ("import", "from"):
            continue
        parts = imp.target.split(".")
        for i, part in enumerate(parts):  # a private module, imported from outside its package
            if _is_private(part) and not _within(imp.module, ".".join(parts[:i])):
                out.append(imp.say(f"private module {'.'.join(parts[: i + 1])}"))
                break
        private = [name for name in imp.names if _is_private(name)]
        if private and imp.target != imp.module:
            out.append(imp.say(f"private name{'s' if len(private) > 1 else ''} {', '.join(private)}"))
    for acc in g.accesses:
        if _is_private(acc.name) and acc.target != acc.module:
            out.append(f"{acc.module}:{acc.line} imports {acc.target} (private name {acc.name}, "
                       f"read as an attribute)")
    return out


def dynamic_imports(g: Graph) -> list[str]:
    return [imp.say("dynamic import: import it directly" if imp.how == "dynamic"
                    else "module named in a string: import it directly")
            for imp in g.imports if imp.how in ("dynamic", "string")]


def _fail(title: str, lines: list[str], by: Counter | None = None) -> None:
    """Fail listing ``lines`` (sorted by module and line), with a count per key of ``by`` if given."""
    if not lines:
        return
    lines = sorted(set(lines), key=_natural)
    text = [f"{len(lines)} {title}:", *("  " + line for line in lines)]
    if by:
        text.append("count per pair: " + ", ".join(f"{k} {n}" for k, n in by.most_common()))
    pytest.fail("\n".join(text), pytrace=False)


def _natural(line: str) -> tuple[str, int, str]:
    module, _, rest = line.partition(":")
    num, _, tail = rest.partition(" ")
    return (module, int(num) if num.isdigit() else 0, tail)


# ------------------------------------------------------------------------------------ the package's rules


@pytest.fixture(scope="module")
def graph() -> Graph:
    return scan(PACKAGE)


def test_every_module_has_a_layer_and_every_import_exists(graph):
    _fail("modules without a layer or imports of missing modules", unplaced(graph))


def test_layers(graph):
    _fail("imports break the layer contracts (CONTRACTS in tests/test_layout.py)", layer_violations(graph),
          Counter(f"{a}→{b}" for _, a, b in layer_breaks(graph)))


def test_no_import_cycles(graph):
    report = cycle_report(graph)
    n = sum(1 for line in report if line.startswith("cycle "))
    if report:
        pytest.fail(f"{n} import cycles (strongly connected components), with the imports that close them:\n"
                    + "\n".join(report), pytrace=False)


def test_no_private_name_crosses_a_module(graph):
    _fail("imports take a private name from another module", private_violations(graph))


def test_imports_are_direct(graph):
    _fail("dynamic imports or module names in strings", dynamic_imports(graph))


def loaded_by_the_registry(root: Path) -> list[str]:
    """What ``import graphmech.problems`` (in a fresh interpreter, from ``root``) loads that it must not:
    scipy, matplotlib, shapely, or any module of a kind's own (its reader, check, figures, bench):
    those load when a scene of that kind is read, checked or drawn."""
    r = subprocess.run([sys.executable, "-c", "import graphmech.problems, sys; print(sorted(sys.modules))"],
                       cwd=root, capture_output=True, text=True, timeout=60, env={**os.environ, "PYTHONPATH": str(root)})
    assert r.returncode == 0, r.stderr
    loaded = ast.literal_eval(r.stdout.strip())
    heavy = [m for m in loaded if m.split(".")[0] in ("scipy", "matplotlib", "shapely")]
    kind_code = [m for m in loaded for k in kinds(root / "graphmech") if m.startswith(f"graphmech.problems.{k}.")]
    return sorted(heavy + kind_code)


def test_the_registry_imports_light():
    assert kinds(), "no kind found under graphmech/problems/"
    assert loaded_by_the_registry(ROOT) == [], "import graphmech.problems loads these at start-up"


# ------------------------------------------------------------------------------------ the checker's own tests


def fake(files: dict[str, str]) -> dict[str, str]:
    """A fake graphmech's sources ``{"exact/cam.py": source}``, dedented; every package gets an __init__."""
    out = {"__init__.py": ""}
    for path, source in files.items():
        parts = path.split("/")
        for i in range(1, len(parts)):
            out.setdefault("/".join(parts[:i]) + "/__init__.py", "")
        out[path] = textwrap.dedent(source)
    return out


def make_package(tmp_path: Path, files: dict[str, str]) -> Path:
    """The fake graphmech written under ``tmp_path`` (for what needs files: kinds, a fresh interpreter)."""
    for path, source in fake(files).items():
        p = tmp_path / "graphmech" / path
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(source, encoding="utf-8")
    return tmp_path / "graphmech"


#: A package that keeps every rule: one module per layer, each importing what it may.
CLEAN = {
    "errors.py": "class GraphmechError(Exception): pass\n",
    "tolerances.py": "from graphmech.errors import GraphmechError\n",
    "__main__.py": "from graphmech.cli import main\n",
    "geometry/primitives.py": "from graphmech import errors\n",
    "construction/graph.py": "import graphmech.geometry.primitives as gp\nx = gp.point\n",
    "mechanisms/linkage.py": "from graphmech.construction.graph import Graph\n",
    "exact/linkage.py": "from graphmech.mechanisms.linkage import solve\nfrom graphmech import tolerances\n",
    "methods/polygons.py": "from ..mechanisms import linkage\nfrom .velocity import plan\n",
    "methods/velocity.py": """
        from typing import TYPE_CHECKING
        if TYPE_CHECKING:
            from graphmech.mechanisms.linkage import Linkage
        def plan(): ...
        """,
    "drawing/primitives.py": "from graphmech.errors import GraphmechError\n",
    "render/svg.py": "from graphmech.drawing.primitives import Sheet\n",
    "problems/__init__.py": """
        def sheet(scene):
            from graphmech.problems.linkage.figures import linkage_sheet
            return linkage_sheet(scene)
        """,
    "problems/judging.py": "from graphmech.exact.linkage import solve\n",
    "problems/linkage/check.py": "from graphmech.methods.polygons import build\n",
    "problems/linkage/figures.py": "from graphmech.render.svg import render\nfrom .check import build\n",
    "problems/forces/check.py": "from graphmech.problems.linkage.check import build  # a public cross-kind import\n",
    "scene.py": """
        from graphmech.mechanisms.linkage import Linkage
        def load():
            from graphmech.problems.forces.check import build
        """,
    "bench.py": "from graphmech.problems import sheet\nfrom graphmech.methods import polygons\n",
    "cli.py": "import graphmech\nfrom graphmech.scene import load\nfrom graphmech.bench import run\n",
}


def _id(value) -> str | None:
    """A short test id: the files changed, or the rule expected."""
    if isinstance(value, dict):
        return "+".join(value)
    return value[value.index("(") + 1: -1] if value.startswith("graphmech") else None


def violations(files: dict[str, str]) -> list[str]:
    """Everything the rules find in a fake graphmech."""
    g = scan_sources("graphmech", fake(files))
    report = cycle_report(g)
    return unplaced(g) + layer_violations(g) + private_violations(g) + dynamic_imports(g) + report


def test_checker_passes_a_clean_package():
    assert violations(CLEAN) == []


def test_checker_resolves_imports():
    g = scan_sources("graphmech", fake(CLEAN))
    got = {(i.module, i.target, i.where) for i in g.imports}
    assert ("graphmech.construction.graph", "graphmech.geometry.primitives", "") in got  # import … as
    assert ("graphmech.geometry.primitives", "graphmech.errors", "") in got  # from pkg import module
    assert ("graphmech.methods.polygons", "graphmech.mechanisms.linkage", "") in got  # relative, level 2
    assert ("graphmech.methods.polygons", "graphmech.methods.velocity", "") in got  # relative, level 1
    assert ("graphmech.methods.velocity", "graphmech.mechanisms.linkage", "TYPE_CHECKING") in got
    assert ("graphmech.problems", "graphmech.problems.linkage.figures", "function-level") in got
    assert ("graphmech.bench", "graphmech.problems", "") in got  # from pkg import name: the package
    assert ("graphmech.cli", "graphmech", "") in got


@pytest.mark.parametrize("files, expected", [
    ({"exact/cam.py": "from graphmech.construction.graph import Graph\n"},
     "graphmech.exact.cam:1 imports graphmech.construction.graph (layers: exact may not import construction)"),
    ({"geometry/kernels.py": "\n\nimport graphmech.mechanisms.linkage\n"},
     "graphmech.geometry.kernels:3 imports graphmech.mechanisms.linkage (layers: geometry may not import mechanisms)"),
    ({"methods/velocity.py": "def f():\n    from graphmech.drawing import primitives\n"},
     "graphmech.methods.velocity:2 imports graphmech.drawing.primitives "
     "(layers: methods may not import drawing; function-level)"),
    ({"drawing/primitives.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
                               "    from graphmech.methods.polygons import Plan\n"},
     "graphmech.drawing.primitives:3 imports graphmech.methods.polygons "
     "(layers: drawing may not import methods; TYPE_CHECKING)"),
    ({"render/svg.py": "from ..methods.polygons import Plan\n"},
     "graphmech.render.svg:1 imports graphmech.methods.polygons (layers: render may not import methods)"),
    ({"problems/cam/check.py": "from graphmech.scene import load\n"},
     "graphmech.problems.cam.check:1 imports graphmech.scene (layers: problems may not import scene)"),
    ({"scene.py": "from graphmech.bench import run\n"},
     "graphmech.scene:1 imports graphmech.bench (layers: scene may not import bench)"),
    ({"bench.py": "from graphmech.cli import main\n", "cli.py": "import graphmech\n"},
     "graphmech.bench:1 imports graphmech.cli (layers: bench may not import cli)"),
    ({"timing.py": "def f():\n    from graphmech.render.svg import render\n"},
     "graphmech.timing:2 imports graphmech.render.svg (layers: base may not import render; function-level)"),
    ({"mechanisms/cam.py": "from graphmech.exact import linkage\n"},
     "graphmech.mechanisms.cam:1 imports graphmech.exact.linkage (layers: mechanisms may not import exact)"),
    ({"exact/cam.py": "from graphmech.geometry.primitives import Point\n"},
     "graphmech.exact.cam:1 imports graphmech.geometry.primitives (layers: exact may not import geometry)"),
    ({"exact/cam.py": "from graphmech.methods import polygons\n"},
     "graphmech.exact.cam:1 imports graphmech.methods.polygons (layers: exact may not import methods)"),
    ({"construction/graph.py": "from graphmech.mechanisms.cam import Cam\n", "mechanisms/cam.py": ""},
     "graphmech.construction.graph:1 imports graphmech.mechanisms.cam (layers: construction may not import mechanisms)"),
    ({"render/sheet.py": "from graphmech.problems import sheet\n"},
     "graphmech.render.sheet:1 imports graphmech.problems (layers: render may not import problems)"),
    ({"problems/linkage/bench.py": "import graphmech.cli\n"},
     "graphmech.problems.linkage.bench:1 imports graphmech.cli (layers: problems may not import cli)"),
], ids=_id)
def test_checker_catches_a_layer_violation(files, expected):
    assert violations({**CLEAN, **files}) == [expected]


def test_checker_finds_kinds_on_disk(tmp_path):
    pkg = make_package(tmp_path, {**CLEAN, "problems/gears/check.py": "from graphmech.scene import load\n"})
    assert kinds(pkg) == ["forces", "gears", "linkage"]
    assert layer_of("graphmech.problems.gears.check") == "problems"
    g = scan(pkg)
    assert layer_violations(g) == ["graphmech.problems.gears.check:1 imports graphmech.scene "
                                   "(layers: problems may not import scene)"]


def test_checker_classifies_by_the_longest_prefix():
    contracts = {"low": ("__init__ a", ""), "high": ("a.b", "low")}
    assert layer_of("graphmech", contracts) == "low"
    assert layer_of("graphmech.a.x", contracts) == "low"
    assert layer_of("graphmech.a.b", contracts) == "high"
    assert layer_of("graphmech.a.b.c", contracts) == "high"
    assert layer_of("graphmech.ab", contracts) is None  # a prefix is a whole name
    assert layer_of("graphmech.other", contracts) is None  # __init__ names graphmech/__init__.py alone
    assert layer_of("graphmech.__main__") == "main" and layer_of("graphmech") == "package"


def test_checker_wants_every_module_in_a_layer_and_every_import_to_exist():
    assert violations({**CLEAN, "gears.py": "", "cli.py": "from graphmech.gone import x\n"}) == [
        "graphmech.gears: in no layer (add it to CONTRACTS)",
        "graphmech.cli:1 imports graphmech.gone (no such module)",
    ]


def test_checker_finds_a_cycle_through_a_function_level_import():
    files = {**CLEAN, "problems/linkage/check.py": """
        from graphmech.methods.polygons import build
        def ic():
            from graphmech.problems.forces.check import build
        """}
    assert violations(files) == [
        "cycle 1: 2 modules, e.g. graphmech.problems.forces.check → graphmech.problems.linkage.check"
        " → graphmech.problems.forces.check",
        "  graphmech.problems.forces.check:1 imports graphmech.problems.linkage.check (cycle 1)",
        "  graphmech.problems.linkage.check:4 imports graphmech.problems.forces.check (cycle 1; function-level)",
    ]


def test_checker_reports_each_strongly_connected_component():
    g = scan_sources("graphmech", fake({
        "methods/a.py": "import graphmech.methods.b\n", "methods/b.py": "import graphmech.methods.c\n",
        "methods/c.py": "import graphmech.methods.a\nimport graphmech.methods.d\n",
        "methods/d.py": "", "methods/e.py": "from . import f\n", "methods/f.py": "from . import e\n"}))
    assert cycles(g) == [["graphmech.methods.a", "graphmech.methods.b", "graphmech.methods.c"],
                         ["graphmech.methods.e", "graphmech.methods.f"]]
    assert cycle_report(g)[0] == ("cycle 1: 3 modules, e.g. graphmech.methods.a → graphmech.methods.b"
                                  " → graphmech.methods.c → graphmech.methods.a")


@pytest.mark.parametrize("files, expected", [
    ({"problems/forces/figures.py": "from graphmech.problems.linkage.check import build, _guide_spans\n"},
     "graphmech.problems.forces.figures:1 imports graphmech.problems.linkage.check (private name _guide_spans)"),
    ({"scene.py": "def f():\n    from graphmech.mechanisms.linkage import _Reader as R\n"},
     "graphmech.scene:2 imports graphmech.mechanisms.linkage (private name _Reader; function-level)"),
    ({"bench.py": "import graphmech.methods.polygons\nx = graphmech.methods.polygons._frozen\n"},
     "graphmech.bench:2 imports graphmech.methods.polygons (private name _frozen, read as an attribute)"),
    ({"bench.py": "from graphmech.methods import polygons as p\ndef f():\n    return p._frozen(1)\n"},
     "graphmech.bench:3 imports graphmech.methods.polygons (private name _frozen, read as an attribute)"),
    ({"bench.py": "from graphmech.methods._impl import plan\n", "methods/_impl.py": ""},
     "graphmech.bench:1 imports graphmech.methods._impl (private module graphmech.methods._impl)"),
], ids=_id)
def test_checker_catches_a_private_import(files, expected):
    assert violations({**CLEAN, **files}) == [expected]


def test_checker_allows_dunders_own_privates_and_private_modules_at_home():
    files = {**CLEAN,
             "cli.py": "from graphmech import __version__\nfrom graphmech.methods.polygons import build as _build\n",
             "methods/_impl.py": "def _x(): ...\nx = _x\n",
             "methods/velocity.py": "from graphmech.methods._impl import x\nfrom . import _impl\n",
             # a parameter named like an imported module is not that module
             "exact/cam.py": "from graphmech.mechanisms import linkage\ndef f(linkage):\n    return linkage._cache\n"}
    assert violations(files) == []


@pytest.mark.parametrize("source, expected", [
    ("import importlib\nm = importlib.import_module('graphmech.methods.polygons')\n",
     "graphmech.problems:3 imports graphmech.methods.polygons (dynamic import: import it directly)"),
    ("from importlib import import_module as im\ndef f(name):\n    return im(name)\n",
     "graphmech.problems:4 imports im(name) (dynamic import: import it directly; function-level)"),
    ("m = __import__('graphmech.render.svg')\n",
     "graphmech.problems:2 imports graphmech.render.svg (dynamic import: import it directly)"),
    ("CHECK = ('graphmech.problems.linkage.check', 'analyse')\n",
     "graphmech.problems:2 imports graphmech.problems.linkage.check "
     "(module named in a string: import it directly)"),
], ids=["importlib", "alias-of-import_module", "__import__", "string"])
def test_checker_catches_a_dynamic_import(source, expected):
    # the docstring names a module too: a docstring is no import
    assert violations({**CLEAN, "problems/__init__.py": '"""graphmech.scene"""\n' + source}) == [expected]


def test_a_dynamic_import_with_a_literal_is_an_edge():
    files = {**CLEAN, "drawing/primitives.py": "import importlib\nimportlib.import_module('graphmech.render.svg')\n"}
    assert violations(files) == [
        "graphmech.drawing.primitives:2 imports graphmech.render.svg (layers: drawing may not import render)",
        "graphmech.drawing.primitives:2 imports graphmech.render.svg (dynamic import: import it directly)",
        "cycle 1: 2 modules, e.g. graphmech.drawing.primitives → graphmech.render.svg → graphmech.drawing.primitives",
        "  graphmech.drawing.primitives:2 imports graphmech.render.svg (cycle 1)",
        "  graphmech.render.svg:1 imports graphmech.drawing.primitives (cycle 1)",
    ]


def test_the_contracts_table_is_a_layering():
    """Every layer named exists, no module is claimed twice, the layers form no cycle, only main imports cli."""
    prefixes = [p for modules, _ in CONTRACTS.values() for p in modules.split()]
    assert len(prefixes) == len(set(prefixes))
    assert all(b in CONTRACTS and b != a for a, (_, allowed) in CONTRACTS.items() for b in allowed.split())
    g = Graph("layers", {layer: layer for layer in CONTRACTS},
              [Import(a, 0, b) for a, (_, allowed) in CONTRACTS.items() for b in allowed.split()])
    assert cycles(g) == []
    assert [a for a in CONTRACTS if "cli" in may_import(a)] == ["cli", "main"]


def test_checker_sees_what_the_registry_loads(tmp_path):
    make_package(tmp_path, {**CLEAN, "problems/cam/check.py": "", "problems/cam/scene.py": ""})
    assert loaded_by_the_registry(tmp_path) == []
    make_package(tmp_path, {"problems/__init__.py": "from graphmech.problems.cam import check, scene\n"})
    assert loaded_by_the_registry(tmp_path) == ["graphmech.problems.cam.check", "graphmech.problems.cam.scene"]


# ---------------------------------------------------------------------------- the registry


def test_every_kind_package_is_registered_once_and_nothing_else_lists_the_kinds():
    """Each package under problems/ that states a KIND is in graphmech.problems.KINDS, under its
    own name; the Scene record has one ``problem`` field, none per kind."""
    import dataclasses
    import importlib

    from graphmech.problems import KINDS
    from graphmech.problems.reader import Scene

    stated = {}
    for pkg in sorted(p.parent.name for p in (ROOT / "graphmech" / "problems").glob("*/__init__.py")):
        module = importlib.import_module(f"graphmech.problems.{pkg}")
        if hasattr(module, "KIND"):
            stated[module.KIND.name] = module.KIND
    assert stated and stated.keys() == KINDS.keys()
    assert all(KINDS[name] is kind for name, kind in stated.items())
    fields = {f.name for f in dataclasses.fields(Scene)}
    # (``linkage`` is the mechanism several kinds share — forces, a flywheel's machine — not a kind's part)
    assert {"kind", "problem"} <= fields and not fields & (set(KINDS) - {"linkage"})
    tables = [t for k in KINDS.values() for t in k.tables]
    assert len(tables) == len(set(tables))  # a table poses one kind


def test_a_scene_of_each_kind_reads_as_that_kind():
    """Every reference scene reads as the kind its file name says (fly.* a flywheel …), the
    exceptions named one by one; and together they cover every kind."""
    from graphmech.problems import KINDS
    from graphmech.scene import load_scene

    by_prefix = {"cam": "cam", "fly": "flywheel", "force": "forces", "bal": "balancing", "eff": "efficiency",
                 "thread": "efficiency", "dof": "structure", "structure": "structure", "ic": "linkage",
                 "kin": "linkage", "linkage": "cycle", "gear": "gears", "train": "trains", "synthesis": "synthesis",
                 "mech": "other"}
    exceptions = {"fly.compressor_course_project-cycle": "cycle",  # the compressor's linkage through a turn
                  "force.wedge_F1430": "efficiency",  # a wedge: forces alone, no mechanism
                  "linkage.slider_crank_offset": "linkage", "linkage.slider_fixed_angle_guide": "linkage",
                  "linkage.offset_guide_bar": "linkage",
                  "linkage.crank_rocker_synthesis_K1.5": "synthesis",  # the bank's id: a linkage designed
                  "ic.friction_planetary": "centres"}  # wheels in rolling contact: no linkage, its direct centres
    got = {p.stem: load_scene(p).kind for p in sorted((ROOT / "figures" / "scenes").glob("*.toml"))}
    want = {stem: exceptions.get(stem, by_prefix[stem.split(".")[0]]) for stem in got}
    assert got == want
    assert set(got.values()) == set(KINDS)
