"""``facesynth synthesize``: expressive speech motion from the motion-node database
(paper VI and VII-B).

The constrained DP of Algorithm 1 picks one node per input phone minimizing Eq. 4; the
path is concatenated, smoothed, time-warped to the input timing at the capture rate,
back-projected with Eq. 11 and down-sampled to the output rate. Every output frame keeps
its provenance (node, take, source frame).
"""

from __future__ import annotations

import contextlib
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from ..artifacts import RowReader, open_artifact, read, read_strings, write_artifact, write_strings
from ..config import IngestSettings, SynthesizeSettings, settings_json
from ..errors import InputError
from ..phonemes import PAU, viseme
from ..search.costs import StepCosts, path_terms, step_costs, transition_panel_rows, transition_rows
from ..search.dp import PanelMatrix
from ..search.inputs import Utterance, apply_emotions, read_constraints, read_utterance, utterance
from ..motion.head import follow_sources, import_scipy, relative_to_take
from ..motion.postprocess import concatenate, downsample
from ..tables import Takes
from .build_db import Nodes
from .pca import PcaModel, read_pca


@dataclass
class Database:
    """What synthesis needs from a ``motiondb`` artifact."""

    nodes: Nodes
    coeffs: np.ndarray      # (F, K) float32, indexed by node frames
    model: PcaModel
    reference: np.ndarray   # (M, 3) mm, neutral closed-mouth rest pose
    marker_names: list[str]
    takes: Takes
    fps: float
    path: Path
    head_rotation: np.ndarray     # (F, 3, 3) per database frame, relative to its take's mean pose
    head_translation: np.ndarray  # (F, 3) mm, likewise

    def transition(self, settings: SynthesizeSettings) -> np.ndarray:
        """The full (N, N) float32 TC matrix of Table I, streaming the pair terms in row blocks."""
        n = len(self.nodes)
        tc = np.empty((n, n), np.float32)
        block = min(256, n)
        with open_artifact(self.path, "motiondb") as f, contextlib.ExitStack() as stack:
            terms = [stack.enter_context(RowReader(f[f"pairs/{key}"], block)) for key in ("dsc", "pgap", "vgap")]
            for a in range(0, n, block):
                rows = slice(a, min(n, a + block))
                tc[rows] = transition_rows(rows, *(t.rows(rows) for t in terms), self.nodes.viseme, self.nodes.pre, settings)
        return tc

    def transition_panels(self, settings: SynthesizeSettings) -> PanelMatrix:
        """TC assembled straight into the panel-major layout of the OpenCL DP, streaming the
        pair terms in row blocks read in place from the file."""
        n = len(self.nodes)
        out = PanelMatrix(n)
        block = min(128, n)  # half a chunk of build-db: the block's sums stay in cache
        scratch = np.empty((2, block, n), np.float32)
        with open_artifact(self.path, "motiondb") as f, contextlib.ExitStack() as stack:
            terms = [stack.enter_context(RowReader(f[f"pairs/{key}"], block)) for key in ("dsc", "pgap", "vgap")]
            for a in range(0, n, block):
                rows = slice(a, min(n, a + block))
                dsc, pgap, vgap = (t.rows(rows) for t in terms)
                transition_panel_rows(out.panels, rows, dsc, pgap, vgap, self.nodes.viseme, self.nodes.pre, settings,
                                      scratch=scratch)
                del dsc, pgap, vgap  # views of the file's map, which closes with the readers
        return out


def load_database(path: Path) -> Database:
    """Everything but the pairwise terms, which are streamed when the search needs them."""
    with open_artifact(path, "motiondb") as f:
        for key in ("pairs/dsc", "pairs/pgap", "pairs/vgap"):
            read_shape = f[key].shape if key in f else None
            if read_shape != (len(f["nodes/phone"]),) * 2:
                raise InputError(f"{path}: dataset '{key}' is missing or not (nodes x nodes); rebuild it with facesynth build-db.")
        takes = Takes.read(f)
        rotation, translation = relative_to_take(read(f, "head_rotation"), read(f, "head_translation"),
                                                 [takes.frames(i) for i in range(len(takes))])
        return Database(
            Nodes.read(f), read(f, "coefficients"), read_pca(f), read(f, "reference"),
            read_strings(f, "marker_names"), takes, float(f["coefficients"].attrs["fps"]), Path(path),
            rotation, translation,
        )


