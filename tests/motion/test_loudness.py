"""The voice's loudness in the lips (facesynth.domain.speech.loudness) and ``synthesize --audio`` with it."""

from dataclasses import replace

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.cli import main
from facesynth.domain.postprocess.concatenation import downsample, frame_ranges
from facesynth.domain.speech import loudness
from facesynth.domain.speech.utterance import read_utterance
from facesynth.formats.audio import read_audio
from facesynth.model.motion import Motion


def test_envelope_follows_loudness():
    rate, fps = 16000, 30.0
    t = np.arange(rate * 2) / rate
    loud = (t >= 1.0).astype(float)
    samples = np.sin(2 * np.pi * 200 * t) * (0.01 + 0.5 * loud)
    env = loudness.envelope(samples, rate, 60, fps, 0.1)
    assert env.shape == (60,)
    assert env[40:].mean() - env[:20].mean() == pytest.approx(np.log(0.51 / 0.01), rel=0.05)
    # frames after the audio's end are silence, floored, not an error
    past = loudness.envelope(samples, rate, 90, fps, 0.1)
    assert np.isfinite(past).all() and past[-5:].max() < env[40:].min()


def test_quantile_map_gives_the_loudest_frame_the_widest_opening():
    rng = np.random.default_rng(0)
    opening = rng.uniform(0, 20, 200)
    loud = rng.normal(size=200)
    mapped = loudness.quantile_map(loud, opening)
    order = np.argsort(loud)
    assert np.all(np.diff(mapped[order]) >= 0)  # monotone in loudness
    assert mapped.min() >= opening.min() and mapped.max() <= opening.max()  # the method's own range
    assert np.median(mapped) == pytest.approx(np.median(opening), rel=0.05)
    # a microphone's gain (any increasing map of the loudness) changes nothing
    np.testing.assert_array_equal(loudness.quantile_map(3 * loud + 7, opening), mapped)


def test_weights_are_zero_in_pinned_phones_and_eased_outside():
    w = loudness.weights(100, [(40, 50)], 0.6, 5)
    assert np.all(w[40:50] == 0)
    assert np.all(w[:30] == pytest.approx(0.6)) and np.all(w[60:] == pytest.approx(0.6))
    assert np.abs(np.diff(w)).max() <= 0.6 / 5 + 1e-12  # eased: no jump larger than one step of the ramp
    np.testing.assert_array_equal(loudness.weights(10, [], 0.6, 5), np.full(10, 0.6))
    # motions shorter than the ease, and a bilabial shorter than a frame, still hold the lips
    np.testing.assert_array_equal(loudness.weights(1, [(0, 1)], 0.6, 12), [0.0])
    assert loudness.weights(3, [(1, 1)], 0.6, 12)[1] == 0


def _face(n=120, seed=0):
    """Synthetic frames (n, 4, 3) mm: upper lip, lower lip, chin, brow; the jaw (lower lip, chin)
    opens by o(t) along -y, the brow moves on its own."""
    rng = np.random.default_rng(seed)
    o = 5 + 4 * np.sin(np.linspace(0, 12, n)) + rng.normal(0, 0.2, n)
    rest = np.array([[0, 0, 0], [0, -1, 0], [0, -30, 5], [0, 40, 0]], float)
    x = np.repeat(rest[None], n, axis=0)
    x[:, 1, 1] -= o
    x[:, 2, 1] -= 1.5 * o
    x[:, 3, 1] += rng.normal(0, 0.5, n)
    return x, o + 1.0  # the gap includes the 1 mm at rest


