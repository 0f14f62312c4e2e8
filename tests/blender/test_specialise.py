"""A Soak Wet group specialised to a constant liquid amount (wet_constant),
rebuilt after the panel's settings changed, against the group that is not
specialised (the second method: the tables read through image lookups and
the liquid computed by the group's Math nodes), both evaluated by Cycles.

Cases: every quality, the schedule filling and drying, a puddle level, and
a Principled with Metallic 0.5 (a conductor's function mixed in). Two planes
side by side, same dry colours (a Closest-read image, one
colour per pixel, varied off the tables' columns): the left one's material
is made wet at wetness 0.8 and then given the case's Wetness, Puddle Level,
Schedule, Drying and Time through the panel (each change rebuilds its group,
specialised: checked); the right one's gets the same values and then a
Value node linked into each input that sets the liquid, so its group is
rebuilt unspecialised (the full group) by the add-on's handler (checked). Rendered head-on and with both planes
tilted 60 degrees (the view factor between its columns), Emission fed by
each output: Base Color, (Coat Weight, Roughness, Specular), Liquid and,
for thin sheets, Translucency.

A varying wetness (varying_cases): the Wet Map an image, Wetness a value
below the film or keyed over it; the group built for what does not vary
(wet_bounds: fixed inputs folded, the film's terms dropped below the
export's saturation; checked from its tag and node count) against the full
group, and Liquid against Wetness x the map's value.

Tolerance, named terms: 2e-4 for float32 arithmetic and texture
coordinates, as in test_group_values.py; for the colour, plus the sampling
of the curves: Blender evaluates an RGB Curves node from a table of 257
points, which Cycles copies into one of 256, each linear between entries,
so a piecewise-linear curve is off by at most |slope change at a knot| x
h / 4 per sampling (h = 1/256, 1/255), computed here from the tables of
soak_data.json (colour columns and view-factor columns alike)."""
import json
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
N = int(A.get("n", 8))
PRESETS = A.get("presets", "sand,paper,copper").split(",")
LIQUIDS = A.get("liquids", "water,coffee").split(",")
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "soak",
                    "soak_data.json")
FLOAT = 2e-4
LIQUID_INPUTS = ("Wetness", "Wet Map", "Puddle Level", "Schedule", "Drying", "Time", "Start Time", "Fill Time")
# (quality, panel settings) pairs: every quality at a plain wetness, Balanced
# through the schedule (filling and drying) and the puddle level
CASES = (
    ("BALANCED", {"group_wetness": 0.37}),
    ("DRAFT", {"group_wetness": 0.37}),
    ("EXACT", {"group_wetness": 0.93}),
    ("BALANCED", {"group_wetness": 0.9, "schedule": True, "time": 0.4, "start_time": 0.1}),
    ("BALANCED", {"group_wetness": 1.0, "schedule": True, "drying": True, "time": 0.35, "start_time": 0.1}),
    ("BALANCED", {"group_wetness": 0.2, "puddle_level": 0.5}),
    ("EXACT", {"group_wetness": 0.6, "metallic": 0.5}),     # a metallic part: a conductor's function mixed in
    ("DRAFT", {"group_wetness": 0.6, "metallic": 0.5}),
)


def curve_term(rows, knots):
    """The bound above for piecewise-linear rows with `knots` uniform intervals."""
    worst = 0.0
    for row in rows:
        for c in range(3):
            ys = [row[3 * j + c] for j in range(knots + 1)]
            slopes = [(ys[j + 1] - ys[j]) * knots for j in range(knots)]
            for j in range(1, knots):
                worst = max(worst, abs(slopes[j] - slopes[j - 1]))
    return worst * (1 / 256 + 1 / 255) / 4


def scene():
    sc = common.box_filtered_scene(2 * N, N, 4.0)
    planes = []
    for x in (-1.0, 1.0):
        bpy.ops.mesh.primitive_plane_add(size=2, location=(x, 0, 0))
        planes.append(bpy.context.object)
    return sc, planes


def dry_image():
    img = bpy.data.images.get("dry") or bpy.data.images.new("dry", N, N, alpha=False, float_buffer=True)
    img.colorspace_settings.name = "Non-Color"
    px = []
    for k in range(N * N):   # golden-ratio steps: every channel off the columns, 0 and 1 included
        px += [0.0 if k == 0 else 1.0 if k == 1 else (k * 0.6180339887 + 0.3 * c) % 1.0 for c in range(3)] + [1.0]
    img.pixels.foreach_set(px)
    return img


