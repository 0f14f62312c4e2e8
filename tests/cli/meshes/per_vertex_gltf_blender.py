"""Blender check for tests/cli/bake_per_vertex.sh: Blender's own glTF
importer (io_import_scene_gltf2, bundled with Blender) reads the
--per-vertex glTF's COLOR_0 as a colour attribute whose linear value, as the
Color Attribute shader node returns it, is the wetness the CSV of the same
bake holds (the reference: a second output, read by position; Blender may
split vertices per face corner).

usage: blender -b --factory-startup --python-exit-code 1 --python per_vertex_gltf_blender.py -- OUT.gltf|.glb REF.csv"""
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
path, csv = args[0], args[1]
ref = {}
for line in open(csv).read().split("\n")[1:]:
    if line.strip():
        i, x, y, z, w = line.split(",")
        ref[(round(float(x), 4), round(float(y), 4), round(float(z), 4))] = float(w)

for o in list(bpy.data.objects):
    bpy.data.objects.remove(o)
# Debian 12's Blender 3.4 importer fails with its default shading guess
# ("NORMALS": np.bool, gone in numpy 1.24) on any glTF; "SMOOTH" avoids it.
bpy.ops.import_scene.gltf(filepath=path, import_shading="SMOOTH")
obj = next(o for o in bpy.context.scene.objects if o.type == "MESH")
me = obj.data
attrs = list(me.color_attributes)
assert attrs, "no colour attribute"
a = attrs[0]
positions = {}
for v in me.vertices:
    # glTF is y-up, Blender z-up: the importer maps (x, y, z) to (x, -z, y)
    x, y, z = v.co.x, v.co.z, -v.co.y
    positions[v.index] = (round(x, 4), round(y, 4) + 0.0, round(z, 4) + 0.0)
worst, seen = 0.0, set()
for i, d in enumerate(a.data):
    vi = me.loops[i].vertex_index if a.domain == "CORNER" else i
    key = positions[vi]
    key = tuple(k + 0.0 for k in key)
    assert key in ref, f"vertex at {key} is not in the CSV"
    seen.add(key)
    worst = max(worst, abs(d.color[0] - ref[key]))  # linear, as the Color Attribute node returns it
assert seen == set(ref), f"{len(seen)} of the CSV's {len(ref)} positions have a colour"
wet = me.attributes.get("_WETNESS")
worst_w = -1.0
if wet is not None:
    worst_w = 0.0
    for i, d in enumerate(wet.data):
        vi = me.loops[i].vertex_index if wet.domain == "CORNER" else i
        worst_w = max(worst_w, abs(d.value - ref[positions[vi]]))
print(f"PER_VERTEX_GLTF_BLENDER version={bpy.app.version_string} vertices={len(me.vertices)} "
      f"attribute={a.name} domain={a.domain} type={a.data_type} worst={worst:.6f} "
      f"_WETNESS={'absent' if wet is None else f'{wet.data_type} worst={worst_w:.6f}'}")
# A float colour attribute keeps the value (the CSV prints 6 digits: 5e-6);
# a byte one is sRGB-quantised: half a step is at most 2.27 / 510 = 0.0045.
tol = 1e-5 if a.data_type == "FLOAT_COLOR" else 0.005
assert worst <= tol, f"colour attribute differs from the CSV's wetness by {worst} (tolerance {tol})"
assert wet is None or worst_w <= 1e-5, f"_WETNESS differs from the CSV by {worst_w}"