def test_direction_is_the_jaw_and_moving_reaches_the_target_gaps():
    x, gap = _face()
    d = loudness.opening_direction(x, gap)
    np.testing.assert_allclose(d[1], [0, -1, 0], atol=1e-9)
    np.testing.assert_allclose(d[2], [0, -1.5, 0], atol=1e-9)
    assert np.abs(d[0]).max() < 1e-9 and np.abs(d[3]).max() < 0.05  # the upper lip and the brow stay
    target = gap.mean() + 0.5 * (gap - gap.mean())
    moved = loudness.move_to_gaps(x, d, (0, 1), target)
    np.testing.assert_allclose(np.linalg.norm(moved[:, 0] - moved[:, 1], axis=-1), target, atol=1e-6)
    np.testing.assert_allclose(moved[:, 3], x[:, 3], atol=0.05 * np.abs(target - gap).max())
    # a target the direction cannot reach (the lips apart front to back, as in /f v/): as close as
    # it gets, never past the gap it had
    sideways = np.zeros((1, 2, 3))
    sideways[0, 1] = [0.0, -2.69, -7.54]  # the lower lip below and behind the upper
    du = np.zeros((2, 3))
    du[1] = [0.04, -0.91, -0.41]
    moved = loudness.move_to_gaps(sideways, du, (0, 1), np.array([5.5]))
    gap = np.linalg.norm(moved[0, 0] - moved[0, 1])
    before = np.linalg.norm(sideways[0, 1])
    closest = np.linalg.norm(np.cross(sideways[0, 1], du[1])) / np.linalg.norm(du[1])
    assert gap == pytest.approx(closest, abs=1e-9) and 5.5 < gap < before
    # nothing to regress on: no direction, nothing moves
    still = np.repeat(x[:1], 10, axis=0)
    assert not loudness.opening_direction(still, np.full(10, 2.0)).any()


@pytest.fixture(scope="module")
def synthesized(held_out_synthesized, tiny_corpus, held_out_take):
    motion = Motion.read(held_out_synthesized["motion"])
    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    return motion, utt, read_audio(held_out_synthesized["audio"])


def test_the_opening_follows_the_voice_and_bilabials_stay_as_they_were(synthesized, config):
    motion, utt, (samples, rate) = synthesized
    s = config.settings("synthesize")
    lips = s.loudness_lip_markers
    out, warning = loudness.follow(motion, samples, rate, utt.starts, utt.ends, list(utt.phones), s)
    assert warning is None
    before = loudness.lip_gaps(motion.markers_capture, motion.marker_names, lips)
    after = loudness.lip_gaps(out.markers_capture, out.marker_names, lips)
    loud = loudness.envelope(samples, rate, len(before), motion.capture_fps, s.loudness_smoothing_s)
    assert np.corrcoef(loud, after)[0, 1] > np.corrcoef(loud, before)[0, 1] + 0.05
    assert after.min() >= before.min() - 1e-3 and after.max() <= before.max() + 1e-3  # the method's range
    ranges = frame_ranges(utt.starts, utt.ends, motion.capture_fps)
    pinned = [r for r, p in zip(ranges, utt.phones) if p in s.pinned_phones]
    assert pinned
    for a, b in pinned:  # /p b m/ close as the method closed them
        np.testing.assert_allclose(out.markers_capture[a:b], motion.markers_capture[a:b], atol=1e-3)
    np.testing.assert_array_equal(out.markers, downsample(out.markers_capture, motion.capture_fps, motion.fps))


def test_audio_whose_loudness_hardly_varies_leaves_the_motion_with_a_warning(synthesized, config):
    motion, utt, (samples, rate) = synthesized
    s = config.settings("synthesize")
    for flat in (np.zeros_like(samples), 0.3 * np.sin(np.arange(len(samples)) * 2 * np.pi * 220 / rate)):
        out, warning = loudness.follow(motion, flat.astype(np.float32), rate, utt.starts, utt.ends, list(utt.phones), s)
        assert out is motion and "hardly varies" in warning and "synthesize.loudness_weight = 0" in warning


def test_a_motion_without_the_lip_markers_is_left_with_a_warning(synthesized, config):
    motion, utt, (samples, rate) = synthesized
    s = replace(config.settings("synthesize"), loudness_lip_markers=("UL_MISSING", "LLI_C"))
    out, warning = loudness.follow(motion, samples, rate, utt.starts, utt.ends, list(utt.phones), s)
    assert out is motion
    assert "no marker 'UL_MISSING'" in warning and "synthesize.loudness_lip_markers" in warning


def _synthesize(*args):
    return CliRunner().invoke(main, ["synthesize", *map(str, args), "-q"])


