"""The hostile-input suite's fixtures: valid inputs of every kind, built once per session from
the tiny sample corpus and its artifacts (the fixtures of ``tests/conftest.py``)."""

from __future__ import annotations

import pytest

from . import cases


@pytest.fixture(scope="session")
def hostile_bases(tiny_corpus, tiny_artifacts, tiny_db, built_once) -> cases.Bases:
    """Valid inputs of every kind (captures, audio, labels, meshes, settings, every artifact kind),
    built once for every worker of the session."""
    artifacts = {**tiny_artifacts, "motiondb": tiny_db}

    def build(d):
        cases.build_bases(d / "bases", tiny_corpus, artifacts).save(d / "bases.json")

    return cases.Bases.load(built_once("hostile-bases", build) / "bases.json")
