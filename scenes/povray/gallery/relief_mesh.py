"""A carved stone panel (bas-relief) as a height field mesh with UVs, for the POV-Ray
gallery's rain scene: writes relief.obj (for `soak bake rain`, z up) and relief.inc
(the same triangles as a POV-Ray mesh2 with uv_vectors).
The panel spans x in [0, 2], z in [0, 1.2]; the carving stands out towards -y: a
cornice along the top, a string course (ledge) at a third of the height, three
medallions with a rosette each.

usage: relief_mesh.py OUTDIR [N]"""
import math
import os
import sys


def ramp(x, a, b):
    """0 below a, 1 above b, linear in between (edges of a few grid cells: no terraces)."""
    return min(max((x - a) / (b - a), 0.0), 1.0)


def height(u, v):
    """Relief depth (m, towards the viewer) at panel coordinates u in [0, 2], v in [0, 1.2]."""
    h = 0.12 * ramp(v, 0.98, 1.06)                                        # cornice, sloped underside
    h = max(h, 0.05 * ramp(v, 0.34, 0.36) * (1 - ramp(v, 0.42, 0.44)))   # string course
    for cx in (0.45, 1.0, 1.55):                                          # medallions
        r = math.hypot(u - cx, v - 0.7)
        if r < 0.24:
            dome = 0.035 * math.sqrt(max(0.0, 1 - (min(r, 0.22) / 0.22) ** 2))
            ring = 0.02 * ramp(r, 0.17, 0.185) * (1 - ramp(r, 0.215, 0.235))
            petals = 0.01 * (0.5 + 0.5 * math.cos(6 * math.atan2(v - 0.7, u - cx))) * (1 - ramp(r, 0.0, 0.16))
            h = max(h, dome + ring + petals)
    return h


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 160
    nu, nv = 2 * n, int(1.2 * n)
    verts, uvs = [], []
    for j in range(nv + 1):
        for i in range(nu + 1):
            u, v = 2.0 * i / nu, 1.2 * j / nv
            verts.append((u, -height(u, v), v))
            uvs.append((i / nu, j / nv))
    faces = []
    for j in range(nv):
        for i in range(nu):
            a = j * (nu + 1) + i
            b, c, d = a + 1, a + nu + 1, a + nu + 2
            faces += [(a, b, d), (a, d, c)]
    with open(os.path.join(out, "relief.obj"), "w") as f:
        for x, y, z in verts:
            f.write(f"v {x:.5f} {y:.5f} {z:.5f}\n")
        for s, t in uvs:
            f.write(f"vt {s:.6f} {t:.6f}\n")
        for a, b, c in faces:
            f.write(f"f {a + 1}/{a + 1} {b + 1}/{b + 1} {c + 1}/{c + 1}\n")
    with open(os.path.join(out, "relief.inc"), "w") as f:
        f.write("#declare Relief = mesh2 {\n  vertex_vectors { %d,\n" % len(verts))
        f.write(",\n".join(f"    <{x:.5f},{y:.5f},{z:.5f}>" for x, y, z in verts))
        f.write("\n  }\n  uv_vectors { %d,\n" % len(uvs))
        f.write(",\n".join(f"    <{s:.6f},{t:.6f}>" for s, t in uvs))
        f.write("\n  }\n  face_indices { %d,\n" % len(faces))
        f.write(",\n".join(f"    <{a},{b},{c}>" for a, b, c in faces))
        f.write("\n  }\n}\n")


if __name__ == "__main__":
    main()
