"""A wet plane in Cycles (add-on installed from the zip), one description
(plane_cases.json) for Cycles and `soak render`.

Asserted (tolerances derived in blender_addon/README.md, "Error"):
  dielectrics: the diffuse radiance D = L - S (S: the same wet material with
    a black base colour, i.e. its specular and coat lobes) against
    E cos(theta)/pi * albedo_core(w) * view_factor(w), albedo_core and the
    view factor (averaged over the image's view cosines) from `soak export
    --target json` (knots): |D/D_ref - 1| <= coat_dim + 0.005/albedo + the
    factor table term (the sun is a delta light and the world black, so
    Cycles' direct diffuse is noise-free; coat_dim is the coat lobe's
    dimming of the diffuse, measured here in 3.x by coat_dimming(), and
    4.x's specular layering measured per case by furnace());
  the same diffuse against soak render, within those terms + SOAK_NOISE +
    the light-angle term (the interface's transmission at the sun's angle,
    which a base colour cannot follow; the viewer's the factor follows);
  the back-lit thin sheet: L against E cos(theta)/pi * T_core(w) (Translucent);
  the metal (copper, Metallic 1), dry and wet: L against soak render of the
    same GGX conductor (dry: 3 %, the two renderers' GGX and Fresnel are the
    same model, 64 spp noise < 0.5 %); wet, plus the film's LOBE TERM: the
    Principled BSDF has one GGX lobe, the film-covered metal is a lobe seen
    through a refracting flat film (soak/wet_specular.h point 3: one lobe of
    width alpha (1 + c (n_liquid - 1)), the base colour the core's normal-
    incidence film albedo); the term is |model / exact - 1| of that lobe
    against the film-refracted lobe, both evaluated here over the image's
    pixels (GGX D and Smith G, Snell, Fresnel transmission) and SOAK_NOISE;
  a dark texture at the Principled's default Specular 0.5, dry and wet: the
    wet/dry ratio of the whole image against the ratio of a plain Principled
    BSDF (no group) given the core's numbers (wet colours from the json
    export's base-colour table, the knots' roughness ratio, Specular 0.5
    times the base's remaining specular, summed here over the film's
    bounces) to the dry material: 0.005 of albedo (tables) + coat_dim;
Printed, not asserted: the full table against soak render (2-37 % apart for
the dielectric presets: its Lambertian base sits under the material's and the
liquid's interfaces; see the README's error table for what is and is not
explained)."""
import json
import math
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
SOAK, ZIP, TMP = A["soak"], A["addon"], A["tmp"]
CASES = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "plane_cases.json")))
SOAK_NOISE = 0.01  # soak render, 16 spp over 64x64 pixels of a sunlit plane: NEE is exact, the film's lobe choice is not
METAL_TOL = 0.03
FACTOR_TABLE = 0.0025  # export_blender.c: the view-factor rows' goal on the colour (white-weighted)
SUN_SHARE = 1.0  # the world is black: all the irradiance is the sun's
os.makedirs(TMP, exist_ok=True)


def mean_exr(path):
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    w, h = img.size
    bpy.data.images.remove(img)
    s = [0.0, 0.0, 0.0]
    for i in range(w * h):
        for c in range(3):
            s[c] += px[4 * i + c]
    return [x / (w * h) for x in s]


