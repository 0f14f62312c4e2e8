"""Measured error of the POV-Ray front end against `soak render`.

One description (the PATCHES / SHEETS tables below) generates both scenes, a
JSON scene for `soak render` (materials of type "preset") and a .pov that uses
povray/soak.inc, so the two cannot drift. A flat wet ground of square patches
seen from straight above under one sun and a uniform sky; a second scene lights
thin sheets from behind. Per patch: mean radiance over the patch's central
region, and the wet/dry ratio; both are compared within the error budget
derived in povray/README.md ("Measured error").

usage: flat_ground.py SOAK ROOT TMPDIR [--spp N] [--report] [--highlights] [--liquid NAME]
"""
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

# (preset, wetness): four porous presets at three wetness levels, copper under water.
PRESETS = ["sand", "brick", "concrete", "limestone"]
WETNESS = [0.0, 0.5, 1.0]
PATCHES = [(p, w) for p in PRESETS for w in WETNESS]
METALS = [("copper", 0.0), ("copper", 1.0), ("aluminium", 0.0), ("aluminium", 1.0)]
SHEETS = [("paper", 0.0), ("paper", 1.0)]

SUN_DIR = np.array([0.45, 0.25, 0.857])  # towards the sun
SUN_DIR = SUN_DIR / np.linalg.norm(SUN_DIR)
SUN_E = np.pi          # irradiance on a surface facing the sun: POV-Ray light colour E / pi = 1
SKY_L = 0.25           # uniform sky radiance
PATCH = 1.0            # patch size (scene units: 1 unit = 100 mm)
GAP = 0.25
UNIT_MM = 100.0
COLS = 4
RES = 96               # image size (square)


def layout(n):
    rows = (n + COLS - 1) // COLS
    pitch = PATCH + GAP
    span = max(COLS, rows) * pitch
    cells = []
    for i in range(n):
        r, c = divmod(i, COLS)
        x0 = -span / 2 + c * pitch + GAP / 2
        y0 = span / 2 - (r + 1) * pitch + GAP / 2
        cells.append((x0, y0))
    return cells, span


def camera(span):
    height = 20.0
    fov = 2 * np.degrees(np.arctan(span / 2 / height))
    return height, fov


def layered_material(exp, name, w):
    """Thin sheets only (opaque presets use soak render's "preset" material, which
    since the chain's interface landed in scene_material.c is this same model).
    The model the tables represent, traced exactly: the core's liquid-air interface
    (wetness.h step 5, Lekner-Dorf) over a Lambertian base of the core's subsurface
    albedo (step 4). The interface covers the film's area c plus the uncovered pores'
    area (1 - c) a, a = water_specular_weight (zero-thickness pore water; a clear
    liquid's film thickness does not matter for water's absorption)."""
    m = next(m for m in exp["materials"] if m["name"] == name)
    liq = next(l for l in exp["liquids"] if l["name"] == LIQUID)
    k = m["liquids"][LIQUID]["knots"]
    i = k["wetness"].index(w)
    unit_m = UNIT_MM / 1000.0
    film = {"ior": liq["ior"], "thickness": m["film_thickness_m"] / unit_m,
            "absorption": [a * unit_m for a in liq["sigma_a_per_m"]],
            "coverage": k["film_coverage"][i] + (1 - k["film_coverage"][i]) * k["water_specular_weight"][i]}
    if m["kind"] != "thin_sheet":
        return None  # soak render's "preset" material is this model (scene_material.c)
    if m["kind"] == "thin_sheet":
        # the medium of the tables, index matched here (the sheet's transmittance in the tables has faces)
        sig_s = [v * unit_m for v in k["sigma_s_per_m"][i]]
        sig_a = [v * unit_m for v in k["sigma_a_per_m"][i]]
        base = {"type": "medium", "sigma_s": sig_s, "sigma_a": sig_a, "g1": k["phase_g1"][i], "g2": k["phase_g2"][i],
                "w": k["phase_w"][i], "ior": 1.0}
        return {"type": "wet", "film": film, "base": base}
    return {"type": "wet", "film": film, "base": {"type": "lambert", "albedo": k["albedo_subsurface"][i]}}