def wet(plane, preset, liquid, quality, settings, specialised):
    mat = bpy.data.materials.new(f"{preset}_{liquid}_{quality}_{'S' if specialised else 'U'}")
    tree = common.use_nodes(mat)
    plane.data.materials.clear()
    plane.data.materials.append(mat)
    s = mat.soak
    s.preset, s.liquid, s.quality, s.wetness = preset, liquid, quality, 0.8
    bsdf = next(n for n in tree.nodes if n.type == "BSDF_PRINCIPLED")
    bsdf.inputs["Metallic"].default_value = settings.get("metallic", 0.0)
    bpy.context.view_layer.objects.active = plane
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail(f"make_wet {mat.name}")
    gn = tree.nodes["Soak Wet"]
    col = tree.nodes.new("ShaderNodeTexImage")
    col.image = bpy.data.images["dry"]
    col.interpolation = "Closest"
    tree.links.new(col.outputs["Color"], gn.inputs["Base Color"])
    gn.inputs["Fill Time"].default_value = 1.0
    gn.inputs["Specular"].default_value = 0.5
    for k, v in settings.items():
        if k != "metallic":
            setattr(s, k, v)
    if s.status:
        common.fail(f"{mat.name}: {s.status}")
    if not specialised:   # every input that sets the liquid (and the Spill Edge) fed by a node: the full group
        for name in LIQUID_INPUTS + ("Spill Edge",):
            val = tree.nodes.new("ShaderNodeValue")
            val.outputs[0].default_value = gn.inputs[name].default_value
            tree.links.new(val.outputs[0], gn.inputs[name])
        bpy.context.view_layer.update()      # the add-on's handler rebuilds the group
        if json.loads(gn.node_tree["soak_group"]).get("varying") is not None:
            common.fail(f"{mat.name}: the reference group is specialised")
    const = json.loads(gn.node_tree["soak_group"]).get("constant")
    if (const is not None) != specialised:
        common.fail(f"{mat.name}: group specialised {const is not None}, expected {specialised}")
    if specialised and abs(const["Wetness"] - settings["group_wetness"]) > 1e-6:
        common.fail(f"{mat.name}: specialised to wetness {const['Wetness']}, set {settings['group_wetness']}")
    if settings.get("metallic") and preset != "copper" and not json.loads(gn.node_tree["soak_group"]).get("metal"):
        common.fail(f"{mat.name}: Metallic {settings['metallic']} but no conductor's function in the group")
    em = tree.nodes.new("ShaderNodeEmission")
    tree.links.new(em.outputs[0], tree.nodes["Material Output"].inputs["Surface"])
    comb = tree.nodes.new("ShaderNodeCombineXYZ")
    for i, name in enumerate(("Coat Weight", "Roughness", "Specular")):
        tree.links.new(gn.outputs[name], comb.inputs[i])
    return mat, em, comb


def map_image():
    """The wet map: one value per pixel, 0 to 1 (Closest: the pixel's own)."""
    img = bpy.data.images.get("map") or bpy.data.images.new("map", N, N, alpha=False, float_buffer=True)
    img.colorspace_settings.name = "Non-Color"
    px = []
    for k in range(N * N):
        px += [k / (N * N - 1)] * 3 + [1.0]
    img.pixels.foreach_set(px)
    return img


