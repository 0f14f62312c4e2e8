"""Blender's Bake Rain on a concrete yard under a bench, rendered at four
moments: a frame strip for docs/rain.md and blender_addon/README.md.
bash tests/blender/run_blender.sh scenes/blender/rain_frames.py \
    --addon build/soak_blender.zip --soak build/bin/soak --tmp /tmp/rain --out docs/images/blender_rain_strip.png

30 mm/h from frame 1 to 120 at 4 fps (30 s of rain), then drying (20 s
schedule) to frame 160; ripples where the drops map reaches Puddle Level
0.9. Cycles, 32 samples, 320 x 240 per frame; frames 8, 40, 120, 160."""
import math
import os
import sys

import bpy
import mathutils

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon", "tools"))
import soak_install  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from strip import save_strip  # noqa: E402  (scenes/blender/strip.py)

FRAMES = (8, 40, 120, 160)
W, H = 320, 240


def box(name, size, loc):
    bpy.ops.mesh.primitive_cube_add(size=1, location=loc)
    ob = bpy.context.object
    ob.name = name
    ob.scale = size
    mat = bpy.data.materials.new(name)
    mat.diffuse_color = (0.25, 0.16, 0.09, 1)
    if bpy.app.version < (5, 0, 0):
        mat.use_nodes = True
    mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.25, 0.16, 0.09, 1)
    ob.data.materials.append(mat)
    return ob


def scene(tmp):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    soak_install.install(opts["--addon"])
    soak_install.preferences().soak_path = os.path.abspath(opts["--soak"])
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.samples = 32
    sc.cycles.use_denoising = False
    sc.render.resolution_x, sc.render.resolution_y = W, H
    sc.render.fps, sc.frame_start, sc.frame_end = 4, 1, 160
    sc.view_settings.view_transform = "Standard"
    world = bpy.data.worlds.new("Sky")
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (0.55, 0.62, 0.75, 1)
    bg.inputs["Strength"].default_value = 0.6
    sc.world = world
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.data.angle = math.radians(12)
    # low, facing the camera across the yard: the wet film mirrors it, the ripples break the mirror
    to_sun = mathutils.Vector((0.25, 1.0, 0.62)).normalized()
    sun.rotation_euler = to_sun.to_track_quat("Z", "Y").to_euler()
    sc.collection.objects.link(sun)
    cam = bpy.data.objects.new("Cam", bpy.data.cameras.new("Cam"))
    cam.location = (0.12, -1.05, 0.62)
    cam.rotation_euler = (math.radians(60), 0, math.radians(4))
    sc.collection.objects.link(cam)
    sc.camera = cam
    box("Bench top", (0.45, 0.5, 0.03), (-0.27, 0.15, 0.3))
    for x in (-0.46, -0.08):
        box("Bench leg", (0.03, 0.4, 0.3), (x, 0.15, 0.15))
    bpy.ops.mesh.primitive_plane_add(size=1.0)
    ground = bpy.context.object
    ground.name = "Yard"
    mat = bpy.data.materials.new("Concrete")
    if bpy.app.version < (5, 0, 0):
        mat.use_nodes = True
    p = mat.node_tree.nodes["Principled BSDF"]
    p.inputs["Base Color"].default_value = (0.42, 0.40, 0.37, 1)
    p.inputs["Roughness"].default_value = 0.8
    ground.data.materials.append(mat)
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(tmp, "rain_frames.blend"))
    return sc, ground, mat


def bake(sc, ground, mat):
    bpy.context.view_layer.objects.active = ground
    mat.soak.preset = "concrete"
    assert bpy.ops.soak.make_wet() == {"FINISHED"}
    s = sc.soak_rain
    s.rate, s.start_frame, s.end_frame, s.size, s.dry_time, s.rays = 30.0, 1, 120, 256, 20.0, 16
    s.seconds_per_frame = 1.0 / sc.render.fps       # real time: 30 s of rain over frames 1-120 at 4 fps
    assert bpy.ops.soak.bake_rain() == {"FINISHED"}
    mat.soak.puddle_level = 0.9


def main():
    tmp = os.path.abspath(opts["--tmp"])
    os.makedirs(tmp, exist_ok=True)
    sc, ground, mat = scene(tmp)
    bake(sc, ground, mat)
    paths = []
    for f in FRAMES:
        sc.frame_set(f)
        sc.render.filepath = os.path.join(tmp, f"rain_{f:04d}.png")
        bpy.ops.render.render(write_still=True)
        paths.append(sc.render.filepath)
    save_strip(paths, os.path.abspath(opts["--out"]), W, H)
    print("wrote", opts["--out"])


main()
