"""Make Dry: the Soak nodes taken out and the Principled BSDFs' recorded
links and values put back, coping with nodes the user deleted or renamed."""

import json

import bpy

from .checks import check_editable
from .material_tree import NODE_TAG, RESTORE_KEY, group_nodes, out_socket, in_socket, find_ref, clear_refs


def _restore_inputs(tree, bsdf, restore, problems):
    for ident, rec in restore.get("inputs", {}).items():
        s = in_socket(bsdf, ident)
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
            node = find_ref(tree, from_name)
            src = node and out_socket(node, from_id)
            if src is None:
                problems.append(f"'{from_name}' (linked to {s.name}) was deleted or lost that output")
            else:
                tree.links.new(src, s)


def _restore_outputs(tree, bsdf, restore, problems):
    for to_name, to_id in restore.get("bsdf_out", []):
        to = find_ref(tree, to_name)
        sock = to and in_socket(to, to_id)
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
        bsdf = find_ref(tree, restore["bsdf"]) if "bsdf" in restore else None
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
    clear_refs(tree)
    return problems
