# The names facesynth/__init__.py offers from facesynth.api on first use, for type checkers
# (tests/api/test_api.py checks that this list, _API there and facesynth.api.__all__ agree).
from facesynth.api import Alignment as Alignment
from facesynth.api import ArtifactError as ArtifactError
from facesynth.api import CoarticulationModel as CoarticulationModel
from facesynth.api import Config as Config
from facesynth.api import ConfigError as ConfigError
from facesynth.api import FacesynthError as FacesynthError
from facesynth.api import HeadMotion as HeadMotion
from facesynth.api import InputError as InputError
from facesynth.api import MeshAnimation as MeshAnimation
from facesynth.api import Motion as Motion
from facesynth.api import MotionDatabase as MotionDatabase
from facesynth.api import OutputExistsError as OutputExistsError
from facesynth.api import Rig as Rig
from facesynth.api import RigCurves as RigCurves
from facesynth.api import SearchError as SearchError
from facesynth.api import TrajectoryModel as TrajectoryModel
from facesynth.api import UsageError as UsageError
from facesynth.api import Utterance as Utterance
from facesynth.api import export as export
from facesynth.api import export_formats as export_formats
from facesynth.api import load_config as load_config
from facesynth.api import methods as methods
from facesynth.api import read_curves as read_curves
from facesynth.api import read_database as read_database
from facesynth.api import read_model as read_model
from facesynth.api import read_motion as read_motion
from facesynth.api import read_rig as read_rig
from facesynth.api import solve as solve
from facesynth.api import synthesize as synthesize
from facesynth.api import utterance_from_audio as utterance_from_audio
from facesynth.api import utterance_from_phones as utterance_from_phones

__version__: str
_API: tuple[str, ...]
__all__: list[str]
