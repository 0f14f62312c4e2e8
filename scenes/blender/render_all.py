"""Renders the Blender seed scenes with the add-on installed from its zip.
blender -b --factory-startup --python-exit-code 1 --python render_all.py -- \
    --addon build/soak_blender.zip --out out/demo/blender [--size 320x240] [--samples 32] [--only NAME]"""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
out = os.path.abspath(opts.get("--out", "out/demo/blender"))
w, h = (int(x) for x in opts.get("--size", "320x240").split("x"))
samples = int(opts.get("--samples", "32"))
os.makedirs(out, exist_ok=True)
bpy.ops.preferences.addon_install(filepath=os.path.abspath(opts["--addon"]), overwrite=True)
bpy.ops.preferences.addon_enable(module="soak")

import seeds  # noqa: E402

for name, build in seeds.SCENES.items():
    if "--only" in opts and opts["--only"] != name:
        continue
    renders = build()
    sc = bpy.context.scene
    sc.render.resolution_x, sc.render.resolution_y = w, h
    sc.cycles.samples = samples
    for fname, frame in renders:
        sc.frame_set(frame)
        sc.render.filepath = os.path.join(out, fname + ".png")
        bpy.ops.render.render(write_still=True)
        print("wrote", sc.render.filepath)
