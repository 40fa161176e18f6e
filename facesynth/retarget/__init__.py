"""Retargeting marker motion onto a blendshape rig (issue 17).

* :mod:`.rig`: the target rig (the built-in ICT-FaceKit rig, a folder of OBJ files or a glTF with
  morph targets) and its marker binding;
* :mod:`.keyshapes`: key-shapes chosen from data (Chuang & Bregler 2005 §4.1 PCA extremes, Huang et
  al. §5.2 affinity propagation with merging to the error knee) and frames as non-negative
  key-shape weights (Eq. 8 / Huang Eq. 5);
* :mod:`.solve`: bounded least squares for rig weights: keymorph fitting and the direct per-frame
  facial solve with a temporal smoothness term;
* :mod:`.gradients`: deformation-gradient blending of keymorph meshes (Sumner & Popović 2005, Huang
  et al. §3): polar decomposition, rotations blended in log space, one sparse factorization.

Everything here works on arrays; the stages (``keyshapes``, ``solve``, ``retarget``, ``rig-mesh``)
read and write the artifacts.
"""
