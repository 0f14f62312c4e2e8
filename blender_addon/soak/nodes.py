"""Material surgery: the Soak Wet group inserted in front of every
Principled BSDF of a material and taken out again exactly (make_wet,
make_dry, set_source, rebuild), each change all-or-nothing under a
_Snapshot. The group itself is built by wet_group.build_group."""

import json

import bpy

from . import compat, data, wet_bounds
from .wet_constant import LIQUID_INPUTS
from .wet_group import GROUP_TAG, INPUTS, build_group, metal_preset

NODE_TAG = "soak_node"
RESTORE_KEY = "soak_restore"

# Before Make Wet the panel's controls keep their values on the material's
# settings under this prefix (ID properties); Make Wet gives them to the group.
PENDING = "pending_"


def pending_values(settings):
    """{group input name: value} of the controls set before Make Wet."""
    return {name: settings[PENDING + name] for name, *_ in INPUTS if PENDING + name in settings}


def clear_pending(settings):
    for name, *_ in INPUTS:
        if PENDING + name in settings:
            del settings[PENDING + name]



# ---- insertion and exact removal --------------------------------------------
#
# Every change below is all-or-nothing: everything that can be checked is
# checked before the tree is touched (check_wettable), and the rest runs under
# a _Snapshot that puts the material's tree back as it was on any exception.

ROLE_KEY = "soak_role"          # on tagged nodes: "source" | "translucency"
PRIMARY_KEY = "soak_primary"    # on the first group node Make Wet made
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


def group_nodes(tree):
    """Every Soak Wet group node of a material (one per wetted Principled
    BSDF), the first wetted first: the panel reads its controls."""
    gns = [n for n in tree.nodes if n.get(NODE_TAG) and n.type == "GROUP"]
    return sorted(gns, key=lambda n: (not n.get(PRIMARY_KEY), n.name))


def find_group_node(tree):
    gns = group_nodes(tree)
    return gns[0] if gns else None


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
    if not compat.material_uses_nodes(mat):
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
    Returns the Principled BSDFs to wet: every one in the material."""
    check_editable(mat)
    tree = mat.node_tree
    if find_group_node(tree) is not None:
        raise RuntimeError(f"material '{mat.name}' is already wet (Make Dry first)")
    bsdfs = principled_nodes(tree)
    if not bsdfs:
        raise RuntimeError(f"material '{mat.name}' has no Principled BSDF")
    for bsdf in bsdfs:
        missing = [compat.principled_name(r) for r in _REQUIRED_ROLES if compat.principled_input(bsdf, r) is None]
        if missing:
            raise RuntimeError(f"'{bsdf.name}' lacks the inputs {', '.join(missing)}")
    check_data(settings)
    check_source(settings)
    return bsdfs


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
    for name, value in pending_values(settings).items():   # the panel's controls set before Make Wet
        gn.inputs[name].default_value = value


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
    _metal_for_conductor(bsdf, settings)
    _connect_specular_metal(tree, gn, bsdf, settings)


def _metal_for_conductor(bsdf, settings):
    """A conductor preset's function gives a metal's reflectance: a Principled
    BSDF left at Metallic 0 (unlinked) would show it as a diffuse colour, so
    it becomes metallic (Make Dry puts the 0 back). A Metallic the user set
    or linked is theirs."""
    met = compat.principled_input(bsdf, "metallic")
    if data.material(settings.preset)["kind"] != "conductor" or met is None or met.is_linked:
        return
    if met.default_value == 0.0:
        met.default_value = 1.0


def _preset_specular(gn, bsdf, settings):
    """The preset's own dry lobe (colour source Preset): the chain's
    specular weight x the Fresnel reflectance of the preset's index
    (soak/bsdf.h COATED: the lobe soak render traces), as this Principled's
    specular value. A link into the group's Specular is left alone."""
    m = data.material(settings.preset)
    if m["kind"] == "conductor" or gn.inputs["Specular"].is_linked:
        return
    weight = data.table(settings.preset, settings.liquid)["params"][0][4]   # params pixel 1, green
    f0 = data.normal_reflectance(m["ior"])
    gn.inputs["Specular"].default_value = compat.specular_for_f0(bsdf, weight * f0)


