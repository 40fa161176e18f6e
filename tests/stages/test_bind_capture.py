"""A user's own capture on the built-in rig: `bind` places its markers, `ingest` takes it without
audio or phone timing, `normalize` finds its rigid markers, `solve` runs on the normalized take,
then `rig-mesh` and `render` (silent)."""

import csv
import dataclasses
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.retarget.bind import axis_rotation
from facesynth.domain.rig.face import load_face_rig
from facesynth.formats.mesh import read_binding, read_rigid_markers
from facesynth.formats.mocap import MarkerTake, read_mocap, write_c3d
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation
from facesynth.stages import bind, ingest, normalize, render, rig_mesh, solve

#: NaturalPoint's Facial-Sing.c3d (c3d.org sample 29): a singer's face, 38 markers, 100 Hz, no audio.
FACIAL_SING = Path(__file__).resolve().parents[1] / "formats" / "captures" / "Facial-Sing.c3d"


def _truth(tiny_corpus):
    rows = list(csv.DictReader(open(tiny_corpus / "markers.csv")))
    return {r["marker"]: int(r["vertex"]) for r in rows}, {r["marker"] for r in rows if r["rigid"] == "1"}


@pytest.fixture(scope="module")
def user_capture(tiny_corpus, tmp_path_factory):
    """The tiny corpus's first neutral take as a user's capture: in a mocap frame with z up and the
    face toward -y, moved 1 m away, in its own folder with a manifest that has no audio, no
    alignment and no emotion (and no markers.csv beside it)."""
    d = tmp_path_factory.mktemp("capture")
    take = read_mocap(sorted((tiny_corpus / "mocap").glob("neutral_*.c3d"))[0])
    to_capture = axis_rotation("+z", "-y").T
    positions = take.positions.astype(np.float64) @ to_capture.T + [0.0, -1000.0, 1500.0]
    write_c3d(d / "take.c3d", MarkerTake(positions.astype(np.float32), take.names, take.fps))
    (d / "manifest.csv").write_text("take,mocap,audio,alignment,transcript,emotion,sentence,split\ntake,take.c3d,,,,,,\n")
    return d


def test_bind_places_the_capture_on_the_rig(user_capture, tiny_corpus, config, tmp_path):
    truth, true_rigid = _truth(tiny_corpus)
    out = tmp_path / "bound.csv"
    s = bind.run(user_capture / "take.c3d", out, config.settings("bind"), config.settings("normalize"))
    binding = read_binding(out)
    rig = load_face_rig()
    error = np.array([np.linalg.norm(rig.neutral[v] - rig.neutral[truth[n]]) for n, v in binding.items()])
    assert len(binding) == len(truth) and np.median(error) < 1.5 and np.percentile(error, 95) < 8.0
    assert s.residual_median_mm < 2.0 and s.scale == pytest.approx(1.0, abs=0.05)
    assert true_rigid <= set(read_rigid_markers(out)) and set(s.rigid) == set(read_rigid_markers(out))
    assert all(x < 1.0 for x in s.rigid_spreads_mm)
    header = out.read_text().splitlines()[0]
    assert header == "marker,vertex,rigid,residual_mm,flagged"


def test_bind_with_given_axes_agrees(user_capture, config, tmp_path):
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    bind.run(user_capture / "take.c3d", a, config.settings("bind"), config.settings("normalize"))
    bind.run(user_capture / "take.c3d", b, config.settings("bind"), config.settings("normalize"), up="+z", forward="-y")
    x, y = read_binding(a), read_binding(b)
    assert np.mean([x[n] == y[n] for n in x]) > 0.9


@pytest.mark.parametrize("kwargs, match", [
    ({"up": "+z"}, "give both --up and --forward"),
    ({"up": "+z", "forward": "-z"}, "lie on one axis"),
    ({"up": "+q", "forward": "-y"}, "is not an axis"),
])
def test_bind_refuses_bad_axes(user_capture, config, tmp_path, kwargs, match):
    out = tmp_path / "b.csv"
    with pytest.raises(InputError, match=match):
        bind.run(user_capture / "take.c3d", out, config.settings("bind"), config.settings("normalize"), **kwargs)
    assert not out.exists()


def test_bind_refuses_a_frame_past_the_take(user_capture, config, tmp_path):
    settings = dataclasses.replace(config.settings("bind"), frame=100000)
    with pytest.raises(InputError, match=r"bind.frame 100000 is beyond the take's \d+ frames"):
        bind.run(user_capture / "take.c3d", tmp_path / "b.csv", settings, config.settings("normalize"))


def test_bind_cli_reports_residuals_and_rigid_markers(user_capture, tmp_path):
    out = tmp_path / "b.csv"
    r = CliRunner().invoke(main, ["bind", str(user_capture / "take.c3d"), "--rig", "builtin", "-o", str(out)])
    assert r.exit_code == 0, r.output
    summary = [line for line in r.output.splitlines() if "rigid markers found from the data (spread" in line]
    assert len(summary) == 1 and len(summary[0]) < 160 and "-v lists them" in summary[0], r.output
    assert "residual median" in r.output and out.exists()
    verbose = CliRunner().invoke(main, ["bind", str(user_capture / "take.c3d"), "--rig", "builtin", "-o",
                                        str(tmp_path / "v.csv"), "-v"])
    assert verbose.exit_code == 0 and "rigid markers (spread in mm): " in verbose.output
    again = CliRunner().invoke(main, ["bind", str(user_capture / "take.c3d"), "-o", str(out)])
    assert again.exit_code == 1 and "exists" in again.output


