"""The "Soak Wet" node group and its insertion in front of a Principled BSDF.

The group evaluates, with native nodes only, what the core exports
(soak_data.json, layout in its "layout" entry); it derives no formula:
  L      = Wetness * min(Wet Map / Puddle Level, 1) * P, P the export's fill
           schedule program (1 - P when Drying; P = 1 unless Schedule);
  colour = the core's wetness function for each channel of any dry colour:
           the export's column and row programs place the channel and L in
           the table; Linear lookups (one per channel, Cycles' bilinear
           filter is the core's) or, with exact lookups (EEVEE), one Closest
           read per channel of the cell's bilinear form; times the preset's
           view factor at the view's cosine (the exported view_factor image:
           the interface's transmission towards the viewer; the light's
           angle a base colour cannot follow);
  rough  = Roughness * the exported apparent-roughness ratio;
  coat   = the liquid's mirror: film plus water-filled pores (coat / clearcoat weight);
  spec   = Specular * the base's own specular left under the liquid
           (soak/wet_specular.h, exported; replaces the dry lobe);
  metal  = a Metallic material's metallic part gets a conductor preset's
           function (metal under the film), mixed by Metallic;
  sheet  = the thin-sheet transmittance (a Translucent BSDF added);
  normal = a bump from the wet map at spill edges (Spill Edge strength).
Costs are kept low (c_core/bench/bench_blender_overhead.sh): Cycles folds
the nodes whose inputs are constant, but not an image lookup; so where
nothing that sets L varies the group is built for that one L
(build_group's `constant`, wet_constant): the table rows at L become RGB
Curves nodes and numbers, and no image is read."""

import json

from . import compat, data, group_layout, view_factor, wet_bounds, wet_constant
from .node_program import (EDGE, Builder, affine_program, combine, lerp, lookup, run_program,
                           run_program_vector, separate, vec, vec_num)

GROUP_TAG = "soak_group"

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

# What each quality models (the panel's Quality; blender_addon/README.md
# gives each one's Cycles overhead and its colour error against the core):
#   exact        one Closest read per channel of a table cell and an explicit
#                bilinear blend, as the core interpolates (else Linear
#                lookups: the engine's filter; EEVEE 4.2-4.4 always exact)
#   view_factor  the liquid interface's transmission towards the viewer
#                (dropped: the colour is the normal-incidence one at every
#                angle, too light at grazing views)
#   bump         the spill-edge bump from the wet map (dropped: Spill Edge
#                does nothing)
QUALITY = {
    "DRAFT": {"exact": False, "view_factor": False, "bump": False},
    "BALANCED": {"exact": False, "view_factor": True, "bump": True},
    "EXACT": {"exact": True, "view_factor": True, "bump": True},
}

# the group's stages, left to right: each a labelled frame and its own columns
STAGES = ("Liquid: Wetness x Wet Map x fill schedule",
          "Spill-edge bump",
          "Colour lookup: the core's wetness tables",
          "View factor: the liquid's interface towards the viewer",
          "Metal under the liquid: a conductor's tables",
          "Metal mix (by Metallic)",
          "Coat and specular")

