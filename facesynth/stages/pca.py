"""``facesynth pca``: PCA of the normalized marker frames (paper III) and Eq. 11.

Each frame's M markers are packed into a 3M vector (x, y, z per marker, marker-major).
The basis is fitted on the training takes' complete frames; every frame then gets
coefficients, frames with unfilled gaps by least squares on their visible coordinates.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import PcaSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.model.frames import NormalizedFrames
from facesynth.model.pca import PcaFrames, PcaModel


def fit_pca(frames: np.ndarray, *, n_components: int, variance_target: float = 0.0) -> PcaModel:
    """Fit PCA to complete frames (n, M, 3). ``variance_target`` > 0 picks the fewest
    components reaching that fraction of the variance instead of ``n_components``."""
    x = frames.reshape(len(frames), -1).astype(np.float64)
    mean = x.mean(axis=0)
    _, s, vt = np.linalg.svd(x - mean, full_matrices=False)
    variances = s**2 / max(len(x) - 1, 1)
    ratio = np.cumsum(variances) / variances.sum()
    k = int(np.searchsorted(ratio, variance_target) + 1) if variance_target > 0 else n_components
    k = min(k, len(variances))
    basis = vt[:k].T
    # Fix each component's sign (largest |loading| positive) so refits give identical artifacts.
    signs = np.sign(basis[np.abs(basis).argmax(axis=0), np.arange(k)])
    basis = basis * signs
    return PcaModel(mean, basis, variances[:k], float(ratio[k - 1]))


@dataclass(frozen=True)
class PcaResult:
    """What ``facesynth pca`` fitted.

    components: principal components kept.
    explained: the share of the training frames' variance they cover, 0 to 1.
    frames: frames projected.
    rms_error_mm: reconstruction RMS per marker on the complete training frames (mm).
    """

    components: int
    explained: float
    frames: int
    rms_error_mm: float


def run(normalized: Path, out: Path, settings: PcaSettings, overwrite: bool = False) -> PcaResult:
    """Fit the PCA to ``normalized`` and write ``out`` (a ``pca`` artifact)."""
    frames = NormalizedFrames.read(normalized)
    markers, takes = frames.frames.loaded_markers(), frames.takes
    train = np.zeros(len(markers), bool)
    for i in range(len(takes)):
        if takes.split[i] == "train":
            train[takes.frames(i)] = True
    complete = train & ~np.isnan(markers).any(axis=(1, 2))
    if complete.sum() < 2:
        raise InputError(f"{normalized}: fewer than two complete training frames; check the manifest's split column.")
    if settings.variance_target <= 0 and settings.n_components > min(complete.sum(), markers.shape[1] * 3):
        raise InputError(f"pca.n_components={settings.n_components} exceeds what {complete.sum()} frames of {markers.shape[1]} markers allow.")
    model = fit_pca(markers[complete], n_components=settings.n_components, variance_target=settings.variance_target)
    coeffs = model.project(markers)
    PcaFrames(takes, frames.phones, frames.marker_names, model, coeffs, frames.frames).write(
        out, config=settings_json(settings), inputs=[normalized], overwrite=overwrite)
    recon = model.reconstruct(coeffs[complete])
    rms = float(np.sqrt(np.nanmean(np.sum((recon - markers[complete]) ** 2, axis=2))))
    return PcaResult(model.basis.shape[1], model.explained, len(coeffs), rms)

