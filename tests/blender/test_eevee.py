"""EEVEE against Cycles on one wet plane, in the Blender that runs it (3.4:
EEVEE, 4.2+: EEVEE Next), with the description of plane_cases.json (one
sun 30 degrees off the normal, black world, camera along the normal).

Per state (dry: Wetness 0, wet: Wetness 1; sand preset, Exact lookups, the
path EEVEE needs) and engine: L, the plane, and S, the same with a black base
colour (the specular and coat lobes); the diffuse part D = L - S.
Asserted:
  1. the diffuse lobe alone (coat and base specular set to 0, so that each
     engine's own layering drops out) keeps its EEVEE/Cycles ratio when wet:
       |(P_E/P_C)_wet / (P_E/P_C)_dry - 1|
           <= 2^-11 per state (EEVEE reads half-precision GPU copies of the
              tables) + EEVEE Next's half-float render buffer (one half ulp of
              each channel's value, from the pixels; 0 for 3.x's float
              buffer) + 3 sigma
     P the plane's mean; the dry ratio is the baseline (what EEVEE's sun
     shading differs by, measured); a base colour EEVEE cannot read (the
     4.2+ black material) fails it by 100 %;
  2. the wet/dry ratio of the whole image, EEVEE against Cycles:
       |ratio_E / ratio_C - 1| <= sum over dry, wet of |S_E - S_C| / L_C
                                 + 3 sigma
     the named term: EEVEE's specular for a sun (its LTC fit of GGX; split-
     sum only for world light, black here) is not Cycles' sampled GGX,
     measured from the black-base renders of each state;
  3. the highlight view against soak render (plane_cases.json "highlight":
     the camera at the sun's mirror direction; its presets and asserted
     wetness levels; test_render_compare.py's view for Cycles): EEVEE's whole image E
     of the Soak material against soak render's whole preset material F,
       |E - F - (Q_E - Q_C)| <= Cycles' named terms (highlight_named: the
           diffuse part's terms, body hold-back, Fresnel form, 4.x
           multiscatter, film-covered lobe, soak render's noise)
         + 2^-11 E (half-precision tables) + EEVEE Next's half-float
           rounding of E and Q_E (pixel by pixel) + 3 sigma of Q_C
     the EEVEE term Q_E - Q_C, with its sign: a PLAIN Principled BSDF (no
     Soak nodes) given the core's numbers for the preset at that wetness
     (json export: colour x view factor, roughness, ks F0(n) x the lobe left
     under the film, a smooth coat of the interface's area), rendered by
     EEVEE and by Cycles at the same view: how EEVEE draws a GGX lobe, a
     smooth coat and a delta sun (LTC, its sun's mirror image in a smooth
     coat, which Cycles and soak render cannot show), a property of the
     renderer measured without our nodes. Centring the interval on it is
     stricter than adding |Q_E - Q_C| to the tolerance (which it implies),
     and keeps the check meaningful where EEVEE Next's image of the sun is
     0.4-2.7x the rest of the wet image; an error of ours (a wrong lobe weight:
     1.3 x the specular fails 3.4, 1.5 x fails 4.3 and 5.2) is in E only.
     Cycles' image of the Soak material, rendered here for the terms, is
     held to |C - F| <= Cycles' named terms + 3 sigma as well.
sigma: the Monte Carlo error of the ratio, measured: every Cycles image is
rendered with two seeds, and the standard error of each mean comes from the
pixel differences of the pair, std(a - b) / (2 sqrt(n)); EEVEE's anti-aliasing
samples are a fixed pattern (a repeat gives the same pixels), so its images
carry no seed noise. Both engines read the same tables through the same
nodes, so the tables' own error against the core cancels here (it is
measured against the core in test_group_values)."""
import json
import math
import struct
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import test_render_compare as rc  # noqa: E402  (the highlight view's named terms; its main() runs only as a script)

