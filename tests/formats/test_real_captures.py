"""Capture files written by other programs (``tests/formats/captures``, see its README.md),
read by facesynth and compared with values obtained without it (``expected.json``, written by
``captures/reference.py`` with ezc3d, the ``c3d`` library or a plain struct decoding, and the
``csv`` module for TRC): frames, markers, frame rate, left-out model outputs, the fraction of
missing samples and coordinates of three markers at three frames each, to 0.01 mm."""

from __future__ import annotations

import json
import logging
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.formats.mocap import read_mocap

CAPTURES = Path(__file__).parent / "captures"
EXPECTED = json.loads((CAPTURES / "expected.json").read_text())
READ = sorted(name for name, entry in EXPECTED.items() if "refused" not in entry)
REFUSED = sorted(name for name, entry in EXPECTED.items() if "refused" in entry)


def _read(name: str, tmp_path: Path):
    path = CAPTURES / name
    if "CRLF" in name:  # stored with LF in its repository (git normalises it); the line ends its name says
        crlf = tmp_path / name
        crlf.write_bytes(path.read_bytes().replace(b"\n", b"\r\n"))
        assert crlf.read_bytes().count(b"\r\n") > 10
        path = crlf
    return read_mocap(path)


@pytest.mark.parametrize("name", READ)
def test_real_capture_matches_independent_values(name, tmp_path):
    expected = EXPECTED[name]
    take = _read(name, tmp_path)
    assert take.positions.shape == (expected["frames"], expected["markers"], 3)
    assert take.fps == pytest.approx(expected["rate"], rel=1e-5)
    assert len(take.left_out) == expected["left_out"]
    assert float(np.isnan(take.positions).any(axis=2).mean()) == pytest.approx(expected["nan_fraction"], abs=1e-6)
    assert not np.any(np.all(take.positions == 0, axis=2)), "a sample at exactly (0, 0, 0) is a gap"
    for frame, marker, *xyz in expected["samples"]:
        got = take.positions[frame, take.names.index(marker)]
        if xyz[0] is None:
            assert np.isnan(got).all(), f"{name}: frame {frame}, {marker} should be missing"
        else:
            np.testing.assert_allclose(got, xyz, atol=0.01, err_msg=f"{name}: frame {frame}, {marker}")


@pytest.mark.parametrize("name", REFUSED)
def test_real_capture_without_marker_data_is_refused_with_the_reason(name):
    with pytest.raises(InputError, match=EXPECTED[name]["refused"]) as info:
        read_mocap(CAPTURES / name)
    assert str(CAPTURES / name) in str(info.value)


def test_the_processor_and_storage_variants_read_the_same_data():
    """c3d.org sample 02: one capture written as Intel, DEC and SGI, float and integer. The float
    files and the DEC integer one hold the same values; the Intel and SGI integer files (the same
    as each other) differ from them by up to 0.28 mm in 59 of 9612 values, as written (ezc3d and
    the c3d library read the same)."""
    reference = read_mocap(CAPTURES / "pc_real.c3d")
    for name, tolerance in (("dec_real.c3d", 1e-4), ("sgi_real.c3d", 1e-4), ("dec_int.c3d", 0.05),
                            ("sgi_int.c3d", 0.3)):
        take = read_mocap(CAPTURES / name)
        assert take.names == reference.names
        np.testing.assert_array_equal(np.isnan(take.positions), np.isnan(reference.positions))
        np.testing.assert_allclose(take.positions, reference.positions, atol=tolerance, equal_nan=True, err_msg=name)


def test_labels_are_cut_to_point_used():
    """POINT:LABELS of sample 02 holds 75 names for 36 points."""
    assert len(read_mocap(CAPTURES / "pc_real.c3d").names) == 36


def test_labels2_names_the_points_past_255():
    take = read_mocap(CAPTURES / "labels2.c3d")
    assert take.names == [f"M{i:03d}" for i in range(300)]
    # the values written with ezc3d (numpy default_rng(0), see the README)
    rng = np.random.default_rng(0)
    written = np.round(rng.uniform(-1000, 1000, (3, 300, 10)), 3).transpose(2, 1, 0)
    written[2, 7] = written[5, 280] = np.nan
    np.testing.assert_allclose(take.positions, written, atol=1e-3)


