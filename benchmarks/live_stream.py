"""Live synthesis (``facesynth stream``): latency, concurrent real-time streams, and the live output
against the batch output of the same utterance.

    .venv/bin/python benchmarks/live_stream.py --db db.h5 --corpus corpus/ [--trajectory traj.h5] \
        [--takes 8] [--streams 1,4,8,12] [--seconds 8] [--facegood FACEGOOD_DIR] > benchmarks/live_stream.json

``--db`` is a database built from the sample corpus ``--corpus`` (its held-out takes are the
utterances; their clean ground truth scores the mouth); ``--trajectory``, a trajectory model
trained on it (``facesynth train-trajectory``), adds the rows of the trajectory method.

1. ``offline``: each held-out take streamed through a session in 20 ms chunks, for every
   configuration (``method`` dp, greedy or trajectory, ``lookahead`` phones, ``phones``: ``recognize``d live
   from the audio, or ``given`` by a TTS engine as it speaks: each phone's timing sent with the
   chunk where the phone starts, or ``given_ahead``: all of them before the audio, as an engine that
   plans a sentence before speaking it can; the last message says the phones are complete). Time
   is simulated as real time: chunk c arrives at its stream time, its processing starts then (or
   when the previous chunk's ends) and takes the measured wall time; a frame's **latency** is the
   time it is ready minus the arrival of the audio sample it shows (its time; a frame ready before
   its sound counts 0). ``rtf``: processing time over audio time, one stream on one core
   (``rtf_cpu``: its CPU time, less sensitive to a shared machine's load). **Quality** against
   batch synthesis of the same phones (same emotions, the whole-utterance search of the same
   method): RMS marker difference
   (mm), mouth-opening r (inner-lip gap ``ULI_C``-``LLI_C``) between live and batch, the ARKit
   curves' RMS and jawOpen r against ``facesynth solve``'s curves of the batch markers, and the
   mouth-opening r of each against the clean ground truth (``quality_ratio`` = live r / batch r).
   ``path_differs``: the fraction of spoken steps whose node differs from the whole-utterance path
   (none for the trajectory method, which has no nodes: its batch is ``synthesize --method
   trajectory``, solved at the model's capture rate over the whole utterance).
   Rows ending ``_pauses_wait`` hold a pause's frames back until its next phone is decided (the
   frames batch renders there); the others send them ``stream.pause_wait_s`` after their audio.
2. ``concurrent``: ``facesynth stream --serve 127.0.0.1:0 --workers W`` in its own processes; K
   clients push ``--seconds`` of audio each at real-time speed (20 ms chunks) at once, and latency is measured
   on the clock of this process (frame received minus the send of the chunk holding its sample).
   A stream count is **held** when its p95 latency stays within 100 ms of one stream's.
3. ``voice_on_actress``: the voice's frames (``stream.voice = "articulation"``, the default for
   audio) on the held-out takes: latency as in 1., the live mouth opening against the clean
   truth beside batch ``synthesize --audio`` (the phones recognised, the voice fused).
4. ``real_voice`` (with ``--facegood``): a real voice, FACEGOOD's takes (the three used for no
   choice by default), streamed with the voice's frames and with the phones' (``stream.voice =
   "off"``): latency, CPU, and the live mouth opening and jawOpen against the speaker's capture
   and against batch ``synthesize --audio`` of the same audio (cached in ``--work``, as
   ``real_speech_lipsync.py`` caches it), then 2. on that voice, both ways, at ``--voice-seconds``.
   The rows of 1. measure the phones' path (``stream.voice = "off"``); 2. runs the defaults.

Prints JSON; the machine's load average is beside the numbers (a shared machine's wall times
scale with it).
"""

from __future__ import annotations

import argparse
import asyncio
import csv
import json
import os
import selectors
import subprocess
import sys
import time
import wave
from dataclasses import replace
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.base.phonemes import PAU
from facesynth.domain import methods
from facesynth.domain.evaluation.held_out import TruthFolder
from facesynth.domain.live.session import Session
from facesynth.domain.live.synthesizer import LiveModel
from facesynth.domain.methods import MethodSettings, steps
from facesynth.domain.methods.trajectory import synthesize_motion
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.search.synthesis import synthesize
from facesynth.domain.speech.utterance import read_utterance, utterance
from facesynth.model.motiondb import MotionDatabase
from facesynth.model.trajectory import TrajectoryModel

