"""``facesynth fit-articulation``: the voice's articulation model fitted on a capture with its audio
(the tiny corpus), read back by synthesis, deterministic, and its refusals."""

import json

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.voice import articulation, fusion
from facesynth.model.articulation import ArticulationModel
from facesynth.model.corpus import Corpus
from facesynth.stages import fit_articulation


@pytest.fixture(scope="module")
def fitted(tiny_artifacts, config, tmp_path_factory):
    out = tmp_path_factory.mktemp("articulation") / "articulation.h5"
    result = fit_articulation.run(tiny_artifacts["normalized"], tiny_artifacts["corpus"], out,
                                  config.settings("synthesize"), config.settings("solve"))
    return out, result


def test_the_model_learns_the_capture_mouth_from_its_voice(fitted, tiny_artifacts):
    out, result = fitted
    model = ArticulationModel.read(out)
    assert result.solved and list(model.target_names) == ["opening", "closure", "closing", "jawOpen", "mouthFunnel",
                                                          "mouthPucker"]
    corpus = Corpus.read(tiny_artifacts["corpus"], audio=False)
    assert result.takes == [t for i, t in enumerate(corpus.takes.name) if corpus.audio_count[i] > 0]
    assert result.fit_r["opening"] > 0.6 and result.fit_r["jawOpen"] > 0.6  # the actress's voice follows her jaw
    assert result.look_ahead_s == pytest.approx(articulation.model_look_ahead_s(model)) and result.look_ahead_s < 0.05
    with h5py.File(out) as f:
        config = json.loads(f.attrs["config"])
    assert config["takes"] == result.takes and config["lip_markers"] == ["ULI_C", "LLI_C"]
    fusion.articulation_model(str(out))  # what synthesize.articulation_model reads


def test_the_same_capture_gives_the_same_model(fitted, tiny_artifacts, config, tmp_path):
    out, _ = fitted
    again = tmp_path / "again.h5"
    fit_articulation.run(tiny_artifacts["normalized"], tiny_artifacts["corpus"], again, config.settings("synthesize"),
                         config.settings("solve"))
    a, b = ArticulationModel.read(out), ArticulationModel.read(again)
    assert np.array_equal(a.coef, b.coef) and np.array_equal(a.intercept, b.intercept)


def test_synthesis_takes_the_performer_model(fitted, tiny_db, tiny_corpus, held_out_take, tmp_path):
    out, _ = fitted
    wav = tiny_corpus / "audio" / f"{held_out_take}.wav"
    for name, extra in (("packaged", []), ("performer", ["--set", f"synthesize.articulation_model={out}"])):
        result = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--audio", str(wav), "-o",
                                           str(tmp_path / f"{name}.h5"), "-q", *extra])
        assert result.exit_code == 0, result.output
    with h5py.File(tmp_path / "packaged.h5") as a, h5py.File(tmp_path / "performer.h5") as b:
        assert not np.array_equal(a["markers"][()], b["markers"][()])  # another model, another mouth


def test_refusals_name_the_file_and_what_to_do(tiny_artifacts, tiny_corpus, config, tmp_path):
    with pytest.raises(InputError, match="no take 'nope'"):
        fit_articulation.run(tiny_artifacts["normalized"], tiny_artifacts["corpus"], tmp_path / "a.h5",
                             config.settings("synthesize"), config.settings("solve"), takes=["nope"])
    result = CliRunner().invoke(main, ["fit-articulation", str(tiny_artifacts["normalized"]), "--corpus",
                                       str(tiny_artifacts["normalized"]), "-o", str(tmp_path / "b.h5")])
    assert result.exit_code == 1 and "Traceback" not in result.output
    assert str(tiny_artifacts["normalized"]) in result.output
    assert not (tmp_path / "a.h5").exists() and not (tmp_path / "b.h5").exists()
