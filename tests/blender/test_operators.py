"""The operators are all or nothing, and safe on what users do to a wet
material (issue 19, sections 4 and 5):

 1. every failure we can provoke (Image source without an image, a linked
    material given to insertion.make_wet (the operator makes it local
    first), an error half-way through the insertion, a failing rebuild, an
    Image source without image after Make Wet) leaves the node tree exactly
    as before (common.tree_state) and no stray node group;
 2. Preset, Liquid and Exact lookups after Make Wet rebuild the group and keep
    the links to the Principled BSDF, the user's input values, the links into
    the group and the keys on its inputs; sand -> concrete -> sand renders
    the same as the first wet sand (identity); a material sharing the group
    keeps its own preset;
 3. Make Dry after the user deleted or renamed nodes restores what remains
    and names what it could not; Make Dry of a group with no restore record;
 4. several Principled BSDFs: the one feeding the output (or the active node)
    is wetted, the others named and untouched;
 5. the wetness source can be changed after Make Wet;
 6. Key Drying over the scene's frame range keeps Start/Fill Time, replaces
    its old keys;
 7. Bake Wet Map shelters the ground under a torus with the visible scene
    (numbers against the same bake without occluders) and wires the map into
    an already-wet material;
 8. every property, operator and operator setting has a tooltip; greyed
    buttons say why (poll messages, Blender 3.0+)."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
COAT = "Coat Weight" if bpy.app.version >= (4, 0, 0) else "Clearcoat"
check, CHECKS = common.make_check(quiet=True)


def groups():
    return sorted(g.name for g in bpy.data.node_groups)


def textured_material(name="Textured"):
    mat = bpy.data.materials.new(name)
    common.use_nodes(mat)
    t = mat.node_tree
    bsdf = t.nodes["Principled BSDF"]
    img = bpy.data.images.new(name + " checker", 8, 8)
    img.generated_type = "COLOR_GRID"
    tex = t.nodes.new("ShaderNodeTexImage")
    tex.name = "Checker"
    tex.image = img
    t.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    bump = t.nodes.new("ShaderNodeBump")
    bump.name = "MyBump"
    t.links.new(tex.outputs["Alpha"], bump.inputs["Height"])
    t.links.new(bump.outputs["Normal"], bsdf.inputs["Normal"])
    bsdf.inputs["Roughness"].default_value = 0.37
    bsdf.inputs[COAT].default_value = 0.25
    return mat


def use(ob, mat):
    ob.data.materials.clear()
    ob.data.materials.append(mat)
    bpy.context.view_layer.objects.active = ob
    ob.active_material_index = 0


def op_error(fn, **kw):
    """Runs an operator expecting a refusal; returns the message."""
    try:
        r = fn(**kw)
    except RuntimeError as e:
        return str(e)
    return f"returned {r}"


def bsdf_fed_by_group(mat, bsdf_name="Principled BSDF"):
    b = mat.node_tree.nodes[bsdf_name]
    names = ["Base Color", "Roughness", COAT, "Normal"]
    return {n: (b.inputs[n].is_linked and b.inputs[n].links[0].from_node.type == "GROUP"
                and bool(b.inputs[n].links[0].from_node.get("soak_node"))) for n in names}


# ---- 1. failures leave the material as it was ---------------------------------

def test_failures(ob):
    soak = sys.modules["soak"]
    mat = textured_material("Fail")
    use(ob, mat)
    before, g0 = common.tree_state(mat.node_tree), groups()

    mat.soak.wetness_source = "IMAGE"
    mat.soak.wet_map = None
    msg = op_error(bpy.ops.soak.make_wet)
    print("Image source, no image:", msg.strip())
    check("needs an image" in msg, f"no-image refusal message: {msg}")
    check(common.tree_state(mat.node_tree) == before and groups() == g0,
          "Make Wet with the Image source and no image changed the material")
    check(not bpy.ops.soak.make_dry.poll(), "Make Dry is offered after a refused Make Wet")

    # an error half-way through the insertion (after the group and the source
    # nodes exist): rolled back, for our own errors and for bugs
    mat.soak.wetness_source = "NOISE"
    real = soak.sources.wire_source
    for exc in (RuntimeError("provoked failure"), TypeError("provoked bug")):
        def boom(tree, gn, settings, _exc=exc):
            real(tree, gn, settings)
            raise _exc
        soak.sources.wire_source = boom
        try:
            msg = op_error(bpy.ops.soak.make_wet)
        finally:
            soak.sources.wire_source = real
        print(f"{type(exc).__name__} half-way:", msg.strip())
        check("provoked" in msg, f"half-way failure not reported: {msg}")
        check(common.tree_state(mat.node_tree) == before and groups() == g0,
              f"Make Wet failing half-way ({type(exc).__name__}) left the material changed")
    # the same material then wets and dries normally
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "Make Wet after a failed one")
    check(bpy.ops.soak.make_dry() == {"FINISHED"}, "Make Dry after a failed Make Wet")
    check(common.tree_state(mat.node_tree) == before and groups() == g0, "wet/dry after failures: not restored")

    # a failing rebuild (Preset change) leaves the wet material as it was
    bpy.ops.soak.make_wet()
    wet, gw = common.tree_state(mat.node_tree), groups()
    real_build = soak.wet_group.build_group

    def bad_build(tree, *a, **k):
        real_build(tree, *a, **k)
        raise RuntimeError("provoked rebuild failure")
    soak.wet_group.build_group = bad_build
    try:
        mat.soak.preset = "concrete"
    finally:
        soak.wet_group.build_group = real_build
    print("failing rebuild: status =", repr(mat.soak.status))
    check("provoked rebuild failure" in mat.soak.status, "a failed rebuild is not shown in the panel's status")
    check(mat.soak.preset == "sand", f"the refused preset stays selected: {mat.soak.preset}")
    check(common.tree_state(mat.node_tree) == wet and groups() == gw, "a failed rebuild changed the material")
    check(bsdf_fed_by_group(mat) == dict.fromkeys(bsdf_fed_by_group(mat), True),
          "a failed rebuild lost the group's links")

    # a rebuild failing after the new group is swapped in: the old group is back
    real_connect = soak.insertion.connect_outputs

    def bad_connect(*a, **k):
        real_connect(*a, **k)
        raise RuntimeError("provoked failure after the swap")
    soak.insertion.connect_outputs = bad_connect
    try:
        mat.soak.liquid = "coffee"
    finally:
        soak.insertion.connect_outputs = real_connect
    gn = mat.node_tree.nodes["Soak Wet"]
    check("after the swap" in mat.soak.status and common.tree_state(mat.node_tree) == wet and groups() == gw
          and __import__("json").loads(gn.node_tree["soak_group"])["liquid"] == "water",
          "a rebuild failing after the swap changed the material")

    check(mat.soak.liquid == "water", f"the refused liquid stays selected: {mat.soak.liquid}")
    # a source change failing half-way: the old source nodes are still there
    real = soak.sources.wire_source

    def bad_source(tree, gn, settings):
        real(tree, gn, settings)
        raise RuntimeError("provoked source failure")
    soak.sources.wire_source = bad_source
    try:
        mat.soak.wetness_source = "ATTRIBUTE"
    finally:
        soak.sources.wire_source = real
    check("provoked source failure" in mat.soak.status and common.tree_state(mat.node_tree) == wet,
          "a source change failing half-way changed the material")
    check(mat.soak.wetness_source == "NOISE", f"the refused source stays selected: {mat.soak.wetness_source}")
    mat.soak.status = ""

    # Image source without an image chosen after Make Wet: refused, unchanged
    mat.soak.wetness_source = "IMAGE"
    check("needs an image" in mat.soak.status and mat.soak.wetness_source == "NOISE",
          f"source change without image not refused: {mat.soak.status!r}, {mat.soak.wetness_source}")
    check(common.tree_state(mat.node_tree) == wet, "a refused source change changed the material")
    bpy.ops.soak.make_dry()
    check(common.tree_state(mat.node_tree) == before and groups() == g0, "dry after refused changes")
    mat.soak.wetness_source = "CONSTANT"
    mat.soak.status = ""


def test_linked(ob):
    path = os.path.join(A["tmp"], "library.blend")
    lib = bpy.data.materials.new("LibMat")
    common.use_nodes(lib)
    bpy.data.libraries.write(path, {lib}, fake_user=True)
    bpy.data.materials.remove(lib)
    with bpy.data.libraries.load(path, link=True) as (src, dst):
        dst.materials = ["LibMat"]
    mat = dst.materials[0]
    check(mat.library is not None, "the library material is not linked")
    use(ob, mat)
    before = common.tree_state(mat.node_tree)
    try:
        sys.modules["soak"].insertion.make_wet(mat, mat.soak)
        common.fail("insertion.make_wet accepted a linked material")
    except RuntimeError as e:
        check("make it local" in str(e), f"linked refusal does not say what to do: {e}")
    check(common.tree_state(mat.node_tree) == before, "a linked material was changed")
    # the operator (an Asset Browser material) makes it local first, then wets it
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "Make Wet on a linked material")
    local = ob.active_material
    check(local.library is None and sys.modules["soak"].material_tree.find_group_node(local.node_tree) is not None,
          "Make Wet made the linked material local and wet")
    bpy.ops.soak.make_dry()


# ---- 2. rebuild keeps links, values and keys ------------------------------------

def setup_render(sc):
    sc.render.engine = "CYCLES"
    sc.cycles.samples = 4
    sc.cycles.use_denoising = False
    sc.cycles.seed = 1
    sc.render.resolution_x = sc.render.resolution_y = 12
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.view_settings.view_transform = "Standard"
    cd = bpy.data.cameras.new("TopCam")
    cd.type = "ORTHO"
    cd.ortho_scale = 1.5
    cam = bpy.data.objects.new("TopCam", cd)
    sc.collection.objects.link(cam)
    cam.location = (0, 0, 3)
    sc.camera = cam


def render_lum(name):
    return common.render_lum(bpy.context.scene, os.path.join(A["tmp"], name + ".exr"))


def test_rebuild(ob):
    mat = textured_material("Rebuild")
    use(ob, mat)
    mat.soak.preset, mat.soak.liquid, mat.soak.wetness_source = "sand", "water", "ATTRIBUTE"
    dry_lum = render_lum("rebuild_dry")
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "make_wet sand")
    t = mat.node_tree
    gn = t.nodes["Soak Wet"]
    gn.inputs["Wetness"].default_value = 0.8
    gn.inputs["Fill Time"].default_value = 123.0
    gn.inputs["Spill Edge"].default_value = 0.5
    gn.inputs["Time"].default_value = 0.0
    gn.inputs["Time"].keyframe_insert("default_value", frame=1)
    gn.inputs["Time"].default_value = 50.0
    gn.inputs["Time"].keyframe_insert("default_value", frame=11)
    bpy.context.scene.frame_set(1)
    wet_lum = render_lum("rebuild_sand")
    changes = (("preset", "concrete"), ("liquid", "coffee"), ("exact_lookups", True), ("quality", "DRAFT"),
               ("exact_lookups", False), ("quality", "EXACT"), ("liquid", "water"), ("quality", "BALANCED"),
               ("preset", "sand"))
    for attr, value in changes:
        setattr(mat.soak, attr, value)
        check(mat.soak.status == "", f"{attr}={value}: refused: {mat.soak.status}")
        gn = t.nodes["Soak Wet"]
        fed = bsdf_fed_by_group(mat)
        check(all(fed.values()), f"{attr}={value}: links to the Principled BSDF lost: {fed}")
        info = __import__("json").loads(gn.node_tree["soak_group"])
        check(info["preset"] == mat.soak.preset and info["liquid"] == mat.soak.liquid
              and info["exact"] == mat.soak.exact_lookups and info["quality"] == mat.soak.quality,
              f"{attr}={value}: group not rebuilt: {info}")
        vals = (gn.inputs["Wetness"].default_value, gn.inputs["Fill Time"].default_value,
                gn.inputs["Spill Edge"].default_value)
        check(abs(vals[0] - 0.8) < 1e-6 and abs(vals[1] - 123.0) < 1e-4 and abs(vals[2] - 0.5) < 1e-6,
              f"{attr}={value}: user values lost: {vals}")
        src = gn.inputs["Wet Map"].links
        check(len(src) == 1 and src[0].from_node.bl_idname == "ShaderNodeAttribute",
              f"{attr}={value}: the link into Wet Map was lost")
        check(gn.inputs["Base Color"].is_linked and gn.inputs["Base Color"].links[0].from_node.name == "Checker",
              f"{attr}={value}: the texture into the group was lost")
        bpy.context.scene.frame_set(11)
        check(abs(gn.inputs["Time"].default_value - 50.0) < 1e-4, f"{attr}={value}: Time keys lost")
        bpy.context.scene.frame_set(1)
    check(len([g for g in bpy.data.node_groups if g.name.startswith("Soak Wet")]) == 1,
          f"rebuilds left node groups behind: {groups()}")
    back_lum = render_lum("rebuild_sand_again")
    print(f"rebuild: dry {dry_lum:.5f}, wet sand {wet_lum:.5f}, after {len(changes)} changes back to sand "
          f"{back_lum:.5f}")
    check(wet_lum < 0.9 * dry_lum, f"the wet material is not darker than the dry one: {wet_lum} vs {dry_lum}")
    check(abs(back_lum - wet_lum) <= 1e-6 + 1e-5 * wet_lum,
          f"sand -> ... -> sand renders differently: {back_lum} vs {wet_lum}")

    # a Fill Time still at the old preset's value follows the new preset
    soak = sys.modules["soak"]
    gn.inputs["Fill Time"].default_value = soak.data.material("sand")["t_fill"]
    mat.soak.preset = "brick"
    check(abs(t.nodes["Soak Wet"].inputs["Fill Time"].default_value - soak.data.material("brick")["t_fill"])
          <= 1e-6 * max(1.0, soak.data.material("brick")["t_fill"]), "default Fill Time did not follow the preset")

    # a copy of the material shares the group; its preset change leaves the original's group alone
    copy = mat.copy()
    copy.soak.preset = "oak"
    g_orig = mat.node_tree.nodes["Soak Wet"].node_tree
    g_copy = copy.node_tree.nodes["Soak Wet"].node_tree
    check(__import__("json").loads(g_orig["soak_group"])["preset"] == "brick"
          and __import__("json").loads(g_copy["soak_group"])["preset"] == "oak",
          "a preset change on a copy changed the original's group")
    bpy.data.materials.remove(copy)

    # thin sheet on and off: translucency added and removed with the preset
    mat.soak.preset = "paper"
    check(any(n.bl_idname == "ShaderNodeBsdfTranslucent" for n in t.nodes), "paper: no translucency added")
    mat.soak.preset = "sand"
    check(not any(n.bl_idname == "ShaderNodeBsdfTranslucent" for n in t.nodes), "sand: translucency left")
    out = next(n for n in t.nodes if n.type == "OUTPUT_MATERIAL")
    check(out.inputs["Surface"].links[0].from_node.name == "Principled BSDF", "sand: BSDF not back on the output")
    before_keys = t.animation_data
    bpy.ops.soak.make_dry()
    check(before_keys is not None, "keys")


# ---- 3. Make Dry after deletions and renames ------------------------------------

def test_dry_after_edits(ob):
    soak = sys.modules["soak"]
    mat = textured_material("Edited")
    use(ob, mat)
    t = mat.node_tree
    before = common.tree_state(t)
    mat.soak.preset, mat.soak.wetness_source = "sand", "CONSTANT"

    # renamed texture and BSDF: everything restored (names put back to compare)
    bpy.ops.soak.make_wet()
    t.nodes["Checker"].name = "Renamed Checker"
    t.nodes["Principled BSDF"].name = "Renamed BSDF"
    problems = soak.removal.make_dry(mat)
    check(problems == [], f"renamed nodes: problems {problems}")
    t.nodes["Renamed Checker"].name = "Checker"
    t.nodes["Renamed BSDF"].name = "Principled BSDF"
    check(common.tree_state(t) == before, "Make Dry after renames did not restore the tree")
    check(not any("soak_ref" in n for n in t.nodes), "Make Dry left its marks on the user's nodes")

    # a duplicated texture (a copy carries the same mark): the original is relinked
    bpy.ops.soak.make_wet()
    dup = t.nodes.new("ShaderNodeTexImage")
    for k in t.nodes["Checker"].keys():
        dup[k] = t.nodes["Checker"][k]
    problems = soak.removal.make_dry(mat)
    b = t.nodes["Principled BSDF"]
    check(problems == [] and b.inputs["Base Color"].links[0].from_node.name == "Checker",
          f"duplicate of a recorded node: {problems}")
    t.nodes.remove(dup)
    check(common.tree_state(t) == before, "Make Dry with a duplicated node did not restore the tree")

    # deleted texture: the rest restored, the texture named
    bpy.ops.soak.make_wet()
    t.nodes.remove(t.nodes["Checker"])
    r = bpy.ops.soak.make_dry()
    check(r == {"FINISHED"}, f"Make Dry after a deletion: {r}")
    b = t.nodes["Principled BSDF"]
    check(not any(n.get("soak_node") for n in t.nodes), "Soak nodes left")
    check(b.inputs["Normal"].is_linked and b.inputs["Normal"].links[0].from_node.name == "MyBump",
          "the bump link was not restored")
    check(abs(b.inputs["Roughness"].default_value - 0.37) < 1e-6 and not b.inputs["Roughness"].is_linked,
          "roughness not restored")
    check(abs(b.inputs[COAT].default_value - 0.25) < 1e-6 and not b.inputs[COAT].is_linked, "coat not restored")
    check(not b.inputs["Base Color"].is_linked, "base colour still linked")
    # the problem list names the deleted node (through the module, for the text)
    mat2 = textured_material("Edited2")
    use(ob, mat2)
    bpy.ops.soak.make_wet()
    mat2.node_tree.nodes.remove(mat2.node_tree.nodes["Checker"])
    problems = soak.removal.make_dry(mat2)
    print("deleted texture:", problems)
    check(len(problems) == 1 and "'Checker'" in problems[0], f"the deleted texture is not named: {problems}")

    # deleted BSDF: the Soak nodes go, the BSDF is reported
    bpy.ops.soak.make_wet()
    mat2.node_tree.nodes.remove(mat2.node_tree.nodes["Principled BSDF"])
    problems = soak.removal.make_dry(mat2)
    print("deleted BSDF:", problems)
    check(any("Principled BSDF" in p for p in problems) and not any(
        n.get("soak_node") for n in mat2.node_tree.nodes), f"deleted BSDF: {problems}")

    # a group node without a restore record (a file from an older add-on)
    mat3 = textured_material("NoRecord")
    use(ob, mat3)
    bpy.ops.soak.make_wet()
    del mat3.node_tree.nodes["Soak Wet"]["soak_restore"]
    r = bpy.ops.soak.make_dry()
    check(r == {"FINISHED"} and not any(n.get("soak_node") for n in mat3.node_tree.nodes),
          "Make Dry without a restore record")


# ---- 4. several Principled BSDFs ------------------------------------------------

def test_two_principled(ob):
    """Every Principled BSDF of a material is wetted (two behind a Mix
    Shader): each gets its own group node fed by its own colour, one wetness
    source and one set of controls drive both, Make Dry restores the tree."""
    soak = sys.modules["soak"]
    mat = bpy.data.materials.new("TwoBSDF")
    common.use_nodes(mat)
    t = mat.node_tree
    a = t.nodes["Principled BSDF"]
    b = t.nodes.new("ShaderNodeBsdfPrincipled")
    b.name = "Second BSDF"
    a.inputs["Base Color"].default_value = (0.6, 0.3, 0.2, 1.0)
    b.inputs["Base Color"].default_value = (0.1, 0.2, 0.7, 1.0)
    mix = t.nodes.new("ShaderNodeMixShader")
    out = t.nodes["Material Output"]
    t.links.new(a.outputs[0], mix.inputs[1])
    t.links.new(b.outputs[0], mix.inputs[2])
    t.links.new(mix.outputs[0], out.inputs["Surface"])
    use(ob, mat)
    before = common.tree_state(t)
    g0 = groups()
    bsdfs = soak.checks.check_wettable(mat, mat.soak)
    check([n.name for n in bsdfs] == ["Principled BSDF", "Second BSDF"], f"BSDFs to wet: {[n.name for n in bsdfs]}")
    mat.soak.wetness_source = "NOISE"
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "make_wet two BSDFs")
    gns = soak.material_tree.group_nodes(t)
    check(len(gns) == 2 and all(bsdf_fed_by_group(mat, n).values() for n in ("Principled BSDF", "Second BSDF")),
          f"not every BSDF is wet: {len(gns)} group nodes")
    fed = {n.name: n.inputs["Base Color"].links[0].from_node for n in (a, b)}
    cols = {n.name: tuple(round(c, 3) for c in fed[n.name].inputs["Base Color"].default_value[:3]) for n in (a, b)}
    check(fed["Principled BSDF"] != fed["Second BSDF"] and cols == {"Principled BSDF": (0.6, 0.3, 0.2),
                                                                    "Second BSDF": (0.1, 0.2, 0.7)},
          f"each BSDF's own colour into its own group: {cols}")
    src = {g.inputs["Wet Map"].links[0].from_node.name for g in gns if g.inputs["Wet Map"].is_linked}
    check(len(src) == 1, f"one wetness source for both groups: {src}")
    mat.soak.fill_time = 42.0
    check(all(abs(g.inputs["Fill Time"].default_value - 42.0) < 1e-6 for g in gns), "a control set only one group")
    check(bpy.ops.soak.key_drying() == {"FINISHED"}, "key drying two BSDFs")
    ad = t.animation_data
    keyed = {g.name for g in gns if common.find_fcurve(
        t, f'nodes["{g.name}"].inputs[{list(g.inputs).index(g.inputs["Time"])}].default_value')}
    check(keyed == {g.name for g in gns}, f"Key Drying keyed {keyed}")
    if ad is not None:
        ad.action = None
    mat.soak.preset = "concrete"
    check(mat.soak.status == "" and all(__import__("json").loads(g.node_tree["soak_group"])["preset"] == "concrete"
                                        for g in soak.material_tree.group_nodes(t)), "rebuild of two groups")
    bpy.ops.soak.make_dry()
    mat.soak.preset, mat.soak.wetness_source = "sand", "CONSTANT"
    after = common.tree_state(t)
    check(after == before and groups() == g0, "two BSDFs: not restored")


# ---- 5. the source after Make Wet -----------------------------------------------

def test_source_after_wet(ob):
    mat = textured_material("Source")
    use(ob, mat)
    t = mat.node_tree
    before = common.tree_state(t)
    mat.soak.wetness_source = "CONSTANT"
    bpy.ops.soak.make_wet()
    gn = t.nodes["Soak Wet"]
    check(not gn.inputs["Wet Map"].is_linked, "constant source linked")
    mat.soak.wetness_source = "NOISE"
    check(gn.inputs["Wet Map"].is_linked and gn.inputs["Wet Map"].links[0].from_node.bl_idname ==
          "ShaderNodeMapRange", "Noise source not wired after Make Wet")
    mat.soak.noise_scale = 11.0
    noise = next(n for n in t.nodes if n.bl_idname == "ShaderNodeTexNoise")
    check(abs(noise.inputs["Scale"].default_value - 11.0) < 1e-6, "Noise Scale not applied after Make Wet")
    img = bpy.data.images.new("wetmap", 4, 4, float_buffer=True)
    mat.soak.wet_map = img
    mat.soak.wetness_source = "IMAGE"
    link = gn.inputs["Wet Map"].links
    check(link and link[0].from_node.bl_idname == "ShaderNodeTexImage" and link[0].from_node.image == img,
          "Image source not wired after Make Wet")
    check(not any(n.bl_idname == "ShaderNodeTexNoise" for n in t.nodes), "old source nodes left")
    mat.soak.wetness_source = "ATTRIBUTE"
    mat.soak.attribute_name = "my_wet"
    link = gn.inputs["Wet Map"].links
    check(link and link[0].from_node.bl_idname == "ShaderNodeAttribute"
          and link[0].from_node.attribute_name == "my_wet", "Attribute source not wired after Make Wet")
    mat.soak.wetness_source = "CONSTANT"
    check(not gn.inputs["Wet Map"].is_linked, "constant source after others still linked")
    bpy.ops.soak.make_dry()
    check(common.tree_state(t) == before, "source changes: not restored")


# ---- 6. Key Drying ----------------------------------------------------------------

def test_key_drying(ob):
    mat = textured_material("Keys")
    use(ob, mat)
    sc = bpy.context.scene
    sc.frame_start, sc.frame_end = 10, 60
    bpy.ops.soak.make_wet()
    t = mat.node_tree
    gn = t.nodes["Soak Wet"]
    gn.inputs["Fill Time"].default_value = 500.0
    gn.inputs["Start Time"].default_value = 20.0
    check(mat.soak.schedule is False and mat.soak.drying is False, "checkbox proxies: off by default")
    for _ in range(2):   # twice: the second replaces the first's keys
        check(bpy.ops.soak.key_drying() == {"FINISHED"}, "key_drying")
    fcs = [fc for fc in common.fcurves(t) if ".inputs[" in fc.data_path]
    check(len(fcs) == 1, f"Key Drying made {len(fcs)} curves")
    time_path = fcs[0].data_path
    keys = [(k.co[0], k.co[1]) for k in fcs[0].keyframe_points]
    print("Key Drying keys:", keys)
    check(keys == [(10.0, 20.0), (60.0, 520.0)], f"keys not over the scene range from Start to Start + Fill: {keys}")
    check(abs(gn.inputs["Fill Time"].default_value - 500.0) < 1e-4
          and abs(gn.inputs["Start Time"].default_value - 20.0) < 1e-6, "Key Drying overwrote Fill/Start Time")
    check(mat.soak.schedule and mat.soak.drying, "Key Drying did not turn Schedule and Drying on")
    sc.frame_set(35)
    check(abs(gn.inputs["Time"].default_value - 270.0) < 1e-3, f"keys not linear: {gn.inputs['Time'].default_value}")
    # the checkbox proxies drive the float inputs
    mat.soak.drying = False
    check(gn.inputs["Drying"].default_value == 0.0, "Drying checkbox does not drive the input")
    mat.soak.fill_time = 42.0
    check(abs(gn.inputs["Fill Time"].default_value - 42.0) < 1e-6, "Fill Time proxy does not drive the input")
    # the panel's keyframe button keys the node's input itself, and takes the key out again
    sc.frame_set(12)
    wet_path = f'nodes["Soak Wet"].inputs[{list(gn.inputs).index(gn.inputs["Wetness"])}].default_value'
    check(bpy.ops.soak.key_control(name="Wetness") == {"FINISHED"}, "key_control")
    fc = common.find_fcurve(t, wet_path)
    check(fc is not None and [k.co[0] for k in fc.keyframe_points] == [12.0], "the keyframe button did not key")
    bpy.ops.soak.key_control(name="Wetness")
    fc = common.find_fcurve(t, wet_path)
    check(fc is None or len(fc.keyframe_points) == 0, "the keyframe button did not delete its key")
    # explicit frames, and a refusal for an empty range (nothing changed); a
    # modifier the user put on the Time curve survives a re-key (Key Drying
    # keeps the curve: removing it would free every reference to it)
    common.find_fcurve(t, time_path).modifiers.new("CYCLES")
    check(bpy.ops.soak.key_drying(frame_start=5, frame_end=9) == {"FINISHED"}, "key_drying 5..9")
    time_fc = [fc for fc in common.fcurves(t) if fc.keyframe_points and fc.data_path == time_path]
    check(len(time_fc) == 1, f"explicit frames: {len(time_fc)} Time curves")
    keys = [(k.co[0], k.co[1]) for k in time_fc[0].keyframe_points]
    check(keys == [(5.0, 20.0), (9.0, 62.0)], f"explicit frames: {keys}")
    mods = [fm.type for fm in time_fc[0].modifiers]
    check(mods == ["CYCLES"], f"Key Drying dropped the Time curve's modifier: {mods}")
    time_fc[0].modifiers.remove(time_fc[0].modifiers[0])
    bpy.context.view_layer.update()   # the keys bound Time again: the handler rebuilds the group for them
    state = common.tree_state(t)
    msg = op_error(bpy.ops.soak.key_drying, frame_start=9, frame_end=9)
    check("must come after" in msg and common.tree_state(t) == state, f"empty range: {msg}")
    sc.frame_start, sc.frame_end = 1, 250
    bpy.ops.soak.make_dry()


# ---- 7. Bake Wet Map: shelter and wiring ------------------------------------------

def texel(img, u, v):
    w, h = img.size
    x, y = min(int(u * w), w - 1), min(int(v * h), h - 1)
    return img.pixels[4 * (y * w + x)]


def test_bake(scene_objects):
    ground = scene_objects["ground"]
    prefs = common.preferences()
    prefs.soak_path = A["soak"]
    mat = textured_material("Ground")
    use(ground, mat)
    vals = {}
    for mode in ("NONE", "SCENE"):
        # 60 s of 10 mm/h rain: below the film the bake retains (0.2 mm), so no water flows
        r = bpy.ops.soak.bake_wetmap("EXEC_DEFAULT", size=32, rays=32, duration=60.0, occluders=mode)
        check(r == {"FINISHED"}, f"bake {mode}")
        img = mat.soak.wet_map
        # under the ring (x = 1, y = 0 on a 4 x 4 plane: u = 0.75, v = 0.5), in the
        # ring's hole (centre) and in the open corner
        vals[mode] = {"under ring": texel(img, 0.75, 0.5), "hole": texel(img, 0.5, 0.5),
                      "open": texel(img, 0.95, 0.95), "under roof": texel(img, 0.125, 0.875)}
    print("bake wet map values:", vals)
    # open ground: w = 1 - exp(-(rainfall - evaporation) t / saturation) with soak bake rain's
    # defaults (10 mm/h, 0.5 mm/h, 0.2 mm) = 0.547 (+- the Poisson drop noise of 32 x 32 texels)
    w_open = 1.0 - __import__("math").exp(-(10.0 - 0.5) / 3600.0 * 60.0 / 0.2)
    n = vals["NONE"]
    for k in ("under ring", "hole", "open", "under roof"):
        check(abs(n[k] - w_open) < 0.08, f"no occluders: {k} {n[k]:.3f}, open-ground value {w_open:.3f}")
    # the torus's tube (radius 0.25, 0.6 above the ground) covers the ground under its centre line
    # from the whole 10-degree rain cone (0.6 tan 10 deg = 0.11 < 0.25): no rain reaches it
    s = vals["SCENE"]
    check(s["under ring"] < 0.05, f"the torus does not shelter the ground: {s} vs {n}")
    # the instanced roof (0.6 wide, 0.5 up: the cone's 0.09 leaves its centre covered) shelters too
    check(s["under roof"] < 0.05, f"the instanced roof does not shelter the ground: {s} vs {n}")
    check(abs(s["open"] - w_open) < 0.08 and abs(s["hole"] - w_open) < 0.2,
          f"open ground or the ring's hole changed with occluders: {s}")
    # Shelter: a chosen collection (the torus's, then an empty one)
    torus = scene_objects["torus"]
    shelter, empty = bpy.data.collections.new("Shelter"), bpy.data.collections.new("Empty")
    bpy.context.scene.collection.children.link(shelter)
    bpy.context.scene.collection.children.link(empty)
    shelter.objects.link(torus)
    under = {}
    for name in ("Shelter", "Empty"):
        r = bpy.ops.soak.bake_wetmap("EXEC_DEFAULT", size=32, rays=32, duration=60.0, occluders="COLLECTION",
                                     collection=name)
        check(r == {"FINISHED"}, f"bake with collection {name}")
        under[name] = texel(mat.soak.wet_map, 0.75, 0.5)
    print("under the ring, collection shelter:", under)
    check(under["Shelter"] < 0.05 and abs(under["Empty"] - w_open) < 0.08,
          f"collection shelter: {under} (open ground {w_open:.3f})")
    # an already-wet material gets the new map wired in
    mat.soak.wetness_source = "CONSTANT"
    bpy.ops.soak.make_wet()
    r = bpy.ops.soak.bake_wetmap("EXEC_DEFAULT", size=16, rays=4, duration=60.0, occluders="SCENE")
    gn = mat.node_tree.nodes["Soak Wet"]
    link = gn.inputs["Wet Map"].links
    check(r == {"FINISHED"} and link and link[0].from_node.image == mat.soak.wet_map,
          "Bake Wet Map did not wire its map into the wet material")
    # a collection of occluders that does not exist: refused, nothing changed
    state = common.tree_state(mat.node_tree)
    msg = op_error(bpy.ops.soak.bake_wetmap, size=16, rays=4, duration=60.0, occluders="COLLECTION",
                   collection="No Such Collection")
    check("No Such Collection" in msg and common.tree_state(mat.node_tree) == state, f"bad collection: {msg}")
    bpy.ops.soak.make_dry()


def test_rain_direction(ground):
    """Bake Wet Map's Rain From and Spread: rain from 45 degrees towards +x
    (from (1, 0, 1)) moves the roof's rain shadow by its height (0.5) times
    tan 45 deg = 0.5 towards -x, so the ground under the roof's centre
    (x = -1.5, the roof spans -1.8..-1.2) is open to it and the ground at
    x = -1.94 (first texel column) is under the shifted shelter (-2.3..-1.7,
    widened by the 5-degree cone's 0.5 (tan 50 - tan 45) = 0.10)."""
    mat = ground.active_material
    w_open = 1.0 - __import__("math").exp(-(10.0 - 0.5) / 3600.0 * 60.0 / 0.2)
    r = bpy.ops.soak.bake_wetmap("EXEC_DEFAULT", size=32, rays=32, duration=60.0, occluders="SCENE",
                                 rain_from=(1.0, 0.0, 1.0), spread=5.0)
    check(r == {"FINISHED"}, "bake with Rain From (1, 0, 1), Spread 5")
    img = mat.soak.wet_map
    under, shifted = texel(img, 0.125, 0.875), texel(img, 0.01, 0.875)
    print(f"slanted rain: under the roof {under:.3f}, in its shifted shadow {shifted:.3f}")
    check(abs(under - w_open) < 0.08, f"slanted rain: ground under the roof {under:.3f}, open value {w_open:.3f}")
    check(shifted < 0.05, f"slanted rain: the roof's shifted shadow is wet ({shifted:.3f})")
    msg = op_error(bpy.ops.soak.bake_wetmap, size=16, rays=4, rain_from=(1.0, 0.0, -0.5))
    check("above" in msg, f"rain from below the horizon: {msg}")


def test_rain_duration(ground):
    """Bake Wet Map's Rain (s) does what its tooltip says. 0 s bakes the sky
    exposure: 1 on open horizontal ground (soak bake rain's normalisation of
    the exposure), 0 under the ring's tube and the roof, which no ray of the
    10-degree cone reaches (test_bake's geometry). An hour of 10 mm/h rain
    (0.5 mm/h evaporation) leaves 9.5 mm on open ground, 47 times the 0.2 mm
    film a flat surface holds: the surplus spreads over the flat plane, under
    the ring too, where wetness 1 - exp(-depth / 0.2 mm) > 0.99 needs 0.92 mm
    (a tenth of the open depth). And each bake of the ground replaces the
    image its previous bake made (one Ground_wet.exr, no .001, .002...)."""
    mat = ground.active_material
    mine = bpy.data.images.new("Ground_wet.exr.user", 4, 4)    # an image of the user's: never replaced
    r = bpy.ops.soak.bake_wetmap("EXEC_DEFAULT", size=32, rays=32, duration=0.0, occluders="SCENE")
    check(r == {"FINISHED"}, "bake with 0 s of rain")
    img = mat.soak.wet_map
    e = {"open": texel(img, 0.95, 0.95), "under ring": texel(img, 0.75, 0.5), "under roof": texel(img, 0.125, 0.875)}
    print("0 s of rain, sky exposure:", e)
    check(abs(e["open"] - 1.0) < 0.02 and e["under ring"] < 0.02 and e["under roof"] < 0.02,
          f"0 s of rain does not bake the sky exposure (open 1, sheltered 0): {e}")
    r = bpy.ops.soak.bake_wetmap("EXEC_DEFAULT", size=32, rays=32, duration=3600.0, occluders="SCENE")
    check(r == {"FINISHED"}, "bake with an hour of rain")
    img = mat.soak.wet_map
    h = {"open": texel(img, 0.95, 0.95), "under ring": texel(img, 0.75, 0.5), "under roof": texel(img, 0.125, 0.875)}
    print("an hour of rain:", h)
    check(h["under ring"] > 0.99 and h["open"] > 0.99,
          f"after an hour the water has not spread under the ring as the tooltip says: {h}")
    names = sorted(i.name for i in bpy.data.images if i.name.startswith("Ground_wet"))
    check(names == ["Ground_wet.exr", "Ground_wet.exr.user"] and img.name == "Ground_wet.exr"
          and mine.name == "Ground_wet.exr.user", f"the bakes piled up images: {names}")


def test_pending_controls(ob):
    """Controls set in the panel before Make Wet reach the group."""
    mat = textured_material("Pending")
    use(ob, mat)
    s = mat.soak
    s.fill_time, s.start_time, s.time, s.spill_edge = 7.5, 2.0, 3.0, 0.25
    s.schedule, s.drying = True, True
    s.puddle_level = 0.4
    check(abs(s.fill_time - 7.5) < 1e-6 and s.schedule and s.drying, "pending values not kept before Make Wet")
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "make_wet with pending controls")
    gn = mat.node_tree.nodes["Soak Wet"]
    want = {"Fill Time": 7.5, "Start Time": 2.0, "Time": 3.0, "Spill Edge": 0.25, "Schedule": 1.0, "Drying": 1.0,
            "Puddle Level": 0.4}
    got = {k: gn.inputs[k].default_value for k in want}
    check(all(abs(got[k] - v) < 1e-6 for k, v in want.items()), f"controls set before Make Wet: {got}, want {want}")
    check(not any(k.startswith("pending_") for k in s.keys()), "pending values left behind after Make Wet")
    bpy.ops.soak.make_dry()


