"""Video takes (issue 41, item 3): the virtual actress rendered by ``facesynth render`` and ingested
as a filmed take, where the truth is known: MediaPipe Face Mesh's 478 landmarks as markers in mm,
the video's sound as the take's audio, the mouth opening and the markers against her truth. Needs
the ``video`` extra; a video without a face or without sound is refused in one sentence, and
without the extra one sentence says what to install."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.capture.readers import read_capture
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.geometry.rigid import similarity_fit
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.rig.face import BUILTIN_RIG_NAME, builtin_rig_sha256, load_face_rig
from facesynth.domain.rig.markers import build_marker_set
from facesynth.formats.mesh import read_binding
from facesynth.model.corpus import Corpus
from facesynth.model.curves import RigCurves
from facesynth.model.frames import NormalizedFrames

FPS = 25.0
NO_EXTRA = "facesynth[video] is not installed (pip install 'facesynth[video]'): MediaPipe Face Mesh tracks the face"


def _run(*args) -> str:
    result = CliRunner().invoke(main, [*map(str, args), "-q"])
    assert result.exit_code == 0, result.output
    return result.output


def _blank_video(path: Path, sound: bool) -> Path:
    """One second of grey picture (no face), with or without a tone."""
    cmd = [imageio_ffmpeg.get_ffmpeg_exe(), "-loglevel", "error", "-f", "lavfi", "-i", "color=c=gray:s=320x240:d=1:r=25"]
    if sound:
        cmd += ["-f", "lavfi", "-i", "sine=frequency=200:duration=1", "-shortest"]
    subprocess.run(cmd + ["-pix_fmt", "yuv420p", str(path)], check=True)
    return path


def test_without_the_extra_one_sentence_says_what_to_install(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "mediapipe", None)  # import mediapipe fails as when it is not installed
    path = _blank_video(tmp_path / "take.mp4", sound=True)
    (tmp_path / "manifest.csv").write_text("take,mocap\nt,take.mp4\n")
    result = CliRunner().invoke(main, ["ingest", str(tmp_path / "manifest.csv"), "-o", str(tmp_path / "c.h5")])
    assert result.exit_code == 1 and not (tmp_path / "c.h5").exists()
    assert f"error: {path}: reading a video needs MediaPipe Face Mesh" in result.output
    assert "pip install 'facesynth[video]'" in result.output


@pytest.fixture(scope="module")
def mediapipe():
    return pytest.importorskip("mediapipe", reason=NO_EXTRA)


def test_a_video_without_a_face_or_without_sound_is_refused(mediapipe, tmp_path):
    with pytest.raises(InputError, match=r"take\.mp4: no face was found in any of its 25 frames"):
        read_capture(_blank_video(tmp_path / "take.mp4", sound=True))
    silent = _blank_video(tmp_path / "silent.mp4", sound=False)
    with pytest.raises(InputError, match=r"silent\.mp4: the video has no sound; give the take's audio"):
        read_capture(silent)
    (tmp_path / "manifest.csv").write_text("take,mocap\nt,silent.mp4\n")
    (tmp_path / "out").mkdir()
    result = CliRunner().invoke(main, ["ingest", str(tmp_path / "manifest.csv"), "-o", str(tmp_path / "out" / "c.h5")])
    assert result.exit_code == 1 and list((tmp_path / "out").iterdir()) == []
    assert [line for line in result.output.splitlines() if line.startswith("error: ")] == [
        f"error: {silent}: the video has no sound; give the take's audio in the manifest's audio column, or film it "
        "with sound."]


def test_the_rendered_actress_is_tracked_where_her_truth_is_known(mediapipe, tiny_corpus, held_out_take, tmp_path):
    """Render one take of the actress from her truth (rig weights and head motion) at 25 frames/s,
    ingest the video, and score the markers: the mouth opening against her lip gap, and every
    landmark bound to the rig (``facesynth bind`` on the video) against the rig's vertices."""
    rig = load_face_rig()
    truth = read_truth(tiny_corpus / "groundtruth" / f"{held_out_take}_truth.csv")
    capture_fps = 1.0 / float(np.median(np.diff(truth.time_s)))
    rows = list(csv.reader(open(tiny_corpus / "groundtruth" / f"{held_out_take}_head.csv")))[1:]
    head = np.array([[float(v) for v in r] for r in rows])
    weights = downsample(truth.rig_weights.astype(np.float32), capture_fps, FPS)
    RigCurves(weights, FPS, list(rig.shape_names), BUILTIN_RIG_NAME, builtin_rig_sha256(), "truth",
              downsample(head[:, :9].reshape(-1, 3, 3).astype(np.float32), capture_fps, FPS),
              downsample(head[:, 9:].astype(np.float32), capture_fps, FPS)).write(
        tmp_path / "truth.h5", config="{}", inputs=[])
    _run("render", tmp_path / "truth.h5", "--audio", tiny_corpus / "audio" / f"{held_out_take}.wav",
         "-o", tmp_path / "take.avi", "--set", "render.fps=25", "--set", "render.yaw_deg=0", "--set", "render.pitch_deg=0")
    (tmp_path / "manifest.csv").write_text("take,mocap\nfilmed,take.avi\n")
    _run("ingest", tmp_path / "manifest.csv", "-o", tmp_path / "corpus.h5", "--set", "ingest.recognize_phones=false")
    corpus = Corpus.read(tmp_path / "corpus.h5")
    n = len(weights)
    assert corpus.fps == FPS and abs(len(corpus.markers) - n) <= 1 and len(corpus.marker_names) == 478
    assert not np.isnan(corpus.markers).any()  # a face in every frame
    assert corpus.audio_count[0] > 0 and len(corpus.rigid_markers) == 26  # the video's sound; the rigid landmarks
    _run("normalize", tmp_path / "corpus.h5", "-o", tmp_path / "normalized.h5")
    tracked = NormalizedFrames.read(tmp_path / "normalized.h5").frames.loaded_markers()[:n].astype(np.float64)
    n = len(tracked)
    posed = rig.evaluate(weights[:n].astype(np.float64))  # her face, head frame, mm
    markers = build_marker_set(rig)
    lips = [markers.vertices[markers.names.index(m)] for m in ("ULI_C", "LLI_C")]
    truth_gap = np.linalg.norm(posed[:, lips[0]] - posed[:, lips[1]], axis=1)
    names = corpus.marker_names
    gap = np.linalg.norm(tracked[:, names.index("MP013")] - tracked[:, names.index("MP014")], axis=1)
    r = float(np.corrcoef(gap, truth_gap)[0, 1])
    slope = float(np.polyfit(truth_gap, gap, 1)[0])
    assert r > 0.9 and 0.7 < slope < 1.4, (r, slope)
    # every landmark bound to the rig: its error against the rig's vertex, after one similarity
    _run("bind", tmp_path / "take.avi", "--rig", "builtin", "--up", "+y", "--forward", "+z", "-o", tmp_path / "binding.csv")
    binding = read_binding(tmp_path / "binding.csv")
    cols = [i for i, m in enumerate(names) if m in binding]
    x, y = tracked[:, cols], posed[:, [binding[names[i]] for i in cols]]
    s, rotation, t, _ = similarity_fit(x.reshape(-1, 3), y.reshape(-1, 3))
    error = np.linalg.norm(s * x @ rotation.T + t - y, axis=2)
    print(f"video: {len(cols)} landmarks bound; error median {np.median(error):.2f} mm, 95th percentile "
          f"{np.percentile(error, 95):.2f} mm; mouth opening r {r:.3f}, slope {slope:.2f}")
    assert len(cols) > 400 and np.median(error) < 4.0 and abs(s - 1) < 0.1


