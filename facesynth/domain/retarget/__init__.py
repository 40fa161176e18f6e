"""Retargeting marker motion onto a mesh or a blendshape rig (issue 17).

* :mod:`.deform`: marker motion onto any mesh by mesh-distance weights (paper VII-A, Eq. 14-15);
* :mod:`.rig`: loading the target rig (a :class:`facesynth.domain.rig.face.Rig`: the built-in ICT-FaceKit
  rig, a folder of OBJ files or a glTF with morph targets, read by :mod:`facesynth.formats.gltf`)
  and its marker binding;
* :mod:`.keyshapes`: key-shapes chosen from data (Chuang & Bregler 2005 §4.1 PCA extremes, Huang et
  al. §5.2 affinity propagation with merging to the error knee) and frames as non-negative
  key-shape weights (Eq. 8 / Huang Eq. 5);
* :mod:`.solve`: bounded least squares for rig weights: keymorph fitting and the direct per-frame
  facial solve with a temporal smoothness term;
* :mod:`.facial_solve`: that solve for a motion or a capture's take, the steps ``facesynth
  solve`` and :func:`facesynth.solve` share;
* :mod:`.gradients`: deformation-gradient blending of keymorph meshes (Sumner & Popović 2005, Huang
  et al. §3): polar decomposition, rotations blended in log space, one sparse factorization.

Everything here works on arrays; the stages (``deform``, ``keyshapes``, ``solve``, ``retarget``, ``rig-mesh``)
read and write the artifacts.
"""