def test_metal_preset(ob):
    """A conductor preset on a Principled left at Metallic 0 makes it metallic
    (its function is a metal's reflectance, which a dielectric would show as a
    diffuse colour); Make Dry puts the 0 back; a Metallic the user set stays."""
    for start, want in ((0.0, 1.0), (0.4, 0.4)):
        mat = textured_material(f"Metal {start}")
        use(ob, mat)
        b = mat.node_tree.nodes["Principled BSDF"]
        b.inputs["Metallic"].default_value = start
        mat.soak.preset = "copper"
        check(bpy.ops.soak.make_wet() == {"FINISHED"}, "make_wet with the copper preset")
        got = b.inputs["Metallic"].default_value
        check(abs(got - want) < 1e-6, f"copper preset from Metallic {start}: Metallic {got}, want {want}")
        check(bpy.ops.soak.make_dry() == {"FINISHED"}, "make_dry after the copper preset")
        got = b.inputs["Metallic"].default_value
        check(abs(got - start) < 1e-6, f"Make Dry after the copper preset: Metallic {got}, want {start}")
    # copper, then sand after Make Wet: the Metallic copper set goes back
    mat = textured_material("Metal switch")
    use(ob, mat)
    b = mat.node_tree.nodes["Principled BSDF"]
    mat.soak.preset = "copper"
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "make_wet with the copper preset (switch)")
    mat.soak.preset = "sand"
    got = b.inputs["Metallic"].default_value
    check(got == 0.0, f"copper -> sand after Make Wet: Metallic {got}, want the dry 0")
    check(bsdf_fed_by_group(mat)["Base Color"], "copper -> sand: the group no longer feeds the BSDF")
    bpy.ops.soak.make_dry()
    check(b.inputs["Metallic"].default_value == 0.0, "Make Dry after copper -> sand: Metallic not 0")
    mat = textured_material("Metal sand")
    use(ob, mat)
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "make_wet with the sand preset")
    got = mat.node_tree.nodes["Principled BSDF"].inputs["Metallic"].default_value
    check(got == 0.0, f"a dielectric preset changed Metallic to {got}")
    bpy.ops.soak.make_dry()


