"""Render a marble scene JSON with Blender Cycles, as a reference for `marble compare` (issue 5, item 9).

    blender -b --factory-startup -P tools/cycles_reference.py -- SCENE.json OUT.exr \
        [--samples N] [--width W --height H] [--threads T] [--seed S] [--marble PATH] [--bake-size N] [--flat] [--box]

--box: a box pixel filter one pixel wide (default: Blender's Blackman-Harris, 1.5 pixels), so a
reference rendered at 200x200 equals one at 800x800 averaged in 4x4 blocks (marble compare
--downsample 4).

What is matched to marble (docs/scene-format.md, docs/materials.md, src/marble/render/view_setup.cpp):
- Mesh: a file path relative to the scene (OBJ only, positions and faces; `builtin:` meshes exist
  only inside marble, so they are refused). The scene's `up` turn (the same proper rotations as
  src/marble/mesh/mesh.cpp), then normalization: bounding-box centre to the origin, largest extent
  2.0. Normals as marble makes them (src/marble/mesh/vertex_normals.h): the file's own `vn` as
  custom split normals when every face corner has one; otherwise vertices at the same position
  welded into one, every face smooth, Auto Smooth at the scene's `crease_angle_deg` (default 60,
  kDefaultCreaseAngleDeg in src/marble/mesh/mesh.h; 180 = Auto Smooth off): Blender's
  angle-weighted normals with the same hard edges (more than the angle apart, non-manifold, or
  wound against each other).
- Axes: marble is +Y up, Blender +Z up; every point goes through B(x, y, z) = (x, -z, y), a +90 deg
  turn about X, so the picture is the same.
- Camera: same position, target, up and vertical field of view (sensor_fit VERTICAL), same aspect.
- Light: marble's point light of intensity I and colour c gives irradiance E = pi I c (d0 / d)^2
  at normal incidence at distance d, where d0 is the light's distance to the scene centre (the
  origin, where the normalized mesh is centred): pi I c at d0, inverse-square around it
  (light_irradiance() in shaders/lighting.frag.glsl; u_light_ref_distance is set in
  src/marble/render/lighting_pass.cpp). A Cycles point light of power P watts gives
  E = P / (4 pi d^2) (checked by rendering a white Lambertian plane: 0.6331 measured for 0.6333
  predicted). So P = 4 pi^2 d0^2 I makes the two equal at every distance, not only at d0.
  Radius 0 (a true point). A directional light has no falloff in either: it becomes a sun of
  strength pi I (a sun's strength is its irradiance).
- World black (compare with marble scenes that say "render": {"environment": "none"}).
- Veins (a design whose vein colours differ from base_color, or a vein network model; --flat
  turns this off): the stone
  goes through the Blender bridge (tools/blender_marble.py). `marble export SCENE.json` (the
  marble binary: --marble PATH, default build/marble of this repository) bakes the pattern onto
  the mesh's texture coordinates or an unwrap (--bake-size, default 1024) and writes a .glb with
  marble's own normalized mesh and normals (any mesh marble reads, builtin: ones included);
  Blender's glTF importer reads it and the mesh is scaled from metres back to scene units
  (1000 / mm_per_unit); the baked texture is the Base Color and Subsurface Color below. The
  rest of this list holds unchanged.
- Material: Principled BSDF, subsurface method RANDOM_WALK, Subsurface 1, base and subsurface
  colour = base_color (a flat albedo; with veins, the baked texture), Subsurface IOR and IOR =
  ior; Specular = F0 / 0.08 with F0 = ((n-1)/(n+1))^2 (Blender's Principled convention);
  Roughness = roughness (both GGX alpha = roughness^2). Subsurface Radius: in the material's
  radius form (`"scattering": "radius"`, src/marble/scene/material_scattering.h) exactly
  subsurface_radius_mm / mm_per_unit, so marble and Cycles mean the same stone by construction.
  In the coefficient form (sigma_a_mm, sigma_s_mm) Cycles cannot take the coefficients, only a
  radius: the one giving the same extinction sigma_a + sigma_s after Cycles' own rescaling,
  r = 1 / ((sigma_a + sigma_s) sqrt(3 (1 - a'))), a' from Rd(a') = base_color; the walk's
  single-scattering albedo is then Cycles' (from base_color), not sigma_s / (sigma_a + sigma_s),
  and a warning says so.
- Sampling: every pixel --samples samples (no adaptive sampling), nothing clamped: an unbiased
  path tracer, whose only error is its noise (a second --seed measures it).
- Output: linear OpenEXR, RGBA 32-bit float, transparent film (alpha 0 and RGB 0 on the
  background), view transform Standard (EXR is written scene-linear regardless).
"""
import json
import math
import os
import subprocess
import sys
import tempfile

