"""The layering the code relies on (docs/architecture.md): every module has a layer, no module
imports a module of a higher layer (imports inside functions count), there is no import circle,
stages share only the model layer and the domain packages, only the model layer opens
artifacts with h5py, one class is the rig and one word names one concept."""

import ast
import sys
from pathlib import Path

import pytest

import facesynth

PACKAGE = Path(facesynth.__file__).parent

#: The layers, lowest first; a module may import its own layer and those below it.
LAYERS = ("base", "formats", "model", "domain", "stages", "cli")

#: Module or package -> layer; the longest matching prefix decides. A new module needs a line
#: here (test_every_module_has_a_layer), so placing it is a decision, not an accident.
LAYER_OF = {
    # base: the package itself, errors, settings, limits, phone sets, OpenCL, progress, hashing,
    # and the stage declarations (standard library only); nothing here reads an artifact
    "facesynth": "base",
    "facesynth.base.errors": "base",
    "facesynth.base.config": "base",
    "facesynth.base.limits": "base",
    "facesynth.base.phonemes": "base",
    "facesynth.base.opencl": "base",
    "facesynth.base.progress": "base",
    "facesynth.base.hashing": "base",
    "facesynth.base.pipeline": "base",
    # formats: files other tools write or read (C3D, TRC, OBJ, PLY, TextGrid, WAV, glTF)
    "facesynth.formats": "formats",
    # model: the artifact contract, its specification and checker, and one reader/writer per kind
    "facesynth.model.artifacts": "model",
    "facesynth.model.check": "model",
    "facesynth.model": "model",
    # domain: the methods and everything they need, working on arrays and model objects
    "facesynth.domain.speech.alignment": "domain",
    "facesynth.domain.speech.recognition": "domain",
    "facesynth.domain.evaluation.bootstrap": "domain",
    "facesynth.domain.evaluation.baselines": "domain",
    "facesynth.domain.evaluation.held_out": "domain",
    "facesynth.domain.rig.face": "domain",
    "facesynth.domain.database.contamination": "domain",
    "facesynth.domain.database.embedding": "domain",
    "facesynth.domain.methods": "domain",
    "facesynth.domain.search": "domain",
    "facesynth.domain.postprocess": "domain",
    "facesynth.domain.expression": "domain",
    "facesynth.domain.retarget": "domain",
    "facesynth.domain.rendering": "domain",
    "facesynth.domain.exports": "domain",
    "facesynth.domain.corpus": "domain",
    "facesynth.domain.live": "domain",
    "facesynth.domain.batch": "domain",
    # stages: one module per command, reading artifacts, calling the domain, writing artifacts
    "facesynth.stages": "stages",
    # cli: parsing and printing
    "facesynth.cli": "cli",
    "facesynth.__main__": "cli",
}

#: Imports of a higher layer that are known and wait for their callers to move, with the reason;
#: test_known_exceptions_are_still_needed fails once one is gone, so this list only shrinks.
KNOWN_UPWARD = {
    ("facesynth.model.motiondb", "facesynth.domain.search.pairs"):
        "MotionDatabase.read_features/transition_costs/write build the search's PairFeatures and "
        "TransitionCosts; callers throughout the methods use these accessors",
}

#: Modules that import only the standard library (they are read before anything is installed
#: or configured: the stage declarations).
STDLIB_ONLY = ("facesynth.base.pipeline",)


def _modules() -> dict[str, Path]:
    """Every module of the package by dotted name (a package by its ``__init__``)."""
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


MODULES = _modules()


def _imports(path: Path) -> set[str]:
    """Absolute names of the facesynth modules ``path`` imports, anywhere in the file (inside
    functions too); ``from package import name`` counts as importing the module ``name`` when
    there is one."""
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    if parts[-1] == "__init__":
        parts = parts + ("",)  # relative imports of a package start at the package itself
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = list(parts[: len(parts) - node.level])
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            out.add(module)
            out.update(f"{module}.{a.name}" for a in node.names if f"{module}.{a.name}" in MODULES)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return {_known(m) for m in out if m.split(".")[0] == "facesynth"} - {None}


def _known(name: str) -> str | None:
    """The module ``name`` refers to (an attribute's module for ``pkg.mod.attr``)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


GRAPH = {name: _imports(path) - {name} for name, path in MODULES.items()}


def layer(module: str) -> str | None:
    """The layer of ``module`` by the longest prefix in :data:`LAYER_OF`."""
    name = module
    while name:
        if name in LAYER_OF:
            return LAYER_OF[name]
        name = name.rpartition(".")[0]
    return None


def test_every_module_has_a_layer():
    assert [m for m in MODULES if layer(m) is None] == []


def test_no_module_imports_a_higher_layer():
    upward = sorted(f"{m} ({layer(m)}) imports {t} ({layer(t)})" for m, targets in GRAPH.items() for t in targets
                    if LAYERS.index(layer(t)) > LAYERS.index(layer(m)) and (m, t) not in KNOWN_UPWARD)
    assert upward == []


def test_known_exceptions_are_still_needed():
    assert [pair for pair in KNOWN_UPWARD if pair[1] not in GRAPH.get(pair[0], set())] == []


def test_no_import_circle():
    """No strongly connected component of more than one module in the import graph (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    circles = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(GRAPH[v]):
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
    sys.setrecursionlimit(max(limit, 10 * len(GRAPH)))
    try:
        for v in sorted(GRAPH):
            if v not in index:
                visit(v)
    finally:
        sys.setrecursionlimit(limit)
    assert circles == []


def test_the_circle_finder_finds_a_circle(monkeypatch):
    """The test above can fail: an artificial circle through two real modules is found."""
    graph = {m: set(t) for m, t in GRAPH.items()}
    graph["facesynth.base.errors"].add("facesynth.base.config")  # config imports errors
    monkeypatch.setitem(globals(), "GRAPH", graph)
    with pytest.raises(AssertionError):
        test_no_import_circle()


def test_no_domain_module_imports_a_stage():
    crossing = sorted(f"{m} -> {t}" for m, targets in GRAPH.items() for t in targets
                      if t.startswith("facesynth.stages") and layer(m) not in ("stages", "cli"))
    assert crossing == []


def test_no_stage_imports_another_stage():
    crossing = sorted(f"{m} -> {t}" for m, targets in GRAPH.items() if m.startswith("facesynth.stages.")
                      for t in targets if t.startswith("facesynth.stages.") and t != m)
    assert crossing == []


def test_stdlib_only_modules_import_only_the_standard_library():
    for name in STDLIB_ONLY:
        if name not in MODULES:
            continue
        tree = ast.parse(MODULES[name].read_text(encoding="utf-8"))
        roots = {a.name.split(".")[0] for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
        roots |= {"." if n.level else (n.module or "").split(".")[0] for n in ast.walk(tree)
                  if isinstance(n, ast.ImportFrom)}
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


def test_one_module_named_expression():
    """``expression`` names the command (and its artifact kind) only; the style model is
    ``facesynth.domain.expression``, the actress's non-speech face ``facesynth.domain.corpus.nonspeech``."""
    assert [m for m in MODULES if m.rpartition(".")[2] == "expression"] == ["facesynth.stages.expression"]


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
    assert "facesynth.base.opencl" in GRAPH["facesynth.model.artifacts"]  # imported inside read()
    assert layer("facesynth.stages.deform") == "stages" and layer("facesynth.model.spec") == "model"