# ---- 8. tooltips and poll messages ------------------------------------------------

def test_tooltips():
    soak = sys.modules["soak"]
    missing = []
    for p in bpy.types.Material.bl_rna.properties["soak"].fixed_type.properties:
        if p.identifier != "rna_type" and not p.description.strip():
            missing.append("Material.soak." + p.identifier)
    for cls in soak.operators.classes:
        rna = getattr(bpy.ops.soak, cls.bl_idname.split(".")[1]).get_rna_type()
        if not rna.description.strip():
            missing.append(cls.bl_idname)
        for p in rna.properties:
            if p.identifier != "rna_type" and not p.is_hidden and not p.description.strip():
                missing.append(f"{cls.bl_idname}.{p.identifier}")
    for p in bpy.types.Scene.bl_rna.properties["soak_rain"].fixed_type.properties:   # Bake Rain's settings
        if p.identifier != "rna_type" and not p.description.strip():
            missing.append("Scene.soak_rain." + p.identifier)
    for p in soak.preferences.SoakPreferences.bl_rna.properties:
        if p.identifier not in ("rna_type", "bl_idname") and not p.description.strip():
            missing.append("preferences." + p.identifier)
    check(not missing, f"no tooltip: {missing}")
    n = len(bpy.types.Material.bl_rna.properties["soak"].fixed_type.properties)
    print(f"tooltips: {n - 1} material settings, {len(soak.operators.classes)} operators: all described")


