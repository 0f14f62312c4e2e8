"""Import Wet Volume: a `soak bake volume` OpenVDB file as a Volume object
whose material reads the baked grids: scattering and absorption
coefficients per channel (1/m; Blender units are metres) and the phase
function's mean cosine (Cycles' volume shaders have one Henyey-Greenstein
lobe; the two-term lobe is reduced to g = w g1 + (1 - w) g2, its mean
cosine, wetness.h step 3)."""

import os

import bpy
from bpy_extras.io_utils import ImportHelper

from .. import compat

GRIDS = ("sigma_s_r", "sigma_s_g", "sigma_s_b", "sigma_a_r", "sigma_a_g", "sigma_a_b", "g1", "g2", "w")


def _attr(tree, name, x, y):
    n = tree.nodes.new("ShaderNodeAttribute")
    n.attribute_name = name
    n.location = (x, y)
    return n.outputs["Fac"]


def _math(tree, op, a, b, x, y):
    n = tree.nodes.new("ShaderNodeMath")
    n.operation = op
    n.location = (x, y)
    for i, v in enumerate((a, b)):
        if isinstance(v, float):
            n.inputs[i].default_value = v
        else:
            tree.links.new(v, n.inputs[i])
    return n.outputs[0]


def volume_material(name):
    mat = bpy.data.materials.new(name)
    t = compat.ensure_node_tree(mat)
    t.nodes.clear()
    out = t.nodes.new("ShaderNodeOutputMaterial")
    out.location = (900, 0)
    ss = [_attr(t, f"sigma_s_{c}", -600, 300 - 120 * i) for i, c in enumerate("rgb")]
    sa = [_attr(t, f"sigma_a_{c}", -600, -100 - 120 * i) for i, c in enumerate("rgb")]
    sc = t.nodes.new("ShaderNodeCombineColor")
    sc.location = (-300, 300)
    for i in range(3):
        t.links.new(ss[i], sc.inputs[i])
    g1, g2, w = (_attr(t, n, -600, -500 - 120 * i) for i, n in enumerate(("g1", "g2", "w")))
    g = _math(t, "MULTIPLY_ADD", _math(t, "SUBTRACT", g1, g2, -400, -500), w, -200, -500)
    t.links.new(g2, g.node.inputs[2])
    scatter = t.nodes.new("ShaderNodeVolumeScatter")
    scatter.location = (200, 300)
    t.links.new(sc.outputs[0], scatter.inputs["Color"])
    scatter.inputs["Density"].default_value = 1.0
    t.links.new(g, scatter.inputs["Anisotropy"])
    # absorption: density D = max channel, colour 1 - sigma_a / D
    d = _math(t, "ADD", _math(t, "MAXIMUM", _math(t, "MAXIMUM", sa[0], sa[1], -400, -100), sa[2], -300, -100),
              1e-9, -200, -100)
    ac = t.nodes.new("ShaderNodeCombineColor")
    ac.location = (0, -100)
    for i in range(3):
        t.links.new(_math(t, "SUBTRACT", 1.0, _math(t, "DIVIDE", sa[i], d, -200, -200 - 80 * i), -100,
                          -200 - 80 * i), ac.inputs[i])
    absorb = t.nodes.new("ShaderNodeVolumeAbsorption")
    absorb.location = (200, -100)
    t.links.new(ac.outputs[0], absorb.inputs["Color"])
    t.links.new(d, absorb.inputs["Density"])
    add = t.nodes.new("ShaderNodeAddShader")
    add.location = (500, 0)
    t.links.new(scatter.outputs[0], add.inputs[0])
    t.links.new(absorb.outputs[0], add.inputs[1])
    t.links.new(add.outputs[0], out.inputs["Volume"])
    return mat


def import_volume(context, path):
    if not os.path.isfile(path):
        raise RuntimeError(f"{path}: no such file")
    vol = bpy.data.volumes.new(os.path.splitext(os.path.basename(path))[0])
    vol.filepath = path
    if not vol.grids.load():
        raise RuntimeError(f"{path}: not an OpenVDB file Blender can read ({vol.grids.error_message})")
    names = {g.name for g in vol.grids}
    missing = [g for g in GRIDS if g not in names]
    if missing:
        raise RuntimeError(f"{path}: not a soak bake volume (missing grids {', '.join(missing)})")
    ob = bpy.data.objects.new(vol.name, vol)
    context.collection.objects.link(ob)
    vol.materials.append(volume_material(vol.name + " medium"))
    return ob


class SOAK_OT_import_volume(bpy.types.Operator, ImportHelper):
    """Import a soak bake volume (OpenVDB) as a Volume object with its medium wired"""
    bl_idname = "soak.import_volume"
    bl_label = "Import Wet Volume"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".vdb"
    filter_glob: bpy.props.StringProperty(default="*.vdb", options={"HIDDEN"})

    def execute(self, context):
        try:
            ob = import_volume(context, self.filepath)
        except RuntimeError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, f"imported {ob.name} ({len(ob.data.grids)} grids)")
        return {"FINISHED"}


classes = (SOAK_OT_import_volume,)
