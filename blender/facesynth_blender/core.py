"""What the add-on does that needs no Blender: the ARKit names and how shape keys are matched to
them, the user's mapping table, emotion spans from timeline markers, the facesynth commands run
and their one-sentence errors, and the Live Link Face CSV that ``facesynth export`` writes.

No ``bpy`` here, and nothing outside Python's standard library (Blender's own Python has none of
facesynth's dependencies), so tests import this file alone, without Blender.
"""

from __future__ import annotations

import csv
import os
import re
import shutil
import subprocess
import tempfile
import wave
from dataclasses import dataclass, field
from typing import IO

#: The 52 ARKit blendshapes, in the Live Link Face CSV's column order (Apple's spelling). The add-on
#: runs in Blender's own Python, without facesynth, so it keeps its own copy; the tests check it
#: against the CSV facesynth writes.
ARKIT_NAMES = (
    "eyeBlinkLeft", "eyeLookDownLeft", "eyeLookInLeft", "eyeLookOutLeft", "eyeLookUpLeft", "eyeSquintLeft",
    "eyeWideLeft", "eyeBlinkRight", "eyeLookDownRight", "eyeLookInRight", "eyeLookOutRight", "eyeLookUpRight",
    "eyeSquintRight", "eyeWideRight", "jawForward", "jawRight", "jawLeft", "jawOpen", "mouthClose", "mouthFunnel",
    "mouthPucker", "mouthRight", "mouthLeft", "mouthSmileLeft", "mouthSmileRight", "mouthFrownLeft",
    "mouthFrownRight", "mouthDimpleLeft", "mouthDimpleRight", "mouthStretchLeft", "mouthStretchRight",
    "mouthRollLower", "mouthRollUpper", "mouthShrugLower", "mouthShrugUpper", "mouthPressLeft", "mouthPressRight",
    "mouthLowerDownLeft", "mouthLowerDownRight", "mouthUpperUpLeft", "mouthUpperUpRight", "browDownLeft",
    "browDownRight", "browInnerUp", "browOuterUpLeft", "browOuterUpRight", "cheekPuff", "cheekSquintLeft",
    "cheekSquintRight", "noseSneerLeft", "noseSneerRight", "tongueOut",
)

#: The head rotation columns of the Live Link Face CSV (radians, mirrored: see docs/exports.md).
HEAD_COLUMNS = ("HeadYaw", "HeadPitch", "HeadRoll")

#: Emotion names a timeline marker may carry (facesynth's four, and the aliases of its default
#: configuration, ``ingest.emotion_aliases``), any case.
EMOTIONS = {"neutral": "neutral", "happy": "happy", "angry": "angry", "sad": "sad", "happiness": "happy",
            "anger": "angry", "sadness": "sad", "neu": "neutral", "hap": "happy", "ang": "angry"}

#: facesynth's synthesis methods (``facesynth synthesize --method``); the last two read a model
#: fitted by ``facesynth fit-method`` instead of a database.
METHODS = ("dp", "greedy", "mean", "trajectory", "coarticulation")

class AddonError(Exception):
    """A problem the user can fix, said in one sentence (the operator's report)."""


# --- shape-key names ---------------------------------------------------------------------------

_SIDE = re.compile(r"^(.*?)(?:[._\-\s](l|r)|[._\-\s]?(left|right))$", re.IGNORECASE)


def normalized(name: str) -> str:
    """The spelling-free form of a shape name: lower case, no separators, a side as 'left' or
    'right' at the end. 'mouthSmileLeft', 'MouthSmileLeft', 'mouthSmile_L', 'Mouth_Smile_L' and
    'mouthSmile.L' all give 'mouthsmileleft'."""
    name = name.strip()
    side = ""
    m = _SIDE.match(name)
    if m and m.group(1):
        letter = (m.group(2) or m.group(3) or "")[:1].lower()
        side, name = ("left" if letter == "l" else "right"), m.group(1)
    return re.sub(r"[^0-9a-z]", "", name.lower()) + side


