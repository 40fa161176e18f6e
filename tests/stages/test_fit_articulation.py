"""``facesynth fit-articulation``: the voice's articulation model fitted on a capture with its audio
(the tiny corpus), read back by synthesis, deterministic, and its refusals."""

import json

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.voice import articulation, fitting, fusion
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


def test_each_take_held_out_chooses_the_voices_own_closures(fitted):
    out, result = fitted
    held = result.held_out
    assert held is not None and set(held.r) == set(result.targets)
    assert 0.3 < held.r["opening"] < result.fit_r["opening"]  # audio it never heard reads less well than its own
    model = ArticulationModel.read(out)
    assert model.closure_threshold == held.closure_threshold
    if held.closure_threshold is not None:
        assert held.closure_threshold in fitting.CLOSURE_THRESHOLDS and held.precision >= fitting.MIN_CLOSURE_PRECISION
    assert held.closures > 0 and 0 <= held.recall <= 1


def test_closures_are_met_within_the_tolerance_take_by_take():
    real = [np.array([10, 40]), np.array([5])]
    voice = [np.array([12, 25, 44]), np.array([50])]
    # take 1: 10 met by 12, 40 missed by 44 (4 frames); 12 right, 25 and 44 wrong; take 2: nothing met
    assert fitting.closures_met(real, voice, 3) == (1, 3, 1, 4)
    assert fitting.closures_met(real, voice, 4) == (2, 3, 2, 4)


def test_one_take_holds_nothing_out_and_the_voice_closes_no_lips(tiny_artifacts, config, tmp_path):
    corpus = Corpus.read(tiny_artifacts["corpus"], audio=False)
    take = next(t for i, t in enumerate(corpus.takes.name) if corpus.audio_count[i] > 0)
    result = fit_articulation.run(tiny_artifacts["normalized"], tiny_artifacts["corpus"], tmp_path / "one.h5",
                                  config.settings("synthesize"), config.settings("solve"), takes=[take])
    model = ArticulationModel.read(tmp_path / "one.h5")
    assert result.held_out is None and model.closure_threshold is None
    assert fusion.closure_threshold(config.settings("synthesize"), model) == fusion.NO_CLOSURES


def test_the_closure_threshold_is_the_settings_or_else_the_models(config):
    from dataclasses import replace

    settings = config.settings("synthesize")
    packaged = fusion.articulation_model("")
    assert settings.voice_closure_threshold == -1 and packaged.closure_threshold is None
    assert fusion.closure_threshold(settings, packaged) == fusion.NO_CLOSURES  # the packaged model closes none
    performer = replace(packaged, closure_threshold=0.45)
    assert fusion.closure_threshold(settings, performer) == 0.45
    assert fusion.closure_threshold(replace(settings, voice_closure_threshold=0.6), performer) == 0.6
    assert fusion.closure_threshold(replace(settings, voice_closure_threshold=2.0), performer) == 2.0


def test_the_command_says_what_held_out_takes_chose(tiny_artifacts, tmp_path):
    out = tmp_path / "cli.h5"
    result = CliRunner().invoke(main, ["fit-articulation", str(tiny_artifacts["normalized"]), "--corpus",
                                       str(tiny_artifacts["corpus"]), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "each take predicted by the model fitted on the others: opening r" in result.output
    threshold = ArticulationModel.read(out).closure_threshold
    if threshold is not None:
        assert f"at closure score {threshold:.2f} they met" in result.output
    else:
        assert "the model makes none" in result.output
