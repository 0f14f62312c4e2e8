"""Measured error of the POV-Ray front end against `soak render`.

One description (the PATCHES / SHEETS tables below) generates both scenes, a
JSON scene for `soak render` (materials of type "preset") and a .pov that uses
povray/soak.inc, so the two cannot drift. A flat wet ground of square patches
seen from straight above under one sun and a uniform sky; a second scene lights
thin sheets from behind. Per patch: mean radiance over the patch's central
region, and the wet/dry ratio; both are compared within the error budget
derived in povray/README.md ("Measured error"); with highlights off the reference is
the preset without its own interface ("interface": 0). Asserted too: the same ground
with soak.inc's default highlights against `soak render`'s full preset material (the
material's rough interface traced; terms POV-Ray cannot represent: Blinn shape, the
sky in the lobe, the liquid's sun glint, the body light the interface holds back),
and every other liquid of the presets on brick and concrete (knots and
off-knot wetness 0.3, 0.8) against the chain's interface traced as film + pore water.

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


def liquid_of(item):
    return item[2] if len(item) > 2 else LIQUID


def layered_material(exp, name, w, liquid=None):
    """Thin sheets only (opaque presets use soak render's "preset" material, which
    since the chain's interface landed in scene_material.c is this same model).
    The model the tables represent, traced exactly: the core's liquid-air interface
    (wetness.h step 5, Lekner-Dorf) over a Lambertian base of the core's subsurface
    albedo (step 4). The interface covers the film's area c plus the uncovered pores'
    area (1 - c) a, a = water_specular_weight (zero-thickness pore water; a clear
    liquid's film thickness does not matter for water's absorption)."""
    liquid = liquid or LIQUID
    m = next(m for m in exp["materials"] if m["name"] == name)
    liq = next(l for l in exp["liquids"] if l["name"] == liquid)
    k = m["liquids"][liquid]["knots"]
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


def json_scene(items, sun_dir, sky, depth, spp, exp=None, interface=1):
    cells, span = layout(len(items))
    h, fov = camera(span)
    mats, objs = {}, []
    for i, (item, (x0, y0)) in enumerate(zip(items, cells)):
        name, w, key = item[0], item[1], f"m{i}"
        mats[key] = {"type": "preset", "name": name, "wetness": w, "liquid": liquid_of(item), "unit_mm": UNIT_MM,
                     "interface": interface}
        if exp is not None:
            mats[key] = layered_material(exp, name, w, liquid_of(item)) or mats[key]
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


LIQUIDS = ("coffee", "cola", "red_wine")  # the preset file's other liquids, asserted on the canonical ground
LIQUID = "water"  # --liquid NAME: the whole water table with another liquid, reported (LIQUIDS are asserted)
HIGHLIGHTS = 0  # the ground is rendered with 0 and again with soak.inc's default (1), both asserted


def pov_scene(items, sun_dir, sky, depth, sheet=False, highlights=None):
    cells, span = layout(len(items))
    h, fov = camera(span)
    lines = [
        "// generated by tests/povray/flat_ground.py from the same table as the JSON scene",
        "#version 3.7;",
        "global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level 8 }",
        f"#declare Soak_Ambient = {sky};",
        f"#declare Soak_Highlights = {HIGHLIGHTS if highlights is None else highlights};",
        '#include "soak.inc"',
        # soak render: right-handed, z up, looking down -z with up +y, +x to the right.
        f"camera {{ perspective location <0,0,{h}> look_at <0,0,0> sky <0,1,0> right -x up y angle {fov} }}",
        (f"light_source {{ <{sun_dir[0]},{sun_dir[1]},{sun_dir[2]}>*1e5 rgb {SUN_E / np.pi} parallel point_at <0,0,0> }}"
         if sun_dir is not None else "// no sun"),
        f"sky_sphere {{ pigment {{ rgb {sky} }} }}" if sky > 0 else "background { rgb 0 }",
    ]
    for item, (x0, y0) in zip(items, cells):
        lines.append(f'box {{ <{x0},{y0},{-depth}>, <{x0 + PATCH},{y0 + PATCH},0> '
                     f'Soak_Wet_Material("{item[0]}", "{liquid_of(item)}", {item[1]}){" no_shadow" if sheet else ""} }}')
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


def soak_render(soak, tmp, tag, scene):
    js, ref = os.path.join(tmp, f"{tag}.json"), os.path.join(tmp, f"{tag}_soak.exr")
    with open(js, "w") as f:
        json.dump(scene, f, indent=1)
    r = subprocess.run([soak, "render", js, "-o", ref, "--threads", "2", "--seed", "1"], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak render {js}: exit {r.returncode}\n{r.stderr}")
    return ref


def render_pair(soak, root, tmp, tag, items, sun_dir, sky, depth, spp, exp=None, sheet=False, highlights=None):
    """[reference, POV-Ray] region means; with highlights=0 the reference has no interface of
    the material's own, and two more follow: POV-Ray with highlights, the full reference."""
    pv = os.path.join(tmp, f"{tag}.pov")
    with open(pv, "w") as f:
        f.write(pov_scene(items, sun_dir, sky, depth, sheet, highlights))
    pov = os.path.join(tmp, f"{tag}_pov.exr")
    ref = soak_render(soak, tmp, tag, json_scene(items, sun_dir, sky, depth, spp, exp, 0 if highlights == 0 else 1))
    rc, log = povray(pv, pov, RES, RES, os.path.join(root, "povray"))
    if rc != 0:
        fail(f"povray {pv}: exit {rc}\n{log[-2000:]}")
    out = [region_means(read_image(ref), items), region_means(read_image(pov), items)]
    if highlights == 0:  # the same scene again with soak.inc's default highlights
        with open(pv, "w") as f:
            f.write(pov_scene(items, sun_dir, sky, depth, sheet, 1))
        rc, log = povray(pv, pov, RES, RES, os.path.join(root, "povray"))
        if rc != 0:
            fail(f"povray {pv} (highlights): exit {rc}\n{log[-2000:]}")
        out.append(region_means(read_image(pov), items))
        full = soak_render(soak, tmp, f"{tag}_full", json_scene(items, sun_dir, sky, depth, spp, exp, 1))
        out.append(region_means(read_image(full), items))
    return out


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


def film_transmission(n, cos_i, absorb_h):
    """Fresnel transmission into a film of index n at incidence cos_i times the film's
    Beer-Lambert attenuation along the refracted path (absorb_h = sigma_a * thickness)."""
    sin_t = np.sqrt(max(0.0, 1 - cos_i * cos_i)) / n
    cos_t = np.sqrt(1 - sin_t * sin_t)
    return (1 - fresnel(cos_i, n)) * np.exp(-absorb_h / cos_t)


def sun_share(cos_sun, sky):
    """The sun's share of the irradiance on the flat ground (the rest is the uniform sky's)."""
    e_sun = SUN_E * cos_sun
    return e_sun / (e_sun + np.pi * sky)


def light_half(n, cos_sun, absorb_h, share):
    """What POV-Ray cannot represent of the interface's angular transmission: soak.inc's
    pigment follows the viewer's angle (the view factor, T(view) / T_diffuse), but POV-Ray's
    diffuse takes every light as diffuse light. The traced interface lets the sun in at its
    angle: T(sun) / T_diffuse - 1 on the sun's share of the irradiance; the uniform sky's
    part is exact (the cosine-weighted mean of T / T_diffuse is 1). T: the film's
    transmission (Fresnel, then Beer-Lambert along the refracted path)."""
    mu = np.linspace(1e-4, 1, 2001)
    t_diff = np.trapz([film_transmission(n, m, absorb_h) * 2 * m for m in mu], mu)
    return share * abs(film_transmission(n, cos_sun, absorb_h) / t_diff - 1)


def light_term(exp, name, w, liquid, cos_sun, share):
    """light_half for the chain's interface, relative to the luminance: per channel, the film's
    share c at the film's thickness (the liquid's absorption in that channel) plus the pore
    water's (1 - c) a at zero thickness, weighted by the channel's share of the pigment's
    luminance (a channel the film darkens most is also the darkest one: a maximum over channels
    would let coffee's blue set the bound of its luminance)."""
    m = next(m for m in exp["materials"] if m["name"] == name)
    liq = next(l for l in exp["liquids"] if l["name"] == liquid)
    k = m["liquids"][liquid]["knots"]
    c = interp(k["wetness"], k["film_coverage"], w)
    a = interp(k["wetness"], k["water_specular_weight"], w)
    pig = [interp(k["wetness"], [v[j] for v in k["albedo"]], w) for j in range(3)]
    film = [interp(k["wetness"], [v[j] for v in k["albedo_film"]], w) for j in range(3)]
    lum_w = (0.2126, 0.7152, 0.0722)
    pore = (1 - c) * a * light_half(liq["ior"], cos_sun, 0.0, share)
    # channel j's error in luminance: the film's part of the pigment, c A_film, times its term,
    # plus the pore water's share of the pigment times its term
    err = sum(lw * (c * fa * light_half(liq["ior"], cos_sun, sa * m["film_thickness_m"], share) + p * pore)
              for lw, fa, p, sa in zip(lum_w, film, pig, liq["sigma_a_per_m"]))
    return err / max(sum(lw * p for lw, p in zip(lum_w, pig)), 1e-12)


def interp(xs, ys, x):
    return float(np.interp(x, xs, ys))


# ---- highlights: the material's own rough interface (wetness.h step 6) --------------
# soak render's "preset" material traces the material's own rough interface (soak/bsdf.h
# COATED: GGX lobe of weight specular_weight, the body's light through the same facets);
# POV-Ray's `specular albedo` lobe of soak.inc stands for the lobe. The GGX formulas
# below (a second method) size the terms POV-Ray cannot represent; nothing is added to
# the reference.

def ggx_brdf(n_mat, alpha, l, v):
    """GGX microfacet reflection of a dielectric of index n_mat (normal +z): F D G2 / (4 cos cos)."""
    if l[2] <= 0 or v[2] <= 0:
        return 0.0
    h = (l + v) / np.linalg.norm(l + v)
    a2 = alpha * alpha
    d = a2 / (np.pi * (h[2] ** 2 * (a2 - 1) + 1) ** 2)

    def g1(x):
        t2 = max(0.0, 1 - x[2] ** 2) / x[2] ** 2
        return 2 / (1 + np.sqrt(1 + a2 * t2))
    return fresnel(float(np.dot(h, l)), n_mat) * d * g1(l) * g1(v) / (4 * l[2] * v[2])


def ggx_albedo(n_mat, alpha, v, steps=64, white=False):
    """Directional albedo of that lobe at the view v: the integral of f cos over the
    hemisphere (midpoint rule in theta, phi; ggx_brdf's formulas, vectorised); white:
    without the Fresnel factor."""
    th = (np.arange(steps) + 0.5) * (np.pi / 2) / steps
    ph = (np.arange(2 * steps) + 0.5) * np.pi / steps
    T, P = np.meshgrid(th, ph, indexing="ij")
    l = np.stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)], -1)
    hv = l + v
    h = hv / np.linalg.norm(hv, axis=-1, keepdims=True)
    a2 = alpha * alpha
    d = a2 / (np.pi * (h[..., 2] ** 2 * (a2 - 1) + 1) ** 2)

    def g1(cz):
        return 2 / (1 + np.sqrt(1 + a2 * np.maximum(0.0, 1 - cz ** 2) / cz ** 2))
    ci = np.clip(np.sum(h * l, -1), 0, 1)
    sin_t = np.sqrt(np.maximum(0.0, 1 - ci * ci)) / n_mat
    cos_t = np.sqrt(1 - sin_t * sin_t)
    rs = (ci - n_mat * cos_t) / (ci + n_mat * cos_t)
    rp = (n_mat * ci - cos_t) / (n_mat * ci + cos_t)
    f = (1.0 if white else 0.5 * (rs * rs + rp * rp)) * d * g1(l[..., 2]) * g1(v[2]) / (4 * l[..., 2] * v[2])
    return float(np.sum(f * np.cos(T) * np.sin(T)) * (np.pi / 2 / steps) * (np.pi / steps))


