"""A thin sheet's transmitted light: the Translucent BSDF + Add Shader pair
beside the Principled BSDF, added and taken out."""


from .material_tree import NODE_TAG, ROLE_KEY, tag


def add_translucency(tree, gn, bsdf):
    tr = tag(tree.nodes.new("ShaderNodeBsdfTranslucent"), "translucency")
    add = tag(tree.nodes.new("ShaderNodeAddShader"), "translucency")
    tr.location = (bsdf.location.x, bsdf.location.y - 500)
    add.location = (bsdf.location.x + 300, bsdf.location.y - 300)
    tree.links.new(gn.outputs["Translucency"], tr.inputs["Color"])
    tree.links.new(gn.outputs["Normal"], tr.inputs["Normal"])
    targets = [l.to_socket for l in bsdf.outputs[0].links]
    for l in list(bsdf.outputs[0].links):
        tree.links.remove(l)
    tree.links.new(bsdf.outputs[0], add.inputs[0])
    tree.links.new(tr.outputs[0], add.inputs[1])
    for s in targets:
        tree.links.new(add.outputs[0], s)
    return [tr, add]


def sheet_pair(tree, bsdf):
    """The Translucent BSDF + Add Shader pair Make Wet added beside `bsdf`."""
    adds = [n for n in tree.nodes if n.get(NODE_TAG) and n.get(ROLE_KEY) == "translucency"
            and n.bl_idname == "ShaderNodeAddShader" and any(l.from_node == bsdf for l in n.inputs[0].links)]
    trs = [l.from_node for a in adds for l in a.inputs[1].links if l.from_node.get(NODE_TAG)]
    return adds + trs


def remove_translucency(tree, bsdf):
    """Takes the Translucent + Add Shader pair out, re-linking what the Add
    Shader fed to the BSDF itself."""
    pair = sheet_pair(tree, bsdf)
    for add in (n for n in pair if n.bl_idname == "ShaderNodeAddShader"):
        for l in list(add.outputs[0].links):
            if bsdf is not None:
                tree.links.new(bsdf.outputs[0], l.to_socket)
    for n in pair:
        tree.nodes.remove(n)