A = common.args()
ZIP, TMP = A["addon"], A["tmp"]
CASES = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "plane_cases.json")))
EEVEE = common.eevee_engine()
SIZE = 32
quant = {}  # (tag, engine) -> half-buffer quantisation term of that render
rounding = {}  # (tag, engine) -> the same, absolute and pixel by pixel (half_rounding)
pixels = {}  # (tag, engine) -> luminance per pixel (the first seed)
# EEVEE samples the group's float tables from their GPU copies, which
# Blender uploads in half precision (10-bit mantissa): each value read is
# within 2^-11 of the table's, per state.
HALF_TABLE_TERM = 2.0 ** -11
W = (0.2126, 0.7152, 0.0722)
os.makedirs(TMP, exist_ok=True)


def luminance(px):
    return [W[0] * px[i] + W[1] * px[i + 1] + W[2] * px[i + 2] for i in range(0, len(px), 4)]


def half_exact(v):
    return struct.unpack("e", struct.pack("e", v))[0] == v


def half_buffer_term(px):
    """Relative quantisation bound of a render stored in half floats (EEVEE
    Next's render buffers; detected from the pixels themselves: every value a
    half), 0 for a float buffer: one half ulp per channel of the mean."""
    values = [px[i + c] for i in range(0, min(len(px), 4 * 64), 4) for c in range(3)]
    if not all(half_exact(v) for v in values):
        return 0.0
    n = len(px) // 4
    means = [sum(px[c::4]) / n for c in range(3)]
    ulp = [2.0 ** (math.floor(math.log2(m)) - 10) if m > 0 else 0.0 for m in means]
    lum = sum(w * m for w, m in zip(W, means))
    return sum(w * u for w, u in zip(W, ulp)) / lum if lum > 0 else 0.0


