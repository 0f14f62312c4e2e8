"""A 1 m wall (x, z in [0, 1], facing -y, z up) with a ledge 0.4 m wide and
0.2 m deep at z = 0.55-0.6 (a box without UVs: it shelters, it is not baked),
the wall's UVs turned by DEG about the map's centre and scaled by 0.7 (the
layout of test_bake_rain_routing), for pictures of the ledge's rain shadow.

usage: ledge_mesh.py OUT.obj [DEG] [CELLS]"""
import math
import sys

LX0, LX1, LZ0, LZ1, LD = 0.3, 0.7, 0.55, 0.6, 0.2


def main():
    out, deg = sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 30.0
    m = int(sys.argv[3]) if len(sys.argv) > 3 else 80
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    v, vt, f = [], [], []
    for j in range(m + 1):
        for i in range(m + 1):
            x, z = i / m, j / m
            a, b = 0.7 * (x - 0.5), 0.7 * (z - 0.5)
            v.append((x, 0.0, z))
            vt.append((0.5 + c * a - s * b, 0.5 + s * a + c * b))
    for j in range(m):
        for i in range(m):
            xc, zc = (i + 0.5) / m, (j + 0.5) / m
            if LX0 < xc < LX1 and LZ0 < zc < LZ1:
                continue  # the hole behind the ledge
            k = j * (m + 1) + i
            f.append((k, k + 1, k + m + 2, True))
            f.append((k, k + m + 2, k + m + 1, True))
    base = len(v)
    for k in range(8):
        v.append((LX1 if k & 1 else LX0, 0.0 if k & 2 else -LD, LZ1 if k & 4 else LZ0))
    for q in ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)):
        f.append((base + q[0], base + q[1], base + q[2], False))
        f.append((base + q[0], base + q[2], base + q[3], False))
    with open(out, "w") as o:
        for p in v:
            o.write("v %.9g %.9g %.9g\n" % p)
        for t in vt:
            o.write("vt %.9g %.9g\n" % t)
        o.write("vt 5 5\n")  # the ledge's UV: off the map
        off = len(vt) + 1
        for a, b, d, uv in f:
            if uv:
                o.write("f %d/%d %d/%d %d/%d\n" % (a + 1, a + 1, b + 1, b + 1, d + 1, d + 1))
            else:
                o.write("f %d/%d %d/%d %d/%d\n" % (a + 1, off, b + 1, off, d + 1, off))


main()
