"""The "Soak Wet" node group and its insertion in front of a Principled BSDF.

The group evaluates, with native nodes only:
  L      = Wetness * min(Wet Map / Puddle Level, 1) * P,  P = clamp((Time - Start Time) / Fill Time)
           (1 - P when Drying; P = 1 unless Schedule), wetness.h step 1;
  colour = the core's wetness function for any dry colour, looked up per
           channel in the exported float image (bilinear between pixel
           centres, as the core's writer tested);
  rough  = Roughness * R(L) / R(0), R the preset's exported roughness;
  coat   = the film coverage (coat / clearcoat weight);
  sheet  = the thin-sheet transmittance (a Translucent BSDF added);
  normal = a bump from the wet map at spill edges (Spill Edge strength)."""

import json

import bpy

from . import compat, data

GROUP_TAG = "soak_group"
NODE_TAG = "soak_node"
RESTORE_KEY = "soak_restore"

# name, kind, default, min, max
INPUTS = (
    ("Base Color", "color", (0.8, 0.8, 0.8, 1.0), None, None),
    ("Roughness", "factor", 0.5, 0.0, 1.0),
    ("Wetness", "factor", 1.0, 0.0, 1.0),
    ("Wet Map", "factor", 1.0, 0.0, 1.0),
    ("Puddle Level", "factor", 1.0, 0.0, 1.0),
    ("Schedule", "factor", 0.0, 0.0, 1.0),
    ("Drying", "factor", 0.0, 0.0, 1.0),
    ("Time", "float", 1.0, -1e9, 1e9),
    ("Start Time", "float", 0.0, -1e9, 1e9),
    ("Fill Time", "float", 1.0, 0.0, 1e9),
    ("Spill Edge", "float", 0.0, 0.0, 10.0),
    ("Normal", "vector", None, None, None),
)
OUTPUTS = (("Base Color", "color"), ("Roughness", "float"), ("Coat Weight", "float"),
           ("Translucency", "color"), ("Normal", "vector"), ("Liquid", "float"))


class _Builder:
    def __init__(self, tree):
        self.tree = tree
        self.x = 0

    def node(self, kind, **props):
        n = self.tree.nodes.new(kind)
        for k, v in props.items():
            setattr(n, k, v)
        n.location = (self.x, 0)
        self.x += 40
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


def _liquid_schedule(b, gin):
    """L = Wetness * Wet Map * mix(1, P or 1 - P, Schedule)."""
    dt = b.math("SUBTRACT", gin.outputs["Time"], gin.outputs["Start Time"])
    fill = b.math("MAXIMUM", gin.outputs["Fill Time"], 1e-9)
    p = b.math("DIVIDE", dt, fill, clamp=True)
    dry = b.math("MULTIPLY_ADD", p, -2.0, 1.0)          # 1 - 2P
    p = b.math("MULTIPLY_ADD", dry, gin.outputs["Drying"], p)  # P + D (1 - 2P)
    one_minus = b.math("SUBTRACT", 1.0, p)
    p = b.math("MULTIPLY_ADD", one_minus, b.math("SUBTRACT", 1.0, gin.outputs["Schedule"]), p)
    # Puddle Level: wet-map values at or above it count as fully wet (standing
    # water: the core's film at full coverage); 1 leaves the map as it is.
    level = b.math("MAXIMUM", gin.outputs["Puddle Level"], 1e-3)
    wet_map = b.math("DIVIDE", gin.outputs["Wet Map"], level, clamp=True)
    w = b.math("MULTIPLY", gin.outputs["Wetness"], wet_map, clamp=True)
    return b.math("MULTIPLY", w, p, clamp=True)


def _row_coordinate(b, L, t):
    """Texture v of the row for liquid L (layout of soak_data.json)."""
    n1, n2, ws = t["rows_below"], t["rows_above"], t["saturation"]
    rows = n1 + n2 + 1
    above = b.math("DIVIDE", b.math("SUBTRACT", L, ws), max(1.0 - ws, 1e-9), clamp=True)
    r = b.math("MULTIPLY", above, float(n2))
    if n1 > 0:
        q = b.math("SQRT", b.math("DIVIDE", L, ws, clamp=True))
        r = b.math("MULTIPLY_ADD", q, float(n1), r)
    return b.math("MULTIPLY_ADD", r, 1.0 / rows, 0.5 / rows)


def _lookup(b, image, u, v, interpolation):
    xyz = b.node("ShaderNodeCombineXYZ")
    for i, c in enumerate((u, v)):
        if isinstance(c, float):
            xyz.inputs[i].default_value = c
        else:
            b.link(c, xyz.inputs[i])
    tex = b.node("ShaderNodeTexImage", image=image, interpolation=interpolation, extension="EXTEND")
    b.link(xyz.outputs[0], tex.inputs["Vector"])
    return tex.outputs["Color"]


