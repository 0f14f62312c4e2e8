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
     measured from the black-base renders of each state.
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
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
ZIP, TMP = A["addon"], A["tmp"]
CASES = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "plane_cases.json")))
EEVEE = common.eevee_engine()
SIZE = 32
quant = {}  # (tag, engine) -> half-buffer quantisation term of that render
# EEVEE samples the group's float tables from their GPU copies, which
# Blender uploads in half precision (10-bit mantissa): each value read is
# within 2^-11 of the table's, per state.
HALF_TABLE_TERM = 2.0 ** -11
W = (0.2126, 0.7152, 0.0722)
os.makedirs(TMP, exist_ok=True)


def load(path):
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    bpy.data.images.remove(img)
    return px


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


def scene():
    sc, plane, mat = common.plane_case_scene(CASES, SIZE, SIZE)
    sc.eevee.taa_render_samples = 4
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
        px = load(path)
        quant[tag, engine] = half_buffer_term(px)
        images.append(luminance(px))
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


def main():
    common.install_addon(ZIP)
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
    if failures:
        common.fail("; ".join(failures))
    print("PASS")


main()
