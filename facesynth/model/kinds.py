"""The artifact kinds: each kind's schema, the commands that make it and the version of the
group encodings. The data every layer above the formats reads (:mod:`facesynth.model.artifacts`,
:mod:`facesynth.model.check`, :mod:`facesynth.model.spec`); it imports only the stage declarations
(:mod:`facesynth.base.pipeline`, standard library only), whose outputs name the commands that make each kind,
and the registry of kinds (:mod:`facesynth.model.spec` registers them).
"""

from collections.abc import Mapping

from facesynth.base.pipeline import producers
from facesynth.base.registry import ARTIFACT_KINDS

#: Current schema of each artifact kind (its :class:`~facesynth.model.spec.Kind`'s), bumped on an
#: incompatible change; every registered kind (:data:`facesynth.base.registry.ARTIFACT_KINDS`).
SCHEMAS: Mapping[str, int] = ARTIFACT_KINDS.view(lambda entry: entry.load().schema)

#: The commands that write each kind, for messages that say what to do ("pass the output of
#: `facesynth synthesize`, ... or `facesynth capture`"), from the declarations in facesynth.base.pipeline.
PRODUCERS: Mapping[str, str] = ARTIFACT_KINDS.view(lambda entry: producers(entry.name))

#: Version of each group encoding (the ``encoding-type`` attribute names the group's layout,
#: ``encoding-version`` this number); bumped when a group's layout changes incompatibly.
ENCODING_VERSION = "1"
