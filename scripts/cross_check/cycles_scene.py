"""blender -b --python cycles_scene.py -- SCENE.json OUT.exr SPP SEED [normal]

Renders an iblkit scene (.json, docs/scene-format.md) with Blender Cycles, the comparison path
tracer of scripts/cross_check.sh. The subset it reads: `shape: sphere` models and glTF models
(no transforms), the ground (height, size, Lambert material), an explicit camera, the width and
height, the environment (file, rotation, intensity). The materials that both tracers define the
same way, and nothing else (anything else stops the script):

| iblkit (glTF) material                         | Cycles                                 |
| ---------------------------------------------- | -------------------------------------- |
| metallic 0, specular 0, roughness 1 (Lambert)  | Diffuse BSDF, roughness 0              |
| metallic 1, white base colour (F = 1), rough r | Glossy BSDF, GGX (Sharp at r = 0), r   |
| a glTF file's Lambert with textures            | the importer's texture and normal map  |
|                                                | nodes into a Diffuse BSDF              |

Cycles settings that would make it differ from an unbiased estimate are off: clamping, filter
glossy, adaptive sampling, denoising, the shadow terminator offsets; every bounce kind 63 (iblkit
--max-depth 64); the pixel filter a 1-pixel box (iblkit's default). `normal` writes Cycles'
normal pass instead of the image.
"""
import json
import math
import os
import sys

import bpy
import mathutils
import numpy as np

if not hasattr(np, "bool"):
    np.bool = bool  # Blender 3.4's glTF importer predates numpy 1.24

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_io import arguments  # noqa: E402

args = arguments()
scene_path, out_path, spp, seed = args[0], args[1], int(args[2]), int(args[3])
normal_pass = len(args) > 4 and args[4] == "normal"
J = json.load(open(scene_path))
base = os.path.dirname(os.path.abspath(scene_path))


def blender(v):
    """glTF's +Y up to Blender's +Z up, as Blender's glTF importer converts: (x, y, z) -> (x, -z, y)."""
    return mathutils.Vector((v[0], -v[2], v[1]))


s = bpy.context.scene
for o in list(bpy.data.objects):
    bpy.data.objects.remove(o)
s.render.engine = "CYCLES"
c = s.cycles
c.device = "CPU"
c.samples = spp
c.seed = seed
c.use_adaptive_sampling = False
c.use_denoising = False
c.max_bounces = c.diffuse_bounces = c.glossy_bounces = 63
c.transparent_max_bounces = 0
c.sample_clamp_direct = c.sample_clamp_indirect = 0
c.blur_glossy = 0
c.caustics_reflective = c.caustics_refractive = True
c.pixel_filter_type = "BOX"
c.filter_width = 1.0
s.view_layers[0].cycles.use_denoising = False
s.render.threads_mode = "FIXED"
s.render.threads = os.cpu_count() or 1
s.view_settings.view_transform = "Standard"
s.view_settings.look = "None"
s.render.resolution_x = J.get("width", 960)
s.render.resolution_y = J.get("height", 540)
s.render.resolution_percentage = 100
s.render.image_settings.file_format = "OPEN_EXR"
s.render.image_settings.color_depth = "32"


def new_material(m):
    mat = bpy.data.materials.new("m")
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        if n.type != "OUTPUT_MATERIAL":
            nt.nodes.remove(n)
    output = [n for n in nt.nodes if n.type == "OUTPUT_MATERIAL"][0]
    colour = list(m.get("baseColor", [0.5, 0.5, 0.5]))
    metallic, roughness, specular = m.get("metallic", 0.0), m.get("roughness", 1.0), m.get("specular", 1.0)
    if metallic == 0 and specular == 0 and roughness == 1:
        bsdf = nt.nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Roughness"].default_value = 0
    elif metallic == 1 and colour == [1, 1, 1]:
        bsdf = nt.nodes.new("ShaderNodeBsdfGlossy")
        bsdf.distribution = "SHARP" if roughness == 0 else "GGX"
        bsdf.inputs["Roughness"].default_value = roughness
    else:
        raise SystemExit("cycles_scene.py: %s: material %r has no exact Cycles twin" % (scene_path, m))
    bsdf.inputs["Color"].default_value = (*colour, 1)
    nt.links.new(bsdf.outputs[0], output.inputs["Surface"])
    return mat


def lambert_from_importer(obj):
    """The importer's Principled BSDF replaced by a Diffuse BSDF fed by its base colour and normal inputs."""
    for slot in obj.material_slots:
        nt = slot.material.node_tree
        principled = [n for n in nt.nodes if n.type == "BSDF_PRINCIPLED"][0]
        diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Roughness"].default_value = 0
        diffuse.inputs["Color"].default_value = principled.inputs["Base Color"].default_value
        for source, target in (("Base Color", "Color"), ("Normal", "Normal")):
            if principled.inputs[source].links:
                nt.links.new(principled.inputs[source].links[0].from_socket, diffuse.inputs[target])
        output = [n for n in nt.nodes if n.type == "OUTPUT_MATERIAL"][0]
        nt.links.new(diffuse.outputs[0], output.inputs["Surface"])


