"""Beads (issue 48 items 4 and 6): the map of `soak bake beads` as a bump in
a wet material.

Like rain.py it only adds nodes around the Soak Wet group node (tagged as
Make Wet's, so Make Dry removes them) and never changes the group:

  UV (the mesh's map) x Repeat --> Image (the bead map, Non-Color, tiling)
      Alpha (height / --height-range) --> Bump (Height; Distance = the range
      in metres x the object's scale, so the slopes are the baked ones;
      Normal = what fed the group's Normal) --> group Normal

The bump comes after the rain's ripple mix when both are wired (a bead sits
on whatever the surface does). All or nothing through snapshot.atomic."""


from . import checks, material_tree, snapshot

BEADS_ROLE = "beads"
BUMP_LABEL = "Soak Beads: bump"


def _node(tree, kind, x, y, label):
    return material_tree.new_node(tree, kind, x, y, label, BEADS_ROLE)


def bead_nodes(tree):
    return material_tree.role_nodes(tree, BEADS_ROLE)


def _base_normal(gn):
    """What feeds the group's Normal now, seen through an earlier bead bump."""
    links = gn.inputs["Normal"].links
    if not links:
        return None
    src = links[0].from_socket
    if src.node.get(material_tree.ROLE_KEY) == BEADS_ROLE:
        links = src.node.inputs["Normal"].links
        return links[0].from_socket if links else None
    return src


def _wire(mat, gns, image, repeat, uv_map, distance):
    tree = mat.node_tree
    gn = gns[0]
    old = bead_nodes(tree)
    base = _base_normal(gn)
    x, y = gn.location.x - 900, gn.location.y - 700
    if uv_map:
        uv = _node(tree, "ShaderNodeUVMap", x, y, "Soak Beads: UV")
        uv.uv_map = uv_map
    else:
        uv = _node(tree, "ShaderNodeTexCoord", x, y, "Soak Beads: UV")
    mp = _node(tree, "ShaderNodeMapping", x + 180, y, "Soak Beads: tiles")
    mp.inputs["Scale"].default_value = (repeat, repeat, 1.0)
    tex = _node(tree, "ShaderNodeTexImage", x + 360, y, "Soak Beads: map")
    tex.image = image
    tex.extension = "REPEAT"
    tex.interpolation = "Linear"
    bump = _node(tree, "ShaderNodeBump", x + 640, y, BUMP_LABEL)
    bump.inputs["Strength"].default_value = 1.0
    bump.inputs["Distance"].default_value = distance
    tree.links.new(uv.outputs["UV"], mp.inputs["Vector"])
    tree.links.new(mp.outputs["Vector"], tex.inputs["Vector"])
    tree.links.new(tex.outputs["Alpha"], bump.inputs["Height"])
    if base is not None:
        tree.links.new(base, bump.inputs["Normal"])
    for g in gns:
        tree.links.new(bump.outputs["Normal"], g.inputs["Normal"])
    for n in old:
        tree.nodes.remove(n)
    material_tree.record_our_nodes(tree, gns)
    return bump


def wire(mat, image, repeat=1.0, uv_map="", distance=0.006):
    """Wires a bead map (`soak bake beads`, RGBA, alpha = height / range)
    into a wet material as a Bump of Distance `distance` (the bake's
    --height-range in object units), the map repeated `repeat` times across
    the UV square. All or nothing: on failure the tree is as before."""
    tree = mat.node_tree
    gns = material_tree.group_nodes(tree) if tree is not None else []
    if not gns:
        raise RuntimeError(f"material '{mat.name}' is not wet: Make Wet first, then bake the beads")
    checks.check_editable(mat)
    if any(material_tree.RESTORE_KEY not in g for g in gns):
        raise RuntimeError(f"material '{mat.name}': a Soak Wet node has no restore record (Make Dry, then Make Wet)")
    image.colorspace_settings.name = "Non-Color"
    image.alpha_mode = "STRAIGHT"
    return snapshot.atomic(tree, _wire, mat, gns, image, repeat, uv_map, distance)
