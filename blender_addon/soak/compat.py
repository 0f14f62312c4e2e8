"""Blender version differences behind one small interface.

Principled BSDF input names: Blender 3.x (node_shader_bsdf_principled.cc up
to 3.6) vs 4.0+ (renamed, panels). Node-group sockets: ``ng.inputs.new``
(3.x) vs ``ng.interface.new_socket`` (4.0+). Animation: ``Action.fcurves``
(up to 4.x) vs slotted actions' channel bags (5.0 removed the former). EEVEE's
engine id: ``BLENDER_EEVEE`` (up to 4.1, again from 5.0) vs
``BLENDER_EEVEE_NEXT`` (4.2-4.4). ``Material.use_nodes``: deprecated in 5.0
(always true). The tables are checked against the names in Blender's sources
by tests/blender/test_compat.py."""

import bpy

from . import data

# role -> (Blender 3.x name, Blender 4.x name); None: no such input.
PRINCIPLED = {
    "base_color": ("Base Color", "Base Color"),
    "metallic": ("Metallic", "Metallic"),
    "roughness": ("Roughness", "Roughness"),
    "ior": ("IOR", "IOR"),
    "normal": ("Normal", "Normal"),
    "specular": ("Specular", "Specular IOR Level"),
    "subsurface_weight": ("Subsurface", "Subsurface Weight"),
    "subsurface_radius": ("Subsurface Radius", "Subsurface Radius"),
    "coat_weight": ("Clearcoat", "Coat Weight"),
    "coat_roughness": ("Clearcoat Roughness", "Coat Roughness"),
    "coat_ior": (None, "Coat IOR"),
    "coat_tint": (None, "Coat Tint"),
    "coat_normal": ("Clearcoat Normal", "Coat Normal"),
    "transmission": ("Transmission", "Transmission Weight"),
    "emission_color": ("Emission", "Emission Color"),
}


def scheme(version=None):
    """0 for the 3.x names, 1 for 4.0+."""
    v = version if version is not None else bpy.app.version
    return 1 if tuple(v) >= (4, 0, 0) else 0


def principled_name(role, version=None):
    return PRINCIPLED[role][scheme(version)]


def principled_input(node, role):
    """The Principled input for a role, or None where this version has none."""
    name = principled_name(role)
    if name is None:
        return None
    return node.inputs.get(name)


def _socket_type(kind):
    return {"float": "NodeSocketFloat", "factor": "NodeSocketFloatFactor", "color": "NodeSocketColor",
            "vector": "NodeSocketVector", "shader": "NodeSocketShader"}[kind]


def new_socket(tree, name, in_out, kind, default=None, lo=None, hi=None):
    """Adds a group socket; returns the interface item (4.x) or socket (3.x)."""
    if hasattr(tree, "interface"):
        base = "NodeSocketFloat" if kind == "factor" else _socket_type(kind)
        item = tree.interface.new_socket(name, in_out=in_out, socket_type=base)
        if kind == "factor" and hasattr(item, "subtype"):
            try:
                item.subtype = "FACTOR"
            except (TypeError, AttributeError):
                pass
    else:
        coll = tree.inputs if in_out == "INPUT" else tree.outputs
        item = coll.new(_socket_type(kind), name)
    if lo is not None and hasattr(item, "min_value"):
        item.min_value = lo
    if hi is not None and hasattr(item, "max_value"):
        item.max_value = hi
    if default is not None and hasattr(item, "default_value"):
        item.default_value = default
    return item


def clear_sockets(tree):
    if hasattr(tree, "interface"):
        tree.interface.clear()
    else:
        tree.inputs.clear()
        tree.outputs.clear()


def extension_user_dir(package):
    """4.2+ extension user directory, None on older versions."""
    fn = getattr(bpy.utils, "extension_path_user", None)
    if fn is None:
        return None
    try:
        return fn(package, path="", create=True)
    except (TypeError, ValueError):
        return None


def coat_darkens_base(version=None):
    """4.x Principled layers its coat energy-conservingly: everything under it
    is scaled by (1 - coat weight * coat albedo) at the view direction
    (Cycles kernel/svm/closure.h, closure_layering_weight; EEVEE Next the
    same). 3.x's clear coat adds its lobe on top."""
    return scheme(version) == 1


def coat_base_compensation(b, coat_weight, coat_ior, normal):
    """A socket with 1 / (1 - coat weight * F(view)) where the engine's coat
    dims the base (F: Fresnel of the smooth coat, the coat's albedo in Cycles
    and EEVEE Next), None where it does not. b: node_program.Builder."""
    if not coat_darkens_base():
        return None
    fr = b.node("ShaderNodeFresnel")
    fr.inputs["IOR"].default_value = coat_ior
    b.link(normal, fr.inputs["Normal"])
    dim = b.math("MULTIPLY", coat_weight, fr.outputs[0])
    # 1 - dim is 0 only at exact grazing with a full coat, where the engine
    # shows none of the base: Math's safe division gives 0 there
    return b.math("DIVIDE", 1.0, b.math("SUBTRACT", 1.0, dim))


