"""EEVEE right by default (issue 46 item 3): a small textured scene (a
checker ground, a cube and a sphere sharing one Principled material, a sun,
a sky-blue world), Make Wet with the panel's defaults, then EEVEE with the
scene's settings as Make Wet left them against Cycles, per object.

Asserted, per object (the ground, the cube, the sphere; the pixels a mask
render gives wholly to one object, so both engines' anti-aliased edges drop
out):
  1. Make Wet turned EEVEE's reflection switch on (Raytracing in 4.2+,
     Screen Space Reflections before);
  2. |W_E - W_C| <= diffuse term + coat term + specular term + 3 sigma
                    + half buffer
     W the wet object's mean luminance; the named terms, each EEVEE's own
     difference from Cycles measured here on a PLAIN Principled BSDF (no
     Soak nodes) under the same settings, per object:
       diffuse term: the user's material with no specular and no coat,
         |D_E / D_C - 1| x W_C (EEVEE's sky light, shadows and indirect
         light on a diffuse surface: a ratio that does not depend on the
         albedo, so it carries over to the darker wet colours);
       coat term: a black base under a smooth coat of water's index, weight
         1 (the most coat Make Wet can give), |K_E - K_C|;
       specular term: a black base with the material's own roughness and
         Specular 0.5, no coat, |S_E - S_C| (the wet base's lobe is weaker:
         Make Wet lowers it under the film);
       3 sigma: Cycles' Monte Carlo error of those means (two seeds, the
         standard error from the pixel differences of the pair);
       half buffer: EEVEE Next's half-float render buffer (one half ulp
         per channel, pixel by pixel; 0 for a float buffer).
Printed: whether each object is within the issue's 2 % target, and the wet
EEVEE image with EEVEE's default settings (the switch off), which the issue
measured 5-9 % brighter than Cycles (in 4.3 and 5.2 the test fails with it:
cube +10.8 %; 3.4's Screen Space Reflections change the cube by 0.4 % only)."""
import math
import os
import struct
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
ZIP, TMP = A["addon"], A["tmp"]
EEVEE = common.eevee_engine()
W, H = 64, 40
CYCLES_SAMPLES = 64
TARGET = 0.02
LUM = (0.2126, 0.7152, 0.0722)
OBJECTS = ("Ground", "Cube", "Sphere")
V4 = bpy.app.version >= (4, 0, 0)
os.makedirs(TMP, exist_ok=True)


def half_exact(v):
    return struct.unpack("e", struct.pack("e", v))[0] == v


def textured_material():
    mat = bpy.data.materials.new("Textured")
    common.use_nodes(mat)
    t = mat.node_tree
    bsdf = t.nodes["Principled BSDF"]
    chk = t.nodes.new("ShaderNodeTexChecker")
    chk.inputs["Scale"].default_value = 6.0
    chk.inputs["Color1"].default_value = (0.55, 0.35, 0.2, 1)
    chk.inputs["Color2"].default_value = (0.25, 0.25, 0.22, 1)
    t.links.new(chk.outputs["Color"], bsdf.inputs["Base Color"])
    bsdf.inputs["Roughness"].default_value = 0.6
    return mat


def scene():
    sc = common.box_filtered_scene(W, H, 1.0)
    for coll in (bpy.data.cameras, bpy.data.lights, bpy.data.worlds):
        for item in list(coll):
            coll.remove(item)
    sc.cycles.samples = CYCLES_SAMPLES
    sc.cycles.pixel_filter_type = "BLACKMAN_HARRIS"
    sc.cycles.filter_width = 1.5
    sc.eevee.taa_render_samples = int(A.get("taa", 8))
    world = bpy.data.worlds.new("Sky")
    common.use_nodes(world)
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.35, 0.55, 1.0, 1)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
    sc.world = world
    if bpy.app.version >= (4, 2, 0):
        sc.world.probe_resolution = "128"
    else:
        sc.eevee.gi_cubemap_resolution = "64"
    cd = bpy.data.cameras.new("Cam")
    cd.lens = 35
    cam = bpy.data.objects.new("Cam", cd)
    sc.collection.objects.link(cam)
    cam.location = (0.0, -6.0, 3.2)
    cam.rotation_euler = (math.radians(65), 0.0, 0.0)
    sc.camera = cam
    ld = bpy.data.lights.new("Sun", "SUN")
    ld.energy = 3.0
    sun = bpy.data.objects.new("Sun", ld)
    sc.collection.objects.link(sun)
    sun.rotation_euler = (math.radians(40), math.radians(15), math.radians(30))
    mat = textured_material()
    bpy.ops.mesh.primitive_plane_add(size=12)
    bpy.context.object.name = "Ground"
    bpy.ops.mesh.primitive_cube_add(size=1.2, location=(-1.1, 0.0, 0.6))
    bpy.context.object.name = "Cube"
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.7, location=(1.1, 0.3, 0.7), segments=48, ring_count=24)
    bpy.context.object.name = "Sphere"
    bpy.ops.object.shade_smooth()
    for name in OBJECTS:
        bpy.data.objects[name].data.materials.append(mat)
    return sc, mat


