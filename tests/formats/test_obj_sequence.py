"""OBJ sequences (formats/obj_sequence.py): one complete OBJ per frame, numbered so they sort,
written block by block, each read back as the frame it was given."""

import numpy as np

from facesynth.formats.mesh import read_mesh
from facesynth.formats.obj_sequence import frame_name, write_obj_sequence


def test_every_frame_is_a_complete_mesh_read_back_as_given(tmp_path):
    rng = np.random.default_rng(0)
    faces = np.array([[0, 1, 2], [0, 2, 3], [1, 3, 2]])
    frames = rng.normal(0, 20, (7, 4, 3))
    blocks = [(0, frames[:3]), (3, frames[3:6]), (6, frames[6:])]  # blocks of any size, in order
    files = write_obj_sequence(tmp_path, faces, blocks, n_frames=7, fps=30.0)
    assert [f.name for f in files] == [frame_name(i) for i in range(7)] == sorted(f.name for f in files)
    assert frame_name(0) == "frame_000001.obj" and sorted(p.name for p in tmp_path.iterdir()) == [f.name for f in files]
    for i, path in enumerate(files):
        first = path.read_text(encoding="utf-8").splitlines()[0]
        assert first == (f"# facesynth export: frame {i + 1} of 7, t = {i / 30:.6f} s at 30 frames/s; "
                         "millimetres, +y up, face toward +z")
        vertices, read_faces = read_mesh(path)
        np.testing.assert_allclose(vertices, frames[i], atol=5e-5)  # four decimals of a millimetre
        np.testing.assert_array_equal(read_faces, faces)


def test_no_blocks_write_no_files(tmp_path):
    assert write_obj_sequence(tmp_path, np.zeros((0, 3), int), [], n_frames=0, fps=30.0) == []
    assert list(tmp_path.iterdir()) == []
