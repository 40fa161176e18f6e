"""Audio in and out: any sound file, or the sound of any video, that ffmpeg reads; mono float32
in [-1, 1] at the file's own rate.

:func:`read_audio` is the one reader of speech for every command (``synthesize``, ``ingest``,
``align``, ``render``, ``batch``, ``stream``, ``export``, ``player``, ``head-motion``) and for a
filmed take's sound. It takes one of two routes:

* WAV, FLAC and AIFF through ``soundfile`` (libsndfile), read exactly: 16-bit PCM becomes
  ``k / 32768``;
* everything else (M4A/AAC, MP3, Opus, Ogg Vorbis, the sound of MP4, MOV, MKV, WebM, AVI, ...),
  and a WAV or FLAC that libsndfile cannot read, decoded by the ffmpeg binary that the
  ``imageio-ffmpeg`` dependency ships (no system ffmpeg is needed). ffmpeg decodes the first
  audio stream, keeping its channels and its own sample rate, and writes it to a pipe as a WAV
  of 32-bit float samples; the rate and the channel count are read from that WAV's header. So
  one run of ffmpeg gives both, and they describe the samples that came out (a separate probe
  of the container could disagree with what the decoder delivers).

Either way several channels are mixed to their mean, and the length is bounded by
``limits.max_utterance_s``. A missing file, a file that is neither sound nor video, a video
without an audio stream and a stream without samples are refused in one sentence each.
"""

from __future__ import annotations

import re
import struct
import subprocess
from pathlib import Path
from typing import NoReturn

import imageio_ffmpeg
import numpy as np
import soundfile as sf

from facesynth.base import limits
from facesynth.base.errors import InputError

#: libsndfile's formats read through ``soundfile`` (lossless: the same samples as ffmpeg, faster);
#: any other format it recognises (Ogg, MP3) goes to ffmpeg, so each codec has one decoder.
SOUNDFILE_FORMATS = frozenset({"WAV", "WAVEX", "W64", "RF64", "FLAC", "AIFF"})

#: What the refusals name as accepted.
ACCEPTED = "a sound file (WAV, FLAC, M4A/AAC, MP3, Opus, Ogg, ...) or a video with sound (MP4, MOV, MKV, ...)"


