"""Run inside Blender by test_blender_addon.py: ``blender -b --factory-startup --python
blender_scene.py -- job.json``. Installs and enables the add-on from its zip, builds the face
(a mesh with ARKit-named shape keys, from the arrays the test wrote) and a head bone, runs
``bpy.ops.facesynth.animate`` on a sentence, then the failures the test asks for, and writes
what it finds (keyframes, posed head, sound strips, reports, a render) to the job's result file.

Blender's own Python has no numpy: arrays travel as raw float32/int32 files read with ``array``.
"""

from __future__ import annotations

import json
import sys
import time
import traceback
from array import array

import addon_utils
import bpy
from mathutils import Vector


def load(path: str, code: str) -> array:
    data = array(code)
    with open(path, "rb") as fh:
        data.frombytes(fh.read())
    return data


def build_face(job: dict):
    """The mesh: the rest vertices and triangles, a basis and one shape key per name (its
    vertices = rest + delta), in Blender's axes (the test converted them)."""
    mesh = bpy.data.meshes.new("Face")
    verts, faces = load(job["vertices"], "f"), load(job["faces"], "i")
    n, f = len(verts) // 3, len(faces) // 3
    mesh.vertices.add(n)
    mesh.vertices.foreach_set("co", verts)
    mesh.loops.add(3 * f)
    mesh.loops.foreach_set("vertex_index", faces)
    mesh.polygons.add(f)
    mesh.polygons.foreach_set("loop_start", array("i", range(0, 3 * f, 3)))
    mesh.polygons.foreach_set("loop_total", array("i", [3]) * f)
    mesh.polygons.foreach_set("use_smooth", array("b", [1]) * f)
    mesh.update()
    mesh.validate()
    obj = bpy.data.objects.new("Face", mesh)
    bpy.context.scene.collection.objects.link(obj)
    obj.shape_key_add(name="Basis", from_mix=False)
    shapes = load(job["shapes"], "f")
    size = 3 * n
    for i, name in enumerate(job["shape_names"]):
        key = obj.shape_key_add(name=name, from_mix=False)
        key.data.foreach_set("co", shapes[i * size:(i + 1) * size])
    return obj


def build_head_bone(job: dict):
    """An armature with one bone 'head' leaning forward and rolled, so that its rest frame is not
    the armature's."""
    data = bpy.data.armatures.new("Rig")
    arm = bpy.data.objects.new("Rig", data)
    bpy.context.scene.collection.objects.link(arm)
    bpy.context.view_layer.objects.active = arm
    bpy.ops.object.mode_set(mode="EDIT")
    bone = data.edit_bones.new("head")
    bone.head, bone.tail, bone.roll = job["bone_head"], job["bone_tail"], job["bone_roll"]
    bpy.ops.object.mode_set(mode="OBJECT")
    return arm


def snapshot(scene, face, arm) -> dict:
    """Every keyframe of the face's shape keys and of the armature, and the sound strips."""
    out = {"shape_keys": {}, "bone": {}, "strips": []}
    key = face.data.shape_keys
    if key.animation_data and key.animation_data.action:
        for fc in key.animation_data.action.fcurves:
            name = fc.data_path.split('"')[1]
            out["shape_keys"][name] = [list(p.co) for p in fc.keyframe_points]
    if arm.animation_data and arm.animation_data.action:
        for fc in arm.animation_data.action.fcurves:
            out["bone"][f"{fc.data_path}[{fc.array_index}]"] = [list(p.co) for p in fc.keyframe_points]
    if scene.sequence_editor:
        out["strips"] = [{"name": s.name, "type": s.type, "frame_start": s.frame_start, "channel": s.channel,
                          "frame_final_end": s.frame_final_end,
                          "filepath": bpy.path.abspath(s.sound.filepath) if s.type == "SOUND" else ""}
                         for s in scene.sequence_editor.sequences_all]
    return out


def posed_head(scene, arm, frames) -> dict:
    """Per frame the head bone's rotation in the armature's space, relative to its rest:
    pose matrix @ rest matrix^-1 (3x3, rows)."""
    bone, pose_bone = arm.data.bones["head"], arm.pose.bones["head"]
    rest_inv = bone.matrix_local.to_3x3().inverted()
    out = {}
    for frame in frames:
        scene.frame_set(int(frame))
        m = pose_bone.matrix.to_3x3() @ rest_inv
        out[str(int(frame))] = [list(row) for row in m]
    return out


