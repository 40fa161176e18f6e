"""The live core: fixed-lag decisions against the whole-utterance search, frames that are never
revised, emotion switches, given phone timings."""

from dataclasses import replace

import numpy as np
import pytest

from facesynth.base.errors import ArtifactError, InputError
from facesynth.domain.live.phones import given_phones
from facesynth.domain.live.synthesizer import LiveModel, LiveSynthesizer
from facesynth.domain.methods.trajectory import synthesize_motion
from facesynth.domain.search.costs import step_costs
from facesynth.domain.search.dp import dp_numpy
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.synthesis import render_path, synthesize
from facesynth.domain.speech.utterance import read_utterance
from facesynth.model.motiondb import MotionDatabase


@pytest.fixture(scope="module")
def db(tiny_db):
    return MotionDatabase.read(tiny_db)


@pytest.fixture(scope="module")
def utt(tiny_corpus, held_out_take):
    return read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")


def _model(db, config, **stream):
    return LiveModel(db, config.settings("synthesize"), replace(config.settings("stream"), **stream),
                     config.settings("solve"))


def _stream(model, utt, switch: dict | None = None):
    """Feed ``utt`` phone by phone (``switch``: step -> emotion set before it; its IPA, for a line
    in another language); returns the synthesizer, the frames in the order sent and the committed
    prefix after each step."""
    live = LiveSynthesizer(model)
    frames, prefixes = [], []
    for t, (p, a, b) in enumerate(zip(utt.phones, utt.starts, utt.ends)):
        if switch and t in switch:
            live.set_emotion(switch[t])
        live.add_phone(p, a, b, utt.ipa[t] if utt.ipa else "")
        frames += live.step(b)
        prefixes.append(list(live.committed))
    frames += live.finish(utt.ends[-1])
    return live, frames, prefixes


def _batch(db, utt, config, search="dp"):
    s = replace(config.settings("synthesize"), use_opencl=False, search=search)
    return synthesize(db, utt, {}, s)


def test_fixed_lag_dp_is_the_whole_utterance_dp_when_the_lookahead_covers_it(db, utt, config):
    model = _model(db, config, method="dp", lookahead_phones=len(utt), pause_wait_s=3600.0)
    live, frames, prefixes = _stream(model, utt)
    batch = _batch(db, utt, config)
    assert all(p == [] for p in prefixes)  # nothing is decided before the end
    np.testing.assert_array_equal(live.committed, batch.path)
    markers = np.stack([f.markers for f in frames])
    assert markers.shape == batch.rendered.markers.shape
    np.testing.assert_allclose(markers, batch.rendered.markers, atol=1e-4)


def test_a_line_in_another_language_is_searched_by_its_phones_features_as_batch_does(db, utt, config):
    """German /ç/ and French /y/ given live (their nearest English phones /sh/ and /uw/, with
    their IPA): the live DP matches them by their features (synthesize.phone_match), so with
    the whole utterance in view it takes batch's path for the same line, not the English one's."""
    ipa = {"sh": "ç", "s": "ç", "uw": "y", "iy": "y", "ih": "y"}
    foreign = replace(utt, phones=[{"ç": "sh", "y": "uw"}.get(ipa.get(p, ""), p) for p in utt.phones],
                      ipa=[ipa.get(p, "") for p in utt.phones])
    assert any(foreign.ipa)
    model = _model(db, config, method="dp", lookahead_phones=len(utt), pause_wait_s=3600.0)
    live, _, _ = _stream(model, foreign)
    batch = _batch(db, foreign, config).path
    english = _batch(db, replace(foreign, ipa=None), config).path
    assert not np.array_equal(batch, english)  # the features change the path on this line
    np.testing.assert_array_equal(live.committed, batch)
    assert live.ipa == foreign.ipa


@pytest.mark.parametrize("method,lookahead,fps", [("dp", 0, 30), ("dp", 1, 30), ("dp", 2, 30), ("greedy", 1, 30),
                                                  ("dp", 1, 60), ("dp", 1, 25)])
def test_frames_are_sent_once_in_order_and_never_need_revision(db, utt, config, method, lookahead, fps):
    # pauses wait for their next phone here (a wait longer than any pause): every frame is batch's
    model = _model(db, config, method=method, lookahead_phones=lookahead, fps=fps, pause_wait_s=3600.0)
    live, frames, prefixes = _stream(model, utt)
    assert [f.index for f in frames] == list(range(len(frames)))
    # committed decisions only grow: each prefix is a prefix of the final path
    for p in prefixes:
        assert p == live.committed[: len(p)]
    # most frames go out before the end, and each sent frame is what rendering the final path gives
    early = [f for f in frames if f.ready_at < utt.ends[-1]]
    assert len(early) > len(frames) // 2
    final = render_path(db, utt, np.array(live.committed), live.model.synth).markers
    assert len(final) == len(frames)
    np.testing.assert_allclose(np.stack([f.markers for f in frames]), final, atol=1e-3)
    arkit = np.stack([f.arkit for f in frames])
    assert arkit.shape == (len(frames), 52) and arkit.min() >= 0 and arkit.max() <= 1
    jaw = arkit[:, live.model.arkit_names.index("jawOpen")]
    assert jaw.max() > 0.1 and jaw.min() < 0.5 * jaw.max()  # the mouth opens and closes