def pov_highlight(rough, l, v):
    """POV-Ray 3.7's `specular albedo 1 roughness r` radiance per unit light colour:
    K (N.H)^(1/r), K = (n + 2) / (4 (2 - 2^(-n/2))) (POV-Ray normalises the Blinn lobe
    to albedo 1 at normal view; measured here: 1.5234 at n = 10, formula 1.5238)."""
    n = 1.0 / rough
    h = (l + v) / np.linalg.norm(l + v)
    return (n + 2) / (4 * (2 - 2 ** (-n / 2))) * max(h[2], 0.0) ** n


def region_views(items):
    """Per patch: view directions (towards the camera) at 3 x 3 points of its central region."""
    cells, span = layout(len(items))
    h, _ = camera(span)
    out = []
    for x0, y0 in cells:
        vs = []
        for fx in (0.3, 0.5, 0.7):
            for fy in (0.3, 0.5, 0.7):
                d = np.array([0.0, 0.0, h]) - np.array([x0 + fx * PATCH, y0 + fy * PATCH, 0.0])
                vs.append(d / np.linalg.norm(d))
        out.append(vs)
    return out


def highlight_terms(exp, items, sun_dir, sky):
    """Per patch (luminance, absolute): the reference's missing lobe under the sun and
    the sky, and the three terms POV-Ray cannot represent (README, "With highlights on"):
      shape: POV-Ray's highlight is a Blinn lobe, not GGX: |Blinn - GGX| under the sun;
      sky:   POV-Ray's highlights answer light sources only: the lobe's reflection of
             the uniform sky (its directional albedo times the sky) is missing;
      glint: POV-Ray's reflection rays do not see light sources: the sun's image in the
             liquid (film and pore water, R F0(n_liquid)) is drawn as a highlight as wide
             as the wet surface; the smooth traced interface puts it at the mirror
             direction only, outside this view."""
    out = []
    for (name, w), vs in zip(items, region_views(items)):
        m = next(m for m in exp["materials"] if m["name"] == name)
        liq = next(l for l in exp["liquids"] if l["name"] == LIQUID)
        k = m["liquids"][LIQUID]["knots"]
        i = k["wetness"].index(w)
        c, alpha, n_mat = k["film_coverage"][i], k["ggx_alpha"][i], m["ior"]
        weight = k["specular_weight"][i] * (1 - c)
        film_r = c + (1 - c) * k["water_specular_weight"][i]
        f0m, f0l = ((n_mat - 1) / (n_mat + 1)) ** 2, ((liq["ior"] - 1) / (liq["ior"] + 1)) ** 2
        a2 = alpha * alpha
        nb = 2 / a2 - 2 if a2 < 1 else 0.0
        rough = 1.0 if nb <= 1 else min(max(1 / nb, 5e-4), 1.0)
        ggx_sun = np.mean([weight * ggx_brdf(n_mat, alpha, sun_dir, v) * SUN_E * sun_dir[2] for v in vs])
        pov_mat = np.mean([weight * f0m * pov_highlight(rough, sun_dir, v) * SUN_E / np.pi for v in vs])
        glint = np.mean([film_r * f0l * pov_highlight(rough, sun_dir, v) * SUN_E / np.pi for v in vs])
        sky_lobe = weight * sky * ggx_albedo(n_mat, alpha, vs[4]) if weight > 0 else 0.0
        out.append({"shape": abs(pov_mat - ggx_sun), "sky": sky_lobe, "glint": glint,
                    "body": body_factor(k, i, n_mat, alpha, vs[4], sun_dir, sky)})
    return out


