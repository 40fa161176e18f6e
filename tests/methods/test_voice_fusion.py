"""The voice in the mouth (facesynth.domain.voice.fusion): the fusion's cores on curves, its paths
by where the phones came from, and what it does to a synthesized motion with real audio."""

from dataclasses import replace

import numpy as np
import pytest

from facesynth.base.errors import ArtifactError, InputError
from facesynth.domain.methods import MethodSettings, steps
from facesynth.domain.postprocess.concatenation import frame_ranges
from facesynth.domain.speech.loudness import lip_gaps
from facesynth.domain.voice import activity, articulation, fusion


@pytest.fixture(scope="module")
def synth(config):
    # the fusion's cores: the voice always trusted (the trust gate has its own test), at full weight,
    # its closures and the method's confirmed closings on (the thresholds chosen on FACEGOOD's voice;
    # the defaults leave them off for voices the model was not fitted on), the opening mapped affinely
    return replace(config.settings("synthesize"), voice_trust_low=-1.0, voice_trust_high=-1.0, voice_weight=1.0,
                   voice_closure_threshold=0.45, voice_closing_threshold=0.2, voice_opening_map="percentiles")


def test_range_map_keeps_the_shape_in_the_method_range():
    rng = np.random.default_rng(0)
    predicted = rng.normal(size=500)
    opening = 2.0 + 6.0 * rng.random(500)
    mapped = fusion.range_map(predicted, opening)
    assert np.corrcoef(mapped, predicted)[0, 1] > 0.99  # monotone, nearly affine
    np.testing.assert_allclose(np.percentile(mapped, [5, 95]), np.percentile(opening, [5, 95]), rtol=0.02)
    assert mapped.min() > 0  # the soft floor stays above a closed mouth
    assert np.array_equal(fusion.range_map(np.ones(10), np.arange(10.0)), np.arange(10.0))  # a flat prediction says nothing


def test_target_gap_follows_the_voice_and_closes_where_it_says(synth):
    fps, n = 30.0, 300
    t = np.arange(n) / fps
    opening = 5 + 3 * np.sin(2 * np.pi * 0.7 * t)  # the method's gaps, mm
    predicted = np.sin(2 * np.pi * 1.3 * t)  # the voice's opening, another rhythm
    score = np.zeros(n)
    score[150] = 1.0
    score = np.convolve(score, np.exp(-0.5 * (np.arange(-9, 10) / 3.0) ** 2), "same")
    target, done = fusion.target_gap(opening, predicted, score, None, np.ones(n), [], fps, synth)
    assert np.corrcoef(target[:140], predicted[:140])[0, 1] > 0.95  # weight 1: the voice's opening
    assert target[150] == pytest.approx(min(opening.min(), target.min()), abs=1e-6)  # closed at the score's peak
    assert target[150] < target[145] and target[150] < target[155]
    assert done["closures_from_voice"] == 1
    _, unresolved = fusion.target_gap(opening, predicted, score, None, np.ones(n), [], fps,
                                      replace(synth, voice_closure_threshold=-1.0))
    assert unresolved["closures_from_voice"] == 0  # the model's own threshold, not resolved here: none
    none, _ = fusion.target_gap(opening, predicted, None, None, np.ones(n), [], fps, replace(synth, voice_weight=0.0))
    np.testing.assert_allclose(none, opening)  # weight 0: the phones' opening
    quiet, _ = fusion.target_gap(opening, predicted, None, None, np.zeros(n), [], fps, synth)
    np.testing.assert_allclose(quiet, opening)  # no confidence in the voice: the phones' opening