def soak_render(name, material, back_lit=False, sheet_m=0.0):
    sun = dict(CASES["sun"])
    if back_lit:
        sun["direction"] = [sun["direction"][0], sun["direction"][1], -sun["direction"][2]]
    unit = CASES["soak_unit_mm"]
    t = (sheet_m if sheet_m > 0 else 0.2) / (unit * 1e-3)  # a sheet's own thickness / 0.2 m slabs
    k = 1.0 / (unit * 1e-3)  # metres -> scene units
    scene = {
        "render": {"width": CASES["render"]["width"], "height": CASES["render"]["height"],
                   "spp": CASES["render"]["soak_spp"], "max_depth": 256},
        "camera": {"position": [x * k for x in CASES["camera"]["position"]], "look_at": [0, 0, 0],
                   "up": CASES["camera"]["up"], "fov": CASES["camera"]["fov"]},
        "lights": [{"type": "sun", "direction": sun["direction"], "irradiance": sun["irradiance"]}],
        "materials": {"m": material},
        "objects": [{"type": "box", "min": [-k, -k, -t], "max": [k, k, 0], "material": "m"}],
    }
    js = os.path.join(TMP, name + ".json")
    exr = os.path.join(TMP, name + "_soak.exr")
    with open(js, "w") as f:
        json.dump(scene, f)
    r = subprocess.run([SOAK, "render", js, "-o", exr, "--threads", "2"], capture_output=True, text=True)
    if r.returncode != 0:
        common.fail(f"soak render {js}: {r.stderr.strip()}")
    return mean_exr(exr)


def setup_scene():
    return common.plane_case_scene(CASES, CASES["render"]["width"], CASES["render"]["height"])


def add_sun(sc, back_lit=False):
    common.add_case_sun(sc, CASES, back_lit)


def blender_render(sc, name):
    path = os.path.join(TMP, name + "_blender.exr")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    return mean_exr(path)


def furnace(sc, name):
    """The scene's material (base colour black) in a white furnace, the sun
    off: the directional albedo of its specular and coat lobes at the view."""
    bg = sc.world.node_tree.nodes["Background"]
    sun = bpy.data.objects["S"]
    sun.hide_render = True
    bg.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    bg.inputs["Strength"].default_value = 1.0
    e = lum(blender_render(sc, name + "_furnace"))
    sun.hide_render = False
    bg.inputs["Strength"].default_value = 0.0
    return e


def coat_dimming():
    """Blender's own dimming of the diffuse by the film's coat lobe: the
    diffuse D = L - S (S: the same with a black base) of a plain grey
    Principled BSDF (no group) under the cases' sun, coat weight 1 and
    roughness 0 as the group sets them at full cover, over D at coat weight
    0. Measured in 3.x, whose Principled v1 adds its clear coat on top of
    the base (2026-11-28: 1.00000 at coat 0.25 and 1, so the term is ~0
    and a missing view factor shows); in 4.x the group undoes the coat's
    dimming and the specular lobe's is measured per case (furnace())."""
    if bpy.app.version >= (4, 0, 0):
        return 0.0
    coat = "Clearcoat"
    d = []
    for weight in (0.0, 1.0):
        sc, plane, mat = setup_scene()
        add_sun(sc)
        bsdf = mat.node_tree.nodes["Principled BSDF"]
        bsdf.inputs[coat].default_value = weight
        bsdf.inputs[coat + " Roughness"].default_value = 0.0
        bsdf.inputs["Base Color"].default_value = (0.5, 0.5, 0.5, 1.0)
        lg = lum(blender_render(sc, f"coat_{weight}_grey"))
        bsdf.inputs["Base Color"].default_value = (0.0, 0.0, 0.0, 1.0)
        d.append(lg - lum(blender_render(sc, f"coat_{weight}_black")))
    term = abs(d[1] / d[0] - 1.0)
    print(f"coat dimming of the diffuse at coat weight 1 (3.x): {term:.5f}")
    return term


def lum(c):
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def knot(table, key, w):
    ws, vs = table["knots"]["wetness"], table["knots"][key]
    for i in range(len(ws) - 1):
        if ws[i] <= w <= ws[i + 1]:
            t = (w - ws[i]) / (ws[i + 1] - ws[i])
            return [a + (b - a) * t for a, b in zip(vs[i], vs[i + 1])]
    return vs[-1]


def film_total(base, incidence):
    """Lekner-Dorf total reflectance of a water film over a Lambertian base
    (soak albedo --model film: the core's closed form, a second method)."""
    r = subprocess.run([SOAK, "albedo", "--model", "film", "--base-albedo", f"{base:.6f}", "--ior", "1.333",
                        "--incidence", str(incidence)], capture_output=True, text=True)
    if r.returncode != 0:
        common.fail(r.stderr)
    return float(r.stdout.strip().splitlines()[-1])


