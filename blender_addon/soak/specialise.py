"""Specialisation: a Soak Wet group rebuilt for what its inputs can give.

A group whose liquid amount cannot vary is built for that one amount
(wet_group.build_group's `constant`, wet_constant): its tables become
curves and numbers. One whose amount varies is built for what does not
(`varying`, wet_bounds): the inputs only their value sets fold into
numbers, and a liquid that never reaches the film leaves the film's terms
out. It is rebuilt whenever what it was built for changes: a control set
from the panel, a key, a link, a source, the wet map's pixels."""

import bpy

from . import compat, data, wet_bounds, wet_group
from .checks import check_editable
from .material_tree import group_nodes, group_info, socket_value
from .snapshot import Snapshot
from .wet_constant import LIQUID_INPUTS
from .wet_group import GROUP_TAG


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
    the liquid amount (LIQUID_INPUTS) when none is linked,
    keyed or driven (else None); varying, for a liquid that can vary:
    {"fixed": {name: value} of the inputs only the node's value sets,
    "film": False when the liquid provably stays below the table's
    saturation, where the film starts (wet_bounds), "bump": False when the
    Spill Edge is 0 and cannot change (no spill-edge bump built)}."""
    fcurve_of = _fcurve_of(tree, gn)
    bounds, fixed = wet_bounds.input_bounds(gn, fcurve_of)
    if len(fixed) == len(LIQUID_INPUTS):
        return {name: bounds[name][0] for name in LIQUID_INPUTS}, None
    info = group_info(gn)
    varying = {"fixed": {name: bounds[name][0] for name in LIQUID_INPUTS if name in fixed},
               "film": not wet_bounds.film_free(data.table(info["preset"], info["liquid"]), bounds)}
    if _no_spill_edge(gn, fcurve_of):
        varying["bump"] = False
    if varying["fixed"] or not varying["film"] or "bump" in varying:
        return None, varying
    return None, None       # the full group


def _no_spill_edge(gn, fcurve_of):
    """True when the Spill Edge is 0 and only its value sets it. Cycles
    evaluates a Bump node's height three times (its own finite
    differences) even at strength 0 (BumpNode::constant_fold folds only an
    unlinked height): the Wet Map's whole texture would run three times
    for a bump that does nothing."""
    s = gn.inputs.get("Spill Edge")
    return s is not None and not s.is_linked and fcurve_of("Spill Edge") is None and s.default_value == 0.0


def constant_inputs(tree, gn):
    """{name: value} of the inputs that set the liquid amount when none
    varies; else None."""
    return specialisation(tree, gn)[0]


def is_specialised(gn):
    """True when the node's group is built for one constant liquid amount."""
    return group_info(gn).get("constant") is not None


def is_film_free(gn):
    """True when the node's group leaves the film's terms out (its liquid
    never reaches the film)."""
    return (group_info(gn).get("varying") or {}).get("film") is False


def stale_groups(tree):
    """The group nodes whose group was built for another constant liquid
    (or for a varying one) than their inputs now give."""
    stale = []
    for gn in group_nodes(tree):
        info = group_info(gn)
        if "preset" in info and (info.get("constant"), info.get("varying")) != specialisation(tree, gn):
            stale.append(gn)
    return stale


def swap_group(tree, gn, ng):
    """Gives the group node the node group ng, keeping its input values and
    the links into and out of it (by socket name)."""
    keep = {s.name: socket_value(s) for s in gn.inputs}
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


def specialise_stale(tree):
    """Rebuilds every stale group into a new node group; returns the groups
    replaced (the caller removes them once nothing can fail any more)."""
    replaced = []
    for gn in stale_groups(tree):
        info = group_info(gn)
        ng = bpy.data.node_groups.new("Soak Wet", "ShaderNodeTree")
        constant, varying = specialisation(tree, gn)
        wet_group.build_group(ng, info["preset"], info["liquid"], info.get("exact", False), metal=info.get("metal"),
                              quality=info.get("quality", "BALANCED"), constant=constant, varying=varying)
        replaced.append(gn.node_tree)
        swap_group(tree, gn, ng)
    for gn in group_nodes(tree):
        show_baked(gn)
    return replaced


def unused_inputs(gn):
    """{name: value} of the group node's inputs its group does not read: the
    liquid's inputs folded into numbers (a constant liquid: all of them; a
    varying one: those only their values set), the Spill Edge where no bump
    is built (Quality Draft, a constant liquid) and the Metallic where no
    conductor's function is mixed in."""
    info = group_info(gn)
    folded = dict(info.get("constant") or (info.get("varying") or {}).get("fixed") or {})
    if (info.get("constant") is not None or info.get("quality") == "DRAFT"
            or (info.get("varying") or {}).get("bump") is False):
        folded["Spill Edge"] = None
    if info.get("metal") is None:
        folded["Metallic"] = None
    return folded


def baked_label(folded):
    """The group node's label: what its group was built for, so that in a
    Blender without the add-on the node says which values are baked in
    (the Wetness always, the other liquid inputs where they differ from
    their defaults; Blender keeps 63 characters of a label)."""
    defaults = {name: default for name, _, default, *_ in wet_group.INPUTS}
    items = [(k, v) for k, v in folded.items()
             if k in LIQUID_INPUTS and (k == "Wetness" or abs(v - defaults[k]) > 1e-6)]
    if not items:
        return "Soak Wet"
    if folded.get("Schedule") == 0.0:     # the schedule off: its times do nothing
        items = [(k, v) for k, v in items if k not in ("Drying", "Time", "Start Time", "Fill Time")]
    words = [f"{k} {'on' if v else 'off'}" if k in ("Schedule", "Drying") else f"{k} {v:.3g}" for k, v in items]
    label = "Soak Wet (baked: " + ", ".join(words) + ")"
    return label if len(label) <= 63 else label[:59] + "...)"


def show_baked(gn):
    """Hides the group node's unlinked inputs its group does not read (they
    would do nothing in a Blender without the add-on, where nothing rebuilds
    the group) and labels the node with the baked values; the add-on's
    panel still sets them (the group is rebuilt, and they show again when it
    reads them)."""
    folded = unused_inputs(gn)
    for s in gn.inputs:
        hide = s.name in folded and not s.is_linked
        if s.hide != hide:
            s.hide = hide
    label = baked_label(folded)
    if gn.label != label:
        gn.label = label


def drop_unused(groups):
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
    snap = Snapshot(tree)
    try:
        specialise_stale(tree)
    except BaseException:
        for gn, tr in zip(gns, old):
            if gn.node_tree != tr:
                gn.node_tree = tr
        snap.restore()
        raise
    drop_unused(old)
    return len(gns)
