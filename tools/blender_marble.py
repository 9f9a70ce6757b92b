"""The Blender bridge: a marble design as a Principled BSDF material in Blender, veins kept.

    blender -b --factory-startup -P tools/blender_marble.py -- MODEL.glb \
        [--render OUT.png] [--width W --height H] [--samples N] [--threads T] [--save OUT.blend]

MODEL.glb comes from `marble export` (it carries the design in materials[0].extras.marble, every
key of a preset file, and mm_per_unit). The file is imported with Blender's own glTF importer
(what a user does); its material is then rebuilt as marble means it (docs/export.md, "Blender"):

- Base Color and Subsurface Color: the baked base colour texture (the veins), sRGB.
- Subsurface 1, method RANDOM_WALK, Subsurface Radius = 1 / sigma_tr per channel in metres (the
  .glb is in metres), sigma_tr = sqrt(3 sigma_a (sigma_a + sigma_s')) per mm (Jensen et al. 2001,
  eq. 5): the distance over which diffused light falls to 1/e, as in marble's `marble` mode and
  tools/cycles_reference.py.
- IOR and Subsurface IOR = ior; Specular = F0 / 0.08 with F0 = ((n-1)/(n+1))^2 (Blender's
  convention for the Principled BSDF); Specular Tint 0; Roughness = roughness (both perceptual).
- Metallic = metalness.

--render also sets up marble's default scene, in metres: camera at (0, 0.8, 4.2) marble units
looking at the origin with a 40 degree vertical field of view; a point light at (3, 3, 3) of the
power that gives marble's irradiance pi I (d0/d)^2 (tools/cycles_reference.py derives it), a dim
world that lights the stone (transparent in the picture); Cycles on the CPU, Standard view
transform, sRGB PNG with alpha.
"""
import json
import math
import os
import struct
import sys

import bpy
from mathutils import Matrix, Vector


def fail(msg):
    print("blender_marble: " + msg, file=sys.stderr)
    sys.exit(2)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    opts = {"render": None, "save": None, "width": 400, "height": 400, "samples": 32, "threads": 2}
    pos = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("--render", "--save", "--width", "--height", "--samples", "--threads"):
            if i + 1 >= len(argv):
                fail(a + " needs a value")
            v = argv[i + 1]
            opts[a[2:]] = v if a in ("--render", "--save") else int(v)
            i += 2
        else:
            pos.append(a)
            i += 1
    if len(pos) != 1:
        fail("usage: blender -b -P tools/blender_marble.py -- MODEL.glb [--render OUT.png] [--save OUT.blend]")
    return pos[0], opts


def glb_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if len(data) < 20 or data[:4] != b"glTF":
        fail(path + ": not a .glb file")
    length, kind = struct.unpack_from("<II", data, 12)
    if kind != 0x4E4F534A:
        fail(path + ": the first chunk is not JSON")
    return json.loads(data[20:20 + length].decode("utf-8"))


def marble_design(doc, path):
    for m in doc.get("materials", []):
        extras = m.get("extras", {})
        if "marble" in extras:
            return extras["marble"], float(extras.get("mm_per_unit", 100.0))
    fail(path + ": no marble design in materials[].extras (export it with `marble export`)")


def build_material(mat, design, mm_per_unit):
    """Rewires an imported material's node tree into marble's Principled BSDF."""
    nodes = mat.node_tree.nodes
    bsdf = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
    if bsdf is None:
        fail("the imported material has no Principled BSDF")
    base_image = None
    link = bsdf.inputs["Base Color"].links
    if link and link[0].from_node.type == "TEX_IMAGE":
        base_image = link[0].from_node
    if base_image is None:
        fail("the imported material has no base colour texture")
    links = mat.node_tree.links
    sa = design.get("sigma_a_mm", [0.0021, 0.0041, 0.0071])
    ss = design.get("sigma_s_mm", [2.19, 2.62, 3.0])
    sigma_tr_mm = [math.sqrt(3.0 * a * (a + s)) for a, s in zip(sa, ss)]
    radius_m = [1.0 / max(t, 1e-9) / 1000.0 for t in sigma_tr_mm]
    ior = float(design.get("ior", 1.55))
    f0 = ((ior - 1.0) / (ior + 1.0)) ** 2
    bsdf.subsurface_method = "RANDOM_WALK"
    bsdf.inputs["Subsurface"].default_value = 1.0
    links.new(base_image.outputs["Color"], bsdf.inputs["Subsurface Color"])
    bsdf.inputs["Subsurface Radius"].default_value = radius_m
    bsdf.inputs["Subsurface IOR"].default_value = ior
    bsdf.inputs["IOR"].default_value = ior
    bsdf.inputs["Specular"].default_value = f0 / 0.08
    bsdf.inputs["Specular Tint"].default_value = 0.0
    # The file's metallic-roughness texture holds the same constants; set them as values.
    for name in ("Roughness", "Metallic"):
        for l in list(bsdf.inputs[name].links):
            links.remove(l)
    bsdf.inputs["Roughness"].default_value = float(design.get("roughness", 0.12))
    bsdf.inputs["Metallic"].default_value = float(design.get("metalness", 0.0))
    # The importer maps transmission/volume extensions onto its own inputs; marble's light
    # transport is the subsurface above.
    if "Transmission" in bsdf.inputs:
        bsdf.inputs["Transmission"].default_value = 0.0
    return radius_m


