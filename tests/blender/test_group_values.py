"""The Soak Wet group, evaluated by Cycles, against the core.

For every preset and liquid a plane is rendered with an Emission shader fed
by the group's Base Color (and Coat Weight, Roughness) outputs, one test
point per pixel: the dry colour and wetness come from Closest-interpolated
input images, so pixel (i, j) evaluates the group at exactly one point. The
expected values come from `soak export --target json` (an independent
writer): its base_colour table at its own nodes (exact core values,
7 digits), its knot table for coverage and roughness. Tolerance: the core's
SOAK_EXPORT_BASE_TOL 0.005 for the colour (the Blender table's bilinear error
is below it) plus 2e-4 for float32 texture coordinates; 0.005 for the coat
weight and roughness (piecewise linear tables at different knots).

Coat weight: the liquid's interface area, film coverage c plus the
uncovered water-filled pores (1 - c) * water specular weight (wetness.h
step 5), from the knots. Roughness: the knots'; conductors seen through the
film: sqrt(alpha (1 + c (n_liquid - 1))) (soak/wet_specular.h point 3).
Specular (group input 1): the base's own specular left under the liquid,
(1 - c) + c R_under / F0(n), R_under summed bounce by bounce here from
Fresnel's normal-incidence formula with the json's film thickness and the
liquid's absorption (a second method for the core's closed form); 1 for
conductors. Blender 4.x: its coat dims what lies under it by
(1 - coat * F(view)); the group undoes that, so Base Color and Specular are
expected times 1 / (1 - coat * F0(n_liquid)) (the camera looks along the
normal; F0: the json's film_normal_reflectance).

--quality DRAFT|BALANCED|EXACT (the panel's Quality): each quality's
colour is held to the same tolerance plus the named terms it leaves out,
computed here from the json export: Draft's view factor, the colour times
|1 - view factor at the camera's cosine 1| (its spill-edge bump does
nothing on this flat, uniformly wet plane: no term). The worst error
printed is the one blender_addon/README.md publishes per version.

--constant 1: the wetness is one number per render, set through the
panel's Wetness after Make Wet (which made the group at another wetness),
so the group is specialised to it and rebuilt (wet_constant: the table row
as RGB Curves nodes); each render holds one of the export's wetness nodes,
its pixels the dry colours. Same tolerance: the curves run through the
tables' columns, uniform in the column coordinate, and Blender's 256-point
sampling of them departs from the columns' interpolation by at most
2e-4 (test_specialise.py bounds it from the tables)."""
import json
import math
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
ENGINE = A.get("engine", "CYCLES")
TOL = float(A.get("tol", 0.005 + 2e-4))
N = int(A.get("n", 16))  # N x N test points per render
ROUNDS = int(A.get("rounds", 1))  # renders per preset and liquid (different points)
QUALITY = A.get("quality", "BALANCED")
DROPS_VIEW_FACTOR = QUALITY == "DRAFT"
ONLY = A.get("presets", "").split(",") if A.get("presets") else None
LIQUIDS = A.get("liquids", "").split(",") if A.get("liquids") else None
CONSTANT = bool(int(A.get("constant", "0")))


def image(name, px):
    img = bpy.data.images.new(name, N, N, alpha=False, float_buffer=True)
    img.colorspace_settings.name = "Non-Color"
    img.pixels.foreach_set([v for p in px for v in (p[0], p[1], p[2], 1.0)])
    img.pack()
    return img


def setup():
    sc = bpy.context.scene
    sc.render.engine = ENGINE
    sc.cycles.samples = 1
    if ENGINE == "BLENDER_EEVEE":
        sc.eevee.taa_render_samples = 1
        sc.render.filter_size = 0.0
    sc.cycles.use_denoising = False
    sc.cycles.pixel_filter_type = "BOX"
    sc.cycles.filter_width = 0.01
    sc.render.resolution_x = sc.render.resolution_y = max(N, 4)
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.render.image_settings.color_depth = "32"
    sc.view_settings.view_transform = "Standard"
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    cd = bpy.data.cameras.new("C")
    cd.type = "ORTHO"
    cd.ortho_scale = 2.0
    co = bpy.data.objects.new("C", cd)
    sc.collection.objects.link(co)
    co.location = (0, 0, 1)
    sc.camera = co
    bpy.ops.mesh.primitive_plane_add(size=2)
    return sc, bpy.context.object