_ARKIT_BY_NORMALIZED = {normalized(n): n for n in ARKIT_NAMES}


def arkit_name(name: str) -> str | None:
    """The ARKit name ``name`` spells (any case, ``_L``/``.L``/``Left`` sides), or None."""
    return _ARKIT_BY_NORMALIZED.get(normalized(name))


def parse_mapping(text: str) -> dict[str, list[str]]:
    """The user's mapping table: 'arkitName=ShapeKey' entries separated by commas, semicolons or
    lines; several shape keys joined by '+' (one ARKit weight drives them all); an empty right
    side leaves that ARKit shape unkeyed. Returns {ARKit name: [shape key names]}."""
    table: dict[str, list[str]] = {}
    for entry in re.split(r"[,;\n]", text or ""):
        entry = entry.strip()
        if not entry or entry.startswith("#"):
            continue
        if "=" not in entry:
            raise AddonError(f"mapping entry '{entry}' is not 'arkitName=ShapeKey' (e.g. 'jawOpen=JawDrop').")
        left, right = (part.strip() for part in entry.split("=", 1))
        name = arkit_name(left)
        if name is None:
            raise AddonError(f"mapping entry '{entry}': '{left}' is not one of the 52 ARKit shape names "
                             "(e.g. jawOpen, mouthSmileLeft).")
        table[name] = [key.strip() for key in right.split("+") if key.strip()]
    return table


def match_shape_keys(columns, key_names, mapping: dict[str, list[str]] | None = None) -> dict[str, list[str]]:
    """Which shape keys each CSV column drives: {column: [shape key names]}.

    columns : the CSV's shape columns (ARKit names in Live Link capitals, e.g. 'JawOpen');
    key_names : the mesh's shape keys (the basis excluded); mapping : the user's table
    (:func:`parse_mapping`), which wins over the names. Otherwise a key drives the column its
    name spells (:func:`normalized`); an ARKit shape without sides that the mesh splits in two
    ('browInnerUp' as 'browInnerUp_L' and 'browInnerUp_R', as ICT-FaceKit does) drives both.
    Columns no key matches are left out."""
    mapping = mapping or {}
    keys = list(key_names)
    missing = [k for targets in mapping.values() for k in targets if k not in keys]
    if missing:
        raise AddonError(f"the mapping names the shape key '{missing[0]}', which the mesh does not have.")
    by_form: dict[str, list[str]] = {}
    for key in keys:
        by_form.setdefault(normalized(key), []).append(key)
    found: dict[str, list[str]] = {}
    for column in columns:
        name = arkit_name(column)
        if name is not None and name in mapping:
            targets = list(mapping[name])
        else:
            form = normalized(column)
            targets = list(by_form.get(form, []))
            if not targets and name is not None and not form.endswith(("left", "right")):
                targets = by_form.get(form + "left", []) + by_form.get(form + "right", [])
        if targets:
            found[column] = targets
    return found


# --- emotion spans from timeline markers -------------------------------------------------------

def spans_from_markers(markers, start_frame: float, fps: float, duration_s: float | None = None):
    """Emotion spans (start_s, end_s, emotion) from timeline markers [(name, frame), ...] named by
    an emotion (:data:`EMOTIONS`, any case; others are ignored): each holds from its frame to the
    next emotion marker, the last to the end; times from ``start_frame`` (the sound's start) at
    ``fps``. Spans that end before the sound or start after ``duration_s`` are dropped."""
    named = sorted((frame, EMOTIONS[name.strip().lower()]) for name, frame in markers
                   if name.strip().lower() in EMOTIONS)
    spans = []
    for i, (frame, emotion) in enumerate(named):
        start = (frame - start_frame) / fps
        end = (named[i + 1][0] - start_frame) / fps if i + 1 < len(named) else None
        if end is not None and end <= 0:
            continue
        if duration_s is not None and start >= duration_s:
            continue
        end = end if end is not None else max(start, 0.0) + 1000.0
        spans.append((max(start, 0.0), end, emotion))
    return spans


