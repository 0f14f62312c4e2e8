"""Meshes and wetness maps for the soak render column of docs/gallery.md, written
into OUTDIR (scenes/gallery/render.sh calls this; nothing here is checked in):
  sheet.obj       a sheet of paper 210 x 297 x 0.1 mm (mm), closed, UVs over its faces
  paper_blot.pgm  its wet blot (u, v over the sheet), 16 bit: the tracer's thin sheet
                  takes its medium and its film from this map (dry where it is 0)
  wall.obj        a brick wall 1.6 x 0.9 m, bricks 4 mm proud of the mortar, UVs over the wall
  mortar.obj      the mortar behind them, same UVs
  pot.obj         a flowerpot 0.16 m high (lathe, closed: outer wall, rim, inner wall, floor)
  glass.obj       a tumbler 0.16 m high, 2 mm walls (closed), 384 facets round: the tracer
                  refracts at the flat facets, whose shadow stripes and split caustic
                  show at 96
  cognac.obj      the liquid in it, 5 cm deep, 0.3 mm inside the glass, 384 facets round
  table.obj       a table top 1.0 x 0.9 x 0.04 m from (-0.5, -0.4, -0.04), UVs over its top
  spill.pgm       the spilled pool on the table (u, v over the top), 16 bit
  rock_a.obj ...  four beach rocks (rock_a .. rock_d), each an icosphere (5120 faces)
                  stretched to a boulder about 1.7 x 1.3 x 1.1 m and displaced by four
                  octaves of smooth noise, with a few flattened faces; centred on the
                  origin (the scene translates them), spherical UVs
usage: meshes.py OUTDIR"""
import math
import os
import sys


def write_obj(path, verts, uvs, faces):
    """faces: lists of (vertex index, uv index), 0-based."""
    with open(path, "w") as f:
        for v in verts:
            f.write("v %.6f %.6f %.6f\n" % v)
        for t in uvs:
            f.write("vt %.6f %.6f\n" % t)
        for face in faces:
            f.write("f " + " ".join("%d/%d" % (v + 1, t + 1) for v, t in face) + "\n")


def box_faces(verts, uvs, faces, lo, hi, uv_of):
    """An axis-aligned box, outward faces, each corner's UV from uv_of(x, y, z)."""
    quads = (((0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)),   # -z
             ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)),   # +z
             ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)),   # -y
             ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),   # +y
             ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)),   # -x
             ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)))   # +x
    for quad in quads:
        idx = []
        for c in quad:
            p = tuple(lo[i] if c[i] == 0 else hi[i] for i in range(3))
            verts.append(p)
            uvs.append(uv_of(*p))
            idx.append((len(verts) - 1, len(uvs) - 1))
        faces.append([idx[0], idx[1], idx[2]])
        faces.append([idx[0], idx[2], idx[3]])


def lathe(profile, steps=96):
    """A closed surface of revolution about z from (r, z) points; the first and last
    points must lie on the axis (r = 0)."""
    verts, uvs, faces = [], [(0.5, 0.5)], []
    ring = []
    for r, z in profile:
        if r == 0:
            verts.append((0.0, 0.0, z))
            ring.append([len(verts) - 1] * steps)
        else:
            row = []
            for k in range(steps):
                a = 2 * math.pi * k / steps
                verts.append((r * math.cos(a), r * math.sin(a), z))
                row.append(len(verts) - 1)
            ring.append(row)
    for j in range(len(ring) - 1):
        a, b = ring[j], ring[j + 1]
        for k in range(steps):
            k1 = (k + 1) % steps
            tri = [(a[k], 0), (a[k1], 0), (b[k1], 0)]
            tri2 = [(a[k], 0), (b[k1], 0), (b[k], 0)]
            for t in (tri, tri2):
                if len({v for v, _ in t}) == 3:
                    faces.append(t)
    return verts, uvs, faces


def write_pgm(path, n_u, n_v, value):
    """value(u, v) in [0, 1]; row 0 is v = 1 (top)."""
    with open(path, "wb") as f:
        f.write(b"P5\n%d %d\n65535\n" % (n_u, n_v))
        row = bytearray()
        for j in range(n_v):
            v = 1 - (j + 0.5) / n_v
            for i in range(n_u):
                q = int(round(65535 * min(max(value((i + 0.5) / n_u, v), 0.0), 1.0)))
                row += bytes((q >> 8, q & 255))
        f.write(row)


def wobble(u, v, seed):
    """A smooth irregular offset (a few sines) for blob edges."""
    a = math.atan2(v, u)
    return sum(math.sin(k * a + seed * k * 1.7) / k for k in (3, 5, 7)) / 3


def blot(u, v):
    """The blot of the paper: a round wet spot 0.1 of the sheet's width across at
    (0.55, 0.55), a 0.02 soft edge, with a wobbly rim."""
    du, dv = (u - 0.55) * 210, (v - 0.55) * 297
    r = math.hypot(du, dv) / 55 * (1 + 0.12 * wobble(du, dv, 1))
    return min(max((1 - r) / 0.08 + 0.5, 0), 1)