def test_model_outputs_are_left_out_and_said(caplog):
    with caplog.at_level(logging.WARNING, logger="facesynth"):
        take = read_mocap(CAPTURES / "gait-pig.c3d")
    assert "A22:LKneeAngles" in take.left_out and "A22:LKneeAngles" not in take.names
    assert len(take.left_out) == 28 and len(take.names) == 49
    assert "left out 28 model outputs" in caplog.text


def test_a_file_of_model_outputs_only_is_refused(monkeypatch):
    from facesynth.formats import c3dfile, mocap

    points = c3dfile.read_points(CAPTURES / "gait-pig.c3d")
    points.groups["POINT:ANGLES"] = list(points.labels)  # every point declared a model output
    monkeypatch.setattr(mocap, "read_points", lambda path: points)
    with pytest.raises(InputError, match=r"gait-pig\.c3d: none of its 77 points is a marker \(77 are model outputs"):
        read_mocap(CAPTURES / "gait-pig.c3d")


def test_qualisys_invalid_residual_65535_is_missing():
    """Capture0002 writes gaps as (0, 0, 0) with the residual float 65535.0 (the word 0xFFFF)."""
    take = read_mocap(CAPTURES / "Capture0002.c3d")
    assert np.isnan(take.positions).any(axis=2).mean() == pytest.approx(0.0688, abs=1e-4)


def test_biogesta_integer_residual_words_are_read(caplog):
    with caplog.at_level(logging.WARNING, logger="facesynth"):
        take = read_mocap(CAPTURES / "admarche2.c3d")
    assert np.isfinite(take.positions).all(axis=2).mean() > 0.95
    assert "16-bit integers inside the float fields" in caplog.text


def test_nul_padded_units_and_repeated_four_letter_labels(caplog):
    """MACsample (SGI integer): POINT:UNITS 'mm\\0\\0'; RTHI, RSHA... name three markers each,
    told apart by POINT:DESCRIPTIONS."""
    with caplog.at_level(logging.WARNING, logger="facesynth"):
        take = read_mocap(CAPTURES / "MACsample.c3d")
    assert {"r.thigh.upper", "r.thigh.front", "r.thigh.rear", "RSHO"} <= set(take.names)
    assert len(set(take.names)) == 33
    assert "named by their POINT:DESCRIPTIONS" in caplog.text


def test_facial_capture_reads():
    take = read_mocap(CAPTURES / "Facial-Sing.c3d")
    assert take.positions.shape == (3000, 38, 3) and take.fps == 100.0


def _parameter_name_at(data: bytes, name: bytes) -> int:
    """Where the parameter section names ``name`` (the name bytes follow its length and group)."""
    start = (data[0] - 1) * 512
    at = data.index(bytes([len(name)]) + b"\x01" + name, start)
    return at + 2


def test_c3d_without_point_labels_is_refused_in_one_sentence(tmp_path):
    data = bytearray((CAPTURES / "pc_real.c3d").read_bytes())
    at = _parameter_name_at(data, b"LABELS")
    data[at : at + 6] = b"LABELX"
    path = tmp_path / "nolabels.c3d"
    path.write_bytes(bytes(data))
    with pytest.raises(InputError, match=r"nolabels\.c3d: the file has no POINT:LABELS parameter, so its 36 points"):
        read_mocap(path)


def test_c3d_without_point_labels_exits_1_without_traceback(tmp_path):
    from facesynth.cli import main

    data = bytearray((CAPTURES / "pc_real.c3d").read_bytes())
    at = _parameter_name_at(data, b"LABELS")
    data[at : at + 6] = b"LABELX"
    (tmp_path / "take.c3d").write_bytes(bytes(data))
    (tmp_path / "take.wav").write_bytes(b"")
    (tmp_path / "manifest.csv").write_text("take,mocap,audio,alignment,transcript,emotion\n"
                                           "t1,take.c3d,take.wav,,hello,neutral\n")
    result = CliRunner().invoke(main, ["ingest", str(tmp_path / "manifest.csv"), "-o", str(tmp_path / "c.h5")])
    assert result.exit_code == 1, result.output
    assert "no POINT:LABELS" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "c.h5").exists()