def points(table, first=0):
    """(dry rgb, wetness, expected rgb) at the json export's nodes."""
    a, w = table["dry_albedo"], table["wetness"]
    alb = table["albedo"]
    out = []
    k = first * 37
    while len(out) < N * N:
        iw = k % len(w)
        ia = [(k // len(w) + 7 * c) % len(a) for c in range(3)]
        dry = [a[i] for i in ia]
        want = [alb[c][iw][ia[c]] for c in range(3)]
        out.append((dry, w[iw], want))
        k += 1
    return out


def interp(xs, ys, x):
    for i in range(len(xs) - 1):
        if xs[i] <= x <= xs[i + 1]:
            t = (x - xs[i]) / (xs[i + 1] - xs[i]) if xs[i + 1] > xs[i] else 0.0
            return ys[i] + (ys[i + 1] - ys[i]) * t
    return ys[-1]


def r0(n):
    return ((n - 1) / (n + 1)) ** 2


def spec_factor(m, liquid, c):
    """(1 - c) + c R_under / F0(n), R_under as a sum over the film's bounces."""
    if m["kind"] == "conductor" or c <= 0:
        return 1.0
    n, nl, h = m["ior"], liquid["ior"], m["film_thickness_m"]
    r12, r23 = r0(nl), r0(n / nl)
    under = 0.0
    for a in liquid["sigma_a_per_m"]:
        e = math.exp(-2 * a * h)
        bounce, total = (1 - r12) * r23 * e * (1 - r12), 0.0
        for _ in range(40):
            total += bounce
            bounce *= r12 * r23 * e
        under += total / 3
    return (1 - c) + c * under / r0(n)


def points_constant(table, iw):
    """(dry rgb, wetness, expected rgb) at one wetness node, N x N dry colours."""
    a, w, alb = table["dry_albedo"], table["wetness"], table["albedo"]
    return [([a[(k + 7 * c) % len(a)] for c in range(3)], w[iw], [alb[c][iw][(k + 7 * c) % len(a)] for c in range(3)])
            for k in range(N * N)]


def set_constant_wetness(mat, w):
    """The panel's Wetness after Make Wet (made at another wetness): the
    group is rebuilt, specialised to w; fails unless it was."""
    mat.soak.group_wetness = w
    gn = mat.node_tree.nodes["Soak Wet"]
    info = json.loads(gn.node_tree["soak_group"])
    const = info.get("constant")
    if mat.soak.status or const is None or abs(const["Wetness"] - w) > 1e-6:
        common.fail(f"{mat.name}: the group is not specialised to wetness {w}: {const} {mat.soak.status}")
    if any(n.bl_idname == "ShaderNodeTexImage" for n in gn.node_tree.nodes):
        common.fail(f"{mat.name}: the specialised group still reads images")


def main():
    common.install_addon(A["addon"])
    ref_path = os.path.join(A["tmp"], "export.json")
    os.makedirs(A["tmp"], exist_ok=True)
    r = subprocess.run([A["soak"], "export", "--target", "json", "-o", ref_path], capture_output=True, text=True)
    if r.returncode != 0:
        common.fail(f"soak export --target json: {r.stderr}")
    ref = json.load(open(ref_path))
    sc, plane = setup()
    worst = {"colour": 0.0, "coat": 0.0, "rough": 0.0, "spec": 0.0}
    worst_dropped = 0.0
    liquids = {l["name"]: l for l in ref["liquids"]}
    coat_dims = bpy.app.version >= (4, 0, 0)
    failures = []
    combos = [(m, liquid, t, k) for m in ref["materials"] for liquid, t in m["liquids"].items()
              for k in (range(len(t["base_colour"]["wetness"])) if CONSTANT else range(ROUNDS))
              if (ONLY is None or m["name"] in ONLY) and (LIQUIDS is None or liquid in LIQUIDS)]
    for m, liquid, t, k in combos:
        if True:
            pts = points_constant(t["base_colour"], k) if CONSTANT else points(t["base_colour"], k)
            mat = bpy.data.materials.new(f"{m['name']}_{liquid}")
            common.use_nodes(mat)
            plane.data.materials.clear()
            plane.data.materials.append(mat)
            mat.soak.preset, mat.soak.liquid = m["name"], liquid
            mat.soak.colour_source = "MATERIAL"
            mat.soak.exact_lookups = bool(int(A.get("exact", "0")))
            mat.soak.quality = QUALITY
            mat.soak.wetness = 0.5
            bpy.context.view_layer.objects.active = plane
            if bpy.ops.soak.make_wet() != {"FINISHED"}:
                common.fail(f"make_wet {m['name']} {liquid}")
            tree = mat.node_tree
            gn = tree.nodes["Soak Wet"]
            col = tree.nodes.new("ShaderNodeTexImage")
            col.image = image("dry", [p[0] for p in pts])
            col.interpolation = "Closest"
            tree.links.new(col.outputs["Color"], gn.inputs["Base Color"])
            wet = tree.nodes.new("ShaderNodeTexImage")
            wet.image = image("wet", [(p[1], 0, 0) for p in pts])
            if CONSTANT:
                set_constant_wetness(mat, pts[0][1])
            else:
                wet.interpolation = "Closest"
                sep = tree.nodes.new("ShaderNodeSeparateColor")
                tree.links.new(wet.outputs["Color"], sep.inputs[0])
                tree.links.new(sep.outputs[0], gn.inputs["Wetness"])
                bpy.context.view_layer.update()      # the add-on's handler: the group is rebuilt unspecialised
                if json.loads(gn.node_tree["soak_group"]).get("constant") is not None:
                    common.fail(f"{mat.name}: a linked Wetness left the group specialised")
            gn.inputs["Roughness"].default_value = t["knots"]["roughness"][0]
            gn.inputs["Specular"].default_value = 1.0
            em = tree.nodes.new("ShaderNodeEmission")
            out = tree.nodes["Material Output"]
            for what, sock in (("colour", gn.outputs["Base Color"]), ("coat", gn.outputs["Coat Weight"]),
                               ("rough", gn.outputs["Roughness"]), ("spec", gn.outputs["Specular"])):
                tree.links.new(sock, em.inputs["Color"])
                tree.links.new(em.outputs[0], out.inputs["Surface"])
                path = os.path.join(A["tmp"], f"{m['name']}_{liquid}_{k}_{what}.exr")
                sc.render.filepath = path
                bpy.ops.render.render(write_still=True)
                img = bpy.data.images.load(path, check_existing=False)
                px = list(img.pixels)
                bpy.data.images.remove(img)
                kn = t["knots"]
                npx = len(px) // 4
                for i, (dry, w, want) in enumerate(pts):
                    # N = 1: the whole (constant) image is the point: its mean
                    got = px[4 * i: 4 * i + 3] if N > 1 else [sum(px[c::4]) / npx for c in range(3)]
                    c = interp(kn["wetness"], kn["film_coverage"], w)
                    area = c + (1 - c) * interp(kn["wetness"], kn["water_specular_weight"], w)
                    keep = 1 / (1 - area * liquids[liquid]["film_normal_reflectance"]) if coat_dims else 1.0
                    dropped = 0.0          # the named terms the quality leaves out
                    if what == "colour":
                        vf = [interp(kn["wetness"], [f[-1][c] for f in kn["view_factor"]], w) for c in range(3)]
                        exp = [x * f * keep for x, f in zip(want, vf)]
                        if DROPS_VIEW_FACTOR:
                            dropped = max(abs(x * keep * (1 - f)) for x, f in zip(want, vf))
                    elif what == "coat":
                        exp = [area] * 3
                    elif what == "spec":
                        exp = [spec_factor(m, liquids[liquid], c) * keep] * 3
                    else:
                        r = interp(kn["wetness"], kn["roughness"], w)
                        if m["kind"] == "conductor":
                            r *= math.sqrt(1 + c * (liquids[liquid]["ior"] - 1))
                        exp = [r] * 3
                    e = max(abs(g - x) for g, x in zip(got, exp))
                    worst[what] = max(worst[what], e)
                    worst_dropped = max(worst_dropped, dropped) if what == "colour" else worst_dropped
                    if e > TOL + dropped:
                        failures.append(f"{m['name']}/{liquid} {what} dry={dry} w={w}: {got} vs {exp}")
            bpy.data.materials.remove(mat)
            for n in ("dry", "wet"):
                bpy.data.images.remove(bpy.data.images[n])
    print(f"worst |Blender - core|: colour {worst['colour']:.5f}, coat {worst['coat']:.5f}, "
          f"roughness {worst['rough']:.5f}, specular factor {worst['spec']:.5f} (tolerance {TOL})")
    print(f"quality {QUALITY}{' (constant wetness: specialised group)' if CONSTANT else ''}: worst colour error {worst['colour']:.5f} (Blender {bpy.app.version_string}); "
          f"allowance for the terms it leaves out up to {worst_dropped:.5f}")
    if failures:
        common.fail(f"{len(failures)} points off, e.g. " + "; ".join(failures[:5]))
    print("PASS")


main()
