"""A capture in another language: takes transcribed in German become a motion database whose
nodes keep their German (IPA) phones, and a new German line searches it by those phones'
articulatory features."""

import csv
import dataclasses
import importlib.util

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.ipa import features, phone_distance
from facesynth.base.phonemes import PAU
from facesynth.cli import main
from facesynth.domain.search.costs import step_costs
from facesynth.model.corpus import Corpus
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase

pytestmark = pytest.mark.skipif(importlib.util.find_spec("gruut_lang_de") is None,
                                reason="gruut's German pack is not installed (pip install 'facesynth[languages]')")

#: German sentences with the ich-laut /ç/, the ach-laut /x/ and /χ/, the uvular /ʁ/, /pf/ and
#: /ʃ/ but no /y/ (ü): the line synthesized below has /y/, which the database then lacks.
SENTENCES = ("Ich mache Milch mit Honig.", "Das Buch ist rot.", "Mama isst Brot und Butter.",
             "Papa trinkt Wasser.", "Acht Pferde laufen schnell.", "Ich rechne noch.")
LINE = "Die Tür ist grün, ich mache Kuchen."


@pytest.fixture(scope="module")
def german(tiny_corpus, config, tmp_path_factory):
    """The tiny corpus's takes transcribed in German (language column ``de``), ingested and
    built into a database: (corpus.h5, db.h5)."""
    from facesynth.stages import build_db, ingest, normalize, pca

    d = tmp_path_factory.mktemp("german")
    with open(tiny_corpus / "manifest.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    with open(d / "manifest.csv", "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f)
        out.writerow(["take", "mocap", "audio", "transcript", "emotion", "sentence", "split", "language"])
        for i, r in enumerate(rows):
            out.writerow([r["take"], tiny_corpus.resolve() / r["mocap"], tiny_corpus.resolve() / r["audio"],
                          SENTENCES[i % len(SENTENCES)], r["emotion"], r["sentence"], r["split"], "de"])
    ingest.run(d / "manifest.csv", d / "corpus.h5", config.settings("ingest"), config.settings("align"))
    normalize.run(d / "corpus.h5", d / "normalized.h5", config.settings("normalize"))
    pca.run(d / "normalized.h5", d / "pca.h5", config.settings("pca"))
    build_db.run(d / "pca.h5", d / "db.h5", config.settings("build_db"))
    return d / "corpus.h5", d / "db.h5"


def test_the_database_keeps_the_takes_german_phones(german):
    corpus_path, db_path = german
    phones = Corpus.read(corpus_path, audio=False).phones
    assert phones.ipa is not None and len(phones.ipa) == len(phones.phone)
    assert all((q == "") == (p == PAU) for p, q in zip(phones.phone, phones.ipa))
    db = MotionDatabase.read(db_path)
    assert db.nodes.ipa is not None and len(db.nodes.ipa) == len(db.nodes)
    held = set(db.nodes.ipa)
    assert {"ç", "ʁ", "ʃ"} <= held and ("x" in held or "χ" in held)
    assert not any(features(q).rounded and features(q).vowel and features(q).backness < 0.25 for q in held)  # no ü, ö
    # each node's phone is its IPA phone's nearest English phone; /ç/ and /ʃ/ share one, but not their IPA
    at = {q: {p for p, r in zip(db.nodes.phone, db.nodes.ipa) if r == q} for q in ("ç", "ʃ")}
    assert all(len(v) == 1 for v in at.values())


def test_a_german_line_matches_the_databases_german_phones_by_features(german, config, tiny_corpus):
    import facesynth

    _, db_path = german
    db = MotionDatabase.read(db_path)
    heard = facesynth.utterance_from_audio(tiny_corpus / "audio" / "neutral_s000.wav", LINE, language="de")
    utt = heard.data.utterance
    assert utt.ipa is not None
    s = config.settings("synthesize")
    oc = step_costs(utt.phones, utt.emotions, db.nodes.phone, db.nodes.emotion, {}, s, utt.ipa, db.nodes.ipa).oc
    node_ipa = np.array(db.nodes.ipa)
    unit = s.alpha5 * s.pnt
    t = utt.ipa.index("ç")
    # the database has /ç/: its /ç/ nodes cost nothing, its /ʃ/ nodes (the same English phone) do
    assert (oc[t][node_ipa == "ç"] == 0).all() and (oc[t][node_ipa == "ʃ"] > 0).all()
    # /y/ (Tür, grün) the database lacks: its nearest phone's nodes cost 0, every other node by how
    # much further its phone is, the rounded vowels least
    t = next(k for k, q in enumerate(utt.ipa) if q and features(q).vowel and features(q).rounded
             and features(q).backness < 0.25)
    d = np.array([phone_distance(utt.ipa[t], q) for q in node_ipa])
    extra = d - d.min()
    expected = np.where(extra == 0, 0.0, np.minimum(1.0, s.alpha4 + (1 - s.alpha4) * extra / s.phone_match_scale)) * unit
    assert np.allclose(oc[t], expected, rtol=1e-6) and d.min() > 0
    best = node_ipa[np.argmin(oc[t])]
    assert features(best).vowel and features(best).rounded, best


def test_a_german_line_is_synthesized_from_the_german_database(german, tiny_corpus, tmp_path):
    _, db_path = german
    runner = CliRunner()
    made = runner.invoke(main, ["synthesize", str(db_path), "--audio", str(tiny_corpus / "audio" / "neutral_s000.wav"),
                                "--text", LINE, "--language", "de", "--set", "synthesize.voice_given=off",
                                "-o", str(tmp_path / "m.h5")])
    assert made.exit_code == 0, made.output
    motion = Motion.read(tmp_path / "m.h5", search=True)
    db = MotionDatabase.read(db_path)
    assert db.nodes.ipa is not None and motion.path is not None
    import facesynth

    utt = facesynth.utterance_from_audio(tiny_corpus / "audio" / "neutral_s000.wav", LINE, language="de").data.utterance
    assert list(motion.path.phone) == list(utt.phones) and utt.ipa is not None
    chosen = {t: db.nodes.ipa[int(j)] for t, j in enumerate(motion.path.node) if utt.phones[t] != PAU}
    # every step took a German node; the node's IPA is the step's own wherever the database has it
    # and the search took a node of that phone; /y/ of Tür and grün, which it lacks, a rounded vowel
    assert all(chosen.values())
    for t, q in chosen.items():
        if features(utt.ipa[t]).vowel and features(utt.ipa[t]).rounded and features(utt.ipa[t]).backness < 0.25:
            assert features(q).vowel and features(q).rounded, (utt.ipa[t], q)
    check = CliRunner().invoke(main, ["check", str(db_path)])
    assert check.exit_code == 0, check.output


def test_a_database_written_before_phones_kept_their_ipa_reads_as_english(tiny_db):
    db = MotionDatabase.read(tiny_db)
    assert db.nodes.ipa is None


def test_the_paper_rule_ignores_the_ipa(german, config):
    _, db_path = german
    db = MotionDatabase.read(db_path)
    s = dataclasses.replace(config.settings("synthesize"), phone_match="viseme")
    with_ipa = step_costs(["sh"], ["neutral"], db.nodes.phone, db.nodes.emotion, {}, s, ["ç"], db.nodes.ipa).oc
    without = step_costs(["sh"], ["neutral"], db.nodes.phone, db.nodes.emotion, {}, s).oc
    assert np.array_equal(with_ipa, without)
