"""How the virtual actress's jaw and lips move, beside real speakers': articulation statistics.
Prints JSON.

    python benchmarks/articulation_statistics.py --facegood FACEGOOD_DIR [--phones WORK] \
        [--capture LLF.csv] [--before benchmarks/data/actress_uncalibrated.toml]

Sources, each summarised by :func:`facesynth.corpus.statistics.articulation_statistics`:

- ``actress_before`` / ``actress_after``: the sample corpus (``small`` preset, seed 0) generated
  with the settings in ``--before`` (the articulation before calibration, a ``--config`` file
  for ``facesynth sample-corpus``) and with the default settings. Mouth opening = the inner-lip
  gap (mm) between the ``evaluate.lip_markers`` vertices on the rig, from the truth's rig
  weights; jaw = the truth's ARKit ``jawOpen``; audio = the take's WAV; phones = its TextGrid.
- ``facegood_calibration`` / ``facegood_scored``: FACEGOOD's real takes (see
  ``benchmarks/real_speech_lipsync.py`` for the folder and the curves): the calibration takes
  (:data:`CALIBRATION_TAKES`, the only real takes the actress's settings were chosen on) and the
  takes ``real_speech_lipsync.py`` is scored on after calibration (:data:`SCORED_TAKES`), kept
  apart. Mouth opening = ``mouth_stretch_c + mouth_oh_c``, jaw = ``mouth_stretch_c`` (weights);
  phones = the ones that benchmark recognises (``facesynth align`` without text), read from
  its ``--work`` folder (``--phones``) or made again.
- ``live_link_face``: the iPhone Live Link Face capture of ``ict-face`` (5.5 s at 60 frames/s,
  no audio, no phones; calibration only): mouth opening = the inner-lip gap of its ARKit
  weights on the built-in rig (mm), jaw = ``JawOpen``.

Common scale: every curve is resampled to 30 frames/s and every mouth-opening and jaw curve is
divided by its own source's 5th..95th percentile range (over all the source's frames), so
velocities are in ranges per second, accelerations in ranges per second squared, and per-class
openings in fractions of the range, whether the source is in millimetres or weights. The raw
ranges are reported in the source's unit. The audio envelope is the log-RMS envelope of
``real_speech_lipsync.energy_envelope`` (0.1 s moving average).
"""

from __future__ import annotations

import argparse
import csv
import importlib.util
import json
import tempfile
import time
from pathlib import Path

import numpy as np

from facesynth.config import Config
from facesynth.corpus.generate import generate
from facesynth.corpus.statistics import ARTICULATION_FPS, articulation_statistics, read_live_link_face, resample
from facesynth.corpus.truth import read_truth
from facesynth.facerig import load_face_rig
from facesynth.formats.audio import read_audio
from facesynth.formats.labels import read_phone_segments

HERE = Path(__file__).resolve().parent
_SPEC = importlib.util.spec_from_file_location("real_speech_lipsync", HERE / "real_speech_lipsync.py")
lipsync = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(lipsync)

#: FACEGOOD takes the actress's articulation settings were calibrated on.
CALIBRATION_TAKES = ("1114_2_01", "1114_2_02", "1114_2_03")
#: FACEGOOD takes kept out of calibration: the real-speech benchmark's scored takes.
SCORED_TAKES = ("1114_2_04", "1114_2_05", "1114_3_15", "1114_3_16")
ASSETS = HERE.parents[1] / "shared" / "assets"
ENVELOPE_SMOOTH_S = 0.1


def _phones(segments) -> list[tuple[float, float, str]]:
    return [(s.start, s.end, s.label) for s in segments]


def actress_source(corpus: Path, lip_markers: list[str]) -> dict:
    """The sample corpus in ``corpus``: its takes' curves at 30 frames/s, audio envelopes, phones."""
    from facesynth.formats.mesh import read_binding

    rig = load_face_rig()
    binding = read_binding(corpus / "markers.csv")
    lips = np.array([binding[m] for m in lip_markers])
    jaw = list(rig.arkit_names).index("jawOpen")
    openings, jaws, envelopes, phones = [], [], [], []
    for row in csv.DictReader(open(corpus / "manifest.csv", newline="", encoding="utf-8")):
        truth = read_truth(corpus / "groundtruth" / f"{row['take']}_truth.csv")
        fps = 1.0 / float(truth.time_s[1] - truth.time_s[0])
        points = rig.evaluate(truth.rig_weights, vertices=lips)                       # (T, 2, 3) mm
        gap = np.linalg.norm(points[:, 0] - points[:, 1], axis=1)
        curves = resample(np.stack([gap, truth.arkit_weights[:, jaw]], 1), fps, ARTICULATION_FPS)
        samples, rate = read_audio(corpus / row["audio"])
        openings.append(curves[:, 0])
        jaws.append(curves[:, 1])
        envelopes.append(lipsync.energy_envelope(samples, rate, len(curves), ARTICULATION_FPS, ENVELOPE_SMOOTH_S))
        phones.append(_phones(read_phone_segments(corpus / row["alignment"])))
    return {"openings": openings, "jaw": jaws, "envelopes": envelopes, "phones": phones,
            "unit": "mm (inner-lip gap)", "takes": len(openings)}