def call(**kwargs) -> dict:
    """The operator's result, or the report Blender raises for an ERROR (a RuntimeError whose
    text is the report), or anything else raised (which the test rejects)."""
    started = time.perf_counter()
    try:
        result = bpy.ops.facesynth.animate(**kwargs)
        return {"result": sorted(result), "seconds": time.perf_counter() - started}
    except RuntimeError as exc:
        return {"report": str(exc), "seconds": time.perf_counter() - started}
    except Exception as exc:
        return {"raised": f"{type(exc).__name__}: {exc}", "traceback": traceback.format_exc()}


def pixel_stats(path: str) -> dict:
    image = bpy.data.images.load(path)
    width, height = image.size
    pixels = array("f", [0.0]) * (width * height * 4)
    image.pixels.foreach_get(pixels)
    grey = [0.299 * pixels[i] + 0.587 * pixels[i + 1] + 0.114 * pixels[i + 2] for i in range(0, len(pixels), 4)]
    mean = sum(grey) / len(grey)
    spread = (sum((g - mean) ** 2 for g in grey) / len(grey)) ** 0.5
    return {"width": width, "height": height, "mean": mean, "std": spread}


def label(scene, text: str, location, size: float) -> None:
    curve = bpy.data.curves.new(text, "FONT")
    curve.body, curve.size, curve.align_x = text, size, "CENTER"
    obj = bpy.data.objects.new(text, curve)
    obj.location, obj.rotation_euler = location, (1.5708, 0.0, 0.0)  # upright, facing -Y
    scene.collection.objects.link(obj)


def render(scene, face, frame: int, path: str) -> dict:
    """The keyed face at ``frame`` beside the same face at rest, from the front (Workbench, studio
    light; Cycles on the CPU where Workbench cannot draw)."""
    scene.frame_set(frame)
    corners = [face.matrix_world @ v.co for v in face.data.vertices]
    lo = [min(c[i] for c in corners) for i in range(3)]
    hi = [max(c[i] for c in corners) for i in range(3)]
    width, height = hi[0] - lo[0], hi[2] - lo[2]
    rest = face.copy()
    rest.data = face.data.copy()
    rest.data.shape_keys.animation_data_clear()
    for key in rest.data.shape_keys.key_blocks:
        key.value = 0.0
    rest.location.x -= 1.05 * width
    scene.collection.objects.link(rest)
    centre = Vector((lo[0] + 0.5 * width - 0.525 * width, 0.5 * (lo[1] + hi[1]), lo[2] + 0.6 * height))
    for text, x in (("rest", rest.location.x), (f"keyed, frame {frame}", 0.0)):
        label(scene, text, (x, lo[1] - 0.01, centre.z - 0.42 * height), 0.03 * height / 0.34)
    cam_data = bpy.data.cameras.new("Camera")
    cam_data.type = "ORTHO"
    cam_data.ortho_scale = 2.05 * width
    cam = bpy.data.objects.new("Camera", cam_data)
    scene.collection.objects.link(cam)
    cam.location = centre + Vector((0.0, -3.0 * height, 0.0))  # the faces look toward -Y
    cam.rotation_euler = (centre - cam.location).to_track_quat("-Z", "Y").to_euler()
    scene.camera = cam
    scene.render.resolution_x, scene.render.resolution_y = 560, 340
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.compression = 100
    scene.render.filepath = path
    engines = []
    try:
        scene.render.engine = "BLENDER_WORKBENCH"
        shading = scene.display.shading
        shading.light, shading.color_type = "STUDIO", "SINGLE"
        shading.single_color = (0.80, 0.62, 0.52)
        shading.show_cavity = True
        scene.display.render_aa = "8"
        bpy.ops.render.render(write_still=True)
        engines.append("BLENDER_WORKBENCH")
    except RuntimeError as exc:
        engines.append(f"BLENDER_WORKBENCH failed: {exc}")
        scene.render.engine = "CYCLES"
        scene.cycles.device, scene.cycles.samples, scene.cycles.use_denoising = "CPU", 16, False
        light = bpy.data.objects.new("Light", bpy.data.lights.new("Light", "SUN"))
        scene.collection.objects.link(light)
        light.rotation_euler = (1.1, 0.0, -0.4)
        bpy.ops.render.render(write_still=True)
        engines.append("CYCLES")
    return {"path": path, "frame": frame, "engines": engines, **pixel_stats(path)}


