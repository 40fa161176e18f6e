"""Another rig's curves and their mapping to ARKit (facesynth.formats.blendshape_curves)."""

from __future__ import annotations

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.rig.face import load_face_rig
from facesynth.formats.blendshape_curves import read_channel_names, read_curves, read_mapping, write_mapping

NAMES = load_face_rig().arkit_names


def test_a_curve_csv_with_time_gives_its_rate_and_gaps(tmp_path):
    (tmp_path / "c.csv").write_text("frame,time,JawDrop,Smile_L\n0,0.0,0.1,0\n1,0.04,,0.2\n2,0.08,0.3,0.2\n")
    values, names, rate = read_curves(tmp_path / "c.csv", None, None)
    assert names == ["JawDrop", "Smile_L"] and rate == 25.0
    assert np.isnan(values[1, 0]) and values[2, 0] == 0.3


def test_a_npy_take_needs_its_names_and_rate(tmp_path):
    np.save(tmp_path / "c.npy", np.zeros((5, 2)))
    (tmp_path / "names.txt").write_text("a\nb\n")
    with pytest.raises(InputError, match="needs its channel names"):
        read_curves(tmp_path / "c.npy", None, 30.0)
    with pytest.raises(InputError, match="has no time; give its frame rate"):
        read_curves(tmp_path / "c.npy", tmp_path / "names.txt", None)
    values, names, rate = read_curves(tmp_path / "c.npy", tmp_path / "names.txt", 30.0)
    assert values.shape == (5, 2) and names == ["a", "b"] and rate == 30.0
    np.save(tmp_path / "names.npy", np.array(["a", "b", "c"]))
    assert read_channel_names(tmp_path / "names.npy") == ["a", "b", "c"]
    with pytest.raises(InputError, match="2 columns but .* names 3 channels"):
        read_curves(tmp_path / "c.npy", tmp_path / "names.npy", 30.0)


def test_the_mapping_adds_rows_and_refuses_unknown_names_in_one_sentence(tmp_path):
    write_mapping(tmp_path / "m.csv", [("JawDrop", "jawOpen", 1.0, ""), ("Oh", "jawopen", 0.5, "any case"),
                                       ("Smile_L", "mouthSmileLeft", 0.5, "")], ["a comment"])
    matrix = read_mapping(tmp_path / "m.csv", ["JawDrop", "Oh", "Smile_L"], NAMES, "c.csv")
    assert matrix.shape == (3, 52)
    assert matrix[1, NAMES.index("jawOpen")] == 0.5 and matrix[2, NAMES.index("mouthSmileLeft")] == 0.5
    with pytest.raises(InputError) as info:
        read_mapping(tmp_path / "m.csv", ["JawDrop", "Smile_L"], NAMES, "c.csv")
    assert str(info.value).startswith(f"{tmp_path / 'm.csv'}, line 4: the source channel 'Oh' is not a channel of c.csv")
    write_mapping(tmp_path / "bad.csv", [("JawDrop", "jawDrop", 1.0, "")])
    with pytest.raises(InputError, match=r"bad\.csv, line 2: 'jawDrop' is not an ARKit blendshape"):
        read_mapping(tmp_path / "bad.csv", ["JawDrop"], NAMES, "c.csv")
    (tmp_path / "nohead.csv").write_text("from,to\nJawDrop,jawOpen\n")
    with pytest.raises(InputError, match=r"nohead\.csv, line 1: the mapping's header lacks source, arkit, weight"):
        read_mapping(tmp_path / "nohead.csv", ["JawDrop"], NAMES, "c.csv")