def _pause_frames(live, n: int) -> np.ndarray:
    """(n,) whether each output frame lies in a pause of the stream's phones."""
    times = np.arange(n) / live.model.stream.fps
    step = np.searchsorted(np.array(live.starts), times + 1e-9, side="right") - 1
    return np.array([live.phones[k] == "pau" for k in step])


@pytest.mark.parametrize("lookahead", [0, 1])
def test_a_pause_does_not_hold_its_frames_back_for_the_next_phone(db, utt, config, lookahead):
    model = _model(db, config, method="dp", lookahead_phones=lookahead)
    wait = model.stream.pause_wait_s
    live, frames, _ = _stream(model, utt)
    markers = np.stack([f.markers for f in frames])
    final = render_path(db, utt, np.array(live.committed), live.model.synth).markers
    assert [f.index for f in frames] == list(range(len(final)))
    pause = _pause_frames(live, len(final))
    assert pause.sum() > 10
    # every frame outside the pauses is batch's; inside them the face eases toward rest and then
    # into the next phone, without a jump larger than the speech's own frame-to-frame motion
    np.testing.assert_allclose(markers[~pause], final[~pause], atol=1e-3)
    assert np.abs(markers[pause] - final[pause]).max() > 0.01
    motion = np.linalg.norm(np.diff(markers, axis=0), axis=-1).max(-1)
    batch_motion = np.linalg.norm(np.diff(final, axis=0), axis=-1).max(-1)
    assert motion.max() <= batch_motion.max() + 1e-3
    # the pause frames went out when their phone's end was reached (steps are taken at phone
    # ends here), not after the next phone: at most the wait after the pause ended
    ends = np.array(live.ends)
    for f in (f for f, p in zip(frames, pause) if p):
        k = int(np.searchsorted(np.array(live.starts), f.time + 1e-9, side="right")) - 1
        if ends[k] - f.time > wait + 1e-6 and k + 1 < len(ends):
            assert f.ready_at <= ends[k] + 1e-9, (f.index, f.ready_at, ends[k])


@pytest.mark.parametrize("lookahead", [1, 2, 3])
def test_a_short_lookahead_costs_little(db, utt, config, lookahead):
    """The fixed-lag path's cost (Eq. 4, the whole utterance's objective) is within 1% of the
    whole-utterance optimum. Its nodes may differ more: a small database holds near-equal
    stretches (on the tiny corpus a run of 7 of 16 spoken steps differs at every look-ahead
    from 1 to 4, for 0.004% to 0.5% of the cost)."""
    s = replace(config.settings("synthesize"), use_opencl=False)
    tc = transition_costs(db, s, False).dense()
    steps = step_costs(list(utt.phones), list(utt.emotions), db.nodes.phone, db.nodes.emotion, {}, s).total

    def cost(path) -> float:
        path = np.asarray(path)
        return float(steps[np.arange(len(path)), path].sum() + tc[path[:-1], path[1:]].sum())

    best = dp_numpy(tc, steps)
    assert cost(best.path) == pytest.approx(best.cost, rel=1e-5)  # the objective the DP minimizes
    live, _, _ = _stream(_model(db, config, method="dp", lookahead_phones=lookahead), utt)
    assert best.cost <= cost(live.committed) <= 1.01 * best.cost


def test_greedy_with_the_whole_lookahead_is_batch_greedy(db, utt, config):
    live, _, _ = _stream(_model(db, config, method="greedy", lookahead_phones=len(utt)), utt)
    batch = _batch(db, utt, config, search="greedy").path
    spoken = np.array([p != "pau" for p in utt.phones])
    np.testing.assert_array_equal(np.array(live.committed)[spoken], batch[spoken])


def test_an_emotion_switch_applies_to_the_phones_after_it(db, utt, config):
    half = len(utt) // 2
    live, _, _ = _stream(_model(db, config, method="dp", lookahead_phones=1), utt, switch={0: "sad", half: "happy"})
    assert live.emotions[:half] == ["sad"] * half and set(live.emotions[half:]) == {"happy"}
    node_emotion = np.array(db.nodes.emotion)[live.committed]
    spoken = np.array([p != "pau" for p in live.phones])
    after = node_emotion[half:][spoken[half:]]
    assert (after == "happy").mean() > 0.5
    with pytest.raises(InputError, match="emotion 'bored' is not in the motion database; use one of"):
        live.set_emotion("bored")