def test_a_videos_sound_is_read_by_the_one_audio_reader(coded_speech, monkeypatch):
    """The take's audio is what ``read_audio`` gives for the film (its sound at its own rate,
    float32), whatever tracks the face; a film without sound is refused when the take needs it.
    The tracker is replaced by a still face here, so this runs without MediaPipe."""
    from coded_audio import coded

    from facesynth.domain.capture import video_take
    from facesynth.domain.capture.readers import CaptureOptions
    from facesynth.formats.audio import read_audio

    still = np.random.default_rng(0).uniform(0.3, 0.7, (video_take.LANDMARKS, 3))
    monkeypatch.setattr(video_take, "face_mesh_module", lambda where: None)
    monkeypatch.setattr(video_take, "track", lambda pictures, where: np.stack([still for _ in pictures]))
    film = coded(coded_speech, "mp4")
    take = video_take.read_video_take(film, CaptureOptions())
    samples, rate = read_audio(film)
    assert take.audio is not None and take.audio[1] == rate == 16000
    np.testing.assert_array_equal(take.audio[0], samples)
    assert abs(len(samples) / rate - len(take.positions) / take.fps) < 0.1
    with pytest.raises(InputError, match="the video has no sound; give the take's audio in the manifest's audio column"):
        video_take.read_video_take(coded_speech["silent"], CaptureOptions())