def half_rounding(px):
    """Absolute bound on the rounding of the image's mean luminance when the
    render is stored in half floats (detected as half_buffer_term does): half
    an ulp of every channel value, weighted and averaged; 0 for a float
    buffer. Pixel by pixel, so a few very bright pixels (EEVEE Next's mirror
    image of the sun, 80 where the rest is 0.2) count at their own ulp."""
    values = [px[i + c] for i in range(0, min(len(px), 4 * 64), 4) for c in range(3)]
    if not all(half_exact(v) for v in values):
        return 0.0
    total = 0.0
    for i in range(0, len(px), 4):
        for c in range(3):
            v = abs(px[i + c])
            total += W[c] * 2.0 ** (max(math.floor(math.log2(v)), -14) - 11) if v > 0 else 0.0
    return total / (len(px) // 4)


def scene():
    sc, plane, mat = common.plane_case_scene(CASES, SIZE, SIZE)
    sc.eevee.taa_render_samples = 4
    # What costs EEVEE seconds per render here and cannot change a pixel: the
    # world's light probe (the world is black; smallest resolution: 3.4's
    # 512 -> 64 took its render from 2.3 s to 0.1 s of CPU) and, in 4.2+,
    # shadow maps (one flat plane cannot shadow itself; 4.3: 1.7 -> 0.2 s).
    if bpy.app.version >= (4, 2, 0):
        sc.world.probe_resolution = "128"
        sc.eevee.use_shadows = False
    else:
        sc.eevee.gi_cubemap_resolution = "64"
    common.add_case_sun(sc, CASES)
    return sc, plane, mat


def render(sc, engine, tag):
    """(mean, standard error of the mean) of the image's luminance."""
    sc.render.engine = engine
    images = []
    for seed in ((1, 2) if engine == "CYCLES" else (1,)):
        sc.cycles.seed = seed
        path = os.path.join(TMP, f"{tag}_{engine}_{seed}.exr")
        sc.render.filepath = path
        bpy.ops.render.render(write_still=True)
        px = common.load_pixels(path)
        quant[tag, engine] = half_buffer_term(px)
        rounding[tag, engine] = half_rounding(px)
        images.append(luminance(px))
        pixels[tag, engine] = images[0]
    n = len(images[0])
    m = sum(sum(im) for im in images) / (n * len(images))
    if len(images) == 1:
        return m, 0.0
    d = [a - b for a, b in zip(*images)]
    dm = sum(d) / n
    sd = math.sqrt(sum((x - dm) ** 2 for x in d) / (n - 1))
    return m, sd / (2 * math.sqrt(n))


def rel_se(pairs):
    """Relative standard error of a product/quotient of (value, se) factors."""
    return math.sqrt(sum((se / v) ** 2 for v, se in pairs if v != 0))


def f0_of(n):
    return ((n - 1) / (n + 1)) ** 2


def plain_values(ref, water, preset, w, cosines):
    """The core's numbers (the json export's knots) for a plain Principled BSDF
    standing for the preset under water at wetness w: base colour (albedo x
    the view factor over the image's view cosines), roughness, the base
    lobe's normal-incidence reflectance ks F0(n) x its share left under the
    film (summed over the film's bounces), coat weight (the interface area:
    film + water-filled pores) and the coat's index."""
    m, t = ref[preset], ref[preset]["liquids"]["water"]
    k = t["knots"]
    c = rc.interp1(k["wetness"], k["film_coverage"], w)
    pore = rc.interp1(k["wetness"], k["water_specular_weight"], w)
    ks = rc.interp1(k["wetness"], k["specular_weight"], w)
    left = rc.base_specular_factor(m["ior"], water["ior"], water["sigma_a_per_m"], m["film_thickness_m"], c)
    colour = [a * f for a, f in zip(rc.knot(t, "albedo", w), rc.view_factor(t, w, cosines))]
    return {"colour": colour, "roughness": rc.interp1(k["wetness"], k["roughness"], w),
            "f0": ks * f0_of(m["ior"]) * left, "coat": c + (1 - c) * pore, "coat_ior": water["ior"]}


def set_plain(bsdf, v):
    """A Principled BSDF given plain_values through Blender's documented
    inputs (3.x: F0 = 0.08 x Specular; 4.x: F0 = F0(IOR) x 2 x Specular IOR
    Level), the coat smooth as the group sets it."""
    bsdf.inputs["Base Color"].default_value = list(v["colour"]) + [1.0]
    bsdf.inputs["Roughness"].default_value = v["roughness"]
    if bpy.app.version >= (4, 0, 0):
        bsdf.inputs["Specular IOR Level"].default_value = 0.5 * v["f0"] / f0_of(bsdf.inputs["IOR"].default_value)
        bsdf.inputs["Coat Weight"].default_value = v["coat"]
        bsdf.inputs["Coat Roughness"].default_value = 0.0
        bsdf.inputs["Coat IOR"].default_value = v["coat_ior"]
    else:
        bsdf.inputs["Specular"].default_value = v["f0"] / 0.08
        bsdf.inputs["Clearcoat"].default_value = v["coat"]
        bsdf.inputs["Clearcoat Roughness"].default_value = 0.0


def export_json(presets):
    """The core's json export for the presets and water alone (the shipped
    preset file cut to them: each preset's tables are computed on their own;
    the whole file takes 6.5 s of CPU to export)."""
    shipped = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "c_core", "data", "materials.json")
    data = json.load(open(shipped))
    data["materials"] = [m for m in data["materials"] if m["name"] in presets]
    data["liquids"] = [l for l in data["liquids"] if l["name"] == "water"]
    cut, path = os.path.join(TMP, "materials_cut.json"), os.path.join(TMP, "export.json")
    with open(cut, "w") as f:
        json.dump(data, f)
    r = subprocess.run([A["soak"], "export", "--target", "json", "--materials", cut, "-o", path],
                       capture_output=True, text=True)
    if r.returncode != 0:
        common.fail(f"soak export: {r.stderr.strip()}")
    js = json.load(open(path))
    return {m["name"]: m for m in js["materials"]}, {l["name"]: l for l in js["liquids"]}