def unseen_phones(utt: Utterance, db: Database) -> dict[str, str]:
    """Input phones with no node, and how the search will cover them."""
    have = set(db.nodes.phone)
    have_vis = {viseme(p) for p in have}
    out = {}
    for p in dict.fromkeys(utt.phones):
        if p == PAU or p in have:
            continue
        out[p] = "nodes of the same viseme (Table II rule 2)" if viseme(p) in have_vis else "any node (Table II rule 3)"
    return out


def greedy_search(db: Database, tc, utt: Utterance, steps: StepCosts, settings: SynthesizeSettings):
    """Cao et al.'s GreedyMatching; returns a DpResult-like record with the Eq. 4 cost of its path."""
    from ..search.dp import DpResult
    from ..search.greedy import Greedy, anime_graph, cluster_graph, motion_features

    if settings.greedy_clusters > 0:
        features = motion_features(db.coeffs, db.nodes.frame_start, db.nodes.frame_count)
        graph = cluster_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc, features, settings.greedy_clusters)
    else:
        graph = anime_graph(db.nodes.phone, db.nodes.emotion, db.nodes.suc)
    result = Greedy(graph, db.nodes.viseme, db.nodes.emotion, tc, settings.alpha6 * settings.pnt).search(utt.phones, utt.emotions)
    terms = path_terms(result.path, tc, steps)
    cost = float(sum(v.astype(np.float64).sum() for v in terms.values()))
    return DpResult(cost, result.path, np.zeros((0, 0), np.float32)), f"greedy ({'%d clusters' % settings.greedy_clusters if settings.greedy_clusters else 'unclustered'})"


def search(tc, steps: StepCosts, settings: SynthesizeSettings, *, while_running: Callable[[], None] | None = None,
           timings: dict[str, float] | None = None):
    """Run the DP; returns (DpResult, device description). ``while_running`` is host work to do
    while an OpenCL search runs; ``timings`` gets ``opencl_setup_s`` (context, kernel, buffers)."""
    from ..search.dp import OpenCLDp, dp_numpy

    if settings.use_opencl:
        from ..opencl import device_name

        t0 = time.perf_counter()
        runner = OpenCLDp(tc)
        if timings is not None:
            timings["opencl_setup_s"] = time.perf_counter() - t0
        return runner.run(steps.total, while_running), f"OpenCL: {device_name()}"
    return dp_numpy(tc, steps.total), "NumPy"


def table_iv_weight(settings: SynthesizeSettings):
    def weight(phone: str) -> float:
        if phone in settings.high_phones:
            return settings.weight_high
        if phone in settings.low_phones:
            return settings.weight_low
        return settings.weight_intermediate
    return weight


def captured_runs(nodes: Nodes) -> list[slice]:
    """Frames of each maximal run of captured-linked nodes (no pause, no pruned node inside)."""
    runs = []
    for k in np.nonzero(nodes.pre < 0)[0]:
        last = k
        while nodes.suc[last] >= 0:
            last = nodes.suc[last]
        runs.append(slice(int(nodes.frame_start[k]), int(nodes.frame_start[last] + nodes.frame_count[last])))
    return runs


def cao_joins(db: Database, path: np.ndarray, phones: list[str]):
    """Cao et al.'s blending across jumps and learned low-pass (``synthesize.postprocess = "cao"``)."""
    from ..motion.cao import blend_jumps, learned_cutoffs, lowpass

    take_range = np.array([(db.takes.frames(t).start, db.takes.frames(t).stop) for t in db.nodes.take])

    def joins(out: np.ndarray, ranges) -> np.ndarray:
        changed = blend_jumps(out, ranges, path, phones, db.nodes.phone, db.nodes.frame_start, db.nodes.frame_count,
                              db.nodes.pre, take_range, db.coeffs)
        out[:] = lowpass(out, learned_cutoffs(db.coeffs, captured_runs(db.nodes), db.fps), db.fps)
        return changed
    return joins