def _connect_specular_metal(tree, gn, bsdf, settings):
    """The base's own specular through the group (replaced by what is left of
    it under the liquid), the Metallic amount into the group (rebuilt with a
    conductor's function where the material is metallic), Coat Tint white
    (4.x: the liquid's absorption is in the core's colours already)."""
    want = metal_preset(bsdf, gn, settings.preset)
    info = json.loads(gn.node_tree.get(GROUP_TAG, "{}"))
    if info.get("metal") != want:
        build_group(gn.node_tree, settings.preset, settings.liquid, settings.exact_lookups, metal=want,
                    quality=settings.quality, constant=info.get("constant"))
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
    if settings.colour_source == "PRESET":
        _preset_specular(gn, bsdf, settings)
    tree.links.new(gn.outputs["Specular"], compat.principled_input(bsdf, "specular"))
    tint = compat.principled_input(bsdf, "coat_tint")
    if tint is not None:
        tint.default_value = (1.0, 1.0, 1.0, 1.0)


def _undo_conductor_metal(bsdf, restore, settings):
    """Leaving a conductor preset: the Metallic that _metal_for_conductor set
    goes back to the user's dry value (the restore record holds it)."""
    met = compat.principled_input(bsdf, "metallic")
    if met is None or met.is_linked or data.material(settings.preset)["kind"] == "conductor":
        return
    rec = restore["inputs"].get(met.identifier)
    if rec is not None and not rec["links"] and rec["value"] == 0.0 and met.default_value == 1.0:
        met.default_value = 0.0


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
    build_group(ng, settings.preset, settings.liquid, settings.exact_lookups, quality=settings.quality)
    gn = tree.nodes.new("ShaderNodeGroup")
    gn.node_tree = ng
    gn.name = gn.label = "Soak Wet"
    gn[NODE_TAG] = True
    gn.location = (bsdf.location.x - 260, bsdf.location.y)
    _group_defaults(gn, settings, tree, bsdf)
    connect_outputs(tree, gn, bsdf, settings)
    made = []
    if data.material(settings.preset)["kind"] == "thin_sheet" and bsdf.outputs[0].is_linked:
        made += _add_translucency(tree, gn, bsdf)
    _note_changes(restore, before, bsdf)
    restore["nodes"] = [n.name for n in made]
    _refs(tree, restore)
    gn[RESTORE_KEY] = json.dumps(restore)
    return gn


def _insert_all(mat, bsdfs, settings):
    gns = [_insert(mat, bsdf, settings) for bsdf in bsdfs]
    gns[0][PRIMARY_KEY] = True
    made = _wire_source(mat.node_tree, gns, settings)
    restore = json.loads(gns[0][RESTORE_KEY])
    restore["nodes"] += [n.name for n in made]
    gns[0][RESTORE_KEY] = json.dumps(restore)
    _drop_unused(_specialise_stale(mat.node_tree))     # groups made just now
    return gns[0]


def make_wet(mat, settings):
    """Inserts a group in front of every Principled BSDF of the material
    (one wetness source feeds them all); returns the first group node. All
    or nothing: raises RuntimeError (or data.SoakDataError) with the
    material unchanged."""
    bsdfs = check_wettable(mat, settings)
    gn = _atomic(mat.node_tree, _insert_all, mat, bsdfs, settings)
    clear_pending(settings)
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


def _wire_source(tree, gns, settings):
    """The wetness source's nodes, feeding the Wet Map of every group node
    in gns (one node or a list)."""
    gns = list(gns) if isinstance(gns, (list, tuple)) else [gns]
    gn = gns[0]
    src = settings.wetness_source
    check_source(settings)
    made = []
    if src == "IMAGE":
        n = _tag(tree.nodes.new("ShaderNodeTexImage"), "source")
        n.image = settings.wet_map
        n.extension = "EXTEND"
        out = n.outputs["Color"]
        made.append(n)
    elif src == "ATTRIBUTE":
        n = _tag(tree.nodes.new("ShaderNodeAttribute"), "source")
        n.attribute_name = settings.attribute_name
        out = n.outputs["Fac"]
        made.append(n)
    elif src == "NOISE":
        n = _tag(tree.nodes.new("ShaderNodeTexNoise"), "source")
        n.inputs["Scale"].default_value = settings.noise_scale
        r = _tag(tree.nodes.new("ShaderNodeMapRange"), "source")
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
    old = _source_nodes(tree)
    _wire_source(tree, group_nodes(tree), settings)   # new nodes first: a snapshot cannot bring back removed ones
    for n in old:
        tree.nodes.remove(n)
    if settings.wetness_source == "IMAGE":
        settings.wet_map.colorspace_settings.name = "Non-Color"
    restore = json.loads(gn[RESTORE_KEY])
    restore["nodes"] = [n.name for n in tree.nodes if n.get(NODE_TAG) and n != gn]
    gn[RESTORE_KEY] = json.dumps(restore)
    return _specialise_stale(tree)


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
    _drop_unused(_atomic(tree, _replace_source, mat, gn, settings))


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