def test_synthesize_with_phones_and_audio(tiny_db, tiny_corpus, held_out_take, held_out_synthesized, tmp_path, config):
    labels = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    audio = held_out_synthesized["audio"]
    # the loudness step (synthesize.voice_given = "loudness"; the default is the voice's articulation)
    r = _synthesize(tiny_db, "--phonemes", labels, "--audio", audio, "--set", "synthesize.voice_given=loudness",
                    "-o", tmp_path / "loud.h5")
    assert r.exit_code == 0, r.output
    r = _synthesize(tiny_db, "--phonemes", labels, "--audio", audio, "--set", "synthesize.voice_given=loudness",
                    "--set", "synthesize.loudness_weight=0", "-o", tmp_path / "phones.h5")
    assert r.exit_code == 0, r.output
    phones_only, loud = Motion.read(tmp_path / "phones.h5"), Motion.read(tmp_path / "loud.h5")
    # weight 0 is the phones alone, exactly; the default weight moves the mouth
    np.testing.assert_array_equal(phones_only.markers, Motion.read(held_out_synthesized["motion"]).markers)
    lips = config.settings("synthesize").loudness_lip_markers
    change = np.abs(loudness.lip_gaps(loud.markers, loud.marker_names, lips)
                    - loudness.lip_gaps(phones_only.markers, phones_only.marker_names, lips))
    assert change.max() > 0.5


def test_synthesize_refuses_phones_that_outlast_the_audio(tiny_db, tiny_corpus, held_out_take, tmp_path):
    labels = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    samples, rate = read_audio(tiny_corpus / "audio" / f"{held_out_take}.wav")
    import soundfile

    short = tmp_path / "short.wav"
    soundfile.write(short, samples[: rate // 2], rate)
    r = _synthesize(tiny_db, "--phonemes", labels, "--audio", short, "-o", tmp_path / "m.h5")
    assert r.exit_code == 1
    assert "ends at" in r.output and f"after the audio {short}" in r.output and "Traceback" not in r.output
    assert not (tmp_path / "m.h5").exists()


def test_ranks_and_filters_are_scipys():
    from scipy.ndimage import maximum_filter1d, uniform_filter1d
    from scipy.stats import rankdata

    rng = np.random.default_rng(1)
    values = np.round(rng.normal(size=300), 1)  # many ties
    np.testing.assert_array_equal(loudness.mean_ranks(values), rankdata(values))
    assert loudness.mean_ranks(np.zeros(0)).shape == (0,)
    x = rng.normal(size=50)
    for k in (1, 2, 3, 4, 7):
        np.testing.assert_allclose(loudness.moving_average(x, k), uniform_filter1d(x, k, mode="nearest"), atol=1e-12)
    pinned = [(5, 9), (30, 31)]
    mask = np.zeros(60)
    for a, b in pinned:
        mask[a:b] = 1
    for ease in (2, 3, 6):
        expect = 0.6 * (1 - uniform_filter1d(maximum_filter1d(mask, 2 * (ease // 2) + 1), ease, mode="nearest"))
        np.testing.assert_allclose(loudness.weights(60, pinned, 0.6, ease), expect, atol=1e-12)


def test_aligned_audio_is_kept_for_its_loudness(tiny_corpus, held_out_take, config):
    import csv

    from facesynth.domain.methods import steps

    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == held_out_take)
    wav = tiny_corpus / row["audio"]
    read = steps.read_utterance(config.settings("ingest"), audio=wav, text=row["transcript"],
                               align=config.settings("align"))
    samples, rate = read_audio(wav)
    assert read.alignment is not None and read.audio is not None and read.audio[1] == rate
    np.testing.assert_array_equal(read.audio[0], samples)
    # phones from a file: the audio is read for its loudness only
    given = steps.read_utterance(config.settings("ingest"), phones_path=tiny_corpus / row["alignment"], audio=wav)
    assert given.alignment is None and given.audio is not None and len(given.audio[0]) == len(samples)
    assert steps.read_utterance(config.settings("ingest"), phones_path=tiny_corpus / row["alignment"]).audio is None
