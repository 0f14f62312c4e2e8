"""Wet-map placement (Soak_Map_Fn, Soak_Map_Placed_Fn): a map is dry outside its
square unless tiled, tiles repeat, and a placed (scaled, rotated, translated) map
lands where its transform says.

A flat sand ground seen straight from above (orthographic, no antialiasing) under
a light straight overhead, highlights off, black sky: every pixel is the pigment
of its wetness (the export's `albedo` at wetness 0 or 1, soak export --target
json). The reference image is computed here, pixel by pixel, from the map's
definition and the inverse of the stated transform (not by POV-Ray); pixels whose
footprint straddles an edge of the map are left out. Tolerance: 0.002 (table) +
10^-3 relative (half-float EXR).

usage: placement.py SOAK ROOT TMPDIR"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

RES = 64
MAP_N = 16  # map texels per side
VIEW = (-1.0, 2.0)  # x and y range seen


def wet_map(u, v):
    """The test map over its unit square: wet (1) except the quadrant u < 1/2, v > 1/2."""
    return np.where((u < 0.5) & (v > 0.5), 0.0, 1.0)


def write_map(path, n=MAP_N):
    """16-bit grey PNG of wet_map; image row 0 is v = 1 (POV-Ray's image maps)."""
    c = (np.arange(n) + 0.5) / n
    u, v = np.meshgrid(c, 1 - c)
    img = (wet_map(u, v) * 65535).astype(">u2")
    # through a 16-bit PGM (big-endian), which oiiotool reads
    pgm = path + ".pgm"
    with open(pgm, "wb") as f:
        f.write(f"P5\n{n} {n}\n65535\n".encode())
        f.write(img.tobytes())
    r = subprocess.run(["oiiotool", pgm, "-d", "uint16", "-o", path], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"oiiotool {pgm}: {r.stderr}")


def rotation(deg):
    a = np.radians(deg)
    return np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])


# (name, POV-Ray transform, scale s, rotation about z in degrees, translation, tile)
# POV-Ray applies scale, then rotate, then translate: p = R (s q) + t.
CASES = [
    ("default", None, 1.0, 0.0, (0.0, 0.0), 0),
    ("placed", "scale 0.75 rotate 30*z translate <1.4, -0.6, 0>", 0.75, 30.0, (1.4, -0.6), 0),
    ("tiled", "scale 0.375 rotate 90*z translate <0.1, 0.2, 0>", 0.375, 90.0, (0.1, 0.2), 1),
]


def expected_wet(case, x, y):
    """Wetness at world points (x, y) by the inverse transform: q = R^-1 (p - t) / s."""
    _, _, s, deg, t, tile = case
    rinv = rotation(-deg)
    px, py = x - t[0], y - t[1]
    u = (rinv[0, 0] * px + rinv[0, 1] * py) / s
    v = (rinv[1, 0] * px + rinv[1, 1] * py) / s
    if tile:
        return wet_map(u - np.floor(u), v - np.floor(v))
    inside = (u >= 0) & (u <= 1) & (v >= 0) & (v <= 1)
    return np.where(inside, wet_map(np.clip(u, 0, 1), np.clip(v, 0, 1)), 0.0)


def pov_scene(case):
    name, tr, *_rest = case
    tile = case[5]
    span = VIEW[1] - VIEW[0]
    c = (VIEW[0] + VIEW[1]) / 2
    fn = ('Soak_Map_Fn("map.png")' if tr is None
          else f'Soak_Map_Placed_Fn("map.png", transform {{ {tr} }}, 0, {tile})')
    return f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#declare Soak_Highlights = 0;
