"""``bpy.ops.facesynth.animate``: run facesynth on a sound and key the active mesh's shape keys
(and a head bone) with the result, from the scene's current frame at its frame rate."""

from __future__ import annotations

import os
import shutil
import tempfile
import traceback

import bpy
from bpy.props import EnumProperty, IntProperty, StringProperty
from mathutils import Euler

from . import core

ADDON = __package__

_METHOD_ITEMS = [
    ("dp", "DP search", "Search the motion database with the dynamic program (facesynth's default)"),
    ("greedy", "Greedy search", "Tile the phones with the longest captured runs of the database"),
    ("mean", "Mean poses", "Each phone's mean pose from the database"),
    ("trajectory", "Trajectory model", "A model fitted by `facesynth fit-method` (give it as the database)"),
    ("coarticulation", "Coarticulation model", "A Cohen-Massaro model fitted by `facesynth fit-method`"),
]

#: The operator's properties a script may leave out; they are then taken from the panel's settings.
_FROM_PANEL = ("audio", "sound_strip", "text", "language", "database", "method", "emotions", "rig", "binding", "armature",
               "bone", "mapping")


def preferences(context):
    addon = context.preferences.addons.get(ADDON)
    return addon.preferences if addon is not None else None


def abspath(path: str) -> str:
    return os.path.abspath(bpy.path.abspath(path)) if path else ""


class Plan:
    """Everything the operator decided before facesynth runs: the request, the objects to key,
    where the animation starts and what to do with the sound."""

    def __init__(self):
        self.request: core.Request | None = None
        self.job: core.Job | None = None
        self.mesh_name = ""
        self.armature_name = ""
        self.bone = ""
        self.mapping: dict = {}
        self.start_frame = 1
        self.add_strip = True
        self.temporary = ""


