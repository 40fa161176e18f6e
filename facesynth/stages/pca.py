"""``facesynth pca``: PCA of the normalized marker frames (paper III) and Eq. 11.

Each frame's M markers are packed into a 3M vector (x, y, z per marker, marker-major).
The basis is fitted on the training takes' complete frames; every frame then gets
coefficients, frames with unfilled gaps by least squares on their visible coordinates.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..artifacts import open_artifact, read, write_artifact
from ..config import PcaSettings, settings_json
from ..errors import InputError
from ..tables import Takes, copy_tables


@dataclass
class PcaModel:
    """mean : (3M,) mm; basis : (3M, K) orthonormal columns; variances : (K,) mm^2;
    explained : fraction of the total variance covered by the K components."""

    mean: np.ndarray
    basis: np.ndarray
    variances: np.ndarray
    explained: float

    def project(self, frames: np.ndarray) -> np.ndarray:
        """Coefficients (n, K) of frames (n, M, 3) or (n, 3M); NaN coordinates are skipped."""
        x = frames.reshape(len(frames), -1).astype(np.float64) - self.mean
        coeffs = x @ self.basis
        missing = np.isnan(x).any(axis=1)
        for i in np.nonzero(missing)[0]:
            seen = ~np.isnan(x[i])
            coeffs[i] = np.linalg.lstsq(self.basis[seen], x[i, seen], rcond=None)[0]
        return coeffs.astype(np.float32)

    def reconstruct(self, coeffs: np.ndarray) -> np.ndarray:
        """Eq. 11: MrkMotion = MeanMotion + EigMx . PcaCoef. (n, K) -> (n, M, 3) mm."""
        x = self.mean + np.asarray(coeffs, np.float64) @ self.basis.T
        return x.reshape(len(x), -1, 3).astype(np.float32)


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


def read_pca(f) -> PcaModel:
    """The PCA model stored in a ``pca`` (or later) artifact."""
    return PcaModel(read(f, "pca/mean"), read(f, "pca/basis"), read(f, "pca/variances"), float(f["pca"].attrs["explained"]))


def write_pca(g, model: PcaModel) -> None:
    p = g.create_group("pca")
    p.create_dataset("mean", data=model.mean)
    p.create_dataset("basis", data=model.basis)
    p.create_dataset("variances", data=model.variances)
    p.attrs["explained"] = model.explained
    p.attrs["layout"] = "vector index = 3 * marker + axis"


def run(normalized: Path, out: Path, settings: PcaSettings, overwrite: bool = False) -> dict:
    if settings.n_components < 1 and settings.variance_target <= 0:
        raise InputError("pca.n_components must be at least 1 (or set pca.variance_target).")
    with open_artifact(normalized, "normalized") as f:
        markers = read(f, "markers")
        fps = float(f["markers"].attrs["fps"])
        takes = Takes.read(f)
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
        with write_artifact(out, "pca", config=settings_json(settings), inputs=[normalized], overwrite=overwrite) as g:
            copy_tables(f, g)
            write_pca(g, model)
            c = g.create_dataset("coefficients", data=coeffs)
            c.attrs["fps"] = fps
            c.attrs["units"] = "mm"
            for key in ("markers", "reference", "head_rotation", "head_translation"):
                f.copy(f[key], g, name=key)
    recon = model.reconstruct(coeffs[complete])
    rms = float(np.sqrt(np.nanmean(np.sum((recon - markers[complete]) ** 2, axis=2))))
    return {"components": model.basis.shape[1], "explained": model.explained, "frames": len(coeffs), "rms_error_mm": rms}
