"""Make Wet on a Principled BSDF inside node groups, nested two deep, as
asset libraries build materials, and on a material linked from a library
(the Asset Browser's Link import) (issue 46 item 5).

Asserted:
  1. the nested material (Outer group > Inner group > Principled BSDF, with a
     colour ramp, a math node, a linked and an unlinked group input) wets:
     its render after Make Wet equals the same nodes built flat after Make
     Wet within 3 sigma (Cycles, two seeds each; sigma from the pixel
     differences of each pair); the identity a wrong copy of a node's
     settings, a value or a link breaks. The wet render is darker than the
     dry one by more than 10 sigma (the group did wet it);
  2. the groups themselves are unchanged (node by node, values and links)
     and a second material using Outer still uses it;
  3. all or nothing: a Make Wet that fails (Image source without an image,
     checked first; an error provoked in the insertion, after the groups
     were opened) leaves the nested material's tree, the node-group list
     and the groups as before;
  4. Make Dry after it restores the Principled BSDF's values (the opened
     nodes stay, in their labelled frame);
  5. a material linked from a library: Make Wet makes it local (reported)
     and wets it; the library file is not written."""
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
ZIP, TMP = A["addon"], A["tmp"]
check, CHECKS = common.make_check()
SIZE = 32
os.makedirs(TMP, exist_ok=True)
V4 = bpy.app.version >= (4, 0, 0)


def new_socket(ng, name, in_out, kind):
    """A group interface socket (4.0+: ng.interface; 3.x: ng.inputs/outputs)."""
    if V4:
        return ng.interface.new_socket(name, in_out=in_out, socket_type=kind)
    return (ng.inputs if in_out == "INPUT" else ng.outputs).new(kind, name)


def content(t, tint_socket, rough_socket, out_socket):
    """The shared nodes: checker x tint through a colour ramp into a
    Principled BSDF, roughness x 0.8."""
    chk = t.nodes.new("ShaderNodeTexChecker")
    chk.inputs["Scale"].default_value = 5.0
    ramp = t.nodes.new("ShaderNodeValToRGB")
    ramp.color_ramp.elements[0].color = (0.1, 0.05, 0.02, 1)
    ramp.color_ramp.elements.new(0.5).color = (0.6, 0.4, 0.2, 1)
    ramp.color_ramp.elements[-1].color = (0.7, 0.7, 0.6, 1)
    mix = t.nodes.new("ShaderNodeMixRGB")
    mix.blend_type = "MULTIPLY"
    mix.inputs[0].default_value = 1.0
    math_ = t.nodes.new("ShaderNodeMath")
    math_.operation = "MULTIPLY"
    math_.inputs[1].default_value = 0.8
    bsdf = t.nodes.new("ShaderNodeBsdfPrincipled")
    t.links.new(chk.outputs["Fac"], ramp.inputs["Fac"])
    t.links.new(ramp.outputs["Color"], mix.inputs[1])
    t.links.new(tint_socket, mix.inputs[2])
    t.links.new(rough_socket, math_.inputs[0])
    t.links.new(mix.outputs[0], bsdf.inputs["Base Color"])
    t.links.new(math_.outputs[0], bsdf.inputs["Roughness"])
    t.links.new(bsdf.outputs[0], out_socket)


def groups():
    inner = bpy.data.node_groups.new("Inner", "ShaderNodeTree")
    new_socket(inner, "Tint", "INPUT", "NodeSocketColor")
    new_socket(inner, "Rough", "INPUT", "NodeSocketFloat")
    new_socket(inner, "BSDF", "OUTPUT", "NodeSocketShader")
    gi, go = inner.nodes.new("NodeGroupInput"), inner.nodes.new("NodeGroupOutput")
    content(inner, gi.outputs["Tint"], gi.outputs["Rough"], go.inputs["BSDF"])
    outer = bpy.data.node_groups.new("Outer", "ShaderNodeTree")
    new_socket(outer, "Rough", "INPUT", "NodeSocketFloat")
    new_socket(outer, "Shader", "OUTPUT", "NodeSocketShader")
    gi, go = outer.nodes.new("NodeGroupInput"), outer.nodes.new("NodeGroupOutput")
    rgb = outer.nodes.new("ShaderNodeRGB")
    rgb.outputs[0].default_value = (0.9, 0.8, 0.7, 1)
    g = outer.nodes.new("ShaderNodeGroup")
    g.node_tree = inner
    outer.links.new(rgb.outputs[0], g.inputs["Tint"])
    outer.links.new(gi.outputs["Rough"], g.inputs["Rough"])
    outer.links.new(g.outputs["BSDF"], go.inputs["Shader"])
    return inner, outer


