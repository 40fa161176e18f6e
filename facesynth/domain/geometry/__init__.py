"""Geometry every subject shares: rotations (matrices, axis-angle, Euler angles) and the rigid
alignment of point sets (Kabsch, the paper's Eq. 1-2 when head motion is removed)."""
