"""Rebuild: a wet material's groups rebuilt in place for new settings
(Preset, Liquid, Quality, Exact lookups), keeping the group nodes' values,
links and keys."""

import json

import bpy

from . import data, insertion, specialise, translucency, wet_group
from .checks import check_editable, check_data
from .material_tree import NODE_TAG, RESTORE_KEY, group_nodes, find_ref
from .snapshot import Snapshot
from .wet_group import GROUP_TAG


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
    bsdf = find_ref(tree, restore["bsdf"])
    fill_default = _fill_time_is_default(gn, old_info.get("preset", ""))
    ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
    wet_group.build_group(ng, settings.preset, settings.liquid, settings.exact_lookups, quality=settings.quality)
    specialise.swap_group(tree, gn, ng)
    m, t = data.material(settings.preset), data.table(settings.preset, settings.liquid)
    if settings.colour_source == "PRESET":
        gn.inputs["Base Color"].default_value = list(m["dry_albedo"]) + [1.0]
        gn.inputs["Roughness"].default_value = t["params"][0][0]
    if fill_default:
        gn.inputs["Fill Time"].default_value = m["t_fill"]
    if bsdf is not None:
        before = insertion.bsdf_state(bsdf)
        insertion.undo_conductor_metal(bsdf, restore, settings)
        insertion.connect_outputs(tree, gn, bsdf, settings)
        has_sheet = bool(translucency.sheet_pair(tree, bsdf))
        if m["kind"] == "thin_sheet" and not has_sheet and bsdf.outputs[0].is_linked:
            translucency.add_translucency(tree, gn, bsdf)
        elif m["kind"] != "thin_sheet" and has_sheet:
            translucency.remove_translucency(tree, bsdf)
        insertion.note_changes(restore, before, bsdf)
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
    snap = Snapshot(tree)
    try:
        for gn in gns:
            _rebuild(mat, gn, settings)
        made = [gn.node_tree for gn in gns]
        specialise.specialise_stale(tree)
    except BaseException:
        for gn, tr in zip(gns, old):
            if gn.node_tree != tr:
                gn.node_tree = tr       # first: the snapshot's values are the old group's sockets'
        snap.restore()
        raise
    specialise.drop_unused(old + made)            # the old groups go once every node has its new one
    return gns[0]