class FACESYNTH_OT_animate(bpy.types.Operator):
    """Make lip-synced facial animation for a sound with facesynth and key it on the active mesh's
    shape keys (ARKit names) from the current frame"""

    bl_idname = "facesynth.animate"
    bl_label = "Animate with facesynth"
    bl_options = {"REGISTER", "UNDO"}

    audio: StringProperty(options={"SKIP_SAVE"}, name="Sound", subtype="FILE_PATH",
                          description="The speech: a sound file (WAV, FLAC, M4A, MP3, Opus, ...) or a video "
                                      "with sound (placed as a sound strip at the start frame)")
    sound_strip: StringProperty(options={"SKIP_SAVE"}, name="Sound strip",
                                description="Or, with no sound file, a sound strip of the sequencer: its sound, "
                                            "from the strip's start")
    text: StringProperty(options={"SKIP_SAVE"}, name="Text", description="What the sound says (empty: recognised from the speech)")
    language: StringProperty(options={"SKIP_SAVE"}, name="Language",
                             description="What language is spoken, a BCP-47 tag: en, de, fr, es, cmn... (empty: English)")
    database: StringProperty(options={"SKIP_SAVE"}, name="Database", subtype="FILE_PATH",
                             description="facesynth's motion database (db.h5) or a model fitted on it")
    method: EnumProperty(options={"SKIP_SAVE"}, name="Method", items=_METHOD_ITEMS, default="dp")
    emotions: StringProperty(options={"SKIP_SAVE"}, name="Emotions",
                             description="'markers' for spans from the timeline markers named by an emotion, a "
                                         "spans file ('start_s end_s emotion' lines), or empty for neutral")
    rig: StringProperty(options={"SKIP_SAVE"}, name="Rig", subtype="FILE_PATH",
                        description="A rig to solve onto (empty: facesynth's built-in ARKit-named rig)")
    binding: StringProperty(options={"SKIP_SAVE"}, name="Binding", subtype="FILE_PATH", description="The markers' binding for --rig")
    armature: StringProperty(options={"SKIP_SAVE"}, name="Armature", description="Armature object whose bone takes the head rotation")
    bone: StringProperty(options={"SKIP_SAVE"}, name="Head bone", description="The bone that takes the head rotation (empty: none)")
    mapping: StringProperty(options={"SKIP_SAVE"}, name="Mapping",
                            description="Shape keys for ARKit names: 'jawOpen=JawDrop, browInnerUp=BrowsUp_L+BrowsUp_R'")
    frame_start: IntProperty(options={"SKIP_SAVE"}, name="Start frame", description="Frame of the sound's start (default: the current frame)")
    work_dir: StringProperty(options={"SKIP_SAVE"}, name="Work folder", subtype="DIR_PATH",
                             description="Keep facesynth's files (motion.h5, curves.h5, face.csv) here (default: a "
                                         "temporary folder, removed)")

    # --- what to do -----------------------------------------------------------------------

    def _fill_from_panel(self, context) -> None:
        settings = getattr(context.scene, "facesynth", None)
        if settings is None:
            return
        values = settings.operator_values()
        given = {name for name in _FROM_PANEL if self.properties.is_property_set(name)}
        for pair in (("audio", "sound_strip"), ("armature", "bone")):
            if given & set(pair):
                given |= set(pair)  # a script that names one of the pair means the other to be empty
        for name in _FROM_PANEL:
            if name not in given and name in values:
                setattr(self, name, values[name])

    def _plan(self, context) -> Plan:
        scene = context.scene
        plan = Plan()
        obj = context.active_object
        if obj is None or obj.type != "MESH":
            raise core.AddonError("select the face mesh to animate: the active object must be a mesh with shape keys.")
        if obj.data.shape_keys is None or len(obj.data.shape_keys.key_blocks) < 2:
            raise core.AddonError(f"the mesh '{obj.name}' has no shape keys to animate; give it ARKit-named shape keys.")
        plan.mesh_name = obj.name
        plan.mapping = core.parse_mapping(self.mapping)
        _shape_keys_for(obj, [n[0].upper() + n[1:] for n in core.ARKIT_NAMES], plan.mapping)  # before facesynth runs

        audio = abspath(self.audio)
        plan.start_frame = self.frame_start if self.properties.is_property_set("frame_start") else scene.frame_current
        if self.sound_strip and not self.audio:
            strips = _strips(scene.sequence_editor) if scene.sequence_editor else {}
            strip = strips.get(self.sound_strip)
            if strip is None or strip.type != "SOUND":
                raise core.AddonError(f"the scene has no sound strip '{self.sound_strip}'.")
            if strip.sound is None or strip.sound.packed_file is not None:
                raise core.AddonError(f"the sound strip '{strip.name}' holds a packed sound; unpack it to a file first.")
            audio = os.path.abspath(bpy.path.abspath(strip.sound.filepath, library=strip.sound.library))
            plan.start_frame = int(round(strip.frame_start))
            plan.add_strip = False

        if self.armature or self.bone:
            arm = bpy.data.objects.get(self.armature)
            if arm is None or arm.type != "ARMATURE":
                raise core.AddonError(f"'{self.armature}' is not an armature object; pick the armature of the head bone.")
            if self.bone not in arm.data.bones:
                raise core.AddonError(f"the armature '{arm.name}' has no bone '{self.bone}'.")
            plan.armature_name, plan.bone = arm.name, self.bone

        fps = scene.render.fps / scene.render.fps_base
        emotions = self.emotions.strip()
        if emotions.lower() == "markers":
            emotions = ""  # written below, once the work folder exists
        else:
            emotions = abspath(emotions)
        plan.request = core.Request(audio=audio, database=abspath(self.database), method=self.method,
                                    text=self.text, language=self.language, emotions=emotions, rig=abspath(self.rig),
                                    binding=abspath(self.binding), fps=fps, head=bool(plan.bone))
        core.check_request(plan.request)
        setting = getattr(preferences(context), "facesynth_executable", "")
        exe = core.find_executable(bpy.path.abspath(setting) if setting else "")

        if self.work_dir:
            plan.request.work_dir = abspath(self.work_dir)
            try:
                os.makedirs(plan.request.work_dir, exist_ok=True)
            except OSError as exc:
                raise core.AddonError(f"the work folder {plan.request.work_dir} could not be made "
                                      f"({exc.strerror or exc}).") from None
        else:
            plan.temporary = plan.request.work_dir = tempfile.mkdtemp(prefix="facesynth-blender-")
        try:
            if self.emotions.strip().lower() == "markers":
                markers = [(m.name, m.frame) for m in scene.timeline_markers]
                spans = core.spans_from_markers(markers, plan.start_frame, fps, core.audio_duration_s(audio))
                if spans:
                    plan.request.emotions = os.path.join(plan.request.work_dir, "emotions.txt")
                    core.write_spans(plan.request.emotions, spans)
                else:
                    self.report({"INFO"}, "No timeline marker is named by an emotion; the speech is neutral.")
            plan.job = core.Job(core.commands(exe, plan.request))
        except OSError as exc:
            _clean(plan)
            raise core.AddonError(f"the emotion spans could not be written in {plan.request.work_dir} "
                                  f"({exc.strerror or exc}).") from None
        return plan

    # --- running it -----------------------------------------------------------------------

    def execute(self, context):
        """Run facesynth and wait (scripts, and Blender without a window)."""
        self._fill_from_panel(context)
        wm = context.window_manager
        plan = None
        try:
            plan = self._plan(context)
            steps = len(plan.job.steps) + 1
            wm.progress_begin(0, steps)
            try:
                plan.job.run(lambda i, label: self._progress(context, i, label, steps))
                self._progress(context, steps - 1, "keying", steps)
                self._apply(context, plan)
            finally:
                wm.progress_end()
                _status(context, None)
        except core.AddonError as exc:
            self.report({"ERROR"}, str(exc))
            return {"CANCELLED"}
        except Exception as exc:  # a bug: still one sentence in the report (the traceback goes to the console)
            traceback.print_exc()
            self.report({"ERROR"}, _unexpected(exc))
            return {"CANCELLED"}
        finally:
            if plan is not None:
                _clean(plan)
        return {"FINISHED"}

    def invoke(self, context, event):
        """From the panel: facesynth runs in the background, Blender stays usable; Esc cancels."""
        if bpy.app.background or context.window is None:
            return self.execute(context)
        self._fill_from_panel(context)
        try:
            self._running = self._plan(context)
        except Exception as exc:
            if not isinstance(exc, core.AddonError):
                traceback.print_exc()
            self.report({"ERROR"}, str(exc) if isinstance(exc, core.AddonError) else _unexpected(exc))
            return {"CANCELLED"}
        wm = context.window_manager
        wm.progress_begin(0, len(self._running.job.steps) + 1)
        self._timer = wm.event_timer_add(0.2, window=context.window)
        wm.modal_handler_add(self)
        self._progress(context, 0, self._running.job.label, len(self._running.job.steps) + 1)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        plan = self._running
        if event.type == "ESC":
            plan.job.cancel()
            self._finish(context)
            self.report({"WARNING"}, "facesynth was cancelled; nothing was keyed.")
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        try:
            done = plan.job.poll()
            steps = len(plan.job.steps) + 1
            if not done:
                self._progress(context, plan.job.index, plan.job.label, steps)
                return {"RUNNING_MODAL"}
            self._progress(context, steps - 1, "keying", steps)
            self._apply(context, plan)
        except Exception as exc:
            if not isinstance(exc, core.AddonError):
                traceback.print_exc()
            plan.job.cancel()
            self._finish(context)
            self.report({"ERROR"}, str(exc) if isinstance(exc, core.AddonError) else _unexpected(exc))
            return {"CANCELLED"}
        self._finish(context)
        return {"FINISHED"}

    def cancel(self, context):
        if getattr(self, "_running", None) is not None:
            self._running.job.cancel()
            self._finish(context)

    def _finish(self, context) -> None:
        wm = context.window_manager
        if getattr(self, "_timer", None) is not None:
            wm.event_timer_remove(self._timer)
            self._timer = None
        wm.progress_end()
        _status(context, None)
        _clean(self._running)
        self._running = None

    def _progress(self, context, index: int, label: str, steps: int) -> None:
        context.window_manager.progress_update(index)
        _status(context, f"facesynth: {label} ({index + 1}/{steps})")

    # --- keying ---------------------------------------------------------------------------

    def _apply(self, context, plan: Plan) -> None:
        for warning in plan.job.warnings[:5]:
            self.report({"WARNING"}, f"facesynth: {warning}")
        scene = context.scene
        # everything is checked before the first key, so that a failure keys nothing
        obj = bpy.data.objects.get(plan.mesh_name)
        if obj is None or obj.type != "MESH" or obj.data.shape_keys is None:
            raise core.AddonError(f"the mesh '{plan.mesh_name}' or its shape keys went away while facesynth ran.")
        arm = bpy.data.objects.get(plan.armature_name) if plan.bone else None
        if plan.bone and (arm is None or arm.type != "ARMATURE" or plan.bone not in arm.data.bones):
            raise core.AddonError(f"the head bone '{plan.bone}' went away while facesynth ran.")
        curves = core.read_livelink_csv(plan.request.files["csv"])
        if curves.frames == 0:
            raise core.AddonError(f"facesynth's export {plan.request.files['csv']} holds no frames.")
        key = obj.data.shape_keys
        matched = _shape_keys_for(obj, list(curves.shapes), plan.mapping)
        start = plan.start_frame
        frames = [start + i for i in range(curves.frames)]
        action = _action_of(key, f"{obj.name}_facesynth")
        keyed = 0
        for column, targets in matched.items():
            values = curves.shapes[column]
            for target in targets:
                _key(action, key, f'key_blocks["{_quoted(target)}"].value', 0, frames, values, "facesynth")
                keyed += 1
        if arm is not None and curves.head is not None:
            _key_head(arm, plan.bone, frames, curves.head)
        if plan.add_strip:
            _place_sound(scene, plan.request.audio, start, len(frames))
        if frames and scene.frame_end < frames[-1]:
            scene.frame_end = frames[-1]
        unmatched = [c for c in curves.shapes if c not in matched and any(v != 0.0 for v in curves.shapes[c])]
        more = f" and {len(unmatched) - 6} more" if len(unmatched) > 6 else ""
        note = f"; no shape key for {', '.join(unmatched[:6])}{more}" if unmatched else ""
        self.report({"INFO"}, f"facesynth keyed {keyed} shape keys of '{obj.name}' over frames {frames[0]}-{frames[-1]} "
                              f"at {plan.request.fps:g} frames/s{note}.")