def body_factor(k, i, n_mat, alpha, v, sun_dir, sky):
    """Share of the body's light (the highlights-off reference, dry part) that the
    interface holds back: 1 - (1 - ks E(l))(1 - ks E(v)) / (1 - A ks Ebar) (soak/bsdf.h
    COATED), E the GGX lobe's directional albedo (ggx_albedo), Ebar = 2 int E mu dmu,
    E(l) the sun's and the sky's (Ebar) mixed by the sun's share of the irradiance.
    POV-Ray's pigment is the chain's albedo, not lowered by it. Times the dry share of
    the surface, whose coat carries every grain outside the film: weight ks (1 - c) /
    (1 - area) (soak/wet_specular.h point 4; ks when dry); the pore water has no coat;
    under the film the interface's index is n / n_liquid (F0 < 0.004), left out."""
    ks, c = k["specular_weight"][i], k["film_coverage"][i]
    area = c + (1 - c) * k["water_specular_weight"][i]
    if ks <= 0 or area >= 1:
        return 0.0
    ks = min(1.0, ks * (1 - c) / (1 - area))
    A = lum(k["albedo_subsurface"][i])
    mus = (np.arange(12) + 0.5) / 12
    e_bar = 2 * np.mean([mu * ggx_albedo(n_mat, alpha, np.array([np.sqrt(1 - mu * mu), 0.0, mu]), 32) for mu in mus])
    share = sun_share(sun_dir[2], sky)
    e_l = share * ggx_albedo(n_mat, alpha, sun_dir, 32) + (1 - share) * e_bar
    return (1 - area) * (1 - (1 - ks * e_l) * (1 - ks * ggx_albedo(n_mat, alpha, v, 32)) / (1 - A * ks * e_bar))