def write_spans(path: str, spans) -> None:
    """An emotion-spans file as ``facesynth synthesize --emotions`` reads it."""
    with open(path, "w", encoding="utf-8") as fh:
        fh.write("# emotion spans from Blender's timeline markers: start_s end_s emotion\n")
        for start, end, emotion in spans:
            fh.write(f"{start:.6f} {end:.6f} {emotion}\n")


def audio_duration_s(path: str) -> float | None:
    """A WAV file's length (s), or None where Python's ``wave`` cannot tell (FLAC, M4A, MP3, odd
    WAVs: the last emotion span then runs to the end)."""
    try:
        with wave.open(path, "rb") as w:
            return w.getnframes() / float(w.getframerate())
    except (OSError, EOFError, wave.Error):
        return None


# --- the facesynth commands --------------------------------------------------------------------

@dataclass
class Request:
    """One animation asked of facesynth (paths absolute).

    audio : the speech (any sound file, or video with sound, that ffmpeg reads: WAV, FLAC, M4A,
    MP3, Opus, Ogg, MP4, ...); text : what it says ('' to recognise it); language : its BCP-47
    tag ('' for English: ``synthesize --language``); database : the
    database (db.h5) or fitted model; method : one of :data:`METHODS`; emotions : a spans file
    ('' for none); rig, binding : a user's rig and its marker binding ('' for the built-in rig);
    fps : the scene's frame rate; head : whether to export the head's rotation."""

    audio: str
    database: str
    method: str = "dp"
    text: str = ""
    language: str = ""
    emotions: str = ""
    rig: str = ""
    binding: str = ""
    fps: float = 24.0
    head: bool = False
    work_dir: str = ""
    files: dict = field(default_factory=dict)


def check_request(r: Request) -> None:
    """Refuse in one sentence what facesynth would refuse later: missing files, an unknown method.
    Whether the sound reads is facesynth's to say (it reads any sound file or video with sound
    that ffmpeg reads), and its sentence is the operator's report."""
    if not r.audio:
        raise AddonError("no sound chosen: pick a sound file or a sound strip.")
    if not os.path.isfile(r.audio):
        raise AddonError(f"the sound file {r.audio} does not exist.")
    if not r.database:
        raise AddonError("no database chosen: pick the facesynth database (db.h5) or fitted model.")
    if not os.path.isfile(r.database):
        raise AddonError(f"the database {r.database} does not exist.")
    if r.method not in METHODS:
        raise AddonError(f"method '{r.method}' is not one of {', '.join(METHODS)}.")
    for what, path in (("emotion spans file", r.emotions), ("rig", r.rig), ("binding", r.binding)):
        if path and not os.path.exists(path):
            raise AddonError(f"the {what} {path} does not exist.")
    if r.language.strip() and not re.fullmatch(r"[A-Za-z]{2,3}(?:[-_][A-Za-z0-9]{1,8})*", r.language.strip()):
        raise AddonError(f"the language '{r.language}' is not a BCP-47 tag; give one like en, de, fr or cmn.")
    if not (r.fps > 0):
        raise AddonError(f"the scene's frame rate {r.fps:g} is not positive.")


def find_executable(setting: str) -> str:
    """The facesynth command: the add-on preference, else ``facesynth`` on the PATH."""
    if setting:
        path = os.path.expanduser(setting)
        if os.path.isdir(path):
            path = os.path.join(path, "facesynth")
        if not os.path.isfile(path):
            raise AddonError(f"the facesynth executable {setting} does not exist; set the add-on preference to the "
                             "facesynth command of the environment where facesynth is installed.")
        if not os.access(path, os.X_OK):
            raise AddonError(f"the facesynth executable {setting} cannot be run (not executable).")
        return path
    found = shutil.which("facesynth")
    if found is None:
        raise AddonError("facesynth was not found: set the add-on preference 'facesynth executable' to the "
                         "facesynth command of the environment where facesynth is installed (e.g. .venv/bin/facesynth).")
    return found


