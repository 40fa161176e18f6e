"""Text in languages other than English: each language's known words carry the expected
articulatory features, each phone resolves to the English phone nearest in those features
(English phones to themselves), and a synthesized line closes the mouth at its bilabials and
rounds it at its rounded vowels. The G2P backends are an optional extra (``languages``); the
tests that read a language skip without it."""

import importlib.util

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.base.ipa import FESTIVAL_IPA, IPA, PLACES, TARGETS, distance, features, nearest_festival, visemes
from facesynth.base.phonemes import PHONES
from facesynth.cli import main
from facesynth.domain.speech.languages import PINYIN_FINALS, PINYIN_INITIALS, is_english, pinyin_ipa, primary, words_of
from facesynth.formats.labels import read_textgrid
from facesynth.model.motion import Motion

GRUUT = pytest.mark.skipif(importlib.util.find_spec("gruut") is None, reason="gruut is not installed (pip install 'facesynth[languages]')")
PINYIN = pytest.mark.skipif(importlib.util.find_spec("pypinyin") is None,
                            reason="pypinyin is not installed (pip install 'facesynth[languages]')")


def _pack(tag: str):
    return pytest.mark.skipif(importlib.util.find_spec(f"gruut_lang_{tag}") is None,
                              reason=f"gruut's {tag} pack is not installed (pip install 'facesynth[languages]')")


def _word(text: str, language: str, which: str):
    return next(w for w in words_of(text, language) if w.text.lower() == which)


# --- the feature table ---------------------------------------------------------------------------


def test_every_english_phone_is_described_and_resolves_to_itself():
    assert set(FESTIVAL_IPA) == set(PHONES) - {"pau"}
    for phone in TARGETS:
        assert nearest_festival(FESTIVAL_IPA[phone]) == phone
        assert distance(features(FESTIVAL_IPA[phone]), features(FESTIVAL_IPA[phone])) == 0


@pytest.mark.parametrize("ipa, english", [
    ("y", "uw"), ("yː", "uw"), ("ʏ", "uh"),  # rounded front vowels: the rounding, not the tongue
    ("ʂ", "sh"), ("ʐ", "zh"), ("ʈʂ", "ch"), ("tɕ", "ch"), ("ɕ", "sh"),  # retroflexes and palatals -> postalveolar
    ("β", "b"), ("ɸ", "p"),  # bilabial fricatives close the lips
    ("ɾ", "r"), ("r", "r"), ("pf", "f"), ("ɔ̃", "ao"), ("ɛ̃", "eh"),
])
def test_a_foreign_phone_resolves_to_the_english_phone_nearest_in_features(ipa, english):
    assert nearest_festival(ipa) == english


def test_german_ich_laut_resolves_in_the_palatal_region():
    assert nearest_festival("ç") in ("sh", "hh", "y")
    assert nearest_festival("x") in ("hh", "k")


def test_the_visemes_follow_from_the_features():
    assert visemes("m")["lips closed"] and visemes("b")["jaw"] == "closed"
    assert visemes("f")["lower lip to teeth"] and not visemes("f")["lips closed"]
    assert visemes("y")["rounded"] and not visemes("y")["spread"]
    assert visemes("i")["spread"] and visemes("a")["jaw"] == "open"
    assert not any(visemes(p)["lips closed"] for p in ("t", "s", "k", "i", "u"))


def test_unknown_symbols_are_refused_and_every_table_phone_is_described():
    with pytest.raises(KeyError):
        features("☃")
    for table in (PINYIN_INITIALS, PINYIN_FINALS):
        for phones in table.values():
            assert all(features(p) for p in phones)
    assert all(f.place in PLACES for f in IPA.values())


def test_language_tags():
    assert is_english("en") and is_english("en-GB") and is_english("") and not is_english("de")
    assert primary("zh-Hans") == "cmn" and primary("fr_CA") == "fr" and primary("CMN") == "cmn"


# --- each language's known words ----------------------------------------------------------------


@GRUUT
@_pack("fr")
def test_french_tu_has_a_rounded_close_front_vowel():
    tu = _word("Tu vas bien?", "fr", "tu")
    y = features(tu.ipa[-1])
    assert y.vowel and y.rounded and y.backness == 0 and y.height == 0
    assert tu.phones == ("t", "uw")  # rounding wins over the tongue's place
    pomme = _word("Je voudrais une pomme.", "fr", "pomme")
    assert pomme.phones[0] == "p" and pomme.phones[-1] == "m"