def test_the_opening_by_rank_closes_the_mouth_as_often_as_the_method_does(synth):
    """The voice's predicted opening varies less within speech than between speech and silence (as
    the articulation model's does): mapped affinely by percentiles it holds the mouth half open
    through speech (the frozen, lips-apart mouth); by rank the mouth closes between syllables as
    often as the method's, in the voice's order."""
    fps, n = 30.0, 300
    t = np.arange(n) / fps
    speech = (t > 1.0) & (t < 9.0)
    syllable = 0.5 - 0.5 * np.cos(2 * np.pi * 4.0 * t)  # 4 syllables a second, 0 between them
    opening = np.where(speech, 0.5 + 9.5 * syllable, 0.5)  # the method's gaps, mm: closed between syllables
    predicted = np.where(speech, 0.7 + 0.3 * np.roll(syllable, 2), 0.0)  # the voice, a little late
    assert synth.voice_opening_map == "percentiles"
    by_rank, _ = fusion.target_gap(opening, predicted, None, None, np.ones(n), [], fps,
                                  replace(synth, voice_opening_map="rank"))
    affine, _ = fusion.target_gap(opening, predicted, None, None, np.ones(n), [], fps, synth)
    def closed(gap):
        return float(np.mean(gap[speech] < 2.0))  # nearly closed, within speech
    assert closed(opening) > 0.15
    assert closed(by_rank) == pytest.approx(closed(opening), abs=0.03)
    assert closed(affine) < 0.1  # half open throughout
    quartiles = [10, 25, 50, 75, 90]  # the method's gaps, rearranged (ties of the voice share a rank)
    np.testing.assert_allclose(np.percentile(by_rank, quartiles), np.percentile(opening, quartiles), atol=0.5)
    rank = lambda x: np.argsort(np.argsort(x, kind="stable"), kind="stable")  # noqa: E731
    assert np.corrcoef(rank(by_rank[speech]), rank(predicted[speech]))[0, 1] > 0.99  # in the voice's order
    np.testing.assert_allclose(fusion.rank_map(np.ones(10), np.arange(10.0)), np.arange(10.0))  # a flat voice says nothing


def test_a_pinned_phone_keeps_its_closure_unless_the_voice_says_open(synth):
    fps, n = 30.0, 120
    opening = np.full(n, 6.0)
    opening[50:56] = 0.2  # the method's /p/ closure
    predicted = np.linspace(0, 1, n)  # the voice rises through the utterance
    closed_voice, done = fusion.target_gap(opening, predicted, None, None, np.ones(n), [(50, 56)], fps, synth)
    assert closed_voice[52] == pytest.approx(0.2) and done["pinned_kept"] == 1  # low prediction there: kept
    loud = predicted.copy()
    loud[45:60] = 5.0  # the voice says the lips were wide open over the phone
    _, vetoed = fusion.target_gap(opening, loud, None, None, np.ones(n), [(50, 56)], fps, synth)
    assert vetoed["pinned_vetoed"] == 1


def test_the_closure_targets_mark_a_capture_closures():
    x = np.full(200, 10.0)
    x[40:43] = [3, 0.5, 3]  # a closing within speech
    x[120:140] = 0.5  # a rest: the mouth closed through a pause
    frames = articulation.closure_frames_of(x)
    assert 41 in frames
    closings = articulation.closure_target(x, 30.0, kind="closing")
    every = articulation.closure_target(x, 30.0)
    assert closings[41] == pytest.approx(1.0) and every[41] == pytest.approx(1.0)
    assert closings[130] < 0.05  # a rest is no closing


def test_the_packaged_model_predicts_what_the_fusion_reads():
    model = fusion.articulation_model("")
    assert {"opening", "closure", "closing", "jawOpen", "mouthFunnel", "mouthPucker"} <= set(model.target_names)
    assert articulation.model_look_ahead_s(model) <= 0.05  # live frames within 80 ms of their sound


def test_a_missing_model_file_is_one_sentence(tmp_path):
    with pytest.raises(InputError, match="is not a file; give an articulation model"):
        fusion.articulation_model(str(tmp_path / "none.h5"))


