"""``benchmarks/speaker_data.py``: its measures, sync check and file checks on made-up data with
known answers (preparing the real sources needs the raw copies of public repositories, which are
not shipped; it is not part of the test suite)."""

import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.formats.audio import write_wav

SPEC = importlib.util.spec_from_file_location(
    "speaker_data", Path(__file__).resolve().parents[1] / "benchmarks" / "speaker_data.py")
bench = importlib.util.module_from_spec(SPEC)
sys.modules["speaker_data"] = bench  # dataclasses look their module up while the file runs
SPEC.loader.exec_module(bench)


def test_fill_gaps_fills_short_dropouts_and_refuses_long_ones():
    x = np.arange(20.0)
    x[5:7] = np.nan  # 2 frames at 100 Hz = 0.02 s
    filled = bench.fill_gaps(x, 100.0)
    assert filled == pytest.approx(np.arange(20.0))
    y = np.arange(40.0)
    y[10:25] = np.nan  # 0.15 s > 0.1 s
    assert bench.fill_gaps(y, 100.0) is None
    assert bench.fill_gaps(np.full(5, np.nan), 100.0) is None
    two = np.stack([np.arange(10.0), -np.arange(10.0)], 1)
    two[3, 1] = np.nan  # a row with any NaN is a gap in every column
    assert bench.fill_gaps(two, 100.0)[3] == pytest.approx([3.0, -3.0])


def sensors(n=200, flip_vertical=False, swap_axes=False):
    """Made-up EMA: lips 20 mm apart opening by up to 10 mm, jaw following, tongue along +x."""
    t = np.linspace(0, 2 * np.pi, n)
    gap = 20 + 10 * (0.5 - 0.5 * np.cos(3 * t))  # mm
    up = -1.0 if flip_vertical else 1.0
    upper = np.stack([np.full(n, 80.0), np.zeros(n), up * gap / 2], 1)
    lower = np.stack([np.full(n, 80.0), np.zeros(n), -up * gap / 2], 1)
    jaw = np.stack([np.full(n, 70.0), np.zeros(n), -up * (15 + gap / 2)], 1)
    back, tip = np.tile([40.0, 0, 0], (n, 1)), np.tile([65.0, 0, 0], (n, 1))
    arrays = [upper, lower, back, tip, jaw]
    if swap_axes:  # the articulograph's vertical axis second, front-back third
        arrays = [a[:, [1, 2, 0]] for a in arrays]
    return gap, arrays


@pytest.mark.parametrize("flip", [False, True])
@pytest.mark.parametrize("swap", [False, True])
def test_ema_measures_find_the_axes_from_the_sensors(flip, swap):
    gap, (upper, lower, back, tip, jaw) = sensors(flip_vertical=flip, swap_axes=swap)
    vertical, up, front, forward = bench.ema_axes(upper, lower, back, tip)
    assert (vertical, front) == ((1, 2) if swap else (2, 0))
    assert up == (-1.0 if flip else 1.0) and forward == 1.0
    m = bench.ema_measures(upper, lower, back, tip, jaw=jaw)
    assert m["opening"] == pytest.approx(gap)
    assert m["jaw"] == pytest.approx(gap / 2 - gap.min() / 2)  # lowering from its highest, mm
    assert m["jaw"].min() == 0.0
    assert m["rounding"] == pytest.approx(np.zeros(len(gap)))  # lips never move forward here


def test_ema_rounding_is_minus_the_corner_distance_when_both_corners_are_measured():
    gap, (upper, lower, back, tip, _) = sensors()
    width = 50 - 5 * np.sin(np.linspace(0, 6, len(gap)))
    left = np.stack([np.full(len(gap), 75.0), width / 2, np.zeros(len(gap))], 1)
    right = left * [1, -1, 1]
    m = bench.ema_measures(upper, lower, back, tip, corners=(left, right))
    assert m["rounding"] == pytest.approx(-width)


def test_video_measures_are_scaled_by_the_eye_corners():
    points = np.zeros((2, 478, 3))
    points[:, 33] = [[-45, 0, 0], [-90, 0, 0]]  # the face twice as large in frame 1
    points[:, 263] = [[45, 0, 0], [90, 0, 0]]
    points[:, 13], points[:, 14] = [[0, -50, 0], [0, -100, 0]], [[0, -59, 0], [0, -118, 0]]
    points[:, 61], points[:, 291] = [[-25, -55, 0], [-50, -110, 0]], [[25, -55, 0], [50, -110, 0]]
    m = bench.video_measures(points)
    assert m["opening"] == pytest.approx([0.1, 0.1])
    assert m["rounding"] == pytest.approx([-50 / 90, -50 / 90])


