"""Pieces of the leave-speakers-out voice benchmarks (benchmarks/voice_speakers.py,
benchmarks/voice_features.py, benchmarks/voice_posteriors.py) that decide what is scored: GRID's
sentences read from its file names, the channel-free slopes of the bands, the paired comparison of
feature runs, and the recogniser's acoustic model read from its files."""

from __future__ import annotations

import importlib.util
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

BENCHMARKS = Path(__file__).resolve().parents[1] / "benchmarks"


def load(name: str):
    if str(BENCHMARKS) not in sys.path:
        sys.path.insert(0, str(BENCHMARKS))  # voice_speakers imports real_speech_lipsync beside it
    spec = importlib.util.spec_from_file_location(name, BENCHMARKS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


speakers = load("voice_speakers")
features = load("voice_features")


@pytest.mark.parametrize("name, text", [("bbaf2n", "bin blue at f two now"),
                                        ("lwbsza", "lay white by s zero again"),
                                        ("id2_vcd_swwp2s", "set white with p two soon"),
                                        ("PWIJ3P", "place white in j three please")])
def test_a_grid_clip_says_what_its_name_spells(name, text):
    assert speakers.grid_text(name) == text


@pytest.mark.parametrize("name", ["F01_B01_S01_R01_N", "bbaf2", "xbaf2n", "bba12n", "bbaf2x"])
def test_a_name_that_is_no_grid_sentence_has_no_text(name):
    assert speakers.grid_text(name) is None


def test_the_slopes_of_the_bands_ignore_a_channel_and_follow_a_ramp():
    k = np.arange(20, dtype=np.float32)[:, None]
    mel = np.concatenate([0.5 * k, -2.0 * k], 1)
    slopes = speakers.mel_deltas(mel)
    assert slopes.shape == mel.shape
    assert np.allclose(slopes[2:-2], [[0.5, -2.0]])
    assert np.allclose(speakers.mel_deltas(mel + 7.0), slopes)  # a constant gain or colouring is gone


def run(folds, name, values, warps=None):
    per = {f"src{i % 2}/s{i}": {"voice": v} for i, v in enumerate(values)}
    return {"folds": folds, "features": name, "speakers": len(values), "r": {"voice": {"value": float(np.mean(values))}},
            "per_speaker": per, **({"warps": warps} if warps else {})}


def test_feature_runs_are_compared_paired_with_the_mel_run_of_their_folds():
    base = [0.2, 0.4, 0.3, 0.5, 0.1, 0.6]
    better = [v + 0.05 for v in base]
    warps = {"src0/s0": [1.1, 1.1, 1.1], "src1/s1": [0.9, 0.9, 0.9]}
    out = features.compare([run("source", "mel", base), run("source", "vtln", better, warps),
                            run("speaker", "mel", better)], {"src0/s0": "F", "src1/s1": "M"})
    assert "minus_mel" not in out[0] and "minus_mel" not in out[2]  # each mel run is its folds' reference
    diff = out[1]["minus_mel"]
    assert diff["value"] == pytest.approx(0.05) and diff["low"] == pytest.approx(0.05)
    assert out[1]["minus_mel_per_source"] == {"src0": pytest.approx(0.05), "src1": pytest.approx(0.05)}
    assert out[1]["mean_warp"] == {"F": 1.1, "M": 0.9}


def test_the_recognisers_acoustic_model_is_read_as_pocketsphinx_wrote_it(tiny_corpus):
    """benchmarks/voice_posteriors.py reads pocketsphinx's own model files: 42 phones of 3 states,
    each state's 128 mixture weights summing to 1 (to their 8-bit quantization) in every stream,
    and its most likely phone per frame agreeing with the actress's labels far above chance."""
    from facesynth.base.phonemes import to_festival
    from facesynth.domain.voice import articulation as A
    from facesynth.formats.audio import read_audio
    from facesynth.formats.labels import read_textgrid

    posteriors = load("voice_posteriors")
    scorer = posteriors.PhoneScorer(posteriors.model_folder())
    assert len(scorer.phones) == 42 and scorer.states == 3 and "SIL" in scorer.phones
    sums = np.exp(scorer.weights).sum(-1)  # (streams, phones, states)
    assert sums.shape == (3, 42, 3) and 0.9 < sums.min() and sums.max() <= 1.0
    festival = [to_festival(p) for p in scorer.phones]
    hits = frames = 0
    for wav in sorted((tiny_corpus / "audio").glob("*.wav"))[:3]:
        samples, rate = read_audio(wav)
        best = scorer.log_likelihoods(A.to_analysis_rate(samples, rate)).argmax(1)
        for seg in read_textgrid(tiny_corpus / "labels" / f"{wav.stem}.TextGrid")["phones"]:
            said = best[int(seg.start * 100):int(seg.end * 100)]
            hits += sum(festival[k] == seg.label for k in said)
            frames += len(said)
    assert hits / frames > 0.1  # chance: 1 in 40


def test_speakers_are_summarized_against_a_chosen_mode_and_in_named_pairs():
    """The summary of the speakers the packaged model never heard pairs every mode against the
    shipped default (``packaged``) and the live modes against each other, speakers resampled."""
    rng = np.random.default_rng(0)
    per = {f"src/s{i}": {"packaged": [0.3 + 0.01 * i], "phones": [0.3 + 0.01 * i + rng.normal(0, 0.01)],
                         "live_default": [0.2 + 0.01 * i], "live_phones": [0.1 + 0.01 * i], "voice": [0.25]}
           for i in range(8)}
    out = speakers.summarize(per, 500, 0, lead="packaged", pairs=(("live_default", "live_phones"),))
    assert out["speakers"] == 8
    assert out["paired"]["packaged - live_default"]["value"] == pytest.approx(0.1)
    live = out["paired"]["live_default - live_phones"]
    assert live["value"] == pytest.approx(0.1) and live["low"] == pytest.approx(0.1)  # the same gap on every speaker
    assert "default - phones" not in out["paired"] and "packaged - phones" in out["paired"]


def test_clips_prepared_apart_count_as_their_corpus_speaker(tmp_path):
    """More GRID clips (``grid_more``) are utterances of ``grid``'s speakers: one speaker, one source,
    so that leaving a speaker out leaves all its clips out."""
    from facesynth.formats.audio import write_wav

    rate = 16000
    t = np.arange(rate) / rate
    for folder, name in (("grid", "bbaf2n"), ("grid_more", "bbaf3s"), ("grid_more", "lwbsza")):
        speaker = tmp_path / folder / ("grid01" if name != "lwbsza" else "grid11")
        speaker.mkdir(parents=True, exist_ok=True)
        write_wav(speaker / f"{name}.wav", 0.2 * np.sin(2 * np.pi * 150 * t), rate)
        np.savez(speaker / f"{name}.npz", times=np.arange(25) / 25.0, opening=np.linspace(0.1, 0.3, 25))
        (tmp_path / f"READY-{folder}").write_text("{}")
    utts = speakers.speech_data_utterances(tmp_path)
    assert sorted((u.source, u.speaker, u.name) for u in utts) == [
        ("grid", "grid/grid01", "bbaf2n"), ("grid", "grid/grid01", "bbaf3s"), ("grid", "grid/grid11", "lwbsza")]
    assert speakers.speech_data_utterances(tmp_path, skip=("grid",)) == []
    assert len(speakers.speech_data_utterances(tmp_path, only=["grid"])) == 3


def test_closures_are_counted_where_the_real_mouth_closes_and_pooled_over_speakers():
    """Four real closures; a mode closing at two of them (one frame late) and once where the real
    mouth is open meets half the real closures with two of its three."""
    t = np.arange(300)
    real = np.ones(300)
    for c in (40, 100, 160, 220):
        real -= np.exp(-0.5 * ((t - c) / 4.0) ** 2)
    mode = np.ones(300)
    for c in (41, 101, 190):
        mode -= np.exp(-0.5 * ((t - c) / 4.0) ** 2)
    counts = speakers.closure_counts(mode, real, 0.25, 0.25, 3)
    assert counts.tolist() == [2, 4, 2, 3]
    real_unknown = real.copy()
    real_unknown[:5] = np.nan  # unknown frames do not make closures
    assert speakers.closure_counts(mode, real_unknown, 0.25, 0.25, 3).tolist() == [2, 4, 2, 3]
    late = speakers.closure_counts(np.roll(mode, 4), real, 0.25, 0.25, 3)  # four frames late: none meet
    assert late.tolist() == [0, 4, 0, 3]
    pooled = speakers.summarize_closures({"a": {"m": counts}, "b": {"m": late}, "c": {"m": counts}}, 200, 0)
    assert pooled["m"]["recall"]["value"] == pytest.approx(4 / 12, abs=1e-4)  # rounded to 4 places
    assert pooled["m"]["precision"]["value"] == pytest.approx(4 / 9, abs=1e-4)
    assert pooled["m"]["real_closures"] == 12 and pooled["m"]["closures"] == 9
    assert pooled["m"]["recall"]["low"] <= 4 / 12 <= pooled["m"]["recall"]["high"]


def test_a_sweep_point_is_trust_thresholds_or_named_voice_settings(config):
    settings = config.settings("synthesize")
    assert speakers.sweep_point("0.5:0.8:1", settings) == (
        "trust 0.5:0.8:1", {"voice_trust_low": 0.5, "voice_trust_high": 0.8, "voice_weight": 1.0})
    name, changes = speakers.sweep_point("voice_opening_map=percentiles,voice_closing_threshold=2,"
                                         "voice_pin_recognized=true", settings)
    assert name == "set voice_opening_map=percentiles,voice_closing_threshold=2,voice_pin_recognized=true"
    assert changes == {"voice_opening_map": "percentiles", "voice_closing_threshold": 2.0, "voice_pin_recognized": True}
    with pytest.raises(SystemExit, match="use_opencl is not a setting of synthesize's voice step"):
        speakers.sweep_point("use_opencl=false", settings)


def test_speakers_weigh_alike_however_long_each_was_heard():
    """``--speaker-weights equal``: a speaker heard for 2 s counts as much as one heard for 4 s,
    exactly as a fit weighing frames alike that hears the short speaker's utterance twice."""
    from facesynth.domain.voice import articulation as A

    rng = np.random.default_rng(5)

    def utt(speaker: str, seconds: float, seed: int):
        rate = A.RATE
        t = np.arange(int(seconds * rate)) / rate
        syllables = 0.5 + 0.5 * np.sin(2 * np.pi * (3.0 + seed) * t)
        x = (syllables * np.sin(2 * np.pi * (140 + 40 * seed) * t) + 0.01 * rng.normal(size=len(t))).astype(np.float32)
        n = int(seconds * speakers.FPS)
        opening = np.interp(np.arange(n) / speakers.FPS, t, syllables)
        return speakers.Utt("grid", speaker, f"u{seed}", Path(f"u{seed}.wav"), x, rate, n, {"opening": opening},
                            raw=A.frame_features(x, rate))

    long, short = utt("grid/a", 4.0, 0), utt("grid/b", 2.0, 1)
    ref = {"opening": (0.0, 1.0), "jawOpen": (0.0, 0.5)}
    equal = speakers.fit_fold({"grid/a": [long], "grid/b": [short]}, ref, "default", 0, 0, speaker_weights="equal")
    twice = speakers.fit_fold({"grid/a": [long], "grid/b": [short, short]}, ref, "default", 0, 0,
                              speaker_weights="frames")
    frames = speakers.fit_fold({"grid/a": [long], "grid/b": [short]}, ref, "default", 0, 0, speaker_weights="frames")
    np.testing.assert_allclose(equal.coef, twice.coef, rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(equal.feature_mean, twice.feature_mean, rtol=1e-9)
    assert not np.allclose(equal.coef, frames.coef, rtol=1e-3)
    with pytest.raises(ValueError, match="speaker_weights"):
        speakers.fit_fold({"grid/a": [long]}, ref, "default", 0, 0, speaker_weights="seconds")
    # ``sources``: two GRID speakers count as much together as one speaker of another source,
    # exactly as weighing speakers alike with that speaker heard as two
    other = replace(utt("haskins/c", 3.0, 2), source="haskins")
    by_source = speakers.fit_fold({"grid/a": [long], "grid/b": [short], "haskins/c": [other]}, ref, "default", 0, 0,
                                  speaker_weights="sources")
    doubled = speakers.fit_fold({"grid/a": [long], "grid/b": [short], "haskins/c": [other],
                                 "haskins/c2": [replace(other, speaker="haskins/c2")]}, ref, "default", 0, 0,
                                speaker_weights="equal")
    np.testing.assert_allclose(by_source.coef, doubled.coef, rtol=1e-6, atol=1e-9)


def test_the_scored_jaw_is_the_jawopen_an_arkit_export_carries(held_out_synthesized, config, tmp_path):
    import csv

    import facesynth
    from facesynth.domain.rig.loading import load_rig

    motion = facesynth.read_motion(held_out_synthesized["motion"])
    n = len(motion.markers)
    jaw = speakers.solved_jaw(motion, load_rig(None, None), config.settings("solve"), n)
    facesynth.export(facesynth.read_curves(held_out_synthesized["curves"]), "arkit-csv", tmp_path / "c.csv",
                     fps=motion.fps)
    with open(tmp_path / "c.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    exported = np.array([float(r["JawOpen"]) for r in rows])
    assert len(exported) == n and np.ptp(exported) > 0.05  # the mouth moves
    np.testing.assert_allclose(jaw, exported, atol=1e-3)
