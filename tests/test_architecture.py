"""The layering the code relies on: stages share only the model layer and the domain
packages, and only the model layer opens artifacts with h5py."""

import ast
from pathlib import Path

import facesynth

PACKAGE = Path(facesynth.__file__).parent


def _imports(path: Path) -> set[str]:
    """Absolute names of the facesynth modules ``path`` imports."""
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = list(parts[: len(parts) - node.level])
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            out.add(module)
            if not node.module:  # "from . import x" imports the module x
                out.update(f"{module}.{a.name}" for a in node.names)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return {m for m in out if m.startswith("facesynth")}


def test_no_stage_imports_another_stage():
    stages = {p.stem for p in (PACKAGE / "stages").glob("*.py")} - {"__init__"}
    crossing = []
    for path in sorted((PACKAGE / "stages").glob("*.py")):
        for module in _imports(path):
            target = module.split(".")
            if len(target) >= 3 and target[1] == "stages" and target[2] in stages and target[2] != path.stem:
                crossing.append(f"{path.stem} -> {target[2]}")
    assert not crossing


def test_only_the_model_layer_and_the_artifact_contract_use_h5py():
    allowed = {"artifacts.py", "check.py"}
    users = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE)
        if rel.parts[0] == "model" or rel.name in allowed:
            continue
        if "h5py" in {m.split(".")[0] for m in _raw_imports(path)}:
            users.append(str(rel))
    assert not users


def _raw_imports(path: Path) -> set[str]:
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and not node.level and node.module:
            out.add(node.module)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return out