def test_sync_lag_finds_a_known_shift_and_its_sign():
    rng = np.random.default_rng(0)
    rate = 100.0
    pairs = []
    for _ in range(3):
        base = np.convolve(rng.standard_normal(700), np.hanning(15), mode="same")
        # the opening leads the loudness by 8 frames (0.08 s): loudness[t] = opening[t - 8]
        pairs.append((base[100:600], base[92:592]))
    result = bench.sync_lag(pairs, rate)
    assert result["lag_s"] == pytest.approx(0.08)
    assert result["lag_r"] == pytest.approx(1.0, abs=0.02)  # z-scored over the whole curves, not the overlap
    assert result["r0"] < 0.9
    lagging = bench.sync_lag([(b, a) for a, b in pairs], rate)
    assert lagging["lag_s"] == pytest.approx(-0.08)


def test_log_rms_follows_the_loudness_at_the_frame_times():
    rate = 8000
    samples = np.concatenate([np.zeros(rate), 0.5 * np.ones(rate)])
    env = bench.log_rms(samples, rate, np.array([0.5, 1.5]), 0.05)
    assert env[1] == pytest.approx(np.log(0.5))
    assert env[0] == pytest.approx(np.log(0.5e-4))  # silence floored at 1e-4 of the loudest


def test_every_source_lists_its_files_with_a_sha256():
    table = bench.file_table()
    assert set(table) == set(bench.SOURCES)
    for files in table.values():
        assert files and all(len(d) == 64 and int(d, 16) >= 0 for d in files.values())


def test_a_changed_raw_file_is_refused_before_anything_is_written(tmp_path, monkeypatch, capsys):
    raw = tmp_path / "raw" / "copy"
    (raw / "matfiles").mkdir(parents=True)
    (raw / "matfiles" / "X.mat").write_bytes(b"not the file")
    monkeypatch.setattr(bench, "FILES", "stem_e2va matfiles/X.mat " + "0" * 64 + "\n")
    out = tmp_path / "out"
    with pytest.raises(InputError, match=r"X\.mat: sha256 differs"):
        bench.main(["--raw", str(tmp_path / "raw"), "--out", str(out), "--sources", "stem_e2va"])
    assert not any(out.iterdir())


def test_a_source_is_prepared_into_the_layout_with_its_speakers(tmp_path, monkeypatch, capsys):
    """A made-up FACEGOOD-like take through main(): wav + npz per utterance, speakers.json, READY."""
    raw = tmp_path / "raw"
    (raw / "wav").mkdir(parents=True)
    (raw / "bs_value_npy").mkdir()
    rate, n = 16000, 90
    names = ["mouth_stretch_c", "mouth_oh_c", "mouth_funnel", "mouth_pucker"]
    np.save(raw / "shirley_1015_bs_name.npy", np.array(names))
    open_curve = 0.5 - 0.5 * np.cos(np.linspace(0, 12 * np.pi, n))
    values = np.stack([open_curve, 0.1 * open_curve, np.zeros(n), np.zeros(n)], 1)
    np.save(raw / "bs_value_npy" / "bs_value_t1.npy", values)
    t = np.arange(n * rate // 30) / rate
    write_wav(raw / "wav" / "t1.wav", 0.3 * np.sin(2 * np.pi * 200 * t) * np.interp(t, np.arange(n) / 30, open_curve),
              rate)
    table = "".join(f"facegood {rel} {bench.sha256(raw / rel)}\n"
                    for rel in ("shirley_1015_bs_name.npy", "wav/t1.wav", "bs_value_npy/bs_value_t1.npy"))
    monkeypatch.setattr(bench, "FILES", table)
    lipsync = bench.load_lipsync()
    monkeypatch.setattr(lipsync, "read_table", lambda: {"mouthFunnel": ["mouth_funnel"],
                                                        "mouthPucker": ["mouth_pucker"], "jawOpen": ["mouth_stretch_c"]})
    monkeypatch.setattr(lipsync, "ARKIT_SHAPES", {"mouthFunnel": ("mouthFunnel",), "mouthPucker": ("mouthPucker",)})
    monkeypatch.setattr(bench, "load_lipsync", lambda: lipsync)
    out = tmp_path / "out"
    result = bench.main(["--raw", str(raw), "--out", str(out), "--sources", "facegood"])
    data = np.load(out / "facegood" / "performer" / "t1.npz")
    assert set(data) == {"times", "opening", "jaw", "rounding"}
    assert data["times"] == pytest.approx(np.arange(n) / 30)
    assert data["opening"] == pytest.approx(1.1 * open_curve)
    assert data["jaw"] == pytest.approx(open_curve)
    assert all(data[k].dtype == np.float64 for k in data)
    (entry,) = json.loads((out / "speakers.json").read_text())
    assert entry["speaker"] == "performer" and entry["may_ship"] is True and entry["utterances"] == 1
    assert entry["seconds"] == pytest.approx(3.0)
    assert abs(entry["lag_s"]) <= 0.04 and entry["r0"] > 0.9  # the sound was made from the curve itself
    assert entry["sync"] == "ok"
    ready = json.loads((out / "READY-facegood").read_text())
    assert ready["speakers"] == 1 and ready["pooled_sync"]["lag_s"] == entry["lag_s"]
    assert not list(out.glob(".*partial"))
    assert result["speakers"] == [entry] and result["sources"] == [ready]


def _clip_with_a_tone(path: Path, frequency: float) -> Path:
    """One second of grey picture at 25 frames/s with a tone of ``frequency`` Hz (44.1 kHz)."""
    import imageio_ffmpeg

    path.parent.mkdir(parents=True, exist_ok=True)
    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-loglevel", "error", "-f", "lavfi", "-i",
                    "color=c=gray:s=160x120:d=1:r=25", "-f", "lavfi", "-i",
                    f"sine=frequency={frequency}:duration=1:sample_rate=44100", "-shortest", "-pix_fmt", "yuv420p",
                    str(path)], check=True)
    return path


