"""The layering the code relies on (docs/architecture.md): a module's layer is its folder, no
module imports a module of a higher layer (imports inside functions count), there is no import
circle between modules nor between packages, imports inside functions are the few listed with
their reason, stages share only the model layer and the domain packages, only the model layer
opens artifacts with h5py, one class is the rig and one word names one concept."""

import ast
import sys
from pathlib import Path

import facesynth

PACKAGE = Path(facesynth.__file__).parent

#: The layers, lowest first; a module may import its own layer and those below it. A module's
#: layer is its folder: facesynth/<layer>/..., the package itself is base, cli is cli.
LAYERS = ("base", "formats", "model", "domain", "api", "stages", "cli")
#: The only modules at the top of the package.
TOP_LEVEL = ("facesynth", "facesynth.__main__", "facesynth.cli")

#: Imports of facesynth modules inside functions outside the CLI (whose commands load their stage
#: when they run), each with its reason: (importing module, imported module) -> reason.
DEFERRED = {
}

#: The domain's subject packages in the order they may import one another: each imports only
#: those before it (and base, formats, model). docs/architecture.md's table says what each holds.
DOMAIN_ORDER = ("postprocess", "geometry", "speech", "head_motion", "rig", "search", "retarget", "voice", "rendering",
                "expression", "database", "corpus", "capture", "methods", "live", "exports", "evaluation", "batch")

#: Modules that import only the standard library (they are read before anything is installed
#: or configured: the stage declarations, the registries).
STDLIB_ONLY = ("facesynth.base.errors", "facesynth.base.pipeline", "facesynth.base.registry")


def _modules() -> dict[str, Path]:
    """Every module of the package by dotted name (a package by its ``__init__``)."""
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


MODULES = _modules()


def _imports_with_place(path: Path, tree: ast.AST | None = None) -> list[tuple[str, int]]:
    """(module, id of the import statement in ``tree``, the file's parse, parsed here when None)
    for every facesynth module ``path`` imports, anywhere in the file (inside functions too);
    ``from package import name`` counts as importing the module ``name`` when there is one. The
    ids name nodes of ``tree`` only while it lives: a caller comparing them keeps it."""
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    if parts[-1] == "__init__":
        parts = parts + ("",)  # relative imports of a package start at the package itself
    out = []
    for node in ast.walk(tree if tree is not None else ast.parse(path.read_text(encoding="utf-8"))):
        names = set()
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = list(parts[: len(parts) - node.level])
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            names.add(module)
            names.update(f"{module}.{a.name}" for a in node.names if f"{module}.{a.name}" in MODULES)
        elif isinstance(node, ast.Import):
            names.update(a.name for a in node.names)
        out.extend((known, id(node)) for m in names if m.split(".")[0] == "facesynth" and (known := _known(m)))
    return out


def _imports(path: Path) -> set[str]:
    """Absolute names of the facesynth modules ``path`` imports, anywhere in the file."""
    return {m for m, _ in _imports_with_place(path)}


def _known(name: str) -> str | None:
    """The module ``name`` refers to (an attribute's module for ``pkg.mod.attr``)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


GRAPH = {name: _imports(path) - {name} for name, path in MODULES.items()}


def layer(module: str) -> str | None:
    """The layer of ``module``: its folder under the package (the package itself: base)."""
    parts = module.split(".")
    if module in ("facesynth.cli", "facesynth.__main__"):
        return "cli"
    if len(parts) == 1:
        return "base"
    return parts[1] if parts[1] in LAYERS else None


def package(module: str) -> str:
    """The package ``module`` belongs to: its layer's folder, or for the domain its subject's
    package (``facesynth.domain.search``)."""
    parts = module.split(".")
    return ".".join(parts[:3] if len(parts) > 2 and parts[1] == "domain" else parts[:2])


def _deferred(path: Path) -> set[str]:
    """The facesynth modules ``path`` imports inside functions."""
    # one parse for both: ids of two parses' nodes can coincide once the first is freed
    tree = ast.parse(path.read_text(encoding="utf-8"))
    inside = set()
    for fn in ast.walk(tree):
        if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
            inside.update(id(n) for n in ast.walk(fn) if isinstance(n, (ast.Import, ast.ImportFrom)))
    return {m for m, where in _imports_with_place(path, tree) if where in inside}


def _circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one node (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    circles = []

    def visit(v: str) -> None:
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
                circles.append(sorted(component))

    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 10 * len(graph)))
    try:
        for v in sorted(graph):
            if v not in index:
                visit(v)
    finally:
        sys.setrecursionlimit(limit)
    return circles


PACKAGE_GRAPH: dict[str, set[str]] = {}
for _module, _targets in GRAPH.items():
    PACKAGE_GRAPH.setdefault(package(_module), set()).update(package(t) for t in _targets
                                                             if package(t) != package(_module))


def test_every_module_has_a_layer():
    assert [m for m in MODULES if layer(m) is None] == []


def test_the_top_level_holds_only_the_package_and_the_cli():
    """From a file's path its layer is known: the top of the package holds the package, its
    ``__main__`` and the CLI; every other module lives in its layer's folder."""
    top_modules = sorted(p.stem for p in PACKAGE.glob("*.py") if p.stem != "__init__")
    assert top_modules == ["cli"] or top_modules == ["__main__", "cli"]
    code_folders = sorted(p.name for p in PACKAGE.iterdir() if p.is_dir() and (p / "__init__.py").exists())
    assert code_folders == sorted(LAYERS[:-1])