def synthesize(db: Database, utt: Utterance, constraints: dict[int, int], settings: SynthesizeSettings, tc=None) -> dict:
    """Search and post-process. Returns a dict of everything ``motion.h5`` stores, and
    ``timings``: seconds spent on the transition costs (when ``tc`` is not given), the step
    costs, the OpenCL set-up, the search and the post-processing."""
    timings = {}
    t0 = time.perf_counter()
    if tc is None:
        tc = db.transition_panels(settings) if settings.use_opencl else db.transition(settings)
        timings["transition_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    steps = step_costs(utt.phones, utt.emotions, db.nodes.phone, db.nodes.emotion, constraints, settings)
    timings["steps_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    if settings.search == "greedy":
        if constraints:
            raise InputError("motion-node constraints need the DP search (Eq. 10); drop --constraints or use --search dp.")
        result, device = greedy_search(db, tc, utt, steps, settings)
    else:
        # scipy (head motion) is imported while the device searches
        result, device = search(tc, steps, settings, while_running=import_scipy, timings=timings)
    timings["search_s"] = time.perf_counter() - t0 - timings.get("opencl_setup_s", 0.0)
    path = result.path
    for t, node in constraints.items():  # Eq. 10 guarantees this; a failure is a bug
        assert path[t] == node, f"constraint at step {t} not met"
    t0 = time.perf_counter()
    out = {"path": path, "cost": result.cost, "terms": path_terms(path, tc, steps), "device": device,
           "timings": timings, **render_path(db, utt, path, settings)}
    timings["postprocess_s"] = time.perf_counter() - t0
    return out


def render_path(db: Database, utt: Utterance, path: np.ndarray, settings: SynthesizeSettings) -> dict:
    """VII-B for a given node path: concatenate, smooth, regenerate pauses, Eq. 11, down-sample."""
    rest = db.model.project(db.reference[None])[0]
    cat = concatenate(
        path, utt.phones, utt.starts, utt.ends, db.nodes.frame_start, db.nodes.frame_count, db.nodes.pre,
        db.nodes.phone, db.coeffs, rest, db.fps, half_window=settings.smoothing_half_window,
        lam=settings.smoothing_lambda, weight_of=table_iv_weight(settings), interpolation=settings.silence_interpolation,
        joins=cao_joins(db, path, utt.phones) if settings.postprocess == "cao" else None,
    )
    markers = db.model.reconstruct(cat.coeffs)
    joins = sum(1 for t in range(len(path) - 1)
                if utt.phones[t] != PAU and utt.phones[t + 1] != PAU and db.nodes.pre[path[t + 1]] != path[t])
    take = np.where(cat.node >= 0, db.nodes.take[np.maximum(cat.node, 0)], -1)
    head_r, head_t = follow_sources(cat.source_frame, db.head_rotation, db.head_translation)
    return {"concatenated": cat, "markers_capture": markers, "markers": downsample(markers, db.fps, settings.output_fps),
            "non_captured_joins": joins, "take": take,
            "head_rotation": downsample(head_r, db.fps, settings.output_fps),
            "head_translation": downsample(head_t, db.fps, settings.output_fps)}


def prepare(db: Database, phones_path: Path | None, emotions_path: Path | None, constraints_path: Path | None,
            ingest_settings: IngestSettings, audio: Path | None = None, text: str | None = None) -> tuple[Utterance, dict[int, int]]:
    if phones_path is not None:
        utt = read_utterance(phones_path, ingest_settings.phone_tiers)
    elif audio is not None and text is not None:
        from ..formats.audio import read_audio
        from ..formats.labels import Segment
        from .align import align_samples

        samples, rate = read_audio(audio)
        segs: list[Segment] = align_samples(samples, rate, text, where=str(audio))
        utt = utterance([s.label for s in segs], [s.start for s in segs], [s.end for s in segs])
    else:
        raise InputError("give the utterance's phones with --phonemes, or --audio and --text to align them.")
    if emotions_path is not None:
        apply_emotions(utt, emotions_path, ingest_settings.emotions, ingest_settings.emotion_aliases)
    constraints = read_constraints(constraints_path, utt, db.nodes.phone) if constraints_path else {}
    return utt, constraints


def write_motion(out: Path, db: Database, utt: Utterance, res: dict, settings: SynthesizeSettings,
                 records: list[dict], overwrite: bool) -> None:
    cat = res["concatenated"]
    with write_artifact(out, "motion", config=settings_json(settings), records=records, overwrite=overwrite) as g:
        m = g.create_dataset("markers", data=res["markers"])
        m.attrs.update(units="mm", fps=settings.output_fps)
        mc = g.create_dataset("markers_capture", data=res["markers_capture"])
        mc.attrs.update(units="mm", fps=db.fps)
        c = g.create_dataset("coefficients", data=cat.coeffs)
        c.attrs["fps"] = db.fps
        write_head_and_markers(g, db.marker_names, db.reference, res["head_rotation"], res["head_translation"], settings.output_fps)
        p = g.create_group("path")
        p.create_dataset("node", data=res["path"])
        write_strings(p, "phone", utt.phones)
        write_strings(p, "emotion", utt.emotions)
        write_strings(p, "node_phone", [db.nodes.phone[j] for j in res["path"]])
        write_strings(p, "node_emotion", [db.nodes.emotion[j] for j in res["path"]])
        p.create_dataset("start", data=utt.starts).attrs["units"] = "s"
        p.create_dataset("end", data=utt.ends).attrs["units"] = "s"
        for key, value in res["terms"].items():
            p.create_dataset(f"cost_{key}", data=value)
        p.attrs.update(total_cost=res["cost"], non_captured_joins=res["non_captured_joins"],
                       search=settings.search, device=res["device"])
        v = g.create_group("provenance")
        v.attrs["fps"] = db.fps
        v.attrs["meaning"] = "per capture-rate frame: node, take row, source frame in the database (-1: regenerated silence)"
        v.create_dataset("node", data=cat.node)
        v.create_dataset("take", data=res["take"])
        write_strings(v, "take_names", db.takes.name)
        v.create_dataset("source_frame", data=cat.source_frame)
        v.create_dataset("step", data=cat.step)
        v.create_dataset("smoothed", data=cat.smoothed)


def write_head_and_markers(g, names: list[str], reference: np.ndarray, head_r: np.ndarray, head_t: np.ndarray, fps: float) -> None:
    """Marker names, rest pose and the head motion of a ``motion`` artifact."""
    write_strings(g, "marker_names", names)
    r = g.create_dataset("reference", data=reference)
    r.attrs["units"] = "mm"
    hr = g.create_dataset("head_rotation", data=head_r.astype(np.float32))
    hr.attrs.update(fps=fps, convention="head pose relative to the source take's mean: x -> head_rotation @ x + head_translation")
    ht = g.create_dataset("head_translation", data=head_t.astype(np.float32))
    ht.attrs.update(fps=fps, units="mm")


def run(db_path: Path, out: Path, settings: SynthesizeSettings, ingest_settings: IngestSettings, *,
        phones_path: Path | None = None, emotions_path: Path | None = None, constraints_path: Path | None = None,
        audio: Path | None = None, text: str | None = None, overwrite: bool = False) -> dict:
    """Synthesize and write ``out``. The summary's ``*_s`` entries are the seconds of each phase:
    ``load_s`` (database tables), those of :func:`synthesize`, ``hash_wait_s`` (waiting for the
    inputs' sha256, computed on another thread from the start) and ``write_s``."""
    from ..artifacts import check_output, input_records_in_background

    check_output(out, overwrite)
    inputs = [p for p in (db_path, phones_path, emotions_path, constraints_path, audio) if p is not None]
    records = input_records_in_background(inputs)
    t0 = time.perf_counter()
    db = load_database(db_path)
    load_s = time.perf_counter() - t0
    utt, constraints = prepare(db, phones_path, emotions_path, constraints_path, ingest_settings, audio, text)
    res = synthesize(db, utt, constraints, settings)
    t0 = time.perf_counter()
    input_records = records()
    hash_wait_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    write_motion(out, db, utt, res, settings, input_records, overwrite)
    write_s = time.perf_counter() - t0
    return {"phones": len(utt), "cost": res["cost"], "joins": res["non_captured_joins"], "device": res["device"],
            "unseen": unseen_phones(utt, db), "frames": len(res["markers"]), "load_s": load_s, **res["timings"],
            "hash_wait_s": hash_wait_s, "write_s": write_s}
