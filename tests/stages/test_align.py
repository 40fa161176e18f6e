import numpy as np
import pytest
from coded_audio import COMPRESSED, boundary_shift, coded

from facesynth.base.errors import InputError
from facesynth.formats.audio import read_audio
from facesynth.formats.labels import read_phone_segments, read_textgrid
from facesynth.stages import align


def _pronunciations(word):
    from facesynth.base.phonemes import cmudict, to_festival

    return [[to_festival(p) for p in pron] for pron in cmudict()[word]]


def test_alignment_gives_festival_phones_near_the_true_boundaries(tiny_corpus, config, tmp_path):
    import csv

    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == "neutral_s001")
    out = tmp_path / "a.TextGrid"
    align.run(tiny_corpus / row["audio"], row["transcript"], out, config.settings("align"))
    got = read_phone_segments(out)
    words = read_textgrid(out)["words"]
    assert [w.label for w in words] == row["transcript"].split()
    for w in words:  # each word's phones are one of its dictionary pronunciations, stress-mapped
        inside = [s.label for s in got if s.label != "pau" and w.start - 1e-6 <= s.start < w.end - 1e-6]
        assert inside in _pronunciations(w.label)
    truth = [s for s in read_phone_segments(tiny_corpus / row["alignment"]) if s.label != "pau"]
    mine = [s for s in got if s.label != "pau"]
    errors = [abs(a.start - b.start) for a, b in zip(mine, truth)]
    assert np.median(errors) < 0.05  # seconds; the audio is synthetic, the aligner is not tuned to it
    assert got[0].start == 0.0 and got[-1].end == pytest.approx(len(read_audio(tiny_corpus / row["audio"])[0]) / 16000, abs=0.01)


def test_any_rate_and_stereo(tiny_corpus, config, tmp_path):
    from scipy.signal import resample_poly

    x, rate = read_audio(tiny_corpus / "audio" / "neutral_s001.wav")
    stereo = np.stack([resample_poly(x, 441, 160)] * 2, 1)
    p = tmp_path / "stereo.wav"
    import soundfile as sf

    sf.write(p, stereo, 44100)
    import csv

    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == "neutral_s001")
    align.run(p, row["transcript"], tmp_path / "s.TextGrid", config.settings("align"))
    assert "phones" in read_textgrid(tmp_path / "s.TextGrid")


def test_unknown_word_is_named_and_a_dictionary_fixes_it(tiny_corpus, config, tmp_path):
    import csv

    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == "neutral_s001")
    words = row["transcript"].split()
    target = max(words, key=len)  # respell one word; the audio still says it
    text = " ".join("zorblat" if w == target else w for w in words)
    wav = tiny_corpus / row["audio"]
    with pytest.raises(InputError, match=r"no pronunciation for 'zorblat'; give one in a file passed with --dict"):
        align.run(wav, text, tmp_path / "x.TextGrid", config.settings("align"))
    assert not (tmp_path / "x.TextGrid").exists()
    d = tmp_path / "extra.dict"
    d.write_text("zorblat  " + " ".join(lexicon_arpabet(target)) + "\n")
    align.run(wav, text, tmp_path / "x.TextGrid", config.settings("align"), dict_path=d)
    assert "zorblat" in [w.label for w in read_textgrid(tmp_path / "x.TextGrid")["words"]]


def test_text_that_is_not_spoken_is_warned_about(tiny_corpus, config, tmp_path):
    wav = tiny_corpus / "audio" / "neutral_s000.wav"
    summary = align.run(wav, "the water", tmp_path / "x.TextGrid", config.settings("align"))
    assert any("the text may not be what is said" in w or "may lack words" in w for w in summary.warnings)


def lexicon_arpabet(word):
    from facesynth.base.phonemes import cmudict

    return cmudict()[word][0]


def test_align_command_names_the_method_and_warns_of_a_partial_transcript(tiny_corpus, tmp_path):
    import csv

    from click.testing import CliRunner

    from facesynth.cli import main

    row = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == "neutral_s001")
    wav = str(tiny_corpus / row["audio"])
    r = CliRunner().invoke(main, ["align", wav, "--text", row["transcript"], "-o", str(tmp_path / "a.TextGrid")])
    assert r.exit_code == 0 and "(pocketsphinx) ->" in r.output and "warning" not in r.output
    first = row["transcript"].split()[0]
    r = CliRunner().invoke(main, ["align", wav, "--text", first, "-o", str(tmp_path / "b.TextGrid")])
    assert r.exit_code == 0 and "warning: " in r.output and "Traceback" not in r.output


@pytest.mark.parametrize("name", COMPRESSED)
def test_coded_speech_aligns_as_the_wav(coded_speech, tiny_corpus, held_out_take, tmp_path, name):
    """The held-out sentence as M4A, MP3, Opus, Ogg or an MP4's sound: the same phones, each
    boundary within 50 ms of the WAV's (measured: at most 10 ms apart for MP3 and Opus, 30 ms for
    AAC; the aligner's frames are 10 ms)."""
    import csv

    from click.testing import CliRunner

    from facesynth.cli import main

    text = next(r for r in csv.DictReader(open(tiny_corpus / "manifest.csv")) if r["take"] == held_out_take)["transcript"]
    got = {}
    for kind, path in (("wav", coded_speech["wav"]), (name, coded(coded_speech, name))):
        r = CliRunner().invoke(main, ["align", str(path), "--text", text, "-o", str(tmp_path / f"{kind}.TextGrid")])
        assert r.exit_code == 0, r.output
        got[kind] = read_phone_segments(tmp_path / f"{kind}.TextGrid")
    assert boundary_shift(got["wav"], got[name]) <= 0.05
