"""Bake Beads (issue 48 items 4 and 6): `soak bake beads` wired into a wet
material as a labelled Bump, checked by rendering.

A copper plane (contact angle 75 deg in materials.json: above Bake Beads'
60 deg, beads) 0.256 m wide under a straight-down orthographic camera,
lit by a low sun. Cycles, 4 samples, fixed seed.
 1. Bake Beads (the preset's angle) builds the nodes: an image of the map
    and a Bump labelled "Soak Beads: bump" feeding the group's Normal; the
    render changes, and its luminance spread over the plane rises above
    twice the bare wet material's (beads catch the low sun);
 2. a film surface (Contact Angle 30, below the threshold: soak writes a
    flat map) renders as the material without beads (the flat bump is the
    surface normal: every pixel within 1e-4);
 3. Make Dry removes every bead node.
usage: blender -b --python test_beads.py -- --soak SOAK --addon ZIP --tmp DIR"""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
TMP = A["tmp"]
N = 96
SIZE_M = 0.256
check, CHECKS = common.make_check()


def scene():
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.cameras, bpy.data.lights,
                 bpy.data.worlds, bpy.data.images):
        for item in list(coll):
            coll.remove(item)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.cycles.samples = 4
    sc.cycles.seed = 1
    sc.cycles.use_denoising = False
    world = bpy.data.worlds.new("W")
    common.use_nodes(world)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.05
    sc.world = world
    common.ortho_exr_camera(sc, N, N, SIZE_M, z=1.0)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (1.2, 0.0, 0.6)         # 69 deg from the zenith
    sc.collection.objects.link(sun)
    bpy.ops.mesh.primitive_plane_add(size=SIZE_M)
    plane = bpy.context.object
    mat = bpy.data.materials.new("Wet copper")
    common.use_nodes(mat)
    plane.data.materials.append(mat)
    return sc, plane, mat


def render(sc, name):
    path = os.path.join(TMP, name + ".exr")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path, check_existing=False)
    px = list(img.pixels)
    bpy.data.images.remove(img)
    return [0.2126 * px[4 * i] + 0.7152 * px[4 * i + 1] + 0.0722 * px[4 * i + 2] for i in range(len(px) // 4)]


def spread(v):
    m = sum(v) / len(v)
    return (sum((x - m) ** 2 for x in v) / len(v)) ** 0.5


def main():
    os.makedirs(TMP, exist_ok=True)
    common.install_addon(A["addon"])
    common.preferences().soak_path = A["soak"]
    sc, plane, mat = scene()
    bpy.context.view_layer.objects.active = plane
    plane.select_set(True)
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "Make Wet")
    mat.soak.preset = "copper"
    bare = render(sc, "bare")
    kw = dict(duration=60.0, rate=25.0, map_size=SIZE_M, resolution=256, seed=3)
    check(bpy.ops.soak.bake_beads(**kw) == {"FINISHED"}, "Bake Beads with the preset's contact angle")
    tree = mat.node_tree
    gn = next(n for n in tree.nodes if n.type == "GROUP")
    bump = [n for n in tree.nodes if n.type == "BUMP" and n.label == "Soak Beads: bump"]
    check(len(bump) == 1 and gn.inputs["Normal"].links and gn.inputs["Normal"].links[0].from_node == bump[0],
          "a Bump labelled 'Soak Beads: bump' feeds the group's Normal")
    img = [n for n in tree.nodes if n.type == "TEX_IMAGE" and n.get("soak_role") == "beads"]
    check(len(img) == 1 and img[0].image is not None and bump[0].inputs["Height"].links[0].from_node == img[0],
          "the bead map's alpha is the Bump's height")
    beaded = render(sc, "beaded")
    diff = max(abs(a - b) for a, b in zip(beaded, bare))
    sb, s0 = spread(beaded), spread(bare)
    print(f"luminance spread: bare {s0:.5f}, beads {sb:.5f}; largest pixel change {diff:.4f}")
    check(diff > 0.01 and sb > 2 * s0, f"beads show: spread {sb:.5f} > 2 x {s0:.5f}, pixels change by {diff:.4f}")
    check(bpy.ops.soak.bake_beads(contact_angle=30.0, **kw) == {"FINISHED"}, "Bake Beads at 30 deg (a film)")
    check(len([n for n in tree.nodes if n.get("soak_role") == "beads"]) == 4,
          "the second bake replaced the first's nodes")
    film = render(sc, "film")
    d = max(abs(a - b) for a, b in zip(film, bare))
    check(d < 1e-4, f"a film surface's flat map leaves the render as it was (max change {d:.2e})")
    check(bpy.ops.soak.make_dry() == {"FINISHED"} and not any(n.get("soak_role") == "beads" for n in tree.nodes),
          "Make Dry removes the bead nodes")
    print(f"PASS: {len(CHECKS)} checks (Blender {bpy.app.version_string})")


main()
