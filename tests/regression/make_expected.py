"""Regenerate expected_tiny.json after a deliberate quality change:

    .venv/bin/python tests/regression/make_expected.py

It runs the same pipeline as test_regression.py on the tiny corpus (seed 0) and writes the
metrics it checks, so the diff of the JSON shows what changed.
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

from facesynth.base.config import Config
from facesynth.domain.corpus.generate import generate
from facesynth.domain.evaluation import held_out as evaluation
from facesynth.stages import build_db, ingest, normalize, pca

CHECKED = {
    "dp": ["rms_mm", "velocity_rms_mm_s", "lip_closure_rate", "emotion_agreement", "non_captured_joins"],
    "mean_per_phone": ["rms_mm", "velocity_rms_mm_s"],
    "mean": ["rms_mm"],
    "coarticulation_per_phone": ["rms_mm"],
    "coarticulation": ["rms_mm"],
}


def tiny_metrics(folder: Path) -> dict:
    c = Config.load()
    generate(folder / "corpus", "tiny", seed=0)
    ingest.run(folder / "corpus" / "manifest.csv", folder / "corpus.h5", c.settings("ingest"), c.settings("align"))
    normalize.run(folder / "corpus.h5", folder / "normalized.h5", c.settings("normalize"))
    pca.run(folder / "normalized.h5", folder / "pca.h5", c.settings("pca"))
    build_db.run(folder / "pca.h5", folder / "db.h5", c.settings("build_db"))
    metrics, _ = evaluation.evaluate(folder / "db.h5", folder / "corpus.h5", c.settings("evaluate"), c.settings("synthesize"),
                                   c.settings("normalize"))
    return {m: {k: metrics[m]["overall"][k] for k in keys} for m, keys in CHECKED.items()}


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as tmp:
        values = tiny_metrics(Path(tmp))
    out = Path(__file__).with_name("expected_tiny.json")
    out.write_text(json.dumps({"values": values, "relative_tolerance": 0.05}, indent=2, sort_keys=True) + "\n")
    print(out.read_text())
