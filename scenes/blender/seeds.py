"""Seed scenes of the Blender front end, built from scratch (no .blend).
Each build_* function empties the scene, builds it and returns a list of
(name, frame) renders. Run through render_all.py."""
import math

import bpy


def _reset(engine="CYCLES", size=(320, 240), samples=32):
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras,
                 bpy.data.worlds, bpy.data.node_groups):
        for item in list(coll):
            coll.remove(item)
    sc = bpy.context.scene
    sc.render.engine = engine
    sc.cycles.samples = samples
    sc.cycles.use_denoising = False
    sc.render.resolution_x, sc.render.resolution_y = size
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "PNG"
    sc.view_settings.view_transform = "Filmic"
    w = bpy.data.worlds.new("Sky")
    w.use_nodes = True
    w.node_tree.nodes["Background"].inputs["Color"].default_value = (0.45, 0.55, 0.7, 1)
    w.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.4
    sc.world = w
    return sc


def _camera(sc, loc, target, lens=50):
    cd = bpy.data.cameras.new("Cam")
    cd.lens = lens
    co = bpy.data.objects.new("Cam", cd)
    sc.collection.objects.link(co)
    co.location = loc
    from mathutils import Vector
    co.rotation_euler = (Vector(target) - Vector(loc)).to_track_quat("-Z", "Y").to_euler()
    sc.camera = co


def _sun(sc, direction, strength=3.0):
    from mathutils import Vector
    ld = bpy.data.lights.new("Sun", "SUN")
    ld.energy = strength
    ld.angle = math.radians(1.0)
    lo = bpy.data.objects.new("Sun", ld)
    sc.collection.objects.link(lo)
    lo.rotation_euler = Vector(direction).to_track_quat("Z", "Y").to_euler()


def _material(ob, name, preset, liquid="water", wetness=1.0, source="CONSTANT", colour="PRESET", wet_map=None):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    ob.data.materials.append(mat)
    s = mat.soak
    s.preset, s.liquid, s.wetness, s.wetness_source, s.colour_source = preset, liquid, wetness, source, colour
    s.wet_map = wet_map
    bpy.context.view_layer.objects.active = ob
    bpy.ops.soak.make_wet()
    return mat


def _half_map(name, n=64):
    img = bpy.data.images.new(name, n, n, float_buffer=True)
    img.pixels.foreach_set([v for y in range(n) for x in range(n) for v in ((1.0,) * 3 if x < n // 2 else (0.0,) * 3) + (1.0,)])
    img.pack()
    return img


def build_wet_paper(back_lit):
    sc = _reset()
    bpy.ops.mesh.primitive_plane_add(size=2)
    sheet = bpy.context.object
    _material(sheet, "Paper", "paper", source="IMAGE", wet_map=_half_map("paper_wet"))
    _camera(sc, (0, -2.2, 2.2), (0, 0, 0))
    # behind: a bright sun under the sheet (its transmittance is a few per cent)
    _sun(sc, (0.3, -0.5, -0.8) if back_lit else (0.3, -0.5, 0.8), 30.0 if back_lit else 3.0)
    if back_lit:
        sc.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.05
    return [("wet_paper_" + ("back" if back_lit else "front"), 1)]


def build_beach_rock():
    sc = _reset()
    bpy.ops.mesh.primitive_plane_add(size=8)
    ground = bpy.context.object
    _material(ground, "Sand", "sand", wetness=0.3)
    for i, w in enumerate((0.0, 0.2, 0.5, 1.0)):
        bpy.ops.mesh.primitive_uv_sphere_add(radius=0.45, location=(-1.5 + i, 0, 0.35), segments=32, ring_count=16)
        bpy.ops.object.shade_smooth()
        _material(bpy.context.object, f"Rock {w}", "limestone", wetness=w)
    _camera(sc, (0, -6.0, 2.6), (0, 0, 0.3))
    _sun(sc, (-0.4, -0.6, 0.7))
    return [("beach_rock", 1)]


def build_bricks_drying():
    sc = _reset()
    bpy.ops.mesh.primitive_plane_add(size=2)
    wall = bpy.context.object
    _material(wall, "Bricks", "brick", source="NOISE")
    bpy.ops.soak.key_drying(frame_start=1, frame_end=40)
    _camera(sc, (0, -2.6, 2.0), (0, 0, 0))
    _sun(sc, (0.3, -0.4, 0.85))
    return [("bricks_drying_%02d" % f, f) for f in (1, 20, 30, 40)]


def build_cognac_table():
    sc = _reset()
    bpy.ops.mesh.primitive_plane_add(size=3)
    table = bpy.context.object
    mat = _material(table, "Table", "oak", liquid="cola", source="NOISE")
    gn = mat.node_tree.nodes["Soak Wet"]
    gn.inputs["Spill Edge"].default_value = 1.0
    _camera(sc, (0, -2.5, 1.4), (0, 0, 0))
    _sun(sc, (0.0, 0.6, 0.8), 4.0)
    return [("cognac_table", 1)]


SCENES = {
    "wet_paper_front": lambda: build_wet_paper(False),
    "wet_paper_back": lambda: build_wet_paper(True),
    "beach_rock": build_beach_rock,
    "bricks_drying": build_bricks_drying,
    "cognac_table": build_cognac_table,
}