def facegood_source(folder: Path, takes: tuple[str, ...], phones_work: Path | None, work: Path) -> dict:
    """FACEGOOD takes: mouth opening and jaw (weights) at 30 frames/s, envelopes, recognised phones."""
    names = [str(s) for s in lipsync.load_npy(folder / "shirley_1015_bs_name.npy")]
    table = lipsync.read_table()
    settings = Config.load().settings("align")
    openings, jaws, envelopes, phones = [], [], [], []
    for take in takes:
        values = np.asarray(lipsync.load_npy(folder / "bs_value_npy" / f"bs_value_{take}.npy"), np.float64)
        samples, rate = read_audio(folder / "wav" / f"{take}.wav")
        n = min(len(values), int(np.floor(len(samples) / rate * ARTICULATION_FPS)))
        real = lipsync.real_curves(values[:n], names, table)
        cached = phones_work / "takes" / take / "phones.TextGrid" if phones_work else None
        if cached is not None and cached.exists():
            segs = read_phone_segments(cached)
        else:
            segs, _ = lipsync.phones_from_audio(folder / "wav" / f"{take}.wav", work / f"{take}.TextGrid", settings)
        openings.append(real["opening"])
        jaws.append(real["jawOpen"])
        envelopes.append(lipsync.energy_envelope(samples, rate, n, ARTICULATION_FPS, ENVELOPE_SMOOTH_S))
        phones.append(_phones(segs))
    return {"openings": openings, "jaw": jaws, "envelopes": envelopes, "phones": phones,
            "unit": "weight (mouth_stretch_c + mouth_oh_c)", "takes": len(takes), "take_names": list(takes)}


def live_link_face_source(capture: Path, lip_markers: list[str], corpus: Path) -> dict:
    """The Live Link Face capture: the inner-lip gap of its weights on the built-in rig and JawOpen."""
    from facesynth.formats.mesh import read_binding

    rig = load_face_rig()
    names, weights = read_live_link_face(capture)
    arkit = np.zeros((len(weights), len(rig.arkit_names)))
    for k, name in enumerate(names):
        if name in rig.arkit_names:
            arkit[:, list(rig.arkit_names).index(name)] = weights[:, k]
    binding = read_binding(corpus / "markers.csv")
    points = rig.evaluate(rig.from_arkit(arkit), vertices=np.array([binding[m] for m in lip_markers]))
    gap = np.linalg.norm(points[:, 0] - points[:, 1], axis=1)
    curves = resample(np.stack([gap, arkit[:, list(rig.arkit_names).index("jawOpen")]], 1), 60.0, ARTICULATION_FPS)
    return {"openings": [curves[:, 0]], "jaw": [curves[:, 1]], "envelopes": None, "phones": None,
            "unit": "mm (inner-lip gap on the built-in rig)", "takes": 1}


def summarise(source: dict) -> dict:
    """:func:`articulation_statistics` of a source, with its unit and take count."""
    stats = articulation_statistics(source["openings"], source["jaw"], ARTICULATION_FPS,
                                    source["envelopes"], source["phones"])
    return {"unit": source["unit"], "takes": source["takes"], **stats}


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--facegood", type=Path, default=ASSETS / "real-speech" / "facegood",
                    help="the FACEGOOD folder (layout in benchmarks/real_speech_lipsync.py)")
    ap.add_argument("--phones", type=Path, default=None,
                    help="a real_speech_lipsync.py --work folder whose takes/<take>/phones.TextGrid to reuse")
    ap.add_argument("--capture", type=Path, default=ASSETS / "ict-face" / "llf_capture.csv",
                    help="a Live Link Face CSV")
    ap.add_argument("--before", type=Path, default=HERE / "data" / "actress_uncalibrated.toml",
                    help="settings file of the actress before calibration")
    ap.add_argument("--preset", default="small")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    started = time.perf_counter()
    lip_markers = list(Config.load().settings("evaluate").lip_markers)
    result: dict = {"settings": {"fps": ARTICULATION_FPS, "normalisation": "5th..95th percentile range per source",
                                 "preset": args.preset, "seed": args.seed, "envelope_smooth_s": ENVELOPE_SMOOTH_S,
                                 "calibration_takes": list(CALIBRATION_TAKES), "scored_takes": list(SCORED_TAKES)}}
    with tempfile.TemporaryDirectory() as tmp:
        corpora = {}
        for name, config in (("actress_before", args.before), ("actress_after", None)):
            corpora[name] = Path(tmp) / name
            generate(corpora[name], args.preset, args.seed, settings=Config.load(config).settings("sample_corpus"))
            result[name] = summarise(actress_source(corpora[name], lip_markers))
        if (args.facegood / "shirley_1015_bs_name.npy").exists():
            for name, takes in (("facegood_calibration", CALIBRATION_TAKES), ("facegood_scored", SCORED_TAKES)):
                result[name] = summarise(facegood_source(args.facegood, takes, args.phones, Path(tmp)))
        if args.capture.exists():
            result["live_link_face"] = summarise(live_link_face_source(args.capture, lip_markers,
                                                                       corpora["actress_after"]))
    result["seconds"] = round(time.perf_counter() - started, 1)
    return result


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
