"""The search's phone matching by articulatory features (synthesize.phone_match): Table II's
levels as its special case, English lines unchanged, and phones of other languages matched by
their features against an English database."""

import dataclasses
import importlib.util

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.base.ipa import FESTIVAL_IPA, features, match_level, nearest_phone, phone_distance
from facesynth.base.phonemes import PAU, viseme
from facesynth.domain.search.costs import step_costs
from facesynth.domain.speech.utterance import stand_in_phones, utterance
from facesynth.model.motiondb import MotionDatabase


@pytest.fixture()
def s():
    return Config.load(None, ("synthesize.pnt=10", "synthesize.alpha4=0.5", "synthesize.alpha5=4")).settings("synthesize")


def _mode(s, mode: str):
    return dataclasses.replace(s, phone_match=mode)


def _table_ii(phones, node_phone, s) -> np.ndarray:
    """Table II written out: the same phone 0, the same viseme alpha4 alpha5 PNT, else alpha5 PNT."""
    out = np.zeros((len(phones), len(node_phone)), np.float32)
    for t, p in enumerate(phones):
        for j, q in enumerate(node_phone):
            if p != PAU:
                out[t, j] = 0.0 if p == q else s.alpha4 * s.alpha5 * s.pnt if viseme(p) == viseme(q) else s.alpha5 * s.pnt
    return out


def test_match_level_runs_from_table_ii_rule_2_to_rule_3(s):
    assert match_level(0.0, 0.5, 3.0) == 0.0
    assert match_level(1e-9, 0.5, 3.0) == pytest.approx(0.5)         # any other phone: at least rule 2's level
    assert match_level(1.5, 0.5, 3.0) == pytest.approx(0.75)
    assert match_level(3.0, 0.5, 3.0) == 1.0 and match_level(9.0, 0.5, 3.0) == 1.0  # rule 3's level, no more
    levels = [match_level(d, 0.552, 3.0) for d in np.linspace(0.01, 5, 50)]
    assert levels == sorted(levels)


@pytest.mark.parametrize("mode", ["viseme", "unseen"])
def test_an_english_line_costs_table_ii_exactly(s, mode):
    rng = np.random.default_rng(3)
    spoken = sorted(FESTIVAL_IPA)
    phones = [str(p) for p in rng.choice(spoken + [PAU], 40)]
    nodes = [str(p) for p in rng.choice(spoken, 200)]
    want = _table_ii(phones, nodes, s)
    for ipa in (None, [""] * len(phones)):  # an English line carries no IPA, or empty IPA
        got = step_costs(phones, ["neutral"] * 40, nodes, ["neutral"] * 200, {}, _mode(s, mode), ipa).oc
        assert np.array_equal(got.view(np.uint32), want.view(np.uint32))


def test_features_for_every_phone_keep_the_same_phone_free_and_others_dearer(s):
    phones, nodes = ["uw", "s", "m"], ["uw", "uh", "iy", "s", "sh", "m", "p", "aa"]
    oc = step_costs(phones, ["neutral"] * 3, nodes, ["neutral"] * 8, {}, _mode(s, "features")).oc
    unit = s.alpha5 * s.pnt
    assert oc[0, 0] == 0 and oc[1, 3] == 0 and oc[2, 5] == 0
    assert (np.delete(oc[0], 0) >= s.alpha4 * unit - 1e-4).all() and oc.max() <= unit + 1e-4
    assert oc[0, 1] < oc[0, 2]           # /uw/: rounded /uh/ nearer than spread /iy/
    assert oc[2, 6] < oc[2, 7]           # /m/: /p/ (lips closed) nearer than /aa/


def test_a_phone_the_database_has_keeps_table_ii_by_its_english_viseme(s):
    # French /i/ is English /iy/: the database has it, so Table II on /iy/ exactly
    nodes = ["iy", "ih", "uw", "s"]
    oc = step_costs(["iy"], ["neutral"], nodes, ["neutral"] * 4, {}, s, ["i"]).oc
    assert np.allclose(oc[0], _table_ii(["iy"], nodes, s)[0])


@pytest.fixture(scope="module")
def db(tiny_db) -> MotionDatabase:
    return MotionDatabase.read(tiny_db)


def _costs(db, ipa: str, festival: str, s) -> dict[str, float]:
    """The observation cost of the IPA phone ``ipa`` (standing as ``festival``) for each phone of ``db``."""
    oc = step_costs([festival], ["neutral"], db.nodes.phone, db.nodes.emotion, {}, s, [ipa]).oc[0]
    return {p: float(oc[db.nodes.phone.index(p)]) for p in dict.fromkeys(db.nodes.phone)}


