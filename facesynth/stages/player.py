"""``facesynth player``: a motion, mesh animation or rig curves -> one self-contained HTML page
that plays it in 3D (three.js, orbit controls) with its audio, a scrub bar and a timeline of the
phones with their emotion and, for synthesized motion, the take and database node each came from
(:mod:`facesynth.exports.player`). No network is needed to view it."""

from __future__ import annotations

from pathlib import Path

from ..artifacts import atomic_path, check_output
from ..exports.animation import load
from ..exports.player import page, payload


def run(artifact: Path, output: Path, *, audio: Path | None = None, motion: Path | None = None,
        overwrite: bool = False) -> dict:
    """Write the player page of ``artifact`` to ``output``; returns frames, fps, seconds, phones, bytes."""
    check_output(output, overwrite)
    anim = load(artifact, motion=motion)
    html = page(payload(anim, audio))
    with atomic_path(output, overwrite) as tmp:
        Path(tmp).write_text(html, encoding="utf-8")
    return {"frames": anim.n_frames, "fps": anim.fps, "seconds": anim.duration_s, "phones": len(anim.phones),
            "bytes": len(html.encode("utf-8"))}
