"""The add-on's preference (the facesynth executable), the scene's facesynth settings and the
panel: View3D > Sidebar > facesynth."""

from __future__ import annotations

import bpy
from bpy.props import CollectionProperty, EnumProperty, IntProperty, PointerProperty, StringProperty

from . import core
from .operators import _METHOD_ITEMS, ADDON


class FacesynthPreferences(bpy.types.AddonPreferences):
    bl_idname = ADDON

    facesynth_executable: StringProperty(
        name="facesynth executable", subtype="FILE_PATH",
        description="The facesynth command of the environment where facesynth is installed, e.g. "
                    "/path/to/facesynth/.venv/bin/facesynth (empty: 'facesynth' on the PATH)")

    def draw(self, context):
        layout = self.layout
        layout.prop(self, "facesynth_executable")
        layout.label(text="Blender's Python needs none of facesynth's packages: the add-on runs this command.")


class FacesynthMappingItem(bpy.types.PropertyGroup):
    arkit: StringProperty(name="ARKit", description="An ARKit shape name, e.g. jawOpen")
    shape_keys: StringProperty(name="Shape keys", description="The mesh's shape key(s) it drives, joined by '+' "
                                                              "(empty: leave it unkeyed)")


class FacesynthSettings(bpy.types.PropertyGroup):
    """What the panel holds for the operator (``scene.facesynth``)."""

    audio_source: EnumProperty(name="Sound from", items=[("FILE", "File", "A sound file (WAV, FLAC, M4A, MP3, Opus, "
                                                                          "...) or a video with sound"),
                                                         ("STRIP", "Sound strip", "A sound strip of the sequencer")])
    audio: StringProperty(name="Sound file", subtype="FILE_PATH")
    sound_strip: StringProperty(name="Sound strip")
    text: StringProperty(name="Text", description="What is said (empty: recognised from the speech)")
    language: StringProperty(name="Language",
                             description="What language is spoken, a BCP-47 tag: en, de, fr, es, cmn... (empty: English)")
    emotion_source: EnumProperty(name="Emotions", items=[
        ("NONE", "Neutral", "No emotion spans: neutral speech"),
        ("MARKERS", "Timeline markers", "Markers named happy, angry, sad or neutral start a span each"),
        ("FILE", "Spans file", "A file of 'start_s end_s emotion' lines (or a TextGrid with an 'emotions' tier)")])
    emotions_file: StringProperty(name="Spans file", subtype="FILE_PATH")
    database: StringProperty(name="Database", subtype="FILE_PATH",
                             description="facesynth's motion database (db.h5) or a model fitted on it")
    method: EnumProperty(name="Method", items=_METHOD_ITEMS, default="dp")
    rig: StringProperty(name="Rig", subtype="FILE_PATH",
                        description="Solve onto this rig (empty: facesynth's built-in ARKit-named rig)")
    binding: StringProperty(name="Binding", subtype="FILE_PATH", description="The markers' binding on that rig")
    armature: PointerProperty(name="Armature", type=bpy.types.Object,
                              poll=lambda self, obj: obj.type == "ARMATURE",
                              description="The armature of the head bone (empty: no head rotation)")
    bone: StringProperty(name="Head bone")
    mapping: CollectionProperty(type=FacesynthMappingItem)
    mapping_index: IntProperty()

    def operator_values(self) -> dict:
        """The operator's properties as this panel sets them."""
        values = {"text": self.text, "language": self.language, "database": self.database, "method": self.method, "rig": self.rig,
                  "binding": self.binding, "armature": self.armature.name if self.armature else "",
                  "bone": self.bone if self.armature else "",
                  "mapping": ", ".join(f"{m.arkit}={m.shape_keys}" for m in self.mapping if m.arkit.strip())}
        if self.audio_source == "STRIP":
            values.update(audio="", sound_strip=self.sound_strip)
        else:
            values.update(audio=self.audio, sound_strip="")
        values["emotions"] = {"NONE": "", "MARKERS": "markers", "FILE": self.emotions_file}[self.emotion_source]
        return values


class FACESYNTH_UL_mapping(bpy.types.UIList):
    def draw_item(self, context, layout, data, item, icon, active_data, active_propname, index):
        row = layout.row(align=True)
        row.prop(item, "arkit", text="", emboss=False)
        row.prop(item, "shape_keys", text="", emboss=False)