def _lerp(b, a, c, f):
    d = b.node("ShaderNodeVectorMath", operation="SUBTRACT")
    b.link(c, d.inputs[0])
    b.link(a, d.inputs[1])
    m = b.node("ShaderNodeVectorMath", operation="MULTIPLY_ADD")
    b.link(d.outputs[0], m.inputs[0])
    b.link(f, m.inputs[1])
    b.link(a, m.inputs[2])
    return m.outputs[0]


def _texel_pair(b, coord, size):
    """Centres of the two texels around coord (texture space) and the weight."""
    x = b.math("MULTIPLY_ADD", coord, float(size), -0.5)
    x0 = b.math("FLOOR", x)
    f = b.math("SUBTRACT", x, x0)
    c0 = b.math("MULTIPLY_ADD", x0, 1.0 / size, 0.5 / size)
    c1 = b.math("ADD", c0, 1.0 / size)
    return c0, c1, f


def _sample(b, image, u, v, exact=False):
    """Image lookup at (u, v) split into channels. exact: bilinear between
    texel centres from four Closest lookups (EEVEE's Linear filter is not
    the plain bilinear one the core's tables were refined for)."""
    if not exact:
        sep = b.node("ShaderNodeSeparateColor")
        b.link(_lookup(b, image, u, v, "Linear"), sep.inputs[0])
        return sep
    w, h = image.size
    if isinstance(u, float):
        us = (u, u, 0.0)
        uf = b.math("MULTIPLY", 0.0, 0.0)
    else:
        us = _texel_pair(b, u, w)
        uf = us[2]
    v0, v1, vf = _texel_pair(b, v, h)
    rows = []
    for vv in (v0, v1):
        a = _lookup(b, image, us[0], vv, "Closest")
        c = _lookup(b, image, us[1], vv, "Closest")
        rows.append(_lerp(b, a, c, uf))
    sep = b.node("ShaderNodeSeparateXYZ")
    b.link(_lerp(b, rows[0], rows[1], vf), sep.inputs[0])
    return sep


def build_group(tree, preset, liquid_name, exact=False):
    """(Re)builds the inside of a Soak Wet group for a preset and liquid."""
    t = data.table(preset, liquid_name)
    m = data.material(preset)
    alb_img, par_img = data.lookup_images(preset, liquid_name)
    tree.nodes.clear()
    compat.clear_sockets(tree)
    for name, kind, default, lo, hi in INPUTS:
        compat.new_socket(tree, name, "INPUT", kind, default, lo, hi)
    for name, kind in OUTPUTS:
        compat.new_socket(tree, name, "OUTPUT", kind)
    tree[GROUP_TAG] = json.dumps({"preset": preset, "liquid": liquid_name, "exact": bool(exact)})
    b = _Builder(tree)
    gin = b.node("NodeGroupInput")
    gout = b.node("NodeGroupOutput")
    L = _liquid_schedule(b, gin)
    v = _row_coordinate(b, L, t)
    # per channel: column of the dry value a, s = 1 - sqrt(1 - a)
    na = t["columns"]
    sep_in = b.node("ShaderNodeSeparateColor")
    b.link(gin.outputs["Base Color"], sep_in.inputs[0])
    comb = b.node("ShaderNodeCombineColor")
    for c in range(3):
        a = b.math("MINIMUM", b.math("MAXIMUM", sep_in.outputs[c], 0.0), 1.0)
        s = b.math("SUBTRACT", 1.0, b.math("SQRT", b.math("SUBTRACT", 1.0, a)))
        u = b.math("MULTIPLY_ADD", s, (na - 1) / na, 0.5 / na)
        b.link(_sample(b, alb_img, u, v, exact).outputs[c], comb.inputs[c])
    b.link(comb.outputs[0], gout.inputs["Base Color"])
    par = _sample(b, par_img, 0.5 / 3.0, v, exact)
    r0 = max(t["params"][0][0], 1e-4)
    rough = b.math("MULTIPLY", gin.outputs["Roughness"], b.math("DIVIDE", par.outputs[0], r0), clamp=True)
    b.link(rough, gout.inputs["Roughness"])
    b.link(par.outputs[1], gout.inputs["Coat Weight"])
    b.link(L, gout.inputs["Liquid"])
    if m["kind"] == "thin_sheet":
        sheet = _sample(b, par_img, 2.5 / 3.0, v, exact)
        tc = b.node("ShaderNodeCombineColor")
        for c in range(3):
            b.link(sheet.outputs[c], tc.inputs[c])
        b.link(tc.outputs[0], gout.inputs["Translucency"])
    bump = b.node("ShaderNodeBump")
    b.link(gin.outputs["Spill Edge"], bump.inputs["Strength"])
    b.link(gin.outputs["Wet Map"], bump.inputs["Height"])
    bump.inputs["Distance"].default_value = 0.02
    b.link(gin.outputs["Normal"], bump.inputs["Normal"])
    b.link(bump.outputs["Normal"], gout.inputs["Normal"])
    return tree