def test_french_y_costs_least_at_rounded_nodes(db, s):
    costs = _costs(db, "y", "uw", s)
    cheapest = min(costs, key=costs.__getitem__)
    assert features(FESTIVAL_IPA[cheapest]).rounded
    vowels = {p: features(FESTIVAL_IPA[p]) for p in costs if features(FESTIVAL_IPA[p]).vowel}
    rounded = [costs[p] for p, f in vowels.items() if f.rounded]
    spread = [costs[p] for p, f in vowels.items() if not f.rounded]
    assert max(rounded) < min(spread)  # every rounded vowel is nearer than every unrounded one
    # front and close as well: /uw/ (close back rounded) nearer than /ao/ (open-mid back rounded)
    if "ao" in costs and "uw" in costs:
        assert costs["uw"] < costs["ao"]


def _every_english_phone(ipa: str, festival: str, s) -> dict[str, float]:
    """:func:`_costs` against a database holding one node of every English phone."""
    from facesynth.base.ipa import TARGETS

    oc = step_costs([festival], ["neutral"], list(TARGETS), ["neutral"] * len(TARGETS), {}, s, [ipa]).oc[0]
    return dict(zip(TARGETS, map(float, oc)))


def test_german_ich_laut_is_matched_by_its_place(db, s):
    costs = _every_english_phone("ç", "sh", s)
    assert min(costs, key=costs.__getitem__) == "sh"              # postalveolar: the place nearest palatal
    assert costs["sh"] < costs["s"] < costs["th"] < costs["f"] <= costs["p"]  # further forward, dearer; the lips at most
    ach = _every_english_phone("x", "hh", s)
    assert ach["hh"] < ach["k"] < ach["t"] < ach["p"]             # /x/ velar fricative: /hh/, /k/, then forward
    # the tiny database has no /sh/: the alveolar /s/ is its nearest fricative, the labiodental /f/ dearer
    tiny = _costs(db, "ç", "sh", s)
    fricatives = {p: c for p, c in tiny.items() if features(FESTIVAL_IPA[p]).manner == "fricative"}
    assert min(fricatives, key=fricatives.__getitem__) == "s"
    assert tiny["s"] < tiny["th"] < tiny["f"] <= tiny["p"]


def test_mandarin_retroflexes_take_the_postalveolars(db, s):
    for ipa, want in (("ʂ", "sh"), ("ʈʂ", "ch"), ("ʐ", "zh"), ("ɻ", "r")):
        costs = _every_english_phone(ipa, want, s)
        assert min(costs, key=costs.__getitem__) == want, (ipa, costs)
    # on the tiny database (no /sh/, /ch/): /ʂ/ takes the sibilant /s/ before the dental and the lips
    tiny = _costs(db, "ʂ", "sh", s)
    assert min(tiny, key=tiny.__getitem__) == "s" and tiny["s"] < tiny["th"] < tiny["f"]


def test_a_phone_the_database_lacks_costs_by_its_extra_distance(s):
    # French /y/ against an English database: /uw/ is nearest (1.0), so its nodes cost 0 as the same
    # phone's would; /uh/ 0.2 further, /iy/ 2.0 further, /p/ far: capped at Table II's rule 3
    nodes = ["uw", "uh", "iy", "p"]
    oc = step_costs(["uw"], ["neutral"], nodes, ["neutral"] * 4, {}, s, ["y"]).oc[0]
    d = np.array([phone_distance("y", FESTIVAL_IPA[p]) for p in nodes])
    unit = s.alpha5 * s.pnt
    assert oc[0] == 0.0
    assert oc[1] == pytest.approx(unit * match_level(d[1] - d[0], s.alpha4, s.phone_match_scale), rel=1e-6)
    assert oc[2] == pytest.approx(unit * match_level(d[2] - d[0], s.alpha4, s.phone_match_scale), rel=1e-6)
    assert oc[1] < oc[2] < oc[3] == pytest.approx(unit)


def test_the_search_picks_rounded_nodes_for_french_tu(db, config):
    from facesynth.domain.search.synthesis import synthesize

    s = dataclasses.replace(config.settings("synthesize"), dp="dense", use_opencl=False)
    utt = utterance(["pau", "t", "uw", "pau"], [0.0, 0.2, 0.27, 0.45], [0.2, 0.27, 0.45, 0.7], ipa=["", "t", "y", ""])
    for mode in ("unseen", "features"):
        res = synthesize(db, utt, {}, dataclasses.replace(s, phone_match=mode))
        chosen = db.nodes.phone[int(res.path[2])]
        assert features(FESTIVAL_IPA[chosen]).rounded, (mode, chosen)


