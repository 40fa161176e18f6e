"""Mesh reading (OBJ, PLY) and marker-to-vertex bindings."""

import re

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.formats.mesh import read_binding, read_mesh, write_binding, write_obj

# A unit square (vertices 1-4, counter-clockwise seen from +z) and two more vertices: 5 is used
# by a triangle, 6 by nothing. Bindings index this list, so all of it must come back, in order.
VERTICES = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 5 5 5\n"
SIX = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [5, 5, 5]], float)
UVS_NORMALS = "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"


def _write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def _triangles(faces):
    """Faces as a set of triangles, each rotated to start at its smallest index (orientation kept)."""
    out = set()
    for f in np.asarray(faces).tolist():
        k = f.index(min(f))
        out.add(tuple(f[k:] + f[:k]))
    return out


def _normals(vertices, faces):
    v = vertices[faces]
    n = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    return n / np.linalg.norm(n, axis=1, keepdims=True)


# --- OBJ ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("faces", [
    "f 1 2 3 4\nf 2 5 3\n",
    "f 1/1 2/2 3/3 4/4\nf 2/2 5/1 3/3\n",
    "f 1/1/1 2/2/1 3/3/1 4/4/1\nf 2/2/1 5/1/1 3/3/1\n",
    "f 1//1 2//1 3//1 4//1\nf 2//1 5//1 3//1\n",
    "f 1/1/1 2//1 3/3 4\nf 2 5/1/1 3//1\n",  # forms mixed within a face
], ids=["v", "v/vt", "v/vt/vn", "v//vn", "mixed"])
def test_obj_face_forms_give_the_files_vertices_and_triangulated_quads(tmp_path, faces):
    v, f = read_mesh(_write(tmp_path, "m.obj", VERTICES + UVS_NORMALS + faces))
    assert v.dtype == np.float64 and f.dtype == np.int64 and f.shape == (3, 3)
    np.testing.assert_array_equal(v, SIX)  # vertex 6 is used by no face and still there
    # the quad 1-2-3-4 as two triangles on its diagonal 1-3, the triangle 2-5-3 as it is
    assert _triangles(f) == {(0, 1, 2), (0, 2, 3), (1, 4, 2)}
    np.testing.assert_allclose(_normals(v, f), [[0, 0, 1]] * 3)  # winding kept: every normal +z


def test_a_polygon_is_split_into_triangles_covering_it(tmp_path):
    # a regular pentagon, one face
    angles = 2 * np.pi * np.arange(5) / 5
    text = "".join(f"v {np.cos(a):.6f} {np.sin(a):.6f} 0\n" for a in angles) + "f 1 2 3 4 5\n"
    v, f = read_mesh(_write(tmp_path, "pentagon.obj", text))
    assert f.shape == (3, 3)
    area = 0.5 * np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1).sum()
    assert area == pytest.approx(5 / 2 * np.sin(2 * np.pi / 5), rel=1e-5)  # the pentagon's area, no overlap
    np.testing.assert_allclose(_normals(v, f)[:, 2], 1.0)


@pytest.mark.parametrize("corner", ["{i}", "{i}/{i}", "{i}/{i}/1", "{i}//1"])
def test_relative_indices_count_back_from_the_face(tmp_path, corner):
    # OBJ: -1 is the last vertex read before the face, even when more vertices follow
    def f(*idx):
        return "f " + " ".join(corner.format(i=i) for i in idx) + "\n"

    text = (UVS_NORMALS + "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + f(-3, -2, -1)
            + "v 5 0 0\nv 6 0 0\nv 5 1 0\n" + f(-3, -2, -1) + f(1, -2, -1) + "v 9 9 9\n")
    v, faces = read_mesh(_write(tmp_path, "rel.obj", text))
    assert len(v) == 7
    assert faces.tolist() == [[0, 1, 2], [3, 4, 5], [0, 4, 5]]


def test_materials_and_groups_do_not_repeat_or_reorder_vertices(tmp_path):
    text = ("mtllib face.mtl\no face\n" + VERTICES + UVS_NORMALS + "g skin\nusemtl skin\nf 1/1 2/2 3/3\n"
            + "g lips\nusemtl lips\nf 1/1 3/3 4/4\nusemtl skin\ns 1\nf 2 5 3\nl 1 6\n")
    v, f = read_mesh(_write(tmp_path, "m.obj", text))
    np.testing.assert_array_equal(v, SIX)
    assert _triangles(f) == {(0, 1, 2), (0, 2, 3), (1, 4, 2)}