@pytest.fixture(scope="module")
def spoken(tiny_db, tiny_corpus, held_out_take, config):
    """The held-out take's phones and audio, read as synthesize reads them, and the database."""
    from facesynth.domain.methods import get

    member = get("dp")
    source = member.read(tiny_db)
    read = steps.read_utterance(config.settings("ingest"), phones_path=tiny_corpus / "labels" / f"{held_out_take}.TextGrid",
                               audio=tiny_corpus / "audio" / f"{held_out_take}.wav")
    return member, source, read


def _gap(motion, synth):
    return lip_gaps(motion.markers, list(motion.marker_names), tuple(synth.loudness_lip_markers))


def test_audio_takes_the_voice_articulation_with_phones_recognised_or_given(spoken, config):
    member, source, read = spoken
    settings = MethodSettings.of(config)
    # always trusted: the fusion itself (the trust gate has its own test)
    settings = settings.replace(synthesize=replace(settings.synthesize, use_opencl=False, voice_trust_low=-1.0,
                                                    voice_trust_high=-1.0))
    phones = steps.synthesize(member, source, read.utterance, settings)
    given = steps.synthesize(member, source, read.utterance, settings, audio=read.audio)
    heard = steps.synthesize(member, source, read.utterance, settings, audio=read.audio, recognized=True)
    assert (phones.summary.voice, given.summary.voice, heard.summary.voice) == ("off", "articulation", "articulation")
    loud = steps.synthesize(member, source, read.utterance,
                            settings.replace(synthesize=replace(settings.synthesize, voice_given="loudness")),
                            audio=read.audio)
    assert loud.summary.voice == "loudness"
    s = settings.synthesize
    samples, rate = read.audio
    model = fusion.articulation_model("")
    predicted = articulation.predict(model, samples, rate, len(phones.motion.markers), phones.motion.fps)
    opening = predicted[:, model.target_names.index("opening")]
    r_before = np.corrcoef(_gap(phones.motion, s), opening)[0, 1]
    r_after = np.corrcoef(_gap(heard.motion, s), opening)[0, 1]
    assert r_after > r_before + 0.1 and r_after > 0.75  # the mouth now follows what the voice says
    # off is the phones alone, bit for bit
    off = steps.synthesize(member, source, read.utterance,
                          settings.replace(synthesize=replace(s, voice_recognized="off")), audio=read.audio,
                          recognized=True)
    assert np.array_equal(off.motion.markers, phones.motion.markers)


def test_the_fusion_is_deterministic_and_moves_only_where_the_mouth_does(spoken, config):
    member, source, read = spoken
    settings = MethodSettings.of(config)
    settings = settings.replace(synthesize=replace(settings.synthesize, use_opencl=False))
    made = [steps.synthesize(member, source, read.utterance, settings, audio=read.audio, recognized=True).motion
            for _ in range(2)]
    assert np.array_equal(made[0].markers, made[1].markers)
    phones = steps.synthesize(member, source, read.utterance, settings).motion
    moved = np.linalg.norm(made[0].markers - phones.markers, axis=-1).mean(0)  # (M,) mm
    names = list(phones.marker_names)
    brows = [i for i, m in enumerate(names) if m.startswith(("BROW", "FH"))]
    mouth = [names.index(m) for m in ("ULI_C", "LLI_C")]
    assert moved[mouth].mean() > 0.5
    assert moved[brows].mean() < 0.2 * moved[mouth].mean()


def test_audio_that_is_silence_leaves_the_phones(spoken, config):
    member, source, read = spoken
    settings = MethodSettings.of(config)
    settings = settings.replace(synthesize=replace(settings.synthesize, use_opencl=False))
    samples, rate = read.audio
    quiet = (np.zeros_like(samples), rate)
    phones = steps.synthesize(member, source, read.utterance, settings).motion
    heard = steps.synthesize(member, source, read.utterance, settings, audio=quiet, recognized=True).motion
    assert np.abs(heard.markers - phones.markers).max() < 0.5  # no confidence anywhere: barely moved


