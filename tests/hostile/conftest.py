"""The hostile-input suite's fixtures: valid inputs of every kind, built once per session from
the tiny sample corpus and its artifacts (the fixtures of ``tests/conftest.py``)."""

from __future__ import annotations

import pytest

from . import cases


@pytest.fixture(scope="session")
def hostile_bases(tiny_corpus, tiny_artifacts, tiny_db, tmp_path_factory) -> cases.Bases:
    """Valid inputs of every kind (captures, audio, labels, meshes, settings, every artifact kind)."""
    artifacts = {**tiny_artifacts, "motiondb": tiny_db}
    return cases.build_bases(tmp_path_factory.mktemp("hostile") / "bases", tiny_corpus, artifacts)