def json_scene(items, sun_dir, sky, depth, spp, exp=None):
    cells, span = layout(len(items))
    h, fov = camera(span)
    mats, objs = {}, []
    for i, ((name, w), (x0, y0)) in enumerate(zip(items, cells)):
        key = f"m{i}"
        mats[key] = {"type": "preset", "name": name, "wetness": w, "liquid": LIQUID, "unit_mm": UNIT_MM}
        if exp is not None:
            mats[key] = layered_material(exp, name, w) or mats[key]
        objs.append({"type": "box", "min": [x0, y0, -depth], "max": [x0 + PATCH, y0 + PATCH, 0.0], "material": key})
    scene = {
        "render": {"width": RES, "height": RES, "spp": spp, "max_depth": 64},
        "camera": {"position": [0, 0, h], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": fov},
        "lights": [{"type": "sun", "direction": list(sun_dir), "irradiance": SUN_E}] if sun_dir is not None else [],
        "materials": mats,
        "objects": objs,
    }
    if sky > 0:
        scene["environment"] = {"type": "constant", "radiance": sky}
    return scene


LIQUID = "water"  # --liquid NAME: another liquid, reported (budget terms for absorption: issue 23, open)
HIGHLIGHTS = 0  # --highlights: soak.inc's default (1), reported; the reference has no rough dielectric lobe


def pov_scene(items, sun_dir, sky, depth, sheet=False):
    cells, span = layout(len(items))
    h, fov = camera(span)
    lines = [
        "// generated by tests/povray/flat_ground.py from the same table as the JSON scene",
        "#version 3.7;",
        "global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level 8 }",
        f"#declare Soak_Ambient = {sky};",
        f"#declare Soak_Highlights = {HIGHLIGHTS}; // the reference has no rough dielectric lobe",
        '#include "soak.inc"',
        # soak render: right-handed, z up, looking down -z with up +y, +x to the right.
        f"camera {{ perspective location <0,0,{h}> look_at <0,0,0> sky <0,1,0> right -x up y angle {fov} }}",
        (f"light_source {{ <{sun_dir[0]},{sun_dir[1]},{sun_dir[2]}>*1e5 rgb {SUN_E / np.pi} parallel point_at <0,0,0> }}"
         if sun_dir is not None else "// no sun"),
        f"sky_sphere {{ pigment {{ rgb {sky} }} }}" if sky > 0 else "background { rgb 0 }",
    ]
    for (name, w), (x0, y0) in zip(items, cells):
        lines.append(f'box {{ <{x0},{y0},{-depth}>, <{x0 + PATCH},{y0 + PATCH},0> '
                     f'Soak_Wet_Material("{name}", "{LIQUID}", {w}){" no_shadow" if sheet else ""} }}')
    return "\n".join(lines) + "\n"


def region_means(img, items):
    """Mean RGB over the central half of each patch (pixel centres projected by the pinhole)."""
    cells, span = layout(len(items))
    h, fov = camera(span)
    t = np.tan(np.radians(fov) / 2) * h  # half-width of the view on z = 0
    out = []
    for x0, y0 in cells:
        xs = np.array([x0 + PATCH * 0.25, x0 + PATCH * 0.75])
        ys = np.array([y0 + PATCH * 0.25, y0 + PATCH * 0.75])
        px = np.sort(((xs / t + 1) / 2 * RES).astype(int))
        py = np.sort(((1 - ys / t) / 2 * RES).astype(int))
        reg = img[py[0]:py[1], px[0]:px[1]].reshape(-1, 3)
        out.append((reg.mean(0), reg.std(0) / np.sqrt(len(reg))))
    return out


def render_pair(soak, root, tmp, tag, items, sun_dir, sky, depth, spp, exp=None, sheet=False):
    js = os.path.join(tmp, f"{tag}.json")
    pv = os.path.join(tmp, f"{tag}.pov")
    with open(js, "w") as f:
        json.dump(json_scene(items, sun_dir, sky, depth, spp, exp), f, indent=1)
    with open(pv, "w") as f:
        f.write(pov_scene(items, sun_dir, sky, depth, sheet))
    ref = os.path.join(tmp, f"{tag}_soak.exr")
    pov = os.path.join(tmp, f"{tag}_pov.exr")
    r = subprocess.run([soak, "render", js, "-o", ref, "--threads", "2", "--seed", "1"], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak render {js}: exit {r.returncode}\n{r.stderr}")
    rc, log = povray(pv, pov, RES, RES, os.path.join(root, "povray"))
    if rc != 0:
        fail(f"povray {pv}: exit {rc}\n{log[-2000:]}")
    return region_means(read_image(ref), items), region_means(read_image(pov), items)


def wetness_levels(exp, patches):
    """Wetness levels on the export's knots (exact table rows): 0, the knot nearest 0.5, 1."""
    out = []
    for name, w in patches:
        m = next(m for m in exp["materials"] if m["name"] == name)
        knots = m["liquids"][LIQUID]["knots"]["wetness"]
        out.append((name, min(knots, key=lambda k: abs(k - w))))
    return out


def lum(c):
    return float(0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2])


def fresnel(cos_i, n):
    """Unpolarised Fresnel reflectance, air -> n (an independent textbook formula)."""
    sin_t = np.sqrt(max(0.0, 1 - cos_i * cos_i)) / n
    cos_t = np.sqrt(1 - sin_t * sin_t)
    rs = (cos_i - n * cos_t) / (cos_i + n * cos_t)
    rp = (n * cos_i - cos_t) / (n * cos_i + cos_t)
    return 0.5 * (rs * rs + rp * rp)


def film_angle_bound(n, cos_sun):
    """POV-Ray's pigment is the film-covered albedo for diffuse light in and out; the
    traced film lets the sun in at its angle and the light out towards the viewer
    (normal). Relative size of that difference, to first order: the product of the two
    Fresnel transmissions over the square of the cosine-weighted mean one."""
    mu = np.linspace(1e-4, 1, 2001)
    t_mean = np.trapz([(1 - fresnel(m, n)) * 2 * m for m in mu], mu)
    return abs((1 - fresnel(cos_sun, n)) * (1 - fresnel(1.0, n)) / t_mean ** 2 - 1)


def main():
    soak, root, tmp, _ = setup_args(__doc__)
    spp = int(sys.argv[sys.argv.index("--spp") + 1]) if "--spp" in sys.argv else 16
    report = "--report" in sys.argv
    global HIGHLIGHTS, LIQUID
    HIGHLIGHTS = int("--highlights" in sys.argv)
    LIQUID = sys.argv[sys.argv.index("--liquid") + 1] if "--liquid" in sys.argv else "water"
    exp = export_json(soak, tmp)
    n_water = next(l for l in exp["liquids"] if l["name"] == LIQUID)["ior"]
    patches = wetness_levels(exp, PATCHES)
    rows = []

    def collect(tag, items, res, cov_of):
        for (name, w), (rm, rs), (pm, _) in zip(items, *res):
            rows.append((tag, name, w, lum(rm), lum(rs), lum(pm), cov_of(name, w)))

    def coverage(name, w):
        m = next(m for m in exp["materials"] if m["name"] == name)
        k = m["liquids"][LIQUID]["knots"]
        i = k["wetness"].index(w)
        return k["film_coverage"][i] + (1 - k["film_coverage"][i]) * k["water_specular_weight"][i]

    ground = render_pair(soak, root, tmp, "ground", patches, SUN_DIR, SKY_L, 2.0, spp, exp)
    collect("ground", patches, ground, coverage)
    metals = render_pair(soak, root, tmp, "metal", METALS, None, SKY_L, 2.0, spp)
    collect("metal", METALS, metals, lambda n, w: 0.0)
    back = np.array([0.3, 0.2, -0.933])
    back = back / np.linalg.norm(back)
    sheets = wetness_levels(exp, SHEETS)
    sh = render_pair(soak, root, tmp, "sheet", sheets, back, 0.0, 0.8 / UNIT_MM, spp, sheet=True)
    collect("backlit", sheets, sh, coverage)
    if report:
        preset = render_pair(soak, root, tmp, "preset", patches, SUN_DIR, SKY_L, 2.0, spp)
        collect("preset", patches, preset, coverage)

    film_b = film_angle_bound(n_water, SUN_DIR[2])
    # Error budget (povray/README.md, "Measured error"): relative
    #   noise: 4 standard errors of the reference's region mean;
    #   tables: linear interpolation 0.002 (absolute) and half-float EXR output 1e-3 relative;
    #   film: c * 1.5 * film_angle_bound (POV-Ray's pigment cannot vary with the light's angle);
    #   metals: 0.03 (POV-Ray mirror at F0 under the film vs GGX alpha 0.05 directional albedo);
    #   back-lit paper: reported, not asserted. Backside diffuse with the two-flux
    #           transmittance (0.8 mm paper, optical depth 42: neither POV-Ray's media nor its
    #           subsurface fit) is 20-35 % below the traced slab; the asserted back-lit sheet is
    #           tests/povray/media_slab.py (a sheet thin enough for POV-Ray's media).
    def budget(tag, ref, err, cov, name="", w=0.0):
        b = 4 * err / max(ref, 1e-9) + 0.002 / max(ref, 1e-9) + 1e-3
        if tag == "ground":
            b += cov * film_b  # cov: the interface's area (film + pore water)
        elif tag == "metal":
            b += 0.03
        elif tag == "backlit":
            b = float("inf")  # reported, not asserted (README)
        return b

    bad = 0
    print(f"film angle bound (sun cos {SUN_DIR[2]:.3f}, n {n_water}): {film_b:.3f}")
    print(f"{'scene':8} {'preset':10} {'w':>6} {'soak':>8} {'+-':>7} {'povray':>8} {'rel.err':>8} {'budget':>7}")
    for tag, n, w, r, e, p, cov in rows:
        rel = (p - r) / r if r > 0 else float("inf")
        b = budget(tag, r, e, cov, n, w)
        mark = "" if tag == "preset" else ("reported" if b == float("inf") else ("ok" if abs(rel) <= b else "FAIL"))
        bad += mark == "FAIL"
        print(f"{tag:8} {n:10} {w:6.3f} {r:8.4f} {e:7.4f} {p:8.4f} {rel:8.3f} {b:7.3f} {mark}")
    # wet/dry ratios per preset (the darkening the front end reproduces)
    for tag in ("ground", "metal"):
        by = {}
        for t, n, w, r, e, p, cov in rows:
            if t == tag:
                by.setdefault(n, []).append((w, r, e, p, cov))
        for n, lv in by.items():
            lv.sort()
            (w0, r0, e0, p0, c0), (w1, r1, e1, p1, c1) = lv[0], lv[-1]
            ratio_r, ratio_p = r1 / r0, p1 / p0
            rel = ratio_p / ratio_r - 1
            b = budget(tag, r0, e0, c0, n, w0) + budget(tag, r1, e1, c1, n, w1)
            mark = "ok" if abs(rel) <= b else "FAIL"
            bad += mark == "FAIL"
            print(f"ratio {tag:8} {n:10} w {w1:.3f}/{w0:.3f}: soak {ratio_r:.3f} povray {ratio_p:.3f} "
                  f"rel.err {rel:.3f} budget {b:.3f} {mark}")
    # Back-lit sheet: the wet one must be brighter than the dry one in both renderers.
    lit = {w: (r, p) for t, n, w, r, e, p, cov in rows if t == "backlit"}
    (w0, (r0, p0)), (w1, (r1, p1)) = sorted(lit.items())[0], sorted(lit.items())[-1]
    ok = r1 > r0 and p1 > p0
    bad += not ok
    print(f"ratio backlit paper w {w1:.3f}/{w0:.3f}: soak {r1 / max(r0, 1e-9):.2f} povray {p1 / max(p0, 1e-9):.2f} "
          f"(wet brighter in both: {'ok' if ok else 'FAIL'})")
    if bad and (HIGHLIGHTS or LIQUID != "water"):
        print(f"{bad} comparisons outside the budget (--highlights / --liquid: reported, not asserted)")
        return
    if bad:
        fail(f"{bad} comparisons outside their error budget")
    print("PASS")


if __name__ == "__main__":
    main()
