"""Blender helper of bench_rain_vs_cycles.sh: imports the benchmark OBJ, bakes
Cycles ambient occlusion (CPU, SAMPLES samples, no denoising, unlimited AO
distance) into a RES x RES image through an image texture node, saves it as
EXR and prints the bake time. Run:
  blender -b --factory-startup --python-exit-code 1 --python cycles_ao_bake.py -- MESH.obj OUT.exr RES SAMPLES THREADS
"""
import sys
import time

import bpy

mesh_path, out_path, res, samples, threads = sys.argv[sys.argv.index("--") + 1:][:5]
res, samples, threads = int(res), int(samples), int(threads)

bpy.ops.wm.read_factory_settings(use_empty=True)
if hasattr(bpy.ops.wm, "obj_import"):  # Blender >= 3.2 (C++ importer, Y up -> Z up)
    bpy.ops.wm.obj_import(filepath=mesh_path)
else:
    bpy.ops.import_scene.obj(filepath=mesh_path)
obj = [o for o in bpy.context.scene.objects if o.type == "MESH"][0]
bpy.context.view_layer.objects.active = obj
obj.select_set(True)

scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
if scene.world is None:
    scene.world = bpy.data.worlds.new("World")
scene.world.light_settings.distance = 1e4  # rays are unlimited in soak's bake
scene.render.bake.margin = 4               # soak's default gutter

img = bpy.data.images.new("ao", res, res, float_buffer=True)
mat = bpy.data.materials.new("bake")
mat.use_nodes = True
node = mat.node_tree.nodes.new("ShaderNodeTexImage")
node.image = img
mat.node_tree.nodes.active = node
obj.data.materials.clear()
obj.data.materials.append(mat)

t0 = time.perf_counter()
bpy.ops.object.bake(type="AO")
t1 = time.perf_counter()
img.filepath_raw = out_path
img.file_format = "OPEN_EXR"
img.save()
print("CYCLES_AO_BAKE_SECONDS %.3f" % (t1 - t0))