def wet_varying(plane, preset, liquid, wetness, keyed, reference=None):
    """A wet material whose Wet Map is an image (the wetness varies): its
    group specialised to what does not vary (wet_bounds), or for the
    reference every input that sets the liquid fed by a node, which nothing
    can bound (the full group; its Spill Edge too, so it keeps the bump). keyed: Wetness keyed from 0.1 at frame 1 to
    `wetness` at frame 10 (Bezier), seen at frame 5. reference: the
    Wetness the reference gets (the keyed one's value at frame 5), None for
    the specialised group."""
    mat = bpy.data.materials.new(f"{preset}_{liquid}_V{'S' if reference is None else 'R'}")
    tree = common.use_nodes(mat)
    plane.data.materials.clear()
    plane.data.materials.append(mat)
    mat.soak.preset, mat.soak.liquid, mat.soak.quality = preset, liquid, "BALANCED"
    bpy.context.view_layer.objects.active = plane
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail(f"make_wet {mat.name}")
    gn = tree.nodes["Soak Wet"]
    for name, img in (("Base Color", "dry"), ("Wet Map", "map")):
        n = tree.nodes.new("ShaderNodeTexImage")
        n.image = bpy.data.images[img]
        n.interpolation = "Closest"
        tree.links.new(n.outputs["Color"], gn.inputs[name])
    gn.inputs["Specular"].default_value = 0.5
    sc = bpy.context.scene
    w = gn.inputs["Wetness"]
    w.default_value = wetness
    if keyed and reference is None:
        for frame, v in ((1, 0.1), (10, wetness)):
            w.default_value = v
            w.keyframe_insert("default_value", frame=frame)
    sc.frame_set(5 if keyed else 1)
    if reference is not None:
        w.default_value = reference
        for name in LIQUID_INPUTS[:1] + LIQUID_INPUTS[2:] + ("Spill Edge",):
            val = tree.nodes.new("ShaderNodeValue")
            val.outputs[0].default_value = gn.inputs[name].default_value
            tree.links.new(val.outputs[0], gn.inputs[name])
    bpy.context.view_layer.update()      # the add-on's handler rebuilds the group
    em = tree.nodes.new("ShaderNodeEmission")
    tree.links.new(em.outputs[0], tree.nodes["Material Output"].inputs["Surface"])
    comb = tree.nodes.new("ShaderNodeCombineXYZ")
    for i, name in enumerate(("Coat Weight", "Roughness", "Specular")):
        tree.links.new(gn.outputs[name], comb.inputs[i])
    return mat, em, comb


def varying_cases(sc, planes, tables):
    """A varying wetness (an image wet map, a keyed Wetness): the group
    built for what does not vary, without the film's terms where the liquid
    stays below the table's saturation (read from the export), against the
    full group; Liquid against Wetness x map value (its definition)."""
    worst, failures, checked = {}, [], 0
    for preset in PRESETS:
        m = next(x for x in tables["materials"] if x["name"] == preset)
        t = m["liquids"]["water"]
        sat = t["saturation"]
        for keyed in (False, True):
            # unkeyed: below the film for porous presets (a metal, saturation 0, has a film at any
            # wetness); keyed: 0.1 to 1, over the saturation (at frame 5 too), so the film stays
            wetness = 1.0 if keyed else 0.9 * sat if sat > 0 else 0.5
            film = sat == 0 or keyed
            spec = wet_varying(planes[0], preset, "water", wetness, keyed)
            gs = spec[0].node_tree.nodes["Soak Wet"]
            ref = wet_varying(planes[1], preset, "water", wetness, keyed, gs.inputs["Wetness"].default_value)
            gr = ref[0].node_tree.nodes["Soak Wet"]
            info_s, info_r = (json.loads(g.node_tree["soak_group"]) for g in (gs, gr))
            if info_r.get("varying") is not None or info_r.get("constant") is not None:
                common.fail(f"{preset} keyed {keyed}: the reference group is specialised: {info_r}")
            vs = info_s.get("varying")
            if vs is None or vs["film"] != film:
                common.fail(f"{preset} keyed {keyed}: group built for {vs}, expected film {film}")
            if vs.get("bump") is not False:   # Spill Edge 0, unkeyed: no bump (its height would run 3 times)
                common.fail(f"{preset} keyed {keyed}: Spill Edge 0 but the group is built with a bump: {vs}")
            ns, nr = len(gs.node_tree.nodes), len(gr.node_tree.nodes)
            if m["kind"] == "conductor" and any(n.bl_idname == "ShaderNodeLayerWeight" for n in gr.node_tree.nodes):
                common.fail(f"{preset}: a metal has no pores, yet its group models their view factor")
            print(f"{preset} keyed {keyed}: {ns} nodes specialised ({vs}), {nr} in the full group")
            if not ns < nr:
                common.fail(f"{preset} keyed {keyed}: the specialised group has {ns} nodes, the full one {nr}")
            colour_tol = FLOAT + curve_term(t["albedo"], t["columns"] - 1)
            outputs = ["Base Color", "params", "Liquid"] + (["Translucency"] if m["kind"] == "thin_sheet" else [])
            w = gr.inputs["Wetness"].default_value
            # head-on: every output, pixel (i, j) the maps' texel (i, j); tilted: the view factor
            for tilt, outs in ((0.0, outputs), (60.0, ["Base Color"])):
                for p in planes:
                    p.rotation_euler = (math.radians(tilt), 0, 0)
                for out in outs:
                    px = render_output(sc, (spec, ref), out, "spec_v.exr")
                    tol = colour_tol if out == "Base Color" else FLOAT
                    for j in range(N):
                        for i in range(N):
                            a = 4 * (j * 2 * N + i)
                            b = a + 4 * N
                            e = max(abs(px[a + c] - px[b + c]) for c in range(3))
                            if out == "Liquid":      # L = Wetness x map value (Puddle Level 1, no schedule)
                                e = max(e, abs(px[a] - w * (j * N + i) / (N * N - 1)))
                            worst[out] = max(worst.get(out, 0.0), e)
                            checked += 1
                            if e > tol:
                                failures.append(f"{preset} varying keyed {keyed} tilt {tilt} {out} px ({i},{j}): "
                                                f"{px[a:a + 3]} vs {px[b:b + 3]} (tol {tol:.5f})")
            for mat, _, _ in (spec, ref):
                bpy.data.materials.remove(mat)
    sc.frame_set(1)
    return worst, failures, checked


