"""The OSL variant of Make Wet: a Script node running the shipped, generated
shader osl/soak_wet_surface.osl (`soak export --target osl`; osl/README.md;
Blender 2.80-3.3 get soak_wet_surface_legacy.osl, whose metals use the
microfacet_ggx closure that those versions register instead of the generic
microfacet) in place of the native Soak Wet group's output.

apply_osl_variant(material, settings) reads settings.preset, .liquid,
.wetness and .colour_source. The shader's source is loaded as an Internal
text block (it is self-contained); its sockets exist only once Blender has
compiled it, which needs a Blender built with OSL and Cycles' Open Shading
Language option on. Without sockets the node is left in the tree, unlinked
and labelled, and the function returns False (the native nodes stay in
charge). Every node added carries the "soak_node" tag, so Make Dry removes it.
"""
import os

import bpy

SHADER = "soak_wet_surface.osl"
SHADER_LEGACY = "soak_wet_surface_legacy.osl"
TAG = "soak_node"


def shader_name(version=None):
    """The shipped surface shader whose closures this Blender registers."""
    return SHADER if (version or bpy.app.version) >= (3, 4, 0) else SHADER_LEGACY


def shader_path():
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "osl", shader_name())


def _text():
    path = shader_path()
    with open(path, encoding="utf-8") as f:
        source = f.read()
    name = shader_name()
    text = bpy.data.texts.get(name) or bpy.data.texts.new(name)
    if text.as_string() != source:
        text.clear()
        text.write(source)
    return text


def _output(tree):
    for n in tree.nodes:
        if n.bl_idname == "ShaderNodeOutputMaterial" and n.is_active_output:
            return n
    return next((n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputMaterial"), None)


def apply_osl_variant(material, settings):
    """Adds the Script node; wires it when Blender could compile it."""
    if not os.path.isfile(shader_path()):
        return False
    tree = material.node_tree
    node = tree.nodes.new("ShaderNodeScript")
    node[TAG] = True
    node.mode = "INTERNAL"
    node.script = _text()
    node.label = "Soak Wet (OSL)"
    out = _output(tree)
    if out is not None:
        node.location = (out.location[0] - 250, out.location[1] - 300)
    values = {"Preset": settings.preset, "Liquid": settings.liquid, "Wetness": settings.wetness,
              "UseBaseColor": 1 if settings.colour_source == "MATERIAL" else 0}
    if "BSDF" not in node.outputs or out is None:
        node.label = "Soak Wet (OSL: compile with Open Shading Language on)"
        return False
    for name, value in values.items():
        if name in node.inputs:
            node.inputs[name].default_value = value
    # the user's colour: whatever fed the Principled BSDF's Base Color
    bsdf = next((n for n in tree.nodes if n.bl_idname == "ShaderNodeBsdfPrincipled"), None)
    if bsdf is not None and "BaseColor" in node.inputs:
        links = bsdf.inputs["Base Color"].links
        if links:
            tree.links.new(links[0].from_socket, node.inputs["BaseColor"])
        else:
            node.inputs["BaseColor"].default_value = bsdf.inputs["Base Color"].default_value
    tree.links.new(node.outputs["BSDF"], out.inputs["Surface"])
    return True
