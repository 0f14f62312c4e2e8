"""The node-program interpreter: Math and Vector Math nodes for the
programs soak_data.json exports (its "layout" entry: [op, args..., clamp],
an argument a number, an input name or "#i", the result of op i), and the
few node-building primitives the wet group is made of. It derives no
formula: it runs what the core exported."""


# Positions t in [0, 1] are mapped just below 1 onto a table's cells (t = 1
# lies in the last cell, at its far edge).
EDGE = 1.0 - 1e-6


class Builder:
    """Adds nodes to a tree. Each node joins the current stage (a name the
    group's layout gives a labelled frame and a column of its own) and is
    labelled with the current role (what it computes, shown in its header
    instead of its operation's name; a label given to node() wins)."""

    def __init__(self, tree):
        self.tree = tree
        self.stage = None
        self.role = None
        self.stages = {}        # node name -> stage

    def node(self, kind, **props):
        n = self.tree.nodes.new(kind)
        if self.role and "label" not in props:
            n.label = self.role
        for k, v in props.items():
            setattr(n, k, v)
        self.stages[n.name] = self.stage
        return n

    def link(self, a, b):
        self.tree.links.new(a, b)

    def math(self, op, a, b=None, c=None, clamp=False):
        n = self.node("ShaderNodeMath", operation=op, use_clamp=clamp)
        for i, v in enumerate((a, b, c)):
            if v is None:
                continue
            if isinstance(v, (int, float)):
                n.inputs[i].default_value = float(v)
            else:
                self.link(v, n.inputs[i])
        return n.outputs[0]


# as a whole run once for the three channels. SQRT runs as a Gamma node
# (colour ** 0.5 per channel; a negative channel, 1 - x for a colour above 1,
# stays negative where Math's SQRT gives 0: both then map past the table's
# last column, which EXTEND or the clamp below holds there).
_VECTOR_OPS = ("ADD", "SUBTRACT", "MULTIPLY", "DIVIDE", "MULTIPLY_ADD", "MINIMUM", "MAXIMUM", "SQRT")


def _split(op):
    """[op, args..., clamp] -> (op, args, clamp)."""
    return op[0], list(op[1:-1]), bool(op[-1])


def _is_num(a):
    return isinstance(a, (int, float)) and not isinstance(a, bool)


def _uses(ops):
    n = [0] * len(ops)
    for op in ops:
        for a in _split(op)[1]:
            if isinstance(a, str) and a.startswith("#"):
                n[int(a[1:])] += 1
    n[-1] += 1
    return n


def _scale_into(ops, i, k, o, uses):
    """Rewrites op i (used once, unclamped) so it yields result * k + o;
    False when it cannot (the caller appends an operation instead)."""
    op, args, clamp = _split(ops[i])
    if clamp or uses[i] != 1:
        return False
    if op == "MULTIPLY" and _is_num(args[1]):
        ops[i] = ["MULTIPLY_ADD", args[0], args[1] * k, o, False]
        return True
    if op == "MULTIPLY_ADD" and _is_num(args[1]):
        if _is_num(args[2]):
            ops[i] = ["MULTIPLY_ADD", args[0], args[1] * k, args[2] * k + o, False]
            return True
        if isinstance(args[2], str) and args[2].startswith("#") and _scale_into(ops, int(args[2][1:]), k, o, uses):
            ops[i] = ["MULTIPLY_ADD", args[0], args[1] * k, args[2], False]
            return True
    return False


def affine_program(ops, k, o):
    """The program with its output mapped to output * k + o, folded into its
    last operations where they are affine (no extra node), else appended."""
    ops = [list(op) for op in ops]
    if not _scale_into(ops, len(ops) - 1, k, o, _uses(ops)):
        ops.append(["MULTIPLY_ADD", f"#{len(ops) - 1}", k, o, False])
    return ops


def run_program(b, ops, env, results=None):
    """Math nodes for an exported program (layout: soak_data.json); env maps
    input names to sockets or numbers; results: sockets of ops computed
    already (the program runs on from after the last of them); returns the
    output socket."""
    results = dict(results or {})
    start = max(results) + 1 if results else 0
    for i, op in enumerate(ops[start:], start):
        name, args, clamp = _split(op)
        vals = [a if _is_num(a) else (results[int(a[1:])] if a.startswith("#") else env[a]) for a in args]
        results[i] = b.math(name, *vals, clamp=clamp)
    return results[len(ops) - 1]


