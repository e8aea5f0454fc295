# Makes the test plants nobody here designed: Blender's own Sapling Tree Gen add-on grows them from its
# shipped presets (a maple and a bottlebrush bush) and from a grass-like setting of its parameters
# (many long thin leaves on a tiny stem); our part is only the materials (bark, and leaf cards cut by
# a texture's alpha) and the export to glTF binary beside this script.
#   blender -b --factory-startup --python assets/test_plants/make_test_plants.py
import ast
import math
import os

import addon_utils
import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
PRESETS = os.path.join(os.path.dirname(addon_utils.modules()[0].__file__), "add_curve_sapling", "presets")

# name: (preset file or None, overrides of Sapling's parameters, leaf colour, bark colour)
PLANTS = {
    "maple_tree": ("small_maple.py", {
            "leaves": 10, "seed": 3, "bevelRes": 0, "resU": 1, "branches": (0, 36, 10, 6),
            "curveRes": (6, 3, 2, 1),
        }, (0.22, 0.42, 0.10), (0.30, 0.22, 0.15)),
    "bottlebrush_bush": ("callistemon.py", {
            "scale": 1.2, "scaleV": 0.1, "seed": 5, "bevelRes": 0, "resU": 1, "leaves": 60,
            "curveRes": (6, 3, 2, 1),
        }, (0.18, 0.36, 0.12), (0.35, 0.25, 0.18)),
    "grass_clump": (
        None,
        {
            "levels": 1, "scale": 0.5, "scaleV": 0.0, "length": (1.0, 0.3, 0.6, 0.45), "ratio": 0.004,
            "branches": (0, 0, 0, 0), "leaves": 60, "leafScale": 0.35, "leafScaleX": 0.08, "leafShape": "rect",
            "leafDownAngle": 20.0, "leafDownAngleV": 15.0, "leafRotate": 137.5, "leafRotateV": 40.0,
            "leafDist": "4", "leafScaleT": 0.0, "leafScaleV": 0.3, "baseSize": 0.02, "showLeaves": True,
            "bevel": True, "seed": 7, "horzLeaves": False,
        },
        (0.30, 0.50, 0.14),
        (0.30, 0.45, 0.14),
    ),
}


def preset(file_name):
    with open(os.path.join(PRESETS, file_name)) as preset_file:
        for line in preset_file:
            if line.strip() and not line.startswith("#"):
                return ast.literal_eval(line)
    raise RuntimeError("no settings in " + file_name)


def leaf_image(name, colour):
    """A leaf card's texture: an ellipse of the leaf colour with a midrib, clear around it."""
    size = 64
    image = bpy.data.images.new(name, size, size, alpha=True)
    pixels = []
    for y in range(size):
        for x in range(size):
            u = (x + 0.5) / size * 2.0 - 1.0
            v = (y + 0.5) / size
            half_width = 0.9 * math.sin(math.pi * v)  # pointed at both ends
            inside = abs(u) < half_width
            shade = 0.75 if abs(u) < 0.06 else 1.0
            pixels += [colour[0] * shade, colour[1] * shade, colour[2] * shade, 1.0 if inside else 0.0]
    image.pixels = pixels
    image.pack()
    return image


def material(name, colour, image=None):
    made = bpy.data.materials.new(name)
    made.use_nodes = True
    shader = made.node_tree.nodes["Principled BSDF"]
    shader.inputs["Base Color"].default_value = (*colour, 1.0)
    shader.inputs["Roughness"].default_value = 0.8
    if image is not None:
        texture = made.node_tree.nodes.new("ShaderNodeTexImage")
        texture.image = image
        made.node_tree.links.new(texture.outputs["Color"], shader.inputs["Base Color"])
        made.node_tree.links.new(texture.outputs["Alpha"], shader.inputs["Alpha"])
        made.blend_method = "CLIP"
        made.alpha_threshold = 0.5
        made.use_backface_culling = False
    return made


def make(name, preset_file, overrides, leaf_colour, bark_colour):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    addon_utils.enable("add_curve_sapling", default_set=True)
    settings = preset(preset_file) if preset_file else {}
    settings.update(overrides)
    settings.pop("limitImport", None)
    bpy.ops.curve.tree_add(**settings)
    bark = material(name + "_bark", bark_colour)
    leaves = material(name + "_leaves", leaf_colour, leaf_image(name + "_leaf", leaf_colour))
    for obj in list(bpy.data.objects):
        if obj.type == "CURVE":
            bpy.ops.object.select_all(action="DESELECT")
            obj.select_set(True)
            bpy.context.view_layer.objects.active = obj
            bpy.ops.object.convert(target="MESH")
            obj = bpy.context.view_layer.objects.active
            obj.name = "Trunk"
            obj.data.materials.clear()
            obj.data.materials.append(bark)
        elif obj.type == "MESH":
            obj.name = "Leaves"
            obj.data.materials.clear()
            obj.data.materials.append(leaves)
    path = os.path.join(HERE, name + ".glb")
    bpy.ops.export_scene.gltf(filepath=path, export_format="GLB", export_apply=True, export_yup=True)
    counts = {
        obj.name: sum(len(p.vertices) - 2 for p in obj.data.polygons) for obj in bpy.data.objects if obj.type == "MESH"
    }
    print("test plant: %s, triangles %s, %d bytes" % (path, counts, os.path.getsize(path)))


for plant_name, (preset_name, changes, leaf, wood) in PLANTS.items():
    make(plant_name, preset_name, changes, leaf, wood)