#include "soak.inc"
camera {{ orthographic location <{c},{c},5> look_at <{c},{c},0> right -x*{span} up y*{span} sky y }}
light_source {{ <0,0,1e5> rgb 1 parallel point_at 0 }}
background {{ rgb 0 }}
#declare Wet = {fn}
plane {{ z, 0 Soak_Wet_Material_Fn("sand", "water", Wet) }}
"""


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    exp = export_json(soak, tmp)
    k = next(m for m in exp["materials"] if m["name"] == "sand")["liquids"]["water"]["knots"]
    # seen straight from above: the colour times the view factor along the normal (1 when dry)
    j = exp["view_cos"].index(1.0)
    dry, wet = (np.array(k["albedo"][i]) * np.array(k["view_factor"][i][j]) for i in (0, -1))
    if k["wetness"][-1] != 1.0 or k["wetness"][0] != 0.0:
        fail("sand's knots do not start at 0 and end at 1")
    write_map(os.path.join(tmp, "map.png"))
    px = VIEW[0] + (np.arange(RES) + 0.5) / RES * (VIEW[1] - VIEW[0])
    x, y = np.meshgrid(px, px[::-1])  # image row 0 is the top (largest y)
    half = 0.5 * (VIEW[1] - VIEW[0]) / RES
    bad = 0
    for case in CASES:
        pov = os.path.join(tmp, f"{case[0]}.pov")
        with open(pov, "w") as f:
            f.write(pov_scene(case))
        out = os.path.join(tmp, f"{case[0]}.exr")
        rc, log = povray(pov, out, RES, RES, lib, cwd=tmp)
        if rc != 0:
            fail(f"povray {pov}: exit {rc}\n{log[-1500:]}")
        img = read_image(out)
        w = expected_wet(case, x, y)
        # the pixel's footprint, widened by one map texel (interpolate 2 blends neighbouring
        # texels), lies on one side of every edge
        clean = np.ones_like(w, bool)
        reach = half + case[2] / MAP_N
        for dx in (-reach, 0, reach):
            for dy in (-reach, 0, reach):
                clean &= expected_wet(case, x + dx, y + dy) == w
        ref = np.where(w[..., None] > 0.5, wet, dry)
        err = np.abs(img - ref)
        tol = 0.002 + 1e-3 * ref
        n_bad = int(np.sum(np.any(err > tol, axis=2) & clean))
        n_wet, n_dry = int(np.sum(clean & (w > 0.5))), int(np.sum(clean & (w < 0.5)))
        print(f"{case[0]:8} pixels compared {int(clean.sum())} (wet {n_wet}, dry {n_dry}), "
              f"worst |error| {err[clean].max():.2e}, outside tolerance {n_bad}")
        bad += n_bad > 0 or n_wet < 50 or n_dry < 50
        # the named points: a point far outside the square is dry (untiled), tiles repeat
        if case[5] == 0:
            i, j = 2, 2  # pixel near (-0.95, 1.95): outside every untiled map here
            ok = expected_wet(case, x[i, j], y[i, j]) == 0 and np.all(np.abs(img[i, j] - dry) <= tol[i, j])
            print(f"{case[0]:8} point ({x[i, j]:.2f}, {y[i, j]:.2f}) outside the map: {img[i, j]} dry {dry}: "
                  f"{'ok' if ok else 'FAIL'}")
            bad += not ok
        else:
            # one map period along the placed u axis: R (s, 0) = (s cos, s sin); pixels that land
            # on the grid again (within half a pixel) must carry the same value
            s, deg = case[2], case[3]
            step = np.array([s * np.cos(np.radians(deg)), s * np.sin(np.radians(deg))])
            pitch = (VIEW[1] - VIEW[0]) / RES
            same = total = 0
            for i in range(RES):
                for j in range(RES):
                    xx, yy = x[i, j] + step[0], y[i, j] + step[1]
                    jj = int(round((xx - px[0]) / pitch))
                    ii = int(round((px[-1] - yy) / pitch))
                    if not (0 <= ii < RES and 0 <= jj < RES) or not (clean[i, j] and clean[ii, jj]):
                        continue
                    if abs(xx - x[ii, jj]) > 0.2 * pitch or abs(yy - y[ii, jj]) > 0.2 * pitch:
                        continue
                    total += 1
                    same += np.all(np.abs(img[i, j] - img[ii, jj]) <= tol[i, j])
            ok = total > 20 and same == total
            print(f"{case[0]:8} one period apart: {same}/{total} pixel pairs equal: {'ok' if ok else 'FAIL'}")
            bad += not ok
    if bad:
        fail(f"{bad} placement checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