def _sheet_pair(tree, bsdf):
    """The Translucent BSDF + Add Shader pair Make Wet added beside `bsdf`."""
    adds = [n for n in tree.nodes if n.get(NODE_TAG) and n.get(ROLE_KEY) == "translucency"
            and n.bl_idname == "ShaderNodeAddShader" and any(l.from_node == bsdf for l in n.inputs[0].links)]
    trs = [l.from_node for a in adds for l in a.inputs[1].links if l.from_node.get(NODE_TAG)]
    return adds + trs


def _remove_translucency(tree, bsdf):
    """Takes the Translucent + Add Shader pair out, re-linking what the Add
    Shader fed to the BSDF itself."""
    pair = _sheet_pair(tree, bsdf)
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
    gns = group_nodes(tree)
    tagged = [n for n in tree.nodes if n.get(NODE_TAG)]
    if not gns and not tagged:
        raise RuntimeError(f"material '{mat.name}' is not wet")
    problems = []
    records = []
    for gn in gns or [None]:
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
        records.append((bsdf, restore))
    ngs = [gn.node_tree for gn in gns if gn.node_tree is not None]
    for n in tagged:
        tree.nodes.remove(n)
    for ng in ngs:
        if ng.name in bpy.data.node_groups and ng.users == 0:
            bpy.data.node_groups.remove(ng)
    for bsdf, restore in records:
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


def _swap_group(tree, gn, ng):
    """Gives the group node the node group ng, keeping its input values and
    the links into and out of it (by socket name)."""
    keep = {s.name: _value(s) for s in gn.inputs}
    links_in = [(l.from_socket, s.name) for s in gn.inputs for l in s.links]
    links_out = [(s.name, l.to_socket) for s in gn.outputs for l in s.links]
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


def _rebuild(mat, gn, settings):
    tree = mat.node_tree
    old = gn.node_tree
    old_info = json.loads(old.get(GROUP_TAG, "{}")) if old is not None else {}
    restore = json.loads(gn[RESTORE_KEY])
    bsdf = _find_ref(tree, restore["bsdf"])
    fill_default = _fill_time_is_default(gn, old_info.get("preset", ""))
    ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
    build_group(ng, settings.preset, settings.liquid, settings.exact_lookups, quality=settings.quality)
    _swap_group(tree, gn, ng)
    m, t = data.material(settings.preset), data.table(settings.preset, settings.liquid)
    if settings.colour_source == "PRESET":
        gn.inputs["Base Color"].default_value = list(m["dry_albedo"]) + [1.0]
        gn.inputs["Roughness"].default_value = t["params"][0][0]
    if fill_default:
        gn.inputs["Fill Time"].default_value = m["t_fill"]
    if bsdf is not None:
        before = _bsdf_state(bsdf)
        _undo_conductor_metal(bsdf, restore, settings)
        connect_outputs(tree, gn, bsdf, settings)
        has_sheet = bool(_sheet_pair(tree, bsdf))
        if m["kind"] == "thin_sheet" and not has_sheet and bsdf.outputs[0].is_linked:
            _add_translucency(tree, gn, bsdf)
        elif m["kind"] != "thin_sheet" and has_sheet:
            _remove_translucency(tree, bsdf)
        _note_changes(restore, before, bsdf)
    restore["nodes"] = [n.name for n in tree.nodes if n.get(NODE_TAG) and n != gn]
    gn[RESTORE_KEY] = json.dumps(restore)
    return gn


def rebuild(mat, settings):
    """Rebuilds a wet material's group for new settings (Preset, Liquid, Exact
    lookups) into a new node group, keeping the group node's input values,
    links and keyframes (the keys address the inputs by index, which the
    rebuild keeps) and the links from its outputs; a Fill Time still at the
    old preset's value follows the new preset. Another material sharing the
    old group keeps it. All or nothing."""
    tree = mat.node_tree
    gns = group_nodes(tree) if tree is not None else []
    if not gns:
        return None
    check_editable(mat)
    check_data(settings)
    if any(RESTORE_KEY not in gn for gn in gns):
        raise RuntimeError(f"material '{mat.name}': a Soak Wet node has no restore record (Make Dry, then Make Wet)")
    old = [gn.node_tree for gn in gns]
    snap = _Snapshot(tree)
    try:
        for gn in gns:
            _rebuild(mat, gn, settings)
        made = [gn.node_tree for gn in gns]
        _specialise_stale(tree)
    except BaseException:
        for gn, tr in zip(gns, old):
            if gn.node_tree != tr:
                gn.node_tree = tr       # first: the snapshot's values are the old group's sockets'
        snap.restore()
        raise
    _drop_unused(old + made)            # the old groups go once every node has its new one
    return gns[0]