def _shape_keys_for(obj, columns, mapping) -> dict:
    """{column: [shape key names]} of the mesh ``obj``; refused when no key matches."""
    key = obj.data.shape_keys
    names = [kb.name for kb in key.key_blocks if kb != key.reference_key]
    matched = core.match_shape_keys(columns, names, mapping)
    if not matched:
        raise core.AddonError(f"none of the shape keys of '{obj.name}' has an ARKit name (e.g. jawOpen, "
                              "mouthSmileLeft); name them so, or give a mapping.")
    return matched


def _unexpected(exc: Exception) -> str:
    said = " ".join(str(exc).split()) or "no message"
    return f"the facesynth add-on failed unexpectedly ({type(exc).__name__}: {said}); see the system console."


def _status(context, text) -> None:
    workspace = getattr(context, "workspace", None)
    if workspace is not None and not bpy.app.background:
        workspace.status_text_set(text)


def _clean(plan: Plan) -> None:
    if plan is not None and plan.temporary:
        shutil.rmtree(plan.temporary, ignore_errors=True)
        plan.temporary = ""


def _quoted(name: str) -> str:
    return name.replace("\\", "\\\\").replace('"', '\\"')


def _action_of(id_data, name: str):
    """The action animating ``id_data`` (made when it has none)."""
    if id_data.animation_data is None:
        id_data.animation_data_create()
    if id_data.animation_data.action is None:
        id_data.animation_data.action = bpy.data.actions.new(name)
    return id_data.animation_data.action