def test_an_english_search_is_the_same_under_every_setting_but_features(db, config):
    from facesynth.domain.search.synthesis import synthesize

    s = dataclasses.replace(config.settings("synthesize"), dp="dense", use_opencl=False)
    phones = ["pau", "m", "aa", "p", "uw", "s", "iy", "pau"]
    times = np.arange(len(phones) + 1) * 0.12
    utt = utterance(phones, times[:-1], times[1:])
    paper = synthesize(db, utt, {}, dataclasses.replace(s, phone_match="viseme"))
    unseen = synthesize(db, utt, {}, dataclasses.replace(s, phone_match="unseen"))
    assert np.array_equal(paper.path, unseen.path) and paper.cost == unseen.cost
    assert np.array_equal(paper.rendered.markers, unseen.rendered.markers)


def test_stand_ins_are_the_nearest_phone_by_features():
    utt = utterance(["pau", "uw", "sh", "k", "pau"], [0, 1, 2, 3, 4], [1, 2, 3, 4, 5], ipa=["", "y", "ç", "k", ""])
    have = {"iy", "ow", "s", "hh", "k", "aa"}
    assert stand_in_phones(utt, have) == ["pau", "ow", "s", "k", "pau"]  # /y/ rounded: /ow/; /ç/ by place: /s/
    assert stand_in_phones(utt, have, "viseme") == list(utt.phones)       # the paper's rule: the models' own fallback
    english = utterance(["uw", "sh"], [0, 1], [1, 2])
    assert stand_in_phones(english, have) == ["uw", "sh"]                  # an English line: unchanged
    assert stand_in_phones(english, have, "features") == ["ow", "s"]
    assert nearest_phone("y", ["iy", "uw"]) == "uw" and phone_distance("y", "u") < phone_distance("y", "i")


@pytest.mark.skipif(importlib.util.find_spec("gruut_lang_fr") is None,
                    reason="gruut's French pack is not installed (pip install 'facesynth[languages]')")
def test_a_french_line_keeps_its_ipa_phones_through_the_alignment(tiny_corpus):
    import facesynth

    heard = facesynth.utterance_from_audio(tiny_corpus / "audio" / "neutral_s000.wav", "Papa boit une pomme.",
                                           language="fr")
    utt = heard.data.utterance
    assert utt.ipa is not None and len(utt.ipa) == len(utt.phones)
    spoken = [(p, q) for p, q in zip(utt.phones, utt.ipa) if p != PAU]
    assert ("uw", "y") in spoken                       # une: /y/, standing as its nearest English /uw/
    assert all(q for _, q in spoken) and all(not q for p, q in zip(utt.phones, utt.ipa) if p == PAU)
    english = facesynth.utterance_from_audio(tiny_corpus / "audio" / "neutral_s000.wav", "laugh tail with west roll")
    assert english.data.utterance.ipa is None


def test_the_summary_names_a_foreign_phone_the_database_lacks_by_its_ipa(db):
    from facesynth.domain.search.synthesis import unseen_phones

    utt = utterance(["pau", "uw", "aa", "sh", "pau"], [0, 1, 2, 3, 4], [1, 2, 3, 4, 5], ipa=["", "y", "ɑ", "ʃ", ""])
    unseen = unseen_phones(utt, db, "unseen")
    assert set(unseen) == {"y", "ʃ"}                            # /ɑ/ is aa's: the database has it
    assert "/u/ first" in unseen["y"] and "articulatory features" in unseen["y"]
    assert unseen_phones(utt, db, "viseme") == {"sh": "any node (Table II rule 3)"}  # no node of its viseme
    english = utterance(["pau", "sh", "pau"], [0, 1, 2], [1, 2, 3])
    assert list(unseen_phones(english, db, "unseen")) == ["sh"]  # an English line: Table II's message


@pytest.mark.skipif(importlib.util.find_spec("gruut_lang_fr") is None,
                    reason="gruut's French pack is not installed (pip install 'facesynth[languages]')")
