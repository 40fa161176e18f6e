"""``facesynth head-motion`` and ``synthesize --head-motion`` on the tiny corpus, and bad input."""

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.cli import main
from facesynth.formats.audio import write_wav
from facesynth.model.head_motion import HeadMotion
from facesynth.model.motion import Motion


def _cli(*args):
    return CliRunner().invoke(main, [str(a) for a in args], prog_name="facesynth")


@pytest.fixture(scope="module")
def head(tiny_corpus, tiny_artifacts, tiny_db, held_out_take, tmp_path_factory):
    d = tmp_path_factory.mktemp("head")
    r = _cli("head-motion", tiny_db, "--corpus", tiny_artifacts["corpus"], "--audio",
             tiny_corpus / "audio" / f"{held_out_take}.wav", "-o", d / "head.h5")
    assert r.exit_code == 0, r.output
    return d / "head.h5"


def test_head_motion_covers_the_audio_moves_and_checks_clean(head, tiny_corpus, held_out_take):
    from facesynth.formats.audio import read_audio

    samples, rate = read_audio(tiny_corpus / "audio" / f"{held_out_take}.wav")
    h = HeadMotion.read(head)
    assert len(h.rotation) == int(np.ceil(len(samples) / rate * h.fps))
    assert len(h.seg_start) >= 1 and np.all(np.diff(h.seg_start) > 0)
    angles = np.degrees(np.arccos(np.clip((np.trace(h.rotation, axis1=1, axis2=2) - 1) / 2, -1, 1)))
    assert angles.max() > 0.05
    assert np.isfinite(h.pitch).any()
    assert _cli("check", head).exit_code == 0


def test_synthesize_puts_the_head_motion_on_its_output(head, tiny_db, tiny_corpus, held_out_take, tmp_path):
    r = _cli("synthesize", tiny_db, "--phonemes", tiny_corpus / "labels" / f"{held_out_take}.TextGrid",
             "--head-motion", head, "-o", tmp_path / "m.h5")
    assert r.exit_code == 0, r.output
    m, h = Motion.read(tmp_path / "m.h5"), HeadMotion.read(head)
    rot, trans = h.at(np.arange(len(m.markers)) / m.fps)
    assert np.allclose(m.head_rotation, rot, atol=1e-5) and np.allclose(m.head_translation, trans, atol=1e-3)
    r = _cli("deform", tmp_path / "m.h5", "--mesh", tiny_corpus / "face.obj", "--binding", tiny_corpus / "markers.csv",
             "--set", "deform.apply_head_motion=true", "-o", tmp_path / "a.h5")
    assert r.exit_code == 0, r.output


def test_audio_without_voice_gives_the_rest_pose_with_a_warning(tiny_db, tiny_artifacts, tmp_path):
    quiet = tmp_path / "quiet.wav"
    write_wav(quiet, np.random.default_rng(0).normal(0, 1e-4, 16000).astype(np.float32), 16000)
    r = _cli("head-motion", tiny_db, "--corpus", tiny_artifacts["corpus"], "--audio", quiet, "-o", tmp_path / "h.h5")
    assert r.exit_code == 0, r.output
    assert "warning: the audio has no voiced frame" in r.output
    h = HeadMotion.read(tmp_path / "h.h5")
    assert np.allclose(h.rotation, np.eye(3)) and np.allclose(h.translation, 0) and len(h.seg_start) == 0


def test_a_database_without_head_motion_is_one_line_exit_1_and_nothing_written(tiny_db, tiny_artifacts, tiny_corpus,
                                                                                held_out_take, tmp_path):
    still = tmp_path / "still.h5"
    still.write_bytes(tiny_db.read_bytes())
    with h5py.File(still, "r+") as f:
        f["head_rotation"][...] = np.eye(3, dtype=np.float32)
        f["head_translation"][...] = 0.0
    r = _cli("head-motion", still, "--corpus", tiny_artifacts["corpus"], "--audio",
             tiny_corpus / "audio" / f"{held_out_take}.wav", "-o", tmp_path / "h.h5")
    assert r.exit_code == 1
    assert "the database has no head motion" in r.output and len(r.output.strip().splitlines()) == 1
    assert not (tmp_path / "h.h5").exists()
