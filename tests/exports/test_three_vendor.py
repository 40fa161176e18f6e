"""The vendored three.js of the web player (``facesynth/data/three.*``) is the release pinned in
package.json and package-lock.json, as ``make vendor`` makes it: the files' sha256 are the table
below, their version (``REVISION`` in the core build) is package.json's, and, where ``make vendor``
has installed node_modules/, the files are the ones it makes from there (the core and module
builds minified by the pinned terser, the orbit controls and the licence copied)."""

import hashlib
import json
import re
import shutil
import subprocess
from importlib import resources
from pathlib import Path

import pytest

ROOT = next(p for p in Path(__file__).resolve().parents if (p / "pyproject.toml").is_file())
DATA = resources.files("facesynth").joinpath("data")
THREE = ROOT / "node_modules" / "three"

#: sha256 of the vendored files (three 0.187.0; terser 5.51.4 for the two minified builds).
SHA256 = {
    "three.core.js": "b9c27899329d4733334570329d070e93cbbb1aadbabd05075726c7c886c88739",
    "three.module.js": "4ac07dcf780ff92ebc742a83146e0e43156f9d6a2af19bdeaef18caae46866cb",
    "three.OrbitControls.js": "e7fca2fe9e7670a828af9b28084669a5909445b7f36f1f26cee9bf8f2961c32c",
    "three.LICENSE": "8b378ebe60e2fe500158cb0ac71cb5e8b7d92953c2abcc63a0eb90499653b5bc",
}
#: Where `make vendor` takes each vendored file from, and whether it minifies it.
SOURCES = {
    "three.core.js": ("build/three.core.js", True),
    "three.module.js": ("build/three.module.js", True),
    "three.OrbitControls.js": ("examples/jsm/controls/OrbitControls.js", False),
    "three.LICENSE": ("LICENSE", False),
}


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _revision(core: str) -> str:
    """``REVISION`` of three's core build, minified (``const t="187"``, ``t as REVISION``) or not."""
    exported = re.search(r"\b([\w$]+) as REVISION\b", core)
    name = re.escape(exported.group(1) if exported else "REVISION")
    return re.search(rf"(?<![\w$.]){name}\s*=\s*(['\"])(\d+)\1", core).group(2)


def test_vendored_files_are_the_pinned_ones():
    assert {name: _sha256(DATA.joinpath(name).read_bytes()) for name in SHA256} == SHA256
    assert "@license" in DATA.joinpath("three.core.js").read_text(encoding="utf-8")[:200]  # the minifier kept it


def test_the_files_are_the_version_package_json_pins():
    package = json.loads((ROOT / "package.json").read_text(encoding="utf-8"))
    lock = json.loads((ROOT / "package-lock.json").read_text(encoding="utf-8"))
    for deps in ("dependencies", "devDependencies"):
        for name, version in package[deps].items():
            assert re.fullmatch(r"\d+\.\d+\.\d+", version), f"{name} {version}: not pinned to one release"
            assert lock["packages"][f"node_modules/{name}"]["version"] == version  # the lockfile agrees
    version = package["dependencies"]["three"]
    assert version.split(".")[:2] == ["0", _revision(DATA.joinpath("three.core.js").read_text(encoding="utf-8"))]


@pytest.mark.skipif(not THREE.is_dir(), reason="node_modules/ is absent (`make vendor` installs it with npm)")
def test_vendored_files_are_what_make_vendor_makes_from_node_modules(tmp_path):
    package = json.loads((ROOT / "package.json").read_text(encoding="utf-8"))
    installed = json.loads((THREE / "package.json").read_text(encoding="utf-8"))["version"]
    assert installed == package["dependencies"]["three"], "node_modules/ is stale: run `make vendor`"
    npm = shutil.which("npm")
    for name, (source, minified) in SOURCES.items():
        if not minified:
            made = (THREE / source).read_bytes()
        elif npm is None:
            continue  # checked in the sha256 table only
        else:
            out = tmp_path / name
            subprocess.run([npm, "run", "--silent", "minify", "--", str(THREE / source), "-o", str(out)],
                           cwd=ROOT, check=True, capture_output=True, timeout=300)
            made = out.read_bytes()
        assert _sha256(made) == _sha256(DATA.joinpath(name).read_bytes()) == SHA256[name], name
    if npm is None:
        pytest.skip("npm is not installed: the minified builds were not made again")