def test_pinned_phones_keep_their_closure_and_rounding_stays_in_the_method_range(spoken, config):
    """With the phones given (pinned /p b m/) the voice neither opens a kept closure nor shifts the
    lips' rounding off the range the method's motion has."""
    member, source, read = spoken
    settings = MethodSettings.of(config)
    s = replace(settings.synthesize, use_opencl=False)
    motion = steps.synthesize(member, source, read.utterance, settings.replace(synthesize=s)).motion
    samples, rate = read.audio
    model = fusion.articulation_model("")
    utt = read.utterance
    fused, done, _ = fusion.fuse(motion, samples, rate, utt.starts, utt.ends, list(utt.phones), model, s, pinned=True)
    fps = motion.capture_fps
    names, lips = list(motion.marker_names), tuple(s.loudness_lip_markers)
    before, after = (lip_gaps(m.markers_capture, names, lips) for m in (motion, fused))
    ranges = frame_ranges(np.asarray(utt.starts), np.asarray(utt.ends), fps)
    pinned = [r for r, p in zip(ranges, utt.phones) if p in s.pinned_phones]
    raw = articulation.frame_features(samples, rate)
    opening = articulation.predict_raw(model, raw, np.arange(len(before)) / fps)[:, model.target_names.index("opening")]
    kept = fusion.kept_pinned(pinned, opening)
    assert kept and done.pinned_kept == len(kept)
    for a, b in kept:
        assert after[a:b].min() <= before[a:b].min() + 0.05  # the closure is kept, not opened
    shapes = fusion.RigShapes(fusion._builtin_rig(), names, motion.reference)
    for name in fusion.ROUNDING_SHAPES:
        w0, w1 = (shapes.weights(m.markers_capture, [name])[:, 0] for m in (motion, fused))
        lo, hi = np.percentile(w0, [5, 95])
        assert abs(np.median(w1) - np.median(w0)) < 0.25 * (hi - lo)  # moved within its range, not off it


def test_the_voice_closes_the_lips_at_its_models_own_threshold(spoken, config):
    """By default (voice_closure_threshold -1) the packaged model, which carries no threshold, closes
    no lips of its own; a performer's model carrying one closes them there, as the setting would."""
    member, source, read = spoken
    settings = MethodSettings.of(config)
    s = replace(settings.synthesize, use_opencl=False)
    assert s.voice_closure_threshold == -1
    motion = steps.synthesize(member, source, read.utterance, settings.replace(synthesize=s)).motion
    samples, rate = read.audio
    utt = read.utterance
    packaged = fusion.articulation_model("")

    def closures(model, synth):
        return fusion.fuse(motion, samples, rate, utt.starts, utt.ends, list(utt.phones), model, synth)[1]

    assert closures(packaged, s).closures_from_voice == 0
    own = closures(replace(packaged, closure_threshold=0.2), s)
    assert own.closures_from_voice > 0
    assert own == closures(packaged, replace(s, voice_closure_threshold=0.2))  # the same as setting it


def test_no_voice_past_the_audio_end():
    raw = articulation.frame_features(np.sin(np.arange(16000) * 0.05).astype(np.float32) * 0.3, 16000)
    c = fusion.confidence(raw, np.array([0.5, 0.9, 1.2, 2.0]), 0.5, 1.5)
    assert c[2] == 0 and c[3] == 0



def test_audio_that_starts_in_speech_is_heard_from_its_start():
    """Batch's noise floor looks both ways: a recording cut in the middle of speech (a steady tone
    from its first sample, then a pause) is heard from its start, not taken for the noise."""
    x = np.zeros(48000, np.float32)
    x[:16000] = 0.1 * np.sin(np.arange(16000) * 0.05)
    x[32000:] = 0.1 * np.sin(np.arange(16000) * 0.05)
    raw = articulation.frame_features(x, 16000)
    c = fusion.confidence(raw, np.array([0.1, 0.5, 1.5, 2.5]), 0.5, 1.5)
    np.testing.assert_array_equal(c, [1, 1, 0, 1])