def test_given_phone_timings_are_checked():
    assert given_phones([{"phone": "HH", "start": 0, "end": 0.1}, {"phone": "AH0", "start": 0.1, "end": 0.2}],
                        "m") == [("hh", 0.0, 0.1, ""), ("ax", 0.1, 0.2, "")]
    with pytest.raises(InputError, match="m, 0.100 s: unknown phone 'QQ'"):
        given_phones([{"phone": "HH", "start": 0, "end": 0.1}, {"phone": "QQ", "start": 0.1, "end": 0.2}], "m")
    with pytest.raises(InputError, match="starts at 0.050 s, before the previous phone ends"):
        given_phones([{"phone": "HH", "start": 0, "end": 0.1}, {"phone": "AA", "start": 0.05, "end": 0.2}], "m")
    with pytest.raises(InputError, match="needs finite times"):
        given_phones([{"phone": "HH", "start": 0.2, "end": 0.1}], "m")
    with pytest.raises(InputError, match="must be a list"):
        given_phones("hh", "m")


def test_given_ipa_phones_of_another_language_take_their_nearest_english_phones():
    items = [{"phone": "t", "start": 0, "end": 0.1}, {"phone": "y", "start": 0.1, "end": 0.2},
             {"phone": "sil", "start": 0.2, "end": 0.3}, {"phone": "ʁ", "start": 0.3, "end": 0.4},
             {"phone": "ɸ", "start": 0.4, "end": 0.5}]
    # French /y/ is the rounded vowel, /ʁ/ the velar stop, /ɸ/ closes the lips (facesynth.base.ipa)
    assert given_phones(items, "m", ipa=True) == [("t", 0.0, 0.1, "t"), ("uw", 0.1, 0.2, "y"), ("pau", 0.2, 0.3, ""),
                                                  ("g", 0.3, 0.4, "ʁ"), ("p", 0.4, 0.5, "ɸ")]
    assert given_phones(items[:2], "m") == [("t", 0.0, 0.1, ""), ("y", 0.1, 0.2, "")]  # English: /y/ is the glide
    with pytest.raises(InputError, match="m, 0.100 s: 'ǂ' is not an IPA phone facesynth knows"):
        given_phones([items[0], {"phone": "ǂ", "start": 0.1, "end": 0.2}], "m", ipa=True)


def test_a_gap_between_phones_becomes_a_pause(db, config):
    live = LiveSynthesizer(_model(db, config))
    live.add_phone("hh", 0.1, 0.2)
    live.add_phone("pau", 0.2, 0.3)
    live.add_phone("pau", 0.3, 0.4)
    live.add_phone("aa", 0.35, 0.5)  # starts inside the known span: moved to its end
    assert live.phones == ["pau", "hh", "pau", "aa"]
    assert live.starts == [0.0, 0.1, 0.2, 0.4] and live.ends == [0.1, 0.2, 0.4, 0.5]


def test_phones_declared_complete_release_every_frame_before_the_audio_ends(db, utt, config):
    live = LiveSynthesizer(_model(db, config, method="dp", lookahead_phones=3))
    for p, a, b in zip(utt.phones, utt.starts, utt.ends):
        live.add_phone(p, a, b)
    held = live.step(0.0)
    live.phones_complete = True
    frames = held + live.step(0.0)
    assert len(held) < len(frames) == live._total_frames()
    batch = _batch(db, utt, config)
    np.testing.assert_array_equal(live.committed, batch.path)  # the whole utterance in one window
    np.testing.assert_allclose(np.stack([f.markers for f in frames]), batch.rendered.markers, atol=1e-3)
    with pytest.raises(InputError, match="declared complete"):
        live.add_phone("aa", 10.0, 10.1)
    assert live.finish(utt.ends[-1]) == []
    with pytest.raises(InputError, match="the stream has ended"):
        live.add_phone("aa", 10.0, 10.1)


def test_the_recogniser_restarts_in_silences_and_keeps_tiling(tiny_corpus, held_out_take, config):
    import wave

    from facesynth.domain.live.phones import PhoneRecognizer

    with wave.open(str(tiny_corpus / "audio" / f"{held_out_take}.wav")) as w:
        pcm = w.readframes(w.getnframes())
    silence = b"\0\0" * 8000
    audio = (pcm + silence) * 3  # three sentences with half a second of silence after each

    def run(restart_s):
        rec = PhoneRecognizer(config.settings("align"), 1, restart_s)
        phones, restarts = [], 0
        for a in range(0, len(audio), 640):
            before = rec.utterance_start
            phones += rec.feed(audio[a : a + 640])
            restarts += rec.utterance_start != before
        return phones + rec.end(), restarts

    whole, none = run(3600.0)
    split, restarts = run(1.0)
    assert none == 0 and restarts >= 2
    for phones in (whole, split):
        assert phones[0][1] == 0.0 and all(p[2] == q[1] for p, q in zip(phones, phones[1:]))  # they tile the stream
        assert abs(phones[-1][2] - len(audio) / 32000) < 0.05
    spoken = lambda phones: [p[0] for p in phones if p[0] != "pau"]  # noqa: E731
    # each restart falls in a silence: the sentences' phones come out as without restarts, near enough
    assert abs(len(spoken(split)) - len(spoken(whole))) <= 3