@GRUUT
@_pack("de")
def test_german_ich_has_a_palatal_fricative():
    ich = _word("Ich bin müde.", "de", "ich")
    c = features(ich.ipa[-1])
    assert c.place == "palatal" and c.manner == "fricative" and not c.voiced
    mude = _word("Ich bin müde.", "de", "müde")
    assert any(features(p).rounded and features(p).vowel and features(p).backness == 0 for p in mude.ipa)


@GRUUT
@_pack("es")
def test_spanish_trill_and_tap_and_bilabials():
    perro, pero = _word("perro pero", "es", "perro"), _word("perro pero", "es", "pero")
    assert features("r").manner == "trill" and "r" in perro.ipa
    assert "ɾ" in pero.ipa and "r" in pero.phones
    mama = _word("Mi mamá come.", "es", "mamá")
    assert [visemes(p)["lips closed"] for p in mama.ipa] == [True, False, True, False]


@PINYIN
def test_mandarin_zhe_is_retroflex_and_lu_rounded_front():
    zhe = _word("这是绿的", "cmn", "这")
    assert features(zhe.ipa[0]).place == "retroflex" and zhe.phones[0] == "ch"
    shi = _word("这是绿的", "cmn", "是")
    assert features(shi.ipa[0]).place == "retroflex"
    lv = _word("这是绿的", "cmn", "绿")
    assert features(lv.ipa[-1]).rounded and features(lv.ipa[-1]).backness == 0
    assert pinyin_ipa("zh", "e4") == ("ʈʂ", "ɤ") and pinyin_ipa("s", "i4") == ("s", "ɨ")


@GRUUT
@_pack("fr")
def test_the_users_dictionary_comes_first(tmp_path):
    own = tmp_path / "lexicon-fr.txt"
    own.write_text("# my words\npomme  p o m\n", "utf-8")
    pomme = next(w for w in words_of("une pomme", "fr", str(tmp_path / "lexicon-{language}.txt")) if w.text == "pomme")
    assert pomme.ipa == ("p", "o", "m")
    own.write_text("pomme  p ☃ m\n", "utf-8")
    with pytest.raises(InputError, match=r"lexicon-fr.txt, line 1: unknown IPA phone '☃'"):
        words_of("une pomme", "fr", str(own))


def test_a_language_no_backend_reads_is_one_sentence_and_exit_1(tmp_path):
    wav = tmp_path / "a.wav"
    import soundfile

    soundfile.write(wav, np.zeros(16000, np.float32), 16000)
    out = tmp_path / "a.TextGrid"
    result = CliRunner().invoke(main, ["align", str(wav), "--text", "hallo", "--language", "tlh", "-o", str(out)])
    assert result.exit_code == 1
    assert "language 'tlh': no G2P backend reads it" in result.output and "Traceback" not in result.output
    assert not out.exists()


# --- a synthesized line: the mouth closes at bilabials and rounds at rounded vowels --------------


def _mouth(motion: Motion, phones, wanted) -> tuple[np.ndarray, np.ndarray]:
    """The lip gap and mouth width (mm) at the middle of each phone of ``wanted``."""
    names = list(motion.marker_names)
    up, lo, r, left = (names.index(n) for n in ("ULI_C", "LLI_C", "MC_R", "MC_L"))
    gap, width = [], []
    for s in phones:
        if s.label in wanted:
            t = min(int(round((s.start + s.end) / 2 * motion.fps)), len(motion.markers) - 1)
            gap.append(np.linalg.norm(motion.markers[t, up] - motion.markers[t, lo]))
            width.append(np.linalg.norm(motion.markers[t, r] - motion.markers[t, left]))
    return np.array(gap), np.array(width)


LINES = {
    "fr": "Papa boit une pomme, tu vas à Paris.",
    "de": "Mama isst Brot und Butter, bitte.",
    "es": "Papá compra pan y uvas, mamá bebe.",
    "cmn": "爸爸买苹果，妈妈不怕。",
}


