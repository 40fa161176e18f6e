"""Shared fixtures: the tiny sample corpus and the artifacts built from it, made once per session."""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from facesynth.config import Config

SHARED_ASSETS = Path(__file__).resolve().parents[2] / "shared" / "assets"


@functools.lru_cache(maxsize=1)
def _opencl_probes():
    from facesynth import opencl

    return [opencl.probe(d) for d in opencl.candidate_order(opencl.list_devices())]


def pytest_report_header(config):
    """Which OpenCL devices the OpenCL-versus-reference tests run on, and what the rest uses."""
    from facesynth import opencl

    probes = _opencl_probes()
    lines = [f"OpenCL {p.device.spec} {p.device.describe()}: " + ("builds" if p.ok else f"does not build ({p.reason})")
             for p in probes] or ["OpenCL: no device found"]
    try:
        lines.append(f"facesynth's default device: {opencl.choice().description}")
    except opencl.OpenCLUnavailable as exc:
        lines.append(f"facesynth's default device: none ({exc})")
    return lines


def pytest_generate_tests(metafunc):
    """``opencl_device``: every OpenCL device that builds facesynth's kernels, one test each."""
    if "opencl_device" in metafunc.fixturenames:
        working = [p.device for p in _opencl_probes() if p.ok]
        metafunc.parametrize("opencl_device", working or [None], indirect=True,
                             ids=[f"{d.spec}-{d.name}" for d in working] or ["no-device"])


@pytest.fixture
def opencl_device(request, monkeypatch):
    """Run the test with facesynth's OpenCL code on one device (``PYOPENCL_CTX``); skip with the
    reason when no device builds."""
    from facesynth import opencl

    device = request.param
    if device is None:
        reasons = "; ".join(f"{p.device.name}: {p.reason}" for p in _opencl_probes()) or "no OpenCL device found"
        pytest.skip(f"no OpenCL device builds facesynth's kernels ({reasons})")
    monkeypatch.setenv("PYOPENCL_CTX", device.spec)
    monkeypatch.delenv(opencl.FORCE_ENV, raising=False)
    opencl.reset()
    yield device
    opencl.reset()


@pytest.fixture(scope="session")
def shared_assets() -> Path:
    """Real data for tests (``../shared/assets``); tests that need it skip without it."""
    return SHARED_ASSETS


@pytest.fixture(scope="session")
def config() -> Config:
    return Config.load()


@pytest.fixture(scope="session")
def tiny_corpus(tmp_path_factory) -> Path:
    from facesynth.corpus.generate import generate

    out = tmp_path_factory.mktemp("tiny") / "corpus"
    generate(out, "tiny", seed=0)
    return out


@pytest.fixture(scope="session")
def tiny_artifacts(tiny_corpus, config, tmp_path_factory) -> dict[str, Path]:
    """corpus.h5, normalized.h5, pca.h5 built from the tiny corpus."""
    from facesynth.stages import ingest, normalize, pca

    d = tmp_path_factory.mktemp("artifacts")
    paths = {k: d / f"{k}.h5" for k in ("corpus", "normalized", "pca")}
    ingest.run(tiny_corpus / "manifest.csv", paths["corpus"], config.settings("ingest"), config.settings("align"))
    normalize.run(paths["corpus"], paths["normalized"], config.settings("normalize"))
    pca.run(paths["normalized"], paths["pca"], config.settings("pca"))
    return paths


@pytest.fixture(scope="session")
def tiny_db(tiny_artifacts, config) -> Path:
    from facesynth.stages import build_db

    out = tiny_artifacts["pca"].parent / "db.h5"
    build_db.run(tiny_artifacts["pca"], out, config.settings("build_db"))
    return out


@pytest.fixture(scope="session")
def held_out_take(tiny_corpus) -> str:
    import csv

    return next(r["take"] for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["split"] == "test")


@pytest.fixture(scope="session")
def small_db_and_truth(tmp_path_factory, config) -> tuple[Path, Path]:
    """The 'small' preset's database (about 1,700 nodes) and its contamination ground truth."""
    from facesynth.corpus.generate import generate
    from facesynth.stages import build_db, ingest, normalize, pca

    d = tmp_path_factory.mktemp("small")
    generate(d / "corpus", "small", seed=0)
    ingest.run(d / "corpus" / "manifest.csv", d / "corpus.h5", config.settings("ingest"), config.settings("align"))
    normalize.run(d / "corpus.h5", d / "normalized.h5", config.settings("normalize"))
    pca.run(d / "normalized.h5", d / "pca.h5", config.settings("pca"))
    build_db.run(d / "pca.h5", d / "db.h5", config.settings("build_db"))
    return d / "db.h5", d / "corpus" / "contamination.csv"
