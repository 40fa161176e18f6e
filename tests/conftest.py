"""Shared fixtures: the tiny sample corpus and the artifacts built from it, made once per session."""

from __future__ import annotations

from pathlib import Path

import pytest

from facesynth.config import Config

SHARED_ASSETS = Path(__file__).resolve().parents[2] / "shared" / "assets"


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