lowest = math.inf
for model in J["models"]:
    if any(k in model for k in ("translation", "rotation", "scale")):
        raise SystemExit("cycles_scene.py: %s: model transforms are not read" % scene_path)
    if "file" in model:
        over = model.get("material", {})
        if not (over.get("metallic") == 0 and over.get("specular") == 0 and over.get("roughness") == 1):
            raise SystemExit("cycles_scene.py: %s: a glTF model must be overridden to Lambert" % scene_path)
        bpy.ops.import_scene.gltf(filepath=os.path.join(base, model["file"]))
        for o in bpy.context.selected_objects:
            if o.type == "MESH":
                lambert_from_importer(o)
                o.cycles.shadow_terminator_geometry_offset = 0.0
                lowest = min(lowest, min((o.matrix_world @ v.co).z for v in o.data.vertices))
        continue
    if model.get("shape") != "sphere":
        raise SystemExit("cycles_scene.py: %s: only shape sphere and glTF files" % scene_path)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=192, ring_count=96, radius=1)
    o = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    o.data.use_auto_smooth = True
    o.data.normals_split_custom_set_from_vertices([v.co.normalized() for v in o.data.vertices])  # exact normals
    o.data.materials.append(new_material(model.get("material", {})))
    o.cycles.shadow_terminator_geometry_offset = 0.0
    o.cycles.shadow_terminator_offset = 0.0
    lowest = min(lowest, -1.0)

ground = J.get("ground", {})
if ground.get("enabled", False):
    if "size" not in ground:
        raise SystemExit("cycles_scene.py: %s: give ground.size" % scene_path)
    bpy.ops.mesh.primitive_plane_add(size=ground["size"], location=(0, 0, ground.get("height", lowest)))
    o = bpy.context.active_object
    m = {"baseColor": [0.5, 0.5, 0.5], "metallic": 0, "roughness": 1, "specular": 1}
    m.update(ground.get("material", {}))
    o.data.materials.append(new_material(m))
    o.cycles.shadow_terminator_geometry_offset = 0.0

cam = J["camera"]
camera = bpy.data.cameras.new("camera")
camera.sensor_fit = "VERTICAL"
camera.angle_y = math.radians(cam.get("yfov", 45))
camera.clip_start, camera.clip_end = 1e-3, 1e5
co = bpy.data.objects.new("camera", camera)
s.collection.objects.link(co)
s.camera = co
position, target = blender(cam["position"]), blender(cam["target"])
if blender(cam.get("up", [0, 1, 0])) != mathutils.Vector((0, 0, 1)):
    raise SystemExit("cycles_scene.py: %s: only up = +Y" % scene_path)
co.location = position
co.rotation_mode = "QUATERNION"
co.rotation_quaternion = (target - position).to_track_quat("-Z", "Y")

env = J["environment"]
world = bpy.data.worlds.new("world")
s.world = world
world.use_nodes = True
nt = world.node_tree
background = nt.nodes["Background"]
background.inputs["Strength"].default_value = env.get("intensity", 1)
texture = nt.nodes.new("ShaderNodeTexEnvironment")
texture.image = bpy.data.images.load(os.path.join(base, env["file"]))
texture.interpolation = "Linear"
coordinates = nt.nodes.new("ShaderNodeTexCoord")
mapping = nt.nodes.new("ShaderNodeMapping")
mapping.vector_type = "VECTOR"
# Cycles' lat-long map has +X (Blender) at its centre column and +Y a quarter to the left; iblkit's
# (docs/conventions.md) has +Z (glTF) = -Y (Blender) at the centre and +X a quarter to the left: a
# quarter turn about Blender's +Z (glTF's +Y). iblkit looks the map up at R_y(-rotation) d, so the
# environment's rotation turns the lookup the other way.
mapping.inputs["Rotation"].default_value = (0, 0, math.pi / 2 - math.radians(env.get("rotation", 0)))
nt.links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
nt.links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
nt.links.new(texture.outputs["Color"], background.inputs["Color"])
world.cycles.sampling_method = "MANUAL"
world.cycles.sample_map_resolution = max(1024, texture.image.size[0])  # the map's own texels, a small sun too

if normal_pass:
    s.view_layers[0].use_pass_normal = True
    s.use_nodes = True
    layers = [n for n in s.node_tree.nodes if n.type == "R_LAYERS"][0]
    composite = [n for n in s.node_tree.nodes if n.type == "COMPOSITE"][0]
    s.node_tree.links.new(layers.outputs["Normal"], composite.inputs["Image"])
s.render.filepath = out_path
bpy.ops.render.render(write_still=True)