class MockLayout:
    """Stands in for UILayout in the background: records what a draw()
    function draws (Blender draws no UI without a window)."""

    def __init__(self, log):
        self.log = log

    def prop(self, data, name, **kw):
        self.log.append(("prop", data, name))

    def operator(self, idname, **kw):
        self.log.append(("operator", idname))
        return type("OpProps", (), {})()

    def label(self, **kw):
        self.log.append(("label", kw.get("text", "")))

    def __getattr__(self, name):        # row(), column(), box(), separator(), template_ID(), ...
        if name in ("active", "alert", "enabled", "use_property_split", "use_property_decorate", "scale_x"):
            return True
        return lambda *a, **k: self


def draw_log(ob):
    soak = sys.modules["soak"]
    log = []
    holder = type("P", (), {})()
    holder.layout = MockLayout(log)
    for cls in soak.ui.classes:
        if not hasattr(cls, "poll") or cls.poll(bpy.context):
            cls.draw(holder, bpy.context)
    return log


def test_panel(ob):
    """The panel's draw code in each state; every property it draws has a tooltip;
    the EEVEE switch the wet look needs is offered when it is off."""
    mat = textured_material("Panel")
    use(ob, mat)
    sc = bpy.context.scene
    states = {}
    states["dry"] = draw_log(ob)
    bpy.ops.soak.make_wet()
    states["wet"] = draw_log(ob)
    mat.soak.status = "a refused change"
    states["status"] = draw_log(ob)
    mat.soak.status = ""
    for name, log in states.items():
        for item in log:
            if item[0] == "prop":
                data, prop = item[1], item[2]
                desc = data.bl_rna.properties[prop].description
                check(desc.strip() != "", f"panel ({name}) draws {prop} without a tooltip")
    wet_props = {i[2] for i in states["wet"] if i[0] == "prop"}
    check({"schedule", "drying", "time", "start_time", "fill_time", "wetness_source"} <= wet_props,
          f"after Make Wet the panel lacks controls: {sorted(wet_props)}")
    check(("operator", "soak.make_wet") in states["dry"] and ("operator", "soak.make_dry") in states["wet"],
          "Make Wet / Make Dry not drawn")
    check(any(i[0] == "label" and "refused" in i[1] for i in states["status"]), "status not shown")
    engine = common.eevee_engine()
    switch = "use_raytracing" if bpy.app.version >= (4, 2, 0) else "use_ssr"
    sc.render.engine = engine
    setattr(sc.eevee, switch, False)
    log = draw_log(ob)
    check(any(i[0] == "prop" and i[2] == switch for i in log), f"{engine}: the panel does not offer {switch}")
    setattr(sc.eevee, switch, True)
    log = draw_log(ob)
    check(not any(i[0] == "prop" and i[2] == switch for i in log), f"{engine}: {switch} offered while on")
    sc.render.engine = "CYCLES"
    print(f"panel: drawn dry/wet/refused, {len(wet_props)} properties with tooltips, {engine} offers {switch}")
    bpy.ops.soak.make_dry()


