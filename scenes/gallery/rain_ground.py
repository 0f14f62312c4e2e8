"""The paving at the foot of the bas-relief, for the rainfall animation
(rainfall.sh): a height field mesh with UVs (OBJ, z up, metres) for `soak bake
rain`. It spans x in [-0.6, 3.2] (the panel is x in [0, 2.6]) and y in
[-1.6, 0] (the panel's wall at y = 0, the viewer at -y); u = (x + 0.6) / 3.8,
v = (y + 1.6) / 1.6. It falls 0.2 % towards the wall, the way paving is laid to
a gutter, and has a shallow dip along the wall's foot with a level bottom
6.5 mm below the paving's lowest edge, centred under the middle medallion,
with a wavy rim (two sines): the rain that falls on it and runs into it
stands there as a puddle. Flat to the eye (the renderers draw a
plane); only the bake sees the heights.

usage: rain_ground.py OUTDIR [N]   (N x N/2.5 cells, default 200)"""
import math
import os
import sys

X0, X1, Y0, Y1 = -0.6, 3.2, -1.6, 0.0


def height(x, y):
    slope = 0.002 * (y - Y0)                    # 0.2 % down towards the wall (y = 0)
    dx, dy = (x - 1.3) / 0.95, (y + 0.4) / 0.38
    wavy = 1 + 0.18 * math.sin(3.1 * x + 0.7) + 0.1 * math.sin(7.3 * x - 1.1 * y)
    r2 = (dx * dx + dy * dy) / (wavy * wavy)
    return max(-slope - 0.008 * math.exp(-r2 * r2), -0.0065)   # the dip's bottom is level


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    m = max(2, round(n * (Y1 - Y0) / (X1 - X0)))
    lines = ["# rain_ground.py: paving at the relief's foot, z up"]
    for j in range(m + 1):
        for i in range(n + 1):
            x, y = X0 + (X1 - X0) * i / n, Y0 + (Y1 - Y0) * j / m
            lines.append(f"v {x:.5f} {y:.5f} {height(x, y):.6f}")
    for j in range(m + 1):
        for i in range(n + 1):
            lines.append(f"vt {i / n:.6f} {j / m:.6f}")
    for j in range(m):
        for i in range(n):
            a = j * (n + 1) + i + 1
            b, c, d = a + 1, a + n + 2, a + n + 1
            lines.append(f"f {a}/{a} {b}/{b} {c}/{c}")
            lines.append(f"f {a}/{a} {c}/{c} {d}/{d}")
    with open(os.path.join(out, "ground.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
