#!/usr/bin/env python3
"""Writes one small model per mesh format Soak reads, each the same unit
square (two triangles, z = 0, facing +z) whose UVs cover u in [0, U], v in
[0, 1] (U = 0.5 unless --u), for tests/cli/mesh_formats.sh. At W x H texels a
texel centre ((x + 1/2) / W, 1 - (y + 1/2) / H) lies in it for x + 1/2 <= U W,
so U = 0.5 covers exactly half the map: an analytic count every format must
reproduce. Written from the formats' specifications (cited per writer), not
by Assimp.

usage: make_models.py DIR [--u U]"""
import base64
import json
import os
import struct
import sys

P = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)]
TRIS = [(0, 1, 2), (0, 2, 3)]


def uvs(U):
    return [(0.0, 0.0), (U, 0.0), (U, 1.0), (0.0, 1.0)]


def obj_text(U):  # Wavefront OBJ (Wavefront Technologies, Advanced Visualizer manual, appendix B)
    t = "".join(f"v {x} {y} {z}\n" for x, y, z in P) + "".join(f"vt {u} {v}\n" for u, v in uvs(U))
    return t + "".join("f " + " ".join(f"{i + 1}/{i + 1}" for i in tri) + "\n" for tri in TRIS)


def ply(U):  # Stanford PLY (Turk 1994), Assimp's texture_u/texture_v names
    h = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "property float texture_u\nproperty float texture_v\nelement face 2\n"
         "property list uchar int vertex_indices\nend_header\n")
    return h + "".join(f"{x} {y} {z} {u} {v}\n" for (x, y, z), (u, v) in zip(P, uvs(U))) + \
        "".join("3 %d %d %d\n" % t for t in TRIS)


