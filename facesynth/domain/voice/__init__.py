"""The voice's articulation: how the sound of speech moves the mouth.

- :mod:`.articulation`: the acoustic features and the articulation model (features -> mouth
  opening, jaw and rounding), batch and streaming (:class:`~.articulation.StreamingPredictor`);
- :mod:`.fusion`: the voice fused into a method's motion (the mouth's opening moved toward what
  the voice says, weighted by the trust the voice earns);
- :mod:`.fitting`: a performer's own articulation model, fitted on a capture (``fit-articulation``);
- :mod:`.synthetic`: synthetic voices (vocal-tract length, pitch, channel) for training
  invariance.

The live stream's frames from the voice are :mod:`facesynth.domain.live.voice_frames`.
"""
