"""The voice's loudness in the lips (``synthesize.loudness_weight``) on the virtual actress, where
the truth is known. Prints JSON.

Her held-out sentences (``--split``, default ``test``) are synthesized twice by the DP from her
database, from their phones alone and with their audio too (the default weight), and each
synthesized inner-lip gap (``synthesize.loudness_lip_markers``, capture rate) is compared with
her clean truth's (Pearson r and RMS, mm), and every marker with the clean truth's (RMS over
markers and frames, mm: what moving the jaw does to the rest of the face), per sentence, the mean over sentences with a
bootstrap 95% interval, and the paired difference (with audio minus phones alone) on the same
resamples. Her audio is made by the sample corpus from her own articulation, so this says what
the loudness does on a voice that is not a real speaker's; ``real_speech_lipsync.py`` is the
figure on real speech.

    python benchmarks/loudness_on_actress.py --work WORK

``--work`` is a folder with the actress's ``corpus/`` (sample-corpus), ``corpus.h5`` and
``db.h5`` (``real_speech_lipsync.py --work`` builds them: ``small`` preset, seed 0).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain import methods
from facesynth.domain.evaluation.bootstrap import interval, paired_difference, resamples
from facesynth.domain.evaluation.held_out import TruthFolder, heldout
from facesynth.domain.methods import MethodSettings, steps
from facesynth.domain.speech.loudness import lip_gaps
from facesynth.formats.audio import read_audio
from facesynth.model.motiondb import MotionDatabase


def mean_of(values: np.ndarray):
    return lambda idx: float(np.mean(values[idx]))


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", type=Path, required=True)
    ap.add_argument("--split", default="test")
    ap.add_argument("--resamples", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    started = time.perf_counter()
    config = Config.load()
    settings = MethodSettings.of(config)
    lips = settings.synthesize.loudness_lip_markers
    db = MotionDatabase.read(args.work / "db.h5")
    truth = TruthFolder.open(args.work / "corpus", db.marker_names, config.settings("normalize"))
    sentences = heldout(args.work / "corpus.h5", db, args.split, config.settings("normalize"), truth)
    member = methods.get("dp")
    source, prepared = member.read(args.work / "db.h5"), None
    prepared = member.prepare(source, settings)
    rows = {name: {"r": [], "rms_mm": [], "face_rms_mm": []} for name in ("phones", "audio")}
    for s in sentences:
        audio = read_audio(args.work / "corpus" / "audio" / f"{s.take}.wav")
        true_gap = lip_gaps(s.clean, db.marker_names, lips).astype(np.float64)
        for name, given in (("phones", None), ("audio", audio)):
            motion = steps.synthesize(member, source, s.utterance, settings, prepared=prepared, audio=given).motion
            gap = lip_gaps(motion.markers_capture, motion.marker_names, lips).astype(np.float64)
            n = min(len(gap), len(true_gap))
            rows[name]["r"].append(float(np.corrcoef(gap[:n], true_gap[:n])[0, 1]))
            rows[name]["rms_mm"].append(float(np.sqrt(np.mean((gap[:n] - true_gap[:n]) ** 2))))
            error = motion.markers_capture[:n].astype(np.float64) - s.clean[:n]
            rows[name]["face_rms_mm"].append(float(np.sqrt(np.nanmean(np.sum(error ** 2, axis=-1)))))
    index = resamples(len(sentences), args.resamples, args.seed)
    out: dict = {"sentences": len(sentences), "split": args.split, "lip_markers": list(lips),
                 "loudness_weight": settings.synthesize.loudness_weight}
    for figure in ("r", "rms_mm", "face_rms_mm"):
        a, b = np.array(rows["audio"][figure]), np.array(rows["phones"][figure])
        out[figure] = {"phones_alone": interval(mean_of(b), len(b), index),
                       "with_audio": interval(mean_of(a), len(a), index),
                       "with_audio_minus_phones_alone": paired_difference(mean_of(a), mean_of(b), len(a), index)}
    out["per_sentence"] = {s.take: {k: {f: round(v[f][i], 3) for f in v} for k, v in rows.items()}
                           for i, s in enumerate(sentences)}
    out["seconds"] = round(time.perf_counter() - started, 1)
    return out


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