import bpy
from mathutils import Matrix, Vector

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def fail(msg):
    print("cycles_reference: " + msg, file=sys.stderr)
    sys.exit(2)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    opts = {"samples": 64, "width": None, "height": None, "threads": 2, "seed": 0, "bake_size": 1024,
            "marble": os.path.join(REPO, "build", "marble"), "flat": False, "box": False}
    pos = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--box":
            opts["box"] = True
            i += 1
        elif a in ("--samples", "--width", "--height", "--threads", "--seed", "--bake-size", "--marble"):
            if i + 1 >= len(argv):
                fail(a + " needs a value")
            key = a[2:].replace("-", "_")
            opts[key] = argv[i + 1] if a == "--marble" else int(argv[i + 1])
            i += 2
        elif a == "--flat":
            opts["flat"] = True
            i += 1
        else:
            pos.append(a)
            i += 1
    if len(pos) != 2:
        fail("usage: blender -b --factory-startup -P tools/cycles_reference.py -- SCENE.json OUT.exr "
             "[--samples N] [--width W --height H] [--threads T] [--seed S] [--marble PATH] [--bake-size N] [--flat] [--box]")
    return pos[0], pos[1], opts


def load_material(scene, scene_dir):
    mat = dict(scene.get("material", {}))
    preset = mat.pop("preset", "paper")
    path = os.path.join(scene_dir, preset)
    if not os.path.isfile(path):
        path = os.path.join(REPO, "presets", preset + ".json")
    if not os.path.isfile(path):
        fail("material.preset: no preset or file '%s'" % preset)
    with open(path) as f:
        merged = json.load(f)
    # marble's rule for the overrides (selectScatteringForm in src/marble/scene/material_io.cpp):
    # an explicit "scattering" decides, else subsurface_radius_mm selects the radius form and
    # sigma_a_mm/sigma_s_mm the coefficient form; otherwise the preset's form stays.
    if "scattering" not in mat:
        if "subsurface_radius_mm" in mat:
            mat["scattering"] = "radius"
        elif "sigma_a_mm" in mat or "sigma_s_mm" in mat:
            mat["scattering"] = "coefficients"
    merged.update(mat)
    return merged


def cycles_alpha_prime(albedo, ior):
    # Cycles' bssrdf_dipole_compute_alpha_prime (kernel/closure/bssrdf.h): 12 bisection steps on
    # Rd(a') = albedo; marble's copy is cyclesAlphaPrime in src/marble/scene/material_scattering.cpp.
    ior = min(max(ior, 1.01), 3.8)
    inv = 1.0 / ior
    fdr = inv * (-1.440 * inv + 0.710) + 0.668 + 0.0636 * ior
    a43 = 4.0 / 3.0 * (1.0 + fdr) / (1.0 - fdr)
    if albedo < 1e-4:
        return 0.0
    if albedo >= 0.995:
        return 0.999999
    lo, hi, mid = 0.0, 1.0, 0.5
    for _ in range(12):
        mid = 0.5 * (lo + hi)
        s = math.sqrt(3.0 * (1.0 - mid))
        if 0.5 * mid * (1.0 + math.exp(-a43 * s)) * math.exp(-s) < albedo:
            lo = mid
        else:
            hi = mid
    return mid


def rotate_up(v, up):
    # Same proper rotations as rotateUp() in src/marble/mesh/mesh.cpp: the named file axis to +Y.
    x, y, z = v
    return {"y": (x, y, z), "z": (x, z, -y), "-z": (x, -z, y), "x": (-y, x, z),
            "-x": (y, -x, z), "-y": (x, -y, -z)}[up]


def to_blender(v):
    return Vector((v[0], -v[2], v[1]))