def interp1(xs, ys, x):
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            t = (x - xs[i]) / (xs[i + 1] - xs[i]) if xs[i + 1] > xs[i] else 0.0
            return ys[i] + (ys[i + 1] - ys[i]) * t
    return ys[-1]


def base_specular_factor(n, n_liq, sigma_a_per_m, thickness_m, c):
    """(1 - c) + c R_under / F0(n): the base's specular under the film summed
    over its bounces (Fresnel at normal incidence), channel mean."""
    def r0(x):
        return ((x - 1) / (x + 1)) ** 2
    r12, r23, under = r0(n_liq), r0(n / n_liq), 0.0
    for a in sigma_a_per_m:
        e = math.exp(-2 * a * thickness_m)
        bounce, total = (1 - r12) * r23 * e * (1 - r12), 0.0
        for _ in range(40):
            total += bounce
            bounce *= r12 * r23 * e
        under += total / 3
    return (1 - c) + c * under / r0(n)


def light_angle_term(table, w, theta_deg, sun_share):
    """What a base colour cannot follow: the liquid interface's diffuse
    transmission at the light's angle. The group's view factor follows the
    viewer's half (soak_wetness_view_factor); the light's half, D_dir(theta)
    / D_hemi of the film over the subsurface albedo (soak albedo --model
    film, the core's closed form: a second method), stays, on the
    interface's area (film + pore water) and for the sun's share of the
    irradiance (a uniform sky's mean of the factor is 1)."""
    k = table["knots"]
    i = min(range(len(k["wetness"])), key=lambda j: abs(k["wetness"][j] - w))
    c = k["film_coverage"][i] + (1 - k["film_coverage"][i]) * k["water_specular_weight"][i]
    if c <= 0:
        return 0.0
    a = lum(k["albedo_subsurface"][i])
    d_dir = film_total(a, theta_deg) - film_total(0.0, theta_deg)
    d_hemi = film_total(a, "diffuse") - film_total(0.0, "diffuse")
    return sun_share * c * abs(d_dir / d_hemi - 1.0)


def view_cosines(n=16):
    """cos(view zenith) at n x n pixel centres of the camera (looking down
    at the plane from CASES' camera position)."""
    cam_z, fov = CASES["camera"]["position"][2], CASES["camera"]["fov"]
    w, h = CASES["render"]["width"], CASES["render"]["height"]
    tan_half = math.tan(math.radians(fov) / 2)
    out = []
    for j in range(n):
        for i in range(n):
            x = (2 * (i + 0.5) / n - 1) * tan_half * cam_z * w / h
            y = (2 * (j + 0.5) / n - 1) * tan_half * cam_z
            out.append(cam_z / math.sqrt(x * x + y * y + cam_z * cam_z))
    return out


def view_factor(table, w, cosines):
    """The json export's view factor (knots.view_factor: the core's, per knot
    on view_cos) at wetness w, averaged over the image's view cosines: what
    the group's base colour is multiplied by (rgb)."""
    k = table["knots"]
    n = len(k["view_factor"][0]) - 1
    out = [0.0, 0.0, 0.0]
    for cos_o in cosines:
        x = min(cos_o, 1.0) * n
        i = min(int(x), n - 1)
        t = x - i
        for c in range(3):
            lo = interp1(k["wetness"], [f[i][c] for f in k["view_factor"]], w)
            hi = interp1(k["wetness"], [f[i + 1][c] for f in k["view_factor"]], w)
            out[c] += (lo + (hi - lo) * t) / len(cosines)
    return out


