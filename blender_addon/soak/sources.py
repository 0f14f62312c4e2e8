"""The wetness source: the nodes feeding every Soak Wet node's Wet Map
(an image, an attribute or a noise), wired by Make Wet and re-wired by
the panel's Wetness Source."""

import json

from . import specialise
from .checks import check_editable, check_source
from .material_tree import NODE_TAG, RESTORE_KEY, ROLE_KEY, group_nodes, find_group_node, tag
from .snapshot import atomic

SOURCE_TYPES = ("ShaderNodeTexImage", "ShaderNodeAttribute", "ShaderNodeTexNoise", "ShaderNodeMapRange")


def source_nodes(tree):
    return [n for n in tree.nodes if n.get(NODE_TAG) and n.type != "GROUP"
            and (n.get(ROLE_KEY) == "source" or (n.get(ROLE_KEY) is None and n.bl_idname in SOURCE_TYPES))]


def wire_source(tree, gns, settings):
    """The wetness source's nodes, feeding the Wet Map of every group node
    in gns (one node or a list)."""
    gns = list(gns) if isinstance(gns, (list, tuple)) else [gns]
    gn = gns[0]
    src = settings.wetness_source
    check_source(settings)
    made = []
    if src == "IMAGE":
        n = tag(tree.nodes.new("ShaderNodeTexImage"), "source")
        n.image = settings.wet_map
        n.extension = "EXTEND"
        out = n.outputs["Color"]
        made.append(n)
    elif src == "ATTRIBUTE":
        n = tag(tree.nodes.new("ShaderNodeAttribute"), "source")
        n.attribute_name = settings.attribute_name
        out = n.outputs["Fac"]
        made.append(n)
    elif src == "NOISE":
        n = tag(tree.nodes.new("ShaderNodeTexNoise"), "source")
        n.inputs["Scale"].default_value = settings.noise_scale
        r = tag(tree.nodes.new("ShaderNodeMapRange"), "source")
        r.clamp = True
        r.inputs["From Min"].default_value = 0.45
        r.inputs["From Max"].default_value = 0.55
        tree.links.new(n.outputs["Fac"], r.inputs["Value"])
        out = r.outputs["Result"]
        made += [n, r]
    for g in gns:
        if made:
            tree.links.new(out, g.inputs["Wet Map"])
    for i, n in enumerate(made):
        n.location = (gn.location.x - 240 * (len(made) - i), gn.location.y - 200)
    return made


def _replace_source(mat, gn, settings):
    tree = mat.node_tree
    old = source_nodes(tree)
    wire_source(tree, group_nodes(tree), settings)   # new nodes first: a snapshot cannot bring back removed ones
    for n in old:
        tree.nodes.remove(n)
    if settings.wetness_source == "IMAGE":
        settings.wet_map.colorspace_settings.name = "Non-Color"
    restore = json.loads(gn[RESTORE_KEY])
    restore["nodes"] = [n.name for n in tree.nodes if n.get(NODE_TAG) and n != gn]
    gn[RESTORE_KEY] = json.dumps(restore)
    return specialise.specialise_stale(tree)


def current_source(tree):
    """The wetness-source settings a wet material's nodes implement."""
    kinds = {n.bl_idname: n for n in source_nodes(tree)}
    if "ShaderNodeTexImage" in kinds:
        return {"wetness_source": "IMAGE", "wet_map": kinds["ShaderNodeTexImage"].image}
    if "ShaderNodeAttribute" in kinds:
        return {"wetness_source": "ATTRIBUTE", "attribute_name": kinds["ShaderNodeAttribute"].attribute_name}
    if "ShaderNodeTexNoise" in kinds:
        return {"wetness_source": "NOISE",
                "noise_scale": kinds["ShaderNodeTexNoise"].inputs["Scale"].default_value}
    return {"wetness_source": "CONSTANT"}


def set_source(mat, settings):
    """Re-wires the wetness source of a wet material (the panel's Wetness
    Source, Wet Map, Attribute and Noise Scale after Make Wet; Bake Wet Map).
    All or nothing; a no-op on a dry material."""
    tree = mat.node_tree
    gn = find_group_node(tree) if tree is not None else None
    if gn is None:
        return
    check_editable(mat)
    check_source(settings)
    if RESTORE_KEY not in gn:
        raise RuntimeError(f"material '{mat.name}': the Soak Wet node has no restore record")
    specialise.drop_unused(atomic(tree, _replace_source, mat, gn, settings))