def render_output(sc, mats, out, name):
    """Both planes' Emission fed by one output (or "params"), rendered."""
    for mat, em, comb in mats:
        g = mat.node_tree.nodes["Soak Wet"]
        src = comb.outputs[0] if out == "params" else g.outputs[out]
        mat.node_tree.links.new(src, em.inputs["Color"])
    return render(sc, os.path.join(A["tmp"], name))


def render(sc, path):
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    bpy.data.images.remove(img)
    return px


def main():
    common.install_addon(A["addon"])
    os.makedirs(A["tmp"], exist_ok=True)
    tables = json.load(open(DATA))
    sc, planes = scene()
    dry_image()
    worst, failures, checked = {}, [], 0
    for preset in PRESETS:
        for liquid in LIQUIDS:
            m = next(x for x in tables["materials"] if x["name"] == preset)
            t = m["liquids"][liquid]
            colour_tol = FLOAT + curve_term(t["albedo"], t["columns"] - 1) + curve_term(
                t["view_factor"], tables["view_columns"] - 1)
            for quality, settings in CASES:
                mats = [wet(p, preset, liquid, quality, settings, spec) for p, spec in zip(planes, (True, False))]
                outputs = ["Base Color", "params", "Liquid"] + (["Translucency"] if m["kind"] == "thin_sheet" else [])
                for tilt in (0.0, 60.0):
                    for p in planes:
                        p.rotation_euler = (math.radians(tilt), 0, 0)
                    for out in outputs:
                        for mat, em, comb in mats:
                            gn = mat.node_tree.nodes["Soak Wet"]
                            src = comb.outputs[0] if out == "params" else gn.outputs[out]
                            mat.node_tree.links.new(src, em.inputs["Color"])
                        px = render(sc, os.path.join(A["tmp"], "spec.exr"))
                        tol = colour_tol if out == "Base Color" else FLOAT
                        for j in range(N):
                            for i in range(N):
                                a = 4 * (j * 2 * N + i)
                                b = a + 4 * N
                                e = max(abs(px[a + c] - px[b + c]) for c in range(3))
                                worst[out] = max(worst.get(out, 0.0), e)
                                checked += 1
                                if e > tol:
                                    failures.append(f"{preset}/{liquid} {quality} {settings} tilt {tilt} {out} "
                                                    f"px ({i},{j}): {px[a:a + 3]} vs {px[b:b + 3]} (tol {tol:.5f})")
                for mat, _, _ in mats:
                    bpy.data.materials.remove(mat)
    print(f"Blender {bpy.app.version_string}: {checked} pixel comparisons; worst |specialised - not| " +
          ", ".join(f"{k} {v:.6f}" for k, v in worst.items()))
    map_image()
    vworst, vfail, vchecked = varying_cases(sc, planes, tables)
    failures += vfail
    print(f"varying wetness: {vchecked} pixel comparisons; worst " + ", ".join(f"{k} {v:.6f}" for k, v in vworst.items()))
    if failures:
        common.fail(f"{len(failures)} off, e.g. " + "; ".join(failures[:4]))
    print("PASS")


main()
