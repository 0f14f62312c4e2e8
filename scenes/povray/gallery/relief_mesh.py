"""A carved stone panel (bas-relief) as a height field mesh with UVs and smooth
normals, for the POV-Ray gallery's rain scene: writes relief.obj (for `soak bake
rain`, z up) and relief.inc (the same triangles as a POV-Ray mesh2 with
uv_vectors and normal_vectors).
The panel spans x in [0, 2.6], z in [0, 1.3]; the carving stands out towards -y: a
cornice along the top (a cove below it, its top sloping back to the wall: a
weathering that faces the sky), a string course (ledge) at a third of the height
with the same section, and three medallions (a dome, a ring, a rosette of six
smooth petals round a central boss). Every profile is a smoothstep a few grid cells
wide, the petals are lobes with a flat rim (no kinks; nothing pinches at a
centre), and the normals are the height's own (smooth shading).

usage: relief_mesh.py OUTDIR [N]"""
import math
import os
import sys


WIDTH, HEIGHT = 2.6, 1.3            # panel size (m); the wet map's aspect is 2:1
MEDALLIONS = (0.55, 1.3, 2.05)      # their centres along u


def step(x, a, b):
    """0 below a, 1 above b, smoothstep in between (no kinks for the normals)."""
    t = min(max((x - a) / (b - a), 0.0), 1.0)
    return t * t * (3 - 2 * t)


def moulding(v, v0, depth):
    """A horizontal moulding from v0: a cove rising over 0.04 (facing down), a
    front 0.06 high, a top sloping back to the wall over 0.05 (facing up)."""
    return depth * step(v, v0, v0 + 0.04) * (1 - step(v, v0 + 0.1, v0 + 0.15))


def petal(u, v, cx, cy, k):
    """The k-th of six petals round (cx, cy): a smooth lobe, its centre 0.09 out,
    0.065 long radially, 0.03 wide (zero slope at its rim)."""
    a = k * math.pi / 3
    du, dv = u - cx, v - cy
    s = du * math.cos(a) + dv * math.sin(a) - 0.09   # along the petal
    t = -du * math.sin(a) + dv * math.cos(a)         # across it
    q = (s / 0.065) ** 2 + (t / 0.03) ** 2
    return (1 - q) ** 2 if q < 1 else 0.0


def height(u, v):
    """Relief depth (m, towards the viewer) at panel coordinates u in [0, WIDTH], v in [0, HEIGHT]."""
    h = moulding(v, 1.0, 0.1)              # cornice
    h = max(h, moulding(v, 0.28, 0.045))   # string course
    for cx in MEDALLIONS:
        r = math.hypot(u - cx, v - 0.7)
        if r < 0.25:
            dome = 0.03 * (1 - step(r, 0.0, 0.225))
            ring = 0.018 * step(r, 0.165, 0.185) * (1 - step(r, 0.21, 0.232))
            petals = 0.013 * sum(petal(u, v, cx, 0.7, k) for k in range(6))
            boss = 0.014 * (1 - step(r, 0.01, 0.032))
            h = max(h, dome + ring + petals + boss)
    return h


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 160
    nu, nv = int(WIDTH * n), int(HEIGHT * n)
    du, dv = WIDTH / nu, HEIGHT / nv
    hs = [[height(du * i, dv * j) for i in range(nu + 1)] for j in range(nv + 1)]
    verts, uvs, norms = [], [], []
    for j in range(nv + 1):
        for i in range(nu + 1):
            verts.append((du * i, -hs[j][i], dv * j))
            uvs.append((i / nu, j / nv))
            # surface (u, -h, v): normal towards -y from the height's central differences
            hu = (hs[j][min(i + 1, nu)] - hs[j][max(i - 1, 0)]) / (du * (min(i + 1, nu) - max(i - 1, 0)))
            hv = (hs[min(j + 1, nv)][i] - hs[max(j - 1, 0)][i]) / (dv * (min(j + 1, nv) - max(j - 1, 0)))
            nx, ny, nz = -hu, -1.0, -hv
            k = math.sqrt(nx * nx + ny * ny + nz * nz)
            norms.append((nx / k, ny / k, nz / k))
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
        for x, y, z in norms:
            f.write(f"vn {x:.5f} {y:.5f} {z:.5f}\n")
        for a, b, c in faces:
            f.write(f"f {a + 1}/{a + 1}/{a + 1} {b + 1}/{b + 1}/{b + 1} {c + 1}/{c + 1}/{c + 1}\n")
    with open(os.path.join(out, "relief.inc"), "w") as f:
        f.write("#declare Relief = mesh2 {\n  vertex_vectors { %d,\n" % len(verts))
        f.write(",\n".join(f"    <{x:.5f},{y:.5f},{z:.5f}>" for x, y, z in verts))
        f.write("\n  }\n  normal_vectors { %d,\n" % len(norms))
        f.write(",\n".join(f"    <{x:.5f},{y:.5f},{z:.5f}>" for x, y, z in norms))
        f.write("\n  }\n  uv_vectors { %d,\n" % len(uvs))
        f.write(",\n".join(f"    <{s:.6f},{t:.6f}>" for s, t in uvs))
        f.write("\n  }\n  face_indices { %d,\n" % len(faces))
        f.write(",\n".join(f"    <{a},{b},{c}>" for a, b, c in faces))
        f.write("\n  }\n}\n")


if __name__ == "__main__":
    main()