# ---- insertion and exact removal --------------------------------------------

def find_principled(tree):
    out = None
    for n in tree.nodes:
        if n.type == "OUTPUT_MATERIAL" and n.is_active_output:
            out = n
    if out is not None and out.inputs["Surface"].is_linked:
        n = out.inputs["Surface"].links[0].from_node
        if n.type == "BSDF_PRINCIPLED":
            return n
    for n in tree.nodes:
        if n.type == "BSDF_PRINCIPLED" and not n.get(NODE_TAG):
            return n
    return None


def find_group_node(tree):
    for n in tree.nodes:
        if n.get(NODE_TAG) and n.type == "GROUP":
            return n
    return None


def _value(sock):
    v = getattr(sock, "default_value", None)
    if v is None:
        return None
    try:
        return list(v)
    except TypeError:
        return v


def _record(sock):
    return {"links": [[l.from_node.name, l.from_socket.identifier] for l in sock.links], "value": _value(sock)}


def _touched_roles():
    return ("base_color", "roughness", "coat_weight", "coat_roughness", "coat_ior", "normal", "coat_normal")


def _out_socket(node, identifier):
    for s in node.outputs:
        if s.identifier == identifier:
            return s
    return None


def make_wet(mat, settings):
    """Inserts the group; returns the group node. Raises RuntimeError."""
    tree = mat.node_tree
    if tree is None:
        raise RuntimeError(f"material '{mat.name}' does not use nodes")
    if find_group_node(tree) is not None:
        raise RuntimeError(f"material '{mat.name}' is already wet (Make Dry first)")
    bsdf = find_principled(tree)
    if bsdf is None:
        raise RuntimeError(f"material '{mat.name}' has no Principled BSDF")
    restore = {"bsdf": bsdf.name, "inputs": {}, "bsdf_out": [], "nodes": []}
    for role in _touched_roles():
        s = compat.principled_input(bsdf, role)
        if s is not None:
            restore["inputs"][s.identifier] = _record(s)
    restore["bsdf_out"] = [[l.to_node.name, l.to_socket.identifier] for l in bsdf.outputs[0].links]

    ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
    build_group(ng, settings.preset, settings.liquid, settings.exact_lookups)
    gn = tree.nodes.new("ShaderNodeGroup")
    gn.node_tree = ng
    gn.name = gn.label = "Soak Wet"
    gn[NODE_TAG] = True
    gn.location = (bsdf.location.x - 260, bsdf.location.y)
    links = tree.links
    m = data.material(settings.preset)
    t = data.table(settings.preset, settings.liquid)
    bc, rough = compat.principled_input(bsdf, "base_color"), compat.principled_input(bsdf, "roughness")
    if settings.colour_source == "MATERIAL":
        if bc.is_linked:
            links.new(bc.links[0].from_socket, gn.inputs["Base Color"])
        else:
            gn.inputs["Base Color"].default_value = bc.default_value
        if rough.is_linked:
            links.new(rough.links[0].from_socket, gn.inputs["Roughness"])
        else:
            gn.inputs["Roughness"].default_value = rough.default_value
    else:
        gn.inputs["Base Color"].default_value = list(m["dry_albedo"]) + [1.0]
        gn.inputs["Roughness"].default_value = t["params"][0][0]
    nrm = compat.principled_input(bsdf, "normal")
    if nrm.is_linked:
        links.new(nrm.links[0].from_socket, gn.inputs["Normal"])
    gn.inputs["Wetness"].default_value = settings.wetness
    gn.inputs["Fill Time"].default_value = m["t_fill"]
    links.new(gn.outputs["Base Color"], bc)
    links.new(gn.outputs["Roughness"], rough)
    links.new(gn.outputs["Coat Weight"], compat.principled_input(bsdf, "coat_weight"))
    links.new(gn.outputs["Normal"], nrm)
    cn = compat.principled_input(bsdf, "coat_normal")
    if cn is not None:
        links.new(gn.outputs["Normal"], cn)
    compat.principled_input(bsdf, "coat_roughness").default_value = 0.0
    cior = compat.principled_input(bsdf, "coat_ior")
    if cior is not None:
        cior.default_value = data.liquid(settings.liquid)["ior"]
    extra = _wire_source(tree, gn, settings)
    if m["kind"] == "thin_sheet" and bsdf.outputs[0].is_linked:
        extra += _add_translucency(tree, gn, bsdf)
    restore["nodes"] = [n.name for n in extra]
    gn[RESTORE_KEY] = json.dumps(restore)
    return gn