def soak_group_renders(sc, gn, colour, w, tag):
    """The Soak material at wetness w: EEVEE's image, Cycles' image L and its
    specular S (black base), and in 4.x Cycles' specular layering (its lobe's
    albedo at the view, rc.furnace), which Cycles' named terms need."""
    gn.inputs["Wetness"].default_value = w
    gn.inputs["Base Color"].default_value = colour
    e_l = render(sc, EEVEE, tag)[0]
    c_l = render(sc, "CYCLES", tag)
    gn.inputs["Base Color"].default_value = (0, 0, 0, 1)
    c_s = render(sc, "CYCLES", tag + "_S")[0]
    layer = rc.furnace(sc, "eevee_" + tag) if bpy.app.version >= (4, 0, 0) else 0.0
    gn.inputs["Base Color"].default_value = colour
    return e_l, c_l, c_s, layer


def centre_share(tag):
    """(EEVEE - Cycles) of the plain material on the image's central 2 x 2
    pixels, over the image (the sun's mirror image lands there: the camera
    sits at the sun's mirror direction, aimed at the plane's centre)."""
    e, c = pixels[tag, EEVEE], pixels[tag, "CYCLES"]
    mid = [(SIZE // 2 - 1 + j) * SIZE + SIZE // 2 - 1 + i for j in (0, 1) for i in (0, 1)]
    return sum(e[k] - c[k] for k in mid) / len(e)


def judge_cycles(p, w, c_l, full, named):
    """Cycles' image of the same Soak material against soak render within its
    named terms + 3 sigma (test_render_compare.py's highlight view, asserted
    here on the renders this view makes anyway; that script runs its own,
    with the printed levels, only under SOAK_RENDER_COMPARE_ONLY=highlight)."""
    tol = sum(named.values()) + 3 * c_l[1]
    if not abs(c_l[0] - full) <= tol:
        return (f"highlight view {p} w={w}: Cycles {c_l[0]:.5f} vs soak render {full:.5f} "
                f"({c_l[0] / full - 1:+.2%}, tolerance {tol / full:.2%})")
    return None


def judge(p, w, e_l, full, named, p_e, p_c, se_p, tag):
    """Asserts |EEVEE - soak render - EEVEE term| within Cycles' named terms
    + EEVEE's tables and buffer rounding + 3 sigma; returns the row and the
    failure (or None)."""
    shift = p_e - p_c
    extra = {"half tables": HALF_TABLE_TERM * e_l,
             "half buffer": rounding[tag, EEVEE] + rounding[tag + "_plain", EEVEE], "3 sigma": 3 * se_p}
    tol = sum(named.values()) + sum(extra.values())
    rel, resid = e_l / full - 1, (e_l - full - shift) / full
    spot = centre_share(tag + "_plain")
    print(f"highlight view {p} w={w}: soak render {full:.5f}, {EEVEE} {e_l:.5f} ({rel:+.2%}); EEVEE term "
          f"(plain Principled: {EEVEE} {p_e:.5f} - Cycles {p_c:.5f}) {shift / full:+.2%} of soak render, "
          f"{spot / full:+.2%} in the central 2x2 pixels; left {resid:+.2%}, tolerance {tol / full:.2%}")
    print("  terms: " + ", ".join(f"{n} {v / full:.2%}" for n, v in list(named.items()) + list(extra.items())))
    failure = None
    if not abs(resid) * full <= tol:
        failure = (f"highlight view {p} w={w}: {EEVEE} {e_l:.5f} vs soak render {full:.5f} ({rel:+.2%}), "
                   f"less the EEVEE term {shift / full:+.2%}: {resid:+.2%}, tolerance {tol / full:.2%}")
    return (p, w, full, e_l, rel, shift / full, spot / full, resid, tol / full), failure


def highlight_view(sc, plane, mat, coat_dim):
    """EEVEE's highlight view against soak render (the module docstring, 3.).
    Returns the table rows and the failures."""
    hl = rc.CASES["highlight"]
    pos = hl["camera_position"]
    rc.aim_camera(sc, pos)
    ref, liquids = export_json(hl["presets"])
    cosines = [v[2] for v in rc.highlight_pixels(pos)]
    plain = bpy.data.materials.new("plain")
    common.use_nodes(plain)
    rows, failures = [], []
    for p in hl["presets"]:
        plane.material_slots[0].material = mat
        mat.soak.preset = p
        gn = mat.node_tree.nodes["Soak Wet"]
        colour = tuple(gn.inputs["Base Color"].default_value)
        for w in hl["asserted"]:
            tag = f"hl_{p}_{w}"
            plane.material_slots[0].material = mat
            e_l, c_l, c_s, layer = soak_group_renders(sc, gn, colour, w, tag)
            m = {"type": "preset", "name": p, "wetness": w, "liquid": "water", "unit_mm": rc.CASES["soak_unit_mm"]}
            full = rc.lum(rc.soak_render("eevee_" + tag, m, camera=pos))
            body = rc.lum(rc.soak_render("eevee_" + tag + "_body", dict(m, interface=0), camera=pos))
            named = rc.highlight_named(ref, liquids, p, w, c_l[0] - c_s, coat_dim + layer, full, body)
            plane.material_slots[0].material = plain
            set_plain(plain.node_tree.nodes["Principled BSDF"], plain_values(ref, liquids["water"], p, w, cosines))
            p_c, se_p = render(sc, "CYCLES", tag + "_plain")
            p_e = render(sc, EEVEE, tag + "_plain")[0]
            row, failure = judge(p, w, e_l, full, named, p_e, p_c, se_p, tag)
            rows.append(row + (c_l[0] / full - 1,))
            failures += [f for f in (failure, judge_cycles(p, w, c_l, full, named)) if f]
    return rows, failures


def print_highlight_table(rows):
    print(f"\nEEVEE highlight view, Blender {bpy.app.version_string} ({EEVEE}):")
    print("| preset | wetness | soak render | EEVEE | difference | EEVEE term (plain Principled, EEVEE - Cycles) | "
          "of which central 2x2 pixels | difference less the EEVEE term | tolerance | Cycles (same run, asserted) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for p, w, full, e_l, rel, shift, spot, resid, tol, c_rel in rows:
        print(f"| {p} | {w} | {full:.4f} | {e_l:.4f} | {rel:+.2%} | {shift:+.2%} | {spot:+.2%} | {resid:+.2%} | "
              f"{tol:.2%} | {c_rel:+.2%} |")


def main():
    common.install_addon(ZIP)
    coat_dim = rc.coat_dimming()   # Cycles 3.x (0 in 4.x); before this scene: it builds its own
    sc, plane, mat = scene()
    mat.soak.preset, mat.soak.liquid, mat.soak.colour_source = "sand", "water", "PRESET"
    mat.soak.exact_lookups = True
    bpy.context.view_layer.objects.active = plane
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail("make_wet")
    gn = mat.node_tree.nodes["Soak Wet"]
    colour = tuple(gn.inputs["Base Color"].default_value)
    res, se = {}, {}
    for state, w in (("dry", 0.0), ("wet", 1.0)):
        gn.inputs["Wetness"].default_value = w
        for engine in ("CYCLES", EEVEE):
            gn.inputs["Base Color"].default_value = colour
            L, se_l = render(sc, engine, f"{state}_L")
            gn.inputs["Base Color"].default_value = (0, 0, 0, 1)
            S, se_s = render(sc, engine, f"{state}_S")
            res[state, engine] = (L, S, L - S)
            se[state, engine] = (se_l, se_s, math.hypot(se_l, se_s))
            print(f"{state} {engine}: L {L:.5f} +- {se_l:.1e}  S {S:.5f} +- {se_s:.1e}  D {L - S:.5f}")
    # Term 1 on the diffuse lobe alone: the coat and the base's specular
    # layer set to 0 in both states, so that what is compared is the base
    # colour each engine reads from the group (the layering itself is each
    # engine's own and is left to term 2).
    bsdf = next(n for n in mat.node_tree.nodes if n.type == "BSDF_PRINCIPLED")
    unlinked = []
    for name in (("Coat Weight", "Specular IOR Level") if bpy.app.version >= (4, 0, 0) else ("Clearcoat", "Specular")):
        sock = bsdf.inputs[name]
        for link in list(sock.links):
            unlinked.append((link.from_socket, sock))
            mat.node_tree.links.remove(link)
        sock.default_value = 0.0
    diffuse = {}
    for state, w in (("dry", 0.0), ("wet", 1.0)):
        gn.inputs["Wetness"].default_value = w
        gn.inputs["Base Color"].default_value = colour
        for engine in ("CYCLES", EEVEE):
            diffuse[state, engine] = render(sc, engine, f"{state}_diffuse")
            print(f"{state} diffuse only {engine}: {diffuse[state, engine][0]:.5f}")
    for src, sock in unlinked:
        mat.node_tree.links.new(src, sock)
    failures = []
    if not all(diffuse[st, EEVEE][0] > 0 for st in ("dry", "wet")):
        # the group's colour never reached EEVEE's BSDF (5.2: an unlinked Normal group input arrives as 0)
        common.fail(f"{EEVEE} renders no diffuse light through the group: dry {diffuse['dry', EEVEE][0]:.5f}, "
                    f"wet {diffuse['wet', EEVEE][0]:.5f} (Cycles {diffuse['dry', 'CYCLES'][0]:.5f}, "
                    f"{diffuse['wet', 'CYCLES'][0]:.5f})")
    base = {st: diffuse[st, EEVEE][0] / diffuse[st, "CYCLES"][0] for st in ("dry", "wet")}
    sigma1 = rel_se(list(diffuse.values()))
    buffer_term = sum(quant[f"{st}_diffuse", EEVEE] for st in ("dry", "wet"))
    tol1 = 2 * HALF_TABLE_TERM + buffer_term + 3 * sigma1
    rel1 = base["wet"] / base["dry"] - 1
    print(f"diffuse EEVEE/Cycles: dry {base['dry']:.5f} (baseline), wet {base['wet']:.5f}: {rel1:+.3%} "
          f"(tolerance {tol1:.3%} = half tables {2 * HALF_TABLE_TERM:.3%} + half render buffer {buffer_term:.3%} "
          f"+ 3 sigma {3 * sigma1:.3%})")
    if not abs(rel1) <= tol1:
        failures.append(f"diffuse part: EEVEE/Cycles wet {base['wet']:.5f} vs dry {base['dry']:.5f} "
                        f"({rel1:+.3%}, tolerance {tol1:.3%})")
    ratio = {e: res["wet", e][0] / res["dry", e][0] for e in ("CYCLES", EEVEE)}
    spec_term = sum(abs(res[s, EEVEE][1] - res[s, "CYCLES"][1]) / res[s, "CYCLES"][0] for s in ("dry", "wet"))
    sigma2 = rel_se([(res[k][0], se[k][0]) for k in res])
    tol2 = spec_term + 3 * sigma2
    rel2 = ratio[EEVEE] / ratio["CYCLES"] - 1
    print(f"wet/dry: Cycles {ratio['CYCLES']:.4f}, {EEVEE} {ratio[EEVEE]:.4f}: {rel2:+.2%} "
          f"(tolerance {tol2:.2%} = specular term {spec_term:.2%} + 3 sigma {3 * sigma2:.2%})")
    if not abs(rel2) <= tol2:
        failures.append(f"wet/dry {EEVEE} {ratio[EEVEE]:.4f} vs Cycles {ratio['CYCLES']:.4f} ({rel2:+.2%}, "
                        f"tolerance {tol2:.2%})")
    rows, hl_failures = highlight_view(sc, plane, mat, coat_dim)
    print_highlight_table(rows)
    failures += hl_failures
    if failures:
        common.fail("; ".join(failures))
    print("PASS")


main()
