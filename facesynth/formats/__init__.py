"""Readers and writers of the outside formats a user brings: mocap, labels, audio, meshes.

The capture formats a capture manifest's ``mocap`` column may name are registered here, one line
each (:data:`facesynth.base.registry.CAPTURE_READERS`): the module and
:class:`~facesynth.formats.mocap.CaptureReader` reading it, a summary and its file suffixes.
"""

from facesynth.base.registry import CAPTURE_READERS

CAPTURE_READERS.register("c3d", "facesynth.formats.mocap:C3D", "C3D markers (Vicon, Qualisys, OptiTrack, Motive)",
                         suffixes=(".c3d",))
CAPTURE_READERS.register("trc", "facesynth.formats.mocap:TRC", "TRC markers (Cortex, OpenSim)", suffixes=(".trc",))
CAPTURE_READERS.register("csv", "facesynth.formats.mocap:CSV",
                         "marker CSV: a time column, then X, Y, Z per marker (docs/inputs.md)", suffixes=(".csv",))
