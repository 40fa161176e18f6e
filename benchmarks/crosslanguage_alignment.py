"""Cross-language forced alignment measured against hand-corrected phone boundaries of real
speech in languages the English acoustic model never heard. Prints JSON.

The reference is VoxAngeles (Chodroff, Pažon, Baker & Moran, LREC-COLING 2024: audited
phone-level alignments of the UCLA Phonetics Lab Archive's word lists, CC BY-NC 4.0,
https://github.com/pacscilab/voxangeles, ``data/audited_aligned/<lang>.zip``). The data is not
part of facesynth: give the folder holding the zips; each zip's SHA-256 is checked against the
one this benchmark was run on.

For every recorded word, its reference IPA phones are the pronunciation (as a user's ``--dict``
would give it: this measures the alignment, not a grapheme-to-phoneme backend), each played by
its articulatory nearest English phone (``facesynth.base.ipa.nearest_festival``) and
force-aligned by ``align_pronounced`` (the path of ``--language`` text once its words are
pronounced) with the default ``[align]`` settings, against two baselines on the same words: ``duration`` (the phones laid
over the voiced span by typical English durations: ``align.methods = ["duration"]``) and
``uniform`` (the word's reference span cut into equal parts: an oracle of the word's edges). The
error of a word is the mean absolute difference of its phone boundaries (every phone's start,
and the last one's end) from the reference's, in ms; reported per language: the median and mean
over words with a 95% bootstrap interval of the mean (2000 resamples of words, seed 0), the
share of boundaries within 20 ms, and the words whose alignment did not give one phone per
reference phone (left out).

    python benchmarks/crosslanguage_alignment.py --data VOXANGELES/data/audited_aligned [--languages ces ell eus]
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import json
import sys
import tempfile
import zipfile
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.base.ipa import nearest_festival
from facesynth.base.phonemes import PAU
from facesynth.domain.speech.alignment import AlignmentFailed, align_pronounced
from facesynth.domain.speech.languages import Word
from facesynth.formats.audio import read_audio
from facesynth.formats.labels import read_textgrid

#: The zips this benchmark was run on (VoxAngeles at commit c595ea8).
SHA256 = {
    "ces": "e0db2d769e94bfef31d971eb7e6d84cec2bf2f168ca91338ea90d5a1fb545b1c",  # Czech
    "ell": "2079b9852365c68add4f3830b272117d830b7b6844acaf3a92d086a709c5987f",  # Greek
    "eus": "5969e1e318f09c9f8c8cade4224faad5db8bab350faa00aa8be5e225bea2f498",  # Basque
}


def _boundaries(segments) -> np.ndarray:
    return np.array([s.start for s in segments] + [segments[-1].end])


def _uniform(start: float, end: float, n: int) -> np.ndarray:
    return np.linspace(start, end, n + 1)


def _bootstrap_mean(values: np.ndarray, seed: int = 0, n: int = 2000) -> list[float]:
    rng = np.random.default_rng(seed)
    means = values[rng.integers(0, len(values), (n, len(values)))].mean(axis=1)
    return [round(float(np.percentile(means, 2.5)), 1), round(float(np.percentile(means, 97.5)), 1)]


def _summary(errors: list[np.ndarray]) -> dict:
    per_word = np.array([e.mean() for e in errors]) * 1e3
    every = np.concatenate(errors) * 1e3
    return {"words": len(errors), "median_ms": round(float(np.median(per_word)), 1),
            "mean_ms": round(float(per_word.mean()), 1), "mean_ms_ci95": _bootstrap_mean(per_word),
            "within_20ms": round(float((every <= 20).mean()), 3)}


def measure(zip_path: Path, language: str, settings) -> dict:
    duration_settings = dataclasses.replace(settings, methods=("duration",))
    errors: dict[str, list[np.ndarray]] = {"facesynth": [], "duration": [], "uniform": []}
    skipped = {"unreadable": 0, "unknown_phone": 0, "phone_count": 0, "failed": 0}
    methods: dict[str, int] = {}
    with zipfile.ZipFile(zip_path) as archive, tempfile.TemporaryDirectory() as tmp:
        grids = sorted(n for n in archive.namelist()
                       if n.endswith(".TextGrid") and "__MACOSX" not in n and not Path(n).name.startswith("._"))
        for name in grids:
            wav = name[: -len(".TextGrid")] + ".wav"
            if wav not in archive.namelist():
                continue
            grid_path = Path(tmp) / "x.TextGrid"
            grid_path.write_bytes(archive.read(name))
            try:
                tiers = read_textgrid(grid_path)
            except InputError:
                skipped["unreadable"] += 1
                continue
            ref = [s for s in tiers.get("phones", []) if s.label.strip()]
            if not ref:
                continue
            ipa = tuple(s.label.strip() for s in ref)
            try:
                phones = tuple(nearest_festival(p) for p in ipa)
            except KeyError:  # a symbol facesynth.base.ipa does not describe
                skipped["unknown_phone"] += 1
                continue
            samples, rate = _read_wav(archive, wav, tmp)
            word = Word("w", ipa, phones)
            truth = _boundaries(ref)
            for label, s in (("facesynth", settings), ("duration", duration_settings)):
                try:
                    result = align_pronounced(samples, rate, [word], settings=s, where=name)
                except AlignmentFailed:
                    skipped["failed"] += label == "facesynth"
                    break
                hyp = [seg for seg in result.phones if seg.label != PAU]
                if len(hyp) != len(ref):
                    skipped["phone_count"] += label == "facesynth"
                    break
                if label == "facesynth":
                    methods[result.method] = methods.get(result.method, 0) + 1
                errors[label].append(np.abs(_boundaries(hyp) - truth))
            else:
                errors["uniform"].append(np.abs(_uniform(ref[0].start, ref[-1].end, len(ref)) - truth))
                continue
            # a word one method could not align is left out of every method's figures
            for label in ("facesynth", "duration"):
                if len(errors[label]) > len(errors["uniform"]):
                    errors[label].pop()
    return {"words_read": len(grids), "left_out": skipped, "methods_used": methods,
            **{label: _summary(e) for label, e in errors.items() if e}}


def _read_wav(archive: zipfile.ZipFile, name: str, tmp: str):
    path = Path(tmp) / "x.wav"
    path.write_bytes(archive.read(name))
    return read_audio(path)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", type=Path, required=True, help="VoxAngeles' data/audited_aligned folder")
    parser.add_argument("--languages", nargs="+", default=sorted(SHA256))
    args = parser.parse_args()
    settings = Config.load().settings("align")
    out = {"source": "VoxAngeles audited_aligned (CC BY-NC 4.0), https://github.com/pacscilab/voxangeles",
           "languages": {}}
    for language in args.languages:
        path = args.data / f"{language}.zip"
        digest = hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() else "missing"
        if digest != SHA256.get(language):
            sys.exit(f"{path}: SHA-256 {digest} is not the one this benchmark was run on ({SHA256.get(language)}); "
                     "give VoxAngeles' data/audited_aligned folder at commit c595ea8.")
        out["languages"][language] = measure(path, language, settings)
    print(json.dumps(out, indent=2, ensure_ascii=False))


if __name__ == "__main__":
    main()