def _vector_prefix(ops):
    """How many leading ops run on the colour as a vector: unclamped Vector
    Math operations (or SQRT) on x and numbers, a chain the rest reads only
    at its end."""
    n = 0
    for i, op in enumerate(ops):
        name, args, clamp = _split(op)
        ok = name in _VECTOR_OPS and not clamp and all(
            _is_num(a) or a == "x" or a == f"#{i - 1}" for a in args)
        if name == "SQRT":
            ok = ok and not _is_num(args[0])
        if not ok:
            break
        n = i + 1
    while n > 0 and any(a.startswith("#") and int(a[1:]) < n - 1
                        for op in ops[n:] for a in _split(op)[1] if isinstance(a, str)):
        n -= 1
    return n


def _vector_op(b, name, args, v):
    """One op of a program on a whole colour; v: the previous result."""
    if name == "SQRT":
        node = b.node("ShaderNodeGamma")
        node.inputs["Gamma"].default_value = 0.5
        b.link(v, node.inputs["Color"])
        return node.outputs[0]
    node = b.node("ShaderNodeVectorMath", operation=name)
    for i, a in enumerate(args):
        if _is_num(a):
            node.inputs[i].default_value = (float(a),) * 3
        else:
            b.link(v, node.inputs[i])
    return node.outputs[0]


def run_program_vector(b, ops, colour):
    """The program for each channel of a colour, as one vector socket: the
    whole program on the vector where it can run there (the exported column
    programs can), else its remainder per channel, recombined."""
    n = _vector_prefix(ops)
    v = colour
    for op in ops[:n]:
        name, args, _ = _split(op)
        v = _vector_op(b, name, args, v)
    if n == len(ops):
        return v
    sep = b.node("ShaderNodeSeparateXYZ")
    b.link(v, sep.inputs[0])
    comb = b.node("ShaderNodeCombineXYZ")
    for c in range(3):
        b.link(run_program(b, ops, {"x": sep.outputs[c]}, {n - 1: sep.outputs[c]} if n else None), comb.inputs[c])
    return comb.outputs[0]



def lookup(b, image, u, v, interpolation):
    xyz = b.node("ShaderNodeCombineXYZ")
    for i, c in enumerate((u, v)):
        if isinstance(c, float):
            xyz.inputs[i].default_value = c
        else:
            b.link(c, xyz.inputs[i])
    tex = b.node("ShaderNodeTexImage", image=image, interpolation=interpolation, extension="EXTEND")
    b.link(xyz.outputs[0], tex.inputs["Vector"])
    return tex


def vec(b, op, a, c):
    n = b.node("ShaderNodeVectorMath", operation=op)
    b.link(a, n.inputs[0])
    b.link(c, n.inputs[1])
    return n.outputs[0]



def separate(b, v):
    sep = b.node("ShaderNodeSeparateXYZ")
    b.link(v, sep.inputs[0])
    return sep.outputs


def combine(b, x, y, z):
    comb = b.node("ShaderNodeCombineXYZ")
    for i, c in enumerate((x, y, z)):
        if isinstance(c, (int, float)):
            comb.inputs[i].default_value = float(c)
        else:
            b.link(c, comb.inputs[i])
    return comb.outputs[0]


def vec_num(b, op, a, k, c=None):
    """Vector Math op on socket a with numbers k (and c) for every channel."""
    n = b.node("ShaderNodeVectorMath", operation=op)
    b.link(a, n.inputs[0])
    n.inputs[1].default_value = (float(k),) * 3
    if c is not None:
        n.inputs[2].default_value = (float(c),) * 3
    return n.outputs[0]



def lerp(b, a, c, f):
    """a + (c - a) f for vector sockets a, c and a float socket f."""
    m = b.node("ShaderNodeVectorMath", operation="MULTIPLY_ADD")
    b.link(vec(b, "SUBTRACT", c, a), m.inputs[0])
    b.link(f, m.inputs[1])
    b.link(a, m.inputs[2])
    return m.outputs[0]
