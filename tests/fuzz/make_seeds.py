#!/usr/bin/env python3
"""Writes the fuzzers' seed corpora (tests/fuzz/corpus/<target>/). Small, valid files that reach
every branch a real file takes (each format's variants, indices of every width, polygons, strips),
plus a few near-misses, so libFuzzer starts deep inside the parsers instead of at their first
check. Run again after changing it; the outputs are committed."""
import base64, json, os, shutil, struct

HERE = os.path.dirname(os.path.abspath(__file__))
TRI = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
PYRAMID = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
PYRAMID_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
DEEP = "[" * 4000 + "]" * 4000  # far past the 64-level cap, within libFuzzer's 16 KB inputs


def put(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


def obj():
    put("obj", "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    put("obj", "quad_uv_normals.obj", "# quad\no q\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "vn 0 0 1\ns off\nusemtl m\nf 1/1/1 2/2/1 3/3/1 4/4/1\n")
    put("obj", "negative_indices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -3 -2\nf 1//1 2//1 4//1\nvn 0 1 0\n")
    put("obj", "continuation.obj", "v 0 0 0 \\\n\nv 1e0 0 0 1\nv +0 1 0\r\ng a b\nf 1 2 \\\n 3\nl 1 2\n")


def ply():
    verts = "".join(f"{x} {y} {z}\n" for x, y, z in PYRAMID)
    faces = "".join(f"3 {a} {b} {c}\n" for a, b, c in PYRAMID_FACES)
    put("ply", "ascii.ply", "ply\nformat ascii 1.0\ncomment seed\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n" + verts + faces)
    put("ply", "ascii_normals_quad.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
        "property double z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty uchar red\n"
        "element face 1\nproperty list uint8 uint32 vertex_index\nelement edge 0\nproperty int v1\nend_header\n"
        "0 0 0 0 0 1 9\n1 0 0 0 0 1 9\n1 1 0 0 0 1 9\n0 1 0 0 0 1 9\n4 0 1 2 3\n")
    for fmt, endian in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
        head = (f"ply\nformat {fmt} 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 4\nproperty list uchar ushort vertex_indices\nend_header\n").encode()
        body = b"".join(struct.pack(endian + "3f", *v) for v in PYRAMID)
        body += b"".join(struct.pack(endian + "B3H", 3, *f) for f in PYRAMID_FACES)
        put("ply", fmt + ".ply", head + body)


def stl():
    facets = "".join("facet normal 0 0 1\n outer loop\n" + "".join(f"  vertex {x} {y} {z}\n" for x, y, z in
                     (PYRAMID[a], PYRAMID[b], PYRAMID[c])) + " endloop\nendfacet\n" for a, b, c in PYRAMID_FACES)
    put("stl", "ascii.stl", "solid seed\n" + facets + "endsolid seed\n")
    body = b"".join(struct.pack("<12fH", 0, 0, 1, *PYRAMID[a], *PYRAMID[b], *PYRAMID[c], 0) for a, b, c in PYRAMID_FACES)
    put("stl", "binary.stl", b"binary seed".ljust(80, b" ") + struct.pack("<I", 4) + body)
    # Binary whose header starts with "solid": the loader must tell it by its size, not its first word.
    put("stl", "binary_solid_header.stl", b"solid but binary".ljust(80, b" ") + struct.pack("<I", 4) + body)


def gltf_doc(buffer_uri, index_type=5123, mode=None, with_normals=True):
    pos = b"".join(struct.pack("<3f", *v) for v in PYRAMID)
    nrm = b"".join(struct.pack("<3f", 0, 1, 0) for _ in PYRAMID)
    idx_fmt = {5121: "B", 5123: "H", 5125: "I"}[index_type]
    flat = [i for f in PYRAMID_FACES for i in f]
    idx = struct.pack("<%d%s" % (len(flat), idx_fmt), *flat)
    idx += b"\0" * (-len(idx) % 4)
    data = pos + (nrm if with_normals else b"") + idx
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)}]
    attrs = {"POSITION": 0}
    accessors = [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]}]
    if with_normals:
        views.append({"buffer": 0, "byteOffset": len(pos), "byteLength": len(nrm)})
        accessors.append({"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"})
        attrs["NORMAL"] = 1
    views.append({"buffer": 0, "byteOffset": len(data) - len(idx), "byteLength": len(idx)})
    accessors.append({"bufferView": len(views) - 1, "componentType": index_type, "count": len(flat), "type": "SCALAR"})
    prim = {"attributes": attrs, "indices": len(accessors) - 1}
    if mode is not None:
        prim["mode"] = mode
    buf = {"byteLength": len(data)}
    if buffer_uri == "data":
        buf["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"mesh": 0, "translation": [0, 1, 0]}], "meshes": [{"primitives": [prim]}],
           "buffers": [buf], "bufferViews": views, "accessors": accessors}
    return doc, data


def gltf():
    for t in (5121, 5123, 5125):
        put("gltf", f"indices_{t}.gltf", json.dumps(gltf_doc("data", t)[0], indent=1))
    put("gltf", "strip_no_normals.gltf", json.dumps(gltf_doc("data", 5123, mode=5, with_normals=False)[0]))
    put("gltf", "fan.gltf", json.dumps(gltf_doc("data", 5125, mode=6)[0]))
    # Issue 18: node graphs that are not forests, a deep chain, and deep JSON nesting.
    doc = gltf_doc("data", 5123)[0]
    doc["nodes"] = [{"children": [i + 1, i + 1]} for i in range(40)] + [{"mesh": 0}]
    put("gltf", "dag_41_nodes.gltf", json.dumps(doc, separators=(",", ":")))
    doc["nodes"] = [{"children": [i + 1]} for i in range(699)] + [{"mesh": 0}]
    put("gltf", "chain_700_nodes.gltf", json.dumps(doc, separators=(",", ":")))
    doc = gltf_doc("data", 5123)[0]
    doc["extras"] = "NEST"
    put("gltf", "deep_nesting.gltf", json.dumps(doc, separators=(",", ":")).replace('"NEST"', DEEP))


