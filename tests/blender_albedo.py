"""Blender's picture of a rigged file's own colours, for tests/colour_figures.py.
Run by Blender: blender -b --factory-startup --python tests/blender_albedo.py -- RIG OUT.png [WxH]

The file is imported by Blender's own importer (glTF, FBX or COLLADA), in its
rest pose; every material is made to emit what its base colour input
carries (the factor, the texture, the vertex colours, as the importer wired
them) with no light and no shading, so the picture is the materials' colours
as Blender understands them. Rendered by Cycles on the CPU (no GPU needed),
the background transparent, the colours sRGB as stored (the Standard view
transform), from the front, orthographic, the whole body in the frame."""
import math
import sys

import bpy
import numpy as np
from mathutils import Vector

np.bool = bool  # Debian 12's numpy under Blender 3.4's glTF importer

args = sys.argv[sys.argv.index("--") + 1:]
rig, out = args[0], args[1]
width, height = (int(v) for v in (args[2] if len(args) > 2 else "540x960").split("x"))

bpy.ops.wm.read_factory_settings(use_empty=True)
lower = rig.lower()
if lower.endswith((".glb", ".gltf")):
    bpy.ops.import_scene.gltf(filepath=rig)
elif lower.endswith(".fbx"):
    bpy.ops.import_scene.fbx(filepath=rig)
elif lower.endswith(".dae"):
    bpy.ops.wm.collada_import(filepath=rig)
else:
    sys.exit("blender_albedo.py: %s: not glTF, FBX or COLLADA" % rig)


def emit_base_colour(mat):
    """The material's surface replaced by an emission of its base colour."""
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
    output = next((n for n in nodes if n.type == "OUTPUT_MATERIAL"), None) or nodes.new("ShaderNodeOutputMaterial")
    emit = nodes.new("ShaderNodeEmission")
    if bsdf is None:
        emit.inputs["Color"].default_value = tuple(mat.diffuse_color)
    else:
        base = bsdf.inputs["Base Color"]
        if base.is_linked:
            links.new(base.links[0].from_socket, emit.inputs["Color"])
        else:
            emit.inputs["Color"].default_value = base.default_value
    links.new(emit.outputs["Emission"], output.inputs["Surface"])


meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
for o in meshes:
    for slot in o.material_slots:
        if slot.material:
            emit_base_colour(slot.material)

depsgraph = bpy.context.evaluated_depsgraph_get()
lo, hi = Vector((math.inf,) * 3), Vector((-math.inf,) * 3)
for o in meshes:
    ev = o.evaluated_get(depsgraph)
    for corner in ev.bound_box:
        p = ev.matrix_world @ Vector(corner)
        lo = Vector(map(min, lo, p))
        hi = Vector(map(max, hi, p))
if not meshes or lo.x > hi.x:
    sys.exit("blender_albedo.py: %s: no mesh" % rig)

scene = bpy.context.scene
cam_data = bpy.data.cameras.new("front")
cam_data.type = "ORTHO"
size = hi - lo
aspect = width / height
# the orthographic scale spans the frame's longer side
if aspect <= 1:
    cam_data.ortho_scale = 1.08 * max(size.z, size.x / aspect)
else:
    cam_data.ortho_scale = 1.08 * max(size.x, size.z * aspect)
cam = bpy.data.objects.new("front", cam_data)
scene.collection.objects.link(cam)
centre = (lo + hi) / 2
# glTF's front (+Z) is Blender's -Y: the camera stands in front, looking back
cam.location = (centre.x, lo.y - 10 * max(size), centre.z)
cam.rotation_euler = (math.pi / 2, 0, 0)
cam_data.clip_end = 40 * max(size)
scene.camera = cam

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 8
scene.cycles.use_denoising = False
scene.render.film_transparent = True
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_mode = "RGBA"
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
