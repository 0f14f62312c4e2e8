"""Make Wet: the Soak Wet group inserted in front of every Principled BSDF
of a material, wired into it, and the BSDF's dry state recorded for
Make Dry. All or nothing (snapshot.atomic)."""

import json

import bpy

from . import compat, data, sources, specialise, translucency, ungroup, wet_group
from .checks import check_principled, check_wettable
from .material_tree import NODE_TAG, RESTORE_KEY, PRIMARY_KEY, socket_record, set_ref
from .snapshot import atomic
from .wet_group import GROUP_TAG, INPUTS, metal_preset

PENDING = "pending_"


def pending_values(settings):
    """{group input name: value} of the controls set before Make Wet."""
    return {name: settings[PENDING + name] for name, *_ in INPUTS if PENDING + name in settings}


def clear_pending(settings):
    for name, *_ in INPUTS:
        if PENDING + name in settings:
            del settings[PENDING + name]


def bsdf_state(bsdf):
    return {s.identifier: socket_record(s) for s in bsdf.inputs}


def note_changes(restore, before, bsdf):
    """Adds to the restore record every BSDF input whose links or value the
    change made differ from `before` (first record wins: the dry state)."""
    for s in bsdf.inputs:
        rec = before.get(s.identifier)
        if rec is not None and s.identifier not in restore["inputs"] and socket_record(s) != rec:
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
        wet_group.build_group(gn.node_tree, settings.preset, settings.liquid, settings.exact_lookups, metal=want,
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


def undo_conductor_metal(bsdf, restore, settings):
    """Leaving a conductor preset: the Metallic that _metal_for_conductor set
    goes back to the user's dry value (the restore record holds it)."""
    met = compat.principled_input(bsdf, "metallic")
    if met is None or met.is_linked or data.material(settings.preset)["kind"] == "conductor":
        return
    rec = restore["inputs"].get(met.identifier)
    if rec is not None and not rec["links"] and rec["value"] == 0.0 and met.default_value == 1.0:
        met.default_value = 0.0


def _refs(tree, restore):
    """Marks the user's nodes the record names, so Make Dry finds them renamed."""
    names = {restore["bsdf"]}
    names.update(fn for rec in restore["inputs"].values() for fn, _ in rec["links"])
    names.update(tn for tn, _ in restore["bsdf_out"])
    for name in names:
        n = tree.nodes.get(name)
        if n is not None and not n.get(NODE_TAG):
            set_ref(n, name)


def _insert(mat, bsdf, settings):
    tree = mat.node_tree
    before = bsdf_state(bsdf)
    restore = {"bsdf": bsdf.name, "inputs": {}, "nodes": [],
               "bsdf_out": [[l.to_node.name, l.to_socket.identifier] for l in bsdf.outputs[0].links]}
    ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
    wet_group.build_group(ng, settings.preset, settings.liquid, settings.exact_lookups, quality=settings.quality)
    gn = tree.nodes.new("ShaderNodeGroup")
    gn.node_tree = ng
    gn.name = gn.label = "Soak Wet"
    gn[NODE_TAG] = True
    gn.location = (bsdf.location.x - 260, bsdf.location.y)
    _group_defaults(gn, settings, tree, bsdf)
    connect_outputs(tree, gn, bsdf, settings)
    made = []
    if data.material(settings.preset)["kind"] == "thin_sheet" and bsdf.outputs[0].is_linked:
        made += translucency.add_translucency(tree, gn, bsdf)
    note_changes(restore, before, bsdf)
    restore["nodes"] = [n.name for n in made]
    _refs(tree, restore)
    gn[RESTORE_KEY] = json.dumps(restore)
    return gn


def _insert_all(mat, bsdfs, settings, opened):
    if opened is not None:
        opened[:], emptied = ungroup.open_groups(mat.node_tree)
        bsdfs = check_principled(mat)
    gns = [_insert(mat, bsdf, settings) for bsdf in bsdfs]
    gns[0][PRIMARY_KEY] = True
    made = sources.wire_source(mat.node_tree, gns, settings)
    restore = json.loads(gns[0][RESTORE_KEY])
    restore["nodes"] += [n.name for n in made]
    gns[0][RESTORE_KEY] = json.dumps(restore)
    specialise.drop_unused(specialise.specialise_stale(mat.node_tree))     # groups made just now
    if opened is not None:
        ungroup.remove_emptied(mat.node_tree, emptied)
    return gns[0]


def make_wet(mat, settings, opened=None):
    """Inserts a group in front of every Principled BSDF of the material
    (one wetness source feeds them all); returns the first group node. A
    Principled BSDF inside node groups (nested too) is reached by opening
    those groups in this material (ungroup.py; the list `opened` receives
    their names). All or nothing: raises RuntimeError (or
    data.SoakDataError) with the material unchanged."""
    opened = [] if opened is None else opened
    grouped = bool(ungroup.groups_to_open(mat.node_tree))
    bsdfs = check_wettable(mat, settings, grouped)
    gn = atomic(mat.node_tree, _insert_all, mat, bsdfs, settings, opened if grouped else None)
    clear_pending(settings)
    if settings.wetness_source == "IMAGE":
        settings.wet_map.colorspace_settings.name = "Non-Color"   # a data map, not a colour
    return gn