def glb():
    for t, mode in ((5123, None), (5125, 5), (5121, 6)):
        doc, data = gltf_doc(None, t, mode)
        j = json.dumps(doc, separators=(",", ":")).encode()
        j += b" " * (-len(j) % 4)
        data += b"\0" * (-len(data) % 4)
        chunks = struct.pack("<II", len(j), 0x4E4F534A) + j + struct.pack("<II", len(data), 0x004E4942) + data
        put("glb", f"indices_{t}_mode{mode}.glb", b"glTF" + struct.pack("<II", 2, 12 + len(chunks)) + chunks)


def scene():
    full = {"mesh": "builtin:sphere", "up": "z", "mm_per_unit": 50,
            "camera": {"position": [0, 0.8, 4.2], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40},
            "light": {"type": "directional", "position": [3, 3, 3], "color": [1, 1, 1], "intensity": 1},
            "material": {"preset": "calacatta", "turb_power": 6.5},
            "render": {"width": 800, "height": 600, "background": [0.19, 0.11, 0.03], "mode": "paper",
                       "exposure": 0.5, "environment": "none", "environment_intensity": 1,
                       "environment_map": "maps/sky.hdr", "environment_rotation_deg": 45}}
    put("scene", "full.json", json.dumps(full, indent=2))
    put("scene", "minimal.json", '{"mesh": "models/bunny.obj", "unknown": [1, {"a": null}]}')
    put("scene", "deep_nesting.json", '{"camera": ' + DEEP + '}')
    put("scene", "light_point.json", '{"light": {"type": "point", "position": [1e4, -1e4, 0.5]}, "render": {"mode": "thickness"}}')


def hdr_pixels(w, h):
    """RGBE bytes of a small gradient with a bright spot: runs where it is flat, dumps where not."""
    px = []
    for y in range(h):
        for x in range(w):
            bright = x == w // 2 and y == h // 2
            px.append((200, 180, 150, 140) if bright else (128, 64 + 8 * (x // 4 % 4), 192, 128 - y % 2))
    return px


def hdr_header(w, h, signature="#?RADIANCE"):
    return f"{signature}\n# seed\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n-Y {h} +X {w}\n".encode()


def hdr_rle_channel(values):
    out, i = bytearray(), 0
    while i < len(values):
        run = 1
        while i + run < len(values) and run < 127 and values[i + run] == values[i]:
            run += 1
        if run >= 3:
            out += bytes([128 + run, values[i]])
            i += run
            continue
        j = i
        while j < len(values) and j - i < 128 and not (j + 2 < len(values) and values[j] == values[j + 1] == values[j + 2]):
            j += 1
        out += bytes([j - i]) + bytes(values[i:j])
        i = j
    return bytes(out)


def hdr():
    w, h = 4, 2  # narrower than 8: flat
    put("hdr", "flat_4x2.hdr", hdr_header(w, h) + bytes(b for p in hdr_pixels(w, h) for b in p))
    w, h = 16, 8
    flat = bytes(b for p in hdr_pixels(w, h) for b in p)
    put("hdr", "flat_16x8.hdr", hdr_header(w, h, "#?RGBE") + flat)
    px = hdr_pixels(w, h)
    rle = bytearray(hdr_header(w, h))
    for y in range(h):
        row = px[y * w:(y + 1) * w]
        rle += bytes([2, 2, w >> 8, w & 255])
        for c in range(4):
            rle += hdr_rle_channel([p[c] for p in row])
    put("hdr", "rle_16x8.hdr", bytes(rle))


def preset():
    src = os.path.join(HERE, "..", "..", "presets")
    for name in sorted(os.listdir(src)):
        if name.endswith(".json"):
            shutil.copy(os.path.join(src, name), os.path.join(HERE, "corpus", "preset", name))
    put("preset", "deep_nesting.json", '{"turb_power": ' + DEEP + '}')
    put("preset", "based_on_builtin.json", '{"preset": "carrara", "name": "mine", "turb_power": 3, "extra": true}')


def preset_dict():
    """The preset target's dictionary: every key the shipped presets use."""
    keys = set()
    src = os.path.join(HERE, "..", "..", "presets")
    for name in os.listdir(src):
        if name.endswith(".json"):
            with open(os.path.join(src, name)) as f:
                keys |= set(json.load(f).keys())
    with open(os.path.join(HERE, "preset.dict"), "w") as out:
        out.write("# Preset JSON keys, from presets/*.json (written by make_seeds.py).\n")
        for k in sorted(keys) + ["preset"]:
            out.write('"\\"%s\\""\n' % k)
        out.write('"1e400"\n"[0, 0, 0]"\n"\\"carrara\\""\n')


if __name__ == "__main__":
    os.makedirs(os.path.join(HERE, "corpus", "preset"), exist_ok=True)
    for f in (obj, ply, stl, gltf, glb, scene, preset, preset_dict, hdr):
        f()
