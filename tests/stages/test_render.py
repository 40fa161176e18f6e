import subprocess

import imageio_ffmpeg
import numpy as np
import pytest
import soundfile as sf
from coded_audio import COMPRESSED, coded
from scipy import sparse

from facesynth.base.config import Config
from facesynth.base.errors import InputError, UsageError
from facesynth.domain.rendering import parts, video
from facesynth.domain.rendering.camera import Camera
from facesynth.domain.rendering.raster import NumpyRasterizer, OpenCLRasterizer
from facesynth.domain.rig import face
from facesynth.domain.rig.face import load_face_rig
from facesynth.formats.audio import resample
from facesynth.model.meshanim import MeshAnimation
from facesynth.stages import render


@pytest.fixture(scope="module")
def anim(held_out_synthesized):
    return held_out_synthesized["anim"], held_out_synthesized["audio"]


def _scene_frame(clip_rest, faces, vertices, width, height, samples=2, yaw=25.0, pitch=6.0, gaze=None):
    """Projected points, camera normals and the scene for one frame, as ShadedView does it."""
    scene = parts.build_scene(clip_rest, faces)
    cam = Camera.fit(parts.frame_points(scene), width, height, 30.0, yaw, pitch).scaled(samples)
    points = scene.positions(vertices, gaze)
    normals = parts.vertex_normals(points, scene.faces, scene.incidence)
    return scene, cam, cam.project(points), cam.directions(normals)


def _agree(scene, screen, normals, width, height):
    raster = OpenCLRasterizer(scene.faces, scene.albedo, scene.eye, width, height, 2)
    image, ids = raster.render(screen, normals), raster.triangle_ids()
    reference = NumpyRasterizer(scene.faces, scene.albedo, scene.eye, width, height, 2)
    ref_image, ref_ids = reference.render(screen, normals), reference.triangle_ids()
    assert (ref_ids != np.iinfo(np.int32).max).mean() > 0.2  # the face covers much of the frame
    # The documented tolerance: the same triangle for every sample wherever the device divides
    # like IEEE single precision (PoCL on the CPU does; allow a few edge samples elsewhere),
    # colour within one level where the device rounds sqrt/division differently.
    assert (ids == ref_ids).mean() > 0.995
    same = (ids == ref_ids).reshape(height, 2, width, 2).all(axis=(1, 3))
    assert np.abs(image.astype(int) - ref_image.astype(int))[same].max() <= 1
    return ref_image


def test_opencl_rasterizer_matches_the_numpy_reference(anim, opencl_device):
    clip = MeshAnimation.read(anim[0])
    scene, _, screen, normals = _scene_frame(clip.rest, clip.faces, clip.vertices[5], 160, 128)
    _agree(scene, screen, normals, 160, 128)


def test_production_rig_open_mouth_agrees_across_rasterizers(opencl_device):
    """The rig with its eyeballs, cavity, teeth and tongue, mouth wide open, eyes turned."""
    rig = load_face_rig()
    skin = rig.evaluate(_weights(rig, jawOpen=0.9, mouthLowerDown_L=0.5, mouthLowerDown_R=0.5))
    gaze = np.array([[0.3, 0.1], [0.3, 0.1]])
    scene, _, screen, normals = _scene_frame(rig.neutral, rig.faces, skin, 200, 160, gaze=gaze)
    _agree(scene, screen, normals, 200, 160)


def test_both_opencl_z_buffers_give_the_same_frame(opencl_device):
    """The one-pass 64-bit-atomic z-buffer and the two-pass 32-bit one (devices without
    64-bit atomics) choose the same triangle for every sample."""
    rig = load_face_rig()
    skin = rig.evaluate(_weights(rig, jawOpen=0.6))
    scene, _, screen, normals = _scene_frame(rig.neutral, rig.faces, skin, 160, 120)
    frames, ids = [], []
    for wide in (True, False):
        raster = OpenCLRasterizer(scene.faces, scene.albedo, scene.eye, 160, 120, 2, wide_atomics=wide)
        frames.append(raster.render(screen, normals))
        ids.append(raster.triangle_ids())
    assert np.array_equal(ids[0], ids[1]) and np.array_equal(frames[0], frames[1])


def _weights(rig, **named):
    w = np.zeros(len(rig.shape_names))
    for name, value in named.items():
        w[rig.shape_index(name)] = value
    return w