def factor_table_term(table, w):
    """The group's view-factor table error, relative: its rows are refined
    until |factor error| x (wet albedo of a white dry colour) <= 0.0025
    (export_blender.c), so relative to any colour it is at most 0.0025 over
    the white colour's wet albedo (the json export's base-colour table at
    dry albedo 1, interpolated in wetness)."""
    bt = table["base_colour"]
    j = bt["dry_albedo"].index(1.0) if 1.0 in bt["dry_albedo"] else len(bt["dry_albedo"]) - 1
    white = min(interp1(bt["wetness"], [row[j] for row in bt["albedo"][c]], w) for c in range(3))
    return FACTOR_TABLE / white


def _ggx(cos_h, alpha):
    t2 = max(1.0 - cos_h * cos_h, 0.0) / (cos_h * cos_h)
    return alpha * alpha / (math.pi * cos_h ** 4 * (alpha * alpha + t2) ** 2)


def _g1(cos_t, alpha):
    t2 = max(1.0 - cos_t * cos_t, 0.0) / max(cos_t * cos_t, 1e-12)
    return 2.0 / (1.0 + math.sqrt(1.0 + alpha * alpha * t2))


def _lobe(wi, wo, alpha):
    """GGX D G / (4 cos_i cos_o) for unit vectors in the upper hemisphere."""
    h = [a + b for a, b in zip(wi, wo)]
    n = math.sqrt(sum(x * x for x in h))
    return _ggx(h[2] / n, alpha) * _g1(wi[2], alpha) * _g1(wo[2], alpha) / (4 * wi[2] * wo[2])


def _refract_in(w, n):
    """The direction inside a flat film of index n of the outside direction w
    (same azimuth), and the Fresnel transmittance of the top."""
    s = math.sqrt(max(1 - w[2] * w[2], 0.0))
    st = s / n
    ct = math.sqrt(1 - st * st)
    rs = ((w[2] - n * ct) / (w[2] + n * ct)) ** 2
    rp = ((ct - n * w[2]) / (ct + n * w[2])) ** 2
    k = st / s if s > 0 else 0.0
    return (w[0] * k, w[1] * k, ct), 1 - 0.5 * (rs + rp)


def metal_lobe_term(alpha, c, n, width, height, fov, cam_z, sun):
    """|one-lobe model / film-refracted lobe - 1| over the image (see the
    docstring), for the film-covered share c of a GGX conductor of width
    alpha under a flat film of index n; normal-incidence Fresnel in both."""
    s = math.sqrt(sum(x * x for x in sun))
    wi = [x / s for x in sun]
    wi_in, ti = _refract_in(wi, n)
    t0 = 1 - ((n - 1) / (n + 1)) ** 2
    a_app = min(alpha * (1 + c * (n - 1)), 1.0)
    tan_half = math.tan(math.radians(fov) / 2)
    model = exact = 0.0
    for j in range(height):
        for i in range(width):
            x = (2 * (i + 0.5) / width - 1) * tan_half * cam_z * width / height
            y = (2 * (j + 0.5) / height - 1) * tan_half * cam_z
            d = math.sqrt(x * x + y * y + cam_z * cam_z)
            wo = (-x / d, -y / d, cam_z / d)
            wo_in, to = _refract_in(wo, n)
            model += _lobe(wi, wo, a_app)
            film = ti * to / (t0 * t0) * _lobe(wi_in, wo_in, alpha) / (n * n)
            exact += (1 - c) * _lobe(wi, wo, alpha) + c * film
    return abs(model / exact - 1.0)