@pytest.mark.parametrize("language", ["fr", "de", "es", "cmn"])
def test_a_synthesized_line_closes_at_bilabials_and_rounds_at_rounded_vowels(language, tiny_db, tiny_corpus, tmp_path):
    if language == "cmn":
        if importlib.util.find_spec("pypinyin") is None:
            pytest.skip("pypinyin is not installed (pip install 'facesynth[languages]')")
    elif importlib.util.find_spec(f"gruut_lang_{language}") is None:
        pytest.skip(f"gruut's {language} pack is not installed (pip install 'facesynth[languages]')")
    audio = tiny_corpus / "audio" / "neutral_s000.wav"
    line = LINES[language]
    runner = CliRunner()
    made = runner.invoke(main, ["synthesize", str(tiny_db), "--audio", str(audio), "--text", line, "--language", language,
                                "--set", "synthesize.voice_given=off", "-o", str(tmp_path / "m.h5")])
    assert made.exit_code == 0, made.output
    aligned = runner.invoke(main, ["align", str(audio), "--text", line, "--language", language,
                                   "-o", str(tmp_path / "a.TextGrid")])
    assert aligned.exit_code == 0, aligned.output
    phones = read_textgrid(tmp_path / "a.TextGrid")["phones"]
    motion = Motion.read(tmp_path / "m.h5")
    closed, _ = _mouth(motion, phones, {"p", "b", "m"})
    open_, _ = _mouth(motion, phones, {"aa", "ae", "ah"})
    _, rounded = _mouth(motion, phones, {"uw", "uh", "ow", "ao", "w"})
    _, unrounded = _mouth(motion, phones, {"iy", "ih", "ey", "eh", "ae", "aa", "ah", "ay"})
    assert len(closed) >= 3 and len(open_) >= 2 and len(rounded) >= 1
    # measured on the tiny database: lips 0.5-1.0 mm apart at bilabials against 7.5-8.6 mm at open
    # vowels; the mouth 2.4-5.4 mm narrower at rounded vowels than at unrounded ones
    assert closed.mean() < 0.3 * open_.mean()
    assert rounded.mean() < unrounded.mean() - 1.0


def test_the_docs_viseme_table_is_the_code():
    from pathlib import Path

    from facesynth.base.ipa import viseme_table

    page = (Path(__file__).resolve().parents[2] / "docs" / "methods.md").read_text("utf-8")
    assert viseme_table() in page


@GRUUT
@_pack("fr")
def test_the_api_reads_a_line_in_its_language(tiny_corpus):
    import facesynth

    heard = facesynth.utterance_from_audio(tiny_corpus / "audio" / "neutral_s000.wav", "Papa boit une pomme.",
                                           language="fr")
    assert [w.label for w in heard.alignment.words] == ["Papa", "boit", "une", "pomme"]
    spoken = [p for p in heard.phones if p != "pau"]
    assert spoken == [p for w in words_of("Papa boit une pomme.", "fr") for p in w.phones]
    assert "uw" in spoken  # une: the rounded front /y/


@GRUUT
@_pack("de")
def test_a_capture_manifests_language_column_aligns_each_take_in_its_language(tiny_corpus, config, tmp_path):
    from facesynth.model.corpus import Corpus
    from facesynth.stages import ingest

    manifest = tmp_path / "manifest.csv"
    corpus = tiny_corpus.resolve()
    manifest.write_text(
        "take,mocap,audio,transcript,language\n"
        f"de_take,{corpus / 'mocap/neutral_s000.c3d'},{corpus / 'audio/neutral_s000.wav'},Mama isst Brot,de\n"
        f"en_take,{corpus / 'mocap/neutral_s001.c3d'},{corpus / 'audio/neutral_s001.wav'},laugh tail with west roll,\n",
        "utf-8")
    ingest.run(manifest, tmp_path / "corpus.h5", config.settings("ingest"), config.settings("align"))
    read = Corpus.read(tmp_path / "corpus.h5")
    table = read.phones
    phones = {take: [p for p, k in zip(table.phone, table.take) if k == t and p != "pau"]
              for t, take in enumerate(read.takes.name)}
    assert phones["de_take"] == [p for w in words_of("Mama isst Brot", "de") for p in w.phones]
    assert phones["en_take"][:3] == ["l", "ae", "f"]  # English: the CMU dictionary's "laugh"


# --- audio alone in another language: phones, not English words --------------------------------


