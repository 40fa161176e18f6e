"""``facesynth expression fit|analyze|restyle`` on the tiny corpus, and its bad input."""

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.expression.analysis import check_markers
from facesynth.model.expression import ExpressionModel
from facesynth.model.motion import Motion
from facesynth.stages import capture
from facesynth.stages import expression as stage


@pytest.fixture(scope="module")
def fitted(tiny_artifacts, tiny_db, held_out_take, config, tmp_path_factory):
    d = tmp_path_factory.mktemp("expression")
    summary = stage.fit(tiny_artifacts["normalized"], d / "expr.h5", config.settings("expression"))
    capture.run(tiny_db, tiny_artifacts["corpus"], held_out_take, d / "take.h5", config.settings("normalize"), 30.0)
    return d, summary


def _cli(*args):
    return CliRunner().invoke(main, [str(a) for a in args], prog_name="facesynth")


def test_fit_uses_every_training_sentence_in_every_emotion_and_its_error_never_rises(fitted, config):
    d, s = fitted
    model, names = ExpressionModel.read(d / "expr.h5")
    assert s.emotions[0] == "neutral" and set(s.emotions) == {"neutral", "happy", "angry", "sad"}
    assert s.sentences >= 2 and not s.skipped
    assert model.W.shape == (config.settings("expression").components, 4, config.settings("expression").content_dim)
    assert np.all(np.diff(model.errors) <= 1e-9 * model.errors[0])
    assert np.allclose(model.basis @ model.basis.T, np.eye(len(model.basis)), atol=1e-5)


def test_restyle_writes_a_motion_that_check_accepts_and_zero_intensity_changes_nothing(fitted, tmp_path):
    d, _ = fitted
    r = _cli("expression", "restyle", d / "expr.h5", d / "take.h5", "--to", "happy", "--intensity", "0",
             "-o", tmp_path / "same.h5")
    assert r.exit_code == 0, r.output
    src, same = Motion.read(d / "take.h5"), Motion.read(tmp_path / "same.h5")
    assert same.source == "restyle"
    assert np.allclose(same.markers, src.markers, atol=1e-3, equal_nan=True)
    assert np.allclose(same.head_rotation, src.head_rotation)
    r = _cli("expression", "restyle", d / "expr.h5", d / "take.h5", "--to", "happy", "--intensity", "0.6",
             "-o", tmp_path / "happy.h5")
    assert r.exit_code == 0, r.output
    happy = Motion.read(tmp_path / "happy.h5")
    assert np.nanmax(np.abs(happy.markers - src.markers)) > 0.01
    assert _cli("check", tmp_path / "happy.h5").exit_code == 0


def test_an_emotion_file_restyles_only_inside_its_spans(fitted, tmp_path):
    d, _ = fitted
    src = Motion.read(d / "take.h5")
    spans = tmp_path / "spans.txt"
    spans.write_text("0.2 0.8 angry\n")
    r = _cli("expression", "restyle", d / "expr.h5", d / "take.h5", "--emotions", spans, "--set",
             "expression.transition_s=0", "-o", tmp_path / "spans.h5")
    assert r.exit_code == 0, r.output
    out = Motion.read(tmp_path / "spans.h5")
    t = np.arange(len(out.markers)) / out.fps
    moved = np.nanmax(np.abs(out.markers - src.markers), axis=(1, 2))
    assert np.all(moved[(t < 0.15) | (t > 0.85)] < 1e-3)
    assert moved[(t > 0.3) & (t < 0.7)].max() > 0.01


def test_analyze_prints_a_style_and_content_row_per_frame(fitted):
    d, _ = fitted
    r = _cli("expression", "analyze", d / "expr.h5", d / "take.h5")
    assert r.exit_code == 0, r.output
    lines = r.stdout.strip().splitlines()
    assert lines[0].startswith("time_s,emotion,e0,")
    frames = Motion.read(d / "take.h5").markers
    assert len(lines) - 1 == int(np.isfinite(frames.reshape(len(frames), -1)).all(1).sum())


@pytest.mark.parametrize("args, message", [
    (["--to", "excited"], "the model was fitted with neutral, angry, happy, sad, not 'excited'"),
    (["--to", "happy", "--intensity", "1.5"], "--intensity 1.5: give an intensity between 0 and 1"),
    (["--to", "happy", "--intensity", "-0.1"], "--intensity -0.1: give an intensity between 0 and 1"),
])
def test_bad_restyle_requests_are_one_line_exit_1_and_write_nothing(fitted, tmp_path, args, message):
    d, _ = fitted
    r = _cli("expression", "restyle", d / "expr.h5", d / "take.h5", *args, "-o", tmp_path / "out.h5")
    assert r.exit_code == 1
    assert message in r.output and len(r.output.strip().splitlines()) == 1
    assert not (tmp_path / "out.h5").exists()


def test_restyle_of_motion_with_other_markers_is_refused(fitted):
    d, _ = fitted
    model, names = ExpressionModel.read(d / "expr.h5")
    with pytest.raises(InputError, match="its markers differ"):
        check_markers(names[:-1], names, d / "take.h5", d / "expr.h5")


def test_fit_without_a_sentence_in_every_emotion_says_so(tiny_artifacts, config, tmp_path):
    import dataclasses

    with pytest.raises(InputError, match="no takes in the splits"):
        stage.fit(tiny_artifacts["normalized"], tmp_path / "x.h5",
                  dataclasses.replace(config.settings("expression"), splits=("nosuch",)))
    assert not (tmp_path / "x.h5").exists()
