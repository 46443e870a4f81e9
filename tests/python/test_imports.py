"""The package `rockingwall` has no import cycle and uses no private name of another of its modules.

Every module is parsed with `ast` (not imported): imports at module level and inside functions
both count, relative imports are resolved against the importing module's package. An import
cycle is a strongly connected group of modules in that graph; a private name is one that starts
with `_` (not a dunder such as `__version__`), used across modules as `from X import _name`,
`import X._name`, `from X._name import y` or `X._name` with X a module of the package."""
import ast
import pathlib

PACKAGE_DIR = pathlib.Path(__file__).resolve().parents[2] / "python" / "rockingwall"


def is_private(name):
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def module_names(root):
    """{dotted module name: path} of every .py file under the package folder `root`."""
    out = {}
    for path in sorted(root.rglob("*.py")):
        parts = [root.name, *path.relative_to(root).with_suffix("").parts]
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


def _base(module, path, node):
    """The dotted name an ImportFrom node imports from (relative imports resolved)."""
    if node.level == 0:
        return node.module or ""
    package = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    package = package[:len(package) - (node.level - 1)]
    return ".".join(package + ([node.module] if node.module else []))


class Imports:
    """The intra-package imports of one module: edges (to module names) and private-name uses."""

    def __init__(self, module, path, modules):
        self.module, self.path, self.modules = module, path, modules
        self.edges, self.private, self.bound = set(), [], {}

    def target(self, dotted):
        """The longest module of the package that `dotted` names (a.b.c -> a.b if c is a name)."""
        parts = dotted.split(".")
        while parts and ".".join(parts) not in self.modules:
            parts.pop()
        return ".".join(parts) if parts else None

    def add(self, dotted, line, what):
        target = self.target(dotted)
        if target is None:
            return None
        if target != self.module:
            self.edges.add(target)
        if any(is_private(part) for part in dotted.split(".")):
            self.private.append((line, what))
        return target

    def visit(self, tree):
        root = next(iter(self.modules)).split(".")[0]
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.split(".")[0] == root:
                        target = self.add(alias.name, node.lineno, f"import {alias.name}")
                        if target:
                            self.bound[alias.asname or alias.name.split(".")[0]] = (
                                target if alias.asname else root)
            elif isinstance(node, ast.ImportFrom):
                base = _base(self.module, self.path, node)
                if base.split(".")[0] != root:
                    continue
                for alias in node.names:
                    full = f"{base}.{alias.name}"
                    what = f"from {'.' * node.level}{node.module or ''} import {alias.name}"
                    target = self.add(full if full in self.modules else base, node.lineno, what)
                    if full not in self.modules and is_private(alias.name) and target:
                        self.private.append((node.lineno, what))
                    if full in self.modules:
                        self.bound[alias.asname or alias.name] = full
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and is_private(node.attr):
                chain = _dotted(node)
                if chain and chain.split(".")[0] in self.bound:
                    self.private.append((node.lineno, f"{chain} ({self.bound[chain.split('.')[0]]})"))


def _dotted(node):
    """'a.b.c' for an attribute chain on a name, else None."""
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    return ".".join([node.id, *reversed(parts)]) if isinstance(node, ast.Name) else None


def analyse(root):
    """(graph {module: set of modules it imports}, [private-name uses]) of the package at root."""
    modules = module_names(root)
    graph, private = {}, []
    for module, path in modules.items():
        imports = Imports(module, path, modules)
        imports.visit(ast.parse(path.read_text(), filename=str(path)))
        graph[module] = imports.edges
        private += [f"{module}:{line}: {what}" for line, what in sorted(imports.private)]
    return graph, private


def cycles(graph):
    """The strongly connected groups of more than one module, or of one that imports itself
    (Tarjan's algorithm), each sorted."""
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def connect(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1 or v in graph.get(v, ()):
                out.append(sorted(group))

    for v in sorted(graph):
        if v not in index:
            connect(v)
    return out


def longest_chain(graph):
    """The longest import chain (a list of modules) of an acyclic graph."""
    best = {}

    def chain(v):
        if v not in best:
            best[v] = [v] + max((chain(w) for w in graph[v]), key=len, default=[])
        return best[v]

    return max((chain(v) for v in sorted(graph)), key=len)


# ---- the analysis itself, on small packages written here ------------------------------------

def write_package(root, files):
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def test_a_cycle_through_a_function_level_relative_import_is_found(tmp_path):
    pkg = write_package(tmp_path / "pkg", {
        "__init__.py": "",
        "a.py": "from .sub import b\n",
        "sub/__init__.py": "",
        "sub/b.py": "def f():\n    from ..c import g\n",
        "c.py": "import pkg.a\n",
        "d.py": "from . import a\n",
    })
    graph, _ = analyse(pkg)
    assert graph["pkg.a"] == {"pkg.sub.b"} and graph["pkg.sub.b"] == {"pkg.c"} and graph["pkg.c"] == {"pkg.a"}
    assert cycles(graph) == [["pkg.a", "pkg.c", "pkg.sub.b"]]


def test_an_acyclic_package_has_no_cycle_and_its_longest_chain(tmp_path):
    pkg = write_package(tmp_path / "pkg", {
        "__init__.py": "from .a import x\n",
        "a.py": "from . import b\n",
        "b.py": "from .c import y\n",
        "c.py": "import os\n",
    })
    graph, private = analyse(pkg)
    assert cycles(graph) == [] and private == []
    assert longest_chain(graph) == ["pkg", "pkg.a", "pkg.b", "pkg.c"]


def test_private_names_across_modules_are_found(tmp_path):
    pkg = write_package(tmp_path / "pkg", {
        "__init__.py": "__version__ = '1'\n",
        "a.py": "from .b import _helper, public\nfrom . import __version__\n",
        "b.py": "def _helper(): pass\ndef public(): return _helper()\n",
        "c.py": "from . import b\nimport pkg.b\ndef f():\n    return b._helper(), pkg.b._helper()\n",
        "d.py": "from . import _e\n",
        "_e.py": "",
        "f.py": "from ._e import x\n",
    })
    _, private = analyse(pkg)
    assert [p.split(":")[0] for p in private] == ["pkg.a", "pkg.c", "pkg.c", "pkg.d", "pkg.f"], private


# ---- the package ---------------------------------------------------------------------------

def test_the_package_has_no_import_cycle():
    found = cycles(analyse(PACKAGE_DIR)[0])
    assert not found, "import cycles in rockingwall:\n" + "\n".join(" <-> ".join(c) for c in found)


def test_the_package_imports_no_private_name_of_another_module():
    private = analyse(PACKAGE_DIR)[1]
    assert not private, "private names used across modules:\n" + "\n".join(private)
