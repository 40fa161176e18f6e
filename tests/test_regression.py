"""Quality regression: the tiny pipeline's metrics against committed expected values.

A change that quietly worsens synthesis fails here; a change that improves it beyond the
tolerance fails too, asking for ``tests/regression/make_expected.py`` to record the new
values (so the improvement is seen in review and kept from then on).
"""

import dataclasses
import json
from pathlib import Path

import pytest

from facesynth.domain.evaluation import held_out as evaluation

EXPECTED = json.loads((Path(__file__).parent / "regression" / "expected_tiny.json").read_text())
HIGHER_IS_BETTER = {"lip_closure_rate", "emotion_agreement"}


@pytest.fixture(scope="module")
def metrics(tiny_db, tiny_artifacts, config):
    # the overall values compared here do not depend on the bootstrap (it only makes the
    # figures' intervals), so its fewest resamples
    settings = dataclasses.replace(config.settings("evaluate"), bootstrap_resamples=100)
    m, _ = evaluation.evaluate(tiny_db, tiny_artifacts["corpus"], settings, config.settings("synthesize"),
                             config.settings("normalize"))
    return m


@pytest.mark.parametrize("method, key", [(m, k) for m, keys in EXPECTED["values"].items() for k in keys])
def test_metric_has_not_changed(metrics, method, key):
    expected = EXPECTED["values"][method][key]
    got = metrics[method]["overall"][key]
    tol = EXPECTED["relative_tolerance"] * max(abs(expected), 1e-9)
    sign = 1 if key in HIGHER_IS_BETTER else -1
    change = sign * (got - expected)  # > 0: better
    assert change >= -tol, f"{method} {key} got worse: {got:.4g} (expected {expected:.4g})"
    assert change <= tol, f"{method} {key} improved to {got:.4g} from {expected:.4g}: run tests/regression/make_expected.py"


def test_same_seed_gives_identical_artifacts(tiny_corpus, config, tmp_path):
    """Two runs of the chain in one folder write byte-identical artifacts."""
    import hashlib

    from facesynth.stages import build_db, ingest, normalize, pca, synthesize

    def chain():
        ingest.run(tiny_corpus / "manifest.csv", tmp_path / "c.h5", config.settings("ingest"),
                   config.settings("align"), overwrite=True)
        normalize.run(tmp_path / "c.h5", tmp_path / "n.h5", config.settings("normalize"), overwrite=True)
        pca.run(tmp_path / "n.h5", tmp_path / "p.h5", config.settings("pca"), overwrite=True)
        build_db.run(tmp_path / "p.h5", tmp_path / "d.h5", config.settings("build_db"), overwrite=True)
        synthesize.run(tmp_path / "d.h5", tmp_path / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                       config.settings("align"),
                       phones_path=tiny_corpus / "labels" / "happy_s004.TextGrid", overwrite=True)
        return {p: hashlib.sha256((tmp_path / p).read_bytes()).hexdigest() for p in ("c.h5", "n.h5", "p.h5", "d.h5", "m.h5")}

    assert chain() == chain()