def gltf2_parts(U):  # glTF 2.0 (Khronos, sec. 3.6-3.7): positions, TEXCOORD_0, indices
    pos = b"".join(struct.pack("<3f", *p) for p in P)
    uv = b"".join(struct.pack("<2f", u, 1.0 - v) for u, v in uvs(U))  # glTF's v runs down the image
    idx = b"".join(struct.pack("<3H", *t) for t in TRIS)
    body = pos + uv + idx
    j = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}]}],
         "buffers": [{"byteLength": len(body)}],
         "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                         {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                         {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                        "min": [0, 0, 0], "max": [1, 1, 0]},
                       {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                       {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
    return j, body


def pad4(b, fill=b" "):
    return b + fill * (-len(b) % 4)


def glb2(U):  # glTF 2.0 sec. 4.4: header, JSON chunk, BIN chunk
    j, body = gltf2_parts(U)
    js = pad4(json.dumps(j).encode())
    bn = pad4(body, b"\0")
    out = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(bn), 0x004E4942) + bn
    return b"glTF" + struct.pack("<II", 2, 12 + len(out)) + out


def gltf2(U):
    j, body = gltf2_parts(U)
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(body).decode()
    return json.dumps(j)


def gltf1_parts(U):  # glTF 1.0 (Khronos 2016): objects keyed by id
    j, body = gltf2_parts(U)
    acc = {f"a{i}": dict(a, bufferView=f"bv{a['bufferView']}", byteOffset=0) for i, a in enumerate(j["accessors"])}
    for a in acc.values():
        a.pop("min", None), a.pop("max", None)
    return {"asset": {"version": "1.0"}, "scene": "s", "scenes": {"s": {"nodes": ["n"]}},
            "nodes": {"n": {"meshes": ["m"]}},
            "meshes": {"m": {"primitives": [{"attributes": {"POSITION": "a0", "TEXCOORD_0": "a1"},
                                             "indices": "a2", "mode": 4}]}},
            "buffers": {}, "bufferViews": {f"bv{i}": dict(v, buffer="b") for i, v in enumerate(j["bufferViews"])},
            "accessors": acc}, body


def gltf1(U):
    j, body = gltf1_parts(U)
    j["buffers"]["b"] = {"byteLength": len(body), "type": "arraybuffer",
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(body).decode()}
    return json.dumps(j)


def glb1(U):  # KHR_binary_glTF: "glTF", version 1, length, content length, format 0, JSON, body
    j, body = gltf1_parts(U)
    j["buffers"]["binary_glTF"] = {"byteLength": len(body), "type": "arraybuffer", "uri": "data:,"}
    for v in j["bufferViews"].values():
        v["buffer"] = "binary_glTF"
    j["extensionsUsed"] = ["KHR_binary_glTF"]
    js = pad4(json.dumps(j).encode())
    return b"glTF" + struct.pack("<IIII", 1, 20 + len(js) + len(body), len(js), 0) + js + body


def dae(U):  # Collada 1.4.1 (Khronos): <triangles> with VERTEX and TEXCOORD inputs
    pos = " ".join(f"{c}" for p in P for c in p)
    uv = " ".join(f"{c}" for t in uvs(U) for c in t)
    idx = " ".join(f"{i} {i}" for t in TRIS for i in t)
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit meter="1" name="meter"/><up_axis>Z_UP</up_axis></asset>
<library_geometries><geometry id="g"><mesh>
<source id="p"><float_array id="pa" count="12">{pos}</float_array><technique_common>
<accessor source="#pa" count="4" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor>
</technique_common></source>
<source id="t"><float_array id="ta" count="8">{uv}</float_array><technique_common>
<accessor source="#ta" count="4" stride="2"><param name="S" type="float"/><param name="T" type="float"/></accessor>
</technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="2"><input semantic="VERTEX" source="#v" offset="0"/><input semantic="TEXCOORD" source="#t" offset="1" set="0"/><p>{idx}</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""


def x_text(U):  # DirectX .x text (Microsoft DirectX 9 SDK, "X File Format Reference")
    v = ";\n".join(f"{x:.6f};{y:.6f};{z:.6f}" for x, y, z in P)
    f = ";\n".join("3;%d,%d,%d" % t for t in TRIS)
    t = ";\n".join(f"{u:.6f};{1.0 - w:.6f}" for u, w in uvs(U))  # .x's v runs down the image
    return f"xof 0303txt 0032\nMesh quad {{\n4;\n{v};;\n2;\n{f};;\nMeshTextureCoords {{\n4;\n{t};;\n}}\n}}\n"


def ac(U):  # AC3D (Inivis, "AC3D file format"): SURF refs with per-corner UVs
    verts = "".join(f"{x} {y} {z}\n" for x, y, z in P)
    faces = "".join("SURF 0x10\nmat 0\nrefs 3\n" + "".join(f"{i} {uvs(U)[i][0]} {uvs(U)[i][1]}\n" for i in t)
                    for t in TRIS)
    return ("AC3Db\nMATERIAL \"m\" rgb 1 1 1 amb 0.2 0.2 0.2 emis 0 0 0 spec 0 0 0 shi 0 trans 0\n"
            "OBJECT world\nkids 1\nOBJECT poly\nname \"quad\"\ntexture \"quad.png\"\nnumvert 4\n" + verts +
            "numsurf 2\n" + faces + "kids 0\n")


def chunk3ds(cid, payload):
    return struct.pack("<HI", cid, 6 + len(payload)) + payload


def m3ds(U):  # 3D Studio: MAIN 4D4D > EDIT 3D3D > OBJECT 4000 > TRIMESH 4100 > 4110/4140/4120
    verts = chunk3ds(0x4110, struct.pack("<H", 4) + b"".join(struct.pack("<3f", *p) for p in P))
    maps = chunk3ds(0x4140, struct.pack("<H", 4) + b"".join(struct.pack("<2f", *t) for t in uvs(U)))
    faces = chunk3ds(0x4120, struct.pack("<H", 2) + b"".join(struct.pack("<4H", *t, 7) for t in TRIS))
    obj = chunk3ds(0x4000, b"quad\0" + chunk3ds(0x4100, verts + maps + faces))
    return chunk3ds(0x4D4D, chunk3ds(0x0002, struct.pack("<I", 3)) + chunk3ds(0x3D3D, obj))


def ms3d(U):  # MilkShape 3D 1.8 (Chumbalum Soft, msLib ms3dspec.h), version 4
    out = b"MS3D000000" + struct.pack("<i", 4) + struct.pack("<H", 4)
    for p in P:
        out += struct.pack("<B3fbB", 0, *p, -1, 2)
    out += struct.pack("<H", 2)
    t = uvs(U)
    for tri in TRIS:
        out += struct.pack("<H3H", 0, *tri) + struct.pack("<9f", *([0, 0, 1] * 3))
        out += struct.pack("<3f", *(t[i][0] for i in tri)) + struct.pack("<3f", *(1.0 - t[i][1] for i in tri))
        out += struct.pack("<BB", 1, 0)
    out += struct.pack("<H", 1) + struct.pack("<B32sH", 0, b"quad", 2) + \
    struct.pack("<2H", 0, 1) + struct.pack("<b", -1)
    out += struct.pack("<H", 0) + struct.pack("<ffi", 24.0, 0.0, 1) + struct.pack("<H", 0)
    return out


def iff(cid, payload):
    return cid + struct.pack(">I", len(payload)) + payload + (b"\0" if len(payload) % 2 else b"")


def lwo(U):  # LightWave LWO2 (NewTek, "LightWave Object File Format", 2001)
    def s0(text):
        b = text.encode() + b"\0"
        return b + (b"\0" if len(b) % 2 else b"")
    pnts = iff(b"PNTS", b"".join(struct.pack(">3f", *p) for p in P))
    pols = iff(b"POLS", b"FACE" + b"".join(struct.pack(">H3H", 3, *t) for t in TRIS))
    vmap = iff(b"VMAP", b"TXUV" + struct.pack(">H", 2) + s0("uv") +
               b"".join(struct.pack(">H2f", i, *t) for i, t in enumerate(uvs(U))))
    tags = iff(b"TAGS", s0("surf"))
    ptag = iff(b"PTAG", b"SURF" + b"".join(struct.pack(">HH", i, 0) for i in range(2)))
    surf = iff(b"SURF", s0("surf") + s0(""))
    body = b"LWO2" + tags + iff(b"LAYR", struct.pack(">HH3f", 0, 0, 0, 0, 0) + \
                                s0("")) + pnts + vmap + pols + ptag + surf
    return b"FORM" + struct.pack(">I", len(body)) + body


def stl():  # no UVs by the format's nature
    return "solid q\n" + "".join(
        "facet normal 0 0 1\nouter loop\n" + "".join("vertex %g %g %g\n" % P[i] for i in t) + "endloop\nendfacet\n"
        for t in TRIS) + "endsolid q\n"


def main():
    d = sys.argv[1]
    U = float(sys.argv[sys.argv.index("--u") + 1]) if "--u" in sys.argv else 0.5
    os.makedirs(d, exist_ok=True)
    text = {"quad.obj": obj_text(U), "quad.ply": ply(U), "quad.gltf": gltf2(U), "quad_v1.gltf": gltf1(U),
            "quad.dae": dae(U), "quad.x": x_text(U), "quad.ac": ac(U), "quad.stl": stl()}
    binary = {"quad.glb": glb2(U), "quad_v1.glb": glb1(U), "quad.3ds": m3ds(U), "quad.ms3d": ms3d(U),
              "quad.lwo": lwo(U), "quad_utf16le.obj": b"\xff\xfe" + obj_text(U).encode("utf-16-le"),
              "quad_utf16be.obj": b"\xfe\xff" + obj_text(U).encode("utf-16-be")}
    for name, t in text.items():
        with open(os.path.join(d, name), "w") as f:
            f.write(t)
    for name, b in binary.items():
        with open(os.path.join(d, name), "wb") as f:
            f.write(b)


if __name__ == "__main__":
    main()
