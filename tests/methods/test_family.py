"""The method family: every member through the registry, the DP bit-identical to the search it
wraps, the coarticulation model fitted, written, read back and checked, constraints refused off
the DP, and the recommendation that ends evaluate's report."""

import dataclasses

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.config import choices
from facesynth.base.errors import ArtifactError, UsageError
from facesynth.base.phonemes import PAU
from facesynth.base.registry import METHODS
from facesynth.cli import main
from facesynth.domain import methods
from facesynth.domain.evaluation.held_out import recommend
from facesynth.domain.methods import Method, MethodSettings, steps
from facesynth.domain.search.synthesis import as_motion, synthesize
from facesynth.domain.speech.utterance import read_utterance
from facesynth.model import check
from facesynth.model.coarticulation import CoarticulationModel
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase


@pytest.fixture(scope="module")
def settings(config):
    every = MethodSettings.of(config)
    return every.replace(coarticulation=dataclasses.replace(every.coarticulation, iterations=8))


@pytest.fixture(scope="module")
def db(tiny_db):
    return MotionDatabase.read(tiny_db)


@pytest.fixture(scope="module")
def sources(tiny_db, db, settings, config, tmp_path_factory):
    """Every member's source: the database, or its model fitted on it (and written, then read back)."""
    from facesynth.stages import fit_method, keyshapes

    d = tmp_path_factory.mktemp("family")
    ks = dataclasses.replace(config.settings("keyshapes"), count=3, curve_frames=200)
    keyshapes.run(tiny_db, d / "keyshapes.h5", ks)
    fit_method.run("trajectory", tiny_db, d / "traj.h5", settings, keyshapes_path=d / "keyshapes.h5")
    fit_method.run("coarticulation", tiny_db, d / "coart.h5", settings)
    files = {"dp": tiny_db, "greedy": tiny_db, "mean": tiny_db, "trajectory": d / "traj.h5",
             "coarticulation": d / "coart.h5"}
    return {name: (path, methods.get(name).read(path)) for name, path in files.items()}


@pytest.fixture(scope="module")
def utt(tiny_corpus, held_out_take):
    u = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    u.emotions = ["sad"] * len(u)
    return u


def test_the_registry_names_every_member_and_refuses_another_name():
    assert methods.names() == ("dp", "greedy", "trajectory", "coarticulation", "mean")
    assert [n for n in methods.names() if methods.get(n).fitted] == ["trajectory", "coarticulation"]
    assert [n for n in methods.names() if methods.get(n).takes_constraints] == ["dp"]
    with pytest.raises(UsageError, match="unknown method 'viterbi'; use one of dp, greedy, trajectory, coarticulation, mean"):
        methods.get("viterbi")


@pytest.mark.parametrize("name", ["dp", "greedy", "trajectory", "coarticulation", "mean"])
def test_every_member_makes_a_motion_with_the_same_fields_and_provenance(name, sources, utt, settings, db):
    _, source = sources[name]
    result = steps.synthesize(methods.get(name), source, utt, settings)
    m = result.motion
    n_capture = round(float(utt.ends[-1]) * db.fps)
    assert abs(len(m.markers_capture) - n_capture) <= 1 and m.capture_fps == db.fps
    assert m.fps == settings.synthesize.output_fps
    assert abs(len(m.markers) - n_capture * m.fps / db.fps) <= 1
    assert m.markers.shape[1:] == (len(db.marker_names), 3) and m.marker_names == list(db.marker_names)
    assert np.isfinite(m.markers).all() and m.head_rotation.shape == (len(m.markers), 3, 3)
    # the path: one row per input phone, the phones and per-phone emotions asked, the method's name
    assert m.path.method == name and m.path.phone == list(utt.phones) and m.path.emotion == ["sad"] * len(utt)
    assert np.array_equal(m.path.start, utt.starts) and len(m.path.node) == len(utt)
    # nodes only where the method has them
    assert (m.path.node >= 0).all() if name in ("dp", "greedy") else (m.path.node == -1).all()
    # per capture-rate frame, the input phone it belongs to, in order, covering every phone
    step = m.provenance.step
    assert len(step) == len(m.markers_capture) and (np.diff(step) >= 0).all() and set(step) == set(range(len(utt)))
    # the motion lies near the captured faces (mm), not anywhere
    assert np.abs(m.markers_capture - db.reference).max() < 60.0