def spill(u, v):
    """The pool of cognac on the table top: a lobed blob about 0.15 m across round
    (-0.05, -0.02) m, a 5 mm soft edge, a 3 cm margin the wood has drawn in at half
    wetness."""
    du, dv = u * 1.0 - 0.45, (v * 0.9 - 0.38) * 1.25
    r = math.hypot(du, dv) / 0.15 * (1 + 0.25 * wobble(du, dv, 2))
    pool = min(max((1 - r) / 0.033 + 0.5, 0), 1)
    rim = 0.5 * min(max((1.2 - r) / 0.2, 0), 1)
    return max(pool, rim)


def icosphere(levels):
    """Unit icosphere: vertices (unit vectors) and triangles, outward."""
    g = (1 + 5 ** 0.5) / 2
    verts = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
             (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    verts = [tuple(c / math.sqrt(1 + g * g) for c in v) for v in verts]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
            (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
            (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        mid = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                m = [(verts[a][k] + verts[b][k]) / 2 for k in range(3)]
                n = math.sqrt(sum(c * c for c in m))
                verts.append(tuple(c / n for c in m))
                mid[key] = len(verts) - 1
            return mid[key]
        new = []
        for a, b, c in tris:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = new
    return verts, tris


def rock(seed, size=(0.85, 0.65, 0.55)):
    """A boulder: an icosphere stretched to `size` (half-axes, m), its radius
    displaced by smooth noise (sums of sines along random directions, four
    octaves) and cut by a few random planes (worn flat faces)."""
    rnd = __import__("random").Random(seed)

    def unit():
        while True:
            d = [rnd.uniform(-1, 1) for _ in range(3)]
            n = math.sqrt(sum(c * c for c in d))
            if 0.1 < n <= 1:
                return [c / n for c in d]
    waves = [(unit(), f, a / 3, rnd.uniform(0, 2 * math.pi))
             for f, a in ((2.0, 0.09), (4.5, 0.035), (11.0, 0.014), (24.0, 0.007)) for _ in range(3)]
    cuts = [(unit(), rnd.uniform(0.8, 0.92)) for _ in range(4)]
    verts, tris = icosphere(4)
    out, uvs = [], []
    for d in verts:
        r = 1 + sum(a * math.sin(f * sum(x * y for x, y in zip(d, w)) + ph) for w, f, a, ph in waves)
        for n, h in cuts:   # a flat face: the radius reaches no further than the plane
            c = sum(x * y for x, y in zip(d, n))
            if c > 0 and r * c > h:
                r = h / c
        out.append(tuple(r * d[k] * size[k] for k in range(3)))
        uvs.append((0.5 + math.atan2(d[1], d[0]) / (2 * math.pi), 0.5 + math.asin(max(-1, min(1, d[2]))) / math.pi))
    return out, uvs, [[(a, a), (b, b), (c, c)] for a, b, c in tris]


def main(out):
    os.makedirs(out, exist_ok=True)
    v, t, f = [], [], []
    box_faces(v, t, f, (0, 0, 0), (210, 297, 0.1), lambda x, y, z: (x / 210, y / 297))
    write_obj(os.path.join(out, "sheet.obj"), v, t, f)
    write_pgm(os.path.join(out, "paper_blot.pgm"), 420, 594, blot)
    v, t, f = [], [], []
    W, H = 1.6, 0.9
    for j in range(12):
        for i in range(-1, 8):
            x0 = i * 0.23 + (j % 2) * 0.115
            if x0 < W and x0 + 0.22 > 0:
                box_faces(v, t, f, (max(x0, 0), -0.004, j * 0.075 + 0.005),
                          (min(x0 + 0.22, W), 0.1, j * 0.075 + 0.07), lambda x, y, z: (x / W, z / H))
    write_obj(os.path.join(out, "wall.obj"), v, t, f)
    v, t, f = [], [], []
    box_faces(v, t, f, (0, 0, 0), (W, 0.1, H), lambda x, y, z: (x / W, z / H))
    write_obj(os.path.join(out, "mortar.obj"), v, t, f)
    pot = [(0, 0), (0.055, 0), (0.08, 0.14), (0.088, 0.142), (0.088, 0.16), (0.072, 0.16),
           (0.072, 0.145), (0.05, 0.012), (0, 0.012)]
    write_obj(os.path.join(out, "pot.obj"), *lathe(pot))
    glass = [(0, 0), (0.035, 0), (0.036, 0.16), (0.034, 0.16), (0.033, 0.008), (0, 0.008)]
    write_obj(os.path.join(out, "glass.obj"), *lathe(glass, steps=384))
    cognac = [(0, 0.0083), (0.0327, 0.0083), (0.0327, 0.058), (0, 0.058)]
    write_obj(os.path.join(out, "cognac.obj"), *lathe(cognac, steps=384))
    v, t, f = [], [], []
    box_faces(v, t, f, (-0.5, -0.4, -0.04), (0.5, 0.5, 0), lambda x, y, z: (x + 0.5, (y + 0.4) / 0.9))
    write_obj(os.path.join(out, "table.obj"), v, t, f)
    write_pgm(os.path.join(out, "spill.pgm"), 400, 360, spill)
    for k, name in enumerate("abcd"):
        write_obj(os.path.join(out, "rock_%s.obj" % name), *rock(11 + k))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