def test_a_texture_seam_does_not_split_a_vertex(tmp_path):
    # vertices 1 and 3 carry different texture coordinates in the two triangles
    text = VERTICES + UVS_NORMALS + "f 1/1 2/2 3/3\nf 1/4 3/1 4/4\n"
    v, f = read_mesh(_write(tmp_path, "seam.obj", text))
    assert len(v) == 6 and _triangles(f) == {(0, 1, 2), (0, 2, 3)}


def test_write_obj_then_read_mesh_round_trip(tmp_path):
    rng = np.random.default_rng(0)
    verts = rng.uniform(-150, 150, size=(40, 3))
    faces = rng.integers(0, 40, size=(25, 3))
    p = tmp_path / "out.obj"
    write_obj(p, verts, faces, comment="facesynth test, millimetres")
    assert p.read_text(encoding="utf-8").startswith("# facesynth test, millimetres\nv ")
    v, f = read_mesh(p)
    np.testing.assert_allclose(v, verts, atol=5e-6)  # written with five decimals
    np.testing.assert_array_equal(f, faces)  # 1-based in the file, 0-based again here


# --- PLY ---------------------------------------------------------------------------------------


def test_ascii_ply_with_a_quad_and_an_unused_vertex(tmp_path):
    header = ("ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 2\nproperty list uchar int vertex_indices\nend_header\n")
    body = "".join(f"{x:g} {y:g} {z:g}\n" for x, y, z in SIX) + "4 0 1 2 3\n3 1 4 2\n"
    v, f = read_mesh(_write(tmp_path, "m.ply", header + body))
    np.testing.assert_array_equal(v, SIX)
    assert _triangles(f) == {(0, 1, 2), (0, 2, 3), (1, 4, 2)}


def test_binary_ply_written_by_trimesh(tmp_path):
    import trimesh

    faces = np.array([[0, 1, 2], [0, 2, 3], [1, 4, 2]])
    trimesh.Trimesh(SIX, faces, process=False).export(tmp_path / "m.ply")
    assert b"binary_little_endian" in (tmp_path / "m.ply").read_bytes()[:80]
    v, f = read_mesh(tmp_path / "m.ply")
    np.testing.assert_array_equal(v, SIX)
    np.testing.assert_array_equal(f, faces)


# --- bad files ---------------------------------------------------------------------------------


BAD_MESHES = [
    ("empty.obj", "", "the mesh has no triangles"),
    ("points.obj", VERTICES, "the mesh has no triangles"),
    ("words.obj", "this is not a mesh\nat all\n", "the mesh has no triangles"),
    ("range.obj", VERTICES + "f 1 2 3\nf 1 2 7\n", "line 8: vertex index 7 but the file has 6 vertices"),
    ("zero.obj", VERTICES + "f 0 1 2\n", r"line 7: vertex index 0 refers to no vertex \(6 read so far; OBJ indices start at 1\)"),
    ("back.obj", VERTICES + "f -1 -2 -7\n", "line 7: vertex index -7 refers to no vertex"),
    ("corner.obj", VERTICES + "f 1 2 three\n", "line 7: face corner 'three' is not a vertex index"),
    ("coords.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n", "unreadable mesh"),
    ("mesh.stl", "solid x\nendsolid x\n", r"unsupported mesh format '\.stl'; use \.obj or \.ply"),
    ("short.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n",
     "(unreadable mesh|the mesh has no triangles)"),
    ("header.ply", "ply\nformat nonsense 9.0\nend_header\n", "(unreadable mesh|the mesh has no triangles)"),
]


@pytest.mark.parametrize("name, content, message", BAD_MESHES, ids=[b[0] for b in BAD_MESHES])
def test_bad_mesh_files_are_refused_naming_the_file(tmp_path, name, content, message):
    p = _write(tmp_path, name, content)
    with pytest.raises(InputError, match=re.escape(str(p)) + "[:,] .*" + message):
        read_mesh(p)


def test_binary_junk_and_a_missing_file_are_refused(tmp_path):
    junk = tmp_path / "junk.obj"
    junk.write_bytes(np.random.default_rng(0).integers(0, 256, 400, dtype=np.uint8).tobytes())
    with pytest.raises(InputError, match=re.escape(str(junk))):
        read_mesh(junk)
    with pytest.raises(InputError, match=re.escape(str(tmp_path / "nowhere.obj")) + ": mesh file not found"):
        read_mesh(tmp_path / "nowhere.obj")


# --- bindings ----------------------------------------------------------------------------------