CHUNK_S = 0.02
#: (method, look-ahead phones, recognition hold phones, stream.pause_wait_s: None the default; a
#: wait longer than any pause makes a pause's frames wait for the next phone, as batch renders them)
CONFIGS = [("dp", 0, 1, None), ("dp", 0, 1, 3600.0), ("dp", 1, 1, None), ("dp", 1, 1, 3600.0), ("dp", 2, 1, None),
           ("dp", 2, 2, None), ("dp", 4, 1, None), ("greedy", 1, 1, None), ("trajectory", 0, 1, None),
           ("trajectory", 1, 1, None)]
#: How the phones arrive: recognised from the audio; given by a TTS engine with the chunk where
#: each starts; given for the whole utterance before its audio (a TTS engine that plans a sentence).
MODES = ("recognize", "given", "given_ahead")


def pearson(a: np.ndarray, b: np.ndarray) -> float:
    a, b = a - a.mean(), b - b.mean()
    d = np.sqrt((a * a).sum() * (b * b).sum())
    return float((a * b).sum() / d) if d > 0 else float("nan")


def read_pcm(path: Path) -> bytes:
    with wave.open(str(path)) as w:
        assert (w.getframerate(), w.getnchannels(), w.getsampwidth()) == (16000, 1, 2), path
        return w.readframes(w.getnframes())


def opening(markers: np.ndarray, names: list[str]) -> np.ndarray:
    """(T,) inner-lip gap, mm."""
    return np.linalg.norm(markers[:, names.index("ULI_C")] - markers[:, names.index("LLI_C")], axis=1)


