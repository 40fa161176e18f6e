"""Animation that leaves facesynth: writers for the formats other tools read (Live Link Face
CSV, USD, C3D, OBJ sequences; glTF is :mod:`facesynth.formats.gltf`, beside its reader) and a
self-contained web player.

:mod:`.animation` loads any exportable artifact (``motion``, ``meshanim``, ``curves``) into one
:class:`~.animation.Exportable`; each format module writes one. Units and axes, per format, are
in ``docs/exports.md``: facesynth works in millimetres with +y up, the face looking toward +z and
+x the subject's left.
"""