def main():
    common.install_addon(ZIP)
    ref_path = os.path.join(TMP, "export.json")
    r = subprocess.run([SOAK, "export", "--target", "json", "-o", ref_path], capture_output=True, text=True)
    if r.returncode != 0:
        common.fail(r.stderr)
    ref = {m["name"]: m for m in json.load(open(ref_path))["materials"]}
    import math
    d = CASES["sun"]["direction"]
    e_cos = CASES["sun"]["irradiance"] * d[2] / math.sqrt(sum(x * x for x in d)) / math.pi
    rows, failures, vs_soak = [], [], []
    coat_dim = coat_dimming()
    theta_sun = math.degrees(math.acos(d[2] / math.sqrt(sum(x * x for x in d))))
    cosines = view_cosines()

    layer = [0.0]  # the 4.x specular layer's dimming of the last case's diffuse

    def case(name, preset, wetness, liquid="water", back_lit=False, metallic=0.0, black=False):
        sc, plane, mat = setup_scene()
        add_sun(sc, back_lit)
        bsdf = mat.node_tree.nodes["Principled BSDF"]
        bsdf.inputs["Metallic"].default_value = metallic
        mat.soak.preset, mat.soak.liquid = preset, liquid
        mat.soak.colour_source = "PRESET"
        mat.soak.wetness = wetness
        bpy.context.view_layer.objects.active = plane
        assert bpy.ops.soak.make_wet() == {"FINISHED"}
        lb = blender_render(sc, name)
        for l in list(bsdf.inputs["Base Color"].links):
            mat.node_tree.links.remove(l)
        bsdf.inputs["Base Color"].default_value = (0, 0, 0, 1)
        spec = blender_render(sc, name + "_black")
        layer[0] = 0.0
        if bpy.app.version >= (4, 0, 0) and not back_lit:
            # 4.x layers the base under its specular lobe: the diffuse is
            # dimmed by that lobe's directional albedo at the view, which a
            # black base in a white furnace (no sun) shows (the coat's share
            # included, an upper bound: the group undoes the coat's)
            layer[0] = furnace(sc, name)
        # "interface": 0: the Lambertian body alone under the liquid, without the material's
        # own rough interface, so that the reference's image is the diffuse part compared
        # below (the Principled BSDF's own specular lobe is taken out by the black-base render)
        ls = soak_render(name, {"type": "preset", "name": preset, "wetness": wetness, "liquid": liquid,
                                "unit_mm": CASES["soak_unit_mm"], "interface": 0}, back_lit,
                         ref[preset].get("sheet_thickness_m", 0.0))
        return lb, spec, ls

    def check(label, got, want, tol):
        rel = got / want - 1.0 if want > 0 else float("inf")
        if not abs(rel) <= tol:
            failures.append(f"{label}: blender {got:.5f} vs reference {want:.5f} ({rel:+.2%}, tol {tol:.2%})")
        return rel

    for p in CASES["presets"]:
        t = ref[p]["liquids"]["water"]
        for w in [0.0] + CASES["wetness_levels"]:
            lb, sb, ls = case(f"{p}_{w}", p, w)
            alb = knot(t, "albedo", w)
            vf = view_factor(t, w, cosines)
            want = lum([a * f for a, f in zip(alb, vf)]) * e_cos
            got = lum(lb) - lum(sb)
            table = 0.005 / lum(alb) + factor_table_term(t, w)
            rel = check(f"{p} w={w} diffuse", got, want, coat_dim + table + layer[0])
            rows.append((p, w, lum(lb), want + lum(sb), rel, lum(ls)))
            # Against the reference tracer (black world: the film's mirror image of
            # the sun misses the camera, so soak render's image is its diffuse part).
            light = light_angle_term(t, w, theta_sun, SUN_SHARE)
            tol = coat_dim + table + layer[0] + light + SOAK_NOISE
            r2 = got / lum(ls) - 1.0
            if not abs(r2) <= tol:
                failures.append(f"{p} w={w}: Cycles diffuse {got:.5f} vs soak render {lum(ls):.5f} ({r2:+.2%}, tol {tol:.2%})")
            vs_soak.append((p, w, got, lum(ls), r2, tol, coat_dim + layer[0], table, light, lum(vf)))
    m = CASES["metal"]
    mk = ref[m]["liquids"]["water"]["knots"]
    metal_rows = []
    for w in [0.0] + CASES["wetness_levels"]:
        lb, sb, ls = case(f"{m}_{w}", m, w, metallic=1.0)
        c = interp1(mk["wetness"], mk["film_coverage"], w)
        water_ior = {l["name"]: l for l in json.load(open(ref_path))["liquids"]}["water"]["ior"]
        term = metal_lobe_term(ref[m]["ggx_alpha_dry"], c, water_ior, 16, 16, CASES["camera"]["fov"],
                               CASES["camera"]["position"][2], CASES["sun"]["direction"])
        tol = METAL_TOL + term + (SOAK_NOISE if w > 0 else 0.0)
        rel = check(f"{m} w={w} vs soak render", lum(lb), lum(ls), tol)
        rows.append((m, w, lum(lb), lum(ls), rel, lum(ls)))
        metal_rows.append((w, lum(lb), lum(ls), rel, term, tol))
        if w == 1.0:
            # a copper-coloured Metallic material wetted with the default
            # preset (sand): recognised as a metal, it gets the conductor's
            # function and must render as the copper preset does
            sc, plane, mat = setup_scene()
            add_sun(sc)
            bsdf = mat.node_tree.nodes["Principled BSDF"]
            bsdf.inputs["Metallic"].default_value = 1.0
            bsdf.inputs["Base Color"].default_value = list(ref[m]["dry_albedo"]) + [1.0]
            bsdf.inputs["Roughness"].default_value = math.sqrt(ref[m]["ggx_alpha_dry"])
            mat.soak.preset, mat.soak.liquid, mat.soak.colour_source = "sand", "water", "MATERIAL"
            mat.soak.wetness = w
            bpy.context.view_layer.objects.active = plane
            assert bpy.ops.soak.make_wet() == {"FINISHED"}
            lm = blender_render(sc, f"{m}_as_metallic_sand_{w}")
            rel = check(f"Metallic {m}-coloured material, preset sand, w={w} vs soak render {m}", lum(lm), lum(ls), tol)
            rows.append((f"{m}-coloured Metallic, preset sand", w, lum(lm), lum(ls), rel, lum(ls)))
    # a textured material: left half colour A, right half B (an image texture,
    # Closest), its own colours through the group; the view is centred, so
    # the reference is the mean of the two halves' core albedos, read from
    # the json export's base-colour table at its own nodes (exact core values)
    tx = CASES["textured"]
    bt = ref[tx["preset"]]["liquids"][tx["liquid"]]["base_colour"]
    for w in tx["wetness"]:
        sc, plane, mat = setup_scene()
        add_sun(sc)
        img = bpy.data.images.new("halves", 2, 1, float_buffer=True)
        img.colorspace_settings.name = "Non-Color"
        img.pixels.foreach_set([v for c in tx["colours"] for v in list(c) + [1.0]])
        tex = mat.node_tree.nodes.new("ShaderNodeTexImage")
        tex.image, tex.interpolation = img, "Closest"
        bsdf = mat.node_tree.nodes["Principled BSDF"]
        mat.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
        mat.soak.preset, mat.soak.liquid, mat.soak.colour_source = tx["preset"], tx["liquid"], "MATERIAL"
        mat.soak.wetness = w
        bpy.context.view_layer.objects.active = plane
        assert bpy.ops.soak.make_wet() == {"FINISHED"}
        lb = blender_render(sc, f"textured_{w}")
        gn = mat.node_tree.nodes["Soak Wet"]
        for l in list(gn.inputs["Base Color"].links):
            mat.node_tree.links.remove(l)
        gn.inputs["Base Color"].default_value = (0, 0, 0, 1)
        sb = blender_render(sc, f"textured_{w}_black")
        dim = furnace(sc, f"textured_{w}") if bpy.app.version >= (4, 0, 0) else 0.0  # as in case()
        assert w in bt["wetness"], f"plane_cases.json: wetness {w} is not a knot of the export's base-colour table {bt['wetness']}"
        iw = bt["wetness"].index(w)
        alb = [0.5 * sum(bt["albedo"][c][iw][bt["dry_albedo"].index(col[c])] for col in tx["colours"])
               for c in range(3)]
        tt = ref[tx["preset"]]["liquids"][tx["liquid"]]
        vf = view_factor(tt, w, cosines)   # the preset's, on the user's colours
        want = lum([a * f for a, f in zip(alb, vf)]) * e_cos
        rel = check(f"textured w={w} diffuse", lum(lb) - lum(sb), want,
                    coat_dim + 0.005 / lum(alb) + factor_table_term(tt, w) + dim)
        rows.append((f"textured ({tx['preset']} class)", w, lum(lb), want + lum(sb), rel, float("nan")))
    # a dark texture at the Principled's default Specular (0.5): wet/dry of
    # the whole image against a plain Principled given the core's numbers
    dk = CASES["dark_texture"]
    dt = ref[dk["preset"]]["liquids"][dk["liquid"]]
    liq = {l["name"]: l for l in json.load(open(ref_path))["liquids"]}[dk["liquid"]]
    spec_name = "Specular IOR Level" if bpy.app.version >= (4, 0, 0) else "Specular"
    dark_rows = []

    def halves(colours):
        img = bpy.data.images.new("halves", 2, 1, float_buffer=True)
        img.colorspace_settings.name = "Non-Color"
        img.pixels.foreach_set([v for c in colours for v in list(c) + [1.0]])
        return img

    for w in dk["wetness"]:
        sc, plane, mat = setup_scene()
        add_sun(sc)
        tex = mat.node_tree.nodes.new("ShaderNodeTexImage")
        tex.image, tex.interpolation = halves(dk["colours"]), "Closest"
        bsdf = mat.node_tree.nodes["Principled BSDF"]
        mat.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
        spec0, rough0 = bsdf.inputs[spec_name].default_value, bsdf.inputs["Roughness"].default_value
        l_dry = lum(blender_render(sc, f"dark_dry_{w}"))
        mat.soak.preset, mat.soak.liquid, mat.soak.colour_source = dk["preset"], dk["liquid"], "MATERIAL"
        mat.soak.wetness = w
        bpy.context.view_layer.objects.active = plane
        assert bpy.ops.soak.make_wet() == {"FINISHED"}
        l_wet = lum(blender_render(sc, f"dark_wet_{w}"))
        # the reference: a plain Principled BSDF with the core's numbers
        bt = dt["base_colour"]
        assert w in bt["wetness"], f"plane_cases.json: wetness {w} is not a knot of the export's base-colour table {bt['wetness']}"
        iw = bt["wetness"].index(w)
        vf = view_factor(dt, w, cosines)   # the preset's view factor, on the user's colours
        wet_cols = [[bt["albedo"][c][iw][bt["dry_albedo"].index(col[c])] * vf[c] for c in range(3)]
                    for col in dk["colours"]]
        kn = dt["knots"]
        cov = interp1(kn["wetness"], kn["film_coverage"], w)
        factor = base_specular_factor(ref[dk["preset"]]["ior"], liq["ior"], liq["sigma_a_per_m"],
                                      ref[dk["preset"]]["film_thickness_m"], cov)
        sc, plane, mat = setup_scene()
        add_sun(sc)
        tex = mat.node_tree.nodes.new("ShaderNodeTexImage")
        tex.image, tex.interpolation = halves(wet_cols), "Closest"
        bsdf = mat.node_tree.nodes["Principled BSDF"]
        mat.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
        bsdf.inputs[spec_name].default_value = spec0 * factor
        bsdf.inputs["Roughness"].default_value = rough0 * interp1(kn["wetness"], kn["roughness"], w) / kn["roughness"][0]
        l_ref = lum(blender_render(sc, f"dark_ref_{w}"))
        a_dry = sum(lum(col) for col in dk["colours"]) / 2
        a_wet = sum(lum(col) for col in wet_cols) / 2
        tol = (0.005 + FACTOR_TABLE) * e_cos / l_ref + coat_dim
        rel = check(f"dark texture w={w}: wet/dry", l_wet / l_dry, l_ref / l_dry, tol)
        dark_rows.append((w, l_dry, l_wet, l_wet / l_dry, l_ref / l_dry, a_wet / a_dry, factor, rel, tol))
    ts = CASES["thin_sheet"]
    t = ref[ts["preset"]]["liquids"]["water"]
    back = {}
    for w in ts["wetness"]:
        lb, sb, ls = case(f"{ts['preset']}_back_{w}", ts["preset"], w, back_lit=True)
        back[w] = lb
        tr = knot(t, "sheet_transmittance", w)
        want = lum(tr) * e_cos
        rel = check(f"{ts['preset']} back-lit w={w}", lum(lb), want, 0.01 + 0.005 / lum(tr))
        rows.append((ts["preset"] + " back-lit", w, lum(lb), want, rel, lum(ls)))
        # issue 39: white light through office paper is not blue
        rb = lb[0] / max(lb[2], 1e-9)
        print(f"{ts['preset']} back-lit w={w}: red/blue {rb:.3f} (white sun)")
        if not 0.75 < rb < 1.6:   # within 25 % of neutral (issue 39: 0.05); the preset is slightly cool
            failures.append(f"{ts['preset']} back-lit w={w}: red/blue {rb:.3f} outside [0.75, 1.6] (blue paper)")
    w_dry, w_wet = min(back), max(back)
    ratio = lum(back[w_wet]) / max(lum(back[w_dry]), 1e-9)
    print(f"{ts['preset']} back-lit wet/dry (w {w_wet} / {w_dry}): {ratio:.3f}")
    if not ratio > 1.0:   # [JLD99] sec. 4.1: the wet spot is brighter lit from behind
        failures.append(f"{ts['preset']} back-lit wet/dry {ratio:.3f}: not brighter wet")
    print("\n| preset | wetness | Cycles | reference | Cycles vs reference | soak render | Cycles / soak render |")
    print("|---|---|---|---|---|---|---|")
    for p, w, lb, want, rel, ls in rows:
        if ls == ls:
            print(f"| {p} | {w} | {lb:.4f} | {want:.4f} | {rel:+.2%} | {ls:.4f} | {lb / ls:.2f} |")
        else:
            print(f"| {p} | {w} | {lb:.4f} | {want:.4f} | {rel:+.2%} | - | - |")
    print("\n| preset | wetness | Cycles diffuse | soak render | difference | tolerance | version term | "
          "tables (albedo + view factor) | light-angle term | view factor (image mean) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for p, w, got, ls, r2, tol, ver, table, light, vf in vs_soak:
        print(f"| {p} | {w} | {got:.4f} | {ls:.4f} | {r2:+.2%} | {tol:.2%} | {ver:.2%} | {table:.2%} | "
              f"{light:.2%} | {vf:.4f} |")
    print(f"\n{m} (Metallic 1) against soak render, Blender {bpy.app.version_string}:")
    print("| wetness | Blender | soak render | difference | lobe term | tolerance |")
    print("|---|---|---|---|---|---|")
    for w, lb, ls, rel, term, tol in metal_rows:
        print(f"| {w} | {lb:.4f} | {ls:.4f} | {rel:+.2%} | {term:.2%} | {tol:.2%} |")
    print(f"\ndark texture {dk['colours']} ({dk['preset']}, {dk['liquid']}), default Specular, "
          f"Blender {bpy.app.version_string}:")
    print("| wetness | dry | wet | wet/dry | reference wet/dry | core albedo wet/dry | base specular factor | "
          "difference | tolerance |")
    print("|---|---|---|---|---|---|---|---|---|")
    for w, ld, lw, r, rr, ra, f, rel, tol in dark_rows:
        print(f"| {w} | {ld:.4f} | {lw:.4f} | {r:.3f} | {rr:.3f} | {ra:.3f} | {f:.3f} | {rel:+.2%} | {tol:.2%} |")
    if failures:
        common.fail("; ".join(failures))
    print("PASS")


main()
