"""Head motion: removing it from a capture (:mod:`.removal`: the rigid markers, paper Eq. 1-2, with
:mod:`facesynth.domain.geometry.rigid`) and synthesizing it from pitch (:mod:`.synthesis`)."""