def commands(exe: str, r: Request) -> list[tuple[str, list[str]]]:
    """The facesynth runs, in order, as (label, argv); output paths go into ``r.files``."""
    w = r.work_dir
    r.files = {"motion": os.path.join(w, "motion.h5"), "curves": os.path.join(w, "curves.h5"),
               "csv": os.path.join(w, "face.csv")}
    synth = [exe, "synthesize", r.database, "--audio", r.audio, "--method", r.method]
    if r.text.strip():
        synth += ["--text", r.text.strip()]
    if r.language.strip():
        synth += ["--language", r.language.strip()]
    if r.emotions:
        synth += ["--emotions", r.emotions]
    solve = [exe, "solve", r.files["motion"]]
    if r.rig:
        solve += ["--rig", r.rig]
    if r.binding:
        solve += ["--binding", r.binding]
    export = [exe, "export", r.files["curves"], "--format", "arkit-csv", "--fps", repr(float(r.fps))]
    if r.head:
        export.append("--head-motion")
    return [("synthesize", synth + ["-o", r.files["motion"], "--overwrite"]),
            ("solve", solve + ["-o", r.files["curves"], "--overwrite"]),
            ("export", export + ["-o", r.files["csv"], "--overwrite"])]


def failure(label: str, returncode: int, stderr: str) -> AddonError:
    """One sentence for a facesynth run that failed: facesynth's own one-line error where it
    wrote one, else the last line it wrote (never a traceback)."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    said = next((line for line in reversed(lines) if line.lower().startswith("error:")), None)
    if said is not None:
        text = said.split(":", 1)[1].strip()
    elif returncode in (-2, 130):
        text = "interrupted"
    elif lines:
        text = f"it stopped with exit status {returncode}: {lines[-1]}"
    else:
        text = f"it stopped with exit status {returncode}"
    text = text.rstrip(".")
    return AddonError(f"facesynth {label} failed: {text}.")


def warnings_of(output: str) -> list[str]:
    """facesynth's 'warning: ...' lines, without the prefix."""
    return [line.split(":", 1)[1].strip() for line in output.splitlines() if line.lower().startswith("warning:")]


def _environment() -> dict[str, str]:
    # Blender's own Python settings must not reach facesynth's interpreter.
    env = dict(os.environ)
    env.pop("PYTHONHOME", None)
    return env


class Job:
    """The facesynth runs of one request, one after another, each in its own process (polled by
    the operator's timer, or waited for by :meth:`run`)."""

    def __init__(self, steps: list[tuple[str, list[str]]]):
        self.steps = steps
        self.index = 0
        self.process: subprocess.Popen | None = None
        self.warnings: list[str] = []
        self._out: IO[str] | None = None
        self._err: IO[str] | None = None

    @property
    def label(self) -> str:
        return self.steps[min(self.index, len(self.steps) - 1)][0]

    def _start(self) -> None:
        label, argv = self.steps[self.index]
        self._out = tempfile.TemporaryFile("w+", encoding="utf-8", errors="replace")
        self._err = tempfile.TemporaryFile("w+", encoding="utf-8", errors="replace")
        try:
            self.process = subprocess.Popen(argv, stdout=self._out, stderr=self._err, stdin=subprocess.DEVNULL,
                                            env=_environment())
        except OSError as exc:
            self._close()
            raise AddonError(f"facesynth could not be started ({argv[0]}: {exc.strerror or exc}); check the add-on "
                             "preference 'facesynth executable'.") from None

    def _close(self) -> None:
        for fh in (self._out, self._err):
            if fh is not None:
                fh.close()
        self._out = self._err = None

    def poll(self) -> bool:
        """Advance: start the next run when none is running. True when every run is done;
        raises :class:`AddonError` when one failed."""
        if self.index >= len(self.steps):
            return True
        if self.process is None:
            self._start()
            return False
        code = self.process.poll()
        if code is None:
            return False
        assert self._out is not None and self._err is not None
        self._out.seek(0)
        self._err.seek(0)
        out, err = self._out.read(), self._err.read()
        self._close()
        self.process = None
        if code != 0:
            raise failure(self.steps[self.index][0], code, err + "\n" + out)
        self.warnings += warnings_of(out + "\n" + err)
        self.index += 1
        return self.index >= len(self.steps)

    def run(self, progress=None) -> None:
        """Run every step, waiting for each; ``progress(index, label)`` before each."""
        while self.index < len(self.steps):
            if progress is not None:
                progress(self.index, self.steps[self.index][0])
            self._start()
            self.process.wait()
            self.poll()

    def cancel(self) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.process = None
        self._close()