def stream_offline(model: LiveModel, align, pcm: bytes, phones_given: list[dict] | None, ahead: bool = False):
    """Stream ``pcm`` in 20 ms chunks through a session on a simulated real-time clock (``ahead``:
    every given phone before the first chunk). Returns the frames' markers (T, M, 3), times (T,)
    s, latencies (T,) s, processing seconds and the session."""
    session = Session(model, align, "benchmark")
    session.markers = True
    if phones_given is not None:
        session.control(json.dumps({"type": "start", "phones": "given", "markers": True}))
    step = int(CHUNK_S * 16000) * 2
    clock, busy, cpu, frames, times, latency, arkit = 0.0, 0.0, 0.0, [], [], [], []
    pending = list(phones_given or [])
    n_chunks = -(-len(pcm) // step)
    for c in range(n_chunks + 1):
        arrival = min((c + 1) * step, len(pcm)) / 32000
        t0, c0 = time.perf_counter(), time.process_time()
        if c < n_chunks:
            out = []
            starting = [p for p in pending if p["start"] < arrival or ahead]
            if starting:
                pending = pending[len(starting):]
                out += session.control(json.dumps({"type": "phones", "phones": starting, "final": not pending}))
            out += session.audio(pcm[c * step : (c + 1) * step])
        else:
            out = session.end()
        dt = time.perf_counter() - t0
        busy += dt
        cpu += time.process_time() - c0
        clock = max(clock, arrival) + dt
        for m in out:
            if m["type"] == "frame":
                sample_arrival = min(np.ceil(m["time"] / CHUNK_S - 1e-9) * CHUNK_S, len(pcm) / 32000)
                latency.append(max(0.0, clock - max(sample_arrival, m["time"])))
                frames.append(np.array(m["markers"], np.float32).reshape(-1, 3))
                times.append(m["time"])
                arkit.append(m["arkit"])
    session.arkit = np.array(arkit)
    return np.stack(frames), np.array(times), np.array(latency), busy, cpu, session


def offline(db_path: Path, corpus: Path, takes: list[str], config: Config, trajectory_path: Path | None) -> dict:
    db = MotionDatabase.read(db_path)
    trajectory = TrajectoryModel.read(trajectory_path) if trajectory_path is not None else None
    truth = TruthFolder.open(corpus, db.marker_names, config.settings("normalize"))
    align = config.settings("align")
    names = db.marker_names
    out = {}
    for method, lookahead, hold, pause_wait in CONFIGS:
        if method == "trajectory" and trajectory is None:
            continue
        stream = replace(config.settings("stream"), method=method, lookahead_phones=lookahead, recognition_hold=hold,
                         voice="off")  # these rows measure the phones' path
        if pause_wait is not None:
            stream = replace(stream, pause_wait_s=pause_wait)
        model = LiveModel(trajectory if method == "trajectory" else db, config.settings("synthesize"), stream,
                          config.settings("solve"), config.settings("trajectory"))
        for mode in MODES:
            if mode != "recognize" and hold != 1:
                continue  # the hold only matters to recognition
            speech_lat, lat, rms, r_batch, r_live_truth, r_batch_truth, decisions = [], [], [], [], [], [], []
            arkit_rms, jaw_r = [], []
            busy, cpu_s, audio_s, differ, spoken = 0.0, 0.0, 0.0, 0, 0
            for take in takes:
                pcm = read_pcm(corpus / "audio" / f"{take}.wav")
                given = None
                if mode != "recognize":
                    utt = read_utterance(corpus / "labels" / f"{take}.TextGrid")
                    given = [{"phone": p, "start": float(a), "end": float(b)} for p, a, b in zip(utt.phones, utt.starts, utt.ends)]
                live, times, latency, t_busy, t_cpu, session = stream_offline(model, align, pcm, given,
                                                                             mode == "given_ahead")
                lat.append(latency)
                s = session.synth
                step_of = np.searchsorted(np.array(s.starts), times, side="right") - 1
                speech_lat.append(latency[np.array([s.phones[k] != PAU for k in step_of])])
                busy += t_busy
                cpu_s += t_cpu
                audio_s += len(pcm) / 32000
                decisions += session.synth.decision_s
                utt = utterance(s.phones, s.starts, s.ends, s.emotions)
                if method == "trajectory":
                    batch_markers = synthesize_motion(trajectory, utt, config.settings("trajectory"),
                                                      model.stream.fps)[0].markers
                else:
                    batch = synthesize(db, utt, {}, replace(model.synth, search=method))
                    batch_markers = batch.rendered.markers
                    keep = np.array([p != PAU for p in utt.phones])
                    differ += int(((np.array(s.committed) != batch.path) & keep).sum())
                    spoken += int(keep.sum())
                assert batch_markers.shape == live.shape, (take, batch_markers.shape, live.shape)
                rms.append(float(np.sqrt(((live - batch_markers) ** 2).sum(-1).mean())))
                # the curves: the live per-batch solve against `facesynth solve` of the batch markers
                batch_arkit = model.arkit(model.solve(batch_markers, None))
                jaw = model.arkit_names.index("jawOpen")
                arkit_rms.append(float(np.sqrt(((session.arkit - batch_arkit) ** 2).mean())))
                jaw_r.append(pearson(session.arkit[:, jaw], batch_arkit[:, jaw]))
                o_live, o_batch = opening(live, names), opening(batch_markers, names)
                r_batch.append(pearson(o_live, o_batch))
                clean, _ = truth.clean(take, names, db.reference)
                clean = downsample(clean, db.fps, model.stream.fps)
                n = min(len(clean), len(o_live))
                o_truth = opening(clean[:n], names)
                r_live_truth.append(pearson(o_live[:n], o_truth))
                r_batch_truth.append(pearson(o_batch[:n], o_truth))
            lat_all = np.concatenate(lat)
            speech_all = np.concatenate(speech_lat)
            key = (f"{method}_lookahead{lookahead}_{mode}" + (f"_hold{hold}" if mode == "recognize" else "")
                   + ("_pauses_wait" if pause_wait is not None else ""))
            out[key] = {
                "method": method, "lookahead_phones": lookahead, "phones": mode, "frames": int(len(lat_all)),
                "recognition_hold": hold if mode == "recognize" else None, "pause_wait_s": stream.pause_wait_s,
                "latency_median_ms": round(1000 * float(np.median(lat_all)), 1),
                "latency_p95_ms": round(1000 * float(np.percentile(lat_all, 95)), 1),
                "speech_latency_median_ms": round(1000 * float(np.median(speech_all)), 1),
                "speech_latency_p95_ms": round(1000 * float(np.percentile(speech_all, 95)), 1),
                "rtf": round(busy / audio_s, 4), "rtf_cpu": round(cpu_s / audio_s, 4),
                "decision_median_ms": round(1000 * float(np.median(decisions)), 2),
                "decision_p95_ms": round(1000 * float(np.percentile(decisions, 95)), 2),
                "path_differs": round(differ / spoken, 3) if spoken else None,
                "rms_vs_batch_mm": round(float(np.mean(rms)), 3),
                "arkit_rms_vs_batch": round(float(np.mean(arkit_rms)), 4),
                "jaw_open_r_vs_batch": round(float(np.nanmean(jaw_r)), 3),
                "mouth_r_vs_batch": round(float(np.nanmean(r_batch)), 3),
                "mouth_r_truth_live": round(float(np.nanmean(r_live_truth)), 3),
                "mouth_r_truth_batch": round(float(np.nanmean(r_batch_truth)), 3),
                "quality_ratio": round(float(np.nanmean(r_live_truth) / np.nanmean(r_batch_truth)), 3),
            }
            print(key, out[key], file=sys.stderr)
    return out


async def _client(port: int, pcm: bytes, t_start: float) -> list[float]:
    from websockets.asyncio.client import connect

    step = int(CHUNK_S * 16000) * 2
    sent_at: list[float] = []
    latencies: list[float] = []
    async with connect(f"ws://127.0.0.1:{port}", max_size=None) as ws:
        await ws.recv()  # hello

        async def send():
            for c in range(0, len(pcm), step):
                due = t_start + (c // step) * CHUNK_S
                await asyncio.sleep(max(0.0, due - time.monotonic()))
                await ws.send(pcm[c : c + step])
                sent_at.append(time.monotonic())
            await ws.send(json.dumps({"type": "end"}))

        sender = asyncio.create_task(send())
        while True:
            m = json.loads(await ws.recv())
            if m["type"] == "end":
                break
            if m["type"] == "frame":
                chunk = min(int(np.ceil(m["time"] / CHUNK_S - 1e-9)), len(sent_at) - 1)
                latencies.append(time.monotonic() - sent_at[max(chunk, 0)])
        await sender
    return latencies


def concurrent(db_path: Path, pcm: bytes, counts: list[int], seconds: float, workers: int,
               settings: tuple[str, ...] = ()) -> dict:
    """K clients at once for each K of ``counts``, each pushing ``seconds`` of ``pcm`` in real time to
    one ``facesynth stream --serve`` with ``workers`` processes and ``settings`` (``--set`` values)."""
    extra = [a for value in settings for a in ("--set", value)]
    proc = subprocess.Popen([sys.executable, "-m", "facesynth.cli", "stream", str(db_path), "--serve", "127.0.0.1:0",
                             "--workers", str(workers), *extra], stderr=subprocess.PIPE, stdout=subprocess.DEVNULL)
    try:
        with selectors.DefaultSelector() as sel:
            sel.register(proc.stderr, selectors.EVENT_READ)
            if not sel.select(120):
                raise RuntimeError("the server did not start")
        port = int(proc.stderr.readline().decode().split()[2].rsplit(":", 1)[1])
        audio = (pcm * int(np.ceil(seconds * 32000 / len(pcm))))[: int(seconds * 32000) // 2 * 2]
        out = {}
        async def run(count: int):
            t0 = time.monotonic() + 0.2
            # the streams' starts are spread over one chunk, so their chunks do not all arrive at once
            return await asyncio.gather(*[_client(port, audio, t0 + i * CHUNK_S / count) for i in range(count)])

        for k in counts:
            lat = np.concatenate(asyncio.run(run(k)))
            out[str(k)] = {"latency_median_ms": round(1000 * float(np.median(lat)), 1),
                           "latency_p95_ms": round(1000 * float(np.percentile(lat, 95)), 1),
                           "latency_max_ms": round(1000 * float(np.max(lat)), 1), "frames": int(len(lat))}
            print("concurrent", workers, settings, k, out[str(k)], file=sys.stderr)
        base = out[str(counts[0])]["latency_p95_ms"]
        held = [k for k in counts if out[str(k)]["latency_p95_ms"] <= base + 100]
        return {"workers": workers, "settings": list(settings), "streams": out, "held": max(held) if held else 0,
                "criterion": "p95 within 100 ms of one stream's"}
    finally:
        proc.terminate()
        proc.wait(30)


def actress_voice(db_path: Path, corpus: Path, takes: list[str], config: Config) -> dict:
    """The voice's frames (``stream.voice = "articulation"``) on the actress's held-out takes: the
    simulated real-time latency (as ``offline``) and the live mouth opening against her clean
    truth, beside batch synthesis from the same audio alone (the phones recognised, the voice's
    articulation fused: ``synthesize --audio``)."""
    db = MotionDatabase.read(db_path)
    truth = TruthFolder.open(corpus, db.marker_names, config.settings("normalize"))
    model = LiveModel(db, config.settings("synthesize"), config.settings("stream"), config.settings("solve"))
    settings = MethodSettings.of(config)
    settings = settings.replace(synthesize=replace(settings.synthesize, use_opencl=False))
    names = list(db.marker_names)
    member = methods.get("dp")
    latency, r_live, r_batch, cpu, audio_s = [], [], [], 0.0, 0.0
    for take in takes:
        wav = corpus / "audio" / f"{take}.wav"
        pcm = read_pcm(wav)
        live, _, lat, _, t_cpu, _ = stream_offline(model, config.settings("align"), pcm, None)
        latency.append(lat)
        cpu += t_cpu
        audio_s += len(pcm) / 32000
        read = steps.read_utterance(config.settings("ingest"), audio=wav, align=config.settings("align"))
        batch = steps.synthesize_utterance(member, db, read, settings).motion.markers
        clean, _ = truth.clean(take, names, db.reference)
        clean = downsample(clean, db.fps, model.stream.fps)
        n = min(len(clean), len(live), len(batch))
        o_truth = opening(clean[:n], names)
        r_live.append(pearson(opening(live[:n], names), o_truth))
        r_batch.append(pearson(opening(batch[:n], names), o_truth))
    lat = np.concatenate(latency)
    return {"takes": takes, "latency_median_ms": round(1000 * float(np.median(lat)), 1),
            "latency_p95_ms": round(1000 * float(np.percentile(lat, 95)), 1), "rtf_cpu": round(cpu / audio_s, 4),
            "mouth_r_truth_live": round(float(np.nanmean(r_live)), 3),
            "mouth_r_truth_batch_audio": round(float(np.nanmean(r_batch)), 3),
            "quality_ratio": round(float(np.nanmean(r_live) / np.nanmean(r_batch)), 3)}


def real_voice(db_path: Path, facegood: Path, takes: list[str], work: Path, config: Config, counts: list[int],
               seconds: float, workers: int) -> dict:
    """A real voice (FACEGOOD's takes, ``benchmarks/real_speech_lipsync.py``'s layout) streamed with
    the voice's frames (``stream.voice = "articulation"``, the default) and with the phones' (``off``,
    the path before): per take, the simulated real-time latency (as ``offline``) and the live mouth
    against the speaker's captured mouth and against batch ``synthesize --audio`` of the same audio
    (solved onto the rig, as that benchmark does; cached in ``work``); then ``concurrent`` on the
    first take's audio for both."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import real_speech_lipsync as rs

    channel_names = rs.channel_names(facegood)
    table = rs.read_table()
    db = MotionDatabase.read(db_path)
    align, lip = config.settings("align"), config.settings("evaluate").lip_markers
    models = {voice: LiveModel(db, config.settings("synthesize"), replace(config.settings("stream"), voice=voice),
                               config.settings("solve")) for voice in ("articulation", "off")}
    rows: dict[str, dict[str, list]] = {v: {"latency": [], "r_capture": [], "r_batch": [], "jaw_r_capture": [],
                                             "rtf_cpu": []} for v in models}
    batch_r, batch_jaw_r = [], []
    for take in takes:
        wav = facegood / "wav" / f"{take}.wav"
        pcm = read_pcm(wav)
        values = np.asarray(rs.load_npy(facegood / "bs_value_npy" / f"bs_value_{take}.npy"), np.float64)
        n = min(len(values), int(np.floor(len(pcm) / 32000 * rs.FPS)))
        real = {k: v[:n] for k, v in rs.real_curves(values, channel_names, table).items()}
        spans = rs.windows(n, rs.FPS, 10.0)
        folder = work / "takes" / take
        folder.mkdir(parents=True, exist_ok=True)
        batch = rs.facesynth_method(db_path, None, folder, n, lip, audio=wav)
        batch_r.append(rs.window_r(batch["opening"], real["opening"], spans))
        batch_jaw_r.append(rs.window_r(batch["jawOpen"], real["jawOpen"], spans))
        for voice, model in models.items():
            live, times, latency, _, cpu, session = stream_offline(model, align, pcm, None)
            o_live = rs.fit_length(opening(live, list(db.marker_names)), n)
            jaw = rs.fit_length(session.arkit[:, model.arkit_names.index("jawOpen")], n)
            row = rows[voice]
            row["latency"].append(latency)
            row["r_capture"].append(rs.window_r(o_live, real["opening"], spans))
            row["r_batch"].append(rs.window_r(o_live, batch["opening"], spans))
            row["jaw_r_capture"].append(rs.window_r(jaw, real["jawOpen"], spans))
            row["rtf_cpu"].append(cpu / (len(pcm) / 32000))
            print("real voice", take, voice, round(float(np.nanmean(row["r_capture"][-1])), 3), file=sys.stderr)
    r_batch = float(np.nanmean(np.concatenate(batch_r)))
    out: dict = {"takes": takes, "batch_synthesize_audio": {
        "mouth_r_capture": round(r_batch, 3), "jaw_open_r_capture": round(float(np.nanmean(np.concatenate(batch_jaw_r))), 3)}}
    for voice, row in rows.items():
        lat = np.concatenate(row["latency"])
        r_live = float(np.nanmean(np.concatenate(row["r_capture"])))
        out[f"voice_{voice}"] = {
            "latency_median_ms": round(1000 * float(np.median(lat)), 1),
            "latency_p95_ms": round(1000 * float(np.percentile(lat, 95)), 1),
            "latency_max_ms": round(1000 * float(np.max(lat)), 1),
            "rtf_cpu": round(float(np.mean(row["rtf_cpu"])), 4),
            "mouth_r_capture": round(r_live, 3),
            "mouth_r_batch": round(float(np.nanmean(np.concatenate(row["r_batch"]))), 3),
            "jaw_open_r_capture": round(float(np.nanmean(np.concatenate(row["jaw_r_capture"]))), 3),
            "quality_ratio": round(r_live / r_batch, 3)}
    pcm = read_pcm(facegood / "wav" / f"{takes[0]}.wav")
    out["concurrent"] = {voice: concurrent(db_path, pcm, counts, seconds, workers, (f"stream.voice={voice}",))
                         for voice in models}
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--db", type=Path, required=True)
    ap.add_argument("--corpus", type=Path, required=True)
    ap.add_argument("--trajectory", type=Path, default=None, help="a trajectory model of --db: its rows too")
    ap.add_argument("--takes", type=int, default=8, help="held-out takes streamed (first ones in the manifest)")
    ap.add_argument("--streams", default="1,4,8,12", help="concurrent stream counts, the first the reference")
    ap.add_argument("--seconds", type=float, default=8.0, help="audio per concurrent stream")
    ap.add_argument("--workers", default="1,2", help="server processes (--workers) to measure")
    ap.add_argument("--skip-concurrent", action="store_true")
    ap.add_argument("--skip-offline", action="store_true")
    ap.add_argument("--facegood", type=Path, default=None,
                    help="FACEGOOD's folder (benchmarks/real_speech_lipsync.py's layout): the real-voice section")
    ap.add_argument("--facegood-takes", default="1114_2_04,1114_2_05,1114_3_15",
                    help="its takes streamed (default: the three no choice was made on)")
    ap.add_argument("--work", type=Path, default=Path("out/live_bench"), help="cache of the batch syntheses")
    ap.add_argument("--voice-seconds", type=float, default=20.0, help="real voice per concurrent stream")
    args = ap.parse_args()
    config = Config.load()
    rows = list(csv.DictReader(open(args.corpus / "manifest.csv")))
    takes = [r["take"] for r in rows if r["split"] == "test"][: args.takes]
    result = {"db": args.db.name, "takes": takes, "chunk_s": CHUNK_S, "fps": config.settings("stream").fps,
              "cpus": os.cpu_count(), "load_average": os.getloadavg()}
    if not args.skip_offline:
        result["offline"] = offline(args.db, args.corpus, takes, config, args.trajectory)
    result["voice_on_actress"] = actress_voice(args.db, args.corpus, takes, config)
    if not args.skip_concurrent:
        counts = [int(x) for x in args.streams.split(",")]
        pcm = read_pcm(args.corpus / "audio" / f"{takes[0]}.wav")
        result["concurrent"] = [concurrent(args.db, pcm, counts, args.seconds, int(w)) for w in args.workers.split(",")]
    if args.facegood is not None:
        result["real_voice"] = real_voice(args.db, args.facegood, args.facegood_takes.split(","), args.work, config,
                                          [int(x) for x in args.streams.split(",")], args.voice_seconds,
                                          int(args.workers.split(",")[-1]))
    result["load_average_after"] = os.getloadavg()
    print(json.dumps(result, indent=1))


if __name__ == "__main__":
    main()