def test_no_module_imports_a_higher_layer():
    upward = sorted(f"{m} ({layer(m)}) imports {t} ({layer(t)})" for m, targets in GRAPH.items() for t in targets
                    if LAYERS.index(layer(t)) > LAYERS.index(layer(m)))
    assert upward == []


def test_no_import_circle():
    """No strongly connected component of more than one module in the import graph."""
    assert _circles(GRAPH) == []


def test_no_package_import_circle():
    """No circle between packages either (a layer's folder; the domain's subject packages),
    imports inside functions included: each package can be read knowing only those below it."""
    assert _circles(PACKAGE_GRAPH) == []


def test_the_domain_packages_import_only_those_before_them():
    domain = {p.rpartition(".")[2] for p in PACKAGE_GRAPH if p.startswith("facesynth.domain.")}
    assert sorted(domain - set(DOMAIN_ORDER)) == []  # a new package needs its place in the order
    later = sorted(f"{p} imports {t}" for p, targets in PACKAGE_GRAPH.items() if p.startswith("facesynth.domain.")
                   for t in targets if t.startswith("facesynth.domain.")
                   and DOMAIN_ORDER.index(t.rpartition(".")[2]) > DOMAIN_ORDER.index(p.rpartition(".")[2]))
    assert later == []


def test_the_circle_finder_finds_a_circle():
    """The tests above can fail: an artificial circle through two real modules is found, and one
    through two real packages."""
    graph = {m: set(t) for m, t in GRAPH.items()}
    graph["facesynth.base.errors"].add("facesynth.base.config")  # config imports errors
    assert _circles(graph) != []
    packages = {p: set(t) for p, t in PACKAGE_GRAPH.items()}
    packages["facesynth.domain.rig"].add("facesynth.domain.rendering")  # rendering imports the rig
    assert _circles(packages) != []


def test_imports_inside_functions_are_the_listed_ones():
    """Imports of facesynth modules inside functions (outside the CLI) are only those listed with
    their reason in DEFERRED, at most ten."""
    found = {(m, t) for m, path in MODULES.items() if layer(m) != "cli" for t in _deferred(path) if t != m}
    assert sorted(found - set(DEFERRED)) == []
    assert sorted(set(DEFERRED) - found) == []
    assert len(DEFERRED) <= 10


def test_no_module_imports_a_stage():
    """The stages are the command line's, reached through the stage table: the domain and the API
    (below them) import none, and ``cli.py`` calls each command's core as its
    :class:`~facesynth.base.pipeline.Stage` declares it (``Context.core``), importing none by hand."""
    crossing = sorted(f"{m} -> {t}" for m, targets in GRAPH.items() for t in targets
                      if t.startswith("facesynth.stages") and layer(m) != "stages")
    assert crossing == []


def test_no_stage_imports_another_stage():
    crossing = sorted(f"{m} -> {t}" for m, targets in GRAPH.items() if m.startswith("facesynth.stages.")
                      for t in targets if t.startswith("facesynth.stages.") and t != m)
    assert crossing == []


#: The most lines a stage module may have beside its result classes (docs/architecture.md, "How to
#: add a stage"): a stage reads its inputs, calls the domain and writes its outputs.
STAGE_MAX_LINES = 150


def stage_lines(path: Path) -> int:
    """Lines of the stage module ``path`` not counting its result classes (top-level classes whose
    name ends with ``Result``, decorators included)."""
    source = path.read_text(encoding="utf-8")
    results = sum(node.end_lineno - min([node.lineno] + [d.lineno for d in node.decorator_list]) + 1
                  for node in ast.parse(source).body
                  if isinstance(node, ast.ClassDef) and node.name.endswith("Result") and node.end_lineno)
    return len(source.splitlines()) - results


def test_stage_line_counting_leaves_out_only_result_classes(tmp_path):
    stage = tmp_path / "toy.py"
    stage.write_text("import dataclasses\n\n\n@dataclasses.dataclass(frozen=True)\nclass ToyResult:\n    n: int\n\n\n"
                     "class Helper:\n    pass\n\n\ndef run() -> ToyResult:\n    return ToyResult(1)\n", encoding="utf-8")
    assert stage_lines(stage) == 14 - 3  # the decorator and the class's two lines are not counted


def test_no_stage_module_holds_an_algorithm():
    """A stage module is at most STAGE_MAX_LINES lines beside its result classes: the algorithm
    lives in the domain package of its subject."""
    long = sorted(f"{m}: {n} lines" for m, path in MODULES.items() if layer(m) == "stages"
                  and (n := stage_lines(path)) > STAGE_MAX_LINES)
    assert long == []


