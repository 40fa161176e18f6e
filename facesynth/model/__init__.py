"""The objects every stage passes around, each with the one reader and writer of its artifact kind.

============  ==========================  ==========================================
module        objects                     artifact kind(s)
============  ==========================  ==========================================
tables        Takes, Phones               the ``/takes`` and ``/phones`` tables of all
corpus        Corpus                      ``corpus`` (facesynth ingest)
frames        NormalizedFrames            ``normalized`` (facesynth normalize)
pca           PcaModel, PcaFrames         ``pca`` (facesynth pca)
motiondb      Nodes, MotionDatabase       ``motiondb`` (facesynth build-db, prune)
isomap        Cluster, PhonemeMaps        ``isomap`` (facesynth isomap)
motion        Motion                      ``motion`` (facesynth synthesize, capture)
meshanim      MeshAnimation               ``meshanim`` (facesynth deform)
style         ExpressionModel, BilinearModel   ``expression`` (facesynth expression fit)
kinds         SCHEMAS, PRODUCERS          every kind's schema and the commands that write it
spec          KINDS (the specification)   every kind, as data (facesynth check, docs)
============  ==========================  ==========================================

Stage modules (``facesynth.stages``) import these and the domain packages, never another
stage. Nothing else opens these kinds with h5py. This layer imports only the formats and the
base modules below it, with one known exception (docs/architecture.md).
"""