def load_obj(path, up):
    """Positions (welded: one vertex per distinct position, as marble's normals treat them),
    triangles, and one file normal per triangle corner when every corner has one (else None)."""
    verts, normals, faces, corner_normals = [], [], [], []
    all_have_normals = True
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                verts.append(rotate_up(tuple(float(c) for c in parts[1:4]), up))
            elif parts[0] == "vn":
                normals.append(rotate_up(tuple(float(c) for c in parts[1:4]), up))
            elif parts[0] == "f":
                fields = [p.split("/") for p in parts[1:]]
                idx = [int(p[0]) for p in fields]
                idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
                nidx = [int(p[2]) if len(p) > 2 and p[2] else None for p in fields]
                if any(n is None for n in nidx):
                    all_have_normals = False
                nidx = [None if n is None else (n - 1 if n > 0 else len(normals) + n) for n in nidx]
                for k in range(1, len(idx) - 1):  # fan: marble triangulates polygons the same way
                    faces.append((idx[0], idx[k], idx[k + 1]))
                    corner_normals.append((nidx[0], nidx[k], nidx[k + 1]))
    if not verts or not faces:
        fail(path + ": no vertices or faces")
    lo = [min(v[a] for v in verts) for a in range(3)]
    hi = [max(v[a] for v in verts) for a in range(3)]
    centre = [(lo[a] + hi[a]) * 0.5 for a in range(3)]
    scale = 2.0 / max(hi[a] - lo[a] for a in range(3))
    # Weld by exact position (marble: pointIds in src/marble/mesh/vertex_normals.cpp).
    weld, welded, remap = {}, [], []
    for v in verts:
        if v not in weld:
            weld[v] = len(welded)
            welded.append(v)
        remap.append(weld[v])
    faces = [tuple(remap[i] for i in f) for f in faces]
    loop_normals = None
    if all_have_normals and normals:
        loop_normals = [to_blender(normals[n]).normalized() for c in corner_normals for n in c]
    return [to_blender([(v[a] - centre[a]) * scale for a in range(3)]) for v in welded], faces, loop_normals


