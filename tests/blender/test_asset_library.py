"""The Soak asset library (issue 46 item 6), loaded in a Blender without
the add-on (--factory-startup, fresh user folders), as a colleague or a
render farm opens it. Expected names: one "Wet <display name>" per preset of
the core's export (blender_addon/soak/soak_data.json, read here, not through
the add-on) plus the three combinations.
 1. bpy.data.libraries.load(assets_only=True) lists exactly those materials
    (so each is marked as an asset);
 2. linked, each carries a preview of the library's size whose pixels are
    not all alike (a render, not a blank), the tag "Soak", and a node group
    tagged by the add-on ("soak_group") feeding its BSDF;
 3. wet: a 16 x 16 Cycles render of a plane lit by a sun 45 degrees off
    the straight-down camera (no mirror glint reaches it), black sky: each
    material on a porous preset (the export's kind porous_dielectric, and
    the three combinations) renders darker than the dry material made
    from the export alone (a Principled BSDF with the preset's dry_albedo,
    roughness_dry and ior); the other presets' ratios are printed (a film
    on metal, marble or a sheet need not darken under this light).
 blender -b --factory-startup --python test_asset_library.py -- --library L --data soak_data.json"""
import json
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
COMBOS = ("Wet asphalt with puddles", "Wet brick in rain", "Wet sand at a shoreline")
check, CHECKS = common.make_check()


def render_mean(sc, plane, mat):
    plane.data.materials.clear()
    plane.data.materials.append(mat)
    path = os.path.join(A["tmp"], "asset_probe.exr")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path, check_existing=False)
    px = [0.0] * (4 * img.size[0] * img.size[1])
    img.pixels.foreach_get(px)
    bpy.data.images.remove(img)
    lum = [0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2] for i in range(0, len(px), 4)]
    return sum(lum) / len(lum)


def dry_material(preset):
    """The dry material from the core's export alone (no add-on)."""
    mat = bpy.data.materials.new("Dry " + preset["name"])
    b = common.use_nodes(mat).nodes["Principled BSDF"]
    b.inputs["Base Color"].default_value = tuple(preset["dry_albedo"][:3]) + (1.0,)
    b.inputs["Roughness"].default_value = preset["roughness_dry"]
    b.inputs["IOR"].default_value = preset["ior"]
    b.inputs["Metallic"].default_value = 1.0 if preset["kind"] == "conductor" else 0.0
    return mat


def main():
    data = json.load(open(A["data"]))
    want = {f"Wet {m['display_name']}" for m in data["materials"]} | set(COMBOS)
    lib = os.path.abspath(A["library"])
    with bpy.data.libraries.load(lib, assets_only=True) as (src, _dst):
        listed = set(src.materials)
    check(listed == want, f"the library's material assets are the {len(want)} expected "
                          f"(missing {sorted(want - listed)}, extra {sorted(listed - want)})")
    with bpy.data.libraries.load(lib, link=True) as (src, dst):
        dst.materials = sorted(want)
    for ob in list(bpy.data.objects):        # the startup cube would hide the plane
        bpy.data.objects.remove(ob)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.samples = 8
    sc.cycles.use_denoising = False
    sc.render.resolution_x = sc.render.resolution_y = 16
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.view_settings.view_transform = "Standard"
    world = bpy.data.worlds.new("Black")
    common.use_nodes(world).nodes["Background"].inputs["Strength"].default_value = 0.0
    sc.world = world
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (0.7853982, 0, 0)
    sc.collection.objects.link(sun)
    by_display = {f"Wet {m['display_name']}": m for m in data["materials"]}
    by_name = {m["name"]: m for m in data["materials"]}
    combo_preset = dict(zip(COMBOS, ("asphalt", "brick", "sand")))
    bpy.ops.mesh.primitive_plane_add(size=2)
    plane = bpy.context.object
    cam = bpy.data.objects.new("C", bpy.data.cameras.new("C"))
    cam.data.type = "ORTHO"
    cam.data.ortho_scale = 1.5
    cam.location = (0, 0, 2)
    sc.collection.objects.link(cam)
    sc.camera = cam
    for mat in dst.materials:
        name = mat.name
        check(mat.asset_data is not None and "Soak" in mat.asset_data.tags, f"{name}: an asset tagged Soak")
        pv = mat.preview
        size = tuple(pv.image_size) if pv is not None else (0, 0)
        px = list(pv.image_pixels_float) if pv is not None and size[0] else []
        spread = max(px) - min(px) if px else 0.0
        check(size[0] >= 32 and size[0] == size[1] and spread > 0.1,
              f"{name}: a rendered preview {size[0]}x{size[1]} (pixel values span {spread:.2f})")
        groups = [n for n in mat.node_tree.nodes if n.type == "GROUP" and n.node_tree is not None
                  and "soak_group" in n.node_tree]
        check(len(groups) >= 1 and any(l.to_node.type == "BSDF_PRINCIPLED" for g in groups for o in g.outputs
                                       for l in o.links),
              f"{name}: its Soak Wet group feeds the BSDF")
        preset = by_display.get(name) or by_name[combo_preset[name]]
        wet = render_mean(sc, plane, mat)
        dry = render_mean(sc, plane, dry_material(preset))
        if preset["kind"] == "porous_dielectric":
            check(wet < 0.97 * dry, f"{name}: renders wet (mean {wet:.4f}) darker than the dry {preset['name']} "
                                    f"({dry:.4f}, ratio {wet / dry:.3f})")
        else:
            print(f"{name} ({preset['kind']}): wet {wet:.4f}, dry {dry:.4f}, ratio {wet / max(dry, 1e-9):.3f}")
    print(f"test_asset_library: {len(CHECKS)} checks passed (Blender {bpy.app.version_string})")


main()
