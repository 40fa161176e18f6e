"""The search of ``facesynth tune`` (facesynth.domain.search.tuning): the search vector of the
weights, the per-sentence error and the tuned settings' TOML, on values made here."""

import dataclasses

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.domain.search import tuning

# --- the search vector -------------------------------------------------------------------------


def test_vector_is_logs_and_a_logit():
    s = dataclasses.replace(Config.load().settings("synthesize"), alpha1=1.0, alpha2=np.e, alpha3=0.5,
                            alpha4=0.75, alpha5=np.e**2, alpha6=4.0, pnt=np.e**3)
    v = tuning.to_vector(s)
    # log 1, log e, log 0.5, logit 0.75 = log(0.75 / 0.25) = log 3, log e^2, log 4, log e^3
    np.testing.assert_allclose(v, [0.0, 1.0, np.log(0.5), np.log(3.0), 2.0, np.log(4.0), 3.0], rtol=0, atol=1e-12)


def test_round_trip_keeps_every_weight_and_the_other_settings():
    s = dataclasses.replace(Config.load().settings("synthesize"), alpha1=1.75, alpha2=0.00123, alpha3=0.856,
                            alpha4=0.552, alpha5=9.37, alpha6=1.54, pnt=123.0, search="greedy")
    back = tuning.from_vector(tuning.to_vector(s), s)
    for name in tuning.WEIGHTS:
        assert getattr(back, name) == pytest.approx(getattr(s, name), rel=1e-12), name
    # only the weights move (PNT among them: it balances the penalties against PGap, VGap, DSC)
    assert dataclasses.replace(back, **{n: getattr(s, n) for n in tuning.WEIGHTS}) == s


@pytest.mark.parametrize("logit", [-800.0, -40.0, -5.0, 0.0, 5.0, 37.0, 40.0])
def test_alpha4_stays_inside_zero_one_for_any_search_vector(logit):
    s = Config.load().settings("synthesize")
    v = tuning.to_vector(s)
    v[3] = logit
    a4 = tuning.from_vector(v, s).alpha4
    assert 0.0 < a4 < 1.0  # Table II, rule 2: a discount; 1.0 would be refused by Config.load
    assert a4 > 0.5 if logit > 0 else (a4 < 0.5 if logit < 0 else a4 == 0.5)


def test_a_moved_vector_moves_the_alphas_as_logs():
    s = Config.load().settings("synthesize")
    v = tuning.to_vector(s)
    moved = tuning.from_vector(v + np.log(2.0) * np.array([1, 0, -1, 0, 0, 1, 1]), s)
    assert moved.alpha1 == pytest.approx(2 * s.alpha1) and moved.alpha3 == pytest.approx(s.alpha3 / 2)
    assert moved.alpha6 == pytest.approx(2 * s.alpha6) and moved.pnt == pytest.approx(2 * s.pnt)
    assert (moved.alpha2, moved.alpha4, moved.alpha5) == pytest.approx((s.alpha2, s.alpha4, s.alpha5))




# --- the objective's error and the report --------------------------------------------------------


def test_sentence_error_is_the_mean_squared_distance_over_seen_markers_and_common_frames():
    truth = np.zeros((4, 2, 3))
    syn = np.ones((5, 2, 3), np.float32)  # one frame longer: cut to the capture
    truth[1, 1] = np.nan  # a gap the capture could not fill: left out, not NaN
    syn[:, 1] = 2.0
    # marker 0 is off by (1, 1, 1): 3 mm^2; marker 1 by (2, 2, 2): 12 mm^2; 4 + 3 samples seen
    assert tuning.sentence_error(syn, truth) == pytest.approx((4 * 3 + 3 * 12) / 7)


def test_bootstrap_interval_holds_the_mean_and_is_reproducible():
    values = np.array([1.0, 2.0, 3.0, 4.0, 10.0])
    lo, hi = tuning.bootstrap_mean(values, seed=0)
    assert lo <= values.mean() <= hi and lo >= values.min() and hi <= values.max()
    assert tuning.bootstrap_mean(values, seed=0) == [lo, hi]
    assert tuning.bootstrap_mean(np.array([2.5]), seed=0) == [2.5, 2.5]


def _found(**changes):
    weights = {k: 0.5 for k in tuning.WEIGHTS}
    found = tuning.Tuning(4, 4, 20, 2.0, 1.5, True, weights, 6, 5, False, [], 3.0, 2.5, [2.8, 3.2], [2.3, 2.7],
                          [-0.6, -0.4])
    return dataclasses.replace(found, **changes)


def test_config_text_loads_back_as_the_tuned_settings(tmp_path):
    path = tmp_path / "tuned.toml"
    path.write_text(tuning.config_text(_found(), "greedy"), encoding="utf-8")
    text = path.read_text(encoding="utf-8")
    assert "# validation error (Eq. 13, mm^2): 2.0000 -> 1.5000" in text
    assert "3.0000 [2.8000, 3.2000] -> 2.5000 [2.3000, 2.7000]" in text
    loaded = Config.load(path)
    assert {k: getattr(loaded.settings("synthesize"), k) for k in tuning.WEIGHTS} == {k: 0.5 for k in tuning.WEIGHTS}
    assert loaded.settings("synthesize").method == "greedy"  # another member than the DP is named
    assert loaded.settings("synthesize").smoothing_half_window == 6
    assert loaded.settings("build_db").boundary_fit_frames == 5


def test_config_text_of_the_dp_without_test_takes_says_its_warnings():
    text = tuning.config_text(_found(test_err_before=None, test_err_after=None, warnings=["nothing beat the start"]),
                              "dp")
    assert "# warning: nothing beat the start" in text
    assert "test error" not in text and "method =" not in text
