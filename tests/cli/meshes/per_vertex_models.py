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

unique MESH.stl: the number of distinct vertex positions of an ASCII STL.

gltf OUT.gltf|OUT.glb: checks the structure by hand against the glTF 2.0
specification (Khronos): GLB header and chunks, bufferViews inside the
buffer and 4-byte aligned, accessors' types, POSITION's min/max equal to its
data, COLOR_0 = (w, w, w, 1) with w in [0, 1] equal to _WETNESS, indices in
range; prints "nv nf" then one "x y z wetness" line per vertex."""
import base64
import json
import re
import struct
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


def gltf_load(path):
    data = open(path, "rb").read()
    if not path.lower().endswith(".glb"):
        doc = json.loads(data)
        uri = doc["buffers"][0]["uri"]
        prefix = "data:application/octet-stream;base64,"
        assert uri.startswith(prefix), f"buffer uri {uri[:40]}"
        return doc, base64.b64decode(uri[len(prefix):], validate=True)
    magic, version, length = struct.unpack_from("<III", data, 0)
    assert (magic, version) == (0x46546C67, 2), f"GLB header {magic:#x} {version}"
    assert length == len(data), f"GLB length {length}, file {len(data)}"
    jl, jt = struct.unpack_from("<II", data, 12)
    assert jt == 0x4E4F534A and jl % 4 == 0, f"first chunk type {jt:#x} length {jl}"
    doc = json.loads(data[20:20 + jl])
    bl, bt = struct.unpack_from("<II", data, 20 + jl)
    assert bt == 0x004E4942 and bl % 4 == 0, f"second chunk type {bt:#x} length {bl}"
    assert 28 + jl + bl == len(data), "bytes after the BIN chunk"
    assert "uri" not in doc["buffers"][0], "a GLB buffer 0 has no uri"
    binary = data[28 + jl:28 + jl + bl]
    assert 0 <= bl - doc["buffers"][0]["byteLength"] < 4, "BIN chunk padding"
    return doc, binary[:doc["buffers"][0]["byteLength"]]


def gltf_accessor(doc, binary, k, fmt, width):
    a = doc["accessors"][k]
    v = doc["bufferViews"][a["bufferView"]]
    want = {"f": 5126, "I": 5125}[fmt]
    assert a["componentType"] == want, f"accessor {k}: componentType {a['componentType']}"
    assert a["type"] == {1: "SCALAR", 3: "VEC3", 4: "VEC4"}[width], f"accessor {k}: type {a['type']}"
    off, n = v.get("byteOffset", 0) + a.get("byteOffset", 0), a["count"]
    assert off % 4 == 0 and v["byteLength"] % 4 == 0, f"bufferView of accessor {k} not 4-byte aligned"
    assert off + 4 * width * n <= v.get("byteOffset", 0) + v["byteLength"] <= len(binary), f"accessor {k} overruns"
    flat = struct.unpack_from(f"<{width * n}{fmt}", binary, off)
    return [flat[i * width:(i + 1) * width] for i in range(n)]


def f32(v):  # the bounds compare as the float32 values they describe
    return list(struct.unpack("<3f", struct.pack("<3f", *v)))


def gltf(path):
    doc, binary = gltf_load(path)
    assert doc["asset"]["version"] == "2.0", "asset.version"
    assert len(binary) == doc["buffers"][0]["byteLength"], "buffer byteLength"
    prim = doc["meshes"][doc["nodes"][doc["scenes"][doc["scene"]]["nodes"][0]]["mesh"]]["primitives"][0]
    assert prim.get("mode", 4) == 4, "not triangles"
    at = prim["attributes"]
    assert all(k in ("POSITION", "NORMAL", "COLOR_0") or k.startswith("_") for k in at), f"attributes {list(at)}"
    pos = gltf_accessor(doc, binary, at["POSITION"], "f", 3)
    acc = doc["accessors"][at["POSITION"]]
    lo = [min(p[c] for p in pos) for c in range(3)]
    hi = [max(p[c] for p in pos) for c in range(3)]
    assert f32(acc["min"]) == lo and f32(acc["max"]) == hi, \
        f"POSITION min/max {acc['min']} {acc['max']}, data {lo} {hi}"
    col = gltf_accessor(doc, binary, at["COLOR_0"], "f", 4)
    wet = [w[0] for w in gltf_accessor(doc, binary, at["_WETNESS"], "f", 1)]
    if "NORMAL" in at:
        for n in gltf_accessor(doc, binary, at["NORMAL"], "f", 3):
            assert abs(sum(c * c for c in n) - 1) < 1e-5, f"normal {n} not unit"
    for c, w in zip(col, wet):
        assert c[0] == c[1] == c[2] == w and c[3] == 1.0 and 0.0 <= w <= 1.0, f"COLOR_0 {c}, _WETNESS {w}"
    idx = gltf_accessor(doc, binary, prim["indices"], "I", 1)
    assert len(col) == len(wet) == len(pos) and len(idx) % 3 == 0, "counts"
    assert all(i[0] < len(pos) for i in idx), "index out of range"
    print(len(pos), len(idx) // 3)
    for p, w in zip(pos, wet):
        print("%.9g %.9g %.9g %.9g" % (p[0], p[1], p[2], w))


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
    elif cmd == "gltf":
        try:
            gltf(sys.argv[2])
        except (AssertionError, KeyError, IndexError, ValueError, struct.error) as e:
            sys.exit(f"{sys.argv[2]}: {type(e).__name__}: {e}")