def _region(cam, points, pad=0.0):
    """Pixel bounding box (y0, y1, x0, x1) of projected ``points`` shrunk by ``pad`` of its size."""
    p = cam.project(points)[:, :2] / 2  # sample units -> pixels
    x0, y0 = p.min(0)
    x1, y1 = p.max(0)
    dx, dy = pad * (x1 - x0), pad * (y1 - y0)
    return int(y0 + dy), int(np.ceil(y1 - dy)), int(x0 + dx), int(np.ceil(x1 - dx))


def _render_rig(weights, gaze=None, width=320, height=240, samples=2, yaw=25.0):
    rig = load_face_rig()
    skin = rig.evaluate(weights)
    scene, cam, screen, normals = _scene_frame(rig.neutral, rig.faces, skin, width, height, samples, yaw=yaw, gaze=gaze)
    image = NumpyRasterizer(scene.faces, scene.albedo, scene.eye, width, height, samples).render(screen, normals)
    return rig, skin, cam, image


def test_open_mouth_shows_a_dark_cavity_teeth_and_no_see_through():
    rig, skin, cam, image = _render_rig(_weights(load_face_rig(), jawOpen=1.0))
    y0, y1, x0, x1 = _region(cam, skin[rig.loops["mouth"]], pad=0.2)
    mouth = image[y0:y1, x0:x1].astype(int).reshape(-1, 3)
    assert len(mouth) > 100
    brightness = mouth.sum(1) / 3
    assert (brightness < 50).mean() > 0.2                                  # the dark cavity
    teeth = (mouth.min(1) > 150) & (np.ptp(mouth, axis=1) < 60)             # light, unsaturated
    assert teeth.sum() > 10
    # nothing of the background shows through the mouth
    background = np.round(np.asarray(video.BACKGROUND[:3]) * 255)
    assert (np.abs(mouth - background).max(1) > 3).all()


def test_closed_mouth_shows_lips_not_teeth():
    rig, skin, cam, image = _render_rig(_weights(load_face_rig(), mouthClose=0.0))
    y0, y1, x0, x1 = _region(cam, skin[rig.loops["mouth"]], pad=0.1)
    mouth = image[y0:y1, x0:x1].astype(int).reshape(-1, 3)
    assert ((mouth.min(1) > 150) & (np.ptp(mouth, axis=1) < 40)).sum() < 5


def _eye_pixels(cam, skin, loop, image):
    y0, y1, x0, x1 = _region(cam, skin[loop], pad=0.15)
    return image[y0:y1, x0:x1].astype(int)


def test_eyes_show_white_sclera_and_a_dark_pupil_that_follows_the_gaze():
    rig = load_face_rig()
    centres = []
    for yaw in (-0.35, 0.35):
        _, skin, cam, image = _render_rig(np.zeros(len(rig.shape_names)), gaze=np.array([[yaw, 0.0], [yaw, 0.0]]),
                                          width=480, height=360, yaw=0.0)
        eye = _eye_pixels(cam, skin, rig.loops["eye_L"], image)
        sclera = (eye.min(2) > 150) & (np.ptp(eye, axis=2) < 50)
        assert sclera.sum() > 5
        dark = eye.max(2) < 40
        assert dark.sum() > 2
        centres.append(np.nonzero(dark)[1].mean())
    assert centres[1] > centres[0] + 2  # looking toward +x (the image's right in a frontal view) moves the pupil right


def test_supersampled_edges_have_intermediate_values():
    rig = load_face_rig()
    scene, cam, screen, normals = _scene_frame(rig.neutral, rig.faces, rig.neutral, 160, 120, 2)
    raster = NumpyRasterizer(scene.faces, scene.albedo, scene.eye, 160, 120, 2)
    image = raster.render(screen, normals).astype(float)
    covered = (raster.triangle_ids() != np.iinfo(np.int32).max).reshape(120, 2, 160, 2).sum(axis=(1, 3))
    background = np.asarray(video.BACKGROUND[:3]) * 255
    distance = np.abs(image - background).sum(2)
    means = [distance[covered == k].mean() for k in range(5)]
    assert (covered == 2).sum() > 20                                        # silhouette pixels half covered
    assert means[0] < 2 and means[1] < means[2] < means[3] < means[4]       # the more covered, the farther from the background
    one = NumpyRasterizer(scene.faces, scene.albedo, scene.eye, 160, 120, 1)
    cam1 = Camera.fit(parts.frame_points(scene), 160, 120, 30.0, 25.0, 6.0)
    points = scene.positions(rig.neutral)
    plain = one.render(cam1.project(points), cam1.directions(parts.vertex_normals(points, scene.faces, scene.incidence)))
    assert plain.shape == (120, 160, 3)