def flat_mesh(scene, scene_dir, mesh_ref):
    """The scene's OBJ as marble loads it (the docstring's Mesh item), as a Blender object."""
    if mesh_ref.startswith("builtin:"):
        fail("mesh: '%s' exists only inside marble; use a mesh file (e.g. export one as OBJ)" % mesh_ref)
    mesh_path = os.path.join(scene_dir, mesh_ref)
    if not mesh_path.lower().endswith(".obj"):
        fail("mesh: only OBJ files are supported here, got " + mesh_ref)
    verts, faces, loop_normals = load_obj(mesh_path, scene.get("up", "y"))
    me = bpy.data.meshes.new("marble_mesh")
    me.from_pydata([tuple(v) for v in verts], [], faces)
    me.update()
    for p in me.polygons:
        p.use_smooth = True
    crease = float(scene.get("crease_angle_deg", 60.0))  # kDefaultCreaseAngleDeg
    if loop_normals is not None:
        # The file's normals, as given (custom split normals need Auto Smooth; 180 so no edge
        # is split by angle on top of them).
        me.use_auto_smooth = True
        me.auto_smooth_angle = math.pi
        me.normals_split_custom_set(loop_normals)
    elif crease < 180.0:
        me.use_auto_smooth = True
        me.auto_smooth_angle = math.radians(crease)
    obj = bpy.data.objects.new("marble", me)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def import_veined(scene_path, mm_per_unit, opts):
    """The veined stone through the Blender bridge (the docstring's Veins item): returns the
    mesh objects in scene units and the baked base colour image."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import blender_marble
    if not os.access(opts["marble"], os.X_OK):
        fail("--marble: %s is not an executable marble binary (build it, or give --marble PATH)" % opts["marble"])
    work = tempfile.mkdtemp(prefix="cycles-reference-")
    glb = os.path.join(work, "stone.glb")
    r = subprocess.run([opts["marble"], "export", os.path.abspath(scene_path), "-o", glb, "--size", str(opts["bake_size"])],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail("marble export: " + (r.stderr.strip() or r.stdout.strip()))
    objects, _, glb_mm_per_unit = blender_marble.import_glb(glb)
    veins = None
    for o in objects:
        # The .glb is in metres; scene units are mm_per_unit mm (the camera and light are in them).
        o.matrix_world = Matrix.Scale(1000.0 / glb_mm_per_unit, 4) @ o.matrix_world
        for slot in o.material_slots:
            veins = veins or blender_marble.base_color_image(slot.material)
    if veins is None:
        fail("marble export wrote no base colour texture")
    # The importer packs a .glb's images into the scene, so the temporary folder can go.
    for f in os.listdir(work):
        os.remove(os.path.join(work, f))
    os.rmdir(work)
    print("cycles_reference: veins baked by marble export (%dx%d) onto %d mesh(es)" %
          (veins.size[0], veins.size[1], len(objects)))
    return objects, veins


def main():
    scene_path, out_path, opts = parse_args()
    with open(scene_path) as f:
        scene = json.load(f)
    scene_dir = os.path.dirname(os.path.abspath(scene_path))
    mesh_ref = scene.get("mesh", "builtin:sculpture")
    cam = scene.get("camera", {})
    light = scene.get("light", {})
    render = scene.get("render", {})
    mm_per_unit = float(scene.get("mm_per_unit", 100.0))
    mat = load_material(scene, scene_dir)
    if render.get("environment", "studio") != "none":
        print("cycles_reference: warning: the scene uses marble's studio environment; "
              "this reference has a black world", file=sys.stderr)
    veined = (mat.get("vein_color") != mat.get("base_color") or mat.get("vein2_color") != mat.get("base_color")
              or mat.get("vein_model", "paper") != "paper")
    if veined and opts["flat"]:
        print("cycles_reference: warning: base/vein/vein2 colours differ; --flat uses base_color "
              "as a flat albedo", file=sys.stderr)
        veined = False

    bs = bpy.context.scene
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)

    if veined:
        objects, veins = import_veined(scene_path, mm_per_unit, opts)
    else:
        objects, veins = [flat_mesh(scene, scene_dir, mesh_ref)], None

    # Material.
    albedo = list(mat.get("base_color", [0.93, 0.89, 0.8]))
    ior = float(mat.get("ior", 1.55))
    if mat.get("scattering", "coefficients") == "radius":
        radius = [r / mm_per_unit for r in mat.get("subsurface_radius_mm", [9.73, 6.3, 4.1])]
    else:
        sa = mat.get("sigma_a_mm", [0.0021, 0.0041, 0.0071])
        ss = mat.get("sigma_s_mm", [2.19, 2.62, 3.0])
        radius = [1.0 / ((a + s) * math.sqrt(3.0 * (1.0 - cycles_alpha_prime(c, ior)))) / mm_per_unit
                  for a, s, c in zip(sa, ss, albedo)]
        print("cycles_reference: warning: the material gives sigma_a_mm/sigma_s_mm; Cycles takes a radius, "
              "so only the extinction is matched (give subsurface_radius_mm for the same stone)", file=sys.stderr)
    f0 = ((ior - 1.0) / (ior + 1.0)) ** 2
    m = bpy.data.materials.new("marble")
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.subsurface_method = "RANDOM_WALK"
    bsdf.inputs["Base Color"].default_value = albedo + [1.0]
    bsdf.inputs["Subsurface"].default_value = 1.0
    bsdf.inputs["Subsurface Color"].default_value = albedo + [1.0]
    bsdf.inputs["Subsurface Radius"].default_value = radius
    bsdf.inputs["Subsurface IOR"].default_value = ior
    bsdf.inputs["IOR"].default_value = ior
    bsdf.inputs["Specular"].default_value = f0 / 0.08
    bsdf.inputs["Specular Tint"].default_value = 0.0
    bsdf.inputs["Roughness"].default_value = float(mat.get("roughness", 0.12))
    if veins is not None:
        tex = m.node_tree.nodes.new("ShaderNodeTexImage")
        tex.image = veins  # sRGB, as the importer loaded it; the mesh's one UV map
        m.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
        m.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Subsurface Color"])
    for o in objects:
        o.data.materials.clear()
        o.data.materials.append(m)

    # Camera.
    pos = to_blender(cam.get("position", [0.0, 0.8, 4.2]))
    target = to_blender(cam.get("target", [0.0, 0.0, 0.0]))
    up = to_blender(cam.get("up", [0.0, 1.0, 0.0]))
    fwd = (target - pos).normalized()
    right = fwd.cross(up).normalized()
    cup = right.cross(fwd)
    rot = Matrix((right, cup, -fwd)).transposed()  # columns: camera x, y, z (looks down -z)
    cd = bpy.data.cameras.new("camera")
    cd.sensor_fit = "VERTICAL"
    cd.sensor_height = 24.0
    cd.angle_y = math.radians(float(cam.get("fov_y_deg", 40.0)))
    cd.clip_start, cd.clip_end = 0.01, 1000.0
    co = bpy.data.objects.new("camera", cd)
    co.matrix_world = Matrix.Translation(pos) @ rot.to_4x4()
    bs.collection.objects.link(co)
    bs.camera = co

    # Light.
    intensity = float(light.get("intensity", 1.0))
    color = list(light.get("color", [1.0, 1.0, 1.0]))
    lpos = to_blender(light.get("position", [3.0, 3.0, 3.0]))
    if light.get("type", "point") == "directional":
        ld = bpy.data.lights.new("light", "SUN")
        ld.energy = math.pi * intensity
        ld.angle = 0.0
        lo = bpy.data.objects.new("light", ld)
        lo.rotation_euler = (-lpos).to_track_quat("-Z", "Y").to_euler()
    else:
        ld = bpy.data.lights.new("light", "POINT")
        # E = P / (4 pi d^2) = pi I (d0 / d)^2 for every d: marble's falloff (docstring).
        ld.energy = 4.0 * math.pi ** 2 * lpos.length_squared * intensity
        ld.shadow_soft_size = 0.0
        lo = bpy.data.objects.new("light", ld)
        lo.location = lpos
    ld.color = color
    bs.collection.objects.link(lo)

    # World, film, output.
    bs.world = bpy.data.worlds.new("black")
    bs.world.use_nodes = True
    bs.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    bs.render.engine = "CYCLES"
    bs.cycles.device = "CPU"
    bs.cycles.samples = opts["samples"]
    bs.cycles.seed = opts["seed"]  # a second seed measures the reference's own noise
    bs.cycles.use_denoising = False  # Debian's build has no OpenImageDenoise
    # An unbiased estimator, every pixel the same samples (session 21; docs/quality.md, "References
    # that meet item 6"): Cycles' defaults clamp indirect light at 10 per sample, which removed 1.3 %
    # of the back-lit dragon's light (its fireflies: rare walks that are most of the body's light),
    # and adaptive sampling stops a pixel whose noise estimate says "converged" after a lucky (or
    # no) hit on a sub-pixel glint (session 16). The references up to session 21 were made with
    # both defaults (dragon-back at 2048 samples: SSIM 0.997 / 0.988 against itself without the
    # clamp / without adaptive sampling, the same seed).
    bs.cycles.sample_clamp_direct = 0.0
    bs.cycles.sample_clamp_indirect = 0.0
    bs.cycles.use_adaptive_sampling = False
    if opts["box"]:
        # Each pixel the plain mean over its own square: what rendering 4x larger and averaging
        # 4x4 blocks (marble compare --downsample 4, marble render --supersample 4) does, so a
        # small reference rendered directly is compared fairly (the default Blackman-Harris
        # 1.5-pixel filter would blur it by more than a downsampled one).
        bs.cycles.pixel_filter_type = "BOX"
        bs.cycles.filter_width = 1.0
    bs.render.threads_mode = "FIXED"
    bs.render.threads = opts["threads"]
    bs.render.film_transparent = True
    bs.render.resolution_x = opts["width"] or int(render.get("width", 800))
    bs.render.resolution_y = opts["height"] or int(render.get("height", 800))
    bs.render.resolution_percentage = 100
    bs.view_settings.view_transform = "Standard"
    bs.view_settings.look = "None"
    bs.view_settings.exposure = 0.0
    bs.view_settings.gamma = 1.0
    s = bs.render.image_settings
    s.file_format = "OPEN_EXR"
    s.color_mode = "RGBA"
    s.color_depth = "32"
    bs.render.filepath = os.path.abspath(out_path)
    bpy.ops.render.render(write_still=True)
    print("cycles_reference: wrote %s (%dx%d, %d samples, point power %.2f W)" %
          (out_path, bs.render.resolution_x, bs.render.resolution_y, opts["samples"], ld.energy))


main()