def masks(sc):
    """{object: [pixel indices]}: the pixels a Cycles render of flat
    emission colours (red, green, blue per object) gives wholly to it."""
    saved = {n: bpy.data.objects[n].data.materials[0] for n in OBJECTS}
    world = sc.world
    sc.world = None
    for i, n in enumerate(OBJECTS):
        m = bpy.data.materials.new("mask_" + n)
        common.use_nodes(m)
        t = m.node_tree
        t.nodes.remove(t.nodes["Principled BSDF"])
        em = t.nodes.new("ShaderNodeEmission")
        em.inputs["Color"].default_value = [1.0 if c == i else 0.0 for c in range(3)] + [1.0]
        t.links.new(em.outputs[0], t.nodes["Material Output"].inputs["Surface"])
        bpy.data.objects[n].data.materials[0] = m
    sc.render.engine = "CYCLES"
    sc.render.filepath = os.path.join(TMP, "mask.exr")
    bpy.ops.render.render(write_still=True)
    px = common.load_pixels(sc.render.filepath)
    sc.world = world
    for n in OBJECTS:
        bpy.data.objects[n].data.materials[0] = saved[n]
    out = {}
    for i, n in enumerate(OBJECTS):
        out[n] = [k for k in range(len(px) // 4)
                  if px[4 * k + i] > 0.999 and all(px[4 * k + c] < 1e-3 for c in range(3) if c != i)]
        if len(out[n]) < 20:
            common.fail(f"the mask of {n} has {len(out[n])} pixels")
    return out


def lum(px):
    return [sum(w * px[4 * k + c] for c, w in enumerate(LUM)) for k in range(len(px) // 4)]


def half_rounding(px, idx):
    """Half an ulp of every channel of the masked pixels, weighted and
    averaged, when the buffer is half floats (detected: every value a half)."""
    if not all(half_exact(v) for v in px[:4 * 64]):
        return 0.0
    tot = 0.0
    for k in idx:
        for c, w in enumerate(LUM):
            v = abs(px[4 * k + c])
            tot += w * 2.0 ** (max(math.floor(math.log2(v)), -14) - 11) if v > 0 else 0.0
    return tot / len(idx)


def render(sc, engine, tag, mask):
    """{object: (mean, standard error, half rounding)}."""
    sc.render.engine = engine
    images = []
    for seed in ((1, 2) if engine == "CYCLES" else (1,)):
        sc.cycles.seed = seed
        sc.render.filepath = os.path.join(TMP, f"{tag}_{engine}_{seed}.exr")
        bpy.ops.render.render(write_still=True)
        images.append(common.load_pixels(sc.render.filepath))
    lums = [lum(px) for px in images]
    out = {}
    for n, idx in mask.items():
        means = [sum(lm[k] for k in idx) / len(idx) for lm in lums]
        se = 0.0
        if len(lums) == 2:
            d = [lums[0][k] - lums[1][k] for k in idx]
            dm = sum(d) / len(d)
            se = math.sqrt(sum((x - dm) ** 2 for x in d) / (len(d) - 1)) / (2 * math.sqrt(len(d)))
        out[n] = (sum(means) / len(means), se, half_rounding(images[0], idx))
    return out


def plain(mat, name, base, specular, coat):
    """A plain Principled BSDF (no Soak nodes) from the user's material: its
    checker colours (base True) or black, its roughness, Specular as given,
    and a smooth coat of water's index of weight `coat`."""
    p = mat.copy()
    p.name = name
    t = p.node_tree
    bsdf = t.nodes["Principled BSDF"]
    if not base:
        for link in list(bsdf.inputs["Base Color"].links):
            t.links.remove(link)
        bsdf.inputs["Base Color"].default_value = (0, 0, 0, 1)
    if V4:
        bsdf.inputs["Specular IOR Level"].default_value = specular
        bsdf.inputs["Coat Weight"].default_value = coat
        bsdf.inputs["Coat Roughness"].default_value = 0.0
        bsdf.inputs["Coat IOR"].default_value = 1.33
    else:
        bsdf.inputs["Specular"].default_value = specular
        bsdf.inputs["Clearcoat"].default_value = coat
        bsdf.inputs["Clearcoat Roughness"].default_value = 0.0
    return p


def assign(mat):
    for n in OBJECTS:
        bpy.data.objects[n].data.materials[0] = mat


def both(sc, mat, tag, mask):
    assign(mat)
    return render(sc, "CYCLES", tag, mask), render(sc, EEVEE, tag, mask)


def judge(n, wet, default, terms):
    """Prints the object's row; returns the failure or None."""
    (wc, we), (dc, de), (kc, ke), (sc_, se_) = wet, terms["diffuse"], terms["coat"], terms["specular"]
    rel = we[0] / wc[0] - 1
    named = {"diffuse": abs(de[0] / dc[0] - 1) * wc[0], "coat": abs(ke[0] - kc[0]),
             "specular": abs(se_[0] - sc_[0]),
             "3 sigma": 3 * math.sqrt(wc[1] ** 2 + (dc[1] * wc[0] / dc[0]) ** 2 + kc[1] ** 2 + sc_[1] ** 2),
             "half buffer": we[2] + de[2] * wc[0] / dc[0] + ke[2] + se_[2]}
    tol = sum(named.values())
    print(f"| {n} | {wc[0]:.4f} | {default[0] / wc[0] - 1:+.2%} | {we[0]:.4f} | {rel:+.2%} | "
          + " | ".join(f"{v / wc[0]:.2%}" for v in named.values()) + f" | {tol / wc[0]:.2%} | "
          + ("yes" if abs(rel) <= TARGET else "no") + " |")
    if not abs(we[0] - wc[0]) <= tol:
        return f"{n}: {EEVEE} {we[0]:.4f} vs Cycles {wc[0]:.4f} ({rel:+.2%}), tolerance {tol / wc[0]:.2%}"
    return None


def main():
    common.install_addon(ZIP)
    sc, mat = scene()
    mask = masks(sc)
    owner_prop = ("use_raytracing" if hasattr(sc.eevee, "use_raytracing") else "use_ssr")
    print(f"{EEVEE}: {owner_prop} by default {getattr(sc.eevee, owner_prop)}")
    plains = {"diffuse": plain(mat, "PlainDiffuse", True, 0.0, 0.0), "coat": plain(mat, "PlainCoat", False, 0.0, 1.0),
              "specular": plain(mat, "PlainSpecular", False, 0.5, 0.0)}
    bpy.context.view_layer.objects.active = bpy.data.objects["Cube"]
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail("make_wet")
    if not getattr(sc.eevee, owner_prop):
        common.fail(f"Make Wet left EEVEE's {owner_prop} off")
    print(f"after Make Wet: {owner_prop} on")
    # the wet image under EEVEE's default (the switch off): printed, the finding
    setattr(sc.eevee, owner_prop, False)
    default = render(sc, EEVEE, "wet_default", mask)
    setattr(sc.eevee, owner_prop, True)
    wet = (render(sc, "CYCLES", "wet", mask), render(sc, EEVEE, "wet", mask))
    terms = {k: both(sc, m, "plain_" + k, mask) for k, m in plains.items()}
    for k, (c, e) in terms.items():
        print(f"plain {k}: " + ", ".join(f"{n} Cycles {c[n][0]:.4f} {EEVEE} {e[n][0]:.4f}" for n in OBJECTS))
    print(f"\n| object | Cycles wet | {EEVEE} defaults | {EEVEE} after Make Wet | difference | diffuse term | "
          "coat term | specular term | 3 sigma | half buffer | tolerance | within 2 % |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    failures = []
    for n in OBJECTS:
        f = judge(n, (wet[0][n], wet[1][n]), default[n], {k: (c[n], e[n]) for k, (c, e) in terms.items()})
        if f:
            failures.append(f)
    if failures:
        common.fail("; ".join(failures))
    print("PASS")


main()
