#!/usr/bin/env python3
"""Writes a denser copy of a triangle OBJ for benchmarks: each subdivision level splits every
triangle into four at its edge midpoints (shared edges share their midpoint, so the result is
as closed as the input). Two levels turn the 100,000-triangle dragon into 1.6 M triangles, the
size of a scanned statue (issue 20). Positions only ('v' and 'f' lines; normals are computed at
load). The output is benchmark data: write it to /tmp or out/, never into the repository.

    tools/make-dense-mesh.py /work/shared/models/dragon.obj /tmp/dragon-1.6m.obj --levels 2

The output's extension picks the format: .obj (text), .ply (binary little-endian: float x y z,
uchar-counted int vertex_indices) or .stl (binary: every triangle's own corners, as STL stores them),
so that the loaders can be compared on the same mesh (bench/load_compare.cpp). `--ascii` writes
the .ply or .stl as text instead (one vertex or face per line; STL as "solid ... facet ... endsolid").

(A midpoint split adds triangles but no shape: the new triangles lie in the old ones' planes,
which a simplifier can undo almost without error -- a scan's noise would make that harder.)
"""
import argparse
import struct
import sys


def read_obj(path):
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                x, y, z = line.split()[1:4]
                verts.append((float(x), float(y), float(z)))
            elif line.startswith("f "):
                idx = [int(tok.split("/")[0]) for tok in line.split()[1:]]
                idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
                for k in range(1, len(idx) - 1):  # fan-triangulate polygons
                    faces.append((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def subdivide(verts, faces):
    midpoint = {}

    def mid(a, b):
        key = (a, b) if a < b else (b, a)
        m = midpoint.get(key)
        if m is None:
            pa, pb = verts[a], verts[b]
            m = len(verts)
            verts.append(((pa[0] + pb[0]) * 0.5, (pa[1] + pb[1]) * 0.5, (pa[2] + pb[2]) * 0.5))
            midpoint[key] = m
        return m

    out = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return out


def write_ply(path, verts, faces, ascii_text):
    header = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\n"
              "property float y\nproperty float z\nelement face %d\n"
              "property list uchar int vertex_indices\nend_header\n"
              % ("ascii" if ascii_text else "binary_little_endian", len(verts), len(faces)))
    if ascii_text:
        with open(path, "w") as f:
            f.write(header)
            f.write("".join("%.7g %.7g %.7g\n" % v for v in verts))
            f.write("".join("3 %d %d %d\n" % t for t in faces))
        return
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(b"".join(struct.pack("<3f", *v) for v in verts))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))


def write_stl(path, verts, faces, ascii_text):
    if ascii_text:
        with open(path, "w") as f:
            f.write("solid dense\n")
            f.write("".join("facet normal 0 0 0\nouter loop\nvertex %.7g %.7g %.7g\nvertex %.7g %.7g %.7g\n"
                            "vertex %.7g %.7g %.7g\nendloop\nendfacet\n" % (*verts[a], *verts[b], *verts[c])
                            for a, b, c in faces))
            f.write("endsolid dense\n")
        return
    with open(path, "wb") as f:
        f.write(b"make-dense-mesh.py".ljust(80, b" "))
        f.write(struct.pack("<I", len(faces)))
        # The facet normal is written as zero: readers compute their own (ours ignores it).
        f.write(b"".join(struct.pack("<12fH", 0, 0, 0, *verts[a], *verts[b], *verts[c], 0) for a, b, c in faces))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("input")
    p.add_argument("output")
    p.add_argument("--levels", type=int, default=2)
    p.add_argument("--ascii", action="store_true", help=".ply and .stl as text")
    a = p.parse_args()
    if a.levels < 0 or a.levels > 4:
        sys.exit("--levels: expected 0 to 4")
    verts, faces = read_obj(a.input)
    for _ in range(a.levels):
        faces = subdivide(verts, faces)
    if a.output.lower().endswith(".ply"):
        write_ply(a.output, verts, faces, a.ascii)
    elif a.output.lower().endswith(".stl"):
        write_stl(a.output, verts, faces, a.ascii)
    else:
        with open(a.output, "w") as f:
            f.write("".join("v %.7g %.7g %.7g\n" % v for v in verts))
            f.write("".join("f %d %d %d\n" % (x + 1, y + 1, z + 1) for x, y, z in faces))
    print("%s: %d vertices, %d triangles" % (a.output, len(verts), len(faces)))


if __name__ == "__main__":
    main()
