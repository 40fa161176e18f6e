"""Triangle meshes (OBJ, PLY through ``trimesh``) and marker-to-vertex bindings (CSV)."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from ..errors import InputError


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
    try:
        mesh = trimesh.load(str(path), process=False, force="mesh", maintain_order=True)
    except Exception as exc:  # trimesh raises many types for malformed files
        raise InputError(f"{path}: unreadable mesh ({type(exc).__name__}: {exc}); re-export it.") from None
    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    faces = np.asarray(mesh.faces, dtype=np.int64)
    if len(vertices) == 0 or len(faces) == 0:
        raise InputError(f"{path}: the mesh has no triangles.")
    return vertices, faces


def write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray, comment: str = "") -> None:
    """Write a triangle mesh as OBJ (1-based indices)."""
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        if comment:
            fh.write(f"# {comment}\n")
        np.savetxt(fh, vertices, fmt="v %.5f %.5f %.5f")
        np.savetxt(fh, np.asarray(faces) + 1, fmt="f %d %d %d")


def read_binding(path: Path) -> dict[str, int]:
    """Marker-to-vertex binding: a CSV with columns ``marker,vertex`` (0-based vertex index)."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: binding file not found; check the --binding path.")
    binding: dict[str, int] = {}
    with open(path, encoding="utf-8", newline="") as fh:
        reader = csv.DictReader(fh)
        if not reader.fieldnames or {"marker", "vertex"} - set(reader.fieldnames):
            raise InputError(f"{path}: the binding CSV needs the columns 'marker' and 'vertex'.")
        for line, row in enumerate(reader, 2):
            try:
                binding[row["marker"].strip()] = int(row["vertex"])
            except (TypeError, ValueError):
                raise InputError(f"{path}, line {line}: vertex {row['vertex']!r} is not an integer index.") from None
    return binding


def write_binding(path: Path, binding: dict[str, int]) -> None:
    """Write a ``marker,vertex`` CSV binding (vertex: 0-based index into the mesh's vertices)."""
    with open(path, "w", encoding="utf-8", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["marker", "vertex"])
        for name, vertex in binding.items():
            writer.writerow([name, vertex])
