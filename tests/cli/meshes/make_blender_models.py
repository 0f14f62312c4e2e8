"""Blender (3.4 and later) writes the unit square of make_models.py as FBX
and .blend, with two UV sets: "Half" (u in [0, 0.5], the first) and "Full"
(u in [0, 1]), so a test can choose a set by name and by index.
blender -b --factory-startup --python-exit-code 1 --python make_blender_models.py -- DIR"""
import os
import sys

import bpy

d = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
mesh = bpy.data.meshes.new("quad")
mesh.from_pydata([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [], [(0, 1, 2), (0, 2, 3)])
for name, U in (("Half", 0.5), ("Full", 1.0)):
    layer = mesh.uv_layers.new(name=name)
    for poly in mesh.polygons:
        for li in poly.loop_indices:
            x, y, _ = mesh.vertices[mesh.loops[li].vertex_index].co
            layer.data[li].uv = (x * U, y)
obj = bpy.data.objects.new("quad", mesh)
bpy.context.scene.collection.objects.link(obj)
os.makedirs(d, exist_ok=True)
bpy.ops.export_scene.fbx(filepath=os.path.join(d, "quad.fbx"), axis_forward="Y", axis_up="Z")
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(d, "quad.blend"))
