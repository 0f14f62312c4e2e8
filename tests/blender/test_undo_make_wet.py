"""Ctrl-Z after Make Wet (issue 46 items 3 and 5), in Blender with a window
(run with SOAK_BLENDER_UI=1: `ed.undo` needs one): Make Wet on the default
cube's material put inside a node group (as an asset's), then one undo.

Asserted: Make Wet (EEVEE the scene's engine) turned EEVEE's reflection
switch on (Raytracing in 4.2+, Screen Space Reflections before) and the
material's Exact lookups (where they are not always built: 3.x, 5.x), and
opened the group; after the undo the switch and Exact lookups are off again
(the defaults), the material holds its group node
and nothing else of ours, and the group is unchanged; a redo brings the wet
material back (the undo step is one step)."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
check, CHECKS = common.make_check()


def grouped_material():
    """The cube's material with its Principled BSDF moved into a group."""
    mat = bpy.data.objects["Cube"].active_material
    t = mat.node_tree
    t.nodes.remove(t.nodes["Principled BSDF"])
    ng = bpy.data.node_groups.new("Asset", "ShaderNodeTree")
    if bpy.app.version >= (4, 0, 0):
        ng.interface.new_socket("BSDF", in_out="OUTPUT", socket_type="NodeSocketShader")
    else:
        ng.outputs.new("NodeSocketShader", "BSDF")
    bsdf = ng.nodes.new("ShaderNodeBsdfPrincipled")
    out = ng.nodes.new("NodeGroupOutput")
    ng.links.new(bsdf.outputs[0], out.inputs["BSDF"])
    g = t.nodes.new("ShaderNodeGroup")
    g.node_tree = ng
    t.links.new(g.outputs[0], t.nodes["Material Output"].inputs["Surface"])
    return mat, ng


def switch():
    ee = bpy.context.scene.eevee
    return "use_raytracing" if hasattr(ee, "use_raytracing") else "use_ssr"


def state():
    mat = bpy.data.objects["Cube"].active_material
    return (getattr(bpy.context.scene.eevee, switch()), common.tree_state(mat.node_tree),
            common.tree_state(bpy.data.node_groups["Asset"]), mat.soak.exact_lookups)


def leave(code):
    sys.stdout.flush()
    os._exit(code)


def go():
    try:
        run()
    except SystemExit as e:
        leave(e.code or 0)
    except Exception as e:  # a failure inside a timer must still fail the process
        print("FAIL:", type(e).__name__, e)
        leave(1)
    print(f"PASS ({len(CHECKS)} checks)")
    leave(0)


def run():
    win = bpy.context.window_manager.windows[0]
    ob = bpy.data.objects["Cube"]
    mat, ng = grouped_material()
    bpy.context.scene.render.engine = common.eevee_engine()
    forced = sys.modules["soak"].compat.exact_lookups_required()
    with bpy.context.temp_override(window=win, object=ob, active_object=ob):
        bpy.ops.ed.undo_push(message="grouped material")
        before = state()
        check(before[0] is False, f"EEVEE's {switch()} is off by default")
        check(bpy.ops.soak.make_wet("EXEC_DEFAULT", True) == {"FINISHED"}, "Make Wet finishes")
        wet = state()
        check(wet[0] is True, f"Make Wet turned {switch()} on")
        check(wet[3] is True or forced, "Make Wet in an EEVEE scene turned Exact lookups on "
              f"(4.2-4.x build them always: {forced})")
        nodes = bpy.data.objects["Cube"].active_material.node_tree.nodes
        check(not any(n.type == "GROUP" and n.node_tree and n.node_tree.name == "Asset" for n in nodes),
              "Make Wet opened the group")
        bpy.ops.ed.undo()
    check(state() == before, f"Ctrl-Z: {switch()} and Exact lookups off again, the material and the group "
          "as before")
    with bpy.context.temp_override(window=win):
        bpy.ops.ed.redo()
    check(state() == wet, "redo: wet again, the switch on")


common.install_addon(A["addon"])
bpy.app.timers.register(go, first_interval=1.0)
