"""Features that do not carry the speaker, tried: the phone posteriors of the recogniser's own
multi-speaker acoustic model beside the voice's log-mel features. Prints JSON.

pocketsphinx (a dependency: it recognises the phones of ``synthesize --audio``) ships a US-English
tied-mixture acoustic model trained on many voices: per context-independent phone (42, silence
and noises among them) a codebook of 128 diagonal Gaussians per feature stream (13 cepstra, 13
deltas, 13 double deltas: ``-feat 1s_c_d_dd``), and per HMM state (3 per phone) the mixture
weights over its phone's codebook. This benchmark reads those files (``means``, ``variances``,
``sendump``, ``mdef`` of ``pocketsphinx.get_model_path()/en-us/en-us``) and scores every 10 ms
frame of a voice: its cepstra as the model's ``feat.params`` describe them (pre-emphasis 0.97,
25.6 ms Hamming window, 25 mel filters 130..6800 Hz, orthonormal DCT, lifter 22, the utterance's
cepstral mean removed; its spectral noise removal is not reproduced), the log-likelihood of each
phone (the best of its three states, each the log of its mixture over the three streams'
codebooks), and their posteriors over the 42 phones at temperature ``--temperature`` (the
likelihoods of 39 dimensions are sharp: 10 is pocketsphinx's usual acoustic weight).

Protocol (the packaged model's, ``benchmarks/voice_speakers.py``): fitted on the sources that may
ship (FACEGOOD and GRID's ten speakers; no synthetic voices, none can be made for posteriors
without recognising them too), scored on every speaker of the other sources (its first 60 s),
the model's own predicted mouth opening against the real one (Pearson r in 10 s windows, mean per
speaker), pooled over speakers with a 95% bootstrap interval resampling speakers, and paired
against the log-mel features alone:

- ``mel``: the shipped features (``facesynth.domain.voice.articulation.FEATURE_NAMES``);
- ``mel+posteriors``: those and the 42 posteriors;
- ``mel+log_posteriors``: those and the 42 log-likelihoods minus the frame's best, over the
  temperature (the posteriors' logarithm before the softmax's normalization, floored at -20).

    python benchmarks/voice_posteriors.py --facegood FACEGOOD_DIR --speech-data SPEECH_DIR \\
        > benchmarks/voice_posteriors.json
"""

from __future__ import annotations

import argparse
import json
import struct
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import scipy.fft

from facesynth.domain.evaluation.bootstrap import interval, paired_difference, resamples
from facesynth.domain.voice import articulation as A

sys.path.insert(0, str(Path(__file__).resolve().parent))

import voice_speakers as vs  # noqa: E402  (the speakers' loaders, targets, folds and scores)

#: The cepstral front end of pocketsphinx's en-us model (its feat.params).
RATE, HOP, WINDOW, NFFT = 16000, 160, 410, 512
N_FILTERS, LOWER_HZ, UPPER_HZ, N_CEPSTRA, LIFTER = 25, 130.0, 6800.0, 13, 22
PRE_EMPHASIS = 0.97
#: Mixture weights are stored as 8-bit -log values in base 1.0001, shifted by 10 bits.
MIXTURE_LOG_STEP = 1024 * np.log(1.0001)
FEATURE_SETS = ("mel", "mel+posteriors", "mel+log_posteriors")


def model_folder() -> Path:
    import pocketsphinx

    return Path(pocketsphinx.get_model_path()) / "en-us" / "en-us"


def read_gaussians(path: Path) -> np.ndarray:
    """(codebooks, streams, densities, dims) float64 of a Sphinx-3 ``means`` or ``variances`` file."""
    data = path.read_bytes()
    at = data.index(b"endhdr\n") + len(b"endhdr\n")
    magic, n_codebooks, n_streams, n_densities = struct.unpack("<4i", data[at:at + 16])
    if magic != 0x11223344:
        raise SystemExit(f"{path}: not a little-endian Sphinx-3 parameter file")
    dims = struct.unpack(f"<{n_streams}i", data[at + 16:at + 16 + 4 * n_streams])
    if len(set(dims)) != 1:
        raise SystemExit(f"{path}: streams of unequal widths {dims}")
    at += 16 + 4 * n_streams
    total = struct.unpack("<i", data[at:at + 4])[0]
    values = np.frombuffer(data, "<f4", total, at + 4)
    return values.reshape(n_codebooks, n_streams, n_densities, dims[0]).astype(np.float64)


def read_phones(path: Path) -> tuple[list[str], int, int]:
    """The context-independent phones of a binary ``mdef``, its states per phone and its CI senones."""
    data = path.read_bytes()
    if data[:4] != b"BMDF":
        raise SystemExit(f"{path}: not a binary model definition")
    at = 12 + struct.unpack("<i", data[8:12])[0]
    n_ci, _, n_states, n_ci_senones = struct.unpack("<4i", data[at:at + 16])
    names = data[at + 40:].split(b"\0")[:n_ci]
    return [n.decode() for n in names], n_states, n_ci_senones