def test_a_french_lines_rounded_front_vowels_take_rounded_nodes_and_a_narrow_mouth(db, config, tiny_corpus):
    import facesynth
    from facesynth.domain.search.synthesis import synthesize

    s = dataclasses.replace(config.settings("synthesize"), use_opencl=False)
    utt = facesynth.utterance_from_audio(tiny_corpus / "audio" / "neutral_s000.wav", "Tu as vu une rue, du jus.",
                                         language="fr").data.utterance
    assert utt.ipa is not None
    res = synthesize(db, utt, {}, s)
    names = list(db.marker_names)
    right, left = names.index("MC_R"), names.index("MC_L")
    markers = res.rendered.markers_capture

    def width(t: int) -> float:
        f = min(int(round((utt.starts[t] + utt.ends[t]) / 2 * db.fps)), len(markers) - 1)
        return float(np.linalg.norm(markers[f, right] - markers[f, left]))

    front = [(t, features(q)) for t, q in enumerate(utt.ipa) if q and features(q).vowel and features(q).backness < 0.25]
    rounded = [t for t, f in front if f.rounded]
    spread = [t for t, f in front if not f.rounded]
    assert len(rounded) >= 4 and spread
    assert all(features(FESTIVAL_IPA[db.nodes.phone[int(res.path[t])]]).rounded for t in rounded)
    # measured on the tiny database: 42.5 mm wide at /y/ against 54.7 mm at the unrounded front vowels
    assert np.mean([width(t) for t in rounded]) < np.mean([width(t) for t in spread]) - 5.0


# --- the fitted members: a phone of another language they never saw -------------------------


def _ich(ipa: bool):
    """German "ich" with pauses: /ɪ ç/, standing as the English /ih sh/ (the tiny database has no /sh/)."""
    return utterance(["pau", "ih", "sh", "pau"], [0.0, 0.2, 0.3, 0.45], [0.2, 0.3, 0.45, 0.7],
                     ipa=["", "ɪ", "ç", ""] if ipa else None)


def test_mean_takes_the_phone_nearest_in_features_for_a_foreign_phone_it_lacks(db):
    from facesynth.domain.methods.mean import mean_pose_coefficients

    assert "sh" not in db.nodes.phone and "s" in db.nodes.phone
    by_features = mean_pose_coefficients(db, _ich(True), phone_match="unseen")
    as_s = mean_pose_coefficients(db, utterance(["pau", "ih", "s", "pau"], [0.0, 0.2, 0.3, 0.45],
                                                [0.2, 0.3, 0.45, 0.7]))
    assert np.array_equal(by_features, as_s)       # /ç/ looked up as /s/, the nearest phone the database has
    paper = mean_pose_coefficients(db, _ich(True), phone_match="viseme")
    assert np.array_equal(paper, mean_pose_coefficients(db, _ich(False)))  # the viseme rule: as English /sh/
    assert not np.array_equal(paper, by_features)


def test_trajectory_covers_a_foreign_phone_its_viseme_class_lacks(tiny_trajectory, config):
    from facesynth.base.errors import InputError
    from facesynth.domain.methods.trajectory import synthesize_motion
    from facesynth.model.trajectory import TrajectoryModel

    model = TrajectoryModel.read(tiny_trajectory)
    settings = config.settings("trajectory")
    assert "sh" not in model.phones and not {"ch", "jh"} & set(model.phones)
    motion, _ = synthesize_motion(model, _ich(True), settings, 30.0)
    assert motion.path is not None and motion.path.node_phone[2] == "s"  # the nearest phone by features
    with pytest.raises(InputError, match="not in the trajectory model"):  # English /sh/: no phone of its viseme
        synthesize_motion(model, _ich(False), settings, 30.0)


def test_coarticulation_takes_the_phone_nearest_in_features_for_a_foreign_phone_it_lacks(tiny_db, config, tmp_path):
    from facesynth.domain.methods import MethodSettings
    from facesynth.domain.methods.coarticulation import CoarticulationMethod
    from facesynth.model.coarticulation import CoarticulationModel
    from facesynth.stages import fit_method

    every = MethodSettings.of(config)
    quick = every.replace(coarticulation=dataclasses.replace(every.coarticulation, iterations=5))
    fit_method.run("coarticulation", tiny_db, tmp_path / "coart.h5", quick)
    model = CoarticulationModel.read(tmp_path / "coart.h5")
    assert not any(label.split("|")[0] == "sh" for label in model.labels)
    method = CoarticulationMethod()
    as_s = utterance(["pau", "ih", "s", "pau"], [0.0, 0.2, 0.3, 0.45], [0.2, 0.3, 0.45, 0.7])
    got = method.synthesize(model, _ich(True), every).motion.markers
    assert np.array_equal(got, method.synthesize(model, as_s, every).motion.markers)
    paper = every.replace(synthesize=dataclasses.replace(every.synthesize, phone_match="viseme"))
    assert not np.array_equal(got, method.synthesize(model, _ich(True), paper).motion.markers)  # the mean of every phone
