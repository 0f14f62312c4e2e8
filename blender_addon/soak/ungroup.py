"""Opening the node groups that hold a material's Principled BSDF (nested
too), as asset libraries build materials, so that Make Wet can wet it.

A group node whose group holds a Principled BSDF (at any depth) is replaced
in this material by a copy of the group's nodes, inside a labelled frame:
the group's links in and out are reconnected through, and an input left
unlinked on the group node becomes a labelled constant node with its value.
The group itself is not changed: every other material using it (a shared
group, a linked asset's group) renders as before. What a copy cannot carry:
keyframes and drivers inside the group (they stay on the group)."""

FRAME_KEY = "soak_ungrouped"    # on the frame holding a group's copied nodes: the group's name

# Node properties that are the node's place or identity, not its settings
_SKIP = {"rna_type", "name", "location", "dimensions", "parent", "inputs", "outputs", "internal_links", "type",
         "select", "is_active_output"}
_INERT = {"OUTPUT_MATERIAL", "OUTPUT_WORLD", "OUTPUT_LIGHT"}   # ignored inside a group; never copied out
_CONSTANT = {"VALUE": ("ShaderNodeValue", 0), "INT": ("ShaderNodeValue", 0), "BOOLEAN": ("ShaderNodeValue", 0),
             "RGBA": ("ShaderNodeRGB", 0), "VECTOR": ("ShaderNodeCombineXYZ", 0)}


def holds_principled(ng, seen=None):
    """True if the node group (or a group inside it) has a Principled BSDF."""
    if ng is None:
        return False
    seen = set() if seen is None else seen
    if ng.name_full in seen:
        return False
    seen.add(ng.name_full)
    for n in ng.nodes:
        if n.type == "BSDF_PRINCIPLED" or (n.type == "GROUP" and holds_principled(n.node_tree, seen)):
            return True
    return False


def groups_to_open(tree):
    """The group nodes of a tree whose groups hold a Principled BSDF (a
    muted group node passes its inputs through: it is left alone)."""
    return [n for n in tree.nodes if n.type == "GROUP" and not n.mute and holds_principled(n.node_tree)]


def _copy_ramp(src, dst):
    for attr in ("color_mode", "interpolation", "hue_interpolation"):
        setattr(dst, attr, getattr(src, attr))
    els = dst.elements
    while len(els) > 1:
        els.remove(els[-1])
    els[0].position, els[0].color = src.elements[0].position, src.elements[0].color
    for e in list(src.elements)[1:]:
        els.new(e.position).color = e.color


def _copy_curves(src, dst):
    for attr in ("use_clip", "clip_min_x", "clip_min_y", "clip_max_x", "clip_max_y", "extend", "tone",
                 "black_level", "white_level"):
        if hasattr(src, attr):
            setattr(dst, attr, getattr(src, attr))
    for cs, cd in zip(src.curves, dst.curves):
        pts = cd.points
        while len(pts) > max(len(cs.points), 2):
            pts.remove(pts[-1])
        while len(pts) < len(cs.points):
            pts.new(0.0, 0.0)
        for p, q in zip(cs.points, pts):
            q.location, q.handle_type = tuple(p.location), p.handle_type
    dst.update()


def _copy_settings(src, dst):
    """The node's own settings (operation, image, blend type, ...), its ramp
    or curves, and every socket's value, as the group holds them."""
    for p in src.bl_rna.properties:
        ident = p.identifier
        if ident in _SKIP or ident.startswith("bl_"):
            continue
        if ident == "color_ramp" and src.color_ramp is not None:
            _copy_ramp(src.color_ramp, dst.color_ramp)
        elif ident == "mapping" and getattr(src, "mapping", None) is not None and hasattr(src.mapping, "curves"):
            _copy_curves(src.mapping, dst.mapping)
        elif not p.is_readonly and p.type != "COLLECTION":
            try:
                setattr(dst, ident, getattr(src, ident))
            except (AttributeError, TypeError, ValueError):
                pass        # a property this node type keeps read-only in this Blender
    for a, b in ((src.inputs, dst.inputs), (src.outputs, dst.outputs)):
        by_id = {s.identifier: s for s in b}
        for s in a:
            t = by_id.get(s.identifier)
            if t is None:
                continue
            t.hide = s.hide
            if hasattr(s, "default_value") and hasattr(t, "default_value"):
                try:
                    t.default_value = s.default_value
                except (TypeError, ValueError):
                    pass