def test_truncated_c3d_data_block_is_refused(tmp_path):
    data = (CAPTURES / "Facial-Sing.c3d").read_bytes()
    path = tmp_path / "cut.c3d"
    path.write_bytes(data[: len(data) // 2])
    # (914944 bytes - 11 blocks of parameters and header) / (38 points x 16 bytes) = 1495 whole frames
    with pytest.raises(InputError, match=r"cut\.c3d: truncated C3D file: its data block holds 1495 of the 3000 frames"):
        read_mocap(path)


def test_a_header_analog_count_that_does_not_fit_the_data_block_yields_to_the_analog_parameters(tmp_path, caplog):
    """MotionMonitor writes the channel count (30) where the header wants the samples a frame
    (30 channels x 16 samples = 480); the ANALOG parameters fit the size of the data block."""
    data = bytearray((CAPTURES / "gait-pig.c3d").read_bytes())
    assert data[4:6] == (480).to_bytes(2, "little")  # header word 3 (DEC: little-endian)
    data[4:6] = (30).to_bytes(2, "little")
    path = tmp_path / "channels.c3d"
    path.write_bytes(bytes(data))
    with caplog.at_level(logging.WARNING, logger="facesynth"):
        take = read_mocap(path)
    np.testing.assert_array_equal(take.positions, read_mocap(CAPTURES / "gait-pig.c3d").positions)
    assert "the header's 30 analog samples a frame do not fit the size of the data block" in caplog.text


def test_centimetres_are_converted(tmp_path):
    data = bytearray((CAPTURES / "pc_real.c3d").read_bytes())
    at = _parameter_name_at(data, b"UNITS")
    unit = data.index(b"mm", at)
    data[unit : unit + 2] = b"cm"
    path = tmp_path / "cm.c3d"
    path.write_bytes(bytes(data))
    np.testing.assert_allclose(read_mocap(path).positions, 10 * read_mocap(CAPTURES / "pc_real.c3d").positions,
                               rtol=1e-6, equal_nan=True)


def test_trc_rate_is_taken_from_the_time_column_with_a_warning(caplog):
    with caplog.at_level(logging.WARNING, logger="facesynth"):
        take = read_mocap(CAPTURES / "std_walking5_markers.trc")
    assert take.fps == 25.0
    assert "DataRate is 250 frames/s but the Time column steps at 25 frames/s" in caplog.text


def test_trc_rate_with_irregular_time_column_is_refused(tmp_path):
    lines = (CAPTURES / "exampleFormat.trc").read_text().splitlines()
    lines[2] = lines[2].replace("100\t100", "50\t50", 1)
    for k, t in zip(range(5, 10), ("0.01", "0.02", "0.05", "0.06", "0.12")):
        cells = lines[k].split("\t")
        cells[1] = t
        lines[k] = "\t".join(cells)
    path = tmp_path / "irregular.trc"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match="steps irregularly"):
        read_mocap(path)


def test_trc_frame_count_kept_from_a_longer_trial_is_warned(caplog):
    with caplog.at_level(logging.WARNING, logger="facesynth"):
        take = read_mocap(CAPTURES / "walk_free_01.trc")
    assert take.positions.shape[0] == 73
    assert "declares 900 frames but 73 rows follow (frames 185 to 257)" in caplog.text


def test_trc_cut_in_the_middle_of_a_row_is_refused(tmp_path):
    data = (CAPTURES / "walk_free_01.trc").read_bytes()
    path = tmp_path / "cut.trc"
    path.write_bytes(data[: data.rindex(b"\n", 0, len(data) - 1) - 40])
    with pytest.raises(InputError, match=r"cut\.trc, line \d+: the file ends in the middle of this line"):
        read_mocap(path)


def test_expected_values_cover_the_writers():
    """At least 15 real files run here; every entry says which reader gave its values."""
    assert len(READ) + len(REFUSED) >= 15
    assert all(EXPECTED[n]["reference"] in ("ezc3d", "c3d", "struct", "csv") for n in READ)
    assert not any(math.isnan(v) for n in READ for s in EXPECTED[n]["samples"] for v in s[2:] if v is not None)
