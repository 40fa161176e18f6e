"""facesynth for Blender: lip-synced facial animation from a sound, keyed on a mesh's ARKit-named
shape keys (and a head bone) by running the facesynth command of the environment where
facesynth is installed. See docs/blender.md."""

bl_info = {
    "name": "facesynth",
    "author": "facesynth",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > facesynth",
    "description": "Lip-synced, expressive facial animation from speech, keyed on ARKit-named shape keys",
    "category": "Animation",
}

if "bpy" in locals():  # Blender's "Reload Scripts": pick up edited modules
    import importlib

    importlib.reload(core)  # noqa: F821
    importlib.reload(operators)  # noqa: F821
    importlib.reload(ui)  # noqa: F821

import bpy  # noqa: E402

from . import core, operators, ui  # noqa: E402, F401

_CLASSES = (ui.FacesynthPreferences, ui.FacesynthMappingItem, ui.FacesynthSettings, ui.FACESYNTH_UL_mapping,
            ui.FACESYNTH_OT_mapping_add, ui.FACESYNTH_OT_mapping_remove, operators.FACESYNTH_OT_animate,
            ui.FACESYNTH_PT_panel)


def register():
    for cls in _CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.facesynth = bpy.props.PointerProperty(type=ui.FacesynthSettings)


def unregister():
    del bpy.types.Scene.facesynth
    for cls in reversed(_CLASSES):
        bpy.utils.unregister_class(cls)
