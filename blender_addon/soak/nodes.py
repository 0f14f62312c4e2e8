"""The "Soak Wet" node group and its insertion in front of a Principled BSDF.

The group evaluates, with native nodes only:
  L      = Wetness * min(Wet Map / Puddle Level, 1) * P,  P = clamp((Time - Start Time) / Fill Time)
           (1 - P when Drying; P = 1 unless Schedule), wetness.h step 1;
  colour = the core's wetness function for any dry colour, looked up per
           channel in the exported float image (bilinear between pixel
           centres, as the core's writer tested);
  rough  = Roughness * R(L) / R(0), R the preset's exported (apparent) roughness;
  coat   = the liquid's mirror: film plus water-filled pores (coat / clearcoat weight);
  spec   = Specular * the base's own specular left under the liquid
           (soak/wet_specular.h, exported; replaces the dry lobe);
  metal  = a Metallic material's metallic part gets a conductor preset's
           function (metal under the film), mixed by Metallic;
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
    # appended (keyframes address the inputs by index): the Principled's own
    # specular (3.x Specular / 4.x Specular IOR Level) and metallic amount
    ("Specular", "float", 0.5, 0.0, 100.0),
    ("Metallic", "factor", 0.0, 0.0, 1.0),
)
OUTPUTS = (("Base Color", "color"), ("Roughness", "float"), ("Coat Weight", "float"),
           ("Translucency", "color"), ("Normal", "vector"), ("Liquid", "float"), ("Specular", "float"))


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
    v0, v1, vf = _texel_pair(b, v, h)
    rows = []
    if isinstance(u, float):  # a column's centre: one read per row
        rows = [_lookup(b, image, u, vv, "Closest") for vv in (v0, v1)]
    else:
        us = _texel_pair(b, u, w)
        for vv in (v0, v1):
            a = _lookup(b, image, us[0], vv, "Closest")
            c = _lookup(b, image, us[1], vv, "Closest")
            rows.append(_lerp(b, a, c, us[2]))
    sep = b.node("ShaderNodeSeparateXYZ")
    b.link(_lerp(b, rows[0], rows[1], vf), sep.inputs[0])
    return sep


def _sockets_match(tree):
    """True when the group already has exactly INPUTS and OUTPUTS (then a
    rebuild keeps them, and with them the group node's links and values)."""
    if hasattr(tree, "interface"):
        items = [i for i in tree.interface.items_tree if getattr(i, "item_type", "SOCKET") == "SOCKET"]
        ins = [i.name for i in items if i.in_out == "INPUT"]
        outs = [i.name for i in items if i.in_out == "OUTPUT"]
    else:
        ins, outs = [s.name for s in tree.inputs], [s.name for s in tree.outputs]
    return ins == [i[0] for i in INPUTS] and outs == [o[0] for o in OUTPUTS]


def _param(b, par_img, t, v, exact, pixel):
    """Pixel `pixel` of the per-row parameter image (layout: soak_data.json)."""
    n = len(t["params"][0]) // 3
    return _sample(b, par_img, (pixel + 0.5) / n, v, exact)


def _wet_path(b, gin, L, preset, liquid_name, exact):
    """The core's wetness function of one preset's class for the input colour:
    (colour, roughness, coat weight, base specular factor) sockets, and
    (parameter image, table, row coordinate) for further parameter reads."""
    t = data.table(preset, liquid_name)
    alb_img, par_img = data.lookup_images(preset, liquid_name)
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
    spec = _param(b, par_img, t, v, exact, 3)  # (base specular factor, interface area, apparent roughness)
    r0 = max(t["params"][0][11], 1e-4)
    rough = b.math("MULTIPLY", gin.outputs["Roughness"], b.math("DIVIDE", spec.outputs[2], r0), clamp=True)
    return comb.outputs[0], rough, spec.outputs[1], spec.outputs[0], (par_img, t, v)


def build_group(tree, preset, liquid_name, exact=False, metal=None):
    """(Re)builds the inside of a Soak Wet group for a preset and liquid.
    metal: a conductor preset whose function the metallic part of the
    material gets (mixed by the Metallic input), None for none. Sockets that
    already match INPUTS/OUTPUTS are kept (the node's links and values too)."""
    m = data.material(preset)
    if metal is not None and data.material(metal)["kind"] != "conductor":
        raise data.SoakDataError(f"'{metal}' is not a conductor preset")
    tree.nodes.clear()
    if not _sockets_match(tree):
        compat.clear_sockets(tree)
        for name, kind, default, lo, hi in INPUTS:
            compat.new_socket(tree, name, "INPUT", kind, default, lo, hi)
        for name, kind in OUTPUTS:
            compat.new_socket(tree, name, "OUTPUT", kind)
    tree[GROUP_TAG] = json.dumps({"preset": preset, "liquid": liquid_name, "exact": bool(exact), "metal": metal})
    exact = bool(exact) or compat.exact_lookups_required()
    b = _Builder(tree)
    gin = b.node("NodeGroupInput")
    gout = b.node("NodeGroupOutput")
    L = _liquid_schedule(b, gin)
    colour, rough, coat, factor, (par_img, t, v) = _wet_path(b, gin, L, preset, liquid_name, exact)
    if metal is not None:
        mc, mr, mcoat, _, _ = _wet_path(b, gin, L, metal, liquid_name, exact)
        f = b.math("MINIMUM", b.math("MAXIMUM", gin.outputs["Metallic"], 0.0), 1.0)
        colour = _lerp(b, colour, mc, f)
        rough = b.math("MULTIPLY_ADD", b.math("SUBTRACT", mr, rough), f, rough)
        coat = b.math("MULTIPLY_ADD", b.math("SUBTRACT", mcoat, coat), f, coat)
    bump = b.node("ShaderNodeBump")
    b.link(gin.outputs["Spill Edge"], bump.inputs["Strength"])
    b.link(gin.outputs["Wet Map"], bump.inputs["Height"])
    bump.inputs["Distance"].default_value = 0.02
    b.link(gin.outputs["Normal"], bump.inputs["Normal"])
    spec = b.math("MULTIPLY", gin.outputs["Specular"], factor)
    # Blender's own coat dims what lies under it (4.x); the core's values
    # already hold the film's transmission: undo the engine's share.
    keep = compat.coat_base_compensation(b, coat, data.liquid(liquid_name)["ior"], bump.outputs["Normal"])
    if keep is not None:
        sc = b.node("ShaderNodeVectorMath", operation="SCALE")
        b.link(colour, sc.inputs[0])
        b.link(keep, sc.inputs["Scale"])
        colour = sc.outputs[0]
        spec = b.math("MULTIPLY", spec, keep)
    b.link(colour, gout.inputs["Base Color"])
    b.link(rough, gout.inputs["Roughness"])
    b.link(coat, gout.inputs["Coat Weight"])
    b.link(spec, gout.inputs["Specular"])
    b.link(L, gout.inputs["Liquid"])
    if m["kind"] == "thin_sheet":
        sheet = _param(b, par_img, t, v, exact, 2)
        tc = b.node("ShaderNodeCombineColor")
        for c in range(3):
            b.link(sheet.outputs[c], tc.inputs[c])
        b.link(tc.outputs[0], gout.inputs["Translucency"])
    b.link(bump.outputs["Normal"], gout.inputs["Normal"])
    return tree


def metal_preset(bsdf, gn, preset):
    """The conductor preset for the metallic part of a Principled BSDF, or
    None: Metallic neither linked nor above 0, or the preset is a metal
    already. The conductor nearest in colour to the dry base colour (the
    group's input once wet); the first conductor when the colour is a texture."""
    met = compat.principled_input(bsdf, "metallic")
    if met is None or data.material(preset)["kind"] == "conductor":
        return None
    if not met.is_linked and not met.default_value > 0.0:
        return None
    conductors = [x for x in data.load()["materials"] if x["kind"] == "conductor"]
    if not conductors:
        return None
    bc = compat.principled_input(bsdf, "base_color")
    if bc.is_linked and gn is not None and bc.links[0].from_node == gn:
        bc = gn.inputs["Base Color"]
    if bc.is_linked:
        return conductors[0]["name"]
    col = list(bc.default_value)[:3]
    return min(conductors, key=lambda x: sum((p - q) ** 2 for p, q in zip(x["dry_albedo"], col)))["name"]


# ---- insertion and exact removal --------------------------------------------
#
# Every change below is all-or-nothing: everything that can be checked is
# checked before the tree is touched (check_wettable), and the rest runs under
# a _Snapshot that puts the material's tree back as it was on any exception.

ROLE_KEY = "soak_role"          # on tagged nodes: "source" | "translucency"
REF_KEY = "soak_ref"            # on the user's nodes a restore record names (survives renames)
SOURCE_TYPES = ("ShaderNodeTexImage", "ShaderNodeAttribute", "ShaderNodeTexNoise", "ShaderNodeMapRange")
_REQUIRED_ROLES = ("base_color", "roughness", "coat_weight", "coat_roughness", "normal")


def _is_principled(n):
    return n.type == "BSDF_PRINCIPLED" and not n.get(NODE_TAG)


def _active_output(tree):
    out = None
    for n in tree.nodes:
        if n.type == "OUTPUT_MATERIAL" and (out is None or n.is_active_output):
            out = n
    return out


def principled_nodes(tree):
    """Every (untagged) Principled BSDF: those feeding the active output first,
    in depth-first order through Mix/Add shaders and groups' inputs, then the
    others."""
    seen, order = set(), []

    def visit(node):
        if node.name in seen:
            return
        seen.add(node.name)
        if _is_principled(node):
            order.append(node)
            return
        for s in node.inputs:
            for link in s.links:
                visit(link.from_node)

    out = _active_output(tree)
    if out is not None:
        visit(out)
    order += [n for n in tree.nodes if _is_principled(n) and n not in order]
    return order


def find_principled(tree):
    nodes_ = principled_nodes(tree)
    return nodes_[0] if nodes_ else None


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


def _out_socket(node, identifier):
    for s in node.outputs:
        if s.identifier == identifier:
            return s
    return None


def _in_socket(node, identifier):
    for s in node.inputs:
        if s.identifier == identifier:
            return s
    return None


def check_editable(mat):
    """Raises RuntimeError for a material whose node tree may not be edited."""
    if mat.library is not None:
        raise RuntimeError(f"material '{mat.name}' is linked from the library '{mat.library.filepath}': "
                           "its changes would be lost on reload; make it local first "
                           "(Object > Relations > Make Local)")
    if getattr(mat, "override_library", None) is not None:
        raise RuntimeError(f"material '{mat.name}' is a library override: its node tree cannot be edited; "
                           "make it local first (Object > Relations > Make Local)")
    if mat.node_tree is None or not mat.use_nodes:
        raise RuntimeError(f"material '{mat.name}' does not use nodes")


def check_source(settings):
    src = settings.wetness_source
    if src == "IMAGE" and settings.wet_map is None:
        raise RuntimeError("wetness source 'Image' needs an image (choose one or bake a wet map)")
    if src == "ATTRIBUTE" and not settings.attribute_name.strip():
        raise RuntimeError("wetness source 'Attribute' needs an attribute name (e.g. dp_wetmap)")


def check_data(settings):
    """The core's data for the settings (raises SoakDataError)."""
    data.material(settings.preset)
    data.table(settings.preset, settings.liquid)
    data.liquid(settings.liquid)


def check_wettable(mat, settings):
    """Everything Make Wet needs, checked before the tree is touched.
    Returns the Principled BSDF to wet and the other Principled BSDFs."""
    check_editable(mat)
    tree = mat.node_tree
    if find_group_node(tree) is not None:
        raise RuntimeError(f"material '{mat.name}' is already wet (Make Dry first)")
    bsdfs = principled_nodes(tree)
    if not bsdfs:
        raise RuntimeError(f"material '{mat.name}' has no Principled BSDF")
    bsdf = bsdfs[0]
    active = tree.nodes.active
    if len(bsdfs) > 1 and active is not None and _is_principled(active):
        bsdf = active          # the user picked one in the Shader Editor
    missing = [compat.principled_name(r) for r in _REQUIRED_ROLES if compat.principled_input(bsdf, r) is None]
    if missing:
        raise RuntimeError(f"'{bsdf.name}' lacks the inputs {', '.join(missing)}")
    check_data(settings)
    check_source(settings)
    return bsdf, [n for n in bsdfs if n != bsdf]


def _link_key(link):
    return (link.from_node.name, link.from_socket.identifier, link.to_node.name, link.to_socket.identifier)


class _Snapshot:
    """The state of a material's tree (nodes, links, input values) and of the
    node-group list, to put back after a failed change."""

    def __init__(self, tree):
        self.tree = tree
        self.names = {n.name for n in tree.nodes}
        self.links = {_link_key(l) for l in tree.links}
        self.values = {(n.name, s.identifier): _value(s) for n in tree.nodes for s in n.inputs}
        self.groups = {g.name for g in bpy.data.node_groups}
        self.refs = {n.name: n.get(REF_KEY) for n in tree.nodes}

    def restore(self):
        t = self.tree
        for n in [n for n in t.nodes if n.name not in self.names]:
            t.nodes.remove(n)
        for l in [l for l in t.links if _link_key(l) not in self.links]:
            t.links.remove(l)
        have = {_link_key(l) for l in t.links}
        for fn, fs, tn, ts in self.links - have:
            a, b = t.nodes.get(fn), t.nodes.get(tn)
            src, dst = a and _out_socket(a, fs), b and _in_socket(b, ts)
            if src is not None and dst is not None:
                t.links.new(src, dst)
        for (name, ident), v in self.values.items():
            n = t.nodes.get(name)
            s = n and _in_socket(n, ident)
            if s is not None and v is not None and _value(s) != v:
                s.default_value = v
        for name, ref in self.refs.items():
            n = t.nodes.get(name)
            if n is not None and n.get(REF_KEY) != ref:
                if ref is None:
                    del n[REF_KEY]
                else:
                    n[REF_KEY] = ref
        for g in [g for g in bpy.data.node_groups if g.name not in self.groups and g.users == 0]:
            bpy.data.node_groups.remove(g)


def _atomic(tree, fn, *args):
    snap = _Snapshot(tree)
    try:
        return fn(*args)
    except BaseException:
        snap.restore()
        raise


def _bsdf_state(bsdf):
    return {s.identifier: _record(s) for s in bsdf.inputs}


def _note_changes(restore, before, bsdf):
    """Adds to the restore record every BSDF input whose links or value the
    change made differ from `before` (first record wins: the dry state)."""
    for s in bsdf.inputs:
        rec = before.get(s.identifier)
        if rec is not None and s.identifier not in restore["inputs"] and _record(s) != rec:
            restore["inputs"][s.identifier] = rec


def _group_defaults(gn, settings, tree, bsdf):
    m = data.material(settings.preset)
    t = data.table(settings.preset, settings.liquid)
    if settings.colour_source == "MATERIAL":
        for role, name in (("base_color", "Base Color"), ("roughness", "Roughness")):
            s = compat.principled_input(bsdf, role)
            if s.is_linked:
                tree.links.new(s.links[0].from_socket, gn.inputs[name])
            else:
                gn.inputs[name].default_value = s.default_value
    else:
        gn.inputs["Base Color"].default_value = list(m["dry_albedo"]) + [1.0]
        gn.inputs["Roughness"].default_value = t["params"][0][0]
    nrm = compat.principled_input(bsdf, "normal")
    if nrm.is_linked:
        tree.links.new(nrm.links[0].from_socket, gn.inputs["Normal"])
    gn.inputs["Wetness"].default_value = settings.wetness
    gn.inputs["Fill Time"].default_value = m["t_fill"]


def connect_outputs(tree, gn, bsdf, settings):
    """Wires the group's outputs into the Principled BSDF and sets the BSDF
    inputs the wet state fixes. Called by make_wet and rebuild (idempotent);
    every BSDF input it changes is restored by make_dry."""
    links = tree.links
    links.new(gn.outputs["Base Color"], compat.principled_input(bsdf, "base_color"))
    links.new(gn.outputs["Roughness"], compat.principled_input(bsdf, "roughness"))
    links.new(gn.outputs["Coat Weight"], compat.principled_input(bsdf, "coat_weight"))
    links.new(gn.outputs["Normal"], compat.principled_input(bsdf, "normal"))
    cn = compat.principled_input(bsdf, "coat_normal")
    if cn is not None:
        links.new(gn.outputs["Normal"], cn)
    compat.principled_input(bsdf, "coat_roughness").default_value = 0.0
    cior = compat.principled_input(bsdf, "coat_ior")
    if cior is not None:
        cior.default_value = data.liquid(settings.liquid)["ior"]
    _connect_specular_metal(tree, gn, bsdf, settings)


def _connect_specular_metal(tree, gn, bsdf, settings):
    """The base's own specular through the group (replaced by what is left of
    it under the liquid), the Metallic amount into the group (rebuilt with a
    conductor's function where the material is metallic), Coat Tint white
    (4.x: the liquid's absorption is in the core's colours already)."""
    want = metal_preset(bsdf, gn, settings.preset)
    info = json.loads(gn.node_tree.get(GROUP_TAG, "{}"))
    if info.get("metal") != want:
        build_group(gn.node_tree, settings.preset, settings.liquid, settings.exact_lookups, metal=want)
    for role, name in (("specular", "Specular"), ("metallic", "Metallic")):
        s = compat.principled_input(bsdf, role)
        if s.is_linked and s.links[0].from_node == gn:
            continue
        if s.is_linked:
            tree.links.new(s.links[0].from_socket, gn.inputs[name])
        else:
            for l in list(gn.inputs[name].links):
                tree.links.remove(l)
            gn.inputs[name].default_value = s.default_value
    tree.links.new(gn.outputs["Specular"], compat.principled_input(bsdf, "specular"))
    tint = compat.principled_input(bsdf, "coat_tint")
    if tint is not None:
        tint.default_value = (1.0, 1.0, 1.0, 1.0)


def _set_ref(n, key):
    n[REF_KEY] = key
    return key


def _refs(tree, restore):
    """Marks the user's nodes the record names, so Make Dry finds them renamed."""
    names = {restore["bsdf"]}
    names.update(fn for rec in restore["inputs"].values() for fn, _ in rec["links"])
    names.update(tn for tn, _ in restore["bsdf_out"])
    for name in names:
        n = tree.nodes.get(name)
        if n is not None and not n.get(NODE_TAG):
            _set_ref(n, name)


def _insert(mat, bsdf, settings):
    tree = mat.node_tree
    before = _bsdf_state(bsdf)
    restore = {"bsdf": bsdf.name, "inputs": {}, "nodes": [],
               "bsdf_out": [[l.to_node.name, l.to_socket.identifier] for l in bsdf.outputs[0].links]}
    ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
    build_group(ng, settings.preset, settings.liquid, settings.exact_lookups)
    gn = tree.nodes.new("ShaderNodeGroup")
    gn.node_tree = ng
    gn.name = gn.label = "Soak Wet"
    gn[NODE_TAG] = True
    gn.location = (bsdf.location.x - 260, bsdf.location.y)
    _group_defaults(gn, settings, tree, bsdf)
    connect_outputs(tree, gn, bsdf, settings)
    made = _wire_source(tree, gn, settings)
    if data.material(settings.preset)["kind"] == "thin_sheet" and bsdf.outputs[0].is_linked:
        made += _add_translucency(tree, gn, bsdf)
    _note_changes(restore, before, bsdf)
    restore["nodes"] = [n.name for n in made]
    _refs(tree, restore)
    gn[RESTORE_KEY] = json.dumps(restore)
    return gn


def make_wet(mat, settings):
    """Inserts the group in front of one Principled BSDF; returns the group
    node. All or nothing: raises RuntimeError (or data.SoakDataError) with
    the material unchanged."""
    bsdf, _others = check_wettable(mat, settings)
    gn = _atomic(mat.node_tree, _insert, mat, bsdf, settings)
    if settings.wetness_source == "IMAGE":
        settings.wet_map.colorspace_settings.name = "Non-Color"   # a data map, not a colour
    return gn


def _tag(n, role=None):
    n[NODE_TAG] = True
    if role:
        n[ROLE_KEY] = role
    return n


def _source_nodes(tree):
    return [n for n in tree.nodes if n.get(NODE_TAG) and n.type != "GROUP"
            and (n.get(ROLE_KEY) == "source" or (n.get(ROLE_KEY) is None and n.bl_idname in SOURCE_TYPES))]


def _wire_source(tree, gn, settings):
    src = settings.wetness_source
    check_source(settings)
    made = []
    if src == "IMAGE":
        n = _tag(tree.nodes.new("ShaderNodeTexImage"), "source")
        n.image = settings.wet_map
        n.extension = "EXTEND"
        tree.links.new(n.outputs["Color"], gn.inputs["Wet Map"])
        made.append(n)
    elif src == "ATTRIBUTE":
        n = _tag(tree.nodes.new("ShaderNodeAttribute"), "source")
        n.attribute_name = settings.attribute_name
        tree.links.new(n.outputs["Fac"], gn.inputs["Wet Map"])
        made.append(n)
    elif src == "NOISE":
        n = _tag(tree.nodes.new("ShaderNodeTexNoise"), "source")
        n.inputs["Scale"].default_value = settings.noise_scale
        r = _tag(tree.nodes.new("ShaderNodeMapRange"), "source")
        r.clamp = True
        r.inputs["From Min"].default_value = 0.45
        r.inputs["From Max"].default_value = 0.55
        tree.links.new(n.outputs["Fac"], r.inputs["Value"])
        tree.links.new(r.outputs["Result"], gn.inputs["Wet Map"])
        made += [n, r]
    for i, n in enumerate(made):
        n.location = (gn.location.x - 240 * (len(made) - i), gn.location.y - 200)
    return made


def _replace_source(mat, gn, settings):
    tree = mat.node_tree
    old = _source_nodes(tree)
    _wire_source(tree, gn, settings)      # new nodes first: a snapshot cannot bring back removed ones
    for n in old:
        tree.nodes.remove(n)
    if settings.wetness_source == "IMAGE":
        settings.wet_map.colorspace_settings.name = "Non-Color"
    restore = json.loads(gn[RESTORE_KEY])
    restore["nodes"] = [n.name for n in tree.nodes if n.get(NODE_TAG) and n != gn]
    gn[RESTORE_KEY] = json.dumps(restore)


def current_source(tree):
    """The wetness-source settings a wet material's nodes implement."""
    kinds = {n.bl_idname: n for n in _source_nodes(tree)}
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
    _atomic(tree, _replace_source, mat, gn, settings)


def _add_translucency(tree, gn, bsdf):
    tr = _tag(tree.nodes.new("ShaderNodeBsdfTranslucent"), "translucency")
    add = _tag(tree.nodes.new("ShaderNodeAddShader"), "translucency")
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


def _remove_translucency(tree, bsdf):
    """Takes the Translucent + Add Shader pair out, re-linking what the Add
    Shader fed to the BSDF itself."""
    pair = [n for n in tree.nodes if n.get(NODE_TAG) and n.get(ROLE_KEY) == "translucency"]
    for add in (n for n in pair if n.bl_idname == "ShaderNodeAddShader"):
        for l in list(add.outputs[0].links):
            if bsdf is not None:
                tree.links.new(bsdf.outputs[0], l.to_socket)
    for n in pair:
        tree.nodes.remove(n)


def _find_ref(tree, name):
    """A node the restore record names: by name when it still carries its
    soak_ref mark, else by the mark (renamed; a duplicate copies the mark,
    the original keeps the name), else by name."""
    n = tree.nodes.get(name)
    if n is not None and n.get(REF_KEY) == name and not n.get(NODE_TAG):
        return n
    for m in tree.nodes:
        if m.get(REF_KEY) == name and not m.get(NODE_TAG):
            return m
    return n if n is not None and not n.get(NODE_TAG) else None


def _clear_refs(tree):
    for n in tree.nodes:
        if REF_KEY in n:
            del n[REF_KEY]


def _restore_inputs(tree, bsdf, restore, problems):
    for ident, rec in restore.get("inputs", {}).items():
        s = _in_socket(bsdf, ident)
        if s is None:
            problems.append(f"'{bsdf.name}' has no input '{ident}' any more")
            continue
        for l in list(s.links):
            tree.links.remove(l)
        if rec["value"] is not None:
            try:
                s.default_value = rec["value"]
            except (TypeError, ValueError) as e:
                problems.append(f"{s.name}: value not restored ({e})")
        for from_name, from_id in rec["links"]:
            node = _find_ref(tree, from_name)
            src = node and _out_socket(node, from_id)
            if src is None:
                problems.append(f"'{from_name}' (linked to {s.name}) was deleted or lost that output")
            else:
                tree.links.new(src, s)


def _restore_outputs(tree, bsdf, restore, problems):
    for to_name, to_id in restore.get("bsdf_out", []):
        to = _find_ref(tree, to_name)
        sock = to and _in_socket(to, to_id)
        if sock is None:
            problems.append(f"'{to_name}' (fed by the BSDF) was deleted")
        elif not any(l.from_node == bsdf for l in sock.links):
            tree.links.new(bsdf.outputs[0], sock)


def make_dry(mat):
    """Removes the group and the nodes it added and restores the recorded
    links and values. Copes with a user who deleted or renamed nodes since:
    restores what remains; returns the list of what it could not restore."""
    check_editable(mat)
    tree = mat.node_tree
    gn = find_group_node(tree)
    tagged = [n for n in tree.nodes if n.get(NODE_TAG)]
    if gn is None and not tagged:
        raise RuntimeError(f"material '{mat.name}' is not wet")
    problems = []
    try:
        restore = json.loads(gn[RESTORE_KEY]) if gn is not None else None
    except (KeyError, ValueError, TypeError):
        restore = None
    if restore is None:
        problems.append("no restore record (Soak nodes removed; the BSDF's links and values not restored)")
        restore = {}
    bsdf = _find_ref(tree, restore["bsdf"]) if "bsdf" in restore else None
    if "bsdf" in restore and bsdf is None:
        problems.append(f"the Principled BSDF '{restore['bsdf']}' was deleted: its inputs were not restored")
    ng = gn.node_tree if gn is not None else None
    for n in tagged:
        tree.nodes.remove(n)
    if ng is not None and ng.users == 0:
        bpy.data.node_groups.remove(ng)
    if bsdf is not None:
        _restore_inputs(tree, bsdf, restore, problems)
        _restore_outputs(tree, bsdf, restore, problems)
    _clear_refs(tree)
    return problems


def _fill_time_is_default(gn, old_preset):
    try:
        old = data.material(old_preset)["t_fill"]
    except data.SoakDataError:
        return False
    return abs(gn.inputs["Fill Time"].default_value - old) <= 1e-6 * max(1.0, abs(old))


def _rebuild(mat, gn, settings):
    tree = mat.node_tree
    old = gn.node_tree
    old_info = json.loads(old.get(GROUP_TAG, "{}")) if old is not None else {}
    restore = json.loads(gn[RESTORE_KEY])
    bsdf = _find_ref(tree, restore["bsdf"])
    keep = {s.name: _value(s) for s in gn.inputs}
    links_in = [(l.from_socket, s.name) for s in gn.inputs for l in s.links]
    links_out = [(s.name, l.to_socket) for s in gn.outputs for l in s.links]
    fill_default = _fill_time_is_default(gn, old_info.get("preset", ""))
    ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
    build_group(ng, settings.preset, settings.liquid, settings.exact_lookups)
    gn.node_tree = ng
    for s in gn.inputs:
        if keep.get(s.name) is not None:
            s.default_value = keep[s.name]
    for src, name in links_in:
        if name in gn.inputs:
            tree.links.new(src, gn.inputs[name])
    for name, dst in links_out:
        if name in gn.outputs:
            tree.links.new(gn.outputs[name], dst)
    m, t = data.material(settings.preset), data.table(settings.preset, settings.liquid)
    if settings.colour_source == "PRESET":
        gn.inputs["Base Color"].default_value = list(m["dry_albedo"]) + [1.0]
        gn.inputs["Roughness"].default_value = t["params"][0][0]
    if fill_default:
        gn.inputs["Fill Time"].default_value = m["t_fill"]
    if bsdf is not None:
        before = _bsdf_state(bsdf)
        connect_outputs(tree, gn, bsdf, settings)
        has_sheet = any(n.get(ROLE_KEY) == "translucency" for n in tree.nodes if n.get(NODE_TAG))
        if m["kind"] == "thin_sheet" and not has_sheet and bsdf.outputs[0].is_linked:
            _add_translucency(tree, gn, bsdf)
        elif m["kind"] != "thin_sheet" and has_sheet:
            _remove_translucency(tree, bsdf)
        _note_changes(restore, before, bsdf)
    restore["nodes"] = [n.name for n in tree.nodes if n.get(NODE_TAG) and n != gn]
    gn[RESTORE_KEY] = json.dumps(restore)
    if old is not None and old.users == 0:
        bpy.data.node_groups.remove(old)
        ng.name = "Soak Wet"
    return gn


def rebuild(mat, settings):
    """Rebuilds a wet material's group for new settings (Preset, Liquid, Exact
    lookups) into a new node group, keeping the group node's input values,
    links and keyframes (the keys address the inputs by index, which the
    rebuild keeps) and the links from its outputs; a Fill Time still at the
    old preset's value follows the new preset. Another material sharing the
    old group keeps it. All or nothing."""
    tree = mat.node_tree
    gn = find_group_node(tree) if tree is not None else None
    if gn is None:
        return None
    check_editable(mat)
    check_data(settings)
    if RESTORE_KEY not in gn:
        raise RuntimeError(f"material '{mat.name}': the Soak Wet node has no restore record (Make Dry, then Make Wet)")
    old = gn.node_tree
    snap = _Snapshot(tree)
    try:
        return _rebuild(mat, gn, settings)
    except BaseException:
        if gn.node_tree != old:
            gn.node_tree = old          # first: the snapshot's values are the old group's sockets'
        snap.restore()
        raise
