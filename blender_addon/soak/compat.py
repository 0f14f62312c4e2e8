"""Blender version differences behind one small interface.

Principled BSDF input names: Blender 3.x (node_shader_bsdf_principled.cc up
to 3.6) vs 4.0+ (renamed, panels). Node-group sockets: ``ng.inputs.new``
(3.x) vs ``ng.interface.new_socket`` (4.0+). The tables are checked against
the names in Blender's sources by tests/blender/test_compat.py."""

import bpy

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
    and EEVEE Next), None where it does not. b: nodes._Builder."""
    if not coat_darkens_base():
        return None
    fr = b.node("ShaderNodeFresnel")
    fr.inputs["IOR"].default_value = coat_ior
    b.link(normal, fr.inputs["Normal"])
    dim = b.math("MULTIPLY", coat_weight, fr.outputs[0])
    # 1 - dim is 0 only at exact grazing with a full coat, where the engine
    # shows none of the base: Math's safe division gives 0 there
    return b.math("DIVIDE", 1.0, b.math("SUBTRACT", 1.0, dim))


def exact_lookups_required(version=None):
    """EEVEE Next (4.2+) returns 0 (or 65504) from a Linear image lookup whose
    coordinate does not vary over the screen (zero derivatives: a constant
    wetness, the per-row parameter column) when anisotropic filtering is on
    (Preferences > Viewport > Anisotropic Filtering, default 2x; off, the same
    lookup is right), measured in 4.3.2 under Mesa llvmpipe: a wet material
    renders black. Closest lookups are right whatever the preference, so
    4.2+ always builds the exact path (Closest reads, explicit bilinear),
    which EEVEE needed anyway for the core's bilinear tables."""
    v = version if version is not None else bpy.app.version
    return tuple(v) >= (4, 2, 0)