def setup_scene(bs, mm_per_unit, opts):
    m = mm_per_unit / 1000.0  # metres per marble unit

    def to_blender(v):  # marble +Y up -> Blender +Z up, in metres
        return Vector((v[0] * m, -v[2] * m, v[1] * m))

    pos, target, up = to_blender([0.0, 0.8, 4.2]), to_blender([0.0, 0.0, 0.0]), Vector((0.0, 0.0, 1.0))
    fwd = (target - pos).normalized()
    right = fwd.cross(up).normalized()
    cup = right.cross(fwd)
    rot = Matrix((right, cup, -fwd)).transposed()
    cd = bpy.data.cameras.new("camera")
    cd.sensor_fit = "VERTICAL"
    cd.sensor_height = 24.0
    cd.angle_y = math.radians(40.0)
    cd.clip_start, cd.clip_end = 0.001, 100.0
    co = bpy.data.objects.new("camera", cd)
    co.matrix_world = Matrix.Translation(pos) @ rot.to_4x4()
    bs.collection.objects.link(co)
    bs.camera = co
    lpos = to_blender([3.0, 3.0, 3.0])
    ld = bpy.data.lights.new("light", "POINT")
    ld.energy = 4.0 * math.pi ** 2 * lpos.length_squared  # intensity 1 (tools/cycles_reference.py)
    ld.shadow_soft_size = 0.0
    lo = bpy.data.objects.new("light", ld)
    lo.location = lpos
    bs.collection.objects.link(lo)
    bs.world = bpy.data.worlds.new("grey")
    bs.world.use_nodes = True
    bg = bs.world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (0.19, 0.11, 0.03, 1.0)
    bg.inputs["Strength"].default_value = 0.6
    bs.render.engine = "CYCLES"
    bs.cycles.device = "CPU"
    bs.cycles.samples = opts["samples"]
    bs.cycles.use_denoising = False  # Debian's build has no OpenImageDenoise
    bs.render.threads_mode = "FIXED"
    bs.render.threads = opts["threads"]
    bs.render.resolution_x = opts["width"]
    bs.render.resolution_y = opts["height"]
    bs.render.resolution_percentage = 100
    bs.view_settings.view_transform = "Standard"
    bs.render.image_settings.file_format = "PNG"
    bs.render.image_settings.color_mode = "RGBA"
    bs.render.film_transparent = True  # the world lights the stone; the picture's background is the caller's


def import_glb(model):
    """Imports a `marble export` file with Blender's glTF importer into the current scene.
    Returns (mesh objects, design, mm_per_unit). Also used by tools/cycles_reference.py."""
    if not os.path.isfile(model):
        fail(model + ": file not found")
    design, mm_per_unit = marble_design(glb_json(model), model)
    # Debian 12's Blender 3.4 glTF importer still says numpy.bool, which numpy 1.24 removed.
    import warnings
    import numpy
    warnings.filterwarnings("ignore", category=FutureWarning)
    if not hasattr(numpy, "bool") or "bool" in getattr(numpy, "__former_attrs__", {}):
        numpy.bool = bool
    before = set(bpy.context.scene.objects)
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(model))
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH" and o not in before]
    if not meshes:
        fail(model + ": Blender's importer found no mesh")
    return meshes, design, mm_per_unit


def base_color_image(mat):
    """The image behind an imported material's Base Color (the baked veins), or None."""
    bsdf = next((n for n in mat.node_tree.nodes if n.type == "BSDF_PRINCIPLED"), None)
    if bsdf is None:
        return None
    link = bsdf.inputs["Base Color"].links
    return link[0].from_node.image if link and link[0].from_node.type == "TEX_IMAGE" else None


def main():
    model, opts = parse_args()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bs = bpy.context.scene
    meshes, design, mm_per_unit = import_glb(model)
    triangles = 0
    for o in meshes:
        o.data.calc_loop_triangles()
        triangles += len(o.data.loop_triangles)
        for slot in o.material_slots:
            radius = build_material(slot.material, design, mm_per_unit)
    print("blender_marble: imported %d mesh(es), %d triangles, material '%s', subsurface radius %s m" %
          (len(meshes), triangles, design.get("name", "marble"), ", ".join("%.4g" % r for r in radius)))
    if opts["save"]:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(opts["save"]))
        print("blender_marble: wrote " + opts["save"])
    if opts["render"]:
        setup_scene(bs, mm_per_unit, opts)
        bs.render.filepath = os.path.abspath(opts["render"])
        bpy.ops.render.render(write_still=True)
        print("blender_marble: wrote %s (%dx%d, %d samples)" % (opts["render"], opts["width"], opts["height"], opts["samples"]))


if __name__ == "__main__":  # run by blender -P; imported by tools/cycles_reference.py
    main()