def test_more_grid_clips_are_read_with_their_sound_each_repository_one_speaker(tmp_path, monkeypatch):
    """grid_more: a clip's speaker is its repository folder's (two speakers' clips may share a
    name), its sound is the clip's own, its curves the tracked lips at the clip's frame rate."""
    from facesynth.domain.capture import video_take

    monkeypatch.setattr(bench, "GRID_MORE", {"repo-a": ("a", "clips", "grid01", "M"),
                                             "repo-b": ("b", "video/s9", "grid09", "F")})
    files = [str(_clip_with_a_tone(tmp_path / "repo-a" / "clips" / "bbaf3s.mpg", 200).relative_to(tmp_path)),
             str(_clip_with_a_tone(tmp_path / "repo-b" / "video" / "s9" / "bbaf3s.mpg", 300).relative_to(tmp_path))]

    def lips(frames, name):  # Face Mesh stand-in: eyes 10 apart, the inner lips opening and closing
        k = sum(1 for _ in frames)
        points = np.zeros((k, 478, 3))
        points[:, 263, 0] = 10.0
        points[:, 14, 1] = 2.0 + np.sin(np.arange(k) / 3.0)
        points[:, 291, 0] = 5.0
        return points

    monkeypatch.setattr(video_take, "track", lips)
    a, b = bench.grid_more(tmp_path, files)
    assert (a.speaker, b.speaker) == ("grid01", "grid09") and a.name == b.name == "bbaf3s"
    for u, frequency in ((a, 200), (b, 300)):
        assert u.rate == 44100 and len(u.samples) == pytest.approx(44100, abs=1200)
        spectrum = np.abs(np.fft.rfft(u.samples))
        assert np.argmax(spectrum) * u.rate / len(u.samples) == pytest.approx(frequency, abs=3)
        assert u.times == pytest.approx(np.arange(len(u.times)) / 25.0) and len(u.times) == 25
        assert u.opening == pytest.approx((2.0 + np.sin(np.arange(25) / 3.0)) / 10.0)
        assert u.rounding == pytest.approx(np.full(25, -0.5))


def test_sync_verdict_names_offsets_and_weak_evidence():
    assert bench.sync_verdict({"lag_s": 0.04, "lag_r": 0.5, "r0": 0.45}) == "ok"
    assert bench.sync_verdict({"lag_s": -0.24, "lag_r": 0.5, "r0": 0.1}) == "offset"
    assert bench.sync_verdict({"lag_s": 0.0, "lag_r": 0.1, "r0": 0.1}) == "weak"
    # a far peak hardly better than lag 0 is a broad peak, not an offset
    assert bench.sync_verdict({"lag_s": 0.24, "lag_r": 0.53, "r0": 0.47}) == "ok"


def test_a_reader_failing_midway_leaves_no_partial_source(tmp_path):
    def reader(root, files):
        yield bench.Utterance("s1", "u1", np.zeros(800, np.float32), 8000, np.arange(10) / 100.0, np.ones(10))
        raise InputError("u2: broken")

    source = bench.Source("made_up", "nowhere", "none", False, {"s1": bench.Speaker("F", "x", "y")}, "mm", "none",
                          reader)
    with pytest.raises(InputError, match="u2: broken"):
        bench.prepare(source, tmp_path, [], tmp_path / "out")
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_the_script_refuses_a_missing_raw_folder_in_one_sentence(tmp_path):
    script = Path(__file__).resolve().parents[1] / "benchmarks" / "speaker_data.py"
    run = subprocess.run([sys.executable, str(script), "--raw", str(tmp_path / "absent"), "--out", str(tmp_path / "o")],
                         capture_output=True, text=True, check=False)
    assert run.returncode == 1
    assert run.stderr.strip() == f"{tmp_path / 'absent'}: not a folder; --raw names folders holding the raw copies."
    assert not (tmp_path / "o").exists()
