"""Readers and writers of the outside formats a user brings: mocap, labels, audio, meshes."""
