#!/usr/bin/env python3
"""povray_gallery_claims: the measurable part of the source's description, asserted on
the POV-Ray gallery's own scene (scenes/povray/gallery/beach_rock.pov) at reduced size.

[JLD99] sec. 4.2, Fig. 6: (b) the rock's lower part below the last wave's line much
darker; (c) pores full; (d) rock soaked: much darker. The scene is rendered twice more
with every rock dry (Declare=Dry_Rocks=1), so each rock's pixels are divided by the same
pixels of the same rock dry: position, shape and lighting cancel. The pixels are discs
round each rock's centre projected through the scene's camera (never found in the render).

Without the sky and highlights (Declare=No_Sky=1 Declare=Soak_Highlights=0) the ratio is
the core's diffuse albedo ratio (soak export --target json: limestone/water knots at the
saturation wetness and at 1 over the dry knot), within named terms:
  - the light's tint weighs the channels: the bounds take the lowest and highest
    channel's ratio;
  - the liquid interface's view factor (knots.view_factor) over the discs' view angles,
    cos 0.34 .. 1 (the ellipsoid's curvature and its granite bumps);
  - above only: the film's mirror image of the sand and the other rocks, at most water's
    Fresnel reflectance at 60 deg (0.059) times the film's coverage, of surfaces no
    brighter than the dry rock in those pixels.
With the forest HDRI (the gallery's picture) the soaked rock (d) must stay within the
same upper bound: its film's sky does not undo the darkening (the issue's "glossy rather
than darker"), and (d) < (c) < 1.

usage: gallery_claims.py SOAK ROOT TMP   (exit 77 and SKIPPED: when Blender's HDRIs are missing)
"""
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

W, H = 240, 135
CAMERA = (np.array([0.0, -9.5, 2.6]), np.array([0.0, 0.0, 0.5]), 50.0)   # beach_rock.pov
ROCK_X = [(i - 1.5) * 2.4 for i in range(4)]                              # centres at z = 0.6
LUM = np.array([0.2126, 0.7152, 0.0722])
COS_RANGE = (0.34, 1.0)


def fresnel_water(theta_deg, n=1.333):
    ci = math.cos(math.radians(theta_deg))
    st = math.sin(math.radians(theta_deg)) / n
    ct = math.sqrt(1 - st * st)
    rs = (ci - n * ct) / (ci + n * ct)
    rp = (n * ci - ct) / (n * ci + ct)
    return 0.5 * (rs * rs + rp * rp)


def project(p):
    """Pixel (column, row) of world point p through beach_rock.pov's camera (z up, 50 deg across)."""
    loc, look, angle = CAMERA
    f = (look - loc) / np.linalg.norm(look - loc)
    r = np.array([1.0, 0.0, 0.0])
    u = np.cross(r, f)
    u /= np.linalg.norm(u)
    d = p - loc
    t = math.tan(math.radians(angle / 2))
    x = (d @ r) / (d @ f) / t
    y = (d @ u) / (d @ f) / (t * H / W)
    return (0.5 + 0.5 * x) * W, (0.5 - 0.5 * y) * H


def disc(p, radius_px):
    cx, cy = project(p)
    yy, xx = np.mgrid[0:H, 0:W]
    return (xx + 0.5 - cx) ** 2 + (yy + 0.5 - cy) ** 2 < radius_px ** 2


