import pytest

from facesynth.base.errors import InputError
from facesynth.base.phonemes import (
    OTHER_DURATION_S,
    PAU,
    PHONES,
    VISEME_GROUPS,
    map_phones,
    to_festival,
    typical_duration,
    viseme,
)


def test_cmu_stress_marks_are_dropped_and_unstressed_ah_becomes_schwa():
    cmu = ["HH", "AH0", "L", "OW1", "DH", "AH1", "ER0", "IY2"]
    assert map_phones(cmu, "x") == ["hh", "ax", "l", "ow", "dh", "ah", "er", "iy"]


def test_silence_and_noise_labels_become_pau():
    assert [to_festival(x) for x in ("sil", "SIL", "sp", "+NSN+", "", "h#", "<sil>")] == ["pau"] * 7


def test_unknown_phone_names_file_and_time():
    with pytest.raises(InputError, match=r"labels/s012\.TextGrid, 1\.250 s: unknown phone 'q'"):
        map_phones(["aa", "q"], "labels/s012.TextGrid", [0.5, 1.25])


def test_table_vi_has_fifteen_visemes_and_covers_the_phone_set():
    assert len(VISEME_GROUPS) == 15
    assert viseme("p") == viseme("b") == viseme("m")
    assert viseme("f") != viseme("p")
    assert all(isinstance(viseme(p), int) for p in PHONES)


def test_one_table_of_phone_durations():
    """The actress's speech and the alignment's duration model read one table of typical phone
    durations: diphthongs longest, then vowels, sibilants, other fricatives, stops, nasals, and
    the rest (schwa, approximants, /hh/) shortest."""
    assert typical_duration("ay") > typical_duration("iy") > typical_duration("s") > typical_duration("f")
    assert typical_duration("f") > typical_duration("p") > typical_duration("m") > typical_duration("ax")
    assert typical_duration("hh") == typical_duration("l") == OTHER_DURATION_S
    assert all(typical_duration(p) > 0 for p in PHONES if p != PAU)