def nested_material(name, outer):
    mat = bpy.data.materials.new(name)
    common.use_nodes(mat)
    t = mat.node_tree
    t.nodes.remove(t.nodes["Principled BSDF"])
    g = t.nodes.new("ShaderNodeGroup")
    g.node_tree = outer
    g.inputs["Rough"].default_value = 0.5
    t.links.new(g.outputs["Shader"], t.nodes["Material Output"].inputs["Surface"])
    return mat


def flat_material():
    mat = bpy.data.materials.new("Flat")
    common.use_nodes(mat)
    t = mat.node_tree
    t.nodes.remove(t.nodes["Principled BSDF"])
    rgb = t.nodes.new("ShaderNodeRGB")
    rgb.outputs[0].default_value = (0.9, 0.8, 0.7, 1)
    val = t.nodes.new("ShaderNodeValue")
    val.outputs[0].default_value = 0.5
    content(t, rgb.outputs[0], val.outputs[0], t.nodes["Material Output"].inputs["Surface"])
    return mat


def scene():
    sc = common.box_filtered_scene(SIZE, SIZE, 2.0)
    sc.cycles.samples = 32
    sc.cycles.pixel_filter_type = "BLACKMAN_HARRIS"
    sc.cycles.filter_width = 1.5
    world = sc.world or bpy.data.worlds.new("W")
    common.use_nodes(world)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.5
    sc.world = world
    ld = bpy.data.lights.new("Sun", "SUN")
    ld.energy = 3.0
    sun = bpy.data.objects.new("Sun", ld)
    sc.collection.objects.link(sun)
    sun.rotation_euler = (0.5, 0.2, 0.0)
    bpy.ops.mesh.primitive_plane_add(size=2)
    return sc, bpy.context.object


def render(sc, tag):
    """(mean luminance, its standard error) from two seeds."""
    ims = []
    for seed in (1, 2):
        sc.cycles.seed = seed
        sc.render.filepath = os.path.join(TMP, f"{tag}_{seed}.exr")
        bpy.ops.render.render(write_still=True)
        img = bpy.data.images.load(sc.render.filepath, check_existing=False)
        px = list(img.pixels)
        bpy.data.images.remove(img)
        ims.append([0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2] for i in range(0, len(px), 4)])
    n = len(ims[0])
    d = [a - b for a, b in zip(*ims)]
    dm = sum(d) / n
    se = math.sqrt(sum((x - dm) ** 2 for x in d) / (n - 1)) / (2 * math.sqrt(n))
    return (sum(ims[0]) + sum(ims[1])) / (2 * n), se


def use(ob, mat):
    ob.data.materials.clear()
    ob.data.materials.append(mat)
    bpy.context.view_layer.objects.active = ob


def group_states():
    return {g.name: common.tree_state(g) for g in bpy.data.node_groups if g.name in ("Inner", "Outer")}


def test_linked(ob, outer):
    path = os.path.join(TMP, "asset_library.blend")
    lib = nested_material("AssetMat", outer)
    bpy.data.libraries.write(path, {lib}, fake_user=True)
    size = os.path.getsize(path)
    bpy.data.materials.remove(lib)
    with bpy.data.libraries.load(path, link=True) as (src, dst):
        dst.materials = ["AssetMat"]
    mat = dst.materials[0]
    check(mat.library is not None, "the library material is linked")
    use(ob, mat)
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "Make Wet on a linked material finishes")
    local = ob.active_material
    check(local is not None and local.library is None, "the object's material is now local")
    soak = sys.modules["soak"]
    check(soak.material_tree.find_group_node(local.node_tree) is not None, "the local material is wet")
    check(os.path.getsize(path) == size, "the library file is not written")


