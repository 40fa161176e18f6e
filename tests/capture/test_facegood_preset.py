"""FACEGOOD's takes shipped with facesynth (issue 41, items 2 and 5): another rig's curves with a
mapping to ARKit, a capture corpus one command away, phones recognised from the audio, and the
usual chain from it to a database and a synthesis."""

from __future__ import annotations

import csv
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
import soundfile as sf
from click.testing import CliRunner

from facesynth.cli import main
from facesynth.domain.capture import facegood
from facesynth.model.corpus import Corpus
from facesynth.model.motion import Motion

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "facesynth" / "data"
#: Recognition by phone loop: the same route as the default (words), several times faster.
FAST = ("--set", "align.recognition=phones")


def _run(*args) -> str:
    result = CliRunner().invoke(main, [*map(str, args)])
    assert result.exit_code == 0, result.output
    return result.output


@pytest.fixture(scope="module")
def corpus_dir(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("facegood") / "corpus"
    out = _run("sample-corpus", folder, "--preset", "facegood")
    assert "presumably Mandarin" in out
    return folder


def test_the_shipped_takes_are_small_and_complete():
    sizes = {name: (DATA / name).stat().st_size for name in (facegood.CURVES_FILE, facegood.AUDIO_FILE,
                                                             facegood.MAPPING_FILE, facegood.LICENSE_FILE)}
    assert sum(sizes.values()) < 2.5e6, sizes
    arrays, audio, rate = facegood.shipped()
    assert list(arrays["takes"]) == ["1114_2_01", "1114_2_02", "1114_2_03", "1114_2_04", "1114_2_05", "1114_3_15",
                                     "1114_3_16"]
    assert arrays["curves"].shape == (19673, 116) and arrays["curves"].dtype == np.float16
    assert rate == 16000 and len(audio) == arrays["samples"].sum()
    assert abs(len(audio) / rate - 655.9) < 0.1
    np.testing.assert_allclose(arrays["samples"] / rate, arrays["frames"] / 30.0, atol=0.05)  # curves span the speech
    assert "MIT License" in (DATA / facegood.LICENSE_FILE).read_text()


def test_the_mapping_is_facegoods_table_plus_one_row():
    """The valid rows of FACEGOOD's own table (benchmarks/data/facegood_arkit.tsv, its xlsx as text),
    max(...) split into equal weights, plus mouth_oh_c -> jawOpen."""
    expected = []
    for r in csv.DictReader(open(ROOT / "benchmarks" / "data" / "facegood_arkit.tsv"), delimiter="\t"):
        if r["status"].strip().lower() == "valid":
            inner = re.fullmatch(r"max\((.*)\)", r["facegood"].replace(" ", ""))
            parts = inner.group(1).split(",") if inner else [r["facegood"].strip()]
            expected += [(p, r["arkit"].lower(), round(1 / len(parts), 6)) for p in parts]
    expected.append(("mouth_oh_c", "jawopen", 1.0))
    lines = [line for line in open(DATA / facegood.MAPPING_FILE) if not line.startswith("#")]
    shipped = [(r["source"], r["arkit"].lower(), round(float(r["weight"]), 6)) for r in csv.DictReader(lines)]
    assert shipped == expected


def test_the_performer_rests_at_the_rigs_neutral():
    """Her quiet frames (the tenth of each take with the least jaw opening) map to no expression:
    every ARKit weight's median there is 0, eyes and brows included (the mapping leaves them out:
    FACEGOOD's takes never move them), so a database of her motion rests at the rig's neutral and
    needs no neutral of her own subtracted."""
    from facesynth.domain.rig.face import load_face_rig
    from facesynth.formats.blendshape_curves import read_mapping

    rig = load_face_rig()
    arrays, _, _ = facegood.shipped()
    mapping = read_mapping(DATA / facegood.MAPPING_FILE, [str(n) for n in arrays["names"]], rig.arkit_names, "FACEGOOD")
    arkit = np.clip(arrays["curves"].astype(np.float64) @ mapping, 0.0, 1.0)
    jaw = rig.arkit_names.index("jawOpen")
    start = 0
    for take, n in zip(arrays["takes"], arrays["frames"]):
        frames = arkit[start:start + n]
        start += n
        quiet = frames[frames[:, jaw] <= np.percentile(frames[:, jaw], 10)]
        assert np.median(quiet, axis=0).max() <= 0.01, take
        assert np.percentile(frames[:, jaw], 90) > 0.2, take  # and she speaks: the jaw opens well


def test_the_shipped_curves_and_speech_are_facegoods(shared_assets):
    source = shared_assets / "real-speech" / "facegood"
    if not source.is_dir():
        pytest.skip("needs ../shared/assets/real-speech/facegood")
    arrays, audio, rate = facegood.shipped()
    with warnings.catch_warnings():  # FACEGOOD's arrays were written by Python 2
        warnings.simplefilter("ignore", UserWarning)
        names = [str(n) for n in np.load(source / "shirley_1015_bs_name.npy")]
    assert list(arrays["names"]) == names
    start = 0
    for take, n, m in zip(arrays["takes"], arrays["frames"], arrays["samples"]):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            real = np.load(source / "bs_value_npy" / f"bs_value_{take}.npy")
        assert real.shape[0] == n
        np.testing.assert_allclose(arrays["curves"][start:start + n].astype(np.float64), real, atol=2.5e-4)
        assert sf.info(str(source / "wav" / f"{take}.wav")).frames == m
        start += n


def test_a_mapping_naming_an_unknown_channel_is_refused_in_one_sentence(corpus_dir, tmp_path):
    mapping = (corpus_dir / "facegood_arkit.csv").read_text().replace("mouth_press_l,", "mouth_pres_l,")
    (tmp_path / "map.csv").write_text(mapping)
    rows = list(csv.DictReader(open(corpus_dir / "manifest.csv")))
    row = rows[-1]
    (tmp_path / "manifest.csv").write_text("take,mocap,names,fps,mapping,audio\n" + ",".join([
        row["take"], str(corpus_dir / row["mocap"]), str(corpus_dir / row["names"]), "30", "map.csv",
        str(corpus_dir / row["audio"])]) + "\n")
    (tmp_path / "out").mkdir()
    result = CliRunner().invoke(main, ["ingest", str(tmp_path / "manifest.csv"), "-o", str(tmp_path / "out" / "c.h5")])
    assert result.exit_code == 1
    errors = [line for line in result.output.splitlines() if line.startswith("error: ")]
    line = 1 + next(k for k, text in enumerate(mapping.splitlines()) if text.startswith("mouth_pres_l,"))
    assert len(errors) == 1 and errors[0].startswith(
        f"error: {tmp_path / 'map.csv'}, line {line}: the source channel 'mouth_pres_l' is not a channel of "
        f"{corpus_dir / row['mocap']}"), result.output
    assert list((tmp_path / "out").iterdir()) == []


def test_two_takes_become_a_database_and_a_synthesis(corpus_dir, tmp_path, tiny_corpus, held_out_take):
    """The usual chain on FACEGOOD's two short takes: phones recognised from the audio, the markers
    of the built-in rig posed with the mapped curves, a database, a synthesis."""
    rows = list(csv.DictReader(open(corpus_dir / "manifest.csv")))
    short = [r for r in rows if r["take"] in ("1114_3_15", "1114_3_16")]
    with open(corpus_dir / "short.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(short)
    out = _run("ingest", corpus_dir / "short.csv", "-o", tmp_path / "corpus.h5", *FAST)
    assert "no alignment or transcript for 2 takes (1114_3_15, 1114_3_16): phones recognised" in out
    corpus = Corpus.read(tmp_path / "corpus.h5", audio=False)
    assert corpus.posed and corpus.fps == 30.0 and len(corpus.marker_names) == 91
    assert (np.bincount(corpus.phones.take) > 100).all()
    # the recorded lip gap follows FACEGOOD's own mouth opening (its two jaw-opening channels)
    names = (corpus_dir / "curves" / "channels.txt").read_text().split()
    upper, lower = corpus.marker_names.index("ULI_C"), corpus.marker_names.index("LLI_C")
    for i, row in enumerate(short):
        curves = np.load(corpus_dir / row["mocap"])
        opening = curves[:, names.index("mouth_stretch_c")] + curves[:, names.index("mouth_oh_c")]
        take = corpus.markers[corpus.takes.frames(i)]
        gap = np.linalg.norm(take[:, upper] - take[:, lower], axis=1)
        assert np.corrcoef(gap, opening)[0, 1] > 0.95
    _run("normalize", tmp_path / "corpus.h5", "-o", tmp_path / "normalized.h5")
    _run("pca", tmp_path / "normalized.h5", "-o", tmp_path / "pca.h5")
    _run("build-db", tmp_path / "pca.h5", "-o", tmp_path / "db.h5")
    _run("synthesize", tmp_path / "db.h5", "--phonemes", tiny_corpus / "labels" / f"{held_out_take}.TextGrid",
         "-o", tmp_path / "motion.h5")
    motion = Motion.read(tmp_path / "motion.h5")
    assert motion.markers.shape[1] == 91 and np.isfinite(motion.markers).all()