def test_the_voice_is_heard_from_snr_none_to_snr_full():
    np.testing.assert_allclose(activity.snr_share([-1.0, 0.5, 1.0, 1.5, 3.0], 0.5, 1.5), [0, 0, 0.5, 1, 1])
    np.testing.assert_array_equal(activity.snr_share([0.19, 0.2, 0.21], 0.2, 0.2), [0, 0, 1])  # a step
    # a tone at a steady level over silence: linear in the level above the floor, silence unheard
    x = np.zeros(32000, np.float32)
    x[8000:24000] = 0.1 * np.sin(np.arange(16000) * 0.05)
    raw = articulation.frame_features(x, 16000)
    times = np.array([0.1, 0.75])
    wide = fusion.confidence(raw, times, 0.0, 100.0)[1]
    assert 0 < wide < 0.5
    np.testing.assert_allclose(fusion.confidence(raw, times, 0.0, 200.0)[1], wide / 2, rtol=1e-9)
    assert fusion.confidence(raw, times, 0.0, 0.5 * 100.0 * wide)[1] == 1.0
    assert fusion.confidence(raw, times, 0.0, 0.5 * 100.0 * wide)[0] == 0.0  # silence, far from the tone


def test_a_fit_leaves_out_unknown_frames_and_a_broken_model_is_refused():
    rng = np.random.default_rng(0)
    x = (rng.normal(0, 0.1, 16000 * 4)).astype(np.float32)
    raw = articulation.frame_features(x, 16000)
    targets = rng.normal(size=(120, 2))
    targets[30:50, 0] = np.nan  # a capture's gap
    model = articulation.fit([articulation.Take(raw, targets, 30.0)], ("opening", "jawOpen"))
    assert np.isfinite(model.coef).all() and np.isfinite(model.intercept).all()
    model.coef[0, 0] = np.nan
    with pytest.raises(ArtifactError, match="not all finite"):
        articulation.check_model(model, "m.h5")


def test_local_r_is_pearson_over_the_window():
    rng = np.random.default_rng(1)
    a, b = rng.normal(size=200), rng.normal(size=200)
    r = fusion.local_r(a, b, 31)
    for k in (15, 100, 184):
        assert r[k] == pytest.approx(np.corrcoef(a[k - 15:k + 16], b[k - 15:k + 16])[0, 1], abs=1e-9)
    assert np.all(fusion.local_r(np.ones(50), b[:50], 11) == 0)  # a flat curve agrees with nothing


def test_a_voice_that_disagrees_with_the_phones_is_not_trusted(synth):
    fps, n = 30.0, 600
    t = np.arange(n) / fps
    opening = 5 + 3 * np.sin(2 * np.pi * 1.1 * t)  # the phones' syllables
    follows = np.sin(2 * np.pi * 1.1 * t + 0.3) + 0.1 * np.sin(2 * np.pi * 4 * t)  # a voice read well
    lost = np.random.default_rng(0).normal(size=n)  # a voice the model cannot read
    trusting = replace(synth, voice_trust_low=0.1, voice_trust_high=0.4)
    assert fusion.trust(follows, opening, fps, trusting)[30:-30].min() == 1.0
    assert fusion.trust(lost, opening, fps, trusting).mean() < 0.1
    score = np.zeros(n)
    score[300] = 1.0
    kept, done = fusion.target_gap(opening, lost, score, None, np.ones(n), [], fps,
                                  replace(trusting, voice_trust_low=0.5, voice_trust_high=0.9))
    np.testing.assert_allclose(kept, opening)  # untrusted: the phones' opening, no closure of the voice's
    assert done["closures_from_voice"] == 0 and done["mean_trust"] == 0.0
    always = fusion.trust(lost, opening, fps, replace(synth, voice_trust_low=-1.0, voice_trust_high=-1.0))
    assert np.all(always == 1.0)  # -1, -1: always trusted (the release before)
