#!/usr/bin/env python3
"""Models and checks for tests/cli/bake_per_vertex.sh (issue 47 item 3).

make DIR: ground.ply, a 2 x 2 m ground (y = 0, x and z in [-1, 1]) as a
3 x 3 grid of shared vertices (8 triangles facing +y) with UVs u = (x + 1) / 2,
v = (z + 1) / 2; roofed.stl, the same ground without UVs under a 1 x 1 m roof
(y = 0.3, x and z in [-0.5, 0.5], 2 triangles facing +y), ASCII STL.

uvmap DUMP PLY W H: for each vertex of the PLY with texture_u/texture_v, the
map value (oiiotool --dumpdata of a W x H map) at the texel holding its UV,
one per line.

read OUT.ply: checks an output PLY (header, counts, values in [0, 1], the
grey = the sRGB encoding of the wetness) and prints "nv nf" then one
"x y z wetness" line per vertex.

unique MESH.stl: the number of distinct vertex positions of an ASCII STL."""
import re
import sys

GRID = [(x, z) for z in (-1.0, 0.0, 1.0) for x in (-1.0, 0.0, 1.0)]  # index 3 * row + column


def up_tri(p, a, b, c):  # winding with the normal along +y
    e1 = [p[b][k] - p[a][k] for k in range(3)]
    e2 = [p[c][k] - p[a][k] for k in range(3)]
    ny = e1[2] * e2[0] - e1[0] * e2[2]
    return (a, b, c) if ny > 0 else (a, c, b)


def ground_tris(p, base=0):
    t = []
    for r in range(2):
        for c in range(2):
            i = base + 3 * r + c
            t += [up_tri(p, i, i + 1, i + 4), up_tri(p, i, i + 4, i + 3)]
    return t


def make(d):
    p = [(x, 0.0, z) for x, z in GRID]
    tris = ground_tris(p)
    with open(f"{d}/ground.ply", "w") as f:  # Stanford PLY (Turk 1994), Assimp's texture_u/texture_v names
        f.write("ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\nproperty float y\nproperty float z\n"
                "property float texture_u\nproperty float texture_v\nelement face 8\n"
                "property list uchar int vertex_indices\nend_header\n")
        for x, y, z in p:
            f.write(f"{x} {y} {z} {(x + 1) / 2} {(z + 1) / 2}\n")
        for t in tris:
            f.write("3 %d %d %d\n" % t)
    roof = [(-0.5, 0.3, -0.5), (0.5, 0.3, -0.5), (0.5, 0.3, 0.5), (-0.5, 0.3, 0.5)]
    q = p + roof
    tris += [up_tri(q, 9, 10, 11), up_tri(q, 9, 11, 12)]
    with open(f"{d}/roofed.stl", "w") as f:  # ASCII STL (3D Systems, StereoLithography Interface Specification 1988)
        f.write("solid roofed\n")
        for t in tris:
            f.write(" facet normal 0 1 0\n  outer loop\n")
            for i in t:
                f.write("   vertex %g %g %g\n" % q[i])
            f.write("  endloop\n endfacet\n")
        f.write("endsolid roofed\n")


def uvmap(dump, ply, w, h):
    px = {}
    for line in open(dump):
        m = re.match(r"\s*Pixel \((\d+), (\d+)\):\s*([-+0-9.eE]+)", line)
        if m:
            px[(int(m.group(1)), int(m.group(2)))] = float(m.group(3))
    lines = open(ply).read().split("\n")
    start = lines.index("end_header") + 1
    for line in lines[start:start + 9]:
        x, y, z, u, v = map(float, line.split())
        tx = min(max(int(u * w), 0), w - 1)
        ty = min(max(int((1 - v) * h), 0), h - 1)
        print(px[(tx, ty)])


def srgb(lin):  # IEC 61966-2-1:1999
    v = 12.92 * lin if lin <= 0.0031308 else 1.055 * lin ** (1 / 2.4) - 0.055
    return round(255 * min(1.0, max(0.0, v)))


def read(path):
    text = open(path).read().split("\n")
    if text[0] != "ply" or text[1] != "format ascii 1.0":
        sys.exit(f"{path}: not an ASCII PLY")
    end = text.index("end_header")
    header = text[:end]
    nv = int(next(l.split()[2] for l in header if l.startswith("element vertex")))
    nf = int(next(l.split()[2] for l in header if l.startswith("element face")))
    props = [l.split()[-1] for l in header if l.startswith("property") and "list" not in l]
    if props != ["x", "y", "z", "wetness", "red", "green", "blue"]:
        sys.exit(f"{path}: vertex properties {props}")
    out = []
    for line in text[end + 1:end + 1 + nv]:
        x, y, z, w, r, g, b = line.split()
        w = float(w)
        if not (0.0 <= w <= 1.0):
            sys.exit(f"{path}: wetness {w} outside [0, 1]")
        if not (int(r) == int(g) == int(b)) or abs(int(r) - srgb(w)) > 1:
            sys.exit(f"{path}: colour {r} {g} {b} is not the sRGB grey of {w} ({srgb(w)})")
        out.append(f"{x} {y} {z} {w}")
    faces = [l for l in text[end + 1 + nv:] if l.strip()]
    if len(faces) != nf or any(int(i) >= nv for f in faces for i in f.split()[1:]):
        sys.exit(f"{path}: {len(faces)} face lines for {nf}, or an index past {nv}")
    print(nv, nf)
    print("\n".join(out))


def unique(path):
    print(len({l.split(None, 1)[1] for l in open(path) if l.strip().startswith("vertex")}))


if __name__ == "__main__":
    cmd = sys.argv[1]
    if cmd == "make":
        make(sys.argv[2])
    elif cmd == "uvmap":
        uvmap(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]))
    elif cmd == "read":
        read(sys.argv[2])
    elif cmd == "unique":
        unique(sys.argv[2])
