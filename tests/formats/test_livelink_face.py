"""Reading a Live Link Face CSV (facesynth.formats.livelink_face.read): the shipped iPhone capture,
the timecode rate, resampling across a skipped frame number, gaps, and the written file read back."""

from __future__ import annotations

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.rig.face import load_face_rig
from facesynth.formats import livelink_face

NAMES = load_face_rig().arkit_names


def test_the_shipped_capture_reads_at_60_fps_without_gaps(shared_assets):
    path = shared_assets / "ict-face" / "llf_capture.csv"
    if not path.exists():
        pytest.skip("needs ../shared/assets/ict-face/llf_capture.csv")
    take = livelink_face.read(path, NAMES)
    assert take.fps == 60.0 and take.arkit.shape == (328, 52)
    assert not np.isnan(take.arkit).any()  # its FF skips a number once, but no frame is lost
    assert take.head is None and take.notes == []  # its head columns never move
    assert livelink_face.is_live_link_face(path)


def test_the_timecode_rate_comes_from_where_the_frame_numbers_wrap():
    tc = [livelink_face.parse_timecode(f"00:00:0{s}:{f:02d}.000") for s in (1, 2) for f in range(30)]
    seconds, frames, fraction = (np.array(x) for x in zip(*tc))
    assert livelink_face.timecode_rate(seconds, frames, fraction, "x") == 30
    tc = [livelink_face.parse_timecode(f"00:00:01:{f:02d}.500") for f in range(10, 20)]
    seconds, frames, fraction = (np.array(x) for x in zip(*tc))
    assert livelink_face.timecode_rate(seconds, frames, fraction, "x") == 60  # fits every rate: the app's
    assert livelink_face.parse_timecode("00:61:00:00.000") is None
    assert livelink_face.parse_timecode("00:00:01;05") == (1, 5, 0.0)  # drop-frame separator


def test_written_curves_and_head_angles_read_back(tmp_path):
    rng = np.random.default_rng(0)
    arkit = rng.uniform(0, 1, (90, 52))
    head = np.stack([0.2 * np.sin(np.arange(90) / 9), 0.1 * np.cos(np.arange(90) / 7), np.full(90, 0.05)], 1)
    livelink_face.write(tmp_path / "t.csv", NAMES, arkit, 30.0, head=head)
    take = livelink_face.read(tmp_path / "t.csv", NAMES)
    assert take.fps == 30.0
    np.testing.assert_allclose(take.arkit, arkit, atol=1e-9)
    np.testing.assert_allclose(take.head, head, atol=1e-9)
    rotations = livelink_face.head_rotations(take.head)
    np.testing.assert_allclose(livelink_face.head_angles(rotations), head, atol=1e-9)


def test_a_missing_row_is_interpolated_and_a_long_pause_is_a_gap(tmp_path):
    arkit = np.tile(np.linspace(0, 1, 60)[:, None], (1, 52))
    livelink_face.write(tmp_path / "t.csv", NAMES, arkit, 60.0)
    lines = (tmp_path / "t.csv").read_text().splitlines()
    del lines[11]  # one row lost: interpolated
    del lines[30:40]  # 10 rows (0.18 s) lost: a gap
    (tmp_path / "t.csv").write_text("\n".join(lines) + "\n")
    take = livelink_face.read(tmp_path / "t.csv", NAMES)
    assert take.arkit.shape == (60, 52)
    np.testing.assert_allclose(take.arkit[10, 0], arkit[10, 0], atol=1e-9)
    gap = np.isnan(take.arkit).any(axis=1)
    assert gap[31:40].all() and not gap[:30].any() and not gap[42:].any()
    assert any("gaps" in n for n in take.notes)


def test_out_of_range_weights_are_clipped_with_a_note_and_infinite_ones_refused(tmp_path):
    arkit = np.full((20, 52), 0.5)
    livelink_face.write(tmp_path / "t.csv", NAMES, arkit, 60.0)
    text = (tmp_path / "t.csv").read_text().splitlines()
    cells = text[3].split(",")
    cells[2] = "1.5"
    text[3] = ",".join(cells)
    (tmp_path / "t.csv").write_text("\n".join(text) + "\n")
    take = livelink_face.read(tmp_path / "t.csv", NAMES)
    assert take.arkit[2, 0] == 1.0 and any("clipped" in n for n in take.notes)
    cells[2] = "inf"
    text[3] = ",".join(cells)
    (tmp_path / "t.csv").write_text("\n".join(text) + "\n")
    with pytest.raises(InputError, match=r"t\.csv, line 4, column EyeBlinkLeft: 'inf' is not a finite weight"):
        livelink_face.read(tmp_path / "t.csv", NAMES)
