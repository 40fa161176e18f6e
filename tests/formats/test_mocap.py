import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.formats.mocap import MarkerTake, read_mocap, write_c3d, write_csv, write_trc


def _take():
    rng = np.random.default_rng(1)
    pos = rng.normal(0, 50, (12, 4, 3)).astype(np.float32)
    pos[3, 2] = np.nan
    return MarkerTake(pos, ["A", "B", "C", "LLO_C"], 120.0)


@pytest.mark.parametrize("writer, suffix", [(write_c3d, ".c3d"), (write_trc, ".trc"), (write_csv, ".csv")])
def test_round_trip_keeps_names_rate_and_gaps(tmp_path, writer, suffix):
    take = _take()
    p = tmp_path / f"t{suffix}"
    writer(p, take)
    back = read_mocap(p)
    assert back.names == take.names
    assert back.fps == pytest.approx(120.0)
    assert np.isnan(back.positions[3, 2]).all()
    np.testing.assert_allclose(back.positions, take.positions, atol=1e-3)


@pytest.mark.filterwarnings("ignore:No analog data")
def test_c3d_bytes_are_those_of_the_c3d_librarys_frame_loop(tmp_path):
    """write_c3d encodes the frames at once; the c3d library, fed frame by frame, writes the
    same bytes (a missing sample keeps the marker's last coordinates, 0 before its first)."""
    import c3d

    rng = np.random.default_rng(2)
    positions = rng.normal(0, 50, (40, 5, 3)).astype(np.float32)
    positions[rng.random((40, 5)) < 0.2] = np.nan
    positions[:6, 1] = np.nan
    positions[7, 3, 1] = np.nan
    positions[:, 4] = np.nan
    names = ["A", "B", "C", "D", "E"]
    write_c3d(tmp_path / "fast.c3d", MarkerTake(positions, names, 100.0))
    writer = c3d.Writer(point_rate=100.0, point_units="mm  ")
    writer.set_point_labels(names)
    for xyz in positions:
        missing = np.isnan(xyz).any(axis=1)
        points = np.zeros((5, 5), np.float32)
        points[:, :3] = np.where(missing[:, None], 0.0, xyz)
        points[:, 3] = np.where(missing, -1.0, 0.0)
        writer.add_frames([(points, np.zeros((0, 0), np.float32))])
    with open(tmp_path / "library.c3d", "wb") as fh:
        writer.write(fh)
    assert (tmp_path / "fast.c3d").read_bytes() == (tmp_path / "library.c3d").read_bytes()


def test_truncated_c3d_is_refused(tmp_path):
    p = tmp_path / "t.c3d"
    write_c3d(p, _take())
    data = p.read_bytes()
    p.write_bytes(data[: len(data) - 300])
    with pytest.raises(InputError, match="truncated C3D"):
        read_mocap(p)


def test_metres_are_converted_to_millimetres(tmp_path):
    p = tmp_path / "m.csv"
    p.write_text("# units: m\ntime,A_x,A_y,A_z\n0,0.001,0.002,0.003\n0.01,0.001,0.002,0.003\n")
    take = read_mocap(p)
    np.testing.assert_allclose(take.positions[0, 0], [1, 2, 3], atol=1e-5)
    assert take.fps == pytest.approx(100.0)
