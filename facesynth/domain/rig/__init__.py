"""The face rig: the one :class:`~.face.Rig` class (the built-in ICT-FaceKit rig or a user's),
loading and posing a rig, and the marker set recorded on its surface."""
