import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.database import embedding, isomap_images
from facesynth.stages import isomap


@pytest.fixture(scope="module")
def iso(tiny_db, tmp_path_factory):
    d = tmp_path_factory.mktemp("iso")
    summary = isomap.run(tiny_db, d / "iso.h5", Config.load().settings("isomap"), images=d / "img")
    return d, summary


def test_every_phoneme_cluster_is_embedded_with_images(iso, tiny_db):
    d, summary = iso
    with h5py.File(tiny_db) as f:
        phones = {p.decode() for p in f["nodes/phone"][()]}
    with h5py.File(d / "iso.h5") as f:
        assert set(f["clusters"]) == phones
        for phone in phones:
            h = f["clusters"][phone]
            assert h["isomap"].shape == (len(h["frames"]), 2) and h["pca_map"].shape == h["isomap"].shape
            assert h["relative_time"][()].min() == 0.0 and h["relative_time"][()].max() == 1.0
    index = (d / "img" / "index.html").read_text()
    for phone in phones:
        assert (d / "img" / f"{phone}_isomap.png").exists() and (d / "img" / f"{phone}_pca.png").exists()
        assert f"{phone}_isomap.png" in index
    assert "<title>node " in index  # trajectories name their node on hover


def test_small_clusters_fall_back_and_say_so():
    rng = np.random.default_rng(0)
    emb, k, exact, note = embedding.embed(rng.normal(size=(8, 5)), 12, 2500)
    assert k == 6 and "6 neighbours instead of 12" in note
    emb, k, exact, note = embedding.embed(rng.normal(size=(3, 5)), 12, 2500)
    assert k == 0 and "PCA map" in note and emb.shape == (3, 2)


def test_landmark_isomap_places_every_frame():
    rng = np.random.default_rng(1)
    t = rng.uniform(0, 3 * np.pi, 900)
    x = np.stack([t * np.cos(t), rng.uniform(0, 10, 900), t * np.sin(t)], 1)  # a swiss roll
    emb, k, exact, _ = embedding.embed(x, 12, 300)
    assert exact == 300 and np.isfinite(emb).all()
    # Isomap unrolls the roll: one axis follows the roll's arc length (|corr| with t near 1)
    assert max(abs(np.corrcoef(emb[:, 0], t)[0, 1]), abs(np.corrcoef(emb[:, 1], t)[0, 1])) > 0.9


def test_pick_interpolates_the_covering_triangle(iso, tiny_db):
    d, _ = iso
    with h5py.File(d / "iso.h5") as f:
        phone = max(f["clusters"], key=lambda p: len(f["clusters"][p]["frames"]))
        pts = f["clusters"][phone]["isomap"][()]
        tri = f["clusters"][phone]["isomap_triangles"][()]
    corners = pts[tri[0]]
    centre = corners.mean(0)
    info = isomap.pick(d / "iso.h5", phone, *centre)
    markers, names = info.markers, info.marker_names
    assert sorted(info.corners) == sorted(tri[0].tolist())
    assert np.allclose(info.weights, 1 / 3, atol=1e-5)
    # the picked frame is the mean of the three captured frames (Eq. 11 is affine)
    with h5py.File(d / "iso.h5") as f:
        c = f["clusters"][phone]["coefficients"][()][tri[0]].mean(0)
        from facesynth.model.pca import PcaModel

        expected = PcaModel.read(f).reconstruct(c[None])[0]
    np.testing.assert_allclose(markers, expected, atol=1e-3)
    assert len(names) == markers.shape[0]


def test_pick_outside_and_unknown_phone_are_clear(iso):
    d, _ = iso
    with pytest.raises(InputError, match=r"lies outside the triangulation of its isomap \(x .* to .*\); pick a point inside it"):
        isomap.pick(d / "iso.h5", "ax", 1e6, 1e6)
    with pytest.raises(InputError, match="no phoneme cluster /zh/"):
        isomap.pick(d / "iso.h5", "zh", 0, 0)
    r = CliRunner().invoke(main, ["isomap", "pick", str(d / "iso.h5"), "ax", "1e6", "0"])
    assert r.exit_code == 1 and r.output.startswith("error: /ax/")


def _blend_every_pixel(points, emotion, settings):
    """Eq. 3 blended over the whole image, emotion after emotion (what :func:`isomap_images.render_map`
    must equal, bit for bit)."""
    from scipy.ndimage import gaussian_filter

    size, s = settings.image_size, settings.kernel_sigma_px
    t = isomap_images.map_transform(points, size)
    px = np.stack([t.x0 + t.sx * points[:, 0], t.y0 + t.sy * points[:, 1]], -1)
    image = np.ones((size, size, 3))
    for name, colour in isomap_images.EMOTION_COLOURS.items():
        sel = np.array(emotion) == name
        if not sel.any():
            continue
        grid = np.zeros((size, size))
        ij = np.clip(np.round(px[sel]).astype(int), 0, size - 1)
        np.add.at(grid, (ij[:, 1], ij[:, 0]), 1.0)
        density = np.minimum(1.0, settings.rho * gaussian_filter(grid, s, mode="constant") * (2 * np.pi * s * s))
        image = image * (1 - density[..., None]) + (np.array(colour) / 255.0) * density[..., None]
    return (image * 255).astype(np.uint8)


@pytest.mark.parametrize("seed", [0, 1])
def test_the_map_image_blends_only_where_the_kernels_reach_and_is_the_whole_image_blend(seed):
    rng = np.random.default_rng(seed)
    settings = Config.load().settings("isomap")
    # clustered points of four emotions (one emotion's cluster small, so its box is too), some
    # on the plot's edges and repeated frames on one pixel
    points = np.concatenate([rng.normal(0, 1, (300, 2)), rng.normal(3, 0.2, (40, 2)), [[-4, -4], [6, 5], [6, 5]]])
    emotion = list(rng.choice(["neutral", "angry", "happy"], 300)) + ["sad"] * 40 + ["angry"] * 3
    image, _ = isomap_images.render_map(points, emotion, settings)
    np.testing.assert_array_equal(image, _blend_every_pixel(points, emotion, settings))
    assert (image != 255).any(axis=2).mean() > 0.05  # the kernels drew something
