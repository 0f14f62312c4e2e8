"""The OSL variant's Blender side (Debian's Blender has no OSL, so the shader
cannot compile here): apply_osl_variant loads the shipped shader, byte for
byte the generated osl/soak_wet_surface.osl, into a tagged Internal Script
node, reports False when Blender could not compile it, and Make Dry removes
the node and restores the tree."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def main():
    common.install_addon(A["addon"])
    import importlib
    osl = importlib.import_module("soak.osl_nodes")
    with open(os.path.join(ROOT, "osl", "soak_wet_surface.osl"), encoding="utf-8") as f:
        shipped = f.read()
    with open(osl.shader_path(), encoding="utf-8") as f:
        installed = f.read()
    if installed != shipped:
        common.fail("the add-on's OSL shader differs from osl/soak_wet_surface.osl")
    # Blender 2.80-3.3 register microfacet_ggx, not the generic microfacet
    # (tests/osl/osl_check.py holds the registries): they get the legacy file.
    picks = {v: osl.shader_name(v) for v in ((2, 93, 0), (3, 3, 9), (3, 4, 0), (4, 2, 0))}
    want = {(2, 93, 0): "soak_wet_surface_legacy.osl", (3, 3, 9): "soak_wet_surface_legacy.osl",
            (3, 4, 0): "soak_wet_surface.osl", (4, 2, 0): "soak_wet_surface.osl"}
    if picks != want:
        common.fail("shader per Blender version: %s, want %s" % (picks, want))
    legacy = os.path.join(os.path.dirname(osl.shader_path()), "soak_wet_surface_legacy.osl")
    with open(os.path.join(ROOT, "osl", "soak_wet_surface_legacy.osl"), encoding="utf-8") as f:
        if not os.path.isfile(legacy) or open(legacy, encoding="utf-8").read() != f.read():
            common.fail("the add-on does not ship osl/soak_wet_surface_legacy.osl")
    bpy.ops.mesh.primitive_plane_add()
    ob = bpy.context.object
    mat = bpy.data.materials.new("O")
    common.use_nodes(mat)
    ob.data.materials.append(mat)
    before = common.tree_state(mat.node_tree)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.shading_system = True
    mat.soak.preset, mat.soak.use_osl = "sand", True
    if bpy.ops.soak.make_wet() != {"FINISHED"}:
        common.fail("make_wet with Use OSL shader")
    scripts = [n for n in mat.node_tree.nodes if n.bl_idname == "ShaderNodeScript"]
    if len(scripts) != 1:
        common.fail(f"expected one Script node, found {len(scripts)}")
    node = scripts[0]
    if not node.get("soak_node") or node.mode != "INTERNAL" or node.script is None:
        common.fail("Script node not tagged / not Internal / no text")
    if node.script.as_string() != shipped:
        common.fail("the Script node's text is not the shipped shader")
    compiled = "BSDF" in node.outputs
    print(f"OSL compiled by this Blender: {compiled} (cycles_osl build option: "
          f"{getattr(bpy.app.build_options, 'cycles_osl', '?')})")
    if not compiled and osl.apply_osl_variant(mat, mat.soak):
        common.fail("apply_osl_variant reported success without a compiled shader")
    if bpy.ops.soak.make_dry() != {"FINISHED"}:
        common.fail("make_dry")
    if any(n.bl_idname == "ShaderNodeScript" for n in mat.node_tree.nodes):
        common.fail("make_dry left a Script node")
    if common.tree_state(mat.node_tree) != before:
        common.fail("make_dry did not restore the tree after the OSL variant")
    print("PASS")


main()