class FACESYNTH_OT_mapping_add(bpy.types.Operator):
    """Add a row to the mapping table (an ARKit name and the shape keys it drives)"""

    bl_idname = "facesynth.mapping_add"
    bl_label = "Add mapping"
    bl_options = {"UNDO", "INTERNAL"}

    def execute(self, context):
        settings = context.scene.facesynth
        item = settings.mapping.add()
        item.arkit = "jawOpen"
        settings.mapping_index = len(settings.mapping) - 1
        return {"FINISHED"}


class FACESYNTH_OT_mapping_remove(bpy.types.Operator):
    """Remove the selected row of the mapping table"""

    bl_idname = "facesynth.mapping_remove"
    bl_label = "Remove mapping"
    bl_options = {"UNDO", "INTERNAL"}

    def execute(self, context):
        settings = context.scene.facesynth
        if 0 <= settings.mapping_index < len(settings.mapping):
            settings.mapping.remove(settings.mapping_index)
            settings.mapping_index = min(settings.mapping_index, len(settings.mapping) - 1)
        return {"FINISHED"}


class FACESYNTH_PT_panel(bpy.types.Panel):
    bl_label = "facesynth"
    bl_idname = "FACESYNTH_PT_panel"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "facesynth"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        settings = context.scene.facesynth
        obj = context.active_object

        col = layout.column()
        col.prop(settings, "audio_source", expand=True)
        if settings.audio_source == "STRIP":
            if context.scene.sequence_editor is not None:
                editor = context.scene.sequence_editor
                every = "strips_all" if hasattr(editor, "strips_all") else "sequences_all"  # renamed in 4.4
                col.prop_search(settings, "sound_strip", editor, every, text="Strip")
            else:
                col.label(text="The scene has no sound strips.", icon="INFO")
        else:
            col.prop(settings, "audio", text="Sound")
        col.prop(settings, "text")
        col.prop(settings, "language")

        col = layout.column()
        col.prop(settings, "emotion_source")
        if settings.emotion_source == "FILE":
            col.prop(settings, "emotions_file", text="File")
        elif settings.emotion_source == "MARKERS":
            named = [m.name for m in context.scene.timeline_markers if m.name.strip().lower() in core.EMOTIONS]
            col.label(text=f"{len(named)} emotion markers" if named else "No marker named by an emotion yet",
                      icon="MARKER_HLT")

        col = layout.column()
        col.prop(settings, "database")
        col.prop(settings, "method")

        box = layout.box()
        box.label(text="Face", icon="SHAPEKEY_DATA")
        if obj is not None and obj.type == "MESH" and obj.data.shape_keys is not None:
            count = len(obj.data.shape_keys.key_blocks) - 1
            box.label(text=f"{obj.name}: {count} shape key{'' if count == 1 else 's'}")
        else:
            box.label(text="Select a mesh with ARKit-named shape keys", icon="ERROR")
        box.prop(settings, "armature")
        if settings.armature is not None and settings.armature.type == "ARMATURE":
            box.prop_search(settings, "bone", settings.armature.data, "bones", text="Head bone")
        sub = box.column(align=True)
        sub.label(text="Mapping (ARKit name = shape keys)")
        row = sub.row()
        row.template_list("FACESYNTH_UL_mapping", "", settings, "mapping", settings, "mapping_index", rows=2)
        buttons = row.column(align=True)
        buttons.operator("facesynth.mapping_add", icon="ADD", text="")
        buttons.operator("facesynth.mapping_remove", icon="REMOVE", text="")

        sub = layout.column()
        sub.prop(settings, "rig")
        if settings.rig:
            sub.prop(settings, "binding")

        layout.separator()
        layout.operator("facesynth.animate", icon="PLAY_SOUND")
        scene = context.scene
        start = f"frame {scene.frame_current}"
        if settings.audio_source == "STRIP" and scene.sequence_editor is not None:
            editor = scene.sequence_editor
            strips = editor.strips_all if hasattr(editor, "strips_all") else editor.sequences_all
            strip = strips.get(settings.sound_strip)
            if strip is not None:
                start = f"frame {int(round(strip.frame_start))} (the strip)"
        layout.label(text=f"From {start}, {scene.render.fps / scene.render.fps_base:g} fps")