# ---- specialisation to a constant liquid -------------------------------------
#
# A group whose liquid amount cannot vary is built for that one amount
# (wet_group.build_group's `constant`, wet_constant): its tables become
# curves and numbers. One whose amount varies is built for what does not
# (`varying`, wet_bounds): the inputs only their value sets fold into
# numbers, and a liquid that never reaches the film leaves the film's terms
# out. It is rebuilt whenever what it was built for changes: a control set
# from the panel, a key, a link, a source, the wet map's pixels.

def _fcurve_of(tree, gn):
    """name -> the F-curve keying the group node's input, "driver" (a
    driver or NLA strips: anything), or None."""
    index = {s.name: i for i, s in enumerate(gn.inputs)}
    ad = tree.animation_data
    # NLA strips may animate any input, outside the action's curves: unbounded
    nla = ad is not None and any(len(track.strips) for track in ad.nla_tracks)

    def of(name):
        path = f'nodes["{gn.name}"].inputs[{index[name]}].default_value'
        if nla or (ad is not None and ad.drivers.find(path) is not None):
            return "driver"
        return compat.find_fcurve(tree, path)
    return of


def specialisation(tree, gn):
    """(constant, varying): constant {name: value} of the inputs that set
    the liquid amount (wet_constant.LIQUID_INPUTS) when none is linked,
    keyed or driven (else None); varying, for a liquid that can vary:
    {"fixed": {name: value} of the inputs only the node's value sets,
    "film": False when the liquid provably stays below the table's
    saturation, where the film starts (wet_bounds)}."""
    bounds, fixed = wet_bounds.input_bounds(gn, _fcurve_of(tree, gn))
    if len(fixed) == len(LIQUID_INPUTS):
        return {name: bounds[name][0] for name in LIQUID_INPUTS}, None
    info = _group_info(gn)
    varying = {"fixed": {name: bounds[name][0] for name in LIQUID_INPUTS if name in fixed},
               "film": not wet_bounds.film_free(data.table(info["preset"], info["liquid"]), bounds)}
    return None, (varying if varying["fixed"] or not varying["film"] else None)   # None: the full group


def constant_inputs(tree, gn):
    """{name: value} of the inputs that set the liquid amount when none
    varies; else None."""
    return specialisation(tree, gn)[0]


def _group_info(gn):
    ng = gn.node_tree
    return json.loads(ng.get(GROUP_TAG, "{}")) if ng is not None else {}


def is_specialised(gn):
    """True when the node's group is built for one constant liquid amount."""
    return _group_info(gn).get("constant") is not None


def is_film_free(gn):
    """True when the node's group leaves the film's terms out (its liquid
    never reaches the film)."""
    return (_group_info(gn).get("varying") or {}).get("film") is False


def stale_groups(tree):
    """The group nodes whose group was built for another constant liquid
    (or for a varying one) than their inputs now give."""
    stale = []
    for gn in group_nodes(tree):
        info = _group_info(gn)
        if "preset" in info and (info.get("constant"), info.get("varying")) != specialisation(tree, gn):
            stale.append(gn)
    return stale


def _specialise_stale(tree):
    """Rebuilds every stale group into a new node group; returns the groups
    replaced (the caller removes them once nothing can fail any more)."""
    replaced = []
    for gn in stale_groups(tree):
        info = _group_info(gn)
        ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
        constant, varying = specialisation(tree, gn)
        build_group(ng, info["preset"], info["liquid"], info.get("exact", False), metal=info.get("metal"),
                    quality=info.get("quality", "BALANCED"), constant=constant, varying=varying)
        replaced.append(gn.node_tree)
        _swap_group(tree, gn, ng)
    return replaced


def _drop_unused(groups):
    for ng in groups:
        if ng is not None and ng.name in bpy.data.node_groups and ng.users == 0:
            bpy.data.node_groups.remove(ng)
    if "Soak Wet" not in bpy.data.node_groups:
        for ng in bpy.data.node_groups:
            if ng.name.startswith("Soak Wet.") and GROUP_TAG in ng:
                ng.name = "Soak Wet"
                break


def specialise(mat):
    """Rebuilds the material's groups whose liquid amount became constant,
    changed, or stopped being constant (wet_constant); the group nodes keep
    their values, links and keys. All or nothing: raises with the material
    unchanged. Returns how many groups were rebuilt."""
    tree = mat.node_tree
    gns = stale_groups(tree) if tree is not None else []
    if not gns:
        return 0
    check_editable(mat)
    old = [gn.node_tree for gn in gns]
    snap = _Snapshot(tree)
    try:
        _specialise_stale(tree)
    except BaseException:
        for gn, tr in zip(gns, old):
            if gn.node_tree != tr:
                gn.node_tree = tr
        snap.restore()
        raise
    _drop_unused(old)
    return len(gns)
