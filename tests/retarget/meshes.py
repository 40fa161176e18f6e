"""Small hand-made meshes for the retargeting tests."""

import numpy as np


def grid(n: int) -> tuple[np.ndarray, np.ndarray]:
    """An n x n grid of vertices 1 mm apart in the z = 0 plane ((n^2, 3) float), two triangles
    per cell ((2 (n - 1)^2, 3) int)."""
    xs, ys = np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float))
    rest = np.stack([xs.ravel(), ys.ravel(), np.zeros(n * n)], 1)
    faces = []
    for i in range(n - 1):
        for j in range(n - 1):
            a = i * n + j
            faces += [(a, a + 1, a + n + 1), (a, a + n + 1, a + n)]
    return rest, np.array(faces)