# --- the trajectory method ---------------------------------------------------------------------

@pytest.fixture(scope="module")
def trajectory_model(tiny_trajectory):
    from facesynth.model.trajectory import TrajectoryModel

    return TrajectoryModel.read(tiny_trajectory)


def _trajectory_model(model, config, **stream):
    return LiveModel(model, config.settings("synthesize"), replace(config.settings("stream"), method="trajectory", **stream),
                     config.settings("solve"), config.settings("trajectory"))


def _whole_solve(model, utt, config, fps):
    """The whole utterance's trajectory as batch synthesis makes it: markers (T, M, 3) at ``fps``."""
    return synthesize_motion(model, utt, config.settings("trajectory"), fps)[0].markers


@pytest.mark.parametrize("fps", [30, 25, 60])
def test_trajectory_with_the_whole_lookahead_is_batch_synthesis(trajectory_model, utt, config, fps):
    live, frames, _ = _stream(_trajectory_model(trajectory_model, config, lookahead_phones=len(utt), fps=fps,
                                                pause_wait_s=3600.0), utt)
    whole = _whole_solve(trajectory_model, utt, config, live.model.stream.fps)
    assert [f.index for f in frames] == list(range(len(whole)))
    np.testing.assert_allclose(np.stack([f.markers for f in frames]), whole, atol=1e-4)


def test_trajectory_frames_follow_the_solve_given_what_was_sent(trajectory_model, utt, config):
    """Frames go out in order before the end, each from Eq. 7 solved with the frame before it fixed;
    the fixed-lag path stays close to the whole utterance's, and closer with more look-ahead."""
    deviation = []
    for lookahead in (0, 1, 3):
        model = _trajectory_model(trajectory_model, config, lookahead_phones=lookahead, pause_wait_s=3600.0)
        live, frames, _ = _stream(model, utt)
        whole = _whole_solve(trajectory_model, utt, config, model.stream.fps)
        markers = np.stack([f.markers for f in frames])
        assert [f.index for f in frames] == list(range(len(whole)))
        assert len([f for f in frames if f.ready_at < utt.ends[-1]]) > len(frames) // 2
        spread = np.sqrt(((whole - whole.mean(0)) ** 2).sum(-1).mean())  # the utterance's own motion, mm
        deviation.append(np.sqrt(((markers - whole) ** 2).sum(-1).mean()) / spread)
        jaw = np.stack([f.arkit for f in frames])[:, model.arkit_names.index("jawOpen")]
        assert jaw.max() > 0.1 and jaw.min() < 0.5 * jaw.max()  # the mouth opens and closes
    assert 0 < deviation[0] < 0.35 and deviation[1] < 0.05 and deviation[2] <= deviation[1] <= deviation[0], deviation


def test_trajectory_pauses_ease_toward_rest_without_waiting(trajectory_model, utt, config):
    model = _trajectory_model(trajectory_model, config, lookahead_phones=1)
    live, frames, _ = _stream(model, utt)
    assert [f.index for f in frames] == list(range(len(frames)))
    markers = np.stack([f.markers for f in frames])
    jumps = np.linalg.norm(np.diff(markers, axis=0), axis=-1).max()
    whole = _whole_solve(trajectory_model, utt, config, model.stream.fps)
    assert jumps <= np.linalg.norm(np.diff(whole, axis=0), axis=-1).max() + 0.5  # no jump at a pause's end


def test_the_trajectory_method_needs_a_trajectory_model(db, trajectory_model, tiny_trajectory, config, tiny_db):
    from facesynth.stages.stream import load_model

    with pytest.raises(InputError, match="fit-method trajectory"):
        _trajectory_model(db, config)
    with pytest.raises(InputError, match="build-db"):
        _model(trajectory_model, config, method="dp")
    settings = [config.settings(s) for s in ("synthesize", "stream", "solve")]
    with pytest.raises(ArtifactError, match="expected .trajectory."):
        load_model(tiny_db, *settings, method="trajectory", trajectory=config.settings("trajectory"))
    with pytest.raises(InputError, match="add --method trajectory"):
        load_model(tiny_trajectory, *settings, method="dp")