def _fcurve(action, id_data, data_path: str, index: int, group: str):
    """The action's F-curve of ``data_path[index]`` on ``id_data``, made when missing."""
    if hasattr(action, "fcurves"):  # Blender 3.4 to 4.5 (the legacy API; its first slot from 4.4 on)
        fc = action.fcurves.find(data_path, index=index)
        return fc if fc is not None else action.fcurves.new(data_path, index=index, action_group=group)
    # Blender 5.0 removed Action.fcurves: slotted actions (not tested here: Debian ships 3.4)
    return action.fcurve_ensure_for_datablock(id_data, data_path, index=index, group_name=group)


def _strips(editor, every: bool = True):
    """The sequencer's strips (``strips`` from Blender 4.4 on, ``sequences`` before)."""
    if hasattr(editor, "strips"):
        return editor.strips_all if every else editor.strips
    return editor.sequences_all if every else editor.sequences


def _key(action, id_data, data_path: str, index: int, frames, values, group: str) -> None:
    """Key ``values`` at ``frames`` (linear), replacing the curve's keys between the first and last."""
    fc = _fcurve(action, id_data, data_path, index, group)
    points = fc.keyframe_points
    lo, hi = frames[0] - 0.5, frames[-1] + 0.5
    for i in range(len(points) - 1, -1, -1):
        if lo <= points[i].co[0] <= hi:
            points.remove(points[i], fast=True)
    base = len(points)
    points.add(len(frames))
    for i, (frame, value) in enumerate(zip(frames, values)):
        point = points[base + i]
        point.co = (frame, value)
        point.interpolation = "LINEAR"
    fc.update()