def test_a_motion_of_every_member_is_written_and_read_back(sources, utt, settings, tmp_path):
    for name, (_, source) in sources.items():
        out = tmp_path / f"{name}.h5"
        steps.synthesize(methods.get(name), source, utt, settings).motion.write(out, config="{}")
        search, provenance = Motion.read_search(out)
        assert search.method == name and provenance.step.max() == len(utt) - 1
        assert check.check_file(out).problems == [], name


def test_dp_through_the_family_is_bit_identical_to_the_search(sources, utt, settings, db):
    res = synthesize(db, utt, {}, settings.synthesize)
    old = as_motion(db, utt, res, settings.synthesize)
    new = steps.synthesize(methods.get("dp"), sources["dp"][1], utt, settings).motion
    for field in ("markers", "markers_capture", "coefficients", "head_rotation", "head_translation"):
        assert np.array_equal(getattr(old, field), getattr(new, field)), field
    assert np.array_equal(old.path.node, new.path.node) and old.path.total_cost == new.path.total_cost
    assert np.array_equal(old.provenance.source_frame, new.provenance.source_frame)


def test_the_coarticulation_model_is_fitted_written_read_back_and_checked(sources, db, settings, utt, tmp_path):
    from facesynth.domain.methods.coarticulation import (
        DominanceModel,
        emotion_labels,
        fit_dominance,
        training_sentences,
    )

    path, model = sources["coarticulation"]
    assert check.check_file(path).problems == []
    # the file holds the fit: the same parameters as fitting the training takes directly
    direct = fit_dominance(training_sentences(db, by_emotion=True), db.fps, settings.coarticulation.iterations)
    assert model.labels == list(direct.phones) and np.array_equal(model.targets, direct.targets)
    assert np.array_equal(model.rate, direct.rate) and model.fps == db.fps and model.iterations == 8
    assert "aa|happy" in model.labels or any("|happy" in label for label in model.labels)
    assert PAU in model.labels and 0 < model.fit_rms < 5.0
    with h5py.File(path) as f:
        assert f.attrs["facesynth_kind"] == "coarticulation" and "pca/basis" in f
    # synthesis from the file alone equals the database's PCA reconstruction of the fitted model's poses
    motion = steps.synthesize(methods.get("coarticulation"), CoarticulationModel.read(path), utt, settings).motion
    n = len(motion.markers_capture)
    poses = DominanceModel(tuple(direct.phones), direct.targets, direct.magnitude, direct.rate).predict(
        emotion_labels(utt.phones, utt.emotions), utt.starts, utt.ends, n, db.fps)
    assert np.array_equal(motion.markers_capture, db.model.reconstruct(poses))
    # a damaged parameter is found by check, and refused by the reader
    damaged = tmp_path / "damaged.h5"
    damaged.write_bytes(path.read_bytes())
    with h5py.File(damaged, "r+") as f:
        f["rate"][0] = np.nan
    assert [p.key for p in check.check_file(damaged).problems] == ["/rate"]
    with h5py.File(damaged, "r+") as f:
        f["rate"][0] = -1.0
    with pytest.raises(ArtifactError, match="rate"):
        CoarticulationModel.read(damaged)


@pytest.mark.parametrize("name", ["greedy", "trajectory", "coarticulation", "mean"])
def test_constraints_are_refused_off_the_dp_in_one_sentence(name, sources, utt, settings):
    with pytest.raises(UsageError) as err:
        steps.synthesize(methods.get(name), sources[name][1], utt, settings, {1: 0})
    assert str(err.value) == (f"motion-node constraints need the DP search (Eq. 10); the {name} method takes none: "
                              "drop --constraints or use --method dp.")


def test_methods_without_fitting_refuse_fit_method(tiny_db, tmp_path):
    r = CliRunner().invoke(main, ["fit-method", "mean", str(tiny_db), "-o", str(tmp_path / "m.h5")])
    assert r.exit_code == 2 and "'mean' is not one of 'trajectory', 'coarticulation'" in r.output
    with pytest.raises(UsageError, match="the mean method reads the motion database itself and has nothing to fit"):
        methods.get("mean").fit(None, None)


