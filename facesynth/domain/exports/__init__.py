"""Animation that leaves facesynth: writers for the formats other tools read (Live Link Face
CSV, USD, C3D, OBJ sequences; glTF is :mod:`facesynth.formats.gltf`, beside its reader) and a
self-contained web player.

:mod:`.animation` loads any exportable artifact (``motion``, ``meshanim``, ``curves``) into one
:class:`~.animation.Exportable`; each format module writes one. Units and axes, per format, are
in ``docs/exports.md``: facesynth works in millimetres with +y up, the face looking toward +z and
+x the subject's left.
"""

from facesynth.base.registry import EXPORT_FORMATS

# The export formats (``facesynth export --format``; those with ``batch`` also the outputs of
# ``facesynth batch``): name, the module and ExportFormat writing it, a summary, and what the
# command line needs to know without importing it (``suffix`` of a batch output, ``folder``).
EXPORT_FORMATS.register("arkit-csv", "facesynth.domain.exports.files:ARKIT_CSV",
                        "Live Link Face CSV from rig curves (Unreal Live Link, MetaHuman)", suffix=".arkit.csv",
                        batch=True)
EXPORT_FORMATS.register("gltf", "facesynth.domain.exports.files:GLTF",
                        "the rig mesh with its morph targets and a weights animation, the speech beside it",
                        suffix=".gltf", batch=True)
EXPORT_FORMATS.register("glb", "facesynth.domain.exports.files:GLB", "glTF in one binary file", suffix=".glb",
                        batch=True)
EXPORT_FORMATS.register("usd", "facesynth.domain.exports.files:USD",
                        "UsdSkel blendshapes (curves) or time-sampled points (mesh animation)", suffix=".usd",
                        batch=True)
EXPORT_FORMATS.register("usda", "facesynth.domain.exports.files:USDA", "USD as text", suffix=".usda", batch=True)
EXPORT_FORMATS.register("c3d", "facesynth.domain.exports.files:C3D", "the markers, labelled (motion, mesh animation)",
                        suffix=".c3d")
EXPORT_FORMATS.register("obj-seq", "facesynth.domain.exports.objseq:OBJ_SEQUENCE",
                        "a folder of OBJs, one per frame (mesh animation, curves)", folder=True)