def test_stdlib_only_modules_import_only_the_standard_library():
    for name in STDLIB_ONLY:
        if name not in MODULES:
            continue
        tree = ast.parse(MODULES[name].read_text(encoding="utf-8"))
        roots = {a.name.split(".")[0] for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
        roots |= {"." if n.level else (n.module or "").split(".")[0] for n in ast.walk(tree)
                  if isinstance(n, ast.ImportFrom)}
        if GRAPH[name] <= set(STDLIB_ONLY):  # relative imports of other modules of this list only
            roots.discard(".")
        assert sorted(r for r in roots if r not in sys.stdlib_module_names and r != "__future__") == [], name


def test_only_the_model_layer_and_the_artifact_contract_use_h5py():
    users = sorted(m for m, path in MODULES.items()
                   if layer(m) != "model" and "h5py" in {n.split(".")[0] for n in _raw_imports(path)})
    assert users == []


def _raw_imports(path: Path) -> set[str]:
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and not node.level and node.module:
            out.add(node.module)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return out


def _classes() -> list[tuple[str, str]]:
    return [(m, node.name) for m, path in MODULES.items()
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))) if isinstance(node, ast.ClassDef)]


def test_one_rig_class():
    """The built-in rig and a user's rig are one class: no second class named ...Rig."""
    assert [(m, c) for m, c in _classes() if c.endswith("Rig")] == [("facesynth.domain.rig.face", "Rig")]


def test_one_name_for_the_expression_model():
    """The expression model (Chuang & Bregler's bilinear style/content model) is ``expression``
    everywhere: the command, its artifact's module and the domain package; nothing else is called
    expression and nothing is called style."""
    assert [m for m in MODULES if m.rpartition(".")[2] == "expression"] == [
        "facesynth.domain.expression", "facesynth.model.expression", "facesynth.stages.expression"]
    assert [m for m in MODULES if "style" in m.rpartition(".")[2]] == []
    assert [(m, c) for m, c in _classes() if c.startswith("Style")] == []


def test_one_module_per_name_for_live_link():
    """The Live Link Face CSV (a file format) and the Live Link packet (the live transport) are
    two modules with two names."""
    assert sorted(m for m in MODULES if "livelink" in m) == ["facesynth.domain.live.livelink",
                                                              "facesynth.formats.livelink_face"]


def test_the_glTF_format_is_read_and_written_in_one_module():
    """Only formats.gltf builds glTF (pygltflib) or parses a GLB container (its b"glTF" magic)."""
    def touches_gltf(path: Path) -> bool:
        tree = ast.parse(path.read_text(encoding="utf-8"))
        return "pygltflib" in {n.split(".")[0] for n in _raw_imports(path)} or any(
            isinstance(n, ast.Constant) and n.value == b"glTF" for n in ast.walk(tree))

    assert [m for m, path in MODULES.items() if touches_gltf(path)] == ["facesynth.formats.gltf"]


def test_the_layer_map_sees_the_imports():
    """The rules above can fail: the graph has the imports they check (a stage's import of the
    model and the domain, a deferred import inside a function)."""
    assert {"facesynth.model.motion", "facesynth.domain.retarget.deform"} <= GRAPH["facesynth.stages.deform"]
    assert "facesynth.base.opencl" in GRAPH["facesynth.model.artifacts"]
    assert layer("facesynth.stages.deform") == "stages" and layer("facesynth.model.spec") == "model"


def test_the_tree_in_the_docs_lists_every_module():
    """docs/architecture.md's tree names every module of every layer and domain package, in
    DOMAIN_ORDER, and no module that is gone."""
    text = (Path(__file__).parent.parent / "docs" / "architecture.md").read_text(encoding="utf-8")
    block = text.split("### The tree", 1)[1].split("```text\n", 1)[1].split("```", 1)[0]
    listed: dict[str, set[str]] = {}
    folder = ""
    for line in block.splitlines()[2:]:  # after "facesynth/" and "cli.py"
        head, _, rest = line.strip().partition("/")
        if line.startswith("    ") and not line.startswith("      ") or line.startswith("  ") and not line.startswith("    "):
            folder = ("domain/" + head) if line.startswith("    ") else head
            listed[folder] = set(rest.split()) - {"(__init__.py", "only)"}
        else:
            listed[folder] |= set(line.split())
    listed.pop("domain", None)
    root = PACKAGE
    present = {str(d.relative_to(root)): {p.stem for p in d.glob("*.py") if p.stem != "__init__"}
               for d in [root / name for name in ("base", "formats", "model", "api", "stages")]
               + [root / "domain" / pkg for pkg in DOMAIN_ORDER]}
    assert listed == present
    domain_order = [f for f in listed if f.startswith("domain/")]
    assert domain_order == [f"domain/{pkg}" for pkg in DOMAIN_ORDER]
    assert not (set(p.name for p in (root / "domain").iterdir() if (p / "__init__.py").exists()) - set(DOMAIN_ORDER))
