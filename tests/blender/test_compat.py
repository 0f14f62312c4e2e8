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
for scheme, key, version in ((0, "3.4", (3, 4, 1)), (1, "4.x", (4, 2, 0))):
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
mat.use_nodes = True
bsdf = mat.node_tree.nodes["Principled BSDF"]
live = {s.name for s in bsdf.inputs}
key = "4.x" if bpy.app.version >= (4, 0, 0) else "3.4"
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
print("PASS")