@pytest.fixture(scope="module")
def mandarin_clip(tmp_path_factory):
    """Four seconds of FACEGOOD's Mandarin take (shipped with the package), as a WAV."""
    from importlib import resources

    import soundfile

    data, rate = soundfile.read(str(resources.files("facesynth").joinpath("data/facegood_audio.ogg")), dtype="float32")
    path = tmp_path_factory.mktemp("mandarin") / "cmn.wav"
    soundfile.write(path, (data if data.ndim == 1 else data.mean(axis=1))[: 4 * rate], rate)
    return path


def test_audio_alone_in_another_language_is_decoded_as_phones_not_english_words(mandarin_clip, tmp_path):
    runner = CliRunner()
    english = runner.invoke(main, ["align", str(mandarin_clip), "-o", str(tmp_path / "en.TextGrid")])
    mandarin = runner.invoke(main, ["align", str(mandarin_clip), "--language", "cmn", "-o", str(tmp_path / "cmn.TextGrid")])
    assert english.exit_code == 0 and mandarin.exit_code == 0, english.output + mandarin.output
    assert "(words/" in english.output and "words" in read_textgrid(tmp_path / "en.TextGrid")
    assert "(phones)" in mandarin.output and set(read_textgrid(tmp_path / "cmn.TextGrid")) == {"phones"}


@GRUUT
@_pack("fr")
def test_an_english_dict_with_another_language_is_refused_in_one_sentence(mandarin_clip, tmp_path):
    own = tmp_path / "own.dict"
    own.write_text("pomme  P AA M\n")
    out = tmp_path / "a.TextGrid"
    result = CliRunner().invoke(main, ["align", str(mandarin_clip), "--text", "une pomme", "--language", "fr",
                                       "--dict", str(own), "-o", str(out)])
    assert result.exit_code == 1 and "align.dictionary" in result.output and not out.exists()


def test_audio_alone_in_another_language_takes_the_voices_path(mandarin_clip, config):
    """Recognised phones are what sends synthesize's mouth to the voice's articulation model."""
    import dataclasses

    from facesynth.domain.methods import steps

    align = dataclasses.replace(config.settings("align"), language="cmn")
    read = steps.read_utterance(config.settings("ingest"), audio=mandarin_clip, align=align)
    assert read.recognized and read.alignment.method == "phones" and not read.alignment.words


def test_an_english_line_reads_the_users_ipa_dictionary_first(mandarin_clip, tmp_path):
    (tmp_path / "lexicon-en.txt").write_text("zorblax  z ɔ ɹ b l æ k s\n", "utf-8")
    out = tmp_path / "a.TextGrid"
    result = CliRunner().invoke(main, ["align", str(mandarin_clip), "--text", "the zorblax", "--set",
                                       f"align.dictionary={tmp_path / 'lexicon-{language}.txt'}", "-o", str(out)])
    assert result.exit_code == 0, result.output
    phones = [s.label for s in read_textgrid(out)["phones"] if s.label != "pau"]
    assert phones[-8:] == ["z", "ao", "r", "b", "l", "ae", "k", "s"]
    assert [w.label for w in read_textgrid(out)["words"]] == ["the", "zorblax"]


@pytest.mark.parametrize("tag", ["de", "fr", "es"])
def test_every_phone_of_a_gruut_lexicon_has_its_articulation(tag):
    """The feature table covers the phone inventory of each installed pack's lexicon (its
    word_phonemes table), a phone written as several (Spanish ``we``) split into its parts."""
    import sqlite3
    from importlib import resources

    from facesynth.base.ipa import split
    from facesynth.domain.speech.languages import _PAUSES

    if importlib.util.find_spec(f"gruut_lang_{tag}") is None:
        pytest.skip(f"gruut's {tag} pack is not installed (pip install 'facesynth[languages]')")
    lexicon = resources.files(f"gruut_lang_{tag}").joinpath("lexicon.db")
    if not lexicon.is_file():
        pytest.skip(f"gruut's {tag} pack has no lexicon.db here")
    with resources.as_file(lexicon) as path:
        con = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
        inventory = {p for (row,) in con.execute("SELECT phonemes FROM word_phonemes") for p in row.split()}
        con.close()
    assert len(inventory) > 30
    for phone in inventory - _PAUSES:
        assert all(features(p) for p in split(phone)), phone


@GRUUT
@_pack("es")
def test_a_phone_written_as_two_is_read_as_two():
    assert _word("Es bueno.", "es", "bueno").ipa == ("b", "w", "e", "n", "o")