def interface_parts(exp, name, w, liquid):
    """The chain's liquid-air interface (wetness.h step 5) as two traced surfaces: the film
    (coverage c, the preset's film thickness, the liquid's absorption) and the pore water
    (area a = water_specular_weight of the rest, zero thickness), each over a Lambertian
    base of the subsurface albedo. soak render's "preset" material lays one film of the
    whole interface area c + (1 - c) a and gives all of it the film's thickness once a film
    exists (scene_material.c: right for clear liquids); for an absorbing liquid the pore
    part must not absorb, so the reference is c x film + (1 - c) x pores, two patches mixed."""
    m = next(m for m in exp["materials"] if m["name"] == name)
    liq = next(l for l in exp["liquids"] if l["name"] == liquid)
    k = m["liquids"][liquid]["knots"]
    unit_m = UNIT_MM / 1000.0
    c = interp(k["wetness"], k["film_coverage"], w)
    a = interp(k["wetness"], k["water_specular_weight"], w)
    base = {"type": "lambert", "albedo": [interp(k["wetness"], [v[j] for v in k["albedo_subsurface"]], w) for j in range(3)]}

    def wet(coverage, thickness_m):
        return {"type": "wet", "base": base,
                "film": {"ior": liq["ior"], "thickness": thickness_m / unit_m, "coverage": coverage,
                         "absorption": [x * unit_m for x in liq["sigma_a_per_m"]]}}
    return c, wet(1.0, m["film_thickness_m"]), wet(a, 0.0)


