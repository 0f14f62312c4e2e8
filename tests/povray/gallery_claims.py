#!/usr/bin/env python3
"""povray_gallery_claims: the measurable part of the sources' descriptions, asserted on
the POV-Ray gallery's own scenes (scenes/povray/gallery/: the beach rock, the bas-relief
and the drying bricks) at reduced size.

[JLD99] sec. 4.2, Fig. 6: (b) the rock's lower part below the last wave's line much
darker; (c) pores full; (d) rock soaked: much darker. The scene is rendered twice more
with every rock dry (Declare=Dry_Rocks=1), so each rock's pixels are divided by the same
pixels of the same rock dry: position, shape and lighting cancel. The pixels are discs
round each rock's centre projected through the scene's camera (never found in the render).

Without the sky and highlights (Declare=No_Sky=1 Declare=Soak_Highlights=0) the ratio is
the core's diffuse albedo ratio (soak export --target json: limestone/water knots at the
saturation wetness, which (c) draws under a clear water film, and at 1 over the dry
knot), within named terms:
  - the light's tint weighs the channels: the bounds take the lowest and highest
    channel's ratio;
  - the liquid interface's view factor (knots.view_factor) over the discs' view angles,
    cos 0.34 .. 1 (the ellipsoid's curvature and its granite bumps);
  - above only: the film's mirror image of the sand and the other rocks, at most water's
    Fresnel reflectance at 60 deg (0.059) times the film's coverage (1 for (c)'s clear
    film), of surfaces no brighter than the dry rock in those pixels.
With the forest HDRI (the gallery's picture) the soaked rock (d) must stay within the
same upper bound: its film's sky does not undo the darkening (the issue's "glossy rather
than darker"), and (d) < (c) < 1.

[Hnat06] sec. 3.3.1, Fig. 7: the relief goes from dry to wet as the rain map says, and
the strips the mouldings shelter stay dry. scenes/povray/gallery/bas_relief_rain.pov is
rendered (highlights off) with the gallery's rain bake, made smaller (relief_mesh.py at
120 cells a metre, a 400 x 200 map, 16 rays), and with Declare=Dry=1. Pixels: points of
the panel's flat face projected through the camera, chosen where the map (read at the
points' UVs) is 1 (wet: between the medallions and below the string course) or 0 (dry:
under the cornice's cove). Wet over the same pixels dry must be the core's limestone
albedo ratio at wetness 1 within the channels' spread and the view factor at these
angles (cos 0.9 .. 1), plus, above, water's Fresnel reflectance at 20 deg times the
sky's radiance 0.55 over the dry pixels' (the film mirrors the uniform sky); the dry
strip must stay within 3 % of dry and, in the wet render, lighter than the wet faces.

[Hnat06] sec. 3.3 and the pore schedule: a splash on a brick wall dries from its border
inwards. scenes/povray/gallery/bricks_drying.pov at the gallery's clock 0, 0.2, 0.4, 0.6
from the gallery's splash and start map, and at clock 1 (dry), 120 x 68: a 2 x 2 block is
wet where darker than 0.85 x the dry frame (as tests/gallery/gallery_claims.py does for
soak render's frames). The wet area must fall frame by frame and at least 90 % of each
frame's wet blocks must have been wet in the frame before (the patch shrinks; it does
not move).

usage: gallery_claims.py SOAK ROOT TMP   (exit 77 and SKIPPED: when Blender's HDRIs are missing)
"""
import json
import math
import os
import re
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