def main():
    common.install_addon(ZIP)
    soak = sys.modules["soak"]
    sc, ob = scene()
    inner, outer = groups()
    flat, nested = flat_material(), nested_material("Nested", outer)
    sharer = nested_material("Sharer", outer)
    use(ob, nested)
    dry_n = render(sc, "nested_dry")
    use(ob, flat)
    dry_f = render(sc, "flat_dry")
    print(f"dry: nested {dry_n[0]:.5f} +- {dry_n[1]:.1e}, flat {dry_f[0]:.5f} +- {dry_f[1]:.1e}")
    before_groups, g0 = group_states(), sorted(g.name for g in bpy.data.node_groups)

    # 3. all or nothing
    use(ob, nested)
    before = common.tree_state(nested.node_tree)
    nested.soak.wetness_source = "IMAGE"
    try:
        r = bpy.ops.soak.make_wet()
    except RuntimeError as e:      # an operator's error report
        r = str(e)
    check(r != {"FINISHED"}, f"Make Wet with an Image source and no image fails ({r})")
    check(common.tree_state(nested.node_tree) == before, "the failed Make Wet left the nested tree as before")
    check(sorted(g.name for g in bpy.data.node_groups) == g0, "the failed Make Wet left no node group")
    nested.soak.wetness_source = "CONSTANT"
    # an error after the groups were opened (the insertion made to fail): all put back
    insertion = soak.insertion
    real = insertion._insert

    def provoked(*args):
        raise RuntimeError("provoked after opening the groups")
    insertion._insert = provoked
    try:
        try:
            r = bpy.ops.soak.make_wet()
        except RuntimeError as e:
            r = str(e)
    finally:
        insertion._insert = real
    check(r != {"FINISHED"}, f"Make Wet failing after the groups were opened fails ({r})")
    check(common.tree_state(nested.node_tree) == before, "... and leaves the nested tree as before")
    check(sorted(g.name for g in bpy.data.node_groups) == g0 and group_states() == before_groups,
          "... and the node groups as before")

    # 1. nested wets, and renders as the same nodes flat
    for mat in (flat, nested):
        use(ob, mat)
        check(bpy.ops.soak.make_wet() == {"FINISHED"}, f"Make Wet on {mat.name} finishes")
    frames = [n for n in nested.node_tree.nodes if n.type == "FRAME" and n.get(soak.ungroup.FRAME_KEY)]
    check(sorted(f[soak.ungroup.FRAME_KEY] for f in frames) == ["Inner", "Outer"],
          "both groups opened, each in a labelled frame")
    check(all(f.label for f in frames), "the frames are labelled")
    use(ob, flat)
    wet_f = render(sc, "flat_wet")
    use(ob, nested)
    wet_n = render(sc, "nested_wet")
    diff, sig = wet_n[0] - wet_f[0], math.hypot(wet_n[1], wet_f[1])
    print(f"wet: nested {wet_n[0]:.5f} +- {wet_n[1]:.1e}, flat {wet_f[0]:.5f} +- {wet_f[1]:.1e}: "
          f"difference {diff:+.2e}, 3 sigma {3 * sig:.2e}")
    check(abs(diff) <= 3 * sig, f"nested wet {wet_n[0]:.5f} = flat wet {wet_f[0]:.5f} within 3 sigma {3 * sig:.1e}")
    darker = dry_n[0] - wet_n[0]
    check(darker > 10 * math.hypot(dry_n[1], wet_n[1]),
          f"wet darker than dry: {wet_n[0]:.5f} vs {dry_n[0]:.5f} ({-darker / dry_n[0]:+.1%})")

    # 2. the shared groups are untouched
    check(group_states() == before_groups, "the groups Inner and Outer are unchanged")
    check(any(n.type == "GROUP" and n.node_tree == outer for n in sharer.node_tree.nodes),
          "the other material still uses Outer")

    # 4. Make Dry
    check(bpy.ops.soak.make_dry() == {"FINISHED"}, "Make Dry finishes")
    check(soak.material_tree.find_group_node(nested.node_tree) is None, "dry: no Soak Wet node left")
    back = render(sc, "nested_back")
    check(abs(back[0] - dry_n[0]) <= 3 * math.hypot(back[1], dry_n[1]),
          f"dry again renders as before: {back[0]:.5f} vs {dry_n[0]:.5f}")

    # 5. a linked material
    test_linked(ob, outer)
    print(f"PASS ({len(CHECKS)} checks)")


main()