def read_log_weights(path: Path, n_ci_senones: int) -> np.ndarray:
    """(streams, densities, CI senones) natural-log mixture weights of an uncompressed ``sendump``."""
    data = path.read_bytes()
    at = 0
    while True:  # the header: length-prefixed strings up to a zero length
        n = struct.unpack("<i", data[at:at + 4])[0]
        at += 4
        if n == 0:
            break
        if b"cluster_count" in data[at:at + n] and b"cluster_count 0" not in data[at:at + n]:
            raise SystemExit(f"{path}: clustered mixture weights are not read here")
        at += n
    n_densities, n_senones = struct.unpack("<2i", data[at:at + 8])
    n_streams = (len(data) - at - 8) // (n_densities * n_senones)
    raw = np.frombuffer(data, np.uint8, n_streams * n_densities * n_senones, at + 8)
    return -raw.reshape(n_streams, n_densities, n_senones)[:, :, :n_ci_senones].astype(np.float64) * MIXTURE_LOG_STEP


class PhoneScorer:
    """Per-frame log-likelihoods of the model's context-independent phones."""

    def __init__(self, folder: Path):
        self.phones, self.states, n_ci_senones = read_phones(folder / "mdef")
        means, variances = read_gaussians(folder / "means"), np.maximum(read_gaussians(folder / "variances"), 1e-4)
        weights = read_log_weights(folder / "sendump", n_ci_senones)  # CI senone = phone * states + state
        n_phones, self.n_streams, n_densities, _ = means.shape
        if n_phones != len(self.phones) or n_ci_senones != n_phones * self.states:
            raise SystemExit(f"{folder}: {n_phones} codebooks for {len(self.phones)} phones; not a tied-mixture model")
        self.inverse = 1.0 / variances
        self.mean_scaled = means * self.inverse
        self.constant = -0.5 * (np.log(2 * np.pi * variances).sum(-1) + (means * means * self.inverse).sum(-1))
        self.weights = weights.transpose(0, 2, 1).reshape(self.n_streams, n_phones, self.states, n_densities)
        # the model's filters have unit area in Hz; the voice features' filters sum to 1 over bins
        self.filters = A.mel_filterbank(N_FILTERS, NFFT, RATE, LOWER_HZ, UPPER_HZ) * (NFFT / RATE)

    def features(self, samples: np.ndarray) -> np.ndarray:
        """(K, streams, 13) cepstra, deltas and double deltas of 16 kHz samples; frame k centred at
        k * 10 ms, as :func:`facesynth.domain.voice.articulation.frame_features` counts frames."""
        x = np.asarray(samples, np.float64) * 32768.0
        x = np.append(x[:1], x[1:] - PRE_EMPHASIS * x[:-1])
        k = A.frame_count(len(x))
        padded = np.concatenate([np.zeros(WINDOW // 2), x, np.zeros(WINDOW)])
        frames = np.lib.stride_tricks.sliding_window_view(padded, WINDOW)[::HOP][:k]
        power = np.abs(np.fft.rfft(frames * np.hamming(WINDOW), NFFT, axis=1)) ** 2
        cep = scipy.fft.dct(np.log(np.maximum(power @ self.filters.T, 1e-5)), type=2, norm="ortho", axis=1)[:, :N_CEPSTRA]
        cep *= 1 + LIFTER / 2 * np.sin(np.arange(N_CEPSTRA) * np.pi / LIFTER)
        cep -= cep.mean(0)
        padded = np.concatenate([cep[:1]] * 3 + [cep] + [cep[-1:]] * 3)

        def at(d):
            return padded[3 + d:3 + d + k]

        return np.stack([cep, at(2) - at(-2), (at(3) - at(-1)) - (at(1) - at(-3))], 1)

    def log_likelihoods(self, samples: np.ndarray) -> np.ndarray:
        """(K, phones) float32: per frame, each phone's best state's log-likelihood."""
        f = self.features(samples)
        k, n_phones = len(f), len(self.phones)
        out = np.zeros((k, n_phones, self.states))
        for s in range(self.n_streams):
            x = f[:, s]
            inv, ms = self.inverse[:, s], self.mean_scaled[:, s]
            gauss = (-0.5 * (x * x) @ inv.reshape(-1, x.shape[1]).T + x @ ms.reshape(-1, x.shape[1]).T)
            gauss = gauss.reshape(k, n_phones, 1, -1) + self.constant[:, s][None, :, None, :]
            total = gauss + self.weights[s][None]  # (K, phones, states, densities)
            top = total.max(-1)
            out += top + np.log(np.exp(total - top[..., None]).sum(-1))
        return out.max(-1).astype(np.float32)


def _scored(wav: str) -> np.ndarray:
    """Log-likelihoods of one utterance's audio file (a worker's job)."""
    from facesynth.formats.audio import read_audio

    samples, rate = read_audio(Path(wav))
    return _SCORER.log_likelihoods(A.to_analysis_rate(samples, rate))


_SCORER: PhoneScorer


def _start_worker(folder: str) -> None:
    global _SCORER
    _SCORER = PhoneScorer(Path(folder))


def posterior_columns(loglik: np.ndarray, temperature: float) -> tuple[np.ndarray, np.ndarray]:
    """(K, P) posteriors and (K, P) log posteriors before normalization (floored at -20) of (K, P)
    log-likelihoods at ``temperature``."""
    z = (loglik - loglik.max(1, keepdims=True)) / temperature
    post = np.exp(z)
    return (post / post.sum(1, keepdims=True)).astype(np.float32), np.maximum(z, -20.0).astype(np.float32)


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--facegood", type=Path, required=True, help="FACEGOOD's folder (see real_speech_lipsync.py)")
    ap.add_argument("--speech-data", type=Path, required=True, help="a folder of sources (voice_speakers.py)")
    ap.add_argument("--ship-sources", default="facegood,grid", help="the sources the model is fitted on")
    ap.add_argument("--temperature", type=float, default=10.0)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--score-seconds", type=float, default=60.0)
    ap.add_argument("--resamples", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    started = time.perf_counter()
    utts = vs.facegood_utterances(args.facegood) + vs.speech_data_utterances(args.speech_data, ("facegood",))
    folder = model_folder()
    with ProcessPoolExecutor(args.workers, initializer=_start_worker, initargs=(str(folder),)) as pool:
        logliks = list(pool.map(_scored, [str(u.wav) for u in utts]))
    phones = PhoneScorer(folder).phones
    columns = {}
    for u, ll in zip(utts, logliks):
        mel = A.frame_features(u.samples, u.rate)
        post, logpost = posterior_columns(ll[:len(mel)], args.temperature)
        columns[u.key] = {"mel": mel, "mel+posteriors": np.concatenate([mel, post], 1),
                          "mel+log_posteriors": np.concatenate([mel, logpost], 1)}
    by_speaker: dict[str, list[vs.Utt]] = {}
    for u in utts:
        by_speaker.setdefault(u.speaker, []).append(u)
    ref = vs.reference_ranges(by_speaker[vs.FACEGOOD_SPEAKER])
    ship = args.ship_sources.split(",")
    train = {s: v for s, v in by_speaker.items() if v[0].source in ship}
    scored = sorted(s for s in by_speaker if s not in train)
    per_speaker: dict[str, dict[str, float]] = {s: {} for s in scored}
    for name in FEATURE_SETS:
        names = A.FEATURE_NAMES + (tuple(f"p_{p}" for p in phones) if name != "mel" else ())
        for u in utts:
            u.raw = columns[u.key][name]
        model = vs.fit_fold(train, ref, "default", 0, args.seed, feature_names=names, speaker_weights="frames")
        for s in scored:
            windows = []
            for u in vs.scored_utterances(by_speaker[s], args.score_seconds):
                predicted = A.predict_raw(model, u.raw, np.arange(u.n) / vs.FPS)[:, model.column("opening")]
                windows += vs.window_scores(predicted, u.real["opening"], u.n, 10.0)
            per_speaker[s][name] = float(np.nanmean(windows))
    index = resamples(len(scored), args.resamples, args.seed)

    def mean_of(name):
        v = np.array([per_speaker[s][name] for s in scored])
        return lambda i: float(v[i].mean())

    def rounded(d):
        return {k: round(v, 4) for k, v in d.items()}

    return {"benchmark": "voice_posteriors", "fitted_on": sorted(train), "scored": len(scored),
            "temperature": args.temperature, "phones": phones,
            "r": {n: rounded(interval(mean_of(n), len(scored), index)) for n in FEATURE_SETS},
            "paired_minus_mel": {n: rounded(paired_difference(mean_of(n), mean_of("mel"), len(scored), index))
                                 for n in FEATURE_SETS[1:]},
            "per_source": {n: {src: round(float(np.mean([per_speaker[s][n] for s in scored
                                                         if by_speaker[s][0].source == src])), 4)
                               for src in sorted({by_speaker[s][0].source for s in scored})} for n in FEATURE_SETS},
            "per_speaker": {s: rounded(v) for s, v in per_speaker.items()},
            "seconds": round(time.perf_counter() - started, 1)}


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