def _tag(n):
    n[NODE_TAG] = True
    return n


def _wire_source(tree, gn, settings):
    src = settings.wetness_source
    made = []
    if src == "IMAGE":
        if settings.wet_map is None:
            raise RuntimeError("wetness source 'Image' needs an image")
        n = _tag(tree.nodes.new("ShaderNodeTexImage"))
        n.image = settings.wet_map
        n.image.colorspace_settings.name = "Non-Color"
        n.extension = "EXTEND"
        tree.links.new(n.outputs["Color"], gn.inputs["Wet Map"])
        made.append(n)
    elif src == "ATTRIBUTE":
        n = _tag(tree.nodes.new("ShaderNodeAttribute"))
        n.attribute_name = settings.attribute_name
        tree.links.new(n.outputs["Fac"], gn.inputs["Wet Map"])
        made.append(n)
    elif src == "NOISE":
        n = _tag(tree.nodes.new("ShaderNodeTexNoise"))
        n.inputs["Scale"].default_value = settings.noise_scale
        r = _tag(tree.nodes.new("ShaderNodeMapRange"))
        r.clamp = True
        r.inputs["From Min"].default_value = 0.45
        r.inputs["From Max"].default_value = 0.55
        tree.links.new(n.outputs["Fac"], r.inputs["Value"])
        tree.links.new(r.outputs["Result"], gn.inputs["Wet Map"])
        made += [n, r]
    for i, n in enumerate(made):
        n.location = (gn.location.x - 240 * (len(made) - i), gn.location.y - 200)
    return made


def _add_translucency(tree, gn, bsdf):
    tr = _tag(tree.nodes.new("ShaderNodeBsdfTranslucent"))
    add = _tag(tree.nodes.new("ShaderNodeAddShader"))
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


def make_dry(mat):
    """Removes the group and restores the recorded links and values."""
    tree = mat.node_tree
    gn = find_group_node(tree) if tree else None
    if gn is None:
        raise RuntimeError(f"material '{mat.name}' is not wet")
    restore = json.loads(gn[RESTORE_KEY])
    bsdf = tree.nodes.get(restore["bsdf"])
    if bsdf is None:
        raise RuntimeError(f"the Principled BSDF '{restore['bsdf']}' was removed or renamed")
    ng = gn.node_tree
    for n in [n for n in tree.nodes if n.get(NODE_TAG)]:
        tree.nodes.remove(n)
    if ng is not None and ng.users == 0:
        bpy.data.node_groups.remove(ng)
    by_id = {s.identifier: s for s in bsdf.inputs}
    for ident, rec in restore["inputs"].items():
        s = by_id[ident]
        for l in list(s.links):
            tree.links.remove(l)
        if rec["value"] is not None:
            s.default_value = rec["value"]
        for from_name, from_id in rec["links"]:
            src = _out_socket(tree.nodes[from_name], from_id)
            tree.links.new(src, s)
    for to_name, to_id in restore["bsdf_out"]:
        to = tree.nodes[to_name]
        sock = next(s for s in to.inputs if s.identifier == to_id)
        if not any(l.from_node == bsdf for l in sock.links):
            tree.links.new(bsdf.outputs[0], sock)


def rebuild(mat, settings):
    gn = find_group_node(mat.node_tree) if mat.node_tree else None
    if gn is not None and gn.node_tree is not None:
        keep = {s.name: _value(s) for s in gn.inputs}
        links = [(l.from_socket, l.to_socket.name) for s in gn.inputs for l in s.links]
        build_group(gn.node_tree, settings.preset, settings.liquid, settings.exact_lookups)
        for s in gn.inputs:
            if keep.get(s.name) is not None:
                s.default_value = keep[s.name]
        for src, name in links:
            mat.node_tree.links.new(src, gn.inputs[name])
        m, t = data.material(settings.preset), data.table(settings.preset, settings.liquid)
        if settings.colour_source == "PRESET":
            gn.inputs["Base Color"].default_value = list(m["dry_albedo"]) + [1.0]
            gn.inputs["Roughness"].default_value = t["params"][0][0]
        gn.inputs["Fill Time"].default_value = m["t_fill"]
        bsdf = mat.node_tree.nodes.get(json.loads(gn[RESTORE_KEY])["bsdf"])
        cior = compat.principled_input(bsdf, "coat_ior") if bsdf is not None else None
        if cior is not None:
            cior.default_value = data.liquid(settings.liquid)["ior"]