def _constant(tree, sock, name, frame, location):
    """A labelled node giving sock's value (a group input left unlinked),
    or None where the value means 'not connected' (a hidden-value vector
    such as Normal: the BSDF then uses its own shading normal)."""
    kind = _CONSTANT.get(sock.type)
    if kind is None or (sock.type == "VECTOR" and getattr(sock, "hide_value", False)):
        return None
    n = tree.nodes.new(kind[0])
    n.label = name
    n.parent = frame
    n.location = location
    v = sock.default_value
    if sock.type == "VECTOR":
        for i, c in enumerate(("X", "Y", "Z")):
            n.inputs[c].default_value = v[i]
    elif sock.type == "RGBA":
        n.outputs[0].default_value = v
    else:
        n.outputs[0].default_value = float(v)
    return n.outputs[0]


def _copy_nodes(tree, ng, frame, offset):
    """Copies of the group's nodes (not its Group Input/Output, nor inert
    output nodes) in tree: {inner node name: copy}."""
    made = {}
    for n in ng.nodes:
        if n.type in ("GROUP_INPUT", "GROUP_OUTPUT") or n.type in _INERT:
            continue
        c = tree.nodes.new(n.bl_idname)
        _copy_settings(n, c)
        c.location = (n.location.x + offset[0], n.location.y + offset[1])
        made[n.name] = c
    for n in ng.nodes:
        c = made.get(n.name)
        if c is not None:
            c.parent = made.get(n.parent.name, frame) if n.parent is not None else frame
    return made


def _group_output(ng):
    outs = [n for n in ng.nodes if n.type == "GROUP_OUTPUT"]
    return next((n for n in outs if n.is_active_output), outs[0] if outs else None)


def ungroup(tree, gn):
    """Replaces group node gn by its group's nodes (one level). Returns the
    frame holding them. gn is left in the tree, disconnected, for the
    caller to remove once the whole change succeeded (snapshot.atomic puts
    its links back otherwise)."""
    ng = gn.node_tree
    frame = tree.nodes.new("NodeFrame")
    frame.label = f"{ng.name} (opened by Soak Make Wet)"
    frame[FRAME_KEY] = ng.name
    frame.parent = gn.parent
    xs = [n.location.x for n in ng.nodes] or [0.0]
    ys = [n.location.y for n in ng.nodes] or [0.0]
    offset = (gn.location.x - 0.5 * (min(xs) + max(xs)), gn.location.y - 0.5 * (min(ys) + max(ys)))
    made = _copy_nodes(tree, ng, frame, offset)
    sources = {}        # group input identifier -> the socket feeding it outside (or a constant)

    def source_of_input(ident):
        if ident not in sources:
            outer = next((s for s in gn.inputs if s.identifier == ident), None)
            if outer is None:
                sources[ident] = None
            elif outer.is_linked:
                sources[ident] = outer.links[0].from_socket
            else:
                loc = (gn.location.x - 200, gn.location.y - 60 * len(sources))
                sources[ident] = _constant(tree, outer, outer.name, frame, loc)
        return sources[ident]

    def mapped(link):
        if link.from_node.type == "GROUP_INPUT":
            return source_of_input(link.from_socket.identifier)
        c = made.get(link.from_node.name)
        return None if c is None else next((s for s in c.outputs if s.identifier == link.from_socket.identifier),
                                           None)

    out_node = _group_output(ng)
    results = {}        # group output identifier -> the socket that computes it
    for link in ng.links:
        if not link.is_valid:
            continue
        if link.to_node == out_node:
            results[link.to_socket.identifier] = mapped(link)
            continue
        to = made.get(link.to_node.name)
        src = mapped(link)
        dst = to and next((s for s in to.inputs if s.identifier == link.to_socket.identifier), None)
        if src is not None and dst is not None:
            new = tree.links.new(src, dst)
            new.is_muted = link.is_muted
    for out in gn.outputs:
        src = results.get(out.identifier)
        if src is None and out_node is not None:
            inner = next((s for s in out_node.inputs if s.identifier == out.identifier), None)
            if inner is not None and hasattr(inner, "default_value") and out.is_linked:
                src = _constant(tree, inner, out.name, frame, (gn.location.x + 200, gn.location.y))
        for link in list(out.links):
            dst = link.to_socket
            tree.links.remove(link)
            if src is not None:
                tree.links.new(src, dst)
    for s in gn.inputs:
        for link in list(s.links):
            tree.links.remove(link)
    return frame


def open_groups(tree):
    """Opens, level by level, every group node holding a Principled BSDF.
    Returns (the names of the groups opened, the emptied group nodes to
    remove once the change succeeded)."""
    opened, emptied = [], []
    todo = groups_to_open(tree)
    while todo:
        for gn in todo:
            opened.append(gn.node_tree.name)
            ungroup(tree, gn)
            emptied.append(gn)
        todo = [n for n in groups_to_open(tree) if n not in emptied]
    return opened, emptied


def remove_emptied(tree, emptied):
    for gn in emptied:
        tree.nodes.remove(gn)
