"""Blender's Bake Rain with and without Runnels and Splashes (issue 48), the
same bakes' maps rendered for docs/rain.md.
bash tests/blender/run_blender.sh scenes/blender/rain_runnels.py \
    --addon build/soak_blender.zip --soak build/bin/soak --tmp /tmp/runnels --out docs/images/blender_runnels.png

30 mm/h from frame 1 to 40 at 4 fps (10 s of rain, real time), no shelter.
Panels 1-2: a 0.3 m limestone slab leaning at 80 degrees, 512^2 maps (0.6
mm a texel), at frame 50 (2.5 s after the rain: the drops have dried on a
2 s Drying Time, the film still drains), Runnels Off and Contact Angle 30
degrees. Panels 3-4: a 0.3 m concrete yard seen from above at the rain's
end (frame 40), 1024^2 maps (0.3 mm a texel), a 5 cm patch, Splashes off
    and on.
Cycles, 32 samples, 300 x 300 per panel."""
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

W, H = 300, 300
RAIN_END, SLAB_FRAME = 40, 50


def material(name, colour, roughness):
    mat = bpy.data.materials.new(name)
    if bpy.app.version < (5, 0, 0):
        mat.use_nodes = True
    p = mat.node_tree.nodes["Principled BSDF"]
    p.inputs["Base Color"].default_value = colour
    p.inputs["Roughness"].default_value = roughness
    return mat


def plane(name, size, loc, rot, mat):
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=loc, rotation=rot)
    ob = bpy.context.object
    ob.name = name
    ob.scale = size
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    ob.data.materials.append(mat)
    return ob


def camera(sc, name, loc, look_at, lens):
    cam = bpy.data.objects.new(name, bpy.data.cameras.new(name))
    cam.location = loc
    cam.rotation_euler = (mathutils.Vector(look_at) - mathutils.Vector(loc)).to_track_quat("-Z", "Y").to_euler()
    cam.data.lens = lens
    cam.data.clip_start = 0.005        # the yard's camera is 8 cm away
    sc.collection.objects.link(cam)
    return cam


def scene(tmp):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    soak_install.install(opts["--addon"])
    soak_install.preferences().soak_path = os.path.abspath(opts["--soak"])
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.samples = 32
    sc.cycles.use_denoising = False
    sc.render.resolution_x, sc.render.resolution_y = W, H
    sc.render.fps, sc.frame_start, sc.frame_end = 4, 1, SLAB_FRAME
    sc.view_settings.view_transform = "Standard"
    world = bpy.data.worlds.new("Sky")
    if bpy.app.version < (5, 0, 0):
        world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (0.55, 0.62, 0.75, 1)
    bg.inputs["Strength"].default_value = 0.5
    sc.world = world
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.data.energy = 3.0
    sun.data.angle = math.radians(8)
    to_sun = mathutils.Vector((-0.6, -0.5, 0.6)).normalized()    # from the front left: no mirror glint
    sun.rotation_euler = to_sun.to_track_quat("Z", "Y").to_euler()
    sc.collection.objects.link(sun)
    tilt = math.radians(80)
    slab = plane("Slab", (0.3, 0.3, 1), (-2.0, 0.0, 0.15 * math.sin(tilt)), (tilt, 0, 0),
                 material("Stone", (0.45, 0.42, 0.38, 1), 0.7))
    yard = plane("Yard", (0.3, 0.3, 1), (2.0, 0, 0), (0, 0, 0), material("Concrete", (0.42, 0.40, 0.37, 1), 0.8))
    cams = (camera(sc, "Slab cam", (-2.0, -0.75, 0.2), (-2.0, 0.0, 0.15), 50),
            camera(sc, "Yard cam", (2.0, -0.02, 0.08), (2.0, 0.0, 0.0), 50))   # a 5 cm patch
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(tmp, "rain_runnels.blend"))
    return sc, (slab, yard), cams


def bake(sc, ob, on, size):
    bpy.context.view_layer.objects.active = ob
    mat = ob.active_material
    if not any(n.type == "GROUP" for n in mat.node_tree.nodes):
        mat.soak.preset = "limestone" if ob.name == "Slab" else "concrete"
        assert bpy.ops.soak.make_wet() == {"FINISHED"}
    s = sc.soak_rain
    s.rate, s.start_frame, s.end_frame, s.size, s.dry_time, s.rays = 30.0, 1, RAIN_END, size, 2.0, 4
    s.shelter = False
    s.seconds_per_frame = 1.0 / sc.render.fps
    s.runnels, s.contact_angle, s.splashes = ("CUSTOM" if on else "OFF"), math.radians(30.0), on
    assert bpy.ops.soak.bake_rain() == {"FINISHED"}


def main():
    tmp = os.path.abspath(opts["--tmp"])
    os.makedirs(tmp, exist_ok=True)
    sc, obs, cams = scene(tmp)
    shots = {}
    for on in (False, True):
        for ob, cam, size, frame in zip(obs, cams, (512, 1024), (SLAB_FRAME, RAIN_END)):
            bake(sc, ob, on, size)
            sc.camera = cam
            sc.frame_set(frame)
            sc.render.filepath = os.path.join(tmp, f"{ob.name}_{int(on)}.png")
            bpy.ops.render.render(write_still=True)
            shots[(ob.name, on)] = sc.render.filepath
    save_strip([shots[k] for k in (("Slab", False), ("Slab", True), ("Yard", False), ("Yard", True))],
               os.path.abspath(opts["--out"]), W, H)
    print("wrote", opts["--out"])


main()