ANTAGONISTS = (("jawLeft", "jawRight"), ("mouthLeft", "mouthRight"), ("mouthSmile_L", "mouthFrown_L"),
               ("mouthSmile_R", "mouthFrown_R"))


def rest_and_coactivation(weights: np.ndarray, names: list[str]) -> tuple[float, float]:
    """(the largest median weight over the 10% of frames with the smallest jawOpen, the mean over
    antagonist pairs and frames of min(left, right))."""
    jaw = weights[:, names.index("jawOpen")]
    rest = weights[jaw <= np.quantile(jaw, 0.1)]
    both = [np.minimum(weights[:, names.index(a)], weights[:, names.index(b)]).mean() for a, b in ANTAGONISTS]
    return float(np.median(rest, axis=0).max()), float(np.mean(both))


def test_a_filmed_take_is_solved_without_bind_at_rest_and_following_the_mouth(mediapipe, tiny_corpus, held_out_take,
                                                                              tmp_path, capfd):
    """The actress rendered, ingested and solved on the built-in rig with no ``bind`` (the shipped
    Face Mesh binding and the take's own neutral face): at rest the rig rests (largest median
    weight of the quietest 10% <= 0.10), antagonists are not both on (<= 0.02), and the solved
    rig's lip gap follows hers (r >= 0.90)."""
    rig = load_face_rig()
    truth = read_truth(tiny_corpus / "groundtruth" / f"{held_out_take}_truth.csv")
    capture_fps = 1.0 / float(np.median(np.diff(truth.time_s)))
    weights = downsample(truth.rig_weights.astype(np.float32), capture_fps, FPS)
    RigCurves(weights, FPS, list(rig.shape_names), BUILTIN_RIG_NAME, builtin_rig_sha256(), "truth").write(
        tmp_path / "truth.h5", config="{}", inputs=[])
    _run("render", tmp_path / "truth.h5", "--audio", tiny_corpus / "audio" / f"{held_out_take}.wav",
         "-o", tmp_path / "take.avi", "--set", "render.fps=25", "--set", "render.yaw_deg=0", "--set", "render.pitch_deg=0")
    (tmp_path / "manifest.csv").write_text("take,mocap\nfilmed,take.avi\n")
    capfd.readouterr()
    _run("ingest", tmp_path / "manifest.csv", "-o", tmp_path / "corpus.h5", "--set", "ingest.recognize_phones=false")
    quiet = capfd.readouterr()
    assert "TensorFlow Lite" not in quiet.err + quiet.out and "W0000" not in quiet.err  # MediaPipe's own logging: -v
    _run("normalize", tmp_path / "corpus.h5", "-o", tmp_path / "normalized.h5")
    _run("solve", tmp_path / "normalized.h5", "-o", tmp_path / "curves.h5", "--set", "solve.output_fps=25")
    solved = RigCurves.read(tmp_path / "curves.h5").weights.astype(np.float64)
    n = min(len(solved), len(weights))
    names = list(rig.shape_names)
    rest, both = rest_and_coactivation(solved[:n], names)
    markers = build_marker_set(rig)
    lips = [markers.vertices[markers.names.index(m)] for m in ("ULI_C", "LLI_C")]
    gap = [np.linalg.norm(np.diff(rig.evaluate(w[:n].astype(np.float64), vertices=lips), axis=1)[:, 0], axis=1)
           for w in (solved, weights)]
    r = float(np.corrcoef(gap[0], gap[1])[0, 1])
    print(f"video solved without bind: rest {rest:.3f}, antagonists {both:.4f}, lip gap r {r:.3f}")
    assert rest <= 0.10 and both <= 0.02 and r >= 0.90, (rest, both, r)
    # off: the rig's neutral is the normalize reference, as before the neutral face was found
    _run("solve", tmp_path / "normalized.h5", "-o", tmp_path / "off.h5", "--set", "solve.output_fps=25",
         "--set", "solve.neutral=off", "--set", "solve.sparsity=0", "--set", "solve.antagonist=0",
         "--set", "solve.symmetry=0")
    off = RigCurves.read(tmp_path / "off.h5").weights.astype(np.float64)
    off_rest, off_both = rest_and_coactivation(off[:n], names)
    print(f"without neutral or priors: rest {off_rest:.3f}, antagonists {off_both:.4f}")
    assert off_rest > 0.10  # the check above can fail: without the neutral the rig does not rest