def test_fit_method_and_synthesize_through_the_command_line(tiny_db, tiny_corpus, held_out_take, tmp_path):
    model, out = tmp_path / "coart.h5", tmp_path / "m.h5"
    tg = str(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    r = CliRunner().invoke(main, ["fit-method", "coarticulation", str(tiny_db), "-o", str(model),
                                  "--set", "coarticulation.iterations=3"])
    assert r.exit_code == 0, r.output
    assert "coarticulation model:" in r.output and "(phone, emotion) types" in r.output
    r = CliRunner().invoke(main, ["synthesize", "--method", "coarticulation", str(model), "--phonemes", tg, "-o", str(out)])
    assert r.exit_code == 0, r.output
    assert "frames by the coarticulation method" in r.output and Motion.read_search(out)[0].method == "coarticulation"
    r = CliRunner().invoke(main, ["synthesize", "--method", "mean", str(tiny_db), "--phonemes", tg, "--search", "dp",
                                  "-o", str(tmp_path / "x.h5")])
    assert r.exit_code == 2 and "the mean method does not take it" in r.output
    r = CliRunner().invoke(main, ["synthesize", "--method", "coarticulation", str(tiny_db), "--phonemes", tg,
                                  "-o", str(tmp_path / "y.h5")])
    assert r.exit_code == 1 and "coarticulation" in r.output and not (tmp_path / "y.h5").exists()
    r = CliRunner().invoke(main, ["synthesize", "--method", "greedy", str(tiny_db), "--phonemes", tg,
                                  "-o", str(tmp_path / "g.h5")])
    assert r.exit_code == 0 and Motion.read_search(tmp_path / "g.h5")[0].method == "greedy"


def test_tune_refuses_a_method_without_weights(tiny_db, tiny_artifacts, tmp_path):
    r = CliRunner().invoke(main, ["tune", str(tiny_db), "--validation", str(tiny_artifacts["corpus"]), "--method",
                                  "coarticulation", "-o", str(tmp_path / "t.toml")])
    assert r.exit_code == 2 and "Traceback" not in r.output
    assert ("the coarticulation method has no weights to tune: use --method dp or greedy." in r.output)
    assert not (tmp_path / "t.toml").exists()


def _f(value, low, high):
    return {"value": value, "low": low, "high": high}


def test_the_recommendation_is_the_lowest_rms_whose_interval_stands_clear():
    figures = {"dp": {"rms_mm": _f(2.9, 2.7, 3.1)}, "coarticulation": {"rms_mm": _f(2.0, 1.9, 2.1)},
               "mean": {"rms_mm": _f(2.5, 2.3, 2.7)}}
    r = recommend(figures)
    assert r.method == "coarticulation" and r.figure == "rms_mm"
    assert r.sentence == ("Recommended for this database: coarticulation, the lowest RMS vs noisy capture (2.000 mm "
                          "[1.900, 2.100]); every other method is higher beyond its 95% interval (next: mean 2.500 mm "
                          "[2.300, 2.700]).")


def test_tied_intervals_recommend_the_simplest_and_the_clean_truth_decides_where_there_is_one():
    figures = {"dp": {"rms_mm": _f(1.0, 0.5, 1.5), "rms_clean_mm": _f(2.2, 2.0, 2.4)},
               "coarticulation": {"rms_mm": _f(5.0, 4.0, 6.0), "rms_clean_mm": _f(2.1, 1.9, 2.3)},
               "mean": {"rms_mm": _f(5.0, 4.0, 6.0), "rms_clean_mm": _f(3.0, 2.9, 3.1)},
               "greedy": {"rms_mm": _f(1.0, 0.5, 1.5), "rms_clean_mm": _f(2.35, 2.29, 2.5)}}
    r = recommend(figures)
    # coarticulation has the lowest clean RMS, but dp's and greedy's intervals overlap it; mean's does not
    assert r.figure == "rms_clean_mm" and r.method == "coarticulation"
    assert r.sentence == ("Recommended for this database: coarticulation; coarticulation has the lowest RMS vs clean "
                          "truth (2.100 mm [1.900, 2.300]), but its 95% interval does not tell it from dp 2.200 mm "
                          "[2.000, 2.400], greedy 2.350 mm [2.290, 2.500], and it is the simplest and fastest of these.")
    figures["mean"]["rms_clean_mm"] = _f(2.3, 2.2, 2.4)  # now the mean is tied too, and simplest
    tied = recommend(figures)
    assert tied.method == "mean" and tied.sentence.startswith(
        "Recommended for this database: mean, the simplest and fastest of the tied methods (RMS vs clean truth "
        "2.300 mm [2.200, 2.400]); coarticulation has the lowest")
    only = recommend({"dp": {"rms_mm": _f(1.0, 0.9, 1.1)}})
    assert only.method == "dp" and "the only method scored" in only.sentence
    assert recommend({}).method == ""


def test_paired_intervals_decide_where_the_sentences_share_their_difficulty():
    """Every method's own interval overlaps the others' (the sentences differ in difficulty), but on the
    same resamples coarticulation is lower than each other method: it is recommended."""
    figures = {"dp": {"rms_mm": _f(1.90, 1.67, 2.18)}, "coarticulation": {"rms_mm": _f(1.45, 1.25, 1.69)},
               "mean": {"rms_mm": _f(1.76, 1.41, 2.16)}, "trajectory": {"rms_mm": _f(1.69, 1.48, 1.96)}}
    assert recommend(figures).method == "mean"  # by the methods' own intervals: tied
    paired = {"dp": _f(0.45, 0.39, 0.51), "mean": _f(0.31, 0.12, 0.50), "trajectory": _f(0.24, 0.10, 0.35)}
    calls = []

    def difference(key, other, best):
        calls.append((key, other, best))
        return paired[other]

    r = recommend(figures, difference=difference)
    assert r.method == "coarticulation" and all(c[0] == "rms_mm" and c[2] == "coarticulation" for c in calls)
    assert r.sentence.endswith("every other method is higher beyond the paired 95% interval (next: trajectory "
                               "+0.240 mm [+0.100, +0.350]).")
    paired["trajectory"] = _f(0.24, -0.02, 0.35)  # one paired interval holds 0: tied with it, and it is simpler
    tied = recommend(figures, difference=difference)
    assert tied.method == "coarticulation" and "does not tell it from trajectory +0.240 mm [-0.020, +0.350]" in tied.sentence


def test_every_member_declares_its_live_form_or_why_not(settings):
    """A member streams exactly when it has a live form (Method.live) and is registered with
    streams=True; the others say why not; stream.method offers the first."""
    for entry in METHODS.entries():
        member = methods.get(entry.name)
        live = type(member).live is not Method.live
        assert live == bool(entry.facts.get("streams")), entry.name
        if not live:
            assert member.not_live != Method.not_live, f"{entry.name} gives no reason it does not stream"
            with pytest.raises(UsageError, match=f"the {entry.name} method does not stream: .*; use one of dp"):
                member.live(None, settings)
    assert choices("stream", "method") == methods.live_names() == ("dp", "greedy", "trajectory")


def test_every_member_declares_its_settings_section(config):
    sections = {e.name: e.facts.get("settings") for e in METHODS.entries()}
    assert sections == {"dp": "synthesize", "greedy": "synthesize", "trajectory": "trajectory",
                        "coarticulation": "coarticulation", "mean": "synthesize"}
    every = MethodSettings.of(config)
    assert set(every.sections()) == {"synthesize", "trajectory", "coarticulation"}
    assert every.trajectory == config.settings("trajectory") and every.section("coarticulation").iterations > 0
    assert methods.get("coarticulation").fit_settings(every) == every.coarticulation
    with pytest.raises(AttributeError, match=r"no \[nope\] section"):
        every.nope  # noqa: B018


def test_the_deprecated_search_names_warn_and_still_choose(tiny_db, tiny_corpus, held_out_take, tmp_path):
    tg = str(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")

    def run(*extra):
        out = tmp_path / f"m{len(list(tmp_path.iterdir()))}.h5"
        r = CliRunner().invoke(main, ["synthesize", str(tiny_db), "--phonemes", tg, "-o", str(out), *extra])
        assert r.exit_code == 0, r.output
        return r.output, Motion.read_search(out)[0].method

    output, search = run("--search", "greedy")
    assert search == "greedy" and "warning: `--search` is deprecated" in output and "`--method greedy`" in output
    output, search = run("--set", "synthesize.search=greedy")
    assert search == "greedy" and "warning: synthesize.search is deprecated" in output
    assert 'synthesize.method = "greedy"' in output
    output, search = run("--set", "synthesize.method=greedy")
    assert search == "greedy" and "is deprecated" not in output
    output, search = run()
    assert search == "dp" and "is deprecated" not in output
