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
base modules below it.

The kinds are registered below, one line each (:data:`facesynth.base.registry.ARTIFACT_KINDS`):
the name, the :class:`~facesynth.model.spec.Kind` specifying it, and one line on what it holds.
``facesynth check``, every reader (through :func:`~facesynth.model.artifacts.open_artifact`) and
the reference of ``docs/file-format.md`` read them.
"""

from facesynth.base.registry import ARTIFACT_KINDS

ARTIFACT_KINDS.register("corpus", "facesynth.model.spec:CORPUS", "the ingested capture session")
ARTIFACT_KINDS.register("normalized", "facesynth.model.spec:NORMALIZED", "the capture with head motion removed")
ARTIFACT_KINDS.register("pca", "facesynth.model.spec:PCA", "the normalized frames and their PCA coefficients")
ARTIFACT_KINDS.register("motiondb", "facesynth.model.spec:MOTIONDB", "the motion-node database")
ARTIFACT_KINDS.register("isomap", "facesynth.model.spec:ISOMAP", "the phoneme-Isomaps of a database")
ARTIFACT_KINDS.register("motion", "facesynth.model.spec:MOTION", "synthesized or captured marker motion")
ARTIFACT_KINDS.register("meshanim", "facesynth.model.spec:MESHANIM", "a mesh animation")
ARTIFACT_KINDS.register("expression", "facesynth.model.spec:EXPRESSION", "a fitted expression model")
ARTIFACT_KINDS.register("headmotion", "facesynth.model.spec:HEADMOTION", "synthesized head motion")
ARTIFACT_KINDS.register("curves", "facesynth.model.spec:CURVES", "a rig's blendshape weights per frame")
ARTIFACT_KINDS.register("keyshapes", "facesynth.model.spec:KEYSHAPES", "key-shapes chosen from a database")
ARTIFACT_KINDS.register("trajectory", "facesynth.model.spec:TRAJECTORY", "a fitted key-shape trajectory model")
ARTIFACT_KINDS.register("coarticulation", "facesynth.model.spec:COARTICULATION",
                        "a fitted Cohen-Massaro coarticulation model")
ARTIFACT_KINDS.register("articulation", "facesynth.model.spec:ARTICULATION",
                        "a fitted acoustic articulation model (voice features to mouth curves)")