def test_capture_without_audio_goes_to_a_silent_video(user_capture, tiny_corpus, tmp_path):
    """ingest (no audio, no phones) -> normalize (rigid markers from the data) -> solve on the
    built-in rig with the bound markers -> rig-mesh -> render without --audio."""
    config = Config.load()
    binding = tmp_path / "bound.csv"
    bind.run(user_capture / "take.c3d", binding, config.settings("bind"), config.settings("normalize"))
    corpus, normalized = tmp_path / "corpus.h5", tmp_path / "normalized.h5"
    s = ingest.run(user_capture / "manifest.csv", corpus, config.settings("ingest"), config.settings("align"))
    assert s.without_audio == ["take"] and s.without_phones == ["take"] and s.rigid_markers == []
    n = normalize.run(corpus, normalized, config.settings("normalize"))
    _, true_rigid = _truth(tiny_corpus)
    assert n.rigid_source == "data" and true_rigid <= set(n.rigid_markers) and not n.warnings
    assert len(n.rigid_spreads_mm) == len(n.rigid_markers)
    curves, anim = tmp_path / "curves.h5", tmp_path / "anim.h5"
    r = solve.run(normalized, curves, config.settings("solve"), None, binding)
    assert r.take == "take" and r.marker_residual_median_mm < 1.5
    c = RigCurves.read(curves)
    assert c.fps == config.settings("solve").output_fps and c.weights.shape[1] == 55
    rig_mesh.run(curves, anim, None, binding)
    clip = MeshAnimation.read(anim)
    assert len(clip.vertices) == len(c.weights)
    # render a short stretch of it (the NumPy rasterizer takes about a second a frame), silent
    short_curves, short_anim = tmp_path / "short_curves.h5", tmp_path / "short_anim.h5"
    RigCurves(c.weights[:6], c.fps, list(c.shape_names), c.rig_name, c.rig_sha256, c.source, c.head_rotation[:6],
              c.head_translation[:6], residual=c.residual[:6], method=c.method).write(short_curves, config="{}", inputs=[curves])
    rig_mesh.run(short_curves, short_anim, "builtin", binding)
    video = tmp_path / "v.avi"
    out = render.run([short_anim], [], video, dataclasses.replace(config.settings("render"), width=96, height=80))
    assert video.exists() and out.frames == 6


def test_solve_on_a_normalized_capture_with_several_takes_needs_take(tiny_artifacts, config, tmp_path):
    with pytest.raises(InputError, match="choose one with --take"):
        solve.run(tiny_artifacts["normalized"], tmp_path / "c.h5", config.settings("solve"))


def test_facial_sing_binds_and_solves(tmp_path):
    """NaturalPoint's singer: 37 face and head markers bound, the four head markers found rigid,
    and the solve's marker residual small (0.92 mm median, 3.98 mm 95th percentile when written)."""
    config = Config.load()
    binding = tmp_path / "markers.csv"
    s = bind.run(FACIAL_SING, binding, config.settings("bind"), config.settings("normalize"))
    assert sorted(s.rigid) == ["root-1", "root-2", "root-3", "root-4"]
    assert s.residual_median_mm < 4.0 and s.scale == pytest.approx(1.0, abs=0.1)
    # her upper lip (section10-*) rises as she opens her mouth: it must land where the rig's jaw does not reach
    rig = load_face_rig()
    jaw = np.linalg.norm(rig.deltas[rig.shape_index("jawOpen")], axis=1)
    bound = read_binding(binding)
    assert all(jaw[bound[f"section10-{k}"]] < 0.35 * jaw.max() for k in (1, 2, 3))
    assert all(jaw[bound[f"section13-{k}"]] >= 0.35 * jaw.max() for k in (1, 2, 3))
    (tmp_path / "manifest.csv").write_text(f"take,mocap\nsing,{FACIAL_SING}\n")
    ingest.run(tmp_path / "manifest.csv", tmp_path / "corpus.h5", config.settings("ingest"), config.settings("align"))
    n = normalize.run(tmp_path / "corpus.h5", tmp_path / "normalized.h5", config.settings("normalize"))
    assert n.rigid_source == "corpus" and sorted(n.rigid_markers) == ["root-1", "root-2", "root-3", "root-4"]
    r = solve.run(tmp_path / "normalized.h5", tmp_path / "curves.h5", config.settings("solve"), None, binding)
    assert r.marker_residual_median_mm < 1.5 and r.marker_residual_p95_mm < 6.0
    weights = RigCurves.read(tmp_path / "curves.h5").weights
    jaw_open, mouth_close = weights[:, rig.shape_index("jawOpen")], weights[:, rig.shape_index("mouthClose")]
    assert np.percentile(jaw_open, 95) > 0.5  # she sings with her mouth open
    assert mouth_close.mean() < 0.05  # and the lips part with the jaw (no jaw opening undone by lip closing)


def test_bind_on_a_users_obj_rig_matches_the_builtin(user_capture, config, tmp_path):
    """The built-in rig exported as a user's OBJ folder (neutral, jawOpen, one more shape) binds
    the capture to the same vertices."""
    from facesynth.formats.mesh import write_obj

    rig = load_face_rig()
    folder = tmp_path / "rig"
    folder.mkdir()
    write_obj(folder / "neutral.obj", rig.neutral, rig.faces)
    for name in ("jawOpen", "mouthSmile_L"):
        write_obj(folder / f"{name}.obj", rig.neutral + rig.deltas[rig.shape_index(name)], rig.faces)
    ours, builtin = tmp_path / "ours.csv", tmp_path / "builtin.csv"
    s = bind.run(user_capture / "take.c3d", ours, config.settings("bind"), config.settings("normalize"), folder)
    bind.run(user_capture / "take.c3d", builtin, config.settings("bind"), config.settings("normalize"), "builtin")
    assert s.rig == "rig"
    a, b = read_binding(ours), read_binding(builtin)
    assert np.mean([a[n] == b[n] for n in a]) > 0.95