def main():
    soak, root, tmp, lib = setup_args("usage: gallery_claims.py SOAK ROOT TMP")
    hdri_src = os.environ.get("SOAK_HDRI_DIR", "/usr/share/blender/datafiles/studiolights/world")
    forest = os.path.join(hdri_src, "forest.exr")
    if not os.path.isfile(forest):
        print(f"SKIPPED: {forest} not found (Blender's HDRIs: Debian's blender-data, or set SOAK_HDRI_DIR)")
        sys.exit(77)
    hdr = os.path.join(tmp, "forest_x0.45.hdr")
    subprocess.run(["oiiotool", forest, "--clamp:min=0", "--mulc", "0.45", "-o", hdr], check=True)
    scene = os.path.join(root, "scenes", "povray", "gallery", "beach_rock.pov")
    runs = {"wet": [], "dry": ["Declare=Dry_Rocks=1"],
            "wet_bare": ["Declare=No_Sky=1", "Declare=Soak_Highlights=0"],
            "dry_bare": ["Declare=No_Sky=1", "Declare=Soak_Highlights=0", "Declare=Dry_Rocks=1"]}
    lum = {}
    for name, extra in runs.items():
        out = os.path.join(tmp, name + ".exr")
        rc, log = povray(scene, out, W, H, lib, extra=[f"+L{tmp}", f"+L{os.path.dirname(scene)}"] + extra, cwd=tmp)
        if rc != 0:
            fail(f"povray beach_rock.pov {' '.join(extra)}: exit {rc}\n{log[-800:]}")
        lum[name] = (read_image(out) * LUM).sum(-1)

    exp = export_json(soak, tmp)
    cos = exp["view_cos"]
    k = next(m for m in exp["materials"] if m["name"] == "limestone")
    sat = k["saturation_wetness"]
    kn = k["liquids"]["water"]["knots"]
    dry_albedo = np.array(kn["albedo"][0])

    def bounds(w):
        i = kn["wetness"].index(w)
        ratio = np.array(kn["albedo"][i]) / dry_albedo
        vf = [np.interp(c, cos, [v[j] for v in kn["view_factor"][i]]) for c in np.linspace(*COS_RANGE, 33)
              for j in range(3)]
        mirror = fresnel_water(60) * kn["film_coverage"][i]
        core = (np.array(kn["albedo"][i]) @ LUM) / (dry_albedo @ LUM)
        return ratio.min() * min(vf), ratio.max() * max(vf) + mirror, core

    radius = 0.4 * project(np.array([1.0, 0.0, 0.6]))[0] - 0.4 * project(np.array([0.0, 0.0, 0.6]))[0]
    failures = 0

    def check(ok, msg):
        nonlocal failures
        print(("ok   " if ok else "FAIL ") + msg)
        failures += 0 if ok else 1

    def ratio(name, mask):
        return float(lum[name][mask].mean() / lum[name.replace("wet", "dry")][mask].mean())

    cent = [disc(np.array([x, 0.0, 0.75]), radius) for x in ROCK_X]
    r_bare = [ratio("wet_bare", m) for m in cent]
    r_sky = [ratio("wet", m) for m in cent]
    print(f"discs of {radius:.1f} px; wet / dry, bare: {[round(v, 3) for v in r_bare]}; "
          f"with the HDRI: {[round(v, 3) for v in r_sky]}")
    check(abs(r_bare[0] - 1) < 1e-3, f"(a) dry in both renders: {r_bare[0]:.4f} = 1")
    for label, i, w in (("(c) pores full", 2, sat), ("(d) soaked", 3, 1.0)):
        lo, hi, core = bounds(w)
        check(lo <= r_bare[i] <= hi, f"{label}: {r_bare[i]:.3f} in [{lo:.3f}, {hi:.3f}] "
              f"(the core's luminance ratio {core:.3f} at wetness {w:g})")
    lo_d, hi_d, _ = bounds(1.0)
    check(r_sky[3] <= hi_d, f"(d) with the forest HDRI {r_sky[3]:.3f} <= {hi_d:.3f}: darker, not only glossier")
    check(r_sky[3] < r_sky[2] < 0.95, f"with the HDRI (d) {r_sky[3]:.3f} < (c) {r_sky[2]:.3f} < 0.95")
    # (b): below the wave line (z < 0.55) soaked, above it dry
    small = radius * 0.45
    low = ratio("wet_bare", disc(np.array([ROCK_X[1], -0.75, 0.25]), small))
    top = ratio("wet_bare", disc(np.array([ROCK_X[1], -0.5, 1.05]), small))
    check(lo_d <= low <= hi_d, f"(b) below the wave line {low:.3f} in [{lo_d:.3f}, {hi_d:.3f}]")
    check(top > 0.97, f"(b) above the wave line {top:.3f} > 0.97 (dry)")
    if failures:
        fail(f"{failures} claim(s) of the POV-Ray beach rock not shown")
    print("PASS: the POV-Ray beach rock shows (b) wet below its wave line and (c), (d) darker by the core's ratios")


if __name__ == "__main__":
    main()