def main() -> None:
    job = json.loads(open(sys.argv[sys.argv.index("--") + 1], encoding="utf-8").read())
    result: dict = {"blender": bpy.app.version_string}
    timings = {}
    started = time.perf_counter()

    bpy.ops.preferences.addon_install(filepath=job["zip"])
    addon_utils.enable("facesynth_blender", default_set=True, handle_error=None)
    prefs = bpy.context.preferences.addons["facesynth_blender"].preferences
    prefs.facesynth_executable = job["facesynth"]
    result["addon_file"] = sys.modules["facesynth_blender"].__file__
    timings["enable"] = time.perf_counter() - started

    scene = bpy.context.scene
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    scene.render.fps, scene.render.fps_base = job["fps"], 1.0
    face = build_face(job)
    arm = build_head_bone(job)
    bpy.context.view_layer.objects.active = face
    face.select_set(True)
    for name, frame in job["markers"]:
        scene.timeline_markers.new(name, frame=frame)
    scene.frame_current = job["frame_start"]
    timings["scene"] = time.perf_counter() - started - timings["enable"]

    result["animate"] = call(audio=job["audio"], text=job["text"], database=job["database"], method=job["method"],
                             emotions="markers", armature=arm.name, bone="head", mapping=job["mapping"],
                             work_dir=job["work_dir"])
    result["after"] = snapshot(scene, face, arm)
    frames = sorted({int(p[0]) for points in result["after"]["bone"].values() for p in points})
    result["head"] = posed_head(scene, arm, frames)
    result["rest"] = [list(row) for row in arm.data.bones["head"].matrix_local.to_3x3()]

    failures = {}
    prefs.facesynth_executable = job["missing_executable"]
    failures["missing_executable"] = call(audio=job["audio"], database=job["database"])
    prefs.facesynth_executable = job["facesynth"]
    failures["bad_audio"] = call(audio=job["bad_audio"], database=job["database"])
    failures["silent_video"] = call(audio=job["silent_video"], database=job["database"])
    bpy.context.view_layer.objects.active = arm
    failures["no_shape_keys"] = call(audio=job["audio"], database=job["database"])
    other = bpy.data.objects.new("Other", bpy.data.meshes.new("Other"))
    scene.collection.objects.link(other)
    other.shape_key_add(name="Basis")
    other.shape_key_add(name="Smile")
    bpy.context.view_layer.objects.active = other
    failures["no_arkit_names"] = call(audio=job["audio"], database=job["database"])
    bpy.data.objects.remove(other)
    bpy.context.view_layer.objects.active = face
    result["failures"] = failures
    result["after_failures"] = snapshot(scene, face, arm)

    jaw = result["after"]["shape_keys"].get(job["render_key"], [])
    frame = int(max(jaw, key=lambda p: p[1])[0]) if jaw else job["frame_start"]
    result["render"] = render(scene, face, frame, job["render"])

    # again from the sound strip the first run placed (its start, not the current frame), neutral
    [strip] = [s for s in scene.sequence_editor.sequences_all if s.type == "SOUND"]
    scene.frame_current = job["frame_start"] + 100
    result["from_strip"] = call(sound_strip=strip.name, text=job["text"], database=job["database"],
                                method=job["method"], mapping=job["mapping"], work_dir=job["strip_work_dir"])
    result["after_strip"] = snapshot(scene, face, arm)
    timings["total"] = time.perf_counter() - started
    result["timings"] = timings
    with open(job["result"], "w", encoding="utf-8") as fh:
        json.dump(result, fh)


if __name__ == "__main__":
    try:
        main()
    except Exception:
        traceback.print_exc()
        sys.exit(1)
