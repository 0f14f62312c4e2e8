"""Blender check for tests/cli/bake_per_vertex.sh: Blender's own PLY import
(bpy.ops.import_mesh.ply, 3.4; bpy.ops.wm.ply_import, 3.6+) reads the
--per-vertex PLY's colours as a colour attribute whose linear value, as the
Color Attribute shader node returns it, is the file's wetness (Blender
decodes the sRGB bytes; the reference is the float property in the file).

usage: blender -b --factory-startup --python-exit-code 1 --python per_vertex_blender.py -- OUT.ply"""
import sys

import bpy

path = sys.argv[sys.argv.index("--") + 1]
text = open(path).read().split("\n")
end = text.index("end_header")
nv = int(next(l.split()[2] for l in text if l.startswith("element vertex")))
wet = [float(l.split()[3]) for l in text[end + 1:end + 1 + nv]]

for o in list(bpy.data.objects):
    bpy.data.objects.remove(o)
if bpy.app.version >= (3, 6, 0):  # the C++ importer; 3.4 has the Python add-on's
    bpy.ops.wm.ply_import(filepath=path)
else:
    bpy.ops.import_mesh.ply(filepath=path)
me = bpy.context.selected_objects[0].data
assert len(me.vertices) == nv, f"{len(me.vertices)} vertices, want {nv}"
attrs = list(me.color_attributes)
assert attrs, "no colour attribute"
a = attrs[0]
worst = 0.0
for i, d in enumerate(a.data):
    v = me.loops[i].vertex_index if a.domain == "CORNER" else i
    got = d.color[0]  # linear, as the Color Attribute node returns it
    worst = max(worst, abs(got - wet[v]))
# 8-bit sRGB: the decoding's slope is at most 2.4 / 1.055 = 2.27 (at 1), so
# half a byte step is at most 2.27 / 510 = 0.0045 in linear.
print(f"PER_VERTEX_BLENDER attribute={a.name} domain={a.domain} type={a.data_type} worst={worst:.5f}")
assert worst <= 0.005, f"colour attribute differs from the wetness by {worst}"