def project(p, camera=CAMERA):
    """Pixel (column, row) of world point p through a camera (location, look_at, degrees across; z up)."""
    loc, look, angle = camera
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
    for scale in ("0.45", "0.5"):
        subprocess.run(["oiiotool", forest, "--clamp:min=0", "--mulc", scale, "-o",
                        os.path.join(tmp, f"forest_x{scale}.hdr")], check=True)
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

    def bounds(w, cos_range=COS_RANGE):
        i = kn["wetness"].index(w)
        ratio = np.array(kn["albedo"][i]) / dry_albedo
        vf = [np.interp(c, cos, [v[j] for v in kn["view_factor"][i]]) for c in np.linspace(*cos_range, 33)
              for j in range(3)]
        core = (np.array(kn["albedo"][i]) @ LUM) / (dry_albedo @ LUM)
        return ratio.min() * min(vf), ratio.max() * max(vf), core, kn["film_coverage"][i]

    def beach_bounds(w, coverage=None):
        """bounds(w) with the film's mirror image of the sand and the rocks above (coverage: the
        film's, the knot's unless given)."""
        lo, hi, core, knot_coverage = bounds(w)
        return lo, hi + fresnel_water(60) * (knot_coverage if coverage is None else coverage), core

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
    for label, i, w, cover in (("(c) pores full under a clear water film", 2, sat, 1.0), ("(d) soaked", 3, 1.0, None)):
        lo, hi, core = beach_bounds(w, cover)
        check(lo <= r_bare[i] <= hi, f"{label}: {r_bare[i]:.3f} in [{lo:.3f}, {hi:.3f}] "
              f"(the core's luminance ratio {core:.3f} at wetness {w:g})")
    lo_d, hi_d, _ = beach_bounds(1.0)
    check(r_sky[3] <= hi_d, f"(d) with the forest HDRI {r_sky[3]:.3f} <= {hi_d:.3f}: darker, not only glossier")
    check(r_sky[3] < r_sky[2] < 0.95, f"with the HDRI (d) {r_sky[3]:.3f} < (c) {r_sky[2]:.3f} < 0.95")
    # (b): below the wave line (z < 0.55) soaked, above it dry
    small = radius * 0.45
    low = ratio("wet_bare", disc(np.array([ROCK_X[1], -0.75, 0.25]), small))
    top = ratio("wet_bare", disc(np.array([ROCK_X[1], -0.5, 1.05]), small))
    check(lo_d <= low <= hi_d, f"(b) below the wave line {low:.3f} in [{lo_d:.3f}, {hi_d:.3f}]")
    check(top > 0.97, f"(b) above the wave line {top:.3f} > 0.97 (dry)")
    relief(soak, root, tmp, lib, bounds, check)
    bricks(soak, root, tmp, lib, check)
    if failures:
        fail(f"{failures} claim(s) of the POV-Ray gallery not shown")
    print("PASS: the POV-Ray beach rock shows (b) wet below its wave line and (c), (d) darker by the core's "
          "ratios; the relief's wet faces are darker by the core's ratio and its sheltered strips dry")


