import subprocess

import imageio_ffmpeg
import numpy as np
import pytest
import soundfile as sf

from facesynth.config import Config
from facesynth.errors import InputError, UsageError
from facesynth.model.meshanim import MeshAnimation
from facesynth.stages import deform, render, synthesize


@pytest.fixture(scope="module")
def anim(tiny_db, tiny_corpus, held_out_take, tmp_path_factory):
    config = Config.load()
    d = tmp_path_factory.mktemp("render")
    synthesize.run(tiny_db, d / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                   config.settings("align"), phones_path=tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    deform.run(d / "m.h5", tiny_corpus / "face.obj", tiny_corpus / "markers.csv", d / "a.h5", config.settings("deform"))
    return d / "a.h5", tiny_corpus / "audio" / f"{held_out_take}.wav"


def test_opencl_rasterizer_matches_the_numpy_reference(anim, opencl_device):
    clip = MeshAnimation.read(anim[0])
    cam = render.Camera.fit(clip.vertices[0], 160, 128, 30.0)
    screen = cam.project(clip.vertices[5].astype(np.float64))
    raster = render.OpenCLRasterizer(clip.faces, clip.vertices.shape[1], 160, 128)
    normals = render.vertex_normals(clip.vertices[5], clip.faces, render.face_incidence(clip.vertices.shape[1], clip.faces))
    image = raster.render(screen, normals)
    ids = raster.triangle_ids()
    reference = render.NumpyRasterizer(clip.faces, clip.vertices.shape[1], 160, 128)
    ref_image = reference.render(screen, normals)
    assert (reference.triangle_ids() != np.iinfo(np.int32).max).mean() > 0.2  # the face covers much of the frame
    # The documented tolerance: the same triangle on all but pixels on shared edges, colour
    # within one level where the device rounds sqrt/division differently.
    assert (ids == reference.triangle_ids()).mean() > 0.995
    same = ids == reference.triangle_ids()
    assert np.abs(image.astype(int) - ref_image.astype(int))[same].max() <= 1


def _audio_of(avi, tmp_path):
    wav = tmp_path / "back.wav"
    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-loglevel", "error", "-y", "-i", str(avi), str(wav)], check=True)
    return sf.read(wav)


def test_avi_has_every_frame_and_audio_of_equal_length(anim, tmp_path):
    out = tmp_path / "x.avi"
    s = render.run([anim[0]], [anim[1]], out, Config.load().settings("render"))
    n_frames, _ = imageio_ffmpeg.count_frames_and_secs(str(out))
    assert n_frames == s["frames"]
    audio, rate = _audio_of(out, tmp_path)
    assert len(audio) / rate == pytest.approx(s["frames"] / 30.0, abs=1e-3)
    reader = imageio_ffmpeg.read_frames(str(out))
    meta = next(reader)
    assert tuple(meta["size"]) == (640, 480)
    first = np.frombuffer(next(reader), np.uint8)
    assert first.std() > 10  # a face, not a blank frame


def test_rendering_is_deterministic(anim, tmp_path):
    settings = Config.load(None, ("render.width=320", "render.height=240")).settings("render")
    render.run([anim[0]], [anim[1]], tmp_path / "a.avi", settings)
    render.run([anim[0]], [anim[1]], tmp_path / "b.avi", settings)
    assert (tmp_path / "a.avi").read_bytes() == (tmp_path / "b.avi").read_bytes()


def test_marker_and_side_by_side_views(anim, tmp_path):
    base = Config.load(None, ("render.width=320", "render.height=240"))
    render.run([anim[0]], [anim[1]], tmp_path / "m.avi", Config.load(None, ("render.view=markers",)).settings("render"))
    render.run([anim[0]], [anim[1]], tmp_path / "s.avi", Config.load(None, ("render.view=side-by-side",)).settings("render"),
               compare=anim[0])
    assert imageio_ffmpeg.count_frames_and_secs(str(tmp_path / "s.avi"))[0] > 0
    with pytest.raises(UsageError, match="side-by-side view needs --compare"):
        render.run([anim[0]], [anim[1]], tmp_path / "t.avi", Config.load(None, ("render.view=side-by-side",)).settings("render"))
    del base


def test_audio_shorter_than_the_motion_is_refused(anim, tmp_path):
    x, rate = sf.read(anim[1])
    short = tmp_path / "short.wav"
    sf.write(short, x[: rate // 4], rate)
    with pytest.raises(InputError, match="short.wav: the audio lasts 0.25 s but the animation"):
        render.run([anim[0]], [short], tmp_path / "x.avi", Config.load().settings("render"))
    assert not (tmp_path / "x.avi").exists()


def _production_face_open_mouth(shared_assets):
    path = shared_assets / "ict-face" / "ict_face.npz"
    if not path.exists():
        pytest.skip("shared assets not present")
    d = np.load(path)
    verts = d["vertices"].astype(np.float64) + 0.8 * d["expr_deltas"][list(d["expr_names"]).index("jawOpen")].astype(np.float64)
    faces = d["faces"].astype(np.int64)
    screen = render.Camera.fit(verts, 160, 128, 30.0).project(verts)
    normals = render.vertex_normals(verts, faces, render.face_incidence(len(verts), faces))
    mouth = d["loop_mouth"]
    return verts, faces, screen, normals, (int(screen[mouth, 1].mean()), int(screen[mouth, 0].mean()))


def test_production_mesh_shows_a_dark_open_mouth(shared_assets):
    verts, faces, screen, normals, mouth = _production_face_open_mouth(shared_assets)
    image = render.NumpyRasterizer(faces, len(verts), 160, 128).render(screen, normals)
    assert image[mouth].max() < 60  # the open mouth shows the dark interior


def test_production_mesh_rasterizes_like_the_reference(shared_assets, opencl_device):
    verts, faces, screen, normals, mouth = _production_face_open_mouth(shared_assets)
    raster = render.OpenCLRasterizer(faces, len(verts), 160, 128)
    image = raster.render(screen, normals)
    ids = raster.triangle_ids()
    ids = np.where(ids == np.iinfo(np.int32).max, -1, ids)
    ref = render.triangle_ids_numpy(screen, faces, 160, 128)
    assert (ids == ref).mean() > 0.99
    assert image[mouth].max() < 60


def test_side_by_side_halves_are_labelled(anim):
    """The left half says "synthesis", the right "capture": the label region differs from the
    background there, and the two labels differ from each other."""
    settings = Config.load(None, ("render.width=320", "render.height=240", "render.view=side-by-side")).settings("render")
    clip = MeshAnimation.read(anim[0])
    frame = next(render.render_frames(clip, settings, clip))
    half = settings.width // 2
    background = np.round(render.BACKGROUND[:3] * 255)
    left, right = frame[8:30, 8:80].astype(float), frame[8:30, half + 8:half + 80].astype(float)
    for region in (left, right):
        assert (np.abs(region - background).max(-1) > 100).sum() > 40  # white text on the dark box
    assert np.abs(left - right).max() > 100  # "synthesis" is not "capture"
    # the faces themselves are untouched away from the labels: both halves show the same mesh
    assert np.array_equal(frame[120:, :half], frame[120:, half:])
