"""Readers and writers of the outside formats a user brings and takes away: markers, Live Link
Face CSVs, another rig's blendshape curves and their mapping to ARKit, video, labels, audio,
meshes and OBJ sequences, glTF, USD. The capture formats a manifest's ``mocap`` column may name
are registered in :mod:`facesynth.domain.capture`, where the readers that pose a rig live.
"""