def read_audio(path: Path) -> tuple[np.ndarray, int]:
    """Read the speech of ``path`` as mono.

    Returns (samples (n,) float32 in [-1, 1], sample rate Hz (int)): the file's own rate, its
    channels averaged. See the module docstring for the two routes."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: audio file not found; check the path.")
    if not path.is_file():
        raise InputError(f"{path}: unreadable audio (not a file); give {ACCEPTED}.")
    read = _read_soundfile(path)
    data, rate = read if read is not None else _read_ffmpeg(path)
    if data.shape[0] == 0:
        raise InputError(f"{path}: the audio file has no samples.")
    if rate <= 0:
        raise InputError(f"{path}: the header gives a sample rate of {rate} Hz; re-export the audio.")
    finite = np.isfinite(data).all(axis=1)
    if not finite.all():
        first = int(np.argmin(finite))
        raise InputError(f"{path}, {first / rate:.3f} s: a sample is NaN or infinite; re-export the audio.")
    limits.bound(data.shape[0] / rate, "max_utterance_s", "the audio's length (s)", str(path))
    return data.mean(axis=1).astype(np.float32), int(rate)


def _read_soundfile(path: Path) -> tuple[np.ndarray, int] | None:
    """(samples (n, channels) float32, rate) of a WAV, FLAC or AIFF libsndfile reads; None for
    any other file, or one it cannot read (ffmpeg tries those)."""
    try:
        with sf.SoundFile(str(path)) as fh:
            if fh.format not in SOUNDFILE_FORMATS:
                return None
            return fh.read(dtype="float32", always_2d=True), int(fh.samplerate)
    except (sf.LibsndfileError, RuntimeError, TypeError, ValueError):
        return None


def _read_ffmpeg(path: Path) -> tuple[np.ndarray, int]:
    """(samples (n, channels) float32, rate) of the first audio stream of ``path``, decoded by
    the bundled ffmpeg (see the module docstring)."""
    cmd = [imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-nostdin", "-v", "error", "-i", _input(path),
           "-map", "0:a:0", "-vn", "-sn", "-dn", "-c:a", "pcm_f32le", "-f", "wav", "pipe:1"]
    result = subprocess.run(cmd, capture_output=True, check=False)
    if result.returncode != 0:
        _refuse(path, result.stderr.decode(errors="replace"))
    if not result.stdout:
        raise InputError(f"{path}: the audio file has no samples.")
    try:
        channels, rate, start = _wav_layout(result.stdout)
    except ValueError as exc:
        raise InputError(f"{path}: unreadable audio: ffmpeg's decoded stream is not as expected ({exc}); "
                         "re-encode it, e.g. ffmpeg -i IN OUT.wav.") from None
    frame_bytes = 4 * channels
    n = (len(result.stdout) - start) // frame_bytes
    data = np.frombuffer(result.stdout, "<f4", count=n * channels, offset=start).reshape(n, channels)
    return data, rate


def _wav_layout(raw: bytes) -> tuple[int, int, int]:
    """(channels, rate Hz, offset of the first sample) of the float WAV ffmpeg wrote to a pipe:
    the RIFF and data sizes are placeholders there (a pipe cannot be rewound), so the samples run
    to the end of ``raw``."""
    if raw[:4] != b"RIFF" or raw[8:12] != b"WAVE":
        raise ValueError("no RIFF/WAVE header")
    pos, fmt = 12, None
    while pos + 8 <= len(raw):
        chunk, size = raw[pos : pos + 4], struct.unpack_from("<I", raw, pos + 4)[0]
        if chunk == b"fmt ":
            tag, channels, rate = struct.unpack_from("<HHI", raw, pos + 8)
            bits = struct.unpack_from("<H", raw, pos + 22)[0]
            if tag not in (3, 0xFFFE) or bits != 32 or channels < 1:
                raise ValueError(f"format {tag}, {bits}-bit, {channels} channel(s)")
            fmt = (channels, rate)
        elif chunk == b"data":
            if fmt is None:
                raise ValueError("samples before the format")
            return fmt[0], fmt[1], pos + 8
        pos += 8 + size + (size & 1)
    raise ValueError("no samples chunk")


def _input(path: Path) -> str:
    """``path`` as ffmpeg's input: through its ``file:`` protocol, so that a name with a colon
    (``take:2.m4a``) or a leading dash is a file, not a protocol or an option."""
    return f"file:{path}"


def _refuse(path: Path, decode_log: str) -> NoReturn:
    """Raise the one sentence that says why ffmpeg gave no samples for ``path``: not a media
    file, a media file without an audio stream, or a stream that does not decode (ffmpeg is
    asked again, without an output, for its description of the file's streams)."""
    probe = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-nostdin", "-i", _input(path)],
                           capture_output=True, text=True, errors="replace", check=False).stderr
    detail = _last_line(decode_log) or _last_line(probe)
    if not re.search(r"^Input #0", probe, re.MULTILINE):
        raise InputError(f"{path}: unreadable audio: ffmpeg reads neither sound nor video in it ({detail}); give "
                         f"{ACCEPTED}.")
    if not re.search(r"Stream #\S+.*?: Audio:", probe):
        kinds = sorted(set(re.findall(r"Stream #\S+.*?: (Video|Subtitle|Data|Attachment):", probe)))
        holds = f" (it holds {' and '.join(k.lower() for k in kinds)} only)" if kinds else ""
        raise InputError(f"{path}: has no audio stream{holds}; give a file with sound, or the speech as a sound file "
                         "of its own.")
    raise InputError(f"{path}: unreadable audio: ffmpeg cannot decode its sound ({detail}); re-encode it, e.g. "
                     "ffmpeg -i IN OUT.wav.")


def _last_line(log: str) -> str:
    """The last non-empty line of an ffmpeg log, without the ``[component @ 0x...]`` prefix, shortened."""
    lines = [re.sub(r"^(\[[^\]]*\]\s*)?(Error opening input files?( [^:]*)?: )?", "", line).strip()
             for line in log.splitlines()]
    lines = [line for line in lines if line]
    return lines[-1][:160] if lines else ""


def pcm16(samples: np.ndarray) -> bytes:
    """``samples`` (n,) in [-1, 1] as 16-bit little-endian PCM: ``round(x * 32768)`` clipped to
    the int16 range, the inverse of reading 16-bit PCM (a 16-bit file read and written back is
    the same bytes)."""
    return np.clip(np.round(np.asarray(samples, np.float64) * 32768.0), -32768, 32767).astype("<i2").tobytes()


def write_wav(path: Path, samples: np.ndarray, rate: int) -> None:
    """Write mono 16-bit PCM WAV (whatever ``path``'s name: a temporary name is published later)."""
    sf.write(str(path), np.clip(samples, -1.0, 1.0), int(rate), format="WAV", subtype="PCM_16")


def is_wav(path: Path) -> bool:
    """Whether ``path`` is a WAV file libsndfile reads (copied as it is where a WAV is wanted)."""
    try:
        return sf.info(str(path)).format in ("WAV", "WAVEX")
    except (sf.LibsndfileError, RuntimeError, TypeError, ValueError):
        return False


def resample(samples: np.ndarray, rate: int, target: int) -> np.ndarray:
    """Polyphase resampling to ``target`` Hz."""
    if rate == target:
        return samples
    from math import gcd

    from scipy.signal import resample_poly

    g = gcd(int(rate), int(target))
    return resample_poly(samples, target // g, rate // g).astype(np.float32)
