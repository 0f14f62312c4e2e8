"""Cycles render time of a plane with a textured Principled material, with
and without the Soak Wet group (same scene, samples, resolution), runs
interleaved. Prints one line per run and the ratio of the fastest runs.
blender -b --factory-startup --python bench_blender_overhead.py -- --addon ZIP [--repeat 3]"""
import os
import sys
import time

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
opts = dict(zip(argv[::2], argv[1::2]))
bpy.ops.preferences.addon_install(filepath=os.path.abspath(opts["--addon"]), overwrite=True)
bpy.ops.preferences.addon_enable(module="soak")
repeat = int(opts.get("--repeat", "3"))

sc = bpy.context.scene
sc.render.engine = "CYCLES"
sc.cycles.samples = 64
sc.cycles.use_denoising = False
sc.cycles.threads_mode = "FIXED"
sc.render.threads = 1
sc.render.resolution_x = sc.render.resolution_y = 128
for o in list(bpy.data.objects):
    if o.type == "MESH":
        bpy.data.objects.remove(o)
bpy.ops.mesh.primitive_plane_add(size=4)
ob = bpy.context.object
mat = bpy.data.materials.new("M")
mat.use_nodes = True
ob.data.materials.append(mat)
tex = mat.node_tree.nodes.new("ShaderNodeTexChecker")
mat.node_tree.links.new(tex.outputs["Color"], mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"])
cam = sc.camera
cam.location = (0, 0, 5)
cam.rotation_euler = (0, 0, 0)
mat.soak.preset, mat.soak.wetness = "sand", 0.6
mat.soak.exact_lookups = bool(int(opts.get("--exact", "0")))
times = {"dry": [], "wet": []}
for r in range(repeat):
    for state in ("dry", "wet"):
        if state == "wet":
            bpy.ops.soak.make_wet()
        t0 = time.process_time()
        bpy.ops.render.render()
        times[state].append(time.process_time() - t0)
        if state == "wet":
            bpy.ops.soak.make_dry()
        print(f"run {r} {state}: {times[state][-1]:.3f} s CPU")
print(f"fastest: dry {min(times['dry']):.3f} s, wet {min(times['wet']):.3f} s, "
      f"overhead ratio {min(times['wet']) / min(times['dry']):.3f}")
