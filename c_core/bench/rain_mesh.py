#!/usr/bin/env python3
"""Writes the benchmark mesh for bench_rain_vs_cycles.sh: a 2 m x 2 m plane
subdivided into N x N quads (2 N^2 triangles; N = 224 gives 100,352), displaced
by a sum of Gaussian bumps and dimples, Y up (OBJ convention), with UVs over
[0,1]^2 and per-vertex normals. Usage: rain_mesh.py OUT.obj [N]; OUT.ply
writes the same surface as binary little-endian PLY (Turk 1994: float x y
z nx ny nz u v, uchar/int vertex_indices); OUT.stl as binary STL (each
facet its own three corners and its flat normal, no UVs)."""
import math
import random
import struct
import sys


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 224
    rng = random.Random(1)
    bumps = [(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.05, 0.25), rng.uniform(-0.25, 0.35))
             for _ in range(40)]

    def height(x, z):
        return sum(a * math.exp(-((x - bx) ** 2 + (z - bz) ** 2) / (2 * s * s)) for bx, bz, s, a in bumps)

    def normal(x, z, e=1e-4):
        dx = (height(x + e, z) - height(x - e, z)) / (2 * e)
        dz = (height(x, z + e) - height(x, z - e)) / (2 * e)
        l = math.sqrt(dx * dx + 1 + dz * dz)
        return -dx / l, 1 / l, -dz / l

    if out.endswith(".ply"):
        write_ply(out, n, height, normal)
        return
    if out.endswith(".stl"):
        write_stl(out, n, height)
        return
    with open(out, "w") as f:
        f.write("# soak rain benchmark mesh: %d triangles\n" % (2 * n * n))
        for j in range(n + 1):
            for i in range(n + 1):
                x, z = -1 + 2 * i / n, 1 - 2 * j / n
                f.write("v %.6f %.6f %.6f\n" % (x, height(x, z), z))
        for j in range(n + 1):
            for i in range(n + 1):
                f.write("vt %.6f %.6f\n" % (i / n, j / n))
        for j in range(n + 1):
            for i in range(n + 1):
                x, z = -1 + 2 * i / n, 1 - 2 * j / n
                f.write("vn %.6f %.6f %.6f\n" % normal(x, z))
        for j in range(n):
            for i in range(n):
                a = j * (n + 1) + i + 1
                b, c, d = a + 1, a + n + 1, a + n + 2
                # counter-clockwise seen from +y (front faces up)
                f.write("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a, a, a, b, b, b, d, d, d))
                f.write("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a, a, a, d, d, d, c, c, c))


def write_ply(out, n, height, normal):
    nv, nf = (n + 1) ** 2, 2 * n * n
    with open(out, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                 "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
                 "property float v\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                 % (nv, nf)).encode())
        for j in range(n + 1):
            for i in range(n + 1):
                x, z = -1 + 2 * i / n, 1 - 2 * j / n
                f.write(struct.pack("<8f", x, height(x, z), z, *normal(x, z), i / n, j / n))
        for j in range(n):
            for i in range(n):
                a = j * (n + 1) + i
                b, c, d = a + 1, a + n + 1, a + n + 2
                f.write(struct.pack("<B3iB3i", 3, a, b, d, 3, a, d, c))


def write_stl(out, n, height):
    def corner(i, j):
        x, z = -1 + 2 * i / n, 1 - 2 * j / n
        return (x, height(x, z), z)

    with open(out, "wb") as f:
        f.write(b"soak rain benchmark mesh".ljust(80, b" ") + struct.pack("<I", 2 * n * n))
        for j in range(n):
            for i in range(n):
                a, b, c, d = corner(i, j), corner(i + 1, j), corner(i, j + 1), corner(i + 1, j + 1)
                for p, q, r in ((a, b, d), (a, d, c)):
                    e1 = [q[k] - p[k] for k in range(3)]
                    e2 = [r[k] - p[k] for k in range(3)]
                    nx = e1[1] * e2[2] - e1[2] * e2[1]
                    ny = e1[2] * e2[0] - e1[0] * e2[2]
                    nz = e1[0] * e2[1] - e1[1] * e2[0]
                    length = math.sqrt(nx * nx + ny * ny + nz * nz)
                    f.write(struct.pack("<12fH", nx / length, ny / length, nz / length, *p, *q, *r, 0))


if __name__ == "__main__":
    main()