def bricks(soak, root, tmp, lib, check):
    """The drying bricks' claim (see the module's docstring), through check(ok, message)."""
    splash = os.path.join(tmp, "splash.png")
    subprocess.run([soak, "bake", "turbulence", "--width", "320", "--height", "180", "--frequency", "3",
                    "--threshold", "-0.05", "--softness", "0.25", "--seed", "11", "--threads", "2", "-o",
                    splash], check=True, capture_output=True)
    with open(os.path.join(tmp, "export.json")) as f:
        t_fill = next(m["t_fill"] for m in json.load(f)["materials"] if m["name"] == "brick")
    subprocess.run([soak, "bake", "drying", splash, "--start-map", "--t-fill", str(t_fill), "-o",
                    os.path.join(tmp, "brick_start.png")], check=True, capture_output=True)
    w, h = 120, 68

    def frame(clock):
        out = os.path.join(tmp, f"bricks_{clock}.exr")
        rc, log = povray(os.path.join(root, "scenes", "povray", "gallery", "bricks_drying.pov"), out, w, h, lib,
                         extra=[f"+L{tmp}", f"+L{os.path.join(root, 'scenes', 'povray', 'gallery')}",
                                f"+K{clock}"], cwd=tmp)
        if rc != 0:
            fail(f"povray bricks_drying.pov +K{clock}: exit {rc}\n{log[-800:]}")
        y = (read_image(out) * LUM).sum(-1)
        return y.reshape(h // 2, 2, w // 2, 2).sum(axis=(1, 3))
    dry = frame("1.0")
    wet_sets = [set(zip(*np.nonzero(frame(c) < 0.85 * dry))) for c in ("0.0", "0.2", "0.4", "0.6")]
    areas = [len(x) for x in wet_sets]
    kept = [len(wet_sets[k + 1] & wet_sets[k]) / max(1, len(wet_sets[k + 1])) for k in range(3)]
    check(areas[0] >= 30 and all(areas[k + 1] < areas[k] for k in range(3)) and min(kept) >= 0.9,
          f"bricks: wet blocks {areas} at clock 0, 0.2, 0.4, 0.6; wet in the frame before "
          f"{', '.join(f'{x:.2f}' for x in kept)}: the patches shrink from their borders")


RELIEF_CAMERA = (np.array([1.3, -4.6, 0.95]), np.array([1.3, 0.0, 0.62]), 42.0)   # bas_relief_rain.pov
PIXEL = re.compile(r"Pixel \((\d+), (\d+)\):\s+(\d+)")


def read_map(path):
    """The 16-bit grey map as floats in [0, 1], row 0 at the top (v = 1)."""
    out = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    px = [(int(a), int(b), int(c)) for a, b, c in PIXEL.findall(out)]
    m = np.zeros((max(p[1] for p in px) + 1, max(p[0] for p in px) + 1))
    for x, y, v in px:
        m[y, x] = v / 65535.0
    return m


def relief(soak, root, tmp, lib, bounds, check):
    """The bas-relief claims (see the module's docstring), through check(ok, message)."""
    gal = os.path.join(root, "scenes", "povray", "gallery")
    subprocess.run(["/usr/bin/python3", os.path.join(gal, "relief_mesh.py"), tmp, "120"], check=True,
                   capture_output=True)
    wet_png = os.path.join(tmp, "relief_wet.png")
    subprocess.run([soak, "bake", "rain", os.path.join(tmp, "relief.obj"), "-o", wet_png, "--up", "z",
                    "--rain-dir", "0,-0.55,1", "--spread", "15", "--rainfall", "6", "--duration", "600",
                    "--drop-size", "0.0005", "--splat", "0.004", "--flow-iterations", "0", "--width", "400",
                    "--height", "200", "--rays", "16", "--threads", "2"], check=True, capture_output=True)
    wmap = read_map(wet_png)
    lum = {}
    for name, extra in (("relief_wet", []), ("relief_dry", ["Declare=Dry=1"])):
        out = os.path.join(tmp, name + ".exr")
        rc, log = povray(os.path.join(gal, "bas_relief_rain.pov"), out, W, H, lib,
                         extra=[f"+L{tmp}", "Declare=Soak_Highlights=0"] + extra, cwd=tmp)
        if rc != 0:
            fail(f"povray bas_relief_rain.pov {' '.join(extra)}: exit {rc}\n{log[-800:]}")
        lum[name] = (read_image(out) * LUM).sum(-1)

    def pixels(xs, zs, want):
        """Pixels of the flat face's points (x, 0, z) whose map texel and its neighbours are all `want`."""
        mh, mw = wmap.shape
        sel = set()
        for x in xs:
            for z in zs:
                i, j = int(x / 2.6 * mw), int((1 - z / 1.3) * mh)
                if np.all(np.abs(wmap[max(j - 2, 0):j + 3, max(i - 2, 0):i + 3] - want) < 0.02):
                    c, r = project(np.array([x, 0.0, z]), RELIEF_CAMERA)
                    sel.add((int(r), int(c)))
        mask = np.zeros((H, W), bool)
        for r, c in sel:
            mask[r, c] = True
        return mask

    wet = pixels(np.linspace(0.85, 1.0, 12), np.linspace(0.5, 0.85, 24), 1.0) | \
        pixels(np.linspace(0.3, 2.3, 80), np.linspace(0.05, 0.2, 12), 1.0)
    dry = pixels(np.linspace(0.2, 2.4, 120), np.linspace(0.95, 0.99, 6), 0.0)
    if wet.sum() < 20 or dry.sum() < 20:
        check(False, f"relief: too few pixels (wet {wet.sum()}, dry {dry.sum()}): has the map or the camera moved?")
        return
    r_wet = float(lum["relief_wet"][wet].mean() / lum["relief_dry"][wet].mean())
    r_dry = float(lum["relief_wet"][dry].mean() / lum["relief_dry"][dry].mean())
    lo, hi, core, coverage = bounds(1.0, (0.9, 1.0))
    mirror = fresnel_water(20) * coverage * 0.55 / float(lum["relief_dry"][wet].mean())
    for ok, msg in ((lo <= r_wet <= hi + mirror,
                     f"relief, wet faces ({wet.sum()} px): {r_wet:.3f} x dry in [{lo:.3f}, {hi + mirror:.3f}] "
                     f"(the core's {core:.3f})"),
                    (abs(r_dry - 1) < 0.03, f"relief, strip under the cornice ({dry.sum()} px): {r_dry:.3f} x dry"),
                    (lum["relief_wet"][dry].mean() > lum["relief_wet"][wet].mean(),
                     f"relief, wet render: the dry strip {lum['relief_wet'][dry].mean():.3f} lighter than the wet "
                     f"faces {lum['relief_wet'][wet].mean():.3f}")):
        check(ok, msg)


if __name__ == "__main__":
    main()