def test_poll_messages(ob):
    mat = textured_material("Poll")
    use(ob, mat)
    msg = op_error(bpy.ops.soak.make_dry)
    print("Make Dry greyed:", msg.strip())
    msg2 = op_error(bpy.ops.soak.key_drying)
    if bpy.app.version >= (3, 0, 0):
        check("not wet" in msg, f"Make Dry's poll message missing: {msg}")
        check("wet first" in msg2, f"Key Drying's poll message missing: {msg2}")
    if bpy.app.version >= (5, 0, 0):
        # 5.0 deprecated Material.use_nodes (always true): nothing to refuse
        return
    mat.use_nodes = False
    msg = op_error(bpy.ops.soak.make_wet)
    if bpy.app.version >= (3, 0, 0):
        check("Use Nodes" in msg, f"Make Wet's poll message missing: {msg}")


def main():
    common.install_addon(A["addon"])
    os.makedirs(A["tmp"], exist_ok=True)
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    bpy.ops.mesh.primitive_plane_add(size=4)
    ground = bpy.context.object
    ground.name = "Ground"
    attr = ground.data.attributes.new("dp_wetmap", "FLOAT", "POINT")   # the Attribute source reads it
    for d in attr.data:
        d.value = 0.9
    bpy.ops.mesh.primitive_torus_add(major_radius=1.0, minor_radius=0.25, location=(0, 0, 0.6))
    torus = bpy.context.object
    # a roof over one corner as a collection instance (its collection is in no scene)
    roofs = bpy.data.collections.new("Roofs")
    roof = bpy.data.objects.new("Roof", bpy.data.meshes.new("Roof"))
    roof.data.from_pydata([(-0.3, -0.3, 0), (0.3, -0.3, 0), (0.3, 0.3, 0), (-0.3, 0.3, 0)], [], [(0, 1, 2, 3)])
    roofs.objects.link(roof)
    holder = bpy.data.objects.new("Roof instance", None)
    holder.instance_type = "COLLECTION"
    holder.instance_collection = roofs
    holder.location = (-1.5, 1.5, 0.5)
    bpy.context.scene.collection.objects.link(holder)
    bpy.ops.object.light_add(type="SUN", location=(0, 0, 5), rotation=(0.5236, 0.0, 0.0))   # 30 deg off normal
    bpy.context.object.data.energy = 3.0
    bpy.context.view_layer.objects.active = ground
    setup_render(bpy.context.scene)

    test_tooltips()
    test_failures(ground)
    test_linked(ground)
    torus.hide_render = True      # the renders show the ground alone; the bake uses the torus
    test_rebuild(ground)
    torus.hide_render = False
    test_dry_after_edits(ground)
    test_two_principled(ground)
    test_source_after_wet(ground)
    test_key_drying(ground)
    test_poll_messages(ground)
    test_panel(ground)
    test_bake({"ground": ground, "torus": torus})
    test_rain_direction(ground)
    test_rain_duration(ground)
    test_pending_controls(ground)
    test_metal_preset(ground)
    print(f"{len(CHECKS)} checks")
    print("PASS")


main()
