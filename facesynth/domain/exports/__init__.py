"""Animation that leaves facesynth: the export formats other tools read, one module each
(:mod:`.arkit_csv`, :mod:`.gltf`, :mod:`.usd`, :mod:`.c3d`, :mod:`.obj_seq`; their files are
written in :mod:`facesynth.formats`), a self-contained web player and the Isomap pages.

:mod:`.animation` loads any exportable artifact (``motion``, ``meshanim``, ``curves``) into one
:class:`~.animation.Exportable`; each format module writes one. Units and axes, per format, are
in ``docs/exports.md``: facesynth works in millimetres with +y up, the face looking toward +z and
+x the subject's left.
"""

from facesynth.base.registry import EXPORT_FORMATS

# The export formats (``facesynth export --format``; those with ``batch`` also the outputs of
# ``facesynth batch``): name, the module and ExportFormat writing it, a summary, and what the
# command line needs to know without importing it (``suffix`` of a batch output, ``folder``).
EXPORT_FORMATS.register("arkit-csv", "facesynth.domain.exports.arkit_csv:ARKIT_CSV",
                        "Live Link Face CSV from rig curves (Unreal Live Link, MetaHuman)", suffix=".arkit.csv",
                        batch=True)
EXPORT_FORMATS.register("gltf", "facesynth.domain.exports.gltf:GLTF",
                        "the rig mesh with its morph targets and a weights animation, the speech beside it",
                        suffix=".gltf", batch=True)
EXPORT_FORMATS.register("glb", "facesynth.domain.exports.gltf:GLB", "glTF in one binary file", suffix=".glb",
                        batch=True)
EXPORT_FORMATS.register("usd", "facesynth.domain.exports.usd:USD",
                        "UsdSkel blendshapes (curves) or time-sampled points (mesh animation)", suffix=".usd",
                        batch=True)
EXPORT_FORMATS.register("usda", "facesynth.domain.exports.usd:USDA", "USD as text", suffix=".usda", batch=True)
EXPORT_FORMATS.register("c3d", "facesynth.domain.exports.c3d:C3D", "the markers, labelled (motion, mesh animation)",
                        suffix=".c3d")
EXPORT_FORMATS.register("obj-seq", "facesynth.domain.exports.obj_seq:OBJ_SEQUENCE",
                        "a folder of OBJs, one per frame (mesh animation, curves)", folder=True)