def liquid_renders(soak, root, tmp, exp, items, spp):
    """Per item: (reference luminance, its standard error) from the two interface parts, and POV-Ray's."""
    parts, mats = [], []
    for name, w, liquid in items:
        c, film, pores = interface_parts(exp, name, w, liquid)
        parts.append(c)
        mats += [film, pores]
    cells, _ = layout(len(mats))
    scene = json_scene([("x", 0)] * len(mats), SUN_DIR, SKY_L, 2.0, spp)
    scene["materials"] = {f"m{i}": m for i, m in enumerate(mats)}
    js, ref = os.path.join(tmp, "liquids.json"), os.path.join(tmp, "liquids_soak.exr")
    with open(js, "w") as f:
        json.dump(scene, f, indent=1)
    r = subprocess.run([soak, "render", js, "-o", ref, "--threads", "2", "--seed", "1"], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak render {js}: exit {r.returncode}\n{r.stderr}")
    refs = region_means(read_image(ref), [("x", 0)] * len(mats))
    pv, pov = os.path.join(tmp, "liquids.pov"), os.path.join(tmp, "liquids_pov.exr")
    with open(pv, "w") as f:
        f.write(pov_scene(items, SUN_DIR, SKY_L, 2.0, highlights=0))
    rc, log = povray(pv, pov, RES, RES, os.path.join(root, "povray"))
    if rc != 0:
        fail(f"povray {pv}: exit {rc}\n{log[-2000:]}")
    povs = region_means(read_image(pov), items)
    out = []
    for i, item in enumerate(items):
        c = parts[i]
        (fm, fs), (pm_, ps) = refs[2 * i], refs[2 * i + 1]
        out.append((item, (c * lum(fm) + (1 - c) * lum(pm_), np.hypot(c * lum(fs), (1 - c) * lum(ps))), lum(povs[i][0])))
    return out


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
        for item, (rm, rs), (pm, _) in zip(items, res[0], res[1]):
            rows.append((tag, item[0], item[1], lum(rm), lum(rs), lum(pm), cov_of(*item)))

    def coverage(name, w, liquid=None):
        m = next(m for m in exp["materials"] if m["name"] == name)
        k = m["liquids"][liquid or LIQUID]["knots"]
        i = k["wetness"].index(w)
        return k["film_coverage"][i] + (1 - k["film_coverage"][i]) * k["water_specular_weight"][i]

    ground = render_pair(soak, root, tmp, "ground", patches, SUN_DIR, SKY_L, 2.0, spp, exp, highlights=0)
    collect("ground", patches, ground, coverage)
    hl_rows = []
    for (name, w), (rm, rs), (pm, _), (fm, fs), t in zip(patches, ground[0], ground[2], ground[3],
                                                      highlight_terms(exp, patches, SUN_DIR, SKY_L)):
        t["body"] *= lum(rm)  # of the body's light: the highlights-off reference
        hl_rows.append((name, w, lum(fm), lum(fs), lum(pm), coverage(name, w), t))
    liq_rows = []
    if LIQUID == "water":
        # every other liquid on the canonical ground (brick, concrete), below and above the
        # saturation point and off the knots (0.3, 0.8), and at 1
        liq_items = [(p, w, q) for q in LIQUIDS for p in ("brick", "concrete") for w in (0.3, 0.8, 1.0)]
        lq = liquid_renders(soak, root, tmp, exp, liq_items, spp)
        for item, (r, e), pm in lq:
            m = next(m for m in exp["materials"] if m["name"] == item[0])
            on_knot = item[1] in m["liquids"][item[2]]["knots"]["wetness"]
            liq_rows.append((item, r, e, pm, on_knot))
    metals = render_pair(soak, root, tmp, "metal", METALS, None, SKY_L, 2.0, spp)
    collect("metal", METALS, metals, lambda n, w: 0.0)
    back = np.array([0.3, 0.2, -0.933])
    back = back / np.linalg.norm(back)
    sheets = wetness_levels(exp, SHEETS)
    paper_m = next(m for m in exp["materials"] if m["name"] == "paper")["sheet_thickness_m"]
    sh = render_pair(soak, root, tmp, "sheet", sheets, back, 0.0, paper_m * 1e3 / UNIT_MM, spp, sheet=True)
    collect("backlit", sheets, sh, coverage)
    if report:
        preset = render_pair(soak, root, tmp, "preset", patches, SUN_DIR, SKY_L, 2.0, spp)
        collect("preset", patches, preset, coverage)

    share = sun_share(SUN_DIR[2], SKY_L)
    # Error budget (povray/README.md, "Measured error"), relative, as named terms:
    #   noise: 4 standard errors of the reference's region mean;
    #   tables: linear interpolation in wetness 0.002 (absolute);
    #   view_grid: the view factor's knots and angle grid, 0.002 (absolute; export.h);
    #   exr: half-float EXR output 1e-3;
    #   light: the interface's light half (light_term: POV-Ray's diffuse cannot follow the sun's angle);
    #   metals: 0.03 (POV-Ray mirror at F0 under the film vs GGX alpha 0.05 directional albedo);
    #   back-lit paper: reported, not asserted. Backside diffuse with the two-flux
    #           transmittance (0.1 mm paper, optical depth 5.3: neither POV-Ray's media nor its
    #           subsurface fit) is 20-35 % below the traced slab; the asserted back-lit sheet is
    #           tests/povray/media_slab.py (a sheet thin enough for POV-Ray's media).
    def budget_terms(tag, ref, err, name="", w=0.0, liquid=None, on_knot=False):
        r = max(ref, 1e-9)
        t = {"noise": 4 * err / r, "tables": 0.0 if on_knot else 0.002 / r, "exr": 1e-3}
        if tag == "ground":
            t["view_grid"] = 0.002 / r
            t["light"] = light_term(exp, name, w, liquid or LIQUID, SUN_DIR[2], share)
        elif tag == "metal":
            t["metal"] = 0.03
        elif tag == "backlit":
            t["reported"] = float("inf")  # reported, not asserted (README)
        return t

    def budget(tag, ref, err, cov, name="", w=0.0):
        return sum(budget_terms(tag, ref, err, name, w).values())

    bad = 0
    print(f"sun's share of the irradiance {share:.3f} (sun cos {SUN_DIR[2]:.3f}, n {n_water}); "
          f"light half of water's interface: {light_half(n_water, SUN_DIR[2], 0.0, share):.4f} x area")
    print(f"{'scene':8} {'preset':10} {'w':>6} {'soak':>8} {'+-':>7} {'povray':>8} {'rel.err':>8} {'light':>6} {'budget':>7}")
    for tag, n, w, r, e, p, cov in rows:
        rel = (p - r) / r if r > 0 else float("inf")
        b = budget(tag, r, e, cov, n, w)
        light = budget_terms(tag, r, e, n, w).get("light", 0.0)
        mark = "" if tag == "preset" else ("reported" if b == float("inf") else ("ok" if abs(rel) <= b else "FAIL"))
        bad += mark == "FAIL"
        print(f"{tag:8} {n:10} {w:6.3f} {r:8.4f} {e:7.4f} {p:8.4f} {rel:8.3f} {light:6.3f} {b:7.3f} {mark}")
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
    # Highlights on (soak.inc's default) against soak render's full preset material.
    print("highlights on: soak render (the material's own interface traced); terms POV-Ray cannot represent")
    print(f"{'preset':10} {'w':>6} {'soak':>8} {'povray':>8} {'rel.err':>8} {'shape':>6} {'sky':>6} {'glint':>6} "
          f"{'body':>6} {'budget':>7}")
    for name, w, ref, e, p, cov, t in hl_rows:
        rel = (p - ref) / ref
        b = budget("ground", ref, e, cov, name, w) + (t["shape"] + t["sky"] + t["glint"] + t["body"]) / ref
        mark = "ok" if abs(rel) <= b else "FAIL"
        bad += mark == "FAIL"
        print(f"{name:10} {w:6.3f} {ref:8.4f} {p:8.4f} {rel:8.3f} {t['shape'] / ref:6.3f} {t['sky'] / ref:6.3f} "
              f"{t['glint'] / ref:6.3f} {t['body'] / ref:6.3f} {b:7.3f} {mark}")
    # Every other liquid: the interface term with the liquid's index and its film's absorption.
    if liq_rows:
        print("liquids (canonical ground, highlights off): budget = noise + tables + view grid + EXR + light half with absorption")
        print(f"{'liquid':9} {'preset':9} {'w':>5} {'soak':>8} {'povray':>8} {'rel.err':>8} {'light':>6} {'budget':>7}")
    for (name, w, q), r, e, p, on_knot in liq_rows:
        rel = (p - r) / r
        t = budget_terms("ground", r, e, name, w, q, on_knot)  # tables: exact on a knot
        b = sum(t.values())
        mark = "ok" if abs(rel) <= b else "FAIL"
        bad += mark == "FAIL"
        print(f"{q:9} {name:9} {w:5.2f} {r:8.4f} {p:8.4f} {rel:8.3f} {t['light']:6.3f} {b:7.3f} {mark}")
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