def _key_head(arm, bone_name: str, frames, head) -> None:
    """Key the head rotation on the pose bone as quaternions: the rotation in the armature's space
    (character facing -Y) carried into the bone's rest frame."""
    bone = arm.data.bones[bone_name]
    rest = bone.matrix_local.to_3x3().normalized()
    rest_inv = rest.inverted()
    pose_bone = arm.pose.bones[bone_name]
    pose_bone.rotation_mode = "QUATERNION"
    action = _action_of(arm, f"{arm.name}_facesynth")
    quats, previous = [], None
    for yaw, pitch, roll in head:
        angles, order = core.head_euler_blender(yaw, pitch, roll)
        q = (rest_inv @ Euler(angles, order).to_matrix() @ rest).to_quaternion()
        if previous is not None and q.dot(previous) < 0:
            q.negate()  # the same rotation, kept on one side so the keys interpolate the short way
        quats.append(q)
        previous = q
    path = f'pose.bones["{_quoted(bone_name)}"].rotation_quaternion'
    for i in range(4):
        _key(action, arm, path, i, frames, [q[i] for q in quats], bone_name)


def _place_sound(scene, audio: str, start: int, frames: int) -> None:
    """The sound as a strip at ``start`` on the first channel free there (not twice)."""
    editor = scene.sequence_editor or scene.sequence_editor_create()
    for strip in _strips(editor):
        if (strip.type == "SOUND" and strip.sound is not None and int(round(strip.frame_start)) == start
                and os.path.abspath(bpy.path.abspath(strip.sound.filepath)) == audio):
            return
    end = start + max(frames, 1)
    busy = {s.channel for s in _strips(editor) if s.frame_final_start < end and s.frame_final_end > start}
    channel = next(c for c in range(1, 129) if c not in busy)
    _strips(editor, every=False).new_sound(os.path.basename(audio), audio, channel, start)
