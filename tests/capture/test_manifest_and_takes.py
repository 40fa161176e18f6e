"""The capture manifest and the assembly of its takes into a corpus
(facesynth.domain.capture.manifest, .takes), on files and arrays made here."""

from dataclasses import replace

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.capture.manifest import read_manifest
from facesynth.domain.capture.takes import NO_AUDIO_RATE, Ingested, capture_options, phone_emotions
from facesynth.formats.labels import Segment, write_textgrid
from facesynth.model.tables import Phones, Takes


def _manifest(tmp_path, text):
    path = tmp_path / "manifest.csv"
    path.write_text(text, encoding="utf-8")
    return path


def test_a_manifest_row_is_read_with_its_defaults_and_paths_beside_the_manifest(tmp_path, config):
    path = _manifest(tmp_path, "take,mocap,emotion,fps\na,takes/a.c3d,,\nb,b.csv,Joy,30\n")
    settings = replace(config.settings("ingest"), emotion_aliases={"joy": "happy"})
    a, b = read_manifest(path, settings)
    assert (a.line, a.take, a.mocap, a.audio, a.emotion, a.split, a.sentence, a.fps) == \
        (2, "a", tmp_path / "takes/a.c3d", None, "neutral", "train", "a", None)
    assert (b.line, b.emotion, b.fps) == (3, "happy", 30.0)


@pytest.mark.parametrize("text, message", [
    ("take\na\n", "lacks the column\\(s\\) mocap"),
    ("take,mocap\n", "lists no takes"),
    ("take,mocap\na,a.c3d\na,b.c3d\n", "line 3: take 'a' appears twice"),
    ("take,mocap,emotion\na,a.c3d,bored\n", "line 2: unknown emotion 'bored'"),
    ("take,mocap,split\na,a.c3d,dev\n", "line 2: unknown split 'dev'"),
    ("take,mocap,fps\na,a.csv,fast\n", "line 2: the fps 'fast' is not a frame rate"),
    ("take,mocap,transcript\na,a.c3d,hello\n", "line 2: take 'a' has a transcript to align but no audio"),
])
def test_a_bad_manifest_names_its_line(tmp_path, config, text, message):
    with pytest.raises(InputError, match=message):
        read_manifest(_manifest(tmp_path, text), config.settings("ingest"))


def test_phone_emotions_come_from_the_emotion_tier_at_each_phones_centre(tmp_path, config):
    grid = tmp_path / "a.TextGrid"
    phones = [Segment(0.0, 0.5, "aa"), Segment(0.5, 1.0, "b"), Segment(1.0, 1.5, "k")]
    write_textgrid(grid, {"phones": phones, "emotion": [Segment(0.0, 0.6, "sad"), Segment(0.6, 1.2, ""),
                                                        Segment(1.2, 1.5, "angry")]})
    row = read_manifest(_manifest(tmp_path, "take,mocap,alignment,emotion\na,a.c3d,a.TextGrid,happy\n"),
                        config.settings("ingest"))[0]
    # centres 0.25 (sad), 0.75 (an empty interval: the manifest's), 1.25 (angry)
    assert phone_emotions(row, phones, config.settings("ingest")) == ["sad", "happy", "angry"]


def test_a_neutral_take_is_not_chosen_at_ingest(config):
    with pytest.raises(InputError, match="ingest.neutral 'take:a'"):
        capture_options(replace(config.settings("ingest"), neutral="take:a"))


def _ingested(audio):
    takes = Takes(["a", "b"], ["neutral"] * 2, ["a", "b"], ["train"] * 2, ["", ""], np.array([0, 2]), np.array([2, 2]))
    phones = Phones(np.array([0], np.int64), np.array([0.0]), np.array([0.1]), ["aa"], ["neutral"])
    markers = np.zeros((4, 1, 3), np.float32)
    markers[1, 0, 0] = np.nan
    return Ingested(markers, ["m"], 30.0, takes, phones, audio, [], None, None, None, [])


def test_the_corpus_lays_the_takes_audio_end_to_end_at_the_first_takes_rate():
    got = _ingested([(np.ones(800, np.float32), 8000), (np.ones(1600, np.float32), 16000)])
    corpus = got.corpus(["m"])
    assert corpus.sample_rate == 8000
    assert list(corpus.audio_start) == [0, 800] and list(corpus.audio_count) == [800, 800]
    assert corpus.rigid_markers == ["m"]
    assert got.missing_fraction == 0.25 and got.without_audio == [] and got.without_phones == ["b"]


def test_a_corpus_without_audio_records_the_default_rate_and_no_samples():
    got = _ingested([(np.zeros(0, np.float32), None)] * 2)
    corpus = got.corpus([])
    assert corpus.sample_rate == NO_AUDIO_RATE and len(corpus.audio) == 0
    assert got.without_audio == ["a", "b"]
