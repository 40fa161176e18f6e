"""Capture takes of every kind a capture manifest's ``mocap`` column may name, read as markers:
marker files (C3D, TRC, marker CSV: :mod:`facesynth.formats.mocap`), Live Link Face CSVs
(:mod:`.live_link_take`) and another rig's curves with a mapping to ARKit (:mod:`.curve_take`),
which pose the rig (:mod:`.posing`), and filmed faces (:mod:`.video_take`, the ``facesynth[video]``
extra). :func:`.readers.read_capture` reads any of them.

The formats are registered here, one line each (:data:`facesynth.base.registry.CAPTURE_READERS`):
the reader, a summary and its file suffixes. Formats sharing a suffix are tried in this order,
the first that recognizes the file reading it: a ``.csv`` is Live Link Face by its header,
another rig's curves when the take has a mapping, else markers.
"""

from facesynth.base.registry import CAPTURE_READERS
from facesynth.formats.video import SUFFIXES as VIDEO_SUFFIXES

CAPTURE_READERS.register("c3d", "facesynth.formats.mocap:read_c3d", "C3D markers (Vicon, Qualisys, OptiTrack, Motive)",
                         suffixes=(".c3d",))
CAPTURE_READERS.register("trc", "facesynth.formats.mocap:read_trc", "TRC markers (Cortex, OpenSim)", suffixes=(".trc",))
CAPTURE_READERS.register("live-link-face", "facesynth.domain.capture.live_link_take:READER",
                         "Live Link Face CSV (iPhone): 52 ARKit curves and head rotations posing the rig, told by its "
                         "Timecode and BlendShapeCount columns", suffixes=(".csv",))
CAPTURE_READERS.register("curves", "facesynth.domain.capture.curve_take:READER",
                         "another rig's blendshape curves (CSV, or NumPy with channel names) with a mapping to ARKit, "
                         "posing the rig", suffixes=(".csv", ".npy"))
CAPTURE_READERS.register("csv", "facesynth.formats.mocap:read_csv",
                         "marker CSV: a time column, then X, Y, Z per marker (docs/inputs.md)", suffixes=(".csv",))
CAPTURE_READERS.register("video", "facesynth.domain.capture.video_take:READER",
                         "a filmed face, tracked by MediaPipe Face Mesh into 478 markers, with its sound "
                         "(facesynth[video])", suffixes=VIDEO_SUFFIXES, needs="video")
