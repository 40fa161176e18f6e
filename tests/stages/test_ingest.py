"""Each bad input is refused with one sentence naming the place, and no output file."""

import csv
import re
import shutil

import h5py
import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.formats.audio import read_audio, write_wav
from facesynth.formats.labels import Segment, write_textgrid
from facesynth.formats.mocap import MarkerTake, read_mocap, write_c3d
from facesynth.stages import ingest


@pytest.fixture()
def corpus(tiny_corpus, tmp_path):
    """A private copy of the tiny corpus, limited to three takes, that a test may damage."""
    d = tmp_path / "c"
    shutil.copytree(tiny_corpus, d)
    rows = list(csv.DictReader(open(d / "manifest.csv")))[:3]
    _write_manifest(d, rows)
    return d


def _write_manifest(d, rows):
    with open(d / "manifest.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def _rows(d):
    return list(csv.DictReader(open(d / "manifest.csv")))


def _refused(d, config, match):
    out = d / "corpus.h5"
    with pytest.raises(InputError, match=match):
        ingest.run(d / "manifest.csv", out, config.settings("ingest"), config.settings("align"))
    assert not out.exists()
    assert not list(d.glob("corpus.h5.tmp-*"))


def test_good_manifest_is_ingested(corpus, config):
    out = corpus / "corpus.h5"
    summary = ingest.run(corpus / "manifest.csv", out, config.settings("ingest"), config.settings("align"))
    assert summary.takes == 3 and summary.markers == 91
    with h5py.File(out) as f:
        assert f["markers"].attrs["units"] == "mm" and f["markers"].attrs["fps"] == 120
        assert f["audio"].attrs["sample_rate"] == 16000
        assert set(p.decode() for p in f["phones/phone"][()]) <= set(
            "pau aa ae ah ao aw ax ay b ch d dh eh er ey f g hh ih iy jh k l m n ng ow oy p r s sh t th uh uw v w y z zh".split())


def _emotion_tier(d, take, intervals):
    """Rewrite ``take``'s TextGrid with the emotion tier ``intervals`` (start, end, label)."""
    from facesynth.formats.labels import read_textgrid

    path = d / "labels" / f"{take}.TextGrid"
    tiers = read_textgrid(path)
    tiers["emotion"] = [Segment(a, b, label) for a, b, label in intervals]
    write_textgrid(path, tiers, tiers["phones"][-1].end)
    return tiers["phones"]


def test_phones_take_the_emotion_tier(corpus, config):
    from facesynth.model.corpus import Corpus

    take = _rows(corpus)[0]["take"]
    phones = _emotion_tier(corpus, take, [(0.0, 0.5, "neutral"), (0.5, 0.8, ""), (0.8, 99.0, "Anger")])
    out = corpus / "corpus.h5"
    ingest.run(corpus / "manifest.csv", out, config.settings("ingest"), config.settings("align"))
    c = Corpus.read(out, audio=False)
    rows = np.nonzero(c.phones.take == 0)[0]
    emotions = c.phones.emotions(c.takes)
    for r, seg in zip(rows, phones):
        centre = 0.5 * (seg.start + seg.end)
        # an empty interval keeps the manifest's emotion; 'Anger' is an alias of angry
        assert emotions[r] == ("angry" if centre >= 0.8 else c.takes.emotion[0])
    assert "angry" in emotions and c.takes.emotion[0] == "neutral"


def test_unknown_emotion_in_the_tier(corpus, config):
    take = _rows(corpus)[1]["take"]
    _emotion_tier(corpus, take, [(0.0, 0.7, "neutral"), (0.7, 99.0, "bored")])
    _refused(corpus, config, rf"labels/{take}.TextGrid, emotion tier, 0.700 s: unknown emotion 'bored'; use one of neutral")


def test_missing_file(corpus, config):
    (corpus / _rows(corpus)[1]["audio"]).unlink()
    _refused(corpus, config, r"take 'neutral_s001' \(manifest line 3\): audio file .* not found")


def test_truncated_c3d(corpus, config):
    p = corpus / _rows(corpus)[0]["mocap"]
    p.write_bytes(p.read_bytes()[:-2000])
    _refused(corpus, config, r"neutral_s000\.c3d: truncated C3D")


def test_marker_names_differ(corpus, config):
    p = corpus / _rows(corpus)[1]["mocap"]
    take = read_mocap(p)
    take.names[0] = "RENAMED"
    write_c3d(p, take)
    _refused(corpus, config, r"neutral_s001\.c3d: marker names differ .*extra \['RENAMED'\]")


def test_frame_rates_differ(corpus, config):
    p = corpus / _rows(corpus)[2]["mocap"]
    take = read_mocap(p)
    write_c3d(p, MarkerTake(take.positions, take.names, 100.0))
    _refused(corpus, config, r"frame rate 100 Hz differs from the first take's 120 Hz")


def test_audio_much_shorter_than_motion(corpus, config):
    p = corpus / _rows(corpus)[0]["audio"]
    samples, rate = read_audio(p)
    write_wav(p, samples[: rate // 2], rate)
    _refused(corpus, config, r"neutral_s000\.wav: audio lasts 0\.50 s but the motion")


def test_overlapping_segments(corpus, config):
    p = corpus / _rows(corpus)[0]["alignment"]
    write_textgrid(p, {"phones": [Segment(0, 0.3, "pau"), Segment(0.2, 0.5, "b")]})
    _refused(corpus, config, r"neutral_s000\.TextGrid, 0\.200 s: segment 'b' overlaps")


def test_unknown_phone(corpus, config):
    p = corpus / _rows(corpus)[0]["alignment"]
    write_textgrid(p, {"phones": [Segment(0, 0.3, "pau"), Segment(0.3, 0.5, "qq")]})
    _refused(corpus, config, r"neutral_s000\.TextGrid, 0\.300 s: unknown phone 'qq'")


def test_unknown_emotion(corpus, config):
    rows = _rows(corpus)
    rows[1]["emotion"] = "bored"
    _write_manifest(corpus, rows)
    _refused(corpus, config, r"manifest\.csv, line 3: unknown emotion 'bored'")


def test_empty_take(corpus, config):
    p = corpus / _rows(corpus)[0]["mocap"]
    take = read_mocap(p)
    write_c3d(p, MarkerTake(np.full_like(take.positions, np.nan), take.names, 120.0))
    _refused(corpus, config, r"neutral_s000\.c3d: every marker sample is missing")


def test_emotion_aliases_are_accepted(corpus, config):
    rows = _rows(corpus)
    rows[0]["emotion"] = "Happiness"
    _write_manifest(corpus, rows)
    ingest.run(corpus / "manifest.csv", corpus / "c.h5", config.settings("ingest"), config.settings("align"))
    with h5py.File(corpus / "c.h5") as f:
        assert f["takes/emotion"][0].decode() == "happy"


def test_a_take_with_only_a_transcript_is_aligned(corpus, config):
    rows = _rows(corpus)
    rows[1]["alignment"] = ""  # neutral_s001: align its transcript with pocketsphinx
    _write_manifest(corpus, rows)
    out = corpus / "corpus.h5"
    ingest.run(corpus / "manifest.csv", out, config.settings("ingest"), config.settings("align"))
    with h5py.File(out) as f:
        take = f["phones/take"][()]
        phones = [p.decode() for p in f["phones/phone"][()]]
    aligned = [p for p, t in zip(phones, take) if t == 1 and p != "pau"]
    assert len(aligned) >= len(rows[1]["transcript"].split())


def test_align_settings_reach_the_aligner_of_transcript_only_takes(corpus, tmp_path, monkeypatch):
    from click.testing import CliRunner

    from facesynth.cli import main
    from facesynth.domain.capture import takes
    from facesynth.formats.labels import read_phone_segments

    rows = _rows(corpus)
    aligned = corpus / rows[1]["alignment"]
    rows[1]["alignment"] = ""
    _write_manifest(corpus, rows)
    received = []

    def fake_align(samples, rate, text, *, settings=None, extra=None, where="audio"):
        from facesynth.domain.speech.alignment import Alignment

        received.append(settings)
        return Alignment(read_phone_segments(aligned, ("phones",)), [], "given")

    monkeypatch.setattr(takes, "align_robust", fake_align)
    r = CliRunner().invoke(main, ["ingest", str(corpus / "manifest.csv"), "-o", str(tmp_path / "c.h5"),
                                  "--set", "align.sample_rate=8000", "--set", "align.frame_rate=50"])
    assert r.exit_code == 0, r.output
    assert [(s.sample_rate, s.frame_rate) for s in received] == [(8000, 50)]


def test_a_manifest_of_mocap_alone_is_ingested(corpus, config):
    """A user's capture: only take and mocap; no audio, no phones, neutral."""
    rows = _rows(corpus)
    (corpus / "manifest.csv").write_text("take,mocap\n" + "".join(f"{r['take']},{r['mocap']}\n" for r in rows[:2]))
    out = corpus / "corpus.h5"
    s = ingest.run(corpus / "manifest.csv", out, config.settings("ingest"), config.settings("align"))
    assert s.without_audio == s.without_phones == [r["take"] for r in rows[:2]]
    from facesynth.model.corpus import Corpus

    c = Corpus.read(out)
    assert len(c.phones) == 0 and len(c.audio) == 0 and c.audio_count.tolist() == [0, 0]
    assert c.takes.emotion == ["neutral", "neutral"] and c.takes.split == ["train", "train"]


def test_a_transcript_without_audio_is_refused(corpus, config):
    rows = _rows(corpus)
    rows[1]["audio"], rows[1]["alignment"] = "", ""
    _write_manifest(corpus, rows)
    _refused(corpus, config, r"manifest\.csv, line 3: take 'neutral_s001' has a transcript to align but no audio")


def test_coded_speech_in_the_audio_column_is_ingested_as_the_wav(tiny_corpus, held_out_take, coded_speech, config,
                                                               tmp_path):
    """One take with its sound as the WAV and as M4A, MP3, Opus, Ogg and an MP4: the same phones
    (aligned from the transcript; boundaries within 50 ms, measured <= 30 ms) and the same
    audio at the corpus's 16 kHz (r > 0.99, measured >= 0.996; the same length)."""
    from coded_audio import COMPRESSED

    from facesynth.model.corpus import Corpus

    row = next(r for r in _rows(tiny_corpus) if r["take"] == held_out_take)
    names = ["wav"] + [n for n in COMPRESSED if n in coded_speech]
    rows = [{**row, "take": f"as_{n}", "mocap": str(tiny_corpus / row["mocap"]), "audio": str(coded_speech[n]),
             "alignment": ""} for n in names]
    _write_manifest(tmp_path, rows)
    ingest.run(tmp_path / "manifest.csv", tmp_path / "corpus.h5", config.settings("ingest"), config.settings("align"))
    corpus = Corpus.read(tmp_path / "corpus.h5")
    assert corpus.sample_rate == 16000
    ph = corpus.phones
    segs = {n: [(ph.phone[i], ph.start[i], ph.end[i]) for i in np.flatnonzero(ph.take == k)] for k, n in enumerate(names)}
    sound = {n: corpus.audio[corpus.audio_start[k]:corpus.audio_start[k] + corpus.audio_count[k]]
             for k, n in enumerate(names)}
    for n in names[1:]:
        assert [s[0] for s in segs[n]] == [s[0] for s in segs["wav"]], n
        assert max(max(abs(a[1] - b[1]), abs(a[2] - b[2])) for a, b in zip(segs[n], segs["wav"])) <= 0.05, n
        assert len(sound[n]) == len(sound["wav"]) and np.corrcoef(sound[n], sound["wav"])[0, 1] > 0.99, n


@pytest.mark.parametrize("name, said", [("silent", "has no audio stream"),
                                        ("notes", "unreadable audio: ffmpeg reads neither sound nor video")])
def test_an_audio_column_without_sound_is_refused(corpus, coded_speech, config, name, said):
    rows = _rows(corpus)
    rows[1]["audio"] = str(coded_speech[name])
    _write_manifest(corpus, rows)
    _refused(corpus, config, re.escape(f"{coded_speech[name]}: {said}"))


def test_a_takes_own_alignment_in_another_language_is_read_as_ipa(corpus, config, tmp_path):
    """A German take's TextGrid labelled in IPA (as MFA's German model writes it): each phone keeps
    its IPA, standing as its nearest English phone; an English take's labels stay Festival."""
    from facesynth.model.corpus import Corpus

    rows = _rows(corpus)
    labels = ["sil", "ɪ", "ç", "m", "aː", "x", "ə", "sp", "ʁ", "yː", "spn"]
    segs = [Segment(round(0.1 * i, 3), round(0.1 * (i + 1), 3), lab) for i, lab in enumerate(labels)]
    write_textgrid(corpus / "ich.TextGrid", {"phones": segs})
    for r in rows:
        r["language"] = ""
    rows[0]["alignment"], rows[0]["language"] = "ich.TextGrid", "de"
    _write_manifest(corpus, rows)
    ingest.run(corpus / "manifest.csv", tmp_path / "c.h5", config.settings("ingest"), config.settings("align"))
    phones = Corpus.read(tmp_path / "c.h5", audio=False).phones
    first = [k for k, t in enumerate(phones.take) if t == 0]
    assert phones.ipa is not None
    assert [phones.ipa[k] for k in first] == ["", "ɪ", "ç", "m", "aː", "x", "ə", "", "ʁ", "yː", ""]
    assert [phones.phone[k] for k in first][:4] == ["pau", "ih", "sh", "m"]
    assert [phones.phone[k] for k in first][9] == "uw"
    rest = [k for k, t in enumerate(phones.take) if t != 0]
    assert rest and all(phones.ipa[k] == "" for k in rest)  # the English takes: their Festival labels


def test_an_unknown_ipa_label_of_a_take_in_another_language_is_named(corpus, config, tmp_path):
    rows = _rows(corpus)
    write_textgrid(corpus / "bad.TextGrid", {"phones": [Segment(0.0, 0.2, "a"), Segment(0.2, 0.4, "sh")]})
    for r in rows:
        r["language"] = ""
    rows[0]["alignment"], rows[0]["language"] = "bad.TextGrid", "de"
    _write_manifest(corpus, rows)
    with pytest.raises(InputError, match=r"bad\.TextGrid, 0\.200 s: unknown IPA phone 'sh'; a take in language 'de'"):
        ingest.run(corpus / "manifest.csv", tmp_path / "c.h5", config.settings("ingest"), config.settings("align"))
    assert not (tmp_path / "c.h5").exists()
