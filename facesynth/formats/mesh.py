"""Triangle meshes (OBJ, PLY through ``trimesh``) and marker-to-vertex bindings (CSV)."""

from __future__ import annotations

import csv
import io
from pathlib import Path

import numpy as np

from facesynth.base import limits
from facesynth.base.errors import InputError


def read_mesh(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """Read a triangle mesh, keeping the file's vertex order.

    Returns vertices (V, 3) float64 in the file's units and faces (F, 3) int64
    (polygons are triangulated by trimesh).
    """
    import trimesh

    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: mesh file not found; check the --mesh path.")
    if path.suffix.lower() not in (".obj", ".ply"):
        raise InputError(f"{path}: unsupported mesh format {path.suffix!r}; use .obj or .ply.")
    source = io.StringIO(_obj_vertices_and_faces(path)) if path.suffix.lower() == ".obj" else str(path)
    try:
        mesh = trimesh.load(source, file_type=path.suffix.lower()[1:], process=False, force="mesh", maintain_order=True)
    except Exception as exc:  # trimesh raises many types for malformed files
        raise InputError(f"{path}: unreadable mesh ({type(exc).__name__}: {exc}); re-export it.") from None
    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    faces = np.asarray(mesh.faces, dtype=np.int64)
    if len(vertices) == 0 or len(faces) == 0:
        raise InputError(f"{path}: the mesh has no triangles.")
    limits.bound(len(vertices), "max_vertices", "the number of vertices", str(path))
    bad = ~np.isfinite(vertices).all(axis=1)
    if bad.any():
        raise InputError(f"{path}: vertex {int(np.argmax(bad))} has a coordinate that is NaN or infinite; fix the mesh.")
    outside = (faces < 0) | (faces >= len(vertices))
    if outside.any():
        k = int(np.argmax(outside.any(axis=1)))
        raise InputError(f"{path}: triangle {k} names vertex {int(faces[k][outside[k]][0])}, but the mesh has vertices "
                         f"0 to {len(vertices) - 1}; fix the mesh.")
    return vertices, faces


def _obj_vertices_and_faces(path: Path) -> str:
    """The OBJ's ``v`` and ``f`` lines only, each face corner reduced to its absolute 1-based
    vertex index, for trimesh. Given the whole file, trimesh splits it by material (repeating
    the vertices per material), drops the vertices after the last one a face uses when faces
    carry ``vt``/``vn`` references, and counts relative (negative) indices from the end of
    the file instead of from the face; bindings index the file's own vertex list."""
    lines: list[str] = []
    count, highest, highest_line = 0, 0, 0
    with open(path, encoding="utf-8", errors="replace") as fh:
        for number, line in enumerate(fh, 1):
            fields = line.split()
            if not fields or fields[0] not in ("v", "f"):
                continue
            if fields[0] == "v":
                count += 1
                lines.append(line.strip())
                continue
            corners = []
            for corner in fields[1:]:
                try:
                    index = int(corner.split("/")[0])
                except ValueError:
                    raise InputError(f"{path}, line {number}: face corner {corner!r} is not a vertex index; re-export the mesh.") from None
                absolute = index if index > 0 else count + 1 + index  # relative: counted back from this face
                if absolute < 1 or index == 0:
                    raise InputError(f"{path}, line {number}: vertex index {index} refers to no vertex "
                                     f"({count} read so far; OBJ indices start at 1); re-export the mesh.")
                if absolute > highest:
                    highest, highest_line = absolute, number
                corners.append(str(absolute))
            lines.append("f " + " ".join(corners))
    if highest > count:
        raise InputError(f"{path}, line {highest_line}: vertex index {highest} but the file has {count} vertices; re-export the mesh.")
    return "\n".join(lines) + "\n"


def write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray, comment: str = "") -> None:
    """Write a triangle mesh as OBJ (1-based indices)."""
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        if comment:
            fh.write(f"# {comment}\n")
        np.savetxt(fh, vertices, fmt="v %.5f %.5f %.5f")
        np.savetxt(fh, np.asarray(faces) + 1, fmt="f %d %d %d")


def read_binding(path: Path) -> dict[str, int]:
    """Marker-to-vertex binding: a CSV with columns ``marker,vertex`` (0-based vertex index);
    other columns (the sample corpus writes ``rigid``) are ignored here."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: binding file not found; check the --binding path.")
    binding: dict[str, int] = {}
    first_line: dict[str, int] = {}
    # utf-8-sig: spreadsheets save CSV with a byte-order mark, which would hide the 'marker' column
    with open(path, encoding="utf-8-sig", newline="") as fh:
        try:
            reader = csv.DictReader(fh)
            if not reader.fieldnames or {"marker", "vertex"} - set(reader.fieldnames):
                raise InputError(f"{path}: the binding CSV needs the columns 'marker' and 'vertex'.")
            for row in reader:
                line = reader.line_num  # the file's line: blank lines are skipped, not counted as rows
                try:
                    name, vertex = (row["marker"] or "").strip(), int(row["vertex"])
                except (TypeError, ValueError):
                    raise InputError(f"{path}, line {line}: vertex {row['vertex']!r} is not an integer index.") from None
                if name in first_line:
                    raise InputError(f"{path}, line {line}: marker {name!r} is bound again (first on line "
                                     f"{first_line[name]}); bind each marker once.")
                binding[name], first_line[name] = vertex, line
        except UnicodeDecodeError as exc:
            raise InputError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start}); save the binding as UTF-8 CSV.") from None
    return binding


def write_binding(path: Path, binding: dict[str, int], rigid: set[str] | None = None,
                  residual_mm: dict[str, float] | None = None, flagged: set[str] | None = None) -> None:
    """Write a ``marker,vertex`` CSV binding (vertex: 0-based index into the mesh's vertices).
    With ``rigid``, a third column ``rigid`` marks (1) the markers that move only with the
    head, the set a normalizer fits the head pose on (:func:`read_rigid_markers`). With
    ``residual_mm`` and ``flagged`` (what ``facesynth bind`` knows), the columns ``residual_mm``
    (each marker's distance to its vertex after the fit) and ``flagged`` (1: farther than the
    setting; check it); readers ignore them."""
    with open(path, "w", encoding="utf-8", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["marker", "vertex"] + (["rigid"] if rigid is not None else [])
                        + (["residual_mm", "flagged"] if residual_mm is not None else []))
        for name, vertex in binding.items():
            writer.writerow([name, vertex] + ([int(name in rigid)] if rigid is not None else [])
                            + ([f"{residual_mm[name]:.2f}", int(name in (flagged or set()))]
                               if residual_mm is not None else []))


def read_rigid_markers(path: Path) -> list[str]:
    """The markers a binding CSV marks ``rigid`` = 1, in the file's order; [] without that column."""
    binding = read_binding(path)  # checks the file and its marker/vertex columns
    with open(path, encoding="utf-8-sig", newline="") as fh:
        reader = csv.DictReader(fh)
        if "rigid" not in (reader.fieldnames or []):
            return []
        out = []
        for row in reader:
            flag = (row.get("rigid") or "").strip()
            if flag not in ("0", "1", ""):
                raise InputError(f"{path}, line {reader.line_num}: rigid {flag!r} must be 0 or 1.")
            if flag == "1":
                out.append((row["marker"] or "").strip())
    return [name for name in out if name in binding]
