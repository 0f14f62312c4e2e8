"""compat.PRINCIPLED against the Principled BSDF input names declared in
Blender's sources (source/blender/nodes/shader/nodes/node_shader_bsdf_principled.cc):
principled_inputs.json lists them per version (3.4: blender/blender commit
007b7d0353eb, 4.x: the 4.2 declaration with panels). Also against the live
node of the running Blender, and the node-group socket helper."""
import json
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
common.install_addon(A["addon"])
from soak import compat  # noqa: E402

names = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "principled_inputs.json")))
for scheme, key, version in ((0, "3.4", (3, 4, 1)), (1, "4.x", (4, 2, 0)), (1, "5.2", (5, 2, 2))):
    listed = set(names[key])
    for role, pair in compat.PRINCIPLED.items():
        name = pair[scheme]
        if name is not None and name not in listed:
            common.fail(f"compat role {role}: '{name}' is not a Principled input of Blender {key}")
        if compat.principled_name(role, version) != name:
            common.fail(f"principled_name({role}, {version}) is not the {key} name")
    if scheme == 1 and compat.PRINCIPLED["coat_ior"][1] is None:
        common.fail("4.x has a Coat IOR input")

mat = bpy.data.materials.new("t")
compat.ensure_node_tree(mat)
bsdf = mat.node_tree.nodes["Principled BSDF"]
live = {s.name for s in bsdf.inputs}
key = "5.2" if bpy.app.version >= (5, 2, 0) else "4.x" if bpy.app.version >= (4, 0, 0) else "3.4"
missing = set(names[key]) - live
if missing:
    common.fail(f"the listed {key} names are not the running Blender's: {sorted(missing)}")
for role in compat.PRINCIPLED:
    s = compat.principled_input(bsdf, role)
    if compat.principled_name(role) is not None and s is None:
        common.fail(f"role {role} not found on the live node")

ng = bpy.data.node_groups.new("t", "ShaderNodeTree")
item = compat.new_socket(ng, "Wetness", "INPUT", "factor", 0.25, 0.0, 1.0)
if (item.min_value, item.max_value, round(item.default_value, 6)) != (0.0, 1.0, 0.25):
    common.fail(f"group socket limits not set: {item.min_value}, {item.max_value}, {item.default_value}")
# the EEVEE engine id: the one the engine enum of the running Blender lists
# (Blender's release notes: EEVEE Next's id in 4.2-4.4, BLENDER_EEVEE again in 5.0)
if compat.eevee_engine() != common.eevee_engine():
    common.fail(f"compat.eevee_engine() {compat.eevee_engine()}, this Blender's EEVEE is {common.eevee_engine()}")
bpy.context.scene.render.engine = compat.eevee_engine()     # raises for an unknown id

# F-curves: a key on a node input found, listed and removed through compat,
# checked with the version's own API (common.fcurves)
gnode = mat.node_tree.nodes.new("ShaderNodeMath")
path = f'nodes["{gnode.name}"].inputs[0].default_value'
for f, v in ((1, 0.0), (9, 2.0)):
    gnode.inputs[0].default_value = v
    gnode.inputs[0].keyframe_insert("default_value", frame=f)
fc = compat.find_fcurve(mat.node_tree, path)
theirs = common.find_fcurve(mat.node_tree, path)
if fc is None or theirs is None or [tuple(k.co) for k in fc.keyframe_points] != [(1.0, 0.0), (9.0, 2.0)]:
    common.fail(f"compat.find_fcurve: {fc}, the version's own lookup {theirs}")
if [f.data_path for f in compat.fcurves(mat.node_tree)] != [f.data_path for f in common.fcurves(mat.node_tree)]:
    common.fail("compat.fcurves lists other curves than the version's own API")
compat.remove_fcurve(mat.node_tree, fc)
if common.find_fcurve(mat.node_tree, path) is not None:
    common.fail("compat.remove_fcurve left the curve")
if not compat.material_uses_nodes(mat):
    common.fail("a node material reported as not using nodes")
print(f"compat: EEVEE id {compat.eevee_engine()}, F-curves found/listed/removed, exact lookups forced: "
      f"{compat.exact_lookups_required()}")
print("PASS")