DESCRIPTIONS = {
    "Base Color": "The dry base colour (the material's own, textures included) that the liquid darkens",
    "Roughness": "The dry roughness; the liquid smooths it",
    "Wetness": "Amount of liquid, 0 (dry) to 1 (saturated, with a film); multiplied by Wet Map",
    "Wet Map": "Where the surface is wet, 0 to 1 (an image, attribute or noise); its edges also drive the bump",
    "Puddle Level": "Wet Map values at or above this count as fully wet (standing water); 1 leaves the map as it is",
    "Schedule": "1: follow the core's pore-filling schedule over Time; 0: the steady state (fully filled)",
    "Drying": "1: run the schedule backwards (wet at Start Time, dry after Fill Time)",
    "Time": "Time of the schedule in seconds (key it, or use Key Drying)",
    "Start Time": "When the liquid arrives (or drying starts), in seconds",
    "Fill Time": "Seconds the pores take to fill (or dry); the preset's fill time by default",
    "Spill Edge": "Strength of the bump where the wet map changes (liquid standing at a spill's edge); 0 = off",
    "Normal": "The shading normal (a normal map's output); unlinked: the surface's own",
    "Specular": "The dry material's specular (Principled Specular / Specular IOR Level)",
    "Metallic": "The dry material's Metallic: its metallic part gets a conductor's wet function",
    "out Base Color": "Wet base colour (to the Principled BSDF's Base Color)",
    "out Roughness": "Wet roughness",
    "out Coat Weight": "The liquid's mirror: film plus water-filled pores (to Coat / Clearcoat)",
    "out Translucency": "Thin sheets: the wet sheet's transmittance (to a Translucent BSDF)",
    "out Normal": "Shading normal with the spill-edge bump (to Normal and Coat Normal)",
    "out Liquid": "The liquid amount after wet map and schedule, 0 to 1",
    "out Specular": "The base's own specular left under the liquid",
}

OUTPUTS = (("Base Color", "color"), ("Roughness", "float"), ("Coat Weight", "float"),
           ("Translucency", "color"), ("Normal", "vector"), ("Liquid", "float"), ("Specular", "float"))



def _liquid_schedule(b, gin, fixed=None):
    """L = Wetness * min(Wet Map / Puddle Level, 1) * mix(1, P or 1 - P,
    Schedule), P the core's fill progress (the export's schedule program;
    wet_bounds.liquid_program). Puddle Level: wet-map values at or above it
    count as fully wet (standing water: the core's film at full coverage).
    fixed: {input name: value} folded into numbers (the schedule a material
    does not use leaves no node)."""
    fixed = fixed or {}
    env = {v: ((fixed[k], fixed[k]) if k in fixed else wet_bounds.UNKNOWN) for k, v in wet_bounds.NAMES.items()}
    ops = wet_bounds.fold_program(wet_bounds.liquid_program(), env)
    b.role = "Liquid L: Wetness x Wet Map x schedule"
    return run_program(b, ops, {v: gin.outputs[k] for k, v in wet_bounds.NAMES.items()})





class _Rows:
    """Where the liquid L falls in a table's rows: texture v for Linear
    lookups; for exact ones the row cell, its fraction, and the centres of
    the two rows around it."""

    def __init__(self, b, L, t, exact, film=True):
        rows = t["rows_below"] + t["rows_above"] + 1
        self.exact, self.rows = exact, rows
        program = wet_bounds.row_program(t, film)
        b.role = "Row of L in the tables"
        if not exact:
            self.v = run_program(b, affine_program(program, (rows - 1) / rows, 0.5 / rows), {"x": L})
            return
        y = b.math("MULTIPLY", run_program(b, program, {"x": L}), (rows - 1) * EDGE)
        r0 = b.math("FLOOR", y)
        self.fy = b.math("SUBTRACT", y, r0)
        self.gy = b.math("SUBTRACT", 1.0, self.fy)
        self.cell = b.math("MULTIPLY_ADD", r0, 1.0 / (rows - 1), 0.5 / (rows - 1))
        self.v0 = b.math("MULTIPLY_ADD", r0, 1.0 / rows, 0.5 / rows)
        self.v1 = b.math("ADD", self.v0, 1.0 / rows)