# --- the Live Link Face CSV --------------------------------------------------------------------

@dataclass
class Curves:
    """The CSV ``facesynth export --format arkit-csv`` wrote: ``frames`` rows at the export's
    rate (row i at i / fps s). shapes : {column: [T weights]}; head : [T (yaw, pitch, roll)]
    radians in the Live Link convention, or None where the columns are all zero."""

    shapes: dict[str, list[float]]
    head: list[tuple[float, float, float]] | None
    frames: int


def read_livelink_csv(path: str) -> Curves:
    """Read a Live Link Face CSV: the columns between ``BlendShapeCount`` and the rotations are
    shapes (ARKit names, or a rig's own shape names), the Head* columns the head's rotation."""
    try:
        with open(path, newline="", encoding="utf-8") as fh:
            rows = list(csv.reader(fh))
    except OSError as exc:
        raise AddonError(f"facesynth's export {path} could not be read ({exc.strerror or exc}).") from None
    if not rows or "BlendShapeCount" not in rows[0]:
        raise AddonError(f"{path} is not a Live Link Face CSV (no BlendShapeCount column).")
    header = rows[0]
    first = header.index("BlendShapeCount") + 1
    rotations = [i for i, name in enumerate(header) if name.startswith(("Head", "LeftEye", "RightEye"))]
    last = min(rotations) if rotations else len(header)
    try:
        values = [[float(v) for v in row] for row in (r[first:] for r in rows[1:] if r)]
    except ValueError as exc:
        raise AddonError(f"{path}: a value is not a number ({exc}).") from None
    shapes = {header[first + j]: [row[j] for row in values] for j in range(last - first)}
    head = None
    if all(name in header for name in HEAD_COLUMNS):
        idx = [header.index(name) - first for name in HEAD_COLUMNS]
        head = [(row[idx[0]], row[idx[1]], row[idx[2]]) for row in values]
    return Curves(shapes, head, len(values))


def head_euler_blender(yaw: float, pitch: float, roll: float) -> tuple[tuple[float, float, float], str]:
    """The head rotation of a Live Link row as a Blender Euler (angles about Blender's x, y, z,
    and the order), in the armature's space with the character facing -Y, +Z up.

    facesynth's head rotation is R = Ry(a) Rx(b) Rz(c) about its +y (up), +x (the subject's left)
    and +z (toward the viewer), with HeadYaw = -a, HeadPitch = b, HeadRoll = -c (the CSV mirrors
    the face as the phone sees it). facesynth's (x, y, z) is Blender's (x, -y, z) turned so that
    up is +Z: x -> x, y -> z, z -> -y, as Blender's glTF importer does. So R is
    Rz(a) Rx(b) Ry(-c) in Blender's axes: Euler mode 'YXZ' (y first, then x, then z)."""
    a, b, c = -yaw, pitch, -roll
    return (b, -c, a), "YXZ"
