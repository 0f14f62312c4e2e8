"""The Blender column of the rainfall animation (rainfall.sh; docs/gallery.md,
"Rainfall over time"): the bas-relief and the paving at its foot, as in
rainfall.pov, with the bakes rainfall.sh made in WORK wired by the add-on's
Rain wiring (soak.rain.wire: the wet maps as an image sequence, one file per
scene frame, and the ripple flipbooks, sharp and far by the view distance,
where the paving's map floods), Cycles.

tests/blender/run_blender.sh rainfall_blender.py --addon ZIP --work WORK \\
    --frames N --size WxH --samples S      -> WORK/bl.0001.png ... bl.000N.png"""
import math
import os
import sys
import time

import bpy

here = os.path.dirname(os.path.abspath(__file__))
argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
work = os.path.abspath(opts["--work"])
frames = int(opts.get("--frames", "6"))
w, h = (int(x) for x in opts.get("--size", "400x225").split("x"))
samples = int(opts.get("--samples", "24"))
sys.path.insert(0, os.path.join(here, "..", "..", "blender_addon", "tools"))
sys.path.insert(0, os.path.join(here, "..", "blender"))
import soak_install  # noqa: E402

addon = soak_install.install(opts["--addon"])
import seeds  # noqa: E402  (the gallery's scene helpers)

rain = sys.modules[[m for m in sys.modules if m.endswith("soak.rain")][0]]

X0, X1, Y0, Y1 = -0.6, 3.2, -1.6, 0.0     # the paving map's extent (rain_ground.py)
RIPPLE_TILE = 0.5                         # m, soak bake ripples --tile
EXAGGERATE = 10.0                         # the ripples' slopes (rainfall.pov's Exaggerate)


def _sequence(name):
    img = bpy.data.images.load(os.path.join(work, name), check_existing=False)
    img.source = "SEQUENCE"
    img.colorspace_settings.name = "Non-Color"
    return img


def _rain(ob, preset, wet_files, level, tiles):
    """Make Wet, then the add-on's Rain wiring with our frame sequence."""
    seeds.make_wet(ob, preset)
    mat = ob.active_material
    seeds.group_node(mat).inputs["Puddle Level"].default_value = level
    rain.wire(mat, _sequence(wet_files), 1, frames, _sequence("ripples.0000.exr"), 64, 1, 1.0,
              ob.data.uv_layers[0].name, _sequence("ripples_far.0000.exr"), rain.far_distances(bpy.context.scene))
    for n in rain.rain_nodes(mat.node_tree):
        if n.type == "MAPPING":
            n.inputs["Scale"].default_value = (tiles[0], tiles[1], 1.0)
    rain.sync_level(mat)
    for n in rain.rain_nodes(mat.node_tree):   # slopes x 10, as rainfall.pov: the physical rings
        if n.type == "NORMAL_MAP":              # do not show under this overcast light at this size
            n.inputs["Strength"].default_value = EXAGGERATE
    return mat


def build():
    sc = seeds._reset()
    # camera and resolution first: the wiring sets the far ripples' distances from them
    seeds._camera(sc, (1.3, -3.3, 1.75), (1.3, 0.0, 0.3), lens=18 / math.tan(math.radians(27)))
    sc.render.resolution_x, sc.render.resolution_y = w, h
    relief = seeds.import_relief(os.path.join(work, "relief.obj"))
    t = seeds.Tree("Limestone")
    co = t.node("ShaderNodeTexCoord").outputs["Object"]
    t.link(t.ramp(t.noise(9.0, 6.0, 0.6, vector=co), [(0.3, (0.55, 0.50, 0.42)), (0.7, (0.64, 0.59, 0.50))]),
           t.bsdf.inputs["Base Color"])
    t.set(Roughness=0.8)
    seeds._assign(relief, t.mat)
    _rain(relief, "limestone", "relief_wet.0001.png", 1.0, (1.0, 1.0))
    bpy.ops.mesh.primitive_cube_add(size=1, location=(1.3, 0.2005, 0.7))
    wall = bpy.context.object
    wall.name = "Wall"
    wall.scale = (6.6, 0.399, 1.8)
    ws = seeds.Tree("Wall stone")
    ws.set(Base_Color=(0.60, 0.55, 0.46, 1), Roughness=0.8)
    seeds._assign(wall, ws.mat)
    wall_mat = seeds.make_wet(wall, "limestone", wetness=0.0)
    # the paving: the baked map over its extent, the open paving's colour beyond
    bpy.ops.mesh.primitive_plane_add(size=1, location=((X0 + X1) / 2, (Y0 + Y1) / 2, 0))
    ground = bpy.context.object
    ground.name = "Paving"
    ground.scale = (X1 - X0, Y1 - Y0, 1)
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    gr = seeds.Tree("Paving")
    gr.link(gr.ramp(gr.noise(14.0, 6.0, 0.6), [(0.3, (0.30, 0.29, 0.27)), (0.7, (0.40, 0.39, 0.36))]),
            gr.bsdf.inputs["Base Color"])
    gr.set(Roughness=0.6)
    seeds._assign(ground, gr.mat)
    _rain(ground, "concrete", "ground_wet.0001.png", 0.98, ((X1 - X0) / RIPPLE_TILE, (Y1 - Y0) / RIPPLE_TILE))
    seeds._sky(sc, zenith=(0.42, 0.46, 0.52), horizon=(0.62, 0.64, 0.66), ground=(0.12, 0.12, 0.12), strength=1.0)
    seeds._sun(sc, 23, 238, strength=2.5, angle=3.0)
    sc.cycles.samples = samples
    sc.frame_start, sc.frame_end = 1, frames
    return sc, wall_mat


def main():
    sc, wall_mat = build()
    walls = [float(x) for x in open(os.path.join(work, "walls.txt")).read().split()]
    for k in range(1, frames + 1):
        seeds.group_node(wall_mat).inputs["Wetness"].default_value = walls[k - 1]
        sc.frame_set(k)
        sc.render.filepath = os.path.join(work, f"bl.{k:04d}.png")
        t0 = time.time()
        bpy.ops.render.render(write_still=True)
        print(f"rainfall: Blender {bpy.app.version_string} frame {k}: {time.time() - t0:.1f} s", flush=True)
    # the last frame's puddle close up (rainfall.sh pastes it into that frame), half size
    cam = sc.camera
    seeds._camera(sc, (1.3, -1.25, 0.42), (1.3, -0.3, 0.0), lens=18 / math.tan(math.radians(20)))
    sc.render.resolution_x, sc.render.resolution_y = w // 2, h // 2
    sc.render.filepath = os.path.join(work, "bl.close.png")
    bpy.ops.render.render(write_still=True)
    sc.camera = cam


main()