def _param(b, par_img, t, rows, pixel):
    """Pixel `pixel` of the per-row parameter image as a vector socket."""
    u = (pixel + 0.5) / (len(t["params"][0]) // 3)
    b.role = ("Film/pore parameters at L", "Thin sheet's transmittance at L",
              "Specular left, mirror area, roughness ratio")[min(max(pixel - 1, 0), 2)]
    if not rows.exact:
        return lookup(b, par_img, u, rows.v, "Linear").outputs["Color"]
    a = lookup(b, par_img, u, rows.v0, "Closest").outputs["Color"]
    c = lookup(b, par_img, u, rows.v1, "Closest").outputs["Color"]
    m = b.node("ShaderNodeVectorMath", operation="MULTIPLY_ADD")
    b.link(vec(b, "SUBTRACT", c, a), m.inputs[0])
    b.link(rows.fy, m.inputs[1])
    b.link(a, m.inputs[2])
    return m.outputs[0]



def _wet_colour(b, colour, t, images, rows):
    """The core's wetness function for each channel of the dry colour. The
    column program and the cell arithmetic run on the colour as a vector
    (one node for three channels); only the lookups and their weights are
    per channel (c_core/bench/results/2026-11-27-blender-ablation.md)."""
    na = t["columns"]
    b.role = "Column of each dry channel in the tables"
    if not rows.exact:
        us = separate(b, run_program_vector(b, affine_program(t["column_program"], (na - 1) / na, 0.5 / na), colour))
        out, shared = None, []
        for c in range(3):   # image c holds channel c's function in channel c, zeros elsewhere
            b.role = f"Wet {'red green blue'.split()[c]}: the core's table"
            tex = lookup(b, images.linear[c], us[c], rows.v, "Linear")
            tc = tex.outputs["Color"]
            shared.append(tex.outputs["Alpha"])
            out = tc if out is None else vec(b, "ADD", out, tc)
        return out, shared
    top = (na - 1) * EDGE
    x = run_program_vector(b, affine_program(t["column_program"], top, 0.0), colour)
    x = vec_num(b, "MINIMUM", vec_num(b, "MAXIMUM", x, 0.0), top)
    j = vec_num(b, "FLOOR", x, 0.0)
    fxs = separate(b, vec(b, "SUBTRACT", x, j))
    us = separate(b, vec_num(b, "MULTIPLY_ADD", j, 1.0 / (na - 1), 0.5 / (na - 1)))
    # cell texel: corners (f01, f10, f11), alpha f00, weighted by
    # (fx gy, gx fy, fx fy) = fx (gy, -fy, fy) + (0, fy, 0) and gx gy. The
    # weights sum to 1 over non-negative corners, so the GPU's half-precision
    # copy (EEVEE) errs by at most 2^-11 of the value; differences of corners
    # would add their own rounding to it.
    neg_fy = b.math("MULTIPLY", rows.fy, -1.0)
    slope = combine(b, rows.gy, neg_fy, rows.fy)
    base = combine(b, 0.0, rows.fy, 0.0)
    neg_gy = b.math("MULTIPLY", rows.gy, -1.0)
    values = []
    for c in range(3):
        b.role = f"Wet {'red green blue'.split()[c]}: the table cell's bilinear blend"
        tex = lookup(b, images.cells[c], us[c], rows.cell, "Closest")
        w = b.node("ShaderNodeVectorMath", operation="MULTIPLY_ADD")
        b.link(fxs[c], w.inputs[0])
        b.link(slope, w.inputs[1])
        b.link(base, w.inputs[2])
        dot = vec(b, "DOT_PRODUCT", tex.outputs["Color"], w.outputs[0])
        w00 = b.math("MULTIPLY_ADD", fxs[c], neg_gy, rows.gy)
        dot_value = dot.node.outputs["Value"]
        values.append(b.math("MULTIPLY_ADD", tex.outputs["Alpha"], w00, dot_value))
    return combine(b, *values), None



def _wet_path(b, gin, L, preset, liquid_name, exact, normal, stages=(2, 3), view=True, constant_L=None, film=True):
    """The core's wetness function of one preset's class for the input colour
    (times the preset's view factor at the view through `normal`):
    (colour, roughness, coat weight, base specular factor) sockets, and a
    reader of further parameter pixels. stages: the STAGES indices of the
    lookups and of the view factor; view: False leaves the view factor out;
    constant_L: L as a number where it is constant (the parameters are then
    numbers: one row of their table, exact); film: False where L never
    exceeds the table's saturation (the row program's film branch folds)."""
    t = data.table(preset, liquid_name)
    images = data.lookup_images(preset, liquid_name, exact)
    b.stage = STAGES[stages[0]]
    rows = _Rows(b, L, t, exact, film)
    colour, shared = _wet_colour(b, gin.outputs["Base Color"], t, images, rows)
    b.role = "Specular left, mirror area, roughness ratio"
    if shared is not None and constant_L is None:
        factor, area, ratio = shared      # the colour reads' alpha (data.LookupImages.linear)
    elif constant_L is None:
        spec = b.node("ShaderNodeSeparateXYZ")   # (base specular factor, interface area, roughness ratio)
        b.link(_param(b, images.params, t, rows, 3), spec.inputs[0])
        factor, area, ratio = spec.outputs[0], spec.outputs[1], spec.outputs[2]
    else:
        row = wet_constant.Row(t, constant_L)
        factor, area, ratio = (wet_constant.value(b, x) for x in wet_constant.param(t, row, 3))
    b.role = "Wet roughness: Roughness x the liquid's ratio"
    rough = b.math("MULTIPLY", gin.outputs["Roughness"], ratio, clamp=True)
    b.stage = STAGES[stages[1]]
    b.role = "View factor at the view's cosine"
    view = view_factor.lookup(b, t, images.view, rows, normal) if view else None
    if view is not None:
        b.role = "Wet colour x view factor"
        colour = vec(b, "MULTIPLY", colour, view)

    def param(pixel):
        b.stage = STAGES[stages[0]]
        if constant_L is not None:
            b.role = "Thin sheet's transmittance at L"
            return wet_constant.colour_value(b, wet_constant.param(t, row, pixel))
        return _param(b, images.params, t, rows, pixel)
    return colour, rough, area, factor, param


def _wet_path_constant(b, gin, L, preset, liquid_name, normal, stages=(2, 3), view=True):
    """_wet_path at a constant liquid amount L (a number): the table rows at
    L as RGB Curves nodes and numbers (wet_constant)."""
    t = data.table(preset, liquid_name)
    row = wet_constant.Row(t, L)
    b.stage = STAGES[stages[0]]
    b.role = "Wet colour: the core's table at this L"
    colour = wet_constant.wet_colour(b, gin.outputs["Base Color"], t, row)
    factor, area, ratio = wet_constant.param(t, row, 3)
    b.role = "Wet roughness: Roughness x the liquid's ratio"
    rough = b.math("MULTIPLY", gin.outputs["Roughness"], ratio, clamp=True)
    b.stage = STAGES[stages[1]]
    b.role = "View factor at the view's cosine"
    vf = view_factor.curve(b, t, row, normal, wet_constant.curves) if view else None
    if vf is not None:
        b.role = "Wet colour x view factor"
        colour = vec(b, "MULTIPLY", colour, vf)

    def param(pixel):
        b.stage = STAGES[stages[0]]
        b.role = "Thin sheet's transmittance at L"
        return wet_constant.colour_value(b, wet_constant.param(t, row, pixel))
    b.stage = STAGES[stages[0]]
    b.role = "Liquid's mirror area at L"
    area = wet_constant.value(b, area)
    b.role = "Specular left under the liquid at L"
    return colour, rough, area, wet_constant.value(b, factor), param


def _sockets_match(tree):
    """True when the group already has exactly INPUTS and OUTPUTS (then a
    rebuild keeps them, and with them the group node's links and values)."""
    ins, outs = _socket_items(tree)
    return list(ins) == [i[0] for i in INPUTS] and list(outs) == [o[0] for o in OUTPUTS]


class _Inputs:
    """The group's inputs as one Group Input node per stage (each stage's
    frame shows the inputs it reads; layout hides the rest)."""

    def __init__(self, b):
        self.b = b
        self.nodes = {}

    @property
    def outputs(self):
        n = self.nodes.get(self.b.stage)
        if n is None:
            n = self.nodes[self.b.stage] = self.b.node("NodeGroupInput")
        return n.outputs


def _socket_items(tree):
    """The group's (inputs, outputs) interface items, by name."""
    if hasattr(tree, "interface"):
        items = [i for i in tree.interface.items_tree if getattr(i, "item_type", "SOCKET") == "SOCKET"]
        return ({i.name: i for i in items if i.in_out == "INPUT"}, {i.name: i for i in items if i.in_out == "OUTPUT"})
    return {s.name: s for s in tree.inputs}, {s.name: s for s in tree.outputs}


def _make_sockets(tree):
    compat.clear_sockets(tree)
    for name, kind, default, lo, hi in INPUTS:
        compat.new_socket(tree, name, "INPUT", kind, default, lo, hi)
    for name, kind in OUTPUTS:
        compat.new_socket(tree, name, "OUTPUT", kind)


def _socket_hints(tree):
    """Tooltips on every socket, and the Normal input's value hidden: then
    an unlinked Normal is the shading normal, as a built-in node's (Blender
    5.2's EEVEE passes a shown vector input's (0, 0, 0) to the Bump node,
    which then poisons every output: base colour 0, specular 10 624; 3.4 and
    4.3 give the same values either way). Also set on a group an older
    version of the add-on made (a rebuild keeps matching sockets)."""
    ins, outs = _socket_items(tree)
    for name, item in ins.items():
        if hasattr(item, "description"):
            item.description = DESCRIPTIONS[name]
    for name, item in outs.items():
        if hasattr(item, "description"):
            item.description = DESCRIPTIONS["out " + name]
    ins["Normal"].hide_value = True


def _bump(b, gin, spill_edges):
    """The shading normal bumped by the wet map at spill edges. Without them,
    a Bump node with no height: the Normal input, or where that is unlinked
    the shading normal (a group input passed straight through gives
    (0, 0, 0) in Cycles and EEVEE, 5.2 measured), which Cycles folds away
    (BumpNode::constant_fold)."""
    bump = b.node("ShaderNodeBump", label="Spill-edge bump from the Wet Map" if spill_edges else "Shading normal")
    if spill_edges:
        b.link(gin.outputs["Spill Edge"], bump.inputs["Strength"])
        b.link(gin.outputs["Wet Map"], bump.inputs["Height"])
    bump.inputs["Distance"].default_value = 0.02
    b.link(gin.outputs["Normal"], bump.inputs["Normal"])
    return bump.outputs["Normal"]


def _metal_mix(b, gin, L, metal, liquid_name, exact, normal, colour, rough, coat, view, constant_L=None,
               curves=False):
    """The metallic part's own function (a conductor preset) mixed in by Metallic."""
    if not curves:
        mc, mr, mcoat, _, _ = _wet_path(b, gin, L, metal, liquid_name, exact, normal, stages=(4, 4), view=view,
                                        constant_L=constant_L)
    else:
        mc, mr, mcoat, _, _ = _wet_path_constant(b, gin, constant_L, metal, liquid_name, normal, (4, 4), view)
    b.stage = STAGES[5]
    b.role = "Metal mix by Metallic"
    f = b.math("MINIMUM", b.math("MAXIMUM", gin.outputs["Metallic"], 0.0), 1.0)
    colour = lerp(b, colour, mc, f)
    rough = b.math("MULTIPLY_ADD", b.math("SUBTRACT", mr, rough), f, rough)
    coat = b.math("MULTIPLY_ADD", b.math("SUBTRACT", mcoat, coat), f, coat)
    return colour, rough, coat


def build_group(tree, preset, liquid_name, exact=False, metal=None, quality="BALANCED", constant=None,
                varying=None):
    """(Re)builds the inside of a Soak Wet group for a preset and liquid.
    metal: a conductor preset whose function the metallic part of the
    material gets (mixed by the Metallic input), None for none. quality: one
    of QUALITY's keys, the terms the group models (exact lookups, view
    factor, bump). constant: {name: value} of wet_constant.LIQUID_INPUTS
    when none of them varies (the group node's values; None: they may):
    the group is then specialised to that one liquid amount (wet_constant;
    those inputs are read from here, not from the node, and the spill-edge
    bump, which needs a varying wet map, is left out). varying: for a
    liquid that can vary, {"fixed": {name: value} of those inputs the
    node's value alone sets (folded into numbers), "film": False where the
    liquid never exceeds the table's saturation, "bump": False where the
    Spill Edge is 0 and cannot change} (wet_bounds). Sockets that
    already match INPUTS/OUTPUTS are kept (the node's links and values too)."""
    terms = QUALITY[quality]
    m = data.material(preset)
    if metal is not None and data.material(metal)["kind"] != "conductor":
        raise data.SoakDataError(f"'{metal}' is not a conductor preset")
    tree.nodes.clear()
    if not _sockets_match(tree):
        _make_sockets(tree)
    _socket_hints(tree)
    if constant is not None:
        constant = {name: float(constant[name]) for name in wet_constant.LIQUID_INPUTS}
    tree[GROUP_TAG] = json.dumps({"preset": preset, "liquid": liquid_name, "exact": bool(exact), "metal": metal,
                                  "quality": quality, "constant": constant, "varying": varying})
    # Exact lookups asked for (Exact lookups, Quality Exact) keep the tables'
    # Closest reads at a constant liquid too (its row arithmetic folds):
    # EEVEE samples a curve from a half-float texture of its own, which errs
    # by 0.3 % in 4.3 (blender43_eevee); forced ones (EEVEE Next's Linear
    # lookups, compat.exact_lookups_required) do not: a curve reads no image.
    exact_asked = bool(exact) or terms["exact"]
    exact = exact_asked or compat.exact_lookups_required()
    b = Builder(tree)
    gin = _Inputs(b)
    b.stage = STAGES[0]
    b.role = "Liquid L (constant)"
    Lc = wet_constant.liquid(constant) if constant is not None else None
    fixed, film = (varying or {}).get("fixed"), (varying or {}).get("film", True)
    L = _liquid_schedule(b, gin, fixed) if Lc is None else wet_constant.value(b, Lc)
    b.stage = STAGES[1]
    normal = _bump(b, gin, terms["bump"] and Lc is None and (varying or {}).get("bump", True))
    view = terms["view_factor"]
    curves = Lc is not None and not exact_asked
    if not curves:
        colour, rough, coat, factor, param = _wet_path(b, gin, L, preset, liquid_name, exact, normal, view=view,
                                                       constant_L=Lc, film=film)
    else:
        colour, rough, coat, factor, param = _wet_path_constant(b, gin, Lc, preset, liquid_name, normal, view=view)
    if metal is not None:
        colour, rough, coat = _metal_mix(b, gin, L, metal, liquid_name, exact, normal, colour, rough, coat, view,
                                         constant_L=Lc, curves=curves)
    b.stage = STAGES[6]
    b.role = "Specular left under the liquid"
    spec = b.math("MULTIPLY", gin.outputs["Specular"], factor)
    b.role = "Undo the engine's coat dimming (4.x)"
    # Blender's own coat dims what lies under it (4.x); the core's values
    # already hold the film's transmission: undo the engine's share.
    keep = compat.coat_base_compensation(b, coat, data.liquid(liquid_name)["ior"], normal)
    if keep is not None:
        sc = b.node("ShaderNodeVectorMath", operation="SCALE")
        b.link(colour, sc.inputs[0])
        b.link(keep, sc.inputs["Scale"])
        colour = sc.outputs[0]
        spec = b.math("MULTIPLY", spec, keep)
    translucency = param(2) if m["kind"] == "thin_sheet" else None
    b.stage = b.role = None
    gout = b.node("NodeGroupOutput")
    for name, sock in (("Base Color", colour), ("Roughness", rough), ("Coat Weight", coat), ("Specular", spec),
                       ("Liquid", L), ("Translucency", translucency), ("Normal", normal)):
        if sock is not None:
            b.link(sock, gout.inputs[name])
    group_layout.arrange(tree, b.stages, STAGES)
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
