"""Lays out a built Soak Wet group so an artist can read it: the stages left
to right, each in a labelled frame, its nodes in columns by how many of the
stage's own nodes lie before them (data flows left to right inside a frame
as between frames), one Group Input per stage showing only the inputs that
stage reads. Positions only: the group computes the same thing."""

COLUMN = 260          # wide enough for an Image Texture node
GAP = 120             # between two frames
ROW_GAP = 30


def _height(n):
    """A node's drawn height, near enough to stack nodes without overlap."""
    shown = sum(1 for s in n.outputs if s.enabled and not s.hide)
    shown += sum(1 for s in n.inputs if s.enabled and not s.hide)
    extra = 150 if n.bl_idname == "ShaderNodeTexImage" else 30 * (n.bl_idname in ("ShaderNodeMath",
                                                                                   "ShaderNodeVectorMath"))
    return 40 + 22 * shown + extra


def _depths(nodes):
    """node name -> its column in the stage: the longest chain of the
    stage's own nodes feeding it."""
    names = {n.name for n in nodes}
    depth = {}

    def visit(n):
        if n.name not in depth:
            depth[n.name] = 0      # a cycle cannot occur in a shader tree
            d = 0
            for s in n.inputs:
                for link in s.links:
                    if link.from_node.name in names:
                        d = max(d, visit(link.from_node) + 1)
            depth[n.name] = d
        return depth[n.name]

    for n in nodes:
        visit(n)
    return depth


def _hide_unused_inputs(tree):
    for n in tree.nodes:
        if n.bl_idname == "NodeGroupInput":
            for s in n.outputs:
                if not s.is_linked:
                    s.hide = True


def _place_stage(tree, nodes, x0, frame):
    depth = _depths(nodes)
    tops = {}
    for n in nodes:                  # creation order within a column
        d = depth[n.name]
        n.location = (x0 + d * COLUMN, tops.get(d, 0.0))
        tops[d] = tops.get(d, 0.0) - _height(n) - ROW_GAP
        if frame is not None:
            n.parent = frame
    return x0 + (max(depth.values()) + 1) * COLUMN


def arrange(tree, stage_of, stages):
    """stage_of: node name -> stage title (None: outside every frame, the
    Group Output); stages: the titles in their left-to-right order."""
    _hide_unused_inputs(tree)
    by_stage = {}
    for n in tree.nodes:
        by_stage.setdefault(stage_of.get(n.name), []).append(n)
    x = 0.0
    for title in stages:
        nodes = by_stage.get(title)
        if not nodes:
            continue
        frame = tree.nodes.new("NodeFrame")
        frame.label = frame.name = title
        frame.label_size = 28
        frame.shrink = True
        frame.location = (0.0, 0.0)  # children's locations are relative to it in every version
        x = _place_stage(tree, nodes, x, frame) + GAP
    _place_stage(tree, by_stage.get(None, []), x, None)
    for n in tree.nodes:
        n.select = False
