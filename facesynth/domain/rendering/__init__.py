"""Drawing a face: the camera, the rasterizers (NumPy reference and OpenCL) and the parts a
skin mesh lacks (eyeballs, mouth cavity, teeth, tongue), built from the mesh itself.

``facesynth render`` and ``facesynth batch`` use it through :mod:`.video`:

* :mod:`.camera`: a perspective camera orbiting the face (yaw, pitch, field of view);
* :mod:`.parts`: boundary loops of the mesh, which of them are eyes and the mouth, and the
  procedural eyeballs, mouth cavity, teeth and tongue that move with the mesh each frame;
* :mod:`.raster`: z-buffer rasterization with supersampling and smooth shading, in NumPy
  and in OpenCL (``kernels/raster.cl``), agreeing within a documented tolerance;
* :mod:`.video`: the views (shaded, markers, side-by-side) and the AVI with its audio.
"""
