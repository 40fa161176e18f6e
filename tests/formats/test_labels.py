import pytest

from facesynth.base.errors import InputError
from facesynth.formats.labels import Segment, read_lab, read_phone_segments, read_textgrid, write_lab, write_textgrid

SHORT = '''File type = "ooTextFile"
Object class = "TextGrid"

0
1.5
<exists>
1
"IntervalTier"
"phones"
0
1.5
3
0
0.5
"sil"
0.5
1.0
"AH0"
1.0
1.5
"say ""hi"""
'''


def test_textgrid_round_trip(tmp_path):
    segs = [Segment(0.0, 0.25, "pau"), Segment(0.25, 0.4, "hh"), Segment(0.4, 0.8, "ax")]
    p = tmp_path / "a.TextGrid"
    write_textgrid(p, {"phones": segs, "words": [Segment(0.25, 0.8, "a")]})
    tiers = read_textgrid(p)
    assert tiers["phones"] == segs
    assert tiers["words"] == [Segment(0.25, 0.8, "a")]


def test_short_format_and_utf16(tmp_path):
    p = tmp_path / "short.TextGrid"
    p.write_text(SHORT, encoding="utf-16")
    segs = read_textgrid(p)["phones"]
    assert [s.label for s in segs] == ["sil", "AH0", 'say "hi"']
    assert segs[1] == Segment(0.5, 1.0, "AH0")


def test_htk_and_festival_lab(tmp_path):
    p = tmp_path / "a.lab"
    write_lab(p, [Segment(0.0, 0.5, "pau"), Segment(0.5, 0.75, "b")])
    assert read_lab(p) == [Segment(0.0, 0.5, "pau"), Segment(0.5, 0.75, "b")]
    f = tmp_path / "f.lab"
    f.write_text("separator ;\nnfields 1\n#\n0.5 125 pau\n0.75 125 b\n")
    assert read_lab(f) == [Segment(0.0, 0.5, "pau"), Segment(0.5, 0.75, "b")]


def test_overlapping_segments_are_refused_with_time(tmp_path):
    p = tmp_path / "bad.TextGrid"
    write_textgrid(p, {"phones": [Segment(0.0, 0.5, "pau"), Segment(0.4, 0.8, "b")]})
    with pytest.raises(InputError, match=r"bad\.TextGrid, 0\.400 s: segment 'b' overlaps"):
        read_phone_segments(p)


def test_missing_phone_tier_is_named(tmp_path):
    p = tmp_path / "t.TextGrid"
    write_textgrid(p, {"words": [Segment(0, 1, "a")], "other": [Segment(0, 1, "b")]})
    with pytest.raises(InputError, match="no phone tier"):
        read_phone_segments(p)


def test_a_malformed_lab_line_is_named_by_its_number(tmp_path):
    path = tmp_path / "x.lab"
    path.write_text("0 1000000 pau\n1000000 2000000 aa\n2000000 oops b\n")
    with pytest.raises(InputError, match=r"x\.lab, line 3: malformed \.lab line '2000000 oops b'"):
        read_lab(path)


def test_lab_times_in_seconds_or_htk_units_are_told_apart_and_logged(tmp_path, caplog):
    import logging

    from facesynth.formats.labels import lab_time_unit

    seconds, htk, whole = tmp_path / "s.lab", tmp_path / "h.lab", tmp_path / "w.lab"
    seconds.write_text("0 0.25 pau\n0.25 0.4 m\n0.4 1.0 aa\n")
    htk.write_text("0 2500000 pau\n2500000 4000000 m\n4000000 10000000 aa\n")
    whole.write_text("0 1 pau\n1 2 aa\n")
    with caplog.at_level(logging.INFO, logger="facesynth"):
        assert read_lab(seconds) == read_lab(htk) == [Segment(0.0, 0.25, "pau"), Segment(0.25, 0.4, "m"),
                                                      Segment(0.4, 1.0, "aa")]
        assert read_lab(whole) == [Segment(0.0, 1.0, "pau"), Segment(1.0, 2.0, "aa")]
    assert "s.lab: .lab times read as seconds" in caplog.text and "h.lab: .lab times read as HTK 100 ns" in caplog.text
    assert lab_time_unit([("0", "9999")])[0] == 1.0 and lab_time_unit([("0", "10000")])[0] == 1e7
    assert lab_time_unit([("0", "1e5")])[0] == 1.0