def specular_for_f0(bsdf, f0, version=None):
    """The Principled value (3.x Specular / 4.x Specular IOR Level) whose
    normal-incidence reflectance is f0: 3.x's F0 is 0.08 x Specular
    (Principled v1); 4.x scales the F0 of the BSDF's IOR by 2 x the level
    (0.5: no change)."""
    if scheme(version) == 0:
        return f0 / 0.08
    ior = principled_input(bsdf, "ior").default_value
    return 0.5 * f0 / data.normal_reflectance(ior) if ior != 1.0 else 0.5


def exact_lookups_required(version=None):
    """EEVEE Next (4.2-4.4) returns 0 (or 65504) from a Linear image lookup whose
    coordinate does not vary over the screen (zero derivatives: a constant
    wetness, the per-row parameter column) when anisotropic filtering is on
    (Preferences > Viewport > Anisotropic Filtering, default 2x; off, the same
    lookup is right), measured in 4.3.2 under Mesa llvmpipe: a wet material
    renders black. Closest lookups are right whatever the preference, so
    4.2-4.5 always build the exact path (Closest reads, explicit bilinear),
    which EEVEE needed anyway for the core's bilinear tables (4.4 and 4.5
    are not measured here: kept on the safe side). 5.x's EEVEE returns the
    right Linear value at a constant coordinate again (measured in 5.2.2:
    0.25/0.5/0.125 where 4.3 gives 0), so there the user chooses, as in
    3.x."""
    v = tuple(version if version is not None else bpy.app.version)
    return (4, 2, 0) <= v < (5, 0, 0)


def eevee_engine():
    """The render engine id of EEVEE in the running Blender, from the
    engine enum itself: BLENDER_EEVEE_NEXT in 4.2-4.4, BLENDER_EEVEE before
    and again from 5.0."""
    items = bpy.types.RenderSettings.bl_rna.properties["engine"].enum_items.keys()
    return "BLENDER_EEVEE_NEXT" if "BLENDER_EEVEE_NEXT" in items else "BLENDER_EEVEE"


def is_eevee(engine):
    return engine in ("BLENDER_EEVEE", "BLENDER_EEVEE_NEXT")


def eevee_reflection_switch(scene):
    """(owner, property, hint) of the switch EEVEE needs to reflect the wet
    film: Screen Space Reflections in EEVEE Legacy (up to 4.1), Raytracing
    in EEVEE Next and 5.x; None when the running EEVEE has neither."""
    ee = scene.eevee
    if hasattr(ee, "use_raytracing"):
        return ee, "use_raytracing", ("EEVEE reflects the film sharply only with",
                                      "Raytracing on (else light probes only):")
    if hasattr(ee, "use_ssr"):
        return ee, "use_ssr", ("EEVEE shows the liquid film's reflections",
                               "only with Screen Space Reflections on:")
    return None


def ensure_node_tree(mat):
    """Gives a new material its node tree (Use Nodes before 5.0; 5.x
    materials always use nodes)."""
    if bpy.app.version < (5, 0, 0) or mat.node_tree is None:
        mat.use_nodes = True
    return mat.node_tree


def material_uses_nodes(mat):
    """True when the material's node tree is what renders: 5.0 deprecated
    Material.use_nodes (always true, removal planned for 6.0), so it is read
    only before 5.0."""
    if mat.node_tree is None:
        return False
    return True if bpy.app.version >= (5, 0, 0) else bool(mat.use_nodes)


def _channelbags(id_data):
    """The F-curve collections animating id_data: the action's own list up
    to 4.x, the channel bags of the assigned slot in 5.x's slotted actions."""
    ad = id_data.animation_data
    if ad is None or ad.action is None:
        return []
    act = ad.action
    if not hasattr(act, "layers"):            # before 4.4: no slotted actions
        return [act.fcurves]
    slot = getattr(ad, "action_slot", None)
    bags = []
    if slot is not None:
        for layer in act.layers:
            for strip in layer.strips:
                bag = strip.channelbag(slot)
                if bag is not None:
                    bags.append(bag.fcurves)
    if not bags and hasattr(act, "fcurves"):   # 4.4's legacy view of a one-slot action
        bags.append(act.fcurves)
    return bags


def find_fcurve(id_data, path, index=0):
    """The F-curve animating id_data's `path` (array `index`), or None."""
    for fcurves in _channelbags(id_data):
        fc = fcurves.find(path, index=index)
        if fc is not None:
            return fc
    return None


def fcurves(id_data):
    """Every F-curve animating id_data (a list)."""
    return [fc for bag in _channelbags(id_data) for fc in bag]


def remove_fcurve(id_data, fc):
    """Removes one F-curve that find_fcurve returned."""
    for bag in _channelbags(id_data):
        if any(f == fc for f in bag):
            bag.remove(fc)
            return