def test_holes_are_found_on_the_rig_mesh_itself():
    rig = load_face_rig()
    layout = parts.classify_holes(rig.neutral, rig.faces)
    assert set(layout.eyes[0].loop) == set(rig.loops["eye_L"])             # +x: the subject's left
    assert set(layout.eyes[1].loop) == set(rig.loops["eye_R"])
    assert set(layout.mouth.loop) == set(rig.loops["mouth"])
    assert layout.notes == ()


def test_gaze_from_rig_weights():
    rig = load_face_rig()
    w = _weights(rig, eyeLookOut_L=1.0, eyeLookIn_R=1.0, eyeLookUp_L=0.5, eyeLookUp_R=0.5)
    gaze = face.gaze_from_rig_weights(w[None], rig.shape_names)
    k = face.GAZE_RADIANS_PER_WEIGHT
    assert np.allclose(gaze[0], [[k, 0.5 * k], [k, 0.5 * k]])              # both eyes toward +x, up
    assert face.gaze_from_rig_weights(np.zeros((1, 3)), ("a", "b", "c")) is None


def test_a_plain_mesh_without_holes_still_renders(tmp_path):
    """A closed mesh (no loops) and an open sheet (one rim, not a face hole) render as they
    are, and say which parts were left out."""
    import trimesh

    sphere = trimesh.creation.icosphere(subdivisions=3, radius=50.0)
    sheet_v = np.array([[x, y, 0.0] for y in np.linspace(-40, 40, 9) for x in np.linspace(-40, 40, 9)])
    q = np.array([[i + 9 * j, i + 1 + 9 * j, i + 10 + 9 * j] for j in range(8) for i in range(8)]
                 + [[i + 9 * j, i + 10 + 9 * j, i + 9 + 9 * j] for j in range(8) for i in range(8)])
    for verts, faces in ((np.asarray(sphere.vertices), np.asarray(sphere.faces)), (sheet_v, q)):
        scene, _, screen, normals = _scene_frame(verts, faces, verts, 160, 120)
        assert scene.n_vertices == len(verts) and len(scene.notes) == 2
        image = NumpyRasterizer(scene.faces, scene.albedo, scene.eye, 160, 120, 2).render(screen, normals)
        background = np.round(np.asarray(video.BACKGROUND[:3]) * 255)
        assert (np.abs(image.astype(int) - background).max(2) > 20).mean() > 0.1


def _audio_of(avi, tmp_path):
    wav = tmp_path / "back.wav"
    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-loglevel", "error", "-y", "-i", str(avi), str(wav)], check=True)
    return sf.read(wav)


def test_avi_has_every_frame_and_audio_of_equal_length(anim, tmp_path):
    out = tmp_path / "x.avi"
    s = render.run([anim[0]], [anim[1]], out, Config.load().settings("render"))
    n_frames, _ = imageio_ffmpeg.count_frames_and_secs(str(out))
    assert n_frames == s.frames
    audio, rate = _audio_of(out, tmp_path)
    assert len(audio) / rate == pytest.approx(s.frames / 30.0, abs=1e-3)
    # the sound is the audio file's own, at its own rate, to 16-bit rounding (cut or padded at the end)
    source, source_rate = sf.read(anim[1])
    assert rate == source_rate
    n = min(len(audio), len(source))
    assert np.abs(audio[:n] - source[:n]).max() <= 1 / 32768
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
    def view(name: str):  # a quarter of the default frame: the views, not the resolution, are tested here
        return Config.load(None, ("render.width=320", "render.height=240", f"render.view={name}")).settings("render")

    render.run([anim[0]], [anim[1]], tmp_path / "m.avi", view("markers"))
    render.run([anim[0]], [anim[1]], tmp_path / "s.avi", view("side-by-side"), compare=[anim[0]])
    assert imageio_ffmpeg.count_frames_and_secs(str(tmp_path / "s.avi"))[0] > 0
    with pytest.raises(UsageError, match="side-by-side view needs --compare"):
        render.run([anim[0]], [anim[1]], tmp_path / "t.avi", view("side-by-side"))


