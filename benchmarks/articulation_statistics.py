"""How the virtual actress's jaw and lips move, beside real speakers': articulation statistics.
Prints JSON.

    python benchmarks/articulation_statistics.py --facegood FACEGOOD_DIR [--phones WORK] \
        [--capture LLF.csv] [--before benchmarks/data/actress_uncalibrated.toml] [--calibrate]

Sources, each summarised by :func:`facesynth.domain.corpus.statistics.articulation_statistics`:

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
``facesynth.domain.speech.loudness.envelope`` (0.1 s moving average). Speed, events and the span are
taken over speech (pauses of 0.25 s or more left out) where the phones are known.

``--calibrate`` also searches the grid :data:`GRID` of the actress's ``[sample_corpus]``
settings (the pause settings as in the defaults) for the point whose statistics come closest
to the calibration takes' (:func:`calibration_distance`, on :data:`CALIBRATION_STATISTICS`
and the audio lag), on 24 performances of the actress (:func:`quick_actress`), and reports
every point's distance, best first. The defaults of ``[sample_corpus]`` are its best point.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import importlib.util
import json
import tempfile
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.corpus.generate import generate
from facesynth.domain.corpus.statistics import ARTICULATION_FPS, articulation_statistics, read_live_link_face, resample
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.speech.loudness import envelope
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
#: The settings searched by ``--calibrate`` (every combination). The jaw stops at 12 Hz (90% of a
#: step in 62 ms, the fast end of jaw gestures in speech): past it the distance keeps falling
#: slowly (0.023 at 16 Hz, 0.015 at 24 Hz) as the jaw comes to follow its step targets at once,
#: which fits the solve's frame-to-frame motion rather than an articulator.
GRID = {"jaw_stiffness_hz": (4.5, 6.0, 8.0, 10.0, 12.0), "lip_stiffness_scale": (1.0, 1.5, 2.0),
        "target_lead_s": (0.015, 0.03)}
#: The statistics ``--calibrate`` matches (paths into :func:`summarise`'s result).
CALIBRATION_STATISTICS = (("opening", "velocity", "p95"), ("opening", "acceleration", "p50"),
                          ("opening", "acceleration", "p95"), ("jaw", "velocity", "p95"),
                          ("jaw", "acceleration", "p50"), ("jaw", "acceleration", "p95"),
                          ("events", "openings_per_s"), ("coarticulation_span_s",))
#: The audio lag difference (s) that counts as much as a factor e in one statistic.
LAG_SCALE_S = 0.02


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
        envelopes.append(envelope(samples, rate, len(curves), ARTICULATION_FPS, ENVELOPE_SMOOTH_S))
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
        envelopes.append(envelope(samples, rate, n, ARTICULATION_FPS, ENVELOPE_SMOOTH_S))
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
    return {"unit": source["unit"], "takes": source["takes"], **dataclasses.asdict(stats)}


def _get(stats: dict, path: tuple[str, ...]) -> float:
    for key in path:
        stats = stats[key]
    return float(stats)  # type: ignore[arg-type]


def calibration_distance(actress: dict, real: dict) -> float:
    """How far the actress's statistics are from the real ones: the mean over
    :data:`CALIBRATION_STATISTICS` of the squared log ratio, plus the squared audio-lag
    difference in units of :data:`LAG_SCALE_S` over their count."""
    logs = [np.log(_get(actress, p) / _get(real, p)) ** 2 for p in CALIBRATION_STATISTICS]
    lag = (actress["audio_lag"]["lag_s"] - real["audio_lag"]["lag_s"]) / LAG_SCALE_S
    return float(np.mean(logs) + lag**2 / len(logs))


def quick_actress(settings, lip_markers: list[str], takes: int = 24, seed: int = 5) -> dict:
    """The actress's statistics from ``takes`` performances (sentences of the ``small`` preset's
    length, the four emotions in turn) with ``settings``, without writing a corpus."""
    from facesynth.domain.corpus.actress_mouth import ContactSolver
    from facesynth.domain.corpus.generate import CAPTURE_FPS, PRESETS, perform
    from facesynth.domain.corpus.nonspeech import EMOTIONS
    from facesynth.domain.corpus.speech import STYLES, design_sentences, synthesize_audio
    from facesynth.domain.rig.markers import build_marker_set

    rig = load_face_rig()
    markers = build_marker_set(rig)
    solver = ContactSolver(rig, markers.lip_pairs)
    lips = np.array([markers.vertices[list(markers.names).index(m)] for m in lip_markers])
    jaw = list(rig.arkit_names).index("jawOpen")
    preset = PRESETS["small"]
    sentences = design_sentences(takes, np.random.default_rng(seed), preset.min_phones, preset.max_phones)
    source: dict = {"openings": [], "jaw": [], "envelopes": [], "phones": [], "unit": "mm (inner-lip gap)", "takes": takes}
    for k, words in enumerate(sentences):
        emotion = EMOTIONS[k % len(EMOTIONS)]
        rng = np.random.default_rng([seed, k])
        perf = perform(words, emotion, rng, rig, solver, preset.pause_prob, CAPTURE_FPS, settings=settings)
        points = rig.evaluate(perf.weights, vertices=lips)
        gap = np.linalg.norm(points[:, 0] - points[:, 1], axis=1)
        curves = resample(np.stack([gap, rig.to_arkit(perf.weights)[:, jaw]], 1), CAPTURE_FPS, ARTICULATION_FPS)
        audio = synthesize_audio(perf.utterance, perf.f0, CAPTURE_FPS, STYLES[emotion], 16000, rng)
        utt = perf.utterance
        source["openings"].append(curves[:, 0])
        source["jaw"].append(curves[:, 1])
        source["envelopes"].append(envelope(audio, 16000, len(curves), ARTICULATION_FPS,
                                                           ENVELOPE_SMOOTH_S))
        source["phones"].append(list(zip(utt.starts.tolist(), utt.ends.tolist(), utt.phones)))
    return summarise(source)


def calibrate(real: dict, lip_markers: list[str]) -> list[dict]:
    """Every point of :data:`GRID` (the other settings as in the defaults) with its
    :func:`calibration_distance` to the real statistics ``real``, best first."""
    import itertools

    base = Config.load().settings("sample_corpus")
    rows = []
    for values in itertools.product(*GRID.values()):
        point = dict(zip(GRID, values))
        stats = quick_actress(dataclasses.replace(base, **point), lip_markers)
        rows.append({**point, "distance": round(calibration_distance(stats, real), 4)})
    return sorted(rows, key=lambda r: r["distance"])


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
    ap.add_argument("--calibrate", action="store_true", help="also search GRID against the calibration takes")
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
    if args.calibrate and "facegood_calibration" in result:
        result["calibration"] = calibrate(result["facegood_calibration"], lip_markers)
    result["seconds"] = round(time.perf_counter() - started, 1)
    return result


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