def test_binding_round_trip_and_whitespace(tmp_path):
    p = tmp_path / "b.csv"
    write_binding(p, {"ULI_C": 12, "LLI_C": 0, "NOSE": 4031})
    assert read_binding(p) == {"ULI_C": 12, "LLI_C": 0, "NOSE": 4031}
    assert list(read_binding(p)) == ["ULI_C", "LLI_C", "NOSE"]  # the file's order
    q = _write(tmp_path, "spaced.csv", "marker,vertex,note\n ULI_C , 12 ,upper lip\n\nLLI_C,7,\n")
    assert read_binding(q) == {"ULI_C": 12, "LLI_C": 7}


def test_binding_saved_by_a_spreadsheet_with_a_byte_order_mark(tmp_path):
    p = tmp_path / "excel.csv"
    p.write_bytes("marker,vertex\r\nULI_C,12\r\n".encode("utf-8-sig"))
    assert read_binding(p) == {"ULI_C": 12}


BAD_BINDINGS = {
    "misnamed column": ("name,vertex\nULI_C,12\n", "the binding CSV needs the columns 'marker' and 'vertex'"),
    "other column": ("marker,index\nULI_C,12\n", "the binding CSV needs the columns 'marker' and 'vertex'"),
    "empty file": ("", "the binding CSV needs the columns 'marker' and 'vertex'"),
    "word": ("marker,vertex\nULI_C,12\nLLI_C,twelve\n", r"line 3: vertex 'twelve' is not an integer index"),
    "fraction": ("marker,vertex\nULI_C,12.5\n", r"line 2: vertex '12\.5' is not an integer index"),
    "empty cell": ("marker,vertex\nULI_C,\n", r"line 2: vertex '' is not an integer index"),
    "no cell": ("marker,vertex\nULI_C\n", r"line 2: vertex None is not an integer index"),
    "after blank lines": ("marker,vertex\nULI_C,1\n\n\nLLI_C,x\n", r"line 5: vertex 'x' is not an integer index"),
    "bound twice": ("marker,vertex\nULI_C,1\nLLI_C,2\nULI_C,3\n", r"line 4: marker 'ULI_C' is bound again \(first on line 2\)"),
}


@pytest.mark.parametrize("text, message", BAD_BINDINGS.values(), ids=BAD_BINDINGS.keys())
def test_bad_bindings_are_refused_by_line(tmp_path, text, message):
    p = _write(tmp_path, "b.csv", text)
    with pytest.raises(InputError, match=re.escape(str(p)) + "[:,] .*" + message):
        read_binding(p)


def test_binding_that_is_not_utf8_or_missing(tmp_path):
    p = tmp_path / "latin1.csv"
    p.write_bytes("marker,vertex\nl\xe8vre,3\n".encode("latin-1"))
    with pytest.raises(InputError, match=re.escape(str(p)) + ": not UTF-8 text"):
        read_binding(p)
    with pytest.raises(InputError, match="nowhere.csv: binding file not found"):
        read_binding(tmp_path / "nowhere.csv")


def test_a_vertex_out_of_the_mesh_is_refused_when_bound(tmp_path, config):
    """read_binding cannot know the mesh; deform's bind checks the range against it."""
    from facesynth.domain.retarget.deform import bind

    v, f = read_mesh(_write(tmp_path, "m.obj", VERTICES + "f 1 2 3 4\nf 2 5 3\n"))
    for bad, shown in ((-1, -1), (6, 6)):
        p = _write(tmp_path, "b.csv", f"marker,vertex\na,0\nb,1\nc,{bad}\n")
        with pytest.raises(InputError, match=f"marker 'c' is bound to vertex {shown}, but m.obj has vertices 0 to 5"):
            bind(v, f, read_binding(p), ["a", "b", "c"], config.settings("deform"), "m.obj", str(p))


def test_binding_with_rigid_markers(tmp_path):
    from facesynth.formats.mesh import read_rigid_markers

    p = tmp_path / "rigid.csv"
    write_binding(p, {"ULI_C": 12, "FH_T": 3, "NOSE_BRIDGE": 7}, rigid={"FH_T", "NOSE_BRIDGE"})
    assert p.read_text().splitlines()[:2] == ["marker,vertex,rigid", "ULI_C,12,0"]
    assert read_binding(p) == {"ULI_C": 12, "FH_T": 3, "NOSE_BRIDGE": 7}  # the extra column is ignored there
    assert read_rigid_markers(p) == ["FH_T", "NOSE_BRIDGE"]
    assert read_rigid_markers(_write(tmp_path, "plain.csv", "marker,vertex\nA,1\n")) == []
    bad = _write(tmp_path, "bad.csv", "marker,vertex,rigid\nA,1,0\nB,2,yes\n")
    with pytest.raises(InputError, match=r"bad.csv, line 3: rigid 'yes' must be 0 or 1"):
        read_rigid_markers(bad)