def test_audio_shorter_than_the_motion_is_refused(anim, tmp_path):
    x, rate = sf.read(anim[1])
    short = tmp_path / "short.wav"
    sf.write(short, x[: rate // 4], rate)
    with pytest.raises(InputError, match="short.wav: the audio lasts 0.25 s but the animation"):
        render.run([anim[0]], [short], tmp_path / "x.avi", Config.load().settings("render"))
    assert not (tmp_path / "x.avi").exists()


def test_side_by_side_halves_are_labelled(anim):
    """The left half says "synthesis", the right "capture": the label region differs from the
    background there, and the two labels differ from each other."""
    settings = Config.load(None, ("render.width=320", "render.height=240", "render.view=side-by-side")).settings("render")
    clip = MeshAnimation.read(anim[0])
    frame = next(video.render_frames(clip, settings, clip))
    half = settings.width // 2
    background = np.round(video.BACKGROUND[:3] * 255)
    left, right = frame[8:30, 8:80].astype(float), frame[8:30, half + 8:half + 80].astype(float)
    for region in (left, right):
        assert (np.abs(region - background).max(-1) > 100).sum() > 40  # white text on the dark box
    assert np.abs(left - right).max() > 100  # "synthesis" is not "capture"
    # the faces themselves are untouched away from the labels: both halves show the same mesh
    assert np.array_equal(frame[120:, :half], frame[120:, half:])


def test_gaze_track_round_trips_and_marker_motion_leaves_it_unknown(anim, tmp_path):
    clip = MeshAnimation.read(anim[0])
    assert clip.gaze.shape == (len(clip.vertices), 2, 2) and np.isnan(clip.gaze).all()  # markers do not see the eyes
    clip.gaze = np.zeros_like(clip.gaze)
    clip.gaze[:, :, 0] = 0.2
    clip.weights, clip.bound_markers, clip.vertex_of = sparse.csr_matrix((clip.vertices.shape[1], 1)), ["x"], np.array([0])
    clip.write(tmp_path / "g.h5", config="{}", inputs=[])
    assert np.array_equal(MeshAnimation.read(tmp_path / "g.h5").gaze, clip.gaze)


def test_the_command_says_with_v_which_parts_a_plain_mesh_lacks(tmp_path):
    import trimesh
    from click.testing import CliRunner

    from facesynth.cli import main
    from facesynth.formats.audio import write_wav

    sphere = trimesh.creation.icosphere(subdivisions=2, radius=50.0)
    verts = np.asarray(sphere.vertices, np.float32)
    frames = np.stack([verts, verts * 1.05])
    clip = MeshAnimation(frames, 30.0, verts, np.asarray(sphere.faces), np.zeros((2, 1, 3), np.float32), ["m"],
                         sparse.csr_matrix((len(verts), 1), dtype=np.float32), ["m"], np.array([0]))
    clip.write(tmp_path / "a.h5", config="{}", inputs=[])
    write_wav(tmp_path / "a.wav", np.zeros(3200), 48000)
    result = CliRunner().invoke(main, ["render", str(tmp_path / "a.h5"), "--audio", str(tmp_path / "a.wav"), "-v",
                                       "--set", "render.width=160", "--set", "render.height=128", "-o", str(tmp_path / "a.avi")])
    assert result.exit_code == 0, result.output
    assert "no pair of eye holes found" in result.output and "no mouth hole found" in result.output
    assert (tmp_path / "a.avi").exists()


@pytest.mark.parametrize("name", COMPRESSED)
def test_coded_speech_is_the_videos_sound(anim, coded_speech, tmp_path, name):
    """``render --audio`` with the held-out sentence as M4A, MP3, Opus, Ogg or an MP4's sound:
    the video's soundtrack is the WAV's within the codec's error (at the file's own rate, 48 kHz
    for Opus: the same length within a millisecond and r > 0.99 once at 16 kHz, measured >= 0.996),
    and nothing is written for
    a video without sound or a text file."""
    from click.testing import CliRunner

    from facesynth.cli import main

    small = ["--set", "render.width=64", "--set", "render.height=48"]
    for kind, path in (("wav", coded_speech["wav"]), (name, coded(coded_speech, name))):
        r = CliRunner().invoke(main, ["render", str(anim[0]), "--audio", str(path), *small,
                                      "-o", str(tmp_path / f"{kind}.avi")])
        assert r.exit_code == 0, r.output
    (wav, rate), (got, got_rate) = _audio_of(tmp_path / "wav.avi", tmp_path), _audio_of(tmp_path / f"{name}.avi", tmp_path)
    got = resample(got.astype(np.float32), got_rate, rate)  # the file's own rate: Opus's is 48 kHz
    assert rate == 16000 and abs(len(got) - len(wav)) <= 16
    n = min(len(got), len(wav))
    assert np.corrcoef(wav[:n], got[:n])[0, 1] > 0.99
    for bad in ("silent", "notes"):
        r = CliRunner().invoke(main, ["render", str(anim[0]), "--audio", str(coded_speech[bad]), *small,
                                      "-o", str(tmp_path / f"{bad}.avi")])
        assert r.exit_code == 1 and r.output.count("\n") == 1 and str(coded_speech[bad]) in r.output
        assert not list(tmp_path.glob(f"{bad}.avi*"))
